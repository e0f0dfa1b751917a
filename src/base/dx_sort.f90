!> Small sorting helpers shared by the surface builders (contact, conserving contact).
module dx_sort
   implicit none
   private
   public :: sort4
contains
   !> The four node numbers of a face in ascending order (insertion sort): a key under which
   !> the two elements sharing a face see the same face.
   pure function sort4(nd) result(s)
      integer, intent(in) :: nd(4)
      integer :: s(4), i, j, t
      s = nd
      do i = 2, 4
         t = s(i)
         j = i - 1
         do while (j >= 1)
            if (s(j) <= t) exit
            s(j + 1) = s(j)
            j = j - 1
         end do
         s(j + 1) = t
      end do
   end function sort4
end module dx_sort
