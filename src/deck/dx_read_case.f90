!> *CASE: the load cases of a multi-case deck (LS-DYNA Keyword User's Manual Vol. I, *CASE;
!> Oasys PRIMER's "*CASE" notes for how LS-DYNA runs them). Card 1 CASEID (I10) JOBID (A70);
!> then any number of cards, each either the case's command-line arguments (COMMANDS) or a
!> list of subcase ids SCID1..SCID8 (the *CASE_BEGIN_n ... *CASE_END_n blocks, or keywords
!> with CID=n on their keyword line, that the case includes; dx_deck_cards tags the blocks
!> through dx_deck_subcase, which also splits this module's card tokens).
!> LS-DYNA runs every case one after another, each with the keywords outside any subcase
!> plus its own subcases, and names its files after JOBID. dynx (dx_launch) runs each case
!> as its own run in OUTDIR/JOBID (blank JOBID: caseCASEID); `--case ID` runs one case.
!> COMMANDS: LS-DYNA's memory=, memory2= and ncpu= are accepted (they change nothing in
!> dynx, as on dynx's own command line); any other argument is an error naming it.
module dx_read_case
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, lower
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, read_cards
   use dx_deck_registry, only: registry_t
   use dx_deck_subcase, only: next_token
   use dx_model_input, only: model_input_t
   implicit none
   private
   public :: register_case, case_def_t, deck_cases, case_list_text

   !> one *CASE
   type :: case_def_t
      integer :: id = 0
      character(:), allocatable :: jobid   !< the case's name: its output folder
      integer, allocatable :: scids(:)      !< the subcases it includes
      character(:), allocatable :: where    !< file:line of its *CASE
   end type case_def_t

contains

   subroutine register_case(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CASE', read_case_block)
   end subroutine register_case

   !> The registry's reader: the cards are checked (the cases were read before the run by
   !> deck_cases; nothing of them goes into the model).
   subroutine read_case_block(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(case_def_t) :: d
      call parse_case(deck, blk, d, error)
   end subroutine read_case_block

   !> The *CASE definitions of the deck at path, in deck order (none: a one-case deck).
   !> A subcase block no case includes, a repeated CASEID or JOBID is an error.
   subroutine deck_cases(path, cases, error)
      character(*), intent(in) :: path
      type(case_def_t), allocatable, intent(out) :: cases(:)
      type(error_t), allocatable, intent(out) :: error
      type(deck_t) :: deck
      type(case_def_t) :: d
      integer :: ib, k
      allocate(cases(0))
      call read_cards(path, deck, error)
      if (allocated(error)) return
      do ib = 1, deck%nblocks
         if (deck%blocks(ib)%name /= 'CASE') cycle
         call parse_case(deck, deck%blocks(ib), d, error)
         if (allocated(error)) return
         do k = 1, size(cases)
            if (cases(k)%id == d%id .or. cases(k)%jobid == d%jobid) then
               call set_error(error, d%where//': *CASE: '//merge('CASEID', 'JOBID ', &
                  cases(k)%id == d%id)//' of case '//str(d%id)//' ('//d%jobid//') is '// &
                  'already used by the case at '//cases(k)%where)
               return
            end if
         end do
         cases = [cases, d]
      end do
      if (size(cases) == 0 .and. deck%has_subcases) then
         do ib = 1, deck%nblocks
            if (deck%blocks(ib)%scid == 0) cycle
            call set_error(error, deck%files(deck%blocks(ib)%ifile)%s//':'// &
               str(deck%blocks(ib)%line)//': *'//deck%blocks(ib)%name//' belongs to '// &
               'subcase '//str(deck%blocks(ib)%scid)//' but the deck has no *CASE that '// &
               'runs it (dynx never merges subcases into one run)')
            return
         end do
      end if
      do ib = 1, deck%nblocks
         if (deck%blocks(ib)%scid == 0) cycle
         if (any([(any(cases(k)%scids == deck%blocks(ib)%scid), k = 1, size(cases))])) cycle
         call set_error(error, deck%files(deck%blocks(ib)%ifile)%s//':'// &
            str(deck%blocks(ib)%line)//': *'//deck%blocks(ib)%name//' belongs to '// &
            'subcase '//str(deck%blocks(ib)%scid)//', which no *CASE lists (SCID1-8): '// &
            'it would never be read')
         return
      end do
   end subroutine deck_cases

   !> "101 LOW_VELOCITY (subcases 1), 102 ..." for messages.
   function case_list_text(cases) result(s)
      type(case_def_t), intent(in) :: cases(:)
      character(:), allocatable :: s
      integer :: k, j
      s = ''
      do k = 1, size(cases)
         if (k > 1) s = s//', '
         s = s//str(cases(k)%id)//' '//cases(k)%jobid//' (subcases'
         do j = 1, size(cases(k)%scids)
            s = s//' '//str(cases(k)%scids(j))
         end do
         if (size(cases(k)%scids) == 0) s = s//' none'
         s = s//')'
      end do
   end function case_list_text

   !> One *CASE block: CASEID > 0, JOBID a folder name (letters, digits, '_', '-', '.'),
   !> then COMMANDS and SCID cards in any order.
   subroutine parse_case(deck, blk, d, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(case_def_t), intent(out) :: d
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      character(:), allocatable :: t, tok
      integer :: ic, k, n, ios
      character(len=*), parameter :: NAMECH = 'abcdefghijklmnopqrstuvwxyz'// &
         'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.'
      d%where = deck%files(blk%ifile)%s//':'//str(blk%line)
      allocate(d%scids(0))
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (CASEID JOBID)')
      call c%int('CASEID', 0, d%id, min=1)
      if (c%ok()) call c%text_field(2, [10, 70], d%jobid)
      if (c%ok()) then
         if (len(d%jobid) == 0) d%jobid = 'case'//str(d%id)
         if (verify(d%jobid, NAMECH) /= 0 .or. d%jobid(1:1) == '.') &
            call c%fail('JOBID', 'the case''s output folder name may hold letters, digits, '// &
                        '''_'', ''-'' and ''.'' only (and not start with ''.''), got '''// &
                        d%jobid//'''')
      end if
      ic = 1
      do while (c%ok() .and. ic < blk%n)
         ic = ic + 1
         call c%seek(ic)
         t = trim(adjustl(blk%cards(ic)%text))
         if (len(t) == 0) cycle
         if (verify(t, ' ,0123456789') == 0) then        ! SCID1..SCID8
            do while (len(t) > 0)
               call next_token(t, tok, commas=.true.)
               if (len(tok) == 0) exit
               read(tok, *, iostat=ios) n
               if (ios /= 0 .or. n <= 0) then
                  call c%fail_card(ic, 'SCID: a subcase id must be a positive integer, got '// &
                                   tok)
                  exit
               end if
               if (.not. any(d%scids == n)) d%scids = [d%scids, n]
            end do
         else                                            ! COMMANDS
            do while (len(t) > 0 .and. c%ok())
               call next_token(t, tok, commas=.true.)
               if (len(tok) == 0) exit
               k = index(tok, '=')
               if (k > 1) then
                  if (lower(tok(1:k)) == 'memory=' .or. lower(tok(1:k)) == 'memory2=' .or. &
                      lower(tok(1:k)) == 'ncpu=') cycle
               end if
               call c%fail_card(ic, 'COMMANDS: the case''s command-line argument '''//tok// &
                  ''' is not supported by dynx (accepted: memory=, memory2=, ncpu=, which '// &
                  'change nothing in dynx)')
            end do
         end if
      end do
      call c%done(error)
   end subroutine parse_case
end module dx_read_case
