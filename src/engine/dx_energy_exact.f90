!> The energies of an output event (glstat, matsum, ENDENG and the end of the run) as exact
!> sums (dx_repro_sum: the long accumulator, rounded once), the same procedures in a serial
!> run and on every rank of an MPI run: each term is formed by the same code from the same
!> numbers wherever it is formed, and the sums are exact, so the result does not depend on
!> which rank adds which term or in what order: serial = NP 2 = 3 = 4 bit for bit without
!> gathering anything (docs/history.md, "Reproducible sums"). A rank adds the nodal terms
!> of the nodes it owns and the terms of its elements (each element on one rank), then one
!> rs_reduce (one int64 MPI_Allreduce) gives every rank every sum.
!> Terms (energy balance: Hallquist, DYNA3D User's Manual UCRL-MA-107254; Belytschko, Liu &
!> Moran 2000, section 6.2.3): the time-centred kinetic energy 1/2 sum m v(n-1/2).v(n+1/2)
!> (+ 1/2 I w(n-1/2).w(n+1/2) on shell nodes), the element internal and hourglass energies,
!> the element work still to be booked (weighted by dfac), the momentum sum m v(n+1/2).
!> Erosion: the internal energy of the eroded elements and the kinetic energy of the nodes
!> that some element holds and no living element does (corner_counts: under MPI the counts
!> of a shared node are summed over the ranks by the fixed-order slot exchange).
!> Per part (*DATABASE_MATSUM): internal, hourglass and pending work of the part's elements;
!> kinetic energy and momentum element by element, each corner weighted by the element's
!> share of the lumped mass, (rho V0 + added mass) times the family's nodal share (the
!> terms the lumped mass is the sum of), so the parts add up to glstat's totals to
!> round-off, and each element's terms are formed on the one rank that holds it.
module dx_energy_exact
   use dx_kinds, only: wp
   use dx_model, only: model_t, ES_WORK, WORK_PN, WORK_QBV, family_t, element_family
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_value, rs_count, rs_reduce, rs_add_sum
   use dx_energy_sums, only: set_energy
   implicit none
   private
   public :: energy_nsums, energy_terms, energy_values, corner_counts, held_status, &
             exact_mass, exact_initial_ke, work_nsums, work_hit, work_values, added_mass_sums

   !> The sums of an event: kinetic (halved at the end), internal, hourglass, pending
   !> element work, momentum x y z, eroded internal and kinetic; then PS_N per part.
   integer, parameter :: S_KE = 1, S_IE = 2, S_HG = 3, S_PEND = 4, S_MOM = 5, S_EIE = 8, &
                         S_EKE = 9, S_N = 9
   integer, parameter :: P_IE = 1, P_HG = 2, P_PEND = 3, P_KE = 4, P_MOM = 5, P_EIE = 8, &
                         P_EKE = 9, PS_N = 9

