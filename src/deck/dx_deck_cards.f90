!> LS-DYNA keyword deck tokenizer and field reader.
!> Reads a deck (and its *INCLUDE files) into keyword blocks: keyword name, format (standard
!> 10-column or long 20-column fields), and the data cards with their file and line. Handles
!> '$' comments, *KEYWORD [LONG=Y|S] (other tokens such as a memory size or NCPU=
!> ignored), *END, the '+'/'-' keyword suffixes, *INCLUDE (paths relative to the including
!> file, then the *INCLUDE_PATH / *INCLUDE_PATH_RELATIVE directories; depth limit 20; an
!> *INCLUDE whose name lines are all comments is skipped), *TITLE, *PARAMETER (R/I/C, 4 pairs per
!> card) and '&name' / '-&name' references, and comma-separated free format.
!> Reference: LS-DYNA Keyword User's Manual, Vol. I, "General card format" and *KEYWORD,
!> *INCLUDE, *PARAMETER. Fields and messages: dx_card (file:line:col, the card and a caret).
module dx_deck_cards
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, MAX_MORE
   use dx_strings, only: upper, str, rstr
   use dx_model_input, only: string_t
   use dx_io_sys, only: sys_file_kind
   use dx_log, only: log_warn
   use dx_deck_expr, only: eval_expression
   use dx_card_echo, only: echo_t
   use dx_deck_subcase, only: case_tag, next_token
   use dx_param_dup, only: read_dflag, redefine_param
   use dx_card, only: card_line_t, block_t, param_t, card_t, open_card, std_widths, data_start, &
                      block_title, ncards, card_is_blank, field_text, find_param, field_int, &
                      field_real, field_str, error_at_field, error_at_card, error_at_block, &
                      where_card, max_cards_check
   implicit none
   private
   public :: card_t, block_t, deck_t, param_t, read_cards, get_int, get_list_id, get_real, get_text, &
             field_error, block_error, card_error, std_widths, ncards, card_where, &
             card_is_blank, check_max_cards, MAX_INCLUDE_DEPTH, data_start, block_title, &
             deck_cursor, collect_error, include_path

   integer, parameter :: MAX_INCLUDE_DEPTH = 20

   type :: deck_t
      type(string_t), allocatable :: files(:)
      integer :: nfiles = 0
      type(block_t), allocatable :: blocks(:)
      integer :: nblocks = 0
      type(param_t), allocatable :: params(:)
      integer :: nparams = 0
      character(:), allocatable :: title
      logical :: long = .false.             !< *KEYWORD LONG=Y seen
      logical :: check = .false.            !< --check: card cursors collect every error
      !> blank cards stripped from the end of each block (a blank line may stand for a
      !> card of defaults: dx_deck gives one back when a block has no data card else)
      integer, allocatable :: trailing(:)
      type(string_t), allocatable :: paths(:)   !< *INCLUDE_PATH(_RELATIVE) directories
      type(echo_t), pointer :: echo => null()   !< the d3hsp echo the cursors write (null: none)
      !> *CASE: the subcase of the *CASE_BEGIN_n ... *CASE_END_n the reading is in (0: none),
      !> where it began, whether any block belongs to a subcase, and the subcases of the
      !> selected case (allocated: a case is selected; blocks of other subcases are dropped)
      integer :: cur_scid = 0, scid_file = 0, scid_line = 0
      logical :: has_subcases = .false.
      integer, allocatable :: active(:)
      !> *PARAMETER_DUPLICATION DFLAG for the definitions after it (0: no such keyword seen,
      !> a redefinition replaces silently as before)
      integer :: dflag = 0
   end type deck_t

