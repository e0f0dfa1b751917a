!> Readers of the implicit Newton solver's controls (issue 20), card 1 of each, with their
!> LS-DYNA meaning (LS-DYNA Keyword User's Manual vol. I, *CONTROL_IMPLICIT_SOLUTION and
!> *CONTROL_IMPLICIT_AUTO; a blank or 0 field takes LS-DYNA's default):
!>   *CONTROL_IMPLICIT_SOLUTION NSOLVR ILIMIT MAXREF DCTOL ECTOL RCTOL LSTOL ABSTOL
!>     NSOLVR 1 linear (one solve per step), 2 and 12 (default) nonlinear: dynx runs full
!>     Newton (a new tangent every iteration) with a line search for both; MAXREF (15) the
!>     iterations per step; DCTOL (1e-3), ECTOL (1e-2), RCTOL (1e10: off) the displacement,
!>     energy and residual ratios; LSTOL (0.9) the line-search tolerance; ABSTOL (1e-10) the
!>     absolute residual norm that counts as converged.
!>   *CONTROL_IMPLICIT_AUTO IAUTO ITEOPT ITEWIN DTMIN DTMAX
!>     IAUTO 0 fixed steps, 1 automatic (a failed step is retried at half the step; the step
!>     grows or shrinks toward ITEOPT (11) +- ITEWIN (5) iterations, between DTMIN (DT0/1000)
!>     and DTMAX (10 DT0)). Negative values (curve ids in LS-DYNA) are not supported.
!>   *CONTROL_IMPLICIT_EIGENVALUE NEIG CENTER LFLAG LFTEND RFLAG RHTEND EIGMTH SHFSCL
!>     NEIG (>= 1) modes nearest the CENTER frequency (>= 0, cycles per unit time; 0: the
!>     lowest modes) by shift-invert Lanczos (EIGMTH 2, LS-DYNA's default, the only one);
!>     SHFSCL (>= 0) the shift scale, a frequency: with CENTER = 0 and a singular stiffness
!>     (a free body) the shift is -(2 pi SHFSCL)^2 (0: dynx's automatic shift). The
!>     interval (LFLAG, RFLAG = 1), NEIG < 0 (intermittent analysis, a curve) and card 2's
!>     options (ISOLID ... MSTRES, EVDUMP) are not supported: input errors.
!> Values out of range are input errors naming file, line, keyword and field.
module dx_read_implicit
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t
   implicit none
   private
   public :: register_implicit

contains

   subroutine register_implicit(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CONTROL_IMPLICIT_SOLUTION', read_implicit_solution)
      call reg%add('CONTROL_IMPLICIT_AUTO', read_implicit_auto)
      call reg%add('CONTROL_IMPLICIT_EIGENVALUE', read_implicit_eigenvalue)
   end subroutine register_implicit

   subroutine read_implicit_solution(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: k
      real(wp) :: v
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (NSOLVR ILIMIT MAXREF DCTOL ECTOL ...)')
      associate (imp => inp%ctrl%imp)
         call c%int('NSOLVR', 0, k)
         if (k == 0) k = 12
         if (c%ok() .and. k /= 1 .and. k /= 2 .and. k /= 12) call c%fail('NSOLVR', &
            'dynx has 1 (linear) and 2 or 12 (nonlinear: full Newton with a line search), '// &
            'got '//str(k))
         imp%nsolvr = k
         call c%int('ILIMIT', 0, k)
         if (k == 0) k = 11
         if (c%ok() .and. k < 0) call c%fail('ILIMIT', 'must be >= 0, got '//str(k))
         imp%ilimit = k
         call c%int('MAXREF', 0, k)
         if (k == 0) k = 15
         if (c%ok() .and. k < 0) call c%fail('MAXREF', 'a negative MAXREF (go on without '// &
            'convergence) is not supported; the iterations per step must be > 0, got '//str(k))
         imp%maxref = k
         call tol('DCTOL', 1.0e-3_wp, imp%dctol)
         call tol('ECTOL', 1.0e-2_wp, imp%ectol)
         call tol('RCTOL', 1.0e10_wp, imp%rctol)
         call tol('LSTOL', 0.9_wp, imp%lstol)
         call c%real('ABSTOL', 0.0_wp, v)
         if (v == 0.0_wp) v = 1.0e-10_wp
         if (c%ok() .and. .not. (v > 0.0_wp)) call c%fail('ABSTOL', &
            'the absolute residual tolerance must be > 0, got '//rstr(v))
         imp%abstol = v
      end associate
      call c%done(error)
   contains
      subroutine tol(name, def, val)
         character(*), intent(in) :: name
         real(wp), intent(in) :: def
         real(wp), intent(out) :: val
         call c%real(name, 0.0_wp, val)
         if (val == 0.0_wp) val = def
         if (c%ok() .and. .not. (val > 0.0_wp)) call c%fail(name, 'a negative '//name// &
            ' (a curve id in LS-DYNA) is not supported; the tolerance must be > 0, got '// &
            rstr(val))
      end subroutine tol
   end subroutine read_implicit_solution

   subroutine read_implicit_auto(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: k
      real(wp) :: v
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (IAUTO ITEOPT ITEWIN DTMIN DTMAX ...)')
      associate (imp => inp%ctrl%imp)
         call c%int('IAUTO', 0, k)
         if (c%ok() .and. k /= 0 .and. k /= 1) call c%fail('IAUTO', 'dynx has 0 (fixed '// &
            'steps) and 1 (automatic step control), got '//str(k))
         imp%iauto = k
         call c%int('ITEOPT', 0, k)
         if (k == 0) k = 11
         if (c%ok() .and. k < 0) call c%fail('ITEOPT', 'must be > 0, got '//str(k))
         imp%iteopt = k
         call c%int('ITEWIN', 0, k)
         if (k == 0) k = 5
         if (c%ok() .and. k < 0) call c%fail('ITEWIN', 'must be > 0, got '//str(k))
         imp%itewin = k
         call c%real('DTMIN', 0.0_wp, v)
         if (c%ok() .and. v < 0.0_wp) call c%fail('DTMIN', 'must be >= 0 (0: DT0/1000), got '// &
                                                  rstr(v))
         imp%dtmin = v
         call c%real('DTMAX', 0.0_wp, v)
         if (c%ok() .and. v < 0.0_wp) call c%fail('DTMAX', 'a negative DTMAX (a curve id in '// &
            'LS-DYNA) is not supported; must be >= 0 (0: 10 DT0), got '//rstr(v))
         imp%dtmax = v
      end associate
      call c%done(error)
   end subroutine read_implicit_auto

   subroutine read_implicit_eigenvalue(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: k, line
      real(wp) :: v
      character(*), parameter :: no2 = 'card 2''s options of *CONTROL_IMPLICIT_EIGENVALUE '// &
                                       'are not in dynx (blank or 0 only)'
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (NEIG CENTER LFLAG LFTEND RFLAG ...)')
      associate (imp => inp%ctrl%imp)
         call c%int('NEIG', 0, k)
         line = c%card_line()
         if (c%ok() .and. k < 0) call c%fail('NEIG', 'NEIG < 0 (a curve of times for '// &
            'intermittent eigenvalue analysis) is not supported; the number of modes must be '// &
            '>= 1, got '//str(k))
         if (c%ok() .and. k == 0) call c%fail('NEIG', 'the number of modes must be >= 1, '// &
            'got 0 (LS-DYNA: no eigenvalue analysis; remove the keyword for that)')
         imp%neig = k
         call c%real('CENTER', 0.0_wp, v)
         if (c%ok() .and. .not. (v >= 0.0_wp .and. v < huge(v))) call c%fail('CENTER', &
            'the center frequency (cycles per unit time) must be >= 0, got '//rstr(v))
         imp%center = v
         call c%int('LFLAG', 0, k)
         if (c%ok() .and. k /= 0) call c%fail('LFLAG', 'only 0 (no left end: the modes '// &
            'nearest CENTER) is supported, got '//str(k))
         call c%real('LFTEND', 0.0_wp, v)
         call c%int('RFLAG', 0, k)
         if (c%ok() .and. k /= 0) call c%fail('RFLAG', 'only 0 (no right end: the modes '// &
            'nearest CENTER) is supported, got '//str(k))
         call c%real('RHTEND', 0.0_wp, v)
         call c%int('EIGMTH', 0, k)
         if (c%ok() .and. k /= 0 .and. k /= 2) call c%fail('EIGMTH', 'dynx has 2 (shift-'// &
            'invert Lanczos, the default) only, got '//str(k))
         call c%real('SHFSCL', 0.0_wp, v)
         if (c%ok() .and. .not. (v >= 0.0_wp .and. v < huge(v))) call c%fail('SHFSCL', &
            'the shift scale (a frequency) must be >= 0, got '//rstr(v))
         imp%shfscl = v
         call c%next()
         call c%zero_int('ISOLID', no2)
         call c%zero_int('IBEAM', no2)
         call c%zero_int('ISHELL', no2)
         call c%zero_int('ITSHELL', no2)
         call c%zero_int('MSTRES', no2)
         call c%zero_int('EVDUMP', no2)
         imp%eig_ifile = blk%ifile
         imp%eig_line = line
      end associate
      call c%done(error)
   end subroutine read_implicit_eigenvalue
end module dx_read_implicit
