!> Unit tests of the partitioner (dx_partition, dx_metis), the checksum (dx_checksum) and the
!> per-rank files (dx_rank_file): published check values, hand-counted graphs, invariants
!> of the partition (every element on exactly one rank, symmetric shared-node lists, groups
!> whole on one rank, reproducible), the balance statistic, and the rank-file round trip
!> with its error paths (another NP, another deck, another rank, missing, corrupt).
program test_partition
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_INPUT, EXIT_IO
   use dx_checksum, only: checksum_t
   use dx_model, only: model_t, spc_t, load_segment_t
   use dx_model_input, only: model_input_t
   use dx_deck, only: read_deck_input
   use dx_model_build, only: build_model_data
   use dx_partition, only: partition_t, rank_part_t, element_graph, condense_groups, &
                           partition_elements, partition_model, rank_part, face_elements, &
                           scatter_keys, write_report
   use dx_rank_file, only: write_rank_file, read_rank_file, rank_file_name, deck_content_hash
   use dx_io_sys, only: sys_mkdir_p
   use dx_assert, only: check, check_close, assert_summary
   use dx_par_model, only: par_model_verify
   use dx_strings, only: str
   implicit none
   character(*), parameter :: TMP = 'build/test_partition'
   type(error_t), allocatable :: error

   call sys_mkdir_p(TMP, error)
   if (allocated(error)) error stop 'cannot create '//TMP
   call test_checksum()
   call test_condense()
   call test_graph()
   call test_box_partitions()
   call test_contact_pair_group()
   call test_bcs_on_ranks()
   call test_rank_files()
   call test_serial_order_emulation()
   call test_more_ranks_than_elements()
   call test_proximity_edges()
   call test_whole_blocks()
   call assert_summary()

