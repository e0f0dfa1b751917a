!> The small restart deck (bin/dynx -i deck.k -r dump.h5 -R restart.k), LS-DYNA's
!> restart-input idea (Keyword User's Manual Vol. I, "Restart Input Data" and
!> *CHANGE_CURVE_DEFINITION): dynx re-reads the full deck, -r restores the state, then the
!> restart deck overrides. Allowed keywords (same cards and fields as in a full deck):
!>   *CONTROL_TERMINATION (ENDTIM, ENDCYC, DTMIN, ENDENG, ENDMAS), *DATABASE_BINARY_D3PLOT,
!>   *DATABASE_GLSTAT, *DATABASE_NODOUT, *DATABASE_BINARY_D3DUMP, *DATABASE_BINARY_RUNRSF,
!>   *CHANGE_CURVE_DEFINITION (the cards of *DEFINE_CURVE; replaces the curve LCID that
!>   loads, prescribed motions and LCTM use; the curves a material copied at build time are
!>   not changed), and *KEYWORD, *TITLE, *INCLUDE, *PARAMETER, *END.
!> Any other keyword is an input error naming file and line.
module dx_restart_deck
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_deck_cards, only: deck_t, read_cards
   use dx_deck_registry, only: registry_t
   use dx_read_controls, only: register_controls
   use dx_read_curves, only: register_curves
   use dx_read_restart, only: register_restart
   use dx_model, only: model_t
   use dx_model_input, only: model_input_t, input_init
   implicit none
   private
   public :: apply_restart_deck

   character(*), parameter :: ALLOWED = '*CONTROL_TERMINATION, *DATABASE_BINARY_D3PLOT, '// &
      '*DATABASE_GLSTAT, *DATABASE_NODOUT, *DATABASE_BINARY_D3DUMP, '// &
      '*DATABASE_BINARY_RUNRSF, *CHANGE_CURVE_DEFINITION'

contains

   !> Read the restart deck at path and apply it to model (whose state is restored).
   subroutine apply_restart_deck(path, model, error)
      character(*), intent(in) :: path
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(deck_t) :: deck
      type(registry_t) :: reg
      type(model_input_t) :: inp
      integer :: ib, k, i, j
      character(:), allocatable :: name
      logical :: d3plot, glstat, nodout

      call input_init(inp)
      inp%glstat_dt = -1.0_wp        ! sentinels: the keyword was not given
      inp%nodout_dt = -1.0_wp
      inp%d3plot_dt = -1.0_wp
      inp%rst%d3dump_cycl = -1
      inp%rst%runrsf_cycl = -1
      call read_cards(path, deck, error)
      if (allocated(error)) return
      call register_controls(reg)
      call register_curves(reg)
      call register_restart(reg)
      do ib = 1, deck%nblocks
         associate (blk => deck%blocks(ib))
            name = blk%name
            select case (name)
            case ('CONTROL_TERMINATION', 'DATABASE_BINARY_D3PLOT', 'DATABASE_GLSTAT', &
                  'DATABASE_NODOUT', 'DATABASE_BINARY_D3DUMP', 'DATABASE_BINARY_RUNRSF')
            case ('CHANGE_CURVE_DEFINITION')
               name = 'DEFINE_CURVE'
            case default
               call set_error(error, deck%files(blk%ifile)%s//':'//str(blk%line)// &
                  ': keyword *'//blk%name//' is not allowed in a restart deck (allowed: '// &
                  ALLOWED//')')
               return
            end select
            call reg%lookup(name, k, blk%base, blk%opt_title, blk%opt_id)
            call reg%e(k)%read(deck, blk, inp, error)
            if (allocated(error)) return
         end associate
      end do
      ! ---- apply
      if (inp%has_termination) then
         model%ctrl%endtim = inp%ctrl%endtim
         model%ctrl%endcyc = inp%ctrl%endcyc
         model%ctrl%dtmin = inp%ctrl%dtmin
         model%ctrl%endeng = inp%ctrl%endeng
         model%ctrl%endmas = inp%ctrl%endmas
         model%run%tsmin = model%ctrl%dtmin*model%run%dt_first
      end if
      d3plot = inp%d3plot_dt >= 0.0_wp
      if (d3plot) then
         model%db%d3plot_dt = inp%d3plot_dt
         if (inp%d3plot_npltc > 0 .and. model%ctrl%endtim > 0.0_wp) &
            model%db%d3plot_dt = model%ctrl%endtim/inp%d3plot_npltc
      end if
      glstat = inp%glstat_dt >= 0.0_wp
      if (glstat) model%db%glstat_dt = inp%glstat_dt
      nodout = inp%nodout_dt >= 0.0_wp
      if (nodout) model%db%nodout_dt = inp%nodout_dt
      if (inp%rst%d3dump_cycl >= 0) model%rst%d3dump_cycl = inp%rst%d3dump_cycl
      if (inp%rst%runrsf_cycl >= 0) then
         model%rst%runrsf_cycl = inp%rst%runrsf_cycl
         model%rst%runrsf_nr = inp%rst%runrsf_nr
      end if
      do i = 1, size(inp%curves)
         k = 0
         if (allocated(model%curves)) then
            do j = 1, size(model%curves)
               if (model%curves(j)%label == inp%curves(i)%label) k = j
            end do
         end if
         if (k == 0) then
            call set_error(error, deck%files(inp%curve_src(i)%ifile)%s//':'// &
               str(inp%curve_src(i)%line)//': *CHANGE_CURVE_DEFINITION: field LCID: '// &
               'curve '//str(inp%curves(i)%label)//' is not defined in the deck')
            return
         end if
         model%curves(k) = inp%curves(i)
      end do
   end subroutine apply_restart_deck
end module dx_restart_deck
