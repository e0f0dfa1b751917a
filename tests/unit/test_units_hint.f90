!> The d3hsp units hint (src/io/dx_units_hint.f90): steel (rho 7850 kg/m3, E 210 GPa, nu 0.3:
!> dilatational wave speed sqrt(E(1 - nu)/(rho(1 + nu)(1 - 2 nu))) = 6001 m/s) and aluminium
!> (2700 kg/m3, 6400 m/s) written in each common LS-DYNA unit set (rho M^-1 L^3, c T/L) must be
!> named as that set's "likely unit set"; a kg/mm3 density in an mm-s-t (MPa) deck names no
!> likely set; a density off by 1e6 fits no set and says so; an empty list gives no hint.
program test_units_hint
   use dx_kinds, only: wp
   use dx_assert, only: check, assert_summary
   use dx_units_hint, only: units_hint
   implicit none
   character(40), parameter :: names(7) = [character(40) :: 'm, s, kg (N, Pa)', &
      'mm, s, t (N, MPa)', 'mm, ms, kg (kN, GPa)', 'mm, ms, g (N, MPa)', &
      'cm, us, g (1e7 N, Mbar)', 'cm, s, g (dyne, dyne/cm2)', 'in, s, lbf-s2/in (lbf, psi)']
   real(wp), parameter :: l(7) = [1.0_wp, 1.0e-3_wp, 1.0e-3_wp, 1.0e-3_wp, 1.0e-2_wp, &
                                  1.0e-2_wp, 0.0254_wp]
   real(wp), parameter :: t(7) = [1.0_wp, 1.0_wp, 1.0e-3_wp, 1.0e-3_wp, 1.0e-6_wp, 1.0_wp, 1.0_wp]
   real(wp), parameter :: m(7) = [1.0_wp, 1.0e3_wp, 1.0_wp, 1.0e-3_wp, 1.0e-3_wp, 1.0e-3_wp, &
                                  4.4482216152605_wp/0.0254_wp]
   real(wp) :: rho(2), c(2)
   character(:), allocatable :: h
   integer :: k
   do k = 1, 7
      rho = [7850.0_wp, 2700.0_wp]*l(k)**3/m(k)
      c = [6001.0_wp, 6400.0_wp]*t(k)/l(k)
      h = units_hint(rho, c, 1.0_wp)
      call check(index(h, 'likely unit set: '//trim(names(k))) > 0, &
                 'steel and aluminium in '//trim(names(k))//' named as that set')
   end do
   ! the classic slip: a kg/mm3 density (7.85e-6) with MPa moduli (E 2.1e5, an mm-s-t deck):
   ! c = sqrt(2.1e5/7.85e-6) = 1.6355e5, which no set makes a typical solid (mm s kg: 163
   ! m/s); a density off by 1e6 fits no set at all
   h = units_hint([7.85e-6_wp], [1.6355e5_wp], 1.0_wp)
   call check(index(h, 'no common unit set makes every material a typical solid') > 0 .and. &
              index(h, 'likely') == 0, 'kg/mm3 density with MPa moduli: no likely set')
   h = units_hint([7.85e-12_wp], [6.001e6_wp], 1.0_wp)
   call check(index(h, 'no common unit set makes every material a plausible solid') > 0, &
              'density off by 1e6: no set fits')
   h = units_hint([real(wp) ::], [real(wp) ::], 1.0_wp)
   call check(index(h, 'no hint') > 0, 'no material: no hint')
   call assert_summary()
end program test_units_hint
