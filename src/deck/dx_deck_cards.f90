!> LS-DYNA keyword deck tokenizer and field reader.
!> Reads a deck (and its *INCLUDE files) into keyword blocks: keyword name, format (standard
!> 10-column or long 20-column fields), and the data cards with their file and line. Handles
!> '$' comments, *KEYWORD [LONG=Y|S], *END, the '+'/'-' keyword suffixes, *INCLUDE (paths
!> relative to the including file, depth limit 20), *TITLE, *PARAMETER (R/I/C, 4 pairs per
!> card) and '&name' / '-&name' references, and comma-separated free format.
!> Reference: LS-DYNA Keyword User's Manual, Vol. I, "General card format" and *KEYWORD,
!> *INCLUDE, *PARAMETER. Errors follow the fpm pattern: file:line:col, the card and a caret.
module dx_deck_cards
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: upper, str, rstr
   use dx_model_input, only: string_t
   use dx_io_sys, only: sys_file_kind
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, &
                                            ieee_set_halting_mode, ieee_set_flag
   implicit none
   private
   public :: card_t, block_t, deck_t, param_t, read_cards, get_int, get_real, get_text, &
             field_error, block_error, card_error, std_widths, ncards, card_where, &
             card_is_blank, check_max_cards, MAX_INCLUDE_DEPTH, data_start, block_title

   integer, parameter :: MAX_INCLUDE_DEPTH = 20

   !> one data card: raw text and line number (the file is the block's)
   type :: card_t
      character(:), allocatable :: text
      integer :: line = 0
   end type card_t

   !> one keyword with its data cards
   type :: block_t
      character(:), allocatable :: name     !< keyword as written, upper case, no '*', no suffix
      character(:), allocatable :: base     !< registered name it matched (set by the registry)
      logical :: opt_title = .false.        !< _TITLE option: first card is a title
      logical :: opt_id = .false.           !< _ID option: first card holds an id + heading
      logical :: long = .false.             !< 20-column fields
      integer :: ifile = 0, line = 0        !< file index and line of the keyword line
      integer :: n = 0                      !< cards in use
      type(card_t), allocatable :: cards(:)
   end type block_t

   !> a *PARAMETER entry
   type :: param_t
      character(:), allocatable :: name     !< upper case
      character :: kind = 'R'               !< R, I or C
      real(wp) :: value = 0.0_wp
      character(:), allocatable :: text
   end type param_t

   type :: deck_t
      type(string_t), allocatable :: files(:)
      integer :: nfiles = 0
      type(block_t), allocatable :: blocks(:)
      integer :: nblocks = 0
      type(param_t), allocatable :: params(:)
      integer :: nparams = 0
      character(:), allocatable :: title
      logical :: long = .false.             !< *KEYWORD LONG=Y seen
   end type deck_t

contains

   !> Read the deck file path and its includes into deck.
   subroutine read_cards(path, deck, error)
      character(*), intent(in) :: path
      type(deck_t), intent(out) :: deck
      type(error_t), allocatable, intent(out) :: error
      allocate(deck%files(4), deck%blocks(64), deck%params(8))
      call read_file(path, deck, 0, 0, 0, error)
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

   !> Split off the next blank-separated token of s.
   subroutine next_token(s, tok)
      character(:), allocatable, intent(inout) :: s
      character(:), allocatable, intent(out) :: tok
      integer :: k
      s = trim(adjustl(s))
      k = index(s, ' ')
      if (k == 0) then
         tok = s
         s = ''
      else
         tok = s(1:k-1)
         s = s(k+1:)
      end if
   end subroutine next_token

   subroutine add_card(blk, line, lineno)
      type(block_t), intent(inout) :: blk
      character(*), intent(in) :: line
      integer, intent(in) :: lineno
      type(card_t), allocatable :: t(:)
      integer :: i
      if (blk%n == size(blk%cards)) then
         allocate(t(2*size(blk%cards)))
         do i = 1, blk%n
            call move_alloc(blk%cards(i)%text, t(i)%text)
            t(i)%line = blk%cards(i)%line
         end do
         call move_alloc(t, blk%cards)
      end if
      blk%n = blk%n + 1
      blk%cards(blk%n)%text = line
      blk%cards(blk%n)%line = lineno
   end subroutine add_card

   !> A finished block: handle *TITLE, *INCLUDE, *PARAMETER here, keep the others.
   recursive subroutine finish_block(deck, blk, depth, error)
      type(deck_t), intent(inout) :: deck
      type(block_t), intent(inout) :: blk
      integer, intent(in) :: depth
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      character(:), allocatable :: fname
      ! trailing blank cards are layout, not data
      do while (blk%n > 0)
         if (len_trim(blk%cards(blk%n)%text) > 0) exit
         blk%n = blk%n - 1
      end do
      select case (blk%name)
      case ('TITLE')
         if (blk%n >= 1) deck%title = trim(blk%cards(1)%text(1:min(80, len(blk%cards(1)%text))))
      case ('INCLUDE')
         if (blk%n == 0) then
            call block_error(deck, blk, 0, 'missing card 1 (FILENAME)', error); return
         end if
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
            call read_file(resolve_path(deck%files(blk%ifile)%s, fname), deck, depth + 1, &
                           blk%ifile, blk%cards(i)%line, error)
            if (allocated(error)) return
         end do
      case ('PARAMETER')
         call read_parameters(deck, blk, error)
      case default
         if (deck%nblocks == size(deck%blocks)) call grow_blocks(deck)
         deck%nblocks = deck%nblocks + 1
         call move_block(blk, deck%blocks(deck%nblocks))
      end select
   end subroutine finish_block

   pure logical function ends_with_plus(s)
      character(*), intent(in) :: s
      integer :: n
      n = len(s)
      ends_with_plus = .false.
      if (n >= 2) ends_with_plus = s(n-1:n) == ' +'
   end function ends_with_plus

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
      call move_alloc(a%cards, b%cards)
   end subroutine move_block

   subroutine grow_blocks(deck)
      type(deck_t), intent(inout) :: deck
      type(block_t), allocatable :: t(:)
      integer :: i
      allocate(t(2*size(deck%blocks)))
      do i = 1, deck%nblocks
         call move_block(deck%blocks(i), t(i))
      end do
      call move_alloc(t, deck%blocks)
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
      integer :: ic, k, col, w(8), j
      character(:), allocatable :: ptxt, vtxt, name
      character :: kind
      type(param_t) :: p
      type(param_t), allocatable :: t(:)
      real(wp) :: v
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
            ! a redefinition replaces the earlier value
            j = find_param(deck, name)
            if (j > 0) then
               deck%params(j) = p
            else
               if (deck%nparams == size(deck%params)) then
                  allocate(t(2*size(deck%params)))
                  t(1:deck%nparams) = deck%params(1:deck%nparams)
                  call move_alloc(t, deck%params)
               end if
               deck%nparams = deck%nparams + 1
               deck%params(deck%nparams) = p
            end if
         end do
      end do
   end subroutine read_parameters

   integer function find_param(deck, name) result(j)
      type(deck_t), intent(in) :: deck
      character(*), intent(in) :: name
      do j = 1, deck%nparams
         if (deck%params(j)%name == name) return
      end do
      j = 0
   end function find_param

   ! ----------------------------------------------------------------------------------------
   ! fields

   !> n field widths of a standard card: 10 columns, 20 in long format.
   pure function std_widths(blk, n) result(w)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: n
      integer :: w(n)
      w = 10
      if (blk%long) w = 20
   end function std_widths

   !> index of the first data card (after an _TITLE or _ID card)
   pure integer function data_start(blk)
      type(block_t), intent(in) :: blk
      data_start = 1
      if (blk%opt_title .or. blk%opt_id) data_start = 2
   end function data_start

   !> the _TITLE card text (80 columns, trimmed), '' without the option
   function block_title(blk) result(t)
      type(block_t), intent(in) :: blk
      character(:), allocatable :: t
      t = ''
      if (blk%opt_title .and. blk%n >= 1) &
         t = trim(adjustl(blk%cards(1)%text(1:min(80, len(blk%cards(1)%text)))))
   end function block_title

   !> number of cards in the block
   pure integer function ncards(blk)
      type(block_t), intent(in) :: blk
      ncards = blk%n
   end function ncards

   !> .true. when card ic is blank or missing
   pure logical function card_is_blank(blk, ic)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      card_is_blank = .true.
      if (ic >= 1 .and. ic <= blk%n) card_is_blank = len_trim(blk%cards(ic)%text) == 0
   end function card_is_blank

   !> Text of field k of card ic and its first column (blank when the card or field is missing).
   !> A card holding a comma is free format: field k is the k-th comma-separated token.
   subroutine field_text(blk, ic, k, w, text, col)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(:), allocatable, intent(out) :: text
      integer, intent(out) :: col
      integer :: n, j, a, b
      text = ''
      col = 1 + sum(w(1:k-1))
      if (ic < 1 .or. ic > blk%n) return
      associate (c => blk%cards(ic)%text)
         n = len(c)
         if (index(c, ',') > 0) then
            a = 1
            do j = 1, k
               b = index(c(a:), ',')
               if (j < k) then
                  if (b == 0) then
                     col = n + 1
                     return
                  end if
                  a = a + b
               end if
            end do
            col = a
            if (b == 0) then
               text = c(a:n)
            else
               text = c(a:a+b-2)
            end if
         else
            if (col > n) return
            text = c(col:min(n, col + w(k) - 1))
         end if
      end associate
   end subroutine field_text

   !> Integer field k (widths w) of card ic; blank or missing -> def.
   subroutine get_int(deck, blk, ic, k, w, fname, def, val, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      integer, intent(in) :: def
      integer, intent(out) :: val
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: t, msg
      integer :: col
      real(wp) :: r
      logical :: ok
      val = def
      call field_text(blk, ic, k, w, t, col)
      t = trim(adjustl(t))
      if (len(t) == 0) return
      if (is_param_ref(t)) then
         call param_value(deck, t, r, msg)
         if (len(msg) == 0 .and. (r /= anint(r) .or. abs(r) > 2147483647.0_wp)) &
            msg = 'parameter '//t//' = '//rstr(r)//' is not an integer'
         if (len(msg) > 0) then
            call field_error(deck, blk, ic, k, w, fname, msg, error); return
         end if
         val = nint(r)
         return
      end if
      call parse_int(t, val, ok)
      if (ok) then
         call check_boundaries(deck, blk, ic, k, w, fname, error)
         return
      end if
      call parse_real(t, r, ok)
      if (ok) then
         if (r == anint(r) .and. abs(r) <= 2147483647.0_wp) then
            val = nint(r)
            call check_boundaries(deck, blk, ic, k, w, fname, error)
            return
         end if
         call field_error(deck, blk, ic, k, w, fname, 'expected an integer, got '''//t//'''', &
                          error)
         return
      end if
      call field_error(deck, blk, ic, k, w, fname, bad_number_msg(blk, ic, k, w, t), error)
   end subroutine get_int

   !> Real field k (widths w) of card ic; blank or missing -> def.
   subroutine get_real(deck, blk, ic, k, w, fname, def, val, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      real(wp), intent(in) :: def
      real(wp), intent(out) :: val
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: t, msg
      integer :: col
      logical :: ok
      val = def
      call field_text(blk, ic, k, w, t, col)
      t = trim(adjustl(t))
      if (len(t) == 0) return
      if (is_param_ref(t)) then
         call param_value(deck, t, val, msg)
         if (len(msg) > 0) call field_error(deck, blk, ic, k, w, fname, msg, error)
         return
      end if
      call parse_real(t, val, ok)
      if (.not. ok) then
         call field_error(deck, blk, ic, k, w, fname, bad_number_msg(blk, ic, k, w, t), error)
      else
         call check_boundaries(deck, blk, ic, k, w, fname, error)
      end if
   end subroutine get_real

   !> A valid number can still be the front of a value that ran over its columns
   !> ('   123456789012' read as 1234567 and 89012). In fixed format digits (or '.') on both
   !> sides of the boundary between fields j and j+1 are one number running across it,
   !> which is legal only when one of the two fields is full (packed full-width values
   !> such as '1.0000E+001.0000E+00'); otherwise it is an error, checked at both ends of
   !> field k. A letter or a sign at the boundary starts a new token ('0.004I', '1.0-3').
   subroutine check_boundaries(deck, blk, ic, k, w, fname, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      type(error_t), allocatable, intent(out) :: error
      integer :: col, n
      logical :: bad
      if (ic < 1 .or. ic > blk%n) return
      associate (c => blk%cards(ic)%text)
         if (index(c, ',') > 0) return
         n = len(c)
         col = 1 + sum(w(1:k-1))
         bad = .false.
         if (k > 1 .and. col <= n) bad = crosses(col - w(k-1), w(k-1), w(k))
         if (k < size(w) .and. col + w(k) <= n) bad = bad .or. crosses(col, w(k), w(k+1))
      end associate
      if (bad) call field_error(deck, blk, ic, k, w, fname, 'a value runs across the '// &
         'boundary of this '//str(w(k))//'-column field (fixed format: each value must fit '// &
         'its columns; or separate values with commas)', error)
   contains
      !> whether a token crosses from field [a, a+wa) into [a+wa, a+wa+wb) with neither full
      logical function crosses(a, wa, wb)
         integer, intent(in) :: a, wa, wb
         integer :: e
         e = a + wa
         crosses = .false.
         associate (c => blk%cards(ic)%text)
            if (scan(c(e-1:e-1), '0123456789.') == 0 .or. scan(c(e:e), '0123456789.') == 0) &
               return                                      ! not one number across the boundary
            if (index(c(a:e-1), ' ') == 0) return            ! field j full
            if (e + wb - 1 <= n) then
               if (index(c(e:e+wb-1), ' ') == 0) return      ! field j+1 full
            end if
            crosses = .true.
         end associate
      end function crosses
   end subroutine check_boundaries

   !> Text field k (widths w) of card ic, trimmed ('' when blank or missing); C parameters
   !> are substituted.
   subroutine get_text(deck, blk, ic, k, w, text)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(:), allocatable, intent(out) :: text
      integer :: col, j
      call field_text(blk, ic, k, w, text, col)
      text = trim(adjustl(text))
      if (len(text) > 1) then
         if (text(1:1) == '&') then
            j = find_param(deck, upper(text(2:)))
            if (j > 0) then
               if (deck%params(j)%kind == 'C') text = deck%params(j)%text
            end if
         end if
      end if
   end subroutine get_text

   function bad_number_msg(blk, ic, k, w, t) result(msg)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: t
      character(:), allocatable :: msg
      integer :: col, n
      logical :: cross
      msg = 'expected a number, got '''//t//''''
      associate (c => blk%cards(ic)%text)
         if (index(c, ',') > 0) return
         col = 1 + sum(w(1:k-1))
         n = len(c)
         cross = .false.
         ! text running over the field boundary: a value overflowing its columns
         if (col > 1 .and. col <= n) cross = c(col-1:col-1) /= ' ' .and. c(col:col) /= ' '
         if (col + w(k) <= n) cross = cross .or. &
            (c(col+w(k)-1:col+w(k)-1) /= ' ' .and. c(col+w(k):col+w(k)) /= ' ')
         if (cross) msg = msg//' (a value overflows its '//str(w(k))// &
            ' columns into the neighbouring field)'
      end associate
   end function bad_number_msg

   pure logical function is_param_ref(t)
      character(*), intent(in) :: t
      is_param_ref = t(1:1) == '&'
      if (len(t) >= 2) is_param_ref = is_param_ref .or. t(1:2) == '-&'
   end function is_param_ref

   subroutine param_value(deck, t, v, msg)
      type(deck_t), intent(in) :: deck
      character(*), intent(in) :: t
      real(wp), intent(out) :: v
      character(:), allocatable, intent(out) :: msg
      integer :: j
      logical :: neg
      character(:), allocatable :: name
      neg = t(1:1) == '-'
      if (neg) then
         name = upper(trim(t(3:)))
      else
         name = upper(trim(t(2:)))
      end if
      msg = ''
      v = 0.0_wp
      j = find_param(deck, name)
      if (j == 0) then
         msg = 'parameter '''//name//''' is not defined (*PARAMETER)'
      else if (deck%params(j)%kind == 'C') then
         msg = 'character parameter '''//name//''' used in a numeric field'
      else
         v = deck%params(j)%value
         if (neg) v = -v
      end if
   end subroutine param_value

   !> strict integer: [sign] digits
   pure subroutine parse_int(t, val, ok)
      character(*), intent(in) :: t
      integer, intent(out) :: val
      logical, intent(out) :: ok
      integer :: i, i0, d
      integer(i8) :: acc
      logical :: neg
      val = 0
      ok = .false.
      i0 = 1
      neg = .false.
      if (t(1:1) == '-' .or. t(1:1) == '+') then
         neg = t(1:1) == '-'
         i0 = 2
      end if
      if (i0 > len(t) .or. len(t) - i0 > 10) return
      acc = 0
      do i = i0, len(t)
         d = iachar(t(i:i)) - iachar('0')
         if (d < 0 .or. d > 9) return
         acc = 10*acc + d
      end do
      if (acc > 2147483647_i8) return
      val = int(acc)
      if (neg) val = -val
      ok = .true.
   end subroutine parse_int

   !> Fortran-style real: [sign] (d+[.d*] | .d+) [(e|d)[sign]d+ | sign d+]
   subroutine parse_real(t, val, ok)
      character(*), intent(in) :: t
      real(wp), intent(out) :: val
      logical, intent(out) :: ok
      character(len=len(t)+2) :: buf
      integer :: i, n, nd, ios, nb
      logical :: halt
      character :: ch
      val = 0.0_wp
      ok = .false.
      n = len(t)
      i = 1
      nb = 0
      buf = ''
      if (t(1:1) == '-' .or. t(1:1) == '+') then
         nb = nb + 1; buf(nb:nb) = t(1:1); i = 2
      end if
      nd = 0
      do while (i <= n)
         ch = t(i:i)
         if (ch < '0' .or. ch > '9') exit
         nb = nb + 1; buf(nb:nb) = ch; nd = nd + 1; i = i + 1
      end do
      if (i <= n) then
         if (t(i:i) == '.') then
            nb = nb + 1; buf(nb:nb) = '.'; i = i + 1
            do while (i <= n)
               ch = t(i:i)
               if (ch < '0' .or. ch > '9') exit
               nb = nb + 1; buf(nb:nb) = ch; nd = nd + 1; i = i + 1
            end do
         end if
      end if
      if (nd == 0) return
      if (i <= n) then
         ch = upper(t(i:i))
         if (ch == 'E' .or. ch == 'D') then
            i = i + 1
         else if (ch /= '+' .and. ch /= '-') then
            return
         end if
         nb = nb + 1; buf(nb:nb) = 'e'
         if (i <= n) then
            if (t(i:i) == '+' .or. t(i:i) == '-') then
               nb = nb + 1; buf(nb:nb) = t(i:i); i = i + 1
            end if
         end if
         nd = 0
         do while (i <= n)
            ch = t(i:i)
            if (ch < '0' .or. ch > '9') exit
            nb = nb + 1; buf(nb:nb) = ch; nd = nd + 1; i = i + 1
         end do
         if (nd == 0) return
      end if
      if (i <= n) return
      ! 1e309 overflows inside the library's strtod: with overflow trapping on (the debug
      ! build's -ffpe-trap) that is a SIGFPE, so trapping is off for this read; the
      ! infinite result is then rejected below
      call ieee_get_halting_mode(ieee_overflow, halt)
      if (halt) call ieee_set_halting_mode(ieee_overflow, .false.)
      read(buf(1:nb), *, iostat=ios) val
      call ieee_set_flag(ieee_overflow, .false.)
      if (halt) call ieee_set_halting_mode(ieee_overflow, .true.)
      ok = ios == 0
      if (ok) ok = ieee_is_finite(val)
   end subroutine parse_real

   ! ----------------------------------------------------------------------------------------
   ! messages

   !> "file:line" of card ic (0 or missing: the keyword line)
   function card_where(deck, blk, ic) result(s)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(:), allocatable :: s
      if (ic >= 1 .and. ic <= blk%n) then
         s = deck%files(blk%ifile)%s//':'//str(blk%cards(ic)%line)
      else
         s = deck%files(blk%ifile)%s//':'//str(blk%line)
      end if
   end function card_where

   !> Error at field k of card ic: file:line:col: *KEY: field NAME: what, card, caret.
   subroutine field_error(deck, blk, ic, k, w, fname, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, what
      type(error_t), allocatable, intent(inout) :: error
      character(:), allocatable :: t
      integer :: col
      call field_text(blk, ic, k, w, t, col)
      if (ic < 1 .or. ic > blk%n) then
         call set_error(error, card_where(deck, blk, ic)//': *'//blk%name//': field '// &
                        fname//': '//what, EXIT_INPUT)
         return
      end if
      call set_error(error, card_where(deck, blk, ic)//':'//str(col)//': *'//blk%name// &
         ': field '//fname//': '//what//new_line('a')//blk%cards(ic)%text//new_line('a')// &
         repeat(' ', col - 1)//'^', EXIT_INPUT)
   end subroutine field_error

   !> Error about card ic as a whole (0: the keyword line): file:line: *KEY: what.
   subroutine card_error(deck, blk, ic, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      if (ic >= 1 .and. ic <= blk%n) then
         call set_error(error, card_where(deck, blk, ic)//': *'//blk%name//': '//what// &
                        new_line('a')//blk%cards(ic)%text, EXIT_INPUT)
      else
         call set_error(error, card_where(deck, blk, ic)//': *'//blk%name//': '//what, &
                        EXIT_INPUT)
      end if
   end subroutine card_error

   !> Error about the keyword (line of the keyword, or of card ic when ic > 0), no card shown.
   subroutine block_error(deck, blk, ic, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      call set_error(error, card_where(deck, blk, ic)//': *'//blk%name//': '//what, &
                     EXIT_INPUT)
   end subroutine block_error

   !> Error when the block has more than nmax cards (a card dynx would otherwise ignore).
   subroutine check_max_cards(deck, blk, nmax, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: nmax
      type(error_t), allocatable, intent(inout) :: error
      if (blk%n > nmax) call card_error(deck, blk, nmax + 1, 'unexpected card '// &
         str(nmax + 1)//' (this keyword takes '//str(nmax)//' card(s) here)', error)
   end subroutine check_max_cards
end module dx_deck_cards
