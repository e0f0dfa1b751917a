!> Readers for the boundaries of 2D decks (dx_quad2d: *SECTION_SHELL ELFORM 13, 14, 15):
!> *BOUNDARY_NON_REFLECTING_2D card 1: NSID AD AS (LS-DYNA Keyword User's Manual, Vol. I:
!> NSID a node set whose element edges form the transmitting boundary; AD, AS the activation
!> of the dilatational and the shear dashpot: 0 on (the default), nonzero off). The edges
!> and dashpots are made at build (dx_build_twod), the forces in the cycle (dx_nonreflecting).
!> dynx keywords of the laser-damage scenes (seed article 3; docs/keywords.md):
!> *DYNX_PRESSURE_TABLE card 1: NSID SF; card 2: FILE (columns 1-80, found as an *INCLUDE
!>   file): a pressure p(r, t) on the free edges of node set NSID, bilinear in the table of
!>   the data file (LASNEX-style: '#' comments, then NR NT, the NR radii, the NT times, and
!>   NT rows of NR pressures, free format; decks/pressure_table/README.md).
!> *DYNX_PRESSURE_PULSE card 1: NSID PMAX T0 FWHM DX DY: a Gaussian pulse in time with a
!>   cos**2 distribution over the surface, theta between the light's direction (DX, DY) and
!>   the inward normal, zero where the surface faces away.
!> *DYNX_ENERGY_DEPOSITION card 1: PID RATE TSTART TEND: energy into part PID at the constant
!>   RATE (per unit thickness or per radian in 2D) from TSTART to TEND.
!> *CONTACT_2D_AUTOMATIC_SINGLE_SURFACE: the same cards, SIDM blank (the free edges of part set
!>   SIDS against their own nodes).
!> *CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE (_ID/_TITLE) card 1: SIDS SIDM SFACT FREQ FS FD DC
!>   MEMBS (LS-DYNA Keyword User's Manual, *CONTACT_2D_AUTOMATIC; SIDS, SIDM read as *SET_PART
!>   ids); optional card 2: TBIRTH TDEATH SOS SOM NDS NDM COF INIT; optional card 3: VC VDC IPF
!>   SLIDE ISTIFF TIEDGAP IGAPCL TIETYP. FREQ is read past (dynx searches every cycle); ISTIFF
!>   as the manual defines it: 1 the stiffness scaled from the segment masses and the
!>   explicit step (LS-DYNA's explicit default; here the SOFT = 1 form, SOFSCL = 0.1 SFACT,
!>   SFACT at most 10 so the spring stays stable at the step), 2 the stiffness from the
!>   segment stiffness and dimensions (the penalty SFACT x 0.1 K l**2/V); ISTIFF 0 (blank)
!>   is dynx's default, the segment form of 2, which differs from LS-DYNA's explicit default
!>   (1): the build says so in a warning (dx_contact2d);
!>   FD other than 0 or FS, DC, MEMBS and the other fields of cards 2-3 other than their
!>   defaults are refused (not implemented).
module dx_read_twod
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start, include_path
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, nr2d_in_t, edge_press_in_t, deposit_in_t, &
                             c2d_in_t
   use dx_strings, only: str, rstr
   implicit none
   private
   public :: register_twod

