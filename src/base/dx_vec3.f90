!> Small 3-vector helpers.
module dx_vec3
   use dx_kinds, only: wp
   implicit none
   private
   public :: cross
contains
   !> Cross product a x b.
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross
end module dx_vec3
