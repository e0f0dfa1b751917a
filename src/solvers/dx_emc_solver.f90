!> The energy-momentum conserving solver for free systems of rigid bodies in contact
!> (*CONTROL_IMPLICIT_GENERAL IMFLAG = 1 with *DYNX_CONSERVING_CONTACT).
!> Simo & Wong 1991 (IJNME 31:19-52), momentum form of the midpoint rule, with the incremental
!> rotation by the Cayley transform (Simo & Wong sec. 4; cay(T) = (I - T^/2)^-1 (I + T^/2)):
!>   M (v1 - v0) = dt F,            xc1 = xc0 + dt/2 (v0 + v1),
!>   J W1 = cay(Th)^T J W0 + dt R1^T T,   Th = dt/2 (W0 + W1),   R1 = R0 cay(Th),
!> with F and T (spatial torque about the mid centre) from dx_emc_contact at the mid
!> configuration. Since cay(Th) fixes Th, (W0 + W1) . (J W1 - J W0) = 2 Th . R1^T T: the kinetic
!> energy changes by exactly the work of the torque, and pi = R J W changes by exactly dt T.
!> Each step solves these 6 equations per body by Newton iterations (Jacobian by forward
!> differences, LAPACK dgesv); a step that does not converge stops the run (exit 3) or is
!> halved (*DYNX_CONSERVING_CONTROL NFAIL). Output: emcstat (docs/conserving-contact.md).
!> Round-off (docs/conserving-contact.md, "Round-off"): compensated centres (two-sum; Knuth,
!> TAOCP vol. 2, 4.2.2), cay - I formed without the identity, the momentum form of the
!> velocity update (v1 = v0 + dt F/m, W1 = J^-1 (cay^T J W0 + dt R1^T T)).
!> *CONTROL_IMPLICIT_DYNAMICS damping: the contact's dissipative discrete gradient
!> (dx_emc_contact; Armero & Romero 2001, CMAME 190:2603-2649); the energy it takes is
!> booked (ediss) so that KE + U + ediss = E0. The run (emcstat, plot states, the snapshot
!> for restart dumps): conserving_t in dx_emc_run, stepped by the run driver (dx_solver).
module dx_emc_solver
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_strings, only: str
   use dx_model, only: model_t
   use dx_dense_solve, only: dense_solve
   use dx_emc_types, only: emc_system_t, EMC_LAGRANGE
   use dx_emc_contact, only: emc_find_tunnel
   use dx_emc_contact, only: emc_kin_t, emc_pair_t, emc_select_pairs, emc_contact_forces, &
                             emc_inv3, emc_same_plane, emc_split_t, emc_pairs_pack, &
                             emc_pairs_unpack
   use dx_emc_types, only: EMC_PAIR_NI, EMC_PAIR_NR
   implicit none
   private
   public :: emc_state_t, emc_init_state, emc_try_step, emc_step, emc_energy, emc_momenta, &
             emc_to_model, cayley, newton_report_t
   ! (for dx_emc_run's snapshot of the active pairs)
   public :: emc_pairs_pack, emc_pairs_unpack, EMC_PAIR_NI, EMC_PAIR_NR

   !> compliance of a Lagrange constraint row (residual units: momentum per impulse)
   real(wp), parameter :: LAG_COMPLIANCE = 1.0e-12_wp

   !> the bodies' state at t(n)
   type :: emc_state_t
      integer :: nb = 0
      real(wp), allocatable :: m(:), j(:, :), xc(:, :), v(:, :), r(:, :, :), w(:, :)
      !> low parts of the centres: xc + xcl is the compensated sum of the increments
      !> (Kahan 1965 / Knuth's two-sum), so 1e5 steps of x += dt v do not random-walk by
      !> sqrt(n) ulp(x) (which moved L = xc x p by 2.5e-12 in the dt sweep)
      real(wp), allocatable :: xcl(:, :)
      real(wp) :: upen = 0.0_wp      !< penalty energy stored at t(n)
      real(wp) :: ediss = 0.0_wp     !< energy taken by the algorithmic dissipation to t(n)
      type(emc_pair_t), allocatable :: act(:)   !< pairs in penetration at t(n), with g(n)
   end type emc_state_t

   !> what the last step's Newton did
   type :: newton_report_t
      integer :: iters = 0, npair = 0
      !> tunnelling in the step (dx_emc_contact's emc_find_tunnel): contact definition
      !> (0: none), slave point (index into es%snodes, 0: sphere centre), master facet
      integer :: tun_def = 0, tun_src = 0, tun_facet = 0
      real(wp) :: resid = 0.0_wp
      character(:), allocatable :: msg
   end type newton_report_t

contains

   !> cay(th) = (I - th^/2)^-1 (I + th^/2) = I + 4/(4 + |th|^2) (th^ + th^ th^/2)
   pure function cayley(th) result(c)
      real(wp), intent(in) :: th(3)
      real(wp) :: c(3, 3)
      integer :: i
      c = cayley_m1(th)
      do i = 1, 3
         c(i, i) = c(i, i) + 1.0_wp
      end do
   end function cayley

   !> cay(th) - I, formed without the identity (its entries keep full relative precision)
   pure function cayley_m1(th) result(c)
      real(wp), intent(in) :: th(3)
      real(wp) :: c(3, 3), s(3, 3)
      s = reshape([0.0_wp, th(3), -th(2), -th(3), 0.0_wp, th(1), th(2), -th(1), 0.0_wp], &
                  [3, 3])
      c = 4.0_wp/(4.0_wp + dot_product(th, th))*(s + 0.5_wp*matmul(s, s))
   end function cayley_m1

   !> a + b = s + e exactly (two-sum; Knuth, TAOCP vol. 2, sec. 4.2.2)
   elemental subroutine two_sum(a, b, s, e)
      real(wp), intent(in) :: a, b
      real(wp), intent(out) :: s, e
      real(wp) :: bb
      s = a + b
      bb = s - a
      e = (a - (s - bb)) + (b - bb)
   end subroutine two_sum

   !> The state from the model's rigid bodies (principal frames, spatial omega).
   subroutine emc_init_state(model, st)
      type(model_t), intent(in) :: model
      type(emc_state_t), intent(out) :: st
      integer :: b
      st%nb = size(model%rigid%bodies)
      allocate(st%m(st%nb), st%j(3, st%nb), st%xc(3, st%nb), st%v(3, st%nb), &
               st%r(3, 3, st%nb), st%w(3, st%nb), st%xcl(3, st%nb))
      st%xcl = 0.0_wp
      do b = 1, st%nb
         associate (bd => model%rigid%bodies(b))
            st%m(b) = bd%mass
            st%j(:, b) = bd%ip
            st%xc(:, b) = bd%xc
            st%v(:, b) = bd%vc
            st%r(:, :, b) = bd%rot
            st%w(:, b) = matmul(transpose(bd%rot), bd%omega)
         end associate
      end do
   end subroutine emc_init_state

   !> Kinetic energy of the bodies.
   pure real(wp) function emc_energy(st) result(ke)
      type(emc_state_t), intent(in) :: st
      integer :: b
      ke = 0.0_wp
      do b = 1, st%nb
         ke = ke + 0.5_wp*st%m(b)*dot_product(st%v(:, b), st%v(:, b)) + &
              0.5_wp*dot_product(st%w(:, b), st%j(:, b)*st%w(:, b))
      end do
   end function emc_energy

   !> Linear momentum p and angular momentum about the origin lb(:, b) of each body and total
   !> lt; pscale, lscale: sums of magnitudes (for relative errors).
   pure subroutine emc_momenta(st, p, lb, lt, pscale, lscale)
      type(emc_state_t), intent(in) :: st
      real(wp), intent(out) :: p(3), lb(:, :), lt(3), pscale, lscale
      integer :: b
      p = 0.0_wp; lt = 0.0_wp; pscale = 0.0_wp; lscale = 0.0_wp
      do b = 1, st%nb
         p = p + st%m(b)*st%v(:, b)
         pscale = pscale + st%m(b)*norm2(st%v(:, b))
         lb(:, b) = cross(st%xc(:, b), st%m(b)*st%v(:, b)) + &
                    matmul(st%r(:, :, b), st%j(:, b)*st%w(:, b))
         lt = lt + lb(:, b)
         lscale = lscale + norm2(cross(st%xc(:, b), st%m(b)*st%v(:, b))) + &
                  norm2(st%j(:, b)*st%w(:, b))
      end do
   end subroutine emc_momenta

   !> Kinematics over the step for the unknowns y = (v1, W1) per body; rc = cay(Th) - I.
   pure subroutine kinematics(st, dt, y, k, rc)
      type(emc_state_t), intent(in) :: st
      real(wp), intent(in) :: dt, y(:)
      type(emc_kin_t), intent(out) :: k(:)
      real(wp), intent(out) :: rc(:, :, :)
      integer :: b, o
      do b = 1, st%nb
         o = 6*(b - 1)
         k(b)%xc0 = st%xc(:, b)
         k(b)%xl0 = st%xcl(:, b)
         k(b)%dxc = 0.5_wp*dt*(st%v(:, b) + y(o + 1:o + 3))
         k(b)%xc1 = st%xc(:, b) + k(b)%dxc
         k(b)%xm = st%xc(:, b) + 0.5_wp*k(b)%dxc
         rc(:, :, b) = cayley_m1(0.5_wp*dt*(st%w(:, b) + y(o + 4:o + 6)))
         k(b)%r0 = st%r(:, :, b)
         k(b)%dr = matmul(st%r(:, :, b), rc(:, :, b))
         k(b)%r1 = k(b)%r0 + k(b)%dr
         k(b)%a = k(b)%r0 + 0.5_wp*k(b)%dr
         k(b)%ainv = emc_inv3(k(b)%a)
      end do
   end subroutine kinematics

   !> Residual of the midpoint equations; scale: momentum scale of the step.
   subroutine residual(es, st, dt, y, pairs, npair, res, scale, upen1, dis, local, sp)
      type(emc_system_t), intent(in) :: es
      type(emc_state_t), intent(in) :: st
      real(wp), intent(in) :: dt, y(:)
      type(emc_pair_t), intent(inout) :: pairs(:)
      integer, intent(in) :: npair
      real(wp), intent(out) :: res(:), scale, upen1
      real(wp), intent(out), optional :: dis
      logical, intent(in), optional :: local   !< MPI: evaluate the pairs on every rank
      class(emc_split_t), intent(inout), optional :: sp   !< MPI: the rank's slave points
      type(emc_kin_t) :: k(st%nb)
      real(wp) :: rc(3, 3, st%nb), fo(3, st%nb), to(3, st%nb), upen0
      integer :: b, o, i, nb6
      nb6 = 6*st%nb
      do i = 1, npair
         if (pairs(i)%il > 0) pairs(i)%lam = y(nb6 + pairs(i)%il)/dt
      end do
      call kinematics(st, dt, y, k, rc)
      call emc_contact_forces(es, k, pairs, npair, fo, to, upen0, upen1, dis, local, sp)
      scale = tiny(1.0_wp)
      do b = 1, st%nb
         o = 6*(b - 1)
         res(o + 1:o + 3) = st%m(b)*(y(o + 1:o + 3) - st%v(:, b)) - dt*fo(:, b)
         ! J W1 - cay^T J W0 as J (W1 - W0) - (cay - I)^T J W0: no 1 + O(Th^2) is rounded,
         ! which biased the energy of a free spinning body by 1e-16 per step
         res(o + 4:o + 6) = st%j(:, b)*(y(o + 4:o + 6) - st%w(:, b)) - &
                            matmul(transpose(rc(:, :, b)), st%j(:, b)*st%w(:, b)) - &
                            dt*matmul(transpose(k(b)%r1), to(:, b))
         scale = max(scale, st%m(b)*norm2(st%v(:, b)), st%m(b)*norm2(y(o + 1:o + 3)), &
                     norm2(st%j(:, b)*st%w(:, b)), dt*norm2(fo(:, b)), dt*norm2(to(:, b)))
      end do
      ! Lagrange pairs: g(n+1) - g(n) = 0, scaled to momentum by the smaller mass over dt.
      ! Redundant constraints (4 corners of a flat face on a facet have rank 3) make the
      ! Newton matrix singular; a compliance of 1e-12 on the impulse (g1 - g0 = -1e-12
      ! dt*lam dt/m) picks the distribution and costs at most 1e-12 of the impulse's energy.
      do i = 1, npair
         if (pairs(i)%il > 0) res(nb6 + pairs(i)%il) = &
            min(st%m(pairs(i)%sb), st%m(pairs(i)%mb))*(pairs(i)%g1 - pairs(i)%g0)/dt + &
            LAG_COMPLIANCE*y(nb6 + pairs(i)%il)
      end do
   end subroutine residual

   !> Pairs that continue a pair in penetration at t(n) take its algorithmic gap as g(n): the
   !> same facet, or (a node sliding onto the next facet) the facet whose normal is closest
   !> to the old one (cosine >= 0.9). So the stored penalty energy carries over exactly.
   subroutine carry_gaps(es, st, k, list, n, used)
      type(emc_system_t), intent(in) :: es
      type(emc_state_t), intent(in) :: st
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), intent(inout) :: list(:)
      integer, intent(in) :: n
      logical, intent(inout) :: used(:)
      integer :: i, q, best
      real(wp) :: c, cbest, nn(3)
      if (.not. allocated(st%act)) return
      do i = 1, n
         associate (p => list(i))
            best = 0
            cbest = 0.9_wp
            do q = 1, size(st%act)
               if (used(q)) cycle
               if (st%act(q)%def /= p%def .or. st%act(q)%src /= p%src .or. &
                   st%act(q)%kind /= p%kind) cycle
               if (p%kind /= 1 .or. st%act(q)%facet == p%facet) then
                  best = q; exit
               end if
               nn = matmul(k(p%mb)%r0, es%facets(p%facet)%n)
               c = dot_product(nn, st%act(q)%n1)
               if (c > cbest) then
                  cbest = c; best = q
               end if
            end do
            if (best > 0) then
               used(best) = .true.
               p%carried = .true.
               p%g0c = st%act(best)%g1
            end if
         end associate
      end do
   end subroutine carry_gaps

   !> A pair in penetration at t(n) that the search did not find again (deeper than half a
   !> facet edge, or its point left the facet polygon) stays a pair, on its facet's plane or
   !> its sphere, with its algorithmic gap, until it opens (g >= 0). Before, it was dropped:
   !> its stored energy vanished and the bodies passed through each other (two bars at
   !> 1e3 m/s, EPS 1e6: half the energy lost). The potential is then that of the facet's
   !> plane continued (the explicit contact keeps a node on its last segment likewise).
   subroutine keep_penetrated(st, list, n, used)
      type(emc_state_t), intent(in) :: st
      type(emc_pair_t), allocatable, intent(inout) :: list(:)
      integer, intent(inout) :: n
      logical, intent(inout) :: used(:)
      type(emc_pair_t), allocatable :: t(:)
      integer :: q
      if (.not. allocated(st%act)) return
      do q = 1, size(st%act)
         if (used(q)) cycle
         used(q) = .true.
         if (n == size(list)) then
            allocate(t(max(2*n, 4)))
            t(1:n) = list(1:n)
            call move_alloc(t, list)
         end if
         n = n + 1
         list(n) = st%act(q)
         list(n)%carried = .true.
         list(n)%g0c = st%act(q)%g1
         list(n)%il = 0
         list(n)%lam = 0.0_wp
      end do
   end subroutine keep_penetrated

   !> A facet pair that does not continue a penetration must start outside (g(n) >= 0): a
   !> node already behind a facet plane at t(n) is behind the body's far side or was
   !> penetrating at t = 0 (initial penetrations are ignored until they open).
   subroutine drop_new_penetrated(es, list, n)
      type(emc_system_t), intent(in) :: es
      type(emc_pair_t), intent(inout) :: list(:)
      integer, intent(inout) :: n
      integer :: i, m
      m = 0
      do i = 1, n
         ! (a touching point, g(n) = 0 to round-off of the facet size, counts as outside)
         if (list(i)%kind == 1 .and. .not. list(i)%carried) then
            if (list(i)%g0 < -1.0e-12_wp*es%facets(list(i)%facet)%rad) cycle
         end if
         m = m + 1
         if (m /= i) list(m) = list(i)
      end do
      n = m
   end subroutine drop_new_penetrated

   !> Newton iterations for one step of size dt from st; on success st advances to t + dt.
   !> Unknowns: (v1, W1) per body, then one impulse dt*lam per Lagrange pair.
   subroutine emc_try_step(es, st, dt, rep, ok, split)
      type(emc_system_t), intent(in) :: es
      type(emc_state_t), intent(inout) :: st
      real(wp), intent(in) :: dt
      type(newton_report_t), intent(out) :: rep
      logical, intent(out) :: ok
      class(emc_split_t), intent(inout), optional :: split   !< MPI: the rank's slave points
      real(wp), allocatable :: y(:), yp(:), r(:), rp(:), jac(:, :), ysave(:)
      real(wp) :: scale, sp, rn, rn_old, h, upen1, ymag, rc(3, 3, st%nb), xold(3), dxl(3), dis
      type(emc_pair_t), allocatable :: pairs(:), cand(:)
      type(emc_kin_t) :: k(st%nb)
      integer :: nb6, n, it, jc, b, npair, ncand, pass, i, q, nact, nl, nrel
      type(emc_pair_t), allocatable :: rel(:)
      logical :: found, changed
      logical, allocatable :: used(:)
      character(:), allocatable :: msg
      nb6 = 6*st%nb
      if (.not. allocated(st%xcl)) then
         allocate(st%xcl(3, st%nb))
         st%xcl = 0.0_wp
      end if
      allocate(ysave(nb6))
      do b = 1, st%nb
         ysave(6*b - 5:6*b - 3) = st%v(:, b)
         ysave(6*b - 2:6*b) = st%w(:, b)
      end do
      call kinematics(st, dt, ysave, k, rc)
      call emc_select_pairs(es, k, pairs, npair, split)
      nact = 0
      if (allocated(st%act)) nact = size(st%act)
      allocate(used(nact))
      used = .false.
      call carry_gaps(es, st, k, pairs, npair, used)
      call keep_penetrated(st, pairs, npair, used)
      call drop_new_penetrated(es, pairs, npair)
      ok = .false.
      rep%iters = 0
      allocate(rel(4))
      nrel = 0
      do pass = 1, 8
         call number_multipliers(pairs, npair, nl)
         n = nb6 + nl
         if (allocated(y)) deallocate(y, yp, r, rp, jac)
         allocate(y(n), yp(n), r(n), rp(n), jac(n, n))
         y(1:nb6) = ysave
         do i = 1, npair
            if (pairs(i)%il > 0) y(nb6 + pairs(i)%il) = dt*pairs(i)%lam
         end do
         rn_old = huge(1.0_wp)
         ok = .false.
         do it = 1, es%maxit + 1
            call residual(es, st, dt, y, pairs, npair, r, scale, upen1, sp=split)
            rn = maxval(abs(r))/scale
            rep%resid = rn
            if (.not. ieee_is_finite(rn)) exit
            if (rn <= es%rtol) then
               ok = .true.; exit
            end if
            if (rn <= 1.0e-11_wp .and. rn >= 0.5_wp*rn_old) then
               ok = .true.; exit        ! stagnation at round-off
            end if
            if (it > es%maxit) exit
            rn_old = rn
            ymag = maxval(abs(y)) + tiny(1.0_wp)
            do jc = 1, n
               yp = y
               h = 1.0e-7_wp*max(abs(y(jc)), 1.0e-3_wp*ymag, 1.0e-300_wp)
               yp(jc) = y(jc) + h
               call residual(es, st, dt, yp, pairs, npair, rp, sp, upen1, sp=split)
               jac(:, jc) = (rp - r)/h
            end do
            ! the compliance's derivative exactly: a forward difference loses it in the
            ! rounding of a large constraint residual (a deep predictor penetration), and
            ! redundant constraints (8 slave nodes on one facet) then left a zero pivot
            do i = 1, npair
               if (pairs(i)%il > 0) jac(nb6 + pairs(i)%il, nb6 + pairs(i)%il) = LAG_COMPLIANCE
            end do
            call dense_solve(jac, r, msg)
            if (len(msg) > 0) then
               rep%msg = msg; exit
            end if
            y = y - r
            rep%iters = rep%iters + 1
         end do
         if (.not. ok) then
            if (.not. allocated(rep%msg)) rep%msg = 'Newton did not converge in '// &
               str(es%maxit)//' iterations'
            return
         end if
         ysave = y(1:nb6)
         changed = .false.
         ! Lagrange pairs pulling (lam < 0) are released (and not taken again in this step)
         q = 0
         do i = 1, npair
            if (pairs(i)%il > 0) then
               pairs(i)%lam = y(nb6 + pairs(i)%il)/dt
               if (pairs(i)%lam < 0.0_wp) then
                  changed = .true.
                  nrel = nrel + 1
                  if (nrel > size(rel)) rel = [rel, rel]
                  rel(nrel) = pairs(i)
                  cycle
               end if
            end if
            q = q + 1
            if (q /= i) pairs(q) = pairs(i)
         end do
         npair = q
         ! contacts the converged step reaches that the predictor did not see
         call kinematics(st, dt, ysave, k, rc)
         call emc_select_pairs(es, k, cand, ncand, split)
         call carry_gaps(es, st, k, cand, ncand, used)
         call drop_new_penetrated(es, cand, ncand)
         do i = 1, ncand
            found = .false.
            do q = 1, npair
               ! one pair per slave point and plane: a coplanar neighbour facet is the same
               ! contact (it was counted twice, and the energy of one copy was lost when the
               ! next step carried only the other)
               if (pairs(q)%def == cand(i)%def .and. pairs(q)%src == cand(i)%src .and. &
                   pairs(q)%kind == 1 .and. cand(i)%kind == 1) then
                  if (emc_same_plane(es, pairs(q)%facet, cand(i)%facet)) found = .true.
               end if
               if (pairs(q)%def == cand(i)%def .and. pairs(q)%src == cand(i)%src .and. &
                   pairs(q)%kind /= 1) found = .true.
            end do
            do q = 1, nrel
               if (rel(q)%def == cand(i)%def .and. rel(q)%src == cand(i)%src .and. &
                   rel(q)%facet == cand(i)%facet) found = .true.
            end do
            if (found) cycle
            cand(i)%il = 0
            call residual(es, st, dt, ysave, cand(i:i), 1, rp, sp, upen1, local=.true., &
                          sp=split)
            if (cand(i)%g1 >= 0.0_wp) cycle
            if (npair == size(pairs)) pairs = [pairs, pairs]
            npair = npair + 1
            pairs(npair) = cand(i)
            pairs(npair)%lam = 0.0_wp
            changed = .true.
         end do
         if (.not. changed) exit
         ok = .false.
      end do
      if (.not. ok) then
         rep%msg = 'the contact set did not settle in 8 passes'
         return
      end if
      call number_multipliers(pairs, npair, nl)
      deallocate(y)
      allocate(y(nb6 + nl))
      y(1:nb6) = ysave
      do i = 1, npair
         if (pairs(i)%il > 0) y(nb6 + pairs(i)%il) = dt*pairs(i)%lam
      end do
      if (allocated(r)) deallocate(r)
      allocate(r(nb6 + nl))
      call residual(es, st, dt, y, pairs, npair, r, scale, upen1, dis, sp=split)
      call kinematics(st, dt, ysave, k, rc)
      do b = 1, st%nb
         xold = st%xc(:, b)
         dxl = k(b)%dxc + st%xcl(:, b)
         call two_sum(xold, dxl, st%xc(:, b), st%xcl(:, b))
         st%r(:, :, b) = k(b)%r1
         ! momentum form of the update (Simo & Wong: p1 = p0 + dt F, pi1 = pi0 + dt T): the
         ! velocities take the converged step's forces exactly, v1 = v0 + dt F/m and
         ! W1 = J^-1 (cay^T J W0 + dt R1^T T) = y - r/diag(M, J), so the momenta do not
         ! inherit the Newton residual (it only enters the positions, at second order)
         st%v(:, b) = ysave(6*b - 5:6*b - 3) - r(6*b - 5:6*b - 3)/st%m(b)
         st%w(:, b) = ysave(6*b - 2:6*b) - r(6*b - 2:6*b)/st%j(:, b)
      end do
      st%upen = upen1
      st%ediss = st%ediss + dis
      rep%npair = npair
      ! contact the step missed: a slave path through a master surface with no pair
      call emc_find_tunnel(es, k, pairs, npair, rep%tun_def, rep%tun_src, rep%tun_facet)
      st%act = pack(pairs(1:npair), pairs(1:npair)%g1 < 0.0_wp .and. pairs(1:npair)%il == 0)
   contains
      subroutine number_multipliers(list, m, cnt)
         type(emc_pair_t), intent(inout) :: list(:)
         integer, intent(in) :: m
         integer, intent(out) :: cnt
         integer :: j
         cnt = 0
         do j = 1, m
            list(j)%il = 0
            if (es%defs(list(j)%def)%form == EMC_LAGRANGE) then
               cnt = cnt + 1
               list(j)%il = cnt
            end if
         end do
      end subroutine number_multipliers
   end subroutine emc_try_step

   !> One step of size dt, halved up to es%nfail times when Newton fails.
   recursive subroutine emc_step(es, st, dt, level, rep, ok, ncut, split)
      type(emc_system_t), intent(in) :: es
      type(emc_state_t), intent(inout) :: st
      real(wp), intent(in) :: dt
      integer, intent(in) :: level
      type(newton_report_t), intent(out) :: rep
      logical, intent(out) :: ok
      integer, intent(inout) :: ncut
      class(emc_split_t), intent(inout) :: split   !< MPI: the rank's slave points
      type(emc_state_t) :: save
      type(newton_report_t) :: r2
      save = st
      call emc_try_step(es, st, dt, rep, ok, split)
      if (ok .or. level >= es%nfail) return
      st = save
      ncut = ncut + 1
      call emc_step(es, st, 0.5_wp*dt, level + 1, rep, ok, ncut, split)
      if (.not. ok) return
      call emc_step(es, st, 0.5_wp*dt, level + 1, r2, ok, ncut, split)
      rep%iters = rep%iters + r2%iters
      rep%resid = max(rep%resid, r2%resid)
      if (rep%tun_def == 0) then
         rep%tun_def = r2%tun_def; rep%tun_src = r2%tun_src; rep%tun_facet = r2%tun_facet
      end if
      if (.not. ok) rep = r2
   end subroutine emc_step

   !> Copy the state into the model's rigid bodies and nodes (x, v).
   subroutine emc_to_model(st, model)
      type(emc_state_t), intent(in) :: st
      type(model_t), intent(inout) :: model
      integer :: b, i, nd
      do b = 1, st%nb
         associate (bd => model%rigid%bodies(b))
            bd%xc = st%xc(:, b); bd%xc_n = bd%xc
            bd%vc = st%v(:, b)
            bd%rot = st%r(:, :, b); bd%rot_n = bd%rot
            bd%omega = matmul(bd%rot, st%w(:, b))
            bd%lsp = matmul(bd%rot, st%j(:, b)*st%w(:, b))
            do i = 1, size(bd%nodes)
               nd = bd%nodes(i)
               model%x(:, nd) = bd%xc + matmul(bd%rot, bd%s(:, i))
               model%v(:, nd) = bd%vc + cross(bd%omega, model%x(:, nd) - bd%xc)
            end do
         end associate
      end do
   end subroutine emc_to_model
end module dx_emc_solver
