!> dynx-compare's folder mode and its rows matched by time (dx_compare does the file pairs):
!>  - by time: each row of the gold history is compared with the test history linearly
!>    interpolated to the gold row's time, between the two test rows around it (of the same
!>    entity when the column after `time` is an id: node_id, contact_id, body, ...). Linear
!>    interpolation is exact for a signal linear between the rows and errs by at most
!>    h^2/8 |x''| (h the test's row spacing) for a smooth one: two runs whose output times
!>    differ (another time step, dynx writing at the first cycle after each output time)
!>    compare within a tolerance of that size. Gold rows outside the test's time range are
!>    not compared and counted as a failure. HDF5 plot files compare state by state as
!>    usual (their states carry their own times).
!>  - folder mode: every file the two folders share that dynx-compare reads: the plot files
!>    d3plot*.h5 and the column histories (a first line '# dynx ...': glstat, nodout, rcforc,
!>    rbdout, ...); a readable file of gold that the test folder lacks is a failure; the rest
!>    (d3hsp, messages, matsum, restart dumps, ...) are listed as not compared.
!> No paper.
module dx_compare_dir
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: string_t, str
   use dx_io_sys, only: sys_list_dir, sys_file_kind
   use dx_compare, only: tol_table_t, compare_report_t, read_table, compare_tables, &
                         compare_files, find_name
   implicit none
   private
   public :: compare_by_time, compare_folders

contains

   !> Two ASCII histories, rows matched by time (see the module header).
   subroutine compare_by_time(gold_path, test_path, tol, report)
      character(*), intent(in) :: gold_path, test_path
      type(tol_table_t), intent(in) :: tol
      type(compare_report_t), intent(out) :: report
      character(:), allocatable :: gnames(:), tnames(:), fname
      real(wp), allocatable :: gold(:, :), test(:, :), res(:, :)
      logical, allocatable :: inside(:)
      type(error_t), allocatable :: error
      integer :: ig, it, idg, idt, nout
      fname = gold_path(index(gold_path, '/', back=.true.) + 1:)
      report%file = fname
      call read_table(gold_path, gnames, gold, error)
      if (allocated(error)) then
         call report%fail('gold: '//error%message); return
      end if
      call read_table(test_path, tnames, test, error)
      if (allocated(error)) then
         call report%fail('test: '//error%message); return
      end if
      ig = find_name(gnames, 'time')
      it = find_name(tnames, 'time')
      if (ig == 0 .or. it == 0) then
         call report%fail('--by-time: no column named time'); return
      end if
      idg = id_column(gnames, ig)
      idt = id_column(tnames, it)
      call resample(gold, ig, idg, test, it, idt, res, inside)
      nout = count(.not. inside)
      call compare_tables(report, fname, gnames, gold(:, pack([(ig, ig = 1, size(inside))], &
                          inside)), tnames, res(:, pack([(it, it = 1, size(inside))], inside)), tol)
      if (nout > 0) call report%fail('--by-time: '//str(nout)//' gold row(s) outside the '// &
                                     'test''s time range (or entity missing): not compared')
   end subroutine compare_by_time

   !> The entity id column: the one after time when it is named *_id, id or body (0: none).
   integer function id_column(names, itime)
      character(*), intent(in) :: names(:)
      integer, intent(in) :: itime
      character(:), allocatable :: n
      integer :: l
      id_column = 0
      if (itime + 1 > size(names)) return
      n = trim(names(itime + 1))
      l = len(n)
      if (n == 'id' .or. n == 'body') id_column = itime + 1
      if (l > 3) then
         if (n(l - 2:) == '_id') id_column = itime + 1
      end if
   end function id_column

   !> res(:, i): the test's row interpolated at gold row i's time (the same entity); the
   !> columns in the test's order. inside(i): the time lies within the entity's test rows.
   subroutine resample(gold, ig, idg, test, it, idt, res, inside)
      real(wp), intent(in) :: gold(:, :), test(:, :)
      integer, intent(in) :: ig, idg, it, idt
      real(wp), allocatable, intent(out) :: res(:, :)
      logical, allocatable, intent(out) :: inside(:)
      integer :: i, k, lo, hi, mid, n
      integer, allocatable :: rows(:)
      real(wp) :: t, w
      allocate(res(size(test, 1), size(gold, 2)), inside(size(gold, 2)))
      res = 0.0_wp
      inside = .false.
      do i = 1, size(gold, 2)
         t = gold(ig, i)
         if (idg > 0 .and. idt > 0) then      ! the test rows of this entity, in time order
            rows = pack([(k, k = 1, size(test, 2))], test(idt, :) == gold(idg, i))
         else
            rows = [(k, k = 1, size(test, 2))]
         end if
         n = size(rows)
         if (n == 0) cycle
         if (.not. ieee_is_finite(t)) cycle
         if (t < test(it, rows(1)) .or. t > test(it, rows(n))) cycle
         lo = 1; hi = n                       ! test(it, rows(lo)) <= t <= test(it, rows(hi))
         do while (hi - lo > 1)
            mid = (lo + hi)/2
            if (test(it, rows(mid)) <= t) then
               lo = mid
            else
               hi = mid
            end if
         end do
         if (n == 1 .or. test(it, rows(hi)) == test(it, rows(lo))) then
            res(:, i) = test(:, rows(lo))
         else
            w = (t - test(it, rows(lo)))/(test(it, rows(hi)) - test(it, rows(lo)))
            res(:, i) = (1.0_wp - w)*test(:, rows(lo)) + w*test(:, rows(hi))
         end if
         res(it, i) = t
         if (idt > 0) res(idt, i) = test(idt, rows(lo))
         inside(i) = .true.
      end do
   end subroutine resample

   !> Every comparable file the folders gdir and tdir share (see the module header): each
   !> file's report on unit u, then one summary line. nfail: files that failed (a gold file
   !> missing in the test folder counts).
   subroutine compare_folders(gdir, tdir, tol, by_time, verbose, u, nfail, error)
      character(*), intent(in) :: gdir, tdir
      type(tol_table_t), intent(in) :: tol
      logical, intent(in) :: by_time, verbose
      integer, intent(in) :: u
      integer, intent(out) :: nfail
      type(error_t), allocatable, intent(out) :: error
      type(string_t), allocatable :: gn(:), tn(:)
      type(compare_report_t) :: report
      character(:), allocatable :: g, t, skipped, missing
      integer :: k, j, ncmp
      logical :: ascii
      nfail = 0
      ncmp = 0
      skipped = ''
      missing = ''
      call sys_list_dir(gdir, gn, error)
      if (allocated(error)) return
      call sys_list_dir(tdir, tn, error)
      if (allocated(error)) return
      do k = 1, size(gn)
         g = gdir//'/'//gn(k)%s
         t = tdir//'/'//gn(k)%s
         if (sys_file_kind(g) /= 'regular' .or. gn(k)%s(1:1) == '.') cycle   ! (.dynx.lock)
         ascii = column_file(g)
         if (.not. (ascii .or. plot_file(gn(k)%s))) then
            skipped = skipped//' '//gn(k)%s
            cycle
         end if
         if (sys_file_kind(t) /= 'regular') then
            missing = missing//' '//gn(k)%s
            nfail = nfail + 1
            cycle
         end if
         ncmp = ncmp + 1
         if (ascii .and. by_time) then
            call compare_by_time(g, t, tol, report)
         else
            call compare_files(g, t, tol, report)
         end if
         call report%print(u, verbose)
         if (.not. report%passed()) nfail = nfail + 1
      end do
      do k = 1, size(tn)
         if (any([(gn(j)%s == tn(k)%s, j = 1, size(gn))])) cycle
         if (sys_file_kind(tdir//'/'//tn(k)%s) /= 'regular' .or. tn(k)%s(1:1) == '.') cycle
         skipped = skipped//' '//tn(k)%s//'(test only)'
      end do
      if (len(missing) > 0) write(u, '(a)') 'FAIL in '//gdir//', missing in '//tdir//':'// &
                                            missing
      if (len(skipped) > 0) write(u, '(a)') 'not compared (not a plot file or column '// &
                                            'history, or in one folder only):'//skipped
      write(u, '(a)') 'folders: '//str(ncmp)//' file(s) compared, '//str(nfail)//' failed'// &
                      trim(merge(' (rows matched by time)', '                       ', by_time))
   end subroutine compare_folders

   !> A plot file: d3plot*.h5.
   logical function plot_file(name)
      character(*), intent(in) :: name
      integer :: n
      n = len(name)
      plot_file = .false.
      if (n >= 9) plot_file = name(1:6) == 'd3plot' .and. name(n - 2:) == '.h5'
   end function plot_file

   !> A column history: its first line starts with '# dynx'.
   logical function column_file(path)
      character(*), intent(in) :: path
      character(16) :: line
      integer :: u, ios
      column_file = .false.
      open(newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read(u, '(a)', iostat=ios) line
      close(u)
      column_file = ios == 0 .and. line(1:6) == '# dynx'
   end function column_file
end module dx_compare_dir
