!> Unit tests of the material models against closed-form answers
!> (physics-references.md section 3.1: uniaxial stress, E = 200 GPa, sigma_y = 250 MPa,
!> Et = 2 GPa: sigma(0.01) = 267.5 MPa in one step, within 1e-10 relative).
!> The finite-difference tangent (material_t%tangent) against the analytic elastic tangent and
!> the analytic consistent tangent of the radial return of *MAT_PLASTIC_KINEMATIC (Simo &
!> Taylor 1985), *EOS_LINEAR_POLYNOMIAL / *MAT_NULL against hand-calculated pressures (with the
!> PC cut-off, the MU viscosity s = 2 MU deps'/dt, and the flag of a point compressed past a
!> Gruneisen pole), and
!> *EOS_GRUNEISEN against the Rankine-Hugoniot state p = rho0 Us up of its Us-up fit.
program test_materials
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_material, only: material_t, fd_tangent
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_curve, only: curve_t
   use dx_mat_null, only: mat_null_t
   use dx_eos_linear_polynomial, only: eos_linear_polynomial_t
   use dx_eos_gruneisen, only: eos_gruneisen_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: el
   type(mat_plastic_kinematic_t) :: pk
   type(mat_piecewise_linear_t) :: pl
   type(error_t), allocatable :: err
   type(curve_t) :: curves(1)
   real(wp) :: sig(1, 6), hv(1, 7), s, r, g
   real(wp), parameter :: e = 200.0e3_wp, sy = 250.0_wp, et = 2000.0_wp   ! MPa
   real(wp) :: dfd(6, 6), dan(6, 6), de0(6), h, tol, smax
   integer :: ierr

   ! ---- elastic: pure shear
   el%ro = 7.8e-9_wp; el%e = e; el%pr = 0.3_wp
   call el%setup(err)
   call check(.not. allocated(err), 'elastic setup')
   sig = 0.0_wp
   call step(el, [0.0_wp, 0.0_wp, 0.0_wp, 1.0e-4_wp, 0.0_wp, 0.0_wp], 1.0_wp, sig, hv)
   call check_close(sig(1, 4), 2.0_wp*el%shear*1.0e-4_wp, 0.0_wp, 1.0e-14_wp, 'elastic shear')
   call check_close(sig(1, 1), 0.0_wp, 1.0e-12_wp, 0.0_wp, 'elastic shear: no normal stress')
   el%e = -1.0_wp
   call el%setup(err)
   call check(allocated(err), 'elastic: negative E rejected')
   el%e = e; el%ro = -1.0_wp
   call el%setup(err)
   call check(allocated(err), 'elastic: negative density rejected')

   ! ---- plastic kinematic, isotropic (beta = 1) and kinematic (beta = 0)
   pk%ro = 7.8e-9_wp; pk%e = e; pk%pr = 0.3_wp; pk%sigy = sy; pk%etan = et
   pk%beta = 1.0_wp
   call pk%setup(err)
   call check(.not. allocated(err), 'mat3 setup')
   sig = 0.0_wp; hv = 0.0_wp
   s = uniaxial(pk, 0.01_wp, sig, hv)
   call check_close(s, 267.5_wp, 0.0_wp, 1.0e-10_wp, 'mat3 beta=1 uniaxial 0.01')
   s = uniaxial(pk, -0.01_wp, sig, hv)
   call check_close(s, -282.15_wp, 0.0_wp, 1.0e-10_wp, 'mat3 beta=1 reversed to 0 (isotropic)')
   pk%beta = 0.0_wp
   call pk%setup(err)
   sig = 0.0_wp; hv = 0.0_wp
   s = uniaxial(pk, 0.01_wp, sig, hv)
   call check_close(s, 267.5_wp, 0.0_wp, 1.0e-10_wp, 'mat3 beta=0 uniaxial 0.01')
   s = uniaxial(pk, -0.01_wp, sig, hv)
   call check_close(s, -247.5_wp, 0.0_wp, 1.0e-10_wp, 'mat3 beta=0 reversed to 0 (Bauschinger)')
   ! plastic strain: 0.01 - 267.5/E on loading, 0.0075 - 15/E on the reversed branch
   call check_close(hv(1, 1), (0.01_wp - 267.5_wp/e) + (0.0075_wp - 15.0_wp/e), 0.0_wp, &
                    1.0e-10_wp, 'mat3 plastic strain accumulates over both branches')

   ! ---- piecewise linear: bilinear, table, curve, Cowper-Symonds
   pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = 0.3_wp; pl%sigy = sy; pl%etan = et
   call pl%resolve_curves(curves(1:0), err)
   call pl%setup(err)
   call check(.not. allocated(err), 'mat24 bilinear setup')
   sig = 0.0_wp; hv = 0.0_wp
   s = uniaxial(pl, 0.01_wp, sig, hv)
   call check_close(s, 267.5_wp, 0.0_wp, 1.0e-10_wp, 'mat24 bilinear uniaxial 0.01')
   call check_close(hv(1, 1), 0.01_wp - 267.5_wp/e, 0.0_wp, 1.0e-10_wp, &
                    'mat24 bilinear plastic strain')
   pl = mat_piecewise_linear_t()
   pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = 0.3_wp
   curves(1)%label = 7
   curves(1)%x = [0.0_wp, 0.02_wp, 0.2_wp]
   curves(1)%y = [250.0_wp, 290.0_wp, 380.0_wp]
   pl%lcss = 7
   call pl%resolve_curves(curves, err)
   call check(.not. allocated(err), 'mat24 LCSS resolved')
   call pl%setup(err)
   sig = 0.0_wp; hv = 0.0_wp
   s = uniaxial(pl, 0.1_wp, sig, hv)
   call check_close(s, 330.0_wp/1.0025_wp, 0.0_wp, 1.0e-10_wp, 'mat24 curve, crossing a breakpoint')
   pl%lcss = 99
   call pl%resolve_curves(curves, err)
   call check(allocated(err), 'mat24 missing LCSS curve rejected')
   ! EPS/ES table equals the same curve
   pl = mat_piecewise_linear_t()
   pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = 0.3_wp
   pl%eps(1:3) = [0.0_wp, 0.02_wp, 0.2_wp]; pl%es(1:3) = [250.0_wp, 290.0_wp, 380.0_wp]
   call pl%resolve_curves(curves(1:0), err)
   call pl%setup(err)
   call check(.not. allocated(err), 'mat24 EPS/ES setup')
   sig = 0.0_wp; hv = 0.0_wp
   s = uniaxial(pl, 0.1_wp, sig, hv)
   call check_close(s, 330.0_wp/1.0025_wp, 0.0_wp, 1.0e-10_wp, 'mat24 EPS/ES table')
   ! EPS1-8 (LS-DYNA): increasing, the first EPSk = 0 after EPS1 ends the table; a value that
   ! does not increase or one after the end is refused naming the field (no silent cut)
   pl%eps(1:4) = [0.0_wp, 0.02_wp, 0.2_wp, 0.05_wp]; pl%es(1:4) = [250.0_wp, 290.0_wp, &
                                                                   380.0_wp, 400.0_wp]
   pl%bilinear = .true.
   call pl%setup(err)
   call check(allocated(err), 'mat24 EPS4 < EPS3 refused')
   if (allocated(err)) call check(err%field == 'EPS4', 'mat24 EPS4 < EPS3: names EPS4')
   pl%eps(1:4) = [0.0_wp, 0.02_wp, 0.0_wp, 0.3_wp]
   pl%bilinear = .true.
   call pl%setup(err)
   call check(allocated(err), 'mat24 EPS4 after the end (EPS3 = 0) refused')
   if (allocated(err)) call check(err%field == 'EPS4', 'mat24 EPS after the end: names EPS4')
   pl%eps(1:4) = [0.0_wp, 0.02_wp, 0.2_wp, 0.0_wp]; pl%es(4) = 0.0_wp
   pl%bilinear = .true.
   call pl%setup(err)
   call check(.not. allocated(err), 'mat24 EPS table ended by EPS4 = 0')
   if (.not. allocated(err)) call check(size(pl%hard%x) == 3, 'mat24 EPS table: 3 points')
   ! Cowper-Symonds VP=0, perfectly plastic, pure shear at a known rate:
   ! effective deviatoric rate = (2/sqrt 3) e12/dt
   pl = mat_piecewise_linear_t()
   pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = 0.3_wp; pl%sigy = sy; pl%etan = 0.0_wp
   pl%c = 40.0_wp; pl%p = 5.0_wp
   call pl%resolve_curves(curves(1:0), err)
   call pl%setup(err)
   sig = 0.0_wp; hv = 0.0_wp
   call step(pl, [0.0_wp, 0.0_wp, 0.0_wp, 0.01_wp, 0.0_wp, 0.0_wp], 1.0e-3_wp, sig, hv)
   r = 1.0_wp + ((2.0_wp/sqrt(3.0_wp))*0.01_wp/1.0e-3_wp/40.0_wp)**(1.0_wp/5.0_wp)
   call check_close(sig(1, 4), r*sy/sqrt(3.0_wp), 0.0_wp, 1.0e-10_wp, 'mat24 Cowper-Symonds VP=0')
   ! VP = 1: sigma_y = h + SIGY*(rate_p/C)**(1/P) with rate_p = dep/dt
   pl%vp = 1.0_wp
   call pl%setup(err)
   sig = 0.0_wp; hv = 0.0_wp
   call step(pl, [0.0_wp, 0.0_wp, 0.0_wp, 0.01_wp, 0.0_wp, 0.0_wp], 1.0e-3_wp, sig, hv)
   g = pl%shear
   ! consistency: seff_trial - 3G dep = sy*(1 + (dep/dt/C)^(1/P)), seff = sqrt(3) * 2G*0.01
   r = sqrt(3.0_wp)*2.0_wp*g*0.01_wp - 3.0_wp*g*hv(1, 1) - sy*(1.0_wp + &
       (hv(1, 1)/1.0e-3_wp/40.0_wp)**0.2_wp)
   call check_close(r, 0.0_wp, 1.0e-9_wp*sy, 0.0_wp, 'mat24 VP=1 consistency')
   call check_close(sqrt(3.0_wp)*sig(1, 4), sy*(1.0_wp + (hv(1, 1)/1.0e-3_wp/40.0_wp)**0.2_wp), &
                    0.0_wp, 1.0e-10_wp, 'mat24 VP=1 stress on the rate-dependent yield surface')

   ! ---- finite-difference tangent against the analytic elastic tangent. The update is linear
   ! in deps, so the central difference has no truncation error: only round-off, each stress
   ! rounded to ~eps*smax and the difference divided by 2h, bounded by 4*eps*smax/h
   el%ro = 7.8e-9_wp; el%e = e; el%pr = 0.3_wp
   call el%setup(err)
   de0 = [1.0e-3_wp, -2.0e-4_wp, 3.0e-4_wp, 1.0e-4_wp, -5.0e-5_wp, 2.0e-4_wp]
   sig = 0.0_wp
   sig(1, :) = [100.0_wp, -20.0_wp, 5.0_wp, 30.0_wp, 0.0_wp, -10.0_wp]
   call fd_tangent(el, 1.0_wp, de0, 1.0_wp, 0.0_wp, sig(1, :), hv(1, 1:0), dfd, ierr)
   call elastic_matrix(el%bulk, el%shear, dan)
   h = fd_h(de0)
   smax = maxval(abs(sig)) + maxval(abs(dan))*(maxval(abs(de0)) + h)
   tol = 4.0_wp*epsilon(1.0_wp)*smax/h
   call check(ierr == 0, 'tangent: elastic update ok')
   call check_close(maxval(abs(dfd - dan)), 0.0_wp, tol, 0.0_wp, &
                    'FD tangent = analytic elastic tangent (round-off bound 4 eps smax/h)')
   ! *MAT_ELASTIC's own tangent (the implicit solver's) is the same matrix exactly (both are
   ! lambda + 2G on the diagonal, formed from the same K and G)
   call el%tangent(1.0_wp, de0, 1.0_wp, 0.0_wp, sig(1, :), hv(1, 1:0), dfd, ierr)
   call check(ierr == 0 .and. maxval(abs(dfd - dan)) <= 4.0_wp*epsilon(1.0_wp)*maxval(abs(dan)), &
              'elastic analytic tangent = lambda + 2G matrix')

   ! ---- at a yielded point of *MAT_PLASTIC_KINEMATIC (beta = 0.5, no rate effect): load past
   ! yield, then the tangent of the next plastic step against the consistent tangent
   pk = mat_plastic_kinematic_t()
   pk%ro = 7.8e-9_wp; pk%e = e; pk%pr = 0.3_wp; pk%sigy = sy; pk%etan = et; pk%beta = 0.5_wp
   call pk%setup(err)
   sig = 0.0_wp; hv = 0.0_wp
   call step(pk, [4.0e-3_wp, -1.2e-3_wp, -1.2e-3_wp, 5.0e-4_wp, 0.0_wp, 2.0e-4_wp], 1.0_wp, &
             sig, hv)
   call check(hv(1, 1) > 0.0_wp, 'mat3: the first step yields')
   de0 = [1.0e-3_wp, -3.0e-4_wp, 2.0e-4_wp, 4.0e-4_wp, -1.0e-4_wp, 1.0e-4_wp]
   call pk%tangent(1.0_wp, de0, 1.0_wp, 0.0_wp, sig(1, :), hv(1, :), dfd, ierr)
   call pk_consistent(pk, sig(1, :), hv(1, :), de0, dan, tol)
   h = fd_h(de0)
   ! round-off as above plus the central-difference truncation h**2/6 |d3 sig/d deps3|
   ! (pk_consistent returns the third-derivative scale in tol)
   smax = maxval(abs(sig)) + maxval(abs(dan))*(maxval(abs(de0)) + h)
   tol = 4.0_wp*epsilon(1.0_wp)*smax/h + h**2/6.0_wp*tol
   call check(ierr == 0, 'tangent: plastic update ok')
   call check_close(maxval(abs(dfd - dan)), 0.0_wp, tol, 0.0_wp, &
                    'FD tangent = consistent elastic-plastic tangent at a yielded point')
   call check(maxval(abs(dfd - dan)) < 1.0e-6_wp*maxval(abs(dan)), &
              'FD tangent within 1e-6 of the largest modulus')
   call check(abs(dan(1, 1) - (el%bulk + 4.0_wp*el%shear/3.0_wp)) > 1.0e3_wp, &
              'the plastic tangent differs from the elastic one')

   ! ---- *EOS_LINEAR_POLYNOMIAL by hand: C0..C6 = 1, 2, 3, 4, 5, 6, 7 (MPa), E = 0.5
   call eos_checks()
   ! ---- *MAT_NULL with C1 = K: uniform compression V = 0.99 from rest, p = K mu exactly
   call null_checks()
   ! ---- *EOS_GRUNEISEN on the Hugoniot of a linear Us-up fit, its derivatives, mu = 0
   call gruneisen_checks()
   call assert_summary()

