!> Small sorting helpers shared by the surface builders (contact, conserving contact), the
!> contact strips and the MPI layer's ordered gathers.
module dx_sort
   use dx_kinds, only: wp
   implicit none
   private
   public :: sort4, sort_index

   !> Heap sort of an index list idx by (key(idx), idx): a total order, so every rank that
   !> sorts the same data gets the same permutation. Integer or real keys.
   interface sort_index
      module procedure sort_index_int, sort_index_real
   end interface sort_index

   abstract interface
      logical function before_t(a, b)
         integer, intent(in) :: a, b
      end function before_t
   end interface
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

   subroutine sort_index_int(idx, key)
      integer, intent(inout) :: idx(:)
      integer, intent(in) :: key(:)
      call heap_sort(idx, before)
   contains
      logical function before(a, b)
         integer, intent(in) :: a, b
         before = key(a) < key(b) .or. (key(a) == key(b) .and. a < b)
      end function before
   end subroutine sort_index_int

   subroutine sort_index_real(idx, key)
      integer, intent(inout) :: idx(:)
      real(wp), intent(in) :: key(:)
      call heap_sort(idx, before)
   contains
      logical function before(a, b)
         integer, intent(in) :: a, b
         before = key(a) < key(b) .or. (key(a) == key(b) .and. a < b)
      end function before
   end subroutine sort_index_real

   !> Heap sort of idx under the strict order before(a, b).
   subroutine heap_sort(idx, before)
      integer, intent(inout) :: idx(:)
      procedure(before_t) :: before
      integer :: n, i, t
      n = size(idx)
      do i = n/2, 1, -1
         call sift(i, n)
      end do
      do i = n, 2, -1
         t = idx(1); idx(1) = idx(i); idx(i) = t
         call sift(1, i - 1)
      end do
   contains
      subroutine sift(start, m)
         integer, intent(in) :: start, m
         integer :: r, c, tt
         r = start
         do while (2*r <= m)
            c = 2*r
            if (c < m) then
               if (before(idx(c), idx(c + 1))) c = c + 1
            end if
            if (.not. before(idx(r), idx(c))) return
            tt = idx(r); idx(r) = idx(c); idx(c) = tt
            r = c
         end do
      end subroutine sift
   end subroutine heap_sort
end module dx_sort
