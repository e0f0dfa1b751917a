!> 2D solid quadrilaterals in the x-y plane over one element block (*SECTION_SHELL ELFORM 13,
!> 14, 15 with *ELEMENT_SHELL connectivity; a triangle repeats N3), as DYNA2D defines them
!> (Hallquist, DYNA2D - An Explicit Two-Dimensional Hydrodynamic Finite Element Code with
!> Interactive Rezoning and Graphical Display, LLNL UCID-18756 Rev. 3, 1988; LS-DYNA Theory
!> Manual, "Two Dimensional Solid Elements"):
!> - ELFORM 13, plane strain: per unit thickness, d_zz = 0 (sigma_zz from the material).
!> - ELFORM 12, plane stress: thickness t (the section's T1..T4 or the card's, fixed: no
!>   thickness update), sigma_zz = 0 by the material's lamina update (update_plane_stress, as
!>   the shells' layers); everything else as 13 with t in place of the unit thickness.
!> - ELFORM 15, volume-weighted axisymmetric (x = r, y = z, the axis): the Galerkin form over
!>   the volume per radian V = int r dA; one point at the centre with the in-plane B vectors
!>   B_I = dA/dx_I (b_I = B_I/A = dN_I/dx there) scaled by rbar = V/A, and the hoop term
!>   f_rI += sigma_tt A/4 (int N_I dA = A/4 at one point); the hoop strain rate v_r/r is
!>   vbar_r/rbar (vbar_r = sum v_rI/4), the partner of that hoop force, so the stress power is
!>   the work of the nodal forces exactly: f.v = V sigma:D.
!> - ELFORM 14, area-weighted axisymmetric (Petrov-Galerkin): the momentum equation weighted by
!>   N_I over the area, int N_I (div sigma + (sigma_rr - sigma_tt)/r, ...) dA, integrated by
!>   parts: f_rI = A (sigma_rr b_r + sigma_rz b_z) - A/4 (sigma_rr - sigma_tt)/rbar, f_zI = A
!>   (sigma_rz b_r + sigma_zz b_z) - A/4 sigma_rz/rbar (Goudreau & Hallquist 1982, CMAME 33:
!>   725-757; DYNA2D's default). dynx keeps both axisymmetric forms per radian (masses, loads and
!>   energies; LS-DYNA's convention as we read it, not checked against a run): one lumped mass rho0
!>   V0/4 per node, and the area-weighted nodal equation multiplied by a radius: the radial one by
!>   the node's r_I (then m_I a = r_I sum_e f_e + F_ext with m_I ~ r_I sum rho A/4: the area-
!>   weighted acceleration to O(h^2) on a smooth mesh, and no division by r_I), the axial one by
!>   each element's rbar (sum_e rbar (A sigma.b - A/4 sigma_rz/rbar) is r (d sigma_rz/dr + d
!>   sigma_zz/dz) to the same order, and stays finite on the axis, where r_I = 0). (Each element's
!>   radial equation by its own rbar would be d(r sigma_rr)/dr - sigma_rr: wrong by sigma_rr, 26 %
!>   in the Lame test.) The element's internal energy is the work of its own nodal forces (a Petrov-
!>   Galerkin form has no stress power sigma:D V to match).
!> - The axis r = 0: no division by a nodal radius anywhere (rbar = V/A > 0 for any element
!>   with area); nodes on the axis have their radial DOF fixed at build (v_r = 0 by symmetry).
!> The cycle is dx_hex8's one-point pass in 2D: strain increment and spin at the mid-step
!> geometry, Jaumann rotation (spin w_xy only), one material dispatch per block with the 3D
!> strain increment (xx, yy, zz = hoop or 0, xy), DYNA bulk viscosity q with the time step's
!> length L (one length for both, issue 15), the centred work of stress and viscosity
!> (dx_hex8's centred_work_block; 12, 13: B = dA/dx, Simpson exact; 14, 15: the one-point B is
!> not dV/dx, so the work of the last pass's q gets B(n-1).v(n-1/2) itself, quad2d_bdotv).
!> Hourglass: Flanagan & Belytschko 1981 (IJNME 17:679-706) for the 4-node quad, viscous:
!> gamma_I = h_I - (h.x) b_xI - (h.y) b_yI, h = (1, -1, 1, -1), modal rates q_i = gamma_I v_iI,
!> f_iI += a_h q_i gamma_I with a_h = QH rho c sqrt(A) t (t = 1 plane strain, rbar per radian):
!> dx_hex8's QH rho c V**(2/3)/4 on the brick of the quad extruded by sqrt(A), its two layers'
!> modes summed (IHQ 1-3 alike). Stiffness (IHQ 4, 5 alike): FB's kappa = QH (lambda + 2 mu)
!> b_jJ b_jJ/(2A) on the modes normalized by 1/2 (|h|**2 = 4), i.e. the stored resisting force
!> Q_i += k_h dt qdot_i with k_h = QH (K + 4G/3) B_jJ B_jJ/(8A) t (as dx_hex8's /(24V) in 3D),
!> corotated with the in-plane spin, f_iI += Q_i gamma_I. Energy of both: dt/2 (Q(n-1) + Q(n)).qdot
!> (viscous: Q(n-1) as applied, the centred work); the viscous one's explicit bound
!> dt <= sqrt(A)/(8 QH c) in the step (dx_hex8's stable_time_step).
!> Stable step dt_e = L/(Q + sqrt(Q**2 + c**2)), L = A / (the element's diameter: its longest
!> diagonal or edge) - DYNA2D's area over the longest diagonal for every quadrilateral whose
!> diagonal is its longest span, the triangle's and the trapezoid's longest edge otherwise
!> (Wilkins 1964, Calculation of Elastic-Plastic Flow, Methods Comput. Phys. 3, the 2D
!> integral difference scheme whose B vectors these are; LS-DYNA Theory Manual, "Time Step
!> Control"). The z components of every nodal quantity stay zero: these kernels never touch
!> f(3, :), and the z DOF of every node of a 2D deck is fixed at build (dx_build_loads).
module dx_quad2d
   use dx_kinds, only: wp, nv_chunk
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_WORK, ES_HGS, ES_THK, block_result_t, &
                               ELEM_ERR_NEGVOL, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, &
                               ETYPE_QUAD2D_PSS
   use dx_hex8, only: centred_work_block, stable_time_step, first_error
   use dx_solid_point, only: erode_failed
   implicit none
   private
   public :: quad2d_block, quad2d_geometry

   !> collapsed at or below eps V0 (as dx_hex8)
   real(wp), parameter :: vcrush = epsilon(1.0_wp)
   !> the hourglass base vector of the 4-node quadrilateral
   real(wp), parameter :: HG(4) = [1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp]

contains

   !> B vectors bx, by (n, 4) = dA/dx_I, dA/dy_I (exact for the bilinear quadrilateral), the
   !> signed area a (positive counter-clockwise) and the volume measure v: a, or int r dA per
   !> radian when axi (Green's theorem over the straight edges) of n elements x, y (n, 4).
   pure subroutine quad2d_geometry(n, axi, x, y, bx, by, a, v)
      integer, intent(in) :: n
      logical, intent(in) :: axi
      real(wp), dimension(:, :), intent(in) :: x, y
      real(wp), dimension(:, :), intent(out) :: bx, by
      real(wp), intent(out) :: a(:), v(:)
      real(wp) :: s
      integer :: i, k, m
      do i = 1, n
         bx(i, 1) = 0.5_wp*(y(i, 2) - y(i, 4)); bx(i, 2) = 0.5_wp*(y(i, 3) - y(i, 1))
         bx(i, 3) = 0.5_wp*(y(i, 4) - y(i, 2)); bx(i, 4) = 0.5_wp*(y(i, 1) - y(i, 3))
         by(i, 1) = 0.5_wp*(x(i, 4) - x(i, 2)); by(i, 2) = 0.5_wp*(x(i, 1) - x(i, 3))
         by(i, 3) = 0.5_wp*(x(i, 2) - x(i, 4)); by(i, 4) = 0.5_wp*(x(i, 3) - x(i, 1))
         a(i) = 0.5_wp*((x(i, 3) - x(i, 1))*(y(i, 4) - y(i, 2)) &
                        - (x(i, 4) - x(i, 2))*(y(i, 3) - y(i, 1)))
      end do
      if (axi) then
         do i = 1, n
            s = 0.0_wp
            do k = 1, 4
               m = mod(k, 4) + 1
               s = s + (x(i, k) + x(i, m))*(x(i, k)*y(i, m) - x(i, m)*y(i, k))
            end do
            v(i) = s/6.0_wp
         end do
      else
         v(1:n) = a(1:n)
      end if
   end subroutine quad2d_geometry

   !> The power per unit viscosity of the bulk-viscosity nodal forces -q (the B terms and the
   !> formulation's hoop term, as the force pass applies them) at velocities vx, vy: rbar B.v +
   !> A vbar_r (15), sum r_I B_rI v_rI + rbar B_z.v_z (14). Not dV/dt: the one-point B is not
   !> the gradient of int r dA (10 % apart on a distorted quad), so the centred work is given it.
   pure subroutine quad2d_bdotv(n, aw, x, vx, vy, bx, by, a, v, vr, bv)
      integer, intent(in) :: n
      logical, intent(in) :: aw
      real(wp), dimension(:, :), intent(in) :: x, vx, vy, bx, by
      real(wp), dimension(:), intent(in) :: a, v, vr
      real(wp), intent(out) :: bv(:)
      real(wp) :: rb
      integer :: i, k
      do i = 1, n
         bv(i) = 0.0_wp
         if (.not. (a(i) > 0.0_wp)) cycle
         rb = v(i)/a(i)
         do k = 1, 4
            if (aw) bv(i) = bv(i) + x(i, k)*bx(i, k)*vx(i, k) + rb*by(i, k)*vy(i, k)
            if (.not. aw) bv(i) = bv(i) + bx(i, k)*vx(i, k) + by(i, k)*vy(i, k)
         end do
         if (.not. aw) bv(i) = rb*bv(i) + a(i)*vr(i)
      end do
   end subroutine quad2d_bdotv

   !> One explicit pass over a block of 2D quadrilaterals: x = x(n), v = v(n-1/2), dt_old =
   !> dt(n-1/2). Updates stress/history to t(n) and subtracts the internal force from f(1:2, :).
   subroutine quad2d_block(blk, mat, part, x, v, dt_old, f, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), dimension(nv_chunk, 4) :: xe, ye, vx, vy, xm, ym, bx, by, fx, fy, g, bxm, bym
      real(wp), dimension(nv_chunk) :: ar, arm, vol, volm, rb, rbm, rv, c, q, trd, w12, ein, rb0
      real(wp), dimension(nv_chunk) :: alive, bv, bvm, vold, lc, wo, wn
      real(wp), dimension(nv_chunk) :: vr, vz, dh, bvp
      real(wp) :: de6(nv_chunk, 6), so(nv_chunk, 6), sn(nv_chunk, 6)
      real(wp) :: deps(blk%nel, 6)
      real(wp) :: l11, l22, l12, l21, dtl, hdt, d1, d4, s1, s2, s4, hx, hy, hr, hz, ah, qx, qy
      real(wp) :: e, diam, pw(2), kx, ky
      integer :: m, h
      integer :: ierr(nv_chunk)
      logical :: failed(nv_chunk), axi, aw, pss
      real(wp) :: de5(blk%nel, 5), s5(blk%nel, 5), ez(blk%nel)
      integer :: th
      integer :: i, k, n, nn, w
      axi = blk%etype == ETYPE_QUAD2D_AW .or. blk%etype == ETYPE_QUAD2D_VW
      aw = blk%etype == ETYPE_QUAD2D_AW
      pss = blk%etype == ETYPE_QUAD2D_PSS
      th = 0
      if (pss) th = blk%esc(ES_THK)
      if (blk%esc(ES_WORK) == 0) call blk%es_add(ES_WORK, 4)
      if (part%qh > 0.0_wp .and. blk%esc(ES_HGS) == 0) call blk%es_add(ES_HGS, 2)
      w = blk%esc(ES_WORK)
      n = blk%nel
      hdt = 0.5_wp*dt_old
      do k = 1, 4
         do i = 1, n
            nn = blk%conn(k, i)
            xe(i, k) = x(1, nn); ye(i, k) = x(2, nn)
            vx(i, k) = v(1, nn); vy(i, k) = v(2, nn)
            xm(i, k) = xe(i, k) - hdt*vx(i, k)
            ym(i, k) = ye(i, k) - hdt*vy(i, k)
         end do
      end do
      ! ---- mid-step geometry: velocity gradient times A, L_ij A = v_iI B_jI, hoop rate
      call quad2d_geometry(n, axi, xm, ym, bxm, bym, arm, volm)
      if (pss) volm(1:n) = arm(1:n)*blk%es(1:n, th)   ! plane stress: V = A t (t fixed)
      do i = 1, n
         l11 = 0.0_wp; l22 = 0.0_wp; l12 = 0.0_wp; l21 = 0.0_wp
         do k = 1, 4
            l11 = l11 + vx(i, k)*bxm(i, k)
            l22 = l22 + vy(i, k)*bym(i, k)
            l12 = l12 + vx(i, k)*bym(i, k)
            l21 = l21 + vy(i, k)*bxm(i, k)
         end do
         vr(i) = 0.25_wp*(vx(i, 1) + vx(i, 2) + vx(i, 3) + vx(i, 4))
         vz(i) = 0.25_wp*(vy(i, 1) + vy(i, 2) + vy(i, 3) + vy(i, 4))
         ierr(i) = 0
         if (.not. (arm(i) > 0.0_wp .and. volm(i) > vcrush*blk%vol0(i))) then
            ierr(i) = ELEM_ERR_NEGVOL
            arm(i) = 1.0_wp; volm(i) = 1.0_wp
         end if
         alive(i) = merge(0.0_wp, 1.0_wp, blk%failed(i))
         rbm(i) = volm(i)/arm(i)            ! 1 in plane strain
         dh(i) = 0.0_wp
         if (axi) dh(i) = vr(i)/rbm(i)      ! hoop strain rate v_r/r at the centre
         dtl = dt_old/arm(i)
         de6(i, 1) = l11*dtl
         de6(i, 2) = l22*dtl
         de6(i, 3) = dh(i)*dt_old
         de6(i, 4) = 0.5_wp*(l12 + l21)*dtl
         de6(i, 5) = 0.0_wp
         de6(i, 6) = 0.0_wp
         w12(i) = 0.5_wp*(l12 - l21)*dtl
         trd(i) = (l11 + l22)/arm(i) + dh(i)
         ! B(n-1/2).v of the viscosity force (14: r_I and rbar scale the B terms, no hoop q)
         bvm(i) = rbm(i)*(l11 + l22)
         if (axi .and. .not. aw) bvm(i) = bvm(i) + arm(i)*vr(i)
         if (aw) then
            bvm(i) = rbm(i)*l22
            do k = 1, 4
               bvm(i) = bvm(i) + xm(i, k)*bxm(i, k)*vx(i, k)
            end do
         end if
      end do
      do k = 1, 6
         deps(1:n, k) = de6(1:n, k)
      end do
      ! ---- geometry at t(n): forces, volume, time step
      call quad2d_geometry(n, axi, xe, ye, bx, by, ar, vol)
      if (pss) vol(1:n) = ar(1:n)*blk%es(1:n, th)
      do i = 1, n
         vold(i) = blk%vol0(i)*blk%relvol(i)
         if (.not. (ar(i) > 0.0_wp .and. vol(i) > vcrush*blk%vol0(i))) then
            ierr(i) = ELEM_ERR_NEGVOL
            ar(i) = 1.0_wp; vol(i) = 1.0_wp
         end if
         rb(i) = vol(i)/ar(i)
         rv(i) = vol(i)/blk%vol0(i)
         blk%relvol(i) = rv(i)
         ein(i) = blk%eint(i)/blk%vol0(i)
         bv(i) = 0.0_wp
         do k = 1, 4
            bv(i) = bv(i) + bx(i, k)*vx(i, k) + by(i, k)*vy(i, k)
         end do
         bv(i) = rb(i)*bv(i)
         if (axi .and. .not. aw) bv(i) = bv(i) + ar(i)*vr(i)
         if (aw) then
            bv(i) = 0.0_wp
            do k = 1, 4
               bv(i) = bv(i) + xe(i, k)*bx(i, k)*vx(i, k) + rb(i)*by(i, k)*vy(i, k)
            end do
         end if
         ! the one length of the step and the viscosity: area / diameter
         diam = max((xe(i, 3) - xe(i, 1))**2 + (ye(i, 3) - ye(i, 1))**2, &
                    (xe(i, 4) - xe(i, 2))**2 + (ye(i, 4) - ye(i, 2))**2)
         do k = 1, 4
            diam = max(diam, (xe(i, mod(k, 4) + 1) - xe(i, k))**2 &
                             + (ye(i, mod(k, 4) + 1) - ye(i, k))**2)
         end do
         lc(i) = ar(i)/sqrt(diam)
      end do
      ! ---- stress: Jaumann rotation by the in-plane spin increment, then the material
      do k = 1, 6
         so(1:n, k) = blk%sig(1:n, k, 1)
      end do
      do i = 1, n
         d1 = 2.0_wp*w12(i)*so(i, 4)
         d4 = w12(i)*(so(i, 2) - so(i, 1))
         so(i, 1) = so(i, 1) + d1
         so(i, 2) = so(i, 2) - d1
         so(i, 4) = so(i, 4) + d4
      end do
      do k = 1, 6
         blk%sig(1:n, k, 1) = so(1:n, k)
      end do
      if (mat%hv_frame) then   ! directions in the material's history turn with w_xy
         rb0(1:n) = 0.0_wp
         call mat%rotate_history(n, w12, rb0, rb0, blk%hv(:, :, 1))
      end if
      if (pss) then      ! plane stress: the lamina update, sigma_zz = 0 (engineering shear)
         do i = 1, n
            de5(i, 1) = deps(i, 1); de5(i, 2) = deps(i, 2); de5(i, 3) = 2.0_wp*deps(i, 4)
            de5(i, 4) = 0.0_wp; de5(i, 5) = 0.0_wp
            s5(i, 1) = blk%sig(i, 1, 1); s5(i, 2) = blk%sig(i, 2, 1)
            s5(i, 3) = blk%sig(i, 4, 1); s5(i, 4) = 0.0_wp; s5(i, 5) = 0.0_wp
         end do
         call mat%update_plane_stress(n, dt_old, de5, s5, blk%hv(:, :, 1), ierr, ez)
         do i = 1, n
            blk%sig(i, 1, 1) = s5(i, 1); blk%sig(i, 2, 1) = s5(i, 2)
            blk%sig(i, 3, 1) = 0.0_wp; blk%sig(i, 4, 1) = s5(i, 3)
         end do
      else
         call mat%update(n, dt_old, deps, rv, ein, blk%sig(:, :, 1), blk%hv(:, :, 1), ierr)
      end if
      call mat%fails(n, blk%hv(:, :, 1), failed)
      call mat%wave_speed(n, rv, blk%hv(:, :, 1), c)
      call erode_failed(blk, n, failed, sn)
      ! ---- bulk viscosity and the centred work of stress and viscosity
      do i = 1, n
         q(i) = 0.0_wp
         if (trd(i) < 0.0_wp) q(i) = mat%ro/rv(i)*(part%q1*(lc(i)*trd(i))**2 &
                                     - part%q2*c(i)*(lc(i)*trd(i)))
         wo(i) = volm(i)*(so(i, 1)*de6(i, 1) + so(i, 2)*de6(i, 2) + so(i, 3)*de6(i, 3) &
                 + 2.0_wp*so(i, 4)*de6(i, 4))
         wn(i) = volm(i)*(sn(i, 1)*de6(i, 1) + sn(i, 2)*de6(i, 2) + sn(i, 3)*de6(i, 3) &
                 + 2.0_wp*sn(i, 4)*de6(i, 4))
         if (aw) then      ! the work of the nodal forces at the mid-step geometry (header)
            do m = 1, 2
               pw(m) = 0.0_wp
               associate (t => merge(so(i, :), sn(i, :), m == 1))
                  do k = 1, 4
                     pw(m) = pw(m) + xm(i, k)*vx(i, k)*(t(1)*bxm(i, k) + t(4)*bym(i, k) &
                             - 0.25_wp*arm(i)*(t(1) - t(3))/rbm(i)) &
                             + vy(i, k)*(rbm(i)*(t(4)*bxm(i, k) + t(2)*bym(i, k)) &
                             - 0.25_wp*arm(i)*t(4))
                  end do
               end associate
            end do
            wo(i) = dt_old*pw(1)
            wn(i) = dt_old*pw(2)
         end if
      end do
      if (axi) then   ! the last pass's viscosity force: its one-point B(n-1).v(n-1/2) (header)
         xm(1:n, :) = xe(1:n, :) - dt_old*vx(1:n, :)
         ym(1:n, :) = ye(1:n, :) - dt_old*vy(1:n, :)
         call quad2d_geometry(n, axi, xm, ym, bxm, bym, arm, volm)
         call quad2d_bdotv(n, aw, xm, vx, vy, bxm, bym, arm, volm, vr, bvp)
         call centred_work_block(blk, n, w, dt_old, wo, wn, q, vol, vold, bv, bvm, alive, res, &
                                 bvp)
      else
         call centred_work_block(blk, n, w, dt_old, wo, wn, q, vol, vold, bv, bvm, alive, res)
      end if
      ! ---- internal force: rbar (sigma - q) B_I plus the hoop term of the formulation
      do i = 1, n
         s1 = sn(i, 1) - q(i); s2 = sn(i, 2) - q(i); s4 = sn(i, 4)
         hr = 0.0_wp; hz = 0.0_wp
         if (aw) then         ! radial by the node's r_I, axial by the element's rbar
            hr = -0.25_wp*ar(i)*(sn(i, 1) - sn(i, 3))/rb(i)
            hz = -0.25_wp*ar(i)*sn(i, 4)
            do k = 1, 4
               fx(i, k) = alive(i)*xe(i, k)*(s1*bx(i, k) + s4*by(i, k) + hr)
               fy(i, k) = alive(i)*(rb(i)*(s4*bx(i, k) + s2*by(i, k)) + hz)
            end do
            cycle
         end if
         if (axi) hr = 0.25_wp*ar(i)*(sn(i, 3) - q(i))
         do k = 1, 4
            fx(i, k) = alive(i)*(rb(i)*(s1*bx(i, k) + s4*by(i, k)) + hr)
            fy(i, k) = alive(i)*(rb(i)*(s4*bx(i, k) + s2*by(i, k)) + hz)
         end do
      end do
      ! ---- hourglass control (Flanagan-Belytschko: viscous IHQ 1-3, stiffness IHQ 4, 5)
      res%dehg = 0.0_wp
      if (part%qh > 0.0_wp) then
         do i = 1, n
            hx = 0.0_wp; hy = 0.0_wp
            do k = 1, 4
               hx = hx + HG(k)*xe(i, k)
               hy = hy + HG(k)*ye(i, k)
            end do
            qx = 0.0_wp; qy = 0.0_wp
            do k = 1, 4
               g(i, k) = HG(k) - (hx*bx(i, k) + hy*by(i, k))/ar(i)
               qx = qx + g(i, k)*vx(i, k)
               qy = qy + g(i, k)*vy(i, k)
            end do
            h = blk%esc(ES_HGS)
            if (part%ihq >= 4) then
               ! stiffness: corotate the stored resisting force, add k_h dt qdot; the energy
               ! is the trapezoid of the old and new force (exact spring energy)
               ah = 0.0_wp
               do k = 1, 4
                  ah = ah + bx(i, k)**2 + by(i, k)**2
               end do
               ah = part%qh*(mat%bulk + 4.0_wp*mat%shear/3.0_wp)*ah/(8.0_wp*ar(i))*rb(i)
               kx = blk%es(i, h) + w12(i)*blk%es(i, h + 1)
               ky = blk%es(i, h + 1) - w12(i)*blk%es(i, h)
               blk%es(i, h) = kx + ah*dt_old*qx
               blk%es(i, h + 1) = ky + ah*dt_old*qy
            else
               ! viscous: the trapezoid of the last pass's force (as applied) and this one's,
               ! the centred work (dx_hex8's hourglass_gamma_viscous)
               ah = part%qh*(mat%ro/rv(i))*c(i)*sqrt(ar(i))*rb(i)*alive(i)
               kx = blk%es(i, h); ky = blk%es(i, h + 1)
               blk%es(i, h) = ah*qx
               blk%es(i, h + 1) = ah*qy
            end if
            e = 0.5_wp*dt_old*((kx + blk%es(i, h))*qx + (ky + blk%es(i, h + 1))*qy)*alive(i)
            qx = blk%es(i, h)*alive(i)
            qy = blk%es(i, h + 1)*alive(i)
            e = e + 0.0_wp     ! one use of the product (no FMA into two sums: as dx_hex8)
            blk%ehg(i) = blk%ehg(i) + e
            res%dehg = res%dehg + e
            do k = 1, 4
               fx(i, k) = fx(i, k) + qx*g(i, k)
               fy(i, k) = fy(i, k) + qy*g(i, k)
            end do
         end do
      end if
      ! ---- scatter (internal force is subtracted; z untouched)
      do k = 1, 4
         do i = 1, n
            nn = blk%conn(k, i)
            f(1, nn) = f(1, nn) - fx(i, k)
            f(2, nn) = f(2, nn) - fy(i, k)
         end do
      end do
      call stable_time_step(blk, part, lc, trd, c, res, sqrt(ar(1:n)))
      call first_error(n, ierr, blk%failed, res)
   end subroutine quad2d_block
end module dx_quad2d
