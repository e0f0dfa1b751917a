!> The MPI layer: the only module that uses mpi_f08. A serial run needs no mpirun: MPI_Init
!> is called only when the process was started by an MPI launcher (Open MPI's
!> OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK), and every call below is then a no-op with
!> one rank (no separate serial code path).
!>
!> Shared-node sums in a fixed order (the idea of OpenRadioss's /PARITH/ON; the one shared-
!> node exchange per cycle of ParaDyn, LLNL Engineering Thrust Area Report FY97, article 4
!> of shared/seed): the force on a node shared by several ranks is the sum of its elements'
!> contributions taken in global element order (the serial scatter order), whatever the
!> partition. Each rank keeps its contributions to shared nodes apart, tagged by their
!> element's global order key; par_shared_setup exchanges the keys once and builds, for each
!> shared node, the merged list of contributions (own and received) sorted by key;
!> par_shared_sum then exchanges only the values, once per call, and every rank sharing a
!> node forms the same sum from 0 in the same order: bit for bit the serial sum.
!> Module state: the communicator, this rank, the number of ranks, whether MPI is on.
module dx_par
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use mpi_f08
   use dx_kinds, only: wp
   use dx_sort, only: sort_index
   use dx_error, only: error_t, set_error, exit_process, EXIT_NUMERIC
   use dx_strings, only: str
   implicit none
   private
   public :: par_init, par_finalize, par_rank, par_size, par_active, par_barrier, &
             par_allreduce, par_abort, shared_sum_t, par_shared_setup, par_shared_sum, &
             par_shared_sum_plain, par_wtime, par_minloc, par_gather_ordered, PAR_SUM, &
             gather_plan_t, par_gather_setup, par_gather_values, &
             PAR_MIN, PAR_MAX, par_bcast_text, par_minloc_flags, par_alltoallv
   public :: par_gather_setup_root, par_gather_values_root, par_bcast_real, par_minloc8
   public :: par_allgatherv_real, par_sparse_exchange, par_allgather_probe   ! (contact)

   integer, parameter :: PAR_SUM = 1, PAR_MIN = 2, PAR_MAX = 3
   integer, parameter :: TAG_COUNT = 101, TAG_KEYS = 102, TAG_VALUES = 103

   type(MPI_Comm), save :: comm
   logical, save :: mpi_on = .false.
   integer, save :: my_rank = 0, nranks = 1

   !> A shared-node summation plan (built once, used every cycle).
   type :: shared_sum_t
      integer :: nshared = 0            !< shared nodes of this rank, numbered 1..nshared
      integer :: ncontrib = 0           !< own contributions to shared nodes
      integer, allocatable :: nbr(:)    !< neighbour ranks
      integer, allocatable :: send_ptr(:), send_idx(:)   !< own contributions sent to nbr(k)
      integer, allocatable :: recv_ptr(:)                !< received contributions from nbr(k)
      integer, allocatable :: ord_ptr(:), ord_src(:)     !< per shared node: sources by key
      integer, allocatable :: nbr_ptr(:), nbr_snode(:)   !< shared nodes of each neighbour
   end type shared_sum_t

   !> A fixed ordered gather (the same keys every call): counts, offsets and the key order
   !> are exchanged once, so each call is one MPI_Allgatherv of values.
   type :: gather_plan_t
      integer :: n = 0                      !< own entries
      integer, allocatable :: counts(:), displs(:)
      integer, allocatable :: keys(:)       !< all keys, ascending
      integer, allocatable :: perm(:)       !< position in the gathered array of keys(j)
   end type gather_plan_t

   interface par_allreduce
      module procedure allreduce_r0, allreduce_r1, allreduce_i0, allreduce_i1
   end interface par_allreduce

   !> Personalized all-to-all exchange (MPI_Alltoallv): sbuf(scnt(0)) to rank 0, then
   !> scnt(1) to rank 1, ...; rbuf likewise by rcnt (counts in elements, 0:np-1).
   interface par_alltoallv
      module procedure alltoallv_i, alltoallv_r
   end interface par_alltoallv

