!> Logging: info lines, warnings (collected and summarized at the end), status verbosity.
!> The only mutable module state besides parallel/: the log settings and the warning list.
module dx_log
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   implicit none
   private
   public :: log_info, log_warn, log_error, log_summary, log_set_quiet, log_set_unit, &
             nwarnings, log_flush, log_open_messages

   logical :: quiet = .false.
   integer :: extra_unit = -1              !< optional log file (dynx.log in the output dir)
   integer :: msg_unit = 0                 !< the messages file (warnings and errors only) ...
   logical :: msg_on = .false.             !< ... when open (newunit numbers are negative)
   integer :: nwarn = 0
   integer, parameter :: max_kept = 50
   character(len=400) :: kept(max_kept)

contains
   subroutine log_set_quiet(q)
      logical, intent(in) :: q
      quiet = q
   end subroutine log_set_quiet

   !> Also write every message to this open unit (negative: none).
   subroutine log_set_unit(u)
      integer, intent(in) :: u
      extra_unit = u
   end subroutine log_set_unit

   !> An informational line on stdout (and the log file).
   subroutine log_info(msg)
      character(*), intent(in) :: msg
      if (.not. quiet) write(output_unit, '(a)') msg
      if (extra_unit > 0) write(extra_unit, '(a)') msg
   end subroutine log_info

   !> A warning: printed at once, kept for the end-of-run summary.
   subroutine log_warn(msg)
      character(*), intent(in) :: msg
      nwarn = nwarn + 1
      if (nwarn <= max_kept) kept(nwarn) = msg
      if (.not. quiet) write(error_unit, '(a)') 'dynx: warning: '//msg   ! MPI: rank 0 only
      if (extra_unit > 0) write(extra_unit, '(a)') 'dynx: warning: '//msg
      call to_messages('warning: '//msg)
   end subroutine log_warn

   !> An error message on stderr (and the log file).
   subroutine log_error(msg)
      character(*), intent(in) :: msg
      write(error_unit, '(a)') 'dynx: error: '//msg
      if (extra_unit > 0) write(extra_unit, '(a)') 'dynx: error: '//msg
      call to_messages('error: '//msg)
   end subroutine log_error

   !> Every warning and error from now on also goes to the file path (LS-DYNA's messages
   !> file), flushed line by line; the warnings kept so far (the deck's) are written first.
   !> ok: the file could be opened.
   !> append: a restart goes on with the file of the run it continues.
   subroutine log_open_messages(path, append, ok)
      character(*), intent(in) :: path
      logical, intent(in) :: append
      logical, intent(out) :: ok
      integer :: ios, i
      if (append) then
         open(newunit=msg_unit, file=path, position='append', action='write', iostat=ios)
      else
         open(newunit=msg_unit, file=path, status='replace', action='write', iostat=ios)
      end if
      ok = ios == 0
      msg_on = ok
      if (.not. ok) return
      do i = 1, min(nwarn, max_kept)
         call to_messages('warning: '//trim(kept(i)))
      end do
      if (nwarn > max_kept .and. msg_on) write(msg_unit, '(a,i0,a)', iostat=ios) 'note: ', &
         nwarn - max_kept, ' earlier warning(s) not kept (the log has them)'
      if (msg_on) flush(msg_unit, iostat=ios)
   end subroutine log_open_messages

   !> One line into the messages file, flushed; a write that fails (a full disk) closes the
   !> file and ends the copy there: the log and stderr still have every message.
   subroutine to_messages(line)
      character(*), intent(in) :: line
      integer :: ios
      if (.not. msg_on) return
      write(msg_unit, '(a)', iostat=ios) line
      if (ios == 0) flush(msg_unit, iostat=ios)
      if (ios /= 0) then
         close(msg_unit, iostat=ios)
         msg_on = .false.
      end if
   end subroutine to_messages

   integer function nwarnings()
      nwarnings = nwarn
   end function nwarnings

   !> Print the collected warnings once more at the end of a run.
   subroutine log_summary()
      integer :: i
      character(12) :: buf
      if (nwarn == 0) return
      write(buf, '(i0)') nwarn
      call log_info('dynx: '//trim(buf)//' warning(s):')
      do i = 1, min(nwarn, max_kept)
         call log_info('  - '//trim(kept(i)))
      end do
   end subroutine log_summary

   subroutine log_flush()
      flush(output_unit)
      if (extra_unit > 0) flush(extra_unit)
   end subroutine log_flush
end module dx_log
