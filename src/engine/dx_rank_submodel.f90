!> The rank's sub-model as its rank file carries it (issue 22, distributed memory, stage 1;
!> docs/history.md "Ranks from their rank files"): cut from the global model by dynx-part
!> (or by rank 0 when it partitions in the run), written and read by io/dx_rank_file, and
!> turned into the rank's par_model_t by dx_par_model%par_model_from_file without the global
!> model. The pieces are the rank's elements of each serial block, in serial block order and
!> serial position order: the order of the element kernels and of the fixed-order shared-node
!> sums (the idea of OpenRadioss /PARITH/ON; ParaDyn's per-rank files: Hoover et al., LLNL
!> Engineering Thrust Area Report FY97, article 4 of shared/seed).
module dx_rank_submodel
   use dx_model, only: model_t, MAX_NEN
   use dx_rank_part_types, only: rank_part_t
   implicit none
   private
   public :: rank_submodel_cut, rank_local_node

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
