!> Ghost sorts of MPI contact, owner-computes (issue 22; docs/history.md, "Parallel contact"):
!> at a bucket sort a rank needs the current x, v only of the segments within the search
!> reach of its own slave nodes (and of the segments they are in contact with), not of every
!> contact node (before: one MPI_Allgatherv of x, v of all contact nodes at every sort).
!>  - Every segment (master and slave surface) has one sending rank, fixed at the start: the
!>    lowest rank holding all its nodes (a face of one of its elements). A deck with a
!>    segment no rank holds whole, or with rigid bodies in contact, keeps the full gather.
!>  - At a sort every rank sends, per sorting pass, the box of its slave nodes and the
!>    extent of each segment it sends (one MPI_Allgatherv of 6 numbers per pass and one per
!>    such segment). Every rank then sums the extents in segment order, exactly as the
!>    serial mean_extent does (the same bits), so the search margin is the serial one.
!>  - Each rank sends every other rank the nodes of its segments whose box, grown by the
!>    reach (margin + largest depth + shell offset, with room to spare), meets that rank's
!>    box, the segments its slave nodes are in contact with, and the halo of the last sort
!>    (for the passes not sorting now): counts by MPI_Alltoall, data point to point with the
!>    ranks that have something (MPI_Isend/Irecv). A segment whose grown box misses a rank's
!>    box cannot hold any of its slave nodes, i.e. cannot be a candidate there (the bucket
!>    sort's test is that grown box), so each rank's candidates are the serial ones; the
!>    bucket sort takes only the segments whose nodes arrived (p%segok).
!> Spatial decomposition with ghost exchange by bounding-box overlap: Plimpton, Attaway,
!> Hendrickson, Swegle, Vaughan & Gardner 1998, "Parallel transient dynamics simulations:
!> algorithms for contact detection and smoothed particle hydrodynamics", J. Parallel
!> Distrib. Comput. 50:104-122; ParaDyn strips: Hoover et al. 1997 (article 4 of
!> shared/seed).
module dx_par_contact_ghost
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_contact_search, only: segment_box
   use dx_contact, only: idle_sort
   use dx_par, only: par_rank, par_size, par_allreduce, PAR_MIN, PAR_MAX, par_alltoallv, &
                     par_allgatherv_real, par_sparse_exchange
   implicit none
   private
   public :: contact_ghost_t, ghost_setup, ghost_sort, ghost_drop, idle_reduce

   type :: contact_ghost_t
      logical :: on = .false.
      integer, allocatable :: e0(:), f0(:)    !< (npass) offsets of a pass's segments and
                                              !< slave segments in srank
      integer, allocatable :: srank(:)        !< the rank sending each segment
      integer, allocatable :: own_of(:)       !< (nn) owner of a contact node (-1: none)
      integer, allocatable :: stamp(:)        !< (nn) the ghost sort that brought x, v
      integer, allocatable :: mark(:)         !< (nn) work array: node listed for rank mark
      integer :: nstamp = 0
      integer :: nsort = 0                    !< ghost sorts done
      !> a coarse grid over the contact nodes at the start: at a sort each rank sends which
      !> cells hold its slave nodes (a bit each); a segment goes to a rank when its grown
      !> box covers one of them (nodes outside the grid count in its border cells)
      real(wp) :: glo(3) = 0.0_wp, gh = 1.0_wp
      integer :: gn(3) = 1
   end type contact_ghost_t

   integer, parameter :: NBIT = 48            !< cell bits per real sent (exact in a double)

contains

   !> Start of the run: the sending rank of every segment (an MPI_Allreduce over all
   !> segments, once). loc_of: global node -> local index on this rank (0: not held).
   subroutine ghost_setup(gh, g, loc_of, c_all, c_owner)
      type(contact_ghost_t), intent(inout) :: gh
      type(model_t), intent(in) :: g
      integer, intent(in) :: loc_of(:), c_all(:), c_owner(:)
      integer :: i, j, ip, n, s, np, me
      np = par_size()
      me = par_rank()
      associate (cs => g%contact)
         if (allocated(g%rigid)) then
            if (allocated(g%rigid%node_body)) then
               if (any(g%rigid%node_body(cs%node) > 0)) return   ! body inertia: all x
            end if
         end if
         n = sum([(size(cs%iface(i)%pass), i = 1, size(cs%iface))])
         allocate(gh%e0(n), gh%f0(n))
         n = 0
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               gh%e0(ip) = n
               n = n + cs%iface(i)%pass(j)%nseg
               gh%f0(ip) = n
               n = n + cs%iface(i)%pass(j)%nsseg
            end do
         end do
         allocate(gh%srank(n))
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               associate (p => cs%iface(i)%pass(j))
                  do s = 1, p%nseg
                     gh%srank(gh%e0(ip) + s) = merge(me, np, all(loc_of(p%seg(1:p%nsn(s), s)) > 0))
                  end do
                  do s = 1, p%nsseg
                     gh%srank(gh%f0(ip) + s) = merge(me, np, all(loc_of(p%sseg(1:p%ssn(s), s)) > 0))
                  end do
               end associate
            end do
         end do
      end associate
      if (size(gh%srank) > 0) call par_allreduce(gh%srank, PAR_MIN)
      if (any(gh%srank == np)) then       ! a segment no rank holds whole: the full gather
         deallocate(gh%srank, gh%e0, gh%f0)
         return
      end if
      block
         real(wp) :: lo(3), hi(3), ext(3)
         lo = huge(1.0_wp); hi = -huge(1.0_wp)
         do i = 1, size(c_all)
            lo = min(lo, g%x(:, c_all(i)))
            hi = max(hi, g%x(:, c_all(i)))
         end do
         if (size(c_all) == 0) then
            lo = 0.0_wp; hi = 0.0_wp
         end if
         ext = hi - lo
         gh%gh = max(maxval(ext)/64.0_wp, (product(max(ext, maxval(ext)/64.0_wp))/ &
                                           32768.0_wp)**(1.0_wp/3.0_wp), tiny(1.0_wp))
         gh%gn = max(1, min(64, int(ext/gh%gh) + 1))
         gh%glo = lo
      end block
      allocate(gh%own_of(g%nn), gh%stamp(g%nn), gh%mark(g%nn))
      gh%own_of = -1
      gh%own_of(c_all) = c_owner
      gh%stamp = 0
      gh%mark = -1
      gh%on = .true.
   end subroutine ghost_setup

   !> A full gather replaced the ghosts (first stage, restart): every pass takes all segments.
   subroutine ghost_drop(g)
      type(model_t), intent(inout) :: g
      integer :: i, j
      do i = 1, size(g%contact%iface)
         do j = 1, size(g%contact%iface(i)%pass)
            if (allocated(g%contact%iface(i)%pass(j)%segok)) &
               deallocate(g%contact%iface(i)%pass(j)%segok)
         end do
      end do
   end subroutine ghost_drop

   !> A sort cycle: x, v of this rank's held contact nodes (held, global ids) are in g
   !> already; the ghosts of the sorting passes and the last sort's halo (hs_glob, hs_cnt:
   !> global nodes to send to each rank) arrive from the other ranks. Sets p%mext and
   !> p%segok of every sorting pass. nsent/nrecv: numbers sent / received (counted up).
   !> idle: every sorting pass will skip its sort (dx_contact idle_sort, decided from the
   !> margin of the serial bits, so on every rank alike): no ghost is sent, and the caller
   !> brings the last sort's halo (the candidates and contact segments stay).
   subroutine ghost_sort(gh, g, held, hs_glob, hs_cnt, vmax, dt_est, nsent, nrecv, idle)
      type(contact_ghost_t), intent(inout) :: gh
      type(model_t), intent(inout) :: g
      integer, intent(in) :: held(:), hs_glob(:), hs_cnt(0:)
      real(wp), intent(in) :: vmax, dt_est
      integer(8), intent(inout) :: nsent, nrecv
      logical, intent(out) :: idle
      real(wp), allocatable :: sb(:), rb(:), box(:, :, :), ext(:), reach(:)
      logical, allocatable :: occ(:, :)
      integer :: nw, nc, jlo(3), jhi(3)
      integer(int64) :: w
      integer, allocatable :: cnt(:), d(:), lst(:), scnt(:), rcnt(:), one(:)
      real(wp) :: lo(3), hi(3), e
      integer :: i, j, k, ip, iq, nd, nx, s, r, np, me, st, m, pos, nl, h0
      logical, allocatable :: due(:)
      logical :: rigid_or_erodes
      np = par_size()
      me = par_rank()
      idle = .true.
      rigid_or_erodes = allocated(g%rigid)
      if (rigid_or_erodes) rigid_or_erodes = allocated(g%rigid%node_body)
      rigid_or_erodes = rigid_or_erodes .or. g%erodes
      gh%nstamp = gh%nstamp + 1
      st = gh%nstamp
      gh%stamp(held) = st
      associate (cs => g%contact)
         ! ---- the sorting passes, their boxes of this rank's slave nodes, the extents of
         !      the segments this rank sends
         allocate(due(size(gh%e0)))
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               due(ip) = cs%iface(i)%pass(j)%sort_due .and. g%time >= cs%iface(i)%bt .and. &
                         g%time <= cs%iface(i)%dt
            end do
         end do
         nd = count(due)
         nx = 0
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               if (due(ip)) nx = nx + count(gh%srank(gh%e0(ip) + 1:gh%e0(ip) + &
                                                      cs%iface(i)%pass(j)%nseg) == me)
            end do
         end do
         nc = product(gh%gn)
         nw = (nc + NBIT - 1)/NBIT
         allocate(sb(6*nd + nw + nx), occ(nc, 0:np - 1))
         occ = .false.
         m = 0
         ip = 0
         iq = 6*nd + nw
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               if (.not. due(ip)) cycle
               associate (p => cs%iface(i)%pass(j))
                  lo = huge(1.0_wp); hi = -huge(1.0_wp)
                  do k = 1, p%nnode
                     if (.not. cs%mine_node(p%node(k))) cycle
                     lo = min(lo, g%x(:, p%node(k)))
                     hi = max(hi, g%x(:, p%node(k)))
                     call cells(g%x(:, p%node(k)), g%x(:, p%node(k)), jlo, jhi)
                     occ(cell(jlo), me) = .true.
                  end do
                  sb(m + 1:m + 3) = lo
                  sb(m + 4:m + 6) = hi
                  m = m + 6
                  do s = 1, p%nseg
                     if (gh%srank(gh%e0(ip) + s) /= me) cycle
                     call segment_box(p, g%x, s, lo, hi)
                     iq = iq + 1
                     sb(iq) = maxval(hi - lo)
                  end do
               end associate
            end do
         end do
         do k = 1, nw                ! the occupied cells, NBIT to a number
            e = 0.0_wp
            do s = min(nc, k*NBIT), (k - 1)*NBIT + 1, -1
               e = 2.0_wp*e
               if (occ(s, me)) e = e + 1.0_wp
            end do
            sb(6*nd + k) = e
         end do
         call par_allgatherv_real(sb, rb, cnt=cnt)
         nsent = nsent + size(sb)*(np - 1)
         nrecv = nrecv + size(rb) - size(sb)
         allocate(d(0:np - 1), box(6, nd, 0:np - 1), reach(nd))
         d(0) = 0
         do r = 1, np - 1
            d(r) = d(r - 1) + cnt(r - 1)
         end do
         do r = 0, np - 1
            box(:, :, r) = reshape(rb(d(r) + 1:d(r) + 6*nd), [6, nd])
            do k = 1, nw
               w = int(rb(d(r) + 6*nd + k), int64)
               do s = (k - 1)*NBIT + 1, min(nc, k*NBIT)
                  occ(s, r) = btest(w, s - (k - 1)*NBIT - 1)
               end do
            end do
            d(r) = d(r) + 6*nd + nw      ! next: rank r's extents
         end do
         ! ---- the mean extent of each sorting pass in segment order (mean_extent's sum)
         ip = 0
         m = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               if (.not. due(ip)) cycle
               m = m + 1
               associate (p => cs%iface(i)%pass(j))
                  if (allocated(ext)) deallocate(ext)
                  allocate(ext(p%nseg))
                  do s = 1, p%nseg
                     r = gh%srank(gh%e0(ip) + s)
                     d(r) = d(r) + 1
                     ext(s) = rb(d(r))
                  end do
                  e = 0.0_wp
                  do s = 1, p%nseg
                     e = e + ext(s)
                  end do
                  p%mext = e/real(max(1, p%nseg), wp)
                  ! the reach of a candidate (dx_contact: margin = max(mext/4, 4 vmax
                  ! dt_est), grown by depth and shell offset), with room to spare
                  e = max(0.25_wp*p%mext, 4.0_wp*vmax*dt_est)
                  if (p%nseg > 0) e = e + maxval(p%depth(1:p%nseg))
                  if (p%shells) e = e + p%noffmax
                  reach(m) = 1.25_wp*e
                  ! (contact_search_nodes: the same margin, rigid bodies and erosion)
                  if (.not. idle_sort(p, max(0.25_wp*p%mext, 4.0_wp*vmax*dt_est), &
                                      rigid_or_erodes)) idle = .false.
               end associate
            end do
         end do
         if (idle) return
         gh%nsort = gh%nsort + 1
         ! ---- the nodes each other rank gets: the halo of the last sort, then the
         !      segments within reach of its boxes and those its slave nodes touch
         allocate(lst(max(64, size(hs_glob))), scnt(0:np - 1), rcnt(0:np - 1))
         scnt = 0
         h0 = 0
         nl = 0
         do r = 0, np - 1
            pos = nl
            if (r /= me) then
               do k = h0 + 1, h0 + hs_cnt(r)
                  call add_node(hs_glob(k))
               end do
               ip = 0
               m = 0
               do i = 1, size(cs%iface)
                  do j = 1, size(cs%iface(i)%pass)
                     ip = ip + 1
                     if (.not. due(ip)) cycle
                     m = m + 1
                     associate (p => cs%iface(i)%pass(j))
                        if (any(box(1:3, m, r) > box(4:6, m, r))) cycle   ! no slave node
                        do s = 1, p%nseg
                           if (gh%srank(gh%e0(ip) + s) /= me) cycle
                           call segment_box(p, g%x, s, lo, hi)
                           if (near(lo - reach(m), hi + reach(m), m, r)) &
                              call add_seg(p%seg(1:p%nsn(s), s))
                        end do
                        do s = 1, p%nsseg
                           if (gh%srank(gh%f0(ip) + s) /= me) cycle
                           lo = g%x(:, p%sseg(1, s)); hi = lo
                           do k = 2, p%ssn(s)
                              lo = min(lo, g%x(:, p%sseg(k, s)))
                              hi = max(hi, g%x(:, p%sseg(k, s)))
                           end do
                           if (near(lo - reach(m), hi + reach(m), m, r)) &
                              call add_seg(p%sseg(1:p%ssn(s), s))
                        end do
                        do k = 1, p%nnode
                           s = p%iseg(k)
                           if (s == 0) cycle
                           if (gh%own_of(p%node(k)) /= r .or. gh%srank(gh%e0(ip) + s) /= me) cycle
                           call add_seg(p%seg(1:p%nsn(s), s))
                        end do
                     end associate
                  end do
               end do
            end if
            h0 = h0 + hs_cnt(r)
            scnt(r) = nl - pos
            gh%mark(lst(pos + 1:nl)) = -1    ! (unmarked for the next rank)
         end do
         allocate(one(0:np - 1))
         one = 1
         call par_alltoallv(scnt, one, rcnt, one)
         deallocate(sb, rb)
         allocate(sb(7*nl), rb(7*sum(rcnt)))
         do k = 1, nl
            sb(7*k - 6) = real(lst(k), wp)
            sb(7*k - 5:7*k - 3) = g%x(:, lst(k))
            sb(7*k - 2:7*k) = g%v(:, lst(k))
         end do
         call par_sparse_exchange(sb, 7*scnt, rb, 7*rcnt)
         nsent = nsent + size(sb)
         nrecv = nrecv + size(rb)
         do k = 1, sum(rcnt)
            pos = nint(rb(7*k - 6))
            g%x(:, pos) = rb(7*k - 5:7*k - 3)
            g%v(:, pos) = rb(7*k - 2:7*k)
            gh%stamp(pos) = st
         end do
         ! ---- the segments of each sorting pass whose x is current here
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               if (.not. due(ip)) cycle
               associate (p => cs%iface(i)%pass(j))
                  if (allocated(p%segok)) deallocate(p%segok)
                  allocate(p%segok(p%nseg))
                  do s = 1, p%nseg
                     p%segok(s) = all(gh%stamp(p%seg(1:p%nsn(s), s)) == st)
                  end do
               end associate
            end do
         end do
      end associate
   contains
      !> the cells of the coarse grid the box [a, b] covers (clamped to the grid)
      pure subroutine cells(a, b, jl, jh)
         real(wp), intent(in) :: a(3), b(3)
         integer, intent(out) :: jl(3), jh(3)
         jl = min(gh%gn, max(1, int(min(max((a - gh%glo)/gh%gh, -1.0_wp), 1.0e9_wp)) + 1))
         jh = min(gh%gn, max(1, int(min(max((b - gh%glo)/gh%gh, -1.0_wp), 1.0e9_wp)) + 1))
      end subroutine cells
      pure integer function cell(j)
         integer, intent(in) :: j(3)
         cell = j(1) + gh%gn(1)*((j(2) - 1) + gh%gn(2)*(j(3) - 1))
      end function cell
      !> the box [a, b] meets rank r's slave nodes of sorting pass m: its box, then a cell
      !> of the grid that holds one of r's slave nodes
      logical function near(a, b, m, r)
         real(wp), intent(in) :: a(3), b(3)
         integer, intent(in) :: m, r
         integer :: i1, i2, i3, jl(3), jh(3)
         near = all(b >= box(1:3, m, r)) .and. all(a <= box(4:6, m, r))
         if (.not. near) return
         call cells(a, b, jl, jh)
         near = .false.
         do i3 = jl(3), jh(3)
            do i2 = jl(2), jh(2)
               do i1 = jl(1), jh(1)
                  if (occ(cell([i1, i2, i3]), r)) then
                     near = .true.
                     return
                  end if
               end do
            end do
         end do
      end function near
      subroutine add_node(n)
         integer, intent(in) :: n
         integer, allocatable :: tmp(:)
         if (gh%mark(n) == r) return
         gh%mark(n) = r
         if (nl == size(lst)) then
            allocate(tmp(2*nl))
            tmp(1:nl) = lst(1:nl)
            call move_alloc(tmp, lst)
         end if
         nl = nl + 1
         lst(nl) = n
      end subroutine add_node
      subroutine add_seg(nodes)
         integer, intent(in) :: nodes(:)
         integer :: q
         do q = 1, size(nodes)
            call add_node(nodes(q))
         end do
      end subroutine add_seg
   end subroutine ghost_sort

   !> After the bucket sorts of this cycle: each sorted pass's boxes (grown segment boxes,
   !> slave nodes) and candidate count, the ranks' parts reduced by one exact MPI_Allreduce
   !> (MAX of -lo, hi, count: order-free, so the serial bits for any NP), then the serial
   !> test of bucket_sort on the whole pass: no candidate, and the largest gap along an axis
   !> between the two boxes well above the round-off, sets p%clear, which lets a later due
   !> sort be skipped (dx_contact idle_sort) on every rank alike and as in the serial run.
   !> The union of the ranks' sorted segments is every segment (each rank sorts at least
   !> the segments it sends, ghost sorts; or all of them), of their slave nodes every slave
   !> node. Called on every rank at the same cycles (the sorts are decided on replicated
   !> numbers); no message when no pass sorted.
   subroutine idle_reduce(g)
      type(model_t), intent(inout) :: g
      real(wp), allocatable :: b(:)
      real(wp) :: lo(3), hi(3), glo(3), ghi(3), slo(3), shi(3), gap
      integer :: i, j, n
      associate (cs => g%contact)
         n = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               if (cs%iface(i)%pass(j)%sbox_new) n = n + 1
            end do
         end do
         if (n == 0) return
         allocate(b(13*n))
         n = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               associate (p => cs%iface(i)%pass(j))
                  if (.not. p%sbox_new) cycle
                  b(n + 1:n + 3) = -p%sbox(1:3)
                  b(n + 4:n + 6) = p%sbox(4:6)
                  b(n + 7:n + 9) = -p%sbox(7:9)
                  b(n + 10:n + 13) = p%sbox(10:13)
                  n = n + 13
               end associate
            end do
         end do
         call par_allreduce(b, PAR_MAX)
         n = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               associate (p => cs%iface(i)%pass(j))
                  if (.not. p%sbox_new) cycle
                  p%sbox_new = .false.
                  p%cand_none = b(n + 13) == 0.0_wp
                  glo = -b(n + 1:n + 3); ghi = b(n + 4:n + 6)
                  slo = -b(n + 7:n + 9); shi = b(n + 10:n + 12)
                  ! (bucket_sort's test; its lo, hi: the grown boxes' box and the nodes')
                  if (b(n + 13) == 0.0_wp .and. all(glo <= ghi) .and. all(slo <= shi)) then
                     gap = maxval(max(glo - shi, slo - ghi))
                     lo = min(glo, slo); hi = max(ghi, shi)
                     if (gap > 1.0e-9_wp*maxval(max(abs(lo), abs(hi)))) p%clear = gap
                  end if
                  n = n + 13
               end associate
            end do
         end do
      end associate
   end subroutine idle_reduce
end module dx_par_contact_ghost