contains

   !> Start MPI when launched by mpirun/srun (else run serial with one rank).
   subroutine par_init(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: ierr, l
      logical :: launched
      launched = .false.
      call get_environment_variable('OMPI_COMM_WORLD_SIZE', length=l)
      if (l > 0) launched = .true.
      call get_environment_variable('PMI_SIZE', length=l)
      if (l > 0) launched = .true.
      call get_environment_variable('PMIX_RANK', length=l)
      if (l > 0) launched = .true.
      if (.not. launched) return
      call MPI_Init(ierr)
      if (ierr /= MPI_SUCCESS) then
         call set_error(error, 'MPI_Init failed (code '//str(ierr)//')', EXIT_NUMERIC)
         return
      end if
      call MPI_Comm_dup(MPI_COMM_WORLD, comm, ierr)
      call check(ierr, 'MPI_Comm_dup')
      ! errors come back as codes, so a failing call can abort all ranks with a message
      call MPI_Comm_set_errhandler(comm, MPI_ERRORS_RETURN, ierr)
      call check(ierr, 'MPI_Comm_set_errhandler')
      call MPI_Comm_rank(comm, my_rank, ierr)
      call check(ierr, 'MPI_Comm_rank')
      call MPI_Comm_size(comm, nranks, ierr)
      call check(ierr, 'MPI_Comm_size')
      mpi_on = .true.
   end subroutine par_init

   !> Finalize MPI if it was started.
   subroutine par_finalize()
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Comm_free(comm, ierr)
      call MPI_Finalize(ierr)
      mpi_on = .false.
   end subroutine par_finalize

   integer function par_rank()
      par_rank = my_rank
   end function par_rank

   integer function par_size()
      par_size = nranks
   end function par_size

   !> Whether MPI was started (false for a serial run).
   logical function par_active()
      par_active = mpi_on
   end function par_active

   subroutine par_barrier()
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Barrier(comm, ierr)
      call check(ierr, 'MPI_Barrier')
   end subroutine par_barrier

   !> Stop every rank: the message names this rank; exit code code (MPI_Abort under MPI).
   subroutine par_abort(msg, code)
      character(*), intent(in) :: msg
      integer, intent(in) :: code
      integer :: ierr
      if (mpi_on) then
         write(error_unit, '(a)') 'dynx: error: rank '//str(my_rank)//' of '//str(nranks)// &
            ': '//msg
         flush(error_unit)
         call MPI_Abort(MPI_COMM_WORLD, code, ierr)
      end if
      write(error_unit, '(a)') 'dynx: error: '//msg
      call exit_process(code)
   end subroutine par_abort

   !> A failed MPI call aborts all ranks, naming the call and the rank.
   subroutine check(ierr, what)
      integer, intent(in) :: ierr
      character(*), intent(in) :: what
      character(len=MPI_MAX_ERROR_STRING) :: s
      integer :: l, ie
      if (ierr == MPI_SUCCESS) return
      call MPI_Error_string(ierr, s, l, ie)
      call par_abort(what//' failed: '//s(1:l), EXIT_NUMERIC)
   end subroutine check

   function reduce_op(op) result(o)
      integer, intent(in) :: op
      type(MPI_Op) :: o
      select case (op)
      case (PAR_MIN)
         o = MPI_MIN
      case (PAR_MAX)
         o = MPI_MAX
      case default
         o = MPI_SUM
      end select
   end function reduce_op

   !> x = op over ranks of x (PAR_SUM, PAR_MIN, PAR_MAX); all ranks get the result.
   !> A sum over ranks depends on MPI's reduction order: use it for counts and flags, and
   !> the fixed-order paths for anything that must match the serial run bit for bit.
   subroutine allreduce_r0(x, op)
      real(wp), intent(inout) :: x
      integer, intent(in) :: op
      real(wp) :: y(1)
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce([x], y, 1, MPI_DOUBLE_PRECISION, reduce_op(op), comm, ierr)
      call check(ierr, 'MPI_Allreduce')
      x = y(1)
   end subroutine allreduce_r0

   subroutine allreduce_r1(x, op)
      real(wp), intent(inout) :: x(:)
      integer, intent(in) :: op
      real(wp) :: y(size(x))
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce(x, y, size(x), MPI_DOUBLE_PRECISION, reduce_op(op), comm, ierr)
      call check(ierr, 'MPI_Allreduce')
      x = y
   end subroutine allreduce_r1

   subroutine allreduce_i0(x, op)
      integer, intent(inout) :: x
      integer, intent(in) :: op
      integer :: y(1)
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce([x], y, 1, MPI_INTEGER, reduce_op(op), comm, ierr)
      call check(ierr, 'MPI_Allreduce')
      x = y(1)
   end subroutine allreduce_i0

   subroutine allreduce_i1(x, op)
      integer, intent(inout) :: x(:)
      integer, intent(in) :: op
      integer :: y(size(x))
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce(x, y, size(x), MPI_INTEGER, reduce_op(op), comm, ierr)
      call check(ierr, 'MPI_Allreduce')
      x = y
   end subroutine allreduce_i1

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
               call MPI_Irecv(cnt_recv(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_COUNT, comm, &
                              req(k), ierr)
               call check(ierr, 'MPI_Irecv (shared-node counts)')
               call MPI_Isend(cnt_send(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_COUNT, comm, &
                              req(nnb + k), ierr)
               call check(ierr, 'MPI_Isend (shared-node counts)')
            end associate
         end do
         call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
         call check(ierr, 'MPI_Waitall (shared-node counts)')
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
               call MPI_Irecv(keys_recv(a:b), b - a + 1, MPI_INTEGER, nbr(k), TAG_KEYS, comm, &
                              req(k), ierr)
               call check(ierr, 'MPI_Irecv (shared-node keys)')
               call MPI_Isend(keys_send(c:d), d - c + 1, MPI_INTEGER, nbr(k), TAG_KEYS, comm, &
                              req(nnb + k), ierr)
               call check(ierr, 'MPI_Isend (shared-node keys)')
            end associate
         end do
         call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
         call check(ierr, 'MPI_Waitall (shared-node keys)')
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
      type(shared_sum_t), intent(in) :: plan
      real(wp), intent(in) :: cval(:, :)
      real(wp), intent(out) :: res(:, :)
      real(wp), allocatable :: buf(:, :), sendbuf(:, :)
      type(MPI_Request), allocatable :: req(:)
      integer :: nc, nr, ncomp, k, s, i, ierr, nnb
      ncomp = size(cval, 1)
      nc = plan%ncontrib
      nnb = size(plan%nbr)
      nr = plan%recv_ptr(nnb + 1) - 1
      allocate(buf(ncomp, nc + nr))
      buf(:, 1:nc) = cval(:, 1:nc)
      if (nnb > 0) then
         sendbuf = cval(:, plan%send_idx)
         allocate(req(2*nnb))
         do k = 1, nnb
            associate (a => plan%recv_ptr(k), b => plan%recv_ptr(k + 1) - 1, &
                       c => plan%send_ptr(k), d => plan%send_ptr(k + 1) - 1)
               call MPI_Irecv(buf(:, nc + a:nc + b), ncomp*(b - a + 1), MPI_DOUBLE_PRECISION, &
                              plan%nbr(k), TAG_VALUES, comm, req(k), ierr)
               call check(ierr, 'MPI_Irecv (shared-node sum)')
               call MPI_Isend(sendbuf(:, c:d), ncomp*(d - c + 1), MPI_DOUBLE_PRECISION, &
                              plan%nbr(k), TAG_VALUES, comm, req(nnb + k), ierr)
               call check(ierr, 'MPI_Isend (shared-node sum)')
            end associate
         end do
         call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
         call check(ierr, 'MPI_Waitall (shared-node sum)')
      end if
      do s = 1, plan%nshared
         res(:, s) = 0.0_wp
         do i = plan%ord_ptr(s), plan%ord_ptr(s + 1) - 1
            res(:, s) = res(:, s) + buf(:, plan%ord_src(i))
         end do
      end do
   end subroutine par_shared_sum

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
                           TAG_VALUES, comm, req(k), ierr)
            call check(ierr, 'MPI_Irecv (plain shared-node sum)')
            call MPI_Isend(sbuf(:, a:b), ncomp*(b - a + 1), MPI_DOUBLE_PRECISION, plan%nbr(k), &
                           TAG_VALUES, comm, req(nnb + k), ierr)
            call check(ierr, 'MPI_Isend (plain shared-node sum)')
         end associate
      end do
      call MPI_Waitall(2*nnb, req, MPI_STATUSES_IGNORE, ierr)
      call check(ierr, 'MPI_Waitall (plain shared-node sum)')
      ! neighbours in ascending rank order; own partial in its place
      own_added = .false.
      do k = 1, nnb
         if (.not. own_added .and. plan%nbr(k) > my_rank) then
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

   !> Broadcast a message and an integer code from rank root (a failure found on one rank,
   !> made known to all: dx_par_engine). On the other ranks text is replaced.
   subroutine par_bcast_text(text, code, root)
      character(:), allocatable, intent(inout) :: text
      integer, intent(inout) :: code
      integer, intent(in) :: root
      integer :: n(2), ierr
      if (.not. mpi_on) return
      n = 0
      if (my_rank == root) n = [len(text), code]
      call MPI_Bcast(n, 2, MPI_INTEGER, root, comm, ierr)
      call check(ierr, 'MPI_Bcast (failure message length)')
      if (my_rank /= root) then
         if (allocated(text)) deallocate(text)
         allocate(character(n(1)) :: text)
      end if
      code = n(2)
      if (n(1) > 0) then
         call MPI_Bcast(text, n(1), MPI_CHARACTER, root, comm, ierr)
         call check(ierr, 'MPI_Bcast (failure message)')
      end if
   end subroutine par_bcast_text
   subroutine alltoallv_i(sbuf, scnt, rbuf, rcnt)
      integer, intent(in) :: sbuf(:), scnt(0:)
      integer, intent(out) :: rbuf(:)
      integer, intent(in) :: rcnt(0:)
      integer, allocatable :: sd(:), rd(:)
      integer :: r, ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         return
      end if
      allocate(sd(0:nranks - 1), rd(0:nranks - 1))
      sd(0) = 0; rd(0) = 0
      do r = 1, nranks - 1
         sd(r) = sd(r - 1) + scnt(r - 1)
         rd(r) = rd(r - 1) + rcnt(r - 1)
      end do
      call MPI_Alltoallv(sbuf, scnt, sd, MPI_INTEGER, rbuf, rcnt, rd, MPI_INTEGER, comm, ierr)
      call check(ierr, 'MPI_Alltoallv (integer)')
   end subroutine alltoallv_i

   subroutine alltoallv_r(sbuf, scnt, rbuf, rcnt)
      real(wp), intent(in) :: sbuf(:)
      integer, intent(in) :: scnt(0:)
      real(wp), intent(out) :: rbuf(:)
      integer, intent(in) :: rcnt(0:)
      integer, allocatable :: sd(:), rd(:)
      integer :: r, ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         return
      end if
      allocate(sd(0:nranks - 1), rd(0:nranks - 1))
      sd(0) = 0; rd(0) = 0
      do r = 1, nranks - 1
         sd(r) = sd(r - 1) + scnt(r - 1)
         rd(r) = rd(r - 1) + rcnt(r - 1)
      end do
      call MPI_Alltoallv(sbuf, scnt, sd, MPI_DOUBLE_PRECISION, rbuf, rcnt, rd, &
                         MPI_DOUBLE_PRECISION, comm, ierr)
      call check(ierr, 'MPI_Alltoallv (real)')
   end subroutine alltoallv_r

   !> The global minimum of x and, among ranks holding it, the lowest key (the serial loop's
   !> first minimum): for the stable time step and its controlling element. key < 2**53.
   subroutine par_minloc(x, key)
      real(wp), intent(inout) :: x
      integer, intent(inout) :: key
      real(wp) :: pin(2, 1), pout(2, 1)
      integer :: ierr
      if (.not. mpi_on) return
      ! MPI_MINLOC takes the lowest index among equal values, exactly the tie rule wanted
      pin(1, 1) = x
      pin(2, 1) = real(key, wp)
      call MPI_Allreduce(pin, pout, 1, MPI_2DOUBLE_PRECISION, MPI_MINLOC, comm, ierr)
      call check(ierr, 'MPI_Allreduce (MINLOC)')
      x = pout(1, 1)
      key = nint(pout(2, 1))
   end subroutine par_minloc

   !> par_minloc with flags folded into the same reduction (no extra synchronization): the
   !> MINLOC runs on 1 + size(flags) (value, index) pairs at once; flag k travels as the pair
   !> (-flags(k), 0), so its minimum is the largest flag over the ranks. Used for the
   !> collective stop/dump decision of an MPI run (dx_checkpoint): a signal that reached one
   !> rank, or one rank's wall-clock limit, becomes every rank's decision in the same cycle.
   subroutine par_minloc_flags(x, key, flags)
      real(wp), intent(inout) :: x
      integer, intent(inout) :: key
      integer, intent(inout) :: flags(:)
      real(wp) :: pin(2, 1 + size(flags)), pout(2, 1 + size(flags))
      integer :: ierr, k
      if (.not. mpi_on) return
      pin(1, 1) = x
      pin(2, 1) = real(key, wp)
      do k = 1, size(flags)
         pin(1, 1 + k) = -real(flags(k), wp)
         pin(2, 1 + k) = 0.0_wp
      end do
      call MPI_Allreduce(pin, pout, 1 + size(flags), MPI_2DOUBLE_PRECISION, MPI_MINLOC, &
                         comm, ierr)
      call check(ierr, 'MPI_Allreduce (MINLOC with flags)')
      x = pout(1, 1)
      key = nint(pout(2, 1))
      do k = 1, size(flags)
         flags(k) = -nint(pout(1, 1 + k))
      end do
   end subroutine par_minloc_flags

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
      integer :: ncomp, ntot, r, ierr, i
      ncomp = size(vals, 1)
      if (.not. mpi_on) then
         kk = keys
         vv = vals
      else
         allocate(counts(0:nranks - 1), displs(0:nranks - 1))
         call MPI_Allgather(size(keys), 1, MPI_INTEGER, counts, 1, MPI_INTEGER, comm, ierr)
         call check(ierr, 'MPI_Allgather (ordered gather counts)')
         displs(0) = 0
         do r = 1, nranks - 1
            displs(r) = displs(r - 1) + counts(r - 1)
         end do
         ntot = sum(counts)
         allocate(kk(ntot), vv(ncomp, ntot))
         call MPI_Allgatherv(keys, size(keys), MPI_INTEGER, kk, counts, displs, MPI_INTEGER, &
                             comm, ierr)
         call check(ierr, 'MPI_Allgatherv (ordered gather keys)')
         call MPI_Allgatherv(vals, size(vals), MPI_DOUBLE_PRECISION, vv, ncomp*counts, &
                             ncomp*displs, MPI_DOUBLE_PRECISION, comm, ierr)
         call check(ierr, 'MPI_Allgatherv (ordered gather values)')
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
      integer :: r, ierr, i
      plan%n = size(keys)
      if (.not. mpi_on) then
         kk = keys
         plan%counts = [size(keys)]
         plan%displs = [0]
      else
         allocate(plan%counts(0:nranks - 1), plan%displs(0:nranks - 1))
         call MPI_Allgather(size(keys), 1, MPI_INTEGER, plan%counts, 1, MPI_INTEGER, comm, ierr)
         call check(ierr, 'MPI_Allgather (gather plan counts)')
         plan%displs(0) = 0
         do r = 1, nranks - 1
            plan%displs(r) = plan%displs(r - 1) + plan%counts(r - 1)
         end do
         allocate(kk(sum(plan%counts)))
         call MPI_Allgatherv(keys, size(keys), MPI_INTEGER, kk, plan%counts, plan%displs, &
                             MPI_INTEGER, comm, ierr)
         call check(ierr, 'MPI_Allgatherv (gather plan keys)')
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
      real(wp), allocatable :: vv(:, :)
      integer :: ncomp, ierr
      ncomp = size(vals, 1)
      if (.not. mpi_on) then
         all_vals(:, 1:plan%n) = vals(:, plan%perm)
         return
      end if
      allocate(vv(ncomp, size(plan%keys)))
      call MPI_Allgatherv(vals, ncomp*plan%n, MPI_DOUBLE_PRECISION, vv, ncomp*plan%counts, &
                          ncomp*plan%displs, MPI_DOUBLE_PRECISION, comm, ierr)
      call check(ierr, 'MPI_Allgatherv (gather plan values)')
      all_vals(:, 1:size(plan%keys)) = vv(:, plan%perm)
   end subroutine par_gather_values


   !> Every rank's sbuf, concatenated in rank order into rbuf (MPI_Allgatherv). counts
   !> (0:np-1, numbers per rank): given, or when absent exchanged first (MPI_Allgather) and
   !> returned in cnt. Serial: rbuf = sbuf.
   subroutine par_allgatherv_real(sbuf, rbuf, counts, cnt)
      real(wp), intent(in) :: sbuf(:)
      real(wp), allocatable, intent(out) :: rbuf(:)
      integer, intent(in), optional :: counts(0:)
      integer, allocatable, intent(out), optional :: cnt(:)
      integer, allocatable :: c(:), d(:)
      integer :: r, ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         if (present(cnt)) cnt = [size(sbuf)]
         return
      end if
      allocate(c(0:nranks - 1), d(0:nranks - 1))
      if (present(counts)) then
         c = counts
      else
         call MPI_Allgather(size(sbuf), 1, MPI_INTEGER, c, 1, MPI_INTEGER, comm, ierr)
         call check(ierr, 'MPI_Allgather (counts)')
      end if
      d(0) = 0
      do r = 1, nranks - 1
         d(r) = d(r - 1) + c(r - 1)
      end do
      allocate(rbuf(sum(c)))
      call MPI_Allgatherv(sbuf, size(sbuf), MPI_DOUBLE_PRECISION, rbuf, c, d, &
                          MPI_DOUBLE_PRECISION, comm, ierr)
      call check(ierr, 'MPI_Allgatherv (real)')
      if (present(cnt)) cnt = c
   end subroutine par_allgatherv_real

   !> Every rank's sbuf (any length) concatenated in rank order into rbuf, cnt(0:np-1) the
   !> lengths: one message to each other rank (MPI_Isend), received with MPI_Probe and
   !> MPI_Get_count, so the lengths need no collective of their own (one round, not two).
   subroutine par_allgather_probe(sbuf, rbuf, cnt)
      real(wp), intent(in), contiguous, asynchronous :: sbuf(:)
      real(wp), allocatable, intent(out) :: rbuf(:)
      integer, allocatable, intent(out) :: cnt(:)
      integer, parameter :: TAG_PROBE = 105
      type(MPI_Request), allocatable :: req(:)
      type(MPI_Status) :: st
      type :: part_t
         real(wp), allocatable :: v(:)
      end type part_t
      type(part_t), allocatable :: part(:)
      integer :: r, nq, ierr, n, a
      if (.not. mpi_on) then
         rbuf = sbuf
         cnt = [size(sbuf)]
         return
      end if
      allocate(req(nranks), part(0:nranks - 1), cnt(0:nranks - 1))
      nq = 0
      do r = 0, nranks - 1
         if (r == my_rank) cycle
         nq = nq + 1
         call MPI_Isend(sbuf, size(sbuf), MPI_DOUBLE_PRECISION, r, TAG_PROBE, comm, &
                        req(nq), ierr)
         call check(ierr, 'MPI_Isend (probe gather)')
      end do
      do r = 0, nranks - 1
         if (r == my_rank) then
            part(r)%v = sbuf
         else
            call MPI_Probe(r, TAG_PROBE, comm, st, ierr)
            call check(ierr, 'MPI_Probe (probe gather)')
            call MPI_Get_count(st, MPI_DOUBLE_PRECISION, n, ierr)
            call check(ierr, 'MPI_Get_count (probe gather)')
            allocate(part(r)%v(n))
            call MPI_Recv(part(r)%v, n, MPI_DOUBLE_PRECISION, r, TAG_PROBE, comm, &
                          MPI_STATUS_IGNORE, ierr)
            call check(ierr, 'MPI_Recv (probe gather)')
         end if
         cnt(r) = size(part(r)%v)
      end do
      call MPI_Waitall(nq, req(1:nq), MPI_STATUSES_IGNORE, ierr)
      call check(ierr, 'MPI_Waitall (probe gather)')
      allocate(rbuf(sum(cnt)))
      a = 0
      do r = 0, nranks - 1
         rbuf(a + 1:a + cnt(r)) = part(r)%v
         a = a + cnt(r)
      end do
   end subroutine par_allgather_probe

   !> Point-to-point exchange with the ranks that share data: scnt(r) numbers of sbuf (in
   !> rank order) to rank r, rcnt(r) numbers from rank r into rbuf (rank order); only the
   !> pairs with a nonzero count send a message (MPI_Isend/MPI_Irecv, MPI_Waitall). Both
   !> sides know the counts (a plan); this rank's own counts are ignored.
   subroutine par_sparse_exchange(sbuf, scnt, rbuf, rcnt)
      real(wp), intent(in), contiguous, asynchronous :: sbuf(:)
      integer, intent(in) :: scnt(0:), rcnt(0:)
      real(wp), intent(inout), contiguous, asynchronous :: rbuf(:)
      type(MPI_Request), allocatable :: req(:)
      integer, parameter :: TAG_SPARSE = 104
      integer :: r, a, b, nq, ierr
      if (.not. mpi_on) return
      allocate(req(2*nranks))
      nq = 0
      a = 0
      do r = 0, nranks - 1
         if (rcnt(r) > 0 .and. r /= my_rank) then
            nq = nq + 1
            call MPI_Irecv(rbuf(a + 1:a + rcnt(r)), rcnt(r), MPI_DOUBLE_PRECISION, r, &
                           TAG_SPARSE, comm, req(nq), ierr)
            call check(ierr, 'MPI_Irecv (sparse exchange)')
         end if
         a = a + rcnt(r)
      end do
      b = 0
      do r = 0, nranks - 1
         if (scnt(r) > 0 .and. r /= my_rank) then
            nq = nq + 1
            call MPI_Isend(sbuf(b + 1:b + scnt(r)), scnt(r), MPI_DOUBLE_PRECISION, r, &
                           TAG_SPARSE, comm, req(nq), ierr)
            call check(ierr, 'MPI_Isend (sparse exchange)')
         end if
         b = b + scnt(r)
      end do
      call MPI_Waitall(nq, req(1:nq), MPI_STATUSES_IGNORE, ierr)
      call check(ierr, 'MPI_Waitall (sparse exchange)')
   end subroutine par_sparse_exchange

   !> Wall-clock seconds (MPI_Wtime under MPI, else the system clock).
   real(wp) function par_wtime()
      integer(int64) :: c, r
      if (mpi_on) then
         par_wtime = MPI_Wtime()
      else
         call system_clock(c, r)
         par_wtime = real(c, wp)/real(r, wp)
      end if
   end function par_wtime
   !> par_gather_setup for a gather to rank 0 only (par_gather_values_root): rank 0 gets
   !> every rank's keys (plan%keys, ascending; plan%perm), the other ranks keep only the
   !> counts (plan%counts: sum(plan%counts) is the total everywhere; keys and perm are empty
   !> there), so no rank but 0 holds the whole key list.
   subroutine par_gather_setup_root(plan, keys)
      type(gather_plan_t), intent(out) :: plan
      integer, intent(in) :: keys(:)
      integer, allocatable :: kk(:)
      integer :: r, ierr, i
      plan%n = size(keys)
      if (.not. mpi_on) then
         call par_gather_setup(plan, keys)
         return
      end if
      allocate(plan%counts(0:nranks - 1), plan%displs(0:nranks - 1))
      call MPI_Allgather(size(keys), 1, MPI_INTEGER, plan%counts, 1, MPI_INTEGER, comm, ierr)
      call check(ierr, 'MPI_Allgather (root gather plan counts)')
      plan%displs(0) = 0
      do r = 1, nranks - 1
         plan%displs(r) = plan%displs(r - 1) + plan%counts(r - 1)
      end do
      allocate(kk(merge(sum(plan%counts), 0, my_rank == 0)))
      call MPI_Gatherv(keys, size(keys), MPI_INTEGER, kk, plan%counts, plan%displs, &
                       MPI_INTEGER, 0, comm, ierr)
      call check(ierr, 'MPI_Gatherv (root gather plan keys)')
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
      real(wp), allocatable :: vv(:, :)
      integer :: ncomp, ierr
      ncomp = size(vals, 1)
      if (.not. mpi_on) then
         all_vals(:, 1:plan%n) = vals(:, plan%perm)
         return
      end if
      allocate(vv(ncomp, size(plan%keys)))
      call MPI_Gatherv(vals, ncomp*plan%n, MPI_DOUBLE_PRECISION, vv, ncomp*plan%counts, &
                       ncomp*plan%displs, MPI_DOUBLE_PRECISION, 0, comm, ierr)
      call check(ierr, 'MPI_Gatherv (root gather plan values)')
      if (my_rank == 0) all_vals(:, 1:size(plan%keys)) = vv(:, plan%perm)
   end subroutine par_gather_values_root

   !> x from rank root to every rank (MPI_Bcast): results formed on one rank, bit for bit.
   subroutine par_bcast_real(x, root)
      real(wp), intent(inout) :: x(:)
      integer, intent(in) :: root
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Bcast(x, size(x), MPI_DOUBLE_PRECISION, root, comm, ierr)
      call check(ierr, 'MPI_Bcast (values)')
   end subroutine par_bcast_real

   !> par_minloc (and par_minloc_flags when flags are given) with a 64-bit key (< 2**53, it
   !> travels as a double): a key that carries the element itself, so no rank needs a
   !> whole-model table to name the element controlling the step.
   subroutine par_minloc8(x, key, flags)
      real(wp), intent(inout) :: x
      integer(int64), intent(inout) :: key
      integer, intent(inout), optional :: flags(:)
      integer :: nf, ierr, k
      real(wp), allocatable :: pin(:, :), pout(:, :)
      if (.not. mpi_on) return
      nf = 0
      if (present(flags)) nf = size(flags)
      allocate(pin(2, 1 + nf), pout(2, 1 + nf))
      pin(1, 1) = x
      pin(2, 1) = real(key, wp)
      do k = 1, nf
         pin(1, 1 + k) = -real(flags(k), wp)
         pin(2, 1 + k) = 0.0_wp
      end do
      call MPI_Allreduce(pin, pout, 1 + nf, MPI_2DOUBLE_PRECISION, MPI_MINLOC, comm, ierr)
      call check(ierr, 'MPI_Allreduce (MINLOC, 64-bit key)')
      x = pout(1, 1)
      key = nint(pout(2, 1), int64)
      do k = 1, nf
         flags(k) = -nint(pout(1, 1 + k))
      end do
   end subroutine par_minloc8
end module dx_par
