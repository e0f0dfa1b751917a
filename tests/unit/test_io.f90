!> Unit tests of the output writers and the comparator: the tolerance rule, tolerance lookup,
!> table comparison (pass, fail, NaN, missing column, row count), and a tiny model
!> (1 hex, 8 nodes) written as plot file + glstat + nodout, read back and compared.
program test_io
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_h5, only: h5_file_t, h5_open_read, h5_close, h5_read, h5_read_attr, h5_dims
   use dx_compare, only: tol_table_t, compare_report_t, within_tol, compare_tables, &
                         compare_files, read_table, read_tolerances
   use dx_io_sys, only: sys_mkdir_p, sys_file_kind, sys_write_file, sys_strerror, &
                        sys_flock_try, sys_read_small
   use dx_sort, only: sort_index
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   character(*), parameter :: TMP = 'build/test_io.tmp'
   type(error_t), allocatable :: error

   call sys_mkdir_p(TMP, error)
   call check(.not. allocated(error), 'create scratch dir '//TMP)
   call test_rule()
   call test_lookup()
   call test_tables()
   call test_plot_roundtrip()
   call test_sys()
   call test_sort()
   call assert_summary()

contains

   subroutine test_rule()
      real(wp) :: nan, inf
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      inf = ieee_value(1.0_wp, ieee_positive_inf)
      write(*, '(a)') 'tolerance rule'
      call check(within_tol(1.0_wp, 1.0_wp + 1.0e-10_wp, 0.0_wp, 1.0e-9_wp), 'rel pass')
      call check(.not. within_tol(1.0_wp, 1.1_wp, 0.0_wp, 1.0e-9_wp), 'rel fail')
      call check(within_tol(100.0_wp, 100.49_wp, 0.1_wp, 0.004_wp), 'abs+rel pass (0.49<=0.5)')
      call check(.not. within_tol(100.0_wp, 100.51_wp, 0.1_wp, 0.004_wp), 'abs+rel fail')
      call check(.not. within_tol(100.0_wp, 100.49_wp, 0.1_wp, 0.0_wp), 'abs alone too tight')
      call check(.not. within_tol(100.0_wp, 100.49_wp, 0.0_wp, 0.004_wp), 'rel alone too tight')
      call check(within_tol(0.0_wp, 1.0e-13_wp, 1.0e-12_wp, 0.0_wp), 'abs near zero')
      call check(.not. within_tol(1.0_wp, nan, 1.0_wp, 1.0_wp), 'NaN test fails')
      call check(.not. within_tol(nan, nan, 1.0_wp, 1.0_wp), 'NaN test fails when gold NaN')
      call check(.not. within_tol(inf, inf, 1.0_wp, 1.0_wp), 'Inf test fails')
      call check(.not. within_tol(nan, 1.0_wp, 1.0_wp, 1.0_wp), 'NaN gold, finite test fails')
   end subroutine test_rule

   subroutine test_lookup()
      type(tol_table_t) :: tol
      real(wp) :: a, r
      write(*, '(a)') 'tolerance lookup'
      call tol%add('*', '*', 1.0_wp, 2.0_wp)
      call tol%add('glstat', 'kinetic', 3.0_wp, 4.0_wp)
      call tol%add('nod*', '*', 5.0_wp, 6.0_wp)
      call tol%add('*', 'x_disp', 7.0_wp, 8.0_wp)
      call tol%lookup('glstat', 'kinetic', a, r)
      call check(a == 3.0_wp .and. r == 4.0_wp, 'exact file and quantity')
      call tol%lookup('glstat', 'internal', a, r)
      call check(a == 1.0_wp .and. r == 2.0_wp, 'default rule')
      call tol%lookup('nodout', 'x_vel', a, r)
      call check(a == 5.0_wp .and. r == 6.0_wp, 'later * rule wins over earlier *')
      call tol%lookup('nodout', 'x_disp', a, r)
      call check(a == 7.0_wp .and. r == 8.0_wp, 'exact quantity beats *')
   end subroutine test_lookup

   subroutine test_tables()
      character(8) :: names(3) = [character(8) :: 'time', 'node_id', 'x_disp']
      character(8) :: names2(2) = [character(8) :: 'time', 'node_id']
      character(8) :: names4(4) = [character(8) :: 'time', 'node_id', 'x_disp', 'extra']
      real(wp) :: gold(3, 3), test(3, 3), test4(4, 3), nan
      type(tol_table_t) :: tol
      type(compare_report_t) :: rep
      integer :: k
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      write(*, '(a)') 'table comparison'
      gold = reshape([0.0_wp, 7.0_wp, 0.0_wp, 1.0_wp, 7.0_wp, 0.5_wp, 2.0_wp, 7.0_wp, 1.0_wp], &
                     [3, 3])
      test = gold
      test(3, 2) = 0.5_wp*(1.0_wp + 1.0e-12_wp)
      call tol%add('*', '*', 0.0_wp, 1.0e-9_wp)
      call compare_tables(rep, 'nodout', names, gold, names, test, tol)
      call check(rep%passed(), 'within tolerance passes')

      test(3, 3) = 1.001_wp
      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names, test, tol)
      call check(.not. rep%passed(), 'outside tolerance fails')
      k = rep%find('x_disp', 'nodout', tol)
      call check(rep%q(k)%nbad == 1, 'one bad value counted')
      call check_close(rep%q(k)%time, 2.0_wp, 0.0_wp, 0.0_wp, 'worst difference time')
      call check(rep%q(k)%id == 7 .and. rep%q(k)%id_kind == 'node', 'worst difference node id')
      call check_close(rep%q(k)%worst_diff, 0.001_wp, 1.0e-12_wp, 0.0_wp, 'worst difference')
      print '(a)', '  (the comparator report of a deliberately failing comparison follows)'
      call rep%print(6)

      test = gold
      test(3, 2) = nan
      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names, test, tol)
      call check(.not. rep%passed(), 'NaN in test fails')

      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names2, gold(1:2, :), tol)
      call check(.not. rep%passed() .and. rep%nmsg == 1, 'missing column fails')

      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names, gold(:, 1:2), tol)
      call check(.not. rep%passed(), 'row count mismatch fails')

      test4(1:3, :) = gold
      test4(4, :) = [1.0_wp, nan, 2.0_wp]
      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names4, test4, tol)
      call check(.not. rep%passed(), 'NaN in a test-only column fails')
      test4(4, 2) = 0.0_wp
      rep = compare_report_t()
      call compare_tables(rep, 'nodout', names, gold, names4, test4, tol)
      call check(rep%passed(), 'extra finite column in test is ignored')
   end subroutine test_tables

   !> 1 hex8 element (nodes 101..108, element 55, part 3), 2 integration points.
   subroutine tiny_model(m)
      type(model_t), intent(out) :: m
      integer :: i
      m%title = 'tiny <hex> & test'
      m%nn = 8
      m%ne = 1
      allocate(m%x0(3, 8))
      m%x0 = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1], &
                     [3, 8])*1.0_wp
      m%node_label = [(100 + i, i = 1, 8)]
      m%x = m%x0
      allocate(m%v(3, 8), m%f(3, 8))
      m%v = 0.0_wp
      m%f = 0.0_wp
      m%mass = [(1.0_wp, i = 1, 7), 0.0_wp]
      m%elem_label = [55]
      m%elem_part = [1]
      m%elem_block = [1]
      m%elem_pos = [1]
      allocate(m%parts(1))
      m%parts(1)%label = 3
      allocate(m%blocks(1))
      associate (b => m%blocks(1))
         b%ipart = 1
         b%nel = 1
         b%nip = 2
         b%nhv = 0
         b%conn = reshape([(i, i = 1, 8)], [8, 1])
         b%elem = [1]
         allocate(b%sig(1, 6, 2), b%hv(1, 0, 2))
         b%sig = 0.0_wp
         b%failed = [.false.]
         b%eint = [0.0_wp]
      end associate
      m%db%glstat_dt = 1.0_wp
      m%db%nodout_dt = 1.0_wp
      m%db%hist_nodes = [2, 8]
   end subroutine tiny_model

   !> Advance the tiny model to state k (1 or 2) with known values.
   subroutine set_state(m, k)
      type(model_t), intent(inout) :: m
      integer, intent(in) :: k
      m%time = 1.0e-3_wp*(k - 1)
      m%cycle = 10*(k - 1)
      m%dt = 1.0e-4_wp
      m%x = m%x0
      m%x(1, :) = m%x0(1, :)*(1.0_wp + 0.01_wp*(k - 1))
      m%v(1, :) = 10.0_wp*(k - 1)*m%x0(1, :)
      m%f(1, :) = 2.0_wp*k
      m%blocks(1)%sig(1, :, 1) = [100.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]*k
      m%blocks(1)%sig(1, :, 2) = [300.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 30.0_wp]*k
      m%blocks(1)%failed(1) = k == 2
      m%energy%kinetic = 5.0_wp*(k - 1)
      m%energy%internal = 1.0_wp*(k - 1)
      m%energy%total = m%energy%kinetic + m%energy%internal
      m%energy%momentum = [1.0_wp, -2.0_wp, 0.0_wp]*(k - 1)
   end subroutine set_state

   subroutine write_run(dir, nstates, sig_scale)
      character(*), intent(in) :: dir
      integer, intent(in) :: nstates
      real(wp), intent(in) :: sig_scale
      type(model_t) :: m
      type(output_t) :: out
      type(error_t), allocatable :: err
      integer :: k
      call tiny_model(m)
      call out%open(m, dir, err)
      call check(.not. allocated(err), 'open output in '//dir)
      if (allocated(err)) then
         write(*, '(a)') err%message
         return
      end if
      call check(out%has_glstat() .and. out%has_nodout(), 'glstat and nodout requested')
      do k = 1, nstates
         call set_state(m, k)
         m%blocks(1)%sig = m%blocks(1)%sig*sig_scale
         call out%write_plot(m, err)
         call check(.not. allocated(err), 'write plot state')
         call out%write_glstat(m, err)
         call check(.not. allocated(err), 'write glstat line')
         call out%write_nodout(m, err)
         call check(.not. allocated(err), 'write nodout lines')
      end do
      call check(out%nplot == nstates, 'nplot counts the states')
      call out%close(err)
      call check(.not. allocated(err), 'close output')
      call out%close(err)
      call check(.not. allocated(err), 'close output twice is harmless')
   end subroutine write_run

   subroutine test_plot_roundtrip()
      type(h5_file_t) :: f
      type(error_t), allocatable :: err
      real(wp), allocatable :: buf(:), rows(:, :)
      integer(i8), allocatable :: dims(:)
      character(:), allocatable :: names(:)
      type(tol_table_t) :: tol
      type(compare_report_t) :: rep
      integer :: n, u, ios, ngrid, k
      real(wp) :: t, svm
      character(512) :: line
      logical :: there

      write(*, '(a)') 'plot file round trip'
      call write_run(TMP//'/a', 2, 1.0_wp)
      call h5_open_read(f, TMP//'/a/d3plot.h5', err)
      call check(.not. allocated(err), 'reopen d3plot.h5')
      if (allocated(err)) return
      call h5_read_attr(f, '/', 'nstates', n, err)
      call check(.not. allocated(err) .and. n == 2, 'attribute nstates = 2')
      call h5_read(f, '/states/times', buf, err)
      call check(size(buf) == 2, '/states/times has 2 entries')
      if (size(buf) == 2) call check_close(buf(2), 1.0e-3_wp, 0.0_wp, 0.0_wp, 'times(2)')
      call h5_read_attr(f, '/states/000002', 'time', t, err)
      call check_close(t, 1.0e-3_wp, 0.0_wp, 0.0_wp, 'state 2 attribute time')
      call h5_dims(f, '/mesh/coordinates', dims, err)
      call check(all(dims == [3, 8]), '/mesh/coordinates is (3,8)')
      call h5_read(f, '/mesh/hex8', buf, err)
      call check(all(nint(buf) == [0, 1, 2, 3, 4, 5, 6, 7]), 'hex8 is 0-based')
      call h5_read(f, '/mesh/node_ids', buf, err)
      call check(nint(buf(8)) == 108, 'node_ids')
      call h5_read(f, '/mesh/element_ids', buf, err)
      call check(nint(buf(1)) == 55, 'element_ids')
      call h5_read(f, '/mesh/part_ids', buf, err)
      call check(nint(buf(1)) == 3, 'part_ids hold part labels')
      call h5_read(f, '/states/000002/coordinates', buf, err)
      call check_close(buf(4), 1.01_wp, 0.0_wp, 1.0e-15_wp, 'state 2 x of node 2')
      call h5_read(f, '/states/000002/displacement', buf, err)
      call check_close(buf(4), 0.01_wp, 1.0e-15_wp, 0.0_wp, 'state 2 x_disp of node 2')
      call h5_read(f, '/states/000002/velocity', buf, err)
      call check_close(buf(4), 10.0_wp, 0.0_wp, 0.0_wp, 'state 2 x_vel of node 2')
      call h5_read(f, '/states/000002/stress', buf, err)
      call check(size(buf) == 6, 'stress is (6,1)')
      call check_close(buf(1), 400.0_wp, 0.0_wp, 1.0e-15_wp, 'stress xx averaged over ips')
      call check_close(buf(6), 30.0_wp, 0.0_wp, 1.0e-15_wp, 'stress zx averaged over ips')
      svm = sqrt(400.0_wp**2 + 3.0_wp*30.0_wp**2)
      call h5_read(f, '/states/000002/von_mises', buf, err)
      call check_close(buf(1), svm, 0.0_wp, 1.0e-14_wp, 'von Mises')
      call h5_read(f, '/states/000002/pressure', buf, err)
      call check_close(buf(1), -400.0_wp/3.0_wp, 0.0_wp, 1.0e-14_wp, 'pressure = -tr/3')
      call h5_read(f, '/states/000002/eff_plastic_strain', buf, err)
      call check_close(buf(1), 0.0_wp, 0.0_wp, 0.0_wp, 'no plastic strain -> 0')
      call h5_read(f, '/states/000001/failed', buf, err)
      call check(nint(buf(1)) == 0, 'state 1 not failed')
      call h5_read(f, '/states/000002/failed', buf, err)
      call check(nint(buf(1)) == 1, 'state 2 failed')
      call h5_close(f, err)
      call check(.not. allocated(err), 'close reopened file')

      ! XDMF lists both states and no temporary file is left
      ngrid = 0
      open(newunit=u, file=TMP//'/a/d3plot.xdmf', status='old', action='read', iostat=ios)
      call check(ios == 0, 'd3plot.xdmf exists')
      do while (ios == 0)
         read(u, '(a)', iostat=ios) line
         if (ios == 0 .and. index(line, '<Grid Name="state') > 0) ngrid = ngrid + 1
      end do
      close(u)
      call check(ngrid == 2, 'XDMF has 2 state grids')
      inquire(file=TMP//'/a/d3plot.xdmf.tmp', exist=there)
      call check(.not. there, 'no d3plot.xdmf.tmp left behind')

      ! glstat and nodout
      call read_table(TMP//'/a/glstat', names, rows, err)
      call check(.not. allocated(err), 'glstat parses')
      if (allocated(err)) write(*, '(a)') err%message
      if (.not. allocated(err)) then
         call check(size(names) == 14 .and. size(rows, 2) == 2, 'glstat: 14 columns, 2 rows')
         call check(names(14) == 'sliding_interface', 'glstat column 14 is sliding_interface')
         call check(names(4) == 'kinetic', 'glstat column 4 is kinetic')
         call check_close(rows(4, 2), 5.0_wp, 0.0_wp, 1.0e-10_wp, 'glstat kinetic')
         call check_close(rows(12, 2), -2.0_wp, 0.0_wp, 1.0e-10_wp, 'glstat ymom')
      end if
      ! the names line without '#' (gnuplot's columnhead form; issue 21): line 3
      open(newunit=u, file=TMP//'/a/glstat', status='old', action='read', iostat=ios)
      do k = 1, 3
         if (ios == 0) read(u, '(a)', iostat=ios) line
      end do
      close(u)
      call check(ios == 0 .and. index(line, 'time cycle dt kinetic ') == 1, &
                 'glstat line 3 is the names line without #')
      ! the former form ('# time ...') still parses (older files and golds)
      open(newunit=u, file=TMP//'/a/old_glstat', status='replace', action='write')
      write(u, '(a)') '# dynx glstat', '# title: old form', '# time kinetic', &
                      ' 0.0 1.5', ' 1.0 2.5'
      close(u)
      call read_table(TMP//'/a/old_glstat', names, rows, err)
      call check(.not. allocated(err), 'old-form glstat parses')
      if (.not. allocated(err)) then
         call check(size(names) == 2 .and. size(rows, 2) == 2, 'old form: 2 columns, 2 rows')
         call check(names(2) == 'kinetic', 'old form: column 2 is kinetic')
         call check_close(rows(2, 2), 2.5_wp, 0.0_wp, 0.0_wp, 'old form: value')
      end if
      call read_table(TMP//'/a/nodout', names, rows, err)
      call check(.not. allocated(err), 'nodout parses')
      if (.not. allocated(err)) then
         call check(size(names) == 14 .and. size(rows, 2) == 4, 'nodout: 14 columns, 4 rows')
         call check(nint(rows(2, 4)) == 108, 'nodout node label')
         call check_close(rows(9, 3), 4.0_wp, 0.0_wp, 1.0e-10_wp, 'nodout x_acc = f/m')
         call check_close(rows(9, 4), 0.0_wp, 0.0_wp, 0.0_wp, 'nodout x_acc = 0 if m = 0')
         call check_close(rows(12, 3), 1.01_wp, 0.0_wp, 1.0e-10_wp, 'nodout x_coor')
      end if

      ! comparator on plot files and histories
      call compare_files(TMP//'/a/d3plot.h5', TMP//'/a/d3plot.h5', tol, rep)
      call check(rep%passed(), 'plot file equals itself')
      call compare_files(TMP//'/a/glstat', TMP//'/a/glstat', tol, rep)
      call check(rep%passed(), 'glstat equals itself')
      call write_run(TMP//'/b', 2, 1.0_wp + 1.0e-6_wp)
      call compare_files(TMP//'/a/d3plot.h5', TMP//'/b/d3plot.h5', tol, rep)
      print '(a)', '  (the comparator report of a deliberately failing comparison follows)'
      call rep%print(6)
      call check(.not. rep%passed(), 'changed stress fails at default tolerance')
      k = rep%find('von_mises', 'd3plot.h5', tol)
      call check(rep%q(k)%nbad == 2 .and. rep%q(k)%id == 55, 'von_mises fails at element 55')
      call check_close(rep%q(k)%time, 1.0e-3_wp, 0.0_wp, 0.0_wp, 'worst von_mises at t=1e-3')

      open(newunit=u, file=TMP//'/tol', status='replace', action='write')
      write(u, '(a)') '# test tolerances'
      write(u, '(a)') '*.h5  *       1e-12  1e-9'
      write(u, '(a)') '*.h5  stress  0      1e-5   # stress may drift'
      write(u, '(a)') 'd3*   von_mises 0    1e-5'
      write(u, '(a)') 'd3*   pressure  0    1e-5'
      close(u)
      tol = tol_table_t()
      call read_tolerances(TMP//'/tol', tol, err)
      call check(.not. allocated(err), 'tolerance file parses')
      call compare_files(TMP//'/a/d3plot.h5', TMP//'/b/d3plot.h5', tol, rep)
      call check(rep%passed(), 'changed stress passes with rel 1e-5')

      call write_run(TMP//'/c', 1, 1.0_wp)
      call compare_files(TMP//'/a/d3plot.h5', TMP//'/c/d3plot.h5', tol, rep)
      print '(a)', '  (the comparator report of a deliberately failing comparison follows)'
      call rep%print(6)
      call check(.not. rep%passed(), 'missing state fails')
      call compare_files(TMP//'/a/glstat', TMP//'/c/glstat', tol, rep)
      call check(.not. rep%passed(), 'missing glstat row fails')
      call compare_files(TMP//'/a/glstat', TMP//'/nonexistent', tol, rep)
      call check(.not. rep%passed(), 'missing test file fails')
   end subroutine test_plot_roundtrip
   !> The write(2) helpers, statx file kinds, strerror, flock (issue 15).
   subroutine test_sys()
      type(error_t), allocatable :: e
      integer :: fd1, fd2
      logical :: got1, got2
      write(*, '(a)') 'system helpers'
      call sys_write_file(TMP//'/w.txt', 'abc'//new_line('a'), e)
      call check(.not. allocated(e), 'sys_write_file')
      call check(sys_read_small(TMP//'/w.txt') == 'abc'//new_line('a'), 'read back')
      call check(sys_file_kind(TMP//'/w.txt') == 'regular', 'kind regular')
      call check(sys_file_kind(TMP) == 'directory', 'kind directory')
      call check(sys_file_kind('/dev/zero') == 'device', 'kind device')
      call check(sys_file_kind(TMP//'/none') == 'missing', 'kind missing')
      call check(sys_strerror(28) == 'No space left on device', 'strerror ENOSPC')
      call sys_write_file(TMP//'/no/such/dir/x', 'x', e)
      call check(allocated(e), 'write into a missing folder fails')
      if (allocated(e)) call check(index(e%message, 'No such file or directory') > 0, &
                                   'the message has the OS reason')
      call sys_flock_try(TMP//'/lock', fd1, got1, e)
      call check(got1 .and. .not. allocated(e), 'first flock taken')
      call sys_flock_try(TMP//'/lock', fd2, got2, e)   ! a second open file: refused
      call check(.not. got2 .and. .not. allocated(e) .and. fd2 < 0, 'second flock refused')
   end subroutine test_sys

   !> sort_index: ascending keys, ties by index (the order every rank agrees on).
   subroutine test_sort()
      integer :: idx(6), ikey(6), k
      real(wp) :: rkey(6)
      write(*, '(a)') 'sort_index'
      ikey = [3, 1, 3, 2, 1, 0]
      idx = [(k, k = 6, 1, -1)]
      call sort_index(idx, ikey)
      call check(all(idx == [6, 2, 5, 4, 1, 3]), 'integer keys, ties by index')
      rkey = [0.5_wp, -1.0_wp, 0.5_wp, 2.0_wp, -1.0_wp, 0.0_wp]
      idx = [(k, k = 1, 6)]
      call sort_index(idx, rkey)
      call check(all(idx == [2, 5, 6, 1, 3, 4]), 'real keys, ties by index')

   end subroutine test_sort
end program test_io
