!> Readers for the restart-dump requests *DATABASE_BINARY_D3DUMP and
!> *DATABASE_BINARY_RUNRSF (LS-DYNA Keyword User's Manual Vol. I, *DATABASE_BINARY_OPTION):
!> card 1 CYCL NR BEAM NPLTC PSETID. CYCL: cycles between dumps (0: none; LS-DYNA also
!> reads CYCL < 0 as a curve of intervals, not supported); NR: for RUNRSF the number of
!> running restart files written in rotation (default 1: one file overwritten); BEAM,
!> NPLTC, PSETID concern plot databases only and must be blank or 0 here.
module dx_read_restart
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_log, only: log_warn
   use dx_deck_cards, only: deck_t, block_t, get_int, field_error, block_error, &
                            std_widths, check_max_cards
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t
   implicit none
   private
   public :: register_restart

contains

   subroutine register_restart(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('DATABASE_BINARY_D3DUMP', read_dump_request)
      call reg%add('DATABASE_BINARY_RUNRSF', read_dump_request)
   end subroutine register_restart

   subroutine read_dump_request(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), cycl, nr, k, v
      character(len=6), parameter :: unused(3) = ['BEAM  ', 'NPLTC ', 'PSETID']
      w = std_widths(blk, 8)
      if (blk%n < 1) then
         call block_error(deck, blk, 0, 'missing card 1 (CYCL NR BEAM NPLTC PSETID)', error)
         return
      end if
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_int(deck, blk, 1, 1, w, 'CYCL', 0, cycl, error)
      if (allocated(error)) return
      if (cycl < 0) then
         call field_error(deck, blk, 1, 1, w, 'CYCL', 'CYCL < 0 (a curve of dump '// &
                          'intervals) is not supported; give the cycles between dumps', error)
         return
      end if
      call get_int(deck, blk, 1, 2, w, 'NR', 0, nr, error)
      if (allocated(error)) return
      if (nr < 0 .or. nr > 99) then
         call field_error(deck, blk, 1, 2, w, 'NR', 'must be 0 to 99, got '//str(nr), error)
         return
      end if
      do k = 3, 5
         call get_int(deck, blk, 1, k, w, trim(unused(k - 2)), 0, v, error)
         if (allocated(error)) return
         if (v /= 0) then
            call field_error(deck, blk, 1, k, w, trim(unused(k - 2)), 'applies to plot '// &
                             'databases only; leave it blank for restart dumps', error)
            return
         end if
      end do
      if (blk%base == 'DATABASE_BINARY_D3DUMP') then
         ! LS-DYNA counts running restart files with NR only for RUNRSF; each d3dump is a
         ! new file (d3dump01, 02, ...), so NR has nothing to act on here
         if (nr /= 0) call log_warn(deck%files(blk%ifile)%s//':'//str(blk%cards(1)%line)// &
            ': *DATABASE_BINARY_D3DUMP NR = '//str(nr)//' has no effect: NR counts the '// &
            'running restart files of *DATABASE_BINARY_RUNRSF; every d3dump is a new file')
         inp%rst%d3dump_cycl = cycl
      else
         inp%rst%runrsf_cycl = cycl
         inp%rst%runrsf_nr = max(1, nr)
      end if
   end subroutine read_dump_request
end module dx_read_restart
