!> dynx-thist: columns of any dynx time-history file (glstat, nodout, rcforc, rbdout, matsum,
!> sleout, spcforc, ...) by name, resampled to a uniform step, filtered (SAE J211 / ISO 6487
!> CFC, FFT low pass), as power spectra or a transfer function; CSV out, a gnuplot PNG with
!> --png. Manual: docs/toolbox.md. Reader: dx_thist_read; filter and resampling: dx_sae;
!> spectra: dx_fft (FFTW).
!>   dynx-thist FILE --col NAME[@ID] [--col ...] [--dt DT] [--time-unit s|ms|us|ns]
!>              [--cfc CFC [--iso]] [--lowpass FC] [--psd [--nseg N] [--rect]]
!>              [--h1 IN OUT] [--raw] [-o out.csv] [--png out.png] [--list]
!> Every column is resampled (linear interpolation) onto a uniform step over the time window
!> the columns share, except with --raw (the file's own output times, no filter).
!> Exit status: 0 done, 2 bad arguments or input (message naming the file and line),
!> 4 a file cannot be read or written.
program dynx_thist
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_io_sys, only: sys_exit
   use dx_strings, only: command_arg, str, rstr
   use dx_thist_read, only: thist_table_t, thist_read, parse_column
   use dx_sae, only: cfc_filter, interp_linear, SAE_J211, ISO_6487
   use dx_fft, only: psd_welch, transfer_h1, fft_lowpass
   implicit none
   type(thist_table_t) :: tab
   type(error_t), allocatable :: error
   character(:), allocatable :: arg, path, csv, png, cols(:), unit_name
   character(64) :: colbuf(64)
   integer :: i, n, ncol, nseg, std, ios
   real(wp) :: dt, cfc, fc, tscale
   logical :: list, psd, hann, h1, raw

   n = command_argument_count()
   ncol = 0
   dt = 0.0_wp
   cfc = 0.0_wp
   fc = 0.0_wp
   tscale = 1.0_wp
   unit_name = 's'
   nseg = 8
   std = SAE_J211
   list = .false.
   psd = .false.
   hann = .true.
   h1 = .false.
   raw = .false.
   i = 0
   do while (i < n)
      i = i + 1
      arg = command_arg(i)
      select case (arg)
      case ('--col')
         call add_col(next('--col needs NAME or NAME@ID'))
      case ('--h1')
         h1 = .true.
         call add_col(next('--h1 needs the input and output columns'))
         call add_col(next('--h1 needs the input and output columns'))
      case ('--dt')
         dt = real_arg(next('--dt needs a step'), '--dt')
      case ('--cfc')
         cfc = real_arg(next('--cfc needs a class (60, 180, 600, 1000)'), '--cfc')
      case ('--iso')
         std = ISO_6487
      case ('--lowpass')
         fc = real_arg(next('--lowpass needs a frequency in Hz'), '--lowpass')
      case ('--psd')
         psd = .true.
      case ('--nseg')
         nseg = nint(real_arg(next('--nseg needs a count'), '--nseg'))
         if (nseg < 1) call usage('--nseg must be >= 1')
      case ('--rect')
         hann = .false.
      case ('--time-unit')
         unit_name = next('--time-unit needs s, ms, us or ns')
         select case (unit_name)
         case ('s', 'sec')
            tscale = 1.0_wp
         case ('ms', 'msec')
            tscale = 1.0e-3_wp
         case ('us', 'usec')
            tscale = 1.0e-6_wp
         case ('ns', 'nsec')
            tscale = 1.0e-9_wp
         case default
            call usage('--time-unit: "'//unit_name//'" is not s, ms, us or ns')
         end select
      case ('-o')
         csv = next('-o needs a file')
      case ('--png')
         png = next('--png needs a file')
      case ('--raw')
         raw = .true.
      case ('--list')
         list = .true.
      case ('-h', '--help')
         call usage('')
      case default
         if (arg(1:min(1, len(arg))) == '-' .and. len(arg) > 1) call usage('unknown option '//arg)
         if (allocated(path)) call usage('one time-history file only ('//path//', '//arg//')')
         path = arg
      end select
   end do
   if (.not. allocated(path)) call usage('no time-history file')
   call thist_read(path, tab, error)
   call stop_on(error)
   if (list) then
      call print_list()
      call sys_exit(0)
   end if
   if (ncol == 0) call usage('no --col')
   if (cfc > 0.0_wp .and. fc > 0.0_wp) call usage('--cfc and --lowpass: one filter at a time')
   if (h1 .and. (ncol /= 2 .or. psd)) call usage('--h1 takes exactly its two columns, no --psd')
   if (raw .and. (h1 .or. psd .or. cfc > 0.0_wp .or. fc > 0.0_wp .or. dt > 0.0_wp)) &
      call usage('--raw keeps the file''s own times: no --dt, filter, --psd or --h1 with it')
   if (allocated(png) .and. .not. allocated(csv)) csv = png//'.csv'
   call run()
   call sys_exit(0)

contains

   subroutine run()
      real(wp), allocatable :: t(:), x(:), tu(:), xu(:, :), y(:), f(:), p(:), coh(:)
      complex(wp), allocatable :: h(:)
      real(wp), allocatable :: out(:, :)
      character(:), allocatable :: head, name
      real(wp) :: t0, t1
      integer :: k, m, id, j
      if (raw) then
         call run_raw()
         return
      end if
      ! the common time window and the step (default: the mean spacing of the first column)
      do k = 1, ncol
         call split_col(cols(k), name, id)
         call tab%select(name, id, t, x, error)
         call stop_on(error)
         if (size(t) < 3) then
            write(error_unit, '(a)') 'dynx-thist: error: '//path//': column '//trim(cols(k))// &
               ' has '//str(size(t))//' samples; at least 3 are needed'
            call sys_exit(2)
         end if
         if (k == 1) then
            t0 = t(1)
            t1 = t(size(t))
            if (dt <= 0.0_wp) dt = (t(size(t)) - t(1))/real(size(t) - 1, wp)
         else
            t0 = max(t0, t(1))
            t1 = min(t1, t(size(t)))
         end if
      end do
      if ((t1 - t0)/dt > 1.0e7_wp) call usage('--dt '//rstr(dt)//' makes more than 1e7 '// &
         'samples of the window '//rstr(t0)//' to '//rstr(t1)//' (80 MB a column): a larger --dt')
      m = floor((t1 - t0)/dt*(1.0_wp + 1.0e-12_wp)) + 1
      if (m < 3) call usage('the columns share fewer than 3 samples at --dt '//rstr(dt))
      allocate(xu(m, ncol), tu(m))
      do j = 1, m
         tu(j) = t0 + real(j - 1, wp)*dt
      end do
      tu(m) = min(tu(m), t1)
      do k = 1, ncol
         call split_col(cols(k), name, id)
         call tab%select(name, id, t, x, error)
         call stop_on(error)
         call interp_linear(t, x, tu, y, error)
         call stop_on(error)
         xu(:, k) = y
      end do
      if (h1) then
         call transfer_h1(xu(:, 1), xu(:, 2), dt*tscale, nseg, hann, f, h, coh, error)
         call stop_on(error)
         allocate(out(size(f), 6))
         out(:, 1) = f
         out(:, 2) = abs(h)
         out(:, 3) = atan2(aimag(h), real(h))*180.0_wp/3.14159265358979323846_wp
         out(:, 4) = real(h)
         out(:, 5) = aimag(h)
         out(:, 6) = coh
         head = 'frequency_hz,h1_magnitude,h1_phase_deg,h1_real,h1_imag,coherence'
         call write_csv(head, out)
         if (allocated(png)) call plot_png(.true., 'frequency (Hz)', 2)
         return
      end if
      if (psd) then
         head = 'frequency_hz'
         do k = 1, ncol
            if (cfc > 0.0_wp) then
               call cfc_filter(xu(:, k), dt*tscale, cfc, y, error, std)
               call stop_on(error)
               xu(:, k) = y
            else if (fc > 0.0_wp) then
               call fft_lowpass(xu(:, k), dt*tscale, fc, y, error)
               call stop_on(error)
               xu(:, k) = y
            end if
            call psd_welch(xu(:, k), dt*tscale, nseg, hann, f, p, error)
            call stop_on(error)
            if (k == 1) then
               allocate(out(size(f), ncol + 1))
               out(:, 1) = f
            end if
            out(:, k + 1) = p
            head = head//',psd_'//col_label(cols(k))//suffix()
         end do
         call write_csv(head, out)
         if (allocated(png)) call plot_png(.true., 'frequency (Hz)', ncol + 1)
         return
      end if
      head = 'time'
      j = 1
      if (cfc > 0.0_wp .or. fc > 0.0_wp) j = 2
      allocate(out(m, 1 + j*ncol))
      out(:, 1) = tu
      do k = 1, ncol
         out(:, 1 + j*(k - 1) + 1) = xu(:, k)
         head = head//','//col_label(cols(k))
         if (j == 2) then
            if (cfc > 0.0_wp) then
               call cfc_filter(xu(:, k), dt*tscale, cfc, y, error, std)
            else
               call fft_lowpass(xu(:, k), dt*tscale, fc, y, error)
            end if
            call stop_on(error)
            out(:, 1 + j*(k - 1) + 2) = y
            head = head//','//col_label(cols(k))//suffix()
         end if
      end do
      call write_csv(head, out)
      if (allocated(png)) call plot_png(.false., 'time ('//unit_name//')', 1 + j*ncol)
   end subroutine run

   !> --raw: the columns at the file's own output times (they must share them).
   subroutine run_raw()
      real(wp), allocatable :: t(:), x(:), t1(:), out(:, :)
      character(:), allocatable :: head, name
      integer :: k, id
      head = 'time'
      do k = 1, ncol
         call split_col(cols(k), name, id)
         call tab%select(name, id, t, x, error)
         call stop_on(error)
         if (k == 1) then
            t1 = t
            allocate(out(size(t), ncol + 1))
            out(:, 1) = t
         else if (size(t) /= size(t1)) then
            call usage('--raw: '//trim(cols(k))//' has other output times than '//trim(cols(1)))
         else if (any(t /= t1)) then
            call usage('--raw: '//trim(cols(k))//' has other output times than '//trim(cols(1)))
         end if
         out(:, k + 1) = x
         head = head//','//col_label(cols(k))
      end do
      call write_csv(head, out)
      if (allocated(png)) call plot_png(.false., 'time ('//unit_name//')', ncol + 1)
   end subroutine run_raw

   !> '_cfc60' (SAE), '_iso60' (ISO) or '_lp500' for the filter in force, else ''.
   function suffix() result(s)
      character(:), allocatable :: s
      s = ''
      if (cfc > 0.0_wp .and. std == ISO_6487) s = '_iso'//num(cfc)
      if (cfc > 0.0_wp .and. std == SAE_J211) s = '_cfc'//num(cfc)
      if (fc > 0.0_wp) s = '_lp'//num(fc)
   end function suffix

   function num(x) result(s)
      real(wp), intent(in) :: x
      character(:), allocatable :: s
      if (x == anint(x) .and. abs(x) < 1.0e9_wp) then
         s = str(nint(x))
      else
         s = rstr(x, 4)
      end if
   end function num

   !> NAME@ID as name_ID, NAME as name.
   function col_label(c) result(s)
      character(*), intent(in) :: c
      character(:), allocatable :: s
      integer :: p
      p = index(c, '@')
      if (p > 0) then
         s = c(1:p - 1)//'_'//trim(c(p + 1:))
      else
         s = trim(c)
      end if
   end function col_label

   subroutine write_csv(head, out)
      character(*), intent(in) :: head
      real(wp), intent(in) :: out(:, :)
      integer :: u, k
      character(32) :: fmt
      if (allocated(csv)) then
         open(newunit=u, file=csv, status='replace', action='write', iostat=ios)
         if (ios /= 0) then
            write(error_unit, '(a)') 'dynx-thist: error: cannot write '//csv
            call sys_exit(4)
         end if
      else
         u = output_unit
      end if
      write(u, '(a)') head
      write(fmt, '(a,i0,a)') '(es18.10e3,', size(out, 2) - 1, '(",",es18.10e3))'
      do k = 1, size(out, 1)
         write(u, fmt) out(k, :)
      end do
      if (u /= output_unit) close(u)
   end subroutine write_csv

   !> A gnuplot PNG of every column of the CSV against the first.
   subroutine plot_png(logy, xlabel, nc)
      logical, intent(in) :: logy
      character(*), intent(in) :: xlabel
      integer, intent(in) :: nc
      integer :: u, st
      character(:), allocatable :: gp
      gp = png//'.gp'
      open(newunit=u, file=gp, status='replace', action='write')
      write(u, '(a)') 'set terminal pngcairo size 1000,600 noenhanced'
      write(u, '(a)') 'set output "'//png//'"'
      write(u, '(a)') 'set datafile separator ","'
      write(u, '(a)') 'set key autotitle columnhead'
      write(u, '(a)') 'set title "'//path//'"'
      write(u, '(a)') 'set xlabel "'//xlabel//'"'
      write(u, '(a)') 'set grid'
      if (logy) write(u, '(a)') 'set logscale y'
      write(u, '(a)') 'plot for [i=2:'//str(nc)//'] "'//csv//'" using 1:i with lines lw 2'
      close(u)
      call execute_command_line('gnuplot "'//gp//'"', exitstat=st)
      if (st /= 0) then
         write(error_unit, '(a)') 'dynx-thist: error: gnuplot failed on '//gp// &
            ' (is gnuplot installed? apt-get install gnuplot-nox)'
         call sys_exit(4)
      end if
      open(newunit=u, file=gp, status='old')
      close(u, status='delete')
   end subroutine plot_png

   subroutine print_list()
      integer :: k, m
      integer, allocatable :: ids(:)
      write(output_unit, '(a)') path//': '//str(tab%nnames)//' columns'
      do k = 1, tab%nnames
         ids = tab%entities(k)
         m = min(size(ids), 12)
         if (size(ids) == 1 .and. ids(1) == 0) then
            write(output_unit, '(2x,a)') trim(tab%names(k))
         else
            write(output_unit, '(2x,a,a,i0,a,*(1x,i0))', advance='no') trim(tab%names(k)), &
               ' (', size(ids), ' ids:', ids(1:m)
            if (m < size(ids)) write(output_unit, '(a)', advance='no') ' ...'
            write(output_unit, '(a)') ')'
         end if
      end do
   end subroutine print_list

   subroutine split_col(c, name, id)
      character(*), intent(in) :: c
      character(:), allocatable, intent(out) :: name
      integer, intent(out) :: id
      call parse_column(c, name, id, error)
      call stop_on(error)
   end subroutine split_col

   subroutine add_col(c)
      character(*), intent(in) :: c
      ncol = ncol + 1
      if (ncol > size(colbuf)) call usage('at most 64 columns')
      colbuf(ncol) = c
      cols = colbuf(1:ncol)
   end subroutine add_col

   function next(msg) result(v)
      character(*), intent(in) :: msg
      character(:), allocatable :: v
      if (i >= n) call usage(msg)
      i = i + 1
      v = command_arg(i)
   end function next

   real(wp) function real_arg(s, opt) result(x)
      character(*), intent(in) :: s, opt
      integer :: st
      read(s, *, iostat=st) x
      if (st /= 0) call usage(opt//' '//s//': not a number')
      if (.not. (x > 0.0_wp)) call usage(opt//' '//s//': must be > 0')
   end function real_arg

   subroutine stop_on(e)
      type(error_t), allocatable, intent(in) :: e
      if (.not. allocated(e)) return
      write(error_unit, '(a)') 'dynx-thist: error: '//e%message
      call sys_exit(e%code)
   end subroutine stop_on

   subroutine usage(msg)
      character(*), intent(in) :: msg
      if (len(msg) > 0) write(error_unit, '(a)') 'dynx-thist: error: '//msg
      write(error_unit, '(a)') 'usage: dynx-thist FILE --col NAME[@ID] [--col ...] '// &
         '[--dt DT] [--time-unit s|ms|us|ns] [--cfc CFC [--iso]] [--lowpass FC_HZ] '// &
         '[--psd [--nseg N] [--rect]] [--h1 IN OUT] [--raw] [-o out.csv] [--png out.png] [--list]'
      if (len(msg) == 0) call sys_exit(0)
      call sys_exit(2)
   end subroutine usage
end program dynx_thist
