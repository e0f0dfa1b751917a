!> The card cursor over the data cards of a keyword block; the blocks, fields and messages
!> are dx_card_fields (re-exported here, so a reader uses dx_card alone).
!> The cursor card_t walks the data cards of one block and keeps the first error, so a reader
!> is a list of calls without an error check after each:
!>    call c%int('MID', 0, mid); call c%real('FS', 0.0_wp, fs, min=0.0_wp); call c%done(error)
!> It remembers where each named field was read, so a later check (a material's setup) can
!> point at the field by name (c%fail) without parsing a message.
!> Collect mode (c%collect, set for `dynx --check` by dx_deck_cards' deck_cursor): the reads
!> go on after an error, and every later error of the block is kept too (the first line of
!> each, in error%more), so --check lists every bad field of a block in one run; without it
!> the first error stops the reading of the block (the later reads give their defaults).
!> Echo (c%echo associated: a run that writes d3hsp, dx_deck_cards' deck_cursor): every
!> field read is echoed with its value and whether it is the default (dx_card_echo).
!> Reference: LS-DYNA Keyword User's Manual, Vol. I, "General card format" (fixed 10-column
!> fields, 8 per card; 20 columns with *KEYWORD LONG=Y or the '+' suffix; free format with
!> commas) and *PARAMETER.
module dx_card
   use dx_kinds, only: wp
   use dx_error, only: error_t, MAX_MORE
   use dx_strings, only: str, rstr
   use dx_card_echo, only: echo_t
   use dx_card_fields, only: card_line_t, block_t, param_t, find_param, std_widths, &
                             data_start, block_title, ncards, card_is_blank, field_text, &
                             field_int, field_real, field_str, error_at_field, error_at_card, &
                             error_at_block, where_card, max_cards_check, REAL_FIELD_MAX
   implicit none
   private
   public :: card_line_t, block_t, param_t, card_t, open_card, find_param, std_widths, &
             data_start, block_title, ncards, card_is_blank, field_text, field_int, &
             field_real, field_str, error_at_field, error_at_card, error_at_block, where_card, &
             max_cards_check, REAL_FIELD_MAX

   !> where a named field was read (card, field number)
   type :: field_pos_t
      character(:), allocatable :: name
      integer :: ic = 0, k = 0
   end type field_pos_t

   !> Cursor over the data cards of one keyword block; keeps the first error.
   type :: card_t
      character(:), allocatable :: file     !< deck file of the block
      type(block_t) :: blk
      type(param_t), allocatable :: params(:)
      integer :: ic = 1                     !< current card (index into blk%cards)
      integer :: k = 0                      !< last field read on the current card
      integer :: w(16) = 10                 !< field widths of the current card (1:nw)
      integer :: nw = 8                     !< fields on a card
      type(field_pos_t), allocatable :: seen(:)
      integer :: nseen = 0
      type(error_t), allocatable :: error   !< the first error
      logical :: collect = .false.          !< keep reading after an error (--check)
      integer :: nerr = 0                   !< errors so far (collect: all of them)
      character(:), allocatable :: more     !< collect: first lines of the later errors
      integer :: nmore = 0, ndrop = 0       !< lines in more; later errors only counted
      type(echo_t), pointer :: echo => null()   !< the d3hsp echo (null: none)
   contains
      procedure :: next => cursor_next      !< go to the next data card
      procedure :: seek => cursor_seek      !< go to card ic of the block (field 0)
      procedure :: text => cursor_text      !< raw text of the current card ('' if missing)
      procedure :: skip => cursor_skip      !< skip n fields of the current card
      procedure :: int => cursor_int        !< next field as an integer
      procedure :: real => cursor_real      !< next field as a real
      procedure :: fail => cursor_fail      !< error at a field read before (by name)
      procedure :: fail_here => cursor_fail_here  !< error at the field last read or skipped
      procedure :: fail_block => cursor_fail_block  !< error about the keyword (no field)
      procedure :: fail_card => cursor_fail_card    !< error about a card as a whole
      procedure :: max_cards => cursor_max_cards    !< error when the block has > nmax cards
      procedure :: zero => cursor_zero      !< next field as a real that must be blank or 0
      procedure :: zero_int => cursor_zero_int    !< next field: an integer option, blank or 0
      procedure :: zero_real => cursor_zero_real  !< next field: a real option, blank or 0
      procedure :: id => cursor_id          !< next field as an id > 0
      procedure :: list_id => cursor_list_id      !< next field of an id list (>= 0, 0: none)
      procedure :: need => cursor_need      !< error when the block has fewer than n cards
      procedure :: at => cursor_at          !< the next read is field k of the current card
      procedure :: widths => cursor_widths  !< the field widths of the cards (fixed format)
      procedure :: ncard => cursor_ncard    !< number of cards in the block
      procedure :: text_field => cursor_text_field  !< field k (widths w) of the card as text
      procedure :: ok => cursor_ok          !< no error so far
      procedure :: halt => cursor_halt      !< stop reading the block: an error, not collecting
      procedure :: done => cursor_done      !< hand the first error (if any) to the caller
      procedure :: title => cursor_title    !< the _TITLE card text
      procedure :: card_line => cursor_card_line  !< line number of the current card
   end type card_t

contains

   !> A cursor on the first data card (after an _TITLE or _ID card) of blk in file; params
   !> resolves '&name' references.
   subroutine open_card(file, params, blk, c)
      character(*), intent(in) :: file
      type(param_t), intent(in) :: params(:)
      type(block_t), intent(in) :: blk
      type(card_t), intent(out) :: c
      c%file = file
      c%blk = blk
      c%params = params
      c%ic = data_start(blk)
      c%k = 0
      c%w(1:8) = std_widths(blk, 8)
      c%nw = 8
      allocate(c%seen(16))
   end subroutine open_card

   !> Field widths of the cards from now on (a *NODE card: 8, 16, 16, 16, 8, 8).
   subroutine cursor_widths(c, w)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: w(:)
      c%nw = min(size(w), size(c%w))
      c%w(1:c%nw) = w(1:c%nw)
   end subroutine cursor_widths

   !> The next read is field k of the current card.
   subroutine cursor_at(c, k)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: k
      c%k = k - 1
   end subroutine cursor_at

   !> Field k of the current card as text, trimmed, with its own widths w (a heading in
   !> columns 11-80: k = 2, w = [10, 70]); a C *PARAMETER is substituted. The position of
   !> the cursor does not move.
   subroutine cursor_text_field(c, k, w, text)
      class(card_t), intent(in) :: c
      integer, intent(in) :: k, w(:)
      character(:), allocatable, intent(out) :: text
      call field_str(c%file, c%params, c%blk, c%ic, k, w, text)
   end subroutine cursor_text_field

   !> Number of cards of the block (a title or id card included).
   pure integer function cursor_ncard(c)
      class(card_t), intent(in) :: c
      cursor_ncard = c%blk%n
   end function cursor_ncard

   !> Error about the keyword when the block holds fewer than n cards ('missing card ...').
   subroutine cursor_need(c, n, what)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: n
      character(*), intent(in) :: what
      if (c%blk%n < n) call c%fail_block(0, what)
   end subroutine cursor_need

   !> Go to the next data card (field 0).
   subroutine cursor_next(c)
      class(card_t), intent(inout) :: c
      c%ic = c%ic + 1
      c%k = 0
   end subroutine cursor_next

   !> Go to card ic of the block (1 = the first card, a title card included), field 0.
   subroutine cursor_seek(c, ic)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: ic
      c%ic = ic
      c%k = 0
   end subroutine cursor_seek

   !> Raw text of the current card ('' when it is missing).
   function cursor_text(c) result(t)
      class(card_t), intent(in) :: c
      character(:), allocatable :: t
      t = ''
      if (c%ic >= 1 .and. c%ic <= c%blk%n) t = c%blk%cards(c%ic)%text
   end function cursor_text

   !> Skip n fields of the current card.
   subroutine cursor_skip(c, n)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: n
      c%k = c%k + n
   end subroutine cursor_skip

   pure logical function cursor_ok(c)
      class(card_t), intent(in) :: c
      cursor_ok = .not. allocated(c%error)
   end function cursor_ok

   !> Whether a reader stops reading the block now: an error and no collect mode (collect
   !> mode: the next cards are read too, each error is kept).
   pure logical function cursor_halt(c)
      class(card_t), intent(in) :: c
      cursor_halt = allocated(c%error) .and. .not. c%collect
   end function cursor_halt

   !> Move the first error (if any) to error.
   subroutine cursor_done(c, error)
      class(card_t), intent(inout) :: c
      type(error_t), allocatable, intent(out) :: error
      if (allocated(c%error)) then
         if (allocated(c%more)) c%error%more = c%more
         c%error%nmore = c%nmore
         c%error%ndrop = c%ndrop
         call move_alloc(c%error, error)
      end if
   end subroutine cursor_done

   !> Keep the error e: the first of the block, or (collect mode) one more line.
   subroutine keep(c, e)
      class(card_t), intent(inout) :: c
      type(error_t), allocatable, intent(inout) :: e
      integer :: k
      if (.not. allocated(e)) return
      c%nerr = c%nerr + 1
      if (.not. allocated(c%error)) then
         call move_alloc(e, c%error)
         return
      end if
      if (c%collect .and. c%nmore >= MAX_MORE) then
         c%ndrop = c%ndrop + 1
      else if (c%collect) then
         c%nmore = c%nmore + 1
         k = index(e%message, new_line('a'))
         if (k == 0) k = len(e%message) + 1
         if (.not. allocated(c%more)) then
            c%more = e%message(1:k - 1)
         else
            c%more = c%more//new_line('a')//e%message(1:k - 1)
         end if
      end if
      deallocate(e)
   end subroutine keep

   function cursor_title(c) result(t)
      class(card_t), intent(in) :: c
      character(:), allocatable :: t
      t = block_title(c%blk)
   end function cursor_title

   !> Line of the current card (the keyword line when the card is missing).
   pure integer function cursor_card_line(c)
      class(card_t), intent(in) :: c
      cursor_card_line = c%blk%line
      if (c%ic >= 1 .and. c%ic <= c%blk%n) cursor_card_line = c%blk%cards(c%ic)%line
   end function cursor_card_line

   subroutine remember(c, name)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      type(field_pos_t), allocatable :: t(:)
      integer :: j
      if (.not. allocated(c%seen)) allocate(c%seen(16))
      ! one entry a name (the last read): a list keyword of many cards keeps a short table
      do j = c%nseen, 1, -1
         if (len(c%seen(j)%name) == len(name)) then
            if (c%seen(j)%name == name) then
               c%seen(j)%ic = c%ic
               c%seen(j)%k = c%k
               return
            end if
         end if
      end do
      if (c%nseen == size(c%seen)) then
         allocate(t(2*size(c%seen)))
         t(1:c%nseen) = c%seen(1:c%nseen)
         call move_alloc(t, c%seen)
      end if
      c%nseen = c%nseen + 1
      c%seen(c%nseen) = field_pos_t(name, c%ic, c%k)
   end subroutine remember

   !> Next field as an integer NAME (blank: def); optional bounds min <= val <= max.
   subroutine cursor_int(c, name, def, val, min, max)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      integer, intent(in) :: def
      integer, intent(out) :: val
      integer, intent(in), optional :: min, max
      type(error_t), allocatable :: e
      integer :: n0
      n0 = c%nerr
      c%k = c%k + 1
      val = def
      if (allocated(c%error) .and. .not. c%collect) return
      call remember(c, name)
      if (c%k > c%nw) then              ! past the card's fields: the default
         if (associated(c%echo)) call echo_read(c, name, str(val))
         return
      end if
      call field_int(c%file, c%params, c%blk, c%ic, c%k, c%w(1:c%nw), name, def, val, e)
      if (allocated(e)) then
         val = def
         call keep(c, e)
         return
      end if
      if (present(min)) then
         if (val < min) call c%fail(name, 'must be >= '//str(min)//', got '//str(val))
      end if
      if (present(max)) then
         if (val > max) call c%fail(name, 'must be <= '//str(max)//', got '//str(val))
      end if
      ! collect mode reads on: a value out of its bounds is not handed on, its default is
      if (c%collect .and. c%nerr > n0) val = def
      if (associated(c%echo)) call echo_read(c, name, str(val))
   end subroutine cursor_int

   !> Next field as a real NAME (blank: def); optional bounds min <= val <= max, val > gt.
   subroutine cursor_real(c, name, def, val, min, max, gt)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      real(wp), intent(in) :: def
      real(wp), intent(out) :: val
      real(wp), intent(in), optional :: min, max, gt
      type(error_t), allocatable :: e
      integer :: n0
      n0 = c%nerr
      c%k = c%k + 1
      val = def
      if (allocated(c%error) .and. .not. c%collect) return
      call remember(c, name)
      if (c%k > c%nw) then
         if (associated(c%echo)) call echo_read(c, name, rstr(val))
         return
      end if
      call field_real(c%file, c%params, c%blk, c%ic, c%k, c%w(1:c%nw), name, def, val, e)
      if (allocated(e)) then
         val = def
         call keep(c, e)
         return
      end if
      if (present(min)) then
         if (.not. (val >= min)) call c%fail(name, 'must be >= '//bound(min)//', got '//rstr(val))
      end if
      if (present(max)) then
         if (.not. (val <= max)) call c%fail(name, 'must be <= '//bound(max)//', got '//rstr(val))
      end if
      if (present(gt)) then
         if (.not. (val > gt)) call c%fail(name, 'must be > '//bound(gt)//', got '//rstr(val))
      end if
      if (c%collect .and. c%nerr > n0) val = def
      if (associated(c%echo)) call echo_read(c, name, rstr(val))
   end subroutine cursor_real

   !> The field just read (name, its value as text) into the d3hsp echo: a default when the
   !> field is blank or past the card's fields.
   subroutine echo_read(c, name, value)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, value
      character(:), allocatable :: t
      integer :: col
      logical :: dflt
      dflt = c%k > c%nw
      if (.not. dflt) then
         call field_text(c%blk, c%ic, c%k, c%w(1:c%nw), t, col)
         dflt = len_trim(t) == 0
      end if
      call c%echo%block(c%blk%name, c%blk%ifile, c%file, c%blk%line, c%blk%n)
      call c%echo%field(c%ic, merge(c%card_line(), 0, c%ic <= c%blk%n), name, value, dflt)
   end subroutine echo_read

   !> A bound as written in a message: an integral value without exponent (0, 1), else rstr.
   function bound(x) result(s)
      real(wp), intent(in) :: x
      character(:), allocatable :: s
      if (x == anint(x) .and. abs(x) < 1.0e9_wp) then
         s = str(nint(x))
      else
         s = rstr(x)
      end if
   end function bound

   !> Error at the field NAME read before (the last read of that name), unless an error is
   !> already kept; a name not read gives an error about the first data card.
   subroutine cursor_fail(c, name, what)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, what
      integer :: j
      type(error_t), allocatable :: e
      if (allocated(c%error) .and. .not. c%collect) return
      do j = c%nseen, 1, -1
         if (c%seen(j)%name == name) then
            call error_at_field(c%file, c%blk, c%seen(j)%ic, c%seen(j)%k, c%w(1:c%nw), name, &
                                what, e)
            call keep(c, e)
            return
         end if
      end do
      call error_at_block(c%file, c%blk, data_start(c%blk), 'field '//name//': '//what, e)
      call keep(c, e)
   end subroutine cursor_fail

   !> Error at the current field (the last read or skipped) of the current card, named NAME.
   subroutine cursor_fail_here(c, name, what)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, what
      type(error_t), allocatable :: e
      if (allocated(c%error) .and. .not. c%collect) return
      call error_at_field(c%file, c%blk, c%ic, max(c%k, 1), c%w(1:c%nw), name, what, e)
      call keep(c, e)
   end subroutine cursor_fail_here

   !> Error about card ic as a whole (the card is shown, no caret).
   subroutine cursor_fail_card(c, ic, what)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable :: e
      if (allocated(c%error) .and. .not. c%collect) return
      call error_at_card(c%file, c%blk, ic, what, e)
      call keep(c, e)
   end subroutine cursor_fail_card

   !> Error when the block holds more than nmax cards (a card dynx would otherwise ignore).
   subroutine cursor_max_cards(c, nmax)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: nmax
      type(error_t), allocatable :: e
      if (allocated(c%error) .and. .not. c%collect) return
      call max_cards_check(c%file, c%blk, nmax, e)
      call keep(c, e)
   end subroutine cursor_max_cards

   !> Next field NAME: an unsupported option, error unless blank or 0 ('value V is not
   !> supported: why').
   subroutine cursor_zero(c, name, why)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, why
      real(wp) :: v
      integer :: n0
      n0 = c%nerr
      call c%real(name, 0.0_wp, v)
      if (c%nerr == n0 .and. v /= 0.0_wp) call c%fail(name, 'value '//rstr(v)// &
                                                       ' is not supported: '//why)
   end subroutine cursor_zero

   !> Next field NAME: an integer option dynx lacks, error unless blank or 0 ('nonzero value
   !> V is not supported: why').
   subroutine cursor_zero_int(c, name, why)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, why
      integer :: v, n0
      n0 = c%nerr
      call c%int(name, 0, v)
      if (c%nerr == n0 .and. v /= 0) call c%fail(name, 'nonzero value '//str(v)// &
                                                  ' is not supported: '//why)
   end subroutine cursor_zero_int

   !> Next field NAME: a real option dynx lacks, error unless blank or 0.
   subroutine cursor_zero_real(c, name, why)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name, why
      real(wp) :: v
      integer :: n0
      n0 = c%nerr
      call c%real(name, 0.0_wp, v)
      if (c%nerr == n0 .and. v /= 0.0_wp) call c%fail(name, 'nonzero value '//rstr(v)// &
                                                       ' is not supported: '//why)
   end subroutine cursor_zero_real

   !> Next field as an id NAME > 0 (blank: 0, an error); the message is what (default 'an id
   !> > 0 is required') and the value read.
   subroutine cursor_id(c, name, val, what)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      integer, intent(out) :: val
      character(*), intent(in), optional :: what
      integer :: n0
      n0 = c%nerr
      call c%int(name, 0, val)
      if (c%nerr /= n0 .or. val > 0) return
      if (present(what)) then
         call c%fail(name, what//', got '//str(val))
      else
         call c%fail(name, 'an id > 0 is required, got '//str(val))
      end if
   end subroutine cursor_id

   !> Next field of an id list NAME: an integer >= 0 (blank or 0: no id); an id > 0 is
   !> appended to ids(1:n).
   subroutine cursor_list_id(c, name, ids, n)
      class(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      integer, intent(inout) :: ids(:), n
      integer :: id
      call c%int(name, 0, id, min=0)
      if (c%ok() .and. id > 0) then
         n = n + 1
         ids(n) = id
      end if
   end subroutine cursor_list_id

   !> Error about the keyword at data card ic (0: the keyword line), no card shown.
   subroutine cursor_fail_block(c, ic, what)
      class(card_t), intent(inout) :: c
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable :: e
      if (allocated(c%error) .and. .not. c%collect) return
      call error_at_block(c%file, c%blk, ic, what, e)
      call keep(c, e)
   end subroutine cursor_fail_block
end module dx_card
