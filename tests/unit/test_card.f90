!> Unit tests of the card cursor (dx_card): fields in fixed 10-column and comma format, the
!> first error kept, bounds, and the message format the deck readers print (file:line:col,
!> keyword, field, the card and a caret under the field; docs/keywords.md "Card format").
program test_card
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_card, only: card_t, block_t, param_t, open_card
   use dx_assert, only: check, check_close, assert_summary
   use dx_strings, only: str
   implicit none
   type(block_t) :: blk
   type(card_t) :: c
   type(param_t) :: pars(1)
   type(error_t), allocatable :: err
   integer :: mid, n, ids(8), nid, tc, k
   real(wp) :: ro, e, pr
   character(*), parameter :: card1 = '         1    7.8e-9 -210000.0       0.3'
   character(:), allocatable :: want

   pars(1)%name = 'RHO'; pars(1)%kind = 'R'; pars(1)%value = 2.5_wp; pars(1)%text = ''
   call make_block(blk, [character(40) :: card1, '      &rho'])
   ! ---- fixed format, a good read with a lower bound
   call open_card('deck.k', pars, blk, c)
   call c%int('MID', 0, mid)
   call c%real('RO', 0.0_wp, ro, min=0.0_wp)
   call c%real('E', 0.0_wp, e)
   call c%real('PR', 0.0_wp, pr)
   call c%next()
   call c%real('X', 0.0_wp, pr)
   call c%next()
   call c%int('MISSING', 7, n)
   call c%done(err)
   call check(.not. allocated(err), 'cursor: no error')
   call check(mid == 1, 'cursor: MID')
   call check_close(ro, 7.8e-9_wp, 0.0_wp, epsilon(1.0_wp), 'cursor: RO')
   call check_close(e, -2.1e5_wp, 0.0_wp, epsilon(1.0_wp), 'cursor: E')
   call check_close(pr, 2.5_wp, 0.0_wp, 0.0_wp, 'cursor: &rho parameter on card 2')
   call check(n == 7, 'cursor: a missing card gives the default')
   ! ---- a bound error points at field 3 (col 21) and the first error wins
   call open_card('deck.k', pars, blk, c)
   call c%int('MID', 0, mid)
   call c%real('RO', 0.0_wp, ro)
   call c%real('E', 0.0_wp, e, gt=0.0_wp)
   call c%real('PR', 0.0_wp, pr, max=0.0_wp)
   call c%done(err)
   want = 'deck.k:11:21: *MAT_ELASTIC: field E: must be > 0, got -2.10000E+05'//new_line('a')// &
          card1//new_line('a')//repeat(' ', 20)//'^'
   call check(allocated(err), 'cursor: bound error')
   if (allocated(err)) call check(err%message == want, 'cursor: message, column and caret')
   if (allocated(err)) print '(a)', err%message
   ! ---- c%fail names a field read before, by name
   call open_card('deck.k', pars, blk, c)
   call c%int('MID', 0, mid)
   call c%real('RO', 0.0_wp, ro)
   call c%real('E', 0.0_wp, e)
   call c%fail('RO', 'material 1: density must be > 0')
   call check_fails('cursor: fail by name', 'deck.k:11:11: *MAT_ELASTIC: field RO: '// &
                    'material 1: density must be > 0', 'cursor: fail column')
   ! ---- free format: field 3 of '1,7.8e-9,steel' starts at column 10
   call make_block(blk, [character(40) :: '1,7.8e-9,steel'])
   call open_card('deck.k', pars, blk, c)
   call c%int('MID', 0, mid)
   call c%real('RO', 0.0_wp, ro)
   call c%real('E', 0.0_wp, e)
   call check_fails('cursor: comma card, bad number', 'deck.k:11:10: *MAT_ELASTIC: field E: '// &
                    'expected a number, got ''steel''', 'cursor: comma column')
   ! ---- the list readers' calls: id, list_id, zero_int, need, at, widths, fail_here
   call make_block(blk, [character(40) :: '         0', '         3        -2', &
                                          '         0         5'])
   call open_card('deck.k', pars, blk, c)
   call c%id('SID', n, 'set id must be > 0')
   call check_fails('cursor: id 0 is an error', 'deck.k:11:1: *MAT_ELASTIC: field SID: '// &
                    'set id must be > 0, got 0', 'cursor: id message')
   call open_card('deck.k', pars, blk, c)
   n = 0
   call c%seek(2)
   call c%list_id('NID1', ids, n)
   call c%list_id('NID2', ids, n)
   call c%done(err)
   call check(n == 1 .and. ids(1) == 3, 'cursor: list_id appends the ids > 0')
   call check(allocated(err), 'cursor: list_id, a negative id')
   if (allocated(err)) call check(index(err%message, 'deck.k:12:11: *MAT_ELASTIC: field NID2: '// &
                                  'must be >= 0, got -2') == 1, 'cursor: list_id message')
   call open_card('deck.k', pars, blk, c)
   call c%seek(3)
   call c%zero_int('CID', 'local systems')
   call c%zero_int('BOXID', 'boxes')
   call check_fails('cursor: zero_int', 'deck.k:13:11: *MAT_ELASTIC: field BOXID: '// &
                    'nonzero value 5 is not supported: boxes', 'cursor: zero_int message')
   call open_card('deck.k', pars, blk, c)
   call c%need(4, 'missing card 4 (X)')
   call c%done(err)
   call check(allocated(err), 'cursor: need')
   if (allocated(err)) call check(err%message == 'deck.k:10: *MAT_ELASTIC: missing card 4 (X)', &
                                  'cursor: need message')
   call open_card('deck.k', pars, blk, c)
   call c%seek(3)
   call c%at(2)
   call c%int('B', 0, n)
   call c%done(err)
   call check(.not. allocated(err) .and. n == 5, 'cursor: at(2) reads field 2')
   ! a *NODE card: widths 8, 16, ...; many cards keep one position per field name
   call make_block(blk, [character(64) :: '       1             1.5', &
                                          '       2             2.5                                       9'])
   call open_card('deck.k', pars, blk, c)
   call c%widths([8, 16, 16, 16, 8, 8])
   do k = 1, 2
      call c%seek(k)
      call c%id('NID', nid)
      call c%real('X', 0.0_wp, ro)
      call c%skip(2)
      call c%int('TC', 0, tc)
      if (c%ok() .and. tc > 7) call c%fail('TC', 'must be 0 to 7, got '//str(tc))
   end do
   call check(c%nseen == 3, 'cursor: one remembered position per field name')
   call check_fails('cursor: widths, TC on card 2', 'deck.k:12:57: *MAT_ELASTIC: field TC: '// &
                    'must be 0 to 7, got 9', 'cursor: widths column')
   call open_card('deck.k', pars, blk, c)
   call c%skip(1)
   call c%fail_here('OPTION', 'bad')
   call check_fails('cursor: fail_here', 'deck.k:11:1: *MAT_ELASTIC: field OPTION: '// &
                    'bad', 'cursor: fail_here column')
   call assert_summary()

contains

   !> c%done fails (check what) with a message that starts with msg (check what_msg).
   subroutine check_fails(what, msg, what_msg)
      character(*), intent(in) :: what, msg, what_msg
      call c%done(err)
      call check(allocated(err), what)
      if (allocated(err)) call check(index(err%message, msg) == 1, what_msg)
   end subroutine check_fails

   subroutine make_block(b, cards)
      type(block_t), intent(out) :: b
      character(*), intent(in) :: cards(:)
      integer :: i
      b%name = 'MAT_ELASTIC'
      b%base = 'MAT_ELASTIC'
      b%line = 10
      b%n = size(cards)
      allocate(b%cards(b%n))
      do i = 1, b%n
         b%cards(i)%text = trim(cards(i))
         b%cards(i)%line = 10 + i
      end do
   end subroutine make_block
end program test_card
