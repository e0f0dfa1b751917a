!> HDF5 files and attributes (with dx_h5, the datasets, the only users of the `hdf5` Fortran
!> module): thin wrappers that open the library once, check every return code and close every
!> handle they open on every exit path. Callers see an opaque h5_file_t (use dx_h5, which
!> re-exports everything here); errors come back as error_t with code EXIT_IO naming the file,
!> the object and the operation (h5_fail).
!> Module state: one flag remembering that h5open_f was called (the library is opened once
!> per process and left open). HDF5's own clean-up at exit is switched off (H5dont_atexit):
!> dynx closes every file it writes, and after a failed write (a full disk) the library's
!> exit handler flushed the broken file again and crashed (exit 139 instead of 4).
!> Reference: The HDF Group, HDF5 Reference Manual (H5F, H5G, H5O, H5A).
module dx_h5_file
   use hdf5
   use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_loc
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_io_sys, only: sys_io_reason, sys_need_regular
   implicit none
   private
   public :: h5_file_t, h5_create, h5_open_read, h5_close, h5_flush, h5_create_group, &
             h5_write_attr, h5_read_attr, h5_open_rw, h5_delete, h5_fail

   !> An open HDF5 file (id < 0: not open).
   type :: h5_file_t
      integer(hid_t) :: id = -1
      character(:), allocatable :: name
   contains
      procedure :: is_open => h5_is_open
   end type h5_file_t

   interface h5_write_attr
      module procedure attr_write_real, attr_write_int, attr_write_str
   end interface h5_write_attr

   interface h5_read_attr
      module procedure attr_read_real, attr_read_int, attr_read_str
   end interface h5_read_attr

   logical, save :: lib_open = .false.

   interface
      function c_h5dont_atexit() bind(C, name='H5dont_atexit') result(r)
         import :: c_int
         integer(c_int) :: r
      end function c_h5dont_atexit
   end interface

