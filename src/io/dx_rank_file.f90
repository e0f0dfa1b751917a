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
!>   /model/node_label /model/piece_ptr /model/piece_elem /model/piece_pos
!>   /model/pieces (3, npiece) /model/piece_conn (MAX_NEN = 8, nel)
!>   /bc/spc_rec (7, n) /bc/pm_int (4, n) /loads/node_int (3, n)       integers
!>   /model/x0 /model/v0 (3, nloc) /bc/pm_real (6, n) /loads/node_sf (1, n)   float64
!> (the rank's SPC, prescribed-motion and nodal-load records with global node indices,
!> in the order of /bc/spc, /bc/prescribed, /loads/node; dx_rank_submodel)
!> The checksum (dx_checksum) covers the header and every dataset in that order (the
!> float64 arrays as their bit patterns).
!> Errors: missing or unreadable file, or a checksum mismatch: EXIT_IO (4); a file written
!> for another deck, another NP or another rank, or another format version: EXIT_INPUT (2).
module dx_rank_file
   use dx_error, only: error_t, set_error, EXIT_INPUT, EXIT_IO
   use dx_strings, only: str
   use dx_h5, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_create_group, h5_write, &
                    h5_write_attr, h5_read, h5_read_attr, h5_write_int_attrs, &
                    h5_read_int_attrs
   use dx_checksum, only: checksum_t, checksum_file
   use dx_model_input, only: string_t
   use dx_rank_part_types, only: rank_part_t
   use dx_kinds, only: wp
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
   !> format 2: the sub-model's integer datasets and their rows (0: 1-D) ...
   integer, parameter :: NMODEL = 9
   character(*), parameter :: MSETS(NMODEL) = [character(len=17) :: '/model/node_label', &
      '/model/piece_ptr', '/model/piece_elem', '/model/piece_pos', '/model/pieces', &
      '/model/piece_conn', '/bc/spc_rec', '/bc/pm_int', '/loads/node_int']
   integer, parameter :: IROWS(NMODEL) = [0, 0, 0, 0, 3, 8, 7, 4, 3]
   !> ... and its float64 datasets (2-D, rows)
   integer, parameter :: NREAL = 4
   character(*), parameter :: RSETS(NREAL) = [character(len=14) :: '/model/x0', '/model/v0', &
      '/bc/pm_real', '/loads/node_sf']
   integer, parameter :: RROWS(NREAL) = [3, 3, 6, 1]

   type :: rarr_t
      real(wp), allocatable :: a(:)
   end type rarr_t

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
   function payload_checksum(version, np, r, ne, nn, hash, arr, marr, rarr) result(h)
      integer, intent(in) :: version, np, r, ne, nn
      character(*), intent(in) :: hash
      type(iarr_t), intent(in) :: arr(NSETS), marr(NMODEL)
      type(rarr_t), intent(in) :: rarr(NREAL)
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
      do k = 1, NREAL
         call c%add_ints(transfer(rarr(k)%a, [0]))
      end do
      h = c%hex()
   end function payload_checksum

   !> The sub-model's arrays, flat (empty when rp has none).
   subroutine model_arrays(rp, marr, rarr)
      type(rank_part_t), intent(in) :: rp
      type(iarr_t), intent(out) :: marr(NMODEL)
      type(rarr_t), intent(out) :: rarr(NREAL)
      integer :: k
      do k = 1, NMODEL
         marr(k)%a = [integer ::]
      end do
      do k = 1, NREAL
         rarr(k)%a = [real(wp) ::]
      end do
      if (.not. allocated(rp%piece_ptr)) return
      marr(1)%a = rp%node_label; marr(2)%a = rp%piece_ptr; marr(3)%a = rp%piece_elem
      marr(4)%a = rp%piece_pos
      marr(5)%a = reshape(rp%pieces, [size(rp%pieces)])
      marr(6)%a = reshape(rp%piece_conn, [size(rp%piece_conn)])
      marr(7)%a = reshape(rp%spc_rec, [size(rp%spc_rec)])
      marr(8)%a = reshape(rp%pm_int, [size(rp%pm_int)])
      marr(9)%a = reshape(rp%nl_int, [size(rp%nl_int)])
      rarr(1)%a = reshape(rp%x0, [size(rp%x0)])
      rarr(2)%a = reshape(rp%v0, [size(rp%v0)])
      rarr(3)%a = reshape(rp%pm_real, [size(rp%pm_real)])
      rarr(4)%a = reshape(rp%nl_sf, [size(rp%nl_sf)])
   end subroutine model_arrays

   !> The sub-model's arrays back into rp (moved).
   subroutine model_from_arrays(marr, rarr, rp)
      type(iarr_t), intent(inout) :: marr(NMODEL)
      type(rarr_t), intent(inout) :: rarr(NREAL)
      type(rank_part_t), intent(inout) :: rp
      call move_alloc(marr(1)%a, rp%node_label)
      call move_alloc(marr(2)%a, rp%piece_ptr)
      call move_alloc(marr(3)%a, rp%piece_elem)
      call move_alloc(marr(4)%a, rp%piece_pos)
      rp%pieces = reshape(marr(5)%a, [3, size(marr(5)%a)/3])
      rp%piece_conn = reshape(marr(6)%a, [8, size(marr(6)%a)/8])
      rp%spc_rec = reshape(marr(7)%a, [7, size(marr(7)%a)/7])
      rp%pm_int = reshape(marr(8)%a, [4, size(marr(8)%a)/4])
      rp%nl_int = reshape(marr(9)%a, [3, size(marr(9)%a)/3])
      rp%x0 = reshape(rarr(1)%a, [3, size(rarr(1)%a)/3])
      rp%v0 = reshape(rarr(2)%a, [3, size(rarr(2)%a)/3])
      rp%pm_real = reshape(rarr(3)%a, [6, size(rarr(3)%a)/6])
      rp%nl_sf = rarr(4)%a
   end subroutine model_from_arrays

   !> Write rank rp%rank's file at path for the deck with content hash deck_hash.
   subroutine write_rank_file(path, rp, deck_hash, error)
      character(*), intent(in) :: path
      type(rank_part_t), intent(in) :: rp
      character(*), intent(in) :: deck_hash
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      type(h5_file_t) :: f
      type(iarr_t) :: arr(NSETS), marr(NMODEL)
      type(rarr_t) :: rarr(NREAL)
      integer :: k
      call to_arrays(rp, arr)
      call model_arrays(rp, marr, rarr)
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
         do k = 1, NMODEL
            if (IROWS(k) == 0) then
               call h5_write(f, trim(MSETS(k)), marr(k)%a, error)
            else
               call h5_write(f, trim(MSETS(k)), reshape(marr(k)%a, &
                             [IROWS(k), size(marr(k)%a)/IROWS(k)]), error)
            end if
            if (allocated(error)) exit work
         end do
         do k = 1, NREAL
            call h5_write(f, trim(RSETS(k)), reshape(rarr(k)%a, &
                          [RROWS(k), size(rarr(k)%a)/RROWS(k)]), error)
            if (allocated(error)) exit work
         end do
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
                            rp%rank, rp%ne_global, rp%nn_global, deck_hash, arr, marr, &
                            rarr), error)
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
      type(rarr_t) :: rarr(NREAL)
      character(:), allocatable :: fmt, fhash, fsum
      integer :: version, k, hv(size(HEADER))
      real(wp), allocatable :: buf(:)
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
         do k = 1, NMODEL
            call h5_read(f, trim(MSETS(k)), buf, error)
            if (allocated(error)) exit work
            marr(k)%a = nint(buf)
         end do
         do k = 1, NREAL
            call h5_read(f, trim(RSETS(k)), rarr(k)%a, error)
            if (allocated(error)) exit work
         end do
         if (fsum /= payload_checksum(version, rp%np, rp%rank, rp%ne_global, rp%nn_global, &
                                      fhash, arr, marr, rarr)) then
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
         call model_from_arrays(marr, rarr, rp)
      end block work
      call h5_close(f, err2)
      if (.not. allocated(error) .and. allocated(err2)) call move_alloc(err2, error)
      if (allocated(error)) then
         if (error%code == EXIT_IO .and. index(error%message, path) == 0) &
            error%message = path//': '//error%message
      end if
   end subroutine read_rank_file
end module dx_rank_file
