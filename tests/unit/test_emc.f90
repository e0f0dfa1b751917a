!> Unit tests of the energy-momentum conserving rigid-body solver (dx_emc_solver,
!> dx_emc_contact, dx_emc_build):
!> - Cayley transform: orthogonal, fixes its axis, and (R - I) s = th x ((I + R)/2 s), the
!>   identity behind the mid-configuration moment arms (1e-15);
!> - torque-free body, J = diag(1, 2, 3), W0 = (1, 10, 1) (unstable middle axis), dt = 0.05,
!>   10^4 steps (physics-references 1.2): KE to 1e-11 (measured 2.1e-12: round-off of the
!>   10^4 Cayley rotations), spatial angular momentum and R^T R = I to 1e-12;
!>   second order: the error against RK4 (dt 1e-4) at t = 2 falls by 4 +- 0.4 when dt halves;
!> - head-on penalty collision of two equal free spheres (smoothed): velocities exchanged
!>   (elastic, equal masses) to 1e-12 after separation, for dt = 1e-3 and 1e-1 of the contact
!>   duration's scale; energy and momentum at every step to 1e-13;
!> - sphere fit: centre and radius of exact sphere points to 1e-12, the fit error of one
!>   point pushed out by 1e-3 R is reported in [0.5e-3, 1e-3] (the fit absorbs part of it;
!>   measured 8.6e-4).
program test_emc
   use dx_kinds, only: wp
   use dx_assert, only: check, check_close, assert_summary
   use dx_emc_types, only: emc_system_t
   use dx_emc_solver, only: emc_state_t, emc_try_step, emc_energy, emc_momenta, cayley, &
                            newton_report_t
   use dx_emc_build, only: fit_sphere
   implicit none
   call test_cayley()
   call test_free_body()
   call test_two_spheres(1.0e-3_wp)
   call test_two_spheres(2.0e-1_wp)
   call test_fit()
   call assert_summary()

