!> The MPI wrapper: with dx_par_plan the only modules that use mpi_f08. A serial run needs
!> no mpirun: MPI_Init is called only when the process was started by an MPI launcher (Open
!> MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK), and every call below is then a no-op
!> with one rank (no separate serial code path). Every MPI call's return code is checked
!> (par_check: a failed call aborts all ranks, naming the call). The fixed-order shared-node
!> sums and ordered gathers built on it are in dx_par_plan.
!>
!> Module state: the communicator, this rank, the number of ranks, whether MPI is on, and the
!> bytes this rank has sent (par_traffic_add, par_traffic_line): the shared-node sums'
!> values, other point-to-point messages, and its own contribution to each collective (the
!> payload it passes in: what MPI moves on the wire for an Allreduce of P ranks is about
!> 2 x that, which the line does not guess), plus the number of dt MINLOC reductions (the
!> cycles of an explicit run).
module dx_par
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use mpi_f08, only: MPI_2DOUBLE_PRECISION, MPI_Abort, MPI_Allgather, MPI_Allgatherv, &
                        MPI_Allreduce, MPI_Alltoallv, MPI_Barrier, MPI_Bcast, MPI_CHARACTER, &
                        MPI_Comm, MPI_Comm_dup, MPI_Comm_free, MPI_Comm_rank, &
                        MPI_Comm_set_errhandler, MPI_Comm_size, MPI_COMM_WORLD, &
                        MPI_DOUBLE_PRECISION, MPI_Error_string, MPI_ERRORS_RETURN, &
                        MPI_Finalize, MPI_Get_count, MPI_Init, MPI_INTEGER, MPI_Irecv, &
                        MPI_Isend, MPI_MAX, MPI_MAX_ERROR_STRING, MPI_MIN, MPI_MINLOC, MPI_Op, &
                        MPI_Probe, MPI_Recv, MPI_Request, MPI_Status, MPI_STATUS_IGNORE, &
                        MPI_STATUSES_IGNORE, MPI_SUCCESS, MPI_SUM, MPI_Waitall, MPI_Wtime, &
                        MPI_COMM_SELF, MPI_Initialized, MPI_Finalized, MPI_INTEGER8
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, exit_process, EXIT_NUMERIC
   use dx_strings, only: str
   implicit none
   private
   public :: par_init, par_finalize, par_rank, par_size, par_active, par_barrier, &
             par_allreduce, par_abort, par_wtime, par_minloc, PAR_SUM, &
             PAR_MIN, PAR_MAX, par_bcast_text, par_minloc_flags, par_alltoallv
   public :: par_bcast_real, par_minloc8, par_comm, par_check
   public :: par_allgatherv_real, par_sparse_exchange, par_allgather_probe   ! (contact)
   public :: par_displs, par_counts
   public :: par_self_handle, par_comm_handle   ! (the sparse direct solver, dx_mumps)
   public :: par_traffic_add, par_traffic_line, PAR_T_EXCH, PAR_T_P2P, PAR_T_COLL
   public :: par_allreduce_i8  ! (exact reproducible sums, dx_repro_sum)

   integer, parameter :: PAR_SUM = 1, PAR_MIN = 2, PAR_MAX = 3

   type(MPI_Comm), save :: comm
   logical, save :: mpi_on = .false.
   integer, save :: my_rank = 0, nranks = 1
   !> bytes sent by this rank: shared-node sums, other point-to-point, collectives; MINLOCs
   integer, parameter :: PAR_T_EXCH = 1, PAR_T_P2P = 2, PAR_T_COLL = 3, PAR_T_DT = 4
   integer(int64), save :: traffic(4) = 0

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
      call par_check(ierr, 'MPI_Comm_dup')
      ! errors come back as codes, so a failing call can abort all ranks with a message
      call MPI_Comm_set_errhandler(comm, MPI_ERRORS_RETURN, ierr)
      call par_check(ierr, 'MPI_Comm_set_errhandler')
      call MPI_Comm_rank(comm, my_rank, ierr)
      call par_check(ierr, 'MPI_Comm_rank')
      call MPI_Comm_size(comm, nranks, ierr)
      call par_check(ierr, 'MPI_Comm_size')
      mpi_on = .true.
   end subroutine par_init

   !> Finalize MPI if it was started.
   subroutine par_finalize()
      integer :: ierr
      logical :: started, ended
      if (.not. mpi_on) then   ! a serial run that started MPI for a library (par_self_handle)
         call MPI_Initialized(started, ierr)
         call MPI_Finalized(ended, ierr)
         if (started .and. .not. ended) call MPI_Finalize(ierr)
         return
      end if
      call MPI_Comm_free(comm, ierr)
      call MPI_Finalize(ierr)
      mpi_on = .false.
   end subroutine par_finalize

   !> The Fortran handle of MPI_COMM_SELF for a library that needs MPI in any run (MUMPS);
   !> a serial run (no launcher) starts MPI here, once, and par_finalize ends it.
   integer function par_self_handle()
      integer :: ierr
      logical :: started
      call MPI_Initialized(started, ierr)
      if (.not. started) call MPI_Init(ierr)
      par_self_handle = MPI_COMM_SELF%MPI_VAL
   end function par_self_handle

   !> The Fortran handle of the run's communicator (an MPI run of the implicit solver: MUMPS
   !> factorizes on every rank); MPI_COMM_SELF's when MPI is not running on several ranks.
   integer function par_comm_handle()
      if (mpi_on) then
         par_comm_handle = comm%MPI_VAL
      else
         par_comm_handle = par_self_handle()
      end if
   end function par_comm_handle

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

   !> The run's communicator (for dx_par_plan).
   function par_comm() result(c)
      type(MPI_Comm) :: c
      c = comm
   end function par_comm

   subroutine par_barrier()
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Barrier(comm, ierr)
      call par_check(ierr, 'MPI_Barrier')
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
   subroutine par_check(ierr, what)
      integer, intent(in) :: ierr
      character(*), intent(in) :: what
      character(len=MPI_MAX_ERROR_STRING) :: s
      integer :: l, ie
      if (ierr == MPI_SUCCESS) return
      call MPI_Error_string(ierr, s, l, ie)
      call par_abort(what//' failed: '//s(1:l), EXIT_NUMERIC)
   end subroutine par_check

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
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8
      call par_check(ierr, 'MPI_Allreduce')
      x = y(1)
   end subroutine allreduce_r0

   subroutine allreduce_r1(x, op)
      real(wp), intent(inout) :: x(:)
      integer, intent(in) :: op
      real(wp) :: y(size(x))
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce(x, y, size(x), MPI_DOUBLE_PRECISION, reduce_op(op), comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8*size(x)
      call par_check(ierr, 'MPI_Allreduce')
      x = y
   end subroutine allreduce_r1

   subroutine allreduce_i0(x, op)
      integer, intent(inout) :: x
      integer, intent(in) :: op
      integer :: y(1)
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce([x], y, 1, MPI_INTEGER, reduce_op(op), comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 4
      call par_check(ierr, 'MPI_Allreduce')
      x = y(1)
   end subroutine allreduce_i0

   subroutine allreduce_i1(x, op)
      integer, intent(inout) :: x(:)
      integer, intent(in) :: op
      integer :: y(size(x))
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Allreduce(x, y, size(x), MPI_INTEGER, reduce_op(op), comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 4*size(x)
      call par_check(ierr, 'MPI_Allreduce')
      x = y
   end subroutine allreduce_i1

   !> x = sum over ranks of the int64 array x (exact: integer addition, any order). For the
   !> limbs of dx_repro_sum's exact accumulators.
   subroutine par_allreduce_i8(x)
      integer(int64), intent(inout) :: x(:)
      integer(int64), allocatable :: y(:)
      integer :: ierr
      if (.not. mpi_on) return
      allocate(y(size(x)))
      call MPI_Allreduce(x, y, size(x), MPI_INTEGER8, MPI_SUM, comm, ierr)
      call par_check(ierr, 'MPI_Allreduce')
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8*size(x)
      x = y
   end subroutine par_allreduce_i8

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
      call par_check(ierr, 'MPI_Bcast (failure message length)')
      if (my_rank /= root) then
         if (allocated(text)) deallocate(text)
         allocate(character(n(1)) :: text)
      end if
      code = n(2)
      if (n(1) > 0) then
         call MPI_Bcast(text, n(1), MPI_CHARACTER, root, comm, ierr)
         call par_check(ierr, 'MPI_Bcast (failure message)')
      end if
   end subroutine par_bcast_text
   !> The offsets (0-based, rank order) of blocks of cnt(0:np-1) items laid end to end: the
   !> displacements of an MPI "v" collective.
   pure function par_displs(cnt) result(d)
      integer, intent(in) :: cnt(0:)
      integer :: d(0:size(cnt) - 1)
      integer :: r
      if (size(cnt) == 0) return
      d(0) = 0
      do r = 1, size(cnt) - 1
         d(r) = d(r - 1) + cnt(r - 1)
      end do
   end function par_displs

   !> Every rank's n, in rank order (c(0:np-1)), on every rank; [n] without MPI.
   function par_counts(n) result(c)
      integer, intent(in) :: n
      integer, allocatable :: c(:)
      integer :: ierr
      if (.not. mpi_on) then
         c = [n]
         return
      end if
      allocate(c(0:nranks - 1))
      call MPI_Allgather(n, 1, MPI_INTEGER, c, 1, MPI_INTEGER, comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 4
      call par_check(ierr, 'MPI_Allgather (counts)')
   end function par_counts

   subroutine alltoallv_i(sbuf, scnt, rbuf, rcnt)
      integer, intent(in) :: sbuf(:), scnt(0:)
      integer, intent(out) :: rbuf(:)
      integer, intent(in) :: rcnt(0:)
      integer, allocatable :: sd(:), rd(:)
      integer :: ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         return
      end if
      sd = par_displs(scnt)
      rd = par_displs(rcnt)
      call MPI_Alltoallv(sbuf, scnt, sd, MPI_INTEGER, rbuf, rcnt, rd, MPI_INTEGER, comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 4*(sum(int(scnt, int64)) - scnt(my_rank))
      call par_check(ierr, 'MPI_Alltoallv (integer)')
   end subroutine alltoallv_i

   subroutine alltoallv_r(sbuf, scnt, rbuf, rcnt)
      real(wp), intent(in) :: sbuf(:)
      integer, intent(in) :: scnt(0:)
      real(wp), intent(out) :: rbuf(:)
      integer, intent(in) :: rcnt(0:)
      integer, allocatable :: sd(:), rd(:)
      integer :: ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         return
      end if
      sd = par_displs(scnt)
      rd = par_displs(rcnt)
      call MPI_Alltoallv(sbuf, scnt, sd, MPI_DOUBLE_PRECISION, rbuf, rcnt, rd, &
                         MPI_DOUBLE_PRECISION, comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8*(sum(int(scnt, int64)) - scnt(my_rank))
      call par_check(ierr, 'MPI_Alltoallv (real)')
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
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 16
      call par_check(ierr, 'MPI_Allreduce (MINLOC)')
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
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 16*(1 + size(flags))
      call par_check(ierr, 'MPI_Allreduce (MINLOC with flags)')
      x = pout(1, 1)
      key = nint(pout(2, 1))
      do k = 1, size(flags)
         flags(k) = -nint(pout(1, 1 + k))
      end do
   end subroutine par_minloc_flags


   !> Every rank's sbuf, concatenated in rank order into rbuf (MPI_Allgatherv). counts
   !> (0:np-1, numbers per rank): given, or when absent exchanged first (MPI_Allgather) and
   !> returned in cnt. Serial: rbuf = sbuf.
   subroutine par_allgatherv_real(sbuf, rbuf, counts, cnt)
      real(wp), intent(in) :: sbuf(:)
      real(wp), allocatable, intent(out) :: rbuf(:)
      integer, intent(in), optional :: counts(0:)
      integer, allocatable, intent(out), optional :: cnt(:)
      integer, allocatable :: c(:), d(:)
      integer :: ierr
      if (.not. mpi_on) then
         rbuf = sbuf
         if (present(cnt)) cnt = [size(sbuf)]
         return
      end if
      allocate(c(0:nranks - 1))                 ! cnt is 0-based, as before
      if (present(counts)) then
         c = counts
      else
         c = par_counts(size(sbuf))
      end if
      d = par_displs(c)
      allocate(rbuf(sum(c)))
      call MPI_Allgatherv(sbuf, size(sbuf), MPI_DOUBLE_PRECISION, rbuf, c, d, &
                          MPI_DOUBLE_PRECISION, comm, ierr)
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8*size(sbuf)
      call par_check(ierr, 'MPI_Allgatherv (real)')
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
         call par_check(ierr, 'MPI_Isend (probe gather)')
      end do
      do r = 0, nranks - 1
         if (r == my_rank) then
            part(r)%v = sbuf
         else
            call MPI_Probe(r, TAG_PROBE, comm, st, ierr)
            call par_check(ierr, 'MPI_Probe (probe gather)')
            call MPI_Get_count(st, MPI_DOUBLE_PRECISION, n, ierr)
            call par_check(ierr, 'MPI_Get_count (probe gather)')
            allocate(part(r)%v(n))
            call MPI_Recv(part(r)%v, n, MPI_DOUBLE_PRECISION, r, TAG_PROBE, comm, &
                          MPI_STATUS_IGNORE, ierr)
            call par_check(ierr, 'MPI_Recv (probe gather)')
         end if
         cnt(r) = size(part(r)%v)
      end do
      call MPI_Waitall(nq, req(1:nq), MPI_STATUSES_IGNORE, ierr)
      call par_check(ierr, 'MPI_Waitall (probe gather)')
      traffic(PAR_T_P2P) = traffic(PAR_T_P2P) + 8*size(sbuf, kind=int64)*nq
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
            call par_check(ierr, 'MPI_Irecv (sparse exchange)')
         end if
         a = a + rcnt(r)
      end do
      b = 0
      do r = 0, nranks - 1
         if (scnt(r) > 0 .and. r /= my_rank) then
            nq = nq + 1
            call MPI_Isend(sbuf(b + 1:b + scnt(r)), scnt(r), MPI_DOUBLE_PRECISION, r, &
                           TAG_SPARSE, comm, req(nq), ierr)
            traffic(PAR_T_P2P) = traffic(PAR_T_P2P) + 8*scnt(r)
            call par_check(ierr, 'MPI_Isend (sparse exchange)')
         end if
         b = b + scnt(r)
      end do
      call MPI_Waitall(nq, req(1:nq), MPI_STATUSES_IGNORE, ierr)
      call par_check(ierr, 'MPI_Waitall (sparse exchange)')
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
   !> x from rank root to every rank (MPI_Bcast): results formed on one rank, bit for bit.
   subroutine par_bcast_real(x, root)
      real(wp), intent(inout) :: x(:)
      integer, intent(in) :: root
      integer :: ierr
      if (.not. mpi_on) return
      call MPI_Bcast(x, size(x), MPI_DOUBLE_PRECISION, root, comm, ierr)
      if (my_rank == root) traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 8*size(x)
      call par_check(ierr, 'MPI_Bcast (values)')
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
      traffic(PAR_T_COLL) = traffic(PAR_T_COLL) + 16*(1 + nf)
      traffic(PAR_T_DT) = traffic(PAR_T_DT) + 1
      call par_check(ierr, 'MPI_Allreduce (MINLOC, 64-bit key)')
      x = pout(1, 1)
      key = nint(pout(2, 1), int64)
      do k = 1, nf
         flags(k) = -nint(pout(1, 1 + k))
      end do
   end subroutine par_minloc8

   !> Count nbytes sent by this rank as kind k (PAR_T_EXCH, PAR_T_P2P, PAR_T_COLL): for
   !> dx_par_plan's messages (the other mpi_f08 module).
   subroutine par_traffic_add(k, nbytes)
      integer, intent(in) :: k
      integer(int64), intent(in) :: nbytes
      traffic(k) = traffic(k) + nbytes
   end subroutine par_traffic_add

   !> The end-of-run traffic line (a collective: every rank calls it): bytes sent per rank
   !> per dt reduction (per cycle), the largest over the ranks for each kind, and the totals.
   function par_traffic_line() result(s)
      character(:), allocatable :: s
      real(wp) :: t(4), tmax(4), ncyc
      integer :: k
      character(24) :: w(3)
      t = real(traffic, wp)                  ! (before the reduction below counts itself)
      tmax = t
      call allreduce_r1(tmax, PAR_MAX)
      ncyc = max(1.0_wp, tmax(PAR_T_DT))
      do k = 1, 3
         write(w(k), '(i0)') nint(tmax(k)/ncyc, int64)
      end do
      s = 'dynx: MPI bytes sent per rank per cycle (largest over the ranks, '// &
          str(nint(tmax(PAR_T_DT)))//' cycles): shared-node sums '//trim(w(1))// &
          ', other point-to-point '//trim(w(2))//', collectives (own payload) '//trim(w(3))
   end function par_traffic_line
end module dx_par
