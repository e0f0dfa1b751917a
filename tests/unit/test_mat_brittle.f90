!> Material-point driver for the brittle damage models (*DYNX_BRITTLE_DAMAGE MODEL 1-3 and
!> *DYNX_BRITTLE_CRACK): strain paths applied step by step through the material API, D(t) and
!> the stresses asserted against the equations of docs/damage.md. Units mm, ms, kg, GPa; fused
!> silica elastic constants (E 72 GPa, nu 0.17, rho 2.2e-6 kg/mm3; physics-references.md 3.7).
!> Tolerances: every quantity below is a closed form of the step count, so the bounds are
!> round-off: relative 1e-11 (a few ulps times the up to 2000 accumulated additions),
!> absolute 1e-12 GPa for stresses that must vanish (ulps of the 0.1-1 GPa stresses summed).
!> Paths:
!>  - uniaxial strain tension (V = 1 + eps), held: MODEL 1 K = sum dt (sigma1 - SIGR)**LAMBDA,
!>    D = K/KF, the deviator G(D)/G s_i and p = (1 - D) p_i while 0 < D < 1; at D = 1 the
!>    failed material carries no tension (PFMIN = 0, Y_f(0) = 0): sigma = 0;
!>    MODEL 2: D jumps to 1 at the first step with p_i <= -T; MODEL 3 held: D = (D0 + (1 - D0)
!>    (CG c_L t/LC)**3) up to DMAX, where EROD = 1 fails the point;
!>  - triaxial tension (V = (1 + eps)**3): MODEL 1 with sigma1 = -p_i, fully damaged p = PFMIN;
!>  - shear under pressure: MODEL 1 no damage (sigma1 < SIGR), sigma_xy = 2G eps_xy; MODEL 2
!>    perfect plasticity, eps_p = (2 sqrt(3) G e - SIGY)/(3G), D = eps_p/eps_f(p), and the
!>    deviator on Y(D, p) = (1 - D) SIGY + D Y_f(p);
!>  - crack model: uniaxial strain along a skew n: the first crack's normal e1 = +-n (to
!>    1e-12: the Jacobi eigenvectors to round-off), its face traction sigma.n = 0 and, in
!>    uniaxial strain, all of sigma = 0; reversed past zero the crack closes and sigma =
!>    (lambda + 2G) eps along n, lambda eps across; unequal triaxial tension opens three
!>    cracks (D = 1, sigma = 0); shear under pressure: no crack, J2 on Yc(Dc) and Dc = eps_p/EPSC;
!>  - bad parameters refused naming the field.
program test_mat_brittle
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_brittle, only: mat_brittle_t, yield_vs_pressure
   use dx_mat_crack, only: mat_crack_t
   use dx_assert, only: check, check_close, assert_summary
   use dx_strings, only: str
   use dx_vec3, only: cross
   implicit none
   real(wp), parameter :: e = 72.0_wp, nu = 0.17_wp, rho = 2.2e-6_wp, dt = 1.0e-6_wp
   real(wp), parameter :: rtol = 1.0e-11_wp, atol = 1.0e-12_wp
   real(wp), parameter :: g = e/(2.0_wp*(1.0_wp + nu)), kb = e/(3.0_wp*(1.0_wp - 2.0_wp*nu))
   real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]

   call tb_uniaxial()
   call tb_triaxial()
   call tb_shear_pressure()
   call jh2_paths()
   call growth_uniaxial()
   call crack_uniaxial()
   call crack_triaxial()
   call crack_shear_pressure()
   call bad_parameters()
   call assert_summary()

