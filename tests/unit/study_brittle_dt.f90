!> Study (make studies, scripts/studies_hirate.sh part 4): the time-step error of the brittle
!> damage models on the material-point driver paths of tests/unit/test_mat_brittle.f90, against
!> the continuous-time equations of docs/damage.md, with the run time and the observed order.
!> The unit test asserts the discrete update to round-off; this measures how the discrete D
!> converges to the time integral it approximates. Fused silica (E 72 GPa, nu 0.17, rho 2.2e-6;
!> units mm, ms, kg, GPa), ramps over T = 1e-4 ms in N = 25 ... 1600 equal steps:
!>  - MODEL 1 (modified Tuler-Butcher), uniaxial strain x = r t: D = (1/KF) int (sigma1 -
!>    SIGR)_+**2 dt, sigma1 = 4G x/3 + K ln(1 + x); and triaxial tension, sigma1 = 3K ln(1 + x);
!>  - MODEL 2 (JH-2 damage), shear under a growing pressure (V = exp(-3 a t), eps_xy = b t,
!>    perfectly plastic from t_y = SIGY/(2 sqrt3 G b)): D = int (2b/sqrt3)/eps_f(p(t)) dt,
!>    eps_f = D1 ((p + T)/PHEL)**D2, p = 3 K a t;
!>  - MODEL 3 (rate-limited growth), uniaxial strain: D = (CG c_L (T - t*)/LC)**3, sigma1(t*) =
!>    SIGT;
!>  - crack model, uniaxial strain: the time the first crack opens against sigma_xx(t*) = FT
!>    (hypoelastic: sigma_xx = (K + 4G/3) x). MODEL 3 and the crack open at the first step end
!>    past t*: their error is that quantization (below one step, falling with dt, but its
!>    value, and so the pointwise order, jumps with where t* falls in a step).
!> KF, D1 and LC are set so that the continuous D(T) is 0.5. References by 5-point
!> Gauss-Legendre on 4000 panels split at the onset (bisection to round-off): 1e-15.
!> Run time: system_clock over repeats of each path (at least 2e5 point-updates).
program study_brittle_dt
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_brittle, only: mat_brittle_t
   use dx_mat_crack, only: mat_crack_t
   implicit none
   real(wp), parameter :: e = 72.0_wp, nu = 0.17_wp, rho = 2.2e-6_wp, tt = 1.0e-4_wp
   real(wp), parameter :: g = e/(2.0_wp*(1.0_wp + nu)), kb = e/(3.0_wp*(1.0_wp - 2.0_wp*nu))
   real(wp), parameter :: r = 2.0e-3_wp/tt          ! strain rate of the tension ramps
   real(wp), parameter :: s3 = sqrt(3.0_wp)
   integer, parameter :: nsteps(7) = [25, 50, 100, 200, 400, 800, 1600]
   character(len=*), parameter :: names(5) = [character(len=40) :: &
      'MODEL 1, uniaxial strain tension', 'MODEL 1, triaxial tension', &
      'MODEL 2, shear under pressure', 'MODEL 3, uniaxial strain tension', &
      'crack, uniaxial strain: opening time']
   real(wp) :: ref, val, err(7), secs, a, b, ty, tstar, cl
   integer :: path, k

   print '(a)', '| path | N | dt [ms] | value | reference | error | run time [us] |'
   print '(a)', '|---|---|---|---|---|---|---|'
   do path = 1, 5
      do k = 1, size(nsteps)
         call run(path, nsteps(k), val, ref, secs)
         err(k) = val - ref
         print '(a,a,a,i0,a,es9.2,a,es15.8,a,es15.8,a,es10.3,a,f10.2,a)', '| ', trim(names(path)), &
            ' | ', nsteps(k), ' | ', tt/nsteps(k), ' | ', val, ' | ', ref, ' | ', err(k), ' | ', &
            1.0e6_wp*secs, ' |'
      end do
      write (*, '(a)', advance='no') '| '//trim(names(path))//': observed order N -> 2N |'
      do k = 1, size(nsteps) - 1
         if (abs(err(k)) > 0.0_wp .and. abs(err(k + 1)) > 0.0_wp) then
            write (*, '(f6.2,a)', advance='no') log(abs(err(k)/err(k + 1)))/log(2.0_wp), ' |'
         else
            write (*, '(a)', advance='no') ' - |'
         end if
      end do
      print '(a)', ''
   end do

