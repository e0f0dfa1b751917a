!> The echo of a deck as the reader reads it, for the d3hsp file (LS-DYNA's d3hsp: "the
!> input echo with every default made explicit", keyword manual vol. I, *CONTROL_OUTPUT):
!> every keyword block read (with its file and line) and, under it, every field a reader
!> took from it through the card cursor (dx_card's int/real, and so id, list_id, zero, ...)
!> with its value and whether it came from the deck or is the reader's default (a blank or
!> missing field). The cursor calls echo_field as it reads, so the echo is what the reader
!> did, not a copy of its tables that could drift.
!> Long blocks (a *NODE or *ELEMENT list, a curve) show their first ECHO_CARDS data cards and
!> then count the rest; blocks read without the cursor (bulk lists, dx_deck_cards' get_int)
!> are listed with their card count.
!> No paper; the format is dynx's own (docs/toolbox.md, "d3hsp and messages").
module dx_card_echo
   use dx_strings, only: str
   implicit none
   private
   public :: echo_t, ECHO_CARDS

   integer, parameter :: ECHO_CARDS = 8    !< data cards echoed field by field per block

   type :: echo_t
      character(:), allocatable :: buf      !< the text (buf(1:n))
      integer :: n = 0
      integer :: nblocks = 0, nfields = 0, ndefault = 0
      integer :: bfile = -1, bline = -1     !< the block being echoed (file index, line)
      integer :: ic = -1                    !< its card echoed last
      integer :: nshown = 0, nmore = 0      !< its cards echoed, its cards counted only
      integer :: ncards = 0                 !< its card count
   contains
      procedure :: block => echo_block      !< a keyword block starts (once per block)
      procedure :: field => echo_field      !< a field read by the cursor
      procedure :: text => echo_text        !< the whole echo (closes the last block)
   end type echo_t

contains

   subroutine put(e, line)
      class(echo_t), intent(inout) :: e
      character(*), intent(in) :: line
      character(:), allocatable :: t
      integer :: need
      if (.not. allocated(e%buf)) allocate(character(65536) :: e%buf)
      need = e%n + len(line) + 1
      if (need > len(e%buf)) then
         allocate(character(max(need, 2*len(e%buf))) :: t)
         t(1:e%n) = e%buf(1:e%n)
         call move_alloc(t, e%buf)
      end if
      e%buf(e%n + 1:e%n + len(line)) = line
      e%buf(need:need) = new_line('a')
      e%n = need
   end subroutine put

   !> The end of the block echoed so far: how many of its cards were not shown.
   subroutine close_block(e)
      class(echo_t), intent(inout) :: e
      if (e%bline < 0) return
      if (e%nmore > 0) call put(e, '    ... '//str(e%nmore)//' more card(s) read, not '// &
                                'echoed (the first '//str(ECHO_CARDS)//' are)')
      e%bline = -1
   end subroutine close_block

   !> Block name (upper case, no '*'), in file (index ifile, path) at line, ncards cards
   !> (title or id card included). Nothing when it is the block echoed last.
   subroutine echo_block(e, name, ifile, file, line, ncards)
      class(echo_t), intent(inout) :: e
      character(*), intent(in) :: name, file
      integer, intent(in) :: ifile, line, ncards
      if (ifile == e%bfile .and. line == e%bline) return
      call close_block(e)
      e%nblocks = e%nblocks + 1
      e%bfile = ifile
      e%bline = line
      e%ic = -1
      e%nshown = 0
      e%nmore = 0
      e%ncards = ncards
      call put(e, '')
      call put(e, '*'//name//repeat(' ', max(1, 40 - len(name)))//'('//file//':'// &
               str(line)//', '//str(ncards)//' card(s))')
   end subroutine echo_block

   !> Field name on card ic (at file line cline; 0: the card is not in the deck) read as
   !> value (text); dflt: the field was blank or missing and the reader's default was taken.
   subroutine echo_field(e, ic, cline, name, value, dflt)
      class(echo_t), intent(inout) :: e
      integer, intent(in) :: ic, cline
      character(*), intent(in) :: name, value
      logical, intent(in) :: dflt
      character(:), allocatable :: line
      if (ic /= e%ic) then
         e%ic = ic
         if (e%nshown >= ECHO_CARDS) then
            e%nmore = e%nmore + 1
         else
            e%nshown = e%nshown + 1
            if (cline > 0) then
               call put(e, '    card '//str(ic)//' (line '//str(cline)//')')
            else
               call put(e, '    card '//str(ic)//' (not in the deck: all defaults)')
            end if
         end if
      end if
      if (e%nmore > 0) return
      e%nfields = e%nfields + 1
      line = '      '//name//repeat(' ', max(1, 10 - len(name)))//'= '//value
      if (dflt) then
         e%ndefault = e%ndefault + 1
         line = line//repeat(' ', max(1, 38 - len(line)))//'default'
      end if
      call put(e, line)
   end subroutine echo_field

   !> The echo so far, the last block closed.
   function echo_text(e) result(t)
      class(echo_t), intent(inout) :: e
      character(:), allocatable :: t
      call close_block(e)
      t = ''
      if (allocated(e%buf)) t = e%buf(1:e%n)
   end function echo_text
end module dx_card_echo
