!> *MAT_STEINBERG (*MAT_011): the Steinberg-Guinan model of pressure- and temperature-dependent
!> shear modulus and yield strength for high strain rates (Steinberg, Cochran & Guinan, "A
!> constitutive model for metals applicable at high-strain rate", J. Appl. Phys. 51 (1980)
!> 1498-1504; constants for Cu, Ta, Al 6061-T6, ... in its Table I and in Steinberg, UCRL-MA-106439,
!> LLNL 1996), in the form and with the fields of LS-DYNA (Keyword User's Manual Vol. II,
!> *MAT_STEINBERG; DYNA3D material 11, Hallquist, UCID-19401):
!>    G = G0 [1 + b p V**(1/3) - h (T - 300)] exp(-f E/(Em - E)),
!>    Y = Y0' [1 + b' p V**(1/3) - h (T - 300)] exp(-f E/(Em - E)),
!>    Y0' = SIGO [1 + beta (GAMA + eps_p)]**n,  capped at SIGM,
!> with V = v/v0 = 1/eta (so V**(1/3) = eta**(-1/3) of the paper, b = G'p/G0, b' = Y'p/Y0,
!> h = -G'T/G0), each bracket kept >= 0. Melt (Lindemann law, the paper's eq. 6):
!>    Tm = TMO exp(2 a (1 - V)) V**(-2 (GAMO - a - 1/3)),
!> and G = Y = 0 once E >= Em = Ec(V) + 3R' (Tm - 300) (T >= Tm), Em being the energy at melt.
!> Temperature from the internal energy minus the cold energy: T = 300 + (E - Ec(V))/(3 R'),
!> 3R' the heat capacity per reference volume (Dulong-Petit, R' = R rho0/A). dynx assumes no
!> unit system, so R' is given in the deck's units (RP); A alone (RP = 0) is refused with a
!> message, since R in those units is unknown. RP = A = 0: T stays 300 K (then H and TMO must be
!> 0). TMO = 0: no melt.
!> Cold energy Ec: EC0..EC9 of LS-DYNA, Ec = sum ECi x**i with x = mu (FLAG = 0) or eta
!> (FLAG = 1), x limited to [MMN, MMX] when MMX > MMN; when all ECi are 0 (as LS-DYNA does)
!> dynx computes it from the part's EOS: the energy along the isentrope through the reference
!> state (V = 1, E = 0, T = 300 K), dE/dmu = p(V, E) V**2, integrated by classical RK4 on a grid
!> of 1000 steps per unit mu over [MMN, MMX] (defaults -0.5, 1, the upper end kept below a
!> Gruneisen fit's pole) and interpolated linearly (error < h**2/8 |Ec''|), extrapolated with the
!> end slope p V**2 beyond.
!> Spall (SPALL, with PC < 0): 1 p >= PC; 2 (0 = default) the element spalls when the largest
!> principal stress reaches -PC; 3 it spalls when p <= PC. A spalled point has no deviatoric
!> stress and no tension (p >= 0) from then on. PC blank: -1e30 (no cut-off). With SPALL 2 or
!> 3 the spalled flag is the damage variable D (0 or 1) of the plot states (hv_damage), so the
!> spall plane shows as a fringe in ParaView; SPALL 1 (a cut-off, no spall state) has none.
!> Stress update per step (hypoelastic, radial return; Wilkins 1964):
!>   1. G and Y from p(n), T(n), E(n) (history) and V(n+1): the explicit one-step lag of the
!>      pressure and temperature, as in DYNA3D;
!>   2. trial deviator s* = s(n) + 2G de', return to Y(eps_p + deps_p): sqrt(3/2 |s*|) - 3G deps_p
!>      = Y(eps_p + deps_p) solved by Newton from deps_p = 0 (monotone: the residual is convex
!>      in deps_p for n <= 1; bisection safeguard otherwise);
!>   3. the half-step energy correction: E* = E0 + eint + dW', eint the element's energy per
!>      reference volume at t(n) and dW' = (s(n) + s(n+1))/2 : de' V(n+1/2) the deviatoric work of
!>      this step, so that the energy of the EOS carries this step's deviatoric (plastic) heating
!>      instead of lagging it by a step as *MAT_NULL does; then the time-centred pressure work
!>      E(n+1) = E* - (p(n) + p(n+1))/2 (V(n+1) - V(n)), exact for an EOS linear in E (dx_eos);
!>   4. T(n+1) from E(n+1), the spall test, the pressure cut-off.
!> History: 1 V(n) (0: reference state), 2 p, 3 c**2 (EOS plus 4G/3rho), 4 E, 5 eps_p, 6 T,
!> 7 spalled (0/1), 8 G, 9 Y of the last update, 10 Y0'(eps_p) (a cache: 0 = not yet evaluated,
!> so an elastic step costs no power law).
module dx_mat_steinberg
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr, str
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   use dx_eos_gruneisen, only: eos_gruneisen_t
   use dx_mat_hydro_common, only: hydro_material_t, deviatoric_split, &
                                  spall_reached, history_wave_speed
   implicit none
   private
   public :: mat_steinberg_t

   integer, parameter :: NPU = 1000            !< cold-energy grid steps per unit mu

   type, extends(hydro_material_t) :: mat_steinberg_t
      real(wp) :: g0 = 0.0_wp, sigo = 0.0_wp, beta = 0.0_wp, n = 0.0_wp, gama = 0.0_wp
      real(wp) :: sigm = 0.0_wp, b = 0.0_wp, bp = 0.0_wp, h = 0.0_wp, f = 0.0_wp
      real(wp) :: a = 0.0_wp, tmo = 0.0_wp, gamo = 0.0_wp, sa = 0.0_wp
      real(wp) :: pc = -1.0e30_wp, rp = 0.0_wp, mmn = 0.0_wp, mmx = 0.0_wp
      real(wp) :: ec(0:9) = 0.0_wp
      integer :: spall = 2, flag = 0
      real(wp) :: cv = 0.0_wp                 !< 3 R', heat capacity per reference volume
      logical :: ec_table = .false.           !< Ec from the EOS isentrope (all ECi = 0)
      real(wp) :: mu0 = 0.0_wp, dmu = 0.0_wp  !< table grid
      real(wp), allocatable :: ectab(:)       !< Ec at mu0 + k dmu, k = 0..
      real(wp) :: slope_lo = 0.0_wp, slope_hi = 0.0_wp   !< dEc/dmu beyond the table ends
   contains
      procedure :: read_cards => sg_read_cards
      procedure :: setup => sg_setup
      procedure :: nhist => sg_nhist
      procedure :: update => sg_update
      procedure :: wave_speed => sg_wave_speed
      procedure :: eos_ready => sg_eos_ready
      procedure :: cold_energy => sg_cold_energy
      procedure :: melt_temperature => sg_melt_temperature
      procedure :: moduli => sg_moduli
      procedure :: hardening => sg_hardening
   end type mat_steinberg_t