contains

   logical function h5_is_open(self)
      class(h5_file_t), intent(in) :: self
      h5_is_open = self%id >= 0
   end function h5_is_open

   !> Error naming the file, the operation and the object.
   subroutine h5_fail(f, error, op, obj)
      type(h5_file_t), intent(in) :: f
      type(error_t), allocatable, intent(inout) :: error
      character(*), intent(in) :: op, obj
      character(:), allocatable :: fname
      fname = '?'
      if (allocated(f%name)) fname = f%name
      call set_error(error, 'HDF5: '//op//' '''//obj//''' in '//fname//' failed'// &
                     sys_io_reason(), EXIT_IO)
   end subroutine h5_fail

   subroutine lib_init(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      if (lib_open) return
      if (c_h5dont_atexit() < 0) continue   ! before the library starts (see the header)
      call h5open_f(ierr)
      if (ierr < 0) then
         call set_error(error, 'HDF5: h5open_f failed (cannot initialize the library)', EXIT_IO)
         return
      end if
      ! our own messages name the file and the operation; the library's stack trace is noise
      call h5eset_auto_f(0, ierr)
      lib_open = .true.
   end subroutine lib_init

   !> Create (truncate) a file for writing.
   subroutine h5_create(f, path, error)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call lib_init(error)
      if (allocated(error)) return
      f%name = path
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, f%id, ierr)
      if (ierr < 0) then
         f%id = -1
         call h5_fail(f, error, 'create file', path)
      end if
   end subroutine h5_create

   !> Open an existing file read-only.
   subroutine h5_open_read(f, path, error)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      call open_existing(f, path, H5F_ACC_RDONLY_F, 'open file (not an HDF5 file?)', error)
   end subroutine h5_open_read

   !> Open an existing file for reading and writing (a restart appends to the plot file).
   subroutine h5_open_rw(f, path, error)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      call open_existing(f, path, H5F_ACC_RDWR_F, &
                         'open file for writing (not an HDF5 file, or damaged?)', error)
   end subroutine h5_open_rw

   !> Open an existing regular file with access flags acc; what names the failure.
   subroutine open_existing(f, path, acc, what, error)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: path, what
      integer, intent(in) :: acc
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      logical :: there
      call lib_init(error)
      if (allocated(error)) return
      f%name = path
      inquire(file=path, exist=there)
      if (.not. there) then
         call set_error(error, 'cannot open '//path//': no such file', EXIT_IO)
         return
      end if
      call sys_need_regular(path, path, error)   ! a FIFO would hang the open: exit 2
      if (allocated(error)) return
      call h5fopen_f(path, acc, f%id, ierr)
      if (ierr < 0) then
         f%id = -1
         call h5_fail(f, error, what, path)
      end if
   end subroutine open_existing

   !> Remove the link path (a group or dataset) from the file.
   subroutine h5_delete(f, path, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5ldelete_f(f%id, path, ierr)
      if (ierr < 0) call h5_fail(f, error, 'delete', path)
   end subroutine h5_delete

   !> Close the file if open (safe to call twice).
   subroutine h5_close(f, error)
      type(h5_file_t), intent(inout) :: f
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      if (f%id < 0) return
      call h5fclose_f(f%id, ierr)
      f%id = -1
      if (ierr < 0) call h5_fail(f, error, 'close file', '/')
   end subroutine h5_close

   !> Flush all buffers of the file to disk (H5F_SCOPE_GLOBAL).
   subroutine h5_flush(f, error)
      type(h5_file_t), intent(in) :: f
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5fflush_f(f%id, H5F_SCOPE_GLOBAL_F, ierr)
      if (ierr < 0) call h5_fail(f, error, 'flush file', '/')
   end subroutine h5_flush

   !> Create a group (its parent must exist).
   subroutine h5_create_group(f, path, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: gid
      integer :: ierr, ierr2
      call h5gcreate_f(f%id, path, gid, ierr)
      if (ierr < 0) then
         call h5_fail(f, error, 'create group', path)
         return
      end if
      call h5gclose_f(gid, ierr2)
      if (ierr2 < 0) call h5_fail(f, error, 'close group', path)
   end subroutine h5_create_group

   !> Open an object (group or dataset) by path; obj < 0 on failure (error set).
   subroutine open_object(f, path, obj, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(out) :: obj
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5oopen_f(f%id, path, obj, ierr)
      if (ierr < 0) then
         obj = -1
         call h5_fail(f, error, 'open object', path)
      end if
   end subroutine open_object

   subroutine close_object(f, path, obj, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(inout) :: obj
      type(error_t), allocatable, intent(inout) :: error
      integer :: ierr
      if (obj < 0) return
      call h5oclose_f(obj, ierr)
      obj = -1
      if (ierr < 0 .and. .not. allocated(error)) call h5_fail(f, error, 'close object', path)
   end subroutine close_object

   !> Open attribute name on obj for writing, creating it (scalar, type dtype) if absent.
   !> A string attribute is always recreated (its size may change).
   subroutine open_attr_for_write(f, obj, objpath, name, dtype, recreate, attr, error)
      type(h5_file_t), intent(in) :: f
      integer(hid_t), intent(in) :: obj, dtype
      character(*), intent(in) :: objpath, name
      logical, intent(in) :: recreate
      integer(hid_t), intent(out) :: attr
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space
      logical :: exists
      integer :: ierr, ierr2
      attr = -1
      call h5aexists_f(obj, name, exists, ierr)
      if (ierr < 0) then
         call h5_fail(f, error, 'query attribute '//name//' of', objpath)
         return
      end if
      if (exists .and. recreate) then
         call h5adelete_f(obj, name, ierr)
         if (ierr < 0) then
            call h5_fail(f, error, 'delete attribute '//name//' of', objpath)
            return
         end if
         exists = .false.
      end if
      if (exists) then
         call h5aopen_f(obj, name, attr, ierr)
         if (ierr < 0) then
            attr = -1
            call h5_fail(f, error, 'open attribute '//name//' of', objpath)
         end if
         return
      end if
      call h5screate_f(H5S_SCALAR_F, space, ierr)
      if (ierr < 0) then
         call h5_fail(f, error, 'create scalar dataspace for attribute '//name//' of', objpath)
         return
      end if
      call h5acreate_f(obj, name, dtype, space, attr, ierr)
      if (ierr < 0) then
         attr = -1
         call h5_fail(f, error, 'create attribute '//name//' of', objpath)
      end if
      call h5sclose_f(space, ierr2)
      if (ierr2 < 0 .and. .not. allocated(error)) then
         call h5_fail(f, error, 'close dataspace of attribute '//name//' of', objpath)
      end if
   end subroutine open_attr_for_write

   subroutine close_attr(f, objpath, name, attr, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer(hid_t), intent(inout) :: attr
      type(error_t), allocatable, intent(inout) :: error
      integer :: ierr
      if (attr < 0) return
      call h5aclose_f(attr, ierr)
      attr = -1
      if (ierr < 0 .and. .not. allocated(error)) then
         call h5_fail(f, error, 'close attribute '//name//' of', objpath)
      end if
   end subroutine close_attr

   !> Set (create or overwrite) a scalar float64 attribute of the object at objpath.
   subroutine attr_write_real(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      real(wp), intent(in), target :: val
      type(error_t), allocatable, intent(out) :: error
      call attr_scalar_io(f, objpath, name, H5T_NATIVE_DOUBLE, c_loc(val), .true., error)
   end subroutine attr_write_real

   !> Set (create or overwrite) a scalar integer attribute of the object at objpath.
   subroutine attr_write_int(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer, intent(in), target :: val
      type(error_t), allocatable, intent(out) :: error
      call attr_scalar_io(f, objpath, name, H5T_NATIVE_INTEGER, c_loc(val), .true., error)
   end subroutine attr_write_int

   !> Write (put) or read the scalar attribute name of the object at objpath, memory type
   !> dtype, value at buf; written attributes are created when absent.
   subroutine attr_scalar_io(f, objpath, name, dtype, buf, put, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer(hid_t), intent(in) :: dtype
      type(c_ptr), intent(in) :: buf
      logical, intent(in) :: put
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: obj, attr
      type(c_ptr) :: p
      integer :: ierr
      if (put) then
         call open_object(f, objpath, obj, error)
         if (allocated(error)) return
         call open_attr_for_write(f, obj, objpath, name, dtype, .false., attr, error)
         if (.not. allocated(error)) then
            call h5awrite_f(attr, dtype, buf, ierr)
            if (ierr < 0) call h5_fail(f, error, 'write attribute '//name//' of', objpath)
         end if
      else
         call open_attr_read(f, objpath, name, obj, attr, error)
         if (allocated(error)) return
         p = buf                    ! the HDF5 binding takes it intent(inout)
         call h5aread_f(attr, dtype, p, ierr)
         if (ierr < 0) call h5_fail(f, error, 'read attribute '//name//' of', objpath)
      end if
      call close_attr(f, objpath, name, attr, error)
      call close_object(f, objpath, obj, error)
   end subroutine attr_scalar_io

   !> A copy of the native character type of n bytes for attribute name (stype < 0 and an
   !> error on failure).
   subroutine string_type(f, objpath, name, n, stype, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer(size_t), intent(in) :: n
      integer(hid_t), intent(out) :: stype
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5tcopy_f(H5T_NATIVE_CHARACTER, stype, ierr)
      if (ierr < 0) then
         stype = -1
         call h5_fail(f, error, 'copy string type for attribute '//name//' of', objpath)
         return
      end if
      call h5tset_size_f(stype, n, ierr)
      if (ierr < 0) call h5_fail(f, error, 'set string size for attribute '//name//' of', objpath)
   end subroutine string_type

   !> Close a string type of string_type if open (an error only if none is pending).
   subroutine close_string_type(f, objpath, name, stype, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer(hid_t), intent(inout) :: stype
      type(error_t), allocatable, intent(inout) :: error
      integer :: ierr
      if (stype < 0) return
      call h5tclose_f(stype, ierr)
      stype = -1
      if (ierr < 0 .and. .not. allocated(error)) &
         call h5_fail(f, error, 'close string type of attribute '//name//' of', objpath)
   end subroutine close_string_type

   !> Set a fixed-length string attribute (at least one character) of the object at objpath.
   subroutine attr_write_str(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      character(*), intent(in) :: val
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: obj, attr, stype
      integer(hsize_t) :: dims(1) = [1]
      integer :: ierr
      character(len=max(1, len(val))) :: buf
      buf = val
      call open_object(f, objpath, obj, error)
      if (allocated(error)) return
      attr = -1
      call string_type(f, objpath, name, int(len(buf), size_t), stype, error)
      if (.not. allocated(error)) then
         call open_attr_for_write(f, obj, objpath, name, stype, .true., attr, error)
      end if
      if (.not. allocated(error)) then
         call h5awrite_f(attr, stype, buf, dims, ierr)
         if (ierr < 0) call h5_fail(f, error, 'write attribute '//name//' of', objpath)
      end if
      call close_attr(f, objpath, name, attr, error)
      call close_string_type(f, objpath, name, stype, error)
      call close_object(f, objpath, obj, error)
   end subroutine attr_write_str

   !> Open attribute name of objpath for reading.
   subroutine open_attr_read(f, objpath, name, obj, attr, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer(hid_t), intent(out) :: obj, attr
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      attr = -1
      call open_object(f, objpath, obj, error)
      if (allocated(error)) return
      call h5aopen_f(obj, name, attr, ierr)
      if (ierr < 0) then
         attr = -1
         call h5_fail(f, error, 'open attribute '//name//' of', objpath)
         call close_object(f, objpath, obj, error)
      end if
   end subroutine open_attr_read

   subroutine attr_read_real(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      real(wp), intent(out), target :: val
      type(error_t), allocatable, intent(out) :: error
      val = 0.0_wp
      call attr_scalar_io(f, objpath, name, H5T_NATIVE_DOUBLE, c_loc(val), .false., error)
   end subroutine attr_read_real

   subroutine attr_read_int(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      integer, intent(out), target :: val
      type(error_t), allocatable, intent(out) :: error
      val = 0
      call attr_scalar_io(f, objpath, name, H5T_NATIVE_INTEGER, c_loc(val), .false., error)
   end subroutine attr_read_int

   !> Read a fixed-length string attribute (as written by h5_write_attr) of objpath.
   subroutine attr_read_str(f, objpath, name, val, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: objpath, name
      character(:), allocatable, intent(out) :: val
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: obj, attr, ftype, stype
      integer(hsize_t) :: dims(1) = [1]
      integer(size_t) :: n
      integer :: ierr, ierr2
      val = ''
      call open_attr_read(f, objpath, name, obj, attr, error)
      if (allocated(error)) return
      stype = -1
      work: block
         call h5aget_type_f(attr, ftype, ierr)
         if (ierr < 0) then
            call h5_fail(f, error, 'get type of attribute '//name//' of', objpath)
            exit work
         end if
         call h5tget_size_f(ftype, n, ierr)
         call h5tclose_f(ftype, ierr2)
         if (ierr < 0 .or. ierr2 < 0) then
            call h5_fail(f, error, 'get size of attribute '//name//' of', objpath)
            exit work
         end if
         call string_type(f, objpath, name, n, stype, error)
         if (allocated(error)) exit work
         block
            character(len=n) :: buf
            call h5aread_f(attr, stype, buf, dims, ierr)
            if (ierr < 0) then
               call h5_fail(f, error, 'read attribute '//name//' of', objpath)
               exit work
            end if
            val = buf
         end block
      end block work
      call close_string_type(f, objpath, name, stype, error)
      call close_attr(f, objpath, name, attr, error)
      call close_object(f, objpath, obj, error)
   end subroutine attr_read_str

end module dx_h5_file
