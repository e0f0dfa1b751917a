!> The C library's system calls that dynx reaches through bind(C) interfaces, in one place
!> (POSIX, IEEE Std 1003.1-2017; Linux's statx(2) and glibc's __errno_location): files
!> (open/read/write/close/fsync/truncate/ftruncate/unlink/rename/symlink/readlink), folders
!> (mkdir/access/rmdir/chdir/opendir/readdir/closedir), statx(2), flock(2), process
!> (exit/_exit/getpid/gethostname/time/dup, signal/raise), errno/strerror/strlen, fnmatch(3).
!> Only declarations: the callers (dx_io_sys, dx_memory_fault, dx_signals, dx_error, the
!> plot-state files, dynx-fuzz) check the results. open(2) is variadic in C; its mode argument
!> is passed always (ignored by the kernel without O_CREAT).
module dx_libc
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long, c_ptr, c_size_t, c_int16_t, &
      c_int32_t, c_int64_t, c_funptr
   implicit none
   private
   public :: statx_t, c_rename, c_mkdir, c_access, c_fnmatch, c_exit, c_fsync, c_close, &
             c_truncate, c_time, c_open, c_write, c_read, c_ftruncate, c_errno_location, &
             c_strerror, c_strlen, c_statx, c_flock, c_getpid, c_gethostname, c_opendir, &
             c_readdir, c_closedir, c_exit_now, c_signal, c_raise, c_chdir, c_dup, c_unlink, &
             c_rmdir, c_symlink, c_readlink

   !> The head of Linux's struct statx (the same layout on every architecture); 256 bytes.
   type, bind(C) :: statx_t
      integer(c_int32_t) :: mask = 0, blksize = 0
      integer(c_int64_t) :: attributes = 0
      integer(c_int32_t) :: nlink = 0, uid = 0, gid = 0
      integer(c_int16_t) :: mode = 0, spare0 = 0
      integer(c_int64_t) :: rest(28) = 0
   end type statx_t

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
      function c_open(path, flags, mode) bind(C, name='open') result(fd)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: flags, mode
         integer(c_int) :: fd
      end function c_open
      function c_write(fd, buf, n) bind(C, name='write') result(r)
         import :: c_int, c_char, c_size_t, c_long
         integer(c_int), value :: fd
         character(kind=c_char), intent(in) :: buf(*)
         integer(c_size_t), value :: n
         integer(c_long) :: r
      end function c_write
      function c_read(fd, buf, n) bind(C, name='read') result(r)
         import :: c_int, c_char, c_size_t, c_long
         integer(c_int), value :: fd
         character(kind=c_char), intent(inout) :: buf(*)
         integer(c_size_t), value :: n
         integer(c_long) :: r
      end function c_read
      function c_ftruncate(fd, length) bind(C, name='ftruncate') result(r)
         import :: c_int, c_long
         integer(c_int), value :: fd
         integer(c_long), value :: length
         integer(c_int) :: r
      end function c_ftruncate
      function c_errno_location() bind(C, name='__errno_location') result(p)
         import :: c_ptr
         type(c_ptr) :: p
      end function c_errno_location
      function c_strerror(errnum) bind(C, name='strerror') result(p)
         import :: c_int, c_ptr
         integer(c_int), value :: errnum
         type(c_ptr) :: p
      end function c_strerror
      function c_strlen(s) bind(C, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
      function c_statx(dirfd, path, flags, mask, buf) bind(C, name='statx') result(r)
         import :: c_int, c_char, statx_t
         integer(c_int), value :: dirfd, flags, mask
         character(kind=c_char), intent(in) :: path(*)
         type(statx_t), intent(out) :: buf
         integer(c_int) :: r
      end function c_statx
      function c_flock(fd, op) bind(C, name='flock') result(r)
         import :: c_int
         integer(c_int), value :: fd, op
         integer(c_int) :: r
      end function c_flock
      function c_getpid() bind(C, name='getpid') result(p)
         import :: c_int
         integer(c_int) :: p
      end function c_getpid
      function c_gethostname(name, n) bind(C, name='gethostname') result(r)
         import :: c_int, c_char, c_size_t
         character(kind=c_char), intent(inout) :: name(*)
         integer(c_size_t), value :: n
         integer(c_int) :: r
      end function c_gethostname
      function c_opendir(path) bind(C, name='opendir') result(d)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         type(c_ptr) :: d
      end function c_opendir
      function c_readdir(d) bind(C, name='readdir') result(e)
         import :: c_ptr
         type(c_ptr), value :: d
         type(c_ptr) :: e
      end function c_readdir
      function c_closedir(d) bind(C, name='closedir') result(r)
         import :: c_ptr, c_int
         type(c_ptr), value :: d
         integer(c_int) :: r
      end function c_closedir
      subroutine c_exit_now(status) bind(C, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit_now
      function c_signal(sig, handler) bind(C, name='signal') result(old)
         import :: c_int, c_funptr
         integer(c_int), value :: sig
         type(c_funptr), value :: handler
         type(c_funptr) :: old
      end function c_signal
      function c_raise(sig) bind(C, name='raise') result(r)
         import :: c_int
         integer(c_int), value :: sig
         integer(c_int) :: r
      end function c_raise
      function c_chdir(path) bind(C, name='chdir') result(r)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: r
      end function c_chdir
      function c_dup(fd) bind(C, name='dup') result(r)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: r
      end function c_dup
      function c_unlink(path) bind(C, name='unlink') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: r
      end function c_unlink
      function c_rmdir(path) bind(C, name='rmdir') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: r
      end function c_rmdir
      function c_symlink(target, path) bind(C, name='symlink') result(r)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: target(*), path(*)
         integer(c_int) :: r
      end function c_symlink
      function c_readlink(path, buf, n) bind(C, name='readlink') result(r)
         import :: c_char, c_size_t, c_long
         character(kind=c_char), intent(in) :: path(*)
         character(kind=c_char), intent(out) :: buf(*)
         integer(c_size_t), value :: n
         integer(c_long) :: r
      end function c_readlink
   end interface
end module dx_libc
