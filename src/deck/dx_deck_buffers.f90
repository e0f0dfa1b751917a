!> Growable buffers for the records the deck readers gather card by card (one instance of
!> the template dx_deck_buffer.inc per record type; Fortran 2008 has no generic types).
!> Use: `type(spc_buffer_t) :: buf`; `call buf%push(r)` per card; `call buf%flush(inp%spcs)`
!> once per block. Order is kept, so output is the same as appending per card.
module dx_buffer_spc
   use dx_model_input, only: buf_item_t => spc_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_spc

module dx_buffer_motion
   use dx_model_input, only: buf_item_t => motion_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_motion

module dx_buffer_ivel
   use dx_model_input, only: buf_item_t => ivel_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_ivel

module dx_buffer_load_node
   use dx_model_input, only: buf_item_t => load_node_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_load_node

module dx_buffer_load_seg
   use dx_model_input, only: buf_item_t => load_seg_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_load_seg

module dx_buffer_set_step
   use dx_model_input, only: buf_item_t => set_step_in_t
   implicit none
   private
   include 'dx_deck_buffer.inc'
end module dx_buffer_set_step

!> The buffers under one name each.
module dx_deck_buffers
   use dx_buffer_spc, only: spc_buffer_t => buffer_t
   use dx_buffer_motion, only: motion_buffer_t => buffer_t
   use dx_buffer_ivel, only: ivel_buffer_t => buffer_t
   use dx_buffer_load_node, only: load_node_buffer_t => buffer_t
   use dx_buffer_load_seg, only: load_seg_buffer_t => buffer_t
   use dx_buffer_set_step, only: set_step_buffer_t => buffer_t
   implicit none
   private
   public :: spc_buffer_t, motion_buffer_t, ivel_buffer_t, load_node_buffer_t, &
             load_seg_buffer_t, set_step_buffer_t
end module dx_deck_buffers
