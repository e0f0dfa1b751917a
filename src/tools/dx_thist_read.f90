!> Reading any dynx ASCII time-history file into (time, entity id, column name, value)
!> records, and picking one column of one entity as a time series (dynx-thist, dynx-plot).
!>
!> Two layouts (docs/output-format.md):
!>  * column files (glstat, nodout, rcforc, rbdout, ...): '#' header lines, the names line
!>    the last of them with as many words as the first data line has fields (rbdout writes
!>    one '#' line per body after it) or one whose '[per body: ...]' group repeats to that
!>    count (old emcstat: entities 1, 2, ...), its words NAME@ID naming entity ID's column
!>    (emcstat); the names line may also lack the '#' (gnuplot's columnhead form); the time is the column named time (else the
!>    first); the column after it, when named '*_id' (node_id, contact_id, ...), body, node,
!>    part or id, is the entity id of the row, otherwise the entity is 0.
!>  * LS-DYNA block files (matsum, sleout, spcforc, ...): a line holding 'time =' starts a
!>    record; the other lines are 'label= value' pairs. The entity keys 'mat.#=',
!>    'interface=', 'node=', 'part=', 'id=' at the start of a line set the entity of that line
!>    and of the indented continuation lines after it; a line starting with 'summary' or
!>    'force resultants' belongs to entity 0 (the sum). A label followed by several numbers
!>    gives one column per number: 'local x,y,z forces = a b c' becomes x_forces, y_forces,
!>    z_forces, three numbers after another label give label_x, label_y, label_z, more
!>    label_1, label_2, ...; a leading 'summary' word is dropped; names are lower case with blanks as '_'.
!> Header lines before the first 'time =' (titles, part masses, legends) are skipped.
module dx_thist_read
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT, EXIT_IO
   use dx_strings, only: lower, str
   implicit none
   private
   public :: thist_table_t, thist_read, parse_column, NAME_LEN

   integer, parameter :: NAME_LEN = 48

   !> All values of one file, one record per (time, entity, column).
   type :: thist_table_t
      character(:), allocatable :: path
      character(:), allocatable :: title
      character(NAME_LEN), allocatable :: names(:)     !< the column names (no time, no id)
      integer :: nnames = 0
      integer :: nrec = 0
      real(wp), allocatable :: t(:), v(:)
      integer, allocatable :: ent(:), col(:)
   contains
      procedure :: column_index
      procedure :: select => table_select
      procedure :: entities
   end type thist_table_t

