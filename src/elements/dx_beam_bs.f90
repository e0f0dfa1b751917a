!> Belytschko-Schwer resultant beam (ELFORM 2 of *SECTION_BEAM) over one element block: a
!> 2-node co-rotational space-frame element with elastic resultants (Belytschko, Schwer &
!> Klein 1977, "Large displacement, transient analysis of space frames", IJNME 11:65-84;
!> Hallquist, LS-DYNA Theory Manual, "Belytschko Beam"). The element's frame follows its
!> chord and twist; in it the deformation is small: an elongation, a twist and two end
!> rotations about each transverse axis relative to the chord, whose resultants are the
!> linear space-frame ones (cubic Hermite bending, Euler-Bernoulli; with a shear area SA > 0
!> the Timoshenko correction phi = 12 E I / (G SA L0**2): Przemieniecki, Theory of Matrix
!> Structural Analysis, 1968, sec. 5.6).
!> Frame: e1 = (x2 - x1)/L; e2 (the s axis) is carried as element state, set at the start
!> from the orientation node N3 or vector (in the plane of N1, N2, N3) and turned each cycle
!> by the frame's spin omega = e1 x (v2 - v1)/L + ((w1 + w2)/2 . e1) e1 (chord rotation
!> plus mean twist: a rigid rotation omega of the element turns the frame by exactly omega),
!> then re-orthogonalised against e1; e3 = e1 x e2 (the t axis).
!> Rates at the mid-step geometry x(n) - dt/2 v(n-1/2) and its frame (a rigid motion gives
!> a zero elongation rate exactly, and end-rotation rates of relative order (omega dt)**2/12:
!> the chord of a turn against its tangent):
!>   dL/dt = (v2 - v1).e1, dphi/dt = (w2 - w1).e1,
!>   dtheta_s,a/dt = w_a.e2 + (v2 - v1).e3/L, dtheta_t,a/dt = w_a.e3 - (v2 - v1).e2/L;
!> the angles are integrated over the step (element state), the elongation is total:
!>   N = E A (L - L0)/L0, T = G J phi/L0,
!>   M_1 = E I/(L0 (1 + phi)) ((4 + phi) theta_1 + (2 - phi) theta_2), M_2 likewise,
!> about e2 with ISS and about e3 with ITT. Nodal forces and moments are the work conjugates:
!> N e1 and T e1 at N2 (minus at N1), M_t,a e3 and M_s,a e2 at node a, and the shears
!> (M_t,1 + M_t,2)/L along -e2 and (M_s,1 + M_s,2)/L along +e3 at N2 (opposite at N1).
!> Internal energy: the work of the resultants over the step (trapezoid in the resultants),
!> corrected for a change of the step as dx_hex8's centred work (the ES_WORK slot), so that
!> it partners the centred kinetic energy of dx_explicit for any step sequence.
!> Lumped mass rho A L0/2 per node (the family table); rotary inertia (beam_bs_rotary_inertia):
!> the nodal mass times max((ISS + ITT)/A, L0**2/12) - the physical rho I L/2 plus a scaling
!> of the kind Belytschko, Lin & Tsay 1984 and Hughes & Liu 1981 use for the rotations of
!> explicit shells and beams (the rotational modes then do not limit the step of a slender
!> element; dynx's choice, docs/design.md "Beams").
!> Stable step: 2/omega_max of the element with its lumped masses, omega_max the largest of
!> the axial 2c/L (c = sqrt(E/rho): dt = L/c, LS-DYNA's beam step), the bending mode
!> omega**2 = 12 c**2 r**2 (1 + 4 beta)/(beta L**4) (r**2 = max(ISS, ITT)/A, the rotary
!> inertia beta m L**2; the Euler-Bernoulli stiffness bounds the Timoshenko one) and the
!> torsion mode omega**2 = 2 G J/(L beta m L**2) (closed forms of the 12-DOF element's
!> eigenproblem with the diagonal mass: the modes split into axial, torsion and, per plane,
!> a symmetric and an antisymmetric bending mode; the antisymmetric one is the larger).
!> L is the current length (the step then changes every cycle: hence the centred work above;
!> with the plain trapezoid a 4-element bar released at TSSFAC 0.9 showed an energy ratio of
!> 1.025 after 10 ms, with the centred work 1.0000000).
module dx_beam_bs
   use dx_kinds, only: wp, huge_wp
   use dx_vec3, only: cross
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_BEAM, ES_WORK, block_result_t, &
                               ELEM_ERR_NEGVOL, BM_E2, BM_TH, BM_RES, BM_SEC
   use dx_hex8, only: centred_work
   implicit none
   private
   public :: beam_bs_block, beam_bs_rotary_inertia, beam_bs_init, beam_bs_axes
   public :: BM_E2, BM_TH, BM_RES, BM_SEC
   public :: beam_kinematics, beam_end_forces   ! (the Hughes-Liu beam's, dx_beam_hl)
   ! (BM_E2, BM_TH, BM_RES, BM_SEC: the ES_BEAM slot's columns, dx_element_types)

contains

   !> The element's frame at the start: e2 in the plane of e1 and the orientation vector
   !> vo (the N3 - N1 direction or the _ORIENTATION vector), ok = .false. when vo is
   !> (nearly) parallel to the beam (no usable orientation).
   pure subroutine beam_bs_axes(x1, x2, vo, e2, ok)
      real(wp), intent(in) :: x1(3), x2(3), vo(3)
      real(wp), intent(out) :: e2(3)
      logical, intent(out) :: ok
      real(wp) :: e1(3), l, r(3), vn
      e1 = x2 - x1
      l = norm2(e1)
      e2 = 0.0_wp
      ok = .false.
      vn = norm2(vo)
      if (.not. (l > 0.0_wp) .or. .not. (vn > 0.0_wp)) return
      e1 = e1/l
      r = vo/vn - dot_product(vo/vn, e1)*e1
      ! within 1e-6 rad of the axis: no usable plane
      if (norm2(r) <= 1.0e-6_wp) return
      e2 = r/norm2(r)
      ok = .true.
   end subroutine beam_bs_axes

   !> Set up the family state of element i of a beam block: its axis e2 and section
   !> values sec = A, ISS, ITT, J, SA (the angles and resultants start at zero).
   subroutine beam_bs_init(blk, i, e2, sec)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: i
      real(wp), intent(in) :: e2(3), sec(5)
      integer :: c
      c = blk%esc(ES_BEAM)
      blk%es(i, c:c + 2) = e2
      blk%es(i, c + BM_SEC:c + BM_SEC + 4) = sec
   end subroutine beam_bs_init

   !> Add the block's lumped rotary inertia to rinert: the nodal mass rho A L0/2 times
   !> max((ISS + ITT)/A, L0**2/12).
   subroutine beam_bs_rotary_inertia(blk, rho, rinert)
      type(elem_block_t), intent(in) :: blk
      real(wp), intent(in) :: rho
      real(wp), intent(inout) :: rinert(:)
      integer :: i, k, c
      real(wp) :: m, a, l0, ri
      c = blk%esc(ES_BEAM)
      do i = 1, blk%nel
         a = blk%es(i, c + BM_SEC)
         l0 = blk%vol0(i)/a
         m = 0.5_wp*rho*blk%vol0(i)
         ri = m*rot_factor(blk%es(i, c + BM_SEC + 1), blk%es(i, c + BM_SEC + 2), a, l0)
         do k = 1, 2
            rinert(blk%conn(k, i)) = rinert(blk%conn(k, i)) + ri
         end do
      end do
   end subroutine beam_bs_rotary_inertia

   !> rotary inertia per unit nodal mass: max((ISS + ITT)/A, L0**2/12)
   pure real(wp) function rot_factor(iss, itt, a, l0)
      real(wp), intent(in) :: iss, itt, a, l0
      rot_factor = max((iss + itt)/a, l0*l0/12.0_wp)
   end function rot_factor

   !> u turned by the rotation vector th (Rodrigues' formula).
   pure function turn(u, th) result(r)
      real(wp), intent(in) :: u(3), th(3)
      real(wp) :: r(3)
      real(wp) :: a, k(3)
      a = norm2(th)
      if (a == 0.0_wp) then
         r = u
         return
      end if
      k = th/a
      r = u*cos(a) + cross(k, u)*sin(a) + k*dot_product(k, u)*(1.0_wp - cos(a))
   end function turn

   !> e2 made a unit vector normal to e1 (Gram-Schmidt)
   pure function normal_to(e2, e1) result(r)
      real(wp), intent(in) :: e2(3), e1(3)
      real(wp) :: r(3)
      r = e2 - dot_product(e2, e1)*e1
      r = r/norm2(r)
   end function normal_to

   !> The kinematics of one beam (both formulations): the mid-step geometry
   !> x - hdt v, its frame (e1m; e2 turned by half the step's spin), the six rates
   !> rate = ((v2 - v1).e1, (w2 - w1).e1, the end rotation rates about e2 at N1, N2 and about
   !> e3 at N1, N2 relative to the chord) and the mid-step length lm; then the frame of x(n):
   !> its length l, e1 and e2o turned by the whole step's spin, re-orthogonalised.
   !> ok = .false. when a length is not positive. (beam_bs_block keeps its own inline copy of
   !> these lines and of beam_end_forces: moved into these routines they changed the last bits
   !> of beam_frame's outputs, the compiler's contractions differing; dx_beam_hl calls them.)
   pure subroutine beam_kinematics(x1, x2, v1, v2, w1, w2, e2o, hdt, dt_old, lm, rate, l, &
                                   e1, e2, ok)
      real(wp), intent(in) :: x1(3), x2(3), v1(3), v2(3), w1(3), w2(3), e2o(3), hdt, dt_old
      real(wp), intent(out) :: lm, rate(6), l, e1(3), e2(3)
      logical, intent(out) :: ok
      real(wp) :: xm(3, 2), dm(3), e1m(3), e2m(3), e3m(3), om(3), dv(3)
      ok = .false.
      rate = 0.0_wp; l = 0.0_wp; e1 = 0.0_wp; e2 = 0.0_wp
      xm(:, 1) = x1 - hdt*v1
      xm(:, 2) = x2 - hdt*v2
      dm = xm(:, 2) - xm(:, 1)
      lm = norm2(dm)
      if (.not. (lm > 0.0_wp)) return
      e1m = dm/lm
      dv = v2 - v1
      om = cross(e1m, dv)/lm + 0.5_wp*dot_product(w1 + w2, e1m)*e1m
      e2m = normal_to(turn(e2o, hdt*om), e1m)
      e3m = cross(e1m, e2m)
      rate(1) = dot_product(dv, e1m)
      rate(2) = dot_product(w2 - w1, e1m)
      rate(3) = dot_product(w1, e2m) + dot_product(dv, e3m)/lm
      rate(4) = dot_product(w2, e2m) + dot_product(dv, e3m)/lm
      rate(5) = dot_product(w1, e3m) - dot_product(dv, e2m)/lm
      rate(6) = dot_product(w2, e3m) - dot_product(dv, e2m)/lm
      e1 = x2 - x1
      l = norm2(e1)
      if (.not. (l > 0.0_wp)) return
      e1 = e1/l
      e2 = normal_to(turn(e2o, dt_old*om), e1)
      ok = .true.
   end subroutine beam_kinematics

   !> The internal end forces fl(:, a) and moments ml(:, a) of the resultants in end-moment
   !> form r = (N, T, M_s at N1, N2, M_t at N1, N2) in the frame e1, e2, e3 of length l.
   pure subroutine beam_end_forces(r, e1, e2, e3, l, fl, ml)
      real(wp), intent(in) :: r(6), e1(3), e2(3), e3(3), l
      real(wp), intent(out) :: fl(3, 2), ml(3, 2)
      real(wp) :: vs, vt
      vt = (r(5) + r(6))/l
      vs = (r(3) + r(4))/l
      fl(:, 2) = r(1)*e1 - vt*e2 + vs*e3
      fl(:, 1) = -fl(:, 2)
      ml(:, 1) = -r(2)*e1 + r(3)*e2 + r(5)*e3
      ml(:, 2) = r(2)*e1 + r(4)*e2 + r(6)*e3
   end subroutine beam_end_forces

   !> One explicit pass over a block of resultant beams: x = x(n), v = v(n-1/2),
   !> w = w(n-1/2), dt_old = dt(n-1/2). Integrates the deformation angles to t(n), forms the
   !> resultants, subtracts the internal forces from f and moments from mom.
   subroutine beam_bs_block(blk, mat, x, v, w, dt_old, f, mom, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: x(:, :), v(:, :), w(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :), mom(:, :)
      type(block_result_t), intent(out) :: res
      real(wp) :: g, lam, ym, c2, hdt, de
      real(wp) :: xm(3, 2), dm(3), lm, e1m(3), e2o(3), e2m(3), e3m(3), om(3), dv(3)
      real(wp) :: e1(3), e2(3), e3(3), l, l0, rate(6), th(5), r(6), rold(6)
      real(wp) :: a, iss, itt, tj, sa, phs, pht, ks, kt, vs, vt, fl(3, 2), ml(3, 2)
      real(wp) :: r2, beta, wb2, wt2, wmax2, dte, wo, wn
      integer :: i, k, c, n1, n2, cw
      c = blk%esc(ES_BEAM)
      cw = blk%esc(ES_WORK)
      hdt = 0.5_wp*dt_old
      g = mat%shear
      lam = mat%bulk - 2.0_wp*g/3.0_wp
      ym = g*(3.0_wp*lam + 2.0_wp*g)/(lam + g)
      c2 = ym/mat%ro
      res%deint = 0.0_wp; res%dehg = 0.0_wp; res%pend = 0.0_wp
      do i = 1, blk%nel
         n1 = blk%conn(1, i); n2 = blk%conn(2, i)
         a = blk%es(i, c + BM_SEC); iss = blk%es(i, c + BM_SEC + 1)
         itt = blk%es(i, c + BM_SEC + 2); tj = blk%es(i, c + BM_SEC + 3)
         sa = blk%es(i, c + BM_SEC + 4)
         l0 = blk%vol0(i)/a
         ! ---- mid-step frame and the deformation rates
         xm(:, 1) = x(:, n1) - hdt*v(:, n1)
         xm(:, 2) = x(:, n2) - hdt*v(:, n2)
         dm = xm(:, 2) - xm(:, 1)
         lm = norm2(dm)
         if (.not. (lm > 0.0_wp)) then
            res%ibad = i; res%errcode = ELEM_ERR_NEGVOL
            return
         end if
         e1m = dm/lm
         dv = v(:, n2) - v(:, n1)
         om = cross(e1m, dv)/lm + 0.5_wp*dot_product(w(:, n1) + w(:, n2), e1m)*e1m
         e2o = blk%es(i, c + BM_E2:c + BM_E2 + 2)
         e2m = normal_to(turn(e2o, hdt*om), e1m)
         e3m = cross(e1m, e2m)
         rate(1) = dot_product(dv, e1m)
         rate(2) = dot_product(w(:, n2) - w(:, n1), e1m)
         rate(3) = dot_product(w(:, n1), e2m) + dot_product(dv, e3m)/lm
         rate(4) = dot_product(w(:, n2), e2m) + dot_product(dv, e3m)/lm
         rate(5) = dot_product(w(:, n1), e3m) - dot_product(dv, e2m)/lm
         rate(6) = dot_product(w(:, n2), e3m) - dot_product(dv, e2m)/lm
         th = blk%es(i, c + BM_TH:c + BM_TH + 4) + dt_old*rate(2:6)
         blk%es(i, c + BM_TH:c + BM_TH + 4) = th
         ! ---- the frame of x(n)
         e1 = x(:, n2) - x(:, n1)
         l = norm2(e1)
         if (.not. (l > 0.0_wp)) then
            res%ibad = i; res%errcode = ELEM_ERR_NEGVOL
            return
         end if
         e1 = e1/l
         e2 = normal_to(turn(e2o, dt_old*om), e1)
         e3 = cross(e1, e2)
         blk%es(i, c + BM_E2:c + BM_E2 + 2) = e2
         ! ---- resultants: N, T, M_s (N1, N2), M_t (N1, N2)
         phs = 0.0_wp; pht = 0.0_wp
         if (sa > 0.0_wp) then
            phs = 12.0_wp*ym*iss/(g*sa*l0*l0)
            pht = 12.0_wp*ym*itt/(g*sa*l0*l0)
         end if
         ks = ym*iss/(l0*(1.0_wp + phs))
         kt = ym*itt/(l0*(1.0_wp + pht))
         r(1) = ym*a*(l - l0)/l0
         r(2) = g*tj*th(1)/l0
         r(3) = ks*((4.0_wp + phs)*th(2) + (2.0_wp - phs)*th(3))
         r(4) = ks*((2.0_wp - phs)*th(2) + (4.0_wp + phs)*th(3))
         r(5) = kt*((4.0_wp + pht)*th(4) + (2.0_wp - pht)*th(5))
         r(6) = kt*((2.0_wp - pht)*th(4) + (4.0_wp + pht)*th(5))
         if (blk%failed(i)) r = 0.0_wp
         rold = blk%es(i, c + BM_RES:c + BM_RES + 5)
         blk%es(i, c + BM_RES:c + BM_RES + 5) = r
         ! the centred work of the resultants (dx_hex8's centred_work without viscosity):
         ! the trapezoid dt (r_old + r).rate/2 corrected for a change of step, the exact
         ! partner of the centred kinetic energy
         wo = dt_old*dot_product(rold, rate)
         wn = dt_old*dot_product(r, rate)
         associate (s1 => blk%es(i, cw), s2 => blk%es(i, cw + 1), s3 => blk%es(i, cw + 2), &
                    s4 => blk%es(i, cw + 3))
            call centred_work(s1, s2, s3, s4, dt_old, wo, wn, 0.0_wp, 0.0_wp, 0.0_wp, &
                              0.0_wp, 0.0_wp, de)
         end associate
         blk%eint(i) = blk%eint(i) + de
         res%deint = res%deint + de
         blk%sig(i, 1, 1) = r(1)/a
         blk%relvol(i) = l/l0
         ! ---- nodal forces and moments (internal), then into f and mom
         vt = (r(5) + r(6))/l
         vs = (r(3) + r(4))/l
         fl(:, 2) = r(1)*e1 - vt*e2 + vs*e3
         fl(:, 1) = -fl(:, 2)
         ml(:, 1) = -r(2)*e1 + r(3)*e2 + r(5)*e3
         ml(:, 2) = r(2)*e1 + r(4)*e2 + r(6)*e3
         do k = 1, 2
            f(:, blk%conn(k, i)) = f(:, blk%conn(k, i)) - fl(:, k)
            mom(:, blk%conn(k, i)) = mom(:, blk%conn(k, i)) - ml(:, k)
         end do
         ! ---- stable step: the axial 2c/L, the bending and torsion modes (current length)
         r2 = max(iss, itt)/a
         beta = rot_factor(iss, itt, a, l0)/(l0*l0)
         wmax2 = 4.0_wp*c2/(l*l)
         wb2 = 12.0_wp*c2*r2*(1.0_wp + 4.0_wp*beta)/(beta*l**4)
         ! torsion: the ends twisting against each other, 2 G J/L over the nodal inertia
         wt2 = 4.0_wp*g*tj/(mat%ro*a*l*l*beta*l0*l0)
         wmax2 = max(wmax2, wb2, wt2)
         dte = 2.0_wp/sqrt(wmax2)
         if (blk%failed(i)) dte = huge_wp
         if (dte < res%dt) then
            res%dt = dte; res%imin = i
         end if
         res%dte(i) = dte
      end do
   end subroutine beam_bs_block
end module dx_beam_bs
