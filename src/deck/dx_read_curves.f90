!> Reader for *DEFINE_CURVE (_TITLE): LCID SIDR SFA SFO OFFA OFFO DATTYP, then point cards
!> A O (two 20-column fields, also in long format). LS-DYNA applies offsets before scale
!> factors: x = SFA*(A + OFFA), y = SFO*(O + OFFO) (Keyword User's Manual, *DEFINE_CURVE).
module dx_read_curves
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            std_widths, data_start
   use dx_deck_registry, only: registry_t
   use dx_curve, only: curve_t
   use dx_model_input, only: model_input_t, origin
   implicit none
   private
   public :: register_curves

contains

   !> Add *DEFINE_CURVE to the registry.
   subroutine register_curves(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('DEFINE_CURVE', read_define_curve, title=.true.)
   end subroutine register_curves

   subroutine read_define_curve(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), wp2(2), i0, np, ic, i
      real(wp) :: a, o
      type(curve_t) :: c
      w = std_widths(blk, 8)
      wp2 = 20
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (LCID SIDR SFA SFO OFFA OFFO DATTYP)', &
                          error)
         return
      end if
      call get_int(deck, blk, i0, 1, w, 'LCID', 0, c%label, error)
      if (allocated(error)) return
      if (c%label <= 0) then
         call field_error(deck, blk, i0, 1, w, 'LCID', 'curve id must be > 0, got '// &
                          str(c%label), error)
         return
      end if
      call get_int(deck, blk, i0, 2, w, 'SIDR', 0, c%sidr, error)
      if (allocated(error)) return
      if (c%sidr /= 0 .and. c%sidr /= 2) then
         call field_error(deck, blk, i0, 2, w, 'SIDR', 'SIDR '//str(c%sidr)//' is not '// &
            'supported: dynx has no dynamic relaxation phase (use 0 or 2)', error)
         return
      end if
      call get_real(deck, blk, i0, 3, w, 'SFA', 1.0_wp, c%sfa, error)
      if (allocated(error)) return
      if (c%sfa == 0.0_wp) c%sfa = 1.0_wp
      call get_real(deck, blk, i0, 4, w, 'SFO', 1.0_wp, c%sfo, error)
      if (allocated(error)) return
      if (c%sfo == 0.0_wp) c%sfo = 1.0_wp
      call get_real(deck, blk, i0, 5, w, 'OFFA', 0.0_wp, c%offa, error)
      if (allocated(error)) return
      call get_real(deck, blk, i0, 6, w, 'OFFO', 0.0_wp, c%offo, error)
      if (allocated(error)) return
      call get_int(deck, blk, i0, 7, w, 'DATTYP', 0, c%dattyp, error)
      if (allocated(error)) return
      if (c%dattyp /= 0) then
         call field_error(deck, blk, i0, 7, w, 'DATTYP', 'data type '//str(c%dattyp)// &
                          ' is not supported (only 0, a general curve)', error)
         return
      end if
      np = blk%n - i0
      if (np < 1) then
         call block_error(deck, blk, i0, 'curve '//str(c%label)//' has no points (at least '// &
                          'one A O card is needed)', error)
         return
      end if
      allocate(c%x(np), c%y(np))
      do i = 1, np
         ic = i0 + i
         call get_real(deck, blk, ic, 1, wp2, 'A'//str(i), 0.0_wp, a, error)
         if (allocated(error)) return
         call get_real(deck, blk, ic, 2, wp2, 'O'//str(i), 0.0_wp, o, error)
         if (allocated(error)) return
         c%x(i) = c%sfa*(a + c%offa)
         c%y(i) = c%sfo*(o + c%offo)
         if (i > 1) then
            if (.not. (c%x(i) > c%x(i-1))) then
               call field_error(deck, blk, ic, 1, wp2, 'A'//str(i), 'abscissae must '// &
                  'increase: point '//str(i)//' has A = '//rstr(a)//' after '//rstr(c%x(i-1)), &
                  error)
               return
            end if
         end if
      end do
      inp%curves = [inp%curves, c]
      inp%curve_src = [inp%curve_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_define_curve
end module dx_read_curves
