!> The material factory: maps an LS-DYNA material type number to a new material object.
!> The only place that knows every model.
module dx_mat_factory
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_material, only: material_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_mat_rigid, only: mat_rigid_t
   implicit none
   private
   public :: new_material

contains
   !> Allocate the material of LS-DYNA type mtype (1, 3, 20, 24).
   subroutine new_material(mtype, mat, error)
      integer, intent(in) :: mtype
      class(material_t), allocatable, intent(out) :: mat
      type(error_t), allocatable, intent(out) :: error
      select case (mtype)
      case (1)
         allocate(mat_elastic_t :: mat)
      case (3)
         allocate(mat_plastic_kinematic_t :: mat)
      case (24)
         allocate(mat_piecewise_linear_t :: mat)
      case (20)
         allocate(mat_rigid_t :: mat)
      case default
         call set_error(error, 'material type '//str(mtype)//' is not supported'); return
      end select
      mat%mtype = mtype
   end subroutine new_material
end module dx_mat_factory
