!> Numerical comparison of dynx outputs against gold files, used by dynx-compare and the
!> regression runner: ASCII time histories (glstat, nodout: columns by header name, rows by
!> order) and HDF5 plot files (/states/times, every dataset of /mesh and of every state).
!> Rule: a test value t passes against gold g when t is finite and |t - g| <= abs + rel*|g|;
!> NaN or Inf anywhere in the test file fails, even where gold has NaN.
!> Tolerances per (file glob, quantity): docs/output-format.md. No matching rule:
!> DEFAULT_ABS, DEFAULT_REL. Every failing quantity is reported with its worst (largest)
!> difference: time, node/element id and component where known, gold, test, difference.
!> NaN checks come before any arithmetic so the debug build's FPE traps stay quiet.
module dx_compare
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_h5, only: h5_file_t, h5_open_read, h5_close, h5_exists, h5_dims, h5_read, &
                    h5_read_attr, h5_list, H5_GROUP, H5_DATASET
   use dx_compare_report, only: tol_table_t, compare_report_t, qdiff_t, within_tol, &
                                read_tolerances, split_tokens, accumulate, DEFAULT_ABS, &
                                DEFAULT_REL, MAXLINE
   implicit none
   private
   public :: tol_table_t, compare_report_t, qdiff_t, within_tol, read_tolerances, &
             read_table, compare_tables, compare_files, compare_ascii, compare_h5, find_name, &
             DEFAULT_ABS, DEFAULT_REL

   character(*), parameter :: NODE_DSETS(4) = [character(12) :: 'coordinates', &
      'displacement', 'velocity', 'node_ids']

