!> External loads in an MPI run (ParaDyn step 5; docs/design.md, "Rigid bodies and loads under
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
!> - External work: the serial loop adds f.dtavg (v(n-1/2) + v(n+1/2))/2 node by node. The
!>   term of each owned node that can carry a load is computed locally (the serial
!>   expression; it depends on that node alone), kept for up to NBUF_MAX cycles and, when a
!>   sum is needed (glstat, ENDENG, the end) or the buffer is full, gathered and added cycle
!>   by cycle in node order. Nodes without a load have fext = +0 exactly, and adding a +-0
!>   term leaves a sum that started at +0 unchanged, so skipping them changes no bit.
!> Fixed-order sums: the idea of OpenRadioss /PARITH/ON (Hoover et al., ParaDyn, LLNL
!> Engineering Thrust Area Report FY97; shared/seed article 4).
module dx_par_loads
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_par, only: par_allreduce, PAR_MAX
   use dx_par_plan, only: gather_plan_t, par_gather_setup, par_gather_values
   use dx_par_model, only: par_model_t
   use dx_partition, only: rank_part_t
   use dx_loads, only: add_external_loads, has_external_loads
   implicit none
   private
   public :: par_loads_setup, par_loads_any, par_loads_shared, par_loads_work, par_loads_flush, &
             par_loads_take_mass

   logical, save :: active = .false.
   type(model_t), pointer, save :: gp => null()     !< the engine's global model
   type(model_t), save :: lm                         !< loads on this rank's shared nodes
   integer, allocatable, save :: lm_glob(:)          !< (lm%nn) global node of each lm node
   integer, allocatable, save :: lm_out(:, :)        !< (2, n) lm node, local node: results
   logical, save :: lm_mass_set = .false.
   type(gather_plan_t), save :: plan_x               !< owned segment nodes' x
   integer, allocatable, save :: x_src(:)            !< owned local nodes in plan_x
   integer, allocatable, save :: x_lm(:)             !< (all keys) lm node of each key, or 0
   type(gather_plan_t), save :: plan_w               !< owned nodes that can carry a load
   integer, allocatable, save :: w_loc(:)
   integer, parameter :: NBUF_MAX = 32
   integer, save :: nbuf = 0
   real(wp), allocatable, save :: wbuf(:, :)         !< (NBUF_MAX, size(w_loc))

contains

   !> Called by par_engine_setup after par_model_build: restrict the sub-model's nodal and
   !> segment loads to the rank file's lists (local node numbers) and build lm and the plans.
   !> loc: global node -> local node (0: not on this rank); owned: (nloc) owner flags.
   subroutine par_loads_setup(model, g, rp, pm, loc, owned)
      type(model_t), intent(inout) :: model
      type(model_t), intent(inout), target :: g
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(in) :: pm
      integer, intent(in) :: loc(:)
      logical, intent(in) :: owned(:)
      logical, allocatable :: myshared(:), inlm(:), mark(:)
      integer, allocatable :: need(:), cmap(:), nl(:), sl(:)
      integer :: k, j, n, i
      gp => g
      active = has_external_loads(g)
      if (.not. active) return
      if (allocated(g%node_loads)) then
         model%node_loads = g%node_loads(rp%node_loads)
         do k = 1, size(model%node_loads)
            model%node_loads(k)%node = loc(model%node_loads(k)%node)
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
      lm_glob = pack([(i, i = 1, g%nn)], inlm)
      allocate(cmap(g%nn))
      cmap = 0
      cmap(lm_glob) = [(i, i = 1, size(lm_glob))]
      lm%nn = size(lm_glob)
      allocate(lm%x(3, lm%nn), lm%mass(lm%nn))
      lm%x = 0.0_wp
      lm%mass = 0.0_wp
      lm%curves = g%curves
      if (allocated(g%body_loads)) lm%body_loads = g%body_loads
      if (allocated(g%node_loads)) then
         lm%node_loads = g%node_loads(nl)
         do k = 1, size(nl)
            lm%node_loads(k)%node = cmap(lm%node_loads(k)%node)
         end do
      end if
      if (allocated(g%seg_loads)) then
         lm%seg_loads = g%seg_loads(sl)
         do k = 1, size(sl)
            do j = 1, 4
               n = lm%seg_loads(k)%nodes(j)
               if (n > 0) lm%seg_loads(k)%nodes(j) = cmap(n)
            end do
         end do
      end if
      ! results: lm nodes that are this rank's shared nodes
      lm_out = reshape([(cmap(lm_glob(i)), loc(lm_glob(i)), i = 1, size(lm_glob))], &
                       [2, size(lm_glob)])
      lm_out = lm_out(:, pack([(i, i = 1, size(lm_glob))], myshared(lm_glob)))
      ! coordinates every rank needs (segments touching some rank's shared nodes)
      call par_allreduce(need, PAR_MAX)
      x_src = pack([(i, i = 1, pm%nloc)], owned .and. need(pm%node_global) > 0)
      call par_gather_setup(plan_x, pm%node_global(x_src))
      allocate(x_lm(size(plan_x%keys)))
      x_lm = cmap(plan_x%keys)
      ! nodes that can carry a load: all with body loads, else the nodes of the loads
      allocate(mark(g%nn))
      mark = allocated(g%body_loads)
      if (allocated(g%node_loads)) mark(g%node_loads(:)%node) = .true.
      if (allocated(g%seg_loads)) then
         do k = 1, size(g%seg_loads)
            do j = 1, 4
               if (g%seg_loads(k)%nodes(j) > 0) mark(g%seg_loads(k)%nodes(j)) = .true.
            end do
         end do
      end if
      w_loc = pack([(i, i = 1, pm%nloc)], owned .and. mark(pm%node_global))
      call par_gather_setup(plan_w, pm%node_global(w_loc))
      allocate(wbuf(NBUF_MAX, size(w_loc)))
   end subroutine par_loads_setup

   !> True when the deck has external loads (on every rank alike, whatever the rank holds).
   logical function par_loads_any()
      par_loads_any = active
   end function par_loads_any

   !> After add_external_loads on the sub-model: fext at this rank's shared nodes becomes
   !> the serial chain, evaluated on lm with the gathered segment coordinates.
   subroutine par_loads_shared(model, t, fext)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
      real(wp), allocatable :: vals(:, :), gv(:, :), lf(:, :)
      integer :: i
      if (.not. active) return
      if (size(plan_x%keys) > 0) then      ! the same on every rank: collective
         allocate(vals(3, size(x_src)), gv(3, size(plan_x%keys)))
         vals = model%x(:, x_src)
         call par_gather_values(plan_x, vals, gv)
         do i = 1, size(x_lm)
            if (x_lm(i) > 0) lm%x(:, x_lm(i)) = gv(:, i)
         end do
      end if
      if (size(lm_out, 2) == 0) return
      call par_loads_take_mass()
      allocate(lf(3, lm%nn))
      lf = 0.0_wp
      call add_external_loads(lm, t, lf)
      fext(:, lm_out(2, :)) = lf(:, lm_out(1, :))
   end subroutine par_loads_shared

   !> The external work of the step, in serial node order (see the module header); wext is
   !> brought up to date when needed (or every NBUF_MAX cycles).
   subroutine par_loads_work(fext, vold, v, dtavg, wext, needed)
      real(wp), intent(in) :: fext(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: wext
      logical, intent(in) :: needed
      integer :: i
      if (.not. active) return
      nbuf = nbuf + 1
      do i = 1, size(w_loc)
         associate (n => w_loc(i))
            wbuf(nbuf, i) = dot_product(fext(:, n), 0.5_wp*dtavg*(vold(:, n) + v(:, n)))
         end associate
      end do
      if (.not. (needed .or. nbuf == NBUF_MAX)) return
      call par_loads_flush(wext)
   end subroutine par_loads_work

   !> Add the kept external-work terms into wext (collective; nothing when none are kept):
   !> the same additions in the same order as the flush in par_loads_work would make, so a
   !> restart dump (dx_checkpoint) that calls it first keeps wext's bits.
   subroutine par_loads_flush(wext)
      real(wp), intent(inout) :: wext
      real(wp), allocatable :: vals(:, :), gv(:, :)
      integer :: i, c
      if (.not. active) return
      if (nbuf == 0) return
      allocate(gv(nbuf, size(plan_w%keys)))
      vals = wbuf(1:nbuf, :)               ! contiguous for MPI
      call par_gather_values(plan_w, vals, gv)
      do c = 1, nbuf
         do i = 1, size(plan_w%keys)
            wext = wext + gv(c, i)
         end do
      end do
      nbuf = 0
   end subroutine par_loads_flush

   !> The global masses of the loads' nodes on this rank's shared nodes, once (after
   !> init_state; the engine calls it before it frees the global model's masses).
   subroutine par_loads_take_mass()
      if (.not. active .or. lm_mass_set) return
      if (size(lm_out, 2) == 0) return
      lm%mass = gp%mass(lm_glob)
      lm_mass_set = .true.
   end subroutine par_loads_take_mass
end module dx_par_loads
