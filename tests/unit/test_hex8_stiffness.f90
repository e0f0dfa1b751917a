!> Unit tests of the implicit solver's hexahedron (dx_hex8_stiffness, total Lagrangian B-bar):
!> 1. consistency: the tangent stiffness equals central differences of the internal force
!>    at a distorted, stretched and rotated state (*MAT_ELASTIC, St. Venant-Kirchhoff), so the
!>    material and geometric parts and the mean-dilatation terms are linearized exactly.
!>    Bound 1e-6 of max|K|: the difference's truncation error is h^2/6 |f'''| ~ 1e-10 relative
!>    at h = 1e-5 (displacements ~0.3), its round-off eps |f|/h ~ 1e-11 relative;
!> 2. objectivity: a rigid rotation of 60 degrees gives no strain, no stress, no force
!>    (bound 1e-12 of E: round-off of E = (H + H^T + H^T H)/2 with |H| ~ 1);
!> 3. the linear form (NSOLVR 1): f = K u exactly (to 1e-12 relative) and K symmetric;
!> 4. the 4-node tetrahedron (one point) through the same routine: tangent = differences of
!>    the force at finite strain (same bound as 1).
program test_hex8_stiffness
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_hex8_stiffness, only: tl_solid_element
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: el
   type(error_t), allocatable :: err
   real(wp) :: x0(3, 8), u(3, 8), up(3, 8), sc(6, 8), ec(6, 8), hc(0, 8), s(6, 8), e(6, 8), &
               h(0, 8), f(24), fp(24), fm(24), k(24, 24), kd(24, 24), kdum(24, 24), dw, &
               cauchy(6), havg(0), r(3, 3), c, sn, hstep, dmax
   integer :: i, j, ierr, nd, dd
   real(wp), parameter :: pi = acos(-1.0_wp)

   el%ro = 1.0e-9_wp; el%e = 1000.0_wp; el%pr = 0.45_wp
   call el%setup(err)
   call check(.not. allocated(err), 'elastic setup')
   x0 = reshape([0.0_wp, 0.0_wp, 0.0_wp,  1.1_wp, 0.1_wp, -0.05_wp,  1.0_wp, 0.9_wp, 0.1_wp, &
                 -0.1_wp, 1.0_wp, 0.0_wp,  0.05_wp, -0.1_wp, 1.0_wp,  1.0_wp, 0.0_wp, 1.2_wp, &
                 1.2_wp, 1.1_wp, 0.9_wp,  0.0_wp, 0.95_wp, 1.05_wp], [3, 8])
   sc = 0.0_wp; ec = 0.0_wp
   ! a state of finite strain and a 30 degree rotation about z
   c = cos(pi/6.0_wp); sn = sin(pi/6.0_wp)
   r = reshape([c, sn, 0.0_wp, -sn, c, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3])
   do i = 1, 8
      u(:, i) = matmul(r, x0(:, i)*[1.2_wp, 0.9_wp, 1.05_wp] + 0.03_wp*sin(real(3*i, wp))) &
                - x0(:, i)
   end do
   call tl_solid_element(el, x0, u, 1.0_wp, .false., sc, ec, hc, s, e, h, f, .true., k, dw, &
                         cauchy, havg, ierr)
   call check(ierr == 0, 'element at a finite-strain state')
   hstep = 1.0e-5_wp
   do j = 1, 24
      up = u
      nd = (j + 2)/3
      dd = j - 3*(nd - 1)
      up(dd, nd) = up(dd, nd) + hstep
      call tl_solid_element(el, x0, up, 1.0_wp, .false., sc, ec, hc, s, e, h, fp, .false., &
                            kdum, dw, cauchy, havg, ierr)
      up(dd, nd) = up(dd, nd) - 2*hstep
      call tl_solid_element(el, x0, up, 1.0_wp, .false., sc, ec, hc, s, e, h, fm, .false., &
                            kdum, dw, cauchy, havg, ierr)
      kd(:, j) = (fp - fm)/(2.0_wp*hstep)
   end do
   dmax = maxval(abs(k))
   call check_close(maxval(abs(k - kd))/dmax, 0.0_wp, 1.0e-6_wp, 0.0_wp, &
                    'tangent = d fint/du by central differences (relative to max|K|)')

   ! 2. rigid rotation by 60 degrees about (1, 1, 1)/sqrt(3)
   call rotation(pi/3.0_wp, [1.0_wp, 1.0_wp, 1.0_wp]/sqrt(3.0_wp), r)
   do i = 1, 8
      u(:, i) = matmul(r, x0(:, i)) - x0(:, i)
   end do
   call tl_solid_element(el, x0, u, 1.0_wp, .false., sc, ec, hc, s, e, h, f, .false., kdum, &
                         dw, cauchy, havg, ierr)
   call check_close(maxval(abs(e)), 0.0_wp, 1.0e-12_wp, 0.0_wp, 'rigid rotation: strain')
   call check_close(maxval(abs(f))/el%e, 0.0_wp, 1.0e-12_wp, 0.0_wp, &
                    'rigid rotation: internal force / E')

   ! 3. linear form: f = K u, K symmetric
   do i = 1, 8
      u(:, i) = 1.0e-3_wp*[sin(real(i, wp)), cos(real(2*i, wp)), sin(real(5*i, wp))]
   end do
   call tl_solid_element(el, x0, u, 1.0_wp, .true., sc, ec, hc, s, e, h, f, .true., k, dw, &
                         cauchy, havg, ierr)
   fp = matmul(k, reshape(u, [24]))
   call check_close(maxval(abs(fp - f))/maxval(abs(f)), 0.0_wp, 1.0e-12_wp, 0.0_wp, &
                    'linear form: f = K u')
   call check(maxval(abs(k - transpose(k))) <= 1.0e-14_wp*maxval(abs(k)), 'linear form: K symmetric')

   ! 4. tetrahedron
   call tet_consistency()
   call assert_summary()
