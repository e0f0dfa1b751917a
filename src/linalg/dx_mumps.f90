!> The sparse direct solver: the only user of MUMPS (Amestoy, Duff, L'Excellent & Koster,
!> "A fully asynchronous multifrontal solver using distributed dynamic scheduling", SIAM J.
!> Matrix Anal. Appl. 23 (2001) 15-41; MUMPS 5.5 Users' guide, Debian libmumps-dev 5.5.1).
!> A symmetric matrix (dx_sparse: the upper triangle as COO triples, centralized on the host)
!> goes through JOB = -1 (init: SYM = 2 general symmetric, so an indefinite tangent past a
!> limit point factors too, or SYM = 0 for an unsymmetric one, every entry stored; PAR = 1
!> the host works), JOB = 1 (analysis, once per pattern:
!> ICNTL(7) = 5 METIS ordering), JOB = 2 (factorization, once per Newton matrix), JOB = 3
!> (solve) and JOB = -2 (end). MUMPS's own printing is off (ICNTL(1:4)); INFOG(1) < 0 becomes
!> a dynx error naming MUMPS's code. Null pivots are detected (ICNTL(24) = 1, a pivot row of
!> infinity norm below CNTL(3) = 1e-12 ||A|| is null): the factorization then succeeds
!> and the caller reads the null equations (null_eq) to name the free nodes and modes; MUMPS's
!> -10 (numerically singular) is reported the same way.
!> comm: the MPI communicator's Fortran handle (a serial run: MPI_COMM_SELF, which the
!> engine's dx_par%par_self_handle gives after starting MPI; linalg itself uses no MPI).
!> MPI runs (loc given to analyse): the distributed assembled input (ICNTL(18) = 3, users'
!> guide 5.2.2.2): each rank passes the entries loc(:) of s that it assembled (IRN_loc,
!> JCN_loc, A_loc; MUMPS sums an entry given by several ranks), MUMPS factorizes on every
!> rank of comm; the right-hand side and the solution are centralized on the host (rank 0
!> of comm: ICNTL(20) = 0, ICNTL(21) = 0): solve's b is the solution on the host only (the
!> caller broadcasts it); INFOG (nnull) is global, null_eq is the host's.
module dx_mumps
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str
   use dx_sparse, only: sparse_sym_t
   implicit none
   private
   public :: mumps_t
   include 'dmumps_struc.h'

   interface
      !> MUMPS's double-precision driver (the JOB in id says what it does)
      subroutine dmumps(id)
         import :: dmumps_struc
         type(dmumps_struc), intent(inout) :: id
      end subroutine dmumps
   end interface

   type :: mumps_t
      type(dmumps_struc) :: id
      logical :: on = .false.          !< JOB = -1 done
      logical :: analysed = .false.    !< JOB = 1 done for the current pattern
      integer :: nnull = 0             !< null pivots of the last factorization
      integer, allocatable :: null_eq(:)   !< their equations
      real(wp) :: flops = 0.0_wp           !< this process's elimination flops so far (RINFO(3))
      logical :: dist = .false.            !< distributed assembled input (ICNTL(18) = 3)
      integer, allocatable :: loc(:)       !< its entries (positions in the matrix's values)
      real(wp) :: null_tol = 1.0e-12_wp    !< CNTL(3): null pivot threshold relative to ||A||
   contains
      procedure :: analyse => m_analyse
      procedure :: factor => m_factor
      procedure :: solve => m_solve
      procedure :: finish => m_finish
   end type mumps_t

contains

   !> Init (first call) and the analysis of s's pattern (ordering, symbolic factorization).
   subroutine m_analyse(self, s, comm, error, loc)
      class(mumps_t), intent(inout) :: self
      type(sparse_sym_t), intent(in) :: s
      integer, intent(in) :: comm
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: loc(:)   !< MPI: this rank's entries (distributed input)
      if (.not. self%on) then
         self%id%COMM = comm
         self%id%SYM = 2
         if (.not. s%sym) self%id%SYM = 0     ! unsymmetric (LU): the friction tangent
         self%id%PAR = 1
         self%id%JOB = -1
         call dmumps(self%id)
         if (self%id%INFOG(1) < 0) then
            call fail(self, 'initialization (JOB = -1)', error)
            return
         end if
         self%on = .true.
      end if
      call quiet(self)
      if (associated(self%id%IRN)) deallocate(self%id%IRN)
      if (associated(self%id%JCN)) deallocate(self%id%JCN)
      if (associated(self%id%A)) deallocate(self%id%A)
      if (associated(self%id%RHS)) deallocate(self%id%RHS)
      self%id%N = s%n
      if (present(loc)) then
         call dist_entries(self, s, loc)
      else
         self%id%NNZ = int(s%nnz, kind(self%id%NNZ))
         allocate(self%id%IRN(s%nnz), self%id%JCN(s%nnz), self%id%A(s%nnz), self%id%RHS(s%n))
         self%id%IRN = s%irn
         self%id%JCN = s%col
         self%id%A = 0.0_wp
      end if
      self%id%JOB = 1
      call dmumps(self%id)
      if (self%id%INFOG(1) < 0) then
         call fail(self, 'analysis (JOB = 1)', error)
         return
      end if
      self%analysed = .true.
   end subroutine m_analyse

   !> Numerical factorization of s's values (the pattern analysed before). A null pivot is
   !> not an error here: nnull > 0 and null_eq list the equations (the caller names them).
   subroutine m_factor(self, s, error)
      class(mumps_t), intent(inout) :: self
      type(sparse_sym_t), intent(in) :: s
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      if (.not. self%analysed) then
         call set_error(error, 'sparse solver: factorization before analysis', EXIT_NUMERIC)
         return
      end if
      call quiet(self)
      if (self%dist) then
         self%id%A_loc = s%a(self%loc)
      else
         self%id%A = s%a
      end if
      self%id%ICNTL(24) = 1
      self%id%CNTL(3) = self%null_tol
      self%id%JOB = 2
      call dmumps(self%id)
      self%nnull = 0
      if (allocated(self%null_eq)) deallocate(self%null_eq)
      if (self%id%INFOG(1) == -10) then
         self%nnull = 1
         self%null_eq = [max(1, self%id%INFOG(2))]
         return
      end if
      if (self%id%INFOG(1) < 0) then
         call fail(self, 'factorization (JOB = 2)', error)
         return
      end if
      self%flops = self%flops + self%id%RINFO(3)
      if (self%id%INFOG(28) > 0) then
         self%nnull = self%id%INFOG(28)
         allocate(self%null_eq(self%nnull))
         self%null_eq = 0
         if (self%id%MYID == 0) then       ! (the host's list; MPI: the caller broadcasts it)
            do k = 1, self%nnull
               self%null_eq(k) = self%id%PIVNUL_LIST(k)
            end do
         end if
      end if
   end subroutine m_factor

   !> Solve A x = b with the last factorization (b becomes x).
   subroutine m_solve(self, b, error)
      class(mumps_t), intent(inout) :: self
      real(wp), intent(inout) :: b(:)
      type(error_t), allocatable, intent(out) :: error
      call quiet(self)
      self%id%RHS = b
      self%id%JOB = 3
      call dmumps(self%id)
      if (self%id%INFOG(1) < 0) then
         call fail(self, 'solve (JOB = 3)', error)
         return
      end if
      b = self%id%RHS
   end subroutine m_solve

   !> End (JOB = -2) and free the arrays.
   subroutine m_finish(self)
      class(mumps_t), intent(inout) :: self
      if (.not. self%on) return
      if (associated(self%id%IRN)) deallocate(self%id%IRN)
      if (associated(self%id%JCN)) deallocate(self%id%JCN)
      if (associated(self%id%A)) deallocate(self%id%A)
      if (associated(self%id%RHS)) deallocate(self%id%RHS)
      call free_loc(self)
      self%id%JOB = -2
      call dmumps(self%id)
      self%on = .false.
      self%analysed = .false.
   end subroutine m_finish

   !> The distributed assembled input: this rank's entries loc of s's pattern (their
   !> values at each factorization), the right-hand side on every rank (the host's is used).
   subroutine dist_entries(self, s, loc)
      class(mumps_t), intent(inout) :: self
      type(sparse_sym_t), intent(in) :: s
      integer, intent(in) :: loc(:)
      call free_loc(self)
      self%dist = .true.
      self%loc = loc
      self%id%ICNTL(18) = 3
      self%id%NNZ_loc = int(size(loc), kind(self%id%NNZ_loc))
      allocate(self%id%IRN_loc(size(loc)), self%id%JCN_loc(size(loc)), &
               self%id%A_loc(size(loc)), self%id%RHS(s%n))
      self%id%IRN_loc = s%irn(loc)
      self%id%JCN_loc = s%col(loc)
      self%id%A_loc = 0.0_wp
   end subroutine dist_entries

   subroutine free_loc(self)
      class(mumps_t), intent(inout) :: self
      if (associated(self%id%IRN_loc)) deallocate(self%id%IRN_loc)
      if (associated(self%id%JCN_loc)) deallocate(self%id%JCN_loc)
      if (associated(self%id%A_loc)) deallocate(self%id%A_loc)
   end subroutine free_loc

   !> MUMPS prints nothing (errors come back through INFOG); METIS ordering.
   subroutine quiet(self)
      class(mumps_t), intent(inout) :: self
      self%id%ICNTL(1) = -1
      self%id%ICNTL(2) = -1
      self%id%ICNTL(3) = -1
      self%id%ICNTL(4) = 0
      self%id%ICNTL(7) = 5
   end subroutine quiet

   subroutine fail(self, what, error)
      class(mumps_t), intent(in) :: self
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: why
      select case (self%id%INFOG(1))
      case (-5, -7, -9, -13)
         why = 'out of memory'
      case (-6)
         why = 'the matrix is structurally singular'
      case (-10)
         why = 'the matrix is numerically singular'
      case default
         why = 'see the MUMPS 5.5 users'' guide, section "Error diagnostics"'
      end select
      call set_error(error, 'sparse solver (MUMPS) '//what//' failed: INFOG(1) = '// &
         str(self%id%INFOG(1))//', INFOG(2) = '//str(self%id%INFOG(2))//' ('//why//')', &
         EXIT_NUMERIC)
   end subroutine fail
end module dx_mumps
