!> The implicit solver under MPI (issue 20, "Under MPI"): every rank holds the whole model
!> and repeats the Newton decisions identically (replicated, as the conserving solver under
!> MPI); the work that grows with the mesh is split:
!>  - assembly: each rank forms the internal forces, the tangent and the material update of
!>    its own elements, the element split of the METIS partition the explicit engine uses
!>    (dx_partition: partition_model, element graph weighted by the element cost);
!>  - factorization: MUMPS on every rank of the run's communicator with the distributed
!>    assembled input (ICNTL(18) = 3; Amestoy, Duff, L'Excellent & Koster, SIAM J. Matrix
!>    Anal. Appl. 23 (2001) 15-41, the distributed-entry interface of the MUMPS 5.5 guide).
!>    Each entry of the tangent is passed by one rank, its owner: the lowest rank whose
!>    elements touch it (rank 0 for every diagonal and the rigid bodies' rows, which the
!>    solver adds once). The other ranks that touch it send their partial values to the owner
!>    (one MPI_Alltoallv per factorization, the lists set up once per pattern), which adds
!>    them in rank order. Letting MUMPS sum an entry given by several ranks was measured not
!>    reproducible: it adds them in the order the messages arrive (elastica at NP 2: nodout
!>    differed run to run; with one rank per entry three runs were identical). The
!>    right-hand side and the solution are on rank 0, the solution is broadcast;
!>  - the internal force is the sum of the ranks' partial vectors taken in rank order on
!>    every rank (MPI_Allgatherv, then a fixed-order sum: the fixed-order sums of ParaDyn,
!>    Hoover et al., LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed), so
!>    the residual, its norms and every convergence test are the same bits on every rank and
!>    from run to run; the committed element fields (stress, history, work) are gathered by a
!>    sum where only the owner's entry is nonzero (exact).
!> Across NP the results differ by round-off only (the partial sums' order and MUMPS's
!> parallel elimination): equal to the solver's tolerance, not bit for bit
!> (shared/docs/clarifications.md, "Reproducibility"). Run to run at the same NP: every
!> input of MUMPS is the same bits (checked by hashing A_loc on each rank and the right-hand
!> side), but MUMPS's parallel factorization picks the processes of its fronts from the
!> current loads (the paper's "distributed dynamic scheduling"), so the solution was seen to
!> differ in the last bit from run to run (rigid_punch, rigid_torsion, friction_block at
!> NP 2; same input hashes, different solution hash). A serial run is bitwise run to run; a
!> serial run (one rank) never calls anything here that changes a number (on = .false.).
module dx_implicit_par
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_log, only: log_info
   use dx_model, only: model_t
   use dx_sparse, only: sparse_sym_t
   use dx_par, only: par_size, par_rank, par_allreduce, par_bcast_real, par_allgatherv_real, &
                     par_comm_handle, par_alltoallv, par_displs, PAR_SUM, PAR_MIN, PAR_MAX
   use dx_par_agree, only: par_agree, par_agreed
   use dx_partition, only: partition_t, partition_model
   implicit none
   private
   public :: ipar_t, ipar_setup, ipar_entries, ipar_sum, ipar_exact, ipar_bcast, &
             ipar_bcast_int, ipar_first, ipar_agree, ipar_agreed, ipar_comm, ipar_max_flags, &
             ipar_global, ipar_assemble, ipar_per_rank

   !> This rank's share of an MPI run of the implicit solver.
   type :: ipar_t
      logical :: on = .false.              !< more than one rank
      integer :: me = 0, np = 1
      logical, allocatable :: own(:)       !< (ne) the dense elements this rank assembles
      integer, allocatable :: epart(:)     !< (ne) the rank of each dense element
      integer, allocatable :: loc(:)       !< the tangent's entries this rank owns (to MUMPS)
      logical, allocatable :: owned(:)     !< (nnz) loc as a mask
      !> partial values sent to their owners: entries spos in rank blocks of scnt(0:np-1);
      !> received: entries rpos in rank blocks of rcnt (each block ascending)
      integer, allocatable :: spos(:), scnt(:), rpos(:), rcnt(:)
      integer, allocatable :: eidx(:)      !< (ne) assembly index of each dense element (0: none)
      integer :: qbody = huge(1)           !< the rigid bodies' first equation
   end type ipar_t

contains

   !> The element split (every rank computes the same METIS partition of the whole model).
   subroutine ipar_setup(model, ip, error)
      type(model_t), intent(in) :: model
      type(ipar_t), intent(inout) :: ip
      type(error_t), allocatable, intent(out) :: error
      type(partition_t) :: part
      integer :: gp(1), ge(0), r
      character(:), allocatable :: t
      ip%np = par_size()
      ip%on = ip%np > 1
      if (.not. ip%on) return
      ip%me = par_rank()
      gp = 1
      call partition_model(model, ip%np, gp, ge, part, error)
      if (allocated(error)) return
      ip%own = part%epart == ip%me
      ip%epart = part%epart
      t = ''
      do r = 0, min(ip%np, 16) - 1
         t = t//'; rank '//str(r)//': '//str(count(part%epart == r))//' elements'
      end do
      call log_info('dynx: implicit: MPI run on '//str(ip%np)//' ranks: the whole model on '// &
         'every rank, each rank assembles its elements of the METIS partition'//t)
   end subroutine ipar_setup

   !> The owner of every entry of k (the lowest rank whose elements touch it: elements' maps
   !> pos of assembly index eidx(e) of dense element e, 0 not assembled; rank 0 also every
   !> diagonal, every entry in a row or column >= qbody, the rigid bodies' equations, and the
   !> contact pairs' pseudo-elements q1..q2), the entries this rank owns (loc) and the
   !> partial values it sends and receives. eidx and qbody: given once (kept for the calls
   !> after a new contact pattern).
   subroutine ipar_entries(ip, k, q1, q2, eidx, qbody)
      type(ipar_t), intent(inout) :: ip
      type(sparse_sym_t), intent(in) :: k
      integer, intent(in) :: q1, q2
      integer, intent(in), optional :: eidx(:), qbody
      logical, allocatable :: mine(:)
      integer, allocatable :: owner(:), fill(:), sbuf(:)
      integer :: e, q, p, i, a, r, n
      if (.not. ip%on) return
      if (present(eidx)) ip%eidx = eidx
      if (present(qbody)) ip%qbody = qbody
      if (allocated(ip%scnt)) deallocate(ip%scnt, ip%rcnt, ip%spos, ip%rpos)
      allocate(mine(k%nnz), owner(k%nnz))
      mine = .false.
      owner = huge(1)
      if (ip%me == 0) mine(k%dg) = .true.
      owner(k%dg) = 0
      where (k%irn >= ip%qbody .or. k%col >= ip%qbody) owner = 0
      if (ip%me == 0) where (k%irn >= ip%qbody .or. k%col >= ip%qbody) mine = .true.
      do q = q1, q2                  ! contact pairs: rank 0's
         do i = 1, k%nde
            do a = 1, k%nde
               p = k%pos(a, i, q)
               if (p <= 0) cycle
               owner(p) = 0
               if (ip%me == 0) mine(p) = .true.
            end do
         end do
      end do
      do e = 1, size(ip%eidx)
         q = ip%eidx(e)
         if (q <= 0) cycle
         r = ip%epart(e)
         do i = 1, k%nde
            do a = 1, k%nde
               p = k%pos(a, i, q)
               if (p <= 0) cycle
               owner(p) = min(owner(p), r)
               if (r == ip%me) mine(p) = .true.
            end do
         end do
      end do
      ip%owned = mine .and. owner == ip%me
      ip%loc = pack([(i, i = 1, k%nnz)], ip%owned)
      ! partial values to send: this rank's entries owned elsewhere, by owner, ascending
      allocate(ip%scnt(0:ip%np - 1), ip%rcnt(0:ip%np - 1), fill(0:ip%np - 1))
      ip%scnt = 0
      do p = 1, k%nnz
         if (mine(p) .and. owner(p) /= ip%me) ip%scnt(owner(p)) = ip%scnt(owner(p)) + 1
      end do
      fill = par_displs(ip%scnt)
      allocate(ip%spos(sum(ip%scnt)))
      do p = 1, k%nnz
         if (mine(p) .and. owner(p) /= ip%me) then
            fill(owner(p)) = fill(owner(p)) + 1
            ip%spos(fill(owner(p))) = p
         end if
      end do
      call par_alltoallv(ip%scnt, [(1, r = 0, ip%np - 1)], ip%rcnt, [(1, r = 0, ip%np - 1)])
      n = sum(ip%rcnt)
      allocate(ip%rpos(n))
      sbuf = ip%spos
      call par_alltoallv(sbuf, ip%scnt, ip%rpos, ip%rcnt)
      call log_info('dynx: implicit: MUMPS distributed assembled input (ICNTL(18) = 3): '// &
         'rank 0 owns '//str(size(ip%loc))//' of '//str(k%nnz)//' entries, sends '// &
         str(size(ip%spos))//' partial values and receives '//str(n)//' per factorization')
   end subroutine ipar_entries

   !> The owned entries of k summed: this rank's partial value, then the other ranks' in
   !> rank order (before each factorization).
   subroutine ipar_assemble(ip, k)
      type(ipar_t), intent(in) :: ip
      type(sparse_sym_t), intent(inout) :: k
      real(wp), allocatable :: rb(:)
      integer :: j
      if (.not. ip%on) return
      allocate(rb(size(ip%rpos)))
      call par_alltoallv(k%a(ip%spos), ip%scnt, rb, ip%rcnt)
      do j = 1, size(ip%rpos)          ! (rank blocks in rank order)
         k%a(ip%rpos(j)) = k%a(ip%rpos(j)) + rb(j)
      end do
   end subroutine ipar_assemble

   !> f = the sum over the ranks of their partial f, in rank order, the same on every rank.
   subroutine ipar_sum(ip, f)
      type(ipar_t), intent(in) :: ip
      real(wp), intent(inout) :: f(:, :)
      real(wp), allocatable :: rb(:)
      integer :: n, r
      if (.not. ip%on) return
      n = size(f)
      call par_allgatherv_real(reshape(f, [n]), rb)
      f = reshape(rb(1:n), shape(f))
      do r = 1, ip%np - 1
         f = f + reshape(rb(r*n + 1:(r + 1)*n), shape(f))
      end do
   end subroutine ipar_sum

   !> x = its owner's values on every rank (x zero on the other ranks: the sum is exact).
   subroutine ipar_exact(ip, x)
      type(ipar_t), intent(in) :: ip
      real(wp), intent(inout) :: x(:)
      if (.not. ip%on) return
      if (size(x) == 0) return
      call par_allreduce(x, PAR_SUM)
   end subroutine ipar_exact

   !> x from rank 0 (the MUMPS host's solution) to every rank.
   subroutine ipar_bcast(ip, x)
      type(ipar_t), intent(in) :: ip
      real(wp), intent(inout) :: x(:)
      if (.not. ip%on) return
      call par_bcast_real(x, 0)
   end subroutine ipar_bcast

   !> Integers from rank 0 to every rank (the null pivots' equations, host's list).
   subroutine ipar_bcast_int(ip, iv)
      type(ipar_t), intent(in) :: ip
      integer, intent(inout) :: iv(:)
      real(wp) :: x(size(iv))
      if (.not. ip%on) return
      x = real(iv, wp)
      call par_bcast_real(x, 0)
      iv = nint(x)
   end subroutine ipar_bcast_int

   !> The smallest key over the ranks (a failed element: the first in serial order).
   subroutine ipar_first(ip, key)
      type(ipar_t), intent(in) :: ip
      integer, intent(inout) :: key
      if (.not. ip%on) return
      call par_allreduce(key, PAR_MIN)
   end subroutine ipar_first

   !> Collective after the start and every step (MPI, every rank; no-op serially): a failure
   !> (found on every rank alike) is known to all and the run stops together (dx_par_agree).
   subroutine ipar_agree(error)
      type(error_t), allocatable, intent(inout) :: error
      if (par_size() <= 1) return
      call par_agree(error)
   end subroutine ipar_agree

   !> Whether a failure is known to every rank (always in a serial run).
   logical function ipar_agreed(ip)
      type(ipar_t), intent(in) :: ip
      ipar_agreed = .not. ip%on .or. par_agreed()
   end function ipar_agreed

   !> The communicator MUMPS factorizes on (every rank of the run).
   integer function ipar_comm()
      ipar_comm = par_comm_handle()
   end function ipar_comm

   !> The stop/dump requests' maximum over the ranks (dx_checkpoint's replicated runs).
   subroutine ipar_max_flags(flags)
      integer, intent(inout) :: flags(:)
      call par_allreduce(flags, PAR_MAX)
   end subroutine ipar_max_flags

   !> Every rank's value x, in rank order, on every rank ([x] serially).
   function ipar_per_rank(x) result(v)
      real(wp), intent(in) :: x
      real(wp), allocatable :: v(:)
      call par_allgatherv_real([x], v)
   end function ipar_per_rank

   !> The whole tangent on every rank (after ipar_assemble; the singular-stiffness diagnosis
   !> multiplies by it): the owners' sums, zero elsewhere, summed over the ranks (exact).
   subroutine ipar_global(ip, k)
      type(ipar_t), intent(in) :: ip
      type(sparse_sym_t), intent(inout) :: k
      if (.not. ip%on) return
      where (.not. ip%owned) k%a = 0.0_wp
      call par_allreduce(k%a, PAR_SUM)
   end subroutine ipar_global
end module dx_implicit_par
