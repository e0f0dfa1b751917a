!> Tet4 element kernel over one element block (ELFORM 10 of *SECTION_SOLID): the 4-node
!> linear tetrahedron with one integration point, constant strain (Zienkiewicz, Taylor & Zhu,
!> The Finite Element Method: Its Basis and Fundamentals, 7th ed., 2013, sec. 6.2;
!> Belytschko, Liu & Moran, Nonlinear Finite Elements for Continua and Structures, 2000,
!> sec. 4.5). The gradient vectors B_I = int dN_I/dx dV = dV/dx_I are exact: with
!> a = x2 - x1, b = x3 - x1, c = x4 - x1: 6V = a.(b x c), 6 B2 = b x c, 6 B3 = c x a,
!> 6 B4 = a x b, B1 = -(B2 + B3 + B4). Constant strain, so no hourglass modes and no control.
!> The cycle is dx_hex8's one-point pass with these B: strain increment and spin at the
!> mid-step geometry, Jaumann rotation, one material dispatch per block, DYNA bulk viscosity
!> with the time step's length L (below; one length for both, issue 15), the centred work of stress and viscosity (V is cubic in x, so Simpson's
!> rule of centred_work is exact here as for the hexahedron), force scatter f_iI = sig_ij B_jI.
!> Stable step: dt_e = L/(Q + sqrt(Q**2 + c**2)) as for the hexahedron, with L the smallest
!> altitude of the tetrahedron, 3V/A_max = V/max_I |B_I| (|B_I| is a third of the area of the
!> face opposite node I); LS-DYNA's length for tetrahedra (LS-DYNA Theory Manual, "Time Step
!> Control", solid elements; Ansys LS-DYNA help, "Characteristic Length (LS-DYNA)").
module dx_tet4
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_material, only: material_t
   use dx_erosion, only: erosion_strain
   use dx_element_types, only: elem_block_t, part_t, ES_WORK, block_result_t, ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL
   use dx_hex8, only: centred_work_block, stable_time_step   ! one copy, inlined in dx_hex8
   use dx_solid_point, only: gather_mid, strain_increments, volumes_now, point_stress, &
                             work_rates, stress_forces, scatter_forces
   implicit none
   private
   public :: tet4_block, tet4_bvectors

   integer, parameter :: NEN = 4

