!> Error reporting in the fpm pattern: library code returns type(error_t), allocatable;
!> only the main program turns an error into an exit code.
!> Exit codes: 2 input error, 3 numerical failure in the run, 4 I/O failure,
!> 5 stopped at a checkpoint (signal or wall-clock limit; continue with -r).
module dx_error
   use, intrinsic :: iso_c_binding, only: c_int
   use dx_libc, only: c_exit
   implicit none
   private
   public :: error_t, set_error, set_field_error, EXIT_INPUT, EXIT_NUMERIC, EXIT_IO, EXIT_OK, &
             exit_process, EXIT_CHECKPOINT

   integer, parameter :: EXIT_OK = 0, EXIT_INPUT = 2, EXIT_NUMERIC = 3, EXIT_IO = 4
   integer, parameter :: EXIT_CHECKPOINT = 5   !< clean stop with a restart dump
   !> further errors of one block kept as text (--check); the rest are counted (a damaged
   !> block of thousands of cards: the text grew with the square of their number)
   integer, parameter, public :: MAX_MORE = 200

   type :: error_t
      character(:), allocatable :: message   !< full message, may span lines
      integer :: code = EXIT_INPUT           !< exit code the main program uses
      character(:), allocatable :: field     !< the input field at fault (set_field_error)
      character(:), allocatable :: detail    !< the message without the 'field NAME: ' prefix
      character(:), allocatable :: more      !< further errors of the same keyword block, one
                                             !< line each (dynx --check lists them: dx_card)
      integer :: nmore = 0                   !< lines in more (at most MAX_MORE)
      integer :: ndrop = 0                   !< further errors past MAX_MORE, only counted
   end type error_t

contains

   !> End the process with this exit code (only the main programs call it).
   subroutine exit_process(code)
      integer, intent(in) :: code
      flush(6)
      flush(0)
      call c_exit(int(code, c_int))
   end subroutine exit_process

   !> Allocate error and set its message and exit code (default: input error).
   subroutine set_error(error, message, code)
      type(error_t), allocatable, intent(inout) :: error
      character(*), intent(in) :: message
      integer, intent(in), optional :: code
      if (allocated(error)) deallocate(error)
      allocate(error)
      error%message = message
      error%code = EXIT_INPUT
      if (present(code)) error%code = code
   end subroutine set_error

   !> An error about one input field: message 'field NAME: what', with the name and the bare
   !> text kept apart so a reader can point at the field's columns (dx_card) unparsed.
   subroutine set_field_error(error, field, what, code)
      type(error_t), allocatable, intent(inout) :: error
      character(*), intent(in) :: field, what
      integer, intent(in), optional :: code
      call set_error(error, 'field '//field//': '//what, code)
      error%field = field
      error%detail = what
   end subroutine set_field_error
end module dx_error
