!> *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024): isotropic J2 plasticity with tabulated
!> hardening, radial return (Wilkins 1964; Krieg & Krieg 1977) solved exactly for the
!> piecewise-linear hardening curve by a safeguarded Newton iteration.
!> Yield curve, in LS-DYNA's order of precedence: LCSS (curve of yield stress against effective
!> plastic strain, extrapolated linearly beyond its last point), else the EPS1-8/ES1-8 pairs,
!> else the bilinear SIGY + Ep*eps_p with Ep = E*ETAN/(E - ETAN).
!> Rate effects: LCSR (yield scale factor against strain rate), else Cowper-Symonds C, P.
!> VP = 0 scales the yield stress with the effective total (deviatoric) strain rate,
!> R = 1 + (rate/C)**(1/P); VP = 1 is viscoplastic: sigma_y = h(eps_p) + SIGY*(rate_p/C)**(1/P)
!> with the plastic strain rate of the step, solved in the same return.
!> FAIL: effective plastic strain at which the element erodes. History: 1 = eff. plastic strain,
!> 2 = static yield stress h(eps_p) at that strain (a cache: 0 = not yet evaluated), so an
!> elastic step costs no curve lookup and no square root.
!> Laminae (update_plane_stress, sigma33 = 0): dx_plane_stress by the algorithm ps_alg with the
!> yield radius R*h(eps_p) (the curve itself, or its bilinear form), isotropic hardening; R from
!> the lamina strain rate ps_rate. VP = 1 with C, P > 0 has no plane-stress form yet
!> (MAT_ERR_NO_PLANE_STRESS).
module dx_mat_piecewise_linear
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, set_field_error
   use dx_strings, only: rstr, str
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro, MAT_ERR_NO_PLANE_STRESS, MAT_ERR_PS_ALG
   use dx_plane_stress, only: ps_update, ps_rate, ps_alg_valid, ps_fibre_constants
   use dx_mat_elastic, only: check_elastic_constants
   use dx_curve, only: curve_t
   implicit none
   private
   public :: mat_piecewise_linear_t

   type, extends(material_t) :: mat_piecewise_linear_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp, sigy = 0.0_wp, etan = 0.0_wp
      real(wp) :: fail = 1.0e21_wp, tdel = 0.0_wp
      real(wp) :: c = 0.0_wp, p = 0.0_wp
      integer :: lcss = 0, lcsr = 0          !< curve labels from the deck
      real(wp) :: vp = 0.0_wp
      real(wp) :: eps(8) = 0.0_wp, es(8) = 0.0_wp
      type(curve_t) :: hard                  !< hardening curve h(eps_p) in use
      logical :: bilinear = .true.
      real(wp) :: ep = 0.0_wp                !< bilinear plastic modulus
      type(curve_t) :: rate_curve
      logical :: has_rate_curve = .false.
   contains
      procedure :: read_cards => pl_read_cards
      procedure :: reads_curves => pl_reads_curves
      procedure :: setup => pl_setup
      procedure :: nhist => pl_nhist
      procedure :: update => pl_update
      procedure :: fails => pl_fails
      procedure :: resolve_curves => pl_resolve
      procedure :: yield_static            !< h(eps_p)
      procedure :: update_plane_stress => pl_update_plane_stress
   end type mat_piecewise_linear_t

