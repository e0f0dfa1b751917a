!> MPI test of the exact reproducible sum (dx_repro_sum) with real ranks, run by
!> scripts/run_mpi_tests.sh serially and under mpirun -np 2, 3, 4. Every rank makes the same
!> 20000 values (both signs, 1e-30 .. 1e12) and deposits a scattered share of them (value i
!> on rank mod(7919 i, NP)), three sums at once (the values, their squares, minus the
!> values); one rs_reduce: on every rank the bits of each sum equal those of one
!> accumulator over all the values in order (the serial sum), for any NP. A NaN deposited on
!> the last rank alone is seen as NaN by every rank; a +Inf on rank 0 alone as +Inf.
program mpi_repro_test
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                            ieee_is_nan
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_allreduce, PAR_MAX
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_value, rs_reduce
   use dx_assert, only: check, assert_summary
   implicit none
   type(error_t), allocatable :: error
   integer, parameter :: n = 20000
   integer(int64) :: seed = 88172645463325252_int64
   real(wp) :: x(n), pinf
   type(rsum_t) :: loc, ref
   integer :: np, me, i
   logical :: ok

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size()
   me = par_rank()
   if (me == 0) write(output_unit, '(a,i0,a)') 'mpi_repro_test on ', np, ' rank(s)'
   do i = 1, n
      x(i) = 10.0_wp**(-30.0_wp + 42.0_wp*urand())
      if (urand() < 0.5_wp) x(i) = -x(i)
   end do
   call rs_init(ref, 3)
   call rs_init(loc, 3)
   do i = 1, n
      call put(ref, x(i))
      if (mod(7919*i, np) == me) call put(loc, x(i))
   end do
   call rs_reduce(loc)
   ok = .true.
   do i = 1, 3
      ok = ok .and. transfer(rs_value(loc, i), 0_int64) == transfer(rs_value(ref, i), 0_int64)
   end do
   call check_all(ok, 'repro over the ranks: 3 sums of 20000 values, serial bits')
   call rs_init(loc, 2)
   call rs_add(loc, 1, 1.0_wp)
   call rs_add(loc, 2, 1.0_wp)
   if (me == np - 1) call rs_add(loc, 1, ieee_value(1.0_wp, ieee_quiet_nan))
   if (me == 0) call rs_add(loc, 2, ieee_value(1.0_wp, ieee_positive_inf))
   call rs_reduce(loc)
   pinf = ieee_value(1.0_wp, ieee_positive_inf)
   call check_all(ieee_is_nan(rs_value(loc, 1)), 'repro over the ranks: a NaN on one rank')
   call check_all(rs_value(loc, 2) == pinf, 'repro over the ranks: +Inf on rank 0')
   call par_finalize()
   if (me == 0) call assert_summary()

contains

   subroutine put(s, v)
      type(rsum_t), intent(inout) :: s
      real(wp), intent(in) :: v
      call rs_add(s, 1, v)
      call rs_add(s, 2, v*v)
      call rs_add(s, 3, -v)
   end subroutine put

   real(wp) function urand()
      seed = ieor(seed, shiftl(seed, 13))
      seed = ieor(seed, shiftr(seed, 7))
      seed = ieor(seed, shiftl(seed, 17))
      urand = real(shiftr(seed, 11), wp)*2.0_wp**(-53)
   end function urand

   subroutine check_all(ok, name)
      logical, intent(in) :: ok
      character(*), intent(in) :: name
      integer :: bad
      bad = merge(0, 1, ok)
      call par_allreduce(bad, PAR_MAX)
      if (me == 0) call check(bad == 0, name)
   end subroutine check_all
end program mpi_repro_test
