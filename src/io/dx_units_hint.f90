!> The units hint of d3hsp (issue 21): dynx, like LS-DYNA, uses whatever consistent set of
!> units the deck is written in and never converts. The hint names the common LS-DYNA sets
!> (LS-DYNA Keyword User's Manual, Vol. I, "consistent units" table: m s kg, mm s t,
!> mm ms kg, mm ms g, cm us g, in s lbf-s2/in, ...) in which the deck's materials look like
!> real solids: each material's density rho and wave speed c = sqrt(modulus/rho) at t = 0
!> are turned into SI by the set's length L, time T and mass M (rho L^-3 M, c L/T) and must
!> fall in rho 10 .. 25,000 kg/m3 (foams to tungsten) and c 20 .. 15,000 m/s (soft
!> elastomers to beryllium). Density fixes M/L^3 and the wave speed L/T, so the common sets
!> are told apart; sets that differ by a scaling a (aL, aT, a^3 M) are not, and none of the
!> common ones do. A steel in one set can look like a foam in another (mm ms kg steel is
!> 84 kg/m3, 152 m/s in inch units), so the set where every material is a typical solid
!> (rho 900 .. 20,000 kg/m3, c 1,000 .. 8,000 m/s) is named the likely one when it is
!> alone. A hint only: the run does not depend on it.
module dx_units_hint
   use dx_kinds, only: wp
   implicit none
   private
   public :: units_hint

   type :: uset_t
      character(40) :: name
      real(wp) :: l, t, m          !< the set's length, time and mass in m, s, kg
      character(6) :: tname        !< the time unit's name
   end type uset_t

   integer, parameter :: NSET = 8
   real(wp), parameter :: SLUG_IN = 4.4482216152605_wp/0.0254_wp   !< lbf s2/in in kg

contains

   !> Lines (each ending with a new line) for d3hsp: the materials' rho and c, the sets that
   !> fit every material, and the end time in that set's time unit. rho(k), c(k): the k-th
   !> material's density and wave speed in deck units (k over the deck's deformable parts);
   !> endtim: *CONTROL_TERMINATION ENDTIM.
   function units_hint(rho, c, endtim) result(t)
      real(wp), intent(in) :: rho(:), c(:), endtim
      character(:), allocatable :: t
      type(uset_t) :: s(NSET)
      logical :: fits(NSET), core(NSET)
      integer :: k, j, nfit
      character, parameter :: nl = new_line('a')
      s = [uset_t('m, s, kg (N, Pa)', 1.0_wp, 1.0_wp, 1.0_wp, 's'), &
           uset_t('mm, s, t (N, MPa)', 1.0e-3_wp, 1.0_wp, 1.0e3_wp, 's'), &
           uset_t('mm, ms, kg (kN, GPa)', 1.0e-3_wp, 1.0e-3_wp, 1.0_wp, 'ms'), &
           uset_t('mm, ms, g (N, MPa)', 1.0e-3_wp, 1.0e-3_wp, 1.0e-3_wp, 'ms'), &
           uset_t('cm, us, g (1e7 N, Mbar)', 1.0e-2_wp, 1.0e-6_wp, 1.0e-3_wp, 'us'), &
           uset_t('cm, s, g (dyne, dyne/cm2)', 1.0e-2_wp, 1.0_wp, 1.0e-3_wp, 's'), &
           uset_t('mm, s, kg (mN, kPa)', 1.0e-3_wp, 1.0_wp, 1.0_wp, 's'), &
           uset_t('in, s, lbf-s2/in (lbf, psi)', 0.0254_wp, 1.0_wp, SLUG_IN, 's')]
      t = '  units hint (dynx uses the deck''s units as they are; this only names the '// &
          'common set they look like):'//nl
      if (size(rho) == 0) then
         t = t//'    no deformable material with a density and a wave speed: no hint'//nl
         return
      end if
      fits = .true.
      core = .true.
      do k = 1, size(rho)
         do j = 1, NSET
            fits(j) = fits(j) .and. plausible(rho(k), c(k), s(j), .false.)
            core(j) = core(j) .and. plausible(rho(k), c(k), s(j), .true.)
         end do
      end do
      do k = 1, min(size(rho), 5)
         t = t//'    material '//trim(num(real(k, wp), .true.))//': density '// &
             trim(num(rho(k)))//', wave speed '//trim(num(c(k)))//', modulus rho c^2 '// &
             trim(num(rho(k)*c(k)**2))//nl
      end do
      if (size(rho) > 5) t = t//'    (and '//trim(num(real(size(rho) - 5, wp), .true.))// &
         ' more)'//nl
      nfit = count(fits)
      if (nfit == 0) then
         t = t//'    no common unit set makes every material a plausible solid (density '// &
             '10-25000 kg/m3, wave speed 20-15000 m/s): check the units of RO and E'//nl
         return
      end if
      do j = 1, NSET
         if (.not. fits(j)) cycle
         t = t//'    consistent with '//trim(s(j)%name)//': material 1 is '// &
             trim(num(rho(1)*s(j)%m/s(j)%l**3))//' kg/m3, '// &
             trim(num(c(1)*s(j)%l/s(j)%t))//' m/s'//trim(merge(' (typical solids)', &
             '                 ', core(j)))//'; the end time '//trim(num(endtim))//' '// &
             trim(s(j)%tname)//nl
      end do
      if (count(core) == 1) then
         t = t//'    likely unit set: '//trim(s(findloc(core, .true., dim=1))%name)//nl
      else if (count(core) > 1) then
         t = t//'    several common sets fit; the end time and the loads tell which'//nl
      else
         t = t//'    no common unit set makes every material a typical solid (density '// &
             '900-20000 kg/m3, wave speed 1000-8000 m/s): soft or light materials, or check '// &
             'the units of RO and E'//nl
      end if
   end function units_hint

   !> rho and c in SI fall in the ranges of real solids (typical: those of metals, ceramics,
   !> polymers, water: rho 900 .. 20,000 kg/m3, c 1,000 .. 8,000 m/s).
   logical function plausible(rho, c, s, typical)
      real(wp), intent(in) :: rho, c
      type(uset_t), intent(in) :: s
      logical, intent(in) :: typical
      real(wp) :: r, v
      r = rho*s%m/s%l**3
      v = c*s%l/s%t
      if (typical) then
         plausible = r >= 900.0_wp .and. r <= 20000.0_wp .and. v >= 1000.0_wp .and. &
                     v <= 8000.0_wp
      else
         plausible = r >= 10.0_wp .and. r <= 25000.0_wp .and. v >= 20.0_wp .and. &
                     v <= 15000.0_wp
      end if
   end function plausible

   !> x with 4 significant digits (an integer when asked)
   function num(x, int) result(s)
      real(wp), intent(in) :: x
      logical, intent(in), optional :: int
      character(24) :: s
      if (present(int)) then
         write(s, '(i0)') nint(x)
      else
         write(s, '(es11.4)') x
         s = adjustl(s)
      end if
   end function num
end module dx_units_hint
