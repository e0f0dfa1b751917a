!> *MAT_ELASTIC_PLASTIC_HYDRO (*MAT_010): J2 plasticity with isotropic hardening and a pressure
!> term, the pressure from the part's equation of state (LS-DYNA Keyword User's Manual Vol. II,
!> *MAT_ELASTIC_PLASTIC_HYDRO; DYNA3D material 10, Hallquist, Theoretical Manual for DYNA3D,
!> UCID-19401, 1983). Yield stress
!>    sigma_y = h(eps_p) + (A1 + A2 p) max(p, 0),
!> h the table ES(EPS) of up to 16 points (linear between points, extrapolated with the last
!> segment, ES1 below EPS1) when ES is given, else SIGO + EH eps_p (EH the plastic hardening
!> modulus). Radial return (Wilkins 1964) for h(eps_p + deps_p) with the pressure of the step
!> before, solved exactly by safeguarded Newton (piecewise linear h: exact after the segment is
!> found). Pressure from the EOS with the half-step energy correction of dx_mat_steinberg
!> (this step's deviatoric work in E*), cut off at PC (PC = 0: no cut-off, -infinity, as
!> LS-DYNA). FS > 0: the point fails (erodes) at eps_p >= FS.
!> Cards: MID RO G SIGO EH PC FS CHARL; EPS1-8; EPS9-16; ES1-8; ES9-16; and dynx reads A1 A2
!> from an optional sixth card (their card position in the manual could not be checked;
!> written in docs/keywords.md). CHARL (the _SPALL variant's element thickness) must be 0.
!> Checks (exit 2 naming the field): G > 0, EPS strictly increasing over the points given
!> (a non-monotone table names the first EPSk out of order), ES >= 0.
!> History: 1 eps_p, 2 p, 3 V(n) (0: reference), 4 E, 5 c**2, 6 sigma_y of the last update.
module dx_mat_hydro
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr, str
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   use dx_mat_hydro_common, only: hydro_material_t, deviatoric_split, &
                                  history_wave_speed
   implicit none
   private
   public :: mat_hydro_t

   type, extends(hydro_material_t) :: mat_hydro_t
      real(wp) :: g = 0.0_wp, sigo = 0.0_wp, eh = 0.0_wp, pc = 0.0_wp, fs = 0.0_wp
      real(wp) :: a1 = 0.0_wp, a2 = 0.0_wp
      real(wp) :: eps(16) = 0.0_wp, es(16) = 0.0_wp
      integer :: npt = 0                     !< table points in use (0: SIGO + EH eps_p)
   contains
      procedure :: read_cards => hy_read_cards
      procedure :: setup => hy_setup
      procedure :: nhist => hy_nhist
      procedure :: update => hy_update
      procedure :: wave_speed => hy_wave_speed
      procedure :: fails => hy_fails
      procedure :: hardening => hy_hardening
   end type mat_hydro_t

contains

   subroutine hy_read_cards(self, c)
      class(mat_hydro_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      real(wp) :: x
      integer :: k
      call read_mid_ro(self, c)
      call c%real('G', 0.0_wp, self%g)
      call c%real('SIGO', 0.0_wp, self%sigo)
      call c%real('EH', 0.0_wp, self%eh)
      call c%real('PC', 0.0_wp, self%pc)
      call c%real('FS', 0.0_wp, self%fs)
      call c%real('CHARL', 0.0_wp, x)
      if (c%ok() .and. x /= 0.0_wp) call c%fail('CHARL', 'the spall option''s element '// &
         'thickness is not supported (CHARL must be 0), got '//rstr(x))
      do k = 1, 16
         if (k == 1 .or. k == 9) call c%next()
         call c%real('EPS'//str(k), 0.0_wp, self%eps(k))
      end do
      do k = 1, 16
         if (k == 1 .or. k == 9) call c%next()
         call c%real('ES'//str(k), 0.0_wp, self%es(k))
      end do
      call c%next()
      call c%real('A1', 0.0_wp, self%a1)
      call c%real('A2', 0.0_wp, self%a2)
   end subroutine hy_read_cards

   subroutine hy_setup(self, error)
      class(mat_hydro_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      if (.not. (self%ro > 0.0_wp)) then
         call set_field_error(error, 'RO', 'density must be > 0, got '//rstr(self%ro)); return
      end if
      if (.not. (self%g > 0.0_wp)) then
         call set_field_error(error, 'G', 'shear modulus must be > 0, got '//rstr(self%g)); return
      end if
      if (.not. (self%pc <= 0.0_wp)) then
         call set_field_error(error, 'PC', 'the pressure cut-off must be <= 0, got '// &
                              rstr(self%pc)); return
      end if
      if (.not. (self%fs >= 0.0_wp)) then
         call set_field_error(error, 'FS', 'must be >= 0, got '//rstr(self%fs)); return
      end if
      if (.not. (self%eh >= 0.0_wp)) then
         call set_field_error(error, 'EH', 'must be >= 0, got '//rstr(self%eh)); return
      end if
      self%npt = 0
      do k = 16, 1, -1
         if (self%es(k) /= 0.0_wp .or. self%eps(k) /= 0.0_wp) then
            self%npt = k
            exit
         end if
      end do
      if (self%npt == 1) then
         call set_field_error(error, 'ES2', 'the yield table needs at least 2 points'); return
      end if
      do k = 1, self%npt
         if (.not. (self%es(k) >= 0.0_wp)) then
            call set_field_error(error, 'ES'//str(k), 'yield stress must be >= 0, got '// &
                                 rstr(self%es(k))); return
         end if
      end do
      do k = 2, self%npt
         if (.not. (self%eps(k) > self%eps(k - 1))) then
            call set_field_error(error, 'EPS'//str(k), 'the plastic strains must increase: '// &
               'EPS'//str(k)//' = '//rstr(self%eps(k))//' after EPS'//str(k - 1)//' = '// &
               rstr(self%eps(k - 1))); return
         end if
      end do
      if (self%npt == 0 .and. .not. (self%sigo > 0.0_wp)) then
         call set_field_error(error, 'SIGO', 'yield stress must be > 0 (or the ES table '// &
                              'given), got '//rstr(self%sigo)); return
      end if
      if (self%pc == 0.0_wp) self%pc = -huge(1.0_wp)
      self%shear = self%g
      self%hv_eps_p = 1
   end subroutine hy_setup

   pure integer function hy_nhist(self)
      class(mat_hydro_t), intent(in) :: self
      hy_nhist = 6
      if (.false.) hy_nhist = int(self%ro)
   end function hy_nhist

   !> h(eps_p) and its slope (module header).
   pure subroutine hy_hardening(self, ep, h, dh)
      class(mat_hydro_t), intent(in) :: self
      real(wp), intent(in) :: ep
      real(wp), intent(out) :: h, dh
      integer :: k
      if (self%npt == 0) then
         h = self%sigo + self%eh*ep
         dh = self%eh
         return
      end if
      if (ep <= self%eps(1)) then
         h = self%es(1)
         dh = 0.0_wp
         return
      end if
      do k = 2, self%npt - 1
         if (ep <= self%eps(k)) exit
      end do
      k = min(k, self%npt)
      dh = (self%es(k) - self%es(k - 1))/(self%eps(k) - self%eps(k - 1))
      h = self%es(k - 1) + dh*(ep - self%eps(k - 1))
   end subroutine hy_hardening

   subroutine hy_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_hydro_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), parameter :: w(6) = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]
      real(wp) :: v, vold, pn, so(6), s(6), de(6), tr, seq, ep, dep, h, dh, r, lo, hi, g
      real(wp) :: yp, estar, e1, p1
      integer :: i, k
      g = self%g
      do i = 1, nv
         v = relvol(i)
         if (self%fs > 0.0_wp .and. hv(i, 1) >= self%fs) then
            sig(i, :) = 0.0_wp          ! eroded (fails): no stress, no EOS, never flagged
            hv(i, 3) = v
            cycle
         end if
         vold = hv(i, 3)
         if (vold == 0.0_wp) then
            vold = 1.0_wp
            hv(i, 2) = self%eos%pressure(1.0_wp, self%eos%e0 + eint(i))
         end if
         pn = hv(i, 2)
         ep = hv(i, 1)
         call deviatoric_split(sig(i, :), deps(i, :), so, de, tr)
         yp = (self%a1 + self%a2*pn)*max(pn, 0.0_wp)
         s = so + 2.0_wp*g*de
         seq = sqrt(1.5_wp*sum(w*s**2))
         call self%hardening(ep, h, dh)
         dep = 0.0_wp
         if (seq > h + yp) then
            lo = 0.0_wp
            hi = seq/(3.0_wp*g)
            dep = (seq - h - yp)/(3.0_wp*g + dh)
            do k = 1, 80
               if (.not. (dep > lo .and. dep < hi)) dep = 0.5_wp*(lo + hi)
               call self%hardening(ep + dep, h, dh)
               r = seq - 3.0_wp*g*dep - h - yp
               if (abs(r) <= 4.0_wp*epsilon(1.0_wp)*seq) exit
               if (r > 0.0_wp) then
                  lo = dep
               else
                  hi = dep
               end if
               dep = dep + r/(3.0_wp*g + dh)
            end do
            s = s*(1.0_wp - 3.0_wp*g*dep/seq)
         end if
         estar = self%eos%e0 + eint(i) + sum(w*0.5_wp*(so + s)*de)*0.5_wp*(v + vold)
         call self%eos%energy_update(v, v - vold, estar, pn, e1, p1)
         p1 = max(p1, self%pc)
         if (.not. (abs(p1) < huge(1.0_wp))) ierr(i) = 2   ! a material failure
         if (.not. self%eos%in_range(v)) ierr(i) = 2   ! compressed past the EOS's range
         sig(i, :) = s
         sig(i, 1:3) = s(1:3) - p1
         hv(i, 1) = ep + dep
         hv(i, 2) = p1
         hv(i, 3) = v
         hv(i, 4) = e1
         hv(i, 5) = self%eos%sound_speed2(self%ro, v, e1) + 4.0_wp*g*v/(3.0_wp*self%ro)
         call self%hardening(ep + dep, h, dh)
         hv(i, 6) = h + yp
      end do
      if (.false.) hv(1, 1) = dt
   end subroutine hy_update

   subroutine hy_wave_speed(self, nv, relvol, hv, c)
      class(mat_hydro_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: relvol(nv)
      real(wp), intent(in) :: hv(:, :)
      real(wp), intent(out) :: c(nv)
      call history_wave_speed(nv, relvol, hv, 3, 5, self%bulk + 4.0_wp*self%g/3.0_wp, self%ro, c)
   end subroutine hy_wave_speed

   !> Erosion at eps_p >= FS (FS > 0).
   subroutine hy_fails(self, nv, hv, failed)
      class(mat_hydro_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      integer :: i
      do i = 1, nv
         failed(i) = self%fs > 0.0_wp .and. hv(i, 1) >= self%fs
      end do
   end subroutine hy_fails
end module dx_mat_hydro
