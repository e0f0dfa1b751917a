!> Unit tests of dx_append_file (rbdout and rcforc across a restart): the byte count of an
!> open formatted file equals the bytes written (3 lines of 'abc' = 12 bytes, 2 more lines of
!> 'defgh' = 24 bytes; a newline is one byte), append_from cuts the file back to the count
!> and appends after it (content read back exactly), and refuses a file shorter than the
!> count or a missing file with an I/O error (exit 4) naming the file.
program test_append_file
   use dx_error, only: error_t, EXIT_IO
   use dx_io_sys, only: sys_mkdir_p
   use dx_append_file, only: unit_bytes, append_from
   use dx_assert, only: check, assert_summary
   implicit none
   character(*), parameter :: TMP = 'build/test_append_file.tmp'
   character(*), parameter :: PATH = TMP//'/hist'
   type(error_t), allocatable :: error
   integer :: u, i, ios
   integer(8) :: n12, n24, sz
   character(16) :: line
   character(16) :: got(8)

   call sys_mkdir_p(TMP, error)
   call check(.not. allocated(error), 'create scratch dir '//TMP)
   write(*, '(a)') 'byte count of an open formatted file'
   open(newunit=u, file=PATH, status='replace', action='write', form='formatted')
   do i = 1, 3
      write(u, '(a)') 'abc'
   end do
   n12 = unit_bytes(u)
   call check(n12 == 12_8, 'three lines abc: 12 bytes')
   write(u, '(a)') 'defgh'
   write(u, '(a)') 'defgh'
   n24 = unit_bytes(u)
   call check(n24 == 24_8, 'two more lines defgh: 24 bytes')
   close(u)

   write(*, '(a)') 'cut back and append'
   call append_from(PATH, n12, u, error)
   call check(.not. allocated(error), 'append_from at 12 bytes')
   if (.not. allocated(error)) then
      write(u, '(a)') 'xyz'
      close(u)
   end if
   inquire(file=PATH, size=sz)
   call check(sz == 16_8, 'file is 12 + 4 bytes')
   got = ''
   open(newunit=u, file=PATH, status='old', action='read', form='formatted')
   do i = 1, 8
      read(u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      got(i) = line
   end do
   close(u)
   call check(all(got(1:3) == 'abc') .and. got(4) == 'xyz' .and. got(5) == '', &
              'content abc abc abc xyz')

   write(*, '(a)') 'refusals'
   call append_from(PATH, 100_8, u, error)
   call check(allocated(error), 'a file shorter than the dump count is refused')
   if (allocated(error)) call check(error%code == EXIT_IO .and. &
      index(error%message, 'cannot continue '//PATH) > 0 .and. &
      index(error%message, 'expects at least 100') > 0, 'message names the file and count, exit 4')
   inquire(file=PATH, size=sz)
   call check(sz == 16_8, 'the refused file is left as it was')
   call append_from(TMP//'/none', 10_8, u, error)
   call check(allocated(error), 'a missing file is refused')
   if (allocated(error)) call check(error%code == EXIT_IO, 'missing file: exit 4')
   call assert_summary()
end program test_append_file
