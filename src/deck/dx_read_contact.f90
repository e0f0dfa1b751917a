!> Readers for the contact keywords: *CONTACT_NODES_TO_SURFACE, *CONTACT_SURFACE_TO_SURFACE,
!> *CONTACT_ONE_WAY_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_SINGLE_SURFACE,
!> *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_NODES_TO_SURFACE,
!> *CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE (each with the _ID or _TITLE option card
!> CID HEADING), *CONTROL_CONTACT, *DATABASE_RCFORC and *DEFINE_BOX.
!> Contact cards (LS-DYNA Keyword User's Manual, Vol. I, *CONTACT): card 1 SSID MSID SSTYP
!> MSTYP SBOXID MBOXID SPR MPR; card 2 FS FD DC VC VDC PENCHK BT DT; card 3 SFS SFM SST MST
!> SFST SFMT FSF VSF; optional card A SOFT SOFSCL LCIDAB MAXPAR SBOPT DEPTH BSORT FRCFRQ.
!> Cards 2, 3 and A are optional; a blank field (or 0 where the default is not 0) takes the
!> default. Optional cards B and beyond are read past and ignored (docs/keywords.md).
module dx_read_contact
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t
   use dx_contact_input, only: contact_in_t, box_in_t, CT_NODES_TO_SURFACE, &
                               CT_SURFACE_TO_SURFACE, CT_ONE_WAY, CT_SINGLE_SURFACE
   implicit none
   private
   public :: register_contact

contains

   !> Add the contact keywords to the registry.
   subroutine register_contact(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CONTACT_NODES_TO_SURFACE', read_contact, title=.true., id=.true.)
      call reg%add('CONTACT_SURFACE_TO_SURFACE', read_contact, title=.true., id=.true.)
      call reg%add('CONTACT_ONE_WAY_SURFACE_TO_SURFACE', read_contact, title=.true., id=.true.)
      call reg%add('CONTACT_AUTOMATIC_SINGLE_SURFACE', read_contact, title=.true., id=.true.)
      call reg%add('CONTACT_AUTOMATIC_SURFACE_TO_SURFACE', read_contact, title=.true., &
                   id=.true.)
      call reg%add('CONTACT_AUTOMATIC_NODES_TO_SURFACE', read_contact, title=.true., id=.true.)
      call reg%add('CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE', read_contact, &
                   title=.true., id=.true.)
      call reg%add('CONTROL_CONTACT', read_control_contact)
      call reg%add('DATABASE_RCFORC', read_rcforc)
      call reg%add('DEFINE_BOX', read_define_box, title=.true.)
   end subroutine register_contact

   !> One *CONTACT_... keyword.
   subroutine read_contact(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(contact_in_t) :: ct
      type(card_t) :: c
      integer :: i0
      character(:), allocatable :: t
      call deck_cursor(deck, blk, c)
      i0 = data_start(blk)
      ct%key = blk%name
      ct%automatic = index(blk%base, 'AUTOMATIC') > 0
      select case (blk%base)
      case ('CONTACT_NODES_TO_SURFACE', 'CONTACT_AUTOMATIC_NODES_TO_SURFACE')
         ct%kind = CT_NODES_TO_SURFACE
      case ('CONTACT_ONE_WAY_SURFACE_TO_SURFACE', 'CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE')
         ct%kind = CT_ONE_WAY
      case ('CONTACT_AUTOMATIC_SINGLE_SURFACE')
         ct%kind = CT_SINGLE_SURFACE
      case default
         ct%kind = CT_SURFACE_TO_SURFACE
      end select
      if (blk%opt_id .or. blk%opt_title) then
         call c%seek(1)
         call c%int('CID', 0, ct%label, min=0)
         call c%text_field(2, [10, 70], t)       ! HEADING: columns 11-80
         ct%title = t
      end if
      call c%need(i0, 'missing card 1 (SSID MSID SSTYP MSTYP SBOXID MBOXID SPR MPR)')
      call c%done(error)
      if (allocated(error)) return
      ct%ifile = blk%ifile
      ct%line = blk%cards(i0)%line
      ! ---- card 1
      call c%seek(i0)
      call c%int('SSID', 0, ct%ssid)
      call c%int('MSID', 0, ct%msid)
      call c%int('SSTYP', 0, ct%sstyp)
      call c%int('MSTYP', 0, ct%mstyp)
      call c%int('SBOXID', 0, ct%sboxid)
      call c%int('MBOXID', 0, ct%mboxid)
      call c%int('SPR', 0, ct%spr)
      call c%int('MPR', 0, ct%mpr)
      if (c%ok()) call check_types(c, ct)
      ! ---- card 2
      if (blk%n >= i0 + 1 .and. c%ok()) then
         call c%next()
         ct%line2 = c%card_line()
         call c%real('FS', 0.0_wp, ct%fs)
         if (c%ok() .and. ct%fs < 0.0_wp) call c%fail('FS', 'must be >= 0, got '// &
            rstr(ct%fs)//' (-1, the parts'' friction of *PART_CONTACT, and -2, friction '// &
            'tables, are not implemented)')
         call c%real('FD', 0.0_wp, ct%fd, min=0.0_wp)
         call c%real('DC', 0.0_wp, ct%dc, min=0.0_wp)
         call c%real('VC', 0.0_wp, ct%vc, min=0.0_wp)
         call c%real('VDC', 0.0_wp, ct%vdc, min=0.0_wp)
         call c%int('PENCHK', 0, ct%penchk)
         call c%real('BT', 0.0_wp, ct%bt)
         call c%real('DT', 1.0e20_wp, ct%dt)
         if (ct%dt == 0.0_wp) ct%dt = 1.0e20_wp
         if (c%ok() .and. ct%dt < 0.0_wp) call c%fail('DT', 'a negative death time '// &
            '(deactivation during dynamic relaxation) is not supported')
         if (c%ok() .and. ct%fd > 0.0_wp .and. ct%fs == 0.0_wp) call c%fail('FD', 'FD > 0 '// &
            'needs FS > 0 (with FS = 0 LS-DYNA ignores friction)')
      end if
      ! ---- card 3
      if (blk%n >= i0 + 2 .and. c%ok()) then
         call c%seek(i0 + 2)
         ct%line3 = c%card_line()
         call scale(c, 'SFS', ct%sfs)
         call scale(c, 'SFM', ct%sfm)
         call c%real('SST', 0.0_wp, ct%sst)
         call c%real('MST', 0.0_wp, ct%mst)
         call scale(c, 'SFST', ct%sfst)
         call scale(c, 'SFMT', ct%sfmt)
         call scale(c, 'FSF', ct%fsf)
         call scale(c, 'VSF', ct%vsf)
      end if
      ! ---- optional card A
      if (blk%n >= i0 + 3 .and. c%ok()) then
         call c%seek(i0 + 3)
         call c%int('SOFT', 0, ct%soft)
         if (c%ok() .and. ct%soft == 2) call c%fail('SOFT', 'SOFT = 2 (segment-based '// &
            'contact: segment against segment, pinball search) is not supported (supported: '// &
            '0 segment stiffness, 1 soft constraint)')
         if (c%ok() .and. ct%soft /= 0 .and. ct%soft /= 1) call c%fail('SOFT', 'only SOFT = '// &
            '0 (segment stiffness) and 1 (soft constraint) are supported, got '//str(ct%soft))
         call c%real('SOFSCL', 0.1_wp, ct%sofscl)
         if (ct%sofscl == 0.0_wp) ct%sofscl = 0.1_wp
         if (c%ok() .and. ct%sofscl < 0.0_wp) call c%fail('SOFSCL', 'must be >= 0, got '// &
                                                          rstr(ct%sofscl))
         call c%at(7)
         call c%int('BSORT', 10, ct%bsort)
         if (ct%bsort == 0) ct%bsort = 10
         ct%bsort = abs(ct%bsort)
      end if
      call c%done(error)
      if (allocated(error)) return
      if (ct%kind == CT_SINGLE_SURFACE) ct%sfm = ct%sfs
      if (.not. allocated(inp%contact%contacts)) allocate(inp%contact%contacts(0))
      inp%contact%contacts = [inp%contact%contacts, ct]
   end subroutine read_contact

   !> the next field, a scale factor: blank or 0 means 1 (LS-DYNA default), < 0 (a load
   !> curve in LS-DYNA) an error
   subroutine scale(c, name, val)
      type(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      real(wp), intent(out) :: val
      call c%real(name, 1.0_wp, val)
      if (val == 0.0_wp) val = 1.0_wp
      if (c%ok() .and. val < 0.0_wp) call c%fail(name, 'must be > 0, got '//rstr(val)// &
                                                 ' (load curves are not supported)')
   end subroutine scale

   !> SSTYP/MSTYP against what the contact type accepts (card 1 read by the cursor).
   subroutine check_types(c, ct)
      type(card_t), intent(inout) :: c
      type(contact_in_t), intent(inout) :: ct
      select case (ct%sstyp)
      case (0, 2, 3)
      case (4)
         if (ct%kind /= CT_NODES_TO_SURFACE) call c%fail('SSTYP', 'a node set (4) is a '// &
            'slave side of *CONTACT_NODES_TO_SURFACE only')
      case (5)
         if (ct%kind /= CT_SINGLE_SURFACE) call c%fail('SSTYP', '5 (all parts) is for '// &
                                                       'single surface contact only')
      case (1, 6)
         call c%fail('SSTYP', str(ct%sstyp)//' (shell element set / exempted part set) is '// &
            'not supported: use 0 segment set, 2 part set, 3 part, 4 node set or 5 all')
      case default
         call c%fail('SSTYP', 'unknown set type '//str(ct%sstyp)//' (0 segment set, 2 part '// &
                     'set, 3 part, 4 node set, 5 all)')
      end select
      if (.not. c%ok()) return
      if (ct%kind == CT_SINGLE_SURFACE) then
         if (ct%ssid == 0) ct%sstyp = 5
         return
      end if
      if (ct%ssid <= 0) call c%fail('SSID', 'slave set id must be > 0, got '//str(ct%ssid))
      select case (ct%mstyp)
      case (0, 2, 3)
      case (1, 4, 5, 6)
         call c%fail('MSTYP', str(ct%mstyp)//' is not supported for the master side: use 0 '// &
                     'segment set, 2 part set or 3 part')
      case default
         call c%fail('MSTYP', 'unknown set type '//str(ct%mstyp)//' (0 segment set, 2 part '// &
                     'set, 3 part)')
      end select
      if (ct%msid <= 0) call c%fail('MSID', 'master set id must be > 0, got '//str(ct%msid))
   end subroutine check_types

   !> *CONTROL_CONTACT: SLSFAC of card 1 is used; every other field is read past.
   subroutine read_control_contact(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      if (blk%n < 1) return
      call deck_cursor(deck, blk, c)
      call c%real('SLSFAC', 0.1_wp, inp%contact%slsfac)
      if (inp%contact%slsfac == 0.0_wp) inp%contact%slsfac = 0.1_wp
      if (c%ok() .and. inp%contact%slsfac < 0.0_wp) call c%fail('SLSFAC', 'must be > 0, got '// &
         rstr(inp%contact%slsfac)//' (load curves are not supported)')
      call c%done(error)
   end subroutine read_control_contact

   !> *DATABASE_RCFORC: DT BINARY LCUR IOOPT (DT used; 0 means no rcforc file, as in
   !> LS-DYNA).
   subroutine read_rcforc(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (DT BINARY LCUR IOOPT)')
      call c%max_cards(1)
      call c%real('DT', 0.0_wp, inp%contact%rcforc_dt)
      if (c%ok() .and. .not. (inp%contact%rcforc_dt >= 0.0_wp)) call c%fail('DT', 'output '// &
         'interval must be >= 0 (0: no rcforc file), got '//rstr(inp%contact%rcforc_dt))
      call c%done(error)
   end subroutine read_rcforc

   !> *DEFINE_BOX: BOXID XMN XMX YMN YMX ZMN ZMX.
   subroutine read_define_box(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(box_in_t) :: b
      type(card_t) :: c
      integer :: d
      character(3), parameter :: ax(3) = ['X', 'Y', 'Z']
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (BOXID XMN XMX YMN YMX ZMN ZMX)')
      call c%id('BOXID', b%label, 'box id must be > 0')
      do d = 1, 3
         call c%real(trim(ax(d))//'MN', 0.0_wp, b%lo(d))
         call c%real(trim(ax(d))//'MX', 0.0_wp, b%hi(d))
         if (c%ok() .and. b%hi(d) < b%lo(d)) call c%fail(trim(ax(d))//'MX', 'must be >= '// &
                                                         trim(ax(d))//'MN = '//rstr(b%lo(d)))
      end do
      call c%done(error)
      if (allocated(error)) return
      b%ifile = blk%ifile
      b%line = blk%cards(data_start(blk))%line
      if (.not. allocated(inp%contact%boxes)) allocate(inp%contact%boxes(0))
      inp%contact%boxes = [inp%contact%boxes, b]
   end subroutine read_define_box
end module dx_read_contact