contains

   !> Read an ASCII history: the last '#' line before the data names the columns;
   !> rows(ncol, nrow). A data line with a wrong column count or a token that is not a
   !> number is an error.
   subroutine read_table(path, names, rows, error)
      character(*), intent(in) :: path
      character(:), allocatable, intent(out) :: names(:)
      real(wp), allocatable, intent(out) :: rows(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, lineno, nt, nrow, ncol, j
      character(MAXLINE) :: line
      character(256) :: msg
      character(:), allocatable :: toks(:)
      real(wp), allocatable :: tmp(:, :)
      character(16) :: buf
      logical :: have_header
      open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call set_error(error, 'cannot open '//path//': '//trim(msg), EXIT_INPUT)
         return
      end if
      have_header = .false.
      ncol = 0
      nrow = 0
      allocate(character(1) :: names(0))
      allocate(rows(0, 0))
      lineno = 0
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         write(buf, '(i0)') lineno
         if (len_trim(line) == 0) cycle
         line = adjustl(line)
         if (line(1:1) == '#') then
            if (nrow == 0) then
               call split_tokens(line(index(line, '#') + 1:), names, ncol)
               have_header = .true.
            end if
            cycle
         end if
         ! the names line without '#' (gnuplot's columnhead form; docs/output-format.md):
         ! before the first data row, a line whose first word is not a number
         if (nrow == 0 .and. index('+-.0123456789', line(1:1)) == 0) then
            call split_tokens(line, names, ncol)
            have_header = .true.
            cycle
         end if
         if (.not. have_header) then
            call set_error(error, path//':'//trim(buf)//': data before a # header naming '// &
                           'the columns', EXIT_INPUT)
            exit
         end if
         if (nrow == 0) then
            deallocate(rows)
            allocate(rows(ncol, 64))
         end if
         call split_tokens(line, toks, nt)
         if (nt /= ncol) then
            write(msg, '(a,i0,a,i0,a)') ': ', nt, ' columns, header names ', ncol, ''
            call set_error(error, path//':'//trim(buf)//trim(msg), EXIT_INPUT)
            exit
         end if
         if (nrow == size(rows, 2)) then
            allocate(tmp(ncol, 2*nrow))
            tmp(:, 1:nrow) = rows(:, 1:nrow)
            call move_alloc(tmp, rows)
         end if
         nrow = nrow + 1
         do j = 1, ncol
            read(toks(j), *, iostat=ios) rows(j, nrow)
            if (ios /= 0) exit
         end do
         if (ios /= 0) then
            call set_error(error, path//':'//trim(buf)//': not a number: '//trim(toks(j)), &
                           EXIT_INPUT)
            exit
         end if
      end do
      close(u)
      if (allocated(error)) return
      if (.not. have_header) then
         call set_error(error, path//': no # header line naming the columns', EXIT_INPUT)
         return
      end if
      if (nrow == 0) then
         deallocate(rows)
         allocate(rows(ncol, 0))
      else
         rows = rows(:, 1:nrow)
      end if
   end subroutine read_table

   !> Compare two tables (columns by name, rows by order) into report.
   subroutine compare_tables(report, fname, gnames, gold, tnames, test, tol)
      type(compare_report_t), intent(inout) :: report
      character(*), intent(in) :: fname
      character(*), intent(in) :: gnames(:), tnames(:)
      real(wp), intent(in) :: gold(:, :), test(:, :)
      type(tol_table_t), intent(in) :: tol
      integer :: j, jt, i, nrow, itime, iid, q
      character(16) :: a, b
      character(:), allocatable :: kind
      real(wp) :: time
      integer :: id

      report%file = fname
      if (size(gold, 2) /= size(test, 2)) then
         write(a, '(i0)') size(gold, 2)
         write(b, '(i0)') size(test, 2)
         call report%fail('rows: gold has '//trim(a)//', test has '//trim(b))
      end if
      nrow = min(size(gold, 2), size(test, 2))
      itime = find_name(tnames, 'time')
      iid = find_name(tnames, 'node_id')
      kind = ''
      if (iid > 0) kind = 'node'
      do j = 1, size(gnames)
         jt = find_name(tnames, gnames(j))
         if (jt == 0) then
            call report%fail(trim(gnames(j))//': column missing in test')
            cycle
         end if
         q = report%find(trim(gnames(j)), fname, tol)
         do i = 1, nrow
            time = 0.0_wp
            if (itime > 0) time = gold(find_name(gnames, 'time'), i)
            id = 0
            if (iid > 0) id = nint_safe(test(iid, i))
            call accumulate(report%q(q), gold(j, i), test(jt, i), itime > 0, time, &
                            kind, id, 0)
         end do
         ! values beyond the common rows still must be finite
         do i = nrow + 1, size(test, 2)
            if (.not. ieee_is_finite(test(jt, i))) then
               call accumulate(report%q(q), 0.0_wp, test(jt, i), .false., 0.0_wp, '', 0, 0)
            end if
         end do
      end do
      ! NaN/Inf in columns gold does not have
      do jt = 1, size(tnames)
         if (find_name(gnames, tnames(jt)) > 0) cycle
         if (any(.not. ieee_is_finite(test(jt, :)))) then
            call report%fail(trim(tnames(jt))//': NaN or Inf in test (column not in gold)')
         end if
      end do
   end subroutine compare_tables

   integer function nint_safe(x)
      real(wp), intent(in) :: x
      nint_safe = 0
      if (ieee_is_finite(x)) then
         if (abs(x) < 2.0e9_wp) nint_safe = nint(x)
      end if
   end function nint_safe

   integer function find_name(names, name)
      character(*), intent(in) :: names(:), name
      integer :: i
      find_name = 0
      do i = 1, size(names)
         if (trim(names(i)) == trim(name)) then
            find_name = i
            return
         end if
      end do
   end function find_name

   !> Base name of a path.
   function basename(path) result(b)
      character(*), intent(in) :: path
      character(:), allocatable :: b
      b = path(index(path, '/', back=.true.) + 1:)
   end function basename

   !> Compare two files: HDF5 plot files (*.h5) or ASCII histories (anything else).
   subroutine compare_files(gold_path, test_path, tol, report)
      character(*), intent(in) :: gold_path, test_path
      type(tol_table_t), intent(in) :: tol
      type(compare_report_t), intent(out) :: report
      integer :: n
      n = len_trim(gold_path)
      if (n >= 3) then
         if (gold_path(n - 2:n) == '.h5') then
            call compare_h5(gold_path, test_path, tol, report)
            return
         end if
      end if
      call compare_ascii(gold_path, test_path, tol, report)
   end subroutine compare_files

   !> Compare two ASCII histories.
   subroutine compare_ascii(gold_path, test_path, tol, report)
      character(*), intent(in) :: gold_path, test_path
      type(tol_table_t), intent(in) :: tol
      type(compare_report_t), intent(out) :: report
      character(:), allocatable :: gnames(:), tnames(:)
      real(wp), allocatable :: gold(:, :), test(:, :)
      type(error_t), allocatable :: error
      report%file = basename(gold_path)
      call read_table(gold_path, gnames, gold, error)
      if (allocated(error)) then
         call report%fail('gold: '//error%message)
         return
      end if
      call read_table(test_path, tnames, test, error)
      if (allocated(error)) then
         call report%fail('test: '//error%message)
         return
      end if
      call compare_tables(report, basename(gold_path), gnames, gold, tnames, test, tol)
   end subroutine compare_ascii

   !> Compare two HDF5 plot files: /states/times, every dataset of /mesh and of every state.
   subroutine compare_h5(gold_path, test_path, tol, report)
      character(*), intent(in) :: gold_path, test_path
      type(tol_table_t), intent(in) :: tol
      type(compare_report_t), intent(out) :: report
      type(h5_file_t) :: fg, ft
      type(error_t), allocatable :: error, e2
      character(len=256), allocatable :: gm(:), tm(:)
      integer, allocatable :: gk(:), tk(:)
      integer, allocatable :: node_ids(:), elem_ids(:)
      real(wp), allocatable :: buf(:)
      real(wp) :: time
      character(:), allocatable :: fname, grp
      character(16) :: a, b
      integer :: i, j
      logical :: there

      fname = basename(gold_path)
      report%file = fname
      call h5_open_read(fg, gold_path, error)
      if (allocated(error)) then
         call report%fail('gold: '//error%message)
         return
      end if
      call h5_open_read(ft, test_path, error)
      if (allocated(error)) then
         call report%fail('test: '//error%message)
         call h5_close(fg, e2)
         return
      end if

      work: block
         call read_ids('/mesh/node_ids', node_ids)
         if (allocated(error)) exit work
         call read_ids('/mesh/element_ids', elem_ids)
         if (allocated(error)) exit work

         call compare_group('/mesh', .false., 0.0_wp)
         if (allocated(error)) exit work

         ! states: times first, then every state group of gold
         call h5_exists(fg, '/states/times', there, error)
         if (there) call compare_dataset('/states/times', .false., 0.0_wp)
         if (allocated(error)) exit work
         call h5_exists(fg, '/states', there, error)
         if (.not. there) exit work
         call h5_list(fg, '/states', gm, gk, error)
         if (allocated(error)) exit work
         call h5_exists(ft, '/states', there, error)
         if (.not. there) then
            call report%fail('/states: group missing in test')
            exit work
         end if
         call h5_list(ft, '/states', tm, tk, error)
         if (allocated(error)) exit work
         do i = 1, size(gm)
            if (gk(i) /= H5_GROUP) cycle
            grp = '/states/'//trim(gm(i))
            call h5_read_attr(fg, grp, 'time', time, e2)
            if (allocated(e2)) time = 0.0_wp
            if (.not. any(tm == gm(i))) then
               write(a, '(es14.6e3)') time
               call report%fail(grp//': state missing in test (gold time '// &
                                trim(adjustl(a))//')')
               cycle
            end if
            call compare_group(grp, .true., time)
            if (allocated(error)) exit work
         end do
         j = 0
         do i = 1, size(tm)
            if (tk(i) /= H5_GROUP) cycle
            if (any(gm == tm(i))) cycle
            j = j + 1
            ! extra states must still be finite
            call scan_group('/states/'//trim(tm(i)))
         end do
         if (j > 0) then
            write(a, '(i0)') count(gk == H5_GROUP)
            write(b, '(i0)') count(tk == H5_GROUP)
            call report%fail('/states: gold has '//trim(a)//' states, test has '//trim(b))
         end if
      end block work
      if (allocated(error)) call report%fail(error%message)
      call h5_close(fg, e2)
      call h5_close(ft, e2)

   contains

      !> The ids of gold's /mesh dataset path (empty when it has none; a lookup error counts
      !> as none, a read error is returned).
      subroutine read_ids(path, ids)
         character(*), intent(in) :: path
         integer, allocatable, intent(out) :: ids(:)
         allocate(ids(0))
         call h5_exists(fg, path, there, error)
         if (allocated(error)) deallocate(error)
         if (.not. there) return
         call h5_read(fg, path, buf, error)
         if (.not. allocated(error)) ids = nint(buf)
      end subroutine read_ids

      !> Compare every dataset of group grp (present in gold) and scan test-only ones.
      subroutine compare_group(grp, timed, t)
         character(*), intent(in) :: grp
         logical, intent(in) :: timed
         real(wp), intent(in) :: t
         character(len=256), allocatable :: gn(:), tn(:)
         integer, allocatable :: gkk(:), tkk(:)
         integer :: k
         logical :: ok
         call h5_exists(fg, grp, ok, error)
         if (.not. ok .or. allocated(error)) return
         call h5_list(fg, grp, gn, gkk, error)
         if (allocated(error)) return
         call h5_exists(ft, grp, ok, error)
         if (allocated(error)) return
         if (.not. ok) then
            call report%fail(grp//': group missing in test')
            return
         end if
         call h5_list(ft, grp, tn, tkk, error)
         if (allocated(error)) return
         do k = 1, size(gn)
            if (gkk(k) /= H5_DATASET) cycle
            if (.not. any(tn == gn(k))) then
               call report%fail(grp//'/'//trim(gn(k))//': dataset missing in test')
               cycle
            end if
            call compare_dataset(grp//'/'//trim(gn(k)), timed, t)
            if (allocated(error)) return
         end do
         do k = 1, size(tn)
            if (tkk(k) /= H5_DATASET) cycle
            if (any(gn == tn(k))) cycle
            call scan_dataset(grp//'/'//trim(tn(k)))
            if (allocated(error)) return
         end do
      end subroutine compare_group

      !> NaN/Inf check of every dataset of a test-only group.
      subroutine scan_group(grp)
         character(*), intent(in) :: grp
         character(len=256), allocatable :: tn(:)
         integer, allocatable :: tkk(:)
         integer :: k
         call h5_list(ft, grp, tn, tkk, error)
         if (allocated(error)) return
         do k = 1, size(tn)
            if (tkk(k) == H5_DATASET) call scan_dataset(grp//'/'//trim(tn(k)))
            if (allocated(error)) return
         end do
      end subroutine scan_group

      subroutine scan_dataset(path)
         character(*), intent(in) :: path
         real(wp), allocatable :: tv(:)
         call h5_read(ft, path, tv, error)
         if (allocated(error)) return
         if (any(.not. ieee_is_finite(tv))) then
            call report%fail(path//': NaN or Inf in test (dataset not in gold)')
         end if
      end subroutine scan_dataset

      subroutine compare_dataset(path, timed, t)
         character(*), intent(in) :: path
         logical, intent(in) :: timed
         real(wp), intent(in) :: t
         integer(i8), allocatable :: gd(:), td(:)
         real(wp), allocatable :: gv(:), tv(:)
         character(:), allocatable :: name, key, kind
         integer :: q, ncomp, n, ent, id, comp
         integer(i8) :: k
         character(80) :: s1, s2
         call h5_dims(fg, path, gd, error)
         if (allocated(error)) return
         call h5_dims(ft, path, td, error)
         if (allocated(error)) return
         if (size(gd) /= size(td)) then
            call report%fail(path//': rank differs between gold and test')
            return
         end if
         if (any(gd /= td)) then
            write(s1, '(*(i0,:,","))') gd
            write(s2, '(*(i0,:,","))') td
            call report%fail(path//': shape ('//trim(s1)//') in gold, ('//trim(s2)// &
                             ') in test')
            return
         end if
         call h5_read(fg, path, gv, error)
         if (allocated(error)) return
         call h5_read(ft, path, tv, error)
         if (allocated(error)) return
         key = path(index(path, '/', back=.true.) + 1:)
         if (path(1:6) == '/mesh/') then
            name = path
         else if (path == '/states/times') then
            name = path
         else
            name = key
         end if
         q = report%find(name, fname, tol)
         ncomp = 1
         if (size(gd) >= 2) ncomp = int(product(gd(1:size(gd) - 1)))
         n = 0
         if (size(gd) >= 1) n = int(gd(size(gd)))
         kind = ''
         if (any(NODE_DSETS == key) .and. n == size(node_ids)) then
            kind = 'node'
         else if (n == size(elem_ids) .and. path /= '/states/times') then
            kind = 'element'
         end if
         do k = 1, size(gv, kind=i8)
            ent = int((k - 1)/ncomp) + 1
            comp = 0
            if (ncomp > 1) comp = int(mod(k - 1, int(ncomp, i8))) + 1
            id = 0
            if (kind == 'node') id = node_ids(ent)
            if (kind == 'element') id = elem_ids(ent)
            if (path == '/states/times') then
               call accumulate(report%q(q), gv(k), tv(k), .true., gv(k), '', 0, 0)
            else
               call accumulate(report%q(q), gv(k), tv(k), timed, t, kind, id, comp)
            end if
         end do
      end subroutine compare_dataset
   end subroutine compare_h5
end module dx_compare
