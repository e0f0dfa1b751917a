!> *MAT_JOHNSON_COOK (*MAT_015): J2 plasticity with the Johnson-Cook flow stress and damage.
!> Flow stress (Johnson & Cook, "A constitutive model and data for metals subjected to large
!> strains, high strain rates and high temperatures", Proc. 7th Int. Symp. Ballistics, The Hague,
!> 1983, 541-547):
!>    sigma_y = (A + B eps_p**N) (1 + C ln rate*) (1 - T*** M),
!>    rate* = rate/EPSO (the effective total strain rate sqrt(2/3 d':d') of the step; the factor
!>    is kept >= 1, i.e. rate* < 1 gives the quasi-static stress), T* = (T - TR)/(TM - TR);
!>    T* < 0: no thermal term; T* >= 1: melted, sigma_y = 0.
!> Failure strain and damage (Johnson & Cook, "Fracture characteristics of three metals subjected
!> to various strains, strain rates, temperatures and pressures", Eng. Fract. Mech. 21 (1985)
!> 31-48):
!>    eps_f = max(EFMIN, [D1 + D2 exp(D3 sigma*)][1 + D4 ln rate*][1 + D5 T*]),
!>    sigma* = -p/sigma_eq (mean stress over effective stress, tension positive),
!>    D = sum deps_p/eps_f, failure at D >= 1: with EROD = 0 the element erodes (fails; the
!>    deletion is the explicit cycle's), with EROD = 1 it keeps no deviatoric stress and no
!>    tension. D lives in history slot hv_damage for the plot states.
!> Fields and defaults as LS-DYNA (Keyword User's Manual Vol. II, *MAT_JOHNSON_COOK): cards
!> MID RO G E PR DTF VP RATEOP; A B N C M TM TR EPSO; CP PC SPALL IT D1 D2 D3 D4;
!> D5 C2/P EROD EFMIN NUMINT. Pressure from the part's EOS (EOSID > 0, the energy update of
!> dx_eos with the half-step correction of dx_mat_steinberg), else elastic, dp = -K tr(deps)
!> with K = E/(3(1 - 2 PR)) (E > 0 is then required). Temperature: adiabatic heating by the
!> plastic work, T = TR + Wp/(RO CP) (all plastic work to heat; CP = 0: T = TR).
!> SPALL as *MAT_STEINBERG (PC blank: -1e30, no cut-off): 1 p >= PC; 2 (0 = default) the largest principal stress >= -PC
!> spalls; 3 p <= PC spalls; spalled: no deviatoric stress, p >= 0. IT = 0: the yield stress of
!> the step is taken at the plastic strain of its start (no iteration, LS-DYNA's default);
!> IT = 1: the radial return is solved for sigma_y(eps_p + deps_p) by safeguarded Newton.
!> Not supported (exit 2 naming the field): DTF /= 0, VP /= 0, RATEOP /= 0, C2/P /= 0.
!> History: 1 eps_p, 2 D, 3 T, 4 p, 5 V(n) (0: reference), 6 E, 7 c**2, 8 spalled/failed (0/1),
!> 9 sigma_y of the last update, 10 plastic work Wp per reference volume.
module dx_mat_johnson_cook
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   use dx_mat_hydro_common, only: hydro_material_t, deviatoric_split, &
                                  spall_reached, history_wave_speed
   implicit none
   private
   public :: mat_johnson_cook_t

   type, extends(hydro_material_t) :: mat_johnson_cook_t
      real(wp) :: g = 0.0_wp, e = 0.0_wp, pr = 0.0_wp
      real(wp) :: a = 0.0_wp, b = 0.0_wp, n = 0.0_wp, c = 0.0_wp, m = 0.0_wp
      real(wp) :: tm = 0.0_wp, tr = 0.0_wp, epso = 0.0_wp, cp = 0.0_wp, pc = 0.0_wp
      real(wp) :: d(5) = 0.0_wp, efmin = 0.0_wp
      integer :: spall = 2, it = 0, erod = 0
      logical :: damage = .false.
   contains
      procedure :: read_cards => jc_read_cards
      procedure :: setup => jc_setup
      procedure :: nhist => jc_nhist
      procedure :: update => jc_update
      procedure :: wave_speed => jc_wave_speed
      procedure :: fails => jc_fails
      procedure :: needs_eos => jc_needs_eos
      procedure :: flow_stress => jc_flow_stress
      procedure :: failure_strain => jc_failure_strain
   end type mat_johnson_cook_t

contains

   subroutine jc_read_cards(self, c)
      class(mat_johnson_cook_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      real(wp) :: x
      call read_mid_ro(self, c)
      call c%real('G', 0.0_wp, self%g)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('DTF', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('DTF', 'erosion by a minimum time step is '// &
         'not supported (DTF must be 0), got '//rstr(x))
      call c%real('VP', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('VP', 'only the scaled-yield rate form '// &
         '(VP = 0) is supported, got '//rstr(x))
      call c%real('RATEOP', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('RATEOP', 'only the logarithmic rate term '// &
         '(RATEOP = 0) is supported, got '//rstr(x))
      call c%next()
      call c%real('A', 0.0_wp, self%a)
      call c%real('B', 0.0_wp, self%b)
      call c%real('N', 0.0_wp, self%n)
      call c%real('C', 0.0_wp, self%c)
      call c%real('M', 0.0_wp, self%m)
      call c%real('TM', 0.0_wp, self%tm)
      call c%real('TR', 0.0_wp, self%tr)
      call c%real('EPSO', 0.0_wp, self%epso)
      call c%next()
      call c%real('CP', 0.0_wp, self%cp)
      call c%real('PC', -1.0e30_wp, self%pc)
      call c%real('SPALL', 0.0_wp, x)
      if (c%ok() .and. .not. (x == 0.0_wp .or. x == 1.0_wp .or. x == 2.0_wp .or. x == 3.0_wp)) &
         call c%fail('SPALL', 'spall type must be 0, 1, 2 or 3, got '//rstr(x))
      self%spall = nint(x)
      if (self%spall == 0) self%spall = 2
      call c%real('IT', 0.0_wp, x)
      if (c%ok() .and. .not. (x == 0.0_wp .or. x == 1.0_wp)) &
         call c%fail('IT', 'must be 0 (no iterations) or 1 (iterated return), got '//rstr(x))
      self%it = nint(x)
      call c%real('D1', 0.0_wp, self%d(1))
      call c%real('D2', 0.0_wp, self%d(2))
      call c%real('D3', 0.0_wp, self%d(3))
      call c%real('D4', 0.0_wp, self%d(4))
      call c%next()
      call c%real('D5', 0.0_wp, self%d(5))
      call c%real('C2/P', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('C2/P', 'the second rate term is not '// &
         'supported (must be 0), got '//rstr(x))
      call c%real('EROD', 0.0_wp, x)
      if (c%ok() .and. .not. (x == 0.0_wp .or. x == 1.0_wp)) &
         call c%fail('EROD', 'must be 0 (erosion) or 1 (no erosion), got '//rstr(x))
      self%erod = nint(x)
      call c%real('EFMIN', 0.0_wp, self%efmin)
      call c%real('NUMINT', 0.0_wp, x)
   end subroutine jc_read_cards

   subroutine jc_setup(self, error)
      class(mat_johnson_cook_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (.not. (self%ro > 0.0_wp)) then
         call set_field_error(error, 'RO', 'density must be > 0, got '//rstr(self%ro)); return
      end if
      if (.not. (self%g > 0.0_wp)) then
         call set_field_error(error, 'G', 'shear modulus must be > 0, got '//rstr(self%g)); return
      end if
      if (.not. (self%e >= 0.0_wp)) then
         call set_field_error(error, 'E', 'must be >= 0, got '//rstr(self%e)); return
      end if
      if (self%e > 0.0_wp .and. .not. (self%pr >= 0.0_wp .and. self%pr < 0.5_wp)) then
         call set_field_error(error, 'PR', 'Poisson''s ratio must be in [0, 0.5), got '// &
                              rstr(self%pr)); return
      end if
      if (.not. (self%a > 0.0_wp)) then
         call set_field_error(error, 'A', 'yield stress must be > 0, got '//rstr(self%a)); return
      end if
      if (.not. (self%b >= 0.0_wp)) then
         call set_field_error(error, 'B', 'must be >= 0, got '//rstr(self%b)); return
      end if
      if (.not. (self%n >= 0.0_wp)) then
         call set_field_error(error, 'N', 'must be >= 0, got '//rstr(self%n)); return
      end if
      if (self%c /= 0.0_wp .and. .not. (self%epso > 0.0_wp)) then
         call set_field_error(error, 'EPSO', 'the reference strain rate must be > 0 with C = '// &
                              rstr(self%c)//', got '//rstr(self%epso)); return
      end if
      if (self%cp /= 0.0_wp .and. .not. (self%tm > self%tr)) then
         call set_field_error(error, 'TM', 'the melt temperature must exceed TR = '// &
                              rstr(self%tr)//', got '//rstr(self%tm)); return
      end if
      if (.not. (self%cp >= 0.0_wp)) then
         call set_field_error(error, 'CP', 'must be >= 0, got '//rstr(self%cp)); return
      end if
      if (self%cp > 0.0_wp .and. .not. (self%m > 0.0_wp)) then
         call set_field_error(error, 'M', 'the thermal exponent must be > 0, got '// &
                              rstr(self%m)); return
      end if
      if (.not. (self%pc <= 0.0_wp)) then
         call set_field_error(error, 'PC', 'the spall/cut-off pressure must be <= 0, got '// &
                              rstr(self%pc)); return
      end if
      if (.not. (self%efmin >= 0.0_wp)) then
         call set_field_error(error, 'EFMIN', 'must be >= 0, got '//rstr(self%efmin)); return
      end if
      self%damage = any(self%d /= 0.0_wp)
      self%shear = self%g
      self%bulk = 0.0_wp
      if (self%e > 0.0_wp) self%bulk = self%e/(3.0_wp*(1.0_wp - 2.0_wp*self%pr))
      self%hv_eps_p = 1
      if (self%damage) self%hv_damage = 2
   end subroutine jc_setup

   pure integer function jc_nhist(self)
      class(mat_johnson_cook_t), intent(in) :: self
      jc_nhist = 10
      if (.false.) jc_nhist = int(self%ro)
   end function jc_nhist

   !> Without E the elastic pressure has no bulk modulus: an EOS is then needed.
   logical function jc_needs_eos(self)
      class(mat_johnson_cook_t), intent(in) :: self
      jc_needs_eos = .not. (self%e > 0.0_wp)
   end function jc_needs_eos

   !> Johnson-Cook flow stress at plastic strain ep, rate factor rf = max(1, 1 + C ln rate*)
   !> and temperature t; dy = d sigma_y/d eps_p (0 at eps_p = 0 when N < 1: the Newton
   !> iteration is safeguarded).
   pure subroutine jc_flow_stress(self, ep, rf, t, y, dy)
      class(mat_johnson_cook_t), intent(in) :: self
      real(wp), intent(in) :: ep, rf, t
      real(wp), intent(out) :: y, dy
      real(wp) :: tf, ts
      tf = 1.0_wp
      if (self%cp > 0.0_wp) then
         ts = (t - self%tr)/(self%tm - self%tr)
         if (ts >= 1.0_wp) then
            tf = 0.0_wp
         else if (ts > 0.0_wp) then
            tf = 1.0_wp - ts**self%m
         end if
      end if
      y = 0.0_wp
      dy = 0.0_wp
      if (ep > 0.0_wp) then
         y = self%b*ep**self%n
         dy = self%n*y/ep
      end if
      y = (self%a + y)*rf*tf
      dy = dy*rf*tf
   end subroutine jc_flow_stress

   !> Johnson-Cook (1985) failure strain at triaxiality sst = -p/sigma_eq, rate* and T.
   pure real(wp) function jc_failure_strain(self, sst, rate_s, t) result(ef)
      class(mat_johnson_cook_t), intent(in) :: self
      real(wp), intent(in) :: sst, rate_s, t
      real(wp) :: ts
      ts = 0.0_wp
      if (self%tm > self%tr) ts = (t - self%tr)/(self%tm - self%tr)
      ef = (self%d(1) + self%d(2)*exp(self%d(3)*sst))* &
           (1.0_wp + self%d(4)*log(max(rate_s, 1.0_wp)))*(1.0_wp + self%d(5)*ts)
      ef = max(ef, self%efmin)
   end function jc_failure_strain

   subroutine jc_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_johnson_cook_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]
      real(wp) :: v, vold, pn, so(6), s(6), de(6), tr, seq, ep, dep, y, dy, r, lo, hi, g
      real(wp) :: rate, rate_s, rf, t, estar, e1, p1, ef, sst
      integer :: i, k
      g = self%g
      do i = 1, nv
         v = relvol(i)
         if (self%damage .and. self%erod == 0 .and. hv(i, 2) >= 1.0_wp) then
            sig(i, :) = 0.0_wp          ! eroded (fails): no stress, no EOS, never flagged
            hv(i, 5) = v
            cycle
         end if
         vold = hv(i, 5)
         if (vold == 0.0_wp) then
            vold = 1.0_wp
            hv(i, 3) = self%tr
            if (allocated(self%eos)) hv(i, 4) = self%eos%pressure(1.0_wp, self%eos%e0 + eint(i))
         end if
         pn = hv(i, 4)
         ep = hv(i, 1)
         t = hv(i, 3)
         call deviatoric_split(sig(i, :), deps(i, :), so, de, tr)
         rate = 0.0_wp
         if (dt > 0.0_wp) rate = sqrt(2.0_wp/3.0_wp*sum(w*de**2))/dt
         rate_s = 1.0_wp
         if (self%epso > 0.0_wp) rate_s = rate/self%epso
         rf = 1.0_wp
         if (rate_s > 1.0_wp) rf = max(1.0_wp, 1.0_wp + self%c*log(rate_s))
         s = so + 2.0_wp*g*de
         seq = sqrt(1.5_wp*sum(w*s**2))
         call self%flow_stress(ep, rf, t, y, dy)
         dep = 0.0_wp
         if (hv(i, 8) /= 0.0_wp) then
            s = 0.0_wp
         else if (seq > y) then
            if (self%it == 0 .or. y == 0.0_wp) then
               dep = (seq - y)/(3.0_wp*g)
            else
               lo = 0.0_wp
               hi = seq/(3.0_wp*g)
               dep = (seq - y)/(3.0_wp*g + dy)
               do k = 1, 80
                  call self%flow_stress(ep + dep, rf, t, y, dy)
                  r = seq - 3.0_wp*g*dep - y
                  if (abs(r) <= 4.0_wp*epsilon(1.0_wp)*seq) exit
                  if (r > 0.0_wp) then
                     lo = dep
                  else
                     hi = dep
                  end if
                  dep = dep + r/(3.0_wp*g + dy)
                  if (.not. (dep > lo .and. dep < hi)) dep = 0.5_wp*(lo + hi)
               end do
            end if
            s = s*(1.0_wp - 3.0_wp*g*dep/seq)
            hv(i, 10) = hv(i, 10) + 0.5_wp*(y + seq - 3.0_wp*g*dep)*dep*v
         end if
         ! ---- pressure: the EOS with the half-step energy correction, else elastic
         if (allocated(self%eos)) then
            estar = self%eos%e0 + eint(i) + sum(w*0.5_wp*(so + s)*de)*0.5_wp*(v + vold)
            call self%eos%energy_update(v, v - vold, estar, pn, e1, p1)
            hv(i, 7) = self%eos%sound_speed2(self%ro, v, e1) + 4.0_wp*g*v/(3.0_wp*self%ro)
         else
            e1 = eint(i)
            p1 = pn - 3.0_wp*self%bulk*tr
            hv(i, 7) = (self%bulk + 4.0_wp*g/3.0_wp)*v/self%ro
         end if
         if (self%cp > 0.0_wp) t = self%tr + hv(i, 10)/(self%ro*self%cp)
         ! ---- damage (Johnson-Cook 1985) and failure
         seq = sqrt(1.5_wp*sum(w*s**2))
         if (self%damage .and. dep > 0.0_wp .and. hv(i, 2) < 1.0_wp) then
            sst = 0.0_wp
            if (seq > 0.0_wp) sst = -p1/seq
            ef = self%failure_strain(sst, rate_s, t)
            if (ef > 0.0_wp) then
               hv(i, 2) = min(1.0_wp, hv(i, 2) + dep/ef)
            else
               hv(i, 2) = 1.0_wp
            end if
         end if
         if (hv(i, 8) == 0.0_wp) then
            if (spall_reached(self%spall, self%pc, s, p1)) hv(i, 8) = 1.0_wp
            if (self%damage .and. hv(i, 2) >= 1.0_wp) hv(i, 8) = 1.0_wp
         end if
         p1 = max(p1, self%pc)
         if (hv(i, 8) /= 0.0_wp) then
            s = 0.0_wp
            p1 = max(p1, 0.0_wp)
         end if
         if (.not. (abs(p1) < huge(1.0_wp))) ierr(i) = 2   ! a material failure
         if (allocated(self%eos)) then
            if (.not. self%eos%in_range(v)) ierr(i) = 2   ! compressed past the EOS's range
         end if
         sig(i, :) = s
         sig(i, 1:3) = s(1:3) - p1
         hv(i, 1) = ep + dep
         hv(i, 3) = t
         hv(i, 4) = p1
         hv(i, 5) = v
         hv(i, 6) = e1
         call self%flow_stress(ep + dep, rf, t, y, dy)
         hv(i, 9) = y
      end do
   end subroutine jc_update

   subroutine jc_wave_speed(self, nv, relvol, hv, c)
      class(mat_johnson_cook_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: relvol(nv)
      real(wp), intent(in) :: hv(:, :)
      real(wp), intent(out) :: c(nv)
      call history_wave_speed(nv, relvol, hv, 5, 7, self%bulk + 4.0_wp*self%g/3.0_wp, self%ro, c)
   end subroutine jc_wave_speed

   !> Erosion at D >= 1 with EROD = 0 (damage parameters given).
   subroutine jc_fails(self, nv, hv, failed)
      class(mat_johnson_cook_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      integer :: i
      do i = 1, nv
         failed(i) = self%damage .and. self%erod == 0 .and. hv(i, 2) >= 1.0_wp
      end do
   end subroutine jc_fails
end module dx_mat_johnson_cook
