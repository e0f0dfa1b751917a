!> Unit tests of the Belytschko-Schwer resultant beam (dx_beam_bs, the family row of
!> dx_element_types): the initial frame from an orientation vector (orthonormal, s in the
!> plane of the beam and the vector; a vector along the beam has no frame); one elastic element
!> of length L along a skew direction driven for one step dt by
!>  - an angular velocity omega about s at N2: the end moments of the linear space frame,
!>    M1 = 2 E ISS theta/L, M2 = 4 E ISS theta/L, theta = omega dt, and the shears
!>    (M1 + M2)/L along t (Przemieniecki 1968, the 12x12 beam stiffness);
!>  - the same about t (ITT), with a shear area SA: the Timoshenko end moments
!>    E I/(L (1 + phi)) ((4 + phi) theta, (2 - phi) theta), phi = 12 E I/(G SA L**2);
!>  - a twist rate at N2: T = G J omega dt/L;
!>  - a stretch rate: N = E A (L - L0)/L0;
!> and the stable step: L/c for a slender element (the axial mode governs), 2/omega_b with
!> omega_b**2 = 12 c**2 r**2 (1 + 4 beta)/(beta L**4) for a thick one (dx_beam_bs header).
!> Tolerance: the element is driven by 1e-6 relative deformations, so the round-off of a
!> length difference is 1e-16/1e-6 = 1e-10 relative: checked at 1e-8.
program test_beam
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_vec3, only: cross
   use dx_mat_elastic, only: mat_elastic_t
   use dx_element_types, only: elem_block_t, block_result_t, ES_BEAM, ES_WORK, ETYPE_BEAM_BS, &
                               element_family, family_t
   use dx_beam_bs, only: beam_bs_block, beam_bs_init, beam_bs_axes, BM_RES
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: ey = 210.0_wp, pr = 0.3_wp, rho = 7.85e-6_wp, len = 10.0_wp
   real(wp), parameter :: a = 2.0_wp, iss = 1.0_wp/6.0_wp, itt = 2.0_wp/3.0_wp, tj = 0.5_wp
   real(wp), parameter :: dt = 1.0e-6_wp, om = 1.0_wp
   type(mat_elastic_t) :: mat
   type(error_t), allocatable :: err
   real(wp) :: e1(3), e2(3), e3(3), x0(3, 2), g, th, m1, m2, phi, sa
   logical :: ok

   mat%ro = rho; mat%e = ey; mat%pr = pr
   call mat%setup(err)
   call check(.not. allocated(err), 'elastic setup')
   g = ey/(2.0_wp*(1.0_wp + pr))

   ! ---- the frame: a skew beam, the orientation vector z
   x0(:, 1) = [1.0_wp, 2.0_wp, 3.0_wp]
   e1 = [2.0_wp, 1.0_wp, 0.5_wp]
   e1 = e1/norm2(e1)
   x0(:, 2) = x0(:, 1) + len*e1
   call beam_bs_axes(x0(:, 1), x0(:, 2), [0.0_wp, 0.0_wp, 1.0_wp], e2, ok)
   call check(ok, 'frame: a vector off the axis gives a frame')
   call check(abs(norm2(e2) - 1.0_wp) < 4.0_wp*epsilon(1.0_wp) .and. &
              abs(dot_product(e1, e2)) < 4.0_wp*epsilon(1.0_wp), 'frame: s is a unit vector normal to r')
   call check(abs(dot_product(cross(e1, [0.0_wp, 0.0_wp, 1.0_wp]), e2)) < 4.0_wp*epsilon(1.0_wp), &
              'frame: s in the plane of r and the orientation vector')
   e3 = cross(e1, e2)
   call beam_bs_axes(x0(:, 1), x0(:, 2), 3.0_wp*e1, e2, ok)
   call check(.not. ok, 'frame: a vector along the beam gives none (a beam without orientation)')
   call beam_bs_axes(x0(:, 1), x0(:, 2), [0.0_wp, 0.0_wp, 1.0_wp], e2, ok)

   ! ---- end rotation about s at N2 (Euler-Bernoulli, SA = 0)
   th = om*dt
   block
      real(wp) :: f(3, 2), mom(3, 2), v(3, 2), w(3, 2)
      v = 0.0_wp; w = 0.0_wp
      w(:, 2) = om*e2
      call one_step(0.0_wp, v, w, f, mom)
      m1 = 2.0_wp*ey*iss*th/len
      m2 = 4.0_wp*ey*iss*th/len
      call check_close(dot_product(mom(:, 1), e2), -m1, 0.0_wp, 1.0e-8_wp, &
                       'rotation about s at N2: M1 = 2 E ISS theta/L')
      call check_close(dot_product(mom(:, 2), e2), -m2, 0.0_wp, 1.0e-8_wp, &
                       'rotation about s at N2: M2 = 4 E ISS theta/L')
      call check_close(dot_product(f(:, 2), e3), -(m1 + m2)/len, 0.0_wp, 1.0e-8_wp, &
                       'rotation about s at N2: shear (M1 + M2)/L along t')
      call check(maxval(abs(f(:, 1) + f(:, 2))) <= 1.0e-12_wp*(m1 + m2)/len, &
                 'rotation about s at N2: forces in equilibrium')
      call check(maxval(abs(mom(:, 1) + mom(:, 2) + cross(x0(:, 2) - x0(:, 1), f(:, 2)))) <= &
                 1.0e-10_wp*m2, 'rotation about s at N2: moments in equilibrium')
   end block

   ! ---- end rotation about t at N2 with a shear area (Timoshenko)
   sa = 1.5_wp
   phi = 12.0_wp*ey*itt/(g*sa*len*len)
   block
      real(wp) :: f(3, 2), mom(3, 2), v(3, 2), w(3, 2)
      v = 0.0_wp; w = 0.0_wp
      w(:, 2) = om*e3
      call one_step(sa, v, w, f, mom)
      m1 = ey*itt/(len*(1.0_wp + phi))*(2.0_wp - phi)*th
      m2 = ey*itt/(len*(1.0_wp + phi))*(4.0_wp + phi)*th
      call check_close(dot_product(mom(:, 1), e3), -m1, 0.0_wp, 1.0e-8_wp, &
                       'rotation about t, SA > 0: M1 = E I (2 - phi) theta/(L (1 + phi))')
      call check_close(dot_product(mom(:, 2), e3), -m2, 0.0_wp, 1.0e-8_wp, &
                       'rotation about t, SA > 0: M2 = E I (4 + phi) theta/(L (1 + phi))')
   end block

   ! ---- twist and stretch
   block
      real(wp) :: f(3, 2), mom(3, 2), v(3, 2), w(3, 2)
      v = 0.0_wp; w = 0.0_wp
      w(:, 2) = om*e1
      call one_step(0.0_wp, v, w, f, mom)
      call check_close(dot_product(mom(:, 2), e1), -g*tj*th/len, 0.0_wp, 1.0e-8_wp, &
                       'twist at N2: T = G J theta/L')
      v = 0.0_wp; w = 0.0_wp
      v(:, 2) = om*len*e1             ! strain rate om: L - L0 = om L dt
      call one_step(0.0_wp, v, w, f, mom)
      call check_close(dot_product(f(:, 2), e1), -ey*a*om*dt, 0.0_wp, 1.0e-8_wp, &
                       'stretch: N = E A (L - L0)/L0')
   end block

   call step_bounds()
   call assert_summary()

