!> *CASE subcase tagging of the deck reader, and the token splitter that dx_deck_cards
!> (keyword lines) and dx_read_case (*CASE cards) share.
!> *CASE_BEGIN_n opens subcase n (the blocks up to *CASE_END_n belong to it; no nesting),
!> *CASE_END_n closes it (LS-DYNA Keyword User's Manual Vol. I, *CASE). The reading of the
!> *CASE cards themselves is dx_read_case; this module sits below dx_deck_cards (which
!> dx_read_case uses), so it knows the open subcase by its numbers, not by the deck.
module dx_deck_subcase
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_model_input, only: string_t
   implicit none
   private
   public :: case_tag, next_token

contains

   !> Keyword name (CASE_BEGIN_n or CASE_END_n) read at files(ifile), line lineno: open or
   !> close subcase n. cur_scid: the open subcase (0: none), begun at files(scid_file),
   !> line scid_line.
   subroutine case_tag(files, name, ifile, lineno, cur_scid, scid_file, scid_line, error)
      type(string_t), intent(in) :: files(:)
      character(*), intent(in) :: name
      integer, intent(in) :: ifile, lineno
      integer, intent(inout) :: cur_scid, scid_file, scid_line
      type(error_t), allocatable, intent(out) :: error
      integer :: n, ios
      character(:), allocatable :: tail, here
      here = files(ifile)%s//':'//str(lineno)//': *'//name//': '
      tail = name(index(name, '_', back=.true.) + 1:)
      n = 0
      ios = 1
      if (len(tail) > 0 .and. verify(tail, '0123456789') == 0) read(tail, *, iostat=ios) n
      if (ios /= 0 .or. n <= 0) then
         call set_error(error, here//'the subcase number after the last _ must be a '// &
            'positive integer (*CASE_BEGIN_n ... *CASE_END_n)')
      else if (name(6:6) == 'B') then
         if (cur_scid /= 0) then
            call set_error(error, here//'subcase '//str(cur_scid)//' (begun at '// &
               files(scid_file)%s//':'//str(scid_line)//') is still open: '// &
               'close it with *CASE_END_'//str(cur_scid)//' first (no nesting)')
            return
         end if
         cur_scid = n
         scid_file = ifile
         scid_line = lineno
      else if (cur_scid /= n) then
         if (cur_scid == 0) then
            call set_error(error, here//'no *CASE_BEGIN_'//str(n)//' is open')
         else
            call set_error(error, here//'subcase '//str(cur_scid)//' is open (begun at '// &
               files(scid_file)%s//':'//str(scid_line)//'): close it with '// &
               '*CASE_END_'//str(cur_scid))
         end if
      else
         cur_scid = 0
      end if
   end subroutine case_tag

   !> Split off the next token of s: blank-separated, or with commas (commas = .true.)
   !> blank- or comma-separated with leading commas skipped.
   subroutine next_token(s, tok, commas)
      character(:), allocatable, intent(inout) :: s
      character(:), allocatable, intent(out) :: tok
      logical, intent(in), optional :: commas
      integer :: k
      logical :: c
      c = .false.
      if (present(commas)) c = commas
      s = trim(adjustl(s))
      do while (c .and. len(s) > 0)
         if (s(1:1) /= ',') exit
         s = trim(adjustl(s(2:)))
      end do
      if (c) then
         k = scan(s, ' ,')
      else
         k = index(s, ' ')
      end if
      if (k == 0) then
         tok = s
         s = ''
      else
         tok = s(1:k - 1)
         s = s(k + 1:)
      end if
   end subroutine next_token
end module dx_deck_subcase
