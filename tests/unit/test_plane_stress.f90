!> Unit tests of the plane-stress (lamina) update material_t%update_plane_stress against
!> closed-form plane-stress elasticity (sigma33 = 0): uniaxial stress sigma_xx = E e with the
!> lateral strain -nu e giving sigma_yy = 0; biaxial strain sigma = E/(1 - nu**2) (e_xx + nu e_yy);
!> engineering shears sigma = G gamma. Models without a plane-stress form flag
!> MAT_ERR_NO_PLANE_STRESS and leave the stress unchanged.
program test_plane_stress
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_material, only: MAT_ERR_NO_PLANE_STRESS
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_null, only: mat_null_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: el
   type(mat_null_t) :: nu_mat
   type(error_t), allocatable :: err
   real(wp), parameter :: e = 200.0e3_wp, pr = 0.3_wp, eps = 1.0e-3_wp   ! MPa
   real(wp) :: deps(2, 5), sig(2, 5), hv(2, 1), g, q
   integer :: ierr(2)

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
   call assert_summary()
end program test_plane_stress
