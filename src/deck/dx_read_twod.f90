!> Readers for the boundaries of 2D decks (dx_quad2d: *SECTION_SHELL ELFORM 13, 14, 15):
!> *BOUNDARY_NON_REFLECTING_2D card 1: NSID AD AS (LS-DYNA Keyword User's Manual, Vol. I:
!> NSID a node set whose element edges form the transmitting boundary; AD, AS the activation
!> of the dilatational and the shear dashpot: 0 on (the default), nonzero off). The edges
!> and dashpots are made at build (dx_build_twod), the forces in the cycle (dx_nonreflecting).
module dx_read_twod
   use dx_error, only: error_t
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, nr2d_in_t
   use dx_strings, only: str
   implicit none
   private
   public :: register_twod

contains

   !> Add this family's keywords to the registry.
   subroutine register_twod(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('BOUNDARY_NON_REFLECTING_2D', read_nonreflecting_2d)
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
end module dx_read_twod
