!> Batch-job signals, through bind(C) to signal(2) (POSIX; Linux numbers):
!>   SIGTERM, SIGINT: finish the current cycle, write a restart dump and the last plot
!>                    state, close every file, exit with EXIT_CHECKPOINT (5);
!>                    a second SIGTERM/SIGINT before that ends the process at once (_exit);
!>   SIGUSR1:         write a restart dump at the end of the current cycle and go on
!>                    (LS-DYNA's sense switch "sw3": write a restart file and continue).
!>   SIGXFSZ:         ignored, so a file-size limit (ulimit -f) makes write(2) fail with
!>                    EFBIG: an I/O error naming the file (exit 4), not a kill by signal.
!> The handler only stores the signal number in a C int (the sig_atomic_t idiom); the
!> solver polls it once per cycle. This is the only module-level mutable state of dynx
!> besides the log settings.
module dx_signals
   use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_intptr_t
   implicit none
   private
   public :: signals_install, signal_stop_requested, signal_dump_requested, signal_name, &
             signal_dump_pending, &
             SIGINT_NUM, SIGTERM_NUM, SIGUSR1_NUM, signal_raise

   integer(c_int), parameter :: SIGINT_NUM = 2, SIGUSR1_NUM = 10, SIGTERM_NUM = 15
   integer(c_int), parameter :: SIGXFSZ_NUM = 25

   integer(c_int), volatile, save :: stop_sig = 0    !< SIGTERM/SIGINT received (its number)
   integer(c_int), volatile, save :: dump_sig = 0    !< SIGUSR1 received, not yet served

   interface
      function c_signal(sig, handler) bind(C, name='signal') result(old)
         import :: c_int, c_funptr
         integer(c_int), value :: sig
         type(c_funptr), value :: handler
         type(c_funptr) :: old
      end function c_signal
      subroutine c_exit_now(status) bind(C, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit_now
      function c_raise(sig) bind(C, name='raise') result(r)
         import :: c_int
         integer(c_int), value :: sig
         integer(c_int) :: r
      end function c_raise
   end interface

contains

   !> The handler: record, nothing else (async-signal-safe).
   subroutine on_signal(sig) bind(C)
      integer(c_int), value :: sig
      if (sig == SIGUSR1_NUM) then
         dump_sig = sig
      else
         if (stop_sig /= 0) call c_exit_now(128_c_int + sig)   ! second request: stop now
         stop_sig = sig
      end if
   end subroutine on_signal

   !> Install the handler for SIGTERM, SIGINT and SIGUSR1; ignore SIGXFSZ.
   subroutine signals_install()
      type(c_funptr) :: old
      old = c_signal(SIGTERM_NUM, c_funloc(on_signal))
      old = c_signal(SIGINT_NUM, c_funloc(on_signal))
      old = c_signal(SIGUSR1_NUM, c_funloc(on_signal))
      old = c_signal(SIGXFSZ_NUM, transfer(1_c_intptr_t, old))   ! SIG_IGN
   end subroutine signals_install

   !> The signal number of a pending stop request (0: none).
   integer function signal_stop_requested()
      signal_stop_requested = int(stop_sig)
   end function signal_stop_requested

   !> Whether a 'dump and go on' request is pending; clears it.
   logical function signal_dump_requested()
      signal_dump_requested = dump_sig /= 0
      if (signal_dump_requested) dump_sig = 0
   end function signal_dump_requested

   !> Whether a 'dump and go on' request is pending, without clearing it.
   logical function signal_dump_pending()
      signal_dump_pending = dump_sig /= 0
   end function signal_dump_pending

   !> Send sig to this process (tests).
   subroutine signal_raise(sig)
      integer, intent(in) :: sig
      integer(c_int) :: r
      r = c_raise(int(sig, c_int))
   end subroutine signal_raise

   function signal_name(sig) result(s)
      integer, intent(in) :: sig
      character(:), allocatable :: s
      select case (sig)
      case (SIGINT_NUM); s = 'SIGINT'
      case (SIGTERM_NUM); s = 'SIGTERM'
      case (SIGUSR1_NUM); s = 'SIGUSR1'
      case default; s = 'signal'
      end select
   end function signal_name
end module dx_signals
