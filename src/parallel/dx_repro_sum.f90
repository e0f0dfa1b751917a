!> Reproducible global sums: an exact fixed-point long accumulator for IEEE-754 doubles.
!> Every double is an integer multiple of 2^-1074, so the exact sum of any set of finite
!> doubles is an integer times 2^-1074 that fits in RS_NL = 68 limbs of 32 bits (bits 0..2175;
!> the largest double, 2^1024, is bit 2098, which leaves 2^31 values of headroom, twice over).
!> A value is deposited without rounding: its 53-bit significand, shifted to its exponent,
!> is split over three consecutive limbs and added (sign included) to them; each limb is an
!> int64, so 2^30 deposits (or 2^30 merged accumulators) fit before a carry normalisation
!> (rs_normalize: limbs 0..66 into [0, 2^32), the carry into the next; the top limb keeps
!> the sign), which then gives the unique representation of the exact integer. The sum is
!> therefore exact, independent of the order of the deposits and of any split of the data
!> over accumulators; merging two accumulators (limb-wise integer addition) is exact and
!> associative, so MPI_Allreduce(MPI_SUM) of normalised limbs over the ranks (rs_reduce,
!> through dx_par: one int64 allreduce for all the sums of an output event) gives the same
!> integer, and after normalisation the same bits, for any NP and any reduction tree. The
!> value (rs_value) is the exact sum rounded once to the nearest double (ties to even;
!> overflow gives +-Inf, an exact zero +0). Infinities and NaNs are counted apart (a NaN,
!> or +Inf and -Inf together, give NaN; +Inf or -Inf alone give it), so a NaN energy on
!> any rank is still seen.
!> Method: the long (Kulisch) accumulator, U. Kulisch and W. L. Miranker, "Computer
!> Arithmetic in Theory and Practice", Academic Press 1981, and U. Kulisch, "Computer
!> Arithmetic and Validity", de Gruyter 2013 (exact dot product in a fixed-point register
!> spanning the whole exponent range); the int64 limbs of 32 bits with carry headroom and
!> deferred carry propagation are the "small superaccumulator" of R. M. Neal, "Fast exact
!> summation using small and large superaccumulators", arXiv:1505.05571 (2015). The binned
!> reproducible sum of J. Demmel and H. D. Nguyen, "Parallel Reproducible Summation", IEEE
!> Trans. Computers 64(7), 2015 (ReproBLAS) is cheaper per value but not exact; the exact
!> sum was preferred here because the cost only arises at output cycles (docs/history.md,
!> "Reproducible sums": ns per value and whole-run cost measured by scripts/bench_repro_sum.sh).
!> A set of sums is one rsum_t (a(0:RS_W-1, n)): slot RS_CNT counts deposits since the
!> last normalisation, RS_NAN, RS_PINF, RS_NINF count NaNs and infinities.
module dx_repro_sum
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                            ieee_negative_inf
   use dx_kinds, only: wp
   use dx_par, only: par_allreduce_i8
   implicit none
   private
   public :: rsum_t, rs_init, rs_clear, rs_add, rs_merge, rs_normalize, rs_value, rs_reduce, &
             rs_count, rs_add_sum, RS_W

   integer, parameter :: RS_NL = 68                  !< limbs 0..67 of 32 bits
   integer, parameter :: RS_CNT = RS_NL, RS_NAN = RS_NL + 1, RS_PINF = RS_NL + 2, &
                         RS_NINF = RS_NL + 3
   integer, parameter :: RS_W = RS_NL + 4            !< int64 words per sum
   integer(int64), parameter :: MASK32 = 4294967295_int64          ! 2^32 - 1
   integer(int64), parameter :: MASK52 = 4503599627370495_int64    ! 2^52 - 1
   integer(int64), parameter :: HIDDEN = 4503599627370496_int64    ! 2^52
   integer(int64), parameter :: MAXCNT = 1073741824_int64          ! 2^30 deposits

   !> n exact sums (sum k: a(:, k)).
   type :: rsum_t
      integer(int64), allocatable :: a(:, :)
   end type rsum_t

