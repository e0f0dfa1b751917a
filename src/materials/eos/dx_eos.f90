!> The abstract equation of state: pressure p(V, E) of the relative volume V = v/v0 and the
!> internal energy E per unit reference volume (LS-DYNA's convention for the *EOS_ keywords,
!> LS-DYNA Keyword User's Manual Vol. II, "*EOS"), attached to a hydro material by the part's
!> EOSID (*PART field 4). A new equation of state is one module extending eos_t plus one row in
!> dx_mat_factory.
!>
!> Sound speed. Along an isentrope dE = -p dV, and with mu = 1/V - 1 (rho = rho0 (1 + mu)),
!> dE/dmu = p V**2, so c**2 = dp/drho = (dp/dmu + dp/dE p V**2)/rho0.
!>
!> Internal energy update (Hallquist, Theoretical Manual for DYNA3D, UCID-19401, LLNL 1983,
!> "Equations of state": the energy equation is integrated with the time-centred pressure):
!>    E(n+1) = E* - (p(n) + p(n+1))/2 (V(n+1) - V(n)),
!> E* being the energy at t(n) plus the deviatoric and bulk-viscosity work (dynx's element
!> keeps that sum as eint, with the viscosity work of the step before, as DYNA3D lags q by a
!> half step). p(n+1) = p(V(n+1), E(n+1)) makes this implicit in E(n+1); for an equation of
!> state linear in E, p = A(V) + B(V) E, it is solved exactly:
!>    E(n+1) = (E* - (p(n) + A) dV/2)/(1 + B dV/2),   dV = V(n+1) - V(n),
!> which energy_update does for any eos_t by linearising p in E at E* (exact for the linear
!> polynomial; one Newton step otherwise).
module dx_eos
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_card, only: card_t
   implicit none
   private
   public :: eos_t, eos_holder_t

   type, abstract :: eos_t
      integer :: label = 0                  !< EOSID
      integer :: eostype = 0                !< LS-DYNA EOS type number (1, 4, ...)
      character(:), allocatable :: title
      real(wp) :: e0 = 0.0_wp               !< initial internal energy per reference volume
      real(wp) :: v0 = 1.0_wp               !< initial relative volume
      real(wp) :: rho0 = 0.0_wp             !< reference density: the material's RO, set when
                                            !< the part attaches the equation of state
   contains
      procedure(read_i), deferred :: read_cards     !< its *EOS_ card(s), through the cursor
      procedure(state_i), deferred :: state         !< p, dp/dmu, dp/dE at (V, E)
      procedure :: pressure => eos_pressure         !< p(V, E)
      procedure :: sound_speed2 => eos_sound_speed2 !< c**2 at (V, E) for density rho0
      procedure :: energy_update => eos_energy_update !< time-centred E and p at V(n+1)
      procedure :: in_range => eos_in_range         !< V inside the range where p is defined
   end type eos_t

   !> A holder so the model input can keep a list of polymorphic equations of state.
   type :: eos_holder_t
      class(eos_t), allocatable :: e
   end type eos_holder_t

   abstract interface
      !> Read the cards (EOSID first) and check the parameters; errors go to the cursor.
      subroutine read_i(self, c)
         import :: eos_t, card_t
         class(eos_t), intent(inout) :: self
         type(card_t), intent(inout) :: c
      end subroutine read_i

      !> Pressure p and its partial derivatives dp/dmu (at fixed E) and dp/dE (at fixed V).
      pure subroutine state_i(self, relvol, eint, p, dpdmu, dpde)
         import :: eos_t, wp
         class(eos_t), intent(in) :: self
         real(wp), intent(in) :: relvol, eint
         real(wp), intent(out) :: p, dpdmu, dpde
      end subroutine state_i
   end interface

contains

   !> Pressure at relative volume relvol and internal energy eint per reference volume.
   pure real(wp) function eos_pressure(self, relvol, eint) result(p)
      class(eos_t), intent(in) :: self
      real(wp), intent(in) :: relvol, eint
      real(wp) :: dpdmu, dpde
      call self%state(relvol, eint, p, dpdmu, dpde)
   end function eos_pressure

   !> Whether the pressure is defined at relative volume relvol (default: any V > 0). A model
   !> flags a point outside as a failed update (ierr), so the run stops with a message
   !> instead of going on with a meaningless pressure.
   pure logical function eos_in_range(self, relvol) result(ok)
      class(eos_t), intent(in) :: self
      real(wp), intent(in) :: relvol
      ok = relvol > 0.0_wp
      if (.false.) ok = self%rho0 < 0.0_wp
   end function eos_in_range

   !> Isentropic sound speed squared (dp/dmu + dp/dE p V**2)/rho0, at least 0.
   pure real(wp) function eos_sound_speed2(self, rho0, relvol, eint) result(c2)
      class(eos_t), intent(in) :: self
      real(wp), intent(in) :: rho0, relvol, eint
      real(wp) :: p, dpdmu, dpde
      call self%state(relvol, eint, p, dpdmu, dpde)
      c2 = max(0.0_wp, (dpdmu + dpde*p*relvol**2)/rho0)
   end function eos_sound_speed2

   !> Time-centred energy update (module header): from E* (energy before the pressure work of
   !> the step), the pressure p_old at t(n) and the volume change dv = V(n+1) - V(n), the
   !> energy e_new and pressure p_new at V(n+1).
   pure subroutine eos_energy_update(self, relvol, dv, e_star, p_old, e_new, p_new)
      class(eos_t), intent(in) :: self
      real(wp), intent(in) :: relvol, dv, e_star, p_old
      real(wp), intent(out) :: e_new, p_new
      real(wp) :: a, b, dpdmu
      call self%state(relvol, e_star, a, dpdmu, b)
      a = a - b*e_star                               ! p = a + b E at V(n+1)
      e_new = (e_star - 0.5_wp*dv*(p_old + a))/(1.0_wp + 0.5_wp*b*dv)
      p_new = a + b*e_new
   end subroutine eos_energy_update
end module dx_eos
