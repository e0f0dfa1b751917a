!> *MAT_PLASTIC_KINEMATIC (*MAT_003): bilinear elastic-plastic, mixed isotropic/kinematic
!> hardening (BETA = 0 kinematic, 1 isotropic), radial return (Krieg & Krieg 1977), optional
!> Cowper-Symonds rate scaling of the yield stress (SRC = C, SRP = P) and erosion at the
!> failure strain FS. Hallquist, LS-DYNA Theory Manual, material 3.
!> Hardening modulus Ep = E*Et/(E - Et); yield radius R*(sigy + beta*Ep*eps_p) with the
!> Cowper-Symonds factor R = 1 + (rate/C)**(1/P), rate = sqrt(2/3 e':e') the effective
!> deviatoric strain rate of the step (U: LS-DYNA's exact rate measure not confirmed).
!> History: 1 = effective plastic strain, 2..7 = back stress (Voigt).
!> Laminae (update_plane_stress, sigma33 = 0): dx_plane_stress by the algorithm ps_alg, yield
!> radius R*(SIGY + BETA*Ep*eps_p), Ziegler back stress (1 - BETA)*Ep in history 2, 3, 5 (xx, yy,
!> xy; zz, yz, zx stay 0), R from the lamina strain rate ps_rate.
module dx_mat_plastic_kinematic
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, set_field_error
   use dx_strings, only: rstr
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro, MAT_ERR_PS_ALG
   use dx_plane_stress, only: ps_update, ps_rate, ps_alg_valid, ps_fibre_constants
   use dx_mat_elastic, only: check_elastic_constants
   implicit none
   private
   public :: mat_plastic_kinematic_t

   type, extends(material_t) :: mat_plastic_kinematic_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp, sigy = 0.0_wp, etan = 0.0_wp, beta = 0.0_wp
      real(wp) :: src = 0.0_wp, srp = 0.0_wp, fs = 0.0_wp, vp = 0.0_wp
      real(wp) :: ep = 0.0_wp       !< plastic hardening modulus (derived)
   contains
      procedure :: read_cards => pk_read_cards
      procedure :: setup => pk_setup
      procedure :: nhist => pk_nhist
      procedure :: update => pk_update
      procedure :: fails => pk_fails
      procedure :: update_plane_stress => pk_update_plane_stress
   end type mat_plastic_kinematic_t

contains

   !> Card 1: MID RO E PR SIGY ETAN BETA; card 2: SRC SRP FS VP.
   subroutine pk_read_cards(self, c)
      class(mat_plastic_kinematic_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call read_mid_ro(self, c)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('SIGY', 0.0_wp, self%sigy)
      call c%real('ETAN', 0.0_wp, self%etan)
      call c%real('BETA', 0.0_wp, self%beta)
      call c%next()
      call c%real('SRC', 0.0_wp, self%src)
      call c%real('SRP', 0.0_wp, self%srp)
      call c%real('FS', 0.0_wp, self%fs)
      call c%real('VP', 0.0_wp, self%vp)
   end subroutine pk_read_cards

   subroutine pk_setup(self, error)
      class(mat_plastic_kinematic_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call check_elastic_constants(self, self%e, self%pr, error)
      if (allocated(error)) return
      if (.not. (self%sigy > 0.0_wp)) then
         call set_field_error(error, 'SIGY', 'yield stress must be > 0, got '//rstr(self%sigy))
         return
      end if
      if (self%etan < 0.0_wp .or. self%etan >= self%e) then
         call set_field_error(error, 'ETAN', 'tangent modulus must lie in [0, E), got '// &
                        rstr(self%etan)); return
      end if
      if (self%beta < 0.0_wp .or. self%beta > 1.0_wp) then
         call set_field_error(error, 'BETA', 'must lie in [0, 1], got '//rstr(self%beta)); return
      end if
      if (self%src < 0.0_wp .or. self%srp < 0.0_wp .or. &
          ((self%src > 0.0_wp) .neqv. (self%srp > 0.0_wp))) then
         call set_error(error, 'fields SRC, SRP: Cowper-Symonds C and P must both be > 0 '// &
                        '(or both 0), got '//rstr(self%src)//', '//rstr(self%srp)); return
      end if
      ! VP chooses how the strain rate acts (0 scales the yield stress, 1 viscoplastic);
      ! without rate effects (SRC = SRP = 0) it changes nothing, so any LS-DYNA value is
      ! accepted there (LS-PrePost writes VP = 1)
      if (self%vp /= 0.0_wp .and. self%src > 0.0_wp) then
         call set_field_error(error, 'VP', 'VP = '//rstr(self%vp)//' (viscoplastic rate '// &
            'effect) is not supported with SRC, SRP > 0: only VP = 0 (scale the yield '// &
            'stress)'); return
      end if
      if (self%vp /= 0.0_wp .and. self%vp /= 1.0_wp .and. self%vp /= -1.0_wp) then
         call set_field_error(error, 'VP', 'must be -1, 0 or 1, got '//rstr(self%vp)); return
      end if
      self%ep = self%e*self%etan/(self%e - self%etan)
      self%hv_eps_p = 1
   end subroutine pk_setup

   pure integer function pk_nhist(self)
      class(mat_plastic_kinematic_t), intent(in) :: self
      pk_nhist = 7
   end function pk_nhist

   subroutine pk_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_plastic_kinematic_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: g2, k3, p, de(6), s(6), xi(6), xin, seff, rate, r, yld, dep, fac, dtr
      integer :: i
      g2 = 2.0_wp*self%shear
      k3 = self%bulk
      dtr = 0.0_wp
      if (dt > 0.0_wp) dtr = 1.0_wp/dt
      do i = 1, nv
         p = (sig(i, 1) + sig(i, 2) + sig(i, 3))/3.0_wp + k3*(deps(i, 1) + deps(i, 2) + deps(i, 3))
         de(1:3) = deps(i, 1:3) - (deps(i, 1) + deps(i, 2) + deps(i, 3))/3.0_wp
         de(4:6) = deps(i, 4:6)
         s(1:3) = sig(i, 1:3) - (sig(i, 1) + sig(i, 2) + sig(i, 3))/3.0_wp + g2*de(1:3)
         s(4:6) = sig(i, 4:6) + g2*de(4:6)
         xi = s - hv(i, 2:7)
         xin = sqrt(xi(1)**2 + xi(2)**2 + xi(3)**2 + 2.0_wp*(xi(4)**2 + xi(5)**2 + xi(6)**2))
         seff = sqrt(1.5_wp)*xin
         r = 1.0_wp
         if (self%src > 0.0_wp) then
            rate = sqrt((2.0_wp/3.0_wp)*(de(1)**2 + de(2)**2 + de(3)**2 + &
                        2.0_wp*(de(4)**2 + de(5)**2 + de(6)**2)))*dtr
            r = 1.0_wp + (rate/self%src)**(1.0_wp/self%srp)
         end if
         yld = r*(self%sigy + self%beta*self%ep*hv(i, 1))
         if (seff > yld) then
            dep = (seff - yld)/(3.0_wp*self%shear + (1.0_wp - self%beta)*self%ep + &
                                r*self%beta*self%ep)
            fac = sqrt(1.5_wp)*dep/xin          ! unit normal n = xi/xin
            s = s - g2*fac*xi
            hv(i, 2:7) = hv(i, 2:7) + (1.0_wp - self%beta)*self%ep*(2.0_wp/3.0_wp)*fac*xi
            hv(i, 1) = hv(i, 1) + dep
         end if
         sig(i, 1:3) = s(1:3) + p
         sig(i, 4:6) = s(4:6)
      end do
   end subroutine pk_update

   !> Lamina update (sigma33 = 0) of nv points: see the module header and dx_plane_stress.
   subroutine pk_update_plane_stress(self, nv, dt, deps, sig, hv, ierr, dezz, fibre)
      class(mat_plastic_kinematic_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 5)
      real(wp), intent(inout) :: sig(nv, 5)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), intent(out), optional :: dezz(nv)
      logical, intent(in), optional :: fibre
      real(wp) :: ee, nu
      real(wp) :: alpha(nv, 3), epsp(nv), y0(nv), hi(nv), dep(nv), r
      integer :: i
      if (.not. ps_alg_valid(self%ps_alg)) then
         ierr = MAT_ERR_PS_ALG
         return
      end if
      ee = self%e; nu = self%pr
      if (present(fibre)) then   ! a beam's section point (dx_plane_stress: fibre constants)
         if (fibre) call ps_fibre_constants(self%e, self%shear, ee, nu)
      end if
      do i = 1, nv
         r = 1.0_wp
         if (self%src > 0.0_wp) r = 1.0_wp + (ps_rate(dt, deps(i, :))/self%src)**(1.0_wp/self%srp)
         y0(i) = r*(self%sigy + self%beta*self%ep*hv(i, 1))
         hi(i) = r*self%beta*self%ep
         epsp(i) = hv(i, 1)
         alpha(i, 1) = hv(i, 2)
         alpha(i, 2) = hv(i, 3)
         alpha(i, 3) = hv(i, 5)
      end do
      call ps_update(self%ps_alg, nv, ee, nu, self%shear, deps, sig, alpha, epsp, y0, hi, &
                     (1.0_wp - self%beta)*self%ep, dep, ierr, dezz=dezz)
      do i = 1, nv
         hv(i, 1) = epsp(i)
         hv(i, 2) = alpha(i, 1)
         hv(i, 3) = alpha(i, 2)
         hv(i, 5) = alpha(i, 3)
      end do
   end subroutine pk_update_plane_stress

   subroutine pk_fails(self, nv, hv, failed)
      class(mat_plastic_kinematic_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      if (self%fs > 0.0_wp) then
         failed = hv(1:nv, 1) >= self%fs
      else
         failed = .false.
      end if
   end subroutine pk_fails
end module dx_mat_plastic_kinematic
