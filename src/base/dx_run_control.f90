!> Run-time switches through a control file in the output folder, OUT/dynx.ctl: the words
!>   status   a status line now (LS-DYNA's sense switch sw2),
!>   plot     a plot state now (sw4),
!>   dump     a restart dump now, and go on (sw3; the same as SIGUSR1),
!>   stop     a restart dump, the last plot state, exit 5 (sw1; the same as SIGTERM),
!> any number of them, separated by blanks, commas or new lines, case-insensitive; '#' or
!> '$' starts a comment. The idea is OpenRadioss's Engine control file (RUNNAME_0001.ctl,
!> read while the run goes, with /STOP, /ANIM, /H3D, /RFILE, ...) and LS-DYNA's sense
!> switches (keyword manual vol. I, "Sense switch controls": sw1 ... sw4 typed after a
!> ctrl-C). The file is read once and removed (a request is served once); one it cannot
!> remove is renamed dynx.ctl.done, and when it can do neither the switches are turned off
!> for the rest of the run with a warning (a request never repeats every poll).
!> An unknown word is reported (a warning naming the file, its line and the word, with the
!> words known) and ignored: the run goes on; a run-time request cannot end it with exit 2.
!> The caller polls it cheaply (dx_checkpoint: at the first cycle, then once per wall-clock
!> second, by rank 0 alone: the request rides in the cycle's dt reduction, so every rank acts
!> on the same cycle).
module dx_run_control
   use dx_strings, only: str, lower
   use dx_log, only: log_warn
   use dx_error, only: error_t
   use dx_io_sys, only: sys_rename
   implicit none
   private
   public :: ctl_read, CTL_STATUS, CTL_PLOT, CTL_DUMP, CTL_STOP, ctl_has, ctl_words

   !> The requests, as bits of one integer (MPI: rank 0's value rides in a MAX reduction)
   integer, parameter :: CTL_STATUS = 1, CTL_PLOT = 2, CTL_DUMP = 4, CTL_STOP = 8
   character(*), parameter :: WORDS(4) = [character(6) :: 'status', 'plot', 'dump', 'stop']

contains

   !> Whether request bit b is set in req.
   logical function ctl_has(req, b)
      integer, intent(in) :: req, b
      ctl_has = iand(req, b) /= 0
   end function ctl_has

   !> The words of req, for the log ('status plot').
   function ctl_words(req) result(s)
      integer, intent(in) :: req
      character(:), allocatable :: s
      integer :: k
      s = ''
      do k = 1, size(WORDS)
         if (ctl_has(req, 2**(k - 1))) s = s//' '//trim(WORDS(k))
      end do
      if (len(s) > 0) s = s(2:)
   end function ctl_words

   !> The requests of the file at path (0: none or no file), which is then removed. off:
   !> set when it could be neither removed nor renamed (the caller stops polling).
   integer function ctl_read(path, off) result(req)
      character(*), intent(in) :: path
      logical, intent(out) :: off
      logical :: there
      integer :: u, ios, lineno, cut, k, b, sz
      character(512) :: line
      character(:), allocatable :: w
      type(error_t), allocatable :: e
      req = 0
      off = .false.
      inquire(file=path, exist=there)
      if (.not. there) return
      open(newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return                     ! being written: the next poll reads it
      lineno = 0
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         cut = scan(line, '#$')
         if (cut > 0) line(cut:) = ' '
         do k = 1, len_trim(line)
            if (line(k:k) == ',' .or. line(k:k) == achar(9)) line(k:k) = ' '
         end do
         do
            line = adjustl(line)
            if (len_trim(line) == 0) exit
            sz = index(line, ' ') - 1
            if (sz < 0) sz = len_trim(line)     ! a word that fills the whole line
            w = trim(lower(line(1:sz)))
            line(1:sz) = ' '
            b = 0
            do k = 1, size(WORDS)
               if (w == trim(WORDS(k))) b = 2**(k - 1)
            end do
            if (b == 0) then
               call log_warn(path//':'//str(lineno)//': unknown run-time switch "'// &
                  w//'" ignored (known: status, plot, dump, stop)')
            else
               req = ior(req, b)
            end if
         end do
      end do
      close(u, status='delete', iostat=ios)
      inquire(file=path, exist=there)
      if (there) call sys_rename(path, path//'.done', e)
      inquire(file=path, exist=there)
      if (there) then
         off = .true.
         call log_warn(path//': cannot remove or rename it: run-time switches off for the '// &
                       'rest of the run (each request would repeat at every poll)')
      end if
   end function ctl_read

end module dx_run_control
