!> The steps of the one-point solid pass that the hexahedron (dx_hex8, ELFORM 1; gather and
!> Jaumann rotation also ELFORM 2) and the tetrahedron (dx_tet4) share, per block of at most
!> nv_chunk elements with nen nodes each, work arrays (nv_chunk, nen) as the kernels hold them:
!> gather of x(n), v(n-1/2) and the mid-step geometry x(n-1/2) = x(n) - dt/2 v(n-1/2); the
!> strain increment and spin from L V = v_iI B_jI at mid-step; the Jaumann rotation (first
!> order), material update, failure and erosion of the one point; the DYNA bulk viscosity
!> and the old/new stress work rates of the centred work; the internal force
!> f_iI = (sig_ij - q delta_ij) B_jI and its scatter. Formulation and references: dx_hex8's
!> header (Flanagan & Belytschko 1981, IJNME 17:679-706; LS-DYNA Theory Manual, bulk
!> viscosity) and dx_tet4's. Each loop is the kernels' own (same operations in the same order:
!> the same bits); loops run over the elements of the block (unit stride), so they vectorize.
module dx_solid_point
   use dx_kinds, only: wp, nv_chunk
   use dx_material, only: material_t
   use dx_erosion, only: erosion_one_point, erosion_now
   use dx_element_types, only: elem_block_t, part_t, ELEM_ERR_NEGVOL
   implicit none
   private
   public :: gather_mid, strain_increments, volumes_now, jaumann, point_stress, erode_failed, &
             bulk_viscosity, work_rates, stress_forces, scatter_forces

   !> An element whose volume falls to eps*V0 or below is collapsed (dx_hex8's vcrush).
   real(wp), parameter :: vcrush = epsilon(1.0_wp)

contains

   !> Nodal coordinates x(n) and velocities v(n-1/2) of the block's nen-node elements, and the
   !> mid-step coordinates x - hdt v (hdt = dt/2); arrays (nv, nen).
   subroutine gather_mid(blk, n, nv, nen, x, v, hdt, xe, ye, ze, vx, vy, vz, xm, ym, zm)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: n, nv, nen
      real(wp), intent(in) :: x(:, :), v(:, :), hdt
      real(wp), dimension(nv, nen), intent(out) :: xe, ye, ze, vx, vy, vz, xm, ym, zm
      integer :: i, k, nn
      do k = 1, nen
         do i = 1, n
            nn = blk%conn(k, i)
            xe(i, k) = x(1, nn); ye(i, k) = x(2, nn); ze(i, k) = x(3, nn)
            vx(i, k) = v(1, nn); vy(i, k) = v(2, nn); vz(i, k) = v(3, nn)
            xm(i, k) = xe(i, k) - hdt*vx(i, k)
            ym(i, k) = ye(i, k) - hdt*vy(i, k)
            zm(i, k) = ze(i, k) - hdt*vz(i, k)
         end do
      end do
   end subroutine gather_mid

   !> From lg = L V (columns xx yy zz xy yx yz zy zx xz) at the mid-step volume volm: the strain
   !> increment de6 (Voigt, tensor shears) and its copy deps (nel, 6) for the material, the
   !> spin increments w12, w23, w31, tr D = trd; alive = 0 for eroded elements; ierr = 0, or
   !> ELEM_ERR_NEGVOL where volm <= eps V0 (volm then set to 1).
   subroutine strain_increments(blk, n, dt_old, lg, volm, ierr, alive, de6, deps, w12, w23, &
                                w31, trd)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: n
      real(wp), intent(in) :: dt_old, lg(nv_chunk, 9)
      real(wp), intent(inout) :: volm(nv_chunk)
      integer, intent(out) :: ierr(nv_chunk)
      real(wp), dimension(nv_chunk), intent(out) :: alive, w12, w23, w31, trd
      real(wp), intent(out) :: de6(nv_chunk, 6), deps(:, :)
      real(wp) :: dtl
      integer :: i, k
      do i = 1, n
         ierr(i) = 0
         if (.not. (volm(i) > vcrush*blk%vol0(i))) ierr(i) = ELEM_ERR_NEGVOL
         if (.not. (volm(i) > vcrush*blk%vol0(i))) volm(i) = 1.0_wp
         alive(i) = merge(0.0_wp, 1.0_wp, blk%failed(i))
         dtl = dt_old/volm(i)
         de6(i, 1) = lg(i, 1)*dtl
         de6(i, 2) = lg(i, 2)*dtl
         de6(i, 3) = lg(i, 3)*dtl
         de6(i, 4) = 0.5_wp*(lg(i, 4) + lg(i, 5))*dtl
         de6(i, 5) = 0.5_wp*(lg(i, 6) + lg(i, 7))*dtl
         de6(i, 6) = 0.5_wp*(lg(i, 8) + lg(i, 9))*dtl
         w12(i) = 0.5_wp*(lg(i, 4) - lg(i, 5))*dtl
         w23(i) = 0.5_wp*(lg(i, 6) - lg(i, 7))*dtl
         w31(i) = 0.5_wp*(lg(i, 8) - lg(i, 9))*dtl
         trd(i) = (lg(i, 1) + lg(i, 2) + lg(i, 3))/volm(i)
      end do
      do k = 1, 6
         deps(1:n, k) = de6(1:n, k)
      end do
   end subroutine strain_increments

   !> The volumes at t(n): vold = V(n-1) (from relvol), vol = V(n) (set to 1 with ierr =
   !> ELEM_ERR_NEGVOL where it is at most eps V0), the relative volume rv (kept in relvol) and
   !> the internal energy per initial volume ein.
   subroutine volumes_now(blk, n, vol, vold, rv, ein, ierr)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: n
      real(wp), intent(inout) :: vol(nv_chunk)
      real(wp), dimension(nv_chunk), intent(out) :: vold, rv, ein
      integer, intent(inout) :: ierr(nv_chunk)
      integer :: i
      do i = 1, n
         vold(i) = blk%vol0(i)*blk%relvol(i)
         if (.not. (vol(i) > vcrush*blk%vol0(i))) ierr(i) = ELEM_ERR_NEGVOL
         if (.not. (vol(i) > vcrush*blk%vol0(i))) vol(i) = 1.0_wp
         rv(i) = vol(i)/blk%vol0(i)
         blk%relvol(i) = rv(i)
         ein(i) = blk%eint(i)/blk%vol0(i)
      end do
   end subroutine volumes_now

   !> Jaumann rotation of stress (Voigt) by the spin increment (w12, w23, w31) = W*dt.
   pure subroutine jaumann(n, nv, w12, w23, w31, s)
      integer, intent(in) :: n, nv
      real(wp), intent(in) :: w12(nv), w23(nv), w31(nv)
      real(wp), intent(inout) :: s(nv, 6)
      real(wp) :: d1, d2, d3, d4, d5, d6
      integer :: i
      do i = 1, n
         d1 = 2.0_wp*(w12(i)*s(i,4) - w31(i)*s(i,6))
         d2 = 2.0_wp*(w23(i)*s(i,5) - w12(i)*s(i,4))
         d3 = 2.0_wp*(w31(i)*s(i,6) - w23(i)*s(i,5))
         d4 = w12(i)*(s(i,2) - s(i,1)) + w23(i)*s(i,6) - w31(i)*s(i,5)
         d5 = w23(i)*(s(i,3) - s(i,2)) + w31(i)*s(i,4) - w12(i)*s(i,6)
         d6 = w31(i)*(s(i,1) - s(i,3)) + w12(i)*s(i,5) - w23(i)*s(i,4)
         s(i,1) = s(i,1) + d1; s(i,2) = s(i,2) + d2; s(i,3) = s(i,3) + d3
         s(i,4) = s(i,4) + d4; s(i,5) = s(i,5) + d5; s(i,6) = s(i,6) + d6
      end do
   end subroutine jaumann

   !> The stress of the one point to t(n): the rotated old stress so, the material update
   !> (one dispatch per block), failure, *MAT_ADD_EROSION and the erosion criteria of
   !> erosion_now (with time), the wave speed c; an element failing now is marked eroded and
   !> keeps zero stress (sn: the updated stress before that, whose force it still applies in
   !> the work of its last step; the kernels drop its force through alive/failed).
   subroutine point_stress(blk, mat, part, n, dt_old, w12, w23, w31, deps, rv, ein, lc, trd, &
                           c, so, sn, ierr, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      integer, intent(in) :: n
      real(wp), intent(in) :: dt_old, deps(:, :)
      real(wp), dimension(nv_chunk), intent(in) :: w12, w23, w31, rv, ein, lc, trd
      real(wp), intent(out) :: c(nv_chunk), so(nv_chunk, 6), sn(nv_chunk, 6)
      integer, intent(inout) :: ierr(nv_chunk)
      real(wp), intent(in), optional :: time, dtfloor
      logical :: failed(nv_chunk)
      integer :: k
      do k = 1, 6
         so(1:n, k) = blk%sig(1:n, k, 1)
      end do
      call jaumann(n, nv_chunk, w12, w23, w31, so)
      do k = 1, 6
         blk%sig(1:n, k, 1) = so(1:n, k)
      end do
      if (mat%hv_frame) call mat%rotate_history(n, w12, w23, w31, blk%hv(:, :, 1))
      call mat%update(n, dt_old, deps, rv, ein, blk%sig(:, :, 1), blk%hv(:, :, 1), ierr)
      call mat%fails(n, blk%hv(:, :, 1), failed)
      call erosion_one_point(blk, part, n, rv, dt_old, failed)   ! *MAT_ADD_EROSION
      call mat%wave_speed(n, rv, blk%hv(:, :, 1), c)
      if (present(time)) call erosion_now(part, n, time, dtfloor, lc, trd, c, failed)
      call erode_failed(blk, n, failed, sn)
   end subroutine point_stress

   !> Elements failing now (failed) are marked eroded; sn = the updated stress of point 1, and
   !> an eroded element's stress is set to zero (also dx_quad2d's).
   subroutine erode_failed(blk, n, failed, sn)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: n
      logical, intent(in) :: failed(nv_chunk)
      real(wp), intent(out) :: sn(nv_chunk, 6)
      integer :: i, k
      do i = 1, n
         if (failed(i) .and. .not. blk%failed(i)) blk%failed(i) = .true.
      end do
      do k = 1, 6
         do i = 1, n
            sn(i, k) = blk%sig(i, k, 1)
            if (blk%failed(i)) blk%sig(i, k, 1) = 0.0_wp
         end do
      end do
   end subroutine erode_failed

   !> DYNA bulk viscosity q = rho*l*(Q1*l*e_kk**2 - Q2*c*e_kk) for e_kk < 0, l the element's
   !> characteristic length of the time step (issue 15: one length for both), evaluated as
   !> rho*(Q1*(l*e_kk)**2 - Q2*c*(l*e_kk)): l*e_kk = dV/dt/A_max stays bounded as a crushed
   !> element's V -> 0, where e_kk**2 alone overflows (extreme_crushed_element).
   pure real(wp) function bulk_viscosity(part, rho, l, trd, c) result(q)
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: rho, l, trd, c
      real(wp) :: lt
      q = 0.0_wp
      lt = l*trd
      if (trd < 0.0_wp) q = rho*(part%q1*lt*lt - part%q2*c*lt)
   end function bulk_viscosity

   !> The stress work rates of the centred work: wo = V(n-1/2) so:de, wn = V(n-1/2) sn:de
   !> (0, and the bulk viscosity q = 0, for an element eroded now: no force f(n)). q is the
   !> kernel's own: dx_hex8 evaluates bulk_viscosity, dx_tet4 the same formula written out,
   !> and the two differ in the last bit where the compiler fuses a product (FMA).
   subroutine work_rates(blk, n, volm, so, sn, de6, q, wo, wn)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: n
      real(wp), dimension(nv_chunk), intent(in) :: volm
      real(wp), dimension(nv_chunk, 6), intent(in) :: so, sn, de6
      real(wp), dimension(nv_chunk), intent(inout) :: q
      real(wp), dimension(nv_chunk), intent(out) :: wo, wn
      integer :: i
      do i = 1, n
         wo(i) = volm(i)*(so(i,1)*de6(i,1) + so(i,2)*de6(i,2) + so(i,3)*de6(i,3) &
                 + 2.0_wp*(so(i,4)*de6(i,4) + so(i,5)*de6(i,5) + so(i,6)*de6(i,6)))
         wn(i) = volm(i)*(sn(i,1)*de6(i,1) + sn(i,2)*de6(i,2) + sn(i,3)*de6(i,3) &
                 + 2.0_wp*(sn(i,4)*de6(i,4) + sn(i,5)*de6(i,5) + sn(i,6)*de6(i,6)))
         if (blk%failed(i)) wn(i) = 0.0_wp   ! eroding now: no force f(n), W(n) = 0
         if (blk%failed(i)) q(i) = 0.0_wp
      end do
   end subroutine work_rates

   !> Internal force f_iI = alive (sig_ij - q delta_ij) B_jI of the one point.
   subroutine stress_forces(n, nen, alive, sn, q, bx, by, bz, fx, fy, fz)
      integer, intent(in) :: n, nen
      real(wp), intent(in) :: alive(nv_chunk), sn(nv_chunk, 6), q(nv_chunk)
      real(wp), dimension(nv_chunk, nen), intent(in) :: bx, by, bz
      real(wp), dimension(nv_chunk, nen), intent(out) :: fx, fy, fz
      integer :: i, k
      do k = 1, nen
         do i = 1, n
            fx(i, k) = alive(i)*((sn(i,1) - q(i))*bx(i,k) + sn(i,4)*by(i,k) + sn(i,6)*bz(i,k))
            fy(i, k) = alive(i)*(sn(i,4)*bx(i,k) + (sn(i,2) - q(i))*by(i,k) + sn(i,5)*bz(i,k))
            fz(i, k) = alive(i)*(sn(i,6)*bx(i,k) + sn(i,5)*by(i,k) + (sn(i,3) - q(i))*bz(i,k))
         end do
      end do
   end subroutine stress_forces

   !> Scatter: the element forces are subtracted from the nodal force f (internal force).
   subroutine scatter_forces(blk, n, nen, fx, fy, fz, f)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: n, nen
      real(wp), dimension(nv_chunk, nen), intent(in) :: fx, fy, fz
      real(wp), intent(inout) :: f(:, :)
      integer :: i, k, nn
      do k = 1, nen
         do i = 1, n
            nn = blk%conn(k, i)
            f(1, nn) = f(1, nn) - fx(i, k)
            f(2, nn) = f(2, nn) - fy(i, k)
            f(3, nn) = f(3, nn) - fz(i, k)
         end do
      end do
   end subroutine scatter_forces
end module dx_solid_point
