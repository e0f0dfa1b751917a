!> What `dynx --check` reports about a deck, and what `--ignore-unknown` may skip.
!> Every keyword belongs to a family (output, control, load, contact, material, ...), found
!> from its name as in the LS-DYNA Keyword User's Manual's chapters (*DATABASE_ output,
!> *CONTROL_ controls, *LOAD_ loads, ...). Only output requests and performance controls
!> cannot change the mechanics: those alone may be skipped by --ignore-unknown; a skipped
!> load, constraint, contact, initial condition, material, section, element or *CASE
!> would turn the deck into a different problem, so such a keyword stops the run even then.
!> check_list_t collects the findings of a --check pass (unknown keywords, unsupported
!> options reported by a reader) with the place of the first use and a count, and prints
!> them grouped by family. No paper: the grouping follows the manual's keyword chapters.
module dx_deck_check
   use dx_strings, only: str
   implicit none
   private
   public :: check_list_t, keyword_family, keyword_skippable, NFAMILY, FAMILIES

   integer, parameter :: NFAMILY = 19
   !> families in the order the report lists them
   character(len=18), parameter :: FAMILIES(NFAMILY) = [character(len=18) :: &
      'output', 'performance', 'control', 'load', 'constraint', 'contact', &
      'initial condition', 'material', 'section', 'element', 'part', 'set', 'definition', &
      'parameter', 'case', 'structure', 'damping', 'other', 'output not written']

   !> one finding: what (keyword or message without its place), where first, how often
   type :: finding_t
      integer :: family = 0
      character(:), allocatable :: what, where
      integer :: count = 0
      character(:), allocatable :: key      !< the keyword (its findings are capped)
   end type finding_t

   !> distinct findings listed per keyword; the rest of a keyword's findings are counted in
   !> one line (a damaged block of thousands of cards made thousands of distinct messages,
   !> and the list's cost and size grew with their square: fuzz find, case
   !> fuzz_check_many_findings)
   integer, parameter :: MAX_PER_KEY = 50

   type :: check_list_t
      integer :: n = 0
      type(finding_t), allocatable :: f(:)
   contains
      procedure :: record => list_add
      procedure :: report => list_report
      procedure :: nproblems => list_nproblems
      procedure, nopass :: more_line => list_more_line
   end type check_list_t

   !> keyword prefixes and their families; the first match wins (specific ones first)
   !> (*CONTACT_FORCE_TRANSDUCER measures contact forces for output and applies none)
   character(len=25), parameter :: PREFIX(34) = [character(len=25) :: &
      'CONTACT_FORCE_TRANSDUCER', &
      'CONTROL_OUTPUT', 'CONTROL_MPP_IO', 'CONTROL_MPP', 'CONTROL_PARALLEL', 'CONTROL_CPU', &
      'DATABASE', 'CONTROL', 'LOAD', 'BOUNDARY', 'CONSTRAINED', 'RIGIDWALL', 'CONTACT', &
      'INITIAL', 'MAT', 'EOS', 'HOURGLASS', 'SECTION', 'ELEMENT', 'NODE', 'PART', 'SET', &
      'DEFINE', 'PARAMETER', 'CASE', 'INCLUDE', 'KEYWORD', 'TITLE', 'COMMENT', 'DAMPING', &
      'INTEGRATION', 'USER', 'MODULE', 'END']
   integer, parameter :: PFAM(34) = [1, &
      1, 1, 2, 2, 2, &
      1, 3, 4, 5, 5, 5, 6, &
      7, 8, 8, 9, 9, 10, 10, 11, 12, &
      13, 14, 15, 16, 16, 16, 16, 17, &
      9, 18, 18, 16]

