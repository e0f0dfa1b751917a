!> Contact in MPI runs (ParaDyn, issue 6; docs/history.md, "Parallel contact"). Only a deck with
!> *CONTACT reaches any of this; every other MPI run allocates and calls nothing here.
!>  - dynx-part and the engine's own partitioner condense each local contact pair (the
!>    non-automatic *CONTACT_SURFACE_TO_SURFACE / NODES_TO_SURFACE / ONE_WAY interfaces) into
!>    one super element (contact_groups: the elements with a face on either surface, or
!>    holding a slave node of a node set), so a pair lands whole on one rank.
!>  - The search and the forces of automatic / single-surface contacts are split by strips
!>    (dx_contact_strips): the slave nodes of every pass are cut along their longest extent
!>    into NP strips of equal node count, rebuilt with the bucket sort; rank r searches and
!>    computes strip r (pass_node). A local pair is computed by the rank holding it.
!>  - Each cycle x(n), v(n-1/2) reach the global model g: at a sort cycle (owner-computes)
!>    only the segments within reach of the rank's slave nodes (dx_par_contact_ghost; every
!>    contact node's by one allgather at the first stage, with strips, or with rigid bodies
!>    in contact), between sorts only the halo the rank's nodes need (its slave nodes, their
!>    candidate and contact segments' nodes, point to point from the owners; held nodes
!>    from the rank's own copy).
!>    The ranks compute their slave nodes' results, the results
!>    are gathered (one ordered gather) and every rank adds all of them in the serial order
!>    (interface, pass, slave node: pass_apply, the same code the serial run uses): the
!>    contact forces, stiffness row sums, resultants and the contact step bound are the
!>    serial ones bit for bit on every rank. The forces enter the rank's f after the
!>    shared-node exchange (f = element sum + contact force, the serial order at every
!>    node). After the velocity update v(n-1/2), v(n+1/2) of the nodes with a contact force
!>    are gathered and the serial contact_work (centred work, sliding energy, rcforc from
!>    rank 0) runs on the global model.
!> Strips: Hoover et al., ParaDyn, LLNL Engineering Thrust Area Report FY97 (article 4 of
!> shared/seed); the serial algorithm: Hallquist, Goudreau & Benson 1985, CMAME 51:107-137.
!> No module state: the gather plans and local maps of the contact nodes are a par_contact_t,
!> a component of the rank's domain (dx_domain_mpi).
module dx_par_contact
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_model, only: model_t
   use dx_contact, only: contact_search_nodes, contact_assemble, contact_dt, contact_work, &
                         contact_vmax, contact_prepare
   use dx_contact_types, only: contact_set_t, NREC
   use dx_contact_groups, only: contact_groups, write_contact_report   ! (re-exported)
   use dx_par_rigid, only: par_rigid_centres
   use dx_energy_sums, only: interface_work
   use dx_par, only: par_rank, par_size, par_abort, par_allreduce, PAR_MAX, PAR_SUM, par_wtime, &
                     par_alltoallv, par_allgatherv_real, par_sparse_exchange, par_allgather_probe
   use dx_par_plan, only: gather_plan_t, par_gather_setup, par_gather_values, par_gather_ordered
   use dx_par_contact_ghost, only: contact_ghost_t, ghost_setup, ghost_sort, ghost_drop, &
                                   idle_reduce
   implicit none
   private
   public :: par_contact_t, par_contact_setup, par_contact_forces, par_contact_add, &
             par_contact_work, par_contact_report, contact_groups, write_contact_report

   !> The contact stage's part of a rank's domain (a component of mpi_domain_t).
   type :: par_contact_t
      logical :: on = .false.
      !> which rank computes a slave node: 'owner' (the rank owning it) or 'strips' (ParaDyn's
      !> geometric strips); dynx --contact-split, else DYNX_PAR_CONTACT, else 'owner'
      character(16) :: split_mode = ''
      !> true until the first contact stage: it gathers every contact node's x and v and plans
      !> the halo even between sorts (a continued run: g's x is the deck's, the plan empty)
      logical :: fresh = .true.
      type(gather_plan_t) :: plan_c              !< the owned contact nodes, by global id
      integer, allocatable :: c_own(:)           !< local index of each owned contact node
      integer, allocatable :: c_glob(:)          !< its global index
      integer, allocatable :: c_all(:)           !< every contact node (global, ascending)
      integer, allocatable :: c_owner(:)         !< the rank owning each of c_all
      integer, allocatable :: loc_of(:)          !< global node -> local index (0: none)
      integer, allocatable :: h_req(:), h_snd(:) !< halo: nodes received / sent
      integer, allocatable :: h_sglob(:)         !< global ids of h_snd
      !> held contact nodes the halo needs between sorts (local, global): held_xv's subset
      integer, allocatable :: hh_loc(:), hh_glob(:)
      integer, allocatable :: cpos(:)            !< global node -> position in c_all (0: none)
      !> positions in c_all of the nodes with a contact force this cycle, ascending
      integer, allocatable :: fl(:)
      !> this rank's slave nodes in the serial order (mine_list, at each sort): pass, node;
      !> the passes' interface, index and first serial key
      integer, allocatable :: ml_ip(:), ml_k(:), pi(:), pj(:), poff(:)
      logical :: fresh_list = .true.
      !> this cycle's results (this rank's and the others'): pass, slave node
      integer, allocatable :: rk_ip(:), rk_k(:)
      integer :: nrk = 0
      !> ghost sorts (owner-computes): a sort receives only the segments within reach of
      !> this rank's slave nodes (dx_par_contact_ghost), not every contact node
      type(contact_ghost_t) :: gh
      integer, allocatable :: h_rcnt(:), h_scnt(:)   !< (0:np-1) their counts per rank
      integer(8) :: nval_recv = 0                !< numbers received (x, v, work terms)
      integer(8) :: nres_recv = 0                !< numbers received (results)
      !> the largest contact-node speed |v(n+1/2)| over the ranks, found with the work
      !> exchange, for the next cycle's contact stage (v does not change in between)
      real(wp) :: vmax_next = 0.0_wp
      logical :: have_vmax = .false.
      integer, allocatable :: l_loc(:), l_glob(:)   !< held contact nodes: local, global
      real(wp), allocatable :: cvold(:, :)       !< (3, nn global) v(n-1/2), contact nodes
      real(wp) :: t_cont = 0.0_wp, t_comm = 0.0_wp
      !> per stage [s]: x, v exchange (halo, ghosts, full gathers), results exchange, work
      !> exchange, assembly of the results, contact work on g
      real(wp) :: t_xv = 0.0_wp, t_res = 0.0_wp, t_wex = 0.0_wp, t_asm = 0.0_wp, &
                  t_cwork = 0.0_wp
      integer :: ncycle = 0, nfull = 0
      integer(8) :: nrec_sent = 0
      !> numbers sent by this rank: x, v (halo, ghosts, gathers), results, work terms
      integer(8) :: ns_xv = 0, ns_res = 0, ns_wex = 0
   end type par_contact_t

