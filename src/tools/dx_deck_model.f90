!> Read then build: read_deck reads an LS-DYNA keyword deck (dx_deck's read_deck_input) and
!> builds the model the solver runs (dx_build's build_model). It sits above both layers, so
!> the deck layer does not import the build. Used by bin/dynx and the tests.
!> No keyword of its own; no paper.
module dx_deck_model
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_model_input, only: model_input_t
   use dx_deck, only: read_deck_input
   use dx_build, only: build_model
   use dx_card_echo, only: echo_t
   implicit none
   private
   public :: read_deck

contains

   !> Read the deck at path into model (x0, v0, blocks, parts, ...; the solver allocates
   !> x, v, f, mass). Unknown keywords are errors unless ignore_unknown (then warnings).
   !> check (--check): every unknown keyword and unsupported option at once (dx_deck).
   !> echo: the d3hsp echo of the deck (dx_card_echo).
   !> case_id: the *CASE of a multi-case deck to read (dx_deck).
   subroutine read_deck(path, model, error, ignore_unknown, check, echo, case_id)
      character(*), intent(in) :: path
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: ignore_unknown, check
      type(echo_t), intent(inout), optional :: echo
      integer, intent(in), optional :: case_id
      type(model_input_t) :: inp
      call read_deck_input(path, inp, error, ignore_unknown, check, echo, case_id)
      if (allocated(error)) return
      model%deck_file = path
      model%deck_files = inp%files
      call build_model(inp, model, error)
   end subroutine read_deck
end module dx_deck_model
