!> Per-rank partition files (HDF5, through dx_h5): what `dynx-part deck.k -n NP` writes for
!> each rank and what the MPI engine reads back. The file holds the decomposition only; the
!> engine re-reads the deck for the global definitions (materials, curves, controls), and
!> the deck's content hash in the file guarantees both describe the same deck
!> (docs/history.md, "Per-rank files"). Layout, format version 1:
!>   attributes of /: format = 'dynx-rank-partition', version, nprocs, rank, ne_global,
!>                    nn_global, deck_hash (16 hex digits), checksum (16 hex digits)
!>   /elements /nodes /node_owner                       global 1-based indices, ascending
!>   /shared/ranks /shared/offsets /shared/nodes        shared nodes per neighbour rank
!>   /bc/spc /bc/prescribed /loads/node /loads/segment  indices into the deck's lists
!>   /walls/offsets /walls/nodes /output/hist_nodes
!> Format 2 adds the rank's sub-model (issue 22 stage 1; dx_rank_submodel, rank_part_t):
!>   /model/node_label /model/pieces (3, npiece) /model/piece_ptr /model/piece_elem
!>   /model/piece_pos /model/piece_conn (MAX_NEN, nel)        integers
!>   /model/x0 /model/v0 (3, nloc)                             float64
!> The checksum (dx_checksum) covers the header and every dataset in that order (the
!> float64 arrays as their bit patterns).
!> Errors: missing or unreadable file, or a checksum mismatch: EXIT_IO (4); a file written
!> for another deck, another NP or another rank, or another format version: EXIT_INPUT (2).
module dx_rank_file
   use dx_error, only: error_t, set_error, EXIT_INPUT, EXIT_IO
   use dx_strings, only: str
   use dx_h5, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_create_group, h5_write, &
                    h5_write_attr, h5_read, h5_read_attr, h5_write_int_attrs, &
                    h5_read_int_attrs, h5_dims
   use dx_checksum, only: checksum_t, checksum_file
   use dx_model_input, only: string_t
   use dx_rank_part_types, only: rank_part_t
   use dx_kinds, only: wp
   use, intrinsic :: iso_fortran_env, only: i8 => int64
   implicit none
   private
   public :: write_rank_file, read_rank_file, rank_file_name, deck_content_hash, &
             RANK_FILE_VERSION, RANK_FILE_FORMAT

   integer, parameter :: RANK_FILE_VERSION = 2
   character(*), parameter :: RANK_FILE_FORMAT = 'dynx-rank-partition'
   integer, parameter :: NSETS = 13
   !> The integer root attributes after format and version, in write order.
   character(*), parameter :: HEADER(4) = [character(9) :: 'nprocs', 'rank', 'ne_global', &
                                           'nn_global']
   character(*), parameter :: SETS(NSETS) = [character(len=18) :: &
      '/elements', '/nodes', '/node_owner', '/shared/ranks', '/shared/offsets', &
      '/shared/nodes', '/bc/spc', '/bc/prescribed', '/loads/node', '/loads/segment', &
      '/walls/offsets', '/walls/nodes', '/output/hist_nodes']
   character(*), parameter :: GROUPS(6) = [character(len=7) :: &
      '/shared', '/bc', '/loads', '/walls', '/output', '/model']
   !> format 2: the sub-model's integer datasets (1-D, then the two 2-D ones) and reals
   integer, parameter :: NMODEL = 6
   character(*), parameter :: MSETS(NMODEL) = [character(len=17) :: '/model/node_label', &
      '/model/piece_ptr', '/model/piece_elem', '/model/piece_pos', '/model/pieces', &
      '/model/piece_conn']
   character(*), parameter :: RSETS(2) = [character(len=9) :: '/model/x0', '/model/v0']

   type :: iarr_t
      integer, allocatable :: a(:)
   end type iarr_t

