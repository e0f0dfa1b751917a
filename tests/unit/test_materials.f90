!> Unit tests of the material models against closed-form answers
!> (physics-references.md section 3.1: uniaxial stress, E = 200 GPa, sigma_y = 250 MPa,
!> Et = 2 GPa: sigma(0.01) = 267.5 MPa in one step, within 1e-10 relative).
program test_materials
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_material, only: material_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_curve, only: curve_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: el
   type(mat_plastic_kinematic_t) :: pk
   type(mat_piecewise_linear_t) :: pl
   type(error_t), allocatable :: err
   type(curve_t) :: curves(1)
   real(wp) :: sig(1, 6), hv(1, 7), s, r, g
   real(wp), parameter :: e = 200.0e3_wp, sy = 250.0_wp, et = 2000.0_wp   ! MPa

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
   call assert_summary()

contains

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
end program test_materials
