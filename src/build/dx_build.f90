!> The build stage: one build_model turns the deck as read (model_input_t, from dx_deck's
!> read_deck_input) into the model the solver runs: nodes, blocks, sets, loads and rigid bodies
!> (dx_model_build), the contact pairs (dx_contact_build), the conserving rigid contact
!> (dx_emc_build). bin/dynx (through dx_deck_model) and bin/dynx-part both call it.
!> No keyword of its own; no paper.
module dx_build
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_model_input, only: model_input_t
   use dx_model_build, only: build_model_data
   use dx_contact_build, only: build_contact
   use dx_emc_build, only: build_emc
   implicit none
   private
   public :: build_model

contains

   !> Build model from inp: model data, contact, conserving rigid contact (inp's materials
   !> and curves are moved into model).
   subroutine build_model(inp, model, error)
      type(model_input_t), intent(inout) :: inp
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      call build_model_data(inp, model, error)
      if (.not. allocated(error)) call build_contact(inp, model, error)
      if (.not. allocated(error)) call build_emc(inp, model, error)
   end subroutine build_model
end module dx_build
