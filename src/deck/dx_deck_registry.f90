!> The keyword registry: a table of (keyword name, options it takes, reader procedure).
!> Each keyword family module registers its keywords (dx_read_*); dx_deck looks every block
!> up here and calls its reader. Pattern after neko's run-time selectable types.
module dx_deck_registry
   use dx_error, only: error_t
   use dx_deck_cards, only: deck_t, block_t
   use dx_model_input, only: model_input_t
   implicit none
   private
   public :: registry_t, reader_i

   abstract interface
      !> Read one keyword block into the model input.
      subroutine reader_i(deck, blk, inp, error)
         import :: deck_t, block_t, model_input_t, error_t
         type(deck_t), intent(in) :: deck
         type(block_t), intent(in) :: blk
         type(model_input_t), intent(inout) :: inp
         type(error_t), allocatable, intent(out) :: error
      end subroutine reader_i
   end interface

   type :: reg_entry_t
      character(len=48) :: name = ''
      logical :: title = .false.     !< accepts the _TITLE option
      logical :: id = .false.        !< accepts the _ID option
      procedure(reader_i), pointer, nopass :: read => null()
   end type reg_entry_t

   type :: registry_t
      integer :: n = 0
      type(reg_entry_t), allocatable :: e(:)
   contains
      procedure :: add => registry_add
      procedure :: lookup => registry_lookup
   end type registry_t

contains

   !> Register keyword name (no '*') read by proc; title/id: options it accepts.
   subroutine registry_add(self, name, proc, title, id)
      class(registry_t), intent(inout) :: self
      character(*), intent(in) :: name
      procedure(reader_i) :: proc
      logical, intent(in), optional :: title, id
      type(reg_entry_t), allocatable :: t(:)
      if (.not. allocated(self%e)) allocate(self%e(64))
      if (self%n == size(self%e)) then
         allocate(t(2*self%n))
         t(1:self%n) = self%e(1:self%n)
         call move_alloc(t, self%e)
      end if
      self%n = self%n + 1
      self%e(self%n)%name = name
      self%e(self%n)%read => proc
      if (present(title)) self%e(self%n)%title = title
      if (present(id)) self%e(self%n)%id = id
   end subroutine registry_add

   !> Find the entry for keyword name, possibly with an _TITLE or _ID option (k = 0: unknown).
   subroutine registry_lookup(self, name, k, base, opt_title, opt_id)
      class(registry_t), intent(in) :: self
      character(*), intent(in) :: name
      integer, intent(out) :: k
      character(:), allocatable, intent(out) :: base
      logical, intent(out) :: opt_title, opt_id
      integer :: i, n
      opt_title = .false.
      opt_id = .false.
      do i = 1, self%n
         n = len_trim(self%e(i)%name)
         k = i
         if (name == self%e(i)%name(1:n)) exit
         if (self%e(i)%title .and. name == self%e(i)%name(1:n)//'_TITLE') then
            opt_title = .true.; exit
         end if
         if (self%e(i)%id .and. name == self%e(i)%name(1:n)//'_ID') then
            opt_id = .true.; exit
         end if
         k = 0
      end do
      if (k > 0) then
         base = self%e(k)%name(1:len_trim(self%e(k)%name))
      else
         base = ''
      end if
   end subroutine registry_lookup
end module dx_deck_registry
