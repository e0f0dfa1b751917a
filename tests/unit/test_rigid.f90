!> Unit tests of the rigid-body mass properties and rotations (dx_rigid_mass) against closed
!> forms: a frustum of a square pyramid (a trilinear, non-affine hexahedron: bottom a x a,
!> top b x b, height h) has V = h (a^2 + ab + b^2)/3, z_c = h (a^2 + 2ab + 3b^2) /
!> (4 (a^2 + ab + b^2)) and I_zz = rho h (b^5 - a^5) / (30 (b - a)) about its axis, to 1e-13;
!> the principal axes of Q diag(1, 2, 3) Q^T are (1, 2, 3) and the columns of Q to 1e-13, a
!> degenerate tensor still gives a proper rotation; an axis rotation is exact. Deck reading:
!> a deck without rigid bodies allocates neither model%rigid nor model%body_loads; the punch
!> deck's *MAT_RIGID CON1/CON2, prescribed rigid motion and merged mass (3900 to 1e-13).
program test_rigid
   use dx_kinds, only: wp
   use dx_rigid_mass, only: inertia_about, principal_axes, rotation_about
   use dx_element_types, only: elem_moments, ETYPE_HEX8_1PT
   use dx_assert, only: check, check_close, assert_summary
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_deck_model, only: read_deck
   implicit none
   real(wp), parameter :: a = 2.0_wp, b = 1.0_wp, h = 1.5_wp, rho = 3.0_wp
   real(wp), parameter :: pi = 3.14159265358979323846_wp
   real(wp) :: xe(3, 8), vol, m1(3), m2(3, 3), xc(3), ten(3, 3), ip(3), q(3, 3), q0(3, 3)
   real(wp) :: r(3, 3), eye(3, 3), zc, izz
   integer :: k

   ! ---- frustum, centred on the z axis, shifted so the reference point is not the centre
   xe(:, 1) = [-a/2, -a/2, 0.0_wp]; xe(:, 2) = [a/2, -a/2, 0.0_wp]
   xe(:, 3) = [a/2, a/2, 0.0_wp];   xe(:, 4) = [-a/2, a/2, 0.0_wp]
   xe(:, 5) = [-b/2, -b/2, h];      xe(:, 6) = [b/2, -b/2, h]
   xe(:, 7) = [b/2, b/2, h];        xe(:, 8) = [-b/2, b/2, h]
   do k = 1, 8
      xe(:, k) = xe(:, k) + [10.0_wp, -3.0_wp, 2.0_wp]
   end do
   call elem_moments(ETYPE_HEX8_1PT, xe, [9.0_wp, -2.0_wp, 1.0_wp], vol, m1, m2)
   call check_close(vol, h*(a*a + a*b + b*b)/3.0_wp, 0.0_wp, 1.0e-13_wp, 'frustum volume')
   xc = [9.0_wp, -2.0_wp, 1.0_wp] + m1/vol
   zc = h*(a*a + 2*a*b + 3*b*b)/(4*(a*a + a*b + b*b))
   call check_close(xc(1), 10.0_wp, 1.0e-13_wp, 0.0_wp, 'frustum centre x')
   call check_close(xc(2), -3.0_wp, 1.0e-13_wp, 0.0_wp, 'frustum centre y')
   call check_close(xc(3), 2.0_wp + zc, 0.0_wp, 1.0e-13_wp, 'frustum centre z')
   ten = inertia_about(rho*vol, rho*m1, rho*m2, [9.0_wp, -2.0_wp, 1.0_wp], xc)
   izz = rho*h*(b**5 - a**5)/(30.0_wp*(b - a))
   call check_close(ten(3, 3), izz, 0.0_wp, 1.0e-13_wp, 'frustum I_zz about its axis')
   call check_close(ten(1, 1), ten(2, 2), 0.0_wp, 1.0e-13_wp, 'frustum I_xx = I_yy')
   call check_close(ten(1, 2), 0.0_wp, 1.0e-13_wp*izz, 0.0_wp, 'frustum I_xy = 0')
   call check_close(ten(1, 3), 0.0_wp, 1.0e-13_wp*izz, 0.0_wp, 'frustum I_xz = 0')

   ! ---- principal axes of a rotated diagonal tensor
   q0 = matmul(rotation_about(3, 0.3_wp), matmul(rotation_about(1, -1.1_wp), &
               rotation_about(2, 0.7_wp)))
   ten = matmul(q0, matmul(reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, &
                0.0_wp, 3.0_wp], [3, 3]), transpose(q0)))
   call principal_axes(ten, ip, q)
   do k = 1, 3
      call check_close(ip(k), real(k, wp), 0.0_wp, 1.0e-13_wp, 'principal moment '//achar(48 + k))
      call check_close(abs(dot_product(q(:, k), q0(:, k))), 1.0_wp, 1.0e-13_wp, 0.0_wp, &
                       'principal axis '//achar(48 + k))
   end do
   eye = 0.0_wp
   do k = 1, 3
      eye(k, k) = 1.0_wp
   end do
   call check(maxval(abs(matmul(transpose(q), q) - eye)) <= 1.0e-14_wp, 'axes orthonormal')
   call check_close(det(q), 1.0_wp, 1.0e-14_wp, 0.0_wp, 'axes right-handed')
   ! degenerate (symmetric top)
   ten = 0.0_wp
   ten(1, 1) = 2.0_wp; ten(2, 2) = 2.0_wp; ten(3, 3) = 1.0_wp
   ten(1, 2) = 1.0e-300_wp; ten(2, 1) = 1.0e-300_wp
   call principal_axes(ten, ip, q)
   call check_close(ip(1), 1.0_wp, 0.0_wp, 1.0e-15_wp, 'symmetric top: axial moment')
   call check_close(ip(3), 2.0_wp, 0.0_wp, 1.0e-15_wp, 'symmetric top: transverse moment')
   call check_close(det(q), 1.0_wp, 1.0e-14_wp, 0.0_wp, 'symmetric top: proper rotation')

   ! ---- exact axis rotations
   r = rotation_about(3, pi/2)
   call check(maxval(abs(matmul(r, [1.0_wp, 0.0_wp, 0.0_wp]) - [0.0_wp, 1.0_wp, 0.0_wp])) &
              <= 1.0e-15_wp, 'rotation about z by pi/2 maps x to y')
   r = rotation_about(1, 1.234_wp)
   call check(maxval(abs(matmul(transpose(r), r) - eye)) <= 1.0e-15_wp, 'rotation orthogonal')

   ! ---- decks (run from the top directory): nothing allocated without rigid bodies
   call deck_checks()
   call assert_summary()
contains
   subroutine deck_checks()
      type(model_t) :: md
      type(error_t), allocatable :: err
      call read_deck('tests/regression/elastic_wave/deck.k', md, err)
      call check(.not. allocated(err), 'deformable deck reads')
      call check(.not. allocated(md%rigid), 'deformable deck: model%rigid not allocated')
      call check(.not. allocated(md%body_loads), 'deformable deck: no body loads allocated')
      call read_deck('tests/regression/rigid_punch_prescribed/deck.k', md, err)
      call check(.not. allocated(err), 'punch deck reads')
      if (allocated(err)) return
      call check(allocated(md%rigid), 'punch deck: model%rigid allocated')
      call check(size(md%rigid%bodies) == 1, 'punch deck: one rigid body')
      associate (bd => md%rigid%bodies(1))
         call check(bd%label == 2, 'punch: body label = part id 2')
         call check(all(bd%fix_t .eqv. [.true., .true., .false.]), 'punch: CON1 = 4 fixes x, y')
         call check(all(bd%fix_r), 'punch: CON2 = 7 fixes all rotations')
         call check(size(bd%motions) == 1, 'punch: one prescribed motion')
         call check(bd%motions(1)%dof == 3 .and. bd%motions(1)%vad == 0, 'punch: DOF 3, VAD 0')
         call check_close(bd%motions(1)%sf, -1.0_wp, 0.0_wp, 0.0_wp, 'punch: SF')
         call check_close(bd%mass, 3900.0_wp, 0.0_wp, 1.0e-13_wp, &
                          'punch: mass 1950 + 1950 lumped from the block')
         call check(count(md%rigid%node_body > 0) == 18, 'punch: 18 rigid nodes')
      end associate
      call read_deck('tests/regression/rigid_free_fall/deck.k', md, err)
      call check(.not. allocated(err), 'free-fall deck reads')
      if (allocated(err)) return
      call check(allocated(md%body_loads), 'free fall: body loads allocated')
      call check(size(md%body_loads) == 1, 'free fall: one body load')
      call check(md%body_loads(1)%dir == 3, 'free fall: *LOAD_BODY_Z acts along z')
   end subroutine deck_checks

   pure real(wp) function det(m)
      real(wp), intent(in) :: m(3, 3)
      det = m(1, 1)*(m(2, 2)*m(3, 3) - m(3, 2)*m(2, 3)) - m(1, 2)*(m(2, 1)*m(3, 3) - &
            m(3, 1)*m(2, 3)) + m(1, 3)*(m(2, 1)*m(3, 2) - m(3, 1)*m(2, 2))
   end function det
end program test_rigid