contains

   !> One pass of one element from rest at x0 with v(n-1/2) = v, w(n-1/2) = w over dt
   !> (x(n) = x0 + dt v); the internal forces and moments subtracted from zero.
   subroutine one_step(sa, v, w, f, mom)
      real(wp), intent(in) :: sa, v(3, 2), w(3, 2)
      real(wp), intent(out) :: f(3, 2), mom(3, 2)
      type(elem_block_t) :: blk
      type(block_result_t) :: res
      call new_block(blk, [a, iss, itt, tj, sa], len)
      f = 0.0_wp; mom = 0.0_wp
      call beam_bs_block(blk, mat, x0 + dt*v, v, w, dt, f, mom, res)
      call check(res%ibad == 0, 'one element: no error')
   end subroutine one_step

   !> A block of one beam element x0(:, 1) - x0(:, 2) of section sec and length l0.
   subroutine new_block(blk, sec, l0)
      type(elem_block_t), intent(out) :: blk
      real(wp), intent(in) :: sec(5), l0
      type(family_t) :: fam
      fam = element_family(ETYPE_BEAM_BS)
      blk%etype = ETYPE_BEAM_BS
      blk%nel = 1; blk%nip = 1; blk%nhv = 0
      allocate(blk%conn(2, 1), blk%elem(1), blk%sig(1, 6, 1), blk%hv(1, 0, 1), blk%vol0(1), &
               blk%relvol(1), blk%eint(1), blk%ehg(1), blk%failed(1))
      blk%conn(:, 1) = [1, 2]
      blk%elem = 1
      blk%sig = 0.0_wp
      blk%vol0 = sec(1)*l0
      blk%relvol = 1.0_wp; blk%eint = 0.0_wp; blk%ehg = 0.0_wp
      blk%failed = .false.
      call blk%es_add(ES_WORK, fam%es_ncol(ES_WORK))
      call blk%es_add(ES_BEAM, fam%es_ncol(ES_BEAM))
      call beam_bs_init(blk, 1, e2, sec)
      call check(blk%esn(ES_BEAM) == BM_RES + 11, 'family row: 19 beam state columns')
   end subroutine new_block

   !> The element step: L/c for a slender element, the bending mode for a thick one.
   subroutine step_bounds()
      type(elem_block_t) :: blk
      type(block_result_t) :: res
      real(wp) :: f(3, 2), mom(3, 2), z(3, 2), c, r2, beta, thin
      c = sqrt(ey/rho)
      thin = 1.0e-3_wp                 ! section 1e-3 x 1e-3 on L = 10: slender
      call new_block(blk, [thin**2, thin**4/12.0_wp, thin**4/12.0_wp, thin**4/6.0_wp, &
                           0.0_wp], len)
      z = 0.0_wp; f = 0.0_wp; mom = 0.0_wp
      call beam_bs_block(blk, mat, x0, z, z, 0.0_wp, f, mom, res)
      call check_close(res%dt, len/c, 0.0_wp, 1.0e-14_wp, 'slender element: step L/c')
      ! the section a, iss, itt on L = 1: r**2 = ITT/A = 1/3; the rotary inertia per nodal
      ! mass max((ISS + ITT)/A, L**2/12) = 5/12, so beta = 5/12 (the bending mode governs)
      x0(:, 2) = x0(:, 1) + e1
      call new_block(blk, [a, iss, itt, tj, 0.0_wp], 1.0_wp)
      f = 0.0_wp; mom = 0.0_wp
      call beam_bs_block(blk, mat, x0, z, z, 0.0_wp, f, mom, res)
      r2 = itt/a
      beta = (iss + itt)/a
      call check_close(res%dt, 2.0_wp/sqrt(12.0_wp*c*c*r2*(1.0_wp + 4.0_wp*beta)/beta), &
                       0.0_wp, 1.0e-14_wp, 'thick element: step of the bending mode')
      call check(res%dt < 1.0_wp/c, 'thick element: below L/c')
      x0(:, 2) = x0(:, 1) + len*e1
   end subroutine step_bounds
end program test_beam
