!> The contact stage of the explicit cycle (called only when the deck has *CONTACT):
!>  contact_forces: after the element pass, before the velocity update: bucket sort when due
!>    (every BSORT cycles, and whenever twice the largest nodal travel since the last sort
!>    reaches the search margin; in serial runs a due sort that provably finds no candidate,
!>    because the last sort found none with the slave nodes' box a gap away from the grown
!>    segments' box and the travel since cannot have closed it, keeps only its bookkeeping:
!>    contact with nothing to do pays no sorts, and a pass with no candidate and no node in
!>    contact no pass over its slave nodes; results unchanged, the sorts skipped are those
!>    that would have found nothing), local search and penalty forces for every active interface
!>    (BT <= t <= DT), added into model%f; the contact springs enter the critical step as
!>    dt <= 1/sqrt(1/dt_e^2 + w_c^2/4), w_c^2 = max over nodes of the Gershgorin row sum of
!>    the contact stiffness over the nodal mass (2k on a slave node, 2k N_i on a master node,
!>    summed over its springs): an upper bound of the contact frequencies. Nodes of rigid
!>    bodies use the body's mass and inertia instead (dx_rigid_contact).
!>  contact_work: after the velocity update: work of the contact forces with the centred
!>    weighting of docs/history.md, W += f_c(n).dtavg(n)(v(n-1/2) + v(n+1/2))/2; the sliding
!>    interface energy at t(n) is -(W - f_c(n).dtavg(n) v(n+1/2)/2) (stored penalty energy
!>    plus friction dissipation): the partner of KE(n) = m v(n-1/2).v(n+1/2)/2, which
!>    telescopes into the work sums minus the v(n+1/2) half of the last one (as the element
!>    work is booked); with the full W the ratio dipped by that half-step work during each
!>    contact impulse (extreme_contact_1000ms: 0.985). Writes rcforc.
!> Algorithms: dx_contact_search (bucket sort), dx_contact_penalty (forces).
module dx_contact
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_timer, only: wall_time
   use dx_model, only: model_t
   use dx_contact_types, only: contact_set_t
   use dx_contact_search, only: bucket_sort, segment_box
   use dx_contact_penalty, only: pass_records, pass_node, pass_apply
   use dx_contact_strips, only: contact_strips
   use dx_rigid_contact, only: rigid_contact_w2, rigid_effective_mass
   use dx_append_file, only: append_from
   implicit none
   private
   public :: contact_forces, contact_work, contact_search_nodes, contact_assemble, contact_dt, &
             contact_vmax, contact_prepare, idle_sort