contains

   function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   subroutine empty_system(es, nb)
      type(emc_system_t), intent(out) :: es
      integer, intent(in) :: nb
      allocate(es%defs(0), es%facets(0), es%snodes(3, 0), es%sphere(nb))
      allocate(es%fac_ptr(nb + 1), es%sn_ptr(nb + 1))
      es%fac_ptr = 1
      es%sn_ptr = 1
      es%maxit = 20
      es%rtol = 1.0e-15_wp
   end subroutine empty_system

   subroutine one_body(st, j, w)
      type(emc_state_t), intent(out) :: st
      real(wp), intent(in) :: j(3), w(3)
      integer :: i
      st%nb = 1
      allocate(st%m(1), st%j(3, 1), st%xc(3, 1), st%v(3, 1), st%r(3, 3, 1), st%w(3, 1))
      st%m = 1.0_wp; st%j(:, 1) = j; st%xc = 0.0_wp; st%v = 0.0_wp; st%w(:, 1) = w
      st%r = 0.0_wp
      do i = 1, 3
         st%r(i, i, 1) = 1.0_wp
      end do
   end subroutine one_body

   subroutine test_cayley()
      real(wp) :: th(3), r(3, 3), s(3), e(3, 3)
      integer :: i
      th = [0.3_wp, -1.2_wp, 0.7_wp]
      s = [1.0_wp, 2.0_wp, -0.5_wp]
      r = cayley(th)
      e = matmul(transpose(r), r)
      do i = 1, 3
         e(i, i) = e(i, i) - 1.0_wp
      end do
      call check_close(maxval(abs(e)), 0.0_wp, 1.0e-15_wp, 0.0_wp, 'cayley: R^T R = I')
      call check_close(maxval(abs(matmul(r, th) - th)), 0.0_wp, 1.0e-15_wp, 0.0_wp, &
                       'cayley: R th = th')
      call check_close(maxval(abs(matmul(r, s) - s - cross(th, 0.5_wp*(s + matmul(r, s))))), &
                       0.0_wp, 2.0e-15_wp, 0.0_wp, 'cayley: (R - I) s = th x (s + R s)/2')
   end subroutine test_cayley

   !> Euler's equations J dW/dt = (J W) x W by RK4
   function rk4_w(j, w0, t, h) result(w)
      real(wp), intent(in) :: j(3), w0(3), t, h
      real(wp) :: w(3), k1(3), k2(3), k3(3), k4(3)
      integer :: n, i
      n = nint(t/h)
      w = w0
      do i = 1, n
         k1 = euler_f(j, w); k2 = euler_f(j, w + 0.5_wp*h*k1)
         k3 = euler_f(j, w + 0.5_wp*h*k2); k4 = euler_f(j, w + h*k3)
         w = w + h/6.0_wp*(k1 + 2*k2 + 2*k3 + k4)
      end do
   end function rk4_w

   function euler_f(j, x) result(d)
      real(wp), intent(in) :: j(3), x(3)
      real(wp) :: d(3)
      d = cross(j*x, x)/j
   end function euler_f

   subroutine test_free_body()
      type(emc_system_t) :: es
      type(emc_state_t) :: st
      real(wp) :: j(3), w0(3), ke0, pi0(3), e(3, 3), kemax, pimax, wref(3), err(2), dt
      integer :: n, i, lvl
      logical :: ok
      j = [1.0_wp, 2.0_wp, 3.0_wp]
      w0 = [1.0_wp, 10.0_wp, 1.0_wp]
      call empty_system(es, 1)
      call one_body(st, j, w0)
      ke0 = emc_energy(st)
      pi0 = matmul(st%r(:, :, 1), j*st%w(:, 1))
      kemax = 0.0_wp; pimax = 0.0_wp
      do n = 1, 10000
         call step(es, st, 0.05_wp, ok)
         if (.not. ok) exit
         kemax = max(kemax, abs(emc_energy(st) - ke0)/ke0)
         pimax = max(pimax, norm2(matmul(st%r(:, :, 1), j*st%w(:, 1)) - pi0)/norm2(pi0))
      end do
      call check(ok, 'free body: 10^4 Newton steps converge')
      ! momentum-form update and cay - I without the rounded 1 (measured 5.4e-14, 4.0e-15;
      ! 2.1e-12 and 9.2e-13 before)
      call check_close(kemax, 0.0_wp, 1.0e-12_wp, 0.0_wp, 'free body: KE drift (10^4 steps)')
      call check_close(pimax, 0.0_wp, 1.0e-13_wp, 0.0_wp, 'free body: spatial momentum drift')
      e = matmul(transpose(st%r(:, :, 1)), st%r(:, :, 1))
      do i = 1, 3
         e(i, i) = e(i, i) - 1.0_wp
      end do
      call check_close(maxval(abs(e)), 0.0_wp, 1.0e-12_wp, 0.0_wp, 'free body: R^T R = I')
      ! second order against RK4 at t = 2
      wref = rk4_w(j, w0, 2.0_wp, 1.0e-4_wp)
      do lvl = 1, 2
         dt = 0.01_wp/lvl
         call one_body(st, j, w0)
         do n = 1, nint(2.0_wp/dt)
            call step(es, st, dt, ok)
         end do
         err(lvl) = norm2(st%w(:, 1) - wref)
      end do
      call check_close(err(1)/err(2), 4.0_wp, 0.4_wp, 0.0_wp, 'free body: second order '// &
                       '(error ratio for dt/2)')
   end subroutine test_free_body

   subroutine step(es, st, dt, ok)
      type(emc_system_t), intent(in) :: es
      type(emc_state_t), intent(inout) :: st
      real(wp), intent(in) :: dt
      logical, intent(out) :: ok
      type(newton_report_t) :: rep
      call emc_try_step(es, st, dt, rep, ok)
   end subroutine step

   !> two spheres of radius 0.5, mass 2, head-on at 1 m/s, penalty 1e4:
   !> contact scale T = pi sqrt(m_eff/eps) = pi/100 s; dt = frac * T
   subroutine test_two_spheres(frac)
      real(wp), intent(in) :: frac
      type(emc_system_t) :: es
      type(emc_state_t) :: st
      real(wp) :: ke0, p0(3), l0(3), p(3), l(3), lb(3, 2), ps, ls, demax, dpmax, dt, e
      integer :: n
      logical :: ok
      character(16) :: tag
      write(tag, '(es8.1)') frac
      call empty_system(es, 2)
      deallocate(es%defs)
      allocate(es%defs(1))
      es%defs(1)%sb = 1; es%defs(1)%mb = 2; es%defs(1)%eps = 1.0e4_wp
      es%sphere(:)%r = 0.5_wp
      st%nb = 2
      allocate(st%m(2), st%j(3, 2), st%xc(3, 2), st%v(3, 2), st%r(3, 3, 2), st%w(3, 2))
      st%m = 2.0_wp
      st%j = 0.2_wp
      st%xc(:, 1) = [-1.0_wp, 0.0_wp, 0.0_wp]; st%xc(:, 2) = [1.0_wp, 0.0_wp, 0.0_wp]
      st%v(:, 1) = [1.0_wp, 0.0_wp, 0.0_wp];   st%v(:, 2) = 0.0_wp
      st%w(:, 1) = [0.0_wp, 0.0_wp, 3.0_wp];   st%w(:, 2) = [1.0_wp, 0.0_wp, 0.0_wp]
      st%r = 0.0_wp
      st%r(1, 1, :) = 1.0_wp; st%r(2, 2, :) = 1.0_wp; st%r(3, 3, :) = 1.0_wp
      dt = frac*3.14159265358979_wp/100.0_wp
      ke0 = emc_energy(st)
      call emc_momenta(st, p0, lb, l0, ps, ls)
      demax = 0.0_wp; dpmax = 0.0_wp
      do n = 1, nint(3.0_wp/dt)
         call step(es, st, dt, ok)
         if (.not. ok) exit
         e = emc_energy(st) + st%upen
         call emc_momenta(st, p, lb, l, ps, ls)
         demax = max(demax, abs(e - ke0)/ke0)
         dpmax = max(dpmax, norm2(p - p0)/norm2(p0), norm2(l - l0)/max(ls, 1.0_wp))
      end do
      call check(ok, 'two spheres dt/T='//trim(tag)//': Newton converges')
      call check_close(st%v(1, 1), 0.0_wp, 1.0e-12_wp, 0.0_wp, 'two spheres dt/T='// &
                       trim(tag)//': striker stops')
      call check_close(st%v(1, 2), 1.0_wp, 0.0_wp, 1.0e-12_wp, 'two spheres dt/T='// &
                       trim(tag)//': target takes 1 m/s')
      call check_close(demax, 0.0_wp, 1.0e-13_wp, 0.0_wp, 'two spheres dt/T='//trim(tag)// &
                       ': energy at every step')
      call check_close(dpmax, 0.0_wp, 1.0e-13_wp, 0.0_wp, 'two spheres dt/T='//trim(tag)// &
                       ': momenta at every step')
   end subroutine test_two_spheres

   subroutine test_fit()
      real(wp) :: x(3, 26), c(3), r, err
      integer :: i, j, n
      real(wp) :: th, ph
      n = 0
      do i = 0, 4
         do j = 0, 4
            if (n == 26) exit
            th = 0.6_wp*i + 0.1_wp; ph = 1.3_wp*j + 0.2_wp
            n = n + 1
            x(:, n) = [1.0_wp, -2.0_wp, 0.5_wp] + 0.7_wp*[sin(th)*cos(ph), sin(th)*sin(ph), &
                      cos(th)]
         end do
      end do
      x(:, 26) = [1.0_wp, -2.0_wp, 0.5_wp - 0.7_wp]
      call fit_sphere(x, c, r, err)
      call check_close(norm2(c - [1.0_wp, -2.0_wp, 0.5_wp]), 0.0_wp, 1.0e-12_wp, 0.0_wp, &
                       'sphere fit: centre')
      call check_close(r, 0.7_wp, 1.0e-12_wp, 0.0_wp, 'sphere fit: radius')
      call check_close(err, 0.0_wp, 1.0e-12_wp, 0.0_wp, 'sphere fit: error of exact points')
      x(:, 7) = [1.0_wp, -2.0_wp, 0.5_wp] + (x(:, 7) - [1.0_wp, -2.0_wp, 0.5_wp])*1.001_wp
      call fit_sphere(x, c, r, err)
      call check_close(err, 0.75e-3_wp, 0.25e-3_wp, 0.0_wp, 'sphere fit: one point out by 1e-3')
   end subroutine test_fit
end program test_emc