contains

   !> Read the deck file path and its includes into deck. active: the subcases (*CASE SCIDs)
   !> of the case being read; the blocks between *CASE_BEGIN_n and *CASE_END_n (or with
   !> CID=n on their keyword line) of any other subcase n are dropped, includes and
   !> parameters too. Without active every block is kept with its subcase (block_t%scid).
   subroutine read_cards(path, deck, error, active)
      character(*), intent(in) :: path
      type(deck_t), intent(out) :: deck
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: active(:)
      allocate(deck%files(4), deck%blocks(64), deck%params(8), deck%trailing(64), deck%paths(0))
      if (present(active)) deck%active = active
      call read_file(path, deck, 0, 0, 0, error)
      if (allocated(error)) return
      if (deck%cur_scid /= 0) call set_error(error, deck%files(deck%scid_file)%s//':'// &
         str(deck%scid_line)//': *CASE_BEGIN_'//str(deck%cur_scid)//' has no *CASE_END_'// &
         str(deck%cur_scid))
   end subroutine read_cards

   recursive subroutine read_file(path, deck, depth, from_file, from_line, error)
      character(*), intent(in) :: path
      type(deck_t), intent(inout) :: deck
      integer, intent(in) :: depth, from_file, from_line
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, ifile, lineno
      character(:), allocatable :: line, kind
      type(block_t) :: blk
      logical :: have_block, eof

      kind = sys_file_kind(path)    ! a FIFO or /dev/zero would never end, a directory is no deck
      if (kind /= 'regular' .and. kind /= 'missing') then
         if (from_file == 0) then
            call set_error(error, path//': the deck is a '//kind//', not a regular file')
         else
            call set_error(error, deck%files(from_file)%s//':'//str(from_line)// &
               ': *INCLUDE: '''//path//''' is a '//kind//', not a regular file')
         end if
         return
      end if
      open(newunit=u, file=path, status='old', action='read', form='formatted', iostat=ios)
      if (ios /= 0) then
         if (from_file == 0) then
            call set_error(error, path//': cannot open the deck file')
         else
            call set_error(error, deck%files(from_file)%s//':'//str(from_line)// &
               ': *INCLUDE: cannot open file '''//path//'''')
         end if
         return
      end if
      if (deck%nfiles == size(deck%files)) call grow_files(deck)
      deck%nfiles = deck%nfiles + 1
      ifile = deck%nfiles
      deck%files(ifile)%s = path
      lineno = 0
      have_block = .false.
      do
         call read_line(u, line, eof)
         if (eof) exit
         lineno = lineno + 1
         if (len(line) > 0) then
            if (line(1:1) == '$') cycle
         end if
         if (len(line) > 0) then
            if (line(1:1) == '*') then
               if (have_block) then
                  call finish_block(deck, blk, depth, error)
                  if (allocated(error)) exit
                  have_block = .false.
               end if
               call start_block(deck, line, ifile, lineno, blk, have_block, error)
               if (allocated(error)) exit
               if (blk%name == 'END') then
                  have_block = .false.
                  exit
               end if
               cycle
            end if
         end if
         if (.not. have_block) then
            if (len_trim(line) > 0) then
               call set_error(error, path//':'//str(lineno)//': data card before any keyword')
               exit
            end if
            cycle
         end if
         call add_card(blk, line, lineno)
      end do
      close(u)
      if (allocated(error)) return
      if (have_block) call finish_block(deck, blk, depth, error)
   end subroutine read_file

   !> Read one line of any length; strip a trailing CR (DOS files) and expand tabs.
   !> The line grows by doubling: linear in its length (a 2 MB line took 10 s before).
   subroutine read_line(u, line, eof)
      integer, intent(in) :: u
      character(:), allocatable, intent(out) :: line
      logical, intent(out) :: eof
      character(256) :: buf
      character(:), allocatable :: acc, grown
      integer :: ios, sz, i, n
      allocate(character(256) :: acc)
      n = 0
      eof = .false.
      do
         read(u, '(a)', advance='no', iostat=ios, size=sz) buf
         if (n + sz > len(acc)) then
            allocate(character(2*len(acc) + sz) :: grown)
            grown(1:n) = acc(1:n)
            call move_alloc(grown, acc)
         end if
         acc(n + 1:n + sz) = buf(1:sz)
         n = n + sz
         if (is_iostat_eor(ios)) exit
         if (is_iostat_end(ios)) then
            eof = n == 0
            exit
         end if
         if (ios /= 0) then
            eof = .true.
            exit
         end if
      end do
      if (n > 0) then
         if (acc(n:n) == achar(13)) n = n - 1
      end if
      line = acc(1:n)
      do i = 1, n
         if (line(i:i) == achar(9)) line(i:i) = ' '
      end do
   end subroutine read_line

   subroutine start_block(deck, line, ifile, lineno, blk, have_block, error)
      type(deck_t), intent(inout) :: deck
      character(*), intent(in) :: line
      integer, intent(in) :: ifile, lineno
      type(block_t), intent(out) :: blk
      logical, intent(out) :: have_block
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: rest, tok, name
      integer :: k
      character :: suffix
      have_block = .false.
      rest = upper(trim(adjustl(line(2:))))
      call next_token(rest, name)
      suffix = ' '
      k = len(name)
      if (k > 1) then
         if (name(k:k) == '+' .or. name(k:k) == '-' .or. name(k:k) == '%') then
            suffix = name(k:k)
            name = name(1:k-1)
         end if
      end if
      if (name == 'KEYWORD') then
         do
            call next_token(rest, tok)
            if (len(tok) == 0) exit
            if (tok == 'LONG=Y' .or. tok == 'LONG=S') deck%long = .true.
         end do
         blk%name = name
         return
      end if
      call next_token(rest, tok)
      if (len(tok) > 0) then
         if (tok == '+' .or. tok == '-' .or. tok == '%') suffix = tok(1:1)
      end if
      if (suffix == '%') then
         call set_error(error, deck%files(ifile)%s//':'//str(lineno)//': *'//name// &
            ': the I10 format (''%'' suffix) is not supported')
         return
      end if
      if (index(name, 'CASE_BEGIN_') == 1 .or. index(name, 'CASE_END_') == 1) then
         call case_tag(deck%files, name, ifile, lineno, deck%cur_scid, deck%scid_file, &
                       deck%scid_line, error)
         if (deck%cur_scid /= 0) deck%has_subcases = .true.
         blk%name = 'CASE_TAG'         ! no block: the tag only opens or closes a subcase
         return
      end if
      blk%scid = deck%cur_scid
      do while (len(tok) > 0)       ! CID=n: this keyword belongs to subcase n only
         if (len(tok) > 4) then
            if (tok(1:4) == 'CID=') then
               read(tok(5:), *, iostat=k) blk%scid
               if (k /= 0 .or. blk%scid <= 0 .or. verify(tok(5:), '0123456789') /= 0) then
                  call set_error(error, deck%files(ifile)%s//':'//str(lineno)//': *'//name// &
                     ': CID= needs a positive subcase number (*CASE_BEGIN_n), got '//tok(5:))
                  return
               end if
            end if
         end if
         call next_token(rest, tok)
      end do
      if (blk%scid /= 0) deck%has_subcases = .true.
      blk%name = name
      blk%ifile = ifile
      blk%line = lineno
      blk%long = deck%long
      if (suffix == '+') blk%long = .true.
      if (suffix == '-') blk%long = .false.
      allocate(blk%cards(8))
      blk%n = 0
      have_block = name /= 'END'
   end subroutine start_block

   !> Append a card; the card list grows by doubling while the block is read (linear time)
   !> and is cut to its exact size when the block is kept (finish_block: resize_cards).
   subroutine add_card(blk, line, lineno)
      type(block_t), intent(inout) :: blk
      character(*), intent(in) :: line
      integer, intent(in) :: lineno
      if (blk%n == size(blk%cards)) call resize_cards(blk, 2*size(blk%cards))
      blk%n = blk%n + 1
      blk%cards(blk%n)%text = line
      blk%cards(blk%n)%line = lineno
   end subroutine add_card

   !> Give blk's card list room for m cards, keeping the first m stored (texts moved, not copied).
   subroutine resize_cards(blk, m)
      type(block_t), intent(inout) :: blk
      integer, intent(in) :: m
      type(card_line_t), allocatable :: t(:)
      integer :: i
      allocate(t(m))
      do i = 1, min(size(blk%cards), m)     ! cards past blk%n: stripped blanks, if stored
         if (allocated(blk%cards(i)%text)) call move_alloc(blk%cards(i)%text, t(i)%text)
         t(i)%line = blk%cards(i)%line
      end do
      call move_alloc(t, blk%cards)
   end subroutine resize_cards

   !> A finished block: handle *TITLE, *INCLUDE, *PARAMETER here, keep the others.
   recursive subroutine finish_block(deck, blk, depth, error)
      type(deck_t), intent(inout) :: deck
      type(block_t), intent(inout) :: blk
      integer, intent(in) :: depth
      type(error_t), allocatable, intent(out) :: error
      integer :: i, nblank
      character(:), allocatable :: fname
      if (blk%name == 'CASE_TAG') return
      if (blk%scid /= 0 .and. allocated(deck%active)) then
         if (.not. any(deck%active == blk%scid)) return     ! another case's keyword
      end if
      ! trailing blank cards are layout, not data (but see deck%trailing)
      nblank = 0
      do while (blk%n > 0)
         if (len_trim(blk%cards(blk%n)%text) > 0) exit
         blk%n = blk%n - 1
         nblank = nblank + 1
      end do
      select case (blk%name)
      case ('TITLE')
         if (blk%n >= 1) deck%title = trim(blk%cards(1)%text(1:min(80, len(blk%cards(1)%text))))
      case ('INCLUDE_PATH', 'INCLUDE_PATH_RELATIVE')
         ! directories searched for *INCLUDE files not found next to the including file;
         ! _RELATIVE: relative to the directory of the input deck (LS-DYNA manual)
         do i = 1, blk%n
            fname = trim(adjustl(blk%cards(i)%text))
            if (len(fname) == 0) cycle
            if (blk%name == 'INCLUDE_PATH_RELATIVE') fname = resolve_path(deck%files(1)%s, fname)
            deck%paths = [deck%paths, string_t(fname)]
         end do
      case ('INCLUDE')
         ! an *INCLUDE whose file-name lines are all comments (or blank) names no file:
         ! LS-DYNA skips it
         if (blk%n == 0) return
         i = 0
         do while (i < blk%n)
            i = i + 1
            fname = trim(adjustl(blk%cards(i)%text))
            ! a path longer than one card continues on the next when it ends in ' +'
            do while (ends_with_plus(fname) .and. i < blk%n)
               i = i + 1
               fname = fname(1:len(fname)-2)//trim(adjustl(blk%cards(i)%text))
            end do
            if (len(fname) == 0) cycle
            if (depth + 1 > MAX_INCLUDE_DEPTH) then
               call set_error(error, deck%files(blk%ifile)%s//':'//str(blk%cards(i)%line)// &
                  ': *INCLUDE: include depth exceeds '//str(MAX_INCLUDE_DEPTH)// &
                  ' (does a file include itself?)')
               return
            end if
            call read_file(include_path(deck, deck%files(blk%ifile)%s, fname), deck, &
                           depth + 1, blk%ifile, blk%cards(i)%line, error)
            if (allocated(error)) return
         end do
      case ('PARAMETER')
         call read_parameters(deck, blk, error)
      case ('PARAMETER_EXPRESSION')
         call read_parameter_expressions(deck, blk, error)
      case ('PARAMETER_DUPLICATION')
         call read_dflag(deck%files(blk%ifile)%s, deck%params(1:deck%nparams), blk, &
                         deck%dflag, error)
      case default
         ! kept until the deck is read: exact size, not the doubling's up to 2x slots; the
         ! stripped blank cards stay stored (dx_deck gives them back as cards of defaults)
         if (blk%n + nblank < size(blk%cards)) call resize_cards(blk, blk%n + nblank)
         if (deck%nblocks == size(deck%blocks)) call grow_blocks(deck)
         deck%nblocks = deck%nblocks + 1
         call move_block(blk, deck%blocks(deck%nblocks))
         deck%trailing(deck%nblocks) = nblank
      end select
   end subroutine finish_block

   pure logical function ends_with_plus(s)
      character(*), intent(in) :: s
      integer :: n
      n = len(s)
      ends_with_plus = .false.
      if (n >= 2) ends_with_plus = s(n-1:n) == ' +'
   end function ends_with_plus

   !> The file an *INCLUDE names: next to the including file (or absolute); if no such file
   !> exists, the first *INCLUDE_PATH directory that holds it; else the first guess (whose
   !> open error names it).
   function include_path(deck, parent, name) result(p)
      type(deck_t), intent(in) :: deck
      character(*), intent(in) :: parent, name
      character(:), allocatable :: p, q
      logical :: there
      integer :: i
      p = resolve_path(parent, name)
      if (name(1:1) == '/') return
      inquire(file=p, exist=there)
      if (there) return
      do i = 1, size(deck%paths)
         q = deck%paths(i)%s
         if (q(len(q):len(q)) /= '/') q = q//'/'
         inquire(file=q//name, exist=there)
         if (there) then
            p = q//name
            return
         end if
      end do
   end function include_path

   !> name relative to the directory of the including file, unless absolute
   pure function resolve_path(parent, name) result(p)
      character(*), intent(in) :: parent, name
      character(:), allocatable :: p
      integer :: k
      if (name(1:1) == '/') then
         p = name
         return
      end if
      k = index(parent, '/', back=.true.)
      p = parent(1:k)//name
   end function resolve_path

   subroutine move_block(a, b)
      type(block_t), intent(inout) :: a
      type(block_t), intent(out) :: b
      call move_alloc(a%name, b%name)
      b%long = a%long
      b%ifile = a%ifile
      b%line = a%line
      b%n = a%n
      b%scid = a%scid
      call move_alloc(a%cards, b%cards)
   end subroutine move_block

   subroutine grow_blocks(deck)
      type(deck_t), intent(inout) :: deck
      type(block_t), allocatable :: t(:)
      integer, allocatable :: tr(:)
      integer :: i
      allocate(t(2*size(deck%blocks)), tr(2*size(deck%blocks)))
      do i = 1, deck%nblocks
         call move_block(deck%blocks(i), t(i))
      end do
      tr(1:deck%nblocks) = deck%trailing(1:deck%nblocks)
      call move_alloc(t, deck%blocks)
      call move_alloc(tr, deck%trailing)
   end subroutine grow_blocks

   subroutine grow_files(deck)
      type(deck_t), intent(inout) :: deck
      type(string_t), allocatable :: t(:)
      integer :: i
      allocate(t(2*size(deck%files)))
      do i = 1, deck%nfiles
         call move_alloc(deck%files(i)%s, t(i)%s)
      end do
      call move_alloc(t, deck%files)
   end subroutine grow_files

   !> *PARAMETER: pairs (PRMRn, VALn), 4 per card; PRMR = type letter R/I/C + name.
   subroutine read_parameters(deck, blk, error)
      type(deck_t), intent(inout) :: deck
      type(block_t), intent(in) :: blk
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k, col, w(8)
      character(:), allocatable :: ptxt, vtxt, name, note
      character :: kind
      type(param_t) :: p
      real(wp) :: v
      logical :: bad
      w = std_widths(blk, 8)
      do ic = 1, blk%n
         do k = 1, 7, 2
            call field_text(blk, ic, k, w, ptxt, col)
            ptxt = trim(adjustl(ptxt))
            if (len(ptxt) == 0) cycle
            kind = upper(ptxt(1:1))
            name = upper(trim(adjustl(ptxt(2:))))
            if (index('RIC', kind) == 0 .or. len(name) == 0) then
               call field_error(deck, blk, ic, k, w, 'PRMR'//str((k+1)/2), &
                  'expected R, I or C followed by the parameter name, got '''//ptxt//'''', error)
               return
            end if
            p%name = name
            p%kind = kind
            if (kind == 'C') then
               call field_text(blk, ic, k + 1, w, vtxt, col)
               p%text = trim(adjustl(vtxt))
               p%value = 0.0_wp
            else
               call get_real(deck, blk, ic, k + 1, w, 'VAL'//str((k+1)/2), 0.0_wp, v, error)
               if (allocated(error)) return
               if (kind == 'I') then
                  if (v /= anint(v)) then
                     call field_error(deck, blk, ic, k + 1, w, 'VAL'//str((k+1)/2), &
                        'integer parameter '//name//' has value '//rstr(v), error)
                     return
                  end if
               end if
               p%value = v
               p%text = ''
            end if
            call add_param(deck, p, note, bad)
            if (bad) then
               call field_error(deck, blk, ic, k, w, 'PRMR'//str((k+1)/2), note, error)
               return
            end if
            if (len(note) > 0) call log_warn(card_where(deck, blk, ic)//': *'//blk%name// &
                                             ': field PRMR'//str((k+1)/2)//': '//note)
         end do
      end do
   end subroutine read_parameters

   !> Define parameter p. A redefinition follows the *PARAMETER_DUPLICATION DFLAG in force
   !> (dx_param_dup). note: the warning text (bad: the error text), else ''.
   subroutine add_param(deck, p, note, bad)
      type(deck_t), intent(inout) :: deck
      type(param_t), intent(in) :: p
      character(:), allocatable, intent(out) :: note
      logical, intent(out) :: bad
      type(param_t), allocatable :: t(:)
      integer :: j
      logical :: replace
      note = ''
      bad = .false.
      j = find_param(deck%params(1:deck%nparams), p%name)
      if (j > 0) then
         call redefine_param(deck%dflag, p%name, replace, note, bad)
         if (replace) deck%params(j) = p
      else
         if (deck%nparams == size(deck%params)) then
            allocate(t(2*size(deck%params)))
            t(1:deck%nparams) = deck%params(1:deck%nparams)
            call move_alloc(t, deck%params)
         end if
         deck%nparams = deck%nparams + 1
         deck%params(deck%nparams) = p
      end if
   end subroutine add_param

   !> *PARAMETER_EXPRESSION: one parameter per card, PRMR (columns 1-10: type R or I, then
   !> the name; 20 in long format) and EXPRESSION (the rest of the card, dx_deck_expr) in
   !> the parameters defined before it. A card whose PRMR field holds a comma is free
   !> format: PRMR up to the first comma, the expression after it.
   subroutine read_parameter_expressions(deck, blk, error)
      type(deck_t), intent(inout) :: deck
      type(block_t), intent(in) :: blk
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, w, k
      character(:), allocatable :: line, ptxt, etxt, msg, note
      character :: kind
      type(param_t) :: p
      real(wp) :: v
      logical :: bad
      w = 10
      if (blk%long) w = 20
      do ic = 1, blk%n
         line = blk%cards(ic)%text
         if (len_trim(line) == 0) cycle
         k = index(line(1:min(w, len(line))), ',')
         if (k > 0) then
            ptxt = line(1:k - 1)
            etxt = line(k + 1:)
         else
            ptxt = line(1:min(w, len(line)))
            etxt = ''
            if (len(line) > w) etxt = line(w + 1:)
         end if
         ptxt = trim(adjustl(ptxt))
         kind = ' '
         if (len(ptxt) > 0) kind = upper(ptxt(1:1))
         p%name = ''
         if (len(ptxt) > 1) p%name = upper(trim(adjustl(ptxt(2:))))
         if (index('RI', kind) == 0 .or. len(p%name) == 0) then
            call card_error(deck, blk, ic, 'field PRMR: expected R or I followed by the '// &
                            'parameter name, got '''//ptxt//'''', error)
            return
         end if
         call eval_expression(etxt, deck%params(1:deck%nparams), v, msg)
         if (len(msg) > 0) then
            call card_error(deck, blk, ic, 'field EXPRESSION of '//p%name//': '//msg, error)
            return
         end if
         if (kind == 'I') v = aint(v)   ! evaluated in floating point, then truncated
         p%kind = kind
         p%value = v
         p%text = ''
         call add_param(deck, p, note, bad)
         if (bad) then
            call card_error(deck, blk, ic, 'field PRMR: '//note, error)
            return
         end if
         if (len(note) > 0) call log_warn(card_where(deck, blk, ic)//': *'//blk%name// &
                                          ': field PRMR: '//note)
      end do
   end subroutine read_parameter_expressions

   ! ----------------------------------------------------------------------------------------
   ! the deck's view of the dx_card field readers: the file name and *PARAMETER table of deck

   !> Keep error e of a card: the first of the block in first, a later one (--check
   !> lists every bad card) as one more line of first%more (its first line).
   subroutine collect_error(first, e)
      type(error_t), allocatable, intent(inout) :: first, e
      integer :: k
      if (.not. allocated(e)) return
      if (.not. allocated(first)) then
         call move_alloc(e, first)
         return
      end if
      if (first%nmore >= MAX_MORE) then
         first%ndrop = first%ndrop + 1
         deallocate(e)
         return
      end if
      first%nmore = first%nmore + 1
      k = index(e%message, new_line('a'))
      if (k == 0) k = len(e%message) + 1
      if (allocated(first%more)) then
         first%more = first%more//new_line('a')//e%message(1:k - 1)
      else
         first%more = e%message(1:k - 1)
      end if
      deallocate(e)
   end subroutine collect_error

   !> A card cursor on the data cards of blk (dx_card).
   subroutine deck_cursor(deck, blk, c)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(card_t), intent(out) :: c
      type(param_t) :: none(0)
      if (allocated(deck%params)) then
         call open_card(deck%files(blk%ifile)%s, deck%params(1:deck%nparams), blk, c)
      else
         call open_card(deck%files(blk%ifile)%s, none, blk, c)
      end if
      c%collect = deck%check     ! --check: every bad field of the block, not the first only
      c%echo => deck%echo        ! d3hsp: every field read, with its value
   end subroutine deck_cursor

   !> Integer field k (widths w) of card ic; blank or missing -> def.
   subroutine get_int(deck, blk, ic, k, w, fname, def, val, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      integer, intent(in) :: def
      integer, intent(out) :: val
      type(error_t), allocatable, intent(out) :: error
      type(param_t) :: none(0)
      if (allocated(deck%params)) then
         call field_int(deck%files(blk%ifile)%s, deck%params(1:deck%nparams), blk, ic, k, w, &
                        fname, def, val, error)
      else
         call field_int(deck%files(blk%ifile)%s, none, blk, ic, k, w, fname, def, val, error)
      end if
   end subroutine get_int

   !> One field of an id list: an integer >= 0 (0 or blank: no id); an id > 0 is appended to
   !> ids(1:n).
   subroutine get_list_id(deck, blk, ic, k, w, fname, ids, n, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      integer, intent(inout) :: ids(:), n
      type(error_t), allocatable, intent(out) :: error
      integer :: id
      call get_int(deck, blk, ic, k, w, fname, 0, id, error)
      if (allocated(error)) return
      if (id < 0) then
         call field_error(deck, blk, ic, k, w, fname, 'must be >= 0', error)
         return
      end if
      if (id > 0) then
         n = n + 1
         ids(n) = id
      end if
   end subroutine get_list_id

   !> Real field k (widths w) of card ic; blank or missing -> def.
   subroutine get_real(deck, blk, ic, k, w, fname, def, val, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      real(wp), intent(in) :: def
      real(wp), intent(out) :: val
      type(error_t), allocatable, intent(out) :: error
      type(param_t) :: none(0)
      if (allocated(deck%params)) then
         call field_real(deck%files(blk%ifile)%s, deck%params(1:deck%nparams), blk, ic, k, w, &
                         fname, def, val, error)
      else
         call field_real(deck%files(blk%ifile)%s, none, blk, ic, k, w, fname, def, val, error)
      end if
   end subroutine get_real

   !> Text field k (widths w) of card ic, trimmed; C parameters substituted.
   subroutine get_text(deck, blk, ic, k, w, text)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(:), allocatable, intent(out) :: text
      type(param_t) :: none(0)
      if (allocated(deck%params)) then
         call field_str(deck%files(blk%ifile)%s, deck%params(1:deck%nparams), blk, ic, k, w, &
                        text)
      else
         call field_str(deck%files(blk%ifile)%s, none, blk, ic, k, w, text)
      end if
   end subroutine get_text

   !> "file:line" of card ic (0 or missing: the keyword line)
   function card_where(deck, blk, ic) result(s)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(:), allocatable :: s
      s = where_card(deck%files(blk%ifile)%s, blk, ic)
   end function card_where

   !> Error at field k of card ic: file:line:col: *KEY: field NAME: what, card, caret.
   subroutine field_error(deck, blk, ic, k, w, fname, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, what
      type(error_t), allocatable, intent(inout) :: error
      call error_at_field(deck%files(blk%ifile)%s, blk, ic, k, w, fname, what, error)
   end subroutine field_error

   !> Error about card ic as a whole (0: the keyword line): file:line: *KEY: what.
   subroutine card_error(deck, blk, ic, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      call error_at_card(deck%files(blk%ifile)%s, blk, ic, what, error)
   end subroutine card_error

   !> Error about the keyword (line of the keyword, or of card ic when ic > 0), no card shown.
   subroutine block_error(deck, blk, ic, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      call error_at_block(deck%files(blk%ifile)%s, blk, ic, what, error)
   end subroutine block_error

   !> Error when the block has more than nmax cards (a card dynx would otherwise ignore).
   subroutine check_max_cards(deck, blk, nmax, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: nmax
      type(error_t), allocatable, intent(inout) :: error
      call max_cards_check(deck%files(blk%ifile)%s, blk, nmax, error)
   end subroutine check_max_cards
end module dx_deck_cards
