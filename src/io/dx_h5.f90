!> HDF5 datasets (with dx_h5_file, the files and attributes, the only users of the `hdf5`
!> Fortran module): typed writes and reads of whole arrays, extendible 1-D series (h5_append),
!> existence, dimensions and group listings, each checking every return code and closing
!> every handle it opens on every exit path; re-exports dx_h5_file, so callers use dx_h5
!> alone. Errors come back as error_t with code EXIT_IO naming the file, the object and the
!> operation. Arrays are written in Fortran order: a Fortran (3,nn) array is an HDF5 dataset
!> whose dimensions h5dump shows as (nn,3) (C order). h5_dims returns Fortran order.
!> No module state. Reference: The HDF Group, HDF5 Reference Manual (H5D, H5S, H5L).
module dx_h5
   use hdf5
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t
   use dx_h5_file, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_flush, &
                         h5_create_group, h5_write_attr, h5_read_attr, h5_open_rw, h5_delete, &
                         fail => h5_fail
   implicit none
   private
   public :: h5_file_t, h5_create, h5_open_read, h5_close, h5_flush, h5_create_group, &
             h5_write, h5_write_attr, h5_create_extendible, h5_append, h5_exists, h5_dims, &
             h5_read, h5_read_attr, h5_list, H5_GROUP, H5_DATASET, H5_OTHER, &
             h5_open_rw, h5_delete, h5_set_extent

   integer, parameter :: H5_GROUP = 1, H5_DATASET = 2, H5_OTHER = 3
   integer, parameter :: NAME_LEN = 256

   interface h5_write
      module procedure write_r1, write_r2, write_i1, write_i2
   end interface h5_write

