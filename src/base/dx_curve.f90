!> Load curves (*DEFINE_CURVE): piecewise-linear y(x) with LS-DYNA scale and offset factors,
!> constant extrapolation beyond the ends as LS-DYNA does for load curves
!> (value at first/last point; LS-DYNA extrapolates hardening curves linearly: see eval_extrap).
module dx_curve
   use dx_kinds, only: wp
   implicit none
   private
   public :: curve_t

   type :: curve_t
      integer :: label = 0
      integer :: sidr = 0
      real(wp) :: sfa = 1.0_wp, sfo = 1.0_wp, offa = 0.0_wp, offo = 0.0_wp
      integer :: dattyp = 0
      real(wp), allocatable :: x(:), y(:)   !< abscissa (already sfa*x+offa) and ordinate (sfo*y+offo)
   contains
      procedure :: eval          !< value, constant beyond the ends
      procedure :: eval_extrap   !< value, linear extrapolation beyond the ends
      procedure :: slope         !< slope of the segment that holds x
   end type curve_t

contains

   pure integer function find_segment(c, x) result(k)
      type(curve_t), intent(in) :: c
      real(wp), intent(in) :: x
      integer :: lo, hi, mid
      lo = 1; hi = size(c%x)
      if (hi < 2) then
         k = 1; return
      end if
      if (x <= c%x(1)) then
         k = 1; return
      end if
      if (x >= c%x(hi)) then
         k = hi - 1; return
      end if
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (c%x(mid) <= x) then
            lo = mid
         else
            hi = mid
         end if
      end do
      k = lo
   end function find_segment

   !> y(x), linear between points, constant beyond the first and last point.
   pure real(wp) function eval(self, x) result(y)
      class(curve_t), intent(in) :: self
      real(wp), intent(in) :: x
      integer :: k, n
      n = size(self%x)
      if (n == 0) then
         y = 0.0_wp
      else if (n == 1 .or. x <= self%x(1)) then
         y = self%y(1)
      else if (x >= self%x(n)) then
         y = self%y(n)
      else
         k = find_segment(self, x)
         y = self%y(k) + (self%y(k+1) - self%y(k))*(x - self%x(k))/(self%x(k+1) - self%x(k))
      end if
   end function eval

   !> y(x), linear between points and extrapolated linearly beyond the ends.
   pure real(wp) function eval_extrap(self, x) result(y)
      class(curve_t), intent(in) :: self
      real(wp), intent(in) :: x
      integer :: k
      if (size(self%x) < 2) then
         y = self%eval(x); return
      end if
      k = find_segment(self, x)
      y = self%y(k) + (self%y(k+1) - self%y(k))*(x - self%x(k))/(self%x(k+1) - self%x(k))
   end function eval_extrap

   !> dy/dx of the segment holding x (the last segment beyond the end).
   pure real(wp) function slope(self, x) result(s)
      class(curve_t), intent(in) :: self
      real(wp), intent(in) :: x
      integer :: k
      if (size(self%x) < 2) then
         s = 0.0_wp; return
      end if
      k = find_segment(self, x)
      s = (self%y(k+1) - self%y(k))/(self%x(k+1) - self%x(k))
   end function slope
end module dx_curve