contains

   !> Add this family's keywords to the registry.
   subroutine register_twod(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('BOUNDARY_NON_REFLECTING_2D', read_nonreflecting_2d)
      call reg%add('DYNX_PRESSURE_TABLE', read_pressure_table)
      call reg%add('DYNX_PRESSURE_PULSE', read_pulse_or_deposit)
      call reg%add('DYNX_ENERGY_DEPOSITION', read_pulse_or_deposit)
      call reg%add('CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE', read_contact_2d, title=.true., &
                   id=.true.)
      call reg%add('CONTACT_2D_AUTOMATIC_SINGLE_SURFACE', read_contact_2d, title=.true., &
                   id=.true.)
      call reg%add('CONTACT_2D_AUTOMATIC_TIED', read_contact_2d, title=.true., id=.true.)
      call reg%add('CONTACT_2D_AUTOMATIC_TIED_ONE_WAY', read_contact_2d, title=.true., &
                   id=.true.)
   end subroutine register_twod

   !> *BOUNDARY_NON_REFLECTING_2D: one card NSID AD AS per boundary
   subroutine read_nonreflecting_2d(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(nr2d_in_t) :: b
      integer :: ic, ad, as
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card '//str(data_start(blk))//' (NSID AD AS)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         b = nr2d_in_t()
         call c%id('NSID', b%nsid)
         call c%int('AD', 0, ad)
         call c%int('AS', 0, as)
         if (c%ok() .and. ad /= 0 .and. as /= 0) call c%fail('AS', 'AD and AS both off ('// &
            str(ad)//', '//str(as)//') leave no dashpot: remove the card or set one to 0')
         if (c%halt()) exit
         b%ad = ad == 0
         b%as = as == 0
         b%src = origin(blk%ifile, c%card_line(), blk%name)
         inp%nr2d = [inp%nr2d, b]
      end do
      call c%done(error)
   end subroutine read_nonreflecting_2d

   !> *DYNX_PRESSURE_TABLE: card pairs NSID SF / FILE
   subroutine read_pressure_table(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(edge_press_in_t) :: b
      character(:), allocatable :: fname, msg
      integer :: ic
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk) + 1, 'missing card '//str(data_start(blk) + 1)//' (FILE)')
      do ic = data_start(blk), blk%n - 1, 2
         if (c%halt()) exit
         call c%seek(ic)
         b = edge_press_in_t(kind=1)
         call c%id('NSID', b%nsid)
         call c%real('SF', 1.0_wp, b%sf)
         if (b%sf == 0.0_wp) b%sf = 1.0_wp
         call c%seek(ic + 1)
         call c%text_field(1, [80], fname)
         if (c%halt()) exit
         if (len_trim(fname) == 0) then
            call c%fail('FILE', 'the name of the pressure table file is blank')
            exit
         end if
         fname = include_path(deck, deck%files(blk%ifile)%s, fname)   ! as *INCLUDE
         call read_table_file(fname, b, msg)
         if (len(msg) > 0) then
            call c%fail('FILE', msg)
            exit
         end if
         b%src = origin(blk%ifile, c%card_line() - 1, blk%name)
         inp%edge_press = [inp%edge_press, b]
      end do
      call c%done(error)
   end subroutine read_pressure_table

   !> The table of a *DYNX_PRESSURE_TABLE data file into b%r, b%t, b%p; msg: '' or the error
   !> (naming the data file and its line): radii >= 0 and increasing, times increasing.
   subroutine read_table_file(fname, b, msg)
      character(*), intent(in) :: fname
      type(edge_press_in_t), intent(inout) :: b
      character(:), allocatable, intent(out) :: msg
      real(wp), allocatable :: v(:)
      integer, allocatable :: vl(:)
      character(len=4096) :: line
      integer :: u, ios, nl, n, nr, nt, i, j, p0, p1
      real(wp) :: x
      msg = ''
      open(newunit=u, file=fname, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         msg = 'cannot open the pressure table file '//fname
         return
      end if
      allocate(v(1024), vl(1024))
      n = 0; nl = 0
      do
         read(u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         nl = nl + 1
         if (len_trim(line) == len(line)) then
            msg = fname//':'//str(nl)//': line longer than '//str(len(line))//' characters'
            close(u); return
         end if
         if (index(line, '#') > 0) line = line(1:index(line, '#') - 1)
         p0 = 1
         do                                   ! the numbers of the line, in order
            do while (p0 <= len_trim(line) .and. (line(p0:p0) == ' ' .or. line(p0:p0) == ','))
               p0 = p0 + 1
            end do
            if (p0 > len_trim(line)) exit
            p1 = p0
            do while (p1 < len_trim(line) .and. line(p1+1:p1+1) /= ' ' .and. &
                      line(p1+1:p1+1) /= ',')
               p1 = p1 + 1
            end do
            read(line(p0:p1), *, iostat=ios) x
            if (ios /= 0 .or. .not. (abs(x) <= huge(x))) then
               msg = fname//':'//str(nl)//': "'//line(p0:p1)//'" is not a finite number'
               close(u); return
            end if
            if (n == size(v)) then
               v = [v, v]; vl = [vl, vl]
            end if
            n = n + 1; v(n) = x; vl(n) = nl
            p0 = p1 + 1
         end do
      end do
      close(u)
      if (n < 2) then
         msg = fname//':'//str(nl)//': the table needs NR NT first'
         return
      end if
      nr = nint(v(1)); nt = nint(v(2))
      if (nr < 1 .or. nt < 2 .or. v(1) /= nr .or. v(2) /= nt) then
         msg = fname//':'//str(vl(1))//': NR NT = '//rstr(v(1))//' '//rstr(v(2))// &
               ': need whole numbers NR >= 1, NT >= 2'
         return
      end if
      if (n /= 2 + nr + nt + nr*nt) then
         msg = fname//':'//str(vl(n))//': '//str(n - 2)//' numbers after NR NT; the table '// &
               'needs NR + NT + NR*NT = '//str(nr + nt + nr*nt)
         return
      end if
      b%r = v(3:2 + nr)
      b%t = v(3 + nr:2 + nr + nt)
      b%p = reshape(v(3 + nr + nt:n), [nr, nt])
      do i = 1, nr
         if (b%r(i) < 0.0_wp) then
            msg = fname//':'//str(vl(2 + i))//': radius '//str(i)//' = '//rstr(b%r(i))// &
                  ' < 0 (r = x >= 0)'
            return
         end if
         if (i > 1) then
            if (.not. b%r(i) > b%r(i - 1)) then
               msg = fname//':'//str(vl(2 + i))//': radius '//str(i)//' = '//rstr(b%r(i))// &
                     ' is not greater than radius '//str(i - 1)//' = '//rstr(b%r(i - 1))// &
                     ' (radii increase)'
               return
            end if
         end if
      end do
      do j = 2, nt
         if (.not. b%t(j) > b%t(j - 1)) then
            msg = fname//':'//str(vl(2 + nr + j))//': time '//str(j)//' = '//rstr(b%t(j))// &
                  ' is not greater than time '//str(j - 1)//' = '//rstr(b%t(j - 1))// &
                  ' (times increase)'
            return
         end if
      end do
   end subroutine read_table_file

   !> *DYNX_PRESSURE_PULSE (NSID PMAX T0 FWHM DX DY) and *DYNX_ENERGY_DEPOSITION (PID RATE
   !> TSTART TEND): one record per card
   subroutine read_pulse_or_deposit(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(edge_press_in_t) :: b
      type(deposit_in_t) :: dp
      logical :: pulse
      integer :: ic
      pulse = blk%base == 'DYNX_PRESSURE_PULSE'
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card '//str(data_start(blk))//' ('// &
                  trim(merge('NSID PMAX T0 FWHM DX DY', 'PID RATE TSTART TEND   ', pulse))//')')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         if (pulse) then
            b = edge_press_in_t(kind=2)
            call c%id('NSID', b%nsid)
            call c%real('PMAX', 0.0_wp, b%pmax)
            call c%real('T0', 0.0_wp, b%t0)
            call c%real('FWHM', 0.0_wp, b%fwhm, gt=0.0_wp)
            call c%real('DX', 0.0_wp, b%dir(1))
            call c%real('DY', 0.0_wp, b%dir(2))
            if (c%ok() .and. norm2(b%dir) == 0.0_wp) call c%fail('DY', 'the direction of '// &
               'the light (DX, DY) is zero')
         else
            dp = deposit_in_t()
            call c%id('PID', dp%pid)
            call c%real('RATE', 0.0_wp, dp%rate)
            call c%real('TSTART', 0.0_wp, dp%t1, min=0.0_wp)
            call c%real('TEND', 0.0_wp, dp%t2)
            if (c%ok() .and. .not. dp%t2 > dp%t1) call c%fail('TEND', 'TEND = '// &
               rstr(dp%t2)//' must be greater than TSTART = '//rstr(dp%t1))
         end if
         if (c%halt()) exit
         if (pulse) then
            b%dir = b%dir/norm2(b%dir)
            b%src = origin(blk%ifile, c%card_line(), blk%name)
            inp%edge_press = [inp%edge_press, b]
         else
            dp%src = origin(blk%ifile, c%card_line(), blk%name)
            inp%deposits = [inp%deposits, dp]
         end if
      end do
      call c%done(error)
   end subroutine read_pulse_or_deposit

   !> *CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE: card 1 SIDS SIDM SFACT FREQ FS FD DC MEMBS,
   !> optional card 2 TBIRTH TDEATH SOS SOM NDS NDM COF INIT (defaults only), optional card 3
   !> VC VDC IPF SLIDE ISTIFF TIEDGAP IGAPCL TIETYP (ISTIFF 0, 1, 2; the others defaults)
   subroutine read_contact_2d(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(c2d_in_t) :: b
      real(wp) :: r
      integer :: ic, k
      character(len=6), parameter :: c2(8) = ['TBIRTH', 'TDEATH', 'SOS   ', 'SOM   ', &
                                              'NDS   ', 'NDM   ', 'COF   ', 'INIT  ']
      character(len=7), parameter :: c3(7) = ['VC     ', 'VDC    ', 'IPF    ', 'SLIDE  ', &
                                              'TIEDGAP', 'IGAPCL ', 'TIETYP ']
      call deck_cursor(deck, blk, c)
      ic = data_start(blk)
      if (blk%opt_id .or. blk%opt_title) then          ! CID HEADING
         call c%seek(1)
         call c%int('CID', 0, b%label, min=0)
      end if
      call c%need(ic, 'missing card '//str(ic)//' (SIDS SIDM SFACT FREQ FS FD DC MEMBS)')
      call c%max_cards(ic + 2)
      call c%seek(ic)
      b%single = blk%base == 'CONTACT_2D_AUTOMATIC_SINGLE_SURFACE'
      if (blk%base == 'CONTACT_2D_AUTOMATIC_TIED') b%tied = 1
      if (blk%base == 'CONTACT_2D_AUTOMATIC_TIED_ONE_WAY') b%tied = 2
      call c%id('SIDS', b%sids)
      if (b%single) then                               ! (one surface: SIDS)
         call c%zero_int('SIDM', 'a single-surface contact has one part set, SIDS')
      else
         call c%id('SIDM', b%sidm)
      end if
      call c%real('SFACT', 1.0_wp, b%sfact, min=0.0_wp)
      if (b%sfact == 0.0_wp) b%sfact = 1.0_wp
      call c%skip(1)                                   ! FREQ: dynx searches every cycle
      if (b%tied > 0) then                             ! (a tie does not slide)
         call c%zero_real('FS', 'friction on a tied interface')
      else
         call c%real('FS', 0.0_wp, b%fs, min=0.0_wp)
      end if
      call c%real('FD', 0.0_wp, r, min=0.0_wp)
      if (c%ok() .and. r /= 0.0_wp .and. r /= b%fs) call c%fail('FD', 'a dynamic '// &
         'coefficient other than FS is not implemented (one Coulomb coefficient FS)')
      call c%zero_real('DC', 'an exponential friction decay')
      call c%zero_real('MEMBS', 'membrane slave surfaces')
      if (ic + 1 <= blk%n) then
         call c%seek(ic + 1)
         do k = 1, 8
            call c%zero_real(trim(c2(k)), 'this option of the 2D contact')
         end do
      end if
      if (ic + 2 <= blk%n) then                        ! card 3: VC VDC IPF SLIDE ISTIFF ..
         call c%seek(ic + 2)
         do k = 1, 4
            call c%zero_real(trim(c3(k)), 'this option of the 2D contact')
         end do
         call c%int('ISTIFF', 0, b%istiff)
         if (c%ok() .and. all(b%istiff /= [0, 1, 2])) call c%fail('ISTIFF', 'only 1 '// &
            '(stiffness from the segment masses and the step), 2 (from the segment '// &
            'stiffness and dimensions) and 0 (dynx: as 2) are supported, got '//str(b%istiff))
         if (c%ok() .and. b%istiff == 1 .and. b%sfact > 10.0_wp) call c%fail('SFACT', &
            'with ISTIFF = 1 the contact spring 0.05 SFACT m/dt**2 is stable at the step '// &
            'only up to SFACT = 10 (both passes may hold a pair), got '//rstr(b%sfact))
         if (c%ok() .and. b%istiff == 1 .and. b%tied > 0) call c%fail('ISTIFF', 'a tied '// &
            'interface takes its penalty from the segment stiffness and dimensions (ISTIFF '// &
            '0 or 2); ISTIFF = 1 is not implemented for ties')
         if (b%tied > 0) then                          ! TIEDGAP IGAPCL TIETYP
            call c%real('TIEDGAP', 0.0_wp, b%tiedgap)
            call c%zero_int('IGAPCL', 'IGAPCL = 1 (moving the SURFA nodes onto the SURFB '// &
                            'segments to close the gaps)')
            call c%int('TIETYP', 0, b%tietyp)
            if (c%ok() .and. all(b%tietyp /= [0, 1])) call c%fail('TIETYP', 'TIETYP is 0 '// &
               '(LS-DYNA: kinematic constraints where possible) or 1 (penalty), got '// &
               str(b%tietyp))
         else
            do k = 5, 7
               call c%zero_real(trim(c3(k)), 'this option of the 2D contact')
            end do
         end if
      end if
      if (.not. c%halt()) then
         b%src = origin(blk%ifile, c%card_line(), blk%name)
         inp%contacts2d = [inp%contacts2d, b]
      end if
      call c%done(error)
   end subroutine read_contact_2d
end module dx_read_twod
