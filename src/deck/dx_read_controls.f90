!> Readers for the run controls and output requests: *CONTROL_TERMINATION, *CONTROL_TIMESTEP,
!> *CONTROL_HOURGLASS, *CONTROL_BULK_VISCOSITY, *CONTROL_SOLID (ESORT),
!> *DATABASE_BINARY_D3PLOT, *DATABASE_GLSTAT,
!> *DATABASE_NODOUT, *DATABASE_HISTORY_NODE, *DATABASE_HISTORY_NODE_SET.
!> Layouts and defaults: LS-DYNA Keyword User's Manual, Vol. I (*CONTROL, *DATABASE).
!> LS-DYNA reads a blank field as 0 and then applies the default, so a 0 in a field whose
!> default is not 0 (TSSFAC, QH, Q1, Q2, IHQ, TYPE) also gives the default.
module dx_read_controls
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_log, only: log_warn
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            std_widths, check_max_cards
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
   end subroutine register_controls

   !> error unless field k of card ic is blank or 0
   subroutine must_be_zero(deck, blk, ic, k, w, fname, why, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, why
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v
      call get_real(deck, blk, ic, k, w, fname, 0.0_wp, v, error)
      if (allocated(error)) return
      if (v /= 0.0_wp) call field_error(deck, blk, ic, k, w, fname, 'value '//rstr(v)// &
                                        ' is not supported: '//why, error)
   end subroutine must_be_zero

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
      integer :: w(8)
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'ENDTIM ENDCYC DTMIN ENDENG ENDMAS NOSOL', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      associate (c => inp%ctrl)
         call get_real(deck, blk, 1, 1, w, 'ENDTIM', 0.0_wp, c%endtim, error)
         if (allocated(error)) return
         call get_int(deck, blk, 1, 2, w, 'ENDCYC', 0, c%endcyc, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 3, w, 'DTMIN', 0.0_wp, c%dtmin, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 4, w, 'ENDENG', 0.0_wp, c%endeng, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 5, w, 'ENDMAS', 0.0_wp, c%endmas, error)
         if (allocated(error)) return
         ! LS-DYNA: stop when the mass added by mass scaling (*CONTROL_TIMESTEP DT2MS < 0)
         ! reaches ENDMAS percent of the model's mass. dynx adds no mass, so it never acts.
         if (c%endmas /= 0.0_wp) call log_warn(deck%files(blk%ifile)%s//':'// &
            str(blk%cards(1)%line)//': *CONTROL_TERMINATION ENDMAS = '//rstr(c%endmas)// &
            ' has no effect: it limits the mass added by mass scaling, and dynx adds none '// &
            '(DT2MS is not applied)')
      end associate
      call must_be_zero(deck, blk, 1, 6, w, 'NOSOL', 'dynx always solves', error)
      if (allocated(error)) return
      inp%has_termination = .true.
      inp%term_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_termination

   !> DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST
   subroutine read_timestep(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), k
      character(len=7), parameter :: card2(8) = ['DT2MSF ', 'DT2MSLC', 'IMSCL  ', 'UNUSED ', &
         'UNUSED ', 'RMSCL  ', 'EMSCL  ', 'IHDO   ']
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'DTINIT TSSFAC ISDO TSLIMT DT2MS LCTM ERODE MS1ST', error)
      if (allocated(error)) return
      associate (c => inp%ctrl)
         call get_real(deck, blk, 1, 1, w, 'DTINIT', 0.0_wp, c%dtinit, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 2, w, 'TSSFAC', 0.9_wp, c%tssfac, error)
         if (allocated(error)) return
         if (c%tssfac == 0.0_wp) c%tssfac = 0.9_wp
         if (c%tssfac < 0.0_wp) then
            call field_error(deck, blk, 1, 2, w, 'TSSFAC', 'time step curves (TSSFAC < 0) '// &
                             'are not supported', error)
            return
         end if
         call get_int(deck, blk, 1, 3, w, 'ISDO', 0, c%isdo, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 4, w, 'TSLIMT', 0.0_wp, c%tslimt, error)
         if (allocated(error)) return
         call get_real(deck, blk, 1, 5, w, 'DT2MS', 0.0_wp, c%dt2ms, error)
         if (allocated(error)) return
         call get_int(deck, blk, 1, 6, w, 'LCTM', 0, inp%lctm, error)
         if (allocated(error)) return
         call get_int(deck, blk, 1, 7, w, 'ERODE', 0, c%erode, error)
         if (allocated(error)) return
      end associate
      call must_be_zero(deck, blk, 1, 8, w, 'MS1ST', 'first-step-only mass scaling', error)
      if (allocated(error)) return
      ! card 2 (mass scaling variants) may be present but must be empty
      call check_max_cards(deck, blk, 2, error)
      if (allocated(error)) return
      do k = 1, 8
         call must_be_zero(deck, blk, 2, k, w, trim(card2(k)), &
                           'card 2 options of *CONTROL_TIMESTEP', error)
         if (allocated(error)) return
      end do
      inp%timestep_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_timestep

   !> IHQ QH
   subroutine read_control_hourglass(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'IHQ QH', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_int(deck, blk, 1, 1, w, 'IHQ', 1, inp%ctrl%ihq, error)
      if (allocated(error)) return
      if (inp%ctrl%ihq == 0) inp%ctrl%ihq = 1
      if (inp%ctrl%ihq < 1 .or. inp%ctrl%ihq > 5) then
         call field_error(deck, blk, 1, 1, w, 'IHQ', 'hourglass type '//str(inp%ctrl%ihq)// &
                          ' is not supported (supported: 1 to 5)', error)
         return
      end if
      call get_real(deck, blk, 1, 2, w, 'QH', 0.1_wp, inp%ctrl%qh, error)
      if (allocated(error)) return
      if (inp%ctrl%qh == 0.0_wp) inp%ctrl%qh = 0.1_wp
      if (inp%ctrl%qh < 0.0_wp) then
         call field_error(deck, blk, 1, 2, w, 'QH', 'must be >= 0, got '// &
                          rstr(inp%ctrl%qh), error)
      end if
   end subroutine read_control_hourglass

   !> ESORT FMATRX NIPTETS SWLOCL PSFAIL T10JTOL ICOH TET13K: ESORT (0: degenerate solids keep
   !> their section's formulation; 1, 2: degenerate tetrahedra become ELFORM 10;
   !> dx_element_types solid_shape); the other
   !> fields and cards (solid-element options dynx has no use for) are read past.
   subroutine read_control_solid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'ESORT', error)
      if (allocated(error)) return
      call get_int(deck, blk, 1, 1, w, 'ESORT', 0, inp%ctrl%esort, error)
      if (allocated(error)) return
      if (inp%ctrl%esort < 0 .or. inp%ctrl%esort > 2) then
         call field_error(deck, blk, 1, 1, w, 'ESORT', 'value '//str(inp%ctrl%esort)// &
                          ' is not supported (supported: 0, 1, 2)', error)
      end if
   end subroutine read_control_solid

   !> Q1 Q2 TYPE BTYPE
   subroutine read_bulk_viscosity(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'Q1 Q2 TYPE', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      associate (c => inp%ctrl)
         call get_real(deck, blk, 1, 1, w, 'Q1', 1.5_wp, c%q1, error)
         if (allocated(error)) return
         if (c%q1 == 0.0_wp) c%q1 = 1.5_wp
         call get_real(deck, blk, 1, 2, w, 'Q2', 0.06_wp, c%q2, error)
         if (allocated(error)) return
         if (c%q2 == 0.0_wp) c%q2 = 0.06_wp
         if (c%q1 < 0.0_wp .or. c%q2 < 0.0_wp) then
            call field_error(deck, blk, 1, merge(1, 2, c%q1 < 0.0_wp), w, &
                             merge('Q1', 'Q2', c%q1 < 0.0_wp), 'must be >= 0', error)
            return
         end if
         call get_int(deck, blk, 1, 3, w, 'TYPE', 1, c%ibq, error)
         if (allocated(error)) return
         if (c%ibq == 0) c%ibq = 1
         if (c%ibq /= 1 .and. c%ibq /= -1 .and. c%ibq /= -2) then
            call field_error(deck, blk, 1, 3, w, 'TYPE', 'bulk viscosity type '// &
                             str(c%ibq)//' is not supported (supported: 1, -1, -2)', error)
            return
         end if
      end associate
   end subroutine read_bulk_viscosity

   !> DT LCDT BEAM NPLTC PSETID
   subroutine read_d3plot(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), beam
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'DT LCDT BEAM NPLTC PSETID', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_real(deck, blk, 1, 1, w, 'DT', 0.0_wp, inp%d3plot_dt, error)
      if (allocated(error)) return
      call get_int(deck, blk, 1, 2, w, 'LCDT', 0, inp%d3plot_lcdt, error)
      if (allocated(error)) return
      call get_int(deck, blk, 1, 3, w, 'BEAM', 0, beam, error)   ! beams only: no effect
      if (allocated(error)) return
      call get_int(deck, blk, 1, 4, w, 'NPLTC', 0, inp%d3plot_npltc, error)
      if (allocated(error)) return
      call must_be_zero(deck, blk, 1, 5, w, 'PSETID', 'output of a part subset', error)
      if (allocated(error)) return
      if (inp%d3plot_dt < 0.0_wp) then
         call field_error(deck, blk, 1, 1, w, 'DT', 'must be >= 0', error)
         return
      end if
      inp%d3plot_src = origin(blk%ifile, blk%cards(1)%line, blk%name)
   end subroutine read_d3plot

   !> *DATABASE_GLSTAT / *DATABASE_NODOUT: DT BINARY LCUR IOOPT
   subroutine read_ascii_db(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), binary
      real(wp) :: dt
      w = std_widths(blk, 8)
      call need_card(deck, blk, 'DT BINARY LCUR IOOPT', error)
      if (allocated(error)) return
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_real(deck, blk, 1, 1, w, 'DT', 0.0_wp, dt, error)
      if (allocated(error)) return
      if (dt < 0.0_wp) then
         call field_error(deck, blk, 1, 1, w, 'DT', 'must be >= 0', error)
         return
      end if
      call get_int(deck, blk, 1, 2, w, 'BINARY', 0, binary, error)   ! dynx writes ASCII
      if (allocated(error)) return
      call must_be_zero(deck, blk, 1, 3, w, 'LCUR', 'output interval curves', error)
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
      integer :: w(8), ic, k, id, n
      type(label_list_t), allocatable :: l(:)
      integer :: ids(8)
      w = std_widths(blk, 8)
      allocate(l(blk%n))
      do ic = 1, blk%n
         n = 0
         do k = 1, 8
            call get_int(deck, blk, ic, k, w, 'ID'//str(k), 0, id, error)
            if (allocated(error)) return
            if (id < 0) then
               call field_error(deck, blk, ic, k, w, 'ID'//str(k), 'must be >= 0', error)
               return
            end if
            if (id > 0) then
               n = n + 1
               ids(n) = id
            end if
         end do
         l(ic)%ids = ids(1:n)
         l(ic)%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
      end do
      if (blk%base == 'DATABASE_HISTORY_NODE') then
         inp%hist_nodes = [inp%hist_nodes, l]
      else
         inp%hist_node_sets = [inp%hist_node_sets, l]
      end if
   end subroutine read_history
end module dx_read_controls