contains
   subroutine tet_consistency()
      real(wp) :: xt(3, 4), ut(3, 4), upt(3, 4), sct(6, 1), ect(6, 1), hct(0, 1), st(6, 1), &
                  et(6, 1), ht(0, 1), ft(12), fpt(12), fmt(12), kt(12, 12), kdt(12, 12), &
                  kdumt(12, 12)
      integer :: jj, nn, d0
      xt = reshape([0.0_wp, 0.0_wp, 0.0_wp,  1.1_wp, 0.1_wp, -0.05_wp,  0.2_wp, 0.9_wp, 0.1_wp, &
                    0.1_wp, 0.2_wp, 1.05_wp], [3, 4])
      sct = 0.0_wp; ect = 0.0_wp
      do i = 1, 4
         ut(:, i) = matmul(r, xt(:, i)*[1.1_wp, 0.95_wp, 1.02_wp] + 0.02_wp*sin(real(5*i, wp))) &
                    - xt(:, i)
      end do
      call tl_solid_element(el, xt, ut, 1.0_wp, .false., sct, ect, hct, st, et, ht, ft, .true., &
                            kt, dw, cauchy, havg, ierr)
      call check(ierr == 0, 'tetrahedron at a finite-strain state')
      do jj = 1, 12
         nn = (jj + 2)/3
         d0 = jj - 3*(nn - 1)
         upt = ut
         upt(d0, nn) = upt(d0, nn) + hstep
         call tl_solid_element(el, xt, upt, 1.0_wp, .false., sct, ect, hct, st, et, ht, fpt, &
                               .false., kdumt, dw, cauchy, havg, ierr)
         upt(d0, nn) = upt(d0, nn) - 2*hstep
         call tl_solid_element(el, xt, upt, 1.0_wp, .false., sct, ect, hct, st, et, ht, fmt, &
                               .false., kdumt, dw, cauchy, havg, ierr)
         kdt(:, jj) = (fpt - fmt)/(2.0_wp*hstep)
      end do
      call check_close(maxval(abs(kt - kdt))/maxval(abs(kt)), 0.0_wp, 1.0e-6_wp, 0.0_wp, &
                       'tetrahedron: tangent = d fint/du by central differences')
   end subroutine tet_consistency

   subroutine rotation(angle, ax, rm)
      real(wp), intent(in) :: angle, ax(3)
      real(wp), intent(out) :: rm(3, 3)
      real(wp) :: w(3, 3)
      integer :: d
      w = reshape([0.0_wp, ax(3), -ax(2), -ax(3), 0.0_wp, ax(1), ax(2), -ax(1), 0.0_wp], [3, 3])
      rm = sin(angle)*w + (1.0_wp - cos(angle))*matmul(w, w)
      do d = 1, 3
         rm(d, d) = rm(d, d) + 1.0_wp
      end do
   end subroutine rotation
end program test_hex8_stiffness
