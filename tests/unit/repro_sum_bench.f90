!> make bench: the cost of one exact deposit (dx_repro_sum rs_add) against a plain double
!> sum, per value, on N values of both signs from 1e-30 to 1e12 (as energies span), the
!> two variants alternating in one run (R rounds, the best round of each reported), plus
!> the rounding (rs_value) and the normalisation of one sum. Prints
!>   'plain <ns per value>', 'exact <ns>', 'ratio <exact/plain>', 'value <ns per rs_value>'
!> and checks that the exact sum is within 1e-12 relative of the plain one (it must be
!> close: a wrong deposit shows). Arguments: N (default 1000000), R (default 7).
program repro_sum_bench
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use dx_kinds, only: wp
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_value
   implicit none
   integer :: n, r, i, k
   character(32) :: arg
   real(wp), allocatable :: x(:)
   real(wp) :: plain, exact, tp, te, tv, t0, best_p, best_e, best_v
   type(rsum_t) :: s
   integer(int64) :: seed = 88172645463325252_int64
   n = 1000000; r = 7
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg); read(arg, *) n
   end if
   if (command_argument_count() >= 2) then
      call get_command_argument(2, arg); read(arg, *) r
   end if
   allocate(x(n))
   do i = 1, n
      x(i) = 10.0_wp**(-30.0_wp + 42.0_wp*urand())
      if (urand() < 0.5_wp) x(i) = -x(i)
   end do
   best_p = huge(1.0_wp); best_e = huge(1.0_wp); best_v = huge(1.0_wp)
   call rs_init(s, 1)
   do k = 1, r
      t0 = now()
      plain = 0.0_wp
      do i = 1, n
         plain = plain + x(i)
      end do
      tp = now() - t0
      t0 = now()
      call rs_init(s, 1)
      do i = 1, n
         call rs_add(s, 1, x(i))
      end do
      te = now() - t0
      t0 = now()
      do i = 1, 1000
         exact = rs_value(s, 1)
      end do
      tv = (now() - t0)/1000
      best_p = min(best_p, tp); best_e = min(best_e, te); best_v = min(best_v, tv)
   end do
   write(output_unit, '(a,i0,a,i0)') 'n ', n, ' rounds ', r
   write(output_unit, '(a,f10.3)') 'plain ', 1.0e9_wp*best_p/n
   write(output_unit, '(a,f10.3)') 'exact ', 1.0e9_wp*best_e/n
   write(output_unit, '(a,f10.2)') 'ratio ', best_e/max(best_p, tiny(1.0_wp))
   write(output_unit, '(a,f10.1)') 'value ', 1.0e9_wp*best_v
   write(output_unit, '(a,2es24.16)') 'sums ', plain, exact
   if (.not. abs(exact - plain) <= 1.0e-12_wp*maxval(abs(x))*n) then
      write(output_unit, '(a)') 'repro_sum_bench: exact and plain sums disagree'
      error stop 1
   end if
contains
   real(wp) function urand()
      seed = ieor(seed, shiftl(seed, 13))
      seed = ieor(seed, shiftr(seed, 7))
      seed = ieor(seed, shiftl(seed, 17))
      urand = real(shiftr(seed, 11), wp)*2.0_wp**(-53)
   end function urand
   real(wp) function now()
      integer(int64) :: c, rate
      call system_clock(c, rate)
      now = real(c, wp)/real(rate, wp)
   end function now
end program repro_sum_bench
