!> *DYNX_BRITTLE_DAMAGE: the three scalar brittle damage models of the DYNA2D work on glass and
!> ceramics (seed article 3: Four brittle damage models in DYNA2D; LLNL, late 1990s). After the
!> article: undamaged material is isotropic elastic-plastic; failed material follows a
!> piece-wise linear yield stress versus pressure; the shear modulus, the yield strength and
!> the pressure go from their undamaged to their fully damaged values as the scalar D goes from
!> 0 to 1. The three models differ only in the evolution of D. The originals (Tuler & Butcher
!> 1968 as modified at LLNL; Cagnoux-Glenn; Steinberg-Tipton) were searched for and not found
!> except the Tuler-Butcher law (shared damage-and-plane-stress.md), so MODEL 2 and 3 are the
!> closest documented models and are named as such (docs/damage.md):
!>  MODEL 1, modified Tuler-Butcher: K += dt max(0, sigma1 - SIGR)**LAMBDA, Dm = K/KF (Tuler &
!>    Butcher 1968, Int. J. Fract. Mech. 4:431; "modified": D grows continuously with K/KF and
!>    degrades the point instead of failing it at K = KF);
!>  MODEL 2, Johnson-Holmquist (JH-2) damage in place of Cagnoux-Glenn: Dm += deps_p/eps_f,
!>    eps_f = max(EFMIN, D1 ((p + T)/PHEL)**D2), and Dm = 1 once p <= -T (Johnson & Holmquist
!>    1994, AIP Conf. Proc. 309:981; OpenRadioss /MAT/LAW79);
!>  MODEL 3, rate-limited crack growth in place of Steinberg-Tipton: while sigma1 >= SIGT,
!>    d(Dm**(1/3))/dt = CG c_L/LC, c_L the undamaged longitudinal wave speed, LC the flaw
!>    spacing (Grady & Kipp 1980, Int. J. Rock Mech. 17:147; Benz & Asphaug 1994, Icarus
!>    107:98, deterministic: one flaw family, no Weibull activation).
!> The driving stress sigma1 (largest principal) and deps_p are those of the undamaged
!> (effective, Lemaitre 1985) state, an elastic-plastic point carried beside the actual one, so
!> damage does not feed back on its own driver. D = min(DMAX, max(D(n), D0 + (1 - D0) min(1, Dm))).
!> Actual state, with G_f = GFR G, Y_i = SIGY + H eps_p (H = E ETAN/(E - ETAN)),
!> p_i = -K ln(V/V0) and Y_f(p) the PF/YF curve (constant beyond its ends):
!>    G(D) = (1 - D) G + D G_f;  p = (1 - D) p_i + D max(p_i, PFMIN);
!>    Y(D, p) = (1 - D) Y_i + D Y_f(p);  s = (G(D)/G(D_n)) s_n + 2 G(D) de, radially returned
!>    onto Y(D, p) (Wilkins 1964). PFMIN <= 0 is the tension the failed material carries.
!> EROD = 1: a point with D >= DMAX fails (the element erodes, *MAT_ADD_EROSION style).
!> Cards: MID RO E PR SIGY ETAN MODEL EROD; GFR D0 DMAX PFMIN; P1..P8 (the model's parameters:
!> 1 SIGR LAMBDA KF, 2 D1 D2 PHEL T EFMIN, 3 SIGT CG LC); PF1..PF8; YF1..YF8.
!> History: 1 eps_p (undamaged), 2 D, 3 K/Dm/Dm**(1/3), 4-9 undamaged deviator, 10-15 actual deviator.
module dx_mat_brittle
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr, str
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   use dx_mat_elastic, only: check_elastic_constants
   use dx_mat_hydro_common, only: max_principal
   implicit none
   private
   public :: mat_brittle_t, yield_vs_pressure, read_yield_curve, check_yield_curve, radial_return

   integer, parameter :: NPF = 8
   real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]

   type, extends(material_t) :: mat_brittle_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp, sigy = 0.0_wp, etan = 0.0_wp, hard = 0.0_wp
      integer :: model = 0, erod = 0
      real(wp) :: gfr = 1.0_wp, d0 = 0.0_wp, dmax = 1.0_wp, pfmin = 0.0_wp
      real(wp) :: p(8) = 0.0_wp                    !< the model's parameters P1..P8
      real(wp) :: pf(NPF) = 0.0_wp, yf(NPF) = 0.0_wp
      integer :: npf = 0                           !< failed-curve points in use
      real(wp) :: cl = 0.0_wp                      !< undamaged longitudinal wave speed
   contains
      procedure :: read_cards => br_read_cards
      procedure :: setup => br_setup
      procedure :: nhist => br_nhist
      procedure :: update => br_update
      procedure :: fails => br_fails
      procedure :: erodes => br_erodes
   end type mat_brittle_t

