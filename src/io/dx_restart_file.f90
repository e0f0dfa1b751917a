!> One restart dump file in HDF5: a flat list of named float64 datasets, each with a CRC-32
!> of its bytes (attribute crc32), a format version and a writer tag on the root group.
!> Integers and logicals are stored as float64 (exact up to 2**53), so every dataset is one
!> type and one checksum rule. Written atomically: the datasets go to <path>.tmp, the file
!> is closed and fsync'ed, renamed onto <path> (rename(2) is atomic in POSIX) and the
!> directory is fsync'ed, so a crash leaves either the old dump or the new one, never half.
!> Errors are kept in the file object (the first one wins) so a component's dump routine is
!> a plain list of put/get calls; rs_commit / rs_close return it.
!> CRC-32: the IEEE 802.3 polynomial 0xEDB88320 (reflected), table-driven as in
!> Sarwate, "Computation of cyclic redundancy checks via table look-up", CACM 31(8), 1988.
!> Whole-file checksum (issue 15: HDF5 1.10.8 reads out of bounds on some damaged files):
!> rs_commit appends a 16-byte trailer, 'DYNXCRC1' and the CRC-32 of every byte before it as
!> 8 hex digits, after HDF5 closed the file (HDF5 ignores bytes past its end-of-allocation
!> address); rs_open checks it before HDF5 opens the file: a mismatch, or no trailer (a
!> truncated or damaged end, or a dump of a dynx before format version 3), is exit 4 naming
!> the file.
module dx_restart_file
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO, EXIT_INPUT
   use dx_strings, only: str
   use dx_h5, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_flush, h5_write, &
                    h5_write_attr, h5_read, h5_read_attr, h5_exists, h5_dims
   use dx_io_sys, only: sys_rename, sys_fsync, sys_need_regular
   implicit none
   private
   public :: rs_file_t, rs_create, rs_commit, rs_open, rs_close, crc32, RESTART_FORMAT_VERSION, &
             crc32_bytes

   !> Bump when the meaning or the list of datasets changes; readers refuse other versions.
   !> 2: energy record with the sliding energy (13 values), rigid_* and contact_* datasets.
   !> 3: the whole-file CRC-32 trailer, run_energy_guard.
   integer, parameter :: RESTART_FORMAT_VERSION = 3

   character(8), parameter :: TRAILER_MAGIC = 'DYNXCRC1'   !< + 8 hex digits: 16 bytes

   type :: rs_file_t
      type(h5_file_t) :: h5
      character(:), allocatable :: path        !< final name
      logical :: writing = .false.
      type(error_t), allocatable :: err        !< first error
   contains
      procedure :: put_r0, put_r1, put_r2, put_r3, put_i0, put_i1, put_i8, put_l1
      generic :: put => put_r0, put_r1, put_r2, put_r3, put_i0, put_i1, put_i8, put_l1
      procedure :: get_r0, get_r1, get_r2, get_r3, get_i0, get_i1, get_i8, get_l1
      generic :: get => get_r0, get_r1, get_r2, get_r3, get_i0, get_i1, get_i8, get_l1
      procedure :: has => rs_has
      procedure :: ok => rs_ok
      procedure :: same_labels => rs_same_labels
   end type rs_file_t

   integer(int64), save :: table(0:255)
   logical, save :: table_ready = .false.