contains

   pure real(wp) function fd_h(de)
      real(wp), intent(in) :: de(6)
      fd_h = epsilon(1.0_wp)**(1.0_wp/3.0_wp)*max(maxval(abs(de)), 1.0e-4_wp)
   end function fd_h

   !> Isotropic elastic tangent in dynx's Voigt convention (tensor shear strains: D44 = 2G).
   subroutine elastic_matrix(k, g, d)
      real(wp), intent(in) :: k, g
      real(wp), intent(out) :: d(6, 6)
      integer :: i
      d = 0.0_wp
      d(1:3, 1:3) = k - 2.0_wp*g/3.0_wp
      do i = 1, 6
         d(i, i) = d(i, i) + 2.0_wp*g
      end do
   end subroutine elastic_matrix

   !> Consistent tangent of pk_update's radial return (no rate effect), from (sig, hv) by de:
   !> s_new = alpha + xi - a xi + b n with xi the trial relative stress, n = xi/|xi|,
   !> a = 3G/(3G + Ep), b = sqrt(6) G yld/(3G + Ep); d s_new/d xi = (1-a) I + b (I - n n)/|xi|
   !> and d xi/d e = 2G I_dev. c3 returns the scale of the third derivative, 6 b (2G)**3/|xi|**3.
   subroutine pk_consistent(m, sig, hv, de, d, c3)
      type(mat_plastic_kinematic_t), intent(in) :: m
      real(wp), intent(in) :: sig(6), hv(:), de(6)
      real(wp), intent(out) :: d(6, 6), c3
      real(wp) :: g, xi(6), xn, n(6), a, b, yld, g1, g2, w(6)
      integer :: i, j
      g = m%shear
      xi(1:3) = sig(1:3) - sum(sig(1:3))/3.0_wp + 2.0_wp*g*(de(1:3) - sum(de(1:3))/3.0_wp)
      xi(4:6) = sig(4:6) + 2.0_wp*g*de(4:6)
      xi = xi - hv(2:7)
      w = [1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 2.0_wp, 2.0_wp]
      xn = sqrt(sum(w*xi**2))
      n = xi/xn
      yld = m%sigy + m%beta*m%ep*hv(1)
      a = 3.0_wp*g/(3.0_wp*g + m%ep)
      b = sqrt(6.0_wp)*g*yld/(3.0_wp*g + m%ep)
      g1 = 2.0_wp*g*((1.0_wp - a) + b/xn)
      g2 = 2.0_wp*g*b/xn
      call elastic_matrix(m%bulk, 0.5_wp*g1, d)
      do j = 1, 6
         do i = 1, 6
            d(i, j) = d(i, j) - g2*n(i)*n(j)*w(j)
         end do
      end do
      c3 = 6.0_wp*b*(2.0_wp*g)**3/xn**3
   end subroutine pk_consistent

   subroutine eos_checks()
      type(eos_linear_polynomial_t) :: q
      real(wp) :: mu, p, ref, e1, p1, c2
      q%c = [1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp, 7.0_wp]
      ! compression V = 0.8: mu = 0.25
      mu = 0.25_wp
      ref = 1.0_wp + 2.0_wp*mu + 3.0_wp*mu**2 + 4.0_wp*mu**3 + &
            (5.0_wp + 6.0_wp*mu + 7.0_wp*mu**2)*0.5_wp
      p = q%pressure(0.8_wp, 0.5_wp)
      call check_close(p, ref, 0.0_wp, 4.0_wp*epsilon(1.0_wp), 'EOS p at mu = 0.25 (= 5.21875)')
      call check_close(ref, 5.21875_wp, 0.0_wp, epsilon(1.0_wp), 'EOS hand value mu = 0.25')
      ! tension V = 1.25: mu = -0.2, the C2 and C6 terms vanish
      mu = -0.2_wp
      ref = 1.0_wp + 2.0_wp*mu + 4.0_wp*mu**3 + (5.0_wp + 6.0_wp*mu)*0.5_wp
      p = q%pressure(1.25_wp, 0.5_wp)
      call check_close(p, ref, 1.0e-15_wp, 4.0_wp*epsilon(1.0_wp), &
                       'EOS p at mu = -0.2 without C2, C6 (= 2.468)')
      ! time-centred energy update, exact for a linear EOS: E1 = E* - (p0 + p1)/2 dV
      call q%energy_update(0.8_wp, -0.2_wp, 0.5_wp, 1.0_wp, e1, p1)
      call check_close(e1, 0.5_wp - 0.5_wp*(1.0_wp + p1)*(-0.2_wp), 0.0_wp, &
                       8.0_wp*epsilon(1.0_wp), 'EOS energy update is time-centred')
      call check_close(p1, q%pressure(0.8_wp, e1), 0.0_wp, 8.0_wp*epsilon(1.0_wp), &
                       'EOS energy update: p1 = p(V1, E1)')
      ! sound speed of the linear fluid C1 = K at rest: c**2 = K/rho0
      q%c = 0.0_wp
      q%c(1) = 2.2e3_wp
      c2 = q%sound_speed2(1.0e-9_wp, 1.0_wp, 0.0_wp)
      call check_close(c2, 2.2e12_wp, 0.0_wp, 4.0_wp*epsilon(1.0_wp), 'EOS c**2 = C1/rho0')
   end subroutine eos_checks

   subroutine null_checks()
      type(mat_null_t) :: mn
      real(wp) :: s(1, 6), hh(1, 4), d(1, 6), rv(1), ei(1), k
      integer :: ie(1)
      k = 2.2e3_wp
      mn%ro = 1.0e-9_wp
      allocate(eos_linear_polynomial_t :: mn%eos)
      select type (q => mn%eos)
      type is (eos_linear_polynomial_t)
         q%c(1) = k
      end select
      call mn%setup(err)
      call check(.not. allocated(err), 'mat9 setup')
      s = 0.0_wp; hh = 0.0_wp; ie = 0
      d(1, :) = [-1.0_wp/300.0_wp, -1.0_wp/300.0_wp, -1.0_wp/300.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      rv = 0.99_wp; ei = 0.0_wp
      call mn%update(1, 1.0e-6_wp, d, rv, ei, s, hh, ie)
      call check_close(-s(1, 1), k*(1.0_wp/0.99_wp - 1.0_wp), 0.0_wp, 4.0_wp*epsilon(1.0_wp), &
                       'mat9 pressure = C1 mu')
      call check_close(s(1, 4), 0.0_wp, 0.0_wp, 0.0_wp, 'mat9 no shear stress (MU = 0)')
      call check_close(hh(1, 4), 0.5_wp*(-s(1, 1))*0.01_wp, 0.0_wp, 8.0_wp*epsilon(1.0_wp), &
                       'mat9 energy: p/2 dV from rest')
      mn%pc = -1.0_wp
      s = 0.0_wp; hh = 0.0_wp
      rv = 1.01_wp
      call mn%update(1, 1.0e-6_wp, -d, rv, ei, s, hh, ie)
      call check_close(-s(1, 1), -1.0_wp, 0.0_wp, 0.0_wp, 'mat9 tension cut off at PC')
      ! viscosity MU: s = 2 MU e' with e' the deviatoric strain rate deps'/dt (a shear and an
      ! isochoric stretch at V = 1, so p = 0): s_xy = 2 MU deps_xy/dt, s_xx = 2 MU deps'_xx/dt
      mn%pc = 0.0_wp; mn%mu = 1.0e-3_wp
      s = 0.0_wp; hh = 0.0_wp
      d(1, :) = [2.0e-4_wp, -1.0e-4_wp, -1.0e-4_wp, 3.0e-4_wp, 0.0_wp, 0.0_wp]
      rv = 1.0_wp
      call mn%update(1, 1.0e-6_wp, d, rv, ei, s, hh, ie)
      call check_close(s(1, 4), 2.0_wp*1.0e-3_wp*3.0e-4_wp/1.0e-6_wp, 0.0_wp, &
                       4.0_wp*epsilon(1.0_wp), 'mat9 viscous shear s_xy = 2 MU deps_xy/dt')
      call check_close(s(1, 1), 2.0_wp*1.0e-3_wp*2.0e-4_wp/1.0e-6_wp, 0.0_wp, &
                       4.0_wp*epsilon(1.0_wp), 'mat9 viscous deviator s_xx = 2 MU deps''_xx/dt')
      call check(ie(1) == 0, 'mat9 linear EOS: in range')
      ! compressed past the pole of a Gruneisen fit (S1 = 3: D = 1 - 2 mu = 0 at V = 2/3):
      ! the point is flagged (ierr 2: the run stops with exit 3 naming the element), not
      ! updated silently with the fit's pressure beyond the pole; just before it, in range
      deallocate(mn%eos)
      allocate(eos_gruneisen_t :: mn%eos)
      select type (q => mn%eos)
      type is (eos_gruneisen_t)
         q%rho0 = 1.0e-9_wp; q%c = 1.0e3_wp; q%s1 = 3.0_wp; q%gamma0 = 2.0_wp
      end select
      mn%mu = 0.0_wp
      s = 0.0_wp; hh = 0.0_wp; ie = 0
      d = 0.0_wp
      rv = 0.67_wp
      call mn%update(1, 1.0e-6_wp, d, rv, ei, s, hh, ie)
      call check(ie(1) == 0, 'mat9 Gruneisen S1 = 3 at V = 0.67 (before the pole 2/3): in range')
      rv = 0.66_wp
      call mn%update(1, 1.0e-6_wp, d, rv, ei, s, hh, ie)
      call check(ie(1) == 2, 'mat9 Gruneisen S1 = 3 at V = 0.66 (past the pole 2/3): flagged')
   end subroutine null_checks

   subroutine step(m, de, dt, sig, hv)
      class(material_t), intent(in) :: m
      real(wp), intent(in) :: de(6), dt
      real(wp), intent(inout) :: sig(1, 6), hv(1, 7)
      real(wp) :: d(1, 6), rv(1), ei(1)
      integer :: ierr(1)
      d(1, :) = de; rv = 1.0_wp; ei = 0.0_wp; ierr = 0
      call m%update(1, dt, d, rv, ei, sig, hv(:, 1:m%nhist()), ierr)
      if (ierr(1) /= 0) call check(.false., 'material reported an error')
   end subroutine step

   !> One step of axial strain increment de11 under uniaxial stress (lateral strains solved
   !> by the secant method so that sigma22 = sigma33 = 0). Returns sigma11; updates sig, hv.
   function uniaxial(m, de11, sig, hv) result(s11)
      class(material_t), intent(in) :: m
      real(wp), intent(in) :: de11
      real(wp), intent(inout) :: sig(1, 6), hv(1, 7)
      real(wp) :: s11, lat0, lat1, f0, f1, st(1, 6), ht(1, 7), lat2
      integer :: it
      lat0 = 0.0_wp
      st = sig; ht = hv
      call step(m, [de11, lat0, lat0, 0.0_wp, 0.0_wp, 0.0_wp], 1.0_wp, st, ht)
      f0 = st(1, 2)
      lat1 = -0.5_wp*de11
      do it = 1, 100
         st = sig; ht = hv
         call step(m, [de11, lat1, lat1, 0.0_wp, 0.0_wp, 0.0_wp], 1.0_wp, st, ht)
         f1 = st(1, 2)
         if (abs(f1) < 1.0e-12_wp*abs(st(1, 1)) .or. f1 == f0) exit
         lat2 = lat1 - f1*(lat1 - lat0)/(f1 - f0)
         lat0 = lat1; f0 = f1; lat1 = lat2
      end do
      sig = st; hv = ht
      s11 = st(1, 1)
   end function uniaxial
   !> *EOS_GRUNEISEN. With S2 = S3 = 0 and a = 0 the compressed branch is built on the Hugoniot
   !> of Us = C + S1 up: at eta = 1 - V = up/Us and E = p_H eta/2 (the Rankine-Hugoniot
   !> energy per reference volume), p = p_H = rho0 Us up for any gamma0. Copper (Steinberg
   !> UCRL-MA-106439: rho0 8.93 g/cm3, C 3.94 km/s, S1 1.489, gamma0 2.02; units g/cm3, km/s,
   !> GPa): up from 0.1 to 3 km/s; the tolerance is round-off (a few ulps of ~20 operations).
   subroutine gruneisen_checks()
      type(eos_gruneisen_t) :: g
      real(wp) :: up, us, eta, ph, eh, p, dpdmu, dpde, pp, pm, mu, v, hh, e1, p1
      real(wp), parameter :: ups(4) = [0.1_wp, 0.5_wp, 1.0_wp, 3.0_wp], mus(2) = [0.15_wp, -0.1_wp]
      integer :: i
      g%rho0 = 8.93_wp; g%c = 3.94_wp; g%s1 = 1.489_wp; g%gamma0 = 2.02_wp
      do i = 1, 4
         up = ups(i)
         us = g%c + g%s1*up
         eta = up/us
         ph = g%rho0*us*up
         eh = 0.5_wp*ph*eta
         p = g%pressure(1.0_wp - eta, eh)
         call check_close(p, ph, 0.0_wp, 64.0_wp*epsilon(1.0_wp), &
                          'Gruneisen p on the Hugoniot = rho0 Us up, up = '//trim(num(up)))
      end do
      ! the cold curve (E = 0) is the Hugoniot only when gamma0 = 0
      g%gamma0 = 0.0_wp
      up = 1.0_wp; us = g%c + g%s1*up; eta = up/us
      call check_close(g%pressure(1.0_wp - eta, 0.0_wp), g%rho0*us*up, 0.0_wp, &
                       64.0_wp*epsilon(1.0_wp), 'Gruneisen gamma0 = 0: p(V_H, 0) = rho0 Us up')
      ! dp/dmu and dp/dE against central differences, all terms on (S2, S3, a, E)
      g%gamma0 = 2.02_wp; g%s2 = 0.3_wp; g%s3 = -0.2_wp; g%a = 0.47_wp
      do i = 1, 2
         mu = mus(i)
         v = 1.0_wp/(1.0_wp + mu)
         hh = 1.0e-5_wp
         call g%state(v, 0.8_wp, p, dpdmu, dpde)
         pp = g%pressure(1.0_wp/(1.0_wp + mu + hh), 0.8_wp)
         pm = g%pressure(1.0_wp/(1.0_wp + mu - hh), 0.8_wp)
         call check_close(dpdmu, (pp - pm)/(2.0_wp*hh), 0.0_wp, 1.0e-8_wp, &
                          'Gruneisen dp/dmu = central difference, mu = '//trim(num(mu)))
         pp = g%pressure(v, 0.8_wp + hh)
         pm = g%pressure(v, 0.8_wp - hh)
         call check_close(dpde, (pp - pm)/(2.0_wp*hh), 0.0_wp, 1.0e-8_wp, &
                          'Gruneisen dp/dE = central difference, mu = '//trim(num(mu)))
      end do
      ! the branches meet at mu = 0 with the same p and slope rho0 C**2 + a E
      call g%state(1.0_wp/(1.0_wp + 1.0e-12_wp), 0.8_wp, p, dpdmu, dpde)
      call check_close(dpdmu, g%rho0*g%c**2 + g%a*0.8_wp, 0.0_wp, 1.0e-10_wp, &
                       'Gruneisen slope at mu = 0+ = rho0 C**2 + a E')
      call g%state(1.0_wp/(1.0_wp - 1.0e-12_wp), 0.8_wp, pp, dpdmu, dpde)
      call check_close(dpdmu, g%rho0*g%c**2 + g%a*0.8_wp, 0.0_wp, 1.0e-10_wp, &
                       'Gruneisen slope at mu = 0- = rho0 C**2 + a E')
      call check_close(p, pp, 1.0e-9_wp, 0.0_wp, 'Gruneisen p continuous at mu = 0')
      ! p is linear in E: the time-centred energy update is exact
      call g%energy_update(0.9_wp, -0.05_wp, 0.3_wp, 1.0_wp, e1, p1)
      call check_close(e1, 0.3_wp - 0.5_wp*(1.0_wp + p1)*(-0.05_wp), 0.0_wp, &
                       16.0_wp*epsilon(1.0_wp), 'Gruneisen energy update is time-centred')
   end subroutine gruneisen_checks

   function num(x) result(s)
      real(wp), intent(in) :: x
      character(24) :: s
      write(s, '(g0.3)') x
   end function num
end program test_materials
