!> The material and equation-of-state registry: one row per model maps its LS-DYNA keyword and
!> type number to a constructor, after the run-time selectable types of ExtremeFLOW/neko
!> (doc/pages/developer-guide/run_time_selectable_types.md). A new model is one module plus one
!> row here; the deck reader registers every row's keyword and its *MAT_nnn / *EOS_nnn alias,
!> and the error for an unknown type lists the known ones.
!> Keywords: LS-DYNA Keyword User's Manual Vol. II (material models, *EOS).
module dx_mat_factory
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_material, only: material_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_null, only: mat_null_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_mat_rigid, only: mat_rigid_t
   use dx_eos, only: eos_t
   use dx_eos_linear_polynomial, only: eos_linear_polynomial_t
   implicit none
   private
   public :: model_kind_t, material_kinds, eos_kinds, new_material, new_eos, known_materials

   !> One registry row: keyword (without '*'), type number, data cards it takes, and whether
   !> the generic *MAT_ reader reads it (*MAT_RIGID has a reader of its own, dx_read_rigid).
   type :: model_kind_t
      character(40) :: keyword = ''
      integer :: mtype = 0
      integer :: ncards = 1
      logical :: generic = .true.
   end type model_kind_t

contains

   !> The material rows.
   pure function material_kinds() result(t)
      type(model_kind_t), allocatable :: t(:)
      t = [model_kind_t('MAT_ELASTIC', 1, 1, .true.), &
           model_kind_t('MAT_PLASTIC_KINEMATIC', 3, 2, .true.), &
           model_kind_t('MAT_NULL', 9, 1, .true.), &
           model_kind_t('MAT_RIGID', 20, 3, .false.), &
           model_kind_t('MAT_PIECEWISE_LINEAR_PLASTICITY', 24, 4, .true.)]
   end function material_kinds

   !> The equation-of-state rows.
   pure function eos_kinds() result(t)
      type(model_kind_t), allocatable :: t(:)
      t = [model_kind_t('EOS_LINEAR_POLYNOMIAL', 1, 2, .true.)]
   end function eos_kinds

   !> "1 (*MAT_ELASTIC), 3 (*MAT_PLASTIC_KINEMATIC), ..." for messages.
   function known_materials() result(s)
      character(:), allocatable :: s
      type(model_kind_t), allocatable :: t(:)
      integer :: i
      t = material_kinds()
      s = ''
      do i = 1, size(t)
         if (i > 1) s = s//', '
         s = s//str(t(i)%mtype)//' (*'//trim(t(i)%keyword)//')'
      end do
   end function known_materials

   !> Allocate the material of LS-DYNA type mtype.
   subroutine new_material(mtype, mat, error)
      integer, intent(in) :: mtype
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      select case (mtype)
      case (1)
         allocate(mat_elastic_t :: mat)
      case (3)
         allocate(mat_plastic_kinematic_t :: mat)
      case (9)
         allocate(mat_null_t :: mat)
      case (20)
         allocate(mat_rigid_t :: mat)
      case (24)
         allocate(mat_piecewise_linear_t :: mat)
      case default
         call set_error(error, 'material type '//str(mtype)//' is not supported (known: '// &
                        known_materials()//')'); return
      end select
      mat%mtype = mtype
   end subroutine new_material

   !> Allocate the equation of state of LS-DYNA EOS type eostype.
   subroutine new_eos(eostype, eos, error)
      integer, intent(in) :: eostype
      class(eos_t), allocatable, intent(out) :: eos
      type(error_t), allocatable, intent(out) :: error
      select case (eostype)
      case (1)
         allocate(eos_linear_polynomial_t :: eos)
      case default
         call set_error(error, 'equation of state type '//str(eostype)//' is not supported '// &
                        '(known: 1 (*EOS_LINEAR_POLYNOMIAL))'); return
      end select
      eos%eostype = eostype
   end subroutine new_eos
end module dx_mat_factory
