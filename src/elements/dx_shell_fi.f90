!> Fully integrated shell (ELFORM 16 of *SECTION_SHELL) over one element block: the 4-node
!> co-rotational Mindlin plate of the BT shell (dx_shell_bt: frame, stresses held in the
!> frame and turned by the material's in-plane spin, laminae, thickness update, time step,
!> lumped mass and rotary inertia) with 2x2 in-plane Gauss points for the membrane and
!> bending strains and the Bathe-Dvorkin assumed transverse shear (Bathe & Dvorkin 1985,
!> "A four-node plate bending element based on Mindlin/Reissner plate theory and a mixed
!> interpolation", IJNME 21:367-383; Dvorkin & Bathe 1984, Eng. Comput. 1:77-88; Hallquist,
!> LS-DYNA Theory Manual, "Fully Integrated Shell (type 16)"). No hourglass modes, so no
!> hourglass control; no warping stiffness (LS-DYNA's IHQ 8 is refused by the readers).
!> In the frame e of the mid-step geometry, with the bilinear map of the projected nodes
!> xl(2, 4), J = [x_xi y_xi; x_eta y_eta] and b1 = dN/dx, b2 = dN/dy at a Gauss point:
!>   d_xx = b1.vx + z b1.wy,  d_yy = b2.vy - z b2.wx,
!>   2d_xy = b2.vx + b1.vy + z (b2.wy - b1.wx)       (as dx_shell_bt at its one point),
!> and the transverse shears from the covariant ones g_xi = dvz/dxi + x_xi wy - y_xi wx,
!> g_eta = dvz/deta + x_eta wy - y_eta wx sampled at the edge mid-points (A: xi = 0,
!> eta = -1; C: 0, 1 for g_xi; D: -1, 0; B: 1, 0 for g_eta), interpolated linearly across
!> (g_xi = (1 - eta)/2 g_xi(A) + (1 + eta)/2 g_xi(C), g_eta likewise in xi) and turned
!> to Cartesian ones by J^-1: [g_zx, g_yz] = J^-1 [g_xi, g_eta]. SHRF scales the shear
!> resultants. Internal forces: sum over the points of det J B^T r (r the resultants N, M,
!> Q of the point), B of x(n) in the mid-step frame (as dx_shell_bt). Integration point
!> (g, ip) of in-plane point g and lamina ip is blk%sig(:, :, (g - 1) NIP + ip).
module dx_shell_fi
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_THK, block_result_t, &
                               ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, shell_frame
   use dx_shell_bt, only: thickness_rule
   implicit none
   private
   public :: shell_fi_block, shell_fi_bmat

   integer, parameter :: NEN = 4, NDF = 20     ! 5 dofs per node: vx vy vz wx wy (local)
   real(wp), parameter :: GP = 0.5773502691896257645_wp      ! 1/sqrt(3)
   real(wp), parameter :: XIG(4) = [-GP, GP, GP, -GP], ETG(4) = [-GP, -GP, GP, GP]

contains

   !> Strain-rate matrix bm(8, 20) and det J at in-plane point (xi, eta) of the element with
   !> projected nodes xl(2, 4): rows d_xx, d_yy, 2d_xy, k_xx, k_yy, 2k_xy (the curvature
   !> rates: the z factors), 2d_yz, 2d_zx (assumed shear); columns 5(k - 1) + (vx, vy, vz,
   !> wx, wy) of node k, in the element frame.
   pure subroutine shell_fi_bmat(xl, xi, eta, bm, det)
      real(wp), intent(in) :: xl(2, 4), xi, eta
      real(wp), intent(out) :: bm(8, NDF), det
      real(wp) :: dnx(4), dne(4), b1(4), b2(4), j11, j12, j21, j22
      real(wp) :: ga(NDF), gc(NDF), gd(NDF), gb(NDF), gx(NDF), ge(NDF)
      integer :: k, c
      dnx = 0.25_wp*[-(1.0_wp - eta), 1.0_wp - eta, 1.0_wp + eta, -(1.0_wp + eta)]
      dne = 0.25_wp*[-(1.0_wp - xi), -(1.0_wp + xi), 1.0_wp + xi, 1.0_wp - xi]
      j11 = dot_product(dnx, xl(1, :)); j12 = dot_product(dnx, xl(2, :))
      j21 = dot_product(dne, xl(1, :)); j22 = dot_product(dne, xl(2, :))
      det = j11*j22 - j12*j21
      b1 = (j22*dnx - j12*dne)/det
      b2 = (-j21*dnx + j11*dne)/det
      bm = 0.0_wp
      do k = 1, NEN
         c = 5*(k - 1)
         bm(1, c + 1) = b1(k)
         bm(2, c + 2) = b2(k)
         bm(3, c + 1) = b2(k); bm(3, c + 2) = b1(k)
         bm(4, c + 5) = b1(k)
         bm(5, c + 4) = -b2(k)
         bm(6, c + 5) = b2(k); bm(6, c + 4) = -b1(k)
      end do
      ! covariant shears at the tying points (edge mid-points)
      call tying(1, 2, ga)      ! A: eta = -1, g_xi along N1 -> N2
      call tying(4, 3, gc)      ! C: eta = +1, N4 -> N3
      call tying(1, 4, gd)      ! D: xi = -1, g_eta along N1 -> N4
      call tying(2, 3, gb)      ! B: xi = +1, N2 -> N3
      gx = 0.5_wp*(1.0_wp - eta)*ga + 0.5_wp*(1.0_wp + eta)*gc
      ge = 0.5_wp*(1.0_wp - xi)*gd + 0.5_wp*(1.0_wp + xi)*gb
      bm(7, :) = (-j21*gx + j11*ge)/det      ! 2d_yz
      bm(8, :) = (j22*gx - j12*ge)/det       ! 2d_zx
   contains
      !> the covariant shear along the edge ka -> kb at its mid-point:
      !> (vz_b - vz_a)/2 + t_x (wy_a + wy_b)/2 - t_y (wx_a + wx_b)/2, t = (x_b - x_a)/2
      pure subroutine tying(ka, kb, g)
         integer, intent(in) :: ka, kb
         real(wp), intent(out) :: g(NDF)
         real(wp) :: tx, ty
         tx = 0.5_wp*(xl(1, kb) - xl(1, ka)); ty = 0.5_wp*(xl(2, kb) - xl(2, ka))
         g = 0.0_wp
         g(5*(ka - 1) + 3) = -0.5_wp; g(5*(kb - 1) + 3) = 0.5_wp
         g(5*(ka - 1) + 5) = 0.5_wp*tx; g(5*(kb - 1) + 5) = 0.5_wp*tx
         g(5*(ka - 1) + 4) = -0.5_wp*ty; g(5*(kb - 1) + 4) = -0.5_wp*ty
      end subroutine tying
   end subroutine shell_fi_bmat

   !> One explicit pass over a block of fully integrated shells: x = x(n), v = v(n-1/2),
   !> w = w(n-1/2), dt_old = dt(n-1/2). Updates the stresses of the 4 x NIP points to t(n),
   !> subtracts the internal forces from f and moments from mom (as shell_bt_block).
   subroutine shell_fi_block(blk, mat, shrf, lobatto, istupd, x, v, w, dt_old, f, mom, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: shrf
      logical, intent(in) :: lobatto
      integer, intent(in) :: istupd
      real(wp), intent(in) :: x(:, :), v(:, :), w(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :), mom(:, :)
      type(block_result_t), intent(out) :: res
      integer, parameter :: MAXIP = 5
      real(wp) :: eps(nv_chunk, 8, 4), agm(nv_chunk, 4), thk(nv_chunk)
      real(wp) :: rc(nv_chunk), rs(nv_chunk), rc2(nv_chunk), rs2(nv_chunk)
      real(wp) :: rold(nv_chunk, 8, 4), rnew(nv_chunk, 8, 4)
      real(wp) :: de5(blk%nel, 5), s5(blk%nel, 5), ez(blk%nel), dzt(nv_chunk)
      real(wp) :: zeta(MAXIP), wt(MAXIP)
      real(wp) :: xe(3, 4), xm(3, 4), ve(3, 4), we(3, 4), vl(3, 4), wl(3, 4), e(3, 3), ea(3, 3)
      real(wp) :: xl(2, 4), xla(2, 4), am, aa, area, psi, u(NDF), bm(8, NDF), det, fl(NDF)
      real(wp) :: b1(4), b2(4), zw(4), ym, nu, lam, g, cs, hdt, z, tw, lmax, de, rhs, h
      integer :: ierr(nv_chunk)
      integer :: i, k, n, nn, ip, ig, c0, nip, q
      logical :: ok, tri
      n = blk%nel
      nip = blk%nip/4
      c0 = blk%esc(ES_THK)
      hdt = 0.5_wp*dt_old
      call thickness_rule(nip, lobatto, zeta, wt, ok)
      g = mat%shear
      lam = mat%bulk - 2.0_wp*g/3.0_wp
      ym = g*(3.0_wp*lam + 2.0_wp*g)/(lam + g)
      nu = 0.5_wp*lam/(lam + g)
      cs = sqrt(ym/(mat%ro*(1.0_wp - nu*nu)))
      res%deint = 0.0_wp; res%dehg = 0.0_wp; res%pend = 0.0_wp
      ierr(1:n) = 0
      ! ---- strain rates at the four points of the mid-step geometry, in its frame
      do i = 1, n
         thk(i) = blk%es(i, c0)
         do k = 1, NEN
            nn = blk%conn(k, i)
            ve(:, k) = v(:, nn); we(:, k) = w(:, nn)
            xm(:, k) = x(:, nn) - hdt*ve(:, k)
         end do
         call shell_frame(xm, e, xl, am)
         if (.not. (am > 0.0_wp)) then
            ierr(i) = ELEM_ERR_NEGVOL
            am = 1.0_wp
         end if
         vl = matmul(transpose(e), ve)
         wl = matmul(transpose(e), we)
         h = 0.5_wp/am
         b1 = h*[xl(2, 2) - xl(2, 4), xl(2, 3) - xl(2, 1), xl(2, 4) - xl(2, 2), xl(2, 1) - xl(2, 3)]
         b2 = h*[xl(1, 4) - xl(1, 2), xl(1, 1) - xl(1, 3), xl(1, 2) - xl(1, 4), xl(1, 3) - xl(1, 1)]
         ! warping: the in-plane velocities less those of the element's rigid rotation about
         ! its in-plane axes at the nodes' offsets zw from the mean plane
         zw = matmul(e(:, 3), xm) - 0.25_wp*sum(matmul(e(:, 3), xm))
         call unwarp(vl, zw, b1, b2)
         do k = 1, NEN
            u(5*k - 4:5*k - 2) = vl(:, k); u(5*k - 1:5*k) = wl(1:2, k)
         end do
         do ig = 1, 4
            call shell_fi_bmat(xl, XIG(ig), ETG(ig), bm, det)
            if (.not. (det > 0.0_wp)) then
               ierr(i) = ELEM_ERR_NEGVOL
               det = 0.0_wp; bm = 0.0_wp
            end if
            eps(i, :, ig) = matmul(bm, u)
            agm(i, ig) = det
         end do
         ! the turn of the stresses (as dx_shell_bt): the material's in-plane spin at the
         ! centre less the frame's own rotation, half a step each side of the mid-step frame
         psi = 0.25_wp*dt_old*(dot_product(b1, vl(2, :)) - dot_product(b2, vl(1, :)))
         call shell_frame(xm - hdt*ve, ea, xla, aa)
         z = psi - atan2(-dot_product(ea(:, 1), e(:, 2)), dot_product(ea(:, 1), e(:, 1)))
         rc(i) = cos(z); rs(i) = sin(z)
         call shell_frame(xm + hdt*ve, ea, xla, aa)
         z = psi - atan2(-dot_product(e(:, 1), ea(:, 2)), dot_product(e(:, 1), ea(:, 1)))
         rc2(i) = cos(z); rs2(i) = sin(z)
      end do
      ! ---- laminae of each in-plane point: resultants before (rold) and after (rnew)
      rold(1:n, :, :) = 0.0_wp; rnew(1:n, :, :) = 0.0_wp
      dzt(1:n) = 0.0_wp
      do ig = 1, 4
         do ip = 1, nip
            q = (ig - 1)*nip + ip
            call turn_stress(n, rc, rs, blk%sig(:, :, q))
            do i = 1, n
               z = 0.5_wp*zeta(ip)*thk(i)
               de5(i, 1) = dt_old*(eps(i, 1, ig) + z*eps(i, 4, ig))
               de5(i, 2) = dt_old*(eps(i, 2, ig) + z*eps(i, 5, ig))
               de5(i, 3) = dt_old*(eps(i, 3, ig) + z*eps(i, 6, ig))
               de5(i, 4) = dt_old*eps(i, 7, ig)
               de5(i, 5) = dt_old*eps(i, 8, ig)
               s5(i, 1) = blk%sig(i, 1, q); s5(i, 2) = blk%sig(i, 2, q)
               s5(i, 3) = blk%sig(i, 4, q); s5(i, 4) = blk%sig(i, 5, q)
               s5(i, 5) = blk%sig(i, 6, q)
               tw = 0.5_wp*wt(ip)*thk(i)
               call add_resultants(rold(i, :, ig), s5(i, :), tw, z)
            end do
            call mat%update_plane_stress(n, dt_old, de5, s5, blk%hv(:, :, q), ierr, ez)
            do i = 1, n
               dzt(i) = dzt(i) + 0.125_wp*wt(ip)*ez(i)   ! mean over the 4 x NIP points
               z = 0.5_wp*zeta(ip)*thk(i)
               tw = 0.5_wp*wt(ip)*thk(i)
               if (blk%failed(i)) s5(i, :) = 0.0_wp
               blk%sig(i, 1, q) = s5(i, 1); blk%sig(i, 2, q) = s5(i, 2)
               blk%sig(i, 3, q) = 0.0_wp
               blk%sig(i, 4, q) = s5(i, 3); blk%sig(i, 5, q) = s5(i, 4)
               blk%sig(i, 6, q) = s5(i, 5)
               call add_resultants(rnew(i, :, ig), s5(i, :), tw, z)
            end do
            call turn_stress(n, rc2, rs2, blk%sig(:, :, q))
         end do
      end do
      rold(1:n, 7:8, :) = shrf*rold(1:n, 7:8, :)
      rnew(1:n, 7:8, :) = shrf*rnew(1:n, 7:8, :)
      ! ---- forces at x(n) in the mid-step frame, energy, scatter, time step
      do i = 1, n
         do k = 1, NEN
            nn = blk%conn(k, i)
            xe(:, k) = x(:, nn); ve(:, k) = v(:, nn)
            xm(:, k) = xe(:, k) - hdt*ve(:, k)
         end do
         call shell_frame(xm, e, xl, am)
         do k = 1, NEN
            xl(1, k) = dot_product(e(:, 1), xe(:, k) - xe(:, 1))
            xl(2, k) = dot_product(e(:, 2), xe(:, k) - xe(:, 1))
         end do
         area = 0.5_wp*((xl(1, 3) - xl(1, 1))*(xl(2, 4) - xl(2, 2)) - &
                        (xl(1, 4) - xl(1, 2))*(xl(2, 3) - xl(2, 1)))
         de = 0.0_wp
         fl = 0.0_wp
         do ig = 1, 4
            de = de + agm(i, ig)*dot_product(0.5_wp*(rold(i, :, ig) + rnew(i, :, ig)), &
                                             eps(i, :, ig))
            call shell_fi_bmat(xl, XIG(ig), ETG(ig), bm, det)
            if (.not. (det > 0.0_wp)) then
               ierr(i) = ELEM_ERR_NEGVOL
               det = 0.0_wp; bm = 0.0_wp
            end if
            fl = fl + det*matmul(rnew(i, :, ig), bm)
         end do
         de = dt_old*de
         ! the transpose of the warping projection (unwarp) at x(n)
         if (area > 0.0_wp) then
            h = 0.5_wp/area
            b1 = h*[xl(2, 2) - xl(2, 4), xl(2, 3) - xl(2, 1), xl(2, 4) - xl(2, 2), &
                    xl(2, 1) - xl(2, 3)]
            b2 = h*[xl(1, 4) - xl(1, 2), xl(1, 1) - xl(1, 3), xl(1, 2) - xl(1, 4), &
                    xl(1, 3) - xl(1, 1)]
            zw = matmul(e(:, 3), xe) - 0.25_wp*sum(matmul(e(:, 3), xe))
            z = dot_product(zw, fl(1:NDF:5)); tw = dot_product(zw, fl(2:NDF:5))
            fl(3:NDF:5) = fl(3:NDF:5) + z*b1 + tw*b2
         end if
         if (blk%failed(i)) then
            de = 0.0_wp; fl = 0.0_wp
         end if
         blk%eint(i) = blk%eint(i) + de
         res%deint = res%deint + de
         if (.not. (area > 0.0_wp)) then
            ierr(i) = ELEM_ERR_NEGVOL
            area = 1.0_wp
         end if
         do k = 1, NEN
            nn = blk%conn(k, i)
            f(:, nn) = f(:, nn) - (fl(5*k - 4)*e(:, 1) + fl(5*k - 3)*e(:, 2) + &
                                   fl(5*k - 2)*e(:, 3))
            mom(:, nn) = mom(:, nn) - (fl(5*k - 1)*e(:, 1) + fl(5*k)*e(:, 2))
         end do
         if (istupd == 1) blk%es(i, c0) = thk(i)*(1.0_wp + dzt(i))
         blk%relvol(i) = area*blk%es(i, c0)/blk%vol0(i)
         ! stable step: as dx_shell_bt (LS-DYNA's shell step, ISDO = 0)
         tri = blk%conn(3, i) == blk%conn(4, i) .or. all(xe(:, 3) == xe(:, 4))
         lmax = max(norm2(xe(:, 2) - xe(:, 1)), norm2(xe(:, 3) - xe(:, 2)))
         if (tri) then
            lmax = max(lmax, norm2(xe(:, 1) - xe(:, 3)))
            rhs = 2.0_wp*area/lmax
         else
            lmax = max(lmax, norm2(xe(:, 4) - xe(:, 3)), norm2(xe(:, 1) - xe(:, 4)))
            rhs = area/lmax
         end if
         rhs = rhs/cs
         if (blk%failed(i)) rhs = huge_wp
         if (rhs < res%dt) then
            res%dt = rhs; res%imin = i
         end if
         res%dte(i) = rhs
      end do
      do i = 1, n
         if (ierr(i) /= 0) then
            res%ibad = i
            res%errcode = merge(ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, ierr(i) == ELEM_ERR_NEGVOL)
            exit
         end if
      end do
   end subroutine shell_fi_block

   !> vl(1:2, k) += zw_k (b1.vz, b2.vz): removes the in-plane velocities (w_y zw, -w_x zw) of
   !> the rigid rotation w_x = b2.vz, w_y = -b1.vz of the element about its in-plane axes at
   !> the nodes' offsets zw from the mean plane (a warped element; the rotation part of the
   !> projection of Belytschko & Leviathan 1994, CMAME 113:321-350). The forces take its
   !> transpose: f_vz += b1 (zw.f_x) + b2 (zw.f_y).
   pure subroutine unwarp(vl, zw, b1, b2)
      real(wp), intent(inout) :: vl(3, 4)
      real(wp), intent(in) :: zw(4), b1(4), b2(4)
      real(wp) :: ox, oy
      oy = dot_product(b1, vl(3, :)); ox = dot_product(b2, vl(3, :))
      vl(1, :) = vl(1, :) + zw*oy
      vl(2, :) = vl(2, :) + zw*ox
   end subroutine unwarp

   !> Turns the in-plane stresses of n points by the angle of cosine c, sine s about the
   !> normal (the transverse shears as a vector). The BT shell has its own private copy:
   !> making that one public changed the compiler's inlining of dx_shell_bt and so the last
   !> bits of every BT run, which must stay as they are.
   pure subroutine turn_stress(n, c, s, sig)
      integer, intent(in) :: n
      real(wp), intent(in) :: c(:), s(:)
      real(wp), intent(inout) :: sig(:, :)
      real(wp) :: sxx, syy, sxy, syz, sxz
      integer :: i
      do i = 1, n
         sxx = sig(i, 1); syy = sig(i, 2); sxy = sig(i, 4); syz = sig(i, 5); sxz = sig(i, 6)
         sig(i, 1) = c(i)**2*sxx - 2.0_wp*c(i)*s(i)*sxy + s(i)**2*syy
         sig(i, 2) = s(i)**2*sxx + 2.0_wp*c(i)*s(i)*sxy + c(i)**2*syy
         sig(i, 4) = c(i)*s(i)*(sxx - syy) + (c(i)**2 - s(i)**2)*sxy
         sig(i, 6) = c(i)*sxz - s(i)*syz
         sig(i, 5) = s(i)*sxz + c(i)*syz
      end do
   end subroutine turn_stress

   !> r += the resultants (N, M, Q) of one lamina of stresses s (xx, yy, xy, yz, zx) at z with
   !> weight tw
   pure subroutine add_resultants(r, s, tw, z)
      real(wp), intent(inout) :: r(8)
      real(wp), intent(in) :: s(5), tw, z
      r(1:3) = r(1:3) + tw*s(1:3)
      r(4:6) = r(4:6) + tw*z*s(1:3)
      r(7:8) = r(7:8) + tw*s(4:5)
   end subroutine add_resultants
end module dx_shell_fi
