!> Unit tests of the plane-stress (lamina) update material_t%update_plane_stress against
!> closed-form plane-stress elasticity (sigma33 = 0): uniaxial stress sigma_xx = E e with the
!> lateral strain -nu e giving sigma_yy = 0; biaxial strain sigma = E/(1 - nu**2) (e_xx + nu e_yy);
!> engineering shears sigma = G gamma. Models without a plane-stress form flag
!> MAT_ERR_NO_PLANE_STRESS and leave the stress unchanged.
program test_plane_stress
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_material, only: MAT_ERR_NO_PLANE_STRESS, MAT_ERR_PS_ALG
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_null, only: mat_null_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_curve, only: curve_t
   use dx_plane_stress, only: PS_SECANT3, PS_FULL, PS_RADIAL, PS_ONE_STEP, ps_full_lambda
   use dx_lamina, only: lamina_step, lamina_uniaxial, lamina_vm, lamina_map_point
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: el
   type(mat_null_t) :: nu_mat
   type(error_t), allocatable :: err
   real(wp), parameter :: e = 200.0e3_wp, pr = 0.3_wp, eps = 1.0e-3_wp   ! MPa
   real(wp) :: deps(2, 5), sig(2, 5), hv(2, 1), g, q
   integer :: ierr(2)
   ! error bounds against the full return, single increments of size <= 1e-4 from a yield state
   ! (docs/studies/lamina.md: largest map values 7.6e-4 one-step, 9.8e-9 secant, 1.3e-2 radial,
   ! in sigma_y), and relative bounds of the 100-step uniaxial paths (index: algorithm)
   real(wp), parameter :: bound_a = 1.5e-3_wp, bound_b = 2.0e-8_wp, bound_c = 2.0e-2_wp
   real(wp), parameter :: bound_path(4) = [1.0e-4_wp, 1.0e-12_wp, 3.0e-2_wp, 2.0e-3_wp]

   el%ro = 7.8e-9_wp; el%e = e; el%pr = pr
   call el%setup(err)
   call check(.not. allocated(err), 'elastic setup')
   g = e/(2.0_wp*(1.0_wp + pr))
   q = e/(1.0_wp - pr**2)

   ! point 1: uniaxial stress (e, -nu e); point 2: biaxial strain and all three shears
   deps = 0.0_wp
   deps(1, 1:2) = [eps, -pr*eps]
   deps(2, :) = [eps, 0.5_wp*eps, 2.0e-3_wp, -1.0e-3_wp, 4.0e-4_wp]
   sig = 0.0_wp; hv = 0.0_wp; ierr = 0
   call el%update_plane_stress(2, 1.0e-6_wp, deps, sig, hv, ierr)
   call check(all(ierr == 0), 'elastic lamina: no error')
   ! the elastic constants pass through K and G: a few ulps of E e
   call check_close(sig(1, 1), e*eps, 0.0_wp, 1.0e-14_wp, 'uniaxial stress: sigma_xx = E e')
   call check_close(sig(1, 2), 0.0_wp, 8.0_wp*epsilon(1.0_wp)*e*eps, 0.0_wp, &
                    'uniaxial stress: lateral strain -nu e gives sigma_yy = 0')
   call check(all(sig(1, 3:5) == 0.0_wp), 'uniaxial stress: no shear')
   call check_close(sig(2, 1), q*(eps + pr*0.5_wp*eps), 0.0_wp, 1.0e-14_wp, &
                    'biaxial: sigma_xx = E/(1-nu^2)(e_xx + nu e_yy)')
   call check_close(sig(2, 2), q*(0.5_wp*eps + pr*eps), 0.0_wp, 1.0e-14_wp, &
                    'biaxial: sigma_yy = E/(1-nu^2)(e_yy + nu e_xx)')
   call check_close(sig(2, 3), g*2.0e-3_wp, 0.0_wp, 1.0e-14_wp, 'in-plane shear G gamma_xy')
   call check_close(sig(2, 4), -g*1.0e-3_wp, 0.0_wp, 1.0e-14_wp, 'transverse shear G gamma_yz')
   call check_close(sig(2, 5), g*4.0e-4_wp, 0.0_wp, 1.0e-14_wp, 'transverse shear G gamma_zx')
   ! incremental: a second step from the first adds the same increment (hypoelastic)
   call el%update_plane_stress(2, 1.0e-6_wp, deps, sig, hv, ierr)
   call check_close(sig(1, 1), 2.0_wp*e*eps, 0.0_wp, 1.0e-14_wp, 'two uniaxial steps add')

   ! a hydrodynamic model (equation of state) has no plane-stress form
   sig = 1.0_wp; ierr = 0
   call nu_mat%update_plane_stress(2, 1.0e-6_wp, deps, sig, hv, ierr)
   call check(all(ierr == MAT_ERR_NO_PLANE_STRESS), '*MAT_NULL: no plane-stress form flagged')
   call check(all(sig == 1.0_wp), '*MAT_NULL: stress left unchanged')
   call plastic_checks()
   call assert_summary()
