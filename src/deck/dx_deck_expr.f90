!> The arithmetic expressions of *PARAMETER_EXPRESSION: numbers, the parameters defined
!> before (by name, with or without '&'), + - * / and ** (or ^, right-associative, above
!> unary minus as in Fortran), parentheses and the functions of the LS-DYNA Keyword User's
!> Manual's list that decks use: sin cos tan asin acos atan atan2 sinh cosh tanh sqrt exp
!> log log10 abs sign min max mod int nint aint. A recursive-descent parser (expression =
!> term {(+|-) term}; term = factor {(*|/) factor}; factor = [-|+] power; power = primary
!> [** factor]); an error says what was expected where.
module dx_deck_expr
   use dx_kinds, only: wp
   use dx_strings, only: upper, str
   use dx_card, only: param_t, find_param
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: eval_expression

   type :: parser_t
      character(:), allocatable :: s
      integer :: p = 1
      character(:), allocatable :: msg
   end type parser_t

contains

   !> Value of expression text with the parameters params; msg = '' when it is valid.
   subroutine eval_expression(text, params, val, msg)
      character(*), intent(in) :: text
      type(param_t), intent(in) :: params(:)
      real(wp), intent(out) :: val
      character(:), allocatable, intent(out) :: msg
      type(parser_t) :: ps
      ps%s = trim(text)
      ps%p = 1
      ps%msg = ''
      val = expr(ps, params)
      if (len(ps%msg) == 0) then
         call skip(ps)
         if (ps%p <= len(ps%s)) ps%msg = 'unexpected '''//ps%s(ps%p:)//''''
      end if
      if (len(ps%msg) == 0 .and. .not. ieee_is_finite(val)) ps%msg = 'the value is not finite'
      msg = ps%msg
      if (len(msg) > 0) val = 0.0_wp
   end subroutine eval_expression

   subroutine skip(ps)
      type(parser_t), intent(inout) :: ps
      do while (ps%p <= len(ps%s))
         if (ps%s(ps%p:ps%p) /= ' ') exit
         ps%p = ps%p + 1
      end do
   end subroutine skip

   !> the next character ('' at the end), after blanks
   function peek(ps) result(c)
      type(parser_t), intent(inout) :: ps
      character(:), allocatable :: c
      call skip(ps)
      c = ''
      if (ps%p <= len(ps%s)) c = ps%s(ps%p:ps%p)
   end function peek

   recursive function expr(ps, params) result(v)
      type(parser_t), intent(inout) :: ps
      type(param_t), intent(in) :: params(:)
      real(wp) :: v, w
      character(:), allocatable :: c
      v = term(ps, params)
      do while (len(ps%msg) == 0)
         c = peek(ps)
         if (c /= '+' .and. c /= '-') exit
         ps%p = ps%p + 1
         w = term(ps, params)
         if (c == '+') then
            v = v + w
         else
            v = v - w
         end if
      end do
   end function expr

   recursive function term(ps, params) result(v)
      type(parser_t), intent(inout) :: ps
      type(param_t), intent(in) :: params(:)
      real(wp) :: v, w
      character(:), allocatable :: c
      v = factor(ps, params)
      do while (len(ps%msg) == 0)
         c = peek(ps)
         if (c /= '*' .and. c /= '/') exit
         if (ps%p < len(ps%s)) then
            if (ps%s(ps%p:ps%p + 1) == '**') exit      ! a power, handled below
         end if
         ps%p = ps%p + 1
         w = factor(ps, params)
         if (c == '*') then
            v = v*w
         else if (w == 0.0_wp) then
            if (len(ps%msg) == 0) ps%msg = 'division by zero'
         else
            v = v/w
         end if
      end do
   end function term

   recursive function factor(ps, params) result(v)
      type(parser_t), intent(inout) :: ps
      type(param_t), intent(in) :: params(:)
      real(wp) :: v
      character(:), allocatable :: c
      c = peek(ps)
      if (c == '-' .or. c == '+') then
         ps%p = ps%p + 1
         v = factor(ps, params)
         if (c == '-') v = -v
         return
      end if
      v = power(ps, params)
   end function factor

   recursive function power(ps, params) result(v)
      type(parser_t), intent(inout) :: ps
      type(param_t), intent(in) :: params(:)
      real(wp) :: v, w
      character(:), allocatable :: c
      v = primary(ps, params)
      if (len(ps%msg) > 0) return
      c = peek(ps)
      if (c == '^') then
         ps%p = ps%p + 1
      else if (c == '*' .and. ps%p < len(ps%s)) then
         if (ps%s(ps%p:ps%p + 1) /= '**') return
         ps%p = ps%p + 2
      else
         return
      end if
      w = factor(ps, params)
      if (len(ps%msg) > 0) return
      if (v < 0.0_wp .and. w /= anint(w)) then
         ps%msg = 'a negative number to a non-integral power'
      else if (w == anint(w) .and. abs(w) < 1.0e9_wp) then
         v = v**nint(w)
      else
         v = v**w
      end if
   end function power

   recursive function primary(ps, params) result(v)
      type(parser_t), intent(inout) :: ps
      type(param_t), intent(in) :: params(:)
      real(wp) :: v
      character(:), allocatable :: c, name
      integer :: a, ios, j, nargs
      real(wp) :: args(2)
      v = 0.0_wp
      c = peek(ps)
      if (len(c) == 0) then
         ps%msg = 'the expression ends where a value is expected'
         return
      end if
      if (c == '(') then
         ps%p = ps%p + 1
         v = expr(ps, params)
         if (len(ps%msg) > 0) return
         if (peek(ps) /= ')') then
            ps%msg = 'expected '')'' at column '//str(ps%p)
            return
         end if
         ps%p = ps%p + 1
         return
      end if
      a = ps%p
      if (index('0123456789.', c) > 0) then
         ! digits [. digits] [(e|d) [sign] digits]
         do while (ps%p <= len(ps%s))
            if (index('0123456789.', ps%s(ps%p:ps%p)) == 0) exit
            ps%p = ps%p + 1
         end do
         if (ps%p <= len(ps%s)) then
            if (index('eEdD', ps%s(ps%p:ps%p)) > 0) then
               ps%p = ps%p + 1
               if (ps%p <= len(ps%s)) then
                  if (index('+-', ps%s(ps%p:ps%p)) > 0) ps%p = ps%p + 1
               end if
               do while (ps%p <= len(ps%s))
                  if (index('0123456789', ps%s(ps%p:ps%p)) == 0) exit
                  ps%p = ps%p + 1
               end do
            end if
         end if
         name = ps%s(a:ps%p - 1)
         do j = 1, len(name)
            if (name(j:j) == 'd' .or. name(j:j) == 'D') name(j:j) = 'e'
         end do
         read(name, *, iostat=ios) v
         if (ios /= 0) ps%msg = 'bad number '''//ps%s(a:ps%p - 1)//''''
         return
      end if
      if (c == '&') ps%p = ps%p + 1
      a = ps%p
      do while (ps%p <= len(ps%s))
         if (verify(upper(ps%s(ps%p:ps%p)), 'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_') /= 0) exit
         ps%p = ps%p + 1
      end do
      if (ps%p == a) then
         ps%msg = 'unexpected '''//ps%s(a:)//''''
         return
      end if
      name = upper(ps%s(a:ps%p - 1))
      if (peek(ps) == '(') then                 ! a function call
         ps%p = ps%p + 1
         nargs = 0
         do
            nargs = nargs + 1
            if (nargs > 2) then
               ps%msg = name//': too many arguments'
               return
            end if
            args(nargs) = expr(ps, params)
            if (len(ps%msg) > 0) return
            c = peek(ps)
            if (c == ',') then
               ps%p = ps%p + 1
               cycle
            end if
            if (c /= ')') then
               ps%msg = 'expected '')'' after the arguments of '//name
               return
            end if
            ps%p = ps%p + 1
            exit
         end do
         call apply(ps, name, args(1:nargs), v)
         return
      end if
      if (name == 'PI') then
         j = find_param(params, name)
         v = acos(-1.0_wp)
         if (j > 0) v = params(j)%value
         return
      end if
      j = find_param(params, name)
      if (j == 0) then
         ps%msg = 'parameter '''//name//''' is not defined (before this card)'
      else if (params(j)%kind == 'C') then
         ps%msg = 'character parameter '''//name//''' in an expression'
      else
         v = params(j)%value
      end if
   end function primary

   subroutine apply(ps, name, x, v)
      type(parser_t), intent(inout) :: ps
      character(*), intent(in) :: name
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: v
      integer :: need
      v = 0.0_wp
      select case (name)
      case ('ATAN2', 'MIN', 'MAX', 'MOD', 'SIGN')
         need = 2
      case ('SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN', 'SINH', 'COSH', 'TANH', 'SQRT', &
            'EXP', 'LOG', 'LOG10', 'ABS', 'INT', 'NINT', 'AINT')
         need = 1
      case default
         ps%msg = 'unknown function '''//name//''''
         return
      end select
      if (size(x) /= need) then
         ps%msg = name//' takes '//str(need)//' argument(s)'
         return
      end if
      select case (name)
      case ('SIN'); v = sin(x(1))
      case ('COS'); v = cos(x(1))
      case ('TAN'); v = tan(x(1))
      case ('ASIN', 'ACOS')
         if (abs(x(1)) > 1.0_wp) then
            ps%msg = name//' of a value outside [-1, 1]'; return
         end if
         v = merge(asin(x(1)), acos(x(1)), name == 'ASIN')
      case ('ATAN'); v = atan(x(1))
      case ('SINH'); v = sinh(x(1))
      case ('COSH'); v = cosh(x(1))
      case ('TANH'); v = tanh(x(1))
      case ('SQRT')
         if (x(1) < 0.0_wp) then
            ps%msg = 'SQRT of a negative value'; return
         end if
         v = sqrt(x(1))
      case ('EXP'); v = exp(min(x(1), 700.0_wp))
      case ('LOG', 'LOG10')
         if (x(1) <= 0.0_wp) then
            ps%msg = name//' of a value <= 0'; return
         end if
         v = merge(log(x(1)), log10(x(1)), name == 'LOG')
      case ('ABS'); v = abs(x(1))
      case ('INT', 'AINT'); v = aint(x(1))
      case ('NINT'); v = anint(x(1))
      case ('ATAN2'); v = atan2(x(1), x(2))
      case ('MIN'); v = min(x(1), x(2))
      case ('MAX'); v = max(x(1), x(2))
      case ('SIGN'); v = sign(x(1), x(2))
      case ('MOD')
         if (x(2) == 0.0_wp) then
            ps%msg = 'MOD by zero'; return
         end if
         v = mod(x(1), x(2))
      end select
   end subroutine apply

end module dx_deck_expr
