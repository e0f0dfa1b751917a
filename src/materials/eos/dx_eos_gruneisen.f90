!> *EOS_GRUNEISEN (*EOS_004): the Mie-Gruneisen equation of state with a cubic shock velocity
!> - particle velocity fit, Us = C + S1 up + S2 up**2/Us + S3 up**3/Us**2, in LS-DYNA's form
!> (LS-DYNA Keyword User's Manual Vol. II, *EOS_GRUNEISEN; DYNA3D's EOS type 4, Hallquist,
!> Theoretical Manual for DYNA3D, UCID-19401). With mu = 1/V - 1 and E the internal energy per
!> unit reference volume, in compression (mu > 0)
!>    p = rho0 C**2 mu (1 + (1 - gamma0/2) mu - a/2 mu**2) / D**2 + (gamma0 + a mu) E,
!>    D = 1 - (S1 - 1) mu - S2 mu**2/(mu + 1) - S3 mu**3/(mu + 1)**2,
!> and in expansion (mu <= 0)  p = rho0 C**2 mu + (gamma0 + a mu) E.
!> rho0 is the material's RO (dx_eos: set when the part attaches the EOS). The reference
!> curve is the Hugoniot: with S2 = S3 = 0 and E on it (E = p eta/2, eta = 1 - V), p equals
!> rho0 Us up of the linear Us = C + S1 up for any gamma0 (a = 0), which the unit tests check;
!> the material's own Hugoniot data are in Steinberg, Equation of State and Strength
!> Properties of Selected Materials, UCRL-MA-106439 (LLNL 1996) and in Marsh, LASL Shock
!> Hugoniot Data (1980). p is linear in E, so dx_eos's time-centred energy update is exact.
!> Cards: EOSID C S1 S2 S3 GAMAO A E0; V0 (only 1: the mesh is the reference state), a blank
!> field and LCID (an energy deposition curve, not supported: must be 0).
!> Input checks (exit 2 naming the field): C > 0; S1 >= 1 (S1 < 1 is a Hugoniot with Us < up
!> at large up, a compression past zero volume); GAMAO >= 0; and the fit's denominator D > 0
!> on the checked range 0 < mu <= mu_chk, mu_chk = min(1, 1/(S1 - 1)) (twice the reference
!> density, or the linear fit's own singular compression eta = 1/S1 when that comes first,
!> whose end point itself is excluded): S2 and S3 must not put a pole of p inside it. The
!> range is dynx's choice (LS-DYNA checks nothing); Hugoniot data of metals end well inside it.
!> At run time in_range is false past the first pole (D <= 0): the material models that use it
!> (*MAT_NULL, 010, 011, 015) flag the point, and the run stops with exit 3 naming the element.
module dx_eos_gruneisen
   use dx_kinds, only: wp
   use dx_strings, only: str, rstr
   use dx_card, only: card_t
   use dx_eos, only: eos_t
   implicit none
   private
   public :: eos_gruneisen_t

   type, extends(eos_t) :: eos_gruneisen_t
      real(wp) :: c = 0.0_wp, s1 = 0.0_wp, s2 = 0.0_wp, s3 = 0.0_wp
      real(wp) :: gamma0 = 0.0_wp, a = 0.0_wp
   contains
      procedure :: read_cards => gr_read_cards
      procedure :: state => gr_state
      procedure :: in_range => gr_in_range
   end type eos_gruneisen_t

