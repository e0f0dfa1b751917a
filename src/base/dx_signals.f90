!> Batch-job signals, through bind(C) to signal(2) (POSIX; Linux numbers):
!>   SIGTERM, SIGINT: finish the current cycle, write a restart dump and the last plot
!>                    state, close every file, exit with EXIT_CHECKPOINT (5);
!>                    a second SIGTERM/SIGINT before that ends the process at once (_exit);
!>   SIGUSR2:         the same stop as SIGTERM (dump, exit 5). Open MPI's mpirun forwards
!>                    SIGUSR1 and SIGUSR2 to every rank but answers SIGTERM/SIGINT by
!>                    killing the job (SIGTERM, then SIGKILL after odls_base_sigkill_timeout
!>                    = 1 s, and exit 1), so SIGUSR2 is the stop that works the same serial
!>                    and under mpirun (docs/errors.md, "Signals");
!>   SIGUSR1:         write a restart dump at the end of the current cycle and go on
!>                    (LS-DYNA's sense switch "sw3": write a restart file and continue).
!>                    The handler counts SIGUSR1s; a dump is owed while the count exceeds
!>                    the count served. MPI runs reduce the counts with MAX, so one signal
!>                    that mpirun forwards to every rank (reaching them in different cycles)
!>                    is one dump, not one per rank.
!>   SIGXFSZ:         ignored, so a file-size limit (ulimit -f) makes write(2) fail with
!>                    EFBIG: an I/O error naming the file (exit 4), not a kill by signal.
!>   SIGSEGV:         an exhausted address space (ulimit -v) is exit 4 with a message
!>                    (dx_memory_fault); any other fault goes to the previous handler.
!> The handler only stores the signal number in a C int (the sig_atomic_t idiom); the
!> solver polls it once per cycle. This is the only module-level mutable state of dynx
!> besides the log settings.
module dx_signals
   use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_intptr_t
   use dx_memory_fault, only: memory_fault_install
   use dx_libc, only: c_signal, c_exit_now, c_raise
   implicit none
   private
   public :: signals_install, signal_stop_requested, signal_dump_requested, signal_name, &
             signal_dump_pending, signal_dump_count, signal_dump_served, signal_dump_serve, &
             SIGINT_NUM, SIGTERM_NUM, SIGUSR1_NUM, SIGUSR2_NUM, signal_raise

   integer(c_int), parameter :: SIGINT_NUM = 2, SIGUSR1_NUM = 10, SIGUSR2_NUM = 12, &
                                SIGTERM_NUM = 15
   integer(c_int), parameter :: SIGXFSZ_NUM = 25

   integer(c_int), volatile, save :: stop_sig = 0    !< SIGTERM/SIGINT/SIGUSR2 received (number)
   integer(c_int), volatile, save :: dump_cnt = 0    !< SIGUSR1s received (written by the handler)
   integer, save :: dump_done = 0                    !< SIGUSR1 count already served by a dump

contains

   !> The handler: record, nothing else (async-signal-safe).
   subroutine on_signal(sig) bind(C)
      integer(c_int), value :: sig
      if (sig == SIGUSR1_NUM) then
         dump_cnt = dump_cnt + 1_c_int
      else
         if (stop_sig /= 0) call c_exit_now(128_c_int + sig)   ! second request: stop now
         stop_sig = sig
      end if
   end subroutine on_signal

   !> Install the handler for SIGTERM, SIGINT, SIGUSR1 and SIGUSR2; ignore SIGXFSZ. The
   !> main program's first statement (a stop during start-up is a request, not a kill).
   subroutine signals_install()
      type(c_funptr) :: old
      old = c_signal(SIGTERM_NUM, c_funloc(on_signal))
      old = c_signal(SIGINT_NUM, c_funloc(on_signal))
      old = c_signal(SIGUSR1_NUM, c_funloc(on_signal))
      old = c_signal(SIGUSR2_NUM, c_funloc(on_signal))
      old = c_signal(SIGXFSZ_NUM, transfer(1_c_intptr_t, old))   ! SIG_IGN
      call memory_fault_install()      ! out of memory: exit 4 with a message, not SIGSEGV
   end subroutine signals_install

   !> The signal number of a pending stop request (0: none).
   integer function signal_stop_requested()
      signal_stop_requested = int(stop_sig)
   end function signal_stop_requested

   !> Serial runs: whether a 'dump and go on' request is pending; marks it served.
   logical function signal_dump_requested()
      integer :: n
      n = int(dump_cnt)
      signal_dump_requested = n > dump_done
      if (signal_dump_requested) dump_done = n
   end function signal_dump_requested

   !> Whether a 'dump and go on' request of this process is pending, without serving it.
   logical function signal_dump_pending()
      signal_dump_pending = int(dump_cnt) > dump_done
   end function signal_dump_pending

   !> The number of SIGUSR1s this process received (MPI: reduced with MAX over the ranks).
   integer function signal_dump_count()
      signal_dump_count = int(dump_cnt)
   end function signal_dump_count

   !> The SIGUSR1 count already served by a dump.
   integer function signal_dump_served()
      signal_dump_served = dump_done
   end function signal_dump_served

   !> A dump served every request up to count n (MPI: the reduced count, on every rank).
   subroutine signal_dump_serve(n)
      integer, intent(in) :: n
      dump_done = max(dump_done, n)
   end subroutine signal_dump_serve

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
      case (SIGUSR2_NUM); s = 'SIGUSR2'
      case default; s = 'signal'
      end select
   end function signal_name
end module dx_signals
