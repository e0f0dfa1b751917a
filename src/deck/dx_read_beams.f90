!> Readers for the beam and discrete-mass keywords: *SECTION_BEAM, *ELEMENT_BEAM (+ the
!> _THICKNESS, _OFFSET and _ORIENTATION options and their combinations), *ELEMENT_MASS and
!> *ELEMENT_INERTIA, with the fields and defaults of the LS-DYNA Keyword User's Manual,
!> Vol. I (R13). Every field is read; a value that would change LS-DYNA's results and that
!> dynx does not implement is an error naming the field (docs/keywords.md, "Beams").
!> *SECTION_BEAM card 1: SECID ELFORM SHRF QR/IRID CST SCOOR NSM; card 2 (ELFORM 2, the
!>   Belytschko-Schwer resultant beam): A ISS ITT J SA IST (J = 0: ISS + ITT, the polar
!>   moment). ELFORM 1 (Hughes-Liu with cross-section integration, dx_beam_hl): card 2
!>   TS1 TS2 TT1 TT2 NSLOC NTLOC, the thicknesses in s and t at N1 and N2 (CST 0, rectangle) or
!>   the outer and inner diameters at N1 and N2 (CST 1, tube); TS2 = 0 (TT2 = 0) takes TS1
!>   (TT1); QR 1-5 (LS-DYNA's rules) or QR/IRID = -n, the user rule n of *INTEGRATION_BEAM
!>   (CST 0 or 2: TS, TT are the thicknesses that scale its points); CST 2 with a built-in rule,
!>   CST 1 with a user rule and NSLOC, NTLOC other than -1, 0, 1 (or /= 0 on a tube) are
!>   refused naming the field: NSLOC = 1 puts the nodes' line on the side s = +TS/2 (LS-DYNA's
!>   reference surface). The other formulations are refused at ELFORM.
!> *INTEGRATION_BEAM card 1: IRID NIP RA ICST K; card 2 (ICST > 0 only): D1 D2 D3 D4 SREF TREF
!>   D5 D6; then NIP cards S T WF PID (the manual's layout, Vol. I "*INTEGRATION_BEAM"): the
!>   point at (S TS/2, T TT/2) with the area WF A, A = RA TS TT. ICST 0 (the user's points) is
!>   read; the standard sections ICST 1-22 are refused naming ICST, a per-point part PID /= 0
!>   naming PID (one material per section).
!> *ELEMENT_BEAM card 1: EID PID N1 N2 N3 RT1 RR1 RT2 RR2 LOCAL (i8; long i20); then, in
!>   the manual's order, the _THICKNESS card PARM1..PARM5 (ELFORM 2: A ISS ITT J SA; 0: the
!>   section's), the _OFFSET card WX1 WY1 WZ1 WX2 WY2 WZ2 (must be 0: no offsets), the
!>   _ORIENTATION card VX VY VZ (the orientation vector, used when N3 = 0). The other
!>   options (_PID, _SCALAR, _SECTION, _WARPAGE, _ELBOW) are not registered: --check lists
!>   them as unknown keywords.
!> *ELEMENT_MASS: EID NID MASS PID (i8 i8 e16 i8; long 20 each).
!> *ELEMENT_INERTIA card 1: EID NID CSID; card 2: IXX IXY IXZ IYY IYZ IZZ MASS.
module dx_read_beams
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor
   use dx_deck_registry, only: registry_t
   use dx_model, only: section_t
   use dx_model_input, only: model_input_t, add_element, SOLID_CARD_NODES, beam_in_t, &
                             mass_in_t, origin, beam_rule_in_t
   use dx_read_nodes_elements, only: section_block, read_section_id, add_section
   implicit none
   private
   public :: register_beams

contains

   !> Add this family's keywords to the registry.
   subroutine register_beams(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('SECTION_BEAM', read_section_beam, title=.true.)
      call reg%add('ELEMENT_BEAM', read_element_beam)
      call reg%add('ELEMENT_BEAM_THICKNESS', read_element_beam)
      call reg%add('ELEMENT_BEAM_OFFSET', read_element_beam)
      call reg%add('ELEMENT_BEAM_ORIENTATION', read_element_beam)
      call reg%add('ELEMENT_BEAM_THICKNESS_OFFSET', read_element_beam)
      call reg%add('ELEMENT_BEAM_THICKNESS_ORIENTATION', read_element_beam)
      call reg%add('ELEMENT_BEAM_OFFSET_ORIENTATION', read_element_beam)
      call reg%add('ELEMENT_BEAM_THICKNESS_OFFSET_ORIENTATION', read_element_beam)
      call reg%add('ELEMENT_MASS', read_element_mass)
      call reg%add('ELEMENT_INERTIA', read_element_inertia)
      call reg%add('INTEGRATION_BEAM', read_integration_beam)
   end subroutine register_beams

   !> *SECTION_BEAM: two cards per section (a title card first with _TITLE).
   subroutine read_section_beam(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, step, cst, k
      real(wp) :: qr, scoor, nsm
      type(section_t) :: s
      type(card_t) :: c
      character(len=3), parameter :: PNAME(6) = ['A  ', 'ISS', 'ITT', 'J  ', 'SA ', 'IST']
      call section_block(deck, blk, 2, 'SECID ELFORM SHRF QR/IRID CST SCOOR NSM', c, ic, step)
      do while (ic <= blk%n .and. .not. c%halt())
         s = section_t()
         s%beam = .true.
         call read_section_id(blk, ic, c, s)
         call c%int('ELFORM', 1, s%elform)
         if (s%elform == 0) s%elform = 1
         call c%real('SHRF', 1.0_wp, s%shrf)
         if (s%shrf == 0.0_wp) s%shrf = 1.0_wp
         if (c%ok() .and. s%shrf < 0.0_wp) call c%fail('SHRF', 'shear factor must be > 0, '// &
                                                       'got '//rstr(s%shrf))
         call c%real('QR/IRID', 2.0_wp, qr)     ! cross-section rule: integrated beams only
         call c%int('CST', 0, cst, min=0, max=2)   ! cross-section type: integrated beams only
         call c%real('SCOOR', 0.0_wp, scoor)
         call c%real('NSM', 0.0_wp, nsm, min=0.0_wp)
         if (c%ok() .and. s%elform /= 2 .and. s%elform /= 1) call c%fail('ELFORM', 'beam '// &
            'formulation '//str(s%elform)//' is not supported (supported: 1 Hughes-Liu, '// &
            '2 Belytschko-Schwer resultant beam)')
         if (c%ok() .and. s%elform == 1) call hl_rule(c, qr, cst, s)
         if (c%ok() .and. scoor /= 0.0_wp) call c%fail('SCOOR', 'cross-section location '// &
            rstr(scoor)//' is not supported (supported: 0, the frame from N1, N2 and the '// &
            'orientation)')
         s%nsm = nsm
         if (c%halt()) exit
         if (s%elform == 1) then
            if (.not. card_follows(c, blk, ic, 'TS1 TS2 TT1 TT2 NSLOC NTLOC) of section '// &
                                   str(s%label))) exit
            call hl_card(c, s)
            if (c%halt()) exit
            call add_section(inp, s, blk, ic, step)
            cycle
         end if
         if (.not. card_follows(c, blk, ic, 'A ISS ITT J SA IST) of section '//str(s%label))) &
            exit
         do k = 1, 6
            call c%real(trim(PNAME(k)), 0.0_wp, s%bprop(k))
         end do
         if (c%ok() .and. .not. (s%bprop(1) > 0.0_wp)) call c%fail('A', 'cross-section '// &
            'area must be > 0, got '//rstr(s%bprop(1)))
         if (c%ok() .and. .not. (s%bprop(2) > 0.0_wp)) call c%fail('ISS', 'moment of '// &
            'inertia must be > 0, got '//rstr(s%bprop(2)))
         if (c%ok() .and. .not. (s%bprop(3) > 0.0_wp)) call c%fail('ITT', 'moment of '// &
            'inertia must be > 0, got '//rstr(s%bprop(3)))
         if (c%ok() .and. s%bprop(4) < 0.0_wp) call c%fail('J', 'torsional constant must '// &
            'be >= 0, got '//rstr(s%bprop(4)))
         if (s%bprop(4) == 0.0_wp) s%bprop(4) = s%bprop(2) + s%bprop(3)
         if (c%ok() .and. s%bprop(5) < 0.0_wp) call c%fail('SA', 'shear area must be >= 0, '// &
            'got '//rstr(s%bprop(5)))
         if (c%ok() .and. s%bprop(6) /= 0.0_wp) call c%fail('IST', 'product of inertia '// &
            rstr(s%bprop(6))//' is not supported (supported: 0, s and t principal axes)')
         if (c%halt()) exit
         call add_section(inp, s, blk, ic, step)
      end do
      call c%done(error)
   end subroutine read_section_beam

   !> The Hughes-Liu section rule of card 1: QR (1-5, a whole number) and CST (0, 1).
   subroutine hl_rule(c, qr, cst, s)
      type(card_t), intent(inout) :: c
      real(wp), intent(in) :: qr
      integer, intent(in) :: cst
      type(section_t), intent(inout) :: s
      real(wp) :: q
      q = qr
      if (q == 0.0_wp) q = 2.0_wp      ! blank: the default 2x2 Gauss
      if (q < 0.0_wp) then             ! the user rule -q of *INTEGRATION_BEAM (matched at build)
         if (q /= anint(q)) then
            call c%fail('QR/IRID', 'user rule number '//rstr(-q)//' is not a whole number')
         else if (cst == 1) then
            call c%fail('CST', 'a user integration rule (QR/IRID '//rstr(q)//') on a tubular '// &
               'section (CST 1) is not supported (supported: CST 0 or 2, TS and TT the '// &
               'thicknesses that scale the rule''s points)')
         else
            s%qr = nint(q)
            s%cst = 0                  ! the rule's frame: the TS x TT thicknesses
         end if
         return
      end if
      if (q /= anint(q) .or. q < 1.0_wp .or. q > 5.0_wp) then
         call c%fail('QR/IRID', 'quadrature rule '//rstr(q)//' is not supported (supported:'// &
            ' 1 one point, 2 2x2 Gauss, 3 3x3 Gauss, 4 3x3 Lobatto, 5 4x4 Gauss)')
         return
      end if
      if (cst == 2) then
         call c%fail('CST', 'cross-section type 2 (arbitrary) with the built-in rule QR '// &
            str(nint(q))//' is not supported (supported: 0 rectangular, 1 tubular; CST 2 '// &
            'with a user rule, QR/IRID < 0 and *INTEGRATION_BEAM)')
         return
      end if
      s%qr = nint(q)
      s%cst = cst
   end subroutine hl_rule

   !> Card 2 of a Hughes-Liu section: TS1 TS2 TT1 TT2 NSLOC NTLOC into s%bprop(1:4).
   subroutine hl_card(c, s)
      type(card_t), intent(inout) :: c
      type(section_t), intent(inout) :: s
      real(wp) :: v
      integer :: k
      character(len=5), parameter :: DN(4) = ['TS1  ', 'TS2  ', 'TT1  ', 'TT2  ']
      character(len=5), parameter :: LN(2) = ['NSLOC', 'NTLOC']
      do k = 1, 4
         call c%real(trim(DN(k)), 0.0_wp, s%bprop(k))
         if (c%ok() .and. s%bprop(k) < 0.0_wp) call c%fail(trim(DN(k)), 'section '// &
            'dimension must be >= 0, got '//rstr(s%bprop(k)))
      end do
      do k = 1, 2
         call c%real(trim(LN(k)), 0.0_wp, v)
         if (c%ok() .and. v /= 0.0_wp .and. abs(v) /= 1.0_wp) call c%fail(trim(LN(k)), &
            'reference surface location '//rstr(v)//' is not supported (supported: 0 the '// &
            'centre, 1 the side at +1, -1 the side at -1)')
         if (c%ok() .and. v /= 0.0_wp .and. s%cst == 1) call c%fail(trim(LN(k)), &
            'reference surface location '//rstr(v)//' on a tubular section (CST 1) is not '// &
            'supported (supported: 0; the offsets of CST 0 and 2)')
         s%bloc(k) = v
      end do
      if (s%bprop(2) == 0.0_wp) s%bprop(2) = s%bprop(1)
      if (s%bprop(4) == 0.0_wp) s%bprop(4) = s%bprop(3)
      if (.not. c%ok()) return
      if (s%cst == 0) then
         if (.not. (s%bprop(1) > 0.0_wp)) call c%fail('TS1', 'thickness in s must be > 0 '// &
            '(rectangular section, CST 0), got '//rstr(s%bprop(1)))
         if (c%ok() .and. .not. (s%bprop(3) > 0.0_wp)) call c%fail('TT1', 'thickness in t '// &
            'must be > 0 (rectangular section, CST 0), got '//rstr(s%bprop(3)))
      else
         if (.not. (s%bprop(1) > 0.0_wp)) call c%fail('TS1', 'outer diameter must be > 0 '// &
            '(tubular section, CST 1), got '//rstr(s%bprop(1)))
         if (c%ok() .and. .not. (s%bprop(3) < s%bprop(1) .and. s%bprop(4) < s%bprop(2))) &
            call c%fail('TT1', 'inner diameters ('//rstr(s%bprop(3))//', '// &
            rstr(s%bprop(4))//') must be below the outer ones ('//rstr(s%bprop(1))//', '// &
            rstr(s%bprop(2))//') (tubular section, CST 1)')
      end if
   end subroutine hl_card

   !> *INTEGRATION_BEAM: card 1 IRID NIP RA ICST K, then (ICST 0) NIP point cards S T WF PID.
   subroutine read_integration_beam(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, nip, icst, kref, k, pid
      type(beam_rule_in_t) :: r
      type(card_t) :: c
      character(len=19), parameter :: SNAME(7) = ['W-section          ', &
         'C-section          ', 'angle section      ', 'T-section          ', &
         'rectangular tubing ', 'Z-section          ', 'trapezoidal section']
      call deck_cursor(deck, blk, c)
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         call c%seek(ic)
         r = beam_rule_in_t()
         call c%int('IRID', 0, r%irid)
         if (c%ok() .and. r%irid <= 0) call c%fail('IRID', 'rule id must be > 0, got '// &
                                                   str(r%irid))
         call c%int('NIP', 0, nip)
         call c%real('RA', 0.0_wp, r%ra)
         call c%int('ICST', 0, icst)
         call c%int('K', 1, kref)           ! the refinement of the standard sections only
         if (c%ok() .and. icst >= 1 .and. icst <= 7) call c%fail('ICST', 'standard '// &
            'cross-section type '//str(icst)//' ('//trim(SNAME(icst))//') is not supported '// &
            '(supported: 0, the user''s points S T WF on NIP cards)')
         if (c%ok() .and. icst /= 0) call c%fail('ICST', 'standard cross-section type '// &
            str(icst)//' is not supported (supported: 0, the user''s points S T WF on NIP cards)')
         if (c%ok() .and. nip <= 0) call c%fail('NIP', 'number of integration points must '// &
            'be > 0 (ICST 0: the user''s points), got '//str(nip))
         if (c%ok() .and. .not. (r%ra > 0.0_wp)) call c%fail('RA', 'relative area must be '// &
            '> 0 (ICST 0: the section area is RA TS TT), got '//rstr(r%ra))
         if (c%ok() .and. allocated(inp%brules)) then
            do k = 1, size(inp%brules)
               if (inp%brules(k)%irid /= r%irid) cycle
               call c%fail('IRID', 'rule '//str(r%irid)//' is defined twice (first at line '// &
                  str(inp%brules(k)%src%line)//')')
               exit
            end do
         end if
         if (c%halt()) exit
         r%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         allocate(r%pts(3, nip))
         do k = 1, nip
            if (ic + 1 > blk%n) then
               call c%fail_card(ic, 'missing point card '//str(k)//' of '//str(nip)// &
                                ' (S T WF PID) of rule '//str(r%irid))
               exit
            end if
            ic = ic + 1
            call c%seek(ic)
            call c%real('S', 0.0_wp, r%pts(1, k))
            if (c%ok() .and. abs(r%pts(1, k)) > 1.0_wp) call c%fail('S', 'normalised s '// &
               'of a point must be in [-1, 1], got '//rstr(r%pts(1, k)))
            call c%real('T', 0.0_wp, r%pts(2, k))
            if (c%ok() .and. abs(r%pts(2, k)) > 1.0_wp) call c%fail('T', 'normalised t '// &
               'of a point must be in [-1, 1], got '//rstr(r%pts(2, k)))
            call c%real('WF', 0.0_wp, r%pts(3, k))
            if (c%ok() .and. .not. (r%pts(3, k) > 0.0_wp)) call c%fail('WF', 'weight '// &
               '(area fraction) of a point must be > 0, got '//rstr(r%pts(3, k)))
            call c%int('PID', 0, pid)
            if (c%ok() .and. pid /= 0) call c%fail('PID', 'a part (material) of its own '// &
               'for a point ('//str(pid)//') is not supported (supported: 0, the element''s '// &
               'part)')
            if (c%halt()) exit
         end do
         if (c%halt()) exit
         if (.not. allocated(inp%brules)) allocate(inp%brules(0))
         inp%brules = [inp%brules, r]
         ic = ic + 1
      end do
      call c%done(error)
   end subroutine read_integration_beam

   !> *ELEMENT_BEAM and its _THICKNESS, _OFFSET, _ORIENTATION options: the element goes to
   !> the element list (N1, N2; the other node fields 0), its extras to inp%beams.
   subroutine read_element_beam(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, eid, pid, conn(SOLID_CARD_NODES), k, iv, local, wi
      logical :: thick, offs, orient
      real(wp) :: v
      type(beam_in_t) :: b
      type(card_t) :: c
      character(len=4), parameter :: REL(4) = ['RT1 ', 'RR1 ', 'RT2 ', 'RR2 ']
      character(len=3), parameter :: OFFN(6) = ['WX1', 'WY1', 'WZ1', 'WX2', 'WY2', 'WZ2']
      character(len=2), parameter :: VN(3) = ['VX', 'VY', 'VZ']
      thick = index(blk%base, '_THICKNESS') > 0
      offs = index(blk%base, '_OFFSET') > 0
      orient = index(blk%base, '_ORIENTATION') > 0
      wi = merge(20, 8, blk%long)
      call deck_cursor(deck, blk, c)
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         call c%seek(ic)
         call c%widths([(wi, k = 1, 10)])
         call c%int('EID', 0, eid)
         if (c%ok() .and. eid <= 0) call c%fail('EID', 'element id must be > 0, got '//str(eid))
         call c%int('PID', 0, pid)
         if (c%ok() .and. pid <= 0) call c%fail('PID', 'part id must be > 0, got '//str(pid))
         conn = 0
         do k = 1, 2
            call c%int('N'//str(k), 0, conn(k))
            if (c%ok() .and. conn(k) <= 0) call c%fail('N'//str(k), 'node id must be > 0, '// &
                                                       'got '//str(conn(k)))
         end do
         b = beam_in_t()
         call c%int('N3', 0, b%n3)
         if (c%ok() .and. b%n3 < 0) call c%fail('N3', 'orientation node id must be >= 0, '// &
            'got '//str(b%n3))
         do k = 1, 4
            call c%int(trim(REL(k)), 0, iv)
            if (c%ok() .and. iv /= 0) call c%fail(trim(REL(k)), 'release condition '// &
               str(iv)//' is not supported (supported: 0, no release)')
         end do
         call c%int('LOCAL', 2, local, min=0, max=2)   ! the axes of the release flags
         if (c%halt()) exit
         call add_element(inp, eid, pid, conn, blk%ifile, blk%cards(ic)%line)
         if (thick) then
            call next_card('PARM1 PARM2 PARM3 PARM4 PARM5')
            if (c%halt() .or. ic > blk%n) exit
            do k = 1, 5
               call c%real('PARM'//str(k), 0.0_wp, b%parm(k))
               if (c%ok() .and. b%parm(k) < 0.0_wp) call c%fail('PARM'//str(k), 'section '// &
                  'value must be >= 0, got '//rstr(b%parm(k)))
            end do
         end if
         if (offs) then
            call next_card('WX1 WY1 WZ1 WX2 WY2 WZ2')
            if (c%halt() .or. ic > blk%n) exit
            do k = 1, 6
               call c%real(trim(OFFN(k)), 0.0_wp, v)
               if (c%ok() .and. v /= 0.0_wp) call c%fail(trim(OFFN(k)), 'beam offset '// &
                  rstr(v)//' is not supported (supported: 0, the beam axis through N1, N2)')
            end do
         end if
         if (orient) then
            call next_card('VX VY VZ')
            if (c%halt() .or. ic > blk%n) exit
            do k = 1, 3
               call c%real(VN(k), 0.0_wp, b%v(k))
            end do
            b%has_v = any(b%v /= 0.0_wp)
         end if
         if (c%halt()) exit
         b%e = inp%ne
         call add_beam(inp, b)
         ic = ic + 1
      end do
      call c%done(error)
   contains
      !> the next option card of the element (ic advances), fields of 10 (long: 20)
      subroutine next_card(names)
         character(*), intent(in) :: names
         ic = ic + 1
         if (ic > blk%n) then
            call c%fail_card(ic - 1, 'missing option card ('//names//') of element '//str(eid))
            return
         end if
         call c%seek(ic)
         call c%widths([(merge(20, 10, blk%long), k = 1, 8)])
      end subroutine next_card
   end subroutine read_element_beam

   !> Append the extras of one beam (capacity doubles).
   subroutine add_beam(inp, b)
      type(model_input_t), intent(inout) :: inp
      type(beam_in_t), intent(in) :: b
      type(beam_in_t), allocatable :: t(:)
      if (.not. allocated(inp%beams)) allocate(inp%beams(64))
      if (inp%nbeam == size(inp%beams)) then
         allocate(t(2*inp%nbeam))
         t(1:inp%nbeam) = inp%beams(1:inp%nbeam)
         call move_alloc(t, inp%beams)
      end if
      inp%nbeam = inp%nbeam + 1
      inp%beams(inp%nbeam) = b
   end subroutine add_beam

   !> *ELEMENT_MASS: one card per point mass.
   subroutine read_element_mass(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(mass_in_t) :: m
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         call c%seek(ic)
         if (blk%long) then
            call c%widths([20, 20, 20, 20])
         else
            call c%widths([8, 8, 16, 8])
         end if
         m = mass_in_t()
         call read_eid_nid(c, m)
         call c%real('MASS', 0.0_wp, m%mass)
         if (c%ok() .and. m%mass < 0.0_wp) call c%fail('MASS', 'mass must be >= 0, got '// &
                                                       rstr(m%mass))
         call c%int('PID', 0, m%pid, min=0)   ! the part for output only
         if (c%halt()) exit
         m%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         call add_mass(inp, m)
         ic = ic + 1
      end do
      call c%done(error)
   end subroutine read_element_mass

   !> *ELEMENT_INERTIA: two cards per element. dynx carries one rotary inertia per node
   !> (the explicit rotations have no gyroscopic term), so the tensor must be isotropic.
   subroutine read_element_inertia(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k
      type(mass_in_t) :: m
      type(card_t) :: c
      character(len=3), parameter :: IN(6) = ['IXX', 'IXY', 'IXZ', 'IYY', 'IYZ', 'IZZ']
      call deck_cursor(deck, blk, c)
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         call c%seek(ic)
         call c%widths([(merge(20, 8, blk%long), k = 1, 3)])
         m = mass_in_t()
         m%inertia = .true.
         call read_eid_nid(c, m)
         call c%int('CSID', 0, m%csid, min=0)   ! axes of the tensor: none for an isotropic one
         if (c%halt()) exit
         if (.not. card_follows(c, blk, ic, 'IXX IXY IXZ IYY IYZ IZZ MASS) of element '// &
                                str(m%eid))) exit
         call c%widths([(merge(20, 10, blk%long), k = 1, 7)])
         do k = 1, 6
            call c%real(trim(IN(k)), 0.0_wp, m%ixx(k))
         end do
         call c%real('MASS', 0.0_wp, m%mass)
         if (c%ok() .and. m%ixx(1) < 0.0_wp) call c%fail('IXX', 'inertia must be >= 0, got '// &
                                                         rstr(m%ixx(1)))
         do k = 2, 6
            if (k == 4 .or. k == 6) then
               if (c%ok() .and. m%ixx(k) /= m%ixx(1)) call c%fail(trim(IN(k)), 'an anisotropic '// &
                  'nodal inertia ('//trim(IN(k))//' = '//rstr(m%ixx(k))//', IXX = '// &
                  rstr(m%ixx(1))//') is not supported: dynx carries one rotary inertia per '// &
                  'node (IXX = IYY = IZZ, products 0)')
            else
               if (c%ok() .and. m%ixx(k) /= 0.0_wp) call c%fail(trim(IN(k)), 'a product of '// &
                  'inertia ('//rstr(m%ixx(k))//') is not supported: dynx carries one rotary '// &
                  'inertia per node (IXX = IYY = IZZ, products 0)')
            end if
         end do
         if (c%ok() .and. m%mass < 0.0_wp) call c%fail('MASS', 'mass must be >= 0, got '// &
                                                       rstr(m%mass))
         if (c%halt()) exit
         m%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         call add_mass(inp, m)
         ic = ic + 2
      end do
      call c%done(error)
   end subroutine read_element_inertia

   !> EID and NID (both > 0) of an *ELEMENT_MASS or *ELEMENT_INERTIA card into m.
   subroutine read_eid_nid(c, m)
      type(card_t), intent(inout) :: c
      type(mass_in_t), intent(inout) :: m
      call c%int('EID', 0, m%eid)
      if (c%ok() .and. m%eid <= 0) call c%fail('EID', 'element id must be > 0, got '// &
                                               str(m%eid))
      call c%int('NID', 0, m%nid)
      if (c%ok() .and. m%nid <= 0) call c%fail('NID', 'node id must be > 0, got '// &
                                               str(m%nid))
   end subroutine read_eid_nid

   !> The cursor on card ic + 1 of blk, the second card of a record whose first is ic; .false.
   !> (and the error 'missing card 2 (what') when the block ends first.
   logical function card_follows(c, blk, ic, what) result(ok)
      type(card_t), intent(inout) :: c
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      character(*), intent(in) :: what
      ok = ic + 1 <= blk%n
      if (ok) then
         call c%seek(ic + 1)
      else
         call c%fail_card(ic, 'missing card 2 ('//what)
      end if
   end function card_follows

   !> Append one point mass / inertia record.
   subroutine add_mass(inp, m)
      type(model_input_t), intent(inout) :: inp
      type(mass_in_t), intent(in) :: m
      if (.not. allocated(inp%pmass)) allocate(inp%pmass(0))
      inp%pmass = [inp%pmass, m]
   end subroutine add_mass
end module dx_read_beams
