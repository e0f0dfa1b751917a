!> Domain decomposition for ParaDyn-style runs: "Parallel contact in ParaDyn", LLNL
!> Engineering Thrust Area Report FY97, Computational Mechanics (article 4 of
!> shared/seed/000_ada67627fd8120d3.txt: element graph, super elements for contact pairs,
!> balance statistic); graph partitioning with METIS (Karypis and Kumar, SIAM J. Sci.
!> Comput. 20(1), 1998).
!>
!> The element graph: one vertex per element, weighted by the element formulation's measured
!> cost (the element family's weight; docs/history.md), one edge between two elements that
!> share at least one node (METIS_MeshToDual with ncommon = 1), weighted by the number of
!> nodes they share. Elements that share only an edge or a corner still put that node on two
!> ranks, so they cost communication too; the face-only dual graph (ncommon = 4) would not
!> see that cost.
!> Groups of elements that must stay on one rank (contact surface pairs) are condensed into
!> one super vertex whose weight is the sum of its elements' weights (the number of elements
!> condensed, times their cost) and whose edge weights sum the node connectivity of its
!> elements. Overlapping groups are merged (union-find).
!> From the element partition: nodes per rank, the owner of each node (the lowest rank
!> holding it), shared-node lists per pair of ranks (symmetric by construction), and the
!> balance statistic max(rank weight)/mean(rank weight) (1.0 = perfect).
!> The graph itself (condensed groups, node-sharing and proximity edges) is dx_partition_graph.
!> Whole serial blocks: a deck without contact groups and with at least BLOCKS_PER_RANK
!> element blocks per rank is partitioned with each serial block (nv_chunk elements of one
!> part, the unit of the element pass) condensed into one vertex, so every rank's block
!> pieces are whole blocks: an element cut through the blocks (a box cut across its rows
!> leaves every block half on each rank) makes each rank run twice the blocks at half length,
!> measured 14 % more element-pass time per element at NP 2 (docs/scaling.md). Results do not
!> depend on the partition (fixed-order sums), only the time does.
module dx_partition
   use dx_kinds, only: wp, nv_chunk
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_model, only: model_t, family_t, element_family, etype_of_elform, MAX_NEN
   use dx_element_types, only: ETYPE_SHELL_BT
   use dx_metis, only: metis_part_kway, METIS_RECURSIVE
   use dx_contact_input, only: CT_SINGLE_SURFACE
   use dx_rank_part_types, only: rank_part_t   ! what one rank holds (re-exported)
   use dx_rank_submodel, only: rank_submodel_cut
   use dx_partition_graph, only: node_elements, condense_groups, element_graph, &
                                 add_proximity_edges, sort_int
   implicit none
   private
   public :: partition_t, rank_part_t, element_graph, condense_groups, partition_model, has_shells, &
             partition_elements, rank_part, elem_costs, serial_order, write_report, face_elements, &
             model_conn, scatter_keys, COST_RIGID, RIGID_SCALE

   !> Element cost weights (integer, METIS needs integers): the element family's weight
   !> (dx_element_types: ELFORM 2 measured at about 8x ELFORM 1 per element-cycle;
   !> docs/history.md, "Partition weights").
   !> Elements of *MAT_RIGID parts have no stress update (the element pass skips them): in a
   !> deck that has them the deformable weights are scaled by RIGID_SCALE and a rigid
   !> element weighs COST_RIGID, i.e. 1/4 of ELFORM 1 (measured 0.27-0.34 serially, which
   !> includes the rigid-body solver that an MPI run repeats on every rank whatever the
   !> partition; docs/history.md, "Rigid bodies and loads under MPI"). Decks without rigid
   !> parts keep the weights above (and their partitions).
   integer, parameter :: RIGID_SCALE = 4, COST_RIGID = 1
   !> fewest serial blocks per rank for whole-block vertices (a rank's weight in steps of
   !> 1/32 at worst, within METIS's 3 % tolerance on the box decks)
   integer, parameter :: BLOCKS_PER_RANK = 32

   !> A partition of the whole model.
   type :: partition_t
      integer :: np = 1
      integer :: ne = 0, nn = 0
      integer :: edgecut = 0
      logical :: direct = .false.            !< fewer vertices than ranks: one per rank, no METIS
      integer, allocatable :: epart(:)       !< (ne) rank of each element, 0..np-1
      integer, allocatable :: ewgt(:)        !< (ne) element cost weight
      integer, allocatable :: node_owner(:)  !< (nn) lowest rank holding the node
      integer, allocatable :: rank_wgt(:)    !< (0:np-1) summed element weight
      integer :: wscale = 1                  !< RIGID_SCALE when the deck has rigid elements
      integer :: wshell = 0                  !< the shell family's weight (0: no shells)
      integer, allocatable :: rank_ne(:), rank_nn(:), rank_nshared(:)   !< (0:np-1)
      real(wp) :: balance = 1.0_wp           !< max(rank_wgt) / mean(rank_wgt)
      ! node -> ranks holding it (CSR over nodes; ranks ascending)
      integer, allocatable :: nr_ptr(:), nr_rank(:)
      integer :: ncomp = 0                   !< connected components of the vertex graph
      integer :: nprox = 0                   !< proximity edges added (vertex pairs)
   end type partition_t

contains

   !> Cost weight of every element from its formulation.
   subroutine elem_costs(model, ewgt)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: ewgt(:)
      integer :: ib, sc
      logical :: rig
      type(family_t) :: fam
      allocate(ewgt(model%ne))
      sc = 1
      if (has_rigid_elements(model)) sc = RIGID_SCALE
      do ib = 1, size(model%blocks)
         associate (b => model%blocks(ib))
            rig = model%mats(model%parts(b%ipart)%imat)%m%is_rigid
            if (rig) then
               ewgt(b%elem) = COST_RIGID
            else
               fam = element_family(b%etype)
               ewgt(b%elem) = sc*fam%weight
            end if
         end associate
      end do
   end subroutine elem_costs

   !> True when some element block belongs to a *MAT_RIGID part.
   logical function has_rigid_elements(model)
      type(model_t), intent(in) :: model
      integer :: ib
      has_rigid_elements = .false.
      do ib = 1, size(model%blocks)
         if (model%mats(model%parts(model%blocks(ib)%ipart)%imat)%m%is_rigid) &
            has_rigid_elements = .true.
      end do
   end function has_rigid_elements

   !> Position of each element in the serial scatter order (blocks in order, elements in
   !> block order): the order in which the serial run adds element forces into a node.
   subroutine serial_order(model, seq)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: seq(:)
      integer :: ib, k, n
      allocate(seq(model%ne))
      n = 0
      do ib = 1, size(model%blocks)
         do k = 1, model%blocks(ib)%nel
            n = n + 1
            seq(model%blocks(ib)%elem(k)) = n
         end do
      end do
   end subroutine serial_order

   !> Partition elements with connectivity conn(nen, ne) over nn nodes into np ranks.
   !> ewgt: element weights; groups (CSR grp_ptr/grp_elem) stay whole on one rank.
   subroutine partition_elements(conn, nn, ewgt, grp_ptr, grp_elem, np, part, error, x)
      integer, intent(in) :: conn(:, :), nn, ewgt(:), grp_ptr(:), grp_elem(:), np
      type(partition_t), intent(out) :: part
      type(error_t), allocatable, intent(out) :: error
      !> node coordinates (3, nn), given for decks with automatic contact: separate bodies
      !> are joined by proximity edges (add_proximity_edges)
      real(wp), intent(in), optional :: x(:, :)
      integer, allocatable :: vtx(:), vwgt(:), xadj(:), adjncy(:), adjwgt(:), vpart(:)
      integer :: nv, ne, e, n, k, r, i, j, q
      integer, allocatable :: mark(:)
      ne = size(conn, 2)
      if (np < 1) then
         call set_error(error, 'number of ranks must be >= 1, got '//str(np), EXIT_INPUT)
         return
      end if
      part%np = np
      part%ne = ne
      part%nn = nn
      part%ewgt = ewgt
      allocate(part%epart(ne))
      if (np == 1) then
         part%epart = 0
      else
         call condense_groups(ne, ewgt, grp_ptr, grp_elem, vtx, nv, vwgt, error)
         if (allocated(error)) return
         call element_graph(conn, nn, vtx, nv, xadj, adjncy, adjwgt)
         if (present(x)) call add_proximity_edges(conn, x, vtx, nv, xadj, adjncy, adjwgt, &
                                                  part%ncomp, part%nprox)
         allocate(vpart(nv))
         if (nv < np) then
            ! more ranks than vertices (a one-element deck on 4 ranks; a contact pair holding
            ! most of the model): METIS needs nparts <= nvtxs, and the best partition is one
            ! vertex per rank, so vertex v goes to rank v - 1 and ranks nv..np-1 stay empty
            ! (allowed, as in LS-DYNA MPP and ParaDyn). Every edge is cut.
            vpart = [(i, i = 0, nv - 1)]
            part%edgecut = sum(adjwgt)/2
            part%direct = .true.
         else
            call metis_part_kway(nv, xadj, adjncy, vwgt, adjwgt, np, vpart, part%edgecut, error)
            if (allocated(error)) return
            ! k-way can leave ranks empty or unbalanced on small graphs; then recursive
            ! bisection is tried too and the partition with the lighter heaviest rank is kept
            if (max_weight(vpart, vwgt, np) > 1.1_wp*real(sum(vwgt), wp)/real(np, wp)) then
               block
                  integer, allocatable :: vpart2(:)
                  integer :: cut2
                  allocate(vpart2(nv))
                  call metis_part_kway(nv, xadj, adjncy, vwgt, adjwgt, np, vpart2, cut2, error, &
                                       METIS_RECURSIVE)
                  if (allocated(error)) return
                  if (max_weight(vpart2, vwgt, np) < max_weight(vpart, vwgt, np)) then
                     vpart = vpart2
                     part%edgecut = cut2
                  end if
               end block
            end if
            if (max_weight(vpart, vwgt, np) > 1.1_wp*real(sum(vwgt), wp)/real(np, wp)) &
               call rebalance(xadj, adjncy, adjwgt, vwgt, np, vpart)
         end if
         part%epart = vpart(vtx)
      end if
      ! ranks of each node (ascending, distinct); a node of no element goes to rank 0
      allocate(mark(0:np - 1))
      mark = 0
      allocate(part%nr_ptr(nn + 1))
      block
         integer, allocatable :: nptr(:), nlst(:), tmp(:)
         call node_elements(conn, nn, nptr, nlst)
         allocate(tmp(np))
         part%nr_ptr(1) = 1
         allocate(part%nr_rank(size(nlst) + nn))
         do n = 1, nn
            k = 0
            do i = nptr(n), nptr(n + 1) - 1
               r = part%epart(nlst(i))
               if (mark(r) /= n) then
                  mark(r) = n
                  k = k + 1
                  tmp(k) = r
               end if
            end do
            if (k == 0) then
               k = 1
               tmp(1) = 0
            end if
            call sort_int(tmp(1:k))
            part%nr_rank(part%nr_ptr(n):part%nr_ptr(n) + k - 1) = tmp(1:k)
            part%nr_ptr(n + 1) = part%nr_ptr(n) + k
         end do
         part%nr_rank = part%nr_rank(1:part%nr_ptr(nn + 1) - 1)
      end block
      allocate(part%node_owner(nn))
      allocate(part%rank_wgt(0:np - 1), part%rank_ne(0:np - 1), part%rank_nn(0:np - 1), &
               part%rank_nshared(0:np - 1))
      part%rank_wgt = 0; part%rank_ne = 0; part%rank_nn = 0; part%rank_nshared = 0
      do e = 1, ne
         part%rank_wgt(part%epart(e)) = part%rank_wgt(part%epart(e)) + ewgt(e)
         part%rank_ne(part%epart(e)) = part%rank_ne(part%epart(e)) + 1
      end do
      do n = 1, nn
         i = part%nr_ptr(n); j = part%nr_ptr(n + 1) - 1
         part%node_owner(n) = part%nr_rank(i)
         do k = i, j
            q = part%nr_rank(k)
            part%rank_nn(q) = part%rank_nn(q) + 1
            if (j > i) part%rank_nshared(q) = part%rank_nshared(q) + 1
         end do
      end do
      if (sum(part%rank_wgt) > 0) then
         part%balance = real(maxval(part%rank_wgt), wp)* &
                        real(np, wp)/real(sum(part%rank_wgt), wp)
      else
         part%balance = 1.0_wp
      end if
   end subroutine partition_elements

   !> Greedy repair of a partition METIS left above 1.1 x the mean weight (small graphs, where
   !> its 3 % tolerance cannot be met by its coarsening): repeatedly move one vertex from the
   !> heaviest rank to an adjacent rank that stays lighter than the heaviest one after the move,
   !> choosing the lightest such target and, among its candidates, the vertex with the largest
   !> gain (edge weight to the target minus edge weight kept at home). Stops when the heaviest
   !> rank is within 1.05 x the mean or no move lowers it. Deterministic (lowest index wins ties).
   subroutine rebalance(xadj, adjncy, adjwgt, vwgt, np, vpart)
      integer, intent(in) :: xadj(:), adjncy(:), adjwgt(:), vwgt(:), np
      integer, intent(inout) :: vpart(:)
      integer :: w(0:np - 1), conn(0:np - 1), v, k, h, q, it, best_v, best_q, best_gain, gain
      real(wp) :: target
      w = 0
      do v = 1, size(vpart)
         w(vpart(v)) = w(vpart(v)) + vwgt(v)
      end do
      target = 1.05_wp*real(sum(vwgt), wp)/real(np, wp)
      do it = 1, size(vpart)*np
         h = maxloc(w, 1) - 1
         if (real(w(h), wp) <= target) exit
         best_v = 0; best_q = -1; best_gain = -huge(1)
         do v = 1, size(vpart)
            if (vpart(v) /= h) cycle
            conn = 0
            do k = xadj(v) + 1, xadj(v + 1)
               conn(vpart(adjncy(k) + 1)) = conn(vpart(adjncy(k) + 1)) + adjwgt(k)
            end do
            do q = 0, np - 1
               if (q == h .or. conn(q) == 0) cycle
               if (w(q) + vwgt(v) >= w(h)) cycle
               gain = conn(q) - conn(h)
               if (best_q < 0) then
                  best_v = v; best_q = q; best_gain = gain
               else if (w(q) < w(best_q) .or. (w(q) == w(best_q) .and. gain > best_gain)) then
                  best_v = v; best_q = q; best_gain = gain
               end if
            end do
         end do
         if (best_v == 0) exit
         w(h) = w(h) - vwgt(best_v)
         w(best_q) = w(best_q) + vwgt(best_v)
         vpart(best_v) = best_q
      end do
   end subroutine rebalance

   !> Heaviest rank weight of a vertex partition.
   integer function max_weight(vpart, vwgt, np) result(m)
      integer, intent(in) :: vpart(:), vwgt(:), np
      integer :: w(0:np - 1), v
      w = 0
      do v = 1, size(vpart)
         w(vpart(v)) = w(vpart(v)) + vwgt(v)
      end do
      m = maxval(w)
   end function max_weight


   !> The order key of every element force contribution (corner k, element e): the serial
   !> run adds them into f block by block, in the loop `do k = 1, nen; do i = 1, nel` of
   !> the element kernels, so key = ((block - 1)*MAX_NEN + k - 1)*nv_chunk + position in the
   !> block. Summing a node's contributions from 0 in key order gives the serial f bit for
   !> bit. Corners past the family's nen get key -1.
   subroutine scatter_keys(model, keys)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: keys(:, :)
      integer :: e, k
      allocate(keys(MAX_NEN, model%ne))
      keys = -1
      do e = 1, model%ne
         do k = 1, size(model%blocks(model%elem_block(e))%conn, 1)
            keys(k, e) = ((model%elem_block(e) - 1)*MAX_NEN + k - 1)*nv_chunk + &
                         model%elem_pos(e)
         end do
      end do
   end subroutine scatter_keys

   !> Connectivity conn(MAX_NEN, ne) of a built model, in global element order; an element
   !> of fewer nodes repeats its last node (as a degenerate solid's card does).
   subroutine model_conn(model, conn)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: conn(:, :)
      integer :: ib, nen, k
      allocate(conn(MAX_NEN, model%ne))
      do ib = 1, size(model%blocks)
         associate (b => model%blocks(ib))
            nen = size(b%conn, 1)
            conn(1:nen, b%elem) = b%conn
            do k = nen + 1, MAX_NEN
               conn(k, b%elem) = b%conn(nen, :)
            end do
         end associate
      end do
   end subroutine model_conn

   !> The elements having a face on a surface: for each segment seg(4, nseg) (dense nodes; a
   !> triangle repeats n3), every element holding all its nodes. Ascending, no repeats.
   !> A contact pair's group is face_elements of its master and slave segments together.
   subroutine face_elements(conn, nn, seg, elems)
      integer, intent(in) :: conn(:, :), nn, seg(:, :)
      integer, allocatable, intent(out) :: elems(:)
      integer, allocatable :: nptr(:), nlst(:)
      logical, allocatable :: take(:)
      integer :: s, i, e, j
      logical :: all_in
      call node_elements(conn, nn, nptr, nlst)
      allocate(take(size(conn, 2)))
      take = .false.
      do s = 1, size(seg, 2)
         ! candidates: the elements of the segment's first node
         do i = nptr(seg(1, s)), nptr(seg(1, s) + 1) - 1
            e = nlst(i)
            all_in = .true.
            do j = 2, 4
               if (.not. any(conn(:, e) == seg(j, s))) all_in = .false.
            end do
            if (all_in) take(e) = .true.
         end do
      end do
      elems = pack([(e, e = 1, size(conn, 2))], take)
   end subroutine face_elements

   !> Whether the model has a block of a family with rotations (shells, beams: the MPI engine
   !> then exchanges moments and rotary inertia beside the forces and masses).
   logical function has_shells(model)
      type(model_t), intent(in) :: model
      type(family_t) :: f
      integer :: b
      has_shells = .false.
      do b = 1, size(model%blocks)
         f = element_family(model%blocks(b)%etype)
         has_shells = has_shells .or. f%rot
      end do
   end function has_shells

   !> Partition a built model: connectivity and costs from its blocks.
   subroutine partition_model(model, np, grp_ptr, grp_elem, part, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: np, grp_ptr(:), grp_elem(:)
      type(partition_t), intent(out) :: part
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: conn(:, :), ewgt(:), gp(:), ge(:)
      type(family_t) :: fs
      integer :: ib
      call model_conn(model, conn)
      call elem_costs(model, ewgt)
      gp = grp_ptr
      ge = grp_elem
      if (size(grp_ptr) <= 1 .and. size(model%blocks) >= BLOCKS_PER_RANK*np) then
         ! whole serial blocks as vertices (header)
         deallocate(gp, ge)
         allocate(gp(size(model%blocks) + 1), ge(model%ne))
         gp(1) = 1
         do ib = 1, size(model%blocks)
            associate (b => model%blocks(ib))
               gp(ib + 1) = gp(ib) + b%nel
               ge(gp(ib):gp(ib + 1) - 1) = b%elem(1:b%nel)
            end associate
         end do
      end if
      if (has_auto_contact(model)) then   ! separate bodies joined by proximity edges
         call partition_elements(conn, model%nn, ewgt, gp, ge, np, part, error, model%x0)
      else
         call partition_elements(conn, model%nn, ewgt, gp, ge, np, part, error)
      end if
      if (has_rigid_elements(model)) part%wscale = RIGID_SCALE
      if (has_shells(model)) then
         fs = element_family(ETYPE_SHELL_BT)
         part%wshell = part%wscale*fs%weight
      end if
   end subroutine partition_model

   !> Whether the deck has an automatic or single-surface contact (split over the ranks by
   !> slave node, so the element partition decides where its contact work is).
   logical function has_auto_contact(model)
      type(model_t), intent(in) :: model
      integer :: i
      has_auto_contact = .false.
      if (.not. allocated(model%contact)) return
      do i = 1, size(model%contact%iface)
         if (model%contact%iface(i)%kind == CT_SINGLE_SURFACE .or. &
             index(model%contact%iface(i)%name, 'AUTOMATIC') > 0) has_auto_contact = .true.
      end do
   end function has_auto_contact

   !> What rank r holds: its elements and nodes, shared-node lists per neighbour, and the
   !> boundary conditions and loads on its nodes. A segment load is computed by the lowest
   !> rank holding all of its nodes (error if no rank holds them all).
   subroutine rank_part(model, part, r, rp, error)
      type(model_t), intent(in) :: model
      type(partition_t), intent(in) :: part
      integer, intent(in) :: r
      type(rank_part_t), intent(out) :: rp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: local(:), cnt(:)
      integer :: n, k, i, q, nl, w, j
      logical :: all_here
      rp%rank = r
      rp%np = part%np
      rp%ne_global = part%ne
      rp%nn_global = part%nn
      rp%elements = pack([(i, i = 1, part%ne)], part%epart == r)
      ! local(n): position of node n in this rank's node list (0: not here)
      allocate(local(part%nn))
      local = 0
      nl = 0
      do n = 1, part%nn
         if (any(part%nr_rank(part%nr_ptr(n):part%nr_ptr(n + 1) - 1) == r)) then
            nl = nl + 1
            local(n) = nl
         end if
      end do
      allocate(rp%nodes(nl), rp%node_owner(nl))
      do n = 1, part%nn
         if (local(n) > 0) then
            rp%nodes(local(n)) = n
            rp%node_owner(local(n)) = part%node_owner(n)
         end if
      end do
      ! shared-node lists: for each other rank q, the local nodes q holds too
      allocate(cnt(0:part%np - 1))
      cnt = 0
      do i = 1, nl
         n = rp%nodes(i)
         do k = part%nr_ptr(n), part%nr_ptr(n + 1) - 1
            q = part%nr_rank(k)
            if (q /= r) cnt(q) = cnt(q) + 1
         end do
      end do
      rp%nbr = pack([(q, q = 0, part%np - 1)], cnt > 0)
      allocate(rp%nbr_ptr(size(rp%nbr) + 1))
      rp%nbr_ptr(1) = 1
      do k = 1, size(rp%nbr)
         rp%nbr_ptr(k + 1) = rp%nbr_ptr(k) + cnt(rp%nbr(k))
      end do
      allocate(rp%nbr_nodes(rp%nbr_ptr(size(rp%nbr) + 1) - 1))
      do k = 1, size(rp%nbr)
         q = rp%nbr(k)
         j = rp%nbr_ptr(k)
         do i = 1, nl
            n = rp%nodes(i)
            if (any(part%nr_rank(part%nr_ptr(n):part%nr_ptr(n + 1) - 1) == q)) then
               rp%nbr_nodes(j) = n
               j = j + 1
            end if
         end do
      end do
      ! boundary conditions and loads restricted to the local nodes
      rp%spcs = [integer ::]
      rp%prescribed = [integer ::]
      rp%node_loads = [integer ::]
      rp%seg_loads = [integer ::]
      rp%hist_nodes = [integer ::]
      if (allocated(model%spcs)) &
         rp%spcs = pack([(k, k = 1, size(model%spcs))], local(model%spcs(:)%node) > 0)
      if (allocated(model%prescribed)) rp%prescribed = &
         pack([(k, k = 1, size(model%prescribed))], local(model%prescribed(:)%node) > 0)
      if (allocated(model%node_loads)) rp%node_loads = &
         pack([(k, k = 1, size(model%node_loads))], local(model%node_loads(:)%node) > 0)
      if (allocated(model%db%hist_nodes)) rp%hist_nodes = &
         pack([(k, k = 1, size(model%db%hist_nodes))], local(model%db%hist_nodes) > 0)
      if (allocated(model%seg_loads)) then
         do k = 1, size(model%seg_loads)
            associate (nd => model%seg_loads(k)%nodes)
               ! the lowest rank holding all the segment's nodes computes it
               q = -1
               do i = part%nr_ptr(nd(1)), part%nr_ptr(nd(1) + 1) - 1
                  all_here = .true.
                  do j = 2, 4
                     if (nd(j) <= 0) cycle      ! a 2-node edge of a 2D deck (N3 = 0, N4 <= 0)
                     if (.not. any(part%nr_rank(part%nr_ptr(nd(j)):part%nr_ptr(nd(j) + 1) - 1) &
                                   == part%nr_rank(i))) all_here = .false.
                  end do
                  if (all_here) then
                     q = part%nr_rank(i)
                     exit
                  end if
               end do
               if (q < 0) then
                  call set_error(error, '*LOAD_SEGMENT '//str(k)//': no rank holds all '// &
                     'its nodes (the segment is not the face of an element)', EXIT_INPUT)
                  return
               end if
               if (q == r) rp%seg_loads = [rp%seg_loads, k]
            end associate
         end do
      end if
      allocate(rp%wall_ptr(1))
      rp%wall_ptr(1) = 1
      rp%wall_nodes = [integer ::]
      if (allocated(model%walls)) then
         deallocate(rp%wall_ptr)
         allocate(rp%wall_ptr(size(model%walls) + 1))
         rp%wall_ptr(1) = 1
         do w = 1, size(model%walls)
            rp%wall_nodes = [rp%wall_nodes, pack(model%walls(w)%nodes, &
                                                 local(model%walls(w)%nodes) > 0)]
            rp%wall_ptr(w + 1) = size(rp%wall_nodes) + 1
         end do
      end if
      call rank_submodel_cut(model, rp)    ! the sub-model the rank file carries (format 2)
   end subroutine rank_part

   !> The partition report: elements, weight, nodes, shared nodes and neighbours per rank,
   !> the edge cut and the balance statistic max(weight)/mean(weight).
   subroutine write_report(unit, part, deck, hash)
      integer, intent(in) :: unit
      type(partition_t), intent(in) :: part
      character(*), intent(in) :: deck, hash
      integer :: r, n, k, nshared_total
      type(family_t) :: f1, f2
      integer, allocatable :: nnb(:)
      logical, allocatable :: adj(:, :)
      allocate(adj(0:part%np - 1, 0:part%np - 1), nnb(0:part%np - 1))
      adj = .false.
      nshared_total = 0
      do n = 1, part%nn
         if (part%nr_ptr(n + 1) - part%nr_ptr(n) > 1) nshared_total = nshared_total + 1
         do k = part%nr_ptr(n), part%nr_ptr(n + 1) - 1
            do r = part%nr_ptr(n), part%nr_ptr(n + 1) - 1
               if (r /= k) adj(part%nr_rank(k), part%nr_rank(r)) = .true.
            end do
         end do
      end do
      nnb = count(adj, dim=2)
      write(unit, '(a)') 'dynx-part: partition of '//deck//' (deck content hash '//hash//')'
      if (part%direct) then
         write(unit, '(a,i0,a,i0,a,i0,a)') 'ranks ', part%np, ', elements ', part%ne, &
            ', nodes ', part%nn, ' (fewer elements or contact groups than ranks: one per '// &
            'rank, no METIS)'
      else
         write(unit, '(a,i0,a,i0,a,i0,a)') 'ranks ', part%np, ', elements ', part%ne, &
            ', nodes ', part%nn, ' (element graph: elements sharing a node; METIS k-way)'
      end if
      f1 = element_family(etype_of_elform(1))
      f2 = element_family(etype_of_elform(2))
      if (part%wscale == 1) then
         write(unit, '(a,i0,a,i0,a)') 'element cost weights: ELFORM 1 = ', f1%weight, &
            ', ELFORM 2 = ', f2%weight, ' (measured per element-cycle ratio)'
      else
         write(unit, '(a,i0,a,i0,a,i0,a)') 'element cost weights: ELFORM 1 = ', &
            part%wscale*f1%weight, ', ELFORM 2 = ', part%wscale*f2%weight, &
            ', rigid = ', COST_RIGID, ' (measured per element-cycle ratio)'
      end if
      if (part%wshell > 0) write(unit, '(a,i0,a)') 'shell cost weight: *SECTION_SHELL '// &
         'ELFORM 2 (Belytschko-Lin-Tsay) = ', part%wshell, ' (measured at NIP 3)'
      write(unit, '(a)') '  rank   elements     weight      nodes     shared  neighbours'
      do r = 0, part%np - 1
         write(unit, '(i6,4i11,i12)') r, part%rank_ne(r), part%rank_wgt(r), part%rank_nn(r), &
            part%rank_nshared(r), nnb(r)
      end do
      if (any(part%rank_ne == 0)) write(unit, '(a,i0,a,i0,a)') 'empty ranks (no elements): ', &
         count(part%rank_ne == 0), ' of ', part%np, ': '//rank_list(part%rank_ne == 0)
      write(unit, '(a,i0)') 'shared nodes (held by more than one rank): ', nshared_total
      write(unit, '(a,i0)') 'edge cut (weighted): ', part%edgecut
      if (part%nprox > 0) write(unit, '(a,i0,a,i0,a)') 'proximity edges (automatic contact): ', &
         part%nprox, ' between ', part%ncomp, ' separate bodies'
      if (allocated(part%ewgt)) then
         if (size(part%ewgt) > 0) write(unit, '(a,i0)') 'heaviest element weight: ', &
                                                        maxval(part%ewgt)
      end if
      write(unit, '(a,f8.4,a)') 'balance (max weight / mean weight): ', part%balance, &
         '   (1.0 = perfect; 1.0-1.1 reasonable)'
   end subroutine write_report

   !> The ranks r (0-based) where sel(r) holds, as a list of ranges: "1, 3-5, 9".
   function rank_list(sel) result(t)
      logical, intent(in) :: sel(0:)
      character(:), allocatable :: t
      integer :: r, r1
      t = ''
      r = 0
      do while (r < size(sel))
         if (.not. sel(r)) then
            r = r + 1
            cycle
         end if
         r1 = r
         do while (r1 + 1 < size(sel))
            if (.not. sel(r1 + 1)) exit
            r1 = r1 + 1
         end do
         if (len(t) > 0) t = t//', '
         t = t//str(r)
         if (r1 > r) t = t//'-'//str(r1)
         r = r1 + 1
      end do
   end function rank_list
end module dx_partition
