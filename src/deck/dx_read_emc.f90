!> Readers for the energy-momentum conserving rigid-body contact keywords:
!>   *CONTROL_IMPLICIT_GENERAL  IMFLAG DT0 (IMFORM NSBS IGS CNSTN FORM ZERO_V read past)
!>   *CONTROL_IMPLICIT_DYNAMICS IMASS GAMMA BETA (TDYBIR TDYDTH TDYBUR IRATE) ALPHA
!>     (HHT: Hilber, Hughes & Taylor 1977, Earthq. Eng. Struct. Dyn. 5:283-292)
!>   *DYNX_CONSERVING_CONTACT   CID SPID MPID FORM EPS FS DFRIC
!>   *DYNX_RIGID_SPHERE         PID SIDE TOL
!>   *DYNX_CONSERVING_CONTROL   MAXIT RTOL NFAIL OUTDT
!> Field meanings: docs/keywords.md, section "Conserving rigid-body contact";
!> formulation: docs/conserving-contact.md (Simo & Wong 1991; Laursen & Chawla 1997).
module dx_read_emc
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t
   use dx_emc_types, only: emc_contact_in_t, emc_sphere_in_t, EMC_PENALTY, EMC_LAGRANGE
   implicit none
   private
   public :: register_emc, emc_finish

