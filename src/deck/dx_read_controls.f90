!> Readers for the run controls and output requests: *CONTROL_TERMINATION, *CONTROL_TIMESTEP,
!> *CONTROL_HOURGLASS, *CONTROL_BULK_VISCOSITY, *CONTROL_SOLID (ESORT),
!> *DATABASE_BINARY_D3PLOT, *DATABASE_GLSTAT,
!> *DATABASE_NODOUT, *DATABASE_HISTORY_NODE, *DATABASE_HISTORY_NODE_SET, *DATABASE_HISTORY_SOLID (elout).
!> Layouts and defaults: LS-DYNA Keyword User's Manual, Vol. I (*CONTROL, *DATABASE).
!> LS-DYNA reads a blank field as 0 and then applies the default, so a 0 in a field whose
!> default is not 0 (TSSFAC, QH, Q1, Q2, IHQ, TYPE) also gives the default.
module dx_read_controls
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, get_int, get_list_id, field_error, &
                            block_error, std_widths, check_max_cards
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, label_list_t
   implicit none
   private
   public :: register_controls

contains

   !> Add the *CONTROL_* and *DATABASE_* keywords to the registry.
   subroutine register_controls(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CONTROL_TERMINATION', read_termination)
      call reg%add('CONTROL_TIMESTEP', read_timestep)
      call reg%add('CONTROL_HOURGLASS', read_control_hourglass)
      call reg%add('CONTROL_BULK_VISCOSITY', read_bulk_viscosity)
      call reg%add('CONTROL_SOLID', read_control_solid)
      call reg%add('DATABASE_BINARY_D3PLOT', read_d3plot)
      call reg%add('DATABASE_GLSTAT', read_ascii_db)
      call reg%add('DATABASE_NODOUT', read_ascii_db)
      call reg%add('DATABASE_HISTORY_NODE', read_history)
      call reg%add('DATABASE_HISTORY_NODE_SET', read_history)
      call reg%add('DATABASE_HISTORY_SOLID', read_history)
   end subroutine register_controls

   subroutine need_card(deck, blk, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (blk%n < 1) call block_error(deck, blk, 0, 'missing card 1 ('//what//')', error)
   end subroutine need_card

   !> ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL
   subroutine read_termination(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call need_card(deck, blk, 'ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      associate (t => inp%ctrl)
         call c%real('ENDTIM', 0.0_wp, t%endtim)
         call c%int('ENDCYC', 0, t%endcyc)
         call c%real('DTMIN', 0.0_wp, t%dtmin)
         call c%real('ENDENG', 0.0_wp, t%endeng)
         call c%real('ENDMAS', 0.0_wp, t%endmas)
         ! ENDMAS (percent; default 1e8, in effect off): stop when the mass added by mass
         ! scaling (*CONTROL_TIMESTEP DT2MS; dx_mass_scaling) passes ENDMAS percent of the
         ! model's mass. Without DT2MS it cannot act (the run's log says so).
         if (c%ok() .and. t%endmas < 0.0_wp) call c%fail('ENDMAS', 'must be >= 0 (percent), '// &
            'got '//rstr(t%endmas))
      end associate
      call c%zero('NOSOL', 'dynx always solves')
      call c%done(error)
      if (allocated(error)) return
      inp%has_termination = .true.
      inp%term_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_termination

   !> DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST; card 2 (selective mass scaling)
   !> must be empty. ISDO and TSLIMT act on shells only (dynx has none): accepted. DT2MS and
   !> MS1ST: mass scaling (dx_mass_scaling). ERODE = 1: solids whose step falls below DTMIN
   !> times the first step are eroded (dx_erosion) instead of stopping the run.
   subroutine read_timestep(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      type(card_t) :: c
      character(len=7), parameter :: card2(8) = ['DT2MSF ', 'DT2MSLC', 'IMSCL  ', 'UNUSED ', &
         'UNUSED ', 'RMSCL  ', 'EMSCL  ', 'IHDO   ']
      call need_card(deck, blk, 'DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST', error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      associate (t => inp%ctrl)
         call c%real('DTINIT', 0.0_wp, t%dtinit)
         call c%real('TSSFAC', 0.9_wp, t%tssfac)
         if (t%tssfac == 0.0_wp) t%tssfac = 0.9_wp
         if (c%ok() .and. t%tssfac < 0.0_wp) call c%fail('TSSFAC', 'time step curves '// &
                                                         '(TSSFAC < 0) are not supported')
         call c%int('ISDO', 0, t%isdo, min=0, max=3)
         call c%real('TSLIMT', 0.0_wp, t%tslimt)
         call c%real('DT2MS', 0.0_wp, t%dt2ms)
         call c%int('LCTM', 0, inp%lctm)
         ! ERODE = 1: solids whose step falls below DTMIN * the first step are eroded
         ! (dx_erosion); 0: the run stops there (LS-DYNA's meaning)
         call c%int('ERODE', 0, t%erode, min=0, max=1)
         call c%int('MS1ST', 0, t%ms1st, min=0, max=1)
      end associate
      call c%max_cards(2)
      call c%next()
      do k = 1, 8
         call c%zero(trim(card2(k)), 'card 2 options of *CONTROL_TIMESTEP')
      end do
      call c%done(error)
      if (allocated(error)) return
      inp%timestep_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_timestep

   !> IHQ QH
   subroutine read_control_hourglass(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call need_card(deck, blk, 'IHQ QH', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      associate (t => inp%ctrl)
         call c%int('IHQ', 1, t%ihq)
         if (t%ihq == 0) t%ihq = 1
         if (c%ok() .and. (t%ihq < 1 .or. t%ihq > 5)) call c%fail('IHQ', 'hourglass type '// &
            str(t%ihq)//' is not supported (supported: 1 to 5)')
         call c%real('QH', 0.1_wp, t%qh)
         if (t%qh == 0.0_wp) t%qh = 0.1_wp
         if (c%ok() .and. t%qh < 0.0_wp) call c%fail('QH', 'must be >= 0, got '//rstr(t%qh))
      end associate
      call c%done(error)
   end subroutine read_control_hourglass

   !> Card 1 ESORT FMATRX NIPTETS SWLOCL PSFAIL T10JTOL ICOH TET13K; card 2 PM1-PM10
   !> (node permutation of 10-node tetrahedra, 8 columns each); card 3 (TET13V).
   !> ESORT (0: degenerate solids keep their section's formulation; 1, 2: degenerate
   !> tetrahedra become ELFORM 10; dx_element_types solid_shape). FMATRX (how the
   !> deformation gradient is computed for materials that use it: dynx's are hypoelastic),
   !> NIPTETS (ELFORM 4 tetrahedra), SWLOCL (output), T10JTOL, ICOH (cohesive elements),
   !> TET13K and the permutation act on element types dynx does not have: accepted.
   !> PSFAIL (erosion of the solids of a part set on a negative volume) would change the
   !> results and is not implemented: an error.
   subroutine read_control_solid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      real(wp) :: r
      call need_card(deck, blk, 'ESORT', error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      call c%max_cards(3)
      call c%int('ESORT', 0, inp%ctrl%esort)
      if (c%ok() .and. (inp%ctrl%esort < 0 .or. inp%ctrl%esort > 2)) call c%fail('ESORT', &
         'value '//str(inp%ctrl%esort)//' is not supported (supported: 0, 1, 2)')
      call c%int('FMATRX', 0, v, min=0, max=2)
      call c%int('NIPTETS', 0, v, min=0)
      call c%int('SWLOCL', 0, v, min=0, max=2)
      call c%int('PSFAIL', 0, v)
      if (c%ok() .and. v /= 0) call c%fail('PSFAIL', 'the erosion of solids with a '// &
         'negative volume (part set '//str(v)//') is not implemented')
      call c%real('T10JTOL', 0.0_wp, r)
      call c%real('ICOH', 0.0_wp, r)
      call c%real('TET13K', 0.0_wp, r)
      call c%done(error)
   end subroutine read_control_solid

   !> Q1 Q2 TYPE BTYPE
   subroutine read_bulk_viscosity(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call need_card(deck, blk, 'Q1 Q2 TYPE', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      associate (t => inp%ctrl)
         call c%real('Q1', 1.5_wp, t%q1)
         if (t%q1 == 0.0_wp) t%q1 = 1.5_wp
         call c%real('Q2', 0.06_wp, t%q2)
         if (t%q2 == 0.0_wp) t%q2 = 0.06_wp
         if (c%ok() .and. t%q1 < 0.0_wp) call c%fail('Q1', 'must be >= 0')
         if (c%ok() .and. t%q2 < 0.0_wp) call c%fail('Q2', 'must be >= 0')
         call c%int('TYPE', 1, t%ibq)
         if (t%ibq == 0) t%ibq = 1
         if (c%ok() .and. t%ibq /= 1 .and. t%ibq /= -1 .and. t%ibq /= -2) call c%fail('TYPE', &
            'bulk viscosity type '//str(t%ibq)//' is not supported (supported: 1, -1, -2)')
      end associate
      call c%done(error)
   end subroutine read_bulk_viscosity

   !> Card 1 DT LCDT BEAM NPLTC PSETID; optional card 2 IOOPT RATE CUTOFF WINDOW TYPE PSET.
   !> LCDT (a plot-interval curve) and PSETID (a part subset) are not implemented: errors.
   !> IOOPT (how LCDT is used) matters only with LCDT, RATE CUTOFF WINDOW PSET only with a
   !> filter TYPE 1 or 2 (Butterworth filtering of the plotted element data), which dynx
   !> does not implement: TYPE /= 0 is an error, the other fields are then unused and
   !> accepted (LS-DYNA Keyword User's Manual, *DATABASE_BINARY_D3PLOT).
   subroutine read_d3plot(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: beam, psetid, ioopt, ftype, pset
      real(wp) :: rate, cutoff, window
      type(card_t) :: c
      call need_card(deck, blk, 'DT LCDT BEAM NPLTC PSETID', error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      call c%max_cards(2)
      call c%real('DT', 0.0_wp, inp%d3plot_dt)
      call c%int('LCDT', 0, inp%d3plot_lcdt)
      if (c%ok() .and. inp%d3plot_lcdt /= 0) call c%fail('LCDT', 'plot interval curves '// &
         'are not implemented: give the interval DT (or NPLTC)')
      call c%int('BEAM', 0, beam)   ! discrete elements and beams only: no effect on solids
      call c%int('NPLTC', 0, inp%d3plot_npltc)
      call c%int('PSETID', 0, psetid)
      if (c%ok() .and. psetid /= 0) call c%fail('PSETID', 'value '//str(psetid)// &
         ' is not supported: output of a part subset (d3plot.h5 holds every part)')
      if (c%ok() .and. inp%d3plot_dt < 0.0_wp) call c%fail('DT', 'must be >= 0')
      call c%next()
      call c%int('IOOPT', 0, ioopt, min=0, max=3)
      call c%real('RATE', 0.0_wp, rate, min=0.0_wp)
      call c%real('CUTOFF', 0.0_wp, cutoff, min=0.0_wp)
      call c%real('WINDOW', 0.0_wp, window, min=0.0_wp)
      call c%int('TYPE', 0, ftype, min=0, max=2)
      if (c%ok() .and. ftype /= 0) call c%fail('TYPE', 'filtering of the plotted element '// &
         'data (TYPE = '//str(ftype)//') is not implemented: set TYPE = 0')
      call c%int('PSET', 0, pset, min=0)
      call c%done(error)
      if (allocated(error)) return
      inp%d3plot_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_d3plot

   !> *DATABASE_GLSTAT / *DATABASE_NODOUT: DT BINARY LCUR IOOPT
   subroutine read_ascii_db(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: binary
      real(wp) :: dt
      type(card_t) :: c
      call need_card(deck, blk, 'DT BINARY LCUR IOOPT', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call deck_cursor(deck, blk, c)
      call c%real('DT', 0.0_wp, dt)
      if (c%ok() .and. dt < 0.0_wp) call c%fail('DT', 'must be >= 0')
      call c%int('BINARY', 0, binary)   ! dynx writes ASCII
      call c%zero('LCUR', 'output interval curves')
      call c%done(error)
      if (allocated(error)) return
      if (blk%base == 'DATABASE_GLSTAT') then
         inp%glstat_dt = dt
      else
         inp%nodout_dt = dt
      end if
   end subroutine read_ascii_db

   !> node ids (or node set ids with _SET), 8 per card; zeros are skipped. The block's cards
   !> are appended to the lists at once (card by card was quadratic in the card count).
   subroutine read_history(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k, n
      type(label_list_t), allocatable :: l(:)
      integer :: ids(8)
      w = std_widths(blk, 8)
      allocate(l(blk%n))
      do ic = 1, blk%n
         n = 0
         do k = 1, 8
            call get_list_id(deck, blk, ic, k, w, 'ID'//str(k), ids, n, error)
            if (allocated(error)) return
         end do
         l(ic)%ids = ids(1:n)
         l(ic)%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
      end do
      if (blk%base == 'DATABASE_HISTORY_NODE') then
         inp%hist_nodes = [inp%hist_nodes, l]
      else if (blk%base == 'DATABASE_HISTORY_SOLID') then
         inp%hist_solids = [inp%hist_solids, l]      ! solid element ids (elout)
      else
         inp%hist_node_sets = [inp%hist_node_sets, l]
      end if
   end subroutine read_history
end module dx_read_controls
