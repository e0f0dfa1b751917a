!> *MAT_NULL (*MAT_009): a hydrodynamic material without shear strength. The pressure comes from
!> the equation of state of the part (EOSID, dx_eos), cut off in tension at PC (p >= PC, PC <= 0);
!> the deviatoric stress is viscous, s = 2 MU e', e' the deviatoric strain rate. Erosion when the
!> relative volume exceeds TEROD (> 0) or falls below CEROD (> 0). YM and PR serve null beams and
!> shells only and are read, not used, for solids.
!> Card: MID RO PC MU TEROD CEROD YM PR. LS-DYNA Keyword User's Manual Vol. II (R7.1, 2014),
!> *MAT_NULL; DYNA3D material 9 (Hallquist, Theoretical Manual for DYNA3D, UCID-19401, 1983).
!> The internal energy of the EOS is updated with the time-centred pressure (dx_eos header):
!> E* = E0 + eint (eint, the element's energy per reference volume at t(n), already holds the
!> deviatoric and bulk-viscosity work up to t(n); the viscous work of this step enters at the next
!> one, a half-step lag as in DYNA3D).
!> A point compressed past the range of the EOS (eos%in_range: past the first pole of a
!> Gruneisen fit) gets ierr = 2, and the run stops with exit 3 naming the element, as for
!> *MAT_010, 011 and 015 (before, *MAT_NULL went on with the pressure of the fit beyond its pole).
!> History: 1 = relative volume at the last update (0: the reference state), 2 = pressure,
!> 3 = sound speed squared, 4 = internal energy per reference volume E(n+1).
module dx_mat_null
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr
   use dx_mat_hydro_common, only: hydro_material_t, history_wave_speed
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   implicit none
   private
   public :: mat_null_t

   type, extends(hydro_material_t) :: mat_null_t
      real(wp) :: pc = 0.0_wp, mu = 0.0_wp, terod = 0.0_wp, cerod = 0.0_wp
      real(wp) :: ym = 0.0_wp, pr = 0.0_wp
   contains
      procedure :: read_cards => null_read_cards
      procedure :: setup => null_setup
      procedure :: nhist => null_nhist
      procedure :: update => null_update
      procedure :: wave_speed => null_wave_speed
      procedure :: fails => null_fails
   end type mat_null_t

contains

   subroutine null_read_cards(self, c)
      class(mat_null_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call read_mid_ro(self, c)
      call c%real('PC', 0.0_wp, self%pc)
      call c%real('MU', 0.0_wp, self%mu)
      call c%real('TEROD', 0.0_wp, self%terod)
      call c%real('CEROD', 0.0_wp, self%cerod)
      call c%real('YM', 0.0_wp, self%ym)
      call c%real('PR', 0.0_wp, self%pr)
   end subroutine null_read_cards

   subroutine null_setup(self, error)
      class(mat_null_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (.not. (self%ro > 0.0_wp)) then
         call set_field_error(error, 'RO', 'density must be > 0, got '//rstr(self%ro)); return
      end if
      if (.not. (self%pc <= 0.0_wp)) then
         call set_field_error(error, 'PC', 'the pressure cutoff must be <= 0 (tension is '// &
                              'negative pressure), got '//rstr(self%pc)); return
      end if
      if (.not. (self%mu >= 0.0_wp)) then
         call set_field_error(error, 'MU', 'viscosity must be >= 0, got '//rstr(self%mu)); return
      end if
      if (.not. (self%terod >= 0.0_wp)) then
         call set_field_error(error, 'TEROD', 'must be >= 0, got '//rstr(self%terod)); return
      end if
      if (.not. (self%cerod >= 0.0_wp)) then
         call set_field_error(error, 'CEROD', 'must be >= 0, got '//rstr(self%cerod)); return
      end if
      self%shear = 0.0_wp
   end subroutine null_setup

   pure integer function null_nhist(self)
      class(mat_null_t), intent(in) :: self
      null_nhist = 4
   end function null_nhist

   !> Pressure from the EOS with the time-centred energy, cut off at PC; viscous deviator.
   subroutine null_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_null_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: vold, e1, p1, tr, f
      integer :: i
      f = 0.0_wp
      if (dt > 0.0_wp) f = 2.0_wp*self%mu/dt
      do i = 1, nv
         vold = hv(i, 1)
         if (vold == 0.0_wp) vold = 1.0_wp
         if (allocated(self%eos)) then
            call self%eos%energy_update(relvol(i), relvol(i) - vold, self%eos%e0 + eint(i), &
                                        hv(i, 2), e1, p1)
            p1 = max(p1, self%pc)
            hv(i, 3) = self%eos%sound_speed2(self%ro, relvol(i), e1)
            if (.not. self%eos%in_range(relvol(i))) ierr(i) = 2   ! compressed past the EOS's range
         else
            e1 = eint(i)
            p1 = 0.0_wp
            hv(i, 3) = 0.0_wp
         end if
         tr = (deps(i, 1) + deps(i, 2) + deps(i, 3))/3.0_wp
         sig(i, 1) = f*(deps(i, 1) - tr) - p1
         sig(i, 2) = f*(deps(i, 2) - tr) - p1
         sig(i, 3) = f*(deps(i, 3) - tr) - p1
         sig(i, 4) = f*deps(i, 4)
         sig(i, 5) = f*deps(i, 5)
         sig(i, 6) = f*deps(i, 6)
         hv(i, 1) = relvol(i)
         hv(i, 2) = p1
         hv(i, 4) = e1
      end do
   end subroutine null_update

   !> Sound speed of the EOS at the last update (before any update: sqrt(K V/rho0), K the
   !> bulk modulus rho0 c0**2 set from the EOS when the part attached it).
   subroutine null_wave_speed(self, nv, relvol, hv, c)
      class(mat_null_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: relvol(nv)
      real(wp), intent(in) :: hv(:, :)
      real(wp), intent(out) :: c(nv)
      call history_wave_speed(nv, relvol, hv, 1, 3, self%bulk, self%ro, c)
   end subroutine null_wave_speed

   !> Erosion by relative volume: above TEROD or below CEROD (each when > 0).
   subroutine null_fails(self, nv, hv, failed)
      class(mat_null_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      integer :: i
      do i = 1, nv
         failed(i) = .false.
         if (hv(i, 1) <= 0.0_wp) cycle
         if (self%terod > 0.0_wp) failed(i) = hv(i, 1) > self%terod
         if (self%cerod > 0.0_wp) failed(i) = failed(i) .or. hv(i, 1) < self%cerod
      end do
   end subroutine null_fails
end module dx_mat_null
