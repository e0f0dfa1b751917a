!> Wall-clock time.
module dx_timer
   use dx_kinds, only: wp, i8
   implicit none
   private
   public :: wall_time, peak_memory_kb, current_memory_kb
contains
   !> Seconds since an arbitrary origin, from system_clock.
   function wall_time() result(t)
      real(wp) :: t
      integer(i8) :: c, r
      call system_clock(c, r)
      t = real(c, wp)/real(r, wp)
   end function wall_time

   !> Peak resident memory of this process in KiB (VmHWM from /proc/self/status; 0 if unknown).
   function peak_memory_kb() result(kb)
      integer(i8) :: kb
      kb = status_kb('VmHWM:')
   end function peak_memory_kb

   !> Resident memory of this process now in KiB (VmRSS; 0 if unknown).
   function current_memory_kb() result(kb)
      integer(i8) :: kb
      kb = status_kb('VmRSS:')
   end function current_memory_kb

   !> A "Name: value kB" line of /proc/self/status (0 if unknown).
   function status_kb(name) result(kb)
      character(6), intent(in) :: name
      integer(i8) :: kb
      character(256) :: line
      integer :: u, ios
      kb = 0
      open(newunit=u, file='/proc/self/status', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:6) == name) then
            read(line(7:), *, iostat=ios) kb
            exit
         end if
      end do
      close(u)
   end function status_kb
end module dx_timer
