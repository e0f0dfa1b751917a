!> The exact reproducible sum (src/parallel/dx_repro_sum.f90).
!>  * order and split: 2000 values of both signs from 1e-30 to 1e12 (and 2^-1074 .. 2^1000),
!>    permuted and cut into 1..7 pieces, each piece summed apart and the pieces merged in
!>    a random order: the same bits as the sum in the original order, every time.
!>  * against real128: values of 53 bits between 2^-20 and 2^20 have an exact real128 sum
!>    (at most 104 significant bits), which rounded once to double is the exact sum
!>    correctly rounded: equal bit for bit; data from 1e-30 to 1e12: within 1 ulp.
!>  * cancellation: 1e12 + 1e-30 - 1e12 is 1e-30; x and -x in any order give +0; huge +
!>    huge - huge - huge + 2^-1074 is 2^-1074 (no overflow inside the accumulator); the
!>    ties-to-even cases 1 + 2^-53 (1), 1 + 2^-52 + 2^-53 (1 + 2^-51), 1 + 2^-53 + 2^-80
!>    (1 + 2^-52, the sticky bit); subnormals add exactly.
!>  * NaN and infinities propagate: NaN + 1 is NaN, +Inf + 1 is +Inf, +Inf - Inf is NaN;
!>    huge + huge overflows to +Inf once rounded, -huge - huge to -Inf.
program test_repro_sum
   use, intrinsic :: iso_fortran_env, only: int64, real128
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                            ieee_negative_inf, ieee_is_nan
   use dx_kinds, only: wp
   use dx_assert, only: check, check_close, assert_summary
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_merge, rs_value, rs_reduce
   implicit none
   integer(int64) :: seed = 88172645463325252_int64
   call test_order_split(.false.)
   call test_order_split(.true.)
   call test_quad_exact()
   call test_quad_wide()
   call test_cancellation()
   call test_rounding()
   call test_special()
   call assert_summary()
