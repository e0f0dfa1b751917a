!> Readers for *SET_NODE_LIST, *SET_PART_LIST (SID DA1..DA4 SOLVER, then ids 8 per card,
!> zeros skipped) and *SET_SEGMENT (SID DA1..DA4, then N1 N2 N3 N4 A1..A4 per segment;
!> N4 blank or equal to N3 makes a triangle), each with the _TITLE option.
!> LS-DYNA Keyword User's Manual, Vol. I, *SET.
module dx_read_sets
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_deck_cards, only: deck_t, block_t, get_int, field_error, block_error, &
                            std_widths, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, label_list_t, segment_list_t
   implicit none
   private
   public :: register_sets

contains

   !> Add the *SET_* keywords to the registry.
   subroutine register_sets(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('SET_NODE_LIST', read_set_list, title=.true.)
      call reg%add('SET_PART_LIST', read_set_list, title=.true.)
      call reg%add('SET_SEGMENT', read_set_segment, title=.true.)
   end subroutine register_sets

   subroutine read_set_list(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), i0, ic, k, id, n
      integer, allocatable :: ids(:)
      type(label_list_t) :: s
      character(:), allocatable :: what
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      what = merge('NID', 'PID', blk%base == 'SET_NODE_LIST')
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (SID DA1 DA2 DA3 DA4 SOLVER)', error)
         return
      end if
      call get_int(deck, blk, i0, 1, w, 'SID', 0, s%label, error)
      if (allocated(error)) return
      if (s%label <= 0) then
         call field_error(deck, blk, i0, 1, w, 'SID', 'set id must be > 0, got '// &
                          str(s%label), error)
         return
      end if
      allocate(ids(8*(blk%n - i0)))
      n = 0
      do ic = i0 + 1, blk%n
         do k = 1, 8
            call get_int(deck, blk, ic, k, w, what//str(k), 0, id, error)
            if (allocated(error)) return
            if (id < 0) then
               call field_error(deck, blk, ic, k, w, what//str(k), 'must be >= 0', error)
               return
            end if
            if (id > 0) then
               n = n + 1
               ids(n) = id
            end if
         end do
      end do
      s%ids = ids(1:n)
      s%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      if (blk%base == 'SET_NODE_LIST') then
         inp%node_sets = [inp%node_sets, s]
      else
         inp%part_sets = [inp%part_sets, s]
      end if
   end subroutine read_set_list

   subroutine read_set_segment(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), i0, ic, k, n
      type(segment_list_t) :: s
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (SID DA1 DA2 DA3 DA4)', error)
         return
      end if
      call get_int(deck, blk, i0, 1, w, 'SID', 0, s%label, error)
      if (allocated(error)) return
      if (s%label <= 0) then
         call field_error(deck, blk, i0, 1, w, 'SID', 'set id must be > 0, got '// &
                          str(s%label), error)
         return
      end if
      allocate(s%seg(4, blk%n - i0))
      n = 0
      do ic = i0 + 1, blk%n
         n = n + 1
         do k = 1, 4
            call get_int(deck, blk, ic, k, w, 'N'//str(k), 0, s%seg(k, n), error)
            if (allocated(error)) return
            if (k <= 3 .and. s%seg(k, n) <= 0) then
               call field_error(deck, blk, ic, k, w, 'N'//str(k), 'node id must be > 0', error)
               return
            end if
         end do
         if (s%seg(4, n) == 0) s%seg(4, n) = s%seg(3, n)
      end do
      s%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      inp%segment_sets = [inp%segment_sets, s]
   end subroutine read_set_segment
end module dx_read_sets