contains

   subroutine test_checksum()
      type(checksum_t) :: c1, c2, c3
      character(16) :: h
      write(*, '(a)') 'checksum'
      call c1%add_text('123456789')
      ! CRC-32/IEEE check value of '123456789' (Rocksoft catalogue): CBF43926
      h = c1%hex()
      call check(h(1:8) == 'CBF43926', 'CRC-32 of "123456789" = CBF43926')
      call c2%add_text('a')
      ! FNV-1a 32-bit of 'a' (Fowler-Noll-Vo test vectors): E40C292C
      h = c2%hex()
      call check(h(9:16) == 'E40C292C', 'FNV-1a-32 of "a" = E40C292C')
      call c3%add_ints([1, 2])
      call c2%add_ints([1])
      call c2%add_ints([2])
      call check(c3%hex() /= c2%hex(), 'length-prefixed arrays: [1,2] differs from [1],[2]')
   end subroutine test_checksum

   !> Synthetic groups: {2,5,7}, {7,9} (overlap: merge), {1}, {} over 10 elements.
   subroutine test_condense()
      integer, allocatable :: vtx(:), vwgt(:)
      integer :: nv
      write(*, '(a)') 'condense_groups'
      call condense_groups(10, [1, 1, 1, 1, 1, 1, 8, 1, 1, 1], [1, 4, 6, 7, 7], &
                           [2, 5, 7, 7, 9, 1], vtx, nv, vwgt, error)
      call check(.not. allocated(error), 'condense: no error')
      call check(nv == 7, 'condense: 10 elements, groups {2,5,7}+{7,9} merged -> 7 vertices')
      call check(all(vtx == [1, 2, 3, 4, 2, 5, 2, 6, 2, 7]), 'condense: vertex of each element')
      call check(vwgt(2) == 11 .and. sum(vwgt) == 17, &
                 'condense: super vertex weight = sum of its 4 element weights (1+1+8+1)')
      call condense_groups(3, [1, 1, 1], [1, 2], [4], vtx, nv, vwgt, error)
      call check(allocated(error), 'condense: element index out of range is an error')
      if (allocated(error)) call check(error%code == EXIT_INPUT, 'condense: exit code 2')
   end subroutine test_condense

   !> Structured box of nx*ny*nz hex8 (nodes numbered i fastest).
   subroutine box(nx, ny, nz, conn, nn)
      integer, intent(in) :: nx, ny, nz
      integer, allocatable, intent(out) :: conn(:, :)
      integer, intent(out) :: nn
      integer :: i, j, k, e
      allocate(conn(8, nx*ny*nz))
      nn = (nx + 1)*(ny + 1)*(nz + 1)
      e = 0
      do k = 0, nz - 1
         do j = 0, ny - 1
            do i = 0, nx - 1
               e = e + 1
               conn(:, e) = [gid(i, j, k, nx, ny), gid(i + 1, j, k, nx, ny), &
                  gid(i + 1, j + 1, k, nx, ny), gid(i, j + 1, k, nx, ny), &
                  gid(i, j, k + 1, nx, ny), gid(i + 1, j, k + 1, nx, ny), &
                  gid(i + 1, j + 1, k + 1, nx, ny), gid(i, j + 1, k + 1, nx, ny)]
            end do
         end do
      end do
   end subroutine box

   pure integer function gid(a, b, c, nx, ny)
      integer, intent(in) :: a, b, c, nx, ny
      gid = 1 + a + (nx + 1)*(b + (ny + 1)*c)
   end function gid

   subroutine test_graph()
      integer, allocatable :: conn(:, :), xadj(:), adjncy(:), adjwgt(:), vtx(:)
      integer :: nn, c, e
      write(*, '(a)') 'element_graph'
      call box(2, 1, 1, conn, nn)
      vtx = [1, 2]
      call element_graph(conn, nn, vtx, 2, xadj, adjncy, adjwgt)
      call check(all(xadj == [0, 1, 2]) .and. all(adjncy == [1, 0]) .and. all(adjwgt == 4), &
                 'two hexes sharing a face: one edge each way, weight 4 shared nodes')
      call box(3, 3, 3, conn, nn)
      vtx = [(e, e = 1, 27)]
      call element_graph(conn, nn, vtx, 27, xadj, adjncy, adjwgt)
      c = 14   ! the centre element of the 3x3x3 box
      call check(xadj(c + 1) - xadj(c) == 26, '3x3x3 box: centre element has 26 neighbours')
      call check(sum(adjwgt(xadj(c) + 1:xadj(c + 1))) == 6*4 + 12*2 + 8*1, &
                 '3x3x3 box: centre edge weights 6 faces x4 + 12 edges x2 + 8 corners x1 = 56')
      call check(xadj(2) - xadj(1) == 7, '3x3x3 box: corner element has 7 neighbours')
      call check(sum(xadj(2:) - xadj(:27)) == size(adjncy) .and. &
                 mod(size(adjncy), 2) == 0, '3x3x3 box: adjacency is symmetric in size')
      ! a group {1,27} (opposite corners) condensed: its vertex touches both corners' sets
      vtx = [1, (e, e = 2, 26), 1]
      call element_graph(conn, nn, vtx, 26, xadj, adjncy, adjwgt)
      ! corners 1 and 27 have 7 neighbours each; the centre element 14 is common to both
      call check(xadj(2) - xadj(1) == 13, 'condensed corners {1,27}: 7 + 7 - 1 neighbours')
      call check(adjwgt(xadj(1) + findloc(adjncy(xadj(1) + 1:xadj(2)), 13, dim=1)) == 2, &
                 'condensed corners {1,27}: edge weight to the centre = 1 + 1 shared nodes')
   end subroutine test_graph

   !> Partition invariants on a 10x10x10 box with groups, np = 2, 3, 4.
   subroutine test_box_partitions()
      integer, allocatable :: conn(:, :), ewgt(:), gp(:), ge(:), first(:)
      type(partition_t) :: part, part2
      type(rank_part_t), allocatable :: rps(:)
      integer :: nn, np, e, r, q, k, kq, n, i
      logical :: ok
      character(1) :: c
      write(*, '(a)') 'partition of a 10x10x10 box with groups'
      call box(10, 10, 10, conn, nn)
      allocate(ewgt(size(conn, 2)))
      ewgt = 1
      ! groups: the bottom layer (100 elements), {5, 900}, {900, 950} (overlapping)
      gp = [1, 101, 103, 105]
      ge = [[(e, e = 1, 100)], 5, 900, 900, 950]
      do np = 2, 4
         write(c, '(i1)') np
         call partition_elements(conn, nn, ewgt, gp, ge, np, part, error)
         call check(.not. allocated(error), 'np='//c//': partition without error')
         if (allocated(error)) cycle
         call check(all(part%epart >= 0 .and. part%epart < np) .and. &
                    sum(part%rank_ne) == 1000, 'np='//c//': every element on exactly one rank')
         call check(all(part%rank_ne > 0), 'np='//c//': no empty rank')
         call check(all(part%epart(1:100) == part%epart(1)), &
                    'np='//c//': group of 100 elements whole on one rank')
         call check(part%epart(5) == part%epart(900) .and. part%epart(900) == part%epart(950), &
                    'np='//c//': overlapping groups {5,900},{900,950} on one rank')
         call check(part%balance <= 1.1_wp, 'np='//c//': balance <= 1.1 (got '// &
                    trim(rs(part%balance))//')')
         call check_close(part%balance, real(maxval(part%rank_wgt), wp)/(1000.0_wp/np), &
                          0.0_wp, 1.0e-14_wp, 'np='//c//': balance = max/mean weight')
         call partition_elements(conn, nn, ewgt, gp, ge, np, part2, error)
         call check(all(part2%epart == part%epart), 'np='//c//': partition is reproducible')
         ! rank contents: shared lists symmetric, nodes and owners consistent
         if (allocated(rps)) deallocate(rps)
         allocate(rps(0:np - 1))
         do r = 0, np - 1
            block
               type(model_t) :: empty
               call rank_part(empty, part, r, rps(r), error)
            end block
         end do
         ok = .true.
         do r = 0, np - 1
            do k = 1, size(rps(r)%nbr)
               q = rps(r)%nbr(k)
               kq = findloc(rps(q)%nbr, r, dim=1)
               if (kq == 0) then
                  ok = .false.
                  cycle
               end if
               if (.not. same(rps(r)%nbr_nodes(rps(r)%nbr_ptr(k):rps(r)%nbr_ptr(k + 1) - 1), &
                              rps(q)%nbr_nodes(rps(q)%nbr_ptr(kq):rps(q)%nbr_ptr(kq + 1) - 1))) &
                  ok = .false.
            end do
         end do
         call check(ok, 'np='//c//': shared-node lists symmetric (node shared by a and b '// &
                    'in both lists)')
         ! every node on >= 1 rank; owner = lowest rank holding it; shared iff on > 1 rank
         allocate(first(nn))
         first = -1
         ok = .true.
         do r = np - 1, 0, -1
            first(rps(r)%nodes) = r
            do i = 1, size(rps(r)%nodes)
               n = rps(r)%nodes(i)
               if (rps(r)%node_owner(i) /= part%node_owner(n)) ok = .false.
            end do
         end do
         call check(all(first >= 0) .and. all(first == part%node_owner) .and. ok, &
                    'np='//c//': every node on a rank, owner = lowest rank holding it')
         deallocate(first)
         ok = .true.
         do e = 1, size(conn, 2)
            r = part%epart(e)
            do k = 1, 8
               if (findloc(rps(r)%nodes, conn(k, e), dim=1) == 0) ok = .false.
            end do
         end do
         call check(ok, 'np='//c//': a rank holds every node of its elements')
      end do
   end subroutine test_box_partitions

   !> A synthetic contact pair on a 8x8x8 box: the top face of the bottom slab (z = 2) and
   !> the bottom face of the top slab (z = 6) as its two surfaces; face_elements gives the
   !> group, which lands whole on one rank at np = 2, 3, 4.
   subroutine test_contact_pair_group()
      integer, allocatable :: conn(:, :), ewgt(:), seg(:, :), grp(:)
      type(partition_t) :: part
      integer :: nn, i, j, k, np
      character(1) :: c
      write(*, '(a)') 'contact pair condensed into one super element'
      call box(8, 8, 8, conn, nn)
      allocate(seg(4, 128), ewgt(size(conn, 2)))
      ewgt = 1
      k = 0
      do j = 0, 7
         do i = 0, 7
            k = k + 1
            seg(:, k) = [gid(i, j, 2, 8, 8), gid(i + 1, j, 2, 8, 8), gid(i + 1, j + 1, 2, 8, 8), &
                         gid(i, j + 1, 2, 8, 8)]
            seg(:, 64 + k) = [gid(i, j, 6, 8, 8), gid(i, j + 1, 6, 8, 8), &
                              gid(i + 1, j + 1, 6, 8, 8), gid(i + 1, j, 6, 8, 8)]
         end do
      end do
      call face_elements(conn, nn, seg, grp)
      ! the face z = 2 belongs to layers 2 and 3 (k = 1, 2), z = 6 to layers 6 and 7
      call check(size(grp) == 4*64 .and. all(grp(1:64) == [(64 + i, i = 1, 64)]) .and. &
                 all(grp(193:256) == [(384 + i, i = 1, 64)]), &
                 'face_elements: 4 layers of 64 elements touch the two surfaces')
      do np = 2, 4
         write(c, '(i1)') np
         call partition_elements(conn, nn, ewgt, [1, size(grp) + 1], grp, np, part, error)
         call check(.not. allocated(error), 'np='//c//': partition with the pair')
         if (allocated(error)) cycle
         call check(all(part%epart(grp) == part%epart(grp(1))), &
                    'np='//c//': the contact pair (256 elements) is whole on one rank')
         ! the pair alone weighs 256 of 512: balance cannot go below 256/(512/np), so the
         ! bound is max(1.1, np/2) (the seed: the largest contact surface limits NP)
         call check(part%balance <= max(1.1_wp, 0.5_wp*np) + 1.0e-12_wp, 'np='//c// &
                    ': balance <= max(1.1, weight of the pair / mean) (got '// &
                    trim(rs(part%balance))//')')
      end do
   end subroutine test_contact_pair_group

   !> The bit-for-bit design on a real model (taylor_simo, 1536 elements in 12 blocks), in one
   !> process: random adversarial corner forces; the serial sum with the hex8 kernels' loop
   !> order; then NP = 3 ranks (METIS): each rank runs the same loop over the pieces of the
   !> serial blocks it holds, adding into interior nodes, and keeps shared-node contributions
   !> apart with their scatter_keys; shared nodes are summed over all ranks in key order.
   !> Every node must equal the serial sum bit for bit. Merging a rank's pieces into full
   !> 128-element blocks instead must not (it interleaves corner slots of two serial blocks).
   subroutine test_serial_order_emulation()
      character(*), parameter :: DECK = 'tests/regression/taylor_simo/deck.k'
      integer, parameter :: NP = 3
      type(model_t) :: model
      type(model_input_t) :: inp
      type(partition_t) :: part
      integer, allocatable :: keys(:, :), nhold(:), ck(:), cn(:), order(:), piece(:)
      real(wp), allocatable :: val(:, :, :), ref(:, :), loc(:, :), cv(:, :), merged(:, :)
      integer :: e, k, b, i, r, n, nc, gp(1), ge(0), nbad, nbad_merged, m, j
      integer(int64) :: st
      write(*, '(a)') 'serial order emulation (taylor_simo, NP = 3)'
      call read_deck_input(DECK, inp, error)
      if (.not. allocated(error)) call build_model_data(inp, model, error)
      call check(.not. allocated(error), 'read and build '//DECK)
      if (allocated(error)) return
      call scatter_keys(model, keys)
      allocate(val(3, 8, model%ne))
      st = 4242_int64
      do e = 1, model%ne
         do k = 1, 8
            do i = 1, 3
               val(i, k, e) = adv(st)
            end do
         end do
      end do
      ! serial: blocks in order, do k = 1, 8; do i = 1, nel (as hex8_1pt / hex8_sri)
      allocate(ref(3, model%nn))
      ref = 0.0_wp
      do b = 1, size(model%blocks)
         do k = 1, 8
            do i = 1, model%blocks(b)%nel
               e = model%blocks(b)%elem(i)
               n = model%blocks(b)%conn(k, i)
               ref(:, n) = ref(:, n) - val(:, k, e)
            end do
         end do
      end do
      gp = 1
      call partition_model(model, NP, gp, ge, part, error)
      allocate(nhold(model%nn))
      nhold = part%nr_ptr(2:) - part%nr_ptr(:model%nn)
      ! ranks: interior nodes summed locally, shared contributions (value, key) collected
      allocate(cv(3, 8*model%ne), ck(8*model%ne), cn(8*model%ne), loc(3, model%nn), &
               merged(3, model%nn))
      nc = 0
      nbad = 0
      nbad_merged = 0
      loc = 0.0_wp
      merged = 0.0_wp
      do r = 0, NP - 1
         do b = 1, size(model%blocks)
            piece = pack([(i, i = 1, model%blocks(b)%nel)], &
                         part%epart(model%blocks(b)%elem) == r)
            do k = 1, 8
               do j = 1, size(piece)
                  i = piece(j)
                  e = model%blocks(b)%elem(i)
                  n = model%blocks(b)%conn(k, i)
                  if (nhold(n) == 1) then
                     loc(:, n) = loc(:, n) - val(:, k, e)
                  else
                     nc = nc + 1
                     cv(:, nc) = -val(:, k, e)
                     ck(nc) = keys(k, e)
                     cn(nc) = n
                  end if
               end do
            end do
         end do
         ! the wrong way: the rank's elements (serial order) in consolidated 128-blocks
         order = pack([(i, i = 1, model%ne)], part%epart == r)
         call sort_by_serial(order, keys)
         do m = 1, size(order), 128
            do k = 1, 8
               do j = m, min(m + 127, size(order))
                  e = order(j)
                  n = model%blocks(model%elem_block(e))%conn(k, model%elem_pos(e))
                  if (nhold(n) == 1) merged(:, n) = merged(:, n) - val(:, k, e)
               end do
            end do
         end do
      end do
      ! shared nodes: all contributions in key order, from 0
      block
         integer, allocatable :: idx(:)
         idx = [(i, i = 1, nc)]
         call sort_by_serial2(idx, ck(1:nc))
         do j = 1, nc
            i = idx(j)
            loc(:, cn(i)) = loc(:, cn(i)) + cv(:, i)
         end do
      end block
      do n = 1, model%nn
         if (any(transfer(loc(:, n), 1_int64, 3) /= transfer(ref(:, n), 1_int64, 3))) &
            nbad = nbad + 1
         if (nhold(n) == 1) then
            if (any(transfer(merged(:, n), 1_int64, 3) /= transfer(ref(:, n), 1_int64, 3))) &
               nbad_merged = nbad_merged + 1
         end if
      end do
      write(*, '(a,i0,a,i0,a)') '    (', count(nhold > 1), ' shared nodes; consolidated '// &
         'blocks differ at ', nbad_merged, ' interior nodes)'
      call check(nbad == 0, 'pieces of serial blocks + key-ordered shared sums = serial f '// &
                 'bit for bit at every node')
      call check(nbad_merged > 0, 'consolidated 128-element rank blocks do not reproduce '// &
                 'the serial f (the rule is needed)')
   end subroutine test_serial_order_emulation

   !> Sort element indices by their first-corner key (= serial block order, then position).
   subroutine sort_by_serial(idx, keys)
      integer, intent(inout) :: idx(:)
      integer, intent(in) :: keys(:, :)
      integer, allocatable :: kk(:)
      kk = keys(1, idx)
      call sort_pairs(kk, idx)
   end subroutine sort_by_serial

   subroutine sort_by_serial2(idx, key)
      integer, intent(inout) :: idx(:)
      integer, intent(in) :: key(:)
      integer, allocatable :: kk(:)
      kk = key(idx)
      call sort_pairs(kk, idx)
   end subroutine sort_by_serial2

   !> Heap sort of kk (distinct keys), carrying idx along.
   subroutine sort_pairs(kk, idx)
      integer, intent(inout) :: kk(:), idx(:)
      integer :: n, i, t
      n = size(kk)
      do i = n/2, 1, -1
         call sift2(kk, idx, i, n)
      end do
      do i = n, 2, -1
         t = kk(1); kk(1) = kk(i); kk(i) = t
         t = idx(1); idx(1) = idx(i); idx(i) = t
         call sift2(kk, idx, 1, i - 1)
      end do
   end subroutine sort_pairs

   subroutine sift2(kk, idx, start, n)
      integer, intent(inout) :: kk(:), idx(:)
      integer, intent(in) :: start, n
      integer :: r, c, t
      r = start
      do while (2*r <= n)
         c = 2*r
         if (c < n) then
            if (kk(c + 1) > kk(c)) c = c + 1
         end if
         if (kk(r) >= kk(c)) return
         t = kk(r); kk(r) = kk(c); kk(c) = t
         t = idx(r); idx(r) = idx(c); idx(c) = t
         r = c
      end do
   end subroutine sift2

   !> Adversarial value: random sign and mantissa times 10**(-30..30) (Park-Miller generator).
   real(wp) function adv(st)
      integer(int64), intent(inout) :: st
      real(wp) :: u(3)
      integer :: i
      do i = 1, 3
         st = modulo(16807_int64*st, 2147483647_int64)
         u(i) = real(st, wp)/2147483647.0_wp
      end do
      adv = merge(1.0_wp, -1.0_wp, u(1) < 0.5_wp)*(1.0_wp + u(2))*10.0_wp**(int(61.0_wp*u(3)) - 30)
   end function adv

   logical function same(a, b)
      integer, intent(in) :: a(:), b(:)
      same = size(a) == size(b)
      if (same) same = all(a == b)
   end function same

   function rs(x) result(s)
      real(wp), intent(in) :: x
      character(16) :: s
      write(s, '(f8.4)') x
   end function rs

   !> BCs and loads restricted to ranks: an SPC on every rank holding its node; each segment
   !> load on exactly one rank, which holds all its nodes.
   subroutine test_bcs_on_ranks()
      integer, allocatable :: conn(:, :), ewgt(:), gp(:), ge(:), cnt(:)
      type(partition_t) :: part
      type(rank_part_t) :: rp
      type(model_t) :: model
      integer :: nn, r, k, n, e, np
      logical :: ok
      write(*, '(a)') 'boundary conditions and loads on ranks'
      np = 3
      call box(6, 6, 6, conn, nn)
      allocate(ewgt(size(conn, 2)), gp(1), ge(0))
      ewgt = 1
      gp = 1
      call partition_elements(conn, nn, ewgt, gp, ge, np, part, error)
      allocate(model%spcs(nn), model%seg_loads(36))
      do n = 1, nn
         model%spcs(n)%node = n
      end do
      do e = 1, 36     ! the bottom faces (z = 0) of the bottom layer
         model%seg_loads(e)%nodes = conn([4, 3, 2, 1], e)
      end do
      allocate(cnt(36))
      cnt = 0
      ok = .true.
      k = 0
      do r = 0, np - 1
         call rank_part(model, part, r, rp, error)
         k = k + size(rp%spcs)
         if (.not. all(rp%nodes(:) == model%spcs(rp%spcs)%node)) ok = .false.
         do e = 1, size(rp%seg_loads)
            cnt(rp%seg_loads(e)) = cnt(rp%seg_loads(e)) + 1
            do n = 1, 4
               if (findloc(rp%nodes, model%seg_loads(rp%seg_loads(e))%nodes(n), dim=1) == 0) &
                  ok = .false.
            end do
         end do
      end do
      call check(k == sum(part%rank_nn) .and. ok, &
                 'an SPC is on every rank holding its node; segment nodes on their rank')
      call check(all(cnt == 1), 'each of 36 segment loads computed by exactly one rank')
   end subroutine test_bcs_on_ranks

   !> Rank files of a real deck: round trip, and every error path.
   subroutine test_rank_files()
      character(*), parameter :: DECK = 'tests/regression/elastic_wave/deck.k'
      character(*), parameter :: DECK2 = 'tests/regression/taylor_simo/deck.k'
      type(model_input_t) :: inp
      type(model_t) :: model
      type(partition_t) :: part
      type(rank_part_t) :: rp, back
      character(16) :: hash, hash2, hash_again
      integer :: r, np, gp(1), ge(0)
      integer, allocatable :: seen_spc(:), seen_pm(:)
      logical :: ok, ok2
      character(:), allocatable :: path, msg
      integer :: bad, nbad
      write(*, '(a)') 'rank files'
      ok2 = .true.
      bad = 0
      nbad = 0
      np = 3
      call read_deck_input(DECK, inp, error)
      call check(.not. allocated(error), 'read '//DECK)
      if (allocated(error)) return
      call build_model_data(inp, model, error)
      call deck_content_hash(inp%files, hash, error)
      call deck_content_hash(inp%files, hash_again, error)
      call check(hash == hash_again, 'deck content hash is reproducible')
      block
         type(model_input_t) :: inp2
         call read_deck_input(DECK2, inp2, error)
         call deck_content_hash(inp2%files, hash2, error)
      end block
      call check(hash /= hash2, 'two decks have different content hashes')
      gp = 1
      call partition_model(model, np, gp, ge, part, error)
      call check(.not. allocated(error), 'partition '//DECK//' into 3')
      ok = .true.
      allocate(seen_spc(size(model%spcs)), seen_pm(size(model%prescribed)))
      seen_spc = 0
      seen_pm = 0
      do r = 0, np - 1
         call rank_part(model, part, r, rp, error)
         seen_spc(rp%spcs) = 1
         seen_pm(rp%prescribed) = 1
         path = rank_file_name(TMP, r)
         call write_rank_file(path, rp, hash, error)
         if (allocated(error)) then
            ok = .false.
            cycle
         end if
         call read_rank_file(path, hash, np, r, back, error)
         if (allocated(error)) then
            ok = .false.
            cycle
         end if
         ok = ok .and. same(back%elements, rp%elements) .and. same(back%nodes, rp%nodes) &
            .and. same(back%node_owner, rp%node_owner) .and. same(back%nbr, rp%nbr) &
            .and. same(back%nbr_ptr, rp%nbr_ptr) .and. same(back%nbr_nodes, rp%nbr_nodes) &
            .and. same(back%spcs, rp%spcs) .and. same(back%prescribed, rp%prescribed) &
            .and. same(back%node_loads, rp%node_loads) .and. same(back%seg_loads, rp%seg_loads)&
            .and. same(back%wall_ptr, rp%wall_ptr) .and. same(back%wall_nodes, rp%wall_nodes) &
            .and. same(back%hist_nodes, rp%hist_nodes) .and. back%rank == r &
            .and. back%np == np .and. back%ne_global == model%ne &
            .and. back%nn_global == model%nn
         ! format 2: the sub-model, bit for bit, and the one built from it = the cut
         ok2 = ok2 .and. same(back%node_label, rp%node_label) .and. &
            same(back%piece_ptr, rp%piece_ptr) .and. same(back%piece_elem, rp%piece_elem) &
            .and. same(back%piece_pos, rp%piece_pos) .and. &
            same(reshape(back%pieces, [size(back%pieces)]), reshape(rp%pieces, [size(rp%pieces)])) &
            .and. all(shape(back%piece_conn) == shape(rp%piece_conn)) .and. &
            same(reshape(back%piece_conn, [size(back%piece_conn)]), &
                 reshape(rp%piece_conn, [size(rp%piece_conn)])) .and. &
            same(transfer(back%x0, [0]), transfer(model%x0(:, rp%nodes), [0])) .and. &
            same(transfer(back%v0, [0]), transfer(model%v0(:, rp%nodes), [0])) .and. &
            size(back%piece_elem) == size(rp%elements)
         call par_model_verify(model, back, msg)
         ok2 = ok2 .and. len(msg) == 0
         ! a sub-model that is not the cut is found, naming what differs: an element's
         ! serial position (its order key), a corner node, a coordinate's last bit
         if (size(back%piece_pos) > 1) then
            back%piece_pos([1, 2]) = back%piece_pos([2, 1])
            call par_model_verify(model, back, msg)
            bad = bad + merge(1, 0, index(msg, 'serial positions') > 0)
            back%piece_pos([1, 2]) = back%piece_pos([2, 1])
            back%piece_conn([1, 2], 1) = back%piece_conn([2, 1], 1)
            call par_model_verify(model, back, msg)
            bad = bad + merge(1, 0, index(msg, 'connectivity') > 0 .or. index(msg, 'keys') > 0 &
                              .or. index(msg, 'slot') > 0)
            back%piece_conn([1, 2], 1) = back%piece_conn([2, 1], 1)
            back%x0(1, 1) = nearest(back%x0(1, 1), 1.0_wp)
            call par_model_verify(model, back, msg)
            bad = bad + merge(1, 0, msg == 'initial coordinates')
            back%x0(1, 1) = nearest(back%x0(1, 1), -1.0_wp)
            nbad = nbad + 3
         end if
         if (size(back%pm_real, 2) > 0) then    ! a prescribed motion's scale, one ulp
            back%pm_real(1, 1) = nearest(back%pm_real(1, 1), 1.0_wp)
            call par_model_verify(model, back, msg)
            bad = bad + merge(1, 0, msg == 'prescribed-motion record 1')
            back%pm_real(1, 1) = nearest(back%pm_real(1, 1), -1.0_wp)
            nbad = nbad + 1
         end if
         if (size(back%spc_rec, 2) > 0) then    ! an SPC's DOF flag
            back%spc_rec(2, 1) = 1 - back%spc_rec(2, 1)
            call par_model_verify(model, back, msg)
            bad = bad + merge(1, 0, msg == 'SPC record 1')
            nbad = nbad + 1
         end if
      end do
      call check(ok, 'rank files round-trip (all 13 arrays and the header, 3 ranks)')
      call check(ok2, 'format 2: the sub-model round-trips bit for bit and the sub-model '// &
                 'built from each file equals the cut (par_model_verify)')
      call check(nbad > 0 .and. bad == nbad, 'par_model_verify finds a swapped serial '// &
                 'position, a swapped corner, a one-ulp coordinate, a one-ulp prescribed-motion '// &
                 'scale and a flipped SPC flag ('//str(bad)//' of '// &
                 str(nbad)//')')
      call check(size(seen_spc) > 0 .and. all(seen_spc == 1) .and. size(seen_pm) > 0 .and. &
                 all(seen_pm == 1), 'every SPC and prescribed motion of the deck is on a rank')
      path = rank_file_name(TMP, 1)
      call read_rank_file(path, hash, 2, 1, back, error)
      call check(has_error(EXIT_INPUT, path, 'NP = 3'), 'another NP: exit 2, file named')
      call read_rank_file(path, hash2, np, 1, back, error)
      call check(has_error(EXIT_INPUT, path, 'another deck'), 'another deck: exit 2, file named')
      call read_rank_file(path, hash, np, 2, back, error)
      call check(has_error(EXIT_INPUT, path, 'holds rank 1'), 'another rank: exit 2, file named')
      call read_rank_file(TMP//'/rank_missing.h5', hash, np, 1, back, error)
      call check(has_error(EXIT_IO, TMP//'/rank_missing.h5', 'no such file'), &
                 'missing file: exit 4, file named')
      call corrupt_elements(path, back_elements_of(path, hash, np))
      call read_rank_file(path, hash, np, 1, back, error)
      call check(has_error(EXIT_IO, path, 'checksum'), 'one flipped payload byte: exit 4 '// &
                 '(checksum), file named')
   end subroutine test_rank_files

   function back_elements_of(path, hash, np) result(el)
      character(*), intent(in) :: path, hash
      integer, intent(in) :: np
      integer, allocatable :: el(:)
      type(rank_part_t) :: b
      call read_rank_file(path, hash, np, 1, b, error)
      el = b%elements
   end function back_elements_of

   logical function has_error(code, path, text)
      integer, intent(in) :: code
      character(*), intent(in) :: path, text
      has_error = allocated(error)
      if (.not. has_error) return
      write(*, '(a)') '    ('//error%message//')'
      has_error = error%code == code .and. index(error%message, path) > 0 .and. &
                  index(error%message, text) > 0
   end function has_error

   !> Flip one bit inside the stored /elements data: find its first three values as
   !> little-endian int32 bytes in the file and change the middle value.
   subroutine corrupt_elements(path, el)
      character(*), intent(in) :: path
      integer, intent(in) :: el(:)
      integer(int8), allocatable :: buf(:), pat(:)
      integer :: u, i, j, k, b
      integer(int64) :: sz
      logical :: found
      allocate(pat(12))
      do k = 1, 3
         do j = 0, 3
            b = iand(ishft(el(k), -8*j), 255)
            if (b > 127) b = b - 256
            pat(4*(k - 1) + j + 1) = int(b, int8)
         end do
      end do
      open(newunit=u, file=path, access='stream', form='unformatted', status='old')
      inquire(unit=u, size=sz)
      allocate(buf(sz))
      read(u) buf
      found = .false.
      do i = 1, int(sz) - 11
         if (all(buf(i:i + 11) == pat)) then
            b = int(buf(i + 4))
            b = ieor(b, 1)
            buf(i + 4) = int(b, int8)
            found = .true.
            exit
         end if
      end do
      call check(found, 'found the /elements payload in '//path)
      write(u, pos=1) buf
      close(u)
   end subroutine corrupt_elements
   !> More ranks than graph vertices (issue 6: one-element decks at NP 2-4, a contact pair
   !> holding the model): no METIS call, one vertex per rank in vertex order, the other ranks
   !> empty (no elements, no nodes, no neighbours), and the report names them. Hand counts:
   !> two elements sharing a face (4 nodes) on 4 ranks; a 3x3x3 box with elements 1..26 in
   !> one group (2 vertices) on 3 ranks: the corner element 27 touches its 7 neighbours by
   !> 3 faces, 3 edges and 1 corner, 3*4 + 3*2 + 1 = 19 shared node slots = the edge cut.
   subroutine test_more_ranks_than_elements()
      integer, allocatable :: conn(:, :), ewgt(:)
      type(partition_t) :: part
      type(rank_part_t) :: rp
      type(model_t) :: empty
      integer :: nn, r, u, ios
      character(200) :: line
      logical :: found
      write(*, '(a)') 'more ranks than elements: direct assignment, empty ranks'
      call box(2, 1, 1, conn, nn)
      ewgt = [1, 1]
      call partition_elements(conn, nn, ewgt, [1], [integer ::], 4, part, error)
      call check(.not. allocated(error), '2 elements on 4 ranks: no error')
      if (allocated(error)) return
      call check(all(part%epart == [0, 1]), '2 elements on 4 ranks: element e on rank e - 1')
      call check(all(part%rank_ne == [1, 1, 0, 0]) .and. all(part%rank_nn == [8, 8, 0, 0]) &
                 .and. all(part%rank_nshared == [4, 4, 0, 0]), &
                 '2 elements on 4 ranks: elements 1 1 0 0, nodes 8 8 0 0, shared 4 4 0 0')
      call check(part%edgecut == 4, '2 elements on 4 ranks: edge cut 4 (one face)')
      call check_close(part%balance, 2.0_wp, 0.0_wp, 1.0e-15_wp, &
                       '2 elements on 4 ranks: balance max/mean = 1/(2/4) = 2')
      do r = 2, 3
         call rank_part(empty, part, r, rp, error)
         call check(.not. allocated(error) .and. size(rp%elements) == 0 .and. &
                    size(rp%nodes) == 0 .and. size(rp%nbr) == 0 .and. &
                    size(rp%nbr_nodes) == 0, '2 elements on 4 ranks: rank '//achar(48 + r)// &
                    ' holds no element, node or neighbour')
      end do
      call rank_part(empty, part, 1, rp, error)
      call check(size(rp%elements) == 1 .and. size(rp%nodes) == 8 .and. &
                 all(rp%nbr == [0]) .and. size(rp%nbr_nodes) == 4, &
                 '2 elements on 4 ranks: rank 1 holds element 2, 8 nodes, 4 shared with rank 0')
      open(newunit=u, file=TMP//'/report_empty.txt', status='replace', action='readwrite')
      call write_report(u, part, 'two.k', '0123456789ABCDEF')
      rewind(u)
      found = .false.
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (trim(line) == 'empty ranks (no elements): 2 of 4: 2-3') found = .true.
      end do
      close(u)
      call check(found, 'report line "empty ranks (no elements): 2 of 4: 2-3"')
      call box(1, 1, 1, conn, nn)
      call partition_elements(conn, nn, [8], [1], [integer ::], 3, part, error)
      call check(.not. allocated(error) .and. all(part%epart == [0]) .and. &
                 all(part%rank_ne == [1, 0, 0]) .and. part%edgecut == 0, &
                 '1 element on 3 ranks: on rank 0, ranks 1-2 empty, no cut')
      call box(3, 3, 3, conn, nn)
      deallocate(ewgt)
      allocate(ewgt(27))
      ewgt = 1
      call partition_elements(conn, nn, ewgt, [1, 27], [(r, r = 1, 26)], 3, part, error)
      call check(.not. allocated(error), '27 elements in 2 vertices on 3 ranks: no error')
      if (allocated(error)) return
      call check(all(part%epart(1:26) == 0) .and. part%epart(27) == 1 .and. &
                 all(part%rank_ne == [26, 1, 0]), &
                 '27 elements in 2 vertices on 3 ranks: group on rank 0, element 27 on 1, 2 empty')
      call check(part%edgecut == 19, '27 elements in 2 vertices on 3 ranks: edge cut 19')
   end subroutine test_more_ranks_than_elements
   !> Proximity edges (automatic contact): 64 separate unit hexes on a 4 x 4 x 4 lattice of
   !> pitch 1.5 (gap 0.5) are 64 components for METIS. With the node coordinates the
   !> partitioner joins lattice neighbours (centroids within 3 x the element extent) and
   !> NP = 2 cuts the lattice like one body: a plane cuts 16 of the 144 face-neighbour pairs;
   !> checked: at most 24 cut, every rank holds 32 +- 2 bodies, no node shared, 64
   !> components found, the proximity pairs reported, reproducible.
   subroutine test_proximity_edges()
      integer, allocatable :: conn(:, :), ewgt(:), gp(:), ge(:)
      real(wp), allocatable :: x(:, :)
      type(partition_t) :: part, part2
      integer :: i, j, k, e, n, ncut, a, b
      integer, parameter :: corner(3, 8) = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, &
                                                   0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1], [3, 8])
      write(*, '(a)') 'proximity edges: 64 separate hexes on a lattice, NP = 2'
      allocate(conn(8, 64), x(3, 512), ewgt(64))
      ewgt = 1
      e = 0
      do k = 0, 3
         do j = 0, 3
            do i = 0, 3
               e = e + 1
               do n = 1, 8
                  conn(n, e) = 8*(e - 1) + n
                  x(:, 8*(e - 1) + n) = 1.5_wp*real([i, j, k], wp) + real(corner(:, n), wp)
               end do
            end do
         end do
      end do
      gp = [1]
      allocate(ge(0))
      call partition_elements(conn, 512, ewgt, gp, ge, 2, part, error, x)
      call check(.not. allocated(error), 'proximity: partition without error')
      if (allocated(error)) return
      call check(part%ncomp == 64, 'proximity: 64 separate bodies found (got '// &
                 str(part%ncomp)//')')
      call check(part%nprox > 0, 'proximity: proximity pairs added ('//str(part%nprox)//')')
      call check(all(part%rank_nshared == 0), 'proximity: no node shared between ranks')
      call check(abs(part%rank_ne(0) - 32) <= 2, 'proximity: 32 +- 2 bodies per rank (rank 0: '// &
                 str(part%rank_ne(0))//')')
      ncut = 0
      do a = 1, 64
         do b = a + 1, 64
            if (abs(norm2(x(:, 8*(a - 1) + 1) - x(:, 8*(b - 1) + 1)) - 1.5_wp) < 1.0e-9_wp .and. &
                part%epart(a) /= part%epart(b)) ncut = ncut + 1
         end do
      end do
      call check(ncut <= 24, 'proximity: lattice neighbours on different ranks <= 24 (a plane: '// &
                 '16; got '//str(ncut)//')')
      call partition_elements(conn, 512, ewgt, gp, ge, 2, part2, error, x)
      call check(all(part2%epart == part%epart), 'proximity: reproducible')
   end subroutine test_proximity_edges

   !> Whole serial blocks (dx_partition, BLOCKS_PER_RANK): a deck without contact groups and
   !> with at least 32 element blocks per rank is cut between blocks, never through one
   !> (each rank then runs full nv_chunk blocks), and stays balanced within 1.1: a
   !> 25 x 24 x 16 box of hex8 (9,600 elements, 75 blocks of 128; rows of 25 elements, so a
   !> block ends mid-row and an element cut across the rows would split blocks) at NP = 2.
   subroutine test_whole_blocks()
      character(*), parameter :: DECK = TMP//'/box_blocks.k'
      integer, parameter :: NP = 2, NX = 25, NY = 24, NZ = 16
      type(model_t) :: model
      type(model_input_t) :: inp
      type(partition_t) :: part
      integer :: b, nsplit, gp(1), ge(0), u, i, j, k, n1
      write(*, '(a)') 'whole serial blocks (25 x 24 x 16 box, NP = 2)'
      open(newunit=u, file=DECK, status='replace', action='write')
      write(u, '(a)') '*KEYWORD', '*CONTROL_TERMINATION', '       1.0        10', '*PART', 'box', &
         '         1         1         1', '*SECTION_SOLID', '         1         1', &
         '*MAT_ELASTIC', '         1    7.8E-6     210.0       0.3', '*NODE'
      do k = 0, NZ
         do j = 0, NY
            do i = 0, NX
               write(u, '(i8, 3f16.6)') 1 + i + (NX + 1)*(j + (NY + 1)*k), real(i, wp), &
                  real(j, wp), real(k, wp)
            end do
         end do
      end do
      write(u, '(a)') '*ELEMENT_SOLID'
      do k = 0, NZ - 1
         do j = 0, NY - 1
            do i = 0, NX - 1
               n1 = 1 + i + (NX + 1)*(j + (NY + 1)*k)
               write(u, '(10i8)') 1 + i + NX*(j + NY*k), 1, n1, n1 + 1, n1 + NX + 2, n1 + NX + 1, &
                  n1 + (NX + 1)*(NY + 1), n1 + 1 + (NX + 1)*(NY + 1), &
                  n1 + NX + 2 + (NX + 1)*(NY + 1), n1 + NX + 1 + (NX + 1)*(NY + 1)
            end do
         end do
      end do
      write(u, '(a)') '*END'
      close(u)
      call read_deck_input(DECK, inp, error)
      if (.not. allocated(error)) call build_model_data(inp, model, error)
      call check(.not. allocated(error), 'read and build '//DECK)
      if (allocated(error)) return
      call check(size(model%blocks) >= 32*NP, 'at least 32 blocks per rank: '// &
                 str(size(model%blocks)))
      gp = 1
      call partition_model(model, NP, gp, ge, part, error)
      call check(.not. allocated(error), 'partition_model')
      if (allocated(error)) return
      nsplit = 0
      do b = 1, size(model%blocks)
         associate (ep => part%epart(model%blocks(b)%elem(1:model%blocks(b)%nel)))
            if (any(ep /= ep(1))) nsplit = nsplit + 1
         end associate
      end do
      call check(nsplit == 0, 'no block split over ranks: '//str(nsplit))
      call check(part%balance <= 1.1_wp, 'balance <= 1.1')
      call check(all(part%rank_ne > 0), 'every rank has elements')
   end subroutine test_whole_blocks
end program test_partition