contains

   !> The number of sums (the same on every rank): with matsum, PS_N per part too (parts:
   !> whether this event writes matsum, default .true.; .false.: the totals only, as on the
   !> cycles that glstat or ENDENG alone need).
   integer function energy_nsums(model, parts)
      type(model_t), intent(in) :: model
      logical, intent(in), optional :: parts
      energy_nsums = S_N
      if (present(parts)) then
         if (.not. parts) return
      end if
      if (model%db%matsum_dt > 0.0_wp .and. allocated(model%parts)) &
         energy_nsums = S_N + PS_N*size(model%parts)
   end function energy_nsums

   !> The element corners at each node (all, and those of living elements): erosion.
   subroutine corner_counts(model, alive, all)
      type(model_t), intent(in) :: model
      real(wp), allocatable, intent(out) :: alive(:), all(:)
      type(family_t) :: fam
      integer :: b, i, k, nd
      allocate(alive(size(model%mass)), all(size(model%mass)))
      alive = 0.0_wp
      all = 0.0_wp
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            fam = element_family(blk%etype)
            do i = 1, blk%nel
               do k = 1, fam%nen
                  nd = blk%conn(k, i)
                  all(nd) = all(nd) + 1.0_wp
                  if (.not. blk%failed(i)) alive(nd) = alive(nd) + 1.0_wp
               end do
            end do
         end associate
      end do
   end subroutine corner_counts

   !> 0: no element holds the node, 1: eroded elements only, 2: a living element.
   function held_status(alive, all) result(held)
      real(wp), intent(in) :: alive(:), all(:)
      integer(1), allocatable :: held(:)
      allocate(held(size(all)))
      held = 0_1
      where (all > 0.0_wp) held = 1_1
      where (alive > 0.0_wp) held = 2_1
   end function held_status

   !> This rank's terms of the event into rs (allocated here, energy_nsums sums). nodes: the
   !> nodes whose nodal terms are added here (absent: every node, a serial run); an element
   !> corner k > nreal is slot k - nreal of local node slot(k - nreal) (MPI sub-model; a
   !> serial run passes nreal = nn). wold: shells' w(n-1/2); held (erosion): held_status;
   !> racc (rigid bodies): the cycle's rigid nodal terms (dx_rigid_exact), which the
   !> bodies' own replace. parts: the parts' sums too (energy_nsums; default .true.).
   subroutine energy_terms(model, vold, nreal, slot, rs, nodes, wold, held, racc, parts)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: vold(:, :)
      integer, intent(in) :: nreal, slot(:)
      type(rsum_t), intent(inout) :: rs
      integer, intent(in), optional :: nodes(:)
      real(wp), intent(in), optional :: wold(:, :)
      integer(1), intent(in), optional :: held(:)
      type(rsum_t), intent(in), optional :: racc
      logical, intent(in), optional :: parts
      integer :: j
      call rs_init(rs, energy_nsums(model, parts))
      if (present(racc)) then
         call rs_add_sum(rs, S_KE, racc, 1)
         do j = 1, 3
            call rs_add_sum(rs, S_MOM + j - 1, racc, 1 + j)
         end do
      end if
      do j = 1, node_count(model, nodes)
         call node_terms(node_at(j, nodes))
      end do
      call element_terms(model, vold, nreal, slot, rs, held)
   contains
      subroutine node_terms(nd)
         integer, intent(in) :: nd
         real(wp) :: m, dv
         integer :: d
         m = model%mass(nd)
         dv = m*dot_product(vold(:, nd), model%v(:, nd))
         call rs_add(rs, S_KE, dv)
         if (present(wold)) &
            call rs_add(rs, S_KE, model%rinert(nd)*dot_product(wold(:, nd), model%w(:, nd)))
         do d = 1, 3
            call rs_add(rs, S_MOM + d - 1, m*model%v(d, nd))
         end do
         if (present(held)) then
            if (held(nd) == 1_1) call rs_add(rs, S_EKE, dv)
         end if
      end subroutine node_terms
   end subroutine energy_terms

   !> The element terms (each element on one rank) and, with matsum, the parts' terms.
   subroutine element_terms(model, vold, nreal, slot, rs, held)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: vold(:, :)
      integer, intent(in) :: nreal, slot(:)
      type(rsum_t), intent(inout) :: rs
      integer(1), intent(in), optional :: held(:)
      type(family_t) :: fam
      real(wp) :: pend, me, dv, rho
      integer :: b, i, k, nd, w, p0, d
      logical :: parts, added
      parts = rs_count(rs) > S_N
      added = allocated(model%added_mass) .and. model%ctrl%dt2ms /= 0.0_wp
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            fam = element_family(blk%etype)
            w = blk%esc(ES_WORK)
            p0 = S_N + PS_N*(blk%ipart - 1)
            rho = 0.0_wp
            if (parts) rho = model%mats(model%parts(blk%ipart)%imat)%m%ro
            do i = 1, blk%nel
               call rs_add(rs, S_IE, blk%eint(i))
               call rs_add(rs, S_HG, blk%ehg(i))
               pend = 0.0_wp
               if (w > 0) then
                  pend = merge(0.0_wp, 1.0_wp, blk%failed(i))* &
                         (blk%es(i, w + WORK_PN) - blk%es(i, w + WORK_QBV))
                  call rs_add(rs, S_PEND, pend)
               end if
               if (present(held)) then
                  if (blk%failed(i)) call rs_add(rs, S_EIE, blk%eint(i))
               end if
               if (.not. parts) cycle
               call rs_add(rs, p0 + P_IE, blk%eint(i))
               call rs_add(rs, p0 + P_HG, blk%ehg(i))
               if (w > 0) call rs_add(rs, p0 + P_PEND, pend)
               if (present(held)) then
                  if (blk%failed(i)) call rs_add(rs, p0 + P_EIE, blk%eint(i))
               end if
               me = rho*blk%vol0(i)
               if (added) me = me + model%added_mass(blk%elem(i))
               me = me*fam%mass_share
               do k = 1, fam%nen
                  nd = blk%conn(k, i)
                  if (nd > nreal) nd = slot(nd - nreal)
                  dv = me*dot_product(vold(:, nd), model%v(:, nd))
                  call rs_add(rs, p0 + P_KE, dv)
                  do d = 1, 3
                     call rs_add(rs, p0 + P_MOM + d - 1, me*model%v(d, nd))
                  end do
                  if (present(held)) then
                     if (held(nd) == 1_1) call rs_add(rs, p0 + P_EKE, dv)
                  end if
               end do
            end do
         end associate
      end do
   end subroutine element_terms

   !> The event's energies from the summed (reduced) rs into model%energy (set_energy: the
   !> total, the ratio, the momentum with the rigid bodies' correction), the eroded
   !> energies with erosion, and the parts' sums into psm%psum when it is allocated (the
   !> serial model, or rank 0's global model that writes matsum). dfac weighs the pending
   !> element work; wext the external work, erw the rigid-wall energy.
   subroutine energy_values(model, rs, dfac, wext, erw, psm)
      type(model_t), intent(inout) :: model
      type(rsum_t), intent(in) :: rs
      real(wp), intent(in) :: dfac, wext, erw
      type(model_t), intent(inout), optional :: psm
      real(wp) :: ke, eint, mom(3)
      integer :: p, p0, d
      ke = 0.5_wp*rs_value(rs, S_KE)
      mom = [(rs_value(rs, S_MOM + d - 1), d = 1, 3)]
      if (allocated(model%rigid)) then    ! the bodies' own (their nodes' are out: racc)
         ke = ke + model%rigid%ke_body
         mom = mom + model%rigid%p_body
      end if
      eint = rs_value(rs, S_IE) + dfac*rs_value(rs, S_PEND)
      call set_energy(model, ke, eint, rs_value(rs, S_HG), wext, erw, mom)
      if (model%erodes) then
         model%energy%eroded_ie = rs_value(rs, S_EIE)
         model%energy%eroded_ke = 0.5_wp*rs_value(rs, S_EKE)
      end if
      if (.not. present(psm) .or. rs_count(rs) == S_N) return
      associate (ps => psm%psum)
         if (.not. allocated(ps%ie)) return
         do p = 1, size(ps%ie)
            p0 = S_N + PS_N*(p - 1)
            ps%ie(p) = rs_value(rs, p0 + P_IE) + dfac*rs_value(rs, p0 + P_PEND)
            ps%hge(p) = rs_value(rs, p0 + P_HG)
            ps%ke(p) = 0.5_wp*rs_value(rs, p0 + P_KE)
            do d = 1, 3
               ps%mom(d, p) = rs_value(rs, p0 + P_MOM + d - 1)
            end do
            if (model%erodes) then
               ps%eie(p) = rs_value(rs, p0 + P_EIE)
               ps%eke(p) = 0.5_wp*rs_value(rs, p0 + P_EKE)
            end if
         end do
      end associate
   end subroutine energy_values

   !> Sums per cycle of the constraint and rigid-wall work (work_hit, work_values): the
   !> constraint work (translations and rotations), the rigid-wall work, then each wall's
   !> resultant force (3 each). nw: the deck's number of walls.
   integer function work_nsums(nw)
      integer, intent(in) :: nw
      work_nsums = 2 + 3*nw
   end function work_nsums

   !> One rigid-wall hit (dx_constraints wall_hits_t: val(1) the work term, val(2:4) m
   !> dv/dtavg) of wall w into the cycle's sums from c0 + 1.
   subroutine work_hit(rs, c0, w, val)
      type(rsum_t), intent(inout) :: rs
      integer, intent(in) :: c0, w
      real(wp), intent(in) :: val(4)
      integer :: d
      call rs_add(rs, c0 + 2, val(1))
      do d = 1, 3
         call rs_add(rs, c0 + 2 + 3*(w - 1) + d, -val(1 + d))
      end do
   end subroutine work_hit

   !> A cycle's sums (from c0 + 1, summed over the ranks) into the running work sums, each
   !> cycle's exact sum rounded once and added in cycle order (serial = MPI, any NP); the
   !> walls' resultant forces become this cycle's (forces: the walls, when the deck has
   !> them; the rigid-wall work is only added then).
   subroutine work_values(rs, c0, nw, wcon, wrw, forces)
      type(rsum_t), intent(in) :: rs
      integer, intent(in) :: c0, nw
      real(wp), intent(inout) :: wcon, wrw
      real(wp), intent(inout), optional :: forces(:, :)
      integer :: w, d
      wcon = wcon + rs_value(rs, c0 + 1)
      if (nw == 0) return
      wrw = wrw + rs_value(rs, c0 + 2)
      if (.not. present(forces)) return
      do w = 1, nw
         do d = 1, 3
            forces(d, w) = rs_value(rs, c0 + 2 + 3*(w - 1) + d)
         end do
      end do
   end subroutine work_values

   !> Mass scaling (DT2MS): the added mass of the model and of each part, exact sums of the
   !> elements' added masses (model%added_mass by dense element) over the blocks (a rank:
   !> its elements; reduce = .true. sums over the ranks, collective), into
   !> model%energy%added_mass and, where allocated, psm%psum%added (matsum's +mass).
   subroutine added_mass_sums(model, reduce, psm)
      type(model_t), intent(inout) :: model
      logical, intent(in) :: reduce
      type(model_t), intent(inout), optional :: psm
      type(rsum_t) :: rs
      integer :: b, i, p, np
      np = 0
      if (allocated(model%parts)) np = size(model%parts)
      call rs_init(rs, 1 + np)
      if (allocated(model%added_mass)) then
         do b = 1, size(model%blocks)
            associate (blk => model%blocks(b))
               do i = 1, blk%nel
                  call rs_add(rs, 1, model%added_mass(blk%elem(i)))
                  call rs_add(rs, 1 + blk%ipart, model%added_mass(blk%elem(i)))
               end do
            end associate
         end do
      end if
      if (reduce) call rs_reduce(rs)
      model%energy%added_mass = rs_value(rs, 1)
      if (.not. present(psm)) return
      if (.not. allocated(psm%psum%added)) return
      do p = 1, min(np, size(psm%psum%added))
         psm%psum%added(p) = rs_value(rs, 1 + p)
      end do
   end subroutine added_mass_sums

   !> The total nodal mass, an exact sum over the nodes (absent: every node; MPI: the
   !> owned nodes, and reduce = .true. sums over the ranks: collective).
   real(wp) function exact_mass(model, nodes, reduce) result(m)
      type(model_t), intent(in) :: model
      integer, intent(in), optional :: nodes(:)
      logical, intent(in), optional :: reduce
      type(rsum_t) :: rs
      integer :: j
      call rs_init(rs, 1)
      do j = 1, node_count(model, nodes)
         call rs_add(rs, 1, model%mass(node_at(j, nodes)))
      end do
      call reduce_if(rs, reduce)
      m = rs_value(rs, 1)
   end function exact_mass

   !> The initial kinetic energy 1/2 sum m v.v (+ 1/2 I w.w on shell nodes), an exact sum
   !> over the nodes (as exact_mass).
   real(wp) function exact_initial_ke(model, nodes, reduce) result(e0)
      type(model_t), intent(in) :: model
      integer, intent(in), optional :: nodes(:)
      logical, intent(in), optional :: reduce
      type(rsum_t) :: rs
      integer :: j
      call rs_init(rs, 1)
      do j = 1, node_count(model, nodes)
         call node_term(node_at(j, nodes))
      end do
      call reduce_if(rs, reduce)
      e0 = 0.5_wp*rs_value(rs, 1)
   contains
      subroutine node_term(nd)
         integer, intent(in) :: nd
         call rs_add(rs, 1, model%mass(nd)*dot_product(model%v(:, nd), model%v(:, nd)))
         if (allocated(model%w) .and. allocated(model%rinert)) &
            call rs_add(rs, 1, model%rinert(nd)*dot_product(model%w(:, nd), model%w(:, nd)))
      end subroutine node_term
   end function exact_initial_ke

   ! ----------------------------------------------------------------------------------------
   ! the node list of the owned-node sums: the given nodes, or every node when absent

   !> The number of nodes in the list.
   pure integer function node_count(model, nodes)
      type(model_t), intent(in) :: model
      integer, intent(in), optional :: nodes(:)
      if (present(nodes)) then
         node_count = size(nodes)
      else
         node_count = size(model%mass)
      end if
   end function node_count

   !> The j-th node of the list.
   pure integer function node_at(j, nodes)
      integer, intent(in) :: j
      integer, intent(in), optional :: nodes(:)
      node_at = j
      if (present(nodes)) node_at = nodes(j)
   end function node_at

   !> rs summed over the ranks when reduce is present and true (collective).
   subroutine reduce_if(rs, reduce)
      type(rsum_t), intent(inout) :: rs
      logical, intent(in), optional :: reduce
      if (.not. present(reduce)) return
      if (reduce) call rs_reduce(rs)
   end subroutine reduce_if
end module dx_energy_exact
