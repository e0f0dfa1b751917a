!> A label -> dense index map (open addressing, linear probing) for deck ids: node, element,
!> part, ... labels are arbitrary positive integers; the model indexes everything densely.
module dx_label_map
   use dx_kinds, only: i8
   implicit none
   private
   public :: label_map_t

   type :: label_map_t
      integer :: cap = 0, n = 0
      integer, allocatable :: keys(:), vals(:)   !< vals == 0 marks an empty slot
   contains
      procedure :: init => map_init
      procedure :: insert => map_insert
      procedure :: get => map_get
   end type label_map_t

contains

   !> Empty map sized for about n entries.
   subroutine map_init(self, n)
      class(label_map_t), intent(inout) :: self
      integer, intent(in) :: n
      integer :: c
      c = 16
      do while (c < 2*max(n, 1))
         c = 2*c
      end do
      self%cap = c
      self%n = 0
      if (allocated(self%keys)) deallocate(self%keys, self%vals)
      allocate(self%keys(0:c-1), self%vals(0:c-1))
      self%keys = 0
      self%vals = 0
   end subroutine map_init

   pure integer function slot0(key, cap)
      integer, intent(in) :: key, cap
      integer(i8) :: h
      h = int(key, i8)*2654435761_i8
      h = ieor(h, ishft(h, -16))
      slot0 = int(iand(h, int(cap - 1, i8)))
   end function slot0

   !> Map key to val (val >= 1); if key is already present, leave it and return its
   !> index in old (0 when the key was new).
   subroutine map_insert(self, key, val, old)
      class(label_map_t), intent(inout) :: self
      integer, intent(in) :: key, val
      integer, intent(out) :: old
      integer :: s
      if (2*(self%n + 1) > self%cap) call rehash(self)
      s = slot0(key, self%cap)
      do
         if (self%vals(s) == 0) exit
         if (self%keys(s) == key) then
            old = self%vals(s)
            return
         end if
         s = iand(s + 1, self%cap - 1)
      end do
      self%keys(s) = key
      self%vals(s) = val
      self%n = self%n + 1
      old = 0
   end subroutine map_insert

   !> Dense index of key, 0 when absent.
   pure integer function map_get(self, key) result(v)
      class(label_map_t), intent(in) :: self
      integer, intent(in) :: key
      integer :: s
      v = 0
      if (self%cap == 0) return
      s = slot0(key, self%cap)
      do
         if (self%vals(s) == 0) return
         if (self%keys(s) == key) then
            v = self%vals(s)
            return
         end if
         s = iand(s + 1, self%cap - 1)
      end do
   end function map_get

   subroutine rehash(self)
      class(label_map_t), intent(inout) :: self
      integer, allocatable :: k(:), v(:)
      integer :: i, old
      if (self%cap == 0) then
         call self%init(16)
         return
      end if
      call move_alloc(self%keys, k)
      call move_alloc(self%vals, v)
      call self%init(self%cap)
      do i = 0, size(k) - 1
         if (v(i) /= 0) call self%insert(k(i), v(i), old)
      end do
   end subroutine rehash
end module dx_label_map
