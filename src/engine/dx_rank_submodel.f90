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
   public :: rank_submodel_cut, rank_local_node, rank_spcs, rank_prescribed, rank_node_loads, &
             rank_records_verify

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
      integer :: k
      allocate(rp%spc_rec(7, size(rp%spcs)), rp%pm_int(4, size(rp%prescribed)), &
               rp%pm_real(6, size(rp%prescribed)), rp%nl_int(3, size(rp%node_loads)), &
               rp%nl_sf(size(rp%node_loads)))
      do k = 1, size(rp%spcs)
         associate (c => model%spcs(rp%spcs(k)))
            rp%spc_rec(:, k) = [c%node, merge(1, 0, c%dof)]
         end associate
      end do
      do k = 1, size(rp%prescribed)
         associate (c => model%prescribed(rp%prescribed(k)))
            rp%pm_int(:, k) = [c%node, c%dof, c%vad, c%curve]
            rp%pm_real(:, k) = [c%sf, c%dir, c%death, c%birth]
         end associate
      end do
      do k = 1, size(rp%node_loads)
         associate (c => model%node_loads(rp%node_loads(k)))
            rp%nl_int(:, k) = [c%node, c%dof, c%curve]
            rp%nl_sf(k) = c%sf
         end associate
      end do
   end subroutine cut_records

   !> The rank's SPCs from its file, on local node numbers (the rank's node list).
   function rank_spcs(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(spc_t), allocatable :: a(:)
      integer :: k
      allocate(a(size(rp%spc_rec, 2)))
      do k = 1, size(a)
         a(k)%node = rank_local_node(rp%nodes, rp%spc_rec(1, k))
         a(k)%dof = rp%spc_rec(2:7, k) /= 0
      end do
   end function rank_spcs

   !> The rank's prescribed motions from its file, on local node numbers.
   function rank_prescribed(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(prescribed_t), allocatable :: a(:)
      integer :: k
      allocate(a(size(rp%pm_int, 2)))
      do k = 1, size(a)
         a(k)%node = rank_local_node(rp%nodes, rp%pm_int(1, k))
         a(k)%dof = rp%pm_int(2, k)
         a(k)%vad = rp%pm_int(3, k)
         a(k)%curve = rp%pm_int(4, k)
         a(k)%sf = rp%pm_real(1, k)
         a(k)%dir = rp%pm_real(2:4, k)
         a(k)%death = rp%pm_real(5, k)
         a(k)%birth = rp%pm_real(6, k)
      end do
   end function rank_prescribed

   !> The rank's nodal point loads from its file, on local node numbers.
   function rank_node_loads(rp) result(a)
      type(rank_part_t), intent(in) :: rp
      type(load_node_t), allocatable :: a(:)
      integer :: k
      allocate(a(size(rp%nl_int, 2)))
      do k = 1, size(a)
         a(k)%node = rank_local_node(rp%nodes, rp%nl_int(1, k))
         a(k)%dof = rp%nl_int(2, k)
         a(k)%curve = rp%nl_int(3, k)
         a(k)%sf = rp%nl_sf(k)
      end do
   end function rank_node_loads

   !> dynx-part --verify: the file's records, turned into the run's (local nodes), against
   !> the deck's lists at the file's indices, bit for bit. msg: empty when equal.
   subroutine rank_records_verify(model, rp, msg)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      character(:), allocatable, intent(out) :: msg
      type(spc_t), allocatable :: s(:)
      type(prescribed_t), allocatable :: p(:)
      type(load_node_t), allocatable :: l(:)
      integer :: k
      msg = ''
      s = rank_spcs(rp)
      p = rank_prescribed(rp)
      l = rank_node_loads(rp)
      if (size(s) /= size(rp%spcs) .or. size(p) /= size(rp%prescribed) .or. &
          size(l) /= size(rp%node_loads)) then
         msg = 'number of SPC, prescribed-motion or nodal-load records'
         return
      end if
      do k = 1, size(s)
         associate (g => model%spcs(rp%spcs(k)))
            if (rp%nodes(max(1, s(k)%node)) /= g%node .or. s(k)%node < 1 .or. &
                any(s(k)%dof .neqv. g%dof)) msg = 'SPC record '//str(k)
         end associate
      end do
      do k = 1, size(p)
         associate (g => model%prescribed(rp%prescribed(k)))
            if (p(k)%node < 1) then
               msg = 'prescribed-motion record '//str(k)
            else if (rp%nodes(p(k)%node) /= g%node .or. p(k)%dof /= g%dof .or. &
                p(k)%vad /= g%vad .or. p(k)%curve /= g%curve .or. &
                .not. same(p(k)%sf, g%sf) .or. .not. same(p(k)%death, g%death) .or. &
                .not. same(p(k)%birth, g%birth) .or. .not. all(transfer(p(k)%dir, [0]) == &
                transfer(g%dir, [0]))) then
               msg = 'prescribed-motion record '//str(k)
            end if
         end associate
      end do
      do k = 1, size(l)
         associate (g => model%node_loads(rp%node_loads(k)))
            if (l(k)%node < 1) then
               msg = 'nodal-load record '//str(k)
            else if (rp%nodes(l(k)%node) /= g%node .or. l(k)%dof /= g%dof .or. &
                l(k)%curve /= g%curve .or. .not. same(l(k)%sf, g%sf)) then
               msg = 'nodal-load record '//str(k)
            end if
         end associate
      end do
   contains
      logical function same(a, b)
         real(wp), intent(in) :: a, b
         same = transfer(a, 0_8) == transfer(b, 0_8)
      end function same
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