contains

   !> Add the conserving-contact keywords to the registry.
   subroutine register_emc(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CONTROL_IMPLICIT_GENERAL', read_implicit_general)
      call reg%add('CONTROL_IMPLICIT_DYNAMICS', read_implicit_dynamics)
      call reg%add('DYNX_CONSERVING_CONTACT', read_emc_contact)
      call reg%add('DYNX_RIGID_SPHERE', read_emc_sphere)
      call reg%add('DYNX_CONSERVING_CONTROL', read_emc_control)
   end subroutine register_emc

   !> IMFLAG (0 explicit, 1 implicit: the conserving rigid-body solver; 2, explicit then
   !> implicit springback, refused), DT0 (step size), into model%ctrl%imp (dx_solver chooses).
   subroutine read_implicit_general(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (IMFLAG DT0 ...)')
      call c%int('IMFLAG', 0, inp%ctrl%imp%imflag)
      if (c%ok() .and. inp%ctrl%imp%imflag == 2) then
         call c%fail('IMFLAG', 'IMFLAG = 2 (explicit, then implicit springback) is not '// &
            'supported; 0 (explicit) and 1 (implicit: the Newton solver, or the conserving '// &
            'rigid-body solver with *DYNX_CONSERVING_CONTACT) are')
      else if (c%ok() .and. inp%ctrl%imp%imflag /= 0 .and. inp%ctrl%imp%imflag /= 1) then
         call c%fail('IMFLAG', 'only 0 (explicit) and 1 (implicit: Newton, or conserving '// &
                     'rigid-body) are supported, got '//str(inp%ctrl%imp%imflag))
      end if
      call c%real('DT0', 0.0_wp, inp%ctrl%imp%dt0)
      ! DT0 = 0 with IMFLAG = 1 is judged after the whole deck (emc_finish): without
      ! *DYNX_CONSERVING_CONTACT the IMFLAG message (build) says what is missing
      if (c%ok() .and. .not. (inp%ctrl%imp%dt0 >= 0.0_wp)) &
         call c%fail('DT0', 'the implicit step size must be > 0')
      call c%done(error)
      if (allocated(error)) return
      inp%ctrl%imp%ifile = blk%ifile
      inp%ctrl%imp%line = c%card_line()
   end subroutine read_implicit_general

   !> IMASS GAMMA BETA TDYBIR TDYDTH TDYBUR IRATE ALPHA, with their LS-DYNA meaning: the
   !> Newmark parameters GAMMA, BETA and the HHT parameter ALPHA (LS-DYNA's sign: -1/3 <=
   !> ALPHA <= 0, with GAMMA = 1/2 - ALPHA and BETA = (1 - ALPHA)^2/4). The conserving
   !> solver takes from them the high-frequency spectral radius rho_inf of that scheme (HHT:
   !> (1 + ALPHA)/(1 - ALPHA); Newmark: the larger root modulus of
   !> BETA l^2 + (1/2 + GAMMA - 2 BETA) l + (1/2 - GAMMA + BETA) = 0) and gives its penalty
   !> contact the same rho_inf (docs/conserving-contact.md, "Algorithmic dissipation").
   !> GAMMA 1/2, BETA 1/4, ALPHA 0 (the defaults): rho_inf = 1, exact conservation.
   subroutine read_implicit_dynamics(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: imass
      real(wp) :: gamma, beta, alpha, b, c, disc, r1, r2
      type(card_t) :: cur
      call deck_cursor(deck, blk, cur)
      call cur%need(data_start(blk), 'missing card 1 (IMASS GAMMA BETA ...)')
      call cur%int('IMASS', 1, imass)
      if (cur%ok() .and. imass /= 1) call cur%fail('IMASS', 'only 1 (dynamic analysis) is '// &
                                                   'supported, got '//str(imass))
      call cur%at(8)
      call cur%real('ALPHA', 0.0_wp, alpha)
      if (cur%ok() .and. alpha > 0.0_wp) call cur%fail('ALPHA', 'ALPHA > 0 selects the '// &
         'Bathe composite scheme, which the conserving solver does not have; HHT needs '// &
         '-1/3 <= ALPHA <= 0, got '//rstr(alpha))
      if (cur%ok() .and. alpha < -1.0_wp/3.0_wp - 1.0e-12_wp) call cur%fail('ALPHA', &
         'the HHT parameter must be in [-1/3, 0] (unconditional stability), got '//rstr(alpha))
      call cur%at(2)
      call cur%real('GAMMA', 0.0_wp, gamma)
      call cur%real('BETA', 0.0_wp, beta)
      call cur%done(error)
      if (allocated(error)) return
      if (alpha < 0.0_wp) then
         ! HHT: GAMMA and BETA follow from ALPHA; given ones must agree
         if (gamma /= 0.0_wp .and. abs(gamma - (0.5_wp - alpha)) > 1.0e-6_wp) &
            call cur%fail('GAMMA', 'with the HHT ALPHA = '//rstr(alpha)//' GAMMA must be '// &
               '1/2 - ALPHA = '//rstr(0.5_wp - alpha)//' (or blank), got '//rstr(gamma))
         if (beta /= 0.0_wp .and. abs(beta - 0.25_wp*(1.0_wp - alpha)**2) > 1.0e-6_wp) &
            call cur%fail('BETA', 'with the HHT ALPHA = '//rstr(alpha)//' BETA must be '// &
               '(1 - ALPHA)^2/4 = '//rstr(0.25_wp*(1.0_wp - alpha)**2)//' (or blank), got '// &
               rstr(beta))
         call cur%done(error)
         if (allocated(error)) return
         gamma = 0.5_wp - alpha
         beta = 0.25_wp*(1.0_wp - alpha)**2
         inp%ctrl%imp%rho_inf = (1.0_wp + alpha)/(1.0_wp - alpha)
      else
         if (gamma == 0.0_wp) gamma = 0.5_wp
         if (beta == 0.0_wp) beta = 0.25_wp
         if (gamma < 0.5_wp .or. gamma > 1.5_wp) call cur%fail('GAMMA', 'must be in '// &
            '[0.5, 1.5] (0.5: no numerical damping; > 0.5: high-frequency damping), got '// &
            rstr(gamma))
         if (2.0_wp*beta < gamma) call cur%fail('BETA', 'unconditional stability needs '// &
            'BETA >= GAMMA/2 = '//rstr(0.5_wp*gamma)//' (most damping: BETA = '// &
            '(GAMMA + 1/2)^2/4 = '//rstr(0.25_wp*(gamma + 0.5_wp)**2)//'), got '//rstr(beta))
         call cur%done(error)
         if (allocated(error)) return
         if (gamma == 0.5_wp .and. beta == 0.25_wp) then
            inp%ctrl%imp%rho_inf = 1.0_wp
         else
            ! roots of beta l^2 + b l + c = 0, the Newmark amplification at omega dt -> inf
            b = 0.5_wp + gamma - 2.0_wp*beta
            c = 0.5_wp - gamma + beta
            disc = b*b - 4.0_wp*beta*c
            if (disc < 0.0_wp) then
               inp%ctrl%imp%rho_inf = sqrt(c/beta)
            else
               r1 = (-b + sqrt(disc))/(2.0_wp*beta)
               r2 = (-b - sqrt(disc))/(2.0_wp*beta)
               inp%ctrl%imp%rho_inf = max(abs(r1), abs(r2))
            end if
            inp%ctrl%imp%rho_inf = min(inp%ctrl%imp%rho_inf, 1.0_wp)
         end if
      end if
      inp%ctrl%imp%gamma = gamma
      inp%ctrl%imp%beta = beta
      inp%ctrl%imp%alpha = alpha
      inp%ctrl%imp%dynamic = .true.   ! (the Newton solver: Newmark/HHT instead of statics)
   end subroutine read_implicit_dynamics

   !> CID SPID MPID FORM EPS: a conserving contact between two rigid parts.
   subroutine read_emc_contact(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(emc_contact_in_t) :: e
      type(card_t) :: c
      integer :: ic
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (CID SPID MPID FORM EPS FS DFRIC)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         e%ifile = blk%ifile
         e%line = c%card_line()
         call c%int('CID', 0, e%cid)
         call c%int('SPID', 0, e%spid)
         if (c%ok() .and. e%spid <= 0) call c%fail('SPID', 'a slave part id > 0 is required')
         call c%int('MPID', 0, e%mpid)
         if (c%ok() .and. (e%mpid <= 0 .or. e%mpid == e%spid)) call c%fail('MPID', 'a master '// &
            'part id > 0, other than SPID, is required')
         call c%int('FORM', EMC_PENALTY, e%form)
         if (e%form == 0) e%form = EMC_PENALTY
         if (c%ok() .and. e%form /= EMC_PENALTY .and. e%form /= EMC_LAGRANGE) call c%fail('FORM', &
            '1 (penalty with the algorithmic gap) or 2 (Lagrange multipliers), got '//str(e%form))
         call c%real('EPS', 0.0_wp, e%eps)
         if (c%ok() .and. e%form == EMC_PENALTY .and. .not. (e%eps > 0.0_wp)) call c%fail('EPS', &
            'the penalty stiffness [force/length] must be > 0')
         call c%real('FS', 0.0_wp, e%fs)
         if (c%ok() .and. e%fs < 0.0_wp) call c%fail('FS', 'the Coulomb friction coefficient '// &
                                                     'must be >= 0')
         call c%real('DFRIC', 0.0_wp, e%dfric)
         if (c%ok() .and. e%dfric < 0.0_wp) call c%fail('DFRIC', 'the friction regularization '// &
                                                        'slip must be >= 0')
         if (c%halt()) exit
         if (.not. allocated(inp%emc%contacts)) allocate(inp%emc%contacts(0))
         inp%emc%contacts = [inp%emc%contacts, e]
      end do
      call c%done(error)
   end subroutine read_emc_contact

   !> PID SIDE TOL: smooth this rigid part as an exact sphere (outer 0 / inner 1 surface).
   subroutine read_emc_sphere(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(emc_sphere_in_t) :: s
      type(card_t) :: c
      integer :: ic
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (PID SIDE TOL)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         s%ifile = blk%ifile
         s%line = c%card_line()
         call c%int('PID', 0, s%pid)
         if (c%ok() .and. s%pid <= 0) call c%fail('PID', 'a part id > 0 is required')
         call c%int('SIDE', 0, s%side)
         if (c%ok() .and. s%side /= 0 .and. s%side /= 1) call c%fail('SIDE', '0 (outer '// &
            'surface: ball) or 1 (inner surface: shell), got '//str(s%side))
         call c%real('TOL', 1.0e-3_wp, s%tol)
         if (s%tol == 0.0_wp) s%tol = 1.0e-3_wp
         if (c%ok() .and. s%tol < 0.0_wp) call c%fail('TOL', 'must be > 0')
         if (c%halt()) exit
         if (.not. allocated(inp%emc%spheres)) allocate(inp%emc%spheres(0))
         inp%emc%spheres = [inp%emc%spheres, s]
      end do
      call c%done(error)
   end subroutine read_emc_sphere

   !> MAXIT RTOL NFAIL OUTDT: Newton limits, failure action and emcstat interval.
   subroutine read_emc_control(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (MAXIT RTOL NFAIL OUTDT)')
      call c%int('MAXIT', 20, inp%emc%maxit)
      if (inp%emc%maxit == 0) inp%emc%maxit = 20
      if (c%ok() .and. inp%emc%maxit < 0) call c%fail('MAXIT', 'must be > 0')
      call c%real('RTOL', 1.0e-16_wp, inp%emc%rtol)
      if (inp%emc%rtol == 0.0_wp) inp%emc%rtol = 1.0e-16_wp
      if (c%ok() .and. inp%emc%rtol < 0.0_wp) call c%fail('RTOL', 'must be > 0')
      call c%int('NFAIL', 0, inp%emc%nfail)
      if (c%ok() .and. inp%emc%nfail < 0) call c%fail('NFAIL', 'must be >= 0 (0: stop at '// &
         'the first Newton failure; N: up to N step halvings)')
      call c%real('OUTDT', 0.0_wp, inp%emc%out_dt)
      if (c%ok() .and. inp%emc%out_dt < 0.0_wp) call c%fail('OUTDT', 'must be >= 0')
      call c%done(error)
   end subroutine read_emc_control

   !> After the whole deck: IMFLAG = 1 needs DT0 > 0, for the conserving solver
   !> (*DYNX_CONSERVING_CONTACT present) and for the implicit Newton solver (without it);
   !> *CONTROL_IMPLICIT_EIGENVALUE needs IMFLAG = 1 (and then neither DT0 nor ENDTIM).
   subroutine emc_finish(inp, error)
      type(model_input_t), intent(in) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: nc
      nc = 0
      if (allocated(inp%emc%contacts)) nc = size(inp%emc%contacts)
      if (inp%ctrl%imp%neig > 0 .and. (inp%ctrl%imp%imflag /= 1 .or. nc > 0)) then
         call set_error(error, inp%files(inp%ctrl%imp%eig_ifile)%s//':'// &
            str(inp%ctrl%imp%eig_line)//': *CONTROL_IMPLICIT_EIGENVALUE: field NEIG: the '// &
            'eigenvalue analysis needs *CONTROL_IMPLICIT_GENERAL IMFLAG = 1 (and no '// &
            '*DYNX_CONSERVING_CONTACT)')
         return
      end if
      if (inp%ctrl%imp%imflag /= 1) return
      if (inp%ctrl%imp%neig > 0) return   ! the eigenvalue run needs neither DT0 nor ENDTIM
      if (nc == 0 .and. inp%ctrl%imp%dt0 > 0.0_wp .and. .not. (inp%ctrl%endtim > 0.0_wp)) then
         call set_error(error, inp%files(inp%ctrl%imp%ifile)%s//':'//str(inp%ctrl%imp%line)// &
            ': *CONTROL_IMPLICIT_GENERAL: field IMFLAG: IMFLAG = 1 (the implicit Newton '// &
            'solver) steps the loads from 0 to *CONTROL_TERMINATION ENDTIM, which must be > 0')
         return
      end if
      if (inp%ctrl%imp%dt0 > 0.0_wp) return
      if (nc == 0) then
         call set_error(error, inp%files(inp%ctrl%imp%ifile)%s//':'//str(inp%ctrl%imp%line)// &
            ': *CONTROL_IMPLICIT_GENERAL: field DT0: the implicit step size must be > 0 '// &
            '(the implicit Newton solver of IMFLAG = 1 steps the loads by DT0)')
         return
      end if
      call set_error(error, inp%files(inp%ctrl%imp%ifile)%s//':'//str(inp%ctrl%imp%line)// &
         ': *CONTROL_IMPLICIT_GENERAL: field DT0: the implicit step size must be > 0 '// &
         '(the conserving solver of *DYNX_CONSERVING_CONTACT steps by DT0)')
   end subroutine emc_finish
end module dx_read_emc
