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
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            std_widths, data_start
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

   subroutine need_card(deck, blk, i0, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: i0
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (blk%n < i0) call block_error(deck, blk, 0, 'missing card 1 ('//what//')', error)
   end subroutine need_card

   !> IMFLAG (0 explicit, 1 implicit: the conserving rigid-body solver; 2, explicit then
   !> implicit springback, refused), DT0 (step size), into model%ctrl%imp (dx_solver chooses).
   subroutine read_implicit_general(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), i0
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call need_card(deck, blk, i0, 'IMFLAG DT0 ...', error); if (allocated(error)) return
      call get_int(deck, blk, i0, 1, w, 'IMFLAG', 0, inp%ctrl%imp%imflag, error)
      if (allocated(error)) return
      if (inp%ctrl%imp%imflag == 2) then
         call field_error(deck, blk, i0, 1, w, 'IMFLAG', 'IMFLAG = 2 (explicit, then '// &
            'implicit springback) is not supported; 0 (explicit) and 1 (implicit: the '// &
            'conserving rigid-body solver with *DYNX_CONSERVING_CONTACT) are', error)
         return
      else if (inp%ctrl%imp%imflag /= 0 .and. inp%ctrl%imp%imflag /= 1) then
         call field_error(deck, blk, i0, 1, w, 'IMFLAG', 'only 0 (explicit) and 1 '// &
            '(implicit, conserving rigid-body solver) are supported, got '// &
            str(inp%ctrl%imp%imflag), error)
         return
      end if
      call get_real(deck, blk, i0, 2, w, 'DT0', 0.0_wp, inp%ctrl%imp%dt0, error)
      if (allocated(error)) return
      ! DT0 = 0 with IMFLAG = 1 is judged after the whole deck (emc_finish): without
      ! *DYNX_CONSERVING_CONTACT the IMFLAG message (build) says what is missing
      if (.not. (inp%ctrl%imp%dt0 >= 0.0_wp)) then
         call field_error(deck, blk, i0, 2, w, 'DT0', 'the implicit step size must be > 0', &
                          error)
         return
      end if
      inp%ctrl%imp%ifile = blk%ifile
      inp%ctrl%imp%line = blk%cards(i0)%line
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
      integer :: w(8), i0, imass
      real(wp) :: gamma, beta, alpha, b, c, disc, r1, r2
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call need_card(deck, blk, i0, 'IMASS GAMMA BETA ...', error)
      if (allocated(error)) return
      call get_int(deck, blk, i0, 1, w, 'IMASS', 1, imass, error)
      if (allocated(error)) return
      if (imass /= 1) then
         call field_error(deck, blk, i0, 1, w, 'IMASS', 'only 1 (dynamic analysis) is '// &
                          'supported, got '//str(imass), error); return
      end if
      call get_real(deck, blk, i0, 8, w, 'ALPHA', 0.0_wp, alpha, error)
      if (allocated(error)) return
      if (alpha > 0.0_wp) then
         call field_error(deck, blk, i0, 8, w, 'ALPHA', 'ALPHA > 0 selects the Bathe '// &
            'composite scheme, which the conserving solver does not have; HHT needs '// &
            '-1/3 <= ALPHA <= 0, got '//rstr(alpha), error); return
      end if
      if (alpha < -1.0_wp/3.0_wp - 1.0e-12_wp) then
         call field_error(deck, blk, i0, 8, w, 'ALPHA', 'the HHT parameter must be in '// &
            '[-1/3, 0] (unconditional stability), got '//rstr(alpha), error); return
      end if
      call get_real(deck, blk, i0, 2, w, 'GAMMA', 0.0_wp, gamma, error)
      if (allocated(error)) return
      call get_real(deck, blk, i0, 3, w, 'BETA', 0.0_wp, beta, error)
      if (allocated(error)) return
      if (alpha < 0.0_wp) then
         ! HHT: GAMMA and BETA follow from ALPHA; given ones must agree
         if (gamma /= 0.0_wp .and. abs(gamma - (0.5_wp - alpha)) > 1.0e-6_wp) then
            call field_error(deck, blk, i0, 2, w, 'GAMMA', 'with the HHT ALPHA = '// &
               rstr(alpha)//' GAMMA must be 1/2 - ALPHA = '//rstr(0.5_wp - alpha)// &
               ' (or blank), got '//rstr(gamma), error); return
         end if
         if (beta /= 0.0_wp .and. abs(beta - 0.25_wp*(1.0_wp - alpha)**2) > 1.0e-6_wp) then
            call field_error(deck, blk, i0, 3, w, 'BETA', 'with the HHT ALPHA = '// &
               rstr(alpha)//' BETA must be (1 - ALPHA)^2/4 = '// &
               rstr(0.25_wp*(1.0_wp - alpha)**2)//' (or blank), got '//rstr(beta), error)
            return
         end if
         gamma = 0.5_wp - alpha
         beta = 0.25_wp*(1.0_wp - alpha)**2
         inp%ctrl%imp%rho_inf = (1.0_wp + alpha)/(1.0_wp - alpha)
      else
         if (gamma == 0.0_wp) gamma = 0.5_wp
         if (beta == 0.0_wp) beta = 0.25_wp
         if (gamma < 0.5_wp .or. gamma > 1.5_wp) then
            call field_error(deck, blk, i0, 2, w, 'GAMMA', 'must be in [0.5, 1.5] (0.5: '// &
               'no numerical damping; > 0.5: high-frequency damping), got '//rstr(gamma), &
               error); return
         end if
         if (2.0_wp*beta < gamma) then
            call field_error(deck, blk, i0, 3, w, 'BETA', 'unconditional stability needs '// &
               'BETA >= GAMMA/2 = '//rstr(0.5_wp*gamma)//' (most damping: BETA = '// &
               '(GAMMA + 1/2)^2/4 = '//rstr(0.25_wp*(gamma + 0.5_wp)**2)//'), got '// &
               rstr(beta), error); return
         end if
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
   end subroutine read_implicit_dynamics

   !> CID SPID MPID FORM EPS: a conserving contact between two rigid parts.
   subroutine read_emc_contact(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(emc_contact_in_t) :: c
      integer :: w(8), i0, ic
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call need_card(deck, blk, i0, 'CID SPID MPID FORM EPS FS DFRIC', error)
      if (allocated(error)) return
      do ic = i0, blk%n
         c%ifile = blk%ifile
         c%line = blk%cards(ic)%line
         call get_int(deck, blk, ic, 1, w, 'CID', 0, c%cid, error); if (allocated(error)) return
         call get_int(deck, blk, ic, 2, w, 'SPID', 0, c%spid, error)
         if (allocated(error)) return
         if (c%spid <= 0) then
            call field_error(deck, blk, ic, 2, w, 'SPID', 'a slave part id > 0 is required', &
                             error); return
         end if
         call get_int(deck, blk, ic, 3, w, 'MPID', 0, c%mpid, error)
         if (allocated(error)) return
         if (c%mpid <= 0 .or. c%mpid == c%spid) then
            call field_error(deck, blk, ic, 3, w, 'MPID', 'a master part id > 0, other than '// &
                             'SPID, is required', error); return
         end if
         call get_int(deck, blk, ic, 4, w, 'FORM', EMC_PENALTY, c%form, error)
         if (allocated(error)) return
         if (c%form == 0) c%form = EMC_PENALTY
         if (c%form /= EMC_PENALTY .and. c%form /= EMC_LAGRANGE) then
            call field_error(deck, blk, ic, 4, w, 'FORM', '1 (penalty with the algorithmic '// &
               'gap) or 2 (Lagrange multipliers), got '//str(c%form), error); return
         end if
         call get_real(deck, blk, ic, 5, w, 'EPS', 0.0_wp, c%eps, error)
         if (allocated(error)) return
         if (c%form == EMC_PENALTY .and. .not. (c%eps > 0.0_wp)) then
            call field_error(deck, blk, ic, 5, w, 'EPS', 'the penalty stiffness [force/length]'// &
                             ' must be > 0', error); return
         end if
         call get_real(deck, blk, ic, 6, w, 'FS', 0.0_wp, c%fs, error)
         if (allocated(error)) return
         if (c%fs < 0.0_wp) then
            call field_error(deck, blk, ic, 6, w, 'FS', 'the Coulomb friction coefficient '// &
                             'must be >= 0', error); return
         end if
         call get_real(deck, blk, ic, 7, w, 'DFRIC', 0.0_wp, c%dfric, error)
         if (allocated(error)) return
         if (c%dfric < 0.0_wp) then
            call field_error(deck, blk, ic, 7, w, 'DFRIC', 'the friction regularization '// &
                             'slip must be >= 0', error); return
         end if
         if (.not. allocated(inp%emc%contacts)) allocate(inp%emc%contacts(0))
         inp%emc%contacts = [inp%emc%contacts, c]
      end do
   end subroutine read_emc_contact

   !> PID SIDE TOL: smooth this rigid part as an exact sphere (outer 0 / inner 1 surface).
   subroutine read_emc_sphere(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(emc_sphere_in_t) :: s
      integer :: w(8), i0, ic
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call need_card(deck, blk, i0, 'PID SIDE TOL', error); if (allocated(error)) return
      do ic = i0, blk%n
         s%ifile = blk%ifile
         s%line = blk%cards(ic)%line
         call get_int(deck, blk, ic, 1, w, 'PID', 0, s%pid, error); if (allocated(error)) return
         if (s%pid <= 0) then
            call field_error(deck, blk, ic, 1, w, 'PID', 'a part id > 0 is required', error)
            return
         end if
         call get_int(deck, blk, ic, 2, w, 'SIDE', 0, s%side, error)
         if (allocated(error)) return
         if (s%side /= 0 .and. s%side /= 1) then
            call field_error(deck, blk, ic, 2, w, 'SIDE', '0 (outer surface: ball) or 1 '// &
                             '(inner surface: shell), got '//str(s%side), error); return
         end if
         call get_real(deck, blk, ic, 3, w, 'TOL', 1.0e-3_wp, s%tol, error)
         if (allocated(error)) return
         if (s%tol == 0.0_wp) s%tol = 1.0e-3_wp
         if (s%tol < 0.0_wp) then
            call field_error(deck, blk, ic, 3, w, 'TOL', 'must be > 0', error); return
         end if
         if (.not. allocated(inp%emc%spheres)) allocate(inp%emc%spheres(0))
         inp%emc%spheres = [inp%emc%spheres, s]
      end do
   end subroutine read_emc_sphere

   !> MAXIT RTOL NFAIL OUTDT: Newton limits, failure action and emcstat interval.
   subroutine read_emc_control(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), i0
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call need_card(deck, blk, i0, 'MAXIT RTOL NFAIL OUTDT', error)
      if (allocated(error)) return
      call get_int(deck, blk, i0, 1, w, 'MAXIT', 20, inp%emc%maxit, error)
      if (allocated(error)) return
      if (inp%emc%maxit == 0) inp%emc%maxit = 20
      if (inp%emc%maxit < 0) then
         call field_error(deck, blk, i0, 1, w, 'MAXIT', 'must be > 0', error); return
      end if
      call get_real(deck, blk, i0, 2, w, 'RTOL', 1.0e-16_wp, inp%emc%rtol, error)
      if (allocated(error)) return
      if (inp%emc%rtol == 0.0_wp) inp%emc%rtol = 1.0e-16_wp
      if (inp%emc%rtol < 0.0_wp) then
         call field_error(deck, blk, i0, 2, w, 'RTOL', 'must be > 0', error); return
      end if
      call get_int(deck, blk, i0, 3, w, 'NFAIL', 0, inp%emc%nfail, error)
      if (allocated(error)) return
      if (inp%emc%nfail < 0) then
         call field_error(deck, blk, i0, 3, w, 'NFAIL', 'must be >= 0 (0: stop at the '// &
                          'first Newton failure; N: up to N step halvings)', error); return
      end if
      call get_real(deck, blk, i0, 4, w, 'OUTDT', 0.0_wp, inp%emc%out_dt, error)
      if (allocated(error)) return
      if (inp%emc%out_dt < 0.0_wp) then
         call field_error(deck, blk, i0, 4, w, 'OUTDT', 'must be >= 0', error); return
      end if
   end subroutine read_emc_control
   !> After the whole deck: IMFLAG = 1 for the conserving solver (*DYNX_CONSERVING_CONTACT
   !> present) needs DT0 > 0; without it the build names IMFLAG (the Newton solver of issue
   !> 20), so a DT0 of 0 there is not the first thing to say.
   subroutine emc_finish(inp, error)
      type(model_input_t), intent(in) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: nc
      nc = 0
      if (allocated(inp%emc%contacts)) nc = size(inp%emc%contacts)
      if (inp%ctrl%imp%imflag /= 1 .or. nc == 0) return
      if (inp%ctrl%imp%dt0 > 0.0_wp) return
      call set_error(error, inp%files(inp%ctrl%imp%ifile)%s//':'//str(inp%ctrl%imp%line)// &
         ': *CONTROL_IMPLICIT_GENERAL: field DT0: the implicit step size must be > 0 '// &
         '(the conserving solver of *DYNX_CONSERVING_CONTACT steps by DT0)')
   end subroutine emc_finish
end module dx_read_emc
