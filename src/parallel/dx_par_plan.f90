!> Exchange plans over the MPI wrapper (dx_par). Shared-node sums in a fixed order (the idea of
!> OpenRadioss's /PARITH/ON; the one shared-node exchange per cycle of ParaDyn, LLNL Engineering
!> Thrust Area Report FY97, article 4 of shared/seed): the force on a node shared by several
!> ranks is the sum of its elements' contributions taken in global element order (the serial
!> scatter order), whatever the partition. Each rank keeps its contributions to shared nodes
!> apart, tagged by their element's global order key; par_shared_setup exchanges the keys once
!> and builds, for each shared node, the merged list of contributions (own and received) sorted
!> by key; par_shared_sum then exchanges only the values, once per call, and every rank sharing
!> a node forms the same sum from 0 in the same order: bit for bit the serial sum.
!> The value exchange can be split (par_shared_post, par_shared_finish): the sends and receives
!> are posted as soon as the contributions are final and completed only when the sums are
!> needed, so the messages travel while the rank does other work (the overlap of
!> communication with computation of ParaDyn, Hoover et al., article 4 of shared/seed; there
!> the interior elements, here the dt MINLOC, contact and loads: the element order, and so
!> the serial bits, stay as they are). The value buffers and requests live in the plan and are
!> kept from call to call (no allocation per cycle).
!> Ordered gathers (par_gather_*): every rank's (key, value) pairs in key order, for sums formed
!> in the serial order. With one rank every plan is the identity (no MPI call).
!> Bytes sent are counted in dx_par (par_traffic_add: shared-node sums apart from other
!> point-to-point messages and collectives) for the end-of-run traffic line.
!> No module state: a plan is built once (setup) and passed to each call.
module dx_par_plan
   use mpi_f08, only: MPI_Allgatherv, MPI_DOUBLE_PRECISION, MPI_Gatherv, &
                        MPI_INTEGER, MPI_Irecv, MPI_Isend, MPI_Request, MPI_STATUSES_IGNORE, &
                        MPI_Waitall
   use dx_kinds, only: wp
   use dx_sort, only: sort_index
   use dx_par, only: par_comm, par_check, par_active, par_rank, par_size, par_displs, par_counts, &
                     par_traffic_add, PAR_T_EXCH, PAR_T_P2P, PAR_T_COLL
   implicit none
   private
   public :: shared_sum_t, par_shared_setup, par_shared_sum, par_shared_sum_plain, &
             par_shared_post, par_shared_finish, par_shared_drop, &
             gather_plan_t, par_gather_setup, par_gather_values, par_gather_ordered, &
             par_gather_setup_root, par_gather_values_root

   integer, parameter :: TAG_COUNT = 101, TAG_KEYS = 102, TAG_VALUES = 103

   !> A shared-node summation plan (built once, used every cycle).
   type :: shared_sum_t
      integer :: nshared = 0            !< shared nodes of this rank, numbered 1..nshared
      integer :: ncontrib = 0           !< own contributions to shared nodes
      integer, allocatable :: nbr(:)    !< neighbour ranks
      integer, allocatable :: send_ptr(:), send_idx(:)   !< own contributions sent to nbr(k)
      integer, allocatable :: recv_ptr(:)                !< received contributions from nbr(k)
      integer, allocatable :: ord_ptr(:), ord_src(:)     !< per shared node: sources by key
      integer, allocatable :: nbr_ptr(:), nbr_snode(:)   !< shared nodes of each neighbour
      !> the value exchange's buffers (kept between calls): own and received contributions
      !> (ncomp, ncontrib + received), the values sent, the requests; posted: an exchange
      !> was posted (par_shared_post) and not yet finished
      real(wp), allocatable :: buf(:, :), sendbuf(:, :)
      type(MPI_Request), allocatable :: req(:)
      logical :: posted = .false.
   end type shared_sum_t

   !> A fixed ordered gather (the same keys every call): counts, offsets and the key order
   !> are exchanged once, so each call is one MPI_Allgatherv of values.
   type :: gather_plan_t
      integer :: n = 0                      !< own entries
      integer, allocatable :: counts(:), displs(:)
      integer, allocatable :: keys(:)       !< all keys, ascending
      integer, allocatable :: perm(:)       !< position in the gathered array of keys(j)
   end type gather_plan_t

