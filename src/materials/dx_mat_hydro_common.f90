!> Pieces shared by the hydro-type materials that carry an equation of state (*MAT_NULL,
!> *MAT_010, *MAT_JOHNSON_COOK, *MAT_STEINBERG): the deviatoric split of the old stress and
!> of the strain increment, the spall tests (LS-DYNA *MAT_STEINBERG SPALL
!> 2 and 3), the largest principal stress, the sound speed kept in a history column, and
!> their common parent type (it may carry an EOS).
!> Every routine does the operations of the loops it replaced, in the same order. The
!> half-step energy line (E* = E + mean deviatoric stress : de times the mean volume) stays
!> in each material's loop: as a call, gfortran -O3 sums its six terms in another order and
!> the results move in the last bit (measured on hirate_taylor_steinberg).
module dx_mat_hydro_common
   use dx_kinds, only: wp
   use dx_material, only: material_t
   implicit none
   private
   public :: hydro_material_t, deviatoric_split, spall_reached, max_principal, &
             history_wave_speed

   !> Voigt weights of the shear components in s:e sums
   real(wp), parameter :: W6(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]

   !> A material of LS-DYNA's hydro kind (types 9, 10, 11, 15): it may carry an equation of
   !> state (the part's EOSID)
   type, abstract, extends(material_t) :: hydro_material_t
   contains
      procedure :: takes_eos => hydro_takes_eos
   end type hydro_material_t

contains

   logical function hydro_takes_eos(self)
      class(hydro_material_t), intent(in) :: self
      hydro_takes_eos = .true.
      if (.false.) hydro_takes_eos = self%label < 0
   end function hydro_takes_eos

   !> so = deviator of the old stress sig, de = deviator of the strain increment deps,
   !> tr = deps's mean normal component
   pure subroutine deviatoric_split(sig, deps, so, de, tr)
      real(wp), intent(in) :: sig(6), deps(6)
      real(wp), intent(out) :: so(6), de(6), tr
      real(wp) :: pm
      pm = -(sig(1) + sig(2) + sig(3))/3.0_wp
      so = sig
      so(1:3) = so(1:3) + pm
      tr = (deps(1) + deps(2) + deps(3))/3.0_wp
      de = deps
      de(1:3) = de(1:3) - tr
   end subroutine deviatoric_split

   !> Spall test of *MAT_STEINBERG's SPALL option (LS-DYNA Keyword User's Manual): 2, the
   !> largest principal stress reaches -PC; 3, the pressure falls to PC (hydrostatic tension)
   pure logical function spall_reached(spall, pc, s, p1)
      integer, intent(in) :: spall
      real(wp), intent(in) :: pc, s(6), p1
      select case (spall)
      case (2)
         spall_reached = max_principal(s) - p1 >= -pc
      case (3)
         spall_reached = p1 <= pc
      case default
         spall_reached = .false.
      end select
   end function spall_reached

   !> Largest eigenvalue of the symmetric tensor s (Voigt xx,yy,zz,xy,yz,zx), by the
   !> trigonometric solution of the characteristic cubic (Smith, Comm. ACM 4 (1961) 168).
   pure real(wp) function max_principal(s) result(lmax)
      real(wp), intent(in) :: s(6)
      real(wp) :: m, d(3), q, p2, r, phi
      m = (s(1) + s(2) + s(3))/3.0_wp
      d = s(1:3) - m
      q = (d(1)**2 + d(2)**2 + d(3)**2 + 2.0_wp*(s(4)**2 + s(5)**2 + s(6)**2))/6.0_wp
      if (q <= 0.0_wp) then
         lmax = m
         return
      end if
      p2 = sqrt(q)
      r = (d(1)*(d(2)*d(3) - s(5)**2) - s(4)*(s(4)*d(3) - s(5)*s(6)) + &
           s(6)*(s(4)*s(5) - d(2)*s(6)))/(2.0_wp*p2**3)
      r = min(1.0_wp, max(-1.0_wp, r))
      phi = acos(r)/3.0_wp
      lmax = m + 2.0_wp*p2*cos(phi)
   end function max_principal

   !> Sound speed of the last update kept as c**2 in history column jc2 (column jv > 0 marks
   !> a point updated at least once); before any update sqrt(m0 V/rho0), m0 the modulus
   !> of the undeformed material
   pure subroutine history_wave_speed(nv, relvol, hv, jv, jc2, m0, ro, c)
      integer, intent(in) :: nv, jv, jc2
      real(wp), intent(in) :: relvol(nv), hv(:, :), m0, ro
      real(wp), intent(out) :: c(nv)
      integer :: i
      do i = 1, nv
         if (hv(i, jv) > 0.0_wp) then
            c(i) = sqrt(max(hv(i, jc2), 0.0_wp))
         else
            c(i) = sqrt(m0*relvol(i)/ro)
         end if
      end do
   end subroutine history_wave_speed
end module dx_mat_hydro_common
