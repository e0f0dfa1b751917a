!> MPI test of the engine's failure path (dx_par_engine), run by scripts/run_mpi_tests.sh
!> serially and under `mpirun --oversubscribe -np 2/3/4`: a failure kept on one rank
!> (par_engine_defer) reaches every rank through the MINLOC (par_engine_sync_failure at the
!> last cycle, par_engine_dt in a cycle) with the failing rank's message, "rank R of N"
!> and its exit code; with two failing ranks the lowest is reported; without a failure
!> nothing is reported. Rank 0 prints the checks; each holds on every rank.
program mpi_fail_test
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_allreduce, PAR_MIN
   use dx_par_engine, only: par_engine_t, par_engine_defer, par_engine_pending, &
                            par_engine_sync_failure, par_engine_dt, par_engine_together
   use dx_assert, only: check, assert_summary
   implicit none
   type(error_t), allocatable :: error, e
   type(par_engine_t) :: eng           ! the engine's state (a component of the MPI domain)
   integer :: np, me, el
   real(wp) :: dt

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size()
   me = par_rank()

   call par_engine_sync_failure(eng, error)
   call all_check(.not. allocated(error) .and. .not. par_engine_together(eng), &
                  'no failure: nothing reported')

   if (me == np - 1) then
      call set_error(e, 'non-finite velocity (NaN or Inf) at node 42 at cycle 7, time 1.5', &
                     EXIT_NUMERIC)
      call par_engine_defer(eng, e)
      call all_check(.not. allocated(e) .and. par_engine_pending(eng), 'deferred: kept here')
   else
      call all_check(.not. par_engine_pending(eng), 'other ranks hold nothing')
   end if
   call par_engine_sync_failure(eng, error)
   call all_check(allocated(error), 'last cycle: every rank knows the failure')
   if (allocated(error)) then
      call all_check(error%message == 'rank '//str(np - 1)//' of '//str(np)// &
         ': non-finite velocity (NaN or Inf) at node 42 at cycle 7, time 1.5', &
         'message of the failing rank, naming it')
      call all_check(error%code == EXIT_NUMERIC, 'exit code 3')
      deallocate(error)
   end if
   call all_check(par_engine_together(eng), 'stop together (no MPI_Abort)')

   ! two failing ranks in a cycle: the dt reduction reports the lowest
   if (me == 0) then
      call set_error(e, 'negative volume in element 4711 (part 1) at cycle 9, time 2.0', &
                     EXIT_NUMERIC)
      call par_engine_defer(eng, e)
   end if
   dt = 1.0e-3_wp*(me + 1)
   el = 0
   call par_engine_dt(eng, dt, el, error)
   call all_check(allocated(error) .and. dt < 0.0_wp, 'in a cycle: the dt MINLOC carries it')
   if (allocated(error)) then
      if (np > 1) then
         call all_check(error%message == 'rank 0 of '//str(np)// &
            ': negative volume in element 4711 (part 1) at cycle 9, time 2.0', &
            'two failing ranks: the lowest is named')
      else       ! one rank: the failure it kept first
         call all_check(index(error%message, 'rank 0 of 1: non-finite velocity') == 1, &
                        'one rank: the first failure kept is named')
      end if
   end if
   if (me == 0) call assert_summary()
   call par_finalize()

contains

   !> A check that passes only when cond holds on every rank (printed by rank 0).
   subroutine all_check(cond, name)
      logical, intent(in) :: cond
      character(*), intent(in) :: name
      integer :: ok
      ok = merge(1, 0, cond)
      call par_allreduce(ok, PAR_MIN)
      if (me == 0) then
         call check(ok == 1, name)
      end if
   end subroutine all_check
end program mpi_fail_test
