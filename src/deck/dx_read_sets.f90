!> Readers for *SET_NODE_LIST (alias *SET_NODE), *SET_PART_LIST (alias *SET_PART) (SID
!> DA1..DA4 SOLVER, then ids 8 per card, zeros skipped), *SET_SEGMENT (SID DA1..DA4, then
!> N1 N2 N3 N4 A1..A4 per segment; N4 blank or equal to N3 makes a triangle), and the
!> generated sets: *SET_NODE_LIST_GENERATE / *SET_PART_LIST_GENERATE (SID ..., then
!> B1BEG B1END .. B4BEG B4END: every defined id in the ranges) and *SET_NODE_GENERAL
!> (SID ..., then OPTION E1..E7 cards: ALL; NODE, PART, BOX, SET add the nodes given, of
!> the parts' elements, inside the *DEFINE_BOX boxes, of the node sets; DNODE, DPART,
!> DBOX, DSET remove them; applied in card order), each with the _TITLE option. Generated
!> sets are resolved after the whole deck (sets_finish): nodes, parts and boxes may come
!> later in the deck. LS-DYNA Keyword User's Manual, Vol. I, *SET.
module dx_read_sets
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, upper
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, origin_t, label_list_t, segment_list_t, &
                             set_gen_in_t, set_step_in_t
   use dx_label_map, only: label_map_t
   use dx_deck_buffers, only: set_step_buffer_t
   implicit none
   private
   public :: register_sets, sets_finish

