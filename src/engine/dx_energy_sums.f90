!> The global sums of the explicit loop (kinetic energy, element energies, constraint work,
!> momentum, energy ratio), each in one procedure. The energies that are reported (glstat,
!> matsum, ENDENG, the end) are exact sums formed by dx_energy_exact on dx_repro_sum, the
!> same in a serial run and on every rank of an MPI run (docs/history.md, "Reproducible
!> sums"); the plain fixed-order sums here serve the serial loop's cycles between them
!> (the energy guard, the status line), the terms (constraint_terms, rot_node_term) both,
!> and the per-part map (part_mass_map: matsum's part masses).
!> Energy balance: Hallquist, DYNA3D User's Manual (UCRL-MA-107254), and Belytschko, Liu &
!> Moran 2000, section 6.2.3 (time-centred kinetic energy, work of constraint reactions).
!> Per-part sums (*DATABASE_MATSUM; LS-DYNA Keyword User's Manual Vol. I, *DATABASE_MATSUM:
!> "part energies" - internal, kinetic, hourglass energy, momentum and rigid-body velocity
!> of each part): a part's internal and hourglass energies are its elements'; a node shared
!> by elements of several parts gives each part the share of its lumped mass that the part's
!> elements put there (rho V0 times the family's nodal share, the very terms the lumped mass
!> is the sum of), so its kinetic energy 1/2 m v.v and momentum m v are split in proportion
!> to mass: the parts' sums add up to glstat's totals to round-off (docs/output-format.md,
!> "matsum"). The reported part sums are dx_energy_exact's (element by element, exact).
module dx_energy_sums
   use dx_kinds, only: wp
   use dx_model, only: model_t, elem_block_t, energy_t, ES_WORK, WORK_PN, WORK_QBV, &
                       family_t, element_family
   use dx_sort, only: sort_index
   use dx_contact_types, only: contact_set_t, REC_FSL, REC_NB
   implicit none
   private
   public :: kinetic_energy, element_energies, constraint_terms, set_energy, &
             constrained_nodes, energy_bits, part_mass_map, interface_work, rot_node_term, &
             rotation_kinetic

contains

   !> Time-centred kinetic energy 1/2 sum_i m_i v_i(n-1/2).v_i(n+1/2), nodes 1..n in order.
   real(wp) function kinetic_energy(n, mass, vold, v) result(ke)
      integer, intent(in) :: n
      real(wp), intent(in) :: mass(:), vold(:, :), v(:, :)
      integer :: i
      ke = 0.0_wp
      do i = 1, n
         ke = ke + mass(i)*dot_product(vold(:, i), v(:, i))
      end do
      ke = 0.5_wp*ke
   end function kinetic_energy

   !> Internal and hourglass energy: per block sum, blocks in order.
   subroutine element_energies(blocks, eint, ehg, epend)
      type(elem_block_t), intent(in) :: blocks(:)
      real(wp), intent(out) :: eint, ehg
      real(wp), intent(out), optional :: epend  !< sum of the work still to be booked (ework 4 - 2)
      integer :: b
      eint = 0.0_wp; ehg = 0.0_wp
      do b = 1, size(blocks)
         eint = eint + sum(blocks(b)%eint)
         ehg = ehg + sum(blocks(b)%ehg)
      end do
      if (present(epend)) then
         epend = 0.0_wp
         do b = 1, size(blocks)
            if (blocks(b)%esc(ES_WORK) == 0) cycle
            epend = epend + block_pending(blocks(b))
         end do
      end if
   end subroutine element_energies

   !> The work of block blk still to be booked (ework 4 - 2), elements in order.
   real(wp) function block_pending(blk) result(pb)
      type(elem_block_t), intent(in) :: blk
      integer :: i, w
      w = blk%esc(ES_WORK)
      pb = 0.0_wp
      do i = 1, blk%nel
         pb = pb + merge(0.0_wp, 1.0_wp, blk%failed(i))* &
                   (blk%es(i, w + WORK_PN) - blk%es(i, w + WORK_QBV))
      end do
   end function block_pending

   !> Each part's share of the lumped nodal masses (model%psum: CSR over parts, nodes
   !> ascending), from the element blocks before the run (an MPI run: on the global model
   !> before its element arrays are freed). Each share is summed over the part's elements in
   !> block order, as the lumped mass itself is. Also allocates the sums.
   subroutine part_mass_map(model)
      type(model_t), intent(inout) :: model
      integer, allocatable :: stamp(:), touched(:), idx(:), node(:)
      real(wp), allocatable :: w(:), m(:)
      type(family_t) :: fam
      real(wp) :: rho
      integer :: np, p, b, i, k, nd, nt, pos
      if (allocated(model%psum%ptr)) return
      np = size(model%parts)
      ! at most one entry per element node: the parts' lists, one after the other
      pos = 0
      do b = 1, size(model%blocks)
         fam = element_family(model%blocks(b)%etype)
         pos = pos + model%blocks(b)%nel*fam%nen
      end do
      allocate(stamp(model%nn), w(model%nn), touched(model%nn), node(pos), m(pos))
      stamp = 0; w = 0.0_wp
      associate (ps => model%psum)
         allocate(ps%ptr(np + 1))
         ps%ptr(1) = 1
         ! each part's distinct nodes and their shares, summed element by element in block order
         do p = 1, np
            nt = 0
            rho = model%mats(model%parts(p)%imat)%m%ro
            do b = 1, size(model%blocks)
               if (model%blocks(b)%ipart /= p) cycle
               fam = element_family(model%blocks(b)%etype)
               do i = 1, model%blocks(b)%nel
                  do k = 1, fam%nen
                     nd = model%blocks(b)%conn(k, i)
                     if (stamp(nd) /= p) then
                        stamp(nd) = p; w(nd) = 0.0_wp
                        nt = nt + 1; touched(nt) = nd
                     end if
                     w(nd) = w(nd) + rho*model%blocks(b)%vol0(i)*fam%mass_share
                  end do
               end do
            end do
            idx = [(i, i = 1, nt)]
            call sort_index(idx, touched(1:nt))
            pos = ps%ptr(p)
            do i = 1, nt
               node(pos + i - 1) = touched(idx(i))
               m(pos + i - 1) = w(touched(idx(i)))
            end do
            ps%ptr(p + 1) = ps%ptr(p) + nt
         end do
         ps%node = node(1:ps%ptr(np + 1) - 1)
         ps%m = m(1:ps%ptr(np + 1) - 1)
         allocate(ps%mass(np), ps%added(np), ps%ie(np), ps%ke(np), ps%hge(np), ps%mom(3, np))
         do p = 1, np
            ps%mass(p) = sum(ps%m(ps%ptr(p):ps%ptr(p + 1) - 1))
         end do
         ps%added = 0.0_wp    ! mass scaling (branch "mass") adds each part's added mass here
         ps%ie = 0.0_wp; ps%ke = 0.0_wp; ps%hge = 0.0_wp; ps%mom = 0.0_wp
         allocate(ps%eie(np), ps%eke(np))
         ps%eie = 0.0_wp; ps%eke = 0.0_wp
      end associate
   end subroutine part_mass_map

   !> Each contact interface's work of this cycle's forces on its slave nodes and on its
   !> master nodes (sleout), with the centred weighting of the total contact work
   !> (dx_contact%contact_work): W += f(n).dtavg (v(n-1/2) + v(n+1/2))/2, interfaces, passes
   !> and slave nodes in order; f on the slave node is its pass force, on the master
   !> segment's nodes -N_j times it. slave + master over the interfaces is the total work
   !> to round-off. hslave/hmaster hold the v(n+1/2) half of this cycle's work, which
   !> sleout leaves out at t(n) as glstat's sliding energy does. An MPI run calls it on the global model after contact_work (every rank
   !> holds every pass's results and the contact nodes' velocities there).
   subroutine interface_work(cs, vold, v, dtavg)
      type(contact_set_t), intent(inout) :: cs
      real(wp), intent(in) :: vold(:, :), v(:, :), dtavg
      real(wp) :: ws, wm, hs, hm, fsl(3)
      integer :: f, j, i, k, sb, n
      do f = 1, size(cs%iface)
         ws = 0.0_wp; wm = 0.0_wp; hs = 0.0_wp; hm = 0.0_wp
         do j = 1, size(cs%iface(f)%pass)
            associate (p => cs%iface(f)%pass(j))
               do i = 1, p%nnode
                  sb = p%iseg(i)
                  if (sb == 0) cycle
                  k = p%node(i)
                  fsl = p%rval(REC_FSL + 1:REC_FSL + 3, i)
                  ws = ws + dot_product(fsl, vold(:, k) + v(:, k))
                  hs = hs + dot_product(fsl, v(:, k))
                  do n = 1, p%nsn(sb)
                     k = p%seg(n, sb)
                     wm = wm - p%rval(REC_NB + n, i)*dot_product(fsl, vold(:, k) + v(:, k))
                     hm = hm - p%rval(REC_NB + n, i)*dot_product(fsl, v(:, k))
                  end do
               end do
            end associate
         end do
         cs%iface(f)%wslave = cs%iface(f)%wslave + 0.5_wp*dtavg*ws
         cs%iface(f)%wmaster = cs%iface(f)%wmaster + 0.5_wp*dtavg*wm
         cs%iface(f)%hslave = 0.5_wp*dtavg*hs
         cs%iface(f)%hmaster = 0.5_wp*dtavg*hm
      end do
   end subroutine interface_work

   !> The term of each constrained node in the constraint work, m (v(n+1/2) - vfree).du/dtavg
   !> with du = dtavg (v(n-1/2) + v(n+1/2))/2 (one node each: serial and MPI runs add the
   !> terms of their (owned) nodes to the cycle's exact sum, dx_energy_exact work_values).
   subroutine constraint_terms(cnodes, mass, vfree, vold, v, dtavg, terms)
      integer, intent(in) :: cnodes(:)
      real(wp), intent(in) :: mass(:), vfree(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: terms(:)
      real(wp) :: du(3)
      integer :: i, nd
      do i = 1, size(cnodes)
         nd = cnodes(i)
         du = 0.5_wp*dtavg*(vold(:, nd) + v(:, nd))
         terms(i) = mass(nd)*dot_product(v(:, nd) - vfree(:, i), du)/dtavg
      end do
   end subroutine constraint_terms

   !> The work of the constraint moments on the rotations of node i (shells): DOFRX/RY/RZ and
   !> the prescribed rotations set w(n+1/2) against the free wf; the term is
   !> I (w - wf).(w(n-1/2) + w)/2 (as constraint_terms for the translations). rot_node_term
   !> is false (no term) where the constraint left the free w; the terms go into the cycle's
   !> exact constraint-work sum (serial: every node; MPI: the owned nodes).
   logical function rot_node_term(rinert, wf, wold, w, term)
      real(wp), intent(in) :: rinert, wf(3), wold(3), w(3)
      real(wp), intent(out) :: term
      term = 0.0_wp
      rot_node_term = any(wf /= w)
      if (rot_node_term) term = 0.5_wp*rinert*dot_product(w - wf, wold + w)
   end function rot_node_term

   !> The rotational kinetic energy 1/2 I w(n-1/2).w(n+1/2) summed in node order (serial,
   !> and rank 0 of an MPI run on the gathered global arrays).
   real(wp) function rotation_kinetic(nn, rinert, wold, w) result(krot)
      integer, intent(in) :: nn
      real(wp), intent(in) :: rinert(:), wold(:, :), w(:, :)
      integer :: i
      krot = 0.0_wp
      do i = 1, nn
         krot = krot + 0.5_wp*rinert(i)*dot_product(wold(:, i), w(:, i))
      end do
   end function rotation_kinetic

   !> Store the energies and momentum of the current step in model%energy (mom: the exact
   !> momentum of energy_values, rigid bodies included; else summed here in node order).
   subroutine set_energy(model, ke, eint, ehg, wext, erw, mom)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: ke, eint, ehg, wext, erw
      real(wp), intent(in), optional :: mom(3)
      real(wp) :: den
      integer :: d
      model%energy%kinetic = ke
      model%energy%internal = eint
      model%energy%hourglass = ehg
      model%energy%external_work = wext
      model%energy%rigidwall = erw
      model%energy%total = ke + eint + ehg
      den = model%energy%initial + wext
      if (abs(den) > 0.0_wp) then
         model%energy%ratio = (model%energy%total + erw + model%energy%sliding)/den
      else
         model%energy%ratio = 1.0_wp
      end if
      if (present(mom)) then     ! (the bodies' momentum included)
         model%energy%momentum = mom
         return
      end if
      do d = 1, 3
         model%energy%momentum(d) = sum(model%mass*model%v(d, :))
      end do
      if (allocated(model%rigid)) model%energy%momentum = model%energy%momentum + &
                                                         model%rigid%p_corr
   end subroutine set_energy

   !> Nodes with an SPC or prescribed motion (their reaction forces do work).
   subroutine constrained_nodes(model, nodes)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: nodes(:)
      logical, allocatable :: mark(:)
      integer :: k
      allocate(mark(model%nn))
      mark = .false.
      if (allocated(model%spcs)) then
         do k = 1, size(model%spcs)
            if (any(model%spcs(k)%dof(1:3))) mark(model%spcs(k)%node) = .true.
         end do
      end if
      if (allocated(model%prescribed)) then
         do k = 1, size(model%prescribed)
            mark(model%prescribed(k)%node) = .true.
         end do
      end if
      nodes = pack([(k, k = 1, model%nn)], mark)
   end subroutine constrained_nodes

   !> The energies and momentum as IEEE-754 bit patterns (hex), for bitwise comparison of
   !> runs (glstat prints 11 digits, which hides differences in the last bits of a sum).
   function energy_bits(e) result(line)
      type(energy_t), intent(in) :: e
      character(:), allocatable :: line
      character(17) :: h
      real(wp) :: v(12)
      integer :: k
      v = [e%kinetic, e%internal, e%hourglass, e%external_work, e%rigidwall, e%sliding, &
           e%total, e%initial, e%ratio, e%momentum]
      line = 'dynx: energy bits (KE IE HG WEXT RW SI TOTAL E0 RATIO PX PY PZ):'
      do k = 1, size(v)
         write(h, '(1x,z16.16)') transfer(v(k), 0_8)
         line = line//h
      end do
   end function energy_bits
end module dx_energy_sums