contains

   !> Card 1: MID RO E PR SIGY ETAN FAIL TDEL; card 2: C P LCSS LCSR VP LCF;
   !> cards 3, 4: EPS1-8, ES1-8.
   subroutine pl_read_cards(self, c)
      class(mat_piecewise_linear_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      integer :: k, lcf
      call read_mid_ro(self, c)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('SIGY', 0.0_wp, self%sigy)
      call c%real('ETAN', 0.0_wp, self%etan)
      call c%real('FAIL', 1.0e21_wp, self%fail)
      call c%real('TDEL', 0.0_wp, self%tdel)
      if (self%fail == 0.0_wp) self%fail = 1.0e21_wp
      call c%next()
      call c%real('C', 0.0_wp, self%c)
      call c%real('P', 0.0_wp, self%p)
      call c%int('LCSS', 0, self%lcss)
      call c%int('LCSR', 0, self%lcsr)
      call c%real('VP', 0.0_wp, self%vp)
      call c%int('LCF', 0, lcf)
      if (c%ok() .and. lcf /= 0) call c%fail('LCF', 'failure strain curves are not supported')
      call c%next()
      do k = 1, 8
         call c%real('EPS'//str(k), 0.0_wp, self%eps(k))
      end do
      call c%next()
      do k = 1, 8
         call c%real('ES'//str(k), 0.0_wp, self%es(k))
      end do
   end subroutine pl_read_cards

   !> The parameter checks wait for the curves when LCSS or LCSR names one.
   logical function pl_reads_curves(self)
      class(mat_piecewise_linear_t), intent(in) :: self
      pl_reads_curves = self%lcss /= 0 .or. self%lcsr /= 0
   end function pl_reads_curves

   subroutine pl_resolve(self, curves, error)
      class(mat_piecewise_linear_t), intent(inout) :: self
      type(curve_t), intent(in) :: curves(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      if (self%lcss /= 0) then
         k = findloc(curves(:)%label, self%lcss, dim=1)
         if (k == 0) then
            call set_field_error(error, 'LCSS', 'curve '//str(self%lcss)//' is not defined'); return
         end if
         self%hard = curves(k)
         self%bilinear = .false.
      end if
      if (self%lcsr /= 0) then
         k = findloc(curves(:)%label, self%lcsr, dim=1)
         if (k == 0) then
            call set_field_error(error, 'LCSR', 'curve '//str(self%lcsr)//' is not defined'); return
         end if
         self%rate_curve = curves(k)
         self%has_rate_curve = .true.
      end if
   end subroutine pl_resolve

   subroutine pl_setup(self, error)
      class(mat_piecewise_linear_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer :: n
      call check_elastic_constants(self, self%e, self%pr, error)
      if (allocated(error)) return
      if (self%tdel /= 0.0_wp) then
         call set_field_error(error, 'TDEL', 'element deletion by time step is not supported')
         return
      end if
      if (self%fail < 0.0_wp) then
         call set_field_error(error, 'FAIL', 'user failure subroutines (FAIL < 0) are not '// &
                              'supported')
         return
      end if
      if (self%fail == 0.0_wp) self%fail = 1.0e21_wp
      if (self%vp /= 0.0_wp .and. self%vp /= 1.0_wp) then
         call set_field_error(error, 'VP', 'must be 0 or 1, got '//rstr(self%vp)); return
      end if
      if (self%c < 0.0_wp .or. self%p < 0.0_wp .or. &
          ((self%c > 0.0_wp) .neqv. (self%p > 0.0_wp))) then
         call set_error(error, 'fields C, P: Cowper-Symonds C and P must both be > 0 '// &
                        '(or both 0), got '//rstr(self%c)//', '//rstr(self%p)); return
      end if
      if (self%vp == 1.0_wp .and. self%has_rate_curve) then
         call set_field_error(error, 'LCSR', 'VP = 1 with a rate curve is not supported'); return
      end if
      if (self%bilinear .and. any(self%es /= 0.0_wp)) then
         ! EPS/ES pairs (LS-DYNA: EPS1 < EPS2 < ...; the table ends at the first EPSk = 0
         ! after EPS1): a non-zero EPSk that does not increase, or one after the end, is
         ! refused naming the field (never a silently shortened table)
         call eps_table_length(self%eps, n, error)
         if (allocated(error)) return
         if (n < 2) then
            call set_error(error, 'fields EPS1-8/ES1-8: at least two points with increasing '// &
                           'EPS are needed'); return
         end if
         self%hard%x = self%eps(1:n)
         self%hard%y = self%es(1:n)
         self%bilinear = .false.
      end if
      if (self%bilinear) then
         if (.not. (self%sigy > 0.0_wp)) then
            call set_field_error(error, 'SIGY', 'yield stress must be > 0, got '//rstr(self%sigy))
            return
         end if
         if (self%etan < 0.0_wp .or. self%etan >= self%e) then
            call set_field_error(error, 'ETAN', 'tangent modulus must lie in [0, E), got '// &
                           rstr(self%etan)); return
         end if
         self%ep = self%e*self%etan/(self%e - self%etan)
      else
         if (size(self%hard%x) < 1) then
            call set_field_error(error, 'LCSS', 'the hardening curve has no points'); return
         end if
         if (.not. (self%hard%eval_extrap(0.0_wp) > 0.0_wp)) then
            call set_field_error(error, 'LCSS', 'the initial yield stress of the curve must be '// &
                           '> 0, got '//rstr(self%hard%eval_extrap(0.0_wp))); return
         end if
      end if
      self%hv_eps_p = 1
   end subroutine pl_setup

   !> The number n of EPS1-8 points in the table (LS-DYNA's *MAT_024 cards 3-4): EPS1 >= 0,
   !> then EPS2, EPS3, ... each > the one before, up to the first EPSk = 0 (k >= 2) which
   !> ends the table; every EPS after the end must be 0. Errors name the field.
   subroutine eps_table_length(eps, n, error)
      real(wp), intent(in) :: eps(8)
      integer, intent(out) :: n
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      if (.not. (eps(1) >= 0.0_wp)) then
         call set_field_error(error, 'EPS1', 'plastic strain must be >= 0, got '//rstr(eps(1)))
         n = 0; return
      end if
      n = 1
      do i = 2, 8
         if (eps(i) == 0.0_wp) exit
         if (.not. (eps(i) > eps(i-1))) then
            call set_field_error(error, 'EPS'//str(i), 'the plastic strains EPS1-8 must '// &
               'increase: EPS'//str(i)//' = '//rstr(eps(i))//' after EPS'//str(i-1)//' = '// &
               rstr(eps(i-1))//' (EPSk = 0 ends the table)')
            return
         end if
         n = i
      end do
      do i = n + 2, 8
         if (eps(i) /= 0.0_wp) then
            call set_field_error(error, 'EPS'//str(i), 'the table ended at EPS'//str(n+1)// &
               ' = 0; a later value '//rstr(eps(i))//' would be ignored')
            return
         end if
      end do
   end subroutine eps_table_length

   pure integer function pl_nhist(self)
      class(mat_piecewise_linear_t), intent(in) :: self
      pl_nhist = 2
   end function pl_nhist

   !> Static yield stress h(eps_p) and its slope.
   pure subroutine yield_static(self, epsp, h, dh)
      class(mat_piecewise_linear_t), intent(in) :: self
      real(wp), intent(in) :: epsp
      real(wp), intent(out) :: h, dh
      if (self%bilinear) then
         h = self%sigy + self%ep*epsp
         dh = self%ep
      else if (size(self%hard%x) == 1) then
         h = self%hard%y(1); dh = 0.0_wp
      else
         h = self%hard%eval_extrap(epsp)
         dh = self%hard%slope(epsp)
      end if
   end subroutine yield_static

   subroutine pl_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_piecewise_linear_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: g, g2, k, p, dv, s(6), s2, seff, r, h, dh, rate, dep, scale
      integer :: i
      g = self%shear
      g2 = 2.0_wp*g
      k = self%bulk
      do i = 1, nv
         dv = (deps(i, 1) + deps(i, 2) + deps(i, 3))/3.0_wp
         p = (sig(i, 1) + sig(i, 2) + sig(i, 3))/3.0_wp
         s(1) = sig(i, 1) - p + g2*(deps(i, 1) - dv)
         s(2) = sig(i, 2) - p + g2*(deps(i, 2) - dv)
         s(3) = sig(i, 3) - p + g2*(deps(i, 3) - dv)
         s(4) = sig(i, 4) + g2*deps(i, 4)
         s(5) = sig(i, 5) + g2*deps(i, 5)
         s(6) = sig(i, 6) + g2*deps(i, 6)
         p = p + 3.0_wp*k*dv
         s2 = s(1)**2 + s(2)**2 + s(3)**2 + 2.0_wp*(s(4)**2 + s(5)**2 + s(6)**2)
         h = hv(i, 2)
         if (h <= 0.0_wp) then
            call self%yield_static(hv(i, 1), h, dh)
            hv(i, 2) = h
         end if
         r = 1.0_wp
         if (self%vp == 0.0_wp .and. (self%c > 0.0_wp .or. self%has_rate_curve) .and. &
             dt > 0.0_wp) then
            rate = sqrt((2.0_wp/3.0_wp)*((deps(i, 1) - dv)**2 + (deps(i, 2) - dv)**2 + &
                   (deps(i, 3) - dv)**2 + 2.0_wp*(deps(i, 4)**2 + deps(i, 5)**2 + &
                   deps(i, 6)**2)))/dt
            if (self%has_rate_curve) then
               r = self%rate_curve%eval(rate)
            else
               r = 1.0_wp + (rate/self%c)**(1.0_wp/self%p)
            end if
         end if
         ! elastic unless sqrt(3/2 s:s) exceeds the yield stress (compared squared)
         if (1.5_wp*s2 > (r*h)**2 .or. (self%vp == 1.0_wp .and. 1.5_wp*s2 > h**2)) then
            seff = sqrt(1.5_wp*s2)
            if (self%vp == 1.0_wp .and. self%c > 0.0_wp .and. dt > 0.0_wp) then
               dep = -1.0_wp
            else
               call return_map_linear(self, seff, hv(i, 1), r, dep, h)
            end if
            if (dep < 0.0_wp) then
               dep = return_map(self, seff, hv(i, 1), r, dt)
               if (dep < 0.0_wp) then
                  ierr(i) = 1
                  dep = 0.0_wp
               end if
               call self%yield_static(hv(i, 1) + dep, h, dh)
            end if
            scale = 1.0_wp - 3.0_wp*g*dep/seff
            s = s*scale
            hv(i, 1) = hv(i, 1) + dep
            hv(i, 2) = h
         end if
         sig(i, 1:3) = s(1:3) + p
         sig(i, 4:6) = s(4:6)
      end do
   end subroutine pl_update

   !> Rate-independent radial return on the piecewise-linear hardening curve, solved exactly:
   !> on the segment k holding eps_p + dep, h(e) = y_k + s_k (e - x_k) and
   !> seff - 3G dep = r h(eps_p + dep) is linear in dep; walk forward over the segment ends.
   !> Returns dep and the new static yield stress h; dep = -1 when a segment softens faster
   !> than 3G/r (the caller then uses the safeguarded Newton of return_map).
   pure subroutine return_map_linear(self, seff, epsp, r, dep, h)
      class(mat_piecewise_linear_t), intent(in) :: self
      real(wp), intent(in) :: seff, epsp, r
      real(wp), intent(out) :: dep, h
      real(wp) :: sk, den
      integer :: k, n
      if (self%bilinear) then
         den = 3.0_wp*self%shear + r*self%ep
         dep = max(0.0_wp, (seff - r*(self%sigy + self%ep*epsp))/den)
         h = self%sigy + self%ep*(epsp + dep)
         return
      end if
      n = size(self%hard%x)
      if (n == 1) then
         dep = max(0.0_wp, (seff - r*self%hard%y(1))/(3.0_wp*self%shear))
         h = self%hard%y(1)
         return
      end if
      k = 1
      do while (k < n - 1)
         if (self%hard%x(k + 1) > epsp) exit
         k = k + 1
      end do
      do
         sk = (self%hard%y(k + 1) - self%hard%y(k))/(self%hard%x(k + 1) - self%hard%x(k))
         den = 3.0_wp*self%shear + r*sk
         if (.not. (den > 0.0_wp)) then
            dep = -1.0_wp; h = 0.0_wp
            return
         end if
         dep = max(0.0_wp, (seff - r*(self%hard%y(k) + sk*(epsp - self%hard%x(k))))/den)
         if (k == n - 1) exit
         if (epsp + dep <= self%hard%x(k + 1)) exit
         k = k + 1
      end do
      h = self%hard%y(k) + sk*(epsp + dep - self%hard%x(k))
   end subroutine return_map_linear

   !> Solve seff - 3G*dep = yield(eps_p + dep) for dep >= 0: safeguarded Newton on the
   !> piecewise-linear (or viscoplastic) yield function. Returns -1 if it fails.
   function return_map(self, seff, epsp, r, dt) result(dep)
      class(mat_piecewise_linear_t), intent(in) :: self
      real(wp), intent(in) :: seff, epsp, r, dt
      real(wp) :: dep
      real(wp) :: lo, hi, f, df, h, dh, yv, dyv, x
      integer :: it
      lo = 0.0_wp
      hi = seff/(3.0_wp*self%shear)      ! f(hi) <= 0 since the yield stress is >= 0
      call self%yield_static(epsp, h, dh)
      x = max(0.0_wp, (seff - r*h)/(3.0_wp*self%shear + r*max(dh, 0.0_wp)))
      x = min(x, hi)
      do it = 1, 60
         call self%yield_static(epsp + x, h, dh)
         if (self%vp == 1.0_wp .and. self%c > 0.0_wp .and. dt > 0.0_wp) then
            yv = 0.0_wp; dyv = 0.0_wp
            if (x > 0.0_wp) then
               yv = self%sigy*(x/(dt*self%c))**(1.0_wp/self%p)
               dyv = yv/(self%p*x)
            end if
            f = seff - 3.0_wp*self%shear*x - h - yv
            df = -3.0_wp*self%shear - dh - dyv
         else
            f = seff - 3.0_wp*self%shear*x - r*h
            df = -3.0_wp*self%shear - r*dh
         end if
         if (f > 0.0_wp) then
            lo = x
         else
            hi = x
         end if
         if (abs(f) <= 1.0e-13_wp*seff) then
            dep = x; return
         end if
         x = x - f/df
         if (x <= lo .or. x >= hi) x = 0.5_wp*(lo + hi)
         if (hi - lo <= 1.0e-15_wp*max(hi, 1.0e-300_wp)) then
            dep = x; return
         end if
      end do
      dep = -1.0_wp
   end function return_map

   !> Lamina update (sigma33 = 0) of nv points: see the module header and dx_plane_stress.
   subroutine pl_update_plane_stress(self, nv, dt, deps, sig, hv, ierr, dezz, fibre)
      class(mat_piecewise_linear_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 5)
      real(wp), intent(inout) :: sig(nv, 5)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), intent(out), optional :: dezz(nv)
      logical, intent(in), optional :: fibre
      real(wp) :: ee, nu
      real(wp) :: alpha(nv, 3), epsp(nv), y0(nv), hi(nv), dep(nv), r(nv), h, dh, rate
      logical :: tab
      integer :: i
      if (self%vp == 1.0_wp .and. self%c > 0.0_wp) then
         ierr = MAT_ERR_NO_PLANE_STRESS
         return
      end if
      if (.not. ps_alg_valid(self%ps_alg)) then
         ierr = MAT_ERR_PS_ALG
         return
      end if
      ee = self%e; nu = self%pr
      if (present(fibre)) then   ! a beam's section point (dx_plane_stress: fibre constants)
         if (fibre) call ps_fibre_constants(self%e, self%shear, ee, nu)
      end if
      ! the tabulated curve itself (two points or more), else the linear radius
      tab = .not. self%bilinear
      if (tab) tab = size(self%hard%x) >= 2
      do i = 1, nv
         r(i) = 1.0_wp
         if ((self%c > 0.0_wp .or. self%has_rate_curve) .and. dt > 0.0_wp) then
            rate = ps_rate(dt, deps(i, :))
            if (self%has_rate_curve) then
               r(i) = self%rate_curve%eval(rate)
            else
               r(i) = 1.0_wp + (rate/self%c)**(1.0_wp/self%p)
            end if
         end if
         call self%yield_static(hv(i, 1), h, dh)
         y0(i) = r(i)*h
         hi(i) = r(i)*max(dh, 0.0_wp)
         epsp(i) = hv(i, 1)
      end do
      alpha = 0.0_wp
      if (tab) then
         call ps_update(self%ps_alg, nv, ee, nu, self%shear, deps, sig, alpha, epsp, y0, &
                        hi, 0.0_wp, dep, ierr, crv=self%hard, r=r, dezz=dezz)
      else
         call ps_update(self%ps_alg, nv, ee, nu, self%shear, deps, sig, alpha, epsp, y0, &
                        hi, 0.0_wp, dep, ierr, dezz=dezz)
      end if
      do i = 1, nv
         if (dep(i) > 0.0_wp) then
            hv(i, 1) = epsp(i)
            call self%yield_static(epsp(i), h, dh)
            hv(i, 2) = h
         end if
      end do
   end subroutine pl_update_plane_stress

   subroutine pl_fails(self, nv, hv, failed)
      class(mat_piecewise_linear_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      failed = hv(1:nv, 1) >= self%fail
   end subroutine pl_fails
end module dx_mat_piecewise_linear
