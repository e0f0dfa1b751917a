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
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, get_text, field_error, &
                            block_error, std_widths, data_start, check_max_cards
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
      type(contact_in_t) :: c
      integer :: w(8), i0, c1, c2, c3, ca
      character(:), allocatable :: t
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      c%key = blk%name
      c%automatic = index(blk%base, 'AUTOMATIC') > 0
      select case (blk%base)
      case ('CONTACT_NODES_TO_SURFACE', 'CONTACT_AUTOMATIC_NODES_TO_SURFACE')
         c%kind = CT_NODES_TO_SURFACE
      case ('CONTACT_ONE_WAY_SURFACE_TO_SURFACE', 'CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE')
         c%kind = CT_ONE_WAY
      case ('CONTACT_AUTOMATIC_SINGLE_SURFACE')
         c%kind = CT_SINGLE_SURFACE
      case default
         c%kind = CT_SURFACE_TO_SURFACE
      end select
      if (blk%opt_id .or. blk%opt_title) then
         call get_int(deck, blk, 1, 1, w, 'CID', 0, c%label, error)
         if (allocated(error)) return
         if (c%label < 0) then
            call field_error(deck, blk, 1, 1, w, 'CID', 'must be >= 0', error); return
         end if
         call get_text(deck, blk, 1, 2, [10, 70], t)
         c%title = t
      end if
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (SSID MSID SSTYP MSTYP SBOXID '// &
                          'MBOXID SPR MPR)', error)
         return
      end if
      c1 = i0; c2 = i0 + 1; c3 = i0 + 2; ca = i0 + 3
      c%ifile = blk%ifile
      c%line = blk%cards(c1)%line
      ! ---- card 1
      call get_int(deck, blk, c1, 1, w, 'SSID', 0, c%ssid, error); if (allocated(error)) return
      call get_int(deck, blk, c1, 2, w, 'MSID', 0, c%msid, error); if (allocated(error)) return
      call get_int(deck, blk, c1, 3, w, 'SSTYP', 0, c%sstyp, error)
      if (allocated(error)) return
      call get_int(deck, blk, c1, 4, w, 'MSTYP', 0, c%mstyp, error)
      if (allocated(error)) return
      call get_int(deck, blk, c1, 5, w, 'SBOXID', 0, c%sboxid, error)
      if (allocated(error)) return
      call get_int(deck, blk, c1, 6, w, 'MBOXID', 0, c%mboxid, error)
      if (allocated(error)) return
      call get_int(deck, blk, c1, 7, w, 'SPR', 0, c%spr, error); if (allocated(error)) return
      call get_int(deck, blk, c1, 8, w, 'MPR', 0, c%mpr, error); if (allocated(error)) return
      call check_types(deck, blk, c1, w, c, error)
      if (allocated(error)) return
      ! ---- card 2
      if (blk%n >= c2) then
         c%line2 = blk%cards(c2)%line
         call get_nonneg(c2, 1, 'FS', 0.0_wp, c%fs); if (allocated(error)) return
         call get_nonneg(c2, 2, 'FD', 0.0_wp, c%fd); if (allocated(error)) return
         call get_nonneg(c2, 3, 'DC', 0.0_wp, c%dc); if (allocated(error)) return
         call get_nonneg(c2, 4, 'VC', 0.0_wp, c%vc); if (allocated(error)) return
         call get_nonneg(c2, 5, 'VDC', 0.0_wp, c%vdc); if (allocated(error)) return
         call get_int(deck, blk, c2, 6, w, 'PENCHK', 0, c%penchk, error)
         if (allocated(error)) return
         call get_real(deck, blk, c2, 7, w, 'BT', 0.0_wp, c%bt, error)
         if (allocated(error)) return
         call get_real(deck, blk, c2, 8, w, 'DT', 1.0e20_wp, c%dt, error)
         if (allocated(error)) return
         if (c%dt == 0.0_wp) c%dt = 1.0e20_wp
         if (c%dt < 0.0_wp) then
            call field_error(deck, blk, c2, 8, w, 'DT', 'a negative death time (deactivation '// &
                             'during dynamic relaxation) is not supported', error)
            return
         end if
         if (c%fd > 0.0_wp .and. c%fs == 0.0_wp) then
            call field_error(deck, blk, c2, 2, w, 'FD', 'FD > 0 needs FS > 0 (with FS = 0 '// &
                             'LS-DYNA ignores friction)', error)
            return
         end if
      end if
      ! ---- card 3
      if (blk%n >= c3) then
         c%line3 = blk%cards(c3)%line
         call get_scale(c3, 1, 'SFS', c%sfs); if (allocated(error)) return
         call get_scale(c3, 2, 'SFM', c%sfm); if (allocated(error)) return
         call get_real(deck, blk, c3, 3, w, 'SST', 0.0_wp, c%sst, error)
         if (allocated(error)) return
         call get_real(deck, blk, c3, 4, w, 'MST', 0.0_wp, c%mst, error)
         if (allocated(error)) return
         call get_scale(c3, 5, 'SFST', c%sfst); if (allocated(error)) return
         call get_scale(c3, 6, 'SFMT', c%sfmt); if (allocated(error)) return
         call get_scale(c3, 7, 'FSF', c%fsf); if (allocated(error)) return
         call get_scale(c3, 8, 'VSF', c%vsf); if (allocated(error)) return
      end if
      ! ---- optional card A
      if (blk%n >= ca) then
         call get_int(deck, blk, ca, 1, w, 'SOFT', 0, c%soft, error)
         if (allocated(error)) return
         if (c%soft /= 0 .and. c%soft /= 1) then
            call field_error(deck, blk, ca, 1, w, 'SOFT', 'only SOFT = 0 (segment stiffness) '// &
                             'and 1 (soft constraint) are supported, got '//str(c%soft), error)
            return
         end if
         call get_real(deck, blk, ca, 2, w, 'SOFSCL', 0.1_wp, c%sofscl, error)
         if (allocated(error)) return
         if (c%sofscl == 0.0_wp) c%sofscl = 0.1_wp
         if (c%sofscl < 0.0_wp) then
            call field_error(deck, blk, ca, 2, w, 'SOFSCL', 'must be >= 0, got '// &
                             rstr(c%sofscl), error)
            return
         end if
         call get_int(deck, blk, ca, 7, w, 'BSORT', 10, c%bsort, error)
         if (allocated(error)) return
         if (c%bsort == 0) c%bsort = 10
         c%bsort = abs(c%bsort)
      end if
      if (c%kind == CT_SINGLE_SURFACE) c%sfm = c%sfs
      if (.not. allocated(inp%contact%contacts)) allocate(inp%contact%contacts(0))
      inp%contact%contacts = [inp%contact%contacts, c]

   contains

      subroutine get_nonneg(ic, k, name, def, val)
         integer, intent(in) :: ic, k
         character(*), intent(in) :: name
         real(wp), intent(in) :: def
         real(wp), intent(out) :: val
         call get_real(deck, blk, ic, k, w, name, def, val, error)
         if (allocated(error)) return
         if (val < 0.0_wp) call field_error(deck, blk, ic, k, w, name, 'must be >= 0, got '// &
                                            rstr(val), error)
      end subroutine get_nonneg

      !> scale factors: blank or 0 means 1 (LS-DYNA default)
      subroutine get_scale(ic, k, name, val)
         integer, intent(in) :: ic, k
         character(*), intent(in) :: name
         real(wp), intent(out) :: val
         call get_real(deck, blk, ic, k, w, name, 1.0_wp, val, error)
         if (allocated(error)) return
         if (val == 0.0_wp) val = 1.0_wp
         if (val < 0.0_wp) call field_error(deck, blk, ic, k, w, name, 'must be > 0, got '// &
                                            rstr(val)//' (load curves are not supported)', error)
      end subroutine get_scale
   end subroutine read_contact

   !> SSTYP/MSTYP against what the contact type accepts.
   subroutine check_types(deck, blk, ic, w, c, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, w(:)
      type(contact_in_t), intent(inout) :: c
      type(error_t), allocatable, intent(out) :: error
      select case (c%sstyp)
      case (0, 2, 3)
      case (4)
         if (c%kind /= CT_NODES_TO_SURFACE) then
            call field_error(deck, blk, ic, 3, w, 'SSTYP', 'a node set (4) is a slave side '// &
                             'of *CONTACT_NODES_TO_SURFACE only', error)
            return
         end if
      case (5)
         if (c%kind /= CT_SINGLE_SURFACE) then
            call field_error(deck, blk, ic, 3, w, 'SSTYP', '5 (all parts) is for single '// &
                             'surface contact only', error)
            return
         end if
      case (1, 6)
         call field_error(deck, blk, ic, 3, w, 'SSTYP', str(c%sstyp)//' (shell element '// &
            'set / exempted part set) is not supported: use 0 segment set, 2 part set, '// &
            '3 part, 4 node set or 5 all', error)
         return
      case default
         call field_error(deck, blk, ic, 3, w, 'SSTYP', 'unknown set type '//str(c%sstyp)// &
            ' (0 segment set, 2 part set, 3 part, 4 node set, 5 all)', error)
         return
      end select
      if (c%kind == CT_SINGLE_SURFACE) then
         if (c%ssid == 0) c%sstyp = 5
         return
      end if
      if (c%ssid <= 0) then
         call field_error(deck, blk, ic, 1, w, 'SSID', 'slave set id must be > 0, got '// &
                          str(c%ssid), error)
         return
      end if
      select case (c%mstyp)
      case (0, 2, 3)
      case (1, 4, 5, 6)
         call field_error(deck, blk, ic, 4, w, 'MSTYP', str(c%mstyp)//' is not supported '// &
            'for the master side: use 0 segment set, 2 part set or 3 part', error)
         return
      case default
         call field_error(deck, blk, ic, 4, w, 'MSTYP', 'unknown set type '//str(c%mstyp)// &
            ' (0 segment set, 2 part set, 3 part)', error)
         return
      end select
      if (c%msid <= 0) then
         call field_error(deck, blk, ic, 2, w, 'MSID', 'master set id must be > 0, got '// &
                          str(c%msid), error)
      end if
   end subroutine check_types

   !> *CONTROL_CONTACT: SLSFAC of card 1 is used; every other field is read past.
   subroutine read_control_contact(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      if (blk%n < 1) return
      call get_real(deck, blk, 1, 1, w, 'SLSFAC', 0.1_wp, inp%contact%slsfac, error)
      if (allocated(error)) return
      if (inp%contact%slsfac == 0.0_wp) inp%contact%slsfac = 0.1_wp
      if (inp%contact%slsfac < 0.0_wp) call field_error(deck, blk, 1, 1, w, 'SLSFAC', &
         'must be > 0, got '//rstr(inp%contact%slsfac)//' (load curves are not supported)', &
         error)
   end subroutine read_control_contact

   !> *DATABASE_RCFORC: DT BINARY LCUR IOOPT (DT used; 0 means no rcforc file, as in
   !> LS-DYNA).
   subroutine read_rcforc(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      if (blk%n < 1) then
         call block_error(deck, blk, 0, 'missing card 1 (DT BINARY LCUR IOOPT)', error)
         return
      end if
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_real(deck, blk, 1, 1, w, 'DT', 0.0_wp, inp%contact%rcforc_dt, error)
      if (allocated(error)) return
      if (.not. (inp%contact%rcforc_dt >= 0.0_wp)) call field_error(deck, blk, 1, 1, w, 'DT', &
         'output interval must be >= 0 (0: no rcforc file), got '// &
         rstr(inp%contact%rcforc_dt), error)
   end subroutine read_rcforc

   !> *DEFINE_BOX: BOXID XMN XMX YMN YMX ZMN ZMX.
   subroutine read_define_box(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(box_in_t) :: b
      integer :: w(8), i0, d
      character(3), parameter :: ax(3) = ['X', 'Y', 'Z']
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (BOXID XMN XMX YMN YMX ZMN ZMX)', error)
         return
      end if
      call get_int(deck, blk, i0, 1, w, 'BOXID', 0, b%label, error)
      if (allocated(error)) return
      if (b%label <= 0) then
         call field_error(deck, blk, i0, 1, w, 'BOXID', 'box id must be > 0, got '// &
                          str(b%label), error)
         return
      end if
      do d = 1, 3
         call get_real(deck, blk, i0, 2*d, w, trim(ax(d))//'MN', 0.0_wp, b%lo(d), error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 2*d + 1, w, trim(ax(d))//'MX', 0.0_wp, b%hi(d), error)
         if (allocated(error)) return
         if (b%hi(d) < b%lo(d)) then
            call field_error(deck, blk, i0, 2*d + 1, w, trim(ax(d))//'MX', 'must be >= '// &
                             trim(ax(d))//'MN = '//rstr(b%lo(d)), error)
            return
         end if
      end do
      b%ifile = blk%ifile
      b%line = blk%cards(i0)%line
      if (.not. allocated(inp%contact%boxes)) allocate(inp%contact%boxes(0))
      inp%contact%boxes = [inp%contact%boxes, b]
   end subroutine read_define_box
end module dx_read_contact
