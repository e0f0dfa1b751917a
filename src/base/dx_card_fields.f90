!> LS-DYNA card fields: a keyword block (block_t: keyword, file line, raw data cards), the
!> *PARAMETER table entry (param_t), the field readers every deck reader shares through the
!> card cursor (dx_card): fixed 10/20-column fields or comma-separated free format, '&name'
!> parameter references, values running across a field boundary, and the messages they
!> print: file:line:col: *KEY: field NAME: what, the card and a '^' under the field (the fpm
!> pattern, fortran-lang/fpm src/fpm/error.f90).
!> Reference: LS-DYNA Keyword User's Manual, Vol. I, "General card format" (fixed 10-column
!> fields, 8 per card; 20 columns with *KEYWORD LONG=Y or the '+' suffix; free format with
!> commas) and *PARAMETER.
module dx_card_fields
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: upper, str, rstr
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, &
                                            ieee_set_halting_mode, ieee_set_flag
   implicit none
   private
   public :: card_line_t, block_t, param_t, find_param, std_widths, data_start, block_title, &
             ncards, card_is_blank, field_text, field_int, field_real, field_str, &
             error_at_field, error_at_card, error_at_block, where_card, max_cards_check, &
             REAL_FIELD_MAX

   !> The largest magnitude of a real field: huge/1e6 (1.8E+302), so a value times a few
   !> factors of the model (areas, moduli, counts) stays finite; Inf (an overflowing
   !> '1e309') is rejected too. Coordinates have a tighter bound (dx_read_nodes_elements).
   real(wp), parameter :: REAL_FIELD_MAX = huge(1.0_wp)*1.0e-6_wp

   !> one data card: raw text and line number (the file is the block's)
   type :: card_line_t
      character(:), allocatable :: text
      integer :: line = 0
   end type card_line_t

   !> one keyword with its data cards
   type :: block_t
      character(:), allocatable :: name     !< keyword as written, upper case, no '*', no suffix
      character(:), allocatable :: base     !< registered name it matched (set by the registry)
      logical :: opt_title = .false.        !< _TITLE option: first card is a title
      logical :: opt_id = .false.           !< _ID option: first card holds an id + heading
      logical :: long = .false.             !< 20-column fields
      integer :: ifile = 0, line = 0        !< file index and line of the keyword line
      integer :: n = 0                      !< cards in use
      integer :: scid = 0                   !< *CASE subcase of the block (0: every case)
      type(card_line_t), allocatable :: cards(:)
   end type block_t

   !> a *PARAMETER entry
   type :: param_t
      character(:), allocatable :: name     !< upper case
      character :: kind = 'R'               !< R, I or C
      real(wp) :: value = 0.0_wp
      character(:), allocatable :: text
   end type param_t


contains

   integer function find_param(params, name) result(j)
      type(param_t), intent(in) :: params(:)
      character(*), intent(in) :: name
      do j = 1, size(params)
         if (params(j)%name == name) return
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
   subroutine field_int(file, params, blk, ic, k, w, fname, def, val, error)
      character(*), intent(in) :: file
      type(param_t), intent(in) :: params(:)
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
         call param_value(params, t, r, msg)
         if (len(msg) == 0 .and. (r /= anint(r) .or. abs(r) > 2147483647.0_wp)) &
            msg = 'parameter '//t//' = '//rstr(r)//' is not an integer'
         if (len(msg) > 0) then
            call error_at_field(file, blk, ic, k, w, fname, msg, error); return
         end if
         val = nint(r)
         return
      end if
      call parse_int(t, val, ok)
      if (ok) then
         call check_boundaries(file, blk, ic, k, w, fname, error)
         return
      end if
      call parse_real(t, r, ok)
      if (ok) then
         if (r == anint(r) .and. abs(r) <= 2147483647.0_wp) then
            val = nint(r)
            call check_boundaries(file, blk, ic, k, w, fname, error)
            return
         end if
         call error_at_field(file, blk, ic, k, w, fname, 'expected an integer, got '''//t//'''', &
                          error)
         return
      end if
      call error_at_field(file, blk, ic, k, w, fname, bad_number_msg(blk, ic, k, w, t), error)
   end subroutine field_int

   !> Real field k (widths w) of card ic; blank or missing -> def.
   subroutine field_real(file, params, blk, ic, k, w, fname, def, val, error)
      character(*), intent(in) :: file
      type(param_t), intent(in) :: params(:)
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
         call param_value(params, t, val, msg)
         if (len(msg) > 0) call error_at_field(file, blk, ic, k, w, fname, msg, error)
         return                      ! (the *PARAMETER value passed the range check below)
      end if
      call parse_real(t, val, ok)
      if (.not. ok) then
         call error_at_field(file, blk, ic, k, w, fname, bad_number_msg(blk, ic, k, w, t), error)
      else if (.not. ieee_is_finite(val) .or. abs(val) > REAL_FIELD_MAX) then
         call error_at_field(file, blk, ic, k, w, fname, 'value '//t//' is out of range: '// &
            'a real field must not exceed '//rstr(REAL_FIELD_MAX, 2)//' in magnitude (the '// &
            'largest double / 1e6; larger values overflow in the computation)', error)
      else
         call check_boundaries(file, blk, ic, k, w, fname, error)
      end if
   end subroutine field_real

   !> A valid number can still be the front of a value that ran over its columns
   !> ('   123456789012' read as 1234567 and 89012). In fixed format digits (or '.') on both
   !> sides of the boundary between fields j and j+1 are one number running across it,
   !> which is legal only when one of the two fields is full (packed full-width values
   !> such as '1.0000E+001.0000E+00'); otherwise it is an error, checked at both ends of
   !> field k. A letter or a sign at the boundary starts a new token ('0.004I', '1.0-3').
   subroutine check_boundaries(file, blk, ic, k, w, fname, error)
      character(*), intent(in) :: file
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
      if (bad) call error_at_field(file, blk, ic, k, w, fname, 'a value runs across the '// &
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
   subroutine field_str(file, params, blk, ic, k, w, text)
      character(*), intent(in) :: file
      type(param_t), intent(in) :: params(:)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(:), allocatable, intent(out) :: text
      integer :: col, j
      call field_text(blk, ic, k, w, text, col)
      text = trim(adjustl(text))
      if (len(text) > 1) then
         if (text(1:1) == '&') then
            j = find_param(params, upper(text(2:)))
            if (j > 0) then
               if (params(j)%kind == 'C') text = params(j)%text
            end if
         end if
      end if
   end subroutine field_str

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

   subroutine param_value(params, t, v, msg)
      type(param_t), intent(in) :: params(:)
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
      j = find_param(params, name)
      if (j == 0) then
         msg = 'parameter '''//name//''' is not defined (*PARAMETER)'
      else if (params(j)%kind == 'C') then
         msg = 'character parameter '''//name//''' used in a numeric field'
      else
         v = params(j)%value
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
      ok = ios == 0                  ! an overflow to Inf is the caller's range error
   end subroutine parse_real

   ! ----------------------------------------------------------------------------------------
   ! messages

   !> "file:line" of card ic (0 or missing: the keyword line)
   function where_card(file, blk, ic) result(s)
      character(*), intent(in) :: file
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(:), allocatable :: s
      if (ic >= 1 .and. ic <= blk%n) then
         s = file//':'//str(blk%cards(ic)%line)
      else
         s = file//':'//str(blk%line)
      end if
   end function where_card

   !> Error at field k of card ic: file:line:col: *KEY: field NAME: what, card, caret.
   subroutine error_at_field(file, blk, ic, k, w, fname, what, error)
      character(*), intent(in) :: file
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, what
      type(error_t), allocatable, intent(inout) :: error
      character(:), allocatable :: t
      integer :: col
      call field_text(blk, ic, k, w, t, col)
      if (ic < 1 .or. ic > blk%n) then
         call set_error(error, where_card(file, blk, ic)//': *'//blk%name//': field '// &
                        fname//': '//what, EXIT_INPUT)
         return
      end if
      call set_error(error, where_card(file, blk, ic)//':'//str(col)//': *'//blk%name// &
         ': field '//fname//': '//what//new_line('a')//blk%cards(ic)%text//new_line('a')// &
         repeat(' ', col - 1)//'^', EXIT_INPUT)
   end subroutine error_at_field

   !> Error about card ic as a whole (0: the keyword line): file:line: *KEY: what.
   subroutine error_at_card(file, blk, ic, what, error)
      character(*), intent(in) :: file
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      if (ic >= 1 .and. ic <= blk%n) then
         call set_error(error, where_card(file, blk, ic)//': *'//blk%name//': '//what// &
                        new_line('a')//blk%cards(ic)%text, EXIT_INPUT)
      else
         call set_error(error, where_card(file, blk, ic)//': *'//blk%name//': '//what, &
                        EXIT_INPUT)
      end if
   end subroutine error_at_card

   !> Error about the keyword (line of the keyword, or of card ic when ic > 0), no card shown.
   subroutine error_at_block(file, blk, ic, what, error)
      character(*), intent(in) :: file
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      call set_error(error, where_card(file, blk, ic)//': *'//blk%name//': '//what, &
                     EXIT_INPUT)
   end subroutine error_at_block

   !> Error when the block has more than nmax cards (a card dynx would otherwise ignore).
   subroutine max_cards_check(file, blk, nmax, error)
      character(*), intent(in) :: file
      type(block_t), intent(in) :: blk
      integer, intent(in) :: nmax
      type(error_t), allocatable, intent(inout) :: error
      if (blk%n > nmax) call error_at_card(file, blk, nmax + 1, 'unexpected card '// &
         str(nmax + 1)//' (this keyword takes '//str(nmax)//' card(s) here)', error)
   end subroutine max_cards_check
end module dx_card_fields
