!> Belytschko-Lin-Tsay shell (ELFORM 2 of *SECTION_SHELL) over one element block: the
!> 4-node co-rotational plate element with one in-plane integration point, Mindlin
!> kinematics (the fibre is the local normal e3) and NIP points through the thickness
!> (Belytschko, Lin & Tsay 1984, "Explicit algorithms for the nonlinear dynamics of shells",
!> CMAME 42:225-251; Hallquist, LS-DYNA Theory Manual, "Belytschko-Lin-Tsay shell").
!> Co-rotational frame of the mid-surface: e3 = s31 x s42/|.|, e1 = s21 - (s21.e3) e3
!> normalised, e2 = e3 x e1 (sIJ = x_I - x_J); a triangle repeats N3 (the degenerate quad).
!> Stresses live in this frame, so a rigid rotation leaves them unchanged; the in-plane spin
!> of the material relative to the frame (which follows side 1-2) turns them exactly (the
!> Jaumann rate written in the rotating frame, so the stress does not depend on which side
!> is N1-N2; Belytschko, Liu & Moran 2000, sec. 5.4 and 9.5).
!> Velocity strains at the one point, local axes, B1_I = dN_I/dx, B2_I = dN_I/dy
!> (B1 = [y24, y31, y42, y13]/2A, B2 = [x42, x13, x24, x31]/2A), z through the thickness:
!>   d_xx = B1.vx + z B1.wy,  d_yy = B2.vy - z B2.wx,
!>   2d_xy = B2.vx + B1.vy + z (B2.wy - B1.wx),
!>   2d_xz = B1.vz + (sum wy)/4,  2d_yz = B2.vz - (sum wx)/4 (the shear resultants times
!>   SHRF, the transverse shear factor).
!> They are taken at the mid-step geometry x(n) - dt/2 v(n-1/2), so a rigid rotation gives
!> exactly zero strain; the forces use B of x(n) (as dx_hex8 does) projected on the same
!> mid-step frame, so stresses and forces share one frame (the patch test). Each lamina
!> calls the material's plane-stress update (material_t%update_plane_stress, sigma33 = 0;
!> engineering shear increments); resultants N, M, Q by Gauss (default) or Lobatto
!> (*CONTROL_SHELL INTGRD = 1) points on [-t/2, t/2]; nodal forces and moments are the
!> work-conjugates of the strain rates above.
!> Hourglass control (Belytschko & Tsay 1983, IJNME 19:405-419): gamma_I = h_I -
!> (h.x) B1_I - (h.y) B2_I, h = (1, -1, 1, -1); five modes (membrane x, y; out-of-plane w;
!> bending about x, y). IHQ 1-3: viscous, Q = c q_dot with c_m = QM rho c t sqrt(A)/4,
!> c_b = c_m t**2/12, c_w = c_b B.B; IHQ 4, 5: stiffness, Q += r q_dot dt with
!> r_m = QM E t A B.B/8, r_b = r_m t**2/12 (the plate's D in place of E t), r_w = r_b B.B
!> (the w mode bends the plate) - dynx's scaling of the paper's forms (docs/design.md,
!> "Shells"). Energy of both: dt/2 (Q(n-1) + Q(n)).q_dot (viscous: Q(n-1) as applied, the
!> centred work; docs/extreme-cases.md). The warping correction (BWC = 1 of *CONTROL_SHELL) is not implemented (the
!> reader refuses it): LS-DYNA's default BWC = 2 has none either.
!> Thickness update (*CONTROL_SHELL ISTUPD = 1): dt/t = the mean over the laminae of their
!> thickness strain increments (the material's dezz: -lambda/(lambda + 2G) (de_xx + de_yy)
!> when elastic, plastic incompressibility when yielding).
!> Stable step (LS-DYNA Theory Manual, "Time Step Control", shells, ISDO = 0):
!> dt = L/c, L = (1 + beta) A / max(L1, L2, L3, (1 - beta) L4), beta = 0 for the
!> quadrilateral and 1 for the triangle, c = sqrt(E/(rho (1 - nu**2))).
!> Lumped mass rho A t/4 per node; rotary inertia (element_rotary_inertia): the nodal mass
!> times max(t**2/12, A/8) (Belytschko, Lin & Tsay 1984 scale the rotary inertia so that
!> the rotations do not control the step: with A/8 the transverse-shear frequency of a
!> nodal rotation stays below the membrane one) times *CONTROL_SHELL ROTASCL.
module dx_shell_bt
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_THK, block_result_t, &
                               ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, shell_frame, shell_axes
   implicit none
   private
   public :: shell_bt_block, shell_bt_rotary_inertia, thickness_rule

   integer, parameter :: NEN = 4
   real(wp), parameter :: HG(4) = [1.0_wp, -1.0_wp, 1.0_wp, -1.0_wp]

contains

   !> Points zeta(1:nip) in [-1, 1] and weights (summing to 2) of the through-thickness
   !> rule: Gauss-Legendre (lobatto = .false., nip 1 to 5) or Gauss-Lobatto (nip 3 to 5);
   !> ok = .false. outside these ranges. Abramowitz & Stegun 1964, Tables 25.4 and 25.6.
   pure subroutine thickness_rule(nip, lobatto, zeta, wt, ok)
      integer, intent(in) :: nip
      logical, intent(in) :: lobatto
      real(wp), intent(out) :: zeta(:), wt(:)
      logical, intent(out) :: ok
      real(wp) :: a, b
      ok = .true.
      zeta = 0.0_wp; wt = 0.0_wp
      if (.not. lobatto) then
         select case (nip)
         case (1)
            zeta(1) = 0.0_wp; wt(1) = 2.0_wp
         case (2)
            a = 1.0_wp/sqrt(3.0_wp)
            zeta(1:2) = [-a, a]; wt(1:2) = 1.0_wp
         case (3)
            a = sqrt(0.6_wp)
            zeta(1:3) = [-a, 0.0_wp, a]; wt(1:3) = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
         case (4)
            a = sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp))
            b = sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp))
            zeta(1:4) = [-b, -a, a, b]
            wt(1:4) = [(18.0_wp - sqrt(30.0_wp))/36.0_wp, (18.0_wp + sqrt(30.0_wp))/36.0_wp, &
                       (18.0_wp + sqrt(30.0_wp))/36.0_wp, (18.0_wp - sqrt(30.0_wp))/36.0_wp]
         case (5)
            a = sqrt(5.0_wp - 2.0_wp*sqrt(10.0_wp/7.0_wp))/3.0_wp
            b = sqrt(5.0_wp + 2.0_wp*sqrt(10.0_wp/7.0_wp))/3.0_wp
            zeta(1:5) = [-b, -a, 0.0_wp, a, b]
            wt(1:5) = [(322.0_wp - 13.0_wp*sqrt(70.0_wp))/900.0_wp, &
                       (322.0_wp + 13.0_wp*sqrt(70.0_wp))/900.0_wp, 128.0_wp/225.0_wp, &
                       (322.0_wp + 13.0_wp*sqrt(70.0_wp))/900.0_wp, &
                       (322.0_wp - 13.0_wp*sqrt(70.0_wp))/900.0_wp]
         case default
            ok = .false.
         end select
      else
         select case (nip)
         case (3)
            zeta(1:3) = [-1.0_wp, 0.0_wp, 1.0_wp]; wt(1:3) = [1.0_wp, 4.0_wp, 1.0_wp]/3.0_wp
         case (4)
            a = 1.0_wp/sqrt(5.0_wp)
            zeta(1:4) = [-1.0_wp, -a, a, 1.0_wp]
            wt(1:4) = [1.0_wp, 5.0_wp, 5.0_wp, 1.0_wp]/6.0_wp
         case (5)
            a = sqrt(3.0_wp/7.0_wp)
            zeta(1:5) = [-1.0_wp, -a, 0.0_wp, a, 1.0_wp]
            wt(1:5) = [9.0_wp, 49.0_wp, 64.0_wp, 49.0_wp, 9.0_wp]/90.0_wp
         case default
            ok = .false.
         end select
      end if
   end subroutine thickness_rule

   !> B1 = dN/dx, B2 = dN/dy at the centre from local coordinates xl(2, 4) and the area.
   pure subroutine shell_b(xl, area, b1, b2)
      real(wp), intent(in) :: xl(2, 4), area
      real(wp), intent(out) :: b1(4), b2(4)
      real(wp) :: h
      h = 0.5_wp/area
      b1 = h*[xl(2, 2) - xl(2, 4), xl(2, 3) - xl(2, 1), xl(2, 4) - xl(2, 2), xl(2, 1) - xl(2, 3)]
      b2 = h*[xl(1, 4) - xl(1, 2), xl(1, 1) - xl(1, 3), xl(1, 2) - xl(1, 4), xl(1, 3) - xl(1, 1)]
   end subroutine shell_b

   !> Add the block's lumped rotary inertia to rinert: nodal mass rho A t/4 times
   !> rotascl*max(t**2/12, A/8), t the current thickness, A = V0/t0.
   subroutine shell_bt_rotary_inertia(blk, rho, rotascl, rinert)
      type(elem_block_t), intent(in) :: blk
      real(wp), intent(in) :: rho, rotascl
      real(wp), intent(inout) :: rinert(:)
      integer :: i, k, c
      real(wp) :: t, a, m
      c = blk%esc(ES_THK)
      do i = 1, blk%nel
         t = blk%es(i, c)
         a = blk%vol0(i)/t
         m = 0.25_wp*rho*blk%vol0(i)
         do k = 1, NEN
            rinert(blk%conn(k, i)) = rinert(blk%conn(k, i)) + &
                                     rotascl*m*max(t*t/12.0_wp, 0.125_wp*a)
         end do
      end do
   end subroutine shell_bt_rotary_inertia

   !> One explicit pass over a block of BT shells: x = x(n), v = v(n-1/2), w = w(n-1/2),
   !> dt_old = dt(n-1/2). Updates the lamina stresses to t(n), subtracts the internal
   !> forces from f and moments from mom; shrf, lobatto, istupd: section and *CONTROL_SHELL.
   subroutine shell_bt_block(blk, mat, part, shrf, lobatto, istupd, x, v, w, dt_old, f, &
                             mom, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: shrf
      logical, intent(in) :: lobatto
      integer, intent(in) :: istupd
      real(wp), intent(in) :: x(:, :), v(:, :), w(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :), mom(:, :)
      type(block_result_t), intent(out) :: res
      integer, parameter :: MAXIP = 5
      real(wp) :: dm(nv_chunk, 3), kap(nv_chunk, 3), gam(nv_chunk, 2), thk(nv_chunk)
      real(wp) :: rc(nv_chunk), rs(nv_chunk), rc2(nv_chunk), rs2(nv_chunk)
      real(wp) :: ea(3, 3), psi, ef(3, 3, nv_chunk), amf(nv_chunk)
      real(wp) :: rold(nv_chunk, 8), rnew(nv_chunk, 8)
      real(wp) :: de5(blk%nel, 5), s5(blk%nel, 5)
      real(wp) :: zeta(MAXIP), wt(MAXIP)
      real(wp) :: xe(3, 4), xm(3, 4), ve(3, 4), we(3, 4), vl(3, 4), wl(3, 4), e(3, 3)
      real(wp) :: xl(2, 4), b1(4), b2(4), area, am, gm(4), bb, fl(3, 4), ml(2, 4), hq(5)
      real(wp) :: qd(5), qold(5), r(5), cv, ym, nu, lam, g, cs, hdt, z, tw, lmax, de, dh
      real(wp) :: rhs, dzz, ez(blk%nel), dzt(nv_chunk)
      integer :: ierr(nv_chunk)
      integer :: i, k, n, nn, ip, c0, nip
      logical :: ok, tri
      n = blk%nel
      nip = blk%nip
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
      ! ---- velocity strains at the mid-step geometry, in its co-rotational frame
      do i = 1, n
         thk(i) = blk%es(i, c0)
         do k = 1, NEN
            nn = blk%conn(k, i)
            ve(:, k) = v(:, nn); we(:, k) = w(:, nn)
            xm(:, k) = x(:, nn) - hdt*ve(:, k)
         end do
         call shell_frame(xm, e, xl, am)
         ef(:, :, i) = e; amf(i) = am          ! (the forces' frame: built once a cycle)
         if (.not. (am > 0.0_wp)) then
            ierr(i) = ELEM_ERR_NEGVOL
            am = 1.0_wp
         end if
         call shell_b(xl, am, b1, b2)
         vl = matmul(transpose(e), ve)
         wl = matmul(transpose(e), we)
         dm(i, 1) = dot_product(b1, vl(1, :))
         dm(i, 2) = dot_product(b2, vl(2, :))
         dm(i, 3) = dot_product(b2, vl(1, :)) + dot_product(b1, vl(2, :))
         kap(i, 1) = dot_product(b1, wl(2, :))
         kap(i, 2) = -dot_product(b2, wl(1, :))
         kap(i, 3) = dot_product(b2, wl(2, :)) - dot_product(b1, wl(1, :))
         gam(i, 1) = dot_product(b2, vl(3, :)) - 0.25_wp*sum(wl(1, :))   ! yz
         gam(i, 2) = dot_product(b1, vl(3, :)) + 0.25_wp*sum(wl(2, :))   ! zx
         ! the stresses are held in the frame of x(n-1) (the last pass's x(n)); they turn
         ! with the material's in-plane spin, half a step to the mid-step frame here and half
         ! a step to the frame of x(n) after the update, each less the frame's own rotation
         ! (exact angle between the frames: the Jaumann rate in the rotating frame)
         psi = 0.25_wp*dt_old*(dot_product(b1, vl(2, :)) - dot_product(b2, vl(1, :)))
         call shell_axes(xm - hdt*ve, ea)
         z = psi - atan2(-dot_product(ea(:, 1), e(:, 2)), dot_product(ea(:, 1), e(:, 1)))
         rc(i) = cos(z); rs(i) = sin(z)
         call shell_axes(xm + hdt*ve, ea)
         z = psi - atan2(-dot_product(e(:, 1), ea(:, 2)), dot_product(e(:, 1), ea(:, 1)))
         rc2(i) = cos(z); rs2(i) = sin(z)
      end do
      ! ---- laminae: plane-stress update, resultants before (rold) and after (rnew)
      ! r(:, 1:3) N xx, yy, xy; 4:6 M xx, yy, xy; 7:8 Q yz, zx (per unit length)
      rold(1:n, :) = 0.0_wp; rnew(1:n, :) = 0.0_wp
      dzt(1:n) = 0.0_wp
      do ip = 1, nip
         call turn_stress(n, rc, rs, blk%sig(:, :, ip))
         do i = 1, n
            z = 0.5_wp*zeta(ip)*thk(i)
            de5(i, 1) = dt_old*(dm(i, 1) + z*kap(i, 1))
            de5(i, 2) = dt_old*(dm(i, 2) + z*kap(i, 2))
            de5(i, 3) = dt_old*(dm(i, 3) + z*kap(i, 3))
            de5(i, 4) = dt_old*gam(i, 1)
            de5(i, 5) = dt_old*gam(i, 2)
            s5(i, 1) = blk%sig(i, 1, ip); s5(i, 2) = blk%sig(i, 2, ip)
            s5(i, 3) = blk%sig(i, 4, ip); s5(i, 4) = blk%sig(i, 5, ip)
            s5(i, 5) = blk%sig(i, 6, ip)
            tw = 0.5_wp*wt(ip)*thk(i)
            call add_resultants(rold(i, :), s5(i, :), tw, z)
         end do
         call mat%update_plane_stress(n, dt_old, de5, s5, blk%hv(:, :, ip), ierr, ez)
         do i = 1, n
            dzt(i) = dzt(i) + 0.5_wp*wt(ip)*ez(i)     ! mean thickness strain increment
            z = 0.5_wp*zeta(ip)*thk(i)
            tw = 0.5_wp*wt(ip)*thk(i)
            if (blk%failed(i)) s5(i, :) = 0.0_wp
            blk%sig(i, 1, ip) = s5(i, 1); blk%sig(i, 2, ip) = s5(i, 2)
            blk%sig(i, 3, ip) = 0.0_wp
            blk%sig(i, 4, ip) = s5(i, 3); blk%sig(i, 5, ip) = s5(i, 4)
            blk%sig(i, 6, ip) = s5(i, 5)
            call add_resultants(rnew(i, :), s5(i, :), tw, z)
         end do
         call turn_stress(n, rc2, rs2, blk%sig(:, :, ip))
      end do
      ! the transverse shear resultants carry the shear factor SHRF
      rold(1:n, 7:8) = shrf*rold(1:n, 7:8)
      rnew(1:n, 7:8) = shrf*rnew(1:n, 7:8)
      ! ---- forces at x(n): frame, B, energy, hourglass, scatter, time step
      do i = 1, n
         do k = 1, NEN
            nn = blk%conn(k, i)
            xe(:, k) = x(:, nn); ve(:, k) = v(:, nn); we(:, k) = w(:, nn)
         end do
         ! the frame of the stresses (the mid-step one, kept from the strain pass); the
         ! geometry of x(n) in it
         e = ef(:, :, i); am = amf(i)
         do k = 1, NEN
            xl(1, k) = dot_product(e(:, 1), xe(:, k) - xe(:, 1))
            xl(2, k) = dot_product(e(:, 2), xe(:, k) - xe(:, 1))
         end do
         area = 0.5_wp*((xl(1, 3) - xl(1, 1))*(xl(2, 4) - xl(2, 2)) - &
                        (xl(1, 4) - xl(1, 2))*(xl(2, 3) - xl(2, 1)))
         ! work of the stress resultants over the step (trapezoid in the resultants)
         de = dt_old*am*( &
              0.5_wp*(rold(i, 1) + rnew(i, 1))*dm(i, 1) + 0.5_wp*(rold(i, 2) + rnew(i, 2))*dm(i, 2) &
            + 0.5_wp*(rold(i, 3) + rnew(i, 3))*dm(i, 3) + 0.5_wp*(rold(i, 4) + rnew(i, 4))*kap(i, 1) &
            + 0.5_wp*(rold(i, 5) + rnew(i, 5))*kap(i, 2) + 0.5_wp*(rold(i, 6) + rnew(i, 6))*kap(i, 3) &
            + 0.5_wp*(rold(i, 7) + rnew(i, 7))*gam(i, 1) + 0.5_wp*(rold(i, 8) + rnew(i, 8))*gam(i, 2))
         if (blk%failed(i)) de = 0.0_wp
         blk%eint(i) = blk%eint(i) + de
         res%deint = res%deint + de
         if (.not. (area > 0.0_wp)) then
            ierr(i) = ELEM_ERR_NEGVOL
            area = 1.0_wp
         end if
         call shell_b(xl, area, b1, b2)
         vl = matmul(transpose(e), ve)
         wl = matmul(transpose(e), we)
         associate (rn => rnew(i, :))
            do k = 1, NEN
               fl(1, k) = area*(b1(k)*rn(1) + b2(k)*rn(3))
               fl(2, k) = area*(b2(k)*rn(2) + b1(k)*rn(3))
               fl(3, k) = area*(b1(k)*rn(8) + b2(k)*rn(7))
               ml(1, k) = area*(-b2(k)*rn(5) - b1(k)*rn(6) - 0.25_wp*rn(7))
               ml(2, k) = area*(b1(k)*rn(4) + b2(k)*rn(6) + 0.25_wp*rn(8))
            end do
         end associate
         ! hourglass: rates of the five modes, viscous or stiffness generalized forces
         gm = HG - dot_product(HG, xl(1, :))*b1 - dot_product(HG, xl(2, :))*b2
         bb = sum(b1*b1) + sum(b2*b2)
         qd = [dot_product(gm, vl(1, :)), dot_product(gm, vl(2, :)), &
               dot_product(gm, vl(3, :)), dot_product(gm, wl(1, :)), dot_product(gm, wl(2, :))]
         dh = 0.0_wp
         if (part%qh > 0.0_wp) then
            qold = blk%es(i, c0 + 1:c0 + 5)
            if (part%ihq >= 4) then
               r(1:2) = part%qh*ym*thk(i)*area*bb/8.0_wp
               r(4:5) = r(1)*thk(i)**2/12.0_wp
               r(3) = r(4)*bb
               hq = qold + dt_old*r*qd
            else
               cv = 0.25_wp*part%qh*mat%ro*cs*thk(i)*sqrt(area)
               r(1:2) = cv
               r(4:5) = cv*thk(i)**2/12.0_wp
               r(3) = r(4)*bb
               hq = r*qd
            end if
            ! the trapezoid of the last pass's and this pass's generalized forces: the spring
            ! energy (stiffness), the centred work of the force as applied (viscous; with
            ! dt |qd|**2 r alone a mode that flips each step was overcounted, issue 23)
            blk%es(i, c0 + 1:c0 + 5) = hq
            dh = dt_old*dot_product(0.5_wp*(qold + hq), qd)
            do k = 1, NEN
               fl(:, k) = fl(:, k) + gm(k)*hq(1:3)
               ml(:, k) = ml(:, k) + gm(k)*hq(4:5)
            end do
         end if
         if (blk%failed(i)) then
            fl = 0.0_wp; ml = 0.0_wp; dh = 0.0_wp
         end if
         blk%ehg(i) = blk%ehg(i) + dh
         res%dehg = res%dehg + dh
         do k = 1, NEN
            nn = blk%conn(k, i)
            f(:, nn) = f(:, nn) - (fl(1, k)*e(:, 1) + fl(2, k)*e(:, 2) + fl(3, k)*e(:, 3))
            mom(:, nn) = mom(:, nn) - (ml(1, k)*e(:, 1) + ml(2, k)*e(:, 2))
         end do
         ! thickness update (ISTUPD = 1) and the relative volume
         if (istupd == 1) then
            dzz = dzt(i)
            blk%es(i, c0) = thk(i)*(1.0_wp + dzz)
         end if
         blk%relvol(i) = area*blk%es(i, c0)/blk%vol0(i)
         ! stable step: L = (1 + beta) A / max(L1, L2, L3, (1 - beta) L4)
         ! (a triangle repeats N3; under MPI a shared N3 has one slot node per corner,
         ! each holding the node's x: the coordinates tell it too)
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
   end subroutine shell_bt_block

   !> sigma <- R sigma R^T in the plane, (tau_zx, tau_yz) <- R tau, R the rotation by the
   !> angle of cosine c and sine s, for the n first elements of sig(:, 6) (xx yy zz xy yz zx)
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

   !> r += the resultants of one lamina (stresses s: xx, yy, xy, yz, zx) at z with weight tw
   pure subroutine add_resultants(r, s, tw, z)
      real(wp), intent(inout) :: r(8)
      real(wp), intent(in) :: s(5), tw, z
      r(1:3) = r(1:3) + tw*s(1:3)
      r(4:6) = r(4:6) + tw*z*s(1:3)
      r(7:8) = r(7:8) + tw*s(4:5)
   end subroutine add_resultants
end module dx_shell_bt