contains

   !> Add the *SET_* keywords to the registry.
   subroutine register_sets(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('SET_NODE_LIST', read_set_list, title=.true.)
      call reg%add('SET_PART_LIST', read_set_list, title=.true.)
      call reg%add('SET_SEGMENT', read_set_segment, title=.true.)
      call reg%add('SET_NODE', read_set_list, title=.true.)
      call reg%add('SET_PART', read_set_list, title=.true.)
      call reg%add('SET_NODE_LIST_GENERATE', read_set_generate, title=.true.)
      call reg%add('SET_PART_LIST_GENERATE', read_set_generate, title=.true.)
      call reg%add('SET_NODE_GENERAL', read_set_general, title=.true.)
   end subroutine register_sets

   subroutine read_set_list(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i0, ic, k, n
      integer, allocatable :: ids(:)
      type(label_list_t) :: s
      type(card_t) :: c
      character(:), allocatable :: what
      i0 = data_start(blk)
      what = merge('NID', 'PID', is_node_set(blk%base))
      call deck_cursor(deck, blk, c)
      call read_sid(c, i0, s%label)
      call c%done(error)
      if (allocated(error)) return
      allocate(ids(8*(blk%n - i0)))
      n = 0
      do ic = i0 + 1, blk%n
         call c%seek(ic)
         do k = 1, 8
            call c%list_id(what//str(k), ids, n)
         end do
         if (c%halt()) exit
      end do
      call c%done(error)
      if (allocated(error)) return
      s%ids = ids(1:n)
      s%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      if (is_node_set(blk%base)) then
         inp%node_sets = [inp%node_sets, s]
      else
         inp%part_sets = [inp%part_sets, s]
      end if
   end subroutine read_set_list

   pure logical function is_node_set(base)
      character(*), intent(in) :: base
      is_node_set = base(1:min(8, len(base))) == 'SET_NODE'
   end function is_node_set

   !> Card 1 SID (DA1..DA4 SOLVER read past); error when missing or SID <= 0.
   subroutine read_sid(c, i0, sid)
      type(card_t), intent(inout) :: c
      integer, intent(in) :: i0
      integer, intent(out) :: sid
      sid = 0
      call c%need(i0, 'missing card 1 (SID DA1 DA2 DA3 DA4 SOLVER)')
      call c%seek(i0)
      call c%id('SID', sid, 'set id must be > 0')
   end subroutine read_sid

   !> *SET_NODE_LIST_GENERATE / *SET_PART_LIST_GENERATE: B1BEG B1END ... B4BEG B4END.
   subroutine read_set_generate(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i0, ic, k, b, e, n
      integer, allocatable :: ids(:)
      type(set_gen_in_t) :: g
      type(card_t) :: c
      i0 = data_start(blk)
      call deck_cursor(deck, blk, c)
      call read_sid(c, i0, g%label)
      call c%done(error)
      if (allocated(error)) return
      allocate(ids(8*(blk%n - i0)))
      n = 0
      do ic = i0 + 1, blk%n
         call c%seek(ic)
         do k = 1, 4
            call c%int('B'//str(k)//'BEG', 0, b)
            call c%int('B'//str(k)//'END', 0, e)
            if (c%halt()) exit
            if (b == 0 .and. e == 0) cycle
            if (b <= 0 .or. e < b) then
               call c%fail('B'//str(k)//'END', 'a range needs 0 < BEG <= END, got '//str(b)// &
                           ', '//str(e))
               exit
            end if
            ids(n + 1:n + 2) = [b, e]
            n = n + 2
         end do
         if (c%halt()) exit
      end do
      call c%done(error)
      if (allocated(error)) return
      g%nodes = is_node_set(blk%base)
      g%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      allocate(g%steps(1))
      g%steps(1)%op = 'RANGE'
      g%steps(1)%ids = ids(1:n)
      g%steps(1)%src = g%src
      inp%set_gens = [inp%set_gens, g]
   end subroutine read_set_generate

   !> *SET_NODE_GENERAL: cards OPTION E1 .. E7 after card 1.
   subroutine read_set_general(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i0, ic, k, n
      integer :: ids(7)
      character(:), allocatable :: op
      type(set_gen_in_t) :: g
      type(set_step_in_t) :: st
      type(set_step_buffer_t) :: steps
      type(card_t) :: c
      i0 = data_start(blk)
      call deck_cursor(deck, blk, c)
      call read_sid(c, i0, g%label)
      call c%done(error)
      if (allocated(error)) return
      allocate(g%steps(0))
      do ic = i0 + 1, blk%n
         call c%seek(ic)
         call c%text_field(1, c%w(1:c%nw), op)
         op = upper(op)
         call c%skip(1)
         select case (op)
         case ('ALL', 'NODE', 'PART', 'BOX', 'SET', 'DNODE', 'DPART', 'DBOX', 'DSET')
         case ('')
            cycle
         case default
            call c%fail_here('OPTION', "option '"//op//"' is not supported (supported: "// &
                             'ALL, NODE, PART, BOX, SET, DNODE, DPART, DBOX, DSET)')
            exit
         end select
         n = 0
         do k = 1, 7
            call c%list_id('E'//str(k), ids, n)
         end do
         if (c%halt()) exit
         st%op = op
         st%ids = ids(1:n)
         st%src = origin(blk%ifile, c%card_line(), blk%name)
         call steps%push(st)
      end do
      call steps%flush(g%steps)
      call c%done(error)
      if (allocated(error)) return
      g%nodes = .true.
      g%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      inp%set_gens = [inp%set_gens, g]
   end subroutine read_set_general

   !> After the whole deck: each generated set becomes a node or part set list (ids in
   !> node or part order), its steps applied in card order. An id that names no node,
   !> part, box or set is an error at its card.
   subroutine sets_finish(inp, error)
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(label_map_t) :: nmap
      logical, allocatable :: mask(:)
      integer, allocatable :: plab(:)
      integer :: ig, is, i, j, k, e, n
      type(label_list_t) :: s
      logical :: add
      character(:), allocatable :: op
      if (size(inp%set_gens) == 0) return
      call nmap%init(inp%nn)
      do i = 1, inp%nn
         call nmap%insert(inp%node_label(i), i, j)   ! a duplicate: the build names it
      end do
      do ig = 1, size(inp%set_gens)
         associate (g => inp%set_gens(ig))
            if (g%nodes) then
               allocate(mask(inp%nn))
            else
               allocate(mask(inp%nparts))
            end if
            mask = .false.
            do is = 1, size(g%steps)
               associate (st => g%steps(is))
                  op = trim(st%op)
                  add = op(1:1) /= 'D'
                  if (.not. add) op = op(2:)
                  select case (op)
                  case ('ALL')
                     mask = .true.
                  case ('RANGE')
                     do k = 1, size(st%ids), 2
                        if (g%nodes) then
                           where (inp%node_label(1:inp%nn) >= st%ids(k) .and. &
                                  inp%node_label(1:inp%nn) <= st%ids(k + 1)) mask = .true.
                        else
                           where (inp%parts(1:inp%nparts)%label >= st%ids(k) .and. &
                                  inp%parts(1:inp%nparts)%label <= st%ids(k + 1)) mask = .true.
                        end if
                     end do
                  case ('NODE')
                     do k = 1, size(st%ids)
                        i = nmap%get(st%ids(k))
                        if (i == 0) then
                           call fail(st%src, 'NODE: node '//str(st%ids(k))//' is not defined')
                           return
                        end if
                        mask(i) = add
                     end do
                  case ('PART')
                     do k = 1, size(st%ids)
                        j = findloc(inp%parts(1:inp%nparts)%label, st%ids(k), 1)
                        if (j == 0) then
                           call fail(st%src, 'PART: part '//str(st%ids(k))//' is not defined')
                           return
                        end if
                     end do
                     do e = 1, inp%ne
                        if (.not. any(st%ids == inp%elem_pid(e))) cycle
                        do k = 1, size(inp%elem_conn, 1)
                           i = nmap%get(inp%elem_conn(k, e))
                           if (i > 0) mask(i) = add
                        end do
                     end do
                  case ('BOX')
                     do k = 1, size(st%ids)
                        j = 0
                        if (allocated(inp%contact%boxes)) &
                           j = findloc(inp%contact%boxes%label, st%ids(k), 1)
                        if (j == 0) then
                           call fail(st%src, 'BOX: box '//str(st%ids(k))//' is not defined '// &
                                     '(*DEFINE_BOX)')
                           return
                        end if
                        associate (b => inp%contact%boxes(j))
                           do i = 1, inp%nn
                              if (all(inp%x(:, i) >= b%lo .and. inp%x(:, i) <= b%hi)) &
                                 mask(i) = add
                           end do
                        end associate
                     end do
                  case ('SET')
                     do k = 1, size(st%ids)
                        j = 0
                        do n = size(inp%node_sets), 1, -1
                           if (inp%node_sets(n)%label == st%ids(k)) then
                              j = n; exit
                           end if
                        end do
                        if (j == 0) then
                           call fail(st%src, 'SET: node set '//str(st%ids(k))// &
                                     ' is not defined (a *SET_NODE before it)')
                           return
                        end if
                        do n = 1, size(inp%node_sets(j)%ids)
                           i = nmap%get(inp%node_sets(j)%ids(n))
                           if (i > 0) mask(i) = add
                        end do
                     end do
                  end select
               end associate
            end do
            s%label = g%label
            s%src = g%src
            if (g%nodes) then
               s%ids = pack(inp%node_label(1:inp%nn), mask)
               inp%node_sets = [inp%node_sets, s]
            else
               plab = inp%parts(1:inp%nparts)%label
               s%ids = pack(plab, mask)
               inp%part_sets = [inp%part_sets, s]
            end if
            deallocate(mask)
         end associate
      end do
      deallocate(inp%set_gens)
      allocate(inp%set_gens(0))
   contains
      subroutine fail(src, what)
         type(origin_t), intent(in) :: src
         character(*), intent(in) :: what
         call set_error(error, inp%files(src%ifile)%s//':'//str(src%line)//': *'//src%key// &
                        ': option '//what)
      end subroutine fail
   end subroutine sets_finish

   subroutine read_set_segment(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i0, ic, k, n
      type(segment_list_t) :: s
      type(card_t) :: c
      i0 = data_start(blk)
      call deck_cursor(deck, blk, c)
      call c%need(i0, 'missing card 1 (SID DA1 DA2 DA3 DA4)')
      call c%id('SID', s%label, 'set id must be > 0')
      call c%done(error)
      if (allocated(error)) return
      allocate(s%seg(4, blk%n - i0))
      n = 0
      do ic = i0 + 1, blk%n
         n = n + 1
         call c%seek(ic)
         do k = 1, 4
            call c%int('N'//str(k), 0, s%seg(k, n))
            if (c%ok() .and. k <= 3 .and. s%seg(k, n) <= 0) call c%fail('N'//str(k), &
                                                                       'node id must be > 0')
         end do
         if (c%halt()) exit
         if (s%seg(4, n) == 0) s%seg(4, n) = s%seg(3, n)
      end do
      call c%done(error)
      if (allocated(error)) return
      s%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      inp%segment_sets = [inp%segment_sets, s]
   end subroutine read_set_segment
end module dx_read_sets