contains

   !> Start a dump that will become path (written to path.tmp until rs_commit).
   subroutine rs_create(rs, path, writer)
      type(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: path, writer
      type(error_t), allocatable :: e
      rs%path = path
      rs%writing = .true.
      if (allocated(rs%err)) deallocate(rs%err)
      call h5_create(rs%h5, path//'.tmp', e)
      if (allocated(e)) then
         call move_alloc(e, rs%err); return
      end if
      call h5_write_attr(rs%h5, '/', 'format', 'dynx restart dump', e)
      if (.not. allocated(e)) call h5_write_attr(rs%h5, '/', 'format_version', &
                                                 RESTART_FORMAT_VERSION, e)
      if (.not. allocated(e)) call h5_write_attr(rs%h5, '/', 'writer', writer, e)
      if (allocated(e)) call move_alloc(e, rs%err)
   end subroutine rs_create

   !> Close, fsync and rename the dump into place; on any error remove the temporary file.
   subroutine rs_commit(rs, error)
      type(rs_file_t), intent(inout) :: rs
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      integer :: u, ios, k
      character(:), allocatable :: dir
      if (.not. allocated(rs%err)) call h5_write_attr(rs%h5, '/', 'complete', 1, rs%err)
      if (.not. allocated(rs%err)) call h5_flush(rs%h5, rs%err)
      call h5_close(rs%h5, e)
      if (allocated(e) .and. .not. allocated(rs%err)) call move_alloc(e, rs%err)
      if (.not. allocated(rs%err)) call append_trailer(rs%path//'.tmp', rs%err)
      if (.not. allocated(rs%err)) call sys_fsync(rs%path//'.tmp', rs%err)
      if (.not. allocated(rs%err)) call sys_rename(rs%path//'.tmp', rs%path, rs%err)
      if (.not. allocated(rs%err)) then
         k = index(rs%path, '/', back=.true.)
         dir = '.'
         if (k > 1) dir = rs%path(1:k - 1)
         call sys_fsync(dir, e)      ! the rename itself on disk; not fatal if refused
      end if
      rs%writing = .false.
      if (allocated(rs%err)) then
         open(newunit=u, file=rs%path//'.tmp', status='old', iostat=ios)
         if (ios == 0) close(u, status='delete', iostat=ios)
         call move_alloc(rs%err, error)
      end if
   end subroutine rs_commit

   !> Open a dump for reading and check its format and version.
   subroutine rs_open(rs, path, error)
      type(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      integer :: ver, complete
      rs%path = path
      rs%writing = .false.
      if (allocated(rs%err)) deallocate(rs%err)
      call check_trailer(path, error)          ! before HDF5 reads a byte of it
      if (allocated(error)) return
      call h5_open_read(rs%h5, path, error)
      if (allocated(error)) then
         error%message = 'restart file '//path//': '//error%message
         return
      end if
      call h5_read_attr(rs%h5, '/', 'format_version', ver, e)
      if (allocated(e)) then
         call set_error(error, 'restart file '//path//' is not a dynx restart dump '// &
                        '(no format_version attribute)', EXIT_INPUT)
      else if (ver /= RESTART_FORMAT_VERSION) then
         call set_error(error, 'restart file '//path//' has format version '//str(ver)// &
            '; this dynx reads version '//str(RESTART_FORMAT_VERSION), EXIT_INPUT)
      else
         call h5_read_attr(rs%h5, '/', 'complete', complete, e)
         if (allocated(e) .or. complete /= 1) call set_error(error, 'restart file '//path// &
            ' is incomplete (its writer stopped before the end)', EXIT_INPUT)
      end if
      if (allocated(error)) call h5_close(rs%h5, e)
   end subroutine rs_open

   !> Close a dump opened for reading; returns the first error of the gets.
   subroutine rs_close(rs, error)
      type(rs_file_t), intent(inout) :: rs
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      call h5_close(rs%h5, e)
      if (allocated(rs%err)) then
         call move_alloc(rs%err, error)
      else if (allocated(e)) then
         call move_alloc(e, error)
      end if
   end subroutine rs_close

   logical function rs_ok(rs)
      class(rs_file_t), intent(in) :: rs
      rs_ok = .not. allocated(rs%err)
   end function rs_ok

   !> Whether the dump holds dataset name (optional components).
   logical function rs_has(rs, name)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      type(error_t), allocatable :: e
      call h5_exists(rs%h5, '/'//name, rs_has, e)
      if (allocated(e)) rs_has = .false.
   end function rs_has

   !> Whether the dump's component has the deck's records: its count dataset count_name and
   !> labels dataset label_name against labels. Otherwise an input error: "holds N <what>,
   !> this deck has M" or "its <what> <differ>" (differ: how the labels disagree).
   logical function rs_same_labels(rs, count_name, label_name, labels, what, differ) result(same)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: count_name, label_name, what, differ
      integer, intent(in) :: labels(:)
      integer, allocatable :: l(:)
      integer :: n
      same = .false.
      n = -1
      call rs%get(count_name, n)
      if (.not. rs%ok()) return
      if (n /= size(labels)) then
         call set_error(rs%err, 'restart file '//rs%path//' holds '//str(n)//' '//what// &
            ', this deck has '//str(size(labels))//' (is it a dump of this deck?)', EXIT_INPUT)
         return
      end if
      allocate(l(n))
      l = 0
      call rs%get(label_name, l)
      if (rs%ok()) then
         if (any(l /= labels)) then
            call set_error(rs%err, 'restart file '//rs%path//': its '//what//' '//differ// &
               ' than in this deck (is it a dump of this deck?)', EXIT_INPUT)
            return
         end if
      end if
      same = .true.
   end function rs_same_labels

   ! ------------------------------------------------------------------ writing
   !> The one writer: a flat float64 array plus its CRC-32.
   subroutine put_flat(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: a(:)
      if (allocated(rs%err)) return
      call h5_write(rs%h5, '/'//name, a, rs%err)
      if (allocated(rs%err)) return
      call h5_write_attr(rs%h5, '/'//name, 'crc32', real(crc32(a), wp), rs%err)
   end subroutine put_flat

   subroutine put_r0(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: a
      call put_flat(rs, name, [a])
   end subroutine put_r0
   subroutine put_r1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: a(:)
      call put_flat(rs, name, a)
   end subroutine put_r1
   subroutine put_r2(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: a(:, :)
      call put_flat(rs, name, reshape(a, [size(a)]))
   end subroutine put_r2
   subroutine put_r3(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: a(:, :, :)
      call put_flat(rs, name, reshape(a, [size(a)]))
   end subroutine put_r3
   subroutine put_i0(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer, intent(in) :: a
      call put_flat(rs, name, [real(a, wp)])
   end subroutine put_i0
   subroutine put_i8(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer(int64), intent(in) :: a
      call put_flat(rs, name, [real(a, wp)])
   end subroutine put_i8
   subroutine put_i1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer, intent(in) :: a(:)
      call put_flat(rs, name, real(a, wp))
   end subroutine put_i1
   subroutine put_l1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      logical, intent(in) :: a(:)
      call put_flat(rs, name, merge(1.0_wp, 0.0_wp, a))
   end subroutine put_l1

   ! ------------------------------------------------------------------ reading
   !> The one reader: dataset name as a flat array of exactly n values, CRC checked.
   subroutine get_flat(rs, name, n, buf)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: buf(:)
      real(wp) :: crc
      integer(int64), allocatable :: dims(:)
      logical :: there
      if (allocated(rs%err)) then
         allocate(buf(n)); buf = 0.0_wp; return
      end if
      ! the size first (a damaged header could ask for any allocation), then the values
      call h5_exists(rs%h5, '/'//name, there, rs%err)
      if (.not. allocated(rs%err) .and. .not. there) then
         call set_error(rs%err, 'restart file '//rs%path//': no dataset '//name// &
                        ' (a dump of another deck or version?)', EXIT_INPUT)
      end if
      if (.not. allocated(rs%err)) call h5_dims(rs%h5, '/'//name, dims, rs%err)
      if (.not. allocated(rs%err)) then
         if (product(dims) /= int(n, int64)) call set_error(rs%err, 'restart file '// &
            rs%path//': dataset '//name//' has '//str(int(min(product(dims), &
            int(huge(n), int64))))//' values, this deck needs '//str(n)// &
            ' (is it a dump of this deck?)', EXIT_INPUT)
      end if
      if (.not. allocated(rs%err)) call h5_read(rs%h5, '/'//name, buf, rs%err)
      if (allocated(rs%err)) then
         if (rs%err%code == EXIT_IO) rs%err%message = 'restart file '//rs%path// &
            ': cannot read dataset '//name//' (the file is damaged): '//rs%err%message
      else
         call h5_read_attr(rs%h5, '/'//name, 'crc32', crc, rs%err)
         if (.not. allocated(rs%err)) then
            if (crc /= real(crc32(buf), wp)) call set_error(rs%err, 'restart file '// &
               rs%path//': checksum mismatch in dataset '//name//' (the file is damaged)', &
               EXIT_IO)
         end if
      end if
      if (allocated(rs%err)) then
         if (allocated(buf)) deallocate(buf)
         allocate(buf(n)); buf = 0.0_wp
      end if
   end subroutine get_flat

   subroutine get_r0(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(inout) :: a
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, 1, b)
      if (rs%ok()) a = b(1)
   end subroutine get_r0
   subroutine get_r1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(inout) :: a(:)
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, size(a), b)
      if (rs%ok()) a = b
   end subroutine get_r1
   subroutine get_r2(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(inout) :: a(:, :)
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, size(a), b)
      if (rs%ok()) a = reshape(b, shape(a))
   end subroutine get_r2
   subroutine get_r3(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(inout) :: a(:, :, :)
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, size(a), b)
      if (rs%ok()) a = reshape(b, shape(a))
   end subroutine get_r3
   subroutine get_i0(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer, intent(inout) :: a
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, 1, b)
      if (rs%ok()) a = nint(b(1))
   end subroutine get_i0
   subroutine get_i8(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer(int64), intent(inout) :: a
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, 1, b)
      if (rs%ok()) a = nint(b(1), int64)
   end subroutine get_i8
   subroutine get_i1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      integer, intent(inout) :: a(:)
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, size(a), b)
      if (rs%ok()) a = nint(b)
   end subroutine get_i1
   subroutine get_l1(rs, name, a)
      class(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      logical, intent(inout) :: a(:)
      real(wp), allocatable :: b(:)
      call get_flat(rs, name, size(a), b)
      if (rs%ok()) a = b /= 0.0_wp
   end subroutine get_l1

   ! ------------------------------------------------------------------ CRC-32
   !> CRC-32 (IEEE, reflected 0xEDB88320, init and final xor 0xFFFFFFFF) of the bytes of a.
   !> Returned in 0 .. 2**32-1; all arithmetic stays below 2**32 in 64-bit integers.
   integer(int64) function crc32(a) result(c)
      real(wp), intent(in) :: a(:)
      integer(int8), allocatable :: bytes(:)
      allocate(bytes(0))
      if (size(a) > 0) bytes = transfer(a, bytes)
      c = crc32_bytes(bytes)
   end function crc32

   !> CRC-32 of a byte string (the same rule as crc32; whole files, dx_par_restart).
   integer(int64) function crc32_bytes(bytes) result(c)
      integer(int8), intent(in) :: bytes(:)
      integer(int64), parameter :: MASK32 = int(z'FFFFFFFF', int64)
      integer :: i
      if (.not. table_ready) call make_table()
      c = MASK32
      do i = 1, size(bytes)
         c = ieor(table(iand(ieor(c, int(bytes(i), int64)), 255_int64)), shiftr(c, 8))
      end do
      c = ieor(c, MASK32)
   end function crc32_bytes

   !> CRC-32 of the first n bytes of an open stream unit (1 MiB at a time); ok = read fine.
   subroutine crc32_unit(u, n, crc, ok)
      integer, intent(in) :: u
      integer(int64), intent(in) :: n
      integer(int64), intent(out) :: crc
      logical, intent(out) :: ok
      integer(int64), parameter :: MASK32 = int(z'FFFFFFFF', int64), CHUNK = 1048576_int64
      integer(int8), allocatable :: buf(:)
      integer(int64) :: pos, m
      integer :: i, ios
      if (.not. table_ready) call make_table()
      allocate(buf(min(max(n, 1_int64), CHUNK)))
      crc = MASK32
      ok = .true.
      pos = 1
      do while (pos <= n)
         m = min(CHUNK, n - pos + 1)
         read(u, pos=pos, iostat=ios) buf(1:m)
         if (ios /= 0) then
            ok = .false.; return
         end if
         do i = 1, int(m)
            crc = ieor(table(iand(ieor(crc, int(buf(i), int64)), 255_int64)), shiftr(crc, 8))
         end do
         pos = pos + m
      end do
      crc = ieor(crc, MASK32)
   end subroutine crc32_unit

   !> Append the whole-file CRC-32 trailer to path (the closed HDF5 file).
   subroutine append_trailer(path, error)
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(inout) :: error
      integer :: u, ios
      integer(int64) :: n, crc
      logical :: ok
      character(8) :: hx
      open(newunit=u, file=path, access='stream', form='unformatted', status='old', &
           action='readwrite', iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'cannot open '//path//' to add its checksum', EXIT_IO); return
      end if
      inquire(unit=u, size=n)
      call crc32_unit(u, n, crc, ok)
      if (ok) then
         write(hx, '(z8.8)') crc
         write(u, pos=n + 1, iostat=ios) TRAILER_MAGIC//hx
         ok = ios == 0
      end if
      close(u, iostat=ios)
      if (.not. ok .or. ios /= 0) call set_error(error, 'cannot write the checksum of '// &
                                                 path//' (disk full?)', EXIT_IO)
   end subroutine append_trailer

   !> A dump's whole-file CRC-32 against its trailer, before HDF5 opens it: exit 4 on a
   !> mismatch or a missing trailer.
   subroutine check_trailer(path, error)
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios
      integer(int64) :: n, crc, want
      logical :: ok
      character(16) :: tr
      call sys_need_regular(path, 'restart file '//path, error)   ! a FIFO would hang
      if (allocated(error)) return
      open(newunit=u, file=path, access='stream', form='unformatted', status='old', &
           action='read', iostat=ios)
      if (ios /= 0) return                  ! missing or unreadable: HDF5's open says so
      inquire(unit=u, size=n)
      tr = ''
      if (n >= 16) read(u, pos=n - 15, iostat=ios) tr
      if (n < 16 .or. ios /= 0 .or. tr(1:8) /= TRAILER_MAGIC) then
         close(u)
         call set_error(error, 'restart file '//path//' has no whole-file checksum '// &
            'trailer (it is truncated or damaged at its end, not a dynx restart dump, or '// &
            'a dump of a dynx before restart format version 3)', EXIT_IO)
         return
      end if
      read(tr(9:16), '(z8)', iostat=ios) want
      call crc32_unit(u, n - 16, crc, ok)
      close(u)
      if (.not. ok) then
         call set_error(error, 'restart file '//path//': cannot read it to check its '// &
                        'checksum', EXIT_IO)
      else if (ios /= 0 .or. crc /= want) then
         call set_error(error, 'restart file '//path//': whole-file CRC-32 '//crc_hex(crc)// &
            ' is not the '//tr(9:16)//' of its trailer (the file is damaged; continue '// &
            'from an earlier dump)', EXIT_IO)
      end if
   contains
      function crc_hex(c) result(h)
         integer(int64), intent(in) :: c
         character(8) :: h
         write(h, '(z8.8)') c
      end function crc_hex
   end subroutine check_trailer

   subroutine make_table()
      integer(int64), parameter :: POLY = int(z'EDB88320', int64)
      integer(int64) :: c
      integer :: n, k
      do n = 0, 255
         c = int(n, int64)
         do k = 1, 8
            if (iand(c, 1_int64) /= 0) then
               c = ieor(POLY, shiftr(c, 1))
            else
               c = shiftr(c, 1)
            end if
         end do
         table(n) = c
      end do
      table_ready = .true.
   end subroutine make_table
end module dx_restart_file
