!> *MAT_RIGID (*MAT_020): the elements of a part with this material move as one rigid body
!> (dx_rigid_*); they carry no stress, no hourglass forces and no internal energy. As in
!> LS-DYNA, RO gives the mass and inertia (with the element geometry), and E and PR matter only
!> for contact stiffness and for the element time step when no deformable element sets it.
!> CMO = +1: CON1 constrains global translations, CON2 global rotations (codes 0-7: none, x,
!> y, z, x+y, y+z, z+x, x+y+z). CMO = 0: free. CMO = -1 (local system) is not supported.
!> Hallquist, LS-DYNA Theory Manual, rigid bodies; LS-DYNA Keyword User's Manual Vol. II.
module dx_mat_rigid
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, set_field_error
   use dx_strings, only: rstr, str
   use dx_material, only: material_t
   use dx_mat_elastic, only: check_elastic_constants
   implicit none
   private
   public :: mat_rigid_t, rigid_code

   type, extends(material_t) :: mat_rigid_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp
      real(wp) :: n = 0.0_wp, couple = 0.0_wp, m = 0.0_wp, alias = 0.0_wp
      real(wp) :: cmo = 0.0_wp
      integer :: con1 = 0, con2 = 0
   contains
      procedure :: setup => rigid_setup
      procedure :: nhist => rigid_nhist
      procedure :: update => rigid_update
   end type mat_rigid_t

contains

   !> The axes a CON1/CON2 code 0-7 constrains (LS-DYNA *MAT_RIGID).
   pure function rigid_code(c) result(ax)
      integer, intent(in) :: c
      logical :: ax(3)
      select case (c)
      case (1); ax = [.true., .false., .false.]
      case (2); ax = [.false., .true., .false.]
      case (3); ax = [.false., .false., .true.]
      case (4); ax = [.true., .true., .false.]
      case (5); ax = [.false., .true., .true.]
      case (6); ax = [.true., .false., .true.]
      case (7); ax = [.true., .true., .true.]
      case default; ax = .false.
      end select
   end function rigid_code

   subroutine rigid_setup(self, error)
      class(mat_rigid_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      self%is_rigid = .true.
      call check_elastic_constants(self, self%e, self%pr, error)
      if (allocated(error)) return
      if (self%cmo /= 0.0_wp .and. self%cmo /= 1.0_wp) then
         call set_field_error(error, 'CMO', 'only 0 (no constraints) and +1 (global CON1, '// &
                              'CON2) '// &
                        'are supported, got '//rstr(self%cmo)); return
      end if
      if (self%con1 < 0 .or. self%con1 > 7) then
         call set_field_error(error, 'CON1', 'translation constraint code must lie in 0..7, '// &
                              'got '// &
                        str(self%con1)); return
      end if
      if (self%con2 < 0 .or. self%con2 > 7) then
         call set_field_error(error, 'CON2', 'rotation constraint code must lie in 0..7, got '// &
                        str(self%con2)); return
      end if
   end subroutine rigid_setup

   pure integer function rigid_nhist(self)
      class(mat_rigid_t), intent(in) :: self
      rigid_nhist = 0
   end function rigid_nhist

   !> never called by the solver (rigid blocks are skipped); keeps the stress zero
   subroutine rigid_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_rigid_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      sig = 0.0_wp
   end subroutine rigid_update
end module dx_mat_rigid
