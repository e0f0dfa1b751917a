!> Tolerance tables and comparison reports for dynx-compare (dx_compare): the rule, the
!> tolerance file '<file-glob> <quantity> <abs> <rel>' (docs/output-format.md), and the report
!> of one pair of files with the worst difference of every failing quantity.
!> Rule: a test value t passes against gold g when t is finite and |t - g| <= abs + rel*|g|;
!> NaN or Inf anywhere in the test file fails, even where gold has NaN.
module dx_compare_report
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_io_sys, only: sys_fnmatch
   implicit none
   private
   public :: tol_table_t, compare_report_t, qdiff_t, within_tol, read_tolerances, &
             split_tokens, accumulate, DEFAULT_ABS, DEFAULT_REL, MAXLINE

   real(wp), parameter :: DEFAULT_ABS = 1.0e-12_wp, DEFAULT_REL = 1.0e-9_wp
   integer, parameter :: MAXLINE = 4096

   type :: tol_rule_t
      character(:), allocatable :: glob, quantity
      real(wp) :: abs_tol = DEFAULT_ABS, rel_tol = DEFAULT_REL
   end type tol_rule_t

   !> Tolerance rules '<file-glob> <quantity> <abs> <rel>'; exact quantity beats '*',
   !> among equals the later line wins.
   type :: tol_table_t
      integer :: n = 0
      type(tol_rule_t), allocatable :: rules(:)
   contains
      procedure :: add => tol_add
      procedure :: lookup => tol_lookup
   end type tol_table_t

   !> Accumulated differences of one quantity (column or dataset name).
   type :: qdiff_t
      character(:), allocatable :: name
      real(wp) :: abs_tol = DEFAULT_ABS, rel_tol = DEFAULT_REL
      integer(i8) :: nvals = 0, nbad = 0, nnonfinite = 0
      logical :: have_worst = .false.
      real(wp) :: worst_diff = -1.0_wp, gold = 0.0_wp, test = 0.0_wp, time = 0.0_wp
      logical :: has_time = .false., nonfinite_worst = .false.
      integer :: id = 0, comp = 0
      character(:), allocatable :: id_kind
   end type qdiff_t

   type :: msg_t
      character(:), allocatable :: s
   end type msg_t

   !> Result of comparing one pair of files.
   type :: compare_report_t
      character(:), allocatable :: file
      integer :: nq = 0, nmsg = 0
      type(qdiff_t), allocatable :: q(:)
      type(msg_t), allocatable :: msgs(:)      !< structural failures (missing, shape, ...)
   contains
      procedure :: passed => report_passed
      procedure :: nfailed => report_nfailed
      procedure :: print => report_print
      procedure :: fail => report_fail
      procedure :: find => report_find
   end type compare_report_t

