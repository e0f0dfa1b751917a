!> Small sorting helpers shared by the surface builders (contact, conserving contact), the
!> contact strips, the MPI layer's ordered gathers, and name lists (folder listings, the
!> keyword reference).
module dx_sort
   use dx_kinds, only: wp
   implicit none
   private
   public :: sort4, sort_index, sort_names

   !> Heap sort of an index list idx by (key(idx), idx): a total order, so every rank that
   !> sorts the same data gets the same permutation. Integer or real keys.
   interface sort_index
      module procedure sort_index_int, sort_index_real
   end interface sort_index

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
      call heap_sort(idx, ikey=key)
   end subroutine sort_index_int

   subroutine sort_index_real(idx, key)
      integer, intent(inout) :: idx(:)
      real(wp), intent(in) :: key(:)
      call heap_sort(idx, rkey=key)
   end subroutine sort_index_real

   !> The strict total order (key(a), a) < (key(b), b) on the integer or the real keys.
   !> (A module procedure, not an internal one passed as an argument: no stack trampolines,
   !> so the program needs no executable stack.)
   pure logical function before(a, b, ikey, rkey)
      integer, intent(in) :: a, b
      integer, intent(in), optional :: ikey(:)
      real(wp), intent(in), optional :: rkey(:)
      if (present(ikey)) then
         before = ikey(a) < ikey(b) .or. (ikey(a) == ikey(b) .and. a < b)
      else
         before = rkey(a) < rkey(b) .or. (rkey(a) == rkey(b) .and. a < b)
      end if
   end function before

   !> Heap sort of idx under before(a, b) on ikey or rkey (exactly one present).
   pure subroutine heap_sort(idx, ikey, rkey)
      integer, intent(inout) :: idx(:)
      integer, intent(in), optional :: ikey(:)
      real(wp), intent(in), optional :: rkey(:)
      integer :: n, i, t
      n = size(idx)
      do i = n/2, 1, -1
         call sift(idx, i, n, ikey, rkey)
      end do
      do i = n, 2, -1
         t = idx(1); idx(1) = idx(i); idx(i) = t
         call sift(idx, 1, i - 1, ikey, rkey)
      end do
   end subroutine heap_sort

   pure subroutine sift(idx, start, m, ikey, rkey)
      integer, intent(inout) :: idx(:)
      integer, intent(in) :: start, m
      integer, intent(in), optional :: ikey(:)
      real(wp), intent(in), optional :: rkey(:)
      integer :: r, c, tt
      r = start
      do while (2*r <= m)
         c = 2*r
         if (c < m) then
            if (before(idx(c), idx(c + 1), ikey, rkey)) c = c + 1
         end if
         if (.not. before(idx(r), idx(c), ikey, rkey)) return
         tt = idx(r); idx(r) = idx(c); idx(c) = tt
         r = c
      end do
   end subroutine sift

   !> The order of names (idx, a permutation of 1..n) in the C locale (ASCII), stable:
   !> insertion sort, for lists of tens to hundreds of names.
   function sort_names(names) result(idx)
      character(*), intent(in) :: names(:)
      integer, allocatable :: idx(:)
      integer :: i, j, t
      idx = [(i, i = 1, size(names))]
      do i = 2, size(names)
         t = idx(i)
         j = i - 1
         do while (j >= 1)
            if (.not. lgt(names(idx(j)), names(t))) exit
            idx(j + 1) = idx(j)
            j = j - 1
         end do
         idx(j + 1) = t
      end do
   end function sort_names
end module dx_sort
