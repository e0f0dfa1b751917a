!> Material-point driver for one plane-stress lamina (material_t%update_plane_stress): strain
!> increment histories, mixed control (uniaxial stress by a secant iteration on the lateral strain),
!> and the single-increment accuracy maps of Krieg & Krieg (1977, J. Pressure Vessel Technol.
!> 99:510-515) and Schreyer, Kulak & Kramer (1979, J. Pressure Vessel Technol. 101:226-234): from
!> a state on the yield surface, one increment of direction theta in the plane of principal
!> strains (de1, de2) = size (cos theta, sin theta), gamma12 = 0, by each algorithm; the error is
!> the von Mises norm of the stress difference to the converged return (PS_FULL) over the
!> initial yield stress.
module dx_lamina
   use dx_kinds, only: wp
   use dx_material, only: material_t
   use dx_plane_stress, only: PS_FULL
   implicit none
   private
   public :: lamina_step, lamina_uniaxial, lamina_vm, lamina_map_point

contains

   !> One update of a single lamina by algorithm alg (restores m%ps_alg).
   subroutine lamina_step(m, alg, dt, de, sig, hv, ierr)
      class(material_t), intent(inout) :: m
      integer, intent(in) :: alg
      real(wp), intent(in) :: dt, de(5)
      real(wp), intent(inout) :: sig(5), hv(:)
      integer, intent(out) :: ierr
      real(wp) :: d1(1, 5), s1(1, 5), h1(1, max(1, size(hv)))
      integer :: ie(1), keep
      keep = m%ps_alg
      m%ps_alg = alg
      d1(1, :) = de
      s1(1, :) = sig
      h1 = 0.0_wp
      h1(1, 1:size(hv)) = hv
      ie = 0
      call m%update_plane_stress(1, dt, d1, s1, h1, ie)
      sig = s1(1, :)
      hv = h1(1, 1:size(hv))
      ierr = ie(1)
      m%ps_alg = keep
   end subroutine lamina_step

   !> One uniaxial-stress increment de11 in x (sigma_yy = sigma_xy = 0): the lateral strain
   !> increment by secant iteration to |sigma_yy| <= 1e-13 |sigma_xx|. Returns sigma_xx.
   function lamina_uniaxial(m, alg, dt, de11, sig, hv) result(sxx)
      class(material_t), intent(inout) :: m
      integer, intent(in) :: alg
      real(wp), intent(in) :: dt, de11
      real(wp), intent(inout) :: sig(5), hv(:)
      real(wp) :: sxx
      real(wp) :: st(5), ht(size(hv)), l0, l1, l2, f0, f1
      integer :: it, ierr
      st = sig; ht = hv
      l0 = -0.3_wp*de11
      call lamina_step(m, alg, dt, [de11, l0, 0.0_wp, 0.0_wp, 0.0_wp], st, ht, ierr)
      f0 = st(2)
      l1 = -0.5_wp*de11
      do it = 1, 100
         st = sig; ht = hv
         call lamina_step(m, alg, dt, [de11, l1, 0.0_wp, 0.0_wp, 0.0_wp], st, ht, ierr)
         f1 = st(2)
         if (abs(f1) <= 1.0e-13_wp*abs(st(1)) .or. f1 == f0) exit
         l2 = l1 - f1*(l1 - l0)/(f1 - f0)
         l0 = l1; f0 = f1; l1 = l2
      end do
      sig = st; hv = ht
      sxx = st(1)
   end function lamina_uniaxial

   !> von Mises norm of an in-plane stress (xx, yy, xy)
   pure real(wp) function lamina_vm(s)
      real(wp), intent(in) :: s(3)
      lamina_vm = sqrt(max(0.0_wp, s(1)**2 + s(2)**2 - s(1)*s(2) + 3.0_wp*s(3)**2))
   end function lamina_vm

   !> Error of algorithm alg against PS_FULL for one increment de from (sig0, hv0): the von Mises
   !> norm of the stress difference over sy; also the effective plastic strain difference
   !> (absolute) in dep_err.
   subroutine lamina_map_point(m, alg, sig0, hv0, de, sy, err, dep_err)
      class(material_t), intent(inout) :: m
      integer, intent(in) :: alg
      real(wp), intent(in) :: sig0(5), hv0(:), de(5), sy
      real(wp), intent(out) :: err, dep_err
      real(wp) :: sa(5), sr(5), ha(size(hv0)), hr(size(hv0))
      integer :: ierr
      sa = sig0; ha = hv0
      call lamina_step(m, alg, 0.0_wp, de, sa, ha, ierr)
      sr = sig0; hr = hv0
      call lamina_step(m, PS_FULL, 0.0_wp, de, sr, hr, ierr)
      err = lamina_vm(sa(1:3) - sr(1:3))/sy
      dep_err = abs(ha(1) - hr(1))
   end subroutine lamina_map_point
end module dx_lamina