contains

   !> Contact forces at x(n) into model%f; lowers dtcrit (element step) for stiff contact.
   !> Three stages, which an MPI run calls separately (dx_par_contact) with the exchange of
   !> the slave nodes' results between the first and the second.
   subroutine contact_forces(model, dt_old, dtcrit)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: dtcrit
      real(wp) :: w2max, vmax
      logical :: due
      if (model%erodes) call erosion_refresh(model)
      vmax = contact_vmax(model%v, model%contact%node)
      call contact_prepare(model, dt_old, vmax, due)
      call contact_search_nodes(model, dt_old, dtcrit, vmax, w2max)
      call contact_assemble(model, w2max, .true.)
      call contact_dt(model%contact, w2max, dtcrit)
   end subroutine contact_forces

   !> Element erosion (dx_erosion): the live masks of every pass from the eroded flags. A
   !> segment is live when its owner element lives and the element across its face (if
   !> any) does not: the faces of eroded elements leave the surface and the interior faces
   !> they expose join it (the automatic and part-based surfaces hold the interior faces of
   !> a deck that erodes, dormant; dx_contact_build). A slave node takes part while a living
   !> element holds it (LS-DYNA deletes the nodes of eroded elements from contact). When a
   !> mask changes the pass sorts again (its candidates and the slave nodes' normals) and
   !> a slave node loses a contact segment that left. The first call forms the masks
   !> without a sort, so a restarted run (masks not dumped) sorts when the first did.
   !> Serial model only (an MPI run with erosion and contact is an input error).
   subroutine erosion_refresh(model)
      type(model_t), intent(inout) :: model
      logical, allocatable :: alive(:), held(:)
      integer :: e, b, q, k, i, j, n
      logical :: changed, l
      allocate(alive(model%ne), held(model%nn))
      held = .false.
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            n = size(blk%conn, 1)
            do q = 1, blk%nel
               alive(blk%elem(q)) = .not. blk%failed(q)
               if (.not. blk%failed(q)) held(blk%conn(1:n, q)) = .true.
            end do
         end associate
      end do
      do i = 1, size(model%contact%iface)
         do j = 1, size(model%contact%iface(i)%pass)
            associate (p => model%contact%iface(i)%pass(j))
               if (.not. allocated(p%live)) cycle
               changed = .false.
               do k = 1, p%nseg
                  e = p%oelem(k)
                  l = .true.
                  if (e > 0) l = alive(e)
                  if (p%onbr(k) > 0) l = l .and. .not. alive(p%onbr(k))
                  if (l .neqv. p%live(k)) changed = .true.
                  p%live(k) = l
               end do
               if (allocated(p%slive)) then
                  do k = 1, p%nsseg
                     e = p%soelem(k)
                     l = .true.
                     if (e > 0) l = alive(e)
                     if (p%snbr(k) > 0) l = l .and. .not. alive(p%snbr(k))
                     if (l .neqv. p%slive(k)) changed = .true.
                     p%slive(k) = l
                  end do
               end if
               do k = 1, p%nnode
                  l = held(p%node(k))
                  if (l .neqv. p%nlive(k)) changed = .true.
                  p%nlive(k) = l
                  if (p%iseg(k) > 0) then
                     if (.not. (l .and. p%live(p%iseg(k)))) then
                        p%iseg(k) = 0; p%gap(k) = 0.0_wp; p%ft(:, k) = 0.0_wp
                     end if
                  end if
               end do
               if (changed .and. p%live_set) p%last_sort = -1000000
               p%live_set = .true.
            end associate
         end do
      end do
   end subroutine erosion_refresh

   !> The largest speed |v| over the given nodes (the contact nodes, or in an MPI run the
   !> rank's owned contact nodes, then the maximum over the ranks: the same bits).
   real(wp) function contact_vmax(v, nodes) result(vmax)
      real(wp), intent(in) :: v(:, :)
      integer, intent(in) :: nodes(:)
      integer :: i
      vmax = 0.0_wp
      do i = 1, size(nodes)
         vmax = max(vmax, norm2(v(:, nodes(i))))
      end do
   end function contact_vmax

   !> Stage 0: contact forces and row sums to zero, inactive interfaces' state cleared, the
   !> travel since each pass's sort advanced by vmax dt_old and the passes that sort this
   !> cycle marked (p%sort_due; due: any). MPI runs need every contact node's x when due.
   subroutine contact_prepare(model, dt_old, vmax, due)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: dt_old, vmax
      logical, intent(out) :: due
      integer :: i, j
      real(wp) :: t
      t = model%time
      due = .false.
      associate (cs => model%contact)
         do i = 1, size(cs%node)
            cs%fc(:, cs%node(i)) = 0.0_wp
            cs%krow(cs%node(i)) = 0.0_wp
         end do
         do i = 1, size(cs%iface)
            associate (f => cs%iface(i))
               f%fslave = 0.0_wp
               f%fmaster = 0.0_wp
               f%nactive = 0
               if (t < f%bt .or. t > f%dt) then
                  do j = 1, size(f%pass)
                     f%pass(j)%iseg = 0
                     f%pass(j)%ft = 0.0_wp
                     f%pass(j)%gap = 0.0_wp
                     f%pass(j)%sort_due = .false.
                  end do
                  cycle
               end if
               do j = 1, size(f%pass)
                  associate (p => f%pass(j))
                     p%moved = p%moved + vmax*dt_old
                     p%moved_real = p%moved_real + vmax*dt_old
                     p%sort_due = model%cycle - p%last_sort >= f%bsort .or. &
                                  2.0_wp*p%moved >= p%margin .or. &
                                  (cs%nstrip > 1 .and. .not. allocated(p%mine))
                     due = due .or. p%sort_due
                  end associate
               end do
            end associate
         end do
      end associate
   end subroutine contact_prepare

   !> Stage 1: bucket sorts that are due (and, in MPI runs, the strips with them), then the
   !> result of every slave node of this strip (pass_node; all of them in a serial run).
   !> vmax: the largest contact node speed; w2max: the contact frequency^2 bound of the
   !> candidate pairs (this strip's).
   subroutine contact_search_nodes(model, dt_old, dtcrit, vmax, w2max)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: dt_old, dtcrit, vmax
      real(wp), intent(out) :: w2max
      real(wp) :: t, t0, t1, dt_est, margin
      integer :: i, j, k
      real(wp), allocatable :: meff(:)
      logical :: has_rigid
      t0 = wall_time()
      ! (model%rigid is unallocated in a deck without rigid bodies; nested tests, no
      ! short-circuit in Fortran)
      has_rigid = allocated(model%rigid)
      if (has_rigid) has_rigid = allocated(model%rigid%node_body)
      t = model%time
      associate (cs => model%contact)
         dt_est = dt_old
         if (dt_est <= 0.0_wp) dt_est = model%ctrl%tssfac*dtcrit
         w2max = 0.0_wp
         do i = 1, size(cs%iface)
            associate (f => cs%iface(i))
               if (t < f%bt .or. t > f%dt) cycle
               do j = 1, size(f%pass)
                  associate (p => f%pass(j))
                     if (p%sort_due) then
                        t1 = wall_time()
                        if (cs%nstrip > 1 .and. f%rank >= 0) then   ! a local pair: its rank
                           if (.not. allocated(p%mine)) allocate(p%mine(p%nnode))
                           p%mine = f%rank == cs%istrip
                        else if (cs%nstrip > 1) then
                           call contact_strips(p, model%x, cs%nstrip, cs%istrip, &
                                               cs%mine_node)
                        end if
                        if (p%mext >= 0.0_wp) then   ! MPI ghost sorts: from every rank
                           margin = 0.25_wp*p%mext
                           p%mext = -1.0_wp
                        else
                           margin = 0.25_wp*mean_extent(p, model%x)
                        end if
                        margin = max(margin, 4.0_wp*vmax*dt_est)
                        if (idle_sort(p, margin, has_rigid .or. model%erodes)) then
                           ! this sort would find no candidate either: only its bookkeeping
                           p%margin = margin
                           p%moved = 0.0_wp
                           p%nskip = p%nskip + 1
                        else if (has_rigid) then
                           ! rigid nodes: the body's inertia (dx_rigid_contact)
                           meff = model%mass
                           call rigid_effective_mass(model%rigid, cs%node, model%x, meff)
                           call bucket_sort(p, model%x, margin, meff)
                        else
                           call bucket_sort(p, model%x, margin, model%mass)
                        end if
                        p%last_sort = model%cycle
                        cs%t_search = cs%t_search + (wall_time() - t1)
                     end if
                     w2max = max(w2max, p%w2pot)
                     call pass_records(p)
                     if (idle_pass(p)) then
                        ! no candidate and no node in contact: every result is none
                        p%rint = 0
                     else if (allocated(p%mine)) then
                        do k = 1, p%nnode
                           if (p%mine(k)) then
                              call pass_node(f, p, k, model%x, model%v, model%mass, &
                                             dt_old, dt_est, 2.0_wp*vmax*dt_est)
                           else
                              p%rint(:, k) = 0     ! another strip's node: exchanged
                           end if
                        end do
                     else
                        do k = 1, p%nnode
                           call pass_node(f, p, k, model%x, model%v, model%mass, dt_old, &
                                          dt_est, 2.0_wp*vmax*dt_est)
                        end do
                     end if
                  end associate
               end do
            end associate
         end do
         cs%t_force = cs%t_force + (wall_time() - t0)
      end associate
   end subroutine contact_search_nodes

   !> Stage 2: the slave nodes' results added in the serial order (interface, pass, slave
   !> node: pass_apply) into cs%fc, the stiffness row sums and the resultants; when
   !> add_force, cs%fc into model%f (an MPI run adds it after the shared-node exchange).
   !> w2max grows by the row sums over the nodal masses (rigid nodes: body inertia).
   subroutine contact_assemble(model, w2max, add_force)
      type(model_t), intent(inout) :: model
      real(wp), intent(inout) :: w2max
      logical, intent(in) :: add_force
      real(wp) :: t, t0, fsum(3)
      integer :: i, j, k, nd
      logical :: has_rigid
      t0 = wall_time()
      has_rigid = allocated(model%rigid)
      if (has_rigid) has_rigid = allocated(model%rigid%node_body)
      t = model%time
      associate (cs => model%contact)
         do i = 1, size(cs%iface)
            associate (f => cs%iface(i))
               if (t < f%bt .or. t > f%dt) cycle
               do j = 1, size(f%pass)
                  associate (p => f%pass(j))
                     ! serial, idle (contact_search_nodes): no result, every node's state
                     ! already none (iseg, gap, ft 0), fsum 0
                     if (.not. allocated(p%mine)) then
                        if (idle_pass(p)) cycle
                     end if
                     fsum = 0.0_wp
                     do k = 1, p%nnode
                        if (p%rint(1, k) == 0 .and. p%rint(2, k) == 0) then
                           p%iseg(k) = 0          ! what pass_apply does with no result
                           p%gap(k) = 0.0_wp
                           p%ft(:, k) = 0.0_wp
                           cycle
                        end if
                        call pass_apply(p, k, cs%fc, fsum, cs%krow, f%nactive)
                     end do
                     if (j == 1) then
                        f%fslave = f%fslave + fsum
                        f%fmaster = f%fmaster - fsum
                     else
                        f%fmaster = f%fmaster + fsum
                        f%fslave = f%fslave - fsum
                     end if
                  end associate
               end do
            end associate
         end do
         do i = 1, size(cs%node)
            nd = cs%node(i)
            if (add_force) model%f(:, nd) = model%f(:, nd) + cs%fc(:, nd)
            if (has_rigid) then
               if (model%rigid%node_body(nd) > 0) cycle   ! rigid nodes: body inertia below
            end if
            ! (a node without stiffness adds 0 to a maximum that is >= 0: skipped)
            if (cs%krow(nd) == 0.0_wp) cycle
            if (model%mass(nd) > 0.0_wp) w2max = max(w2max, cs%krow(nd)/model%mass(nd))
         end do
         if (has_rigid) &
            w2max = max(w2max, rigid_contact_w2(model%rigid, cs%node, cs%krow, model%x))
         cs%t_force = cs%t_force + (wall_time() - t0)
      end associate
   end subroutine contact_assemble

   !> Stage 3: the contact bound on the critical step, dt <= 1/sqrt(1/dt_e^2 + w2max).
   subroutine contact_dt(cs, w2max, dtcrit)
      type(contact_set_t), intent(inout) :: cs
      real(wp), intent(in) :: w2max
      real(wp), intent(inout) :: dtcrit
      cs%dt_limit = huge(1.0_wp)
      if (w2max > 0.0_wp) then
         cs%dt_limit = 1.0_wp/sqrt(1.0_wp/dtcrit**2 + w2max)
         dtcrit = min(dtcrit, cs%dt_limit)
      end if
   end subroutine contact_dt

   !> A sort of pass p with this margin would find no candidate (serial and MPI runs, no rigid
   !> bodies, no erosion: nodes move by at most v dt per step): the last sort that ran
   !> found none, its slave nodes' box a gap p%clear away from its grown segments' box along
   !> an axis, and since then each node has moved at most p%moved_real, so that gap has
   !> closed by at most 2 moved_real plus the margin's growth. Half the gap is kept as a
   !> safety. The candidates (none), w2pot (0) and so the results are those of the sort.
   logical function idle_sort(p, margin, rigid_or_erodes)
      use dx_contact_types, only: contact_pass_t
      type(contact_pass_t), intent(in) :: p
      real(wp), intent(in) :: margin
      logical, intent(in) :: rigid_or_erodes
      idle_sort = .false.
      ! (MPI runs: p%clear is the serial one, reduced over the ranks: dx_par_contact)
      if (p%clear <= 0.0_wp) return
      if (rigid_or_erodes) return
      idle_sort = 2.0_wp*p%moved_real + max(0.0_wp, margin - p%margin_real) < 0.5_wp*p%clear
   end function idle_sort

   !> Pass p has no candidate pair (on this rank) and no slave node in contact: pass_node
   !> would give every node no result.
   logical function idle_pass(p)
      use dx_contact_types, only: contact_pass_t
      type(contact_pass_t), intent(in) :: p
      idle_pass = size(p%cand) == 0
      if (idle_pass) idle_pass = .not. any(p%iseg(1:p%nnode) > 0)
   end function idle_pass

   !> mean largest extent of the pass's segments
   real(wp) function mean_extent(p, x) result(ext)
      use dx_contact_types, only: contact_pass_t
      type(contact_pass_t), intent(in) :: p
      real(wp), intent(in) :: x(:, :)
      integer :: s
      real(wp) :: lo(3), hi(3)
      ext = 0.0_wp
      do s = 1, p%nseg
         call segment_box(p, x, s, lo, hi)
         ext = ext + maxval(hi - lo)
      end do
      ext = ext/real(max(1, p%nseg), wp)
   end function mean_extent

   !> Work of this cycle's contact forces (centred), sliding energy, rcforc output.
   subroutine contact_work(model, vold, dtavg, outdir, error)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: vold(:, :), dtavg
      character(*), intent(in) :: outdir
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j, nd, ncand, nslave
      real(wp) :: w, wn, t
      logical :: done
      associate (cs => model%contact)
         w = 0.0_wp
         wn = 0.0_wp
         do i = 1, size(cs%node)   ! (a node without contact force adds +-0: skipped)
            nd = cs%node(i)
            if (all(cs%fc(:, nd) == 0.0_wp)) cycle
            w = w + dot_product(cs%fc(:, nd), vold(:, nd) + model%v(:, nd))
            wn = wn + dot_product(cs%fc(:, nd), model%v(:, nd))
         end do
         cs%work = cs%work + 0.5_wp*dtavg*w
         ! at t(n) only the v(n-1/2) half of this cycle's work is booked, as the time-centred
         ! kinetic energy and the element work are (the v(n+1/2) half belongs to t(n+1))
         model%energy%sliding = -(cs%work - 0.5_wp*dtavg*wn)
         t = model%time
         done = (model%ctrl%endtim > 0.0_wp .and. t >= model%ctrl%endtim) .or. &
                (model%ctrl%endcyc > 0 .and. model%cycle >= model%ctrl%endcyc)
         if (cs%rcforc_dt > 0.0_wp .and. (t >= cs%next_rcforc .or. done)) then
            call write_rcforc(cs, t, outdir, error)
            if (allocated(error)) return
            cs%next_rcforc = cs%next_rcforc + cs%rcforc_dt* &
               real(max(1, ceiling((t - cs%next_rcforc)/cs%rcforc_dt + 1.0e-9_wp)), wp)
         end if
         if (done .and. .not. cs%finished) then
            cs%finished = .true.
            ncand = 0; nslave = 0
            do i = 1, size(cs%iface)
               do j = 1, size(cs%iface(i)%pass)
                  ncand = ncand + size(cs%iface(i)%pass(j)%cand)
                  nslave = nslave + cs%iface(i)%pass(j)%nnode
               end do
            end do
            call log_info('dynx: contact: '//str(size(cs%iface))//' interface(s), '// &
               str(size(cs%node))//' contact nodes, '//str(sum([(sum(cs%iface(i)%pass(:)%nsort), &
               i = 1, size(cs%iface))]))//' bucket sorts ('// &
               str(sum([(sum(cs%iface(i)%pass(:)%nskip), i = 1, size(cs%iface))]))// &
               ' more skipped: no candidate possible), wall time search '// &
               rstr(cs%t_search, 4)//' s, local search + forces '// &
               rstr(cs%t_force - cs%t_search, 4)//' s, candidates per slave node '// &
               rstr(real(ncand, wp)/real(max(1, nslave), wp), 4)//', sliding energy '// &
               rstr(model%energy%sliding, 6))
            if (cs%rcforc_open) close(cs%rcforc_unit)
            cs%rcforc_open = .false.
         end if
      end associate
   end subroutine contact_work

   !> rcforc: one line per interface: time, id, resultant force on the slave side and on
   !> the master side (x y z), slave nodes in contact.
   subroutine write_rcforc(cs, t, outdir, error)
      type(contact_set_t), intent(inout) :: cs
      real(wp), intent(in) :: t
      character(*), intent(in) :: outdir
      type(error_t), allocatable, intent(out) :: error
      integer :: ios, i
      character(256) :: msg
      if (.not. cs%rcforc_open .and. cs%rcforc_resume > 0) then
         ! continued run (dx_contact_restart): cut back to the dump point and append
         call append_from(outdir//'/rcforc', cs%rcforc_resume, cs%rcforc_unit, error)
         if (allocated(error)) return
         cs%rcforc_open = .true.
      end if
      if (.not. cs%rcforc_open) then
         open(newunit=cs%rcforc_unit, file=outdir//'/rcforc', status='replace', &
              action='write', form='formatted', iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call set_error(error, 'cannot open '//outdir//'/rcforc for writing: '//trim(msg), &
                           EXIT_IO)
            return
         end if
         cs%rcforc_open = .true.
         write(cs%rcforc_unit, '(a)', iostat=ios) '# dynx rcforc', &
            '# resultant contact forces per interface (slave side, master side)', &
            'time contact_id slave_x slave_y slave_z master_x master_y master_z nactive'
      end if
      do i = 1, size(cs%iface)
         write(cs%rcforc_unit, '(es18.10e3, 1x, i10, 6(1x, es18.10e3), 1x, i10)', &
               iostat=ios, iomsg=msg) t, cs%iface(i)%label, cs%iface(i)%fslave, &
               cs%iface(i)%fmaster, cs%iface(i)%nactive
         if (ios /= 0) exit
      end do
      if (ios == 0) flush(cs%rcforc_unit, iostat=ios, iomsg=msg)
      if (ios /= 0) call set_error(error, 'cannot write '//outdir//'/rcforc: '//trim(msg), &
                                   EXIT_IO)
   end subroutine write_rcforc
end module dx_contact