contains

   !> xorshift64: the same numbers on every compiler.
   real(wp) function urand()
      seed = ieor(seed, shiftl(seed, 13))
      seed = ieor(seed, shiftr(seed, 7))
      seed = ieor(seed, shiftl(seed, 17))
      urand = real(shiftr(seed, 11), wp)*2.0_wp**(-53)
   end function urand

   !> n values, random sign, log-uniform magnitude between 10^lo and 10^hi.
   function wide(n, lo, hi) result(x)
      integer, intent(in) :: n
      real(wp), intent(in) :: lo, hi
      real(wp) :: x(n)
      integer :: i
      do i = 1, n
         x(i) = 10.0_wp**(lo + (hi - lo)*urand())
         if (urand() < 0.5_wp) x(i) = -x(i)
      end do
   end function wide

   real(wp) function rsum(x) result(v)
      real(wp), intent(in) :: x(:)
      type(rsum_t) :: s
      integer :: i
      call rs_init(s, 1)
      do i = 1, size(x)
         call rs_add(s, 1, x(i))
      end do
      call rs_reduce(s)         ! one rank: normalisation only
      v = rs_value(s, 1)
   end function rsum

   logical function same_bits(a, b)
      real(wp), intent(in) :: a, b
      same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
   end function same_bits

   subroutine test_order_split(extreme)
      logical, intent(in) :: extreme
      integer, parameter :: n = 2000
      real(wp) :: x(n), ref, got
      integer :: perm(n), cut(0:7), order(7), np, i, j, k, t, rep
      type(rsum_t) :: piece(7), tot
      logical :: ok
      if (extreme) then
         x = wide(n, -300.0_wp, 300.0_wp)
         x(1) = 2.0_wp**(-1074); x(2) = -huge(1.0_wp)/4; x(3) = huge(1.0_wp)/4
         x(4) = -2.0_wp**(-1073); x(5) = 0.0_wp; x(6) = -0.0_wp
      else
         x = wide(n, -30.0_wp, 12.0_wp)
      end if
      ref = rsum(x)
      ok = .true.
      do rep = 1, 5
         do np = 1, 7
            perm = [(i, i = 1, n)]
            do i = n, 2, -1             ! Fisher-Yates
               j = 1 + int(urand()*i)
               t = perm(i); perm(i) = perm(j); perm(j) = t
            end do
            cut(0) = 0; cut(np) = n
            do k = 1, np - 1
               cut(k) = cut(k - 1) + int(urand()*real(n - cut(k - 1), wp)/2)
            end do
            do k = 1, np
               call rs_init(piece(k), 1)
               do i = cut(k - 1) + 1, cut(k)
                  call rs_add(piece(k), 1, x(perm(i)))
               end do
            end do
            order(1:np) = [(k, k = np, 1, -1)]
            if (np > 2) order(1:2) = order(2:1:-1)
            call rs_init(tot, 1)
            do k = 1, np
               call rs_merge(tot, piece(order(k)))
            end do
            got = rs_value(tot, 1)
            ok = ok .and. same_bits(got, ref)
         end do
      end do
      if (extreme) then
         call check(ok, 'repro: 2^-1074..huge/4, 5 permutations x 1..7 pieces: same bits')
      else
         call check(ok, 'repro: 1e-30..1e12, 5 permutations x 1..7 pieces: same bits')
      end if
   end subroutine test_order_split

   subroutine test_quad_exact()
      integer, parameter :: n = 2000
      real(wp) :: x(n)
      real(real128) :: q
      integer :: i
      logical :: ok
      ok = .true.
      do i = 1, n
         x(i) = sign(1.0_wp, urand() - 0.5_wp)*2.0_wp**(-20 + int(urand()*40))*(1.0_wp + urand())
      end do
      q = 0.0_real128
      do i = 1, n
         q = q + real(x(i), real128)
      end do
      ok = same_bits(rsum(x), real(q, wp))
      call check(ok, 'repro: 2^-20..2^20, exact real128 sum rounded once: same bits')
      ! a sum whose exact value lies between two doubles: 2000 copies of 0.1 and 1
      x = 0.1_wp; x(1) = 1.0_wp
      q = 0.0_real128
      do i = 1, n
         q = q + real(x(i), real128)
      end do
      call check(same_bits(rsum(x), real(q, wp)), 'repro: 1 + 1999 x 0.1 = real128 sum rounded')
   end subroutine test_quad_exact

   subroutine test_quad_wide()
      integer, parameter :: n = 5000
      real(wp) :: x(n), v
      real(real128) :: q
      integer :: i
      x = abs(wide(n, -30.0_wp, 12.0_wp))    ! energies: positive, 1e-30 .. 1e12
      q = 0.0_real128
      do i = 1, n
         q = q + real(x(i), real128)
      end do
      v = rsum(x)
      call check(abs(real(q, wp) - v) <= spacing(v), 'repro: 1e-30..1e12 within 1 ulp of real128')
      x = wide(n, -30.0_wp, 12.0_wp)         ! both signs
      q = 0.0_real128
      do i = 1, n
         q = q + real(x(i), real128)
      end do
      v = rsum(x)
      call check(abs(real(q, wp) - v) <= spacing(v), &
                 'repro: +-1e-30..1e12 within 1 ulp of real128')
   end subroutine test_quad_wide

   subroutine test_cancellation()
      real(wp) :: x(1000), y(2000), h, d
      integer :: i
      call check(same_bits(rsum([1.0e12_wp, 1.0e-30_wp, -1.0e12_wp]), 1.0e-30_wp), &
                 'repro: 1e12 + 1e-30 - 1e12 = 1e-30 exactly')
      x = wide(1000, -30.0_wp, 12.0_wp)
      do i = 1, 1000       ! x(1), -x(1), x(2), ... interleaved from both ends
         y(2*i - 1) = x(i)
         y(2*i) = -x(1001 - i)
      end do
      call check(same_bits(rsum(y), 0.0_wp), 'repro: x and -x of 1000 values: +0')
      h = huge(1.0_wp)
      d = 2.0_wp**(-1074)
      call check(same_bits(rsum([h, h, -h, -h, d]), d), 'repro: huge+huge-huge-huge+2^-1074')
      call check(same_bits(rsum([d, d, d]), 3*d), 'repro: 3 x 2^-1074 exactly (subnormal)')
      call check(same_bits(rsum([-3.5_wp, 1.25_wp]), -2.25_wp), 'repro: negative result')
      call check(same_bits(rsum([-0.0_wp, 0.0_wp, -0.0_wp]), 0.0_wp), 'repro: zeros give +0')
      call check(same_bits(rsum([real(wp) ::]), 0.0_wp), 'repro: empty sum is +0')
   end subroutine test_cancellation

   subroutine test_rounding()
      real(wp) :: u
      u = 2.0_wp**(-53)
      call check(same_bits(rsum([1.0_wp, u]), 1.0_wp), 'repro: 1 + 2^-53 ties to even: 1')
      call check(same_bits(rsum([1.0_wp, 2*u, u]), 1.0_wp + 4*u), &
                 'repro: 1 + 2^-52 + 2^-53 ties to even: 1 + 2^-51')
      call check(same_bits(rsum([1.0_wp, u, 2.0_wp**(-80)]), 1.0_wp + 2*u), &
                 'repro: 1 + 2^-53 + 2^-80 rounds up (sticky)')
      call check(same_bits(rsum([-1.0_wp, -u, -2.0_wp**(-80)]), -1.0_wp - 2*u), &
                 'repro: the same negative')
      call check(same_bits(rsum([2.0_wp**1023, 2.0_wp**1023*(1 - u)]), &
                 ieee_value(1.0_wp, ieee_positive_inf)), 'repro: overflow on rounding: +Inf')
   end subroutine test_rounding

   subroutine test_special()
      real(wp) :: nan, pinf, ninf, h
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      pinf = ieee_value(1.0_wp, ieee_positive_inf)
      ninf = ieee_value(1.0_wp, ieee_negative_inf)
      h = huge(1.0_wp)
      call check(ieee_is_nan(rsum([1.0_wp, nan, 2.0_wp])), 'repro: NaN propagates')
      call check(same_bits(rsum([1.0_wp, pinf]), pinf), 'repro: +Inf + 1 = +Inf')
      call check(same_bits(rsum([ninf, 1.0e300_wp]), ninf), 'repro: -Inf + 1e300 = -Inf')
      call check(ieee_is_nan(rsum([pinf, 1.0_wp, ninf])), 'repro: +Inf - Inf = NaN')
      call check(same_bits(rsum([h, h]), pinf), 'repro: huge + huge = +Inf')
      call check(same_bits(rsum([-h, -h]), ninf), 'repro: -huge - huge = -Inf')
      call check(same_bits(rsum([h, h, -h]), h), 'repro: huge + huge - huge = huge')
   end subroutine test_special
end program test_repro_sum