contains

   !> Start of an MPI run with contact: g is the global model (serial numbering), model the
   !> rank's sub-model (local nodes 1..nloc with global ids node_global, owned(i) if this
   !> rank owns local node i). The contact state lives in g%contact from now on; model
   !> keeps an empty contact set as the marker that the deck has contact.
   subroutine par_contact_setup(pc, model, g, node_global, owned)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(inout) :: model
      type(model_t), intent(inout) :: g
      integer, intent(in) :: node_global(:)
      logical, intent(in) :: owned(:)
      logical, allocatable :: isc(:)
      integer :: i
      if (.not. allocated(g%contact)) return
      g%contact%nstrip = par_size()
      g%contact%istrip = par_rank()
      if (par_rank() /= 0) g%contact%rcforc_dt = 0.0_wp    ! rcforc: rank 0 writes it
      allocate(isc(g%nn))
      isc = .false.
      isc(g%contact%node) = .true.
      pc%l_loc = pack([(i, i = 1, size(node_global))], isc(node_global))
      pc%l_glob = node_global(pc%l_loc)
      pc%c_own = pack(pc%l_loc, owned(pc%l_loc))
      pc%c_glob = node_global(pc%c_own)
      call par_gather_setup(pc%plan_c, pc%c_glob)
      ! owner-computes (default): this rank computes the slave nodes it owns, the same
      ! nodes at every sort (no strips to find, and its slave nodes' x and v are its own);
      ! strips (--contact-split strips or DYNX_PAR_CONTACT=strips): the geometric strips
      ! of dx_contact_strips
      if (len_trim(pc%split_mode) == 0) &
         call get_environment_variable('DYNX_PAR_CONTACT', pc%split_mode)
      if (pc%split_mode /= 'strips') pc%split_mode = 'owner'
      if (pc%split_mode == 'owner') then
         allocate(g%contact%mine_node(g%nn))
         g%contact%mine_node = .false.
         g%contact%mine_node(pc%c_glob) = .true.
      end if
      block
         integer, allocatable :: ak(:)
         real(wp), allocatable :: av(:, :)
         call par_gather_ordered(pc%c_glob, reshape([(real(par_rank(), wp), i = 1, &
                                 size(pc%c_glob))], [1, size(pc%c_glob)]), ak, av)
         pc%c_all = ak
         pc%c_owner = nint(av(1, :))
      end block
      allocate(pc%loc_of(g%nn), pc%h_rcnt(0:par_size() - 1), pc%h_scnt(0:par_size() - 1))
      pc%loc_of = 0
      pc%loc_of(node_global) = [(i, i = 1, size(node_global))]
      pc%h_rcnt = 0
      pc%h_scnt = 0
      allocate(pc%h_req(0), pc%h_snd(0))
      allocate(pc%cvold(3, g%nn))
      pc%cvold = 0.0_wp
      ! a local pair (kept whole by the partitioner) is computed by the rank holding its
      ! elements, without strips: its surface nodes are that rank's own
      block
         integer, allocatable :: gp(:), ge(:), gid(:), gif(:)
         logical, allocatable :: mine_e(:)
         integer :: b, k, r
         call contact_groups(g, gp, ge, gid, gif)
         allocate(mine_e(g%ne))
         mine_e = .false.
         do b = 1, size(model%blocks)
            mine_e(model%blocks(b)%elem(1:model%blocks(b)%nel)) = .true.
         end do
         do k = 1, size(gid)
            r = -1
            if (mine_e(ge(gp(k)))) r = par_rank()
            call par_allreduce(r, PAR_MAX)
            g%contact%iface(gif(k))%rank = r
         end do
      end block
      allocate(pc%h_sglob(0), pc%hh_loc(0), pc%hh_glob(0), pc%fl(0), pc%cpos(g%nn), &
               pc%rk_ip(0), pc%rk_k(0))
      pc%cpos = 0
      pc%cpos(pc%c_all) = [(i, i = 1, size(pc%c_all))]
      if (pc%split_mode == 'owner') call ghost_setup(pc%gh, g, pc%loc_of, pc%c_all, pc%c_owner)
      deallocate(model%contact)
      allocate(model%contact)
      pc%on = .true.
   end subroutine par_contact_setup

   !> x(n) and v(n-1/2) of every contact node from their owners into g (sort cycles).
   subroutine gather_xv(pc, model, g)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: model
      type(model_t), intent(inout) :: g
      real(wp), allocatable :: vals(:, :), gv(:, :)
      integer :: i
      allocate(vals(6, size(pc%c_own)), gv(6, size(pc%plan_c%keys)))
      do i = 1, size(pc%c_own)
         vals(1:3, i) = model%x(:, pc%c_own(i))
         vals(4:6, i) = model%v(:, pc%c_own(i))
      end do
      call par_gather_values(pc%plan_c, vals, gv)
      g%x(:, pc%plan_c%keys) = gv(1:3, :)
      g%v(:, pc%plan_c%keys) = gv(4:6, :)
      pc%nval_recv = pc%nval_recv + 6*(size(pc%plan_c%keys) - size(pc%c_own))
      pc%ns_xv = pc%ns_xv + 6*size(pc%c_own)*(par_size() - 1)
   end subroutine gather_xv

   !> x(n), v(n-1/2) of every contact node this rank holds (owned or shared: the same bits
   !> on every rank holding it) into g.
   subroutine held_xv(pc, model, g)
      type(par_contact_t), intent(in) :: pc
      type(model_t), intent(in) :: model
      type(model_t), intent(inout) :: g
      integer :: i
      do i = 1, size(pc%l_loc)
         g%x(:, pc%l_glob(i)) = model%x(:, pc%l_loc(i))
         g%v(:, pc%l_glob(i)) = model%v(:, pc%l_loc(i))
      end do
   end subroutine held_xv

   !> x(n) and v(n-1/2) of the nodes this rank's strips need (between sorts): its own
   !> contact nodes copied, the others from their owners (MPI_Alltoallv over the halo plan).
   subroutine halo_xv(pc, model, g)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: model
      type(model_t), intent(inout) :: g
      real(wp), allocatable :: sb(:), rb(:)
      integer :: i, n
      do i = 1, size(pc%hh_loc)      ! the held nodes the halo needs (halo_plan)
         g%x(:, pc%hh_glob(i)) = model%x(:, pc%hh_loc(i))
         g%v(:, pc%hh_glob(i)) = model%v(:, pc%hh_loc(i))
      end do
      allocate(sb(6*size(pc%h_snd)), rb(6*size(pc%h_req)))
      do i = 1, size(pc%h_snd)
         n = pc%h_snd(i)
         sb(6*i - 5:6*i - 3) = model%x(:, n)
         sb(6*i - 2:6*i) = model%v(:, n)
      end do
      call par_sparse_exchange(sb, 6*pc%h_scnt, rb, 6*pc%h_rcnt)   ! with the halo's ranks only
      do i = 1, size(pc%h_req)
         n = pc%h_req(i)
         g%x(:, n) = rb(6*i - 5:6*i - 3)
         g%v(:, n) = rb(6*i - 2:6*i)
      end do
      pc%nval_recv = pc%nval_recv + size(rb)
      pc%ns_xv = pc%ns_xv + size(sb)
   end subroutine halo_xv

   !> After a sort: the nodes this rank's strips need until the next sort (its slave nodes,
   !> the nodes of their candidate segments and of the segments they are in contact with),
   !> requested from their owners: h_req (grouped by owner), h_snd (owned local nodes to
   !> send, grouped by requesting rank).
   subroutine halo_plan(pc, g)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: g
      logical, allocatable :: need(:)
      integer, allocatable :: req(:), sglob(:), one(:)
      integer :: i, j, k, c, s, r, np, me
      np = par_size()
      me = par_rank()
      allocate(need(g%nn))
      need = .false.
      associate (cs => g%contact)
         do i = 1, size(cs%iface)
            if (g%time < cs%iface(i)%bt .or. g%time > cs%iface(i)%dt) cycle
            do j = 1, size(cs%iface(i)%pass)
               associate (p => cs%iface(i)%pass(j))
                  if (.not. allocated(p%mine)) cycle
                  do k = 1, p%nnode
                     if (.not. p%mine(k)) cycle
                     ! (a node without candidates and contact reads nothing until the
                     ! next sort: pass_node returns at once)
                     if (p%cand_ptr(k + 1) == p%cand_ptr(k) .and. p%iseg(k) == 0) cycle
                     need(p%node(k)) = .true.
                     do c = p%cand_ptr(k), p%cand_ptr(k + 1) - 1
                        s = p%cand(c)
                        need(p%seg(1:p%nsn(s), s)) = .true.
                     end do
                     s = p%iseg(k)
                     if (s > 0) need(p%seg(1:p%nsn(s), s)) = .true.
                  end do
               end associate
            end do
         end do
      end associate
      ! rigid bodies: the contact step bound reads x of every body node with a contact
      ! stiffness (rigid_contact_w2 in contact_assemble, which runs on all of g's results)
      if (allocated(g%rigid)) then
         if (allocated(g%rigid%node_body)) then
            do i = 1, size(g%contact%node)
               if (g%rigid%node_body(g%contact%node(i)) > 0) need(g%contact%node(i)) = .true.
            end do
         end if
      end if
      allocate(req(0))
      do r = 0, np - 1
         if (r == me) then
            pc%h_rcnt(r) = 0
            cycle
         end if
         ! (a node this rank holds is its own copy: held_xv)
         sglob = pack(pc%c_all, need(pc%c_all) .and. pc%c_owner == r .and. &
                      pc%loc_of(pc%c_all) == 0)
         pc%h_rcnt(r) = size(sglob)
         req = [req, sglob]
      end do
      pc%h_req = req
      one = [(1, r = 0, np - 1)]
      call par_alltoallv(pc%h_rcnt, one, pc%h_scnt, one)
      if (allocated(sglob)) deallocate(sglob)
      allocate(sglob(sum(pc%h_scnt)))
      call par_alltoallv(pc%h_req, pc%h_rcnt, sglob, pc%h_scnt)
      pc%h_snd = pc%loc_of(sglob)
      pc%h_sglob = sglob
      pc%hh_loc = pack(pc%l_loc, need(pc%l_glob))
      pc%hh_glob = pack(pc%l_glob, need(pc%l_glob))
   end subroutine halo_plan

   !> The contact stage of an MPI run, before the shared-node exchange: search and results of
   !> this rank's strips, the results gathered, all of them added in the serial order on the
   !> global model, the contact step bound (dtcrit: the global element step on entry).
   subroutine par_contact_forces(pc, model, g, dt_old, dtcrit)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: model
      type(model_t), intent(inout) :: g
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: dtcrit
      integer, parameter :: NR = NREC + 3
      real(wp) :: w2max, t0, t1, vmax, dt_est
      integer, allocatable :: cnt(:)
      real(wp), allocatable :: sb(:), rb(:)
      integer :: i, j, k, n, off, q, m, pos, r, ip
      logical :: due, idle
      t0 = par_wtime()
      g%time = model%time
      g%cycle = model%cycle
      if (pc%have_vmax) then      ! from the last cycle's work exchange (v unchanged since)
         vmax = pc%vmax_next
      else
         vmax = contact_vmax(model%v, pc%c_own)   ! the owners' largest speed, then the max
         call par_allreduce(vmax, PAR_MAX)
      end if
      pc%have_vmax = .false.
      ! rigid bodies in contact: their centres x_c(n) into g (dx_par_rigid)
      if (allocated(model%rigid)) call par_rigid_centres(model%rigid, g%rigid)
      call contact_prepare(g, dt_old, vmax, due)
      if (pc%fresh .or. (due .and. .not. pc%gh%on)) then
         ! every contact node's x (strips, the first stage of a run or a continued run)
         call gather_xv(pc, model, g)
         call ghost_drop(g)
         pc%nfull = pc%nfull + 1
      else if (due) then   ! a sort: the segments within reach of this rank's slave nodes
         call held_xv(pc, model, g)
         dt_est = dt_old                        ! (as contact_search_nodes takes it)
         if (dt_est <= 0.0_wp) dt_est = g%ctrl%tssfac*dtcrit
         call ghost_sort(pc%gh, g, pc%l_glob, pc%h_sglob, pc%h_scnt, vmax, dt_est, &
                         pc%ns_xv, pc%nval_recv, idle)
         ! every sorting pass skips its sort (idle contact): the last sort's halo only
         if (idle) call halo_xv(pc, model, g)
      else                 ! between sorts: the halo of this rank's strips
         call halo_xv(pc, model, g)
      end if
      t1 = par_wtime()
      pc%t_comm = pc%t_comm + (t1 - t0)
      pc%t_xv = pc%t_xv + (t1 - t0)
      call contact_search_nodes(g, dt_old, dtcrit, vmax, w2max)
      if (due) call idle_reduce(g)
      if (due .or. pc%fresh) call halo_plan(pc, g)
      pc%fresh = .false.
      ! this rank's results (slave nodes near or in contact): after this rank's candidate
      ! bound w2max, per node its serial position and NR numbers (segments, shape
      ! functions, force, gap, tangential force); to every rank in one MPI_Allgatherv (and
      ! the counts), each node's result then in its place
      results: associate (cs => g%contact)
         ! (over this rank's slave nodes only, in the serial order: mine_list)
         if (due .or. pc%fresh_list) call mine_list(pc, g)
         pc%fresh_list = .false.
         n = 0
         do q = 1, size(pc%ml_k)
            i = pc%pi(pc%ml_ip(q)); j = pc%pj(pc%ml_ip(q)); k = pc%ml_k(q)
            if (g%time < cs%iface(i)%bt .or. g%time > cs%iface(i)%dt) cycle   ! inactive
            if (cs%iface(i)%pass(j)%rint(1, k) > 0 .or. cs%iface(i)%pass(j)%rint(2, k) > 0) &
               n = n + 1
         end do
         allocate(sb(1 + NR*n))
         if (size(pc%rk_k) < size(pc%ml_k)) then
            deallocate(pc%rk_k, pc%rk_ip)
            allocate(pc%rk_k(size(pc%ml_k)), pc%rk_ip(size(pc%ml_k)))
         end if
         pc%nrk = 0
         sb(1) = w2max
         m = 1
         do q = 1, size(pc%ml_k)
            i = pc%pi(pc%ml_ip(q)); j = pc%pj(pc%ml_ip(q)); k = pc%ml_k(q)
            if (g%time < cs%iface(i)%bt .or. g%time > cs%iface(i)%dt) cycle
            associate (p => cs%iface(i)%pass(j))
               if (p%rint(1, k) == 0 .and. p%rint(2, k) == 0) cycle
               sb(m + 1) = real(pc%poff(pc%ml_ip(q)) + k, wp)
               sb(m + 2:m + 3) = real(p%rint(:, k), wp)
               sb(m + 4:m + NR) = p%rval(:, k)
               m = m + NR
               call add_rec(pc%ml_ip(q), k)
            end associate
         end do
         pc%nrec_sent = pc%nrec_sent + n
         t0 = par_wtime()
         pc%t_cont = pc%t_cont + (t0 - t1)
         ! no rank can have a result (the last sort of every active pass found no candidate
         ! on any rank, and no slave node is in contact: iseg is replicated), so w2max is 0
         ! on every rank: nothing to exchange (an idle contact under MPI)
         if (quiet()) then
            pc%t_cont = pc%t_cont + (par_wtime() - t0)
            t1 = par_wtime()
            exit results
         end if
         call par_allgather_probe(sb, rb, cnt)
         t1 = par_wtime()
         pc%t_comm = pc%t_comm + (t1 - t0)
         pc%t_res = pc%t_res + (t1 - t0)
         pc%ns_res = pc%ns_res + size(sb)*(par_size() - 1)
         pc%nres_recv = pc%nres_recv + size(rb) - size(sb)
         ! the other ranks' results into their slave nodes (ascending keys per rank)
         pos = 0
         do r = 0, size(cnt) - 1
            if (r /= par_rank()) then
               w2max = max(w2max, rb(pos + 1))
               q = pos + 1                 ! last number read
               off = 0
               ip = 0
               do i = 1, size(cs%iface)
                  do j = 1, size(cs%iface(i)%pass)
                     ip = ip + 1
                     associate (p => cs%iface(i)%pass(j))
                        if (allocated(p%rint)) then
                           do while (q < pos + cnt(r))
                              k = nint(rb(q + 1)) - off
                              if (k > p%nnode) exit
                              p%rint(:, k) = nint(rb(q + 2:q + 3))
                              p%rval(:, k) = rb(q + 4:q + NR)
                              q = q + NR
                              call add_rec(ip, k)
                           end do
                        end if
                        off = off + p%nnode
                     end associate
                  end do
               end do
            end if
            pos = pos + cnt(r)
         end do
      end associate results
      ! the row sums of all results, added in the serial order (every rank alike); w2max
      ! is now the largest candidate bound over the ranks
      t0 = par_wtime()
      call contact_assemble(g, w2max, .false.)
      call force_list(pc, g)
      pc%t_asm = pc%t_asm + (par_wtime() - t0)
      pc%t_cont = pc%t_cont + (par_wtime() - t1)
      call contact_dt(g%contact, w2max, dtcrit)
      pc%ncycle = pc%ncycle + 1
   contains
      !> every active pass's last sort found no candidate on any rank, no node in contact
      logical function quiet()
         integer :: a, b
         quiet = .true.
         associate (cs => g%contact)
            do a = 1, size(cs%iface)
               if (g%time < cs%iface(a)%bt .or. g%time > cs%iface(a)%dt) cycle
               do b = 1, size(cs%iface(a)%pass)
                  associate (p => cs%iface(a)%pass(b))
                     quiet = p%cand_none
                     if (quiet) quiet = size(p%cand) == 0
                     if (quiet) quiet = .not. any(p%iseg(1:p%nnode) > 0)
                  end associate
                  if (.not. quiet) return
               end do
            end do
         end associate
      end function quiet
      subroutine add_rec(jp, kk)
         integer, intent(in) :: jp, kk
         integer, allocatable :: t1(:), t2(:)
         if (pc%nrk == size(pc%rk_k)) then
            allocate(t1(2*pc%nrk + 16), t2(2*pc%nrk + 16))
            t1(1:pc%nrk) = pc%rk_k(1:pc%nrk); t2(1:pc%nrk) = pc%rk_ip(1:pc%nrk)
            call move_alloc(t1, pc%rk_k); call move_alloc(t2, pc%rk_ip)
         end if
         pc%nrk = pc%nrk + 1
         pc%rk_k(pc%nrk) = kk
         pc%rk_ip(pc%nrk) = jp
      end subroutine add_rec
   end subroutine par_contact_forces

   !> The slave nodes this rank computes (p%mine, after a sort) that may have a result until
   !> the next sort (candidates, or a contact segment: a node without either gets none, and
   !> gains none before the next sort), in the serial order (interface, pass, slave node):
   !> pass ip = (pi, pj), its first key poff.
   subroutine mine_list(pc, g)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: g
      integer :: i, j, k, ip, n
      associate (cs => g%contact)
         n = sum([(size(cs%iface(i)%pass), i = 1, size(cs%iface))])
         if (allocated(pc%pi)) deallocate(pc%pi, pc%pj, pc%poff)
         allocate(pc%pi(n), pc%pj(n), pc%poff(n))
         n = 0
         ip = 0
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               ip = ip + 1
               pc%pi(ip) = i; pc%pj(ip) = j; pc%poff(ip) = n
               associate (p => cs%iface(i)%pass(j))
                  n = n + p%nnode
               end associate
            end do
         end do
         n = 0
         do ip = 1, size(pc%pi)
            associate (p => cs%iface(pc%pi(ip))%pass(pc%pj(ip)))
               if (allocated(p%mine)) then
                  do k = 1, p%nnode
                     if (active(p, k)) n = n + 1
                  end do
               end if
            end associate
         end do
         if (allocated(pc%ml_ip)) deallocate(pc%ml_ip, pc%ml_k)
         allocate(pc%ml_ip(n), pc%ml_k(n))
         n = 0
         do ip = 1, size(pc%pi)
            associate (p => cs%iface(pc%pi(ip))%pass(pc%pj(ip)))
               if (.not. allocated(p%mine)) cycle
               do k = 1, p%nnode
                  if (.not. active(p, k)) cycle
                  n = n + 1
                  pc%ml_ip(n) = ip
                  pc%ml_k(n) = k
               end do
            end associate
         end do
      end associate
   contains
      logical function active(p, k)
         use dx_contact_types, only: contact_pass_t
         type(contact_pass_t), intent(in) :: p
         integer, intent(in) :: k
         active = p%mine(k)
         if (active) active = p%cand_ptr(k + 1) > p%cand_ptr(k) .or. p%iseg(k) > 0
      end function active
   end subroutine mine_list

   !> pc%fl: the positions in c_all of the nodes with a nonzero contact force (the nodes of
   !> the results in contact, ascending), for the work exchange (a node without a contact
   !> force adds an exact zero to the work: skipped, as the serial contact_work does).
   subroutine force_list(pc, g)
      use dx_sort, only: sort_index
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(in) :: g
      integer, allocatable :: lst(:), idx(:)
      integer :: i, k, s, n, nd, q
      associate (cs => g%contact)
         allocate(lst(5*pc%nrk))
         n = 0
         do i = 1, pc%nrk                  ! (this cycle's results: mine and the others')
            associate (p => cs%iface(pc%pi(pc%rk_ip(i)))%pass(pc%pj(pc%rk_ip(i))))
               k = pc%rk_k(i)
               s = p%rint(2, k)
               if (s == 0) cycle
               call add(p%node(k))
               do q = 1, p%nsn(s)
                  call add(p%seg(q, s))
               end do
            end associate
         end do
         lst = lst(1:n)
         idx = [(i, i = 1, n)]
         call sort_index(idx, lst)
         pc%fl = lst(idx)
         do i = 1, n
            pc%cpos(pc%c_all(pc%fl(i))) = pc%fl(i)
         end do
         pc%fl = pack(pc%fl, [(any(cs%fc(:, pc%c_all(pc%fl(i))) /= 0.0_wp), i = 1, n)])
      end associate
   contains
      subroutine add(node)
         integer, intent(in) :: node
         nd = pc%cpos(node)
         if (nd <= 0) return                 ! listed already (marked by the sign)
         pc%cpos(node) = -nd
         n = n + 1
         lst(n) = nd
      end subroutine add
   end subroutine force_list

   !> After the shared-node exchange: f = (element sum) + contact force at every held
   !> contact node, as the serial contact_forces adds it.
   subroutine par_contact_add(pc, model, g)
      type(par_contact_t), intent(in) :: pc
      type(model_t), intent(inout) :: model
      type(model_t), intent(in) :: g
      integer :: i
      do i = 1, size(pc%l_loc)
         model%f(:, pc%l_loc(i)) = model%f(:, pc%l_loc(i)) + g%contact%fc(:, pc%l_glob(i))
      end do
   end subroutine par_contact_add

   !> After the velocity update: v(n-1/2) and v(n+1/2) of the nodes with a contact force
   !> (the others add an exact zero to the work) from their owners, then the serial
   !> contact_work on the global model (work, sliding energy; rcforc from rank 0).
   subroutine par_contact_work(pc, model, g, vold, dtavg, outdir)
      type(par_contact_t), intent(inout) :: pc
      type(model_t), intent(inout) :: model
      type(model_t), intent(inout) :: g
      real(wp), intent(in) :: vold(:, :), dtavg
      character(*), intent(in) :: outdir
      type(error_t), allocatable :: error
      integer, allocatable :: cnt(:), d(:)
      real(wp), allocatable :: sb(:), rb(:)
      integer :: i, j, n, np, r, l, nd
      real(wp) :: t0
      t0 = par_wtime()
      ! the nodes with a contact force are the same on every rank (fc is replicated): the
      ! counts per owner are known, one MPI_Allgatherv (ascending global id per rank)
      np = par_size()
      allocate(cnt(0:np - 1), d(0:np - 1))
      cnt = 0
      do j = 1, size(pc%fl)           ! (the nodes with a contact force, ascending)
         i = pc%fl(j)
         cnt(pc%c_owner(i)) = cnt(pc%c_owner(i)) + 6
      end do
      cnt = cnt + 1                  ! first: the rank's largest contact-node speed
      allocate(sb(cnt(par_rank())))
      sb(1) = contact_vmax(model%v, pc%c_own)
      n = 1
      do j = 1, size(pc%fl)
         i = pc%fl(j)
         if (pc%c_owner(i) /= par_rank()) cycle
         l = pc%loc_of(pc%c_all(i))
         sb(n + 1:n + 3) = vold(:, l)
         sb(n + 4:n + 6) = model%v(:, l)
         n = n + 6
      end do
      call par_allgatherv_real(sb, rb, counts=cnt)
      d(0) = 0
      do r = 1, np - 1
         d(r) = d(r - 1) + cnt(r - 1)
      end do
      pc%vmax_next = 0.0_wp
      do r = 0, np - 1
         pc%vmax_next = max(pc%vmax_next, rb(d(r) + 1))
         d(r) = d(r) + 1
      end do
      pc%have_vmax = .true.
      do j = 1, size(pc%fl)
         i = pc%fl(j)
         nd = pc%c_all(i)
         r = pc%c_owner(i)
         pc%cvold(:, nd) = rb(d(r) + 1:d(r) + 3)
         g%v(:, nd) = rb(d(r) + 4:d(r) + 6)
         d(r) = d(r) + 6
      end do
      pc%nval_recv = pc%nval_recv + size(rb) - size(sb)
      pc%ns_wex = pc%ns_wex + size(sb)*(np - 1)
      pc%t_comm = pc%t_comm + (par_wtime() - t0)
      pc%t_wex = pc%t_wex + (par_wtime() - t0)
      t0 = par_wtime()
      call contact_work(g, pc%cvold, dtavg, outdir, error)
      if (allocated(error)) call par_abort(error%message, error%code)   ! rank 0 alone
      if (g%db%sleout_dt > 0.0_wp) &
         call interface_work(g%contact, pc%cvold, g%v, dtavg)   ! per interface (sleout)
      model%energy%sliding = g%energy%sliding
      pc%t_cwork = pc%t_cwork + (par_wtime() - t0)
   end subroutine par_contact_work

   !> End of the run (rank 0 logs): contact time per cycle and the slave nodes per strip.
   subroutine par_contact_report(pc, g)
      type(par_contact_t), intent(in) :: pc
      type(model_t), intent(in) :: g
      real(wp) :: t(4), tm(4), rv, rvm
      integer, allocatable :: cnt(:)
      integer :: i, j, np
      character(:), allocatable :: line
      if (.not. pc%on) return
      np = par_size()
      t = [pc%t_cont, pc%t_comm, g%contact%t_search, g%contact%t_force - g%contact%t_search]/ &
          real(max(1, pc%ncycle), wp)
      tm = t
      call par_allreduce(tm, PAR_MAX)
      call par_allreduce(t, PAR_SUM)
      t = t/real(np, wp)
      rv = real(pc%nval_recv, wp)/real(max(1, pc%ncycle), wp)
      rvm = rv
      call par_allreduce(rv, PAR_SUM)
      call par_allreduce(rvm, PAR_MAX)
      call log_info('dynx: MPI contact: slave nodes split by '//trim(pc%split_mode)// &
                    ' (--contact-split)')
      call log_info('dynx: MPI contact: '//str(size(pc%c_all))//' contact nodes; numbers '// &
         'received per rank and cycle (x, v, work terms; without the results): mean '// &
         rstr(rv/real(par_size(), wp), 4)//', max '//rstr(rvm, 4))
      rv = real(pc%nres_recv, wp)/real(max(1, pc%ncycle), wp)
      rvm = rv
      call par_allreduce(rv, PAR_SUM)
      call par_allreduce(rvm, PAR_MAX)
      call log_info('dynx: MPI contact: numbers received per rank and cycle (results): '// &
         'mean '//rstr(rv/real(par_size(), wp), 4)//', max '//rstr(rvm, 4))
      call log_info('dynx: MPI contact: '//str(pc%ncycle)//' cycles, per cycle: search + '// &
         'forces '//rstr(1.0e6_wp*t(1), 4)//' us (max over ranks '//rstr(1.0e6_wp*tm(1), 4)// &
         '), contact communication '//rstr(1.0e6_wp*t(2), 4)//' us (max '// &
         rstr(1.0e6_wp*tm(2), 4)//'); of search + forces: bucket sorts and strips '// &
         rstr(1.0e6_wp*t(3), 4)//' us (max '//rstr(1.0e6_wp*tm(3), 4)//'), local search, '// &
         'forces and assembly '//rstr(1.0e6_wp*t(4), 4)//' us (max '// &
         rstr(1.0e6_wp*tm(4), 4)//'); means over the ranks')
      call stage_report(pc, g)
      allocate(cnt(0:np - 1))
      associate (cs => g%contact)
         do i = 1, size(cs%iface)
            do j = 1, size(cs%iface(i)%pass)
               associate (p => cs%iface(i)%pass(j))
                  cnt = 0
                  if (allocated(p%mine)) cnt(par_rank()) = count(p%mine)
                  call par_allreduce(cnt, PAR_SUM)
                  line = 'dynx: MPI contact: interface '//str(cs%iface(i)%label)//' pass '// &
                         str(j)//': slave nodes per rank (last sort, strip axis '// &
                         str(p%strip_axis)//'):'
                  do np = 0, size(cnt) - 1
                     line = line//' '//str(cnt(np))
                  end do
                  call log_info(line)
               end associate
            end do
         end do
      end associate
   end subroutine par_contact_report

   !> End of the run (rank 0 logs): time per stage and cycle (mean and max over the
   !> ranks) and the bytes each rank sends per cycle, by stage.
   subroutine stage_report(pc, g)
      type(par_contact_t), intent(in) :: pc
      type(model_t), intent(in) :: g
      real(wp) :: t(8), tm(8), b(4), bm(4), c
      character(:), allocatable :: line
      character(32), parameter :: tn(8) = [character(32) :: 'x, v exchange', 'bucket sorts', &
         'local search + forces', 'results exchange', 'assembly', 'work exchange', &
         'contact work', 'whole contact stage']
      character(16), parameter :: bn(4) = [character(16) :: 'x, v', 'results', 'work', 'total']
      integer :: k
      c = real(max(1, pc%ncycle), wp)
      t(1) = pc%t_xv
      t(2) = g%contact%t_search
      t(3) = g%contact%t_force - g%contact%t_search - pc%t_asm
      t(4) = pc%t_res
      t(5) = pc%t_asm
      t(6) = pc%t_wex
      t(7) = pc%t_cwork
      t(8) = sum(t(1:7))
      t = 1.0e6_wp*t/c
      tm = t
      call par_allreduce(tm, PAR_MAX)
      call par_allreduce(t, PAR_SUM)
      t = t/real(par_size(), wp)
      b = 8.0_wp*real([pc%ns_xv, pc%ns_res, pc%ns_wex, pc%ns_xv + pc%ns_res + pc%ns_wex], &
                      wp)/c
      bm = b
      call par_allreduce(bm, PAR_MAX)
      call par_allreduce(b, PAR_SUM)
      b = b/real(par_size(), wp)
      line = 'dynx: MPI contact stages per cycle [us], mean (max) over the ranks:'
      do k = 1, 8
         line = line//' '//trim(tn(k))//' '//rstr(t(k), 4)//' ('//rstr(tm(k), 4)//');'
      end do
      call log_info(line)
      line = 'dynx: MPI contact: bytes sent per rank and cycle, mean (max):'
      do k = 1, 4
         line = line//' '//trim(bn(k))//' '//rstr(b(k), 4)//' ('//rstr(bm(k), 4)//');'
      end do
      call log_info(line//' sorts with every contact node gathered '//str(pc%nfull)// &
                    ', ghost sorts '//str(pc%gh%nsort))
   end subroutine stage_report

end module dx_par_contact