contains

   pure real(wp) function s1_uni(t)
      real(wp), intent(in) :: t
      s1_uni = 4.0_wp*g*r*t/3.0_wp + kb*log(1.0_wp + r*t)
   end function s1_uni

   pure real(wp) function s1_tri(t)
      real(wp), intent(in) :: t
      s1_tri = 3.0_wp*kb*log(1.0_wp + r*t)
   end function s1_tri

   !> t in [0, tt] where f(t) = level (f increasing), by bisection to round-off.
   real(wp) function onset(path, level) result(t)
      integer, intent(in) :: path
      real(wp), intent(in) :: level
      real(wp) :: lo, hi, f
      integer :: it
      lo = 0.0_wp; hi = tt
      do it = 1, 200
         t = 0.5_wp*(lo + hi)
         select case (path)
         case (2)
            f = s1_tri(t)
         case (5)        ! the crack model is hypoelastic: sigma_xx = (K + 4G/3) x
            f = (kb + 4.0_wp*g/3.0_wp)*r*t
         case default
            f = s1_uni(t)
         end select
         if (f < level) then
            lo = t
         else
            hi = t
         end if
      end do
   end function onset

   !> The integrand of the continuous D of paths 1-3 at time t (before the scale KF or D1).
   real(wp) function integrand(path, t) result(f)
      integer, intent(in) :: path
      real(wp), intent(in) :: t
      select case (path)
      case (1)
         f = max(0.0_wp, s1_uni(t) - 0.1_wp)**2
      case (2)
         f = max(0.0_wp, s1_tri(t) - 0.1_wp)**2
      case default        ! JH-2 with D1 = 1: (2b/sqrt3)/((p + T)/PHEL)**D2
         f = (2.0_wp*b/s3)/(((3.0_wp*kb*a*t + 0.15_wp)/2.0_wp)**0.7_wp)
      end select
   end function integrand

   !> 5-point Gauss-Legendre on np panels over [t0, t1].
   real(wp) function quad(path, t0, t1) result(s)
      integer, intent(in) :: path
      real(wp), intent(in) :: t0, t1
      real(wp), parameter :: x5(5) = [-0.9061798459386640_wp, -0.5384693101056831_wp, 0.0_wp, &
                                      0.5384693101056831_wp, 0.9061798459386640_wp]
      real(wp), parameter :: w5(5) = [0.2369268850561891_wp, 0.4786286704993665_wp, &
                                      0.5688888888888889_wp, 0.4786286704993665_wp, &
                                      0.2369268850561891_wp]
      integer, parameter :: np = 4000
      real(wp) :: h, c
      integer :: i, j
      s = 0.0_wp
      h = (t1 - t0)/np
      do i = 1, np
         c = t0 + (i - 0.5_wp)*h
         do j = 1, 5
            s = s + 0.5_wp*h*w5(j)*integrand(path, c + 0.5_wp*h*x5(j))
         end do
      end do
   end function quad

   subroutine run(path, n, val, ref, secs)
      integer, intent(in) :: path, n
      real(wp), intent(out) :: val, ref, secs
      type(mat_brittle_t) :: m
      type(mat_crack_t) :: mc
      type(error_t), allocatable :: err
      real(wp) :: sig(1, 6), hv(1, 21), deps(1, 6), dt, t, rv, topen
      integer :: i, rep, nrep, c0, c1, crate, ierr(1)
      dt = tt/n
      m%ro = rho; m%e = e; m%pr = nu; m%sigy = 10.0_wp; m%gfr = 0.5_wp
      m%pf(1:3) = [0.0_wp, 1.0_wp, 5.0_wp]
      m%yf(1:3) = [0.0_wp, 0.5_wp, 1.5_wp]
      select case (path)
      case (1, 2)
         tstar = onset(path, 0.1_wp)
         ref = quad(path, tstar, tt)
         m%model = 1
         m%p(1:3) = [0.1_wp, 2.0_wp, 2.0_wp*ref]     ! KF = 2 int: D(T) = 0.5
         ref = 0.5_wp
      case (3)
         m%model = 2
         m%sigy = 0.5_wp
         a = 1.0_wp/(3.0_wp*kb*tt)                     ! p(T) = 1 GPa
         b = m%sigy/(2.0_wp*s3*g*0.25_wp*tt)           ! yield at t_y = T/4
         ty = 0.25_wp*tt
         ref = quad(path, ty, tt)
         m%p(1:5) = [2.0_wp*ref, 0.7_wp, 2.0_wp, 0.15_wp, 0.0_wp]   ! D1: D(T) = 0.5
         ref = 0.5_wp
      case (4)
         m%model = 3
         tstar = onset(1, 0.1_wp)
         cl = sqrt((kb + 4.0_wp*g/3.0_wp)/rho)
         m%p(1:3) = [0.1_wp, 0.4_wp, 0.4_wp*cl*(tt - tstar)/0.5_wp**(1.0_wp/3.0_wp)]
         ref = 0.5_wp
      case default
         mc%ro = rho; mc%e = e; mc%pr = nu; mc%ft = 0.1_wp
         mc%sigc = 6.0_wp; mc%ycf = 1.0_wp; mc%epsc = 0.01_wp
         call mc%setup(err)
         ref = onset(5, 0.1_wp)
      end select
      if (path <= 4) call m%setup(err)
      if (allocated(err)) error stop 'study_brittle_dt: setup failed'
      nrep = max(1, 200000/n)
      call system_clock(c0, crate)
      do rep = 1, nrep
         sig = 0.0_wp; hv = 0.0_wp
         topen = -1.0_wp
         do i = 1, n
            t = i*dt
            deps = 0.0_wp
            select case (path)
            case (1, 4, 5)
               deps(1, 1) = r*dt
               rv = 1.0_wp + r*t
            case (2)
               deps(1, 1:3) = r*dt
               rv = (1.0_wp + r*t)**3
            case default
               deps(1, 1:3) = -a*dt
               deps(1, 4) = b*dt
               rv = exp(-3.0_wp*a*t)
            end select
            ierr = 0
            if (path == 5) then
               call mc%update(1, dt, deps, [rv], [0.0_wp], sig, hv, ierr)
            else
               call m%update(1, dt, deps, [rv], [0.0_wp], sig, hv(:, 1:15), ierr)
            end if
            if (path == 5 .and. topen < 0.0_wp .and. hv(1, 1) == 1.0_wp) topen = t
         end do
      end do
      call system_clock(c1)
      secs = real(c1 - c0, wp)/real(crate, wp)/nrep
      val = merge(topen, hv(1, 2), path == 5)
   end subroutine run
end program study_brittle_dt