contains

   !> Set the length of an extendible 1-D dataset (shrink or grow).
   subroutine h5_set_extent(f, path, n, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer, intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: ierr
      call open_dataset(f, path, dset, error)
      if (allocated(error)) return
      dims(1) = int(n, hsize_t)
      call h5dset_extent_f(dset, dims, ierr)
      if (ierr < 0) call fail(f, error, 'set the extent of', path)
      call close_dataset(f, path, dset, error)
   end subroutine h5_set_extent

   !> Create a dataset of type dtype and shape dims; returns its id (caller closes).
   subroutine create_dataset(f, path, dtype, dims, dset, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(in) :: dtype
      integer(hsize_t), intent(in) :: dims(:)
      integer(hid_t), intent(out) :: dset
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space
      integer :: ierr, ierr2
      dset = -1
      call h5screate_simple_f(size(dims), dims, space, ierr)
      if (ierr < 0) then
         call fail(f, error, 'create dataspace for', path)
         return
      end if
      block
         integer(hid_t) :: pl
         call h5pcreate_f(H5P_DATASET_CREATE_F, pl, ierr)
         call h5pset_obj_track_times_f(pl, .false., ierr)
         call h5dcreate_f(f%id, path, dtype, space, dset, ierr, pl)
         call h5pclose_f(pl, ierr2)
      end block
      if (ierr < 0) then
         dset = -1
         call fail(f, error, 'create dataset', path)
      end if
      call h5sclose_f(space, ierr2)
      if (ierr2 < 0 .and. .not. allocated(error)) call fail(f, error, 'close dataspace of', path)
   end subroutine create_dataset

   !> Close a dataset; report a failure only if no earlier error is pending.
   subroutine close_dataset(f, path, dset, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(inout) :: dset
      type(error_t), allocatable, intent(inout) :: error
      integer :: ierr
      if (dset < 0) return
      call h5dclose_f(dset, ierr)
      dset = -1
      if (ierr < 0 .and. .not. allocated(error)) call fail(f, error, 'close dataset', path)
   end subroutine close_dataset

   !> Open dataset path (dset = -1 and an error on failure).
   subroutine open_dataset(f, path, dset, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(out) :: dset
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5dopen_f(f%id, path, dset, ierr)
      if (ierr < 0) then
         dset = -1
         call fail(f, error, 'open dataset', path)
      end if
   end subroutine open_dataset

   !> The dataspace of an open dataset (space = -1 and an error "what path" on failure).
   subroutine dataset_space(f, path, dset, what, space, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path, what
      integer(hid_t), intent(in) :: dset
      integer(hid_t), intent(out) :: space
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr
      call h5dget_space_f(dset, space, ierr)
      if (ierr < 0) then
         space = -1
         call fail(f, error, what, path)
      end if
   end subroutine dataset_space

   !> Close a dataspace if open; report a failure only if no earlier error is pending.
   subroutine close_space(f, path, space, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(inout) :: space
      type(error_t), allocatable, intent(inout) :: error
      integer :: ierr
      if (space < 0) return
      call h5sclose_f(space, ierr)
      space = -1
      if (ierr < 0 .and. .not. allocated(error)) call fail(f, error, 'close space of', path)
   end subroutine close_space

   !> The typed writers of h5_write: one dataset of the array's shape, through write_data.
   subroutine write_r1(f, path, a, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      real(wp), intent(in), target, contiguous :: a(:)
      type(error_t), allocatable, intent(out) :: error
      call write_data(f, path, H5T_NATIVE_DOUBLE, shape(a, kind=hsize_t), c_loc(a), error)
   end subroutine write_r1

   subroutine write_r2(f, path, a, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      real(wp), intent(in), target, contiguous :: a(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_data(f, path, H5T_NATIVE_DOUBLE, shape(a, kind=hsize_t), c_loc(a), error)
   end subroutine write_r2

   subroutine write_i1(f, path, a, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer, intent(in), target, contiguous :: a(:)
      type(error_t), allocatable, intent(out) :: error
      call write_data(f, path, H5T_NATIVE_INTEGER, shape(a, kind=hsize_t), c_loc(a), error)
   end subroutine write_i1

   subroutine write_i2(f, path, a, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer, intent(in), target, contiguous :: a(:, :)
      type(error_t), allocatable, intent(out) :: error
      call write_data(f, path, H5T_NATIVE_INTEGER, shape(a, kind=hsize_t), c_loc(a), error)
   end subroutine write_i2

   !> Create dataset path of type dtype and shape dims and write the contiguous buffer buf
   !> (memory type dtype) into it.
   subroutine write_data(f, path, dtype, dims, buf, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(hid_t), intent(in) :: dtype
      integer(hsize_t), intent(in) :: dims(:)
      type(c_ptr), intent(in) :: buf
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: ierr
      call create_dataset(f, path, dtype, dims, dset, error)
      if (allocated(error)) return
      call h5dwrite_f(dset, dtype, buf, ierr)
      if (ierr < 0) call fail(f, error, 'write dataset', path)
      call close_dataset(f, path, dset, error)
   end subroutine write_data

   !> Create an empty, extendible (unlimited, chunked) 1-D float64 dataset.
   subroutine h5_create_extendible(f, path, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: space, plist, dset
      integer(hsize_t) :: dims(1), maxdims(1), chunk(1)
      integer :: ierr
      dims = 0
      maxdims = H5S_UNLIMITED_F
      chunk = 64
      space = -1; plist = -1; dset = -1
      work: block
         call h5screate_simple_f(1, dims, space, ierr, maxdims)
         if (ierr < 0) then
            space = -1
            call fail(f, error, 'create unlimited dataspace for', path)
            exit work
         end if
         call h5pcreate_f(H5P_DATASET_CREATE_F, plist, ierr)
         if (ierr < 0) then
            plist = -1
            call fail(f, error, 'create property list for', path)
            exit work
         end if
         call h5pset_chunk_f(plist, 1, chunk, ierr)
         call h5pset_obj_track_times_f(plist, .false., ierr)
         if (ierr < 0) then
            call fail(f, error, 'set chunking of', path)
            exit work
         end if
         call h5dcreate_f(f%id, path, H5T_NATIVE_DOUBLE, space, dset, ierr, plist)
         if (ierr < 0) then
            dset = -1
            call fail(f, error, 'create extendible dataset', path)
            exit work
         end if
      end block work
      call close_dataset(f, path, dset, error)
      if (plist >= 0) then
         call h5pclose_f(plist, ierr)
         if (ierr < 0 .and. .not. allocated(error)) call fail(f, error, 'close plist of', path)
      end if
      call close_space(f, path, space, error)
   end subroutine h5_create_extendible

   !> Append one value to an extendible 1-D float64 dataset; n returns its new length.
   subroutine h5_append(f, path, val, n, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      real(wp), intent(in) :: val
      integer, intent(out) :: n
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, fspace, mspace
      integer(hsize_t) :: dims(1), maxdims(1), start(1), count(1)
      real(wp) :: buf(1)
      integer :: ierr
      dset = -1; fspace = -1; mspace = -1
      n = 0
      buf(1) = val
      work: block
         call open_dataset(f, path, dset, error)
         if (allocated(error)) exit work
         call dataset_space(f, path, dset, 'get dataspace of', fspace, error)
         if (allocated(error)) exit work
         call h5sget_simple_extent_dims_f(fspace, dims, maxdims, ierr)
         if (ierr < 0) then
            call fail(f, error, 'get extent of', path)
            exit work
         end if
         call h5sclose_f(fspace, ierr)
         fspace = -1
         if (ierr < 0) then
            call fail(f, error, 'close dataspace of', path)
            exit work
         end if
         start = dims
         dims = dims + 1
         call h5dset_extent_f(dset, dims, ierr)
         if (ierr < 0) then
            call fail(f, error, 'extend dataset', path)
            exit work
         end if
         call dataset_space(f, path, dset, 'get extended dataspace of', fspace, error)
         if (allocated(error)) exit work
         count = 1
         call h5sselect_hyperslab_f(fspace, H5S_SELECT_SET_F, start, count, ierr)
         if (ierr < 0) then
            call fail(f, error, 'select hyperslab of', path)
            exit work
         end if
         call h5screate_simple_f(1, count, mspace, ierr)
         if (ierr < 0) then
            mspace = -1
            call fail(f, error, 'create memory dataspace for', path)
            exit work
         end if
         call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, buf, count, ierr, mspace, fspace)
         if (ierr < 0) then
            call fail(f, error, 'append to dataset', path)
            exit work
         end if
         n = int(dims(1))
      end block work
      call close_space(f, path, mspace, error)
      call close_space(f, path, fspace, error)
      call close_dataset(f, path, dset, error)
   end subroutine h5_append

   !> Whether every link along an absolute path exists.
   subroutine h5_exists(f, path, exists, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      logical, intent(out) :: exists
      type(error_t), allocatable, intent(out) :: error
      integer :: i, ierr
      exists = .true.
      if (path == '/' .or. len_trim(path) == 0) return
      do i = 2, len_trim(path) + 1
         if (i <= len_trim(path)) then
            if (path(i:i) /= '/') cycle
         end if
         call h5lexists_f(f%id, path(1:i - 1), exists, ierr)
         if (ierr < 0) then
            exists = .false.
            call fail(f, error, 'check link', path(1:i - 1))
            return
         end if
         if (.not. exists) return
      end do
   end subroutine h5_exists

   !> Dimensions of a dataset, Fortran order (a Fortran (3,nn) array gives [3, nn]).
   subroutine h5_dims(f, path, dims, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer(i8), allocatable, intent(out) :: dims(:)
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: dset, space
      integer(hsize_t), allocatable :: d(:), md(:)
      integer :: ierr, rank
      dset = -1; space = -1
      work: block
         call open_dataset(f, path, dset, error)
         if (allocated(error)) exit work
         call dataset_space(f, path, dset, 'get dataspace of', space, error)
         if (allocated(error)) exit work
         call h5sget_simple_extent_ndims_f(space, rank, ierr)
         if (ierr < 0) then
            call fail(f, error, 'get rank of', path)
            exit work
         end if
         allocate(d(rank), md(rank))
         if (rank > 0) then
            call h5sget_simple_extent_dims_f(space, d, md, ierr)
            if (ierr < 0) then
               call fail(f, error, 'get dimensions of', path)
               exit work
            end if
         end if
         dims = int(d, i8)
      end block work
      call close_space(f, path, space, error)
      call close_dataset(f, path, dset, error)
   end subroutine h5_dims

   !> Read a whole dataset (any numeric type) as a flat float64 array in Fortran order.
   subroutine h5_read(f, path, buf, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      real(wp), allocatable, intent(out) :: buf(:)
      type(error_t), allocatable, intent(out) :: error
      integer(i8), allocatable :: dims(:)
      integer(hsize_t) :: n(1)
      integer(hid_t) :: dset
      integer :: ierr
      call h5_dims(f, path, dims, error)
      if (allocated(error)) return
      n(1) = int(product(dims), hsize_t)
      allocate(buf(n(1)))
      if (n(1) == 0) return
      call open_dataset(f, path, dset, error)
      if (allocated(error)) return
      call h5dread_f(dset, H5T_NATIVE_DOUBLE, buf, n, ierr)
      if (ierr < 0) call fail(f, error, 'read dataset', path)
      call close_dataset(f, path, dset, error)
   end subroutine h5_read

   !> Members of a group with their kinds (H5_GROUP, H5_DATASET, H5_OTHER), in name order.
   subroutine h5_list(f, group, names, kinds, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: group
      character(len=NAME_LEN), allocatable, intent(out) :: names(:)
      integer, allocatable, intent(out) :: kinds(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: n, i, ierr, otype
      call h5gn_members_f(f%id, group, n, ierr)
      if (ierr < 0) then
         call fail(f, error, 'count members of group', group)
         return
      end if
      allocate(names(n), kinds(n))
      do i = 1, n
         names(i) = ''
         call h5gget_obj_info_idx_f(f%id, group, i - 1, names(i), otype, ierr)
         if (ierr < 0) then
            call fail(f, error, 'get member of group', group)
            return
         end if
         if (otype == H5G_GROUP_F) then
            kinds(i) = H5_GROUP
         else if (otype == H5G_DATASET_F) then
            kinds(i) = H5_DATASET
         else
            kinds(i) = H5_OTHER
         end if
      end do
   end subroutine h5_list
end module dx_h5
