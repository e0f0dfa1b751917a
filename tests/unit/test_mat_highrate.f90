!> Material-point tests of the high-rate models through the material API (update, history).
!> Units g/cm3, GPa, K (energy per volume in GPa = GJ/m3). Copper constants of Steinberg,
!> Cochran & Guinan 1980 (Table I; physics-references.md 3.3): G0 47.7, Y0 0.12, Ymax 0.64,
!> beta 36, n 0.45, b = b' = 0.0283 /GPa, h 3.77e-4 /K, Tm0 1790 K, gamma0 2.02, a 1.5;
!> heat capacity rho cp = 8.93 x 0.383 J/(cm3 K) = 3.42e-3 GPa/K, so RP = R' = 1.14e-3.
!> Steinberg-Guinan:
!>  - the paper's hand values (physics-references.md): Y(eps_p = 1, p = 0, 300 K) = 0.12 x
!>    37**0.45 = 0.6094 GPa, capped at 0.64 for eps_p = 2, G(p = 10 GPa, eta = 1.05) = 60.981 GPa
!>    (the printed 4-5 digits), and the same formulas evaluated here to round-off;
!>  - a uniaxial-strain compression path (de_xx = -2e-4 per step to V = 0.9) with the linear
!>    equation of state p = K mu (C1 = K = 137 GPa): at the end, G and Y against the paper's
!>    equations computed here from the pressure and temperature of the step before (the
!>    one-step lag of the module header), sigma_xx - sigma_yy = -Y (uniaxial strain, radial
!>    return), p = K mu, the energy update E(n+1) = E(n) + dW' - (p(n) + p(n+1))/2 dV, and the
!>    temperature against the closed-form cold energy of that EOS,
!>    Ec(mu) = K (ln(1 + mu) + 1/(1 + mu) - 1), within the table's interpolation error
!>    K h**2/8 (h = 1e-3) over the heat capacity;
!>  - melt (G = Y = 0 above the melt energy), SPALL 1 (cut-off at PC), 2 (largest principal
!>    stress >= -PC spalls: no deviator, no tension after), 3 (p <= PC spalls);
!>  - the largest principal stress of a rotated tensor.
!> Johnson-Cook (4340 steel flow constants of Johnson & Cook 1983 as in physics-references.md
!> 3.6: A 0.792, B 0.510 GPa, N 0.26, C 0.014, M 1.03, TM 1793 K, TR 294 K, EPSO 1/s; G 77.5,
!> E 200 GPa, PR 0.29, rho 7.83, CP 477e-6 GPa/(K g/cm3) = 477 J/(kg K)), pure shear (no pressure):
!>  - one large step, CP = 0: sigma_eq = (A + B eps_p**N)(1 + C ln rate*) to round-off (IT = 1),
!>    and IT = 0 (yield at the step's start): sigma_eq = A (1 + C ln rate*);
!>  - 400 steps with adiabatic heating: sigma_eq = (A + B eps_p**N)(1 + C ln rate*)(1 - T*** M)
!>    with T = TR + Wp/(rho CP) from the history, to round-off;
!>  - damage at constant triaxiality 0 (pure shear, CP = 0), D1 = 0.05, D2 = 0.15, D4 = 0.002:
!>    D = eps_p/eps_f, eps_f = 0.2 (1 + 0.002 ln rate*), to round-off; the point fails at D = 1.
!> *MAT_ELASTIC_PLASTIC_HYDRO: a 4-point yield table (EPS 0, 0.05, 0.2, 1; ES 0.3, 0.4, 0.5,
!> 0.55 GPa) in pure shear at p = 0 (the linear EOS p = K mu at V = 1): sigma_eq = h(eps_p) by
!> linear interpolation to round-off in each segment and extrapolated past the last point;
!> then at p = K mu after a volumetric compression, sigma_eq = h + (A1 + A2 p) p; a
!> non-monotone table is refused naming the EPS field; FS erodes.
!> *MAT_ELASTIC_PLASTIC_HYDRO: a 4-point yield table (EPS 0, 0.05, 0.2, 1; ES 0.3, 0.4, 0.5,
!> 0.55 GPa) in pure shear at p = 0 (the linear EOS p = K mu at V = 1): sigma_eq = h(eps_p) by
!> linear interpolation to round-off in each segment and extrapolated past the last point;
!> then at p = K mu after a volumetric compression, sigma_eq = h + (A1 + A2 p) p; a
!> non-monotone table is refused naming the EPS field; FS erodes.
program test_mat_highrate
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_steinberg, only: mat_steinberg_t
   use dx_mat_hydro_common, only: max_principal
   use dx_eos_linear_polynomial, only: eos_linear_polynomial_t
   use dx_mat_johnson_cook, only: mat_johnson_cook_t
   use dx_mat_hydro, only: mat_hydro_t
   use dx_eos_gruneisen, only: eos_gruneisen_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: k_bulk = 137.0_wp, cv = 3.42e-3_wp
   real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]

   call steinberg_formulas()
   call steinberg_uniaxial_strain()
   call steinberg_melt_spall()
   call johnson_cook_checks()
   call pole_check()
   call hydro_checks()
   call check_close(max_principal([2.0_wp, 2.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, 0.0_wp]), 3.0_wp, &
                    0.0_wp, 8.0_wp*epsilon(1.0_wp), 'largest principal stress of [[2,1,0],[1,2,0],[0,0,1]] = 3')
   call check_close(max_principal([-1.0_wp, -1.0_wp, -1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]), -1.0_wp, &
                    0.0_wp, 8.0_wp*epsilon(1.0_wp), 'largest principal stress of -I = -1')
   call assert_summary()