contains

   !> Read path into tab; error (exit 2 or 4) naming the file and line on bad input.
   subroutine thist_read(path, tab, error)
      character(*), intent(in) :: path
      type(thist_table_t), intent(out) :: tab
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios
      character(4096) :: buf
      logical :: block, there
      inquire(file=path, exist=there)
      if (.not. there) then
         call set_error(error, path//': no such file', EXIT_IO)
         return
      end if
      open(newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         call set_error(error, path//': cannot open', EXIT_IO)
         return
      end if
      tab%path = path
      tab%title = ''
      allocate(tab%names(16), tab%t(1024), tab%v(1024), tab%ent(1024), tab%col(1024))
      ! the layout: a '#' first line is a column file, anything else a block file
      read(u, '(a)', iostat=ios) buf
      if (ios /= 0) then
         call set_error(error, path//': empty file (no header)', EXIT_INPUT)
         close(u)
         return
      end if
      block = adjustl(buf(1:1)) /= '#'
      rewind(u)
      if (.not. block) then
         call read_columns(u, tab, path, error)
      else
         call read_blocks(u, tab, path, error)
      end if
      close(u)
      if (allocated(error)) return
      if (tab%nrec == 0) call set_error(error, path//': no data lines', EXIT_INPUT)
   end subroutine thist_read

   subroutine read_columns(u, tab, path, error)
      integer, intent(in) :: u
      type(thist_table_t), intent(inout) :: tab
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      character(4096) :: buf
      character(NAME_LEN), allocatable :: hdr(:), words(:)
      integer, allocatable :: cidx(:), cent(:)
      real(wp), allocatable :: vals(:)
      integer :: ios, lineno, nc, k, e, nfirst, tcol, icol
      character(:), allocatable :: header, line
      header = ''
      lineno = 0
      nc = 0
      do
         read(u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         lineno = lineno + 1
         if (len_trim(buf) == 0) cycle
         ! a header line: '#' ..., or (gnuplot's columnhead form, before the first data
         ! line) a line whose first word is not a number: the names without '#'
         if (adjustl(buf(1:1)) == '#' .or. buf(1:1) == '#' .or. &
             (nc == 0 .and. .not. starts_number(buf))) then
            line = trim(adjustl(buf(index(buf, '#') + 1:)))
            if (index(adjustl(buf), '#') /= 1) line = trim(adjustl(buf))
            if (index(line, 'title:') == 1) tab%title = trim(adjustl(line(7:)))
            ! the names line: the last '#' line with as many words as the data lines
            ! have fields (rbdout's per-body '#' lines come after its names line), or
            ! one with a '[per body: ...]' group that repeats to that count (emcstat)
            if (nc == 0) then
               nfirst = count_fields(next_data_line(u))
               call expand_names(line, nfirst, words, cent)
               if (size(words) == nfirst .and. nfirst >= 2) then
                  header = line
                  hdr = words
               end if
            end if
            cycle
         end if
         if (nc == 0) then
            if (len(header) == 0) then
               call set_error(error, path//':'//str(lineno)//': no # header line names '// &
                              'the '//str(count_fields(trim(buf)))//' columns of this line', &
                              EXIT_INPUT)
               return
            end if
            call expand_names(header, size(hdr), hdr, cent)
            nc = size(hdr)
            ! the time column (the first unless one is named time), the entity column (the
            ! one after it when its name is *_id, body, node, part or id)
            tcol = 1
            do k = 1, nc
               if (hdr(k) == 'time') then
                  tcol = k
                  exit
               end if
            end do
            icol = 0
            if (tcol < nc) then
               if (ends_with(hdr(tcol + 1), '_id') .or. hdr(tcol + 1) == 'body' .or. &
                   hdr(tcol + 1) == 'node' .or. hdr(tcol + 1) == 'part' .or. &
                   hdr(tcol + 1) == 'id') icol = tcol + 1
            end if
            allocate(cidx(nc), vals(nc))
            cidx = 0
            do k = 1, nc
               if (k /= tcol .and. k /= icol) cidx(k) = add_name(tab, hdr(k))
            end do
         end if
         read(buf, *, iostat=ios) vals
         if (ios /= 0) then
            call set_error(error, path//':'//str(lineno)//': expected '//str(nc)// &
                           ' numbers (columns '//trim(header)//')', EXIT_INPUT)
            return
         end if
         e = 0
         if (icol > 0) e = nint(vals(icol))
         do k = 1, nc
            if (cidx(k) == 0) cycle
            if (cent(k) > 0) then
               call add_rec(tab, vals(tcol), cent(k), cidx(k), vals(k))
            else
               call add_rec(tab, vals(tcol), e, cidx(k), vals(k))
            end if
         end do
      end do
   end subroutine read_columns

   subroutine read_blocks(u, tab, path, error)
      integer, intent(in) :: u
      type(thist_table_t), intent(inout) :: tab
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      character(4096) :: buf
      character(:), allocatable :: s, label, base
      character(NAME_LEN), allocatable :: words(:)
      real(wp) :: time, x
      integer :: ios, lineno, ent, k, j, nv, p, q
      logical :: intime, first_label
      real(wp), allocatable :: nums(:)
      intime = .false.
      ent = 0
      lineno = 0
      time = 0.0_wp
      allocate(nums(64))
      do
         read(u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         lineno = lineno + 1
         s = lower(trim(buf))
         if (len_trim(s) == 0) cycle
         p = index(s, 'time =')
         if (p == 0) p = index(s, 'time=')
         if (p > 0) then
            k = index(s(p:), '=') + p
            read(s(k:), *, iostat=ios) time
            if (ios /= 0) then
               call set_error(error, path//':'//str(lineno)//': no number after '// &
                              '"time ="', EXIT_INPUT)
               return
            end if
            intime = .true.
            ent = 0
            cycle
         end if
         if (.not. intime) then
            if (len_trim(tab%title) == 0) tab%title = trim(adjustl(buf))
            cycle
         end if
         ! tokens: '=' stands alone
         call split_words(spread_eq(s), words)
         if (words(1) == 'summary' .or. words(1) == 'force') ent = 0
         label = ''
         first_label = .true.
         k = 1
         if (words(1) == 'summary') k = 2
         do while (k <= size(words))
            if (words(k) == '=') then
               nv = 0
               j = k + 1
               do while (j <= size(words))
                  read(words(j), *, iostat=ios) x
                  if (ios /= 0 .or. .not. is_number(words(j))) exit
                  nv = nv + 1
                  nums(min(nv, size(nums))) = x
                  j = j + 1
               end do
               if (nv == 0 .or. len(label) == 0) then
                  call set_error(error, path//':'//str(lineno)//': "'//trim(buf)// &
                                 '": a label without a number', EXIT_INPUT)
                  return
               end if
               if (first_label .and. is_entity_key(label) .and. nv == 1) then
                  ent = nint(nums(1))
               else if (nv == 1) then
                  call add_rec(tab, time, ent, add_name(tab, label), nums(1))
               else
                  base = label
                  do p = 1, min(nv, size(nums))
                     q = index(base, 'x,y,z')
                     if (q > 0) then
                        call add_rec(tab, time, ent, add_name(tab, base(1:q - 1)// &
                                     'xyz'(p:p)//base(q + 5:)), nums(p))
                     else if (nv == 3) then
                        call add_rec(tab, time, ent, add_name(tab, base//'_'//'xyz'(p:p)), &
                                     nums(p))
                     else
                        call add_rec(tab, time, ent, add_name(tab, base//'_'//str(p)), &
                                     nums(p))
                     end if
                  end do
               end if
               first_label = .false.
               label = ''
               k = j
            else
               if (is_number(words(k)) .and. len(label) == 0) then
                  k = k + 1          ! a stray number (setid 0 after the forces): skipped
                  cycle
               end if
               if (len(label) > 0) then
                  label = label//'_'//trim(words(k))
               else
                  label = trim(words(k))
               end if
               k = k + 1
            end if
         end do
         ! trailing words without '=' (setid 0 of spcforc) carry no column
      end do
   end subroutine read_blocks

   !> The column names of a header line and each column's entity (0: the row's own). A
   !> group '[per body: a b c (note)]' after the plain names repeats a, b, c once per body
   !> (entities 1, 2, ...) to fill nfields columns (emcstat before 2026-12-07); a word
   !> NAME@ID is column NAME of entity ID (emcstat now); otherwise the words as they are.
   subroutine expand_names(line, nfields, names, ent)
      character(*), intent(in) :: line
      integer, intent(in) :: nfields
      character(NAME_LEN), allocatable, intent(out) :: names(:)
      integer, allocatable, intent(out) :: ent(:)
      character(NAME_LEN), allocatable :: base(:), per(:)
      integer :: p, q, r, nb, b, k
      p = index(line, '[per body:')
      if (p == 0) then
         call split_words(line, names)
         allocate(ent(size(names)))
         ent = 0
         do k = 1, size(names)            ! NAME@ID: the column of entity ID (emcstat)
            q = index(names(k), '@', back=.true.)
            if (q < 2) cycle
            read(names(k)(q + 1:), *, iostat=r) b
            if (r /= 0 .or. verify(trim(names(k)(q + 1:)), '0123456789') /= 0) cycle
            ent(k) = b
            names(k) = names(k)(1:q - 1)
         end do
         return
      end if
      call split_words(line(1:p - 1), base)
      q = index(line(p:), ']') + p - 1
      if (q < p) q = len(line) + 1
      r = index(line(p:q - 1), '(')
      if (r > 0) then
         call split_words(line(p + 10:p + r - 2), per)
      else
         call split_words(line(p + 10:q - 1), per)
      end if
      nb = 0
      if (size(per) > 0) nb = (nfields - size(base))/size(per)
      if (size(per) == 0 .or. nb < 1 .or. size(base) + nb*size(per) /= nfields) then
         call split_words(line, names)        ! no fit: the plain words (they will not match)
         allocate(ent(size(names)))
         ent = 0
         return
      end if
      allocate(names(nfields), ent(nfields))
      names(1:size(base)) = base
      ent(1:size(base)) = 0
      k = size(base)
      do b = 1, nb
         names(k + 1:k + size(per)) = per
         ent(k + 1:k + size(per)) = b
         k = k + size(per)
      end do
   end subroutine expand_names

   !> A column as the tools name it: NAME or NAME@ID (id -1: none given); a bad id is an
   !> error (exit 2).
   subroutine parse_column(spec, name, id, error)
      character(*), intent(in) :: spec
      character(:), allocatable, intent(out) :: name
      integer, intent(out) :: id
      type(error_t), allocatable, intent(out) :: error
      integer :: p, st
      p = index(spec, '@')
      id = -1
      if (p == 0) then
         name = trim(spec)
         return
      end if
      name = trim(spec(1:p - 1))
      read(spec(p + 1:), *, iostat=st) id
      if (st /= 0 .or. id < 0) call set_error(error, 'column '//trim(spec)// &
                                              ': the id after @ is not an integer >= 0', EXIT_INPUT)
   end subroutine parse_column

   !> The next line of u that is not blank and not a '#' line ('' at the end), the file
   !> position left where it was.
   function next_data_line(u) result(l)
      integer, intent(in) :: u
      character(:), allocatable :: l
      character(4096) :: buf
      integer :: ios, nread, k
      l = ''
      nread = 0
      do
         read(u, '(a)', iostat=ios) buf
         if (ios /= 0) exit
         nread = nread + 1
         if (len_trim(buf) == 0) cycle
         if (adjustl(buf(1:1)) == '#' .or. buf(1:1) == '#') cycle
         l = trim(buf)
         exit
      end do
      do k = 1, nread
         backspace(u)
      end do
   end function next_data_line

   !> The number of blank-separated fields of s.
   integer function count_fields(s) result(n)
      character(*), intent(in) :: s
      character(NAME_LEN), allocatable :: w(:)
      call split_words(s, w)
      n = size(w)
   end function count_fields

   logical function is_entity_key(label)
      character(*), intent(in) :: label
      is_entity_key = label == 'mat.#' .or. label == 'interface' .or. label == 'node' .or. &
                      label == 'part' .or. label == 'id'
   end function is_entity_key

   logical function is_number(w)
      character(*), intent(in) :: w
      character(1) :: c
      c = adjustl(w)
      is_number = verify(c, '0123456789+-.') == 0 .and. verify(trim(w), '0123456789+-.eE') == 0
   end function is_number

   logical function ends_with(s, tail)
      character(*), intent(in) :: s, tail
      integer :: n
      n = len_trim(s)
      ends_with = n >= len(tail)
      if (ends_with) ends_with = s(n - len(tail) + 1:n) == tail
   end function ends_with

   !> s with blanks around every '='.
   function spread_eq(s) result(r)
      character(*), intent(in) :: s
      character(:), allocatable :: r
      integer :: k
      r = ''
      do k = 1, len(s)
         if (s(k:k) == '=') then
            r = r//' = '
         else
            r = r//s(k:k)
         end if
      end do
   end function spread_eq

   !> The blank-separated words of s.
   subroutine split_words(s, w)
      character(*), intent(in) :: s
      character(NAME_LEN), allocatable, intent(out) :: w(:)
      integer :: k, n, i0
      logical :: inw
      n = 0
      inw = .false.
      do k = 1, len(s)
         if (s(k:k) /= ' ' .and. .not. inw) n = n + 1
         inw = s(k:k) /= ' '
      end do
      allocate(w(n))
      n = 0
      inw = .false.
      i0 = 1
      do k = 1, len(s) + 1
         if (k <= len(s)) then
            if (s(k:k) /= ' ') then
               if (.not. inw) i0 = k
               inw = .true.
               cycle
            end if
         end if
         if (inw) then
            n = n + 1
            w(n) = s(i0:k - 1)
         end if
         inw = .false.
      end do
   end subroutine split_words

   !> The index of name in tab%names (added when new).
   integer function add_name(tab, name) result(k)
      type(thist_table_t), intent(inout) :: tab
      character(*), intent(in) :: name
      character(NAME_LEN), allocatable :: tmp(:)
      do k = 1, tab%nnames
         if (tab%names(k) == name) return
      end do
      if (tab%nnames == size(tab%names)) then
         allocate(tmp(2*size(tab%names)))
         tmp(1:tab%nnames) = tab%names(1:tab%nnames)
         call move_alloc(tmp, tab%names)
      end if
      tab%nnames = tab%nnames + 1
      k = tab%nnames
      tab%names(k) = name
   end function add_name

   subroutine add_rec(tab, t, e, c, v)
      type(thist_table_t), intent(inout) :: tab
      real(wp), intent(in) :: t, v
      integer, intent(in) :: e, c
      real(wp), allocatable :: rt(:)
      integer, allocatable :: it(:)
      integer :: n
      n = tab%nrec
      if (n == size(tab%t)) then
         allocate(rt(2*n)); rt(1:n) = tab%t; call move_alloc(rt, tab%t)
         allocate(rt(2*n)); rt(1:n) = tab%v; call move_alloc(rt, tab%v)
         allocate(it(2*n)); it(1:n) = tab%ent; call move_alloc(it, tab%ent)
         allocate(it(2*n)); it(1:n) = tab%col; call move_alloc(it, tab%col)
      end if
      n = n + 1
      tab%t(n) = t
      tab%v(n) = v
      tab%ent(n) = e
      tab%col(n) = c
      tab%nrec = n
   end subroutine add_rec

   !> The index of a column name (0 when absent).
   integer function column_index(self, name) result(k)
      class(thist_table_t), intent(in) :: self
      character(*), intent(in) :: name
      do k = 1, self%nnames
         if (self%names(k) == lower(name)) return
      end do
      k = 0
   end function column_index

   !> The distinct entity ids that have column c, in order of appearance.
   function entities(self, c) result(ids)
      class(thist_table_t), intent(in) :: self
      integer, intent(in) :: c
      integer, allocatable :: ids(:)
      integer :: i
      allocate(ids(0))
      do i = 1, self%nrec
         if (self%col(i) /= c) cycle
         if (any(ids == self%ent(i))) cycle
         ids = [ids, self%ent(i)]
      end do
   end function entities

   !> The series (t, x) of column name for entity id (id < 0: the only entity there is).
   !> A time equal to the one before (a restart writing the same time again) replaces it.
   subroutine table_select(self, name, id, t, x, error)
      class(thist_table_t), intent(in) :: self
      character(*), intent(in) :: name
      integer, intent(in) :: id
      real(wp), allocatable, intent(out) :: t(:), x(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: c, e, i, n
      integer, allocatable :: ids(:)
      character(:), allocatable :: list
      c = self%column_index(name)
      if (c == 0) then
         list = ''
         do i = 1, self%nnames
            list = list//' '//trim(self%names(i))
         end do
         call set_error(error, self%path//': no column "'//name//'" (columns:'//list//')', &
                        EXIT_INPUT)
         return
      end if
      ids = self%entities(c)
      e = id
      if (id < 0) then
         if (size(ids) > 1) then
            list = ''
            do i = 1, min(size(ids), 20)
               list = list//' '//str(ids(i))
            end do
            call set_error(error, self%path//': column "'//name//'" has '// &
                           str(size(ids))//' entities; name one as '//name// &
                           '@ID (ids:'//list//')', EXIT_INPUT)
            return
         end if
         e = ids(1)
      else if (.not. any(ids == id)) then
         call set_error(error, self%path//': column "'//name//'" has no entity '// &
                        str(id), EXIT_INPUT)
         return
      end if
      allocate(t(self%nrec), x(self%nrec))
      n = 0
      do i = 1, self%nrec
         if (self%col(i) /= c .or. self%ent(i) /= e) cycle
         if (n > 0) then
            if (self%t(i) == t(n)) then
               x(n) = self%v(i)
               cycle
            end if
         end if
         n = n + 1
         t(n) = self%t(i)
         x(n) = self%v(i)
      end do
      t = t(1:n)
      x = x(1:n)
   end subroutine table_select
   !> whether the line's first non-blank character can start a number
   pure logical function starts_number(buf)
      character(*), intent(in) :: buf
      character(:), allocatable :: w
      w = adjustl(buf)
      starts_number = .false.
      if (len_trim(w) > 0) starts_number = index('+-.0123456789', w(1:1)) > 0
   end function starts_number
end module dx_thist_read
