!> Unit tests of the Belytschko-Lin-Tsay shell (dx_shell_bt, dx_element_types):
!> the through-thickness rules integrate zeta**k exactly up to degree 2n-1 (Gauss) and 2n-3
!> (Lobatto) (Abramowitz & Stegun 1964, 25.4.29 and 25.4.32); the co-rotational frame of a
!> rotated square is orthonormal and right-handed with the square's area; one elastic square
!> element driven by a uniform membrane strain rate and a uniform curvature rate (rotations
!> w_y = kappa x, transverse velocities w = -kappa x/2 so that the transverse shear vanishes)
!> gives, after one step, the nodal forces and moments of the plate resultants
!> N_xx = E t/(1 - nu**2) e, M_xx = E t**3/(12 (1 - nu**2)) kappa (Gauss 2 points are exact for
!> the linear stress through the thickness). Tolerance of the last: the step moves the nodes by
!> |v| dt = 1e-11 of the element size, so the mid-step geometry differs from the square by that
!> much, and the transverse shear, (L/t)**2 = 100 times stiffer than the bending, sees it
!> amplified: 1e-9 relative, checked at 1e-8.
program test_shell
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_element_types, only: elem_block_t, part_t, block_result_t, ES_THK, ETYPE_SHELL_BT, &
                               shell_frame, element_family, family_t
   use dx_shell_bt, only: thickness_rule, shell_bt_block
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp) :: zeta(5), wt(5), e(3, 3), xl(2, 4), area, xe(3, 4), r(3, 3)
   real(wp) :: c, s
   integer :: n
   logical :: ok

   ! ---- through-thickness rules
   do n = 1, 5
      call check_rule(n, .false., 'Gauss', 2*n - 1)
   end do
   do n = 3, 5
      call check_rule(n, .true., 'Lobatto', 2*n - 3)
      call check(zeta(1) == -1.0_wp .and. zeta(n) == 1.0_wp, 'Lobatto: points on the surfaces')
   end do
   call thickness_rule(6, .false., zeta, wt, ok)
   call check(.not. ok, 'Gauss 6 points: not supported')
   call thickness_rule(2, .true., zeta, wt, ok)
   call check(.not. ok, 'Lobatto 2 points: not supported')

   ! ---- frame of a unit square rotated by 30 degrees about x then placed at an offset
   c = cos(0.5235987755982988_wp); s = sin(0.5235987755982988_wp)
   r = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, c, s, 0.0_wp, -s, c], [3, 3])
   xe(:, 1) = matmul(r, [0.0_wp, 0.0_wp, 0.0_wp]) + [1.0_wp, 2.0_wp, 3.0_wp]
   xe(:, 2) = matmul(r, [1.0_wp, 0.0_wp, 0.0_wp]) + [1.0_wp, 2.0_wp, 3.0_wp]
   xe(:, 3) = matmul(r, [1.0_wp, 1.0_wp, 0.0_wp]) + [1.0_wp, 2.0_wp, 3.0_wp]
   xe(:, 4) = matmul(r, [0.0_wp, 1.0_wp, 0.0_wp]) + [1.0_wp, 2.0_wp, 3.0_wp]
   call shell_frame(xe, e, xl, area)
   call check_close(area, 1.0_wp, 4.0_wp*epsilon(1.0_wp), 0.0_wp, 'frame: area of the square')
   call check(maxval(abs(matmul(transpose(e), e) - reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
              1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3]))) < 8.0_wp*epsilon(1.0_wp), &
              'frame: orthonormal')
   call check(maxval(abs(e - r)) < 8.0_wp*epsilon(1.0_wp), &
              'frame: e1 along side 1-2, e3 the normal (the rotation itself)')
   call check(maxval(abs(xl - reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, &
              0.0_wp, 1.0_wp], [2, 4]))) < 8.0_wp*epsilon(1.0_wp), 'frame: local coordinates')

   call one_element_resultants()
   call assert_summary()