contains

   subroutine gr_read_cards(self, c)
      class(eos_gruneisen_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      integer :: lcid
      self%eostype = 4
      call c%int('EOSID', 0, self%label)
      if (c%ok() .and. self%label <= 0) &
         call c%fail('EOSID', 'equation of state id must be > 0, got '//str(self%label))
      call c%real('C', 0.0_wp, self%c)
      if (c%ok() .and. .not. (self%c > 0.0_wp)) &
         call c%fail('C', 'the bulk sound speed must be > 0, got '//rstr(self%c))
      call c%real('S1', 0.0_wp, self%s1)
      if (c%ok() .and. .not. (self%s1 >= 1.0_wp)) call c%fail('S1', 'the Us-up slope must be '// &
         '>= 1 (S1 < 1 gives Us < up at large up, a compression past zero volume), got '// &
         rstr(self%s1))
      call c%real('S2', 0.0_wp, self%s2)
      call c%real('S3', 0.0_wp, self%s3)
      if (c%ok()) call check_pole(self, c)
      call c%real('GAMAO', 0.0_wp, self%gamma0)
      if (c%ok() .and. .not. (self%gamma0 >= 0.0_wp)) call c%fail('GAMAO', 'the Gruneisen '// &
         'gamma must be >= 0, got '//rstr(self%gamma0))
      call c%real('A', 0.0_wp, self%a)
      call c%real('E0', 0.0_wp, self%e0)
      call c%next()
      call c%real('V0', 0.0_wp, self%v0)
      if (self%v0 == 0.0_wp) self%v0 = 1.0_wp
      if (c%ok() .and. self%v0 /= 1.0_wp) call c%fail('V0', 'only V0 = 1 (the mesh is the '// &
         'reference state) is supported, got '//rstr(self%v0))
      call c%skip(1)
      call c%int('LCID', 0, lcid)
      if (c%ok() .and. lcid /= 0) call c%fail('LCID', 'an energy deposition curve is not '// &
         'supported (LCID must be 0), got '//str(lcid))
      self%title = c%title()
   end subroutine gr_read_cards

   !> The denominator D(mu) of the compressed branch (module header).
   pure real(wp) function gr_denominator(self, mu) result(d)
      class(eos_gruneisen_t), intent(in) :: self
      real(wp), intent(in) :: mu
      real(wp) :: q
      q = 1.0_wp/(mu + 1.0_wp)
      d = 1.0_wp - (self%s1 - 1.0_wp)*mu - self%s2*mu**2*q - self%s3*mu**3*q**2
   end function gr_denominator

   !> Compression up to the first pole of the fit (D > 0); beyond it p is meaningless.
   pure logical function gr_in_range(self, relvol) result(ok)
      class(eos_gruneisen_t), intent(in) :: self
      real(wp), intent(in) :: relvol
      real(wp) :: mu
      ok = relvol > 0.0_wp
      if (.not. ok) return
      mu = 1.0_wp/relvol - 1.0_wp
      if (mu > 0.0_wp) ok = gr_denominator(self, mu) > 0.0_wp
   end function gr_in_range

   !> D > 0 on 0 < mu <= mu_chk (module header), sampled at 2000 points (the end point
   !> excluded when it is the linear fit's pole 1/(S1 - 1)); the first sign change is named.
   subroutine check_pole(self, c)
      class(eos_gruneisen_t), intent(in) :: self
      type(card_t), intent(inout) :: c
      integer, parameter :: NS = 2000
      real(wp) :: mchk, mu
      character(2) :: fld
      integer :: k
      if (self%s2 == 0.0_wp .and. self%s3 == 0.0_wp) return   ! the linear fit: D = 1 - (S1-1) mu
      mchk = 1.0_wp
      if (self%s1 > 1.0_wp) mchk = min(1.0_wp, 1.0_wp/(self%s1 - 1.0_wp))
      fld = 'S3'
      if (self%s2 /= 0.0_wp) fld = 'S2'
      do k = 1, NS
         mu = mchk*real(k, wp)/real(NS, wp)
         if (k == NS .and. mchk < 1.0_wp) mu = mchk*(1.0_wp - 1.0e-6_wp)
         if (gr_denominator(self, mu) > 0.0_wp) cycle
         call c%fail(fld, 'the Us-up fit (S1, S2, S3) has a pole of the pressure at mu = '// &
            rstr(mu)//' (V = '//rstr(1.0_wp/(1.0_wp + mu))//'), inside the checked '// &
            'compression range 0 < mu <= '//rstr(mchk)//': D = 1 - (S1-1) mu - S2 mu**2/(mu+1)'// &
            ' - S3 mu**3/(mu+1)**2 must stay > 0 there')
         return
      end do
   end subroutine check_pole

   !> p, dp/dmu and dp/dE (module header). In compression p = N/D**2 + (gamma0 + a mu) E with
   !> N = rho0 C**2 mu (1 + (1 - gamma0/2) mu - a/2 mu**2), so
   !> dp/dmu = N'/D**2 - 2 N D'/D**3 + a E.
   pure subroutine gr_state(self, relvol, eint, p, dpdmu, dpde)
      class(eos_gruneisen_t), intent(in) :: self
      real(wp), intent(in) :: relvol, eint
      real(wp), intent(out) :: p, dpdmu, dpde
      real(wp) :: mu, rc2, q, n, dn, d, dd
      mu = 1.0_wp/relvol - 1.0_wp
      rc2 = self%rho0*self%c**2
      dpde = self%gamma0 + self%a*mu
      if (mu > 0.0_wp) then
         q = 1.0_wp/(mu + 1.0_wp)
         n = rc2*mu*(1.0_wp + mu*((1.0_wp - 0.5_wp*self%gamma0) - 0.5_wp*self%a*mu))
         dn = rc2*(1.0_wp + mu*((2.0_wp - self%gamma0) - 1.5_wp*self%a*mu))
         d = 1.0_wp - (self%s1 - 1.0_wp)*mu - self%s2*mu**2*q - self%s3*mu**3*q**2
         dd = -(self%s1 - 1.0_wp) - self%s2*mu*(mu + 2.0_wp)*q**2 - &
              self%s3*mu**2*(mu + 3.0_wp)*q**3
         p = n/d**2 + dpde*eint
         dpdmu = dn/d**2 - 2.0_wp*n*dd/d**3 + self%a*eint
      else
         p = rc2*mu + dpde*eint
         dpdmu = rc2 + self%a*eint
      end if
   end subroutine gr_state
end module dx_eos_gruneisen