contains

   subroutine br_read_cards(self, c)
      class(mat_brittle_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      integer :: k
      call read_mid_ro(self, c)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('SIGY', 0.0_wp, self%sigy)
      call c%real('ETAN', 0.0_wp, self%etan)
      call c%int('MODEL', 0, self%model)
      call c%int('EROD', 0, self%erod)
      call c%next()
      call c%real('GFR', 1.0_wp, self%gfr)
      call c%real('D0', 0.0_wp, self%d0)
      call c%real('DMAX', 1.0_wp, self%dmax)
      call c%real('PFMIN', 0.0_wp, self%pfmin)
      call c%next()
      do k = 1, 8
         call c%real('P'//str(k), 0.0_wp, self%p(k))
      end do
      call read_yield_curve(c, self%pf, self%yf)
   end subroutine br_read_cards

   !> The failed-material curve: card PF1..PF8 (pressures), card YF1..YF8 (yield stresses).
   subroutine read_yield_curve(c, pf, yf)
      type(card_t), intent(inout) :: c
      real(wp), intent(out) :: pf(NPF), yf(NPF)
      integer :: k
      call c%next()
      do k = 1, NPF
         call c%real('PF'//str(k), 0.0_wp, pf(k))
      end do
      call c%next()
      do k = 1, NPF
         call c%real('YF'//str(k), 0.0_wp, yf(k))
      end do
   end subroutine read_yield_curve

   !> Points in use n (the last one with a non-zero PF or YF; at least 1); PF strictly
   !> increasing, YF >= 0 and non-decreasing (strength does not fall with pressure).
   subroutine check_yield_curve(pf, yf, n, error)
      real(wp), intent(in) :: pf(NPF), yf(NPF)
      integer, intent(out) :: n
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      n = 1
      do k = NPF, 1, -1
         if (pf(k) /= 0.0_wp .or. yf(k) /= 0.0_wp) then
            n = k
            exit
         end if
      end do
      do k = 1, n
         if (.not. (yf(k) >= 0.0_wp)) then
            call set_field_error(error, 'YF'//str(k), 'failed yield stress must be >= 0, got '// &
                                 rstr(yf(k))); return
         end if
      end do
      do k = 2, n
         if (.not. (pf(k) > pf(k - 1))) then
            call set_field_error(error, 'PF'//str(k), 'the pressures must increase: PF'// &
               str(k)//' = '//rstr(pf(k))//' after PF'//str(k - 1)//' = '//rstr(pf(k - 1))); return
         end if
         if (.not. (yf(k) >= yf(k - 1))) then
            call set_field_error(error, 'YF'//str(k), 'yield versus pressure must not decrease: YF'// &
               str(k)//' = '//rstr(yf(k))//' after YF'//str(k - 1)//' = '//rstr(yf(k - 1))); return
         end if
      end do
   end subroutine check_yield_curve

   !> Y_f(p): linear between the n points (pf, yf), constant beyond the ends.
   pure real(wp) function yield_vs_pressure(pf, yf, n, p) result(y)
      real(wp), intent(in) :: pf(:), yf(:), p
      integer, intent(in) :: n
      integer :: k
      if (p <= pf(1) .or. n == 1) then
         y = yf(1)
         return
      end if
      do k = 2, n
         if (p <= pf(k)) then
            y = yf(k - 1) + (yf(k) - yf(k - 1))*(p - pf(k - 1))/(pf(k) - pf(k - 1))
            return
         end if
      end do
      y = yf(n)
   end function yield_vs_pressure

   subroutine br_setup(self, error)
      class(mat_brittle_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      character(6), parameter :: names(3, 5) = reshape([character(6) :: &
         'SIGR', 'D1', 'SIGT', 'LAMBDA', 'D2', 'CG', 'KF', 'PHEL', 'LC', '', 'T', '', '', 'EFMIN', ''], &
         [3, 5])
      integer :: k
      call check_elastic_constants(self, self%e, self%pr, error)
      if (allocated(error)) return
      if (.not. (self%sigy > 0.0_wp)) then
         call set_field_error(error, 'SIGY', 'yield stress must be > 0, got '//rstr(self%sigy)); return
      end if
      if (.not. (self%etan >= 0.0_wp .and. self%etan < self%e)) then
         call set_field_error(error, 'ETAN', 'must lie in [0, E), got '//rstr(self%etan)); return
      end if
      if (self%model < 1 .or. self%model > 3) then
         call set_field_error(error, 'MODEL', 'must be 1 (modified Tuler-Butcher), 2 (JH-2 '// &
            'damage) or 3 (rate-limited growth), got '//str(self%model)); return
      end if
      if (self%erod /= 0 .and. self%erod /= 1) then
         call set_field_error(error, 'EROD', 'must be 0 or 1, got '//str(self%erod)); return
      end if
      if (.not. (self%gfr >= 0.0_wp .and. self%gfr <= 1.0_wp)) then
         call set_field_error(error, 'GFR', 'the damaged/undamaged shear modulus ratio must '// &
                              'lie in [0, 1], got '//rstr(self%gfr)); return
      end if
      if (.not. (self%d0 >= 0.0_wp .and. self%d0 <= 1.0_wp)) then
         call set_field_error(error, 'D0', 'the initial damage must lie in [0, 1], got '// &
                              rstr(self%d0)); return
      end if
      if (.not. (self%dmax >= self%d0 .and. self%dmax <= 1.0_wp)) then
         call set_field_error(error, 'DMAX', 'the damage limit must lie in [D0, 1], got '// &
                              rstr(self%dmax)); return
      end if
      if (.not. (self%pfmin <= 0.0_wp)) then
         call set_field_error(error, 'PFMIN', 'the failed material''s tension cut-off must '// &
                              'be <= 0, got '//rstr(self%pfmin)); return
      end if
      ! model parameters: thresholds >= 0, rates and scales > 0; a field the model does not
      ! use must stay blank or 0 (never silently ignored)
      ! (P1-P5: by the model's names; P6-P8: no model uses them)
      do k = 1, 5
         if (len_trim(names(self%model, k)) == 0) then
            call unused_field(k)
            if (allocated(error)) return
            cycle
         end if
         if (.not. (self%p(k) >= 0.0_wp)) then
            call set_field_error(error, 'P'//str(k), trim(names(self%model, k))// &
                                 ' must be >= 0, got '//rstr(self%p(k))); return
         end if
      end do
      do k = 6, 8
         call unused_field(k)
         if (allocated(error)) return
      end do
      select case (self%model)
      case (1)
         call positive(2); if (allocated(error)) return
         call positive(3); if (allocated(error)) return
      case (2)
         call positive(1); if (allocated(error)) return
         call positive(3); if (allocated(error)) return
      case (3)
         call positive(2); if (allocated(error)) return
         call positive(3); if (allocated(error)) return
      end select
      call check_yield_curve(self%pf, self%yf, self%npf, error)
      if (allocated(error)) return
      self%hard = self%e*self%etan/(self%e - self%etan)
      self%cl = sqrt((self%bulk + 4.0_wp*self%shear/3.0_wp)/self%ro)
      self%hv_eps_p = 1
      self%hv_damage = 2
   contains
      subroutine positive(k)
         integer, intent(in) :: k
         if (.not. (self%p(k) > 0.0_wp)) call set_field_error(error, 'P'//str(k), &
            trim(names(self%model, k))//' must be > 0, got '//rstr(self%p(k)))
      end subroutine positive
      !> a field the model does not use: blank or 0
      subroutine unused_field(k)
         integer, intent(in) :: k
         if (self%p(k) /= 0.0_wp) call set_field_error(error, 'P'//str(k), 'MODEL '// &
            str(self%model)//' does not use P'//str(k)//' (leave it blank or 0), got '// &
            rstr(self%p(k)))
      end subroutine unused_field
   end subroutine br_setup

   pure integer function br_nhist(self)
      class(mat_brittle_t), intent(in) :: self
      br_nhist = 15
      if (.false.) br_nhist = int(self%ro)
   end function br_nhist

   !> Radial return of the deviator s onto the von Mises radius y (y <= 0: s = 0); seq is
   !> sqrt(3/2 s:s) before the return.
   pure subroutine radial_return(s, y, seq)
      real(wp), intent(inout) :: s(6)
      real(wp), intent(in) :: y
      real(wp), intent(out) :: seq
      seq = sqrt(1.5_wp*sum(w*s**2))
      if (seq > y) then
         if (y > 0.0_wp) then
            s = s*(y/seq)
         else
            s = 0.0_wp
         end if
      end if
   end subroutine radial_return

   subroutine br_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_brittle_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: g, de(6), tr, si(6), s(6), seq, yi, dep, pi, p, dn, d, dm, q, gn, g1, s1, ef, y
      integer :: i
      g = self%shear
      do i = 1, nv
         if (.not. (relvol(i) > 0.0_wp)) then
            ierr(i) = 2
            cycle
         end if
         tr = (deps(i, 1) + deps(i, 2) + deps(i, 3))/3.0_wp
         de = deps(i, :)
         de(1:3) = de(1:3) - tr
         ! undamaged (effective) elastic-plastic point
         si = hv(i, 4:9) + 2.0_wp*g*de
         yi = self%sigy + self%hard*hv(i, 1)
         seq = sqrt(1.5_wp*sum(w*si**2))
         dep = 0.0_wp
         if (seq > yi) then
            dep = (seq - yi)/(3.0_wp*g + self%hard)
            si = si*(1.0_wp - 3.0_wp*g*dep/seq)
         end if
         pi = -self%bulk*log(relvol(i))
         ! damage evolution, driven by the undamaged state
         dn = hv(i, 2)
         q = hv(i, 3)
         select case (self%model)
         case (1)
            s1 = max_principal(si) - pi
            if (s1 > self%p(1)) q = q + dt*(s1 - self%p(1))**self%p(2)
            dm = q/self%p(3)
         case (2)
            if (pi <= -self%p(4)) then
               q = 1.0_wp
            else
               ef = max(self%p(5), self%p(1)*((pi + self%p(4))/self%p(3))**self%p(2))
               if (dep > 0.0_wp) q = q + dep/max(ef, tiny(1.0_wp))
            end if
            dm = q
         case default
            s1 = max_principal(si) - pi
            if (s1 >= self%p(1)) q = min(1.0_wp, q + self%p(2)*self%cl*dt/self%p(3))
            dm = q**3
         end select
         d = min(self%dmax, max(dn, self%d0 + (1.0_wp - self%d0)*min(1.0_wp, dm)))
         ! actual state: moduli, pressure and strength blended by D
         gn = g*(1.0_wp - dn + dn*self%gfr)
         g1 = g*(1.0_wp - d + d*self%gfr)
         s = hv(i, 10:15)
         if (gn > 0.0_wp) then
            s = s*(g1/gn)
         else
            s = 0.0_wp
         end if
         s = s + 2.0_wp*g1*de
         p = (1.0_wp - d)*pi + d*max(pi, self%pfmin)
         y = (1.0_wp - d)*(self%sigy + self%hard*(hv(i, 1) + dep)) + &
             d*yield_vs_pressure(self%pf, self%yf, self%npf, p)
         call radial_return(s, y, seq)
         sig(i, :) = s
         sig(i, 1:3) = s(1:3) - p
         hv(i, 1) = hv(i, 1) + dep
         hv(i, 2) = d
         hv(i, 3) = q
         hv(i, 4:9) = si
         hv(i, 10:15) = s
         if (.not. all(abs(sig(i, :)) < huge(1.0_wp))) ierr(i) = 2
      end do
      if (.false.) hv(1, 1) = eint(1)
   end subroutine br_update

   !> EROD = 1: points with D >= DMAX fail.
   subroutine br_fails(self, nv, hv, failed)
      class(mat_brittle_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      integer :: i
      do i = 1, nv
         failed(i) = self%erod == 1 .and. hv(i, 2) >= self%dmax
      end do
   end subroutine br_fails

   logical function br_erodes(self)
      class(mat_brittle_t), intent(in) :: self
      br_erodes = self%erod == 1
   end function br_erodes
end module dx_mat_brittle