contains

   !> sbar(sigma - alpha) - Y of a *MAT_003 lamina state (linear hardening, no rate)
   real(wp) function yield_gap(m, sig, hv) result(f)
      type(mat_plastic_kinematic_t), intent(in) :: m
      real(wp), intent(in) :: sig(5), hv(7)
      f = lamina_vm(sig(1:3) - [hv(2), hv(3), hv(5)]) - (m%sigy + m%beta*m%ep*hv(1))
   end function yield_gap

   subroutine plastic_checks()
      type(mat_plastic_kinematic_t) :: pk
      type(mat_piecewise_linear_t) :: pl
      type(curve_t) :: curves(1)
      real(wp) :: s0(5), h0(7), s1(5), h1(7), de(5), sz, th, gmax, f, emax(4), ep, sxx, dz(1)
      real(wp) :: d1(1, 5), sg(1, 5), hh(1, 7), res(30), lam, aa, bb, a1, a2, sb
      integer :: alg, k, j, ie, nit, kk
      real(wp), parameter :: sy = 250.0_wp, et = 2000.0_wp
      pk%ro = 7.8e-9_wp; pk%e = e; pk%pr = pr; pk%sigy = sy; pk%etan = et; pk%beta = 0.5_wp
      call pk%setup(err)
      call check(.not. allocated(err), 'mat3 setup (beta = 0.5)')

      ! ---- (a) one-step: on the yield surface to round-off for linear hardening, from a
      ! prestrained mixed-hardening state, 36 directions (with shear) x 9 sizes 1e-6..1e-2
      s0 = 0.0_wp; h0 = 0.0_wp
      sxx = lamina_uniaxial(pk, PS_FULL, 0.0_wp, 0.004_wp, s0, h0)
      gmax = 0.0_wp
      do k = 0, 35
         th = 10.0_wp*k*acos(-1.0_wp)/180.0_wp
         do j = 0, 8
            sz = 10.0_wp**(-6.0_wp + 0.5_wp*j)
            de = sz*[cos(th), sin(th), 0.7_wp*sin(2.0_wp*th), 0.0_wp, 0.0_wp]
            s1 = s0; h1 = h0
            call lamina_step(pk, PS_ONE_STEP, 0.0_wp, de, s1, h1, ie)
            if (h1(1) > h0(1)) gmax = max(gmax, abs(yield_gap(pk, s1, h1))/sy)
         end do
      end do
      ! about 70 floating-point operations from the state to the stress and the check's own
      ! radius, each within half an ulp of quantities <= 2 sigma_y: bound 70 eps (1.6e-14)
      call check_close(gmax, 0.0_wp, 70.0_wp*epsilon(1.0_wp), 0.0_wp, &
                       'one-step: max |f|/sigma_y over 324 plastic increments')

      ! ---- (d) full iteration: quadratic convergence of the Newton iteration (residual history
      ! of a 1e-2 increment mixing sum and difference modes)
      aa = 0.25_wp*(900.0_wp)**2; bb = 0.75_wp*(1500.0_wp)**2 + 3.0_wp*(400.0_wp)**2
      a1 = e/(2.0_wp*(1.0_wp - pr)) + 1000.0_wp; a2 = 3.0_wp*g + 1000.0_wp
      lam = ps_full_lambda(aa, bb, a1, a2, sy, 1000.0_wp, 0.0_wp, nit, res=res)
      call check(lam > 0.0_wp .and. nit <= 8, 'full return converges in <= 8 Newton steps, took '// &
                 achar(48 + min(nit, 9)))
      kk = 0
      do k = 1, nit
         if (res(k) < 1.0e-3_wp .and. res(k + 1) > 1.0e-14_wp) then
            kk = kk + 1
            call check(res(k + 1) <= 10.0_wp*res(k)**2, 'full return: quadratic step')
         end if
      end do
      call check(kk >= 1, 'full return: at least one asymptotic step observed')
      call check(res(nit + 1) <= 4.0_wp*epsilon(1.0_wp), 'full return: residual <= 4 eps')
      ! closed forms without hardening: pure shear lam = (sbar*/y - 1)/a2, equibiaxial /a1
      sb = sqrt(3.0_wp)*600.0_wp
      lam = ps_full_lambda(0.0_wp, sb**2, a1, a2, sy, 0.0_wp, 0.0_wp, nit)
      call check_close(lam, (sb/sy - 1.0_wp)/a2, 0.0_wp, 1.0e-14_wp, 'full return: pure shear')
      lam = ps_full_lambda(sb**2, 0.0_wp, a1, a2, sy, 0.0_wp, 0.0_wp, nit)
      call check_close(lam, (sb/sy - 1.0_wp)/a1, 0.0_wp, 1.0e-14_wp, 'full return: equibiaxial')

      ! ---- (a), (b), (c) against (d): largest error over the map directions at sizes up to
      ! 1e-4 (explicit steps; docs/studies/lamina.md); from the uniaxial yield state
      emax = 0.0_wp
      do alg = 1, 4
         do k = 0, 71
            th = 5.0_wp*k*acos(-1.0_wp)/180.0_wp
            do j = 0, 4
               sz = 10.0_wp**(-6.0_wp + 0.5_wp*j)
               de = sz*[cos(th), sin(th), 0.0_wp, 0.0_wp, 0.0_wp]
               call lamina_map_point(pk, alg, s0, h0, de, sy, f, ep)
               emax(alg) = max(emax(alg), f)
            end do
         end do
      end do
      print '(a,4es10.2)', '  max error against (d), sizes <= 1e-4, algs 1..4:', emax
      call check(emax(PS_SECANT3) <= bound_b, 'secant3 error <= bound')
      call check(emax(PS_RADIAL) <= bound_c, 'radial error <= bound')
      call check(emax(PS_ONE_STEP) <= bound_a, 'one-step error <= bound')
      call check(emax(PS_FULL) == 0.0_wp, 'full against itself')

      ! ---- elastic unloading from the plastic state is the trial stress, bitwise
      do alg = 1, 4
         s1 = s0; h1 = h0
         de = [-2.0e-4_wp, 0.6e-4_wp, 1.0e-4_wp, 3.0e-5_wp, -1.0e-5_wp]
         call lamina_step(pk, alg, 0.0_wp, de, s1, h1, ie)
         call check(s1(1) == s0(1) + e*pr/(1.0_wp - pr**2)*(de(1) + de(2)) + 2.0_wp*g*de(1) .and. &
                    s1(2) == s0(2) + e*pr/(1.0_wp - pr**2)*(de(1) + de(2)) + 2.0_wp*g*de(2) .and. &
                    s1(3) == s0(3) + g*de(3) .and. all(h1 == h0), &
                    'elastic unloading exact, algorithm '//achar(48 + alg))
      end do

      ! ---- uniaxial stress, closed form (physics-references 3.1): E = 200 GPa, sigma_y = 250,
      ! Et = 2 GPa: 0.01 in one step gives 267.5; back to 0: isotropic (BETA = 1) -282.15,
      ! kinematic (BETA = 0) -247.5 (reverse yield at 267.5 - 2*250 + ...)
      do j = 0, 1
         pk%beta = real(j, wp)
         call pk%setup(err)
         s1 = 0.0_wp; h1 = 0.0_wp
         sxx = lamina_uniaxial(pk, PS_FULL, 0.0_wp, 0.01_wp, s1, h1)
         call check_close(sxx, 267.5_wp, 0.0_wp, 1.0e-12_wp, 'lamina uniaxial 0.01, beta '//achar(48 + j))
         sxx = lamina_uniaxial(pk, PS_FULL, 0.0_wp, -0.01_wp, s1, h1)
         call check_close(sxx, merge(-282.15_wp, -247.5_wp, j == 1), 0.0_wp, 1.0e-12_wp, &
                          'lamina uniaxial reversed to 0, beta '//achar(48 + j))
         if (j == 0) call check_close(h1(1), (0.01_wp - 267.5_wp/e) + (0.0075_wp - 15.0_wp/e), &
                                      0.0_wp, 1.0e-12_wp, 'lamina beta 0: plastic strain over both branches')
         ! all algorithms in 100 steps of 1e-4 against the closed form
         do alg = 1, 4
            s1 = 0.0_wp; h1 = 0.0_wp
            do k = 1, 100
               sxx = lamina_uniaxial(pk, alg, 0.0_wp, 1.0e-4_wp, s1, h1)
            end do
            call check_close(sxx, 267.5_wp, 0.0_wp, bound_path(alg), 'lamina uniaxial 100 steps, beta '// &
                             achar(48 + j)//', algorithm '//achar(48 + alg))
         end do
      end do
      ! thickness strain of the one-step uniaxial 0.01 (beta = 1): -nu sigma/E - eps_p/2
      pk%beta = 1.0_wp
      call pk%setup(err)
      s1 = 0.0_wp; h1 = 0.0_wp
      sxx = lamina_uniaxial(pk, PS_FULL, 0.0_wp, 0.01_wp, s1, h1)
      d1(1, :) = [0.01_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      s1 = 0.0_wp; h1 = 0.0_wp
      ! the lateral strain that made sigma_yy = 0 is not returned: recover it from eps_p
      d1(1, 2) = -pr*267.5_wp/e - 0.5_wp*(0.01_wp - 267.5_wp/e)
      sg = 0.0_wp; hh = 0.0_wp; ierr = 0
      pk%ps_alg = PS_FULL
      call pk%update_plane_stress(1, 0.0_wp, d1, sg, hh, ierr(1:1), dezz=dz)
      call check_close(sg(1, 2), 0.0_wp, 1.0e-10_wp, 0.0_wp, 'uniaxial lateral strain: sigma_yy = 0')
      call check_close(dz(1), d1(1, 2), 0.0_wp, 1.0e-12_wp, &
                       'uniaxial thickness strain = lateral strain (-nu sigma/E - eps_p/2)')

      ! ---- Cowper-Symonds (SRC = 40/s, SRP = 5): after a plastic step the radius is
      ! R (SIGY + BETA Ep eps_p) with R = 1 + (rate/C)**(1/P), rate = ps_rate of the increment
      pk%src = 40.0_wp; pk%srp = 5.0_wp; pk%beta = 0.5_wp
      call pk%setup(err)
      do alg = 1, 4
         s1 = 0.0_wp; h1 = 0.0_wp
         s1(1) = sy
         de = [1.0e-3_wp, -4.0e-4_wp, 2.0e-4_wp, 0.0_wp, 0.0_wp]
         call lamina_step(pk, alg, 0.5_wp, de, s1, h1, ie)
         f = 1.0_wp + (sqrt((4.0_wp/3.0_wp)*(de(1)**2 + de(2)**2 + de(1)*de(2)) + de(3)**2/3.0_wp)/ &
                       0.5_wp/40.0_wp)**0.2_wp
         call check(h1(1) > 0.0_wp, 'Cowper-Symonds step is plastic, algorithm '//achar(48 + alg))
         call check_close(lamina_vm(s1(1:3) - [h1(2), h1(3), h1(5)]), f*(sy + 0.5_wp*pk%ep*h1(1)), &
                          0.0_wp, merge(1.0e-3_wp, 1.0e-13_wp, alg == PS_SECANT3), &
                          'Cowper-Symonds radius R (SIGY + BETA Ep eps_p), algorithm '//achar(48 + alg))
      end do
      pk%src = 0.0_wp; pk%srp = 0.0_wp
      call pk%setup(err)
      ! an algorithm number outside 1..5 is flagged
      pk%ps_alg = 7
      d1(1, :) = 1.0e-3_wp; sg = 0.0_wp; hh = 0.0_wp; ierr = 0
      call pk%update_plane_stress(1, 0.0_wp, d1, sg, hh, ierr(1:1))
      call check(ierr(1) == MAT_ERR_PS_ALG, 'ps_alg 7 gives MAT_ERR_PS_ALG')
      pk%ps_alg = PS_SECANT3

      ! ---- *MAT_024: bilinear and a curve crossing a breakpoint (the 3-D test's values)
      pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = pr; pl%sigy = sy; pl%etan = et
      call pl%resolve_curves(curves(1:0), err)
      call pl%setup(err)
      s1 = 0.0_wp; hh = 0.0_wp
      sxx = lamina_uniaxial(pl, PS_FULL, 0.0_wp, 0.01_wp, s1, hh(1, 1:2))
      call check_close(sxx, 267.5_wp, 0.0_wp, 1.0e-12_wp, 'mat24 lamina bilinear uniaxial 0.01')
      pl = mat_piecewise_linear_t()
      pl%ro = 7.8e-9_wp; pl%e = e; pl%pr = pr
      curves(1)%label = 7
      curves(1)%x = [0.0_wp, 0.02_wp, 0.2_wp]
      curves(1)%y = [250.0_wp, 290.0_wp, 380.0_wp]
      pl%lcss = 7
      call pl%resolve_curves(curves, err)
      call pl%setup(err)
      s1 = 0.0_wp; hh = 0.0_wp
      sxx = lamina_uniaxial(pl, PS_FULL, 0.0_wp, 0.1_wp, s1, hh(1, 1:2))
      call check_close(sxx, 330.0_wp/1.0025_wp, 0.0_wp, 1.0e-12_wp, &
                       'mat24 lamina curve, one step crossing a breakpoint')
      ! all algorithms in 100 steps of 1e-3 (the breakpoint inside a step)
      do alg = 1, 4
         s1 = 0.0_wp; hh = 0.0_wp
         do k = 1, 100
            sxx = lamina_uniaxial(pl, alg, 0.0_wp, 1.0e-3_wp, s1, hh(1, 1:2))
         end do
         call check_close(sxx, 330.0_wp/1.0025_wp, 0.0_wp, bound_path(alg), &
                          'mat24 lamina curve, 100 steps of 1e-3, algorithm '//achar(48 + alg))
      end do
      ! VP = 1 (viscoplastic) has no plane-stress form yet
      pl%vp = 1.0_wp; pl%c = 40.0_wp; pl%p = 5.0_wp
      d1(1, :) = 1.0e-3_wp; sg = 0.0_wp; hh = 0.0_wp; ierr = 0
      call pl%update_plane_stress(1, 1.0e-6_wp, d1, sg, hh(:, 1:2), ierr(1:1))
      call check(ierr(1) == MAT_ERR_NO_PLANE_STRESS, '*MAT_024 VP = 1: no plane-stress form flagged')
   end subroutine plastic_checks
end program test_plane_stress
