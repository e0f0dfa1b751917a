!> *EOS_LINEAR_POLYNOMIAL (*EOS_001): pressure linear in the internal energy,
!>    p = C0 + C1 mu + C2 mu**2 + C3 mu**3 + (C4 + C5 mu + C6 mu**2) E,   mu = 1/V - 1,
!> V the relative volume and E the internal energy per unit reference volume; in expanded
!> elements (mu < 0) the C2 mu**2 and C6 mu**2 terms are set to zero.
!> Cards: EOSID C0 C1 C2 C3 C4 C5 C6; E0 V0 (initial energy per reference volume, initial
!> relative volume). LS-DYNA Keyword User's Manual Vol. II (R7.1, 2014), *EOS_LINEAR_POLYNOMIAL;
!> the same law is DYNA3D's EOS type 1 (Hallquist, Theoretical Manual for DYNA3D, UCID-19401).
!> Only V0 = 1 (the default) is supported: the mesh is the reference state.
!> C1 alone (C4 = C5 = 0) is a linear fluid of bulk modulus K = C1 and sound speed
!> sqrt(C1/rho0); C4 = C5 = gamma - 1 with C0..C3 = C6 = 0 is the ideal gas.
module dx_eos_linear_polynomial
   use dx_kinds, only: wp
   use dx_strings, only: str, rstr
   use dx_card, only: card_t
   use dx_eos, only: eos_t
   implicit none
   private
   public :: eos_linear_polynomial_t

   type, extends(eos_t) :: eos_linear_polynomial_t
      real(wp) :: c(0:6) = 0.0_wp
   contains
      procedure :: read_cards => lp_read_cards
      procedure :: state => lp_state
   end type eos_linear_polynomial_t

contains

   subroutine lp_read_cards(self, c)
      class(eos_linear_polynomial_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      integer :: k
      self%eostype = 1
      call c%int('EOSID', 0, self%label)
      if (c%ok() .and. self%label <= 0) &
         call c%fail('EOSID', 'equation of state id must be > 0, got '//str(self%label))
      do k = 0, 6
         call c%real('C'//str(k), 0.0_wp, self%c(k))
      end do
      call c%next()
      call c%real('E0', 0.0_wp, self%e0)
      call c%real('V0', 0.0_wp, self%v0)
      if (self%v0 == 0.0_wp) self%v0 = 1.0_wp
      if (c%ok() .and. self%v0 /= 1.0_wp) call c%fail('V0', 'only V0 = 1 (the mesh is the '// &
         'reference state) is supported, got '//rstr(self%v0))
      self%title = c%title()
   end subroutine lp_read_cards

   !> p, dp/dmu and dp/dE; the mu**2 terms vanish in tension.
   pure subroutine lp_state(self, relvol, eint, p, dpdmu, dpde)
      class(eos_linear_polynomial_t), intent(in) :: self
      real(wp), intent(in) :: relvol, eint
      real(wp), intent(out) :: p, dpdmu, dpde
      real(wp) :: mu, c2, c6
      mu = 1.0_wp/relvol - 1.0_wp
      c2 = self%c(2)
      c6 = self%c(6)
      if (mu < 0.0_wp) then
         c2 = 0.0_wp
         c6 = 0.0_wp
      end if
      dpde = self%c(4) + self%c(5)*mu + c6*mu**2
      p = self%c(0) + mu*(self%c(1) + mu*(c2 + mu*self%c(3))) + dpde*eint
      dpdmu = self%c(1) + mu*(2.0_wp*c2 + 3.0_wp*mu*self%c(3)) + &
              (self%c(5) + 2.0_wp*c6*mu)*eint
   end subroutine lp_state
end module dx_eos_linear_polynomial
