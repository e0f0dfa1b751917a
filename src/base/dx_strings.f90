!> Small string helpers.
module dx_strings
   use dx_kinds, only: wp
   implicit none
   private
   public :: upper, lower, str, rstr, string_t, command_arg

   interface str
      module procedure str_int, str_int8
   end interface str
   !> A string in an array of strings (file names and the like).
   type :: string_t
      character(:), allocatable :: s
   end type string_t

contains
   !> Upper-case copy of s (ASCII).
   pure function upper(s) result(u)
      character(*), intent(in) :: s
      character(len(s)) :: u
      u = shift_case(s, 'a', 'z', -32)
   end function upper

   !> Lower-case copy of s (ASCII).
   pure function lower(s) result(u)
      character(*), intent(in) :: s
      character(len(s)) :: u
      u = shift_case(s, 'A', 'Z', 32)
   end function lower

   !> s with the letters first..last moved by d in ASCII (the case change of upper/lower).
   pure function shift_case(s, first, last, d) result(u)
      character(*), intent(in) :: s
      character, intent(in) :: first, last
      integer, intent(in) :: d
      character(len(s)) :: u
      integer :: i, k
      u = s
      do i = 1, len(s)
         k = iachar(s(i:i))
         if (k >= iachar(first) .and. k <= iachar(last)) u(i:i) = achar(k + d)
      end do
   end function shift_case

   !> Integer as a trimmed string.
   pure function str_int(i) result(s)
      integer, intent(in) :: i
      character(:), allocatable :: s
      character(24) :: buf
      write(buf, '(i0)') i
      s = trim(buf)
   end function str_int

   pure function str_int8(i) result(s)
      use dx_kinds, only: i8
      integer(i8), intent(in) :: i
      character(:), allocatable :: s
      character(24) :: buf
      write(buf, '(i0)') i
      s = trim(buf)
   end function str_int8

   !> Real as a short trimmed string (es format with given significant digits, default 6).
   function rstr(x, digits) result(s)
      real(wp), intent(in) :: x
      integer, intent(in), optional :: digits
      character(:), allocatable :: s
      character(40) :: buf
      character(20) :: fmt
      integer :: d
      d = 6
      if (present(digits)) d = digits
      write(fmt, '(a,i0,a,i0,a)') '(es', d + 8, '.', d - 1, ')'
      write(buf, fmt) x
      s = trim(adjustl(buf))
   end function rstr
   !> The k-th command-line argument, whole ('' when there is none: k past the count).
   function command_arg(k) result(a)
      integer, intent(in) :: k
      character(:), allocatable :: a
      integer :: l
      if (k < 1 .or. k > command_argument_count()) then
         a = ''
         return
      end if
      call get_command_argument(k, length=l)
      allocate(character(l) :: a)
      call get_command_argument(k, a)
   end function command_arg
end module dx_strings