contains

   function base(model) result(m)
      integer, intent(in) :: model
      type(mat_brittle_t) :: m
      type(error_t), allocatable :: err
      m%ro = rho; m%e = e; m%pr = nu; m%sigy = 10.0_wp; m%model = model
      m%gfr = 0.5_wp
      m%pf(1:3) = [0.0_wp, 1.0_wp, 5.0_wp]
      m%yf(1:3) = [0.0_wp, 0.5_wp, 1.5_wp]
      select case (model)
      case (1)
         m%p(1:3) = [0.1_wp, 2.0_wp, 2.0e-6_wp]
      case (2)
         m%sigy = 0.5_wp
         m%p(1:5) = [0.01_wp, 0.7_wp, 2.0_wp, 0.15_wp, 1.0e-3_wp]
      case (3)
         m%p(1:3) = [0.1_wp, 0.4_wp, 5.0_wp]
      end select
      call m%setup(err)
      call check(.not. allocated(err), 'setup of MODEL '//achar(48 + model))
   end function base

   pure real(wp) function vm(s)
      real(wp), intent(in) :: s(6)
      real(wp) :: d(6)
      d = s
      d(1:3) = s(1:3) - (s(1) + s(2) + s(3))/3.0_wp
      vm = sqrt(1.5_wp*sum(w*d**2))
   end function vm

   !> sigma1 of the undamaged point in uniaxial strain eps_xx = x (module header of dx_mat_brittle)
   pure real(wp) function s1_uni(x)
      real(wp), intent(in) :: x
      s1_uni = 4.0_wp*g*x/3.0_wp + kb*log(1.0_wp + x)
   end function s1_uni

   subroutine tb_uniaxial()
      type(mat_brittle_t) :: m
      real(wp) :: sig(1, 6), hv(1, 15), deps(1, 6), x, kk, d, r, s1, pi
      integer :: ierr(1), n
      logical :: mid_checked
      m = base(1)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      r = 2.0e-5_wp
      kk = 0.0_wp
      x = 0.0_wp
      mid_checked = .false.
      do n = 1, 3000
         deps = 0.0_wp
         if (n <= 100) deps(1, 1) = r
         x = r*min(n, 100)
         s1 = s1_uni(x)
         if (s1 > m%p(1)) kk = kk + dt*(s1 - m%p(1))**2
         call m%update(1, dt, deps, [1.0_wp + x], [0.0_wp], sig, hv, ierr)
         d = min(1.0_wp, kk/m%p(3))
         if (n == 100 .or. n == 400 .or. n == 900) call check_close(hv(1, 2), d, 0.0_wp, rtol, &
            'TB uniaxial tension: D = (1/KF) sum dt (sigma1 - SIGR)**2, step '//str(n))
         if (.not. mid_checked .and. d > 0.5_wp .and. d < 1.0_wp) then
            mid_checked = .true.
            pi = -kb*log(1.0_wp + x)
            call check_close(sig(1, 1) - sig(1, 2), (1.0_wp - 0.5_wp*d)*2.0_wp*g*x, 0.0_wp, rtol, &
                             'TB uniaxial: deviator scaled by G(D)/G (GFR 0.5)')
            call check_close(-(sig(1, 1) + sig(1, 2) + sig(1, 3))/3.0_wp, (1.0_wp - d)*pi, 0.0_wp, &
                             rtol, 'TB uniaxial: p = (1 - D) p_i (PFMIN 0)')
         end if
      end do
      call check(mid_checked, 'TB uniaxial: a state with 0.5 < D < 1 was reached')
      call check(hv(1, 2) == 1.0_wp, 'TB uniaxial: D reaches 1')
      call check(maxval(abs(sig)) <= atol, 'TB uniaxial, fully damaged: tension cut-off, sigma = 0')
      call check(ierr(1) == 0, 'TB uniaxial: no point flagged')
   end subroutine tb_uniaxial

   subroutine tb_triaxial()
      type(mat_brittle_t) :: m
      real(wp) :: sig(1, 6), hv(1, 15), deps(1, 6), x, kk, r, s1
      integer :: ierr(1), n
      m = base(1)
      m%pfmin = -0.05_wp
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      r = 2.0e-5_wp
      kk = 0.0_wp
      do n = 1, 2000
         deps = 0.0_wp
         if (n <= 100) deps(1, 1:3) = r
         x = r*min(n, 100)
         s1 = 3.0_wp*kb*log(1.0_wp + x)
         if (s1 > m%p(1)) kk = kk + dt*(s1 - m%p(1))**2
         call m%update(1, dt, deps, [(1.0_wp + x)**3], [0.0_wp], sig, hv, ierr)
         if (n == 150) call check_close(hv(1, 2), min(1.0_wp, kk/m%p(3)), 0.0_wp, rtol, &
                                        'TB triaxial tension: D = K/KF with sigma1 = -p_i')
      end do
      call check(hv(1, 2) == 1.0_wp, 'TB triaxial: D reaches 1')
      call check_close(sig(1, 1), 0.05_wp, atol, rtol, 'TB triaxial, fully damaged: mean stress = -PFMIN')
      call check_close(vm(sig(1, :)), 0.0_wp, atol, 0.0_wp, 'TB triaxial: no deviator')
   end subroutine tb_triaxial

   subroutine tb_shear_pressure()
      type(mat_brittle_t) :: m
      real(wp) :: sig(1, 6), hv(1, 15), deps(1, 6), v
      integer :: ierr(1), n
      m = base(1)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      v = 1.0_wp
      do n = 1, 200
         deps = 0.0_wp
         if (n <= 100) then
            deps(1, 1:3) = -1.0e-4_wp
            v = (1.0_wp - 1.0e-4_wp*n)**3
         else
            deps(1, 4) = 1.0e-4_wp
         end if
         call m%update(1, dt, deps, [v], [0.0_wp], sig, hv, ierr)
      end do
      call check(hv(1, 2) == 0.0_wp, 'TB shear under pressure: sigma1 < SIGR, D = 0')
      call check_close(sig(1, 4), 2.0_wp*g*100*1.0e-4_wp, 0.0_wp, rtol, 'TB shear: sigma_xy = 2G eps_xy')
      call check_close(-sig(1, 1), -kb*log(v), 0.0_wp, rtol, 'TB shear: p = -K ln V')
   end subroutine tb_shear_pressure

   subroutine jh2_paths()
      type(mat_brittle_t) :: m
      real(wp) :: sig(1, 6), hv(1, 15), deps(1, 6), v, p0, ef, ee, ep, d, dprev, y
      integer :: ierr(1), n, nfirst, ncheck
      m = base(2)
      ! uniaxial strain tension: D = 1 at the first step with p_i = -K ln(1 + n r) <= -T
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      nfirst = 0
      do n = 1, 1000
         if (kb*log(1.0_wp + 1.0e-5_wp*n) >= m%p(4)) then
            nfirst = n
            exit
         end if
      end do
      do n = 1, nfirst
         deps = 0.0_wp
         deps(1, 1) = 1.0e-5_wp
         dprev = hv(1, 2)
         call m%update(1, dt, deps, [1.0_wp + 1.0e-5_wp*n], [0.0_wp], sig, hv, ierr)
      end do
      call check(dprev < 1.0_wp .and. hv(1, 2) == 1.0_wp, &
                 'JH-2 uniaxial tension: D = 1 exactly at the first step with p_i <= -T')
      ! shear under pressure, perfect plasticity
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      v = (1.0_wp - 1.0e-4_wp*50)**3
      p0 = -kb*log(v)
      ef = max(m%p(5), m%p(1)*((p0 + m%p(4))/m%p(3))**m%p(2))
      ncheck = 0
      do n = 1, 1200
         deps = 0.0_wp
         if (n <= 50) then
            deps(1, 1:3) = -1.0e-4_wp
            call m%update(1, dt, deps, [(1.0_wp - 1.0e-4_wp*n)**3], [0.0_wp], sig, hv, ierr)
            cycle
         end if
         deps(1, 4) = 1.0e-5_wp
         dprev = hv(1, 2)
         call m%update(1, dt, deps, [v], [0.0_wp], sig, hv, ierr)
         ee = 1.0e-5_wp*(n - 50)
         ep = (2.0_wp*sqrt(3.0_wp)*g*ee - m%sigy)/(3.0_wp*g)
         if (ep <= 0.0_wp .or. hv(1, 2) >= 1.0_wp .or. mod(n, 20) /= 0) cycle
         ncheck = ncheck + 1
         d = hv(1, 2)
         call check_close(hv(1, 1), ep, 1.0e-15_wp, rtol, 'JH-2 shear under pressure: eps_p = '// &
                          '(2 sqrt3 G e - SIGY)/(3G), step '//str(n))
         call check_close(d, ep/ef, 0.0_wp, rtol, 'JH-2: D = eps_p/eps_f(p), step '//str(n))
         y = (1.0_wp - d)*m%sigy + d*yield_vs_pressure(m%pf, m%yf, m%npf, (1.0_wp - d)*p0 + d*p0)
         call check_close(vm(sig(1, :)), y, 0.0_wp, rtol, 'JH-2: sigma_eq = Y(D, p), step '//str(n))
      end do
      call check(ncheck >= 3, 'JH-2: at least 3 damaged plastic states checked')
      call check_close(yield_vs_pressure(m%pf, m%yf, m%npf, p0), 0.5_wp*p0, 0.0_wp, rtol, &
                       'failed curve between (0, 0) and (1, 0.5): Y_f(p0) = p0/2')
   end subroutine jh2_paths

   subroutine growth_uniaxial()
      type(mat_brittle_t) :: m
      type(error_t), allocatable :: err
      real(wp) :: sig(1, 6), hv(1, 15), deps(1, 6), x, cl, d, tact
      integer :: ierr(1), n, nact
      logical :: failed(1), seen_fail
      m = base(3)
      m%d0 = 0.1_wp; m%dmax = 0.9_wp; m%erod = 1
      call m%setup(err)
      call check(.not. allocated(err), 'MODEL 3 with D0 0.1, DMAX 0.9, EROD 1')
      cl = sqrt((kb + 4.0_wp*g/3.0_wp)/rho)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      nact = 0
      seen_fail = .false.
      do n = 1, 2600
         deps = 0.0_wp
         if (n <= 100) deps(1, 1) = 2.0e-5_wp
         x = 2.0e-5_wp*min(n, 100)
         if (s1_uni(x) >= m%p(1)) nact = nact + 1
         call m%update(1, dt, deps, [1.0_wp + x], [0.0_wp], sig, hv, ierr)
         tact = nact*dt
         d = min(0.9_wp, 0.1_wp + 0.9_wp*min(1.0_wp, (0.4_wp*cl*tact/5.0_wp))**3)
         if (n == 150 .or. n == 400) call check_close(hv(1, 2), d, 0.0_wp, rtol, &
            'growth: D = D0 + (1 - D0)(CG c_L t/LC)**3, step '//str(n))
         call m%fails(1, hv, failed)
         if (failed(1) .and. .not. seen_fail) then
            seen_fail = .true.
            call check(hv(1, 2) == 0.9_wp, 'growth: the point fails (EROD 1) when D reaches DMAX')
         end if
      end do
      call check(seen_fail, 'growth: EROD 1 fails the point')
   end subroutine growth_uniaxial

   !> uniaxial strain r n n^T per step along the unit vector n
   function along(n, r) result(d)
      real(wp), intent(in) :: n(3), r
      real(wp) :: d(1, 6)
      d(1, :) = r*[n(1)**2, n(2)**2, n(3)**2, n(1)*n(2), n(2)*n(3), n(3)*n(1)]
   end function along

   function crack_base() result(m)
      type(mat_crack_t) :: m
      type(error_t), allocatable :: err
      m%ro = rho; m%e = e; m%pr = nu; m%ft = 0.1_wp
      m%sigc = 1.0_wp; m%ycf = 0.4_wp; m%epsc = 0.01_wp
      call m%setup(err)
      call check(.not. allocated(err), 'crack model setup')
   end function crack_base

   subroutine crack_uniaxial()
      type(mat_crack_t) :: m
      real(wp) :: sig(1, 6), hv(1, 21), n(3), q(3, 3), t(3), a(3, 3), x, lam
      integer :: ierr(1), k
      m = crack_base()
      lam = kb - 2.0_wp*g/3.0_wp
      n = [1.0_wp, 2.0_wp, 3.0_wp]/sqrt(14.0_wp)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      do k = 1, 200
         call m%update(1, dt, along(n, 2.0e-5_wp), [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      q = reshape(hv(1, 4:12), [3, 3])
      call check_close(abs(dot_product(q(:, 1), n)), 1.0_wp, 1.0e-12_wp, 0.0_wp, &
                       'crack: first fracture surface normal to sigma1 (|e1.n| = 1)')
      call check_close(abs(dot_product(q(:, 1), cross(q(:, 2), q(:, 3)))), 1.0_wp, 1.0e-12_wp, &
                       0.0_wp, 'crack: the triad is orthonormal')
      call check(hv(1, 1) == 1.0_wp .and. hv(1, 2) == 0.0_wp .and. hv(1, 3) == 0.0_wp, &
                 'crack: uniaxial strain opens one crack only')
      a = reshape([sig(1, 1), sig(1, 4), sig(1, 6), sig(1, 4), sig(1, 2), sig(1, 5), &
                   sig(1, 6), sig(1, 5), sig(1, 3)], [3, 3])
      t = matmul(a, n)
      call check(maxval(abs(t)) <= atol, 'crack: the open surface is traction-free (sigma.n = 0)')
      call check(maxval(abs(sig)) <= atol, 'crack: uniaxial strain across an open crack: sigma = 0')
      call check_close(hv(1, 13), 200*2.0e-5_wp, 0.0_wp, rtol, 'crack: void strain ev_11 = eps_nn')
      ! reverse: closes at eps = 0, then elastic compression
      do k = 1, 300
         call m%update(1, dt, along(n, -2.0e-5_wp), [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      x = -100*2.0e-5_wp
      a = reshape([sig(1, 1), sig(1, 4), sig(1, 6), sig(1, 4), sig(1, 2), sig(1, 5), &
                   sig(1, 6), sig(1, 5), sig(1, 3)], [3, 3])
      call check_close(dot_product(n, matmul(a, n)), (lam + 2.0_wp*g)*x, 0.0_wp, 1.0e-9_wp, &
                       'crack closed: sigma_nn = (lambda + 2G) eps (round-off of 500 steps)')
      call check_close(dot_product(q(:, 2), matmul(a, q(:, 2))), lam*x, 0.0_wp, 1.0e-9_wp, &
                       'crack closed: sigma across = lambda eps')
      call check(hv(1, 13) == 0.0_wp, 'crack closed: void strain back to 0')
   end subroutine crack_uniaxial


   subroutine crack_triaxial()
      type(mat_crack_t) :: m
      real(wp) :: sig(1, 6), hv(1, 21), deps(1, 6), q(3, 3)
      integer :: ierr(1), k
      m = crack_base()
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      deps = 0.0_wp
      deps(1, 1:3) = [3.0e-5_wp, 2.0e-5_wp, 1.0e-5_wp]
      do k = 1, 400
         call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      q = reshape(hv(1, 4:12), [3, 3])
      call check_close(abs(q(1, 1)), 1.0_wp, 1.0e-12_wp, 0.0_wp, 'crack triaxial: e1 = x (largest tension)')
      call check(all(hv(1, 1:3) == 1.0_wp), 'crack triaxial: three orthogonal cracks open')
      call check(maxval(abs(sig)) <= atol, 'crack triaxial: sigma = 0')
      call check(hv(1, 21) == 1.0_wp, 'crack triaxial: D = 1')
   end subroutine crack_triaxial

   subroutine crack_shear_pressure()
      type(mat_crack_t) :: m
      real(wp) :: sig(1, 6), hv(1, 21), deps(1, 6), dcp
      integer :: ierr(1), k, nchk
      m = crack_base()
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      nchk = 0
      do k = 1, 1000
         deps = 0.0_wp
         if (k <= 100) then
            deps(1, 1:3) = -2.0e-4_wp
         else
            deps(1, 4) = 2.0e-5_wp
         end if
         dcp = hv(1, 20)
         call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
         if (hv(1, 19) > 0.0_wp .and. hv(1, 20) < 1.0_wp .and. mod(k, 25) == 0) then
            nchk = nchk + 1
            call check_close(vm(sig(1, :)), (1.0_wp - dcp)*m%sigc + dcp*m%ycf, 0.0_wp, rtol, &
                             'crack model compression: sigma_eq = Yc(Dc) (Dc of the step before)')
            call check_close(hv(1, 20), hv(1, 19)/m%epsc, 0.0_wp, rtol, 'crack model: Dc = eps_p/EPSC')
         end if
      end do
      call check(nchk >= 2, 'crack model: compressive damage states checked')
      call check(all(hv(1, 1:3) == 0.0_wp), 'crack model: no crack under pressure')
   end subroutine crack_shear_pressure

   subroutine bad_parameters()
      type(mat_brittle_t) :: m
      type(mat_crack_t) :: c
      type(error_t), allocatable :: err
      m = base(1); m%p(1) = -0.1_wp
      call m%setup(err)
      call check(field_is(err, 'P1'), 'negative threshold SIGR refused at P1')
      m = base(1); m%dmax = 1.5_wp
      call m%setup(err)
      call check(field_is(err, 'DMAX'), 'DMAX outside [0, 1] refused')
      m = base(1); m%d0 = -0.1_wp
      call m%setup(err)
      call check(field_is(err, 'D0'), 'D0 outside [0, 1] refused')
      m = base(1); m%yf(3) = 0.2_wp
      call m%setup(err)
      call check(field_is(err, 'YF3'), 'non-monotone yield vs pressure refused at YF3')
      m = base(1); m%pf(2) = 0.0_wp
      call m%setup(err)
      call check(field_is(err, 'PF2'), 'pressures not increasing refused at PF2')
      m = base(1); m%pfmin = 0.1_wp
      call m%setup(err)
      call check(field_is(err, 'PFMIN'), 'positive PFMIN refused')
      m = base(2); m%p(3) = 0.0_wp
      call m%setup(err)
      call check(field_is(err, 'P3'), 'JH-2 PHEL = 0 refused at P3')
      c = crack_base(); c%ft = -1.0_wp
      call c%setup(err)
      call check(field_is(err, 'FT'), 'crack model negative FT refused')
      c = crack_base(); c%ycf = 2.0_wp
      call c%setup(err)
      call check(field_is(err, 'YCF'), 'crack model YCF > SIGC refused')
   end subroutine bad_parameters

   logical function field_is(err, f)
      type(error_t), allocatable, intent(in) :: err
      character(*), intent(in) :: f
      field_is = .false.
      if (.not. allocated(err)) return
      if (.not. allocated(err%field)) return
      field_is = err%field == f
   end function field_is

end program test_mat_brittle
