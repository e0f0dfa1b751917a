!> dynx-plot: a gnuplot PNG of any columns of any dynx time-history files (glstat, nodout,
!> rcforc, rbdout, matsum, sleout, spcforc, ...) by name, several runs on one plot.
!>   dynx-plot -o out.png --y NAME[@ID] [--y ...] [--x NAME[@ID]] [--title T]
!>             [--deck deck.k] [--units LENGTH,TIME,MASS] [--logy] FILE [FILE ...]
!> Every --y column of every FILE is one curve (legend: the file's folder and the column);
!> the x axis is the time, or the column --x of the same file (same output times). Axis
!> labels: the column names with their unit, the units from --units or from the deck's
!> *CONTROL_UNITS card (LS-DYNA: LENGTH TIME MASS; without either, "consistent units").
!> The curves go to FILE.d/ next to the PNG (two columns, es18.10, readable by gnuplot) with
!> the gnuplot script plot.gp, so a plot can be restyled by hand. Reader: dx_thist_read.
!> Exit status: 0 done, 2 bad arguments or input, 4 a file cannot be read or written or
!> gnuplot failed. Manual: docs/toolbox.md.
program dynx_plot
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_io_sys, only: sys_exit
   use dx_strings, only: command_arg, str, lower
   use dx_thist_read, only: thist_table_t, thist_read, parse_column
   implicit none
   character(256) :: files(32), ycols(32)
   character(:), allocatable :: arg, png, xcol, title, deck, units, ulen, utime, umass, dir
   integer :: i, n, nf, ny, st
   logical :: logy

   n = command_argument_count()
   nf = 0
   ny = 0
   logy = .false.
   title = ''
   i = 0
   do while (i < n)
      i = i + 1
      arg = command_arg(i)
      select case (arg)
      case ('-o')
         png = next('-o needs a PNG file')
      case ('--y')
         ny = ny + 1
         if (ny > size(ycols)) call usage('at most 32 --y columns')
         ycols(ny) = next('--y needs NAME or NAME@ID')
      case ('--x')
         xcol = next('--x needs NAME or NAME@ID')
      case ('--title')
         title = next('--title needs a text')
      case ('--deck')
         deck = next('--deck needs a deck file')
      case ('--units')
         units = next('--units needs LENGTH,TIME,MASS (e.g. mm,ms,kg)')
      case ('--logy')
         logy = .true.
      case ('-h', '--help')
         call usage('')
      case default
         if (arg(1:1) == '-' .and. len(arg) > 1) call usage('unknown option '//arg)
         nf = nf + 1
         if (nf > size(files)) call usage('at most 32 files')
         files(nf) = arg
      end select
   end do
   if (nf == 0) call usage('no time-history file')
   if (ny == 0) call usage('no --y column')
   if (.not. allocated(png)) call usage('no -o out.png')
   ulen = ''
   utime = ''
   umass = ''
   if (allocated(units)) then
      call split3(units, ulen, utime, umass, st)
      if (st /= 0) call usage('--units '//units//': expected LENGTH,TIME,MASS')
   else if (allocated(deck)) then
      call deck_units(deck)
   end if
   dir = png//'.d'
   call execute_command_line('mkdir -p "'//dir//'"', exitstat=st)
   if (st /= 0) call fail('cannot create '//dir, 4)
   call plot()
   call sys_exit(0)

contains

   subroutine plot()
      type(thist_table_t) :: tab
      type(error_t), allocatable :: error
      real(wp), allocatable :: t(:), y(:), tx(:), x(:)
      character(:), allocatable :: name, dat, gp, curves, ylabel, leg
      integer :: f, k, id, u, j, xid
      character(:), allocatable :: xname
      curves = ''
      ylabel = ''
      do f = 1, nf
         call thist_read(trim(files(f)), tab, error)
         if (allocated(error)) call fail(error%message, error%code)
         if (allocated(xcol)) then
            call split_col(xcol, xname, xid)
            call tab%select(xname, xid, tx, x, error)
            if (allocated(error)) call fail(error%message, error%code)
         end if
         do k = 1, ny
            call split_col(trim(ycols(k)), name, id)
            call tab%select(name, id, t, y, error)
            if (allocated(error)) call fail(error%message, error%code)
            if (allocated(xcol)) then
               if (size(tx) /= size(t)) call fail(trim(files(f))//': --x '//xcol// &
                  ' and --y '//trim(ycols(k))//' have different output times', 2)
               if (any(tx /= t)) call fail(trim(files(f))//': --x '//xcol// &
                  ' and --y '//trim(ycols(k))//' have different output times', 2)
               t = x
            end if
            dat = dir//'/'//str(f)//'_'//safe(trim(ycols(k)))//'.dat'
            open(newunit=u, file=dat, status='replace', action='write', iostat=st)
            if (st /= 0) call fail('cannot write '//dat, 4)
            write(u, '(a)') '# '//trim(files(f))//' '//trim(ycols(k))
            do j = 1, size(t)
               write(u, '(es18.10e3,1x,es18.10e3)') t(j), y(j)
            end do
            close(u)
            leg = trim(ycols(k))
            if (nf > 1) leg = run_name(trim(files(f)))//': '//leg
            if (len(curves) > 0) curves = curves//', '
            curves = curves//'"'//dat//'" using 1:2 with lines lw 2 title "'//leg//'"'
            if (f == 1) then
               if (index(ylabel, unit_label(name)) == 0) then
                  if (len(ylabel) > 0) ylabel = ylabel//', '
                  ylabel = ylabel//unit_label(name)
               end if
            end if
         end do
      end do
      gp = dir//'/plot.gp'
      open(newunit=u, file=gp, status='replace', action='write', iostat=st)
      if (st /= 0) call fail('cannot write '//gp, 4)
      write(u, '(a)') 'set terminal pngcairo size 1000,600 noenhanced'
      write(u, '(a)') 'set output "'//png//'"'
      if (len(title) > 0) write(u, '(a)') 'set title "'//title//'"'
      if (allocated(xcol)) then
         write(u, '(a)') 'set xlabel "'//unit_label(xname)//'"'
      else
         write(u, '(a)') 'set xlabel "'//unit_label('time')//'"'
      end if
      write(u, '(a)') 'set ylabel "'//ylabel//'"'
      write(u, '(a)') 'set grid'
      write(u, '(a)') 'set key outside bottom center horizontal'
      if (logy) write(u, '(a)') 'set logscale y'
      write(u, '(a)') 'plot '//curves
      close(u)
      call execute_command_line('gnuplot "'//gp//'"', exitstat=st)
      if (st /= 0) call fail('gnuplot failed on '//gp// &
                             ' (is gnuplot installed? apt-get install gnuplot-nox)', 4)
      write(output_unit, '(a)') 'dynx-plot: wrote '//png//' (data and script in '//dir//'/)'
   end subroutine plot

   !> The run's name for the legend: the folder holding the file (else the file).
   function run_name(path) result(s)
      character(*), intent(in) :: path
      character(:), allocatable :: s
      integer :: p
      p = index(path, '/', back=.true.)
      if (p > 1) then
         s = path(1:p - 1)
      else
         s = path
      end if
   end function run_name

   !> A file-name-safe form of a column spec.
   function safe(c) result(s)
      character(*), intent(in) :: c
      character(len(c)) :: s
      integer :: k
      s = c
      do k = 1, len(c)
         if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-', &
                   c(k:k)) == 0) s(k:k) = '_'
      end do
   end function safe

   !> "name (unit)" from the column name's dimension and the units in force.
   function unit_label(name) result(s)
      character(*), intent(in) :: name
      character(:), allocatable :: s, dim, nm
      nm = lower(name)
      dim = ''
      if (nm == 'time') then
         dim = 't'
      else if (has(nm, 'ratio') .or. has(nm, 'percent') .or. nm == 'cycle' .or. &
               nm == 'nactive') then
         dim = ''
      else if (has(nm, 'disp') .or. has(nm, 'coor')) then
         dim = 'L'
      else if (has(nm, 'vel') .or. has(nm, 'rbv')) then
         dim = 'L/T'
      else if (has(nm, 'acc')) then
         dim = 'L/T2'
      else if (has(nm, 'mom')) then
         dim = 'ML/T'
      else if (has(nm, 'energy') .or. has(nm, 'kinetic') .or. has(nm, 'internal') .or. &
               has(nm, 'hourglass') .or. has(nm, 'work') .or. has(nm, 'inten') .or. &
               has(nm, 'kinen') .or. has(nm, 'hgeng') .or. nm == 'total' .or. &
               nm == 'slave' .or. nm == 'master' .or. has(nm, 'frictional') .or. &
               has(nm, 'sliding') .or. has(nm, 'rigidwall') .or. has(nm, 'eroded_')) then
         dim = 'E'
      else if (has(nm, 'slave_') .or. has(nm, 'master_') .or. has(nm, 'force') .or. &
               nm == 'magnitude') then
         dim = 'F'
      else if (has(nm, 'mass')) then
         dim = 'M'
      else if (nm == 'dt') then
         dim = 't'
      end if
      s = name
      if (len(dim) > 0) s = s//' ('//unit_of(dim)//')'
   end function unit_label

   logical function has(s, w)
      character(*), intent(in) :: s, w
      has = index(s, w) > 0
   end function has

   !> The unit of a dimension in the units in force: named for the usual LS-DYNA systems
   !> (m s kg: N, J; mm ms kg: kN, J; mm s t: N, mJ), else a product of the base units.
   function unit_of(dim) result(u)
      character(*), intent(in) :: dim
      character(:), allocatable :: u, sys
      if (len(ulen) == 0) then
         u = 'consistent units'
         if (dim == 't') u = 'time'
         return
      end if
      sys = ulen//' '//utime//' '//umass
      select case (dim)
      case ('t')
         u = utime
      case ('L')
         u = ulen
      case ('M')
         u = umass
      case ('L/T')
         u = ulen//'/'//utime
      case ('L/T2')
         u = ulen//'/'//utime//'^2'
      case ('ML/T')
         u = umass//' '//ulen//'/'//utime
      case ('F')
         u = umass//' '//ulen//'/'//utime//'^2'
         if (sys == 'm s kg') u = 'N'
         if (sys == 'mm ms kg') u = 'kN'
         if (sys == 'mm s ton' .or. sys == 'mm s t') u = 'N'
      case ('E')
         u = umass//' '//ulen//'^2/'//utime//'^2'
         if (sys == 'm s kg') u = 'J'
         if (sys == 'mm ms kg') u = 'J'
         if (sys == 'mm s ton' .or. sys == 'mm s t') u = 'mJ'
      case default
         u = '?'
      end select
   end function unit_of

   !> LENGTH, TIME, MASS from the first card after *CONTROL_UNITS ('sec' read as 's').
   subroutine deck_units(path)
      character(*), intent(in) :: path
      character(256) :: buf
      character(32) :: w(3)
      integer :: u, ios
      logical :: after
      open(newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) call fail(path//': cannot open the deck', 4)
      after = .false.
      do
         read(u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         if (buf(1:1) == '$') cycle
         if (buf(1:1) == '*') then
            after = lower(trim(buf)) == '*control_units'
            cycle
         end if
         if (.not. after) cycle
         read(buf, *, iostat=ios) w
         if (ios /= 0) call fail(path//': *CONTROL_UNITS: expected LENGTH TIME MASS on "'// &
                                 trim(buf)//'"', 2)
         ulen = lower(trim(w(1)))
         utime = lower(trim(w(2)))
         if (utime == 'sec') utime = 's'
         umass = lower(trim(w(3)))
         exit
      end do
      close(u)
   end subroutine deck_units

   subroutine split3(s, a, b, c, st)
      character(*), intent(in) :: s
      character(:), allocatable, intent(out) :: a, b, c
      integer, intent(out) :: st
      integer :: p, q
      st = 1
      p = index(s, ',')
      if (p == 0) return
      q = index(s(p + 1:), ',') + p
      if (q == p) return
      a = s(1:p - 1)
      b = s(p + 1:q - 1)
      c = s(q + 1:)
      if (len(a) == 0 .or. len(b) == 0 .or. len(c) == 0) return
      st = 0
   end subroutine split3

   subroutine split_col(c, name, id)
      character(*), intent(in) :: c
      character(:), allocatable, intent(out) :: name
      integer, intent(out) :: id
      type(error_t), allocatable :: error
      call parse_column(c, name, id, error)
      if (allocated(error)) call fail(error%message, error%code)
   end subroutine split_col

   function next(msg) result(v)
      character(*), intent(in) :: msg
      character(:), allocatable :: v
      if (i >= n) call usage(msg)
      i = i + 1
      v = command_arg(i)
   end function next

   subroutine fail(msg, code)
      character(*), intent(in) :: msg
      integer, intent(in) :: code
      write(error_unit, '(a)') 'dynx-plot: error: '//msg
      call sys_exit(code)
   end subroutine fail

   subroutine usage(msg)
      character(*), intent(in) :: msg
      if (len(msg) > 0) write(error_unit, '(a)') 'dynx-plot: error: '//msg
      write(error_unit, '(a)') 'usage: dynx-plot -o out.png --y NAME[@ID] [--y ...] '// &
         '[--x NAME[@ID]] [--title T] [--deck deck.k] [--units LENGTH,TIME,MASS] [--logy] '// &
         'FILE [FILE ...]'
      if (len(msg) == 0) call sys_exit(0)
      call sys_exit(2)
   end subroutine usage
end program dynx_plot
