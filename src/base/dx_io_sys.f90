!> Operating-system calls (in base: every layer may use them), through bind(C) interfaces to libc
!> (POSIX): rename(2) for the atomic replace of the XDMF file, mkdir(2)/access(2) for `mkdir -p`,
!> fnmatch(3) for the file globs of the comparator's tolerance file, exit(3) so command-line tools
!> end with a status code and no runtime trace (ERROR STOP prints a backtrace);
!> open(2)/fsync(2)/close(2) so a restart dump is on disk before it is renamed into place,
!> truncate(2) to cut a time-history file back to a restart point, time(2) for batch limits;
!> write(2) on file descriptors (open_write/write_all/close_fd) because a Fortran FLUSH or CLOSE
!> does not report a failed write (a full disk: ENOSPC lost, the file left short or with holes of
!> NUL bytes), errno + strerror(3) for the OS reason in messages, statx(2) for the type of an input
!> file (only regular files are read: a FIFO or /dev/zero would hang the reader),
!> flock(2)/getpid(2)/gethostname(2) for the output-folder lock.
module dx_io_sys
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_long, c_ptr, &
      c_null_ptr, c_size_t, c_associated, c_f_pointer
   use dx_error, only: error_t, set_error, EXIT_IO, EXIT_INPUT
   use dx_strings, only: string_t
   use dx_sort, only: sort_names
   use dx_libc, only: statx_t, c_rename, c_mkdir, c_access, c_fnmatch, c_exit, c_fsync, c_close, &
      c_truncate, c_time, c_open, c_write, c_read, c_ftruncate, c_errno_location, c_strerror, &
      c_strlen, c_statx, c_flock, c_getpid, c_gethostname, c_opendir, c_readdir, c_closedir
   implicit none
   private
   public :: sys_rename, sys_mkdir_p, sys_fnmatch, sys_exit, sys_fsync, sys_truncate, &
             sys_epoch_seconds, sys_errno, sys_strerror, sys_io_reason, sys_open_write, &
             sys_write_all, sys_close_fd, sys_write_file, sys_file_kind, sys_need_regular, &
             sys_flock_try, sys_getpid, sys_hostname, sys_read_small, &
             sys_ftruncate_fd, sys_list_dir

   integer(c_int), parameter :: O_WRONLY = 1_c_int, O_RDWR = 2_c_int, O_CREAT = 64_c_int, &
                                O_TRUNC = 512_c_int, O_APPEND = 1024_c_int, &
                                O_CLOEXEC = 524288_c_int
   integer(c_int), parameter :: MODE_644 = int(o'644', c_int)
   integer(c_int), parameter :: LOCK_EX = 2_c_int, LOCK_NB = 4_c_int
   integer(c_int), parameter :: AT_FDCWD = -100_c_int, STATX_TYPE = 1_c_int
   integer, parameter :: EINTR = 4, EIO = 5, EFBIG = 27, ENOSPC = 28, &
                         EROFS = 30, EDQUOT = 122
   integer(c_int), parameter :: W_OK = 2_c_int
   integer(c_int), parameter :: MODE_755 = int(o'755', c_int)

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
      fd = c_open(path//c_null_char, 0_c_int, 0_c_int)
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

   !> The calling thread's errno.
   integer function sys_errno()
      integer(c_int), pointer :: e
      call c_f_pointer(c_errno_location(), e)
      sys_errno = int(e)
   end function sys_errno

   !> strerror(3) of errnum ("No space left on device", ...).
   function sys_strerror(errnum) result(msg)
      integer, intent(in) :: errnum
      character(:), allocatable :: msg
      type(c_ptr) :: p
      character(kind=c_char), pointer :: cs(:)
      integer :: n, i
      p = c_strerror(int(errnum, c_int))
      msg = 'error '//itoa(int(errnum, 8))
      if (.not. c_associated(p)) return
      n = int(c_strlen(p))
      call c_f_pointer(p, cs, [n])
      deallocate(msg)
      allocate(character(n) :: msg)
      do i = 1, n
         msg(i:i) = cs(i)
      end do
   end function sys_strerror

   !> ': <OS reason>' when errno holds an I/O error of the storage (a full disk or quota, a
   !> file-size limit, a read-only or failing device), else '' (errno may be stale after a
   !> library call that failed for its own reasons).
   function sys_io_reason() result(r)
      character(:), allocatable :: r
      integer :: e
      e = sys_errno()
      r = ''
      select case (e)
      case (EIO, EFBIG, ENOSPC, EROFS, EDQUOT)
         r = ': '//sys_strerror(e)
      end select
   end function sys_io_reason

   !> Open path for writing (created 0644; truncated, or appended to with append=.true.);
   !> fd < 0 and an error naming the file and the OS reason on failure.
   subroutine sys_open_write(path, append, fd, error)
      character(*), intent(in) :: path
      logical, intent(in) :: append
      integer, intent(out) :: fd
      type(error_t), allocatable, intent(out) :: error
      integer(c_int) :: flags
      flags = ior(ior(O_WRONLY, O_CREAT), O_CLOEXEC)
      if (append) then
         flags = ior(flags, O_APPEND)
      else
         flags = ior(flags, O_TRUNC)
      end if
      fd = int(c_open(path//c_null_char, flags, MODE_644))
      if (fd < 0) call set_error(error, 'cannot open '//path//' for writing: '// &
                                 sys_strerror(sys_errno()), EXIT_IO)
   end subroutine sys_open_write

   !> Write all of text to fd (path names the file in the message); a short write or an
   !> error (ENOSPC, EFBIG, EIO, ...) is an I/O error with the OS reason.
   subroutine sys_write_all(fd, text, path, error)
      integer, intent(in) :: fd
      character(*), intent(in) :: text, path
      type(error_t), allocatable, intent(out) :: error
      integer(8) :: done, n
      integer :: e
      done = 0
      do while (done < len(text, 8))
         n = int(c_write(int(fd, c_int), text(done + 1:), int(len(text, 8) - done, c_size_t)), 8)
         if (n < 0) then
            e = sys_errno()
            if (e == EINTR) cycle
            call set_error(error, 'cannot write '//path//': '//sys_strerror(e), EXIT_IO)
            return
         end if
         if (n == 0) then
            call set_error(error, 'cannot write '//path//': no progress (device full?)', &
                           EXIT_IO)
            return
         end if
         done = done + n
      end do
   end subroutine sys_write_all

   !> Cut the open file fd to nbytes bytes.
   subroutine sys_ftruncate_fd(fd, nbytes, path, error)
      integer, intent(in) :: fd
      integer(8), intent(in) :: nbytes
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      if (c_ftruncate(int(fd, c_int), int(nbytes, c_long)) /= 0) &
         call set_error(error, 'cannot truncate '//path//': '//sys_strerror(sys_errno()), EXIT_IO)
   end subroutine sys_ftruncate_fd

   !> Close fd; with sync, fsync it first (both checked).
   subroutine sys_close_fd(fd, sync, path, error)
      integer, intent(in) :: fd
      logical, intent(in) :: sync
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: e
      if (sync) then
         if (c_fsync(int(fd, c_int)) /= 0) then
            e = sys_errno()
            if (c_close(int(fd, c_int)) /= 0) continue
            call set_error(error, 'cannot sync '//path//' to disk: '//sys_strerror(e), EXIT_IO)
            return
         end if
      end if
      if (c_close(int(fd, c_int)) /= 0) &
         call set_error(error, 'cannot close '//path//': '//sys_strerror(sys_errno()), EXIT_IO)
   end subroutine sys_close_fd

   !> Write text as the whole new content of path: write, fsync, close, every step checked;
   !> on failure the partial file is removed (callers write a .tmp and rename it after).
   subroutine sys_write_file(path, text, error)
      character(*), intent(in) :: path, text
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      integer :: fd
      call sys_open_write(path, .false., fd, error)
      if (allocated(error)) return
      call sys_write_all(fd, text, path, error)
      if (allocated(error)) then
         call sys_close_fd(fd, .false., path, e)
      else
         call sys_close_fd(fd, .true., path, error)
      end if
      if (allocated(error)) call sys_unlink(path)
   end subroutine sys_write_file

   subroutine sys_unlink(path)
      character(*), intent(in) :: path
      integer :: u, ios
      open(newunit=u, file=path, status='old', iostat=ios)
      if (ios == 0) close(u, status='delete', iostat=ios)
   end subroutine sys_unlink

   !> What path is: 'regular', 'directory', 'FIFO', 'device', 'socket', 'missing', 'other'
   !> (symbolic links followed; statx(2)).
   function sys_file_kind(path) result(kind)
      character(*), intent(in) :: path
      character(:), allocatable :: kind
      type(statx_t) :: st
      integer :: fmt
      if (c_statx(AT_FDCWD, path//c_null_char, 0_c_int, STATX_TYPE, st) /= 0) then
         kind = 'missing'
         return
      end if
      fmt = iand(int(st%mode), int(o'170000'))
      select case (fmt)
      case (int(o'100000')); kind = 'regular'
      case (int(o'040000')); kind = 'directory'
      case (int(o'010000')); kind = 'FIFO'
      case (int(o'020000'), int(o'060000')); kind = 'device'
      case (int(o'140000')); kind = 'socket'
      case default; kind = 'other'
      end select
   end function sys_file_kind

   !> An input error unless path is a regular file (or missing: the caller's open reports
   !> that): what names the file for the message, e.g. 'restart file x.h5'.
   subroutine sys_need_regular(path, what, error)
      character(*), intent(in) :: path, what
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: kind
      kind = sys_file_kind(path)
      if (kind == 'regular' .or. kind == 'missing') return
      call set_error(error, what//' is a '//kind//', not a regular file', EXIT_INPUT)
   end subroutine sys_need_regular

   !> Open (create) path read-write and try an exclusive flock(2) without waiting:
   !> fd >= 0 and locked = .true. when held (released when the process ends, even on kill -9);
   !> locked = .false. when another process holds it (fd is then closed, -1).
   subroutine sys_flock_try(path, fd, locked, error)
      character(*), intent(in) :: path
      integer, intent(out) :: fd
      logical, intent(out) :: locked
      type(error_t), allocatable, intent(out) :: error
      integer :: e
      locked = .false.
      fd = int(c_open(path//c_null_char, ior(ior(O_RDWR, O_CREAT), O_CLOEXEC), MODE_644))
      if (fd < 0) then
         call set_error(error, 'cannot open the lock file '//path//': '// &
                        sys_strerror(sys_errno()), EXIT_IO)
         return
      end if
      if (c_flock(int(fd, c_int), ior(LOCK_EX, LOCK_NB)) == 0) then
         locked = .true.
         return
      end if
      e = sys_errno()
      if (c_close(int(fd, c_int)) /= 0) continue
      fd = -1
      if (e /= 11) call set_error(error, 'cannot lock '//path//': '//sys_strerror(e), EXIT_IO)
   end subroutine sys_flock_try

   !> Up to 255 bytes of the file at path ('' when unreadable).
   function sys_read_small(path) result(text)
      character(*), intent(in) :: path
      character(:), allocatable :: text
      character(kind=c_char) :: buf(255)
      integer(c_int) :: fd
      integer(c_long) :: n
      integer :: i
      text = ''
      fd = c_open(path//c_null_char, 0_c_int, 0_c_int)
      if (fd < 0) return
      n = c_read(fd, buf, 255_c_size_t)
      if (c_close(fd) /= 0) continue
      if (n <= 0) return
      deallocate(text)
      allocate(character(n) :: text)
      do i = 1, int(n)
         text(i:i) = buf(i)
      end do
   end function sys_read_small

   integer function sys_getpid()
      sys_getpid = int(c_getpid())
   end function sys_getpid

   !> This host's name (gethostname(2)).
   function sys_hostname() result(h)
      character(:), allocatable :: h
      character(kind=c_char) :: buf(256)
      integer :: i
      buf = c_null_char
      h = 'unknown-host'
      if (c_gethostname(buf, 255_c_size_t) /= 0) return
      h = ''
      do i = 1, 255
         if (buf(i) == c_null_char) exit
         h = h//buf(i)
      end do
   end function sys_hostname

   pure function itoa(i) result(s)
      integer(8), intent(in) :: i
      character(:), allocatable :: s
      character(24) :: buf
      write(buf, '(i0)') i
      s = trim(buf)
   end function itoa

   !> Seconds since the Unix epoch (time(2)).
   integer(8) function sys_epoch_seconds()
      sys_epoch_seconds = int(c_time(c_null_ptr), 8)
   end function sys_epoch_seconds

   !> The names in folder dir (not '.' and '..'), sorted as the C locale does; an I/O error
   !> when it cannot be opened. readdir(3)'s struct dirent on Linux (glibc, 64-bit): d_ino
   !> (8 bytes), d_off (8), d_reclen (2), d_type (1), then d_name (NUL-terminated) at byte 19.
   subroutine sys_list_dir(dir, names, error)
      character(*), intent(in) :: dir
      type(string_t), allocatable, intent(out) :: names(:)
      type(error_t), allocatable, intent(out) :: error
      type(c_ptr) :: d, e
      character(kind=c_char), pointer :: b(:)
      character(:), allocatable :: nm, flat(:)
      integer :: k, i
      integer(c_int) :: r
      allocate(names(0))
      d = c_opendir(dir//c_null_char)
      if (.not. c_associated(d)) then
         call set_error(error, 'cannot open folder '//dir, EXIT_IO); return
      end if
      do
         e = c_readdir(d)
         if (.not. c_associated(e)) exit
         call c_f_pointer(e, b, [19 + 256])
         nm = ''
         do k = 20, 19 + 256
            if (b(k) == c_null_char) exit
            nm = nm//b(k)
         end do
         if (nm == '.' .or. nm == '..') cycle
         names = [names, string_t(nm)]
      end do
      r = c_closedir(d)
      if (size(names) < 2) return
      allocate(character(maxval([(len(names(i)%s), i = 1, size(names))])) :: flat(size(names)))
      do i = 1, size(names)
         flat(i) = names(i)%s
      end do
      names = names(sort_names(flat))
   end subroutine sys_list_dir
end module dx_io_sys
