!> Readers for the shell keywords: *SECTION_SHELL, *ELEMENT_SHELL (+ _THICKNESS) and
!> *CONTROL_SHELL, with the fields and defaults of the LS-DYNA Keyword User's Manual, Vol. I
!> (R13). Every field is read; a value that would change LS-DYNA's results and that dynx
!> does not implement is an error naming the field (docs/keywords.md, "Shells").
!> *SECTION_SHELL card 1: SECID ELFORM SHRF NIP PROPT QR/IRID ICOMP SETYP (ELFORM 2 the shell;
!>   13, 14, 15 the 2D solids of dx_quad2d, for which NIP, SHRF and the thicknesses T1..T4
!>   have no meaning: plane strain is per unit thickness, axisymmetry per radian);
!>   card 2: T1 T2 T3 T4 NLOC MAREA IDOF EDGSET (one pair per section; _TITLE first).
!> *ELEMENT_SHELL: EID PID N1 N2 N3 N4 N5 N6 N7 N8 (i8; long i20); a triangle repeats N3
!>   (N4 = N3); _THICKNESS adds card 2: THIC1 THIC2 THIC3 THIC4 BETA (e16; long e20).
!> *CONTROL_SHELL card 1: WRPANG ESORT IRNXX ISTUPD THEORY BWC MITER PROJ;
!>   card 2: ROTASCL INTGRD LAMSHT CSTYP6 THSHEL; card 3: PSSTUPD SIDT4TU CNTCO ITSFLG IRQUAD
!>   W-MODE STRETCH ICRQ; card 4: NFAIL1 NFAIL4 PSNFAIL KEEPCS DELFR DRCPSID DRCPRM INTPERR.
module dx_read_shells
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor
   use dx_deck_registry, only: registry_t
   use dx_model, only: section_t
   use dx_model_input, only: model_input_t, add_element, SOLID_CARD_NODES
   use dx_read_nodes_elements, only: section_block, read_section_id, add_section
   implicit none
   private
   public :: register_shells

   integer, parameter :: MAX_NIP = 5   !< through-thickness points (dx_shell_bt's rules)

contains

   !> Add this family's keywords to the registry.
   subroutine register_shells(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('SECTION_SHELL', read_section_shell, title=.true.)
      call reg%add('ELEMENT_SHELL', read_element_shell)
      call reg%add('ELEMENT_SHELL_THICKNESS', read_element_shell)
      call reg%add('CONTROL_SHELL', read_control_shell)
   end subroutine register_shells

   !> *SECTION_SHELL: two cards per section (three and more with ICOMP = 1, refused).
   subroutine read_section_shell(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, step, icomp, setyp, nloc, idof, edgset, k
      real(wp) :: propt, qr, marea
      type(section_t) :: s
      type(card_t) :: c
      call section_block(deck, blk, 2, 'SECID ELFORM SHRF NIP PROPT QR ICOMP SETYP', c, ic, step)
      do while (ic <= blk%n .and. .not. c%halt())
         s = section_t()
         s%shell = .true.
         call read_section_id(blk, ic, c, s)
         call c%int('ELFORM', 2, s%elform)
         if (s%elform == 0) s%elform = 2
         if (c%ok() .and. all(s%elform /= [2, 12, 13, 14, 15, 16])) call c%fail('ELFORM', &
            'shell formulation '//str(s%elform)//' is not supported (supported: 2 Belytschko-'// &
            'Lin-Tsay, 16 fully integrated; 2D solids 12 plane stress, 13 plane strain, 14 '// &
            'area-weighted and 15 volume-weighted axisymmetric)')
         call c%real('SHRF', 1.0_wp, s%shrf)
         if (s%shrf == 0.0_wp) s%shrf = 1.0_wp
         if (c%ok() .and. s%shrf < 0.0_wp) call c%fail('SHRF', 'shear factor must be > 0, '// &
                                                       'got '//rstr(s%shrf))
         call c%int('NIP', 2, s%nip)
         if (s%nip == 0) s%nip = 2
         if (s%elform >= 12 .and. s%elform <= 15) s%nip = 1   ! 2D solids (dx_quad2d): NIP unused
         if (c%ok() .and. (s%nip < 1 .or. s%nip > MAX_NIP)) call c%fail('NIP', &
            'through-thickness points '//str(s%nip)//' are not supported (supported: 1 to '// &
            str(MAX_NIP)//'; 3 to '//str(MAX_NIP)//' with *CONTROL_SHELL INTGRD = 1)')
         call c%real('PROPT', 1.0_wp, propt)      ! printout option: no effect on results
         call c%real('QR', 0.0_wp, qr)
         if (c%ok() .and. qr /= 0.0_wp) call c%fail('QR', 'quadrature rule '//rstr(qr)// &
            ' is not supported (supported: 0 Gauss, or Lobatto by *CONTROL_SHELL INTGRD; '// &
            'user rules *INTEGRATION_SHELL are not read)')
         call c%int('ICOMP', 0, icomp)
         if (c%ok() .and. icomp /= 0) call c%fail('ICOMP', 'composite layer angles '// &
            '(ICOMP = 1) are not supported')
         call c%int('SETYP', 1, setyp)
         if (c%ok() .and. (setyp < 0 .or. setyp > 3)) call c%fail('SETYP', 'must be 1, 2 or '// &
            '3, got '//str(setyp))
         if (c%halt()) exit
         if (ic + 1 > blk%n) then
            call c%fail_card(ic, 'missing card 2 (T1 T2 T3 T4 NLOC MAREA IDOF EDGSET) of '// &
                             'section '//str(s%label))
            exit
         end if
         call c%seek(ic + 1)
         call c%real('T1', 0.0_wp, s%t(1))
         if (c%ok() .and. s%t(1) < 0.0_wp) call c%fail('T1', 'thickness must be >= 0, got '// &
                                                       rstr(s%t(1)))
         do k = 2, 4
            call c%real('T'//str(k), 0.0_wp, s%t(k))
            if (s%t(k) == 0.0_wp) s%t(k) = s%t(1)
            if (c%ok() .and. s%t(k) < 0.0_wp) call c%fail('T'//str(k), 'thickness must be '// &
                                                          '>= 0, got '//rstr(s%t(k)))
         end do
         call c%real('NLOC', 0.0_wp, qr)
         nloc = nint(qr)
         if (c%ok() .and. qr /= 0.0_wp) call c%fail('NLOC', 'reference surface offset '// &
            rstr(qr)//' is not supported (supported: 0, the mid-surface)')
         call c%real('MAREA', 0.0_wp, marea)
         if (c%ok() .and. marea /= 0.0_wp) call c%fail('MAREA', 'non-structural mass per '// &
            'area '//rstr(marea)//' is not supported (supported: 0)')
         call c%int('IDOF', 0, idof)           ! ELFORM 25/26 only: no meaning for ELFORM 2
         call c%int('EDGSET', 0, edgset)       ! an edge set for output: no effect on results
         if (c%halt()) exit
         call add_section(inp, s, blk, ic, step)
      end do
      call c%done(error)
   end subroutine read_section_shell

   !> *ELEMENT_SHELL and *ELEMENT_SHELL_THICKNESS: the elements go to the solid element list
   !> of model_input_t with N5..N8 = 0 (a shell card), the nodal thicknesses to elem_thk.
   subroutine read_element_shell(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, eid, pid, conn(SOLID_CARD_NODES), k, nextra
      real(wp) :: th(4), beta
      logical :: thick
      type(card_t) :: c
      thick = blk%base == 'ELEMENT_SHELL_THICKNESS'
      call deck_cursor(deck, blk, c)
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         call c%seek(ic)
         c%w = merge(20, 8, blk%long)
         call c%int('EID', 0, eid)
         if (c%ok() .and. eid <= 0) call c%fail('EID', 'element id must be > 0, got '//str(eid))
         call c%int('PID', 0, pid)
         if (c%ok() .and. pid <= 0) call c%fail('PID', 'part id must be > 0, got '//str(pid))
         conn = 0
         do k = 1, 4
            call c%int('N'//str(k), 0, conn(k))
            if (c%ok() .and. conn(k) <= 0) call c%fail('N'//str(k), 'node id must be > 0, '// &
                                                       'got '//str(conn(k)))
         end do
         do k = 5, 6                  ! N7, N8 lie beyond the cursor's 8 fields
            call c%int('N'//str(k), 0, nextra)
            if (c%ok() .and. nextra /= 0) call c%fail('N'//str(k), '8-node shells are not '// &
                                                      'supported (N5..N8 must be blank)')
         end do
         if (c%halt()) exit
         if (conn(4) == 0) conn(4) = conn(3)
         th = 0.0_wp
         if (thick) then
            ic = ic + 1
            if (ic > blk%n) then
               call c%fail_card(ic - 1, 'missing card 2 (THIC1 THIC2 THIC3 THIC4 BETA) of '// &
                                'element '//str(eid))
               exit
            end if
            call c%seek(ic)
            c%w = merge(20, 16, blk%long)
            do k = 1, 4
               call c%real('THIC'//str(k), 0.0_wp, th(k))
               if (c%ok() .and. th(k) < 0.0_wp) call c%fail('THIC'//str(k), 'thickness '// &
                  'must be >= 0, got '//rstr(th(k)))
            end do
            if (th(1) > 0.0_wp) then
               do k = 2, 4
                  if (th(k) == 0.0_wp) th(k) = th(1)
               end do
            end if
            call c%real('BETA', 0.0_wp, beta)   ! material angle: isotropic laminae only
            if (c%ok() .and. beta /= 0.0_wp) call c%fail('BETA', 'material angle '// &
               rstr(beta)//' is not supported (isotropic laminae only)')
            if (c%halt()) exit
         end if
         call add_element(inp, eid, pid, conn, blk%ifile, blk%cards(ic)%line)
         call add_thickness(inp, th)
         ic = ic + 1
      end do
      call c%done(error)
   end subroutine read_element_shell

   !> Record the nodal thicknesses of the element just added (0: the section's); the list
   !> exists only once a shell card was read and grows with the element list.
   subroutine add_thickness(inp, th)
      type(model_input_t), intent(inout) :: inp
      real(wp), intent(in) :: th(4)
      real(wp), allocatable :: t(:, :)
      integer :: m
      if (.not. allocated(inp%elem_thk)) then
         allocate(inp%elem_thk(4, size(inp%elem_label)))
         inp%elem_thk = 0.0_wp
      else if (size(inp%elem_thk, 2) < size(inp%elem_label)) then
         m = size(inp%elem_thk, 2)
         allocate(t(4, size(inp%elem_label)))
         t(:, 1:m) = inp%elem_thk
         t(:, m + 1:) = 0.0_wp
         call move_alloc(t, inp%elem_thk)
      end if
      inp%elem_thk(:, inp%ne) = th
   end subroutine add_thickness

   !> *CONTROL_SHELL: up to four cards; defaults of LS-DYNA R13.
   subroutine read_control_shell(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: esort, irnxx, theory, bwc, proj, lamsht, cstyp6, thshel, k, iv
      real(wp) :: v
      character(len=7), parameter :: card3(8) = ['PSSTUPD', 'SIDT4TU', 'CNTCO  ', 'ITSFLG ', &
         'IRQUAD ', 'W-MODE ', 'STRETCH', 'ICRQ   ']
      character(len=7), parameter :: card4(8) = ['NFAIL1 ', 'NFAIL4 ', 'PSNFAIL', 'KEEPCS ', &
         'DELFR  ', 'DRCPSID', 'DRCPRM ', 'INTPERR']
      call deck_cursor(deck, blk, c)
      call c%max_cards(4)
      associate (t => inp%ctrl)
         call c%real('WRPANG', 20.0_wp, t%wrpang)
         if (t%wrpang == 0.0_wp) t%wrpang = 20.0_wp
         call c%int('ESORT', 0, esort)
         if (c%ok() .and. esort /= 0) call c%fail('ESORT', 'sorting triangles to a C0 '// &
            'triangle formulation is not supported: triangles run as degenerate '// &
            'Belytschko-Lin-Tsay quadrilaterals (ESORT = 0)')
         call c%int('IRNXX', -1, irnxx, min=-2, max=1)   ! nodal normals: Hughes-Liu only
         call c%int('ISTUPD', 0, t%istupd)
         if (c%ok() .and. t%istupd /= 0 .and. t%istupd /= 1) call c%fail('ISTUPD', &
            'thickness update '//str(t%istupd)//' is not supported (supported: 0 none, 1 '// &
            'membrane straining)')
         call c%int('THEORY', 2, theory)
         if (theory == 0) theory = 2
         if (c%ok() .and. theory /= 2) call c%fail('THEORY', 'default shell theory '// &
            str(theory)//' is not supported (supported: 2 Belytschko-Lin-Tsay)')
         call c%int('BWC', 2, bwc)
         if (bwc == 0) bwc = 2
         if (c%ok() .and. bwc /= 2) call c%fail('BWC', 'the Belytschko-Wong-Chiang warping '// &
            'stiffness (BWC = 1) is not implemented (supported: 2, Belytschko-Tsay)')
         call c%int('MITER', 1, t%miter)
         if (t%miter == 0) t%miter = 1
         if (c%ok() .and. (t%miter < 1 .or. t%miter > 4)) call c%fail('MITER', &
            'must be 1 (3 secant iterations), 2 (full iteration), 3 (radial scaling) or 4 '// &
            '(dynx: one-step analytic return), got '//str(t%miter))
         call c%int('PROJ', 0, proj, min=0, max=1)     ! warping projection: BWC = 1 only
         call c%next()
         call c%real('ROTASCL', 1.0_wp, t%rotascl)
         if (t%rotascl == 0.0_wp) t%rotascl = 1.0_wp
         if (c%ok() .and. t%rotascl < 0.0_wp) call c%fail('ROTASCL', 'rotary inertia scale '// &
            'must be > 0, got '//rstr(t%rotascl))
         call c%int('INTGRD', 0, t%intgrd, min=0, max=1)
         call c%int('LAMSHT', 0, lamsht)
         if (c%ok() .and. lamsht /= 0) call c%fail('LAMSHT', 'laminated shell theory is '// &
                                                   'not supported (supported: 0)')
         call c%int('CSTYP6', 1, cstyp6)   ! ELFORM 6 only
         call c%int('THSHEL', 0, thshel)
         if (c%ok() .and. thshel /= 0) call c%fail('THSHEL', 'thermal shells are not '// &
                                                   'supported (supported: 0)')
         call c%next()
         do k = 1, 8
            if (k == 5) then                ! IRQUAD: ELFORM 16/9 in-plane rule, not ELFORM 2
               call c%int('IRQUAD', 0, iv)
               cycle
            end if
            call c%zero(trim(card3(k)), 'an option of *CONTROL_SHELL card 3 dynx lacks')
         end do
         call c%next()
         do k = 1, 8
            if (k == 7) then                ! DRCPRM: default 1, a factor of DRCPSID parts
               call c%real('DRCPRM', 1.0_wp, v)
               cycle
            end if
            call c%zero(trim(card4(k)), 'an option of *CONTROL_SHELL card 4 dynx lacks')
         end do
      end associate
      call c%done(error)
   end subroutine read_control_shell
end module dx_read_shells
