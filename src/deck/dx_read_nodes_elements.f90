!> Readers for the mesh and part keywords: *NODE, *ELEMENT_SOLID, *PART (and *PART_CONTACT:
!> its card 3 checked by part_contact_card), *SECTION_SOLID, *HOURGLASS. Field layouts and defaults: LS-DYNA Keyword User's Manual, Vol. I.
!> *NODE: NID X Y Z TC RC as i8,3e16,2i8 (long: i20,3e20,2i20).
!> *ELEMENT_SOLID: EID PID on card 1 and N1..N10 on card 2 (i8 fields, long i20), or the
!> older one-card layout EID PID N1..N8, recognised by text beyond column 16 (long: 40).
module dx_read_nodes_elements
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, get_int, get_real, &
                            field_error, card_error, data_start, collect_error
   use dx_deck_registry, only: registry_t
   use dx_model, only: part_t, section_t, hourglass_t
   use dx_model_input, only: model_input_t, add_node, add_element, origin, input_add_part
   implicit none
   private
   public :: register_nodes_elements, section_block, read_section_id, add_section

contains

   !> Add this family's keywords to the registry.
   subroutine register_nodes_elements(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('NODE', read_node)
      call reg%add('ELEMENT_SOLID', read_element_solid)
      call reg%add('PART', read_part)
      call reg%add('PART_CONTACT', read_part)
      call reg%add('SECTION_SOLID', read_section_solid, title=.true.)
      call reg%add('HOURGLASS', read_hourglass, title=.true.)
   end subroutine register_nodes_elements

   !> *NODE and *ELEMENT_SOLID read the fields in place (dx_card_fields through the deck's
   !> get_int/get_real), not through a card cursor: the cursor holds a copy of its block, and a
   !> mesh block of 1e6 cards would be copied (57 MB more and 5 % slower on a 1e6-node deck).
   subroutine read_node(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(6), ic
      type(error_t), allocatable :: e
      if (blk%long) then
         w = 20
      else
         w = [8, 16, 16, 16, 8, 8]
      end if
      do ic = 1, blk%n
         call node_card(ic, e)
         if (.not. allocated(e)) cycle
         ! --check (deck%check): every bad card of the block; else the first stops it
         call collect_error(error, e)
         if (.not. deck%check) return
      end do
   contains
      subroutine node_card(ic, error)
         integer, intent(in) :: ic
         type(error_t), allocatable, intent(out) :: error
         integer :: nid, tc, rc, k
         real(wp) :: x(3)
         character(len=1), parameter :: xyz(3) = ['X', 'Y', 'Z']
         call get_int(deck, blk, ic, 1, w, 'NID', 0, nid, error)
         if (allocated(error)) return
         if (nid <= 0) then
            call field_error(deck, blk, ic, 1, w, 'NID', 'node id must be > 0, got '// &
                             str(nid), error)
            return
         end if
         do k = 1, 3
            call get_real(deck, blk, ic, 1 + k, w, xyz(k), 0.0_wp, x(k), error)
            if (allocated(error)) return
            ! element volumes are cubes of coordinate differences: (2e100)**3 = 8e300
            if (abs(x(k)) > 1.0e100_wp) call field_error(deck, blk, ic, 1 + k, w, xyz(k), &
               'coordinate '//rstr(x(k), 3)//' is out of range (|x| <= 1E+100: a volume '// &
               'is a cube of coordinates and must stay finite)', error)
            if (allocated(error)) return
         end do
         call get_int(deck, blk, ic, 5, w, 'TC', 0, tc, error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 6, w, 'RC', 0, rc, error)
         if (allocated(error)) return
         if (tc < 0 .or. tc > 7) then
            call field_error(deck, blk, ic, 5, w, 'TC', 'must be 0 to 7, got '//str(tc), error)
            return
         end if
         if (rc < 0 .or. rc > 7) then
            call field_error(deck, blk, ic, 6, w, 'RC', 'must be 0 to 7, got '//str(rc), error)
            return
         end if
         call add_node(inp, nid, x, tc, rc, blk%ifile, blk%cards(ic)%line)
      end subroutine node_card
   end subroutine read_node

   !> --check (deck%check): every bad field of every element; else the first stops the block.
   subroutine read_element_solid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(10), ic, eid, pid, conn(10), k, lim, kn, icn, line, nbad
      logical :: one_line
      type(error_t), allocatable :: e
      w = 8
      lim = 16
      if (blk%long) then
         w = 20
         lim = 40
      end if
      ic = 1
      do while (ic <= blk%n)
         associate (c => blk%cards(ic)%text)
            if (index(c, ',') > 0) then
               one_line = count_commas(c) >= 2
            else
               one_line = .false.
               if (len(c) > lim) one_line = len_trim(c(lim+1:)) > 0
            end if
         end associate
         nbad = error_count()
         call id_field(ic, 1, 'EID', 'element id', eid)
         if (halt()) return
         call id_field(ic, 2, 'PID', 'part id', pid)
         if (halt()) return
         line = blk%cards(ic)%line
         if (one_line) then
            icn = ic
            kn = 2            ! N1 is field 3
            conn(9:10) = 0
         else
            icn = ic + 1
            kn = 0
            if (icn > blk%n) then
               call card_error(deck, blk, ic, 'missing card 2 (N1 ... N8) of element '// &
                               str(eid), e)
               call collect_error(error, e)
               return
            end if
         end if
         do k = 1, merge(8, 10, one_line)
            if (k <= 8) then
               call id_field(icn, kn + k, 'N'//str(k), 'node id', conn(k))
            else
               call get_int(deck, blk, icn, kn + k, w, 'N'//str(k), 0, conn(k), e)
               if (.not. allocated(e) .and. conn(k) /= 0) call field_error(deck, blk, icn, &
                  kn + k, w, 'N'//str(k), '10-node tetrahedra are not supported', e)
               call collect_error(error, e)
            end if
            if (halt()) return
         end do
         if (error_count() == nbad) call add_element(inp, eid, pid, conn(1:8), blk%ifile, line)
         ic = icn + 1
      end do
   contains
      !> field k of card jc: an id that must be > 0 (what names it in the message)
      subroutine id_field(jc, k, name, what, val)
         integer, intent(in) :: jc, k
         character(*), intent(in) :: name, what
         integer, intent(out) :: val
         call get_int(deck, blk, jc, k, w, name, 0, val, e)
         if (.not. allocated(e) .and. val <= 0) call field_error(deck, blk, jc, k, w, name, &
            what//' must be > 0, got '//str(val), e)
         call collect_error(error, e)
      end subroutine id_field
      !> an error stops the block unless --check collects them all
      logical function halt()
         halt = allocated(error) .and. .not. deck%check
      end function halt
      !> errors of the block so far
      integer function error_count()
         error_count = 0
         if (allocated(error)) error_count = 1 + error%nmore + error%ndrop
      end function error_count
   end subroutine read_element_solid

   pure integer function count_commas(s)
      character(*), intent(in) :: s
      integer :: i
      count_commas = 0
      do i = 1, len(s)
         if (s(i:i) == ',') count_commas = count_commas + 1
      end do
   end function count_commas

   !> *PART: heading card, then PID SECID MID EOSID HGID GRAV ADPOPT TMID; pairs repeat.
   subroutine read_part(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, v, k
      logical :: contact
      type(part_t) :: p
      type(card_t) :: c
      character(len=6), parameter :: unsup(3) = ['GRAV  ', 'ADPOPT', 'TMID  ']
      contact = blk%base == 'PART_CONTACT'
      call deck_cursor(deck, blk, c)
      call c%need(2, 'missing card 2 (PID SECID MID EOSID HGID GRAV ADPOPT TMID)')
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         if (ic + 1 > blk%n) then
            call c%fail_card(ic, 'missing card 2 (PID SECID MID ...) after the heading card')
            exit
         end if
         p = part_t()
         call c%seek(ic)
         p%title = c%text()
         p%title = trim(adjustl(p%title(1:min(70, len(p%title)))))
         ic = ic + 1
         call c%seek(ic)
         call c%int('PID', 0, p%label)
         if (c%ok() .and. p%label <= 0) call c%fail('PID', 'part id must be > 0, got '// &
                                                    str(p%label))
         call c%int('SECID', 0, p%secid)
         call c%int('MID', 0, p%mid)
         call c%int('EOSID', 0, p%eosid)
         if (c%ok() .and. p%eosid < 0) call c%fail('EOSID', 'equation of state id must be '// &
                                                   '>= 0, got '//str(p%eosid))
         call c%int('HGID', 0, p%hgid)
         do k = 1, 3
            call c%int(trim(unsup(k)), 0, v)
            if (c%ok() .and. v /= 0) call c%fail(trim(unsup(k)), 'nonzero value '//str(v)// &
                                                 ' is not supported')
         end do
         if (c%ok() .and. p%secid <= 0) call c%fail('SECID', 'a section id is required')
         if (c%ok() .and. p%mid <= 0) call c%fail('MID', 'a material id is required')
         if (c%halt()) exit
         ! card 3 of the block's last part left blank (stripped as layout: a blank line
         ! before the next keyword) or missing: a card of defaults, as LS-DYNA reads it
         if (contact .and. ic + 1 <= blk%n) then
            call c%seek(ic + 1)
            call part_contact_card(c)
            if (c%halt()) exit
         end if
         call input_add_part(inp, p, origin(blk%ifile, blk%cards(ic)%line, blk%name))
         ic = ic + merge(2, 1, contact)
      end do
      call c%done(error)
   end subroutine read_part

   !> *PART_CONTACT card 3: FS FD DC VC OPTT SFT SSF CPARM8 (LS-DYNA Keyword User's Manual,
   !> *PART). FS FD DC VC are the part's friction (static, dynamic, decay, viscous): LS-DYNA
   !> uses them only in a *CONTACT whose FS is -1, which dynx refuses naming FS, so they
   !> cannot act here; they are range-checked (>= 0) and accepted. OPTT (a contact thickness
   !> for the part's shells and beams), SFT (its scale factor), SSF (a scale factor of the
   !> part's slave penalty stiffness) and CPARM8 (spot-weld beams in *CONTACT_AUTOMATIC_
   !> GENERAL) would change the contact forces and are not implemented: a value other than
   !> the default (0; SFT and SSF also 1) is an error naming the field.
   subroutine part_contact_card(c)
      type(card_t), intent(inout) :: c
      real(wp) :: x
      integer :: k
      character(len=2), parameter :: fr(4) = ['FS', 'FD', 'DC', 'VC']
      do k = 1, 4
         call c%real(trim(fr(k)), 0.0_wp, x, min=0.0_wp)
      end do
      call c%real('OPTT', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('OPTT', 'a contact thickness of the part ('// &
         rstr(x)//') is not implemented (0: the section''s thickness)')
      call c%real('SFT', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp .and. x /= 1.0_wp) call c%fail('SFT', 'a contact '// &
         'thickness scale factor ('//rstr(x)//') is not implemented (0 or 1)')
      call c%real('SSF', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp .and. x /= 1.0_wp) call c%fail('SSF', 'a part''s slave '// &
         'penalty scale factor ('//rstr(x)//') is not implemented (0 or 1; scale the '// &
         'contact''s SFS instead)')
      call c%real('CPARM8', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('CPARM8', 'spot-weld beam contact ('// &
         'CPARM8 = '//rstr(x)//') is not implemented')
   end subroutine part_contact_card

   !> *SECTION_SOLID: SECID ELFORM AET per card (each after its title card with _TITLE).
   subroutine read_section_solid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, step
      type(section_t) :: s
      type(card_t) :: c
      call section_block(deck, blk, 1, 'SECID ELFORM AET', c, ic, step)
      do while (ic <= blk%n .and. .not. c%halt())
         s = section_t()
         call read_section_id(blk, ic, c, s)
         call c%int('ELFORM', 1, s%elform)
         if (s%elform == 0) s%elform = 1
         if (c%ok() .and. s%elform /= 1 .and. s%elform /= 2 .and. s%elform /= 10) &
            call c%fail('ELFORM', 'solid formulation '//str(s%elform)//' is not supported '// &
                        '(supported: 1 one-point, 2 selectively reduced, 10 one-point '// &
                        'tetrahedron)')
         call c%int('AET', 0, s%aet)
         if (c%ok() .and. s%aet /= 0) call c%fail('AET', 'ambient element types are not '// &
                                                  'supported')
         if (c%halt()) exit
         call add_section(inp, s, blk, ic, step)
      end do
      call c%done(error)
   end subroutine read_section_solid

   !> Start reading a block of sections of ncards cards each (with _TITLE a title card
   !> before each): the cursor c, the first section's card 1 ic and the step from one
   !> section to the next; an error naming the fields of card 1 when it is missing
   !> (*SECTION_SOLID, *SECTION_SHELL, *SECTION_BEAM).
   subroutine section_block(deck, blk, ncards, card1, c, ic, step)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ncards
      character(*), intent(in) :: card1
      type(card_t), intent(out) :: c
      integer, intent(out) :: ic, step
      ic = data_start(blk)
      step = ncards + ic - 1
      call deck_cursor(deck, blk, c)
      call c%need(ic, 'missing card 1 ('//card1//')')
   end subroutine section_block

   !> A section's title (with _TITLE: the card before ic, else blank) and its SECID (> 0) on
   !> card ic; leaves c at card ic (*SECTION_SOLID, *SECTION_SHELL, *SECTION_BEAM).
   subroutine read_section_id(blk, ic, c, s)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      type(card_t), intent(inout) :: c
      type(section_t), intent(inout) :: s
      s%title = ''
      if (blk%opt_title) s%title = trim(adjustl(blk%cards(ic-1)%text))
      call c%seek(ic)
      call c%int('SECID', 0, s%label)
      if (c%ok() .and. s%label <= 0) call c%fail('SECID', 'section id must be > 0, got '// &
                                                 str(s%label))
   end subroutine read_section_id

   !> Append section s, read from card ic of blk, to the input (and where it was read);
   !> ic moves on by step to the next section's card 1.
   subroutine add_section(inp, s, blk, ic, step)
      type(model_input_t), intent(inout) :: inp
      type(section_t), intent(in) :: s
      type(block_t), intent(in) :: blk
      integer, intent(inout) :: ic
      integer, intent(in) :: step
      inp%sections = [inp%sections, s]
      inp%section_src = [inp%section_src, origin(blk%ifile, blk%cards(ic)%line, blk%name)]
      ic = ic + step
   end subroutine add_section

   !> *HOURGLASS: HGID IHQ QM IBQ Q1 Q2 QB/VDC QW; blank or zero values defer to *CONTROL_*.
   subroutine read_hourglass(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, step
      type(hourglass_t) :: h
      type(card_t) :: c
      step = data_start(blk)
      call deck_cursor(deck, blk, c)
      call c%need(step, 'missing card 1 (HGID IHQ QM IBQ Q1 Q2 QB QW)')
      ic = step
      do while (ic <= blk%n .and. .not. c%halt())
         h = hourglass_t()
         call c%seek(ic)
         call c%int('HGID', 0, h%label)
         if (c%ok() .and. h%label <= 0) call c%fail('HGID', 'hourglass id must be > 0, got '// &
                                                    str(h%label))
         call c%int('IHQ', 0, h%ihq)
         if (c%ok() .and. (h%ihq < 0 .or. h%ihq > 5)) call c%fail('IHQ', 'hourglass type '// &
            str(h%ihq)//' is not supported (supported: 1 to 5)')
         call c%real('QM', -1.0_wp, h%qm)
         call c%int('IBQ', 0, h%ibq)
         call c%real('Q1', -1.0_wp, h%q1)
         call c%real('Q2', -1.0_wp, h%q2)
         call c%real('QB', -1.0_wp, h%qb)
         call c%real('QW', -1.0_wp, h%qw)
         if (c%halt()) exit
         inp%hourglasses = [inp%hourglasses, h]
         inp%hourglass_src = [inp%hourglass_src, origin(blk%ifile, blk%cards(ic)%line, &
                                                        blk%name)]
         ic = ic + step
      end do
      call c%done(error)
   end subroutine read_hourglass
end module dx_read_nodes_elements