contains

   !> DIR/rank_NNNNN.h5 (five digits, more when NP needs them).
   function rank_file_name(dir, r) result(path)
      character(*), intent(in) :: dir
      integer, intent(in) :: r
      character(:), allocatable :: path
      character(16) :: buf
      if (r < 100000) then
         write(buf, '(i5.5)') r
      else
         write(buf, '(i0)') r
      end if
      path = dir//'/rank_'//trim(adjustl(buf))//'.h5'
   end function rank_file_name

   !> Content hash of a deck: every file it reads (the deck and its includes), in order.
   subroutine deck_content_hash(files, hash, error)
      type(string_t), intent(in) :: files(:)
      character(16), intent(out) :: hash
      type(error_t), allocatable, intent(out) :: error
      type(checksum_t) :: c
      integer :: k
      do k = 1, size(files)
         call c%add_int(k)
         call checksum_file(c, files(k)%s, error)
         if (allocated(error)) return
      end do
      hash = c%hex()
   end subroutine deck_content_hash

   subroutine to_arrays(rp, arr)
      type(rank_part_t), intent(in) :: rp
      type(iarr_t), intent(out) :: arr(NSETS)
      arr(1)%a = rp%elements;   arr(2)%a = rp%nodes;      arr(3)%a = rp%node_owner
      arr(4)%a = rp%nbr;        arr(5)%a = rp%nbr_ptr;    arr(6)%a = rp%nbr_nodes
      arr(7)%a = rp%spcs;       arr(8)%a = rp%prescribed; arr(9)%a = rp%node_loads
      arr(10)%a = rp%seg_loads; arr(11)%a = rp%wall_ptr;  arr(12)%a = rp%wall_nodes
      arr(13)%a = rp%hist_nodes
   end subroutine to_arrays

   subroutine from_arrays(arr, rp)
      type(iarr_t), intent(inout) :: arr(NSETS)
      type(rank_part_t), intent(inout) :: rp
      call move_alloc(arr(1)%a, rp%elements);   call move_alloc(arr(2)%a, rp%nodes)
      call move_alloc(arr(3)%a, rp%node_owner); call move_alloc(arr(4)%a, rp%nbr)
      call move_alloc(arr(5)%a, rp%nbr_ptr);    call move_alloc(arr(6)%a, rp%nbr_nodes)
      call move_alloc(arr(7)%a, rp%spcs);       call move_alloc(arr(8)%a, rp%prescribed)
      call move_alloc(arr(9)%a, rp%node_loads); call move_alloc(arr(10)%a, rp%seg_loads)
      call move_alloc(arr(11)%a, rp%wall_ptr);  call move_alloc(arr(12)%a, rp%wall_nodes)
      call move_alloc(arr(13)%a, rp%hist_nodes)
   end subroutine from_arrays

   !> The checksum of a rank file's header and datasets.
   function payload_checksum(version, np, r, ne, nn, hash, arr, marr, x0, v0) result(h)
      integer, intent(in) :: version, np, r, ne, nn
      character(*), intent(in) :: hash
      type(iarr_t), intent(in) :: arr(NSETS), marr(NMODEL)
      real(wp), intent(in) :: x0(:, :), v0(:, :)
      character(16) :: h
      type(checksum_t) :: c
      integer :: k
      call c%add_text(RANK_FILE_FORMAT)
      call c%add_int(version); call c%add_int(np); call c%add_int(r)
      call c%add_int(ne); call c%add_int(nn)
      call c%add_text(hash)
      do k = 1, NSETS
         call c%add_ints(arr(k)%a)
      end do
      do k = 1, NMODEL
         call c%add_ints(marr(k)%a)
      end do
      call c%add_ints(transfer(x0, [0]))
      call c%add_ints(transfer(v0, [0]))
      h = c%hex()
   end function payload_checksum

   !> The sub-model's integer arrays, flat (empty when rp has none).
   subroutine model_arrays(rp, marr, x0, v0)
      type(rank_part_t), intent(in) :: rp
      type(iarr_t), intent(out) :: marr(NMODEL)
      real(wp), allocatable, intent(out) :: x0(:, :), v0(:, :)
      integer :: k
      do k = 1, NMODEL
         marr(k)%a = [integer ::]
      end do
      allocate(x0(3, 0), v0(3, 0))
      if (.not. allocated(rp%piece_ptr)) return
      marr(1)%a = rp%node_label; marr(2)%a = rp%piece_ptr; marr(3)%a = rp%piece_elem
      marr(4)%a = rp%piece_pos
      marr(5)%a = reshape(rp%pieces, [size(rp%pieces)])
      marr(6)%a = reshape(rp%piece_conn, [size(rp%piece_conn)])
      x0 = rp%x0
      v0 = rp%v0
   end subroutine model_arrays

   !> Write rank rp%rank's file at path for the deck with content hash deck_hash.
   subroutine write_rank_file(path, rp, deck_hash, error)
      character(*), intent(in) :: path
      type(rank_part_t), intent(in) :: rp
      character(*), intent(in) :: deck_hash
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      type(h5_file_t) :: f
      type(iarr_t) :: arr(NSETS), marr(NMODEL)
      real(wp), allocatable :: x0(:, :), v0(:, :)
      integer :: k
      call to_arrays(rp, arr)
      call model_arrays(rp, marr, x0, v0)
      call h5_create(f, path, error)
      if (allocated(error)) return
      work: block
         do k = 1, size(GROUPS)
            call h5_create_group(f, trim(GROUPS(k)), error)
            if (allocated(error)) exit work
         end do
         do k = 1, NSETS
            call h5_write(f, trim(SETS(k)), arr(k)%a, error)
            if (allocated(error)) exit work
         end do
         do k = 1, NMODEL - 2
            call h5_write(f, trim(MSETS(k)), marr(k)%a, error)
            if (allocated(error)) exit work
         end do
         if (allocated(rp%pieces)) then
            call h5_write(f, trim(MSETS(5)), rp%pieces, error)
            if (allocated(error)) exit work
            call h5_write(f, trim(MSETS(6)), rp%piece_conn, error)
         else
            call h5_write(f, trim(MSETS(5)), reshape(marr(5)%a, [3, 0]), error)
            if (allocated(error)) exit work
            call h5_write(f, trim(MSETS(6)), reshape(marr(6)%a, [8, 0]), error)
         end if
         if (allocated(error)) exit work
         call h5_write(f, trim(RSETS(1)), x0, error)
         if (allocated(error)) exit work
         call h5_write(f, trim(RSETS(2)), v0, error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'format', RANK_FILE_FORMAT, error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'version', RANK_FILE_VERSION, error)
         if (allocated(error)) exit work
         call h5_write_int_attrs(f, '/', HEADER, [rp%np, rp%rank, rp%ne_global, rp%nn_global], &
                                 error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'deck_hash', deck_hash, error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'checksum', payload_checksum(RANK_FILE_VERSION, rp%np, &
                            rp%rank, rp%ne_global, rp%nn_global, deck_hash, arr, marr, x0, &
                            v0), error)
      end block work
      call h5_close(f, err2)
      if (.not. allocated(error) .and. allocated(err2)) call move_alloc(err2, error)
   end subroutine write_rank_file

   !> Read and check the file of rank r of an np-rank partition of the deck whose content
   !> hash is deck_hash.
   subroutine read_rank_file(path, deck_hash, np, r, rp, error)
      character(*), intent(in) :: path, deck_hash
      integer, intent(in) :: np, r
      type(rank_part_t), intent(out) :: rp
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      type(h5_file_t) :: f
      type(iarr_t) :: arr(NSETS), marr(NMODEL)
      character(:), allocatable :: fmt, fhash, fsum
      integer :: version, k, hv(size(HEADER))
      real(wp), allocatable :: buf(:), x0(:, :), v0(:, :)
      integer(i8), allocatable :: dims(:)
      integer :: rows(NMODEL)
      call h5_open_read(f, path, error)
      if (allocated(error)) return
      work: block
         call h5_read_attr(f, '/', 'format', fmt, error)
         if (allocated(error)) exit work
         if (fmt /= RANK_FILE_FORMAT) then
            call set_error(error, path//': not a dynx rank partition file (format '''// &
                           fmt//''')', EXIT_INPUT)
            exit work
         end if
         call h5_read_attr(f, '/', 'version', version, error)
         if (allocated(error)) exit work
         if (version /= RANK_FILE_VERSION) then
            call set_error(error, path//': rank file format version '//str(version)// &
               ', this dynx reads version '//str(RANK_FILE_VERSION)// &
               '; rerun dynx-part', EXIT_INPUT)
            exit work
         end if
         call h5_read_int_attrs(f, '/', HEADER, hv, error)
         if (allocated(error)) exit work
         rp%np = hv(1); rp%rank = hv(2); rp%ne_global = hv(3); rp%nn_global = hv(4)
         call h5_read_attr(f, '/', 'deck_hash', fhash, error)
         if (allocated(error)) exit work
         call h5_read_attr(f, '/', 'checksum', fsum, error)
         if (allocated(error)) exit work
         do k = 1, NSETS
            call h5_read(f, trim(SETS(k)), buf, error)
            if (allocated(error)) exit work
            arr(k)%a = nint(buf)
         end do
         rows = 1
         do k = 1, NMODEL
            call h5_read(f, trim(MSETS(k)), buf, error)
            if (allocated(error)) exit work
            marr(k)%a = nint(buf)
            if (k > NMODEL - 2) then
               call h5_dims(f, trim(MSETS(k)), dims, error)
               if (allocated(error)) exit work
               rows(k) = int(dims(1))
            end if
         end do
         call h5_read(f, trim(RSETS(1)), buf, error)
         if (allocated(error)) exit work
         x0 = reshape(buf, [3, size(buf)/3])
         call h5_read(f, trim(RSETS(2)), buf, error)
         if (allocated(error)) exit work
         v0 = reshape(buf, [3, size(buf)/3])
         if (fsum /= payload_checksum(version, rp%np, rp%rank, rp%ne_global, rp%nn_global, &
                                      fhash, arr, marr, x0, v0)) then
            call set_error(error, path//': rank file is corrupt (checksum mismatch); '// &
                           'rerun dynx-part', EXIT_IO)
            exit work
         end if
         if (fhash /= deck_hash) then
            call set_error(error, path//': rank file was written for another deck '// &
               '(deck content hash '//fhash//', this deck has '//trim(deck_hash)// &
               '); rerun dynx-part on this deck', EXIT_INPUT)
            exit work
         end if
         if (rp%np /= np) then
            call set_error(error, path//': rank file was written for NP = '//str(rp%np)// &
               ', this run has NP = '//str(np)//'; rerun dynx-part -n '//str(np), EXIT_INPUT)
            exit work
         end if
         if (rp%rank /= r) then
            call set_error(error, path//': rank file holds rank '//str(rp%rank)// &
                           ', expected rank '//str(r), EXIT_INPUT)
            exit work
         end if
         call from_arrays(arr, rp)
         call move_alloc(marr(1)%a, rp%node_label)
         call move_alloc(marr(2)%a, rp%piece_ptr)
         call move_alloc(marr(3)%a, rp%piece_elem)
         call move_alloc(marr(4)%a, rp%piece_pos)
         rp%pieces = reshape(marr(5)%a, [rows(5), size(marr(5)%a)/max(1, rows(5))])
         rp%piece_conn = reshape(marr(6)%a, [rows(6), size(marr(6)%a)/max(1, rows(6))])
         call move_alloc(x0, rp%x0)
         call move_alloc(v0, rp%v0)
      end block work
      call h5_close(f, err2)
      if (.not. allocated(error) .and. allocated(err2)) call move_alloc(err2, error)
      if (allocated(error)) then
         if (error%code == EXIT_IO .and. index(error%message, path) == 0) &
            error%message = path//': '//error%message
      end if
   end subroutine read_rank_file
end module dx_rank_file