contains

   !> n sums, all zero.
   subroutine rs_init(s, n)
      type(rsum_t), intent(inout) :: s
      integer, intent(in) :: n
      if (allocated(s%a)) then
         if (size(s%a, 2) /= n) deallocate(s%a)
      end if
      if (.not. allocated(s%a)) allocate(s%a(0:RS_W - 1, n))
      s%a = 0_int64
   end subroutine rs_init

   subroutine rs_clear(s)
      type(rsum_t), intent(inout) :: s
      s%a = 0_int64
   end subroutine rs_clear

   !> The number of sums.
   integer function rs_count(s)
      type(rsum_t), intent(in) :: s
      rs_count = 0
      if (allocated(s%a)) rs_count = size(s%a, 2)
   end function rs_count

   !> Sum k += x, exactly (no rounding; the order of deposits does not matter). The deposit
   !> of deposit(), written out on s%a(:, k) (the hot loop of every sum).
   subroutine rs_add(s, k, x)
      type(rsum_t), intent(inout) :: s
      integer, intent(in) :: k
      real(wp), intent(in) :: x
      integer(int64) :: b, m, r, t0, t1, t2, sg
      integer :: e, i, sh
      b = transfer(x, 0_int64)
      e = int(iand(shiftr(b, 52), 2047_int64))
      if (e == 0 .or. e == 2047) then         ! zero, subnormal, NaN, Inf: the general path
         call deposit(s%a(:, k), x)
         return
      end if
      m = ior(iand(b, MASK52), HIDDEN)
      i = shiftr(e - 1, 5)
      sh = iand(e - 1, 31)
      t0 = shiftl(iand(m, shiftl(1_int64, 32 - sh) - 1_int64), sh)
      r = shiftr(m, 32 - sh)
      t1 = iand(r, MASK32)
      t2 = shiftr(r, 32)
      sg = shifta(b, 63)                      ! 0 or -1: negate without a branch
      t0 = ieor(t0, sg) - sg
      t1 = ieor(t1, sg) - sg
      t2 = ieor(t2, sg) - sg
      s%a(i, k) = s%a(i, k) + t0
      s%a(i + 1, k) = s%a(i + 1, k) + t1
      s%a(i + 2, k) = s%a(i + 2, k) + t2
      s%a(RS_CNT, k) = s%a(RS_CNT, k) + 1
      if (s%a(RS_CNT, k) >= MAXCNT) call normalize(s%a(:, k))
   end subroutine rs_add

   !> One double into the limbs a(0:RS_W-1): significand m (53 bits with the hidden bit) at
   !> bit p = biased exponent - 1 (subnormals: p = 0), split into the limbs p/32 .. p/32+2.
   subroutine deposit(a, x)
      integer(int64), intent(inout) :: a(0:)
      real(wp), intent(in) :: x
      integer(int64) :: b, m, r, t0, t1, t2
      integer :: e, p, i, sh
      b = transfer(x, 0_int64)
      e = int(iand(shiftr(b, 52), 2047_int64))
      m = iand(b, MASK52)
      if (e == 2047) then                      ! NaN or +-Inf
         if (m /= 0_int64) then
            a(RS_NAN) = a(RS_NAN) + 1
         else if (b < 0_int64) then
            a(RS_NINF) = a(RS_NINF) + 1
         else
            a(RS_PINF) = a(RS_PINF) + 1
         end if
         return
      end if
      if (e == 0) then
         if (m == 0_int64) return              ! +-0 adds nothing
         p = 0
      else
         m = ior(m, HIDDEN)
         p = e - 1
      end if
      i = shiftr(p, 5)
      sh = iand(p, 31)
      t0 = shiftl(iand(m, shiftl(1_int64, 32 - sh) - 1_int64), sh)
      r = shiftr(m, 32 - sh)
      t1 = iand(r, MASK32)
      t2 = shiftr(r, 32)
      if (b < 0_int64) then
         a(i) = a(i) - t0
         a(i + 1) = a(i + 1) - t1
         a(i + 2) = a(i + 2) - t2
      else
         a(i) = a(i) + t0
         a(i + 1) = a(i + 1) + t1
         a(i + 2) = a(i + 2) + t2
      end if
      a(RS_CNT) = a(RS_CNT) + 1
      if (a(RS_CNT) >= MAXCNT) call normalize(a)
   end subroutine deposit

   !> Carry propagation: limbs 0..RS_NL-2 into [0, 2^32), the top limb signed (the unique
   !> representation of the integer); the deposit count restarts.
   subroutine normalize(a)
      integer(int64), intent(inout) :: a(0:)
      integer(int64) :: c, v
      integer :: i
      c = 0_int64
      do i = 0, RS_NL - 2
         v = a(i) + c
         a(i) = iand(v, MASK32)
         c = shifta(v, 32)
      end do
      a(RS_NL - 1) = a(RS_NL - 1) + c
      a(RS_CNT) = 0_int64
   end subroutine normalize

   !> Every sum of s in its normalised form.
   subroutine rs_normalize(s)
      type(rsum_t), intent(inout) :: s
      integer :: k
      do k = 1, size(s%a, 2)
         call normalize(s%a(:, k))
      end do
   end subroutine rs_normalize

   !> s += t, sum by sum (exact and associative: integer additions after normalisation).
   subroutine rs_merge(s, t)
      type(rsum_t), intent(inout) :: s
      type(rsum_t), intent(in) :: t
      type(rsum_t) :: u
      integer :: k
      u = t
      call rs_normalize(u)
      call rs_normalize(s)
      s%a = s%a + u%a
      do k = 1, size(s%a, 2)
         call normalize(s%a(:, k))
      end do
   end subroutine rs_merge

   !> Sum k of s += sum j of t, exactly.
   subroutine rs_add_sum(s, k, t, j)
      type(rsum_t), intent(inout) :: s
      integer, intent(in) :: k, j
      type(rsum_t), intent(in) :: t
      integer(int64) :: b(0:RS_W - 1)
      b = t%a(:, j)
      call normalize(b)
      call normalize(s%a(:, k))
      s%a(:, k) = s%a(:, k) + b
      call normalize(s%a(:, k))
   end subroutine rs_add_sum

   !> Over the ranks (collective; one MPI_Allreduce of int64 for all the sums of s): every
   !> rank gets the exact sums, normalised (the same bits for any NP). No-op on one rank
   !> apart from the normalisation.
   subroutine rs_reduce(s)
      type(rsum_t), intent(inout) :: s
      integer(int64), allocatable :: buf(:)
      call rs_normalize(s)
      buf = reshape(s%a, [size(s%a)])
      call par_allreduce_i8(buf)
      s%a = reshape(buf, shape(s%a))
      call rs_normalize(s)
   end subroutine rs_reduce

   !> Sum k rounded once to the nearest double (ties to even).
   real(wp) function rs_value(s, k) result(x)
      type(rsum_t), intent(in) :: s
      integer, intent(in) :: k
      integer(int64) :: a(0:RS_W - 1), w, mnt, rem
      integer :: t, nb, bits, i, kk, pos
      logical :: neg, sticky
      a = s%a(:, k)
      if (a(RS_NAN) > 0 .or. (a(RS_PINF) > 0 .and. a(RS_NINF) > 0)) then
         x = ieee_value(x, ieee_quiet_nan)
         return
      else if (a(RS_PINF) > 0) then
         x = ieee_value(x, ieee_positive_inf)
         return
      else if (a(RS_NINF) > 0) then
         x = ieee_value(x, ieee_negative_inf)
         return
      end if
      call normalize(a)
      neg = a(RS_NL - 1) < 0_int64
      if (neg) then
         a(0:RS_NL - 1) = -a(0:RS_NL - 1)
         call normalize(a)
      end if
      t = -1
      do i = RS_NL - 1, 0, -1
         if (a(i) /= 0_int64) then
            t = i
            exit
         end if
      end do
      if (t < 0) then
         x = 0.0_wp
         return
      end if
      if (t >= 66) then          ! 2^(32*66 - 1074) = 2^1038: beyond the largest double
         x = signed_inf(neg)
         return
      end if
      ! the leading bit pos = 32 t + nb - 1; the 63 bits from it down into w, the rest sticky
      nb = 64 - leadz(a(t))
      pos = 32*t + nb - 1
      w = a(t)
      bits = nb
      i = t - 1
      sticky = .false.
      do while (bits < 63 .and. i >= 0)
         kk = min(32, 63 - bits)
         w = ior(shiftl(w, kk), shiftr(a(i), 32 - kk))
         if (kk < 32) sticky = sticky .or. iand(a(i), shiftl(1_int64, 32 - kk) - 1_int64) /= 0
         bits = bits + kk
         i = i - 1
      end do
      if (bits < 63) w = shiftl(w, 63 - bits)
      do while (i >= 0)
         sticky = sticky .or. a(i) /= 0_int64
         i = i - 1
      end do
      ! w in [2^62, 2^63): 53 bits of significand, 10 rounding bits
      mnt = shiftr(w, 10)
      rem = iand(w, 1023_int64)
      if (rem > 512_int64 .or. (rem == 512_int64 .and. (sticky .or. btest(mnt, 0)))) &
         mnt = mnt + 1
      if (mnt == shiftl(1_int64, 53)) then
         mnt = shiftr(mnt, 1)
         pos = pos + 1
      end if
      if (pos - 1074 > 1023) then
         x = signed_inf(neg)
         return
      end if
      ! exact: below 2^-1022 (pos < 52) the bits under the accumulator's last are zeros
      x = scale(real(mnt, wp), pos - 52 - 1074)
      if (neg) x = -x
   end function rs_value

   real(wp) function signed_inf(neg) result(x)
      logical, intent(in) :: neg
      if (neg) then
         x = ieee_value(x, ieee_negative_inf)
      else
         x = ieee_value(x, ieee_positive_inf)
      end if
   end function signed_inf
end module dx_repro_sum
