!> File-system helpers for the output writers, through bind(C) interfaces to libc (POSIX):
!> rename(2) for the atomic replace of the XDMF file, mkdir(2)/access(2) for `mkdir -p`,
!> fnmatch(3) for the file globs of the comparator's tolerance file, exit(3) so command-line
!> tools end with a status code and no runtime trace (ERROR STOP prints a backtrace);
!> open(2)/fsync(2)/close(2) so a restart dump is on disk before it is renamed into place,
!> truncate(2) to cut a time-history file back to a restart point, time(2) for batch limits.
module dx_io_sys
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_long, c_ptr, c_null_ptr
   use dx_error, only: error_t, set_error, EXIT_IO
   implicit none
   private
   public :: sys_rename, sys_mkdir_p, sys_fnmatch, sys_exit, sys_fsync, sys_truncate, &
             sys_epoch_seconds

   integer(c_int), parameter :: W_OK = 2_c_int
   integer(c_int), parameter :: MODE_755 = int(o'755', c_int)

   interface
      function c_rename(old, new) bind(C, name='rename') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: r
      end function c_rename
      function c_mkdir(path, mode) bind(C, name='mkdir') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: r
      end function c_mkdir
      function c_access(path, mode) bind(C, name='access') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: r
      end function c_access
      function c_fnmatch(pattern, string, flags) bind(C, name='fnmatch') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: pattern(*), string(*)
         integer(c_int), value :: flags
         integer(c_int) :: r
      end function c_fnmatch
      subroutine c_exit(status) bind(C, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
      function c_open(path, flags) bind(C, name='open') result(fd)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: flags
         integer(c_int) :: fd
      end function c_open
      function c_fsync(fd) bind(C, name='fsync') result(r)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: r
      end function c_fsync
      function c_close(fd) bind(C, name='close') result(r)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: r
      end function c_close
      function c_truncate(path, length) bind(C, name='truncate') result(r)
         import :: c_int, c_char, c_long
         character(kind=c_char), intent(in) :: path(*)
         integer(c_long), value :: length
         integer(c_int) :: r
      end function c_truncate
      function c_time(tloc) bind(C, name='time') result(t)
         import :: c_long, c_ptr
         type(c_ptr), value :: tloc
         integer(c_long) :: t
      end function c_time
   end interface

contains

   !> Atomically replace new by old (POSIX rename).
   subroutine sys_rename(old, new, error)
      character(*), intent(in) :: old, new
      type(error_t), allocatable, intent(out) :: error
      if (c_rename(old//c_null_char, new//c_null_char) /= 0) then
         call set_error(error, 'cannot rename '//old//' to '//new, EXIT_IO)
      end if
   end subroutine sys_rename

   !> Create directory dir and its missing parents; error unless it ends up writable.
   subroutine sys_mkdir_p(dir, error)
      character(*), intent(in) :: dir
      type(error_t), allocatable, intent(out) :: error
      integer :: i, n
      integer(c_int) :: r
      n = len_trim(dir)
      if (n == 0) then
         call set_error(error, 'empty output directory name', EXIT_IO)
         return
      end if
      do i = 2, n
         if (dir(i:i) == '/') r = c_mkdir(dir(1:i - 1)//c_null_char, MODE_755)
      end do
      r = c_mkdir(dir(1:n)//c_null_char, MODE_755)   ! fails harmlessly when it exists
      if (c_access(dir(1:n)//c_null_char, W_OK) /= 0) then
         call set_error(error, 'cannot create or write to output directory '//dir(1:n), EXIT_IO)
      end if
   end subroutine sys_mkdir_p

   !> Shell-style glob match (*, ?, [...]) of name against pattern.
   logical function sys_fnmatch(pattern, name)
      character(*), intent(in) :: pattern, name
      sys_fnmatch = c_fnmatch(pattern//c_null_char, name//c_null_char, 0_c_int) == 0
   end function sys_fnmatch

   !> End the program with this exit status (only for main programs; flushes stdout/stderr).
   subroutine sys_exit(status)
      use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
      integer, intent(in) :: status
      flush(output_unit)
      flush(error_unit)
      call c_exit(int(status, c_int))
   end subroutine sys_exit

   !> Flush the file (or directory) at path to stable storage (open O_RDONLY + fsync).
   subroutine sys_fsync(path, error)
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: fd, r
      fd = c_open(path//c_null_char, 0_c_int)
      if (fd < 0) then
         call set_error(error, 'cannot open '//path//' to sync it to disk', EXIT_IO)
         return
      end if
      r = c_fsync(fd)
      if (c_close(fd) /= 0 .or. r /= 0) call set_error(error, 'cannot sync '//path// &
                                                       ' to disk (fsync failed)', EXIT_IO)
   end subroutine sys_fsync

   !> Cut the file at path to nbytes bytes.
   subroutine sys_truncate(path, nbytes, error)
      character(*), intent(in) :: path
      integer(8), intent(in) :: nbytes
      type(error_t), allocatable, intent(out) :: error
      if (c_truncate(path//c_null_char, int(nbytes, c_long)) /= 0) &
         call set_error(error, 'cannot truncate '//path, EXIT_IO)
   end subroutine sys_truncate

   !> Seconds since the Unix epoch (time(2)).
   integer(8) function sys_epoch_seconds()
      sys_epoch_seconds = int(c_time(c_null_ptr), 8)
   end function sys_epoch_seconds
end module dx_io_sys
