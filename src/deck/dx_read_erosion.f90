!> Reader of *MAT_ADD_EROSION (and its _TITLE option): element erosion criteria added to a
!> material, all fields of cards 1 and 2 with LS-DYNA's meaning (LS-DYNA Keyword User's
!> Manual Vol. II, *MAT_ADD_EROSION):
!>   card 1: MID EXCL MXPRES MNEPS EFFEPS VOLEPS NUMFIP NCS
!>   card 2: MNPRES SIGP1 SIGVM MXEPS EPSSH SIGTH IMPULSE FAILTM
!> A criterion whose value equals EXCL (default 0, so a blank field) is off. The criteria
!> dynx checks (dx_erosion): MXPRES, MNPRES (pressure, positive in compression), SIGP1
!> (largest principal stress), SIGVM (von Mises stress), VOLEPS (volumetric strain
!> ln(V/V0), positive in tension), FAILTM (time), SIGTH + IMPULSE (Tuler & Butcher 1968,
!> Int. J. Fract. Mech. 4:431-437: integral of max(0, sigma_1 - SIGTH)^2 dt >= IMPULSE,
!> LS-DYNA's exponent 2), MXEPS, MNEPS (largest and smallest principal strain), EFFEPS
!> (effective strain), EPSSH (tensorial shear strain) of the total strain (ELFORM 1, 2 and
!> 10; ELFORM 2 from its element-mean strain). NUMFIP (failed points before the element erodes;
!> one-point elements have one) and NCS (criteria met at once at a point before it fails).
!> Card 3 onwards
!> (IDAM, the GISSMO/DIEM damage cards) are not read: an error.
!> The criteria are attached to every part of material MID in the build (dx_model_build).
!> *DYNX_TULER_BUTCHER (a dynx keyword): card MID LAMBDA, the exponent of the Tuler-Butcher
!> integral int max(0, sigma_1 - SIGTH)^LAMBDA dt >= IMPULSE for material MID. Tuler &
!> Butcher 1968 leave the exponent a material constant (their fits to 1100-O aluminium and
!> 4340 steel spall data use values of about 2 and above); LS-DYNA's *MAT_ADD_EROSION fixes it
!> at 2, which stays the default. IMPULSE then has the units stress^LAMBDA time. The material
!> must have a *MAT_ADD_EROSION with SIGTH and IMPULSE (checked in the build).
module dx_read_erosion
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_card, only: card_t
   use dx_deck_cards, only: deck_t, block_t, block_error, data_start, deck_cursor
   use dx_deck_registry, only: registry_t
   use dx_model, only: erosion_t
   use dx_model_input, only: model_input_t, origin
   implicit none
   private
   public :: register_erosion

contains

   !> *MAT_ADD_EROSION (with _TITLE).
   subroutine register_erosion(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('MAT_ADD_EROSION', read_add_erosion, title=.true.)
      call reg%add('DYNX_TULER_BUTCHER', read_tuler_butcher)
   end subroutine register_erosion

   subroutine read_add_erosion(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(erosion_t) :: e
      integer :: i0, k
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (MID EXCL MXPRES MNEPS EFFEPS '// &
                          'VOLEPS NUMFIP NCS)', error)
         return
      end if
      call deck_cursor(deck, blk, c)
      call c%max_cards(2)
      call c%id('MID', e%mid)
      call c%real('EXCL', 0.0_wp, e%excl)
      call c%real('MXPRES', e%excl, e%mxpres)
      call c%real('MNEPS', e%excl, e%mneps)
      call c%real('EFFEPS', e%excl, e%effeps)
      call c%real('VOLEPS', e%excl, e%voleps)
      call c%int('NUMFIP', 1, e%numfip)
      if (c%ok() .and. e%numfip < 1) call c%fail('NUMFIP', 'NUMFIP = '//str(e%numfip)// &
         ': negative NUMFIP (a percentage of the shell layers) and 0 are for shells; '// &
         'solids need NUMFIP >= 1')
      call c%int('NCS', 1, e%ncs, min=0, max=7)
      if (e%ncs == 0) e%ncs = 1
      if (c%ncard() >= 2) then
         call c%next()
         call c%real('MNPRES', e%excl, e%mnpres)
         call c%real('SIGP1', e%excl, e%sigp1)
         call c%real('SIGVM', e%excl, e%sigvm)
         call c%real('MXEPS', e%excl, e%mxeps)
            call c%real('EPSSH', e%excl, e%epssh)
            call c%real('SIGTH', e%excl, e%sigth)
         call c%real('IMPULSE', e%excl, e%impulse)
         call c%real('FAILTM', e%excl, e%failtm)
         if (c%ok() .and. (e%sigth /= e%excl .neqv. e%impulse /= e%excl)) then
            if (e%impulse == e%excl) then
               call c%fail('IMPULSE', 'the Tuler-Butcher criterion needs SIGTH and IMPULSE; '// &
                           'IMPULSE is missing')
            else
               call c%fail('SIGTH', 'the Tuler-Butcher criterion needs SIGTH and IMPULSE; '// &
                           'SIGTH is missing')
            end if
         end if
         if (c%ok() .and. e%impulse /= e%excl .and. .not. e%impulse > 0.0_wp) &
            call c%fail('IMPULSE', 'the stress impulse must be > 0')
      else
         e%mnpres = e%excl; e%sigp1 = e%excl; e%sigvm = e%excl; e%mxeps = e%excl
         e%epssh = e%excl; e%sigth = e%excl; e%impulse = e%excl; e%failtm = e%excl
      end if
      if (c%ok()) then
         do k = 1, size(inp%erosions)
            if (inp%erosions(k)%mid == e%mid) then
               call c%fail('MID', 'material '//str(e%mid)//' has a *MAT_ADD_EROSION already '// &
                  '(at '//deck%files(inp%erosion_src(k)%ifile)%s//':'// &
                  str(inp%erosion_src(k)%line)//')')
               exit
            end if
         end do
      end if
      call c%done(error)
      if (allocated(error)) return
      e%on = .true.
      inp%erosions = [inp%erosions, e]
      inp%erosion_src = [inp%erosion_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_add_erosion

   !> *DYNX_TULER_BUTCHER: MID LAMBDA (> 0).
   subroutine read_tuler_butcher(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(erosion_t) :: e
      integer :: i0, k
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (MID LAMBDA)', error)
         return
      end if
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%id('MID', e%mid)
      call c%real('LAMBDA', 2.0_wp, e%lambda, gt=0.0_wp)
      if (c%ok()) then
         do k = 1, size(inp%tb_lambdas)
            if (inp%tb_lambdas(k)%mid == e%mid) then
               call c%fail('MID', 'material '//str(e%mid)//' has a *DYNX_TULER_BUTCHER already')
               exit
            end if
         end do
      end if
      call c%done(error)
      if (allocated(error)) return
      inp%tb_lambdas = [inp%tb_lambdas, e]
      inp%tb_src = [inp%tb_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_tuler_butcher

end module dx_read_erosion