contains

   subroutine copper(m, spall, pc, f)
      type(mat_steinberg_t), intent(out) :: m
      integer, intent(in) :: spall
      real(wp), intent(in) :: pc, f
      type(error_t), allocatable :: err
      m%ro = 8.93_wp; m%g0 = 47.7_wp; m%sigo = 0.12_wp; m%beta = 36.0_wp; m%n = 0.45_wp
      m%gama = 0.0_wp; m%sigm = 0.64_wp; m%b = 0.0283_wp; m%bp = 0.0283_wp; m%h = 3.77e-4_wp
      m%f = f; m%tmo = 1790.0_wp; m%gamo = 2.02_wp; m%sa = 1.5_wp; m%pc = pc
      m%spall = spall; m%rp = cv/3.0_wp
      call m%setup(err)
      call check(.not. allocated(err), 'Steinberg setup')
      allocate(eos_linear_polynomial_t :: m%eos)
      select type (q => m%eos)
      type is (eos_linear_polynomial_t)
         q%c = 0.0_wp
         q%c(1) = k_bulk
      end select
      m%eos%rho0 = m%ro
      m%bulk = k_bulk
      call m%eos_ready(err)
      call check(.not. allocated(err), 'Steinberg cold-energy table')
   end subroutine copper

   !> Closed-form cold energy of p = K mu along an isentrope (p independent of E).
   pure real(wp) function ec_linear(v) result(ec)
      real(wp), intent(in) :: v
      real(wp) :: mu
      mu = 1.0_wp/v - 1.0_wp
      ec = k_bulk*(log(1.0_wp + mu) + 1.0_wp/(1.0_wp + mu) - 1.0_wp)
   end function ec_linear

   subroutine steinberg_formulas()
      type(mat_steinberg_t) :: m
      real(wp) :: y, dy, g, yf, ref
      call copper(m, 2, -1.0e30_wp, 0.0_wp)
      call m%hardening(1.0_wp, y, dy)
      ref = 0.12_wp*37.0_wp**0.45_wp
      call check_close(y, ref, 0.0_wp, 4.0_wp*epsilon(1.0_wp), 'SG Y0(eps_p = 1) = 0.12 37**0.45')
      call check_close(y, 0.6094_wp, 5.0e-5_wp, 0.0_wp, 'SG Y0(eps_p = 1) = 0.6094 GPa (printed)')
      call m%hardening(2.0_wp, y, dy)
      call check_close(y, 0.64_wp, 0.0_wp, 0.0_wp, 'SG Y0(eps_p = 2) capped at Ymax = 0.64 GPa')
      call check_close(dy, 0.0_wp, 0.0_wp, 0.0_wp, 'SG no hardening slope above the cap')
      call m%moduli(10.0_wp, 1.0_wp/1.05_wp, 300.0_wp, 0.0_wp, g, yf)
      ref = 47.7_wp*(1.0_wp + 0.0283_wp*10.0_wp*1.05_wp**(-1.0_wp/3.0_wp))
      call check_close(g, ref, 0.0_wp, 8.0_wp*epsilon(1.0_wp), 'SG G(p = 10, eta = 1.05) formula')
      call check_close(g, 60.981_wp, 5.0e-4_wp, 0.0_wp, 'SG G(p = 10, eta = 1.05) = 60.981 GPa')
      call check_close(yf*47.7_wp, ref, 0.0_wp, 8.0_wp*epsilon(1.0_wp), 'SG Y/Y0 = G/G0 when b = b''')
      ! temperature: G falls by h (T - 300)
      call m%moduli(0.0_wp, 1.0_wp, 800.0_wp, 1.0_wp, g, yf)
      call check_close(g, 47.7_wp*(1.0_wp - 3.77e-4_wp*500.0_wp), 0.0_wp, 8.0_wp*epsilon(1.0_wp), &
                       'SG G(T = 800 K) = G0 (1 - h 500)')
      ! Lindemann melt law at eta = 1.2
      ref = 1790.0_wp*exp(2.0_wp*1.5_wp*(1.0_wp - 1.0_wp/1.2_wp))*1.2_wp**(2.0_wp*(2.02_wp - 1.5_wp - 1.0_wp/3.0_wp))
      call check_close(m%melt_temperature(1.0_wp/1.2_wp), ref, 0.0_wp, 16.0_wp*epsilon(1.0_wp), &
                       'SG melt temperature Tm(eta = 1.2)')
      ! the cold-energy table against the closed form, within K h**2/8
      call check_close(m%cold_energy(1.0_wp/1.3_wp), ec_linear(1.0_wp/1.3_wp), &
                       k_bulk*1.0e-6_wp/8.0_wp, 0.0_wp, 'SG cold energy Ec(mu = 0.3) of p = K mu')
      call check_close(m%cold_energy(1.0_wp/0.8_wp), ec_linear(1.0_wp/0.8_wp), &
                       k_bulk*1.0e-6_wp/8.0_wp, 0.0_wp, 'SG cold energy Ec(mu = -0.2) of p = K mu')
      ! EC0-EC9 given (LS-DYNA's fit): Ec = sum ECi x**i, x = mu (FLAG 0) or eta (FLAG 1)
      m%ec = 0.0_wp
      m%ec(2) = 0.5_wp*k_bulk
      m%ec(3) = -0.1_wp*k_bulk
      m%ec_table = .false.
      call check_close(m%cold_energy(1.0_wp/1.2_wp), k_bulk*(0.5_wp*0.04_wp - 0.1_wp*0.008_wp), &
                       0.0_wp, 8.0_wp*epsilon(1.0_wp), 'SG EC0-9 polynomial in mu (FLAG 0)')
      m%flag = 1
      call check_close(m%cold_energy(1.0_wp/1.2_wp), k_bulk*(0.5_wp*1.44_wp - 0.1_wp*1.728_wp), &
                       0.0_wp, 8.0_wp*epsilon(1.0_wp), 'SG EC0-9 polynomial in eta (FLAG 1)')
      m%mmn = 0.9_wp; m%mmx = 1.1_wp
      call check_close(m%cold_energy(1.0_wp/1.2_wp), k_bulk*(0.5_wp*1.21_wp - 0.1_wp*1.331_wp), &
                       0.0_wp, 8.0_wp*epsilon(1.0_wp), 'SG EC0-9: x limited to [MMN, MMX]')
   end subroutine steinberg_formulas

   subroutine steinberg_uniaxial_strain()
      type(mat_steinberg_t) :: m
      real(wp) :: sig(1, 6), hv(1, 10), hp(1, 10), so(6), de(6), deps(1, 6), v, vold, eint, y, dy
      real(wp) :: g, yf, en, ehand, mu, tr
      integer :: ierr(1), k, nstep
      call copper(m, 2, -1.0e30_wp, 1.0e-3_wp)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      v = 1.0_wp
      eint = 0.0_wp
      nstep = 527                        ! V = exp(-527 x 2e-4) = 0.9
      deps = 0.0_wp
      deps(1, 1) = -2.0e-4_wp
      do k = 1, nstep
         hp = hv
         so = sig(1, :)
         vold = v
         v = v*exp(deps(1, 1))
         call m%update(1, 1.0e-3_wp, deps, [v], [eint], sig, hv, ierr)
         eint = hv(1, 4)                 ! a material point: the element's energy is the EOS's
      end do
      call check(ierr(1) == 0, 'SG uniaxial strain: no failed point')
      call check(hv(1, 5) > 0.0_wp, 'SG uniaxial strain: yielded')
      ! G and Y from the state of the step before (p, T, E) at V(n+1)
      en = hp(1, 4)
      mu = 1.0_wp/v - 1.0_wp
      block
         real(wp) :: em, fx, x
         em = ec_linear(v) + cv*(m%melt_temperature(v) - 300.0_wp)
         fx = exp(-1.0e-3_wp*en/(em - en))
         x = 1.0_wp + 0.0283_wp*hp(1, 2)*v**(1.0_wp/3.0_wp) - 3.77e-4_wp*(hp(1, 6) - 300.0_wp)
         g = 47.7_wp*x*fx
         yf = x*fx
      end block
      ! the table's Ec (not the closed form) sets Em: the same to K h**2/8 over Em - E
      call check_close(hv(1, 8), g, 0.0_wp, 1.0e-9_wp, 'SG uniaxial strain: G(p, T) as the paper')
      call m%hardening(hv(1, 5), y, dy)
      call check_close(y, min(0.12_wp*(1.0_wp + 36.0_wp*hv(1, 5))**0.45_wp, 0.64_wp), 0.0_wp, &
                       4.0_wp*epsilon(1.0_wp), 'SG uniaxial strain: Y0 (1 + beta eps_p)**n')
      call check_close(hv(1, 9), y*yf, 0.0_wp, 1.0e-9_wp, 'SG uniaxial strain: Y(eps_p, p, T)')
      call check_close(sig(1, 1) - sig(1, 2), -hv(1, 9), 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                       'SG uniaxial strain: sigma_xx - sigma_yy = -Y (on the yield surface)')
      call check_close(hv(1, 2), k_bulk*mu, 0.0_wp, 16.0_wp*epsilon(1.0_wp), &
                       'SG uniaxial strain: p = K mu')
      ! energy: this step's deviatoric work, then the time-centred pressure work
      tr = deps(1, 1)/3.0_wp
      de = deps(1, :)
      de(1:3) = de(1:3) - tr
      so(1:3) = so(1:3) + hp(1, 2)
      block
         real(wp) :: s(6)
         s = sig(1, :)
         s(1:3) = s(1:3) + hv(1, 2)
         ehand = en + 0.5_wp*sum(w*(so + s)*de)*0.5_wp*(v + vold) - &
                 0.5_wp*(hp(1, 2) + hv(1, 2))*(v - vold)
      end block
      call check_close(hv(1, 4), ehand, 0.0_wp, 1.0e-13_wp, &
                       'SG uniaxial strain: E(n+1) = E(n) + dW'' - (p(n) + p(n+1))/2 dV')
      call check_close(hv(1, 6), 300.0_wp + (hv(1, 4) - ec_linear(v))/cv, &
                       k_bulk*1.0e-6_wp/8.0_wp/cv + 1.0e-9_wp, 0.0_wp, &
                       'SG uniaxial strain: T = 300 + (E - Ec(V))/(3 R'')')
      call check(hv(1, 6) > 300.0_wp, 'SG uniaxial strain: plastic work heats')
   end subroutine steinberg_uniaxial_strain

   subroutine steinberg_melt_spall()
      type(mat_steinberg_t) :: m
      real(wp) :: sig(1, 6), hv(1, 10), deps(1, 6), g, yf, em
      integer :: ierr(1)
      call copper(m, 2, -1.0_wp, 0.0_wp)
      em = cv*(1790.0_wp - 300.0_wp)
      call m%moduli(0.0_wp, 1.0_wp, 1800.0_wp, em*1.0001_wp, g, yf)
      call check(g == 0.0_wp .and. yf == 0.0_wp, 'SG melted above Em: G = Y = 0')
      call m%moduli(0.0_wp, 1.0_wp, 1780.0_wp, em*0.999_wp, g, yf)
      call check(g > 0.0_wp, 'SG solid just below Em')
      ! SPALL 2: uniaxial-strain tension V = 1.01, sigma_xx = (K + 4G/3) eps > 1 GPa = -PC
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      deps = 0.0_wp; deps(1, 1) = 0.01_wp
      call m%update(1, 1.0e-3_wp, deps, [1.01_wp], [0.0_wp], sig, hv, ierr)
      call check(hv(1, 7) == 1.0_wp, 'SG SPALL 2: sigma_max >= -PC spalls')
      call check(maxval(abs(sig(1, :))) == 0.0_wp, 'SG SPALL 2: spalled in tension, stress 0')
      deps(1, 1) = -0.02_wp
      call m%update(1, 1.0e-3_wp, deps, [0.99_wp], [hv(1, 4)], sig, hv, ierr)
      call check(sig(1, 1) < 0.0_wp .and. sig(1, 1) == sig(1, 2), &
                 'SG spalled: carries pressure, no deviator')
      ! SPALL 3: p <= PC spalls; a small tension (p = -K 0.001 > PC) does not
      call copper(m, 3, -1.0_wp, 0.0_wp)
      sig = 0.0_wp; hv = 0.0_wp
      deps(1, 1) = 0.001_wp
      call m%update(1, 1.0e-3_wp, deps, [1.001_wp], [0.0_wp], sig, hv, ierr)
      call check(hv(1, 7) == 0.0_wp .and. hv(1, 2) < 0.0_wp, 'SG SPALL 3: p > PC holds')
      deps(1, 1) = 0.01_wp
      call m%update(1, 1.0e-3_wp, deps, [1.011_wp], [hv(1, 4)], sig, hv, ierr)
      call check(hv(1, 7) == 1.0_wp .and. hv(1, 2) == 0.0_wp, 'SG SPALL 3: p <= PC spalls, p = 0')
      ! SPALL 1: p >= PC, no spall
      call copper(m, 1, -1.0_wp, 0.0_wp)
      sig = 0.0_wp; hv = 0.0_wp
      call m%update(1, 1.0e-3_wp, deps, [1.011_wp], [0.0_wp], sig, hv, ierr)
      call check(hv(1, 7) == 0.0_wp, 'SG SPALL 1: no spall')
      call check_close(hv(1, 2), -1.0_wp, 0.0_wp, 0.0_wp, 'SG SPALL 1: p cut off at PC')
   end subroutine steinberg_melt_spall

   subroutine steel(m, it, cp, dmg)
      type(mat_johnson_cook_t), intent(out) :: m
      integer, intent(in) :: it
      real(wp), intent(in) :: cp
      logical, intent(in) :: dmg
      type(error_t), allocatable :: err
      m%ro = 7.83_wp; m%g = 77.5_wp; m%e = 200.0_wp; m%pr = 0.29_wp
      m%a = 0.792_wp; m%b = 0.510_wp; m%n = 0.26_wp; m%c = 0.014_wp; m%m = 1.03_wp
      m%tm = 1793.0_wp; m%tr = 294.0_wp; m%epso = 1.0_wp; m%cp = cp; m%it = it
      m%pc = -1.0e30_wp
      if (dmg) m%d = [0.05_wp, 0.15_wp, 0.0_wp, 0.002_wp, 0.0_wp]
      call m%setup(err)
      call check(.not. allocated(err), 'JC setup')
   end subroutine steel

   !> sigma_eq of a stress state
   pure real(wp) function vm(s) result(q)
      real(wp), intent(in) :: s(6)
      real(wp) :: d(3)
      d = s(1:3) - sum(s(1:3))/3.0_wp
      q = sqrt(1.5_wp*(sum(d**2) + 2.0_wp*sum(s(4:6)**2)))
   end function vm

   subroutine johnson_cook_checks()
      type(mat_johnson_cook_t) :: m
      real(wp) :: sig(1, 6), hv(1, 10), deps(1, 6), dt, rate, ref, ts, ef
      integer :: ierr(1), k
      logical :: failed(1)
      ! one large shear step: tensor shear 0.02, dt 1e-5 s: rate = 2 x 0.02/sqrt(3)/1e-5
      dt = 1.0e-5_wp
      deps = 0.0_wp; deps(1, 4) = 0.02_wp
      rate = 2.0_wp*0.02_wp/sqrt(3.0_wp)/dt
      call steel(m, 1, 0.0_wp, .false.)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      ref = (0.792_wp + 0.510_wp*hv(1, 1)**0.26_wp)*(1.0_wp + 0.014_wp*log(rate))
      call check(hv(1, 1) > 0.0_wp, 'JC shear step yields')
      call check_close(vm(sig(1, :)), ref, 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                       'JC IT=1: sigma_eq = (A + B eps_p**N)(1 + C ln rate*)')
      call check_close(3.0_wp*77.5_wp*hv(1, 1) + vm(sig(1, :)), sqrt(3.0_wp)*2.0_wp*77.5_wp*0.02_wp, &
                       0.0_wp, 64.0_wp*epsilon(1.0_wp), 'JC radial return: 3 G deps_p + sigma_eq = trial')
      call steel(m, 0, 0.0_wp, .false.)
      sig = 0.0_wp; hv = 0.0_wp
      call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      call check_close(vm(sig(1, :)), 0.792_wp*(1.0_wp + 0.014_wp*log(rate)), 0.0_wp, &
                       64.0_wp*epsilon(1.0_wp), 'JC IT=0: sigma_eq = A (1 + C ln rate*) (yield at the start)')
      ! adiabatic heating over 400 steps of shear 0.002 (eps_p ~ 0.9)
      call steel(m, 1, 477.0e-6_wp, .false.)
      sig = 0.0_wp; hv = 0.0_wp
      deps(1, 4) = 0.002_wp
      rate = 2.0_wp*0.002_wp/sqrt(3.0_wp)/dt
      do k = 1, 400
         call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      call check_close(hv(1, 3), 294.0_wp + hv(1, 10)/(7.83_wp*477.0e-6_wp), 0.0_wp, &
                       8.0_wp*epsilon(1.0_wp), 'JC T = TR + Wp/(rho CP)')
      call check(hv(1, 3) > 400.0_wp, 'JC adiabatic heating over 100 K')
      ts = (hv(1, 3) - 294.0_wp)/(1793.0_wp - 294.0_wp)
      ref = (0.792_wp + 0.510_wp*hv(1, 1)**0.26_wp)*(1.0_wp + 0.014_wp*log(rate))* &
            (1.0_wp - ts**1.03_wp)
      ! the return of the last step used T of the step before: compare the history's yield
      call check_close(hv(1, 9), ref, 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                       'JC sigma_y = (A + B eps_p**N)(1 + C ln rate*)(1 - T*** M)')
      call check(abs(vm(sig(1, :)) - ref) < 1.0e-3_wp*ref, &
                 'JC on the yield surface within the one-step lag of T (0.1 %)')
      ! damage, pure shear: D = eps_p/eps_f
      call steel(m, 1, 0.0_wp, .true.)
      sig = 0.0_wp; hv = 0.0_wp
      ef = 0.2_wp*(1.0_wp + 0.002_wp*log(rate))
      do k = 1, 50
         call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      call check_close(hv(1, 2), hv(1, 1)/ef, 0.0_wp, 1.0e-13_wp, 'JC damage D = eps_p/eps_f (triaxiality 0)')
      call m%fails(1, hv, failed)
      call check(.not. failed(1) .and. hv(1, 2) < 1.0_wp, 'JC not failed below D = 1')
      call check(m%hv_damage == 2, 'JC damage history slot')
      do k = 1, 200
         call m%update(1, dt, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
      end do
      call m%fails(1, hv, failed)
      call check(failed(1) .and. hv(1, 2) == 1.0_wp, 'JC fails at D = 1 (EROD = 0)')
      call check(maxval(abs(sig(1, :))) == 0.0_wp, 'JC failed point carries no stress in shear')
   end subroutine johnson_cook_checks
   !> the table h of hydro_checks, by hand
   pure real(wp) function htab(ep) result(h)
      real(wp), intent(in) :: ep
      if (ep <= 0.05_wp) then
         h = 0.3_wp + (0.4_wp - 0.3_wp)*ep/0.05_wp
      else if (ep <= 0.2_wp) then
         h = 0.4_wp + (0.5_wp - 0.4_wp)*(ep - 0.05_wp)/0.15_wp
      else
         h = 0.5_wp + (0.55_wp - 0.5_wp)*(ep - 0.2_wp)/0.8_wp
      end if
   end function htab

   subroutine hydro_checks()
      type(mat_hydro_t) :: m
      type(error_t), allocatable :: err
      real(wp) :: sig(1, 6), hv(1, 6), deps(1, 6), p, v
      integer :: ierr(1), k
      logical :: failed(1), seen(4)
      m%ro = 7.83_wp; m%g = 77.5_wp
      m%eps(1:4) = [0.0_wp, 0.05_wp, 0.2_wp, 1.0_wp]
      m%es(1:4) = [0.3_wp, 0.4_wp, 0.5_wp, 0.55_wp]
      m%fs = 1.5_wp
      call m%setup(err)
      call check(.not. allocated(err), 'MAT_010 setup')
      allocate(eos_linear_polynomial_t :: m%eos)
      select type (q => m%eos)
      type is (eos_linear_polynomial_t)
         q%c = 0.0_wp
         q%c(1) = 160.0_wp
      end select
      m%eos%rho0 = m%ro
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      deps = 0.0_wp; deps(1, 4) = 0.004_wp
      seen = .false.
      do k = 1, 500
         call m%update(1, 1.0e-6_wp, deps, [1.0_wp], [0.0_wp], sig, hv, ierr)
         if (hv(1, 1) <= 0.0_wp) cycle
         if (hv(1, 1) < 0.05_wp .and. .not. seen(1)) then
            seen(1) = .true.
            call check_close(vm(sig(1, :)), htab(hv(1, 1)), 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                             'MAT_010 segment 1: sigma_eq = h(eps_p)')
         else if (hv(1, 1) > 0.05_wp .and. hv(1, 1) < 0.2_wp .and. .not. seen(2)) then
            seen(2) = .true.
            call check_close(vm(sig(1, :)), htab(hv(1, 1)), 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                             'MAT_010 segment 2: sigma_eq = h(eps_p)')
         else if (hv(1, 1) > 0.2_wp .and. hv(1, 1) < 1.0_wp .and. .not. seen(3)) then
            seen(3) = .true.
            call check_close(vm(sig(1, :)), htab(hv(1, 1)), 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                             'MAT_010 segment 3: sigma_eq = h(eps_p)')
         else if (hv(1, 1) > 1.0_wp .and. .not. seen(4)) then
            seen(4) = .true.
            call check_close(vm(sig(1, :)), htab(hv(1, 1)), 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                             'MAT_010 past the last point: extrapolated')
         end if
      end do
      call check(all(seen), 'MAT_010 every segment visited')
      call m%fails(1, hv, failed)
      call check(failed(1) .eqv. (hv(1, 1) >= 1.5_wp), 'MAT_010 fails at eps_p >= FS')
      ! pressure term: compress to V = 0.99, then shear at that volume
      m%a1 = 0.01_wp; m%a2 = 0.002_wp
      sig = 0.0_wp; hv = 0.0_wp
      deps = 0.0_wp; deps(1, 1:3) = log(0.99_wp)/3.0_wp
      v = 0.99_wp
      call m%update(1, 1.0e-6_wp, deps, [v], [0.0_wp], sig, hv, ierr)
      p = 160.0_wp*(1.0_wp/v - 1.0_wp)
      call check_close(hv(1, 2), p, 0.0_wp, 16.0_wp*epsilon(1.0_wp), 'MAT_010 p = C1 mu')
      deps = 0.0_wp; deps(1, 4) = 0.004_wp
      do k = 1, 3
         call m%update(1, 1.0e-6_wp, deps, [v], [hv(1, 4)], sig, hv, ierr)
      end do
      call check(hv(1, 1) > 0.0_wp, 'MAT_010 yields under pressure')
      call check_close(vm(sig(1, :)), htab(hv(1, 1)) + (0.01_wp + 0.002_wp*p)*p, 0.0_wp, &
                       64.0_wp*epsilon(1.0_wp), 'MAT_010 sigma_eq = h + (A1 + A2 p) p')
      ! a non-monotone table
      m%eps(3) = 0.04_wp
      call m%setup(err)
      call check(allocated(err), 'MAT_010 non-monotone EPS refused')
      if (allocated(err)) call check(err%field == 'EPS3', 'MAT_010 the error names EPS3')
   end subroutine hydro_checks

   !> Steinberg with *EOS_GRUNEISEN (copper, S1 = 1.489: pole at mu = 1/0.489, V = 0.3284):
   !> V = 0.5 updates; V = 0.3 is past the pole: the point is flagged (ierr = 2), no NaN.
   subroutine pole_check()
      type(mat_steinberg_t) :: m
      type(error_t), allocatable :: err
      real(wp) :: sig(1, 9), hv(1, 10), deps(1, 6)
      integer :: ierr(1)
      m%ro = 8.93_wp; m%g0 = 47.7_wp; m%sigo = 0.12_wp
      call m%setup(err)
      allocate(eos_gruneisen_t :: m%eos)
      select type (q => m%eos)
      type is (eos_gruneisen_t)
         q%c = 3.94_wp; q%s1 = 1.489_wp; q%gamma0 = 2.02_wp; q%a = 0.47_wp
      end select
      m%eos%rho0 = m%ro
      call m%eos_ready(err)
      call check(.not. allocated(err), 'SG + Gruneisen cold-energy table')
      deps = 0.0_wp; deps(1, 1) = log(0.5_wp)
      sig = 0.0_wp; hv = 0.0_wp; ierr = 0
      call m%update(1, 1.0e-3_wp, deps, [0.5_wp], [0.0_wp], sig(:, 1:6), hv, ierr)
      call check(ierr(1) == 0 .and. all(abs(sig(1, 1:6)) < huge(1.0_wp)), 'SG + Gruneisen at V = 0.5')
      deps(1, 1) = log(0.3_wp/0.5_wp)
      call m%update(1, 1.0e-3_wp, deps, [0.3_wp], [hv(1, 4)], sig(:, 1:6), hv, ierr)
      call check(ierr(1) == 2, 'SG + Gruneisen past the pole V = 0.3284: the point is flagged')
   end subroutine pole_check
end program test_mat_highrate
