!> External loads in an MPI run (ParaDyn step 5; docs/history.md, "Rigid bodies and loads under
!> MPI"): *LOAD_NODE_POINT, *LOAD_SEGMENT(_SET) and *LOAD_BODY_X/Y/Z give the serial fext bit
!> for bit at every node a rank holds, and the external work the serial sum over nodes.
!> The serial fext(:, i) is a chain: 0 - m_i a (body loads), then the nodal loads on i in deck
!> order, then the segment loads on i in deck order (dx_loads: add_external_loads). With
!> -march=native the compiler may fuse a product into the running sum (FMA), so fext is not a
!> sum of independent terms that could be exchanged and re-added: each node's chain must be
!> evaluated whole, by the same code, with the same inputs.
!> - A node held by one rank only: every load touching it is on that rank (a nodal load is in
!>   the rank file of every rank holding the node; a segment load on the lowest rank holding
!>   all of its nodes, which must be this one), in deck order: add_external_loads on the
!>   rank's sub-model gives the serial chain.
!> - A shared node: each holder evaluates the whole chain itself on a small model `lm` holding
!>   the loads that touch its shared nodes (global deck order, compact node numbers), the
!>   masses of those nodes and the current coordinates of the segment nodes, gathered from
!>   their owners once per cycle (one MPI_Allgatherv, only when a segment load touches a
!>   shared node). add_external_loads(lm) is the serial chain; its value replaces the
!>   rank-local one at the shared nodes.
!> - *BOUNDARY_NON_REFLECTING_2D: nodal dashpots (dx_nonreflecting), node by node after the
!>   exchange on every rank holding the node: the sub-model keeps the rank's nodes of the list.
!>   *DYNX_PRESSURE_TABLE/_PULSE (dx_edge_pressure) likewise: the shares of the rank's nodes.
!> - External work: the serial loop adds f.dtavg (v(n-1/2) + v(n+1/2))/2 node by node. The
!>   term of each owned node that can carry a load is computed locally (the serial
!>   expression; it depends on that node alone) into the cycle's exact sum (dx_repro_sum),
!>   kept for up to NBUF_MAX cycles; when a sum is needed (glstat, ENDENG, the end) or the
!>   buffer is full, one int64 allreduce sums the kept cycles over the ranks and each
!>   cycle's sum is added to wext in cycle order, as the serial run adds its cycle sums
!>   (dx_domain s_load_work): no term travels.
!> Fixed-order sums: the idea of OpenRadioss /PARITH/ON (Hoover et al., ParaDyn, LLNL
!> Engineering Thrust Area Report FY97; shared/seed article 4).
module dx_par_loads
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_par, only: par_allreduce, PAR_MAX
   use dx_par_plan, only: gather_plan_t, par_gather_setup, par_gather_values
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_reduce, rs_value
   use dx_par_model, only: par_model_t
   use dx_partition, only: rank_part_t
   use dx_rank_submodel, only: rank_node_loads
   use dx_loads, only: add_external_loads, has_external_loads
   implicit none
   private
   public :: par_loads_t, par_loads_setup, par_loads_any, par_loads_shared, par_loads_work, &
             par_loads_flush, par_loads_take_mass, par_loads_remass

   integer, parameter :: NBUF_MAX = 32

   !> The external-load stage's part of a rank's domain (a component of mpi_domain_t).
   type :: par_loads_t
      logical :: active = .false.
      type(model_t), pointer :: gp => null()     !< the engine's global model
      type(model_t) :: lm                         !< loads on this rank's shared nodes
      integer, allocatable :: lm_glob(:)          !< (lm%nn) global node of each lm node
      integer, allocatable :: lm_out(:, :)        !< (2, n) lm node, local node: results
      logical :: lm_mass_set = .false.
      type(gather_plan_t) :: plan_x               !< owned segment nodes' x
      integer, allocatable :: x_src(:)            !< owned local nodes in plan_x
      integer, allocatable :: x_lm(:)             !< (all keys) lm node of each key, or 0
      type(gather_plan_t) :: plan_w               !< owned nodes that can carry a load
      integer, allocatable :: w_loc(:)
      integer :: nbuf = 0
      real(wp), allocatable :: wbuf(:, :)         !< (set-up allocates it; no longer used)
      type(rsum_t) :: wacc                         !< (NBUF_MAX) kept cycle sums
   end type par_loads_t

contains

   !> Called by par_engine_setup after par_model_build: restrict the sub-model's nodal and
   !> segment loads to the rank file's lists (local node numbers) and build lm and the plans.
   !> loc: global node -> local node (0: not on this rank); owned: (nloc) owner flags.
   subroutine par_loads_setup(ld, model, g, rp, pm, loc, owned)
      type(par_loads_t), intent(inout) :: ld
      type(model_t), intent(inout) :: model
      type(model_t), intent(inout), target :: g
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(in) :: pm
      integer, intent(in) :: loc(:)
      logical, intent(in) :: owned(:)
      logical, allocatable :: myshared(:), inlm(:), mark(:), mark0(:)
      integer, allocatable :: need(:), cmap(:), nl(:), sl(:)
      integer :: k, j, n, i
      ld%gp => g
      ld%active = has_external_loads(g)
      if (.not. ld%active) return
      if (allocated(g%node_loads)) model%node_loads = rank_node_loads(rp)   ! its file's records
      if (allocated(g%nr_node)) then      ! non-reflecting nodes on this rank, local numbers
         i = count(loc(g%nr_node) > 0)
         model%nr_node = loc(pack(g%nr_node, loc(g%nr_node) > 0))
         model%nr_c = g%nr_c(:, pack([(k, k = 1, size(g%nr_node))], loc(g%nr_node) > 0))
         if (i == 0) deallocate(model%nr_node, model%nr_c)
      end if
      if (allocated(g%edge_pressures)) then   ! edge pressures: the shares of this rank's nodes
         do j = 1, size(g%edge_pressures)
            associate (ge => g%edge_pressures(j), me => model%edge_pressures(j))
               mark0 = loc(ge%node) > 0
               me%node = loc(pack(ge%node, mark0))
               me%edge = pack(ge%edge, mark0)
               me%w = ge%w(:, pack([(k, k = 1, size(ge%node))], mark0))
            end associate
         end do
      end if
      if (allocated(g%seg_loads)) then
         model%seg_loads = g%seg_loads(rp%seg_loads)
         do k = 1, size(model%seg_loads)
            do j = 1, 4
               n = model%seg_loads(k)%nodes(j)
               if (n > 0) model%seg_loads(k)%nodes(j) = loc(n)
            end do
         end do
      end if
      ! the loads (global deck order) touching one of this rank's shared nodes
      allocate(myshared(g%nn), inlm(g%nn), need(g%nn))
      myshared = .false.
      myshared(pm%node_global(pm%shared_local)) = .true.
      inlm = .false.
      need = 0
      nl = [integer ::]
      sl = [integer ::]
      if (allocated(g%node_loads)) then
         do k = 1, size(g%node_loads)
            if (myshared(g%node_loads(k)%node)) then
               nl = [nl, k]
               inlm(g%node_loads(k)%node) = .true.
            end if
         end do
      end if
      if (allocated(g%seg_loads)) then
         do k = 1, size(g%seg_loads)
            associate (nd => g%seg_loads(k)%nodes)
               if (any(pack(myshared(max(nd, 1)), nd > 0))) then
                  sl = [sl, k]
                  do j = 1, 4
                     if (nd(j) > 0) then
                        inlm(nd(j)) = .true.
                        need(nd(j)) = 1
                     end if
                  end do
               end if
            end associate
         end do
      end if
      ld%lm_glob = pack([(i, i = 1, g%nn)], inlm)
      allocate(cmap(g%nn))
      cmap = 0
      cmap(ld%lm_glob) = [(i, i = 1, size(ld%lm_glob))]
      ld%lm%nn = size(ld%lm_glob)
      allocate(ld%lm%x(3, ld%lm%nn), ld%lm%mass(ld%lm%nn))
      ld%lm%x = 0.0_wp
      ld%lm%mass = 0.0_wp
      ld%lm%curves = g%curves
      if (allocated(g%body_loads)) ld%lm%body_loads = g%body_loads
      if (allocated(g%node_loads)) then
         ld%lm%node_loads = g%node_loads(nl)
         do k = 1, size(nl)
            ld%lm%node_loads(k)%node = cmap(ld%lm%node_loads(k)%node)
         end do
      end if
      if (allocated(g%seg_loads)) then
         ld%lm%seg_loads = g%seg_loads(sl)
         do k = 1, size(sl)
            do j = 1, 4
               n = ld%lm%seg_loads(k)%nodes(j)
               if (n > 0) ld%lm%seg_loads(k)%nodes(j) = cmap(n)
            end do
         end do
      end if
      ! results: lm nodes that are this rank's shared nodes
      ld%lm_out = reshape([(cmap(ld%lm_glob(i)), loc(ld%lm_glob(i)), &
                            i = 1, size(ld%lm_glob))], [2, size(ld%lm_glob)])
      ld%lm_out = ld%lm_out(:, pack([(i, i = 1, size(ld%lm_glob))], myshared(ld%lm_glob)))
      ! coordinates every rank needs (segments touching some rank's shared nodes)
      call par_allreduce(need, PAR_MAX)
      ld%x_src = pack([(i, i = 1, pm%nloc)], owned .and. need(pm%node_global) > 0)
      call par_gather_setup(ld%plan_x, pm%node_global(ld%x_src))
      allocate(ld%x_lm(size(ld%plan_x%keys)))
      ld%x_lm = cmap(ld%plan_x%keys)
      ! nodes that can carry a load: all with body loads, else the nodes of the loads
      allocate(mark(g%nn))
      mark = allocated(g%body_loads)
      if (allocated(g%node_loads)) mark(g%node_loads(:)%node) = .true.
      if (allocated(g%nr_node)) mark(g%nr_node) = .true.
      if (allocated(g%edge_pressures)) then
         do k = 1, size(g%edge_pressures)
            mark(g%edge_pressures(k)%node) = .true.
         end do
      end if
      if (allocated(g%seg_loads)) then
         do k = 1, size(g%seg_loads)
            do j = 1, 4
               if (g%seg_loads(k)%nodes(j) > 0) mark(g%seg_loads(k)%nodes(j)) = .true.
            end do
         end do
      end if
      ld%w_loc = pack([(i, i = 1, pm%nloc)], owned .and. mark(pm%node_global))
      call par_gather_setup(ld%plan_w, pm%node_global(ld%w_loc))
      allocate(ld%wbuf(NBUF_MAX, size(ld%w_loc)))
   end subroutine par_loads_setup

   !> True when the deck has external loads (on every rank alike, whatever the rank holds).
   logical function par_loads_any(ld)
      type(par_loads_t), intent(in) :: ld
      par_loads_any = ld%active
   end function par_loads_any

   !> After add_external_loads on the sub-model: fext at this rank's shared nodes becomes
   !> the serial chain, evaluated on lm with the gathered segment coordinates.
   subroutine par_loads_shared(ld, model, t, fext)
      type(par_loads_t), intent(inout) :: ld
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
      real(wp), allocatable :: vals(:, :), gv(:, :), lf(:, :)
      integer :: i
      if (.not. ld%active) return
      if (size(ld%plan_x%keys) > 0) then      ! the same on every rank: collective
         allocate(vals(3, size(ld%x_src)), gv(3, size(ld%plan_x%keys)))
         vals = model%x(:, ld%x_src)
         call par_gather_values(ld%plan_x, vals, gv)
         do i = 1, size(ld%x_lm)
            if (ld%x_lm(i) > 0) ld%lm%x(:, ld%x_lm(i)) = gv(:, i)
         end do
      end if
      if (size(ld%lm_out, 2) == 0) return
      call par_loads_take_mass(ld)
      allocate(lf(size(fext, 1), ld%lm%nn))   ! (6 rows with nodal moments: load_rows)
      lf = 0.0_wp
      call add_external_loads(ld%lm, t, lf)
      fext(:, ld%lm_out(2, :)) = lf(:, ld%lm_out(1, :))
   end subroutine par_loads_shared

   !> The external work of the step, in serial node order (see the module header); wext is
   !> brought up to date when needed (or every NBUF_MAX cycles).
   subroutine par_loads_work(ld, fext, vold, v, dtavg, wext, needed)
      type(par_loads_t), intent(inout) :: ld
      real(wp), intent(in) :: fext(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: wext
      logical, intent(in) :: needed
      integer :: i
      real(wp) :: term
      if (.not. ld%active) return
      if (ld%nbuf == 0) call rs_init(ld%wacc, NBUF_MAX)
      ld%nbuf = ld%nbuf + 1
      do i = 1, size(ld%w_loc)
         associate (n => ld%w_loc(i))
            term = dot_product(fext(:, n), 0.5_wp*dtavg*(vold(:, n) + v(:, n)))
            if (term /= 0.0_wp) call rs_add(ld%wacc, ld%nbuf, term)
         end associate
      end do
      if (.not. (needed .or. ld%nbuf == NBUF_MAX)) return
      call par_loads_flush(ld, wext)
   end subroutine par_loads_work

   !> Add the kept cycles' external work into wext (collective; nothing when none are
   !> kept): the same additions in the same order as the flush in par_loads_work would
   !> make, so a restart dump (dx_checkpoint) that calls it first keeps wext's bits.
   subroutine par_loads_flush(ld, wext)
      type(par_loads_t), intent(inout) :: ld
      real(wp), intent(inout) :: wext
      type(rsum_t) :: kept
      integer :: c
      if (.not. ld%active) return
      if (ld%nbuf == 0) return
      kept%a = ld%wacc%a(:, 1:ld%nbuf)
      call rs_reduce(kept)
      do c = 1, ld%nbuf
         wext = wext + rs_value(kept, c)
      end do
      ld%nbuf = 0
   end subroutine par_loads_flush

   !> Mass scaling changed the nodal masses: the loads' nodes on this rank's shared nodes
   !> take them from the rank's (summed) masses, as the serial run's loads see them.
   subroutine par_loads_remass(ld, model)
      type(par_loads_t), intent(inout) :: ld
      type(model_t), intent(in) :: model
      integer :: j
      if (.not. ld%active) return
      if (.not. allocated(ld%lm_out)) return
      do j = 1, size(ld%lm_out, 2)
         ld%lm%mass(ld%lm_out(1, j)) = model%mass(ld%lm_out(2, j))
      end do
      ld%lm_mass_set = .true.
   end subroutine par_loads_remass

   !> The global masses of the loads' nodes on this rank's shared nodes, once (after
   !> init_state; the engine calls it before it frees the global model's masses).
   subroutine par_loads_take_mass(ld)
      type(par_loads_t), intent(inout) :: ld
      if (.not. ld%active .or. ld%lm_mass_set) return
      if (size(ld%lm_out, 2) == 0) return
      ld%lm%mass = ld%gp%mass(ld%lm_glob)
      ld%lm_mass_set = .true.
   end subroutine par_loads_take_mass
end module dx_par_loads