contains

   !> Build the plan. nshared: this rank's shared nodes (local numbering 1..nshared);
   !> nbr(k) the neighbour ranks and nbr_ptr/nbr_snode the shared nodes (local numbers) of
   !> each, listed in the same (global-node) order on both sides; c_node(i), c_key(i): the
   !> shared node and the global order key of own contribution i (keys distinct over all
   !> ranks for one node).
   subroutine par_shared_setup(plan, nshared, nbr, nbr_ptr, nbr_snode, c_node, c_key)
      type(shared_sum_t), intent(out) :: plan
      integer, intent(in) :: nshared, nbr(:), nbr_ptr(:), nbr_snode(:), c_node(:), c_key(:)
      integer :: nnb, k, i, j, s, nc, n, m, ierr, pos
      integer, allocatable :: own_ptr(:), own_lst(:), fill(:), cnt_send(:), cnt_recv(:)
      integer, allocatable :: keys_send(:), keys_recv(:), rcnt_ptr(:), rkey_ptr(:)
      integer, allocatable :: src(:), key(:)
      type(MPI_Request), allocatable :: req(:)
      nnb = size(nbr)
      nc = size(c_node)
      plan%nshared = nshared
      plan%ncontrib = nc
      plan%nbr = nbr
      plan%nbr_ptr = nbr_ptr
      plan%nbr_snode = nbr_snode
      ! own contributions per shared node, sorted by key
      allocate(own_ptr(nshared + 1), own_lst(nc), fill(nshared))
      own_ptr = 0
      do i = 1, nc
         own_ptr(c_node(i) + 1) = own_ptr(c_node(i) + 1) + 1
      end do
      own_ptr(1) = 1
      do s = 1, nshared
         own_ptr(s + 1) = own_ptr(s + 1) + own_ptr(s)
      end do
      fill = 0
      do i = 1, nc
         s = c_node(i)
         own_lst(own_ptr(s) + fill(s)) = i
         fill(s) = fill(s) + 1
      end do
      do s = 1, nshared
         call sort_by_key(own_lst(own_ptr(s):own_ptr(s + 1) - 1), c_key)
      end do
      ! what goes to neighbour k: for each node shared with k (in list order) its own
      ! contributions in key order; counts per node first, then keys
      allocate(plan%send_ptr(nnb + 1))
      plan%send_ptr(1) = 1
      do k = 1, nnb
         n = 0
         do j = nbr_ptr(k), nbr_ptr(k + 1) - 1
            s = nbr_snode(j)
            n = n + own_ptr(s + 1) - own_ptr(s)
         end do
         plan%send_ptr(k + 1) = plan%send_ptr(k) + n
      end do
      allocate(plan%send_idx(plan%send_ptr(nnb + 1) - 1))
      allocate(cnt_send(nbr_ptr(nnb + 1) - 1), cnt_recv(nbr_ptr(nnb + 1) - 1))
      pos = 0
      do k = 1, nnb
         do j = nbr_ptr(k), nbr_ptr(k + 1) - 1
            s = nbr_snode(j)
            cnt_send(j) = own_ptr(s + 1) - own_ptr(s)
            do i = own_ptr(s), own_ptr(s + 1) - 1
               pos = pos + 1
               plan%send_idx(pos) = own_lst(i)
            end do
         end do
      end do
      keys_send = c_key(plan%send_idx)
      allocate(req(2*nnb))
      if (nnb > 0) then
         do k = 1, nnb
            associate (a => nbr_ptr(k), b => nbr_ptr(k + 1) - 1)
               call MPI_Irecv(cnt_recv(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_COUNT, &
                              par_comm(), req(k), ierr)
               call par_check(ierr, 'MPI_Irecv (shared-node counts)')
               call MPI_Isend(cnt_send(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_COUNT, &
                              par_comm(), req(nnb + k), ierr)
               call par_check(ierr, 'MPI_Isend (shared-node counts)')
            end associate
         end do
         call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
         call par_check(ierr, 'MPI_Waitall (shared-node counts)')
         call par_traffic_add(PAR_T_P2P, 4*size(cnt_send, kind=8))
      end if
      ! received contributions from neighbour k: recv_ptr
      allocate(plan%recv_ptr(nnb + 1), rcnt_ptr(size(cnt_recv) + 1))
      plan%recv_ptr(1) = 1
      do k = 1, nnb
         plan%recv_ptr(k + 1) = plan%recv_ptr(k) + sum(cnt_recv(nbr_ptr(k):nbr_ptr(k + 1) - 1))
      end do
      rcnt_ptr(1) = 1
      do j = 1, size(cnt_recv)
         rcnt_ptr(j + 1) = rcnt_ptr(j) + cnt_recv(j)
      end do
      allocate(keys_recv(plan%recv_ptr(nnb + 1) - 1))
      if (nnb > 0) then
         do k = 1, nnb
            associate (a => plan%recv_ptr(k), b => plan%recv_ptr(k + 1) - 1, &
                       c => plan%send_ptr(k), d => plan%send_ptr(k + 1) - 1)
               call MPI_Irecv(keys_recv(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_KEYS, &
                              par_comm(), req(k), ierr)
               call par_check(ierr, 'MPI_Irecv (shared-node keys)')
               call MPI_Isend(keys_send(c:d), d - c + 1, MPI_INTEGER, nbr(k), TAG_KEYS, &
                              par_comm(), req(nnb + k), ierr)
               call par_check(ierr, 'MPI_Isend (shared-node keys)')
            end associate
         end do
         call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
         call par_check(ierr, 'MPI_Waitall (shared-node keys)')
         call par_traffic_add(PAR_T_P2P, 4*size(keys_send, kind=8))
      end if
      ! per shared node: all sources (own i -> i; received j -> nc + j), sorted by key
      allocate(rkey_ptr(nshared + 1))
      rkey_ptr = 0
      do j = 1, size(cnt_recv)
         s = nbr_snode(j)
         rkey_ptr(s + 1) = rkey_ptr(s + 1) + cnt_recv(j)
      end do
      allocate(plan%ord_ptr(nshared + 1))
      plan%ord_ptr(1) = 1
      do s = 1, nshared
         plan%ord_ptr(s + 1) = plan%ord_ptr(s) + (own_ptr(s + 1) - own_ptr(s)) + rkey_ptr(s + 1)
      end do
      allocate(plan%ord_src(plan%ord_ptr(nshared + 1) - 1))
      allocate(key(nc + size(keys_recv)))
      key(1:nc) = c_key
      key(nc + 1:) = keys_recv
      fill = 0
      do s = 1, nshared
         do i = own_ptr(s), own_ptr(s + 1) - 1
            plan%ord_src(plan%ord_ptr(s) + fill(s)) = own_lst(i)
            fill(s) = fill(s) + 1
         end do
      end do
      do j = 1, size(cnt_recv)
         s = nbr_snode(j)
         do m = rcnt_ptr(j), rcnt_ptr(j + 1) - 1
            plan%ord_src(plan%ord_ptr(s) + fill(s)) = nc + m
            fill(s) = fill(s) + 1
         end do
      end do
      do s = 1, nshared
         src = plan%ord_src(plan%ord_ptr(s):plan%ord_ptr(s + 1) - 1)
         call sort_by_key(src, key)
         plan%ord_src(plan%ord_ptr(s):plan%ord_ptr(s + 1) - 1) = src
      end do
   end subroutine par_shared_setup

   !> Sort the indices idx by key(idx) (insertion sort: a node has a few dozen at most).
   subroutine sort_by_key(idx, key)
      integer, intent(inout) :: idx(:)
      integer, intent(in) :: key(:)
      integer :: i, j, t
      do i = 2, size(idx)
         t = idx(i)
         j = i - 1
         do while (j >= 1)
            if (key(idx(j)) <= key(t)) exit
            idx(j + 1) = idx(j)
            j = j - 1
         end do
         idx(j + 1) = t
      end do
   end subroutine sort_by_key

   !> res(:, s) = sum over all ranks' contributions to shared node s, from 0 in key order;
   !> cval(:, i) is own contribution i (as in par_shared_setup). One exchange.
   subroutine par_shared_sum(plan, cval, res)
      type(shared_sum_t), intent(inout), asynchronous :: plan
      real(wp), intent(in) :: cval(:, :)
      real(wp), intent(out) :: res(:, :)
      integer :: s
      call par_shared_post(plan, cval)
      call par_shared_finish(plan, res, [(s, s = 1, plan%nshared)])
   end subroutine par_shared_sum

   !> First half of par_shared_sum: own contributions cval(ncomp, ncontrib) copied into the
   !> plan's buffers, the receives and sends posted (no wait). cval may change afterwards;
   !> every rank must call par_shared_finish (or par_shared_drop) before the plan's next use.
   subroutine par_shared_post(plan, cval)
      type(shared_sum_t), intent(inout), asynchronous :: plan
      real(wp), intent(in) :: cval(:, :)
      integer :: nc, nr, ncomp, k, ierr, nnb
      if (plan%posted) error stop 'dx_par_plan: shared-node exchange posted twice'
      ncomp = size(cval, 1)
      nc = plan%ncontrib
      nnb = size(plan%nbr)
      nr = plan%recv_ptr(nnb + 1) - 1
      if (allocated(plan%buf)) then
         if (size(plan%buf, 1) /= ncomp) deallocate(plan%buf, plan%sendbuf)
      end if
      if (.not. allocated(plan%buf)) then
         allocate(plan%buf(ncomp, nc + nr), plan%sendbuf(ncomp, plan%send_ptr(nnb + 1) - 1))
         allocate(plan%req(2*nnb))
      end if
      plan%buf(:, 1:nc) = cval(:, 1:nc)
      plan%posted = .true.
      if (nnb == 0) return
      do k = 1, size(plan%send_idx)
         plan%sendbuf(:, k) = cval(:, plan%send_idx(k))
      end do
      do k = 1, nnb
         associate (a => plan%recv_ptr(k), b => plan%recv_ptr(k + 1) - 1, &
                    c => plan%send_ptr(k), d => plan%send_ptr(k + 1) - 1)
            call MPI_Irecv(plan%buf(:, nc + a:nc + b), ncomp*(b - a + 1), &
                           MPI_DOUBLE_PRECISION, plan%nbr(k), TAG_VALUES, par_comm(), &
                           plan%req(k), ierr)
            call par_check(ierr, 'MPI_Irecv (shared-node sum)')
            call MPI_Isend(plan%sendbuf(:, c:d), ncomp*(d - c + 1), MPI_DOUBLE_PRECISION, &
                           plan%nbr(k), TAG_VALUES, par_comm(), plan%req(nnb + k), ierr)
            call par_check(ierr, 'MPI_Isend (shared-node sum)')
         end associate
      end do
      call par_traffic_add(PAR_T_EXCH, 8*size(plan%sendbuf, kind=8))
   end subroutine par_shared_post

   !> Second half: wait for the posted exchange, then res(:, idx(s)) = the sum at shared
   !> node s in key order (idx: where each shared node's sum goes, e.g. its local node).
   subroutine par_shared_finish(plan, res, idx)
      type(shared_sum_t), intent(inout), asynchronous :: plan
      real(wp), intent(inout) :: res(:, :)
      integer, intent(in) :: idx(:)
      integer :: s, i, j
      real(wp) :: a1, a2, a3
      call wait_posted(plan)
      if (size(plan%buf, 1) == 3) then   ! forces, moments: the sums in registers
         do s = 1, plan%nshared
            a1 = 0.0_wp; a2 = 0.0_wp; a3 = 0.0_wp
            do i = plan%ord_ptr(s), plan%ord_ptr(s + 1) - 1
               j = plan%ord_src(i)
               a1 = a1 + plan%buf(1, j)
               a2 = a2 + plan%buf(2, j)
               a3 = a3 + plan%buf(3, j)
            end do
            res(1, idx(s)) = a1; res(2, idx(s)) = a2; res(3, idx(s)) = a3
         end do
         return
      end if
      do s = 1, plan%nshared
         res(:, idx(s)) = 0.0_wp
         do i = plan%ord_ptr(s), plan%ord_ptr(s + 1) - 1
            res(:, idx(s)) = res(:, idx(s)) + plan%buf(:, plan%ord_src(i))
         end do
      end do
   end subroutine par_shared_finish

   !> A posted exchange whose sums are not wanted (a failure stops the cycle): completed
   !> (every rank posted its sends) and discarded. Nothing when none is posted.
   subroutine par_shared_drop(plan)
      type(shared_sum_t), intent(inout), asynchronous :: plan
      if (plan%posted) call wait_posted(plan)
   end subroutine par_shared_drop

   subroutine wait_posted(plan)
      type(shared_sum_t), intent(inout), asynchronous :: plan
      integer :: ierr
      if (.not. plan%posted) error stop 'dx_par_plan: shared-node exchange not posted'
      plan%posted = .false.
      if (size(plan%nbr) == 0) return
      call MPI_Waitall(size(plan%req), plan%req, MPI_STATUSES_IGNORE, ierr)
      call par_check(ierr, 'MPI_Waitall (shared-node sum)')
   end subroutine wait_posted

   !> The plain alternative, for comparison: partial(:, s) is this rank's own sum at shared
   !> node s; res(:, s) adds the holders' partial sums in rank order. Deterministic for a
   !> given partition, but not the serial sum (the partials round differently); one exchange.
   subroutine par_shared_sum_plain(plan, partial, res)
      type(shared_sum_t), intent(in) :: plan
      real(wp), intent(in) :: partial(:, :)
      real(wp), intent(out) :: res(:, :)
      real(wp), allocatable :: rbuf(:, :), sbuf(:, :)
      type(MPI_Request), allocatable :: req(:)
      integer :: ncomp, nnb, k, j, ierr
      logical :: own_added
      ncomp = size(partial, 1)
      nnb = size(plan%nbr)
      res(:, 1:plan%nshared) = 0.0_wp
      if (nnb == 0) then
         res(:, 1:plan%nshared) = partial(:, 1:plan%nshared)
         return
      end if
      sbuf = partial(:, plan%nbr_snode)
      allocate(rbuf(ncomp, size(plan%nbr_snode)), req(2*nnb))
      do k = 1, nnb
         associate (a => plan%nbr_ptr(k), b => plan%nbr_ptr(k + 1) - 1)
            call MPI_Irecv(rbuf(:, a:b), ncomp*(b - a + 1), MPI_DOUBLE_PRECISION, plan%nbr(k), &
                           TAG_VALUES, par_comm(), req(k), ierr)
            call par_check(ierr, 'MPI_Irecv (plain shared-node sum)')
            call MPI_Isend(sbuf(:, a:b), ncomp*(b - a + 1), MPI_DOUBLE_PRECISION, plan%nbr(k), &
                           TAG_VALUES, par_comm(), req(nnb + k), ierr)
            call par_check(ierr, 'MPI_Isend (plain shared-node sum)')
         end associate
      end do
      call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
      call par_check(ierr, 'MPI_Waitall (plain shared-node sum)')
      call par_traffic_add(PAR_T_EXCH, 8*size(sbuf, kind=8))
      ! neighbours in ascending rank order; own partial in its place
      own_added = .false.
      do k = 1, nnb
         if (.not. own_added .and. plan%nbr(k) > par_rank()) then
            res(:, 1:plan%nshared) = res(:, 1:plan%nshared) + partial(:, 1:plan%nshared)
            own_added = .true.
         end if
         do j = plan%nbr_ptr(k), plan%nbr_ptr(k + 1) - 1
            res(:, plan%nbr_snode(j)) = res(:, plan%nbr_snode(j)) + rbuf(:, j)
         end do
      end do
      if (.not. own_added) res(:, 1:plan%nshared) = res(:, 1:plan%nshared) + &
                                                    partial(:, 1:plan%nshared)
   end subroutine par_shared_sum_plain

   !> Every rank's (key, value) pairs, gathered on every rank and sorted by key (keys distinct
   !> over all ranks): the caller then sums them in the serial order and structure (for
   !> energies, kinetic energy and momentum at output times). vals(ncomp, n).
   subroutine par_gather_ordered(keys, vals, all_keys, all_vals)
      integer, intent(in) :: keys(:)
      real(wp), intent(in) :: vals(:, :)
      integer, allocatable, intent(out) :: all_keys(:)
      real(wp), allocatable, intent(out) :: all_vals(:, :)
      integer, allocatable :: counts(:), displs(:), idx(:), kk(:)
      real(wp), allocatable :: vv(:, :)
      integer :: ncomp, ntot, ierr, i
      ncomp = size(vals, 1)
      if (.not. par_active()) then
         kk = keys
         vv = vals
      else
         counts = par_counts(size(keys))
         displs = par_displs(counts)
         ntot = sum(counts)
         allocate(kk(ntot), vv(ncomp, ntot))
         call MPI_Allgatherv(keys, size(keys), MPI_INTEGER, kk, counts, displs, MPI_INTEGER, &
                             par_comm(), ierr)
         call par_check(ierr, 'MPI_Allgatherv (ordered gather keys)')
         call MPI_Allgatherv(vals, size(vals), MPI_DOUBLE_PRECISION, vv, ncomp*counts, &
                             ncomp*displs, MPI_DOUBLE_PRECISION, par_comm(), ierr)
         call par_check(ierr, 'MPI_Allgatherv (ordered gather values)')
         call par_traffic_add(PAR_T_COLL, 4*size(keys, kind=8) + 8*size(vals, kind=8))
      end if
      idx = [(i, i = 1, size(kk))]
      call sort_index(idx, kk)
      all_keys = kk(idx)
      all_vals = vv(:, idx)
   end subroutine par_gather_ordered

   !> Build a fixed gather plan from this rank's keys (distinct over all ranks).
   subroutine par_gather_setup(plan, keys)
      type(gather_plan_t), intent(out) :: plan
      integer, intent(in) :: keys(:)
      integer, allocatable :: kk(:)
      integer :: ierr, i
      plan%n = size(keys)
      if (.not. par_active()) then
         kk = keys
         plan%counts = [size(keys)]
         plan%displs = [0]
      else
         call plan_counts(plan, size(keys))
         allocate(kk(sum(plan%counts)))
         call MPI_Allgatherv(keys, size(keys), MPI_INTEGER, kk, plan%counts, plan%displs, &
                             MPI_INTEGER, par_comm(), ierr)
         call par_check(ierr, 'MPI_Allgatherv (gather plan keys)')
         call par_traffic_add(PAR_T_COLL, 4*size(keys, kind=8))
      end if
      plan%perm = [(i, i = 1, size(kk))]
      call sort_index(plan%perm, kk)
      plan%keys = kk(plan%perm)
   end subroutine par_gather_setup

   !> One call of a fixed gather: vals(ncomp, plan%n) from every rank, ordered as plan%keys.
   subroutine par_gather_values(plan, vals, all_vals)
      type(gather_plan_t), intent(in) :: plan
      real(wp), intent(in) :: vals(:, :)
      real(wp), intent(out) :: all_vals(:, :)
      call gather_values(plan, vals, all_vals, .false.)
   end subroutine par_gather_values

   !> plan%counts (0:np-1, every rank's number of keys) and plan%displs.
   subroutine plan_counts(plan, n)
      type(gather_plan_t), intent(inout) :: plan
      integer, intent(in) :: n
      allocate(plan%counts(0:par_size() - 1), plan%displs(0:par_size() - 1))
      plan%counts = par_counts(n)
      plan%displs = par_displs(plan%counts)
   end subroutine plan_counts

   !> par_gather_setup for a gather to rank 0 only (par_gather_values_root): rank 0 gets
   !> every rank's keys (plan%keys, ascending; plan%perm), the other ranks keep only the
   !> counts (plan%counts: sum(plan%counts) is the total everywhere; keys and perm are empty
   !> there), so no rank but 0 holds the whole key list.
   subroutine par_gather_setup_root(plan, keys)
      type(gather_plan_t), intent(out) :: plan
      integer, intent(in) :: keys(:)
      integer, allocatable :: kk(:)
      integer :: ierr, i
      plan%n = size(keys)
      if (.not. par_active()) then
         call par_gather_setup(plan, keys)
         return
      end if
      call plan_counts(plan, size(keys))
      allocate(kk(merge(sum(plan%counts), 0, par_rank() == 0)))
      call MPI_Gatherv(keys, size(keys), MPI_INTEGER, kk, plan%counts, plan%displs, &
                       MPI_INTEGER, 0, par_comm(), ierr)
      call par_check(ierr, 'MPI_Gatherv (root gather plan keys)')
      call par_traffic_add(PAR_T_COLL, 4*size(keys, kind=8))
      plan%perm = [(i, i = 1, size(kk))]
      call sort_index(plan%perm, kk)
      plan%keys = kk(plan%perm)
   end subroutine par_gather_setup_root

   !> One call of a root plan (par_gather_setup_root): vals(ncomp, plan%n) from every rank
   !> into all_vals(ncomp, size(plan%keys)) on rank 0, ordered as plan%keys (the same
   !> numbers par_gather_values gives every rank); all_vals is not touched on other ranks.
   subroutine par_gather_values_root(plan, vals, all_vals)
      type(gather_plan_t), intent(in) :: plan
      real(wp), intent(in) :: vals(:, :)
      real(wp), intent(inout) :: all_vals(:, :)
      call gather_values(plan, vals, all_vals, .true.)
   end subroutine par_gather_values_root

   !> The gather of a plan: to every rank (MPI_Allgatherv) or to rank 0 only (MPI_Gatherv,
   !> all_vals untouched elsewhere); serial: this rank's values in key order.
   subroutine gather_values(plan, vals, all_vals, root)
      type(gather_plan_t), intent(in) :: plan
      real(wp), intent(in) :: vals(:, :)
      real(wp), intent(inout) :: all_vals(:, :)
      logical, intent(in) :: root
      real(wp), allocatable :: vv(:, :)
      integer :: ncomp, ierr
      ncomp = size(vals, 1)
      if (.not. par_active()) then
         all_vals(:, 1:plan%n) = vals(:, plan%perm)
         return
      end if
      allocate(vv(ncomp, size(plan%keys)))
      call par_traffic_add(PAR_T_COLL, 8*ncomp*int(plan%n, 8))
      if (root) then
         call MPI_Gatherv(vals, ncomp*plan%n, MPI_DOUBLE_PRECISION, vv, ncomp*plan%counts, &
                          ncomp*plan%displs, MPI_DOUBLE_PRECISION, 0, par_comm(), ierr)
         call par_check(ierr, 'MPI_Gatherv (root gather plan values)')
         if (par_rank() == 0) all_vals(:, 1:size(plan%keys)) = vv(:, plan%perm)
      else
         call MPI_Allgatherv(vals, ncomp*plan%n, MPI_DOUBLE_PRECISION, vv, ncomp*plan%counts, &
                             ncomp*plan%displs, MPI_DOUBLE_PRECISION, par_comm(), ierr)
         call par_check(ierr, 'MPI_Allgatherv (gather plan values)')
         all_vals(:, 1:size(plan%keys)) = vv(:, plan%perm)
      end if
   end subroutine gather_values
end module dx_par_plan