contains

   !> The comparison rule: t finite and |t - g| <= abs + rel*|g| (gold NaN/Inf: fails).
   elemental logical function within_tol(gold, test, abs_tol, rel_tol)
      real(wp), intent(in) :: gold, test, abs_tol, rel_tol
      within_tol = .false.
      if (.not. ieee_is_finite(test)) return
      if (.not. ieee_is_finite(gold)) return
      within_tol = abs(test - gold) <= abs_tol + rel_tol*abs(gold)
   end function within_tol

   subroutine tol_add(self, glob, quantity, abs_tol, rel_tol)
      class(tol_table_t), intent(inout) :: self
      character(*), intent(in) :: glob, quantity
      real(wp), intent(in) :: abs_tol, rel_tol
      type(tol_rule_t), allocatable :: tmp(:)
      if (.not. allocated(self%rules)) allocate(self%rules(8))
      if (self%n == size(self%rules)) then
         allocate(tmp(2*self%n))
         tmp(1:self%n) = self%rules(1:self%n)
         call move_alloc(tmp, self%rules)
      end if
      self%n = self%n + 1
      self%rules(self%n) = tol_rule_t(glob, quantity, abs_tol, rel_tol)
   end subroutine tol_add

   !> Tolerances for quantity in the file named fname (a base name).
   subroutine tol_lookup(self, fname, quantity, abs_tol, rel_tol)
      class(tol_table_t), intent(in) :: self
      character(*), intent(in) :: fname, quantity
      real(wp), intent(out) :: abs_tol, rel_tol
      integer :: i, best, rank
      abs_tol = DEFAULT_ABS
      rel_tol = DEFAULT_REL
      best = 0
      do i = 1, self%n
         associate (r => self%rules(i))
            if (.not. sys_fnmatch(r%glob, fname)) cycle
            if (r%quantity == quantity) then
               rank = 2
            else if (r%quantity == '*') then
               rank = 1
            else
               cycle
            end if
            if (rank >= best) then
               best = rank
               abs_tol = r%abs_tol
               rel_tol = r%rel_tol
            end if
         end associate
      end do
   end subroutine tol_lookup

   !> Read a tolerance file: lines '<file-glob> <quantity> <abs> <rel>', '#' comments.
   subroutine read_tolerances(path, table, error)
      character(*), intent(in) :: path
      type(tol_table_t), intent(inout) :: table
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, lineno, nt
      character(MAXLINE) :: line
      character(256) :: msg
      character(:), allocatable :: toks(:)
      real(wp) :: a, r
      character(16) :: buf
      open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call set_error(error, 'cannot open tolerance file '//path//': '//trim(msg), &
                        EXIT_INPUT)
         return
      end if
      lineno = 0
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         if (index(line, '#') > 0) line = line(1:index(line, '#') - 1)
         call split_tokens(line, toks, nt)
         if (nt == 0) cycle
         write(buf, '(i0)') lineno
         if (nt /= 4) then
            call set_error(error, path//':'//trim(buf)//': expected ''<file-glob> '// &
                           '<quantity> <abs> <rel>'', got '//trim(line), EXIT_INPUT)
            exit
         end if
         read(toks(3), *, iostat=ios) a
         if (ios == 0) read(toks(4), *, iostat=ios) r
         if (ios == 0) then
            if (.not. (ieee_is_finite(a) .and. ieee_is_finite(r))) ios = 1
         end if
         if (ios == 0) then
            if (a < 0.0_wp .or. r < 0.0_wp) ios = 1
         end if
         if (ios /= 0) then
            call set_error(error, path//':'//trim(buf)//': abs and rel must be numbers '// &
                           '>= 0, got '//trim(toks(3))//' '//trim(toks(4)), EXIT_INPUT)
            exit
         end if
         call table%add(trim(toks(1)), trim(toks(2)), a, r)
      end do
      close(u)
   end subroutine read_tolerances

   !> Whitespace-separated tokens of line.
   subroutine split_tokens(line, toks, n)
      character(*), intent(in) :: line
      character(:), allocatable, intent(out) :: toks(:)
      integer, intent(out) :: n
      integer :: i, j, l, k
      integer, allocatable :: b(:, :)     ! first and last column of each token
      l = len_trim(line)
      allocate(b(2, l/2 + 1))
      n = 0
      i = 1
      do while (i <= l)
         if (is_space(line(i:i))) then
            i = i + 1
            cycle
         end if
         j = i
         do while (j < l)
            if (is_space(line(j + 1:j + 1))) exit
            j = j + 1
         end do
         n = n + 1
         b(:, n) = [i, j]
         i = j + 1
      end do
      allocate(character(max(1, maxval(b(2, 1:n) - b(1, 1:n) + 1))) :: toks(n))
      do k = 1, n
         toks(k) = line(b(1, k):b(2, k))
      end do
   contains
      pure logical function is_space(c)
         character, intent(in) :: c
         is_space = c == ' ' .or. c == achar(9) .or. c == achar(13)
      end function is_space
   end subroutine split_tokens

   !> Account one value pair; the worst failing pair is the one with the largest
   !> difference (a non-finite test value outranks any finite difference).
   subroutine accumulate(q, g, t, has_time, time, kind, id, comp)
      type(qdiff_t), intent(inout) :: q
      real(wp), intent(in) :: g, t, time
      logical, intent(in) :: has_time
      character(*), intent(in) :: kind
      integer, intent(in) :: id, comp
      real(wp) :: d
      logical :: nonfinite
      q%nvals = q%nvals + 1
      if (within_tol(g, t, q%abs_tol, q%rel_tol)) return
      q%nbad = q%nbad + 1
      nonfinite = .not. ieee_is_finite(t)
      if (nonfinite) q%nnonfinite = q%nnonfinite + 1
      if (nonfinite .or. .not. ieee_is_finite(g)) then
         d = huge(1.0_wp)
         if (q%have_worst .and. (q%nonfinite_worst .or. .not. nonfinite)) return
      else
         d = abs(t - g)
         if (q%have_worst .and. (q%nonfinite_worst .or. d <= q%worst_diff)) return
      end if
      q%have_worst = .true.
      q%nonfinite_worst = nonfinite
      q%worst_diff = d
      q%gold = g
      q%test = t
      q%has_time = has_time
      q%time = time
      q%id_kind = kind
      q%id = id
      q%comp = comp
   end subroutine accumulate

   !> Index of quantity name in report (added, with its tolerances, if new).
   integer function report_find(self, name, fname, tol) result(k)
      class(compare_report_t), intent(inout) :: self
      character(*), intent(in) :: name, fname
      type(tol_table_t), intent(in) :: tol
      type(qdiff_t), allocatable :: tmp(:)
      character(:), allocatable :: key
      integer :: i
      do k = 1, self%nq
         if (self%q(k)%name == name) return
      end do
      if (.not. allocated(self%q)) allocate(self%q(16))
      if (self%nq == size(self%q)) then
         allocate(tmp(2*self%nq))
         tmp(1:self%nq) = self%q(1:self%nq)
         call move_alloc(tmp, self%q)
      end if
      self%nq = self%nq + 1
      k = self%nq
      self%q(k)%name = name
      ! tolerance key: the dataset or column name without any group prefix
      i = index(name, '/', back=.true.)
      key = name(i + 1:)
      call tol%lookup(fname, key, self%q(k)%abs_tol, self%q(k)%rel_tol)
   end function report_find

   !> Record a structural failure.
   subroutine report_fail(self, msg)
      class(compare_report_t), intent(inout) :: self
      character(*), intent(in) :: msg
      type(msg_t), allocatable :: tmp(:)
      if (.not. allocated(self%msgs)) allocate(self%msgs(8))
      if (self%nmsg == size(self%msgs)) then
         allocate(tmp(2*self%nmsg))
         tmp(1:self%nmsg) = self%msgs(1:self%nmsg)
         call move_alloc(tmp, self%msgs)
      end if
      self%nmsg = self%nmsg + 1
      self%msgs(self%nmsg)%s = msg
   end subroutine report_fail

   !> Number of failures: structural ones plus failing quantities.
   integer function report_nfailed(self)
      class(compare_report_t), intent(in) :: self
      integer :: k
      report_nfailed = self%nmsg
      do k = 1, self%nq
         if (self%q(k)%nbad > 0) report_nfailed = report_nfailed + 1
      end do
   end function report_nfailed

   logical function report_passed(self)
      class(compare_report_t), intent(in) :: self
      report_passed = self%nfailed() == 0
   end function report_passed

   !> Print the verdict and every failure to unit u.
   subroutine report_print(self, u, verbose)
      class(compare_report_t), intent(in) :: self
      integer, intent(in) :: u
      logical, intent(in), optional :: verbose
      integer :: k
      integer(i8) :: nv
      character(:), allocatable :: fname
      character(64) :: b1, b2
      fname = '?'
      if (allocated(self%file)) fname = self%file
      nv = 0
      do k = 1, self%nq
         nv = nv + self%q(k)%nvals
      end do
      if (self%passed()) then
         write(u, '(a,i0,a,i0,a)') 'PASS '//fname//' (', self%nq, ' quantities, ', nv, &
            ' values)'
         if (present(verbose)) then
            if (verbose) call print_quantities(.true.)
         end if
         return
      end if
      write(u, '(a,i0,a)') 'FAIL '//fname//' (', self%nfailed(), ' failing)'
      do k = 1, self%nmsg
         write(u, '(a)') '  '//self%msgs(k)%s
      end do
      call print_quantities(.false.)
   contains
      subroutine print_quantities(all)
         logical, intent(in) :: all
         character(:), allocatable :: where
         integer :: kk
         do kk = 1, self%nq
            associate (q => self%q(kk))
               if (q%nbad == 0) then
                  if (all) write(u, '(a,i0,a)') '  ok '//q%name//' (', q%nvals, ' values)'
                  cycle
               end if
               write(b1, '(es10.3)') q%abs_tol
               write(b2, '(es10.3)') q%rel_tol
               write(u, '(a,i0,a,i0,a)') '  '//q%name//': ', q%nbad, ' of ', q%nvals, &
                  ' values outside |test-gold| <= '//trim(adjustl(b1))//' + '// &
                  trim(adjustl(b2))//'*|gold|'
               if (q%nnonfinite > 0) write(u, '(a,i0,a)') '    test has ', q%nnonfinite, &
                  ' NaN/Inf value(s)'
               where = ''
               if (q%has_time) then
                  write(b1, '(es17.10e3)') q%time
                  where = where//' time '//trim(adjustl(b1))
               end if
               if (allocated(q%id_kind)) then
                  if (len(q%id_kind) > 0 .and. q%id /= 0) then
                     write(b1, '(i0)') q%id
                     where = where//' '//q%id_kind//' '//trim(b1)
                  end if
               end if
               if (q%comp > 0) then
                  write(b1, '(i0)') q%comp
                  where = where//' component '//trim(b1)
               end if
               if (len(where) == 0) where = ' (no time)'
               write(u, '(a)') '    worst at'//where//': gold '//num(q%gold)//', test '// &
                  num(q%test)//', diff '//diffstr(q)
            end associate
         end do
      end subroutine print_quantities
   end subroutine report_print

   function num(x) result(s)
      real(wp), intent(in) :: x
      character(:), allocatable :: s
      character(32) :: buf
      if (ieee_is_nan(x)) then
         s = 'NaN'
      else if (.not. ieee_is_finite(x)) then
         s = 'Inf'
         if (x < 0.0_wp) s = '-Inf'
      else
         write(buf, '(es18.10e3)') x
         s = trim(adjustl(buf))
      end if
   end function num

   function diffstr(q) result(s)
      type(qdiff_t), intent(in) :: q
      character(:), allocatable :: s
      if (q%nonfinite_worst .or. .not. ieee_is_finite(q%gold)) then
         s = 'n/a'
      else
         s = num(q%test - q%gold)
      end if
   end function diffstr
end module dx_compare_report
