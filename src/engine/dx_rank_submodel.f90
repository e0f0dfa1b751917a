!> The rank's sub-model as its rank file carries it (issue 22, distributed memory, stage 1;
!> docs/history.md "Ranks from their rank files"): cut from the global model by dynx-part
!> (or by rank 0 when it partitions in the run), written and read by io/dx_rank_file, and
!> turned into the rank's par_model_t by dx_par_model%par_model_from_file without the global
!> model. The pieces are the rank's elements of each serial block, in serial block order and
!> serial position order: the order of the element kernels and of the fixed-order shared-node
!> sums (the idea of OpenRadioss /PARITH/ON; ParaDyn's per-rank files: Hoover et al., LLNL
!> Engineering Thrust Area Report FY97, article 4 of shared/seed).
module dx_rank_submodel
   use dx_kinds, only: wp
   use dx_model, only: model_t, MAX_NEN, spc_t, prescribed_t, load_node_t
   use dx_rank_part_types, only: rank_part_t
   use dx_strings, only: str
   implicit none
   private
   public :: rank_submodel_cut, rank_local_node, rank_local_nodes, rank_spcs, rank_prescribed, &
             rank_node_loads, rank_records_verify

contains

   !> Fill rp's sub-model (x0, v0, node labels, pieces) from the global model for the
   !> elements rp%elements and nodes rp%nodes (set before); nothing when model is not built.
   subroutine rank_submodel_cut(model, rp)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(inout) :: rp
      logical, allocatable :: here(:)
      integer :: b, i, n, np, nen, m
      ! (a partition of a bare graph, without a built model, has no sub-model)
      if (.not. (allocated(model%x0) .and. allocated(model%v0) .and. &
                 allocated(model%node_label) .and. allocated(model%blocks))) return
      call cut_records(model, rp)
      rp%x0 = model%x0(:, rp%nodes)
      rp%v0 = model%v0(:, rp%nodes)
      rp%node_label = model%node_label(rp%nodes)
      allocate(here(model%ne))
      here = .false.
      here(rp%elements) = .true.
      np = 0
      do b = 1, size(model%blocks)
         associate (sb => model%blocks(b))
            if (any(here(sb%elem(1:sb%nel)))) np = np + 1
         end associate
      end do
      n = size(rp%elements)
      allocate(rp%pieces(3, np), rp%piece_ptr(np + 1), rp%piece_elem(n), rp%piece_pos(n), &
               rp%piece_conn(MAX_NEN, n))
      rp%piece_conn = 0
      rp%piece_ptr(1) = 1
      np = 0
      m = 0
      do b = 1, size(model%blocks)
         associate (sb => model%blocks(b))
            if (.not. any(here(sb%elem(1:sb%nel)))) cycle
            np = np + 1
            rp%pieces(:, np) = [b, sb%ipart, sb%etype]
            nen = size(sb%conn, 1)
            do i = 1, sb%nel
               if (.not. here(sb%elem(i))) cycle
               m = m + 1
               rp%piece_elem(m) = sb%elem(i)
               rp%piece_pos(m) = i
               rp%piece_conn(1:nen, m) = sb%conn(:, i)
            end do
            rp%piece_ptr(np + 1) = m + 1
         end associate
      end do
   end subroutine rank_submodel_cut

   !> The rank's SPC, prescribed-motion and nodal-load records (rp%spcs, rp%prescribed,
   !> rp%node_loads of the deck's lists) as flat integer and real arrays.
   subroutine cut_records(model, rp)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(inout) :: rp
      call encode_records(model%spcs(rp%spcs), model%prescribed(rp%prescribed), &
                          model%node_loads(rp%node_loads), rp%spc_rec, rp%pm_int, &
                          rp%pm_real, rp%nl_int, rp%nl_sf)
   end subroutine cut_records

   !> The rank file's layout of SPC (s), prescribed-motion (p) and nodal-load (l) records,
   !> their node numbers as they are: spc_rec (7, *) node and DOF flags; pm_int (4, *) node,
   !> dof, vad, curve and pm_real (6, *) sf, dir, death, birth; nl_int (3, *) node, dof,
   !> curve and nl_sf (*). The one encoding both the cut and dynx-part --verify use.
   subroutine encode_records(s, p, l, spc_rec, pm_int, pm_real, nl_int, nl_sf)
      type(spc_t), intent(in) :: s(:)
      type(prescribed_t), intent(in) :: p(:)
      type(load_node_t), intent(in) :: l(:)
      integer, allocatable, intent(out) :: spc_rec(:, :), pm_int(:, :), nl_int(:, :)
      real(wp), allocatable, intent(out) :: pm_real(:, :), nl_sf(:)
      integer :: k
      allocate(spc_rec(7, size(s)), pm_int(4, size(p)), pm_real(6, size(p)), &
               nl_int(3, size(l)), nl_sf(size(l)))
      do k = 1, size(s)
         spc_rec(:, k) = [s(k)%node, merge(1, 0, s(k)%dof)]
      end do
      do k = 1, size(p)
         pm_int(:, k) = [p(k)%node, p(k)%dof, p(k)%vad, p(k)%curve]
         pm_real(:, k) = [p(k)%sf, p(k)%dir, p(k)%death, p(k)%birth]
      end do
      nl_int = reshape([(l(k)%node, l(k)%dof, l(k)%curve, k = 1, size(l))], [3, size(l)])
      nl_sf = l%sf
   end subroutine encode_records

   !> The generic gather by global node of every record kind: the local numbers (positions
   !> in the rank's ascending node list nodes) of the global nodes gnode; 0 where the rank
   !> does not hold the node.
   pure function rank_local_nodes(nodes, gnode) result(loc)
      integer, intent(in) :: nodes(:), gnode(:)
      integer :: loc(size(gnode))
      integer :: k
      do k = 1, size(gnode)
         loc(k) = rank_local_node(nodes, gnode(k))
      end do
   end function rank_local_nodes

   !> The rank's SPCs from its file, on local node numbers (the rank's node list).
   function rank_spcs(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(spc_t), allocatable :: a(:)
      integer :: k
      allocate(a(size(rp%spc_rec, 2)))
      a%node = rank_local_nodes(rp%nodes, rp%spc_rec(1, :))
      do k = 1, size(a)
         a(k)%dof = rp%spc_rec(2:7, k) /= 0
      end do
   end function rank_spcs

   !> The rank's prescribed motions from its file, on local node numbers.
   function rank_prescribed(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(prescribed_t), allocatable :: a(:)
      integer :: k
      allocate(a(size(rp%pm_int, 2)))
      a%node = rank_local_nodes(rp%nodes, rp%pm_int(1, :))
      a%dof = rp%pm_int(2, :)
      a%vad = rp%pm_int(3, :)
      a%curve = rp%pm_int(4, :)
      a%sf = rp%pm_real(1, :)
      do k = 1, size(a)
         a(k)%dir = rp%pm_real(2:4, k)
      end do
      a%death = rp%pm_real(5, :)
      a%birth = rp%pm_real(6, :)
   end function rank_prescribed

   !> The rank's nodal point loads from its file, on local node numbers.
   function rank_node_loads(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(load_node_t), allocatable :: a(:)
      allocate(a(size(rp%nl_int, 2)))
      a%node = rank_local_nodes(rp%nodes, rp%nl_int(1, :))
      a%dof = rp%nl_int(2, :)
      a%curve = rp%nl_int(3, :)
      a%sf = rp%nl_sf
   end function rank_node_loads

   !> dynx-part --verify: the file's records, turned into the run's (local nodes) and back
   !> to global nodes through the rank's node list, against the deck's lists at the file's
   !> indices, in the file's encoding, bit for bit. msg: empty when equal.
   subroutine rank_records_verify(model, rp, msg)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      character(:), allocatable, intent(out) :: msg
      type(spc_t), allocatable :: s(:)
      type(prescribed_t), allocatable :: p(:)
      type(load_node_t), allocatable :: l(:)
      integer, allocatable :: as(:, :), api(:, :), ali(:, :), bs(:, :), bpi(:, :), bli(:, :)
      real(wp), allocatable :: apr(:, :), alr(:), bpr(:, :), blr(:)
      msg = ''
      s = rank_spcs(rp)
      p = rank_prescribed(rp)
      l = rank_node_loads(rp)
      if (size(s) /= size(rp%spcs) .or. size(p) /= size(rp%prescribed) .or. &
          size(l) /= size(rp%node_loads)) then
         msg = 'number of SPC, prescribed-motion or nodal-load records'
         return
      end if
      if (any(s%node < 1)) msg = 'SPC record '//str(findloc(s%node < 1, .true., 1))
      if (any(p%node < 1)) msg = 'prescribed-motion record '//str(findloc(p%node < 1, .true., 1))
      if (any(l%node < 1)) msg = 'nodal-load record '//str(findloc(l%node < 1, .true., 1))
      if (len(msg) > 0) return
      s%node = rp%nodes(s%node)
      p%node = rp%nodes(p%node)
      l%node = rp%nodes(l%node)
      call encode_records(s, p, l, as, api, apr, ali, alr)
      call encode_records(model%spcs(rp%spcs), model%prescribed(rp%prescribed), &
                          model%node_loads(rp%node_loads), bs, bpi, bpr, bli, blr)
      if (any(as /= bs)) then
         msg = 'SPC record '//str(first_col(any(as /= bs, 1)))
      else if (any(api /= bpi) .or. any(bits(apr) /= bits(bpr))) then
         msg = 'prescribed-motion record '//str(first_col(any(api /= bpi, 1) .or. &
                                                          any(bits(apr) /= bits(bpr), 1)))
      else if (any(ali /= bli) .or. any(transfer(alr, 0_8, size(alr)) /= &
                                        transfer(blr, 0_8, size(blr)))) then
         msg = 'nodal-load record '//str(first_col(any(ali /= bli, 1) .or. &
               transfer(alr, 0_8, size(alr)) /= transfer(blr, 0_8, size(blr))))
      end if
   contains
      !> The bit patterns of a (6, n) table of doubles.
      function bits(a) result(b)
         real(wp), intent(in) :: a(:, :)
         integer(8) :: b(size(a, 1), size(a, 2))
         b = reshape(transfer(a, 0_8, size(a)), shape(a))
      end function bits
      integer function first_col(d)
         logical, intent(in) :: d(:)
         first_col = findloc(d, .true., 1)
      end function first_col
   end subroutine rank_records_verify

   !> Position of global node n in the ascending list nodes (0: absent); binary search.
   pure integer function rank_local_node(nodes, n) result(k)
      integer, intent(in) :: nodes(:), n
      integer :: lo, hi, mid
      k = 0
      lo = 1
      hi = size(nodes)
      do while (lo <= hi)
         mid = (lo + hi)/2
         if (nodes(mid) == n) then
            k = mid
            return
         else if (nodes(mid) < n) then
            lo = mid + 1
         else
            hi = mid - 1
         end if
      end do
   end function rank_local_node
end module dx_rank_submodel