contains

   !> The n-point rule (lobatto or Gauss, called name) exists and integrates zeta**k exactly
   !> on [-1, 1] for k = 0..kmax; leaves its points and weights in zeta, wt.
   subroutine check_rule(n, lobatto, name, kmax)
      integer, intent(in) :: n, kmax
      logical, intent(in) :: lobatto
      character(*), intent(in) :: name
      real(wp) :: exact, q
      integer :: k
      logical :: ok
      call thickness_rule(n, lobatto, zeta, wt, ok)
      call check(ok, name//' rule with '//achar(48 + n)//' points exists')
      do k = 0, kmax
         exact = merge(2.0_wp/real(k + 1, wp), 0.0_wp, mod(k, 2) == 0)
         q = sum(wt(1:n)*zeta(1:n)**k)
         call check_close(q, exact, 4.0_wp*epsilon(1.0_wp), 0.0_wp, &
                          name//' '//achar(48 + n)//': zeta**'//achar(48 + k)//' exact')
      end do
   end subroutine check_rule

   subroutine one_element_resultants()
      type(mat_elastic_t) :: mat
      type(error_t), allocatable :: err
      type(elem_block_t) :: blk
      type(part_t) :: part
      type(block_result_t) :: res
      type(family_t) :: fam
      real(wp), parameter :: ey = 210.0_wp, pr = 0.3_wp, t = 0.1_wp, dt = 1.0e-11_wp
      real(wp), parameter :: erate = 1.0_wp, krate = 1.0_wp
      real(wp) :: x(3, 4), v(3, 4), w(3, 4), f(3, 4), mom(3, 4), nxx, mxx
      integer :: k
      mat%ro = 7.85e-6_wp; mat%e = ey; mat%pr = pr
      call mat%setup(err)
      call check(.not. allocated(err), 'elastic setup')
      fam = element_family(ETYPE_SHELL_BT)
      blk%etype = ETYPE_SHELL_BT
      blk%nel = 1
      blk%nip = 2
      blk%nhv = 0
      allocate(blk%conn(4, 1), blk%elem(1), blk%sig(1, 6, 2), blk%hv(1, 0, 2), blk%vol0(1), &
               blk%relvol(1), blk%eint(1), blk%ehg(1), blk%failed(1))
      blk%conn(:, 1) = [1, 2, 3, 4]
      blk%elem = 1
      blk%sig = 0.0_wp
      blk%vol0 = t
      blk%relvol = 1.0_wp
      blk%eint = 0.0_wp
      blk%ehg = 0.0_wp
      blk%failed = .false.
      call blk%es_add(ES_THK, fam%es_ncol(ES_THK))
      blk%es(1, blk%esc(ES_THK)) = t
      part%qh = 0.0_wp          ! no hourglass forces: a uniform field has none anyway
      x = reshape([0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, &
                   0.0_wp, 1.0_wp, 0.0_wp], [3, 4])
      ! v_x = e x, w_y = kappa x, v_z = -kappa x/2 (zero transverse shear), at t(n) = dt
      v = 0.0_wp; w = 0.0_wp
      do k = 1, 4
         v(1, k) = erate*x(1, k)
         v(3, k) = -0.5_wp*krate*x(1, k)
         w(2, k) = krate*x(1, k)
      end do
      x = x + dt*v
      f = 0.0_wp; mom = 0.0_wp
      call shell_bt_block(blk, mat, part, 1.0_wp, .false., 0, x, v, w, dt, f, mom, res)
      call check(res%ibad == 0, 'one element: no error')
      nxx = ey*t/(1.0_wp - pr**2)*erate*dt
      mxx = ey*t**3/(12.0_wp*(1.0_wp - pr**2))*krate*dt
      ! f_x(node k) = -A B1_k N_xx, m_y(node k) = -A B1_k M_xx, B1 = [-1, 1, 1, -1]/2
      call check_close(f(1, 2), -0.5_wp*nxx, 0.0_wp, 1.0e-8_wp, 'one element: N_xx = E t e/(1-nu^2)')
      call check_close(f(1, 1), 0.5_wp*nxx, 0.0_wp, 1.0e-8_wp, 'one element: node 1 force')
      call check_close(mom(2, 2), -0.5_wp*mxx, 0.0_wp, 1.0e-8_wp, &
                       'one element: M_xx = E t^3 kappa/(12 (1-nu^2))')
      call check_close(mom(2, 4), 0.5_wp*mxx, 0.0_wp, 1.0e-8_wp, 'one element: node 4 moment')
      call check(abs(f(3, 2)) <= 1.0e-8_wp*nxx, 'one element: no transverse shear force')
      call check_close(res%dt, 1.0_wp/sqrt(ey/(mat%ro*(1.0_wp - pr**2))), 0.0_wp, 1.0e-8_wp, &
                       'one element: stable step A/max(L)/c, c = sqrt(E/(rho(1-nu^2)))')
      ! ISTUPD = 1: the thickness follows the laminae's thickness strain, -nu/(1-nu) e_xx
      ! for plane stress (the curvature's thickness strains cancel over the symmetric rule)
      blk%sig = 0.0_wp
      blk%es(1, blk%esc(ES_THK)) = t
      f = 0.0_wp; mom = 0.0_wp
      call shell_bt_block(blk, mat, part, 1.0_wp, .false., 1, x, v, w, dt, f, mom, res)
      call check_close(blk%es(1, blk%esc(ES_THK)), t*(1.0_wp - pr/(1.0_wp - pr)*erate*dt), &
                       0.0_wp, 1.0e-15_wp, 'ISTUPD = 1: t (1 - nu/(1-nu) e_xx)')
   end subroutine one_element_resultants
end program test_shell
