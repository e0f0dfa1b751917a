!> Element erosion, one place for every solid family: the *MAT_ADD_EROSION criteria at an
!> integration point (called by the kernels right after the material update, beside the
!> material's own failure, so an element that fails at t(n) carries no force from t(n) on)
!> and the criteria that need no stress (erosion_now, after the wave speed: FAILTM, and
!> *CONTROL_TIMESTEP ERODE = 1: the element whose step falls below DTMIN times the first
!> step). An eroded element keeps zero
!> stress, carries no force, no longer limits the step and keeps its internal energy, which
!> glstat and matsum report as eroded internal energy (dx_energy_sums); its nodal mass stays
!> on the nodes (as LS-DYNA does), a node no living element holds any more flies on freely
!> and its kinetic energy is reported as eroded kinetic energy.
!> Criteria (LS-DYNA Keyword User's Manual Vol. II, *MAT_ADD_EROSION; a field equal to EXCL
!> is off): pressure p = -tr(sigma)/3 >= MXPRES or <= MNPRES; largest principal stress
!> sigma_1 >= SIGP1; von Mises stress >= SIGVM; volumetric strain ln(V/V0) >= VOLEPS
!> (VOLEPS > 0) or <= VOLEPS (VOLEPS < 0); time >= FAILTM; Tuler-Butcher: the damage
!> D = (1/IMPULSE) int max(0, sigma_1 - SIGTH)^lambda dt reaches 1 (Tuler & Butcher 1968,
!> "A criterion for the time dependence of dynamic fracture", Int. J. Fract. Mech.
!> 4:431-437, with the exponent lambda = 2 that LS-DYNA's *MAT_ADD_EROSION uses). A point
!> fails when NCS criteria hold at once (Tuler-Butcher counts as one), an element when
!> min(NUMFIP, points) of its points have failed.
!> Strain criteria (parts that have one: the family-state slot ES_EPS; ELFORM 1 and 10 per
!> element, ELFORM 2 from the element-mean gradient, erosion_strain_mean): the
!> total strain is the sum of the strain increments D dt turned with the material like the
!> stress (Jaumann, first order; a logarithmic strain for rotation-free stretching): largest
!> principal strain >= MXEPS, smallest <= MNEPS, effective strain sqrt(2/3 e':e') >= EFFEPS,
!> tensorial shear strain (eps_1 - eps_3)/2 >= EPSSH.
!> Principal stresses: the trigonometric solution of the characteristic cubic (Smith 1961,
!> "Eigenvalues of a symmetric 3x3 matrix", Comm. ACM 4:168).
module dx_erosion
   use dx_kinds, only: wp
   use dx_element_types, only: elem_block_t, part_t, erosion_t, ES_DMG, ES_EPS
   implicit none
   private
   public :: erosion_points, erosion_one_point, erosion_now, erosion_strain, erosion_strain_mean, &
             largest_principal, &
             von_mises

contains

   !> The *MAT_ADD_EROSION criteria of part at one integration point of elements 1..n:
   !> sig(n, 6) the stress at t(n) (xx yy zz xy yz zx), rv the relative volume V/V0, dt the
   !> step the stress acts over (the Tuler-Butcher integral, weighted by wip: 1/points);
   !> nfail(i) counts the points of element i that fail. Elements already eroded are
   !> skipped.
   subroutine erosion_points(blk, ero, n, sig, rv, dt, wip, nfail)
      type(elem_block_t), intent(inout) :: blk
      type(erosion_t), intent(in) :: ero
      integer, intent(in) :: n
      real(wp), intent(in) :: sig(:, :), rv(:), dt, wip
      integer, intent(inout) :: nfail(:)
      real(wp) :: p, s1, d, e(6), e1, e3, em
      integer :: i, nc, jd, je
      if (.not. ero%on) return
      jd = blk%esc(ES_DMG)
      je = blk%esc(ES_EPS)
      do i = 1, n
         if (blk%failed(i)) cycle
         nc = 0
         p = -(sig(i, 1) + sig(i, 2) + sig(i, 3))/3.0_wp
         if (ero%mxpres /= ero%excl) then
            if (p >= ero%mxpres) nc = nc + 1
         end if
         if (ero%mnpres /= ero%excl) then
            if (p <= ero%mnpres) nc = nc + 1
         end if
         s1 = largest_principal(sig(i, :))
         if (ero%sigp1 /= ero%excl) then
            if (s1 >= ero%sigp1) nc = nc + 1
         end if
         if (ero%sigvm /= ero%excl) then
            if (von_mises(sig(i, :)) >= ero%sigvm) nc = nc + 1
         end if
         if (ero%voleps /= ero%excl) then
            if (ero%voleps >= 0.0_wp) then
               if (log(rv(i)) >= ero%voleps) nc = nc + 1
            else
               if (log(rv(i)) <= ero%voleps) nc = nc + 1
            end if
         end if
         if (je > 0) then         ! the total-strain criteria
            e = blk%es(i, je:je + 5)
            e1 = largest_principal(e)
            e3 = -largest_principal(-e)
            if (ero%mxeps /= ero%excl) then
               if (e1 >= ero%mxeps) nc = nc + 1
            end if
            if (ero%mneps /= ero%excl) then
               if (e3 <= ero%mneps) nc = nc + 1
            end if
            if (ero%epssh /= ero%excl) then
               if (0.5_wp*(e1 - e3) >= ero%epssh) nc = nc + 1
            end if
            if (ero%effeps /= ero%excl) then
               em = (e(1) + e(2) + e(3))/3.0_wp
               d = sqrt(2.0_wp/3.0_wp*((e(1) - em)**2 + (e(2) - em)**2 + (e(3) - em)**2 &
                        + 2.0_wp*(e(4)**2 + e(5)**2 + e(6)**2)))
               if (d >= ero%effeps) nc = nc + 1
            end if
         end if
         if (jd > 0) then
            d = max(0.0_wp, s1 - ero%sigth)
            blk%es(i, jd) = blk%es(i, jd) + wip*dt*d**ero%lambda/ero%impulse
            if (blk%es(i, jd) >= 1.0_wp) nc = nc + 1
         end if
         if (nc >= ero%ncs) nfail(i) = nfail(i) + 1
      end do
   end subroutine erosion_points

   !> One-point elements (ELFORM 1, 10): the criteria of part at the point of elements 1..n
   !> (stress blk%sig(:, :, 1)), failed(i) set where the point fails.
   subroutine erosion_one_point(blk, part, n, rv, dt, failed)
      type(elem_block_t), intent(inout) :: blk
      type(part_t), intent(in) :: part
      integer, intent(in) :: n
      real(wp), intent(in) :: rv(:), dt
      logical, intent(inout) :: failed(:)
      integer :: nfp(n)
      if (.not. part%ero%on) return
      nfp = 0
      call erosion_points(blk, part%ero, n, blk%sig(:, :, 1), rv, dt, 1.0_wp, nfp)
      failed(1:n) = failed(1:n) .or. nfp > 0
   end subroutine erosion_one_point

   !> The criteria of the pass at time t that need no stress (called by the kernels after
   !> the wave speed): FAILTM (every element of the part at t >= FAILTM) and, dtfloor > 0
   !> (*CONTROL_TIMESTEP ERODE = 1: DTMIN * first step / TSSFAC), the element whose stable
   !> step lc/(Q + sqrt(Q^2 + c^2)) (Q = Q2 c + Q1 lc |tr D| in compression, as
   !> dx_hex8's stable_time_step) is below it. Decided in the pass, before the forces, so
   !> the element applies no force from it on and books no work for it (energy exact).
   subroutine erosion_now(part, n, t, dtfloor, lc, trd, c, failed)
      type(part_t), intent(in) :: part
      integer, intent(in) :: n
      real(wp), intent(in) :: t, dtfloor, lc(:), trd(:), c(:)
      logical, intent(inout) :: failed(:)
      real(wp) :: qb, dte
      integer :: i
      if (part%ero%on .and. part%ero%failtm /= part%ero%excl) then
         if (t >= part%ero%failtm) failed(1:n) = .true.
      end if
      if (.not. dtfloor > 0.0_wp) return
      do i = 1, n
         qb = 0.0_wp
         if (trd(i) < 0.0_wp) qb = part%q2*c(i) + part%q1*lc(i)*abs(trd(i))
         dte = lc(i)/(qb + sqrt(qb*qb + c(i)*c(i)))
         if (dte < dtfloor) failed(i) = .true.
      end do
   end subroutine erosion_now

   !> The total strain of elements 1..n (slot ES_EPS; nothing when the block has none):
   !> turned by the spin increments w12, w23, w31 (Jaumann, as the stress), then the strain
   !> increment de (n, 6: xx yy zz xy yz zx, tensor shear) added.
   subroutine erosion_strain(blk, n, de, w12, w23, w31)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: n
      real(wp), intent(in) :: de(:, :), w12(:), w23(:), w31(:)
      real(wp) :: e(6), d(6)
      integer :: i, je
      je = blk%esc(ES_EPS)
      if (je == 0) return
      do i = 1, n
         if (blk%failed(i)) cycle
         e = blk%es(i, je:je + 5)
         d(1) = 2.0_wp*(w12(i)*e(4) - w31(i)*e(6))
         d(2) = 2.0_wp*(w23(i)*e(5) - w12(i)*e(4))
         d(3) = 2.0_wp*(w31(i)*e(6) - w23(i)*e(5))
         d(4) = w12(i)*(e(2) - e(1)) + w23(i)*e(6) - w31(i)*e(5)
         d(5) = w23(i)*(e(3) - e(2)) + w31(i)*e(4) - w12(i)*e(6)
         d(6) = w31(i)*(e(1) - e(3)) + w12(i)*e(5) - w23(i)*e(4)
         blk%es(i, je:je + 5) = e + d + de(i, 1:6)
      end do
   end subroutine erosion_strain

   !> The total strain of elements 1..n of the fully integrated hexahedron (ELFORM 2): the
   !> element-mean strain increment and spin, (1/V) sum_I v_I (x) B_I dt with the mid-step B
   !> vectors bx, by, bz and volume volm (the volume average of the points' velocity gradients:
   !> the strain ELFORM 1 accumulates), added by erosion_strain.
   subroutine erosion_strain_mean(blk, n, vx, vy, vz, bx, by, bz, volm, dt)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: n
      real(wp), intent(in) :: vx(:, :), vy(:, :), vz(:, :), bx(:, :), by(:, :), bz(:, :)
      real(wp), intent(in) :: volm(:), dt
      real(wp) :: de(n, 6), w12(n), w23(n), w31(n), l(3, 3), s
      integer :: i
      if (blk%esc(ES_EPS) == 0) return
      do i = 1, n
         s = dt/volm(i)
         l(1, :) = [sum(vx(i, 1:8)*bx(i, 1:8)), sum(vx(i, 1:8)*by(i, 1:8)), sum(vx(i, 1:8)*bz(i, 1:8))]*s
         l(2, :) = [sum(vy(i, 1:8)*bx(i, 1:8)), sum(vy(i, 1:8)*by(i, 1:8)), sum(vy(i, 1:8)*bz(i, 1:8))]*s
         l(3, :) = [sum(vz(i, 1:8)*bx(i, 1:8)), sum(vz(i, 1:8)*by(i, 1:8)), sum(vz(i, 1:8)*bz(i, 1:8))]*s
         de(i, :) = [l(1, 1), l(2, 2), l(3, 3), 0.5_wp*(l(1, 2) + l(2, 1)), &
                     0.5_wp*(l(2, 3) + l(3, 2)), 0.5_wp*(l(3, 1) + l(1, 3))]
         w12(i) = 0.5_wp*(l(1, 2) - l(2, 1))
         w23(i) = 0.5_wp*(l(2, 3) - l(3, 2))
         w31(i) = 0.5_wp*(l(3, 1) - l(1, 3))
      end do
      call erosion_strain(blk, n, de, w12, w23, w31)
   end subroutine erosion_strain_mean

   !> The largest principal value of the symmetric tensor s (xx yy zz xy yz zx).
   pure real(wp) function largest_principal(s) result(s1)
      real(wp), intent(in) :: s(6)
      real(wp) :: m, a, b, c, j2, j3, r, phi
      m = (s(1) + s(2) + s(3))/3.0_wp
      a = s(1) - m; b = s(2) - m; c = s(3) - m
      j2 = 0.5_wp*(a*a + b*b + c*c) + s(4)**2 + s(5)**2 + s(6)**2
      if (.not. j2 > 0.0_wp) then
         s1 = m
         return
      end if
      ! J3 = det of the deviator
      j3 = a*(b*c - s(5)**2) - s(4)*(s(4)*c - s(5)*s(6)) + s(6)*(s(4)*s(5) - b*s(6))
      r = 1.5_wp*sqrt(3.0_wp)*j3/j2**1.5_wp
      r = max(-1.0_wp, min(1.0_wp, r))
      phi = acos(r)/3.0_wp
      s1 = m + 2.0_wp*sqrt(j2/3.0_wp)*cos(phi)
   end function largest_principal

   !> The von Mises stress of s (xx yy zz xy yz zx).
   pure real(wp) function von_mises(s) result(v)
      real(wp), intent(in) :: s(6)
      v = sqrt(0.5_wp*((s(1) - s(2))**2 + (s(2) - s(3))**2 + (s(3) - s(1))**2) + &
               3.0_wp*(s(4)**2 + s(5)**2 + s(6)**2))
   end function von_mises
end module dx_erosion
