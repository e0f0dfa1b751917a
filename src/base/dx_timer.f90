!> Wall-clock time.
module dx_timer
   use dx_kinds, only: wp, i8
   implicit none
   private
   public :: wall_time
contains
   !> Seconds since an arbitrary origin, from system_clock.
   function wall_time() result(t)
      real(wp) :: t
      integer(i8) :: c, r
      call system_clock(c, r)
      t = real(c, wp)/real(r, wp)
   end function wall_time
end module dx_timer
