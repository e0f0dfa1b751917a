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
   use dx_mat_steinberg, only: mat_steinberg_t
   use dx_mat_johnson_cook, only: mat_johnson_cook_t
   use dx_mat_hydro, only: mat_hydro_t
   use dx_mat_brittle, only: mat_brittle_t
   use dx_mat_crack, only: mat_crack_t
   use dx_eos, only: eos_t
   use dx_eos_linear_polynomial, only: eos_linear_polynomial_t
   use dx_eos_gruneisen, only: eos_gruneisen_t
   implicit none
   private
   public :: model_kind_t, material_kinds, eos_kinds, new_material, new_eos, known_materials, &
             known_eoss

   !> One registry row: keyword (without '*'), type number, data cards it takes, whether the
   !> generic *MAT_ reader reads it (*MAT_RIGID has a reader of its own, dx_read_rigid), and a
   !> prototype of the model (default-initialised; new_material/new_eos allocate its mold).
   type :: model_kind_t
      character(40) :: keyword = ''
      integer :: mtype = 0
      integer :: ncards = 1
      logical :: generic = .true.
      class(material_t), allocatable :: mat
      class(eos_t), allocatable :: eos
   end type model_kind_t

contains

   !> The material rows: a new material is its module plus one row here. dynx's own models
   !> (keywords *DYNX_...) take type numbers 900 and up and have no *MAT_nnn alias.
   function material_kinds() result(t)
      type(model_kind_t), allocatable :: t(:)
      t = [mat_row('MAT_ELASTIC', 1, 1, .true., mat_elastic_t()), &
           mat_row('MAT_PLASTIC_KINEMATIC', 3, 2, .true., mat_plastic_kinematic_t()), &
           mat_row('MAT_NULL', 9, 1, .true., mat_null_t()), &
           mat_row('MAT_ELASTIC_PLASTIC_HYDRO', 10, 6, .true., mat_hydro_t()), &
           mat_row('MAT_STEINBERG', 11, 4, .true., mat_steinberg_t()), &
           mat_row('MAT_JOHNSON_COOK', 15, 4, .true., mat_johnson_cook_t()), &
           mat_row('MAT_RIGID', 20, 3, .false., mat_rigid_t()), &
           mat_row('MAT_PIECEWISE_LINEAR_PLASTICITY', 24, 4, .true., mat_piecewise_linear_t()), &
           mat_row('DYNX_BRITTLE_DAMAGE', 918, 5, .true., mat_brittle_t()), &
           mat_row('DYNX_BRITTLE_CRACK', 919, 2, .true., mat_crack_t())]
   end function material_kinds

   !> The equation-of-state rows: a new equation of state is its module plus one row here.
   function eos_kinds() result(t)
      type(model_kind_t), allocatable :: t(:)
      t = [eos_row('EOS_LINEAR_POLYNOMIAL', 1, 2, eos_linear_polynomial_t()), &
           eos_row('EOS_GRUNEISEN', 4, 2, eos_gruneisen_t())]
   end function eos_kinds

   function mat_row(keyword, mtype, ncards, generic, proto) result(r)
      character(*), intent(in) :: keyword
      integer, intent(in) :: mtype, ncards
      logical, intent(in) :: generic
      class(material_t), intent(in) :: proto
      type(model_kind_t) :: r
      r%keyword = keyword
      r%mtype = mtype
      r%ncards = ncards
      r%generic = generic
      allocate(r%mat, source=proto)
   end function mat_row

   function eos_row(keyword, eostype, ncards, proto) result(r)
      character(*), intent(in) :: keyword
      integer, intent(in) :: eostype, ncards
      class(eos_t), intent(in) :: proto
      type(model_kind_t) :: r
      r%keyword = keyword
      r%mtype = eostype
      r%ncards = ncards
      allocate(r%eos, source=proto)
   end function eos_row

   !> "1 (*MAT_ELASTIC), 3 (*MAT_PLASTIC_KINEMATIC), ..." for messages (LS-DYNA types only).
   function known_kinds(t) result(s)
      type(model_kind_t), intent(in) :: t(:)
      character(:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(t)
         if (t(i)%mtype >= 900) cycle         ! dynx's own models: not *MAT_ types
         if (len(s) > 0) s = s//', '
         s = s//str(t(i)%mtype)//' (*'//trim(t(i)%keyword)//')'
      end do
   end function known_kinds

   function known_materials() result(s)
      character(:), allocatable :: s
      s = known_kinds(material_kinds())
   end function known_materials

   function known_eoss() result(s)
      character(:), allocatable :: s
      s = known_kinds(eos_kinds())
   end function known_eoss

   !> Allocate the material of LS-DYNA type mtype (its row's prototype, default-initialised).
   subroutine new_material(mtype, mat, error)
      integer, intent(in) :: mtype
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      type(model_kind_t), allocatable :: t(:)
      integer :: i
      t = material_kinds()
      do i = 1, size(t)
         if (t(i)%mtype /= mtype) cycle
         allocate(mat, mold=t(i)%mat)
         mat%mtype = mtype
         return
      end do
      call set_error(error, 'material type '//str(mtype)//' is not supported (known: '// &
                     known_kinds(t)//')')
   end subroutine new_material

   !> Allocate the equation of state of LS-DYNA EOS type eostype.
   subroutine new_eos(eostype, eos, error)
      integer, intent(in) :: eostype
      class(eos_t), allocatable, intent(out) :: eos
      type(error_t), allocatable, intent(out) :: error
      type(model_kind_t), allocatable :: t(:)
      integer :: i
      t = eos_kinds()
      do i = 1, size(t)
         if (t(i)%mtype /= eostype) cycle
         allocate(eos, mold=t(i)%eos)
         eos%eostype = eostype
         return
      end do
      call set_error(error, 'equation of state type '//str(eostype)//' is not supported '// &
                     '(known: '//known_kinds(t)//')')
   end subroutine new_eos
end module dx_mat_factory