contains

   subroutine sg_read_cards(self, c)
      class(mat_steinberg_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      real(wp) :: x
      integer :: k
      call read_mid_ro(self, c)
      call c%real('G0', 0.0_wp, self%g0)
      call c%real('SIGO', 0.0_wp, self%sigo)
      call c%real('BETA', 0.0_wp, self%beta)
      call c%real('N', 0.0_wp, self%n)
      call c%real('GAMA', 0.0_wp, self%gama)
      call c%real('SIGM', 0.0_wp, self%sigm)
      call c%next()
      call c%real('B', 0.0_wp, self%b)
      call c%real('BP', 0.0_wp, self%bp)
      call c%real('H', 0.0_wp, self%h)
      call c%real('F', 0.0_wp, self%f)
      call c%real('A', 0.0_wp, self%a)
      call c%real('TMO', 0.0_wp, self%tmo)
      call c%real('GAMO', 0.0_wp, self%gamo)
      call c%real('SA', 0.0_wp, self%sa)
      call c%next()
      call c%real('PC', -1.0e30_wp, self%pc)
      call c%real('SPALL', 0.0_wp, x)
      if (c%ok() .and. .not. (x == 0.0_wp .or. x == 1.0_wp .or. x == 2.0_wp .or. x == 3.0_wp)) &
         call c%fail('SPALL', 'spall type must be 0, 1, 2 or 3, got '//rstr(x))
      self%spall = nint(x)
      if (self%spall == 0) self%spall = 2
      call c%real('RP', 0.0_wp, self%rp)
      call c%real('FLAG', 0.0_wp, x)
      if (c%ok() .and. .not. (x == 0.0_wp .or. x == 1.0_wp)) &
         call c%fail('FLAG', 'must be 0 (mu coefficients) or 1 (eta coefficients), got '//rstr(x))
      self%flag = nint(x)
      call c%real('MMN', 0.0_wp, self%mmn)
      call c%real('MMX', 0.0_wp, self%mmx)
      call c%real('EC0', 0.0_wp, self%ec(0))
      call c%real('EC1', 0.0_wp, self%ec(1))
      call c%next()
      do k = 2, 9
         call c%real('EC'//str(k), 0.0_wp, self%ec(k))
      end do
   end subroutine sg_read_cards

   subroutine sg_setup(self, error)
      class(mat_steinberg_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (.not. (self%ro > 0.0_wp)) then
         call set_field_error(error, 'RO', 'density must be > 0, got '//rstr(self%ro)); return
      end if
      if (.not. (self%g0 > 0.0_wp)) then
         call set_field_error(error, 'G0', 'shear modulus must be > 0, got '//rstr(self%g0)); return
      end if
      if (.not. (self%sigo > 0.0_wp)) then
         call set_field_error(error, 'SIGO', 'yield stress must be > 0, got '//rstr(self%sigo))
         return
      end if
      if (.not. (self%beta >= 0.0_wp)) then
         call set_field_error(error, 'BETA', 'must be >= 0, got '//rstr(self%beta)); return
      end if
      if (.not. (self%n >= 0.0_wp .and. self%n <= 1.0_wp)) then
         call set_field_error(error, 'N', 'hardening exponent must be in [0, 1], got '// &
                              rstr(self%n)); return
      end if
      if (.not. (self%gama >= 0.0_wp)) then
         call set_field_error(error, 'GAMA', 'initial plastic strain must be >= 0, got '// &
                              rstr(self%gama)); return
      end if
      if (self%sigm == 0.0_wp) self%sigm = huge(1.0_wp)
      if (.not. (self%sigm >= self%sigo)) then
         call set_field_error(error, 'SIGM', 'the work-hardening cap must be >= SIGO = '// &
                              rstr(self%sigo)//', got '//rstr(self%sigm)); return
      end if
      if (.not. (self%h >= 0.0_wp)) then
         call set_field_error(error, 'H', 'must be >= 0 (G falls with T), got '//rstr(self%h))
         return
      end if
      if (.not. (self%f >= 0.0_wp)) then
         call set_field_error(error, 'F', 'must be >= 0, got '//rstr(self%f)); return
      end if
      if (.not. (self%tmo >= 0.0_wp)) then
         call set_field_error(error, 'TMO', 'melt temperature must be >= 0, got '// &
                              rstr(self%tmo)); return
      end if
      if (.not. (self%pc <= 0.0_wp)) then
         call set_field_error(error, 'PC', 'the spall/cut-off pressure must be <= 0 (tension '// &
                              'is negative pressure), got '//rstr(self%pc)); return
      end if
      if (.not. (self%rp >= 0.0_wp)) then
         call set_field_error(error, 'RP', 'must be >= 0, got '//rstr(self%rp)); return
      end if
      if (self%rp == 0.0_wp .and. self%a /= 0.0_wp) then
         call set_field_error(error, 'RP', 'RP = 0 with the atomic weight A = '//rstr(self%a)// &
            ': dynx assumes no unit system, so give R'' = R rho0/A in the deck''s units '// &
            '(energy per volume and kelvin) in RP'); return
      end if
      if (self%rp == 0.0_wp .and. (self%h /= 0.0_wp .or. self%tmo /= 0.0_wp)) then
         call set_field_error(error, 'RP', 'H or TMO need the temperature, so RP (R'' = '// &
            'R rho0/A, in the deck''s units) must be > 0'); return
      end if
      if (self%mmx < self%mmn) then
         call set_field_error(error, 'MMX', 'must be >= MMN = '//rstr(self%mmn)//', got '// &
                              rstr(self%mmx)); return
      end if
      self%cv = 3.0_wp*self%rp
      self%shear = self%g0
      self%hv_eps_p = 5
      if (self%spall /= 1) self%hv_damage = 7   ! the spalled flag is the plot's D (0 or 1)
      self%ec_table = all(self%ec == 0.0_wp)
   end subroutine sg_setup

   pure integer function sg_nhist(self)
      class(mat_steinberg_t), intent(in) :: self
      sg_nhist = 10
      if (.false.) sg_nhist = int(self%ro)
   end function sg_nhist

   !> The cold-energy table from the attached EOS when all ECi are 0 (module header).
   subroutine sg_eos_ready(self, error)
      class(mat_steinberg_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: lo, hi, h
      integer :: n0, n1, k
      if (.not. self%ec_table) return
      lo = self%mmn
      hi = self%mmx
      if (lo == 0.0_wp .and. hi == 0.0_wp) then
         lo = -0.5_wp
         hi = 1.0_wp
         select type (e => self%eos)
         type is (eos_gruneisen_t)
            if (e%s1 > 1.0_wp) hi = min(hi, 0.9_wp/(e%s1 - 1.0_wp))
         end select
      end if
      if (self%flag == 1) then                 ! MMN, MMX given as eta: the grid is in mu
         lo = lo - 1.0_wp
         hi = hi - 1.0_wp
      end if
      if (.not. (lo <= 0.0_wp .and. hi >= 0.0_wp .and. lo > -1.0_wp)) then
         call set_field_error(error, 'MMN', 'the cold-energy range [MMN, MMX] must contain the '// &
            'reference state and stay above mu = -1, got ['//rstr(lo)//', '//rstr(hi)//'] in mu')
         return
      end if
      h = 1.0_wp/real(NPU, wp)
      n0 = max(1, ceiling(-lo*NPU))
      n1 = max(1, ceiling(hi*NPU))
      self%mu0 = -n0*h
      self%dmu = h
      allocate(self%ectab(0:n0 + n1))
      self%ectab(n0) = 0.0_wp
      do k = n0, n0 + n1 - 1
         self%ectab(k + 1) = rk4(self, self%mu0 + k*h, self%ectab(k), h)
      end do
      do k = n0, 1, -1
         self%ectab(k - 1) = rk4(self, self%mu0 + k*h, self%ectab(k), -h)
      end do
      self%slope_lo = isentrope(self, self%mu0, self%ectab(0))
      self%slope_hi = isentrope(self, self%mu0 + (n0 + n1)*h, self%ectab(n0 + n1))
      if (.not. all(abs(self%ectab) < huge(1.0_wp))) then
         call set_field_error(error, 'MMX', 'the cold energy of the equation of state is not '// &
            'finite on the range mu = ['//rstr(self%mu0)//', '//rstr(self%mu0 + (n0 + n1)*h)//']')
      end if
   end subroutine sg_eos_ready

   !> dE/dmu = p(V, E) V**2 along an isentrope.
   pure real(wp) function isentrope(self, mu, e) result(d)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: mu, e
      real(wp) :: v
      v = 1.0_wp/(1.0_wp + mu)
      d = self%eos%pressure(v, e)*v**2
   end function isentrope

   pure real(wp) function rk4(self, mu, e, h) result(e1)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: mu, e, h
      real(wp) :: k1, k2, k3, k4
      k1 = isentrope(self, mu, e)
      k2 = isentrope(self, mu + 0.5_wp*h, e + 0.5_wp*h*k1)
      k3 = isentrope(self, mu + 0.5_wp*h, e + 0.5_wp*h*k2)
      k4 = isentrope(self, mu + h, e + h*k3)
      e1 = e + h*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4)/6.0_wp
   end function rk4

   !> Cold energy Ec per reference volume at relative volume v (module header).
   pure real(wp) function sg_cold_energy(self, v) result(ec)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: v
      real(wp) :: mu, x, t
      integer :: k, nt
      mu = 1.0_wp/v - 1.0_wp
      if (self%ec_table) then
         if (.not. allocated(self%ectab)) then
            ec = 0.0_wp
            return
         end if
         nt = ubound(self%ectab, 1)
         x = (mu - self%mu0)/self%dmu
         if (x <= 0.0_wp) then
            ec = self%ectab(0) + self%slope_lo*(mu - self%mu0)
         else if (x >= real(nt, wp)) then
            ec = self%ectab(nt) + self%slope_hi*(mu - self%mu0 - nt*self%dmu)
         else
            k = min(int(x), nt - 1)
            t = x - real(k, wp)
            ec = (1.0_wp - t)*self%ectab(k) + t*self%ectab(k + 1)
         end if
      else
         x = mu
         if (self%flag == 1) x = 1.0_wp/v
         if (self%mmx > self%mmn) x = min(max(x, self%mmn), self%mmx)
         ec = self%ec(9)
         do k = 8, 0, -1
            ec = ec*x + self%ec(k)
         end do
      end if
   end function sg_cold_energy

   !> Lindemann melt temperature at relative volume v (0 when TMO = 0: no melt).
   pure real(wp) function sg_melt_temperature(self, v) result(tm)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: v
      tm = self%tmo*exp(2.0_wp*self%sa*(1.0_wp - v))* &
           v**(-2.0_wp*(self%gamo - self%sa - 1.0_wp/3.0_wp))
   end function sg_melt_temperature

   !> Work-hardening part Y0' = min(SIGO [1 + beta (GAMA + eps_p)]**n, SIGM) and its slope.
   pure subroutine sg_hardening(self, ep, y, dy)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: ep
      real(wp), intent(out) :: y, dy
      real(wp) :: q
      q = 1.0_wp + self%beta*(self%gama + ep)
      y = self%sigo*q**self%n
      dy = 0.0_wp
      if (q > 0.0_wp) dy = self%n*self%beta*y/q
      if (y >= self%sigm) then
         y = self%sigm
         dy = 0.0_wp
      end if
   end subroutine sg_hardening

   !> G and the yield factor yf (Y = Y0' yf) at pressure p, relative volume v, temperature t and
   !> internal energy e per reference volume; melted: both 0. ec: the cold energy at v when the
   !> caller has it (else looked up). V**(1/3) and the melt law share one log(V).
   pure subroutine sg_moduli(self, p, v, t, e, g, yf, ec)
      class(mat_steinberg_t), intent(in) :: self
      real(wp), intent(in) :: p, v, t, e
      real(wp), intent(out) :: g, yf
      real(wp), intent(in), optional :: ec
      real(wp) :: v3, em, fx, lv, tm
      g = 0.0_wp
      yf = 0.0_wp
      fx = 1.0_wp
      lv = log(v)
      if (self%tmo > 0.0_wp .and. self%cv > 0.0_wp) then
         tm = self%tmo*exp(2.0_wp*self%sa*(1.0_wp - v) - &
                           2.0_wp*(self%gamo - self%sa - 1.0_wp/3.0_wp)*lv)
         if (present(ec)) then
            em = ec + self%cv*(tm - 300.0_wp)
         else
            em = self%cold_energy(v) + self%cv*(tm - 300.0_wp)
         end if
         if (e >= em) return
         if (self%f > 0.0_wp) fx = exp(-self%f*e/(em - e))
      end if
      v3 = exp(lv/3.0_wp)
      g = self%g0*max(0.0_wp, 1.0_wp + self%b*p*v3 - self%h*(t - 300.0_wp))*fx
      yf = max(0.0_wp, 1.0_wp + self%bp*p*v3 - self%h*(t - 300.0_wp))*fx
   end subroutine sg_moduli

   !> The stress update of the module header.
   subroutine sg_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_steinberg_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]
      real(wp) :: v, vold, pn, tn, en, g, yf, so(6), s(6), de(6), tr, seq, ep, dep, y, dy, r
      real(wp) :: lo, hi, e1, p1, t1, ecv, estar, sm(6)
      integer :: i, it
      do i = 1, nv
         v = relvol(i)
         vold = hv(i, 1)
         en = self%eos%e0 + eint(i)
         if (vold == 0.0_wp) then                ! first update: the reference state
            vold = 1.0_wp
            hv(i, 6) = 300.0_wp
            if (self%cv > 0.0_wp) hv(i, 6) = 300.0_wp + (en - self%cold_energy(1.0_wp))/self%cv
            hv(i, 2) = self%eos%pressure(1.0_wp, en)
         end if
         pn = hv(i, 2)
         tn = hv(i, 6)
         ep = hv(i, 5)
         ! ---- deviatoric trial stress and radial return
         call deviatoric_split(sig(i, :), deps(i, :), so, de, tr)
         ecv = 0.0_wp
         if (self%cv > 0.0_wp) ecv = self%cold_energy(v)
         call self%moduli(pn, v, tn, en, g, yf, ecv)
         if (hv(i, 7) /= 0.0_wp) then
            g = 0.0_wp
            yf = 0.0_wp
         end if
         s = so + 2.0_wp*g*de
         seq = sqrt(1.5_wp*sum(w*s**2))
         y = hv(i, 10)                           ! Y0'(eps_p), cached (0: not yet evaluated)
         if (y == 0.0_wp) call self%hardening(ep, y, dy)
         dep = 0.0_wp
         if (seq > y*yf) then
            if (g > 0.0_wp .and. yf > 0.0_wp) then
               lo = 0.0_wp
               hi = seq/(3.0_wp*g)
               do it = 1, 60
                  call self%hardening(ep + dep, y, dy)
                  r = seq - 3.0_wp*g*dep - yf*y
                  if (abs(r) <= 4.0_wp*epsilon(1.0_wp)*seq) exit
                  if (r > 0.0_wp) then
                     lo = dep
                  else
                     hi = dep
                  end if
                  dep = dep + r/(3.0_wp*g + yf*dy)
                  if (.not. (dep > lo .and. dep < hi)) dep = 0.5_wp*(lo + hi)
               end do
               s = s*(1.0_wp - 3.0_wp*g*dep/seq)
            else
               s = 0.0_wp
            end if
         end if
         ep = ep + dep
         ! ---- the energy: this step's deviatoric work, then the time-centred pressure work
         sm = 0.5_wp*(so + s)
         estar = en + sum(w*sm*de)*0.5_wp*(v + vold)
         call self%eos%energy_update(v, v - vold, estar, pn, e1, p1)
         t1 = 300.0_wp
         if (self%cv > 0.0_wp) t1 = 300.0_wp + (e1 - ecv)/self%cv
         ! ---- spall and pressure cut-off
         if (hv(i, 7) == 0.0_wp) then
            if (spall_reached(self%spall, self%pc, s, p1)) hv(i, 7) = 1.0_wp
         end if
         p1 = max(p1, self%pc)
         if (hv(i, 7) /= 0.0_wp) then
            s = 0.0_wp
            p1 = max(p1, 0.0_wp)
         end if
         if (.not. (abs(p1) < huge(1.0_wp) .and. abs(e1) < huge(1.0_wp))) ierr(i) = 2   ! a material failure
         if (.not. self%eos%in_range(v)) ierr(i) = 2   ! compressed past the EOS's range (not an inverted element)
         sig(i, :) = s
         sig(i, 1:3) = s(1:3) - p1
         hv(i, 1) = v
         hv(i, 2) = p1
         hv(i, 3) = self%eos%sound_speed2(self%ro, v, e1) + 4.0_wp*g*v/(3.0_wp*self%ro)
         hv(i, 4) = e1
         hv(i, 5) = ep
         hv(i, 6) = t1
         hv(i, 8) = g
         if (dep > 0.0_wp) call self%hardening(ep, y, dy)
         hv(i, 9) = yf*y
         hv(i, 10) = y
      end do
      if (.false.) hv(1, 1) = dt
   end subroutine sg_update


   !> sqrt(c**2 of the last update), before any: sqrt((K + 4G0/3) V/rho0).
   subroutine sg_wave_speed(self, nv, relvol, hv, c)
      class(mat_steinberg_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: relvol(nv)
      real(wp), intent(in) :: hv(:, :)
      real(wp), intent(out) :: c(nv)
      call history_wave_speed(nv, relvol, hv, 1, 3, self%bulk + 4.0_wp*self%g0/3.0_wp, self%ro, c)
   end subroutine sg_wave_speed
end module dx_mat_steinberg