contains

   !> Index into FAMILIES of keyword name (upper case, no '*').
   pure integer function family_index(name) result(f)
      character(*), intent(in) :: name
      integer :: i, n
      do i = 1, size(PREFIX)
         n = len_trim(PREFIX(i))
         if (name == PREFIX(i)(1:n)) then
            f = PFAM(i); return
         end if
         if (len(name) > n) then
            if (name(1:n + 1) == PREFIX(i)(1:n)//'_') then
               f = PFAM(i); return
            end if
         end if
      end do
      f = 18
   end function family_index

   !> The family of keyword name: output, control, load, contact, material, ...
   function keyword_family(name) result(s)
      character(*), intent(in) :: name
      character(:), allocatable :: s
      s = trim(FAMILIES(family_index(name)))
   end function keyword_family

   !> Whether skipping keyword name cannot change the mechanics (output requests and
   !> performance controls only).
   pure logical function keyword_skippable(name)
      character(*), intent(in) :: name
      integer :: f
      f = family_index(name)
      keyword_skippable = f == 1 .or. f == 2
   end function keyword_skippable

   !> Count one finding of keyword key: what (the keyword, or a message without its place)
   !> at where; a repeat of (family, what) only counts. key = '' : 'output not written'.
   subroutine list_add(self, key, what, where)
      class(check_list_t), intent(inout) :: self
      character(*), intent(in) :: key, what, where
      type(finding_t), allocatable :: t(:)
      integer :: i, fam, nkey
      character(:), allocatable :: more
      if (len(key) == 0) then
         fam = NFAMILY
      else
         fam = family_index(key)
      end if
      if (.not. allocated(self%f)) allocate(self%f(16))
      more = list_more_line(key)
      nkey = 0
      do i = 1, self%n
         if (self%f(i)%family == fam .and. self%f(i)%what == what) then
            self%f(i)%count = self%f(i)%count + 1
            return
         end if
         if (self%f(i)%key == key) nkey = nkey + 1
      end do
      if (nkey >= MAX_PER_KEY .and. len(key) > 0) then
         do i = 1, self%n
            if (self%f(i)%family == fam .and. self%f(i)%what == more) then
               self%f(i)%count = self%f(i)%count + 1
               return
            end if
         end do
      end if
      if (self%n == size(self%f)) then
         allocate(t(2*self%n))
         t(1:self%n) = self%f(1:self%n)
         call move_alloc(t, self%f)
      end if
      self%n = self%n + 1
      if (nkey >= MAX_PER_KEY .and. len(key) > 0) then
         self%f(self%n) = finding_t(fam, more, where, 1, key)
      else
         self%f(self%n) = finding_t(fam, what, where, 1, key)
      end if
   end subroutine list_add

   !> The line that counts a keyword's findings past the first MAX_PER_KEY.
   function list_more_line(key) result(s)
      character(*), intent(in) :: key
      character(:), allocatable :: s
      s = '*'//key//': more findings past the first '//str(MAX_PER_KEY)//' (not listed)'
   end function list_more_line

   !> Findings that stop the run (everything but 'output not written').
   pure integer function list_nproblems(self) result(n)
      class(check_list_t), intent(in) :: self
      integer :: i
      n = 0
      do i = 1, self%n
         if (self%f(i)%family /= NFAMILY) n = n + 1
      end do
   end function list_nproblems

   !> The findings grouped by family: a heading per family, then one line per finding
   !> (what, first use, count).
   function list_report(self) result(s)
      class(check_list_t), intent(in) :: self
      character(:), allocatable :: s
      integer :: fam, i
      character(len=1), parameter :: nl = new_line('a')
      s = ''
      do fam = 1, NFAMILY
         if (.not. any(self%f(1:self%n)%family == fam)) cycle
         if (fam == NFAMILY) then
            s = s//nl//'  output not written (request accepted, no file; docs/keywords.md):'
         else
            s = s//nl//'  '//trim(FAMILIES(fam))//':'
         end if
         do i = 1, self%n
            if (self%f(i)%family /= fam) cycle
            s = s//nl//'    '//pad(self%f(i)%what, 34)//'  first at '//self%f(i)%where
            if (self%f(i)%count > 1) s = s//'  ('//str(self%f(i)%count)//' times)'
         end do
      end do
   contains
      function pad(t, n) result(p)
         character(*), intent(in) :: t
         integer, intent(in) :: n
         character(:), allocatable :: p
         ! a keyword of thousands of characters (a damaged line: one token, no blank) is
         ! named by its start; so is a message past 200 characters (a field's text echoed
         ! from a damaged line of 40 kB put 'first at' out of sight: fuzz case
         ! fuzz_check_long_value)
         if (len(t) > 100 .and. index(t(1:min(len(t), 100)), ' ') == 0) then
            p = t(1:80)//'... ('//str(len(t))//' characters)'
         else if (len(t) > 200) then
            p = t(1:160)//'... ('//str(len(t))//' characters)'
         else
            p = t
         end if
         if (len(p) < n) p = p//repeat(' ', n - len(p))
      end function pad
   end function list_report
end module dx_deck_check
