!> The output-folder lock: one writer per output folder. A second dynx (or dynx-combine)
!> started on the folder of a running job truncated the job's d3plot.h5.tmp; now it stops
!> with exit 2 naming the holder. The lock is an exclusive flock(2) on OUTDIR/.dynx.lock,
!> which holds "<program> pid <pid> on host <host>" for the message. The kernel releases the
!> lock when the holding process ends in any way (exit, crash, kill -9), so a lock left by a
!> dead run is never stale: the file stays, the lock does not. (flock is advisory and local
!> to one host's kernel on most network file systems: two hosts writing one NFS folder are
!> not detected.) Under MPI only rank 0 takes it.
module dx_out_lock
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_io_sys, only: sys_mkdir_p, sys_flock_try, sys_read_small, sys_getpid, &
                        sys_hostname, sys_ftruncate_fd, sys_write_all
   implicit none
   private
   public :: out_lock, LOCK_NAME

   character(*), parameter :: LOCK_NAME = '.dynx.lock'

contains

   !> Take the lock of folder outdir for program (created if missing); fd stays open until
   !> the process ends (that holds the lock). A busy folder is an input error (exit 2).
   subroutine out_lock(outdir, program, fd, error)
      character(*), intent(in) :: outdir, program
      integer, intent(out) :: fd
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: path, holder
      logical :: locked
      fd = -1
      call sys_mkdir_p(outdir, error)
      if (allocated(error)) return
      path = outdir//'/'//LOCK_NAME
      call sys_flock_try(path, fd, locked, error)
      if (allocated(error)) return
      if (.not. locked) then
         holder = trim(sys_read_small(path))
         if (len(holder) > 0) then
            if (holder(len(holder):) == new_line('a')) holder = holder(1:len(holder) - 1)
         end if
         if (len(holder) == 0) holder = 'another process'
         call set_error(error, 'output folder '//outdir//' is in use by '//holder// &
            ' (lock '//path//'); wait for it to end or choose another output folder', &
            EXIT_INPUT)
         return
      end if
      call sys_ftruncate_fd(fd, 0_8, path, error)
      if (.not. allocated(error)) call sys_write_all(fd, program//' pid '//str(sys_getpid())// &
                                                     ' on host '//sys_hostname()//new_line('a'), &
                                                     path, error)
   end subroutine out_lock
end module dx_out_lock
