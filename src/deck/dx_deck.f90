!> Entry point of the deck layer: read an LS-DYNA keyword deck into a model ready for the
!> solver. Tokenizes the deck (dx_deck_cards), looks every keyword up in the registry and
!> calls its reader (dx_read_* modules) into the model input; the build stage (src/build/,
!> dx_build) turns that into the model (read then build: dx_deck_model).
!> Supported keywords and fields: docs/keywords.md.
module dx_deck
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_log, only: log_warn
   use dx_deck_cards, only: deck_t, read_cards
   use dx_deck_registry, only: registry_t
   use dx_read_nodes_elements, only: register_nodes_elements
   use dx_read_materials, only: register_materials, unknown_model_hint
   use dx_read_controls, only: register_controls
   use dx_read_sets, only: register_sets
   use dx_read_loads, only: register_loads
   use dx_read_curves, only: register_curves
   use dx_read_rigid, only: register_rigid
   use dx_read_contact, only: register_contact
   use dx_read_restart, only: register_restart
   use dx_read_emc, only: register_emc
   use dx_model_input, only: model_input_t, input_init, input_finish
   implicit none
   private
   public :: read_deck_input, new_registry

contains

   !> The registry of every keyword dynx reads.
   function new_registry() result(reg)
      type(registry_t) :: reg
      call register_nodes_elements(reg)
      call register_materials(reg)
      call register_controls(reg)
      call register_sets(reg)
      call register_loads(reg)
      call register_curves(reg)
      call register_rigid(reg)
      call register_contact(reg)
      call register_restart(reg)
      call register_emc(reg)
   end function new_registry

   !> Read the deck at path into the unresolved model input (no build).
   subroutine read_deck_input(path, inp, error, ignore_unknown)
      character(*), intent(in) :: path
      type(model_input_t), intent(out) :: inp
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: ignore_unknown
      type(deck_t) :: deck
      type(registry_t) :: reg
      integer :: ib, k
      logical :: ignore
      ignore = .false.
      if (present(ignore_unknown)) ignore = ignore_unknown
      call input_init(inp)
      call read_cards(path, deck, error)
      if (allocated(error)) return
      reg = new_registry()
      do ib = 1, deck%nblocks
         associate (blk => deck%blocks(ib))
            call reg%lookup(blk%name, k, blk%base, blk%opt_title, blk%opt_id)
            if (k == 0) then
               if (ignore) then
                  call log_warn(deck%files(blk%ifile)%s//':'//str(blk%line)// &
                                ': unknown keyword *'//blk%name//' ignored')
                  cycle
               end if
               call set_error(error, deck%files(blk%ifile)%s//':'//str(blk%line)// &
                              ': unknown keyword *'//blk%name//unknown_model_hint(blk%name))
               return
            end if
            call reg%e(k)%read(deck, blk, inp, error)
            if (allocated(error)) return
         end associate
      end do
      call input_finish(inp)
      deallocate(inp%files)
      allocate(inp%files(deck%nfiles))
      do k = 1, deck%nfiles
         inp%files(k)%s = deck%files(k)%s
      end do
      if (allocated(deck%title)) inp%title = deck%title
   end subroutine read_deck_input
end module dx_deck