contains

   !> B vectors (nv, 4) per direction and volumes of n tetrahedra with node coordinates x,y,z.
   pure subroutine tet4_bvectors(n, x, y, z, bx, by, bz, vol)
      integer, intent(in) :: n
      real(wp), dimension(:, :), intent(in) :: x, y, z
      real(wp), dimension(:, :), intent(out) :: bx, by, bz
      real(wp), intent(out) :: vol(:)
      real(wp), parameter :: c6 = 1.0_wp/6.0_wp
      real(wp) :: a1, a2, a3, b1, b2, b3, d1, d2, d3
      integer :: i
      do i = 1, n
         a1 = x(i, 2) - x(i, 1); a2 = y(i, 2) - y(i, 1); a3 = z(i, 2) - z(i, 1)
         b1 = x(i, 3) - x(i, 1); b2 = y(i, 3) - y(i, 1); b3 = z(i, 3) - z(i, 1)
         d1 = x(i, 4) - x(i, 1); d2 = y(i, 4) - y(i, 1); d3 = z(i, 4) - z(i, 1)
         bx(i, 2) = c6*(b2*d3 - b3*d2); by(i, 2) = c6*(b3*d1 - b1*d3)
         bz(i, 2) = c6*(b1*d2 - b2*d1)
         bx(i, 3) = c6*(d2*a3 - d3*a2); by(i, 3) = c6*(d3*a1 - d1*a3)
         bz(i, 3) = c6*(d1*a2 - d2*a1)
         bx(i, 4) = c6*(a2*b3 - a3*b2); by(i, 4) = c6*(a3*b1 - a1*b3)
         bz(i, 4) = c6*(a1*b2 - a2*b1)
         bx(i, 1) = -(bx(i, 2) + bx(i, 3) + bx(i, 4))
         by(i, 1) = -(by(i, 2) + by(i, 3) + by(i, 4))
         bz(i, 1) = -(bz(i, 2) + bz(i, 3) + bz(i, 4))
         vol(i) = a1*bx(i, 2) + a2*by(i, 2) + a3*bz(i, 2)
      end do
   end subroutine tet4_bvectors

   !> One explicit pass over a block of tetrahedra: x = x(n), v = v(n-1/2), dt_old =
   !> dt(n-1/2). Updates stress/history to t(n) and subtracts the internal force from f.
   subroutine tet4_block(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), intent(in), optional :: time, dtfloor   !< erosion (dx_erosion%erosion_now)
      real(wp), dimension(nv_chunk, NEN) :: xe, ye, ze, vx, vy, vz, bx, by, bz, xm, ym, zm
      real(wp), dimension(nv_chunk, NEN) :: fx, fy, fz
      real(wp), dimension(nv_chunk) :: vol, volm, rv, c, q, trd, w12, w23, w31, ein, alive
      real(wp), dimension(nv_chunk) :: bv, vold, lc, wo, wn, de
      real(wp) :: lg(nv_chunk, 9), de6(nv_chunk, 6), so(nv_chunk, 6), sn(nv_chunk, 6)
      real(wp) :: deps(blk%nel, 6)
      real(wp) :: hdt
      integer :: ierr(nv_chunk)
      integer :: i, k, n, w
      if (blk%esc(ES_WORK) == 0) call blk%es_add(ES_WORK, 4)
      w = blk%esc(ES_WORK)
      n = blk%nel
      hdt = 0.5_wp*dt_old
      call gather_mid(blk, n, nv_chunk, NEN, x, v, hdt, xe, ye, ze, vx, vy, vz, xm, ym, zm)
      ! ---- mid-step B: velocity gradient times V, L_ij V = v_iI B_jI
      call tet4_bvectors(n, xm, ym, zm, bx, by, bz, volm)
      lg(1:n, :) = 0.0_wp
      do k = 1, NEN
         do i = 1, n
            lg(i, 1) = lg(i, 1) + vx(i, k)*bx(i, k)
            lg(i, 2) = lg(i, 2) + vy(i, k)*by(i, k)
            lg(i, 3) = lg(i, 3) + vz(i, k)*bz(i, k)
            lg(i, 4) = lg(i, 4) + vx(i, k)*by(i, k)
            lg(i, 5) = lg(i, 5) + vy(i, k)*bx(i, k)
            lg(i, 6) = lg(i, 6) + vy(i, k)*bz(i, k)
            lg(i, 7) = lg(i, 7) + vz(i, k)*by(i, k)
            lg(i, 8) = lg(i, 8) + vz(i, k)*bx(i, k)
            lg(i, 9) = lg(i, 9) + vx(i, k)*bz(i, k)
         end do
      end do
      call strain_increments(blk, n, dt_old, lg, volm, ierr, alive, de6, deps, w12, w23, w31, &
                             trd)
      if (part%ero%on) call erosion_strain(blk, n, de6, w12, w23, w31)   ! strain criteria
      ! ---- geometry at t(n): forces, volume, time step; B(n).v(n-1/2) for the viscous work
      call tet4_bvectors(n, xe, ye, ze, bx, by, bz, vol)
      bv(1:n) = 0.0_wp
      do k = 1, NEN
         do i = 1, n
            bv(i) = bv(i) + bx(i, k)*vx(i, k) + by(i, k)*vy(i, k) + bz(i, k)*vz(i, k)
         end do
      end do
      call volumes_now(blk, n, vol, vold, rv, ein, ierr)
      call char_lengths(n, bx, by, bz, vol, lc)   ! one length for the step and the viscosity
      ! ---- stress: Jaumann rotation by the spin increment (first order), then the material
      call point_stress(blk, mat, part, n, dt_old, w12, w23, w31, deps, rv, ein, lc, trd, c, &
                        so, sn, ierr, time, dtfloor)
      ! ---- bulk viscosity and the centred work of stress and viscosity
      do i = 1, n
         q(i) = 0.0_wp
         if (trd(i) < 0.0_wp) q(i) = mat%ro/rv(i)*(part%q1*(lc(i)*trd(i))**2 &
                                     - part%q2*c(i)*(lc(i)*trd(i)))   ! (as dx_hex8's)
      end do
      call work_rates(blk, n, volm, so, sn, de6, q, wo, wn)
      de(1:n) = trd(1:n)*volm(1:n)     ! B(n-1/2).v(n-1/2)
      call centred_work_block(blk, n, w, dt_old, wo, wn, q, vol, vold, bv, de, alive, res)
      res%dehg = 0.0_wp
      ! ---- internal force f_iI = (sig_ij - q delta_ij) B_jI, scattered (subtracted)
      call stress_forces(n, NEN, alive, sn, q, bx, by, bz, fx, fy, fz)
      call scatter_forces(blk, n, NEN, fx, fy, fz, f)
      call stable_time_step(blk, part, lc, trd, c, res)
      do i = 1, n
         if (ierr(i) /= 0) then
            res%ibad = i
            res%errcode = merge(ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, ierr(i) == ELEM_ERR_NEGVOL)
            exit
         end if
      end do
   end subroutine tet4_block

   !> The characteristic length of each tetrahedron, L = V/max_I |B_I| (the smallest
   !> altitude), the one length of its time step and its bulk viscosity (a collapsed element
   !> with all B_I = 0: no division by zero).
   pure subroutine char_lengths(n, bx, by, bz, vol, lc)
      integer, intent(in) :: n
      real(wp), intent(in) :: bx(:, :), by(:, :), bz(:, :), vol(:)
      real(wp), intent(out) :: lc(:)
      real(wp) :: b2
      integer :: i, k
      do i = 1, n
         b2 = 0.0_wp
         do k = 1, NEN
            b2 = max(b2, bx(i, k)**2 + by(i, k)**2 + bz(i, k)**2)
         end do
         lc(i) = vol(i)/max(sqrt(b2), tiny(1.0_wp))
      end do
   end subroutine char_lengths
end module dx_tet4
