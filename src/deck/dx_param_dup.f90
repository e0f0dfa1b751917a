!> *PARAMETER_DUPLICATION (LS-DYNA Keyword User's Manual Vol. I, *PARAMETER_DUPLICATION):
!> DFLAG, what a redefinition of a *PARAMETER / *PARAMETER_EXPRESSION name does: 1 warn and
!> keep the first definition, 2 warn and take the new one, 3 error, 4 take the new one
!> silently, 5 keep the first silently. Without that keyword (dflag 0) the new one replaces
!> silently (dynx's rule before the keyword existed). dx_deck_cards keeps the table.
module dx_param_dup
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_card, only: block_t, param_t, std_widths, field_int, error_at_field, error_at_card
   implicit none
   private
   public :: read_dflag, redefine_param

contains

   !> *PARAMETER_DUPLICATION block blk of file path (params: the parameters defined so far):
   !> one card, DFLAG (I10, default 1; 1 to 5). It governs the parameter definitions that
   !> follow it in the deck; a later *PARAMETER_DUPLICATION replaces it. dflag is set only
   !> when the block is good.
   subroutine read_dflag(path, params, blk, dflag, error)
      character(*), intent(in) :: path
      type(param_t), intent(in) :: params(:)
      type(block_t), intent(in) :: blk
      integer, intent(inout) :: dflag
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), v
      w = std_widths(blk, 8)
      v = 1
      if (blk%n > 1) then
         call error_at_card(path, blk, 2, 'one card expected (DFLAG), found '//str(blk%n), &
                            error)
         return
      end if
      if (blk%n == 1) then
         call field_int(path, params, blk, 1, 1, w, 'DFLAG', 1, v, error)
         if (allocated(error)) return
         if (v == 0) v = 1
         if (v < 1 .or. v > 5) then
            call error_at_field(path, blk, 1, 1, w, 'DFLAG', 'expected 1 to 5 (1 warn and '// &
               'keep the first, 2 warn and replace, 3 error, 4 replace, 5 keep the first), '// &
               'got '//str(v), error)
            return
         end if
         if (len_trim(blk%cards(1)%text) > w(1)) then
            call error_at_card(path, blk, 1, 'only DFLAG (columns 1-'//str(w(1))// &
               ') is read; the rest of the card must be blank', error)
            return
         end if
      end if
      dflag = v
   end subroutine read_dflag

   !> Parameter name is defined again under dflag: replace (take the new definition), note
   !> (the warning text, or the error text when bad), else ''.
   subroutine redefine_param(dflag, name, replace, note, bad)
      integer, intent(in) :: dflag
      character(*), intent(in) :: name
      logical, intent(out) :: replace
      character(:), allocatable, intent(out) :: note
      logical, intent(out) :: bad
      note = ''
      bad = .false.
      replace = .false.
      select case (dflag)
      case (1)
         note = 'parameter '//name//' is defined again; the first definition is kept '// &
                '(*PARAMETER_DUPLICATION DFLAG = 1)'
      case (2)
         note = 'parameter '//name//' is defined again; the new definition replaces '// &
                'the first (*PARAMETER_DUPLICATION DFLAG = 2)'
         replace = .true.
      case (3)
         note = 'parameter '//name//' is defined again, an error with '// &
                '*PARAMETER_DUPLICATION DFLAG = 3'
         bad = .true.
      case (5)
         continue
      case default   ! 0 (no keyword) and 4
         replace = .true.
      end select
   end subroutine redefine_param
end module dx_param_dup
