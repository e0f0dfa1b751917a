!> Hex8 element kernels over one element block (at most nv_chunk elements): gather nodal
!> coordinates and velocities, strain increment at the mid-step geometry, Jaumann rotation,
!> material update (one dispatch per block), bulk viscosity, hourglass control, internal force
!> scatter, internal/hourglass energy and the element stable time step.
!> ELFORM 1: uniform-strain one-point hex with hourglass control (Flanagan & Belytschko 1981,
!> IJNME 17:679-706): IHQ 1 = viscous on the base vectors Gamma (Kosloff-Frasier / DYNA
!> standard), IHQ 2,3 = viscous on the FB orthogonal vectors gamma, IHQ 4,5 = stiffness on
!> gamma (B vectors are already the exact volume integrals, so 3 = 2 and 5 = 4 here).
!> ELFORM 2: 2x2x2 selectively reduced (mean-dilatation) hex, no hourglass modes
!> (Hughes 1980, IJNME 15:1413-1418; Nagtegaal, Parks & Rice 1974).
!> Bulk viscosity (DYNA form): q = rho*l*(Q1*l*e_kk**2 - Q2*c*e_kk) for e_kk < 0, l = V**(1/3);
!> time step dt_e = L/(Q + sqrt(Q**2 + c**2)), Q = Q2*c + Q1*L*|e_kk| (LS-DYNA Theory Manual).
!> Viscous hourglass coefficient a_h = QH*rho*c*V**(2/3)/4 (LS-DYNA Theory Manual, U);
!> stiffness k_h = QH*(K + 4G/3)*sum(B_iI**2)/(8V) (dynx choice, see docs/theory/hex8.md).
module dx_hex8
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_model, only: elem_block_t, part_t
   use dx_material, only: material_t
   use dx_hex8_geometry, only: hex8_bvectors, hex8_char_length, inv3, GAMMA_HG, XI_NODE
   implicit none
   private
   public :: hex8_block, HEX_ERR_NEGVOL, HEX_ERR_MATERIAL, hex8_volume

   integer, parameter :: HEX_ERR_NEGVOL = 1, HEX_ERR_MATERIAL = 2

   !> results of one block pass
   type, public :: block_result_t
      real(wp) :: dt = huge_wp        !< smallest element time step (without TSSFAC)
      integer :: imin = 0             !< its position in the block
      integer :: ibad = 0             !< first element in error (position), 0 = none
      integer :: errcode = 0
      real(wp) :: deint = 0.0_wp      !< internal energy increment of the block
      real(wp) :: dehg = 0.0_wp       !< hourglass energy increment of the block
   end type block_result_t

contains

   !> l(1:n) = x(1:n)**(1/3) from exactly rounded operations only, so a vectorized loop
   !> gives every element the same bits in every lane and in the scalar remainder. (pow not:
   !> gfortran pre-includes glibc's math-vector-fortran.h, and the vector body then calls
   !> libmvec's SIMD pow, the remainder scalar libm pow; an element's result depended on its
   !> position in its block, and an MPI rank's piece of a block changes positions.)
   !> Start: the bit pattern of x divided by 3 plus the exponent bias term (the classic
   !> cbrt start, as in FreeBSD's s_cbrt.c; within 3.3 % here), done through a double so the
   !> loop vectorizes; then two steps of Halley's iteration l <- l (l^3 + 2x)/(2 l^3 + x)
   !> (cubic convergence; Traub 1964, Iterative Methods for the Solution of Equations,
   !> sec. 8.4) and one Newton step: within 3 ulp of the correctly rounded cube root on
   !> 1e-90..1e90 (2e5 random samples; pow(x, 1/3) is itself off by up to 16 ulp at
   !> 1e+-40, 1/3 not being a double). Valid for volumes in 1e-90..1e90 (any consistent
   !> units); x <= 0 gives 0. One loop without calls, so it vectorizes; integer/real
   !> conversions, +, *, / are exact or correctly rounded in every lane.
   subroutine cube_roots(n, x, l)
      integer, intent(in) :: n
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: l(:)
      integer(int64), parameter :: CBRT_BIAS = 3071306043645493248_int64   ! 715094163*2**32
      real(wp) :: y, r, r3
      integer :: i
      do i = 1, n
         y = max(x(i), 1.0e-90_wp)
         r = transfer(int(real(transfer(y, 0_int64), wp)/3.0_wp, int64) + CBRT_BIAS, 1.0_wp)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r = r - (r*r*r - y)/(3.0_wp*r*r)
         l(i) = merge(r, 0.0_wp, x(i) > 0.0_wp)
      end do
   end subroutine cube_roots

   !> Volumes of the elements of a block at coordinates x(3,nn).
   subroutine hex8_volume(blk, x, vol)
      type(elem_block_t), intent(in) :: blk
      real(wp), intent(in) :: x(:, :)
      real(wp), intent(out) :: vol(:)
      real(wp), dimension(nv_chunk, 8) :: xe, ye, ze, bx, by, bz
      real(wp) :: v(nv_chunk)
      integer :: i, a, n
      n = blk%nel
      do a = 1, 8
         do i = 1, n
            xe(i, a) = x(1, blk%conn(a, i)); ye(i, a) = x(2, blk%conn(a, i))
            ze(i, a) = x(3, blk%conn(a, i))
         end do
      end do
      call hex8_bvectors(n, nv_chunk, xe, ye, ze, bx, by, bz, v)
      vol(1:n) = v(1:n)
   end subroutine hex8_volume

   !> One explicit pass over a block: x = x(n), v = v(n-1/2), dt_old = dt(n-1/2).
   !> Updates stress/history to t(n) and subtracts the internal force from f.
   subroutine hex8_block(blk, mat, part, x, v, dt_old, f, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      select case (blk%nip)
      case (1)
         call hex8_1pt(blk, mat, part, x, v, dt_old, f, res)
      case default
         call hex8_sri(blk, mat, part, x, v, dt_old, f, res)
      end select
   end subroutine hex8_block

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

   subroutine hex8_1pt(blk, mat, part, x, v, dt_old, f, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), dimension(blk%nel, 8) :: xe, ye, ze, vx, vy, vz, bx, by, bz, xm, ym, zm, fx, fy, fz
      real(wp), dimension(blk%nel) :: vol, volm, rv, c, q, trd, w12, w23, w31, ein, alive, ah
      real(wp) :: deps(blk%nel, 6), sold(blk%nel, 6), l(3, 3), hx(4), hy(4), hz(4), qx(4), qy(4), qz(4)
      real(wp) :: g(4, 8), rho, dtl, rvm, a, kh, bb, hgsum, ein_sum, ehg_sum
      real(wp) :: lv(blk%nel)          ! V**(1/3)
      integer :: ierr(blk%nel)
      logical :: failed(blk%nel)
      integer :: i, k, n, nn, ihq
      n = blk%nel
      ihq = part%ihq
      ! ---- gather
      do k = 1, 8
         do i = 1, n
            nn = blk%conn(k, i)
            xe(i, k) = x(1, nn); ye(i, k) = x(2, nn); ze(i, k) = x(3, nn)
            vx(i, k) = v(1, nn); vy(i, k) = v(2, nn); vz(i, k) = v(3, nn)
         end do
      end do
      ! ---- mid-step geometry x(n-1/2) = x(n) - dt/2 v(n-1/2): strain increment and spin
      do k = 1, 8
         do i = 1, n
            xm(i, k) = xe(i, k) - 0.5_wp*dt_old*vx(i, k)
            ym(i, k) = ye(i, k) - 0.5_wp*dt_old*vy(i, k)
            zm(i, k) = ze(i, k) - 0.5_wp*dt_old*vz(i, k)
         end do
      end do
      call hex8_bvectors(n, n, xm, ym, zm, bx, by, bz, volm)
      ierr = 0
      do i = 1, n
         if (.not. (volm(i) > 0.0_wp)) ierr(i) = HEX_ERR_NEGVOL
         if (.not. (volm(i) > 0.0_wp)) volm(i) = 1.0_wp
         alive(i) = merge(0.0_wp, 1.0_wp, blk%failed(i))
      end do
      do i = 1, n
         l = 0.0_wp
         do k = 1, 8
            l(1, 1) = l(1, 1) + vx(i, k)*bx(i, k)
            l(1, 2) = l(1, 2) + vx(i, k)*by(i, k)
            l(1, 3) = l(1, 3) + vx(i, k)*bz(i, k)
            l(2, 1) = l(2, 1) + vy(i, k)*bx(i, k)
            l(2, 2) = l(2, 2) + vy(i, k)*by(i, k)
            l(2, 3) = l(2, 3) + vy(i, k)*bz(i, k)
            l(3, 1) = l(3, 1) + vz(i, k)*bx(i, k)
            l(3, 2) = l(3, 2) + vz(i, k)*by(i, k)
            l(3, 3) = l(3, 3) + vz(i, k)*bz(i, k)
         end do
         dtl = dt_old/volm(i)
         deps(i, 1) = l(1, 1)*dtl
         deps(i, 2) = l(2, 2)*dtl
         deps(i, 3) = l(3, 3)*dtl
         deps(i, 4) = 0.5_wp*(l(1, 2) + l(2, 1))*dtl
         deps(i, 5) = 0.5_wp*(l(2, 3) + l(3, 2))*dtl
         deps(i, 6) = 0.5_wp*(l(3, 1) + l(1, 3))*dtl
         w12(i) = 0.5_wp*(l(1, 2) - l(2, 1))*dtl
         w23(i) = 0.5_wp*(l(2, 3) - l(3, 2))*dtl
         w31(i) = 0.5_wp*(l(3, 1) - l(1, 3))*dtl
         trd(i) = (l(1, 1) + l(2, 2) + l(3, 3))/volm(i)
      end do
      ! ---- geometry at t(n): forces, volume, time step
      call hex8_bvectors(n, n, xe, ye, ze, bx, by, bz, vol)
      do i = 1, n
         if (.not. (vol(i) > 0.0_wp)) ierr(i) = HEX_ERR_NEGVOL
         if (.not. (vol(i) > 0.0_wp)) vol(i) = 1.0_wp
         rv(i) = vol(i)/blk%vol0(i)
         blk%relvol(i) = rv(i)
         ein(i) = blk%eint(i)/blk%vol0(i)
      end do
      call cube_roots(n, vol, lv)     ! V**(1/3): bulk viscosity, hourglass
      ! ---- stress: rotate, update
      call jaumann(n, n, w12, w23, w31, blk%sig(:, :, 1))
      sold(1:n, :) = blk%sig(1:n, :, 1)
      call mat%update(n, dt_old, deps, rv, ein, blk%sig(:, :, 1), blk%hv(:, :, 1), ierr)
      call mat%fails(n, blk%hv(:, :, 1), failed)
      call mat%wave_speed(n, rv, blk%hv(:, :, 1), c)
      ! ---- bulk viscosity and energies
      ein_sum = 0.0_wp
      do i = 1, n
         rho = mat%ro/rv(i)
         q(i) = bulk_viscosity(part, rho, lv(i), trd(i), c(i))
         rvm = 0.5_wp*volm(i)
         a = rvm*((sold(i,1) + blk%sig(i,1,1))*deps(i,1) + (sold(i,2) + blk%sig(i,2,1))*deps(i,2) &
             + (sold(i,3) + blk%sig(i,3,1))*deps(i,3) + 2.0_wp*((sold(i,4) + blk%sig(i,4,1)) &
             *deps(i,4) + (sold(i,5) + blk%sig(i,5,1))*deps(i,5) + (sold(i,6) + blk%sig(i,6,1)) &
             *deps(i,6))) - q(i)*trd(i)*dt_old*volm(i)
         a = a*alive(i)
         blk%eint(i) = blk%eint(i) + a
         ein_sum = ein_sum + a
      end do
      res%deint = ein_sum
      ! ---- erosion
      do i = 1, n
         if (failed(i) .and. .not. blk%failed(i)) then
            blk%failed(i) = .true.
            alive(i) = 0.0_wp
         end if
         if (blk%failed(i)) blk%sig(i, :, 1) = 0.0_wp
      end do
      ! ---- internal force f_iI = (sig_ij - q delta_ij) B_jI
      do k = 1, 8
         do i = 1, n
            fx(i, k) = alive(i)*((blk%sig(i,1,1) - q(i))*bx(i,k) + blk%sig(i,4,1)*by(i,k) &
                       + blk%sig(i,6,1)*bz(i,k))
            fy(i, k) = alive(i)*(blk%sig(i,4,1)*bx(i,k) + (blk%sig(i,2,1) - q(i))*by(i,k) &
                       + blk%sig(i,5,1)*bz(i,k))
            fz(i, k) = alive(i)*(blk%sig(i,6,1)*bx(i,k) + blk%sig(i,5,1)*by(i,k) &
                       + (blk%sig(i,3,1) - q(i))*bz(i,k))
         end do
      end do
      ! ---- hourglass control
      ehg_sum = 0.0_wp
      if (part%qh > 0.0_wp) then
         do i = 1, n
            rho = mat%ro/rv(i)
            ah(i) = part%qh*rho*c(i)*lv(i)**2/4.0_wp
         end do
         do i = 1, n
            ! hourglass shape vectors: Gamma (IHQ 1) or FB gamma (IHQ 2-5)
            if (ihq == 1) then
               g = GAMMA_HG
            else
               do k = 1, 4
                  hx(k) = sum(GAMMA_HG(k, :)*xe(i, :))
                  hy(k) = sum(GAMMA_HG(k, :)*ye(i, :))
                  hz(k) = sum(GAMMA_HG(k, :)*ze(i, :))
               end do
               do k = 1, 8
                  g(:, k) = GAMMA_HG(:, k) - (hx*bx(i, k) + hy*by(i, k) + hz*bz(i, k))/vol(i)
               end do
            end if
            do k = 1, 4
               qx(k) = sum(g(k, :)*vx(i, :))
               qy(k) = sum(g(k, :)*vy(i, :))
               qz(k) = sum(g(k, :)*vz(i, :))
            end do
            if (ihq >= 4) then
               bb = sum(bx(i, :)**2 + by(i, :)**2 + bz(i, :)**2)
               kh = part%qh*(mat%bulk + 4.0_wp*mat%shear/3.0_wp)*bb/(8.0_wp*vol(i))
               do k = 1, 4
                  ! corotate the stored resisting forces, then add the stiffness increment
                  hx(k) = blk%hgs(i, 1, k) + w12(i)*blk%hgs(i, 2, k) - w31(i)*blk%hgs(i, 3, k)
                  hy(k) = blk%hgs(i, 2, k) - w12(i)*blk%hgs(i, 1, k) + w23(i)*blk%hgs(i, 3, k)
                  hz(k) = blk%hgs(i, 3, k) + w31(i)*blk%hgs(i, 1, k) - w23(i)*blk%hgs(i, 2, k)
                  blk%hgs(i, 1, k) = hx(k) + kh*dt_old*qx(k)
                  blk%hgs(i, 2, k) = hy(k) + kh*dt_old*qy(k)
                  blk%hgs(i, 3, k) = hz(k) + kh*dt_old*qz(k)
               end do
               hx = blk%hgs(i, 1, :); hy = blk%hgs(i, 2, :); hz = blk%hgs(i, 3, :)
            else
               hx = ah(i)*qx; hy = ah(i)*qy; hz = ah(i)*qz
            end if
            hx = hx*alive(i); hy = hy*alive(i); hz = hz*alive(i)
            hgsum = dt_old*sum(hx*qx + hy*qy + hz*qz)
            blk%ehg(i) = blk%ehg(i) + hgsum
            ehg_sum = ehg_sum + hgsum
            do k = 1, 8
               fx(i, k) = fx(i, k) + sum(hx*g(:, k))
               fy(i, k) = fy(i, k) + sum(hy*g(:, k))
               fz(i, k) = fz(i, k) + sum(hz*g(:, k))
            end do
         end do
      end if
      res%dehg = ehg_sum
      ! ---- scatter (internal force is subtracted)
      do k = 1, 8
         do i = 1, n
            nn = blk%conn(k, i)
            f(1, nn) = f(1, nn) - fx(i, k)
            f(2, nn) = f(2, nn) - fy(i, k)
            f(3, nn) = f(3, nn) - fz(i, k)
         end do
      end do
      ! ---- stable time step
      call stable_time_step(blk, part, xe, ye, ze, vol, trd, c, res)
      call first_error(n, ierr, res)
   end subroutine hex8_1pt

   !> DYNA bulk viscosity q = rho*l*(Q1*l*e_kk**2 - Q2*c*e_kk) for e_kk < 0, l = V**(1/3).
   pure real(wp) function bulk_viscosity(part, rho, l, trd, c) result(q)
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: rho, l, trd, c
      q = 0.0_wp
      if (trd < 0.0_wp) then
         q = rho*l*(part%q1*l*trd**2 - part%q2*c*trd)
      end if
   end function bulk_viscosity

   !> Smallest element step L/(Q + sqrt(Q**2 + c**2)), L = V/A_max, Q = Q2*c + Q1*L*|e_kk|
   !> (compression only); eroded elements do not count.
   subroutine stable_time_step(blk, part, xe, ye, ze, vol, trd, c, res)
      type(elem_block_t), intent(in) :: blk
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: xe(:, :), ye(:, :), ze(:, :), vol(:), trd(:), c(:)
      type(block_result_t), intent(inout) :: res
      real(wp) :: lc(blk%nel), qb, trde
      integer :: i, n
      n = blk%nel
      call hex8_char_length(n, n, xe, ye, ze, vol, lc)
      do i = 1, n
         qb = 0.0_wp
         if (trd(i) < 0.0_wp) qb = part%q2*c(i) + part%q1*lc(i)*abs(trd(i))
         trde = lc(i)/(qb + sqrt(qb*qb + c(i)*c(i)))
         if (blk%failed(i)) trde = huge_wp
         if (trde < res%dt) then
            res%dt = trde; res%imin = i
         end if
      end do
   end subroutine stable_time_step

   subroutine first_error(n, ierr, res)
      integer, intent(in) :: n, ierr(:)
      type(block_result_t), intent(inout) :: res
      integer :: i
      do i = 1, n
         if (ierr(i) /= 0) then
            res%ibad = i
            res%errcode = merge(HEX_ERR_NEGVOL, HEX_ERR_MATERIAL, ierr(i) == HEX_ERR_NEGVOL)
            return
         end if
      end do
   end subroutine first_error

   !> ELFORM 2: 2x2x2 Gauss points, deviatoric strain per point, volumetric strain rate
   !> replaced by the element mean (mean dilatation); pressure work through the mean B.
   subroutine hex8_sri(blk, mat, part, x, v, dt_old, f, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), dimension(blk%nel, 8) :: xe, ye, ze, vx, vy, vz, bx, by, bz, xm, ym, zm, fx, fy, fz
      real(wp), dimension(blk%nel) :: vol, volm, rv, c, q, trd, w12, w23, w31, ein, alive, pbar
      real(wp) :: deps(blk%nel, 6), sold(blk%nel, 6), dn(3, 8, 8), dnx(3, 8), l(3, 3)
      real(wp) :: p8(8), q8(8), r8(8)
      real(wp), allocatable :: dng(:, :, :, :)
      real(wp) :: jwg(8, blk%nel), wm(blk%nel), dtl, rho, a, trp, pm, ein_sum
      real(wp) :: lv(blk%nel)          ! V**(1/3)
      integer :: ierr(blk%nel)
      logical :: failed(blk%nel), fpt(blk%nel)
      integer :: i, k, n, nn, ip
      n = blk%nel
      allocate(dng(3, 8, 8, n))
      call shape_derivs(dn)
      do k = 1, 8
         do i = 1, n
            nn = blk%conn(k, i)
            xe(i, k) = x(1, nn); ye(i, k) = x(2, nn); ze(i, k) = x(3, nn)
            vx(i, k) = v(1, nn); vy(i, k) = v(2, nn); vz(i, k) = v(3, nn)
            xm(i, k) = xe(i, k) - 0.5_wp*dt_old*vx(i, k)
            ym(i, k) = ye(i, k) - 0.5_wp*dt_old*vy(i, k)
            zm(i, k) = ze(i, k) - 0.5_wp*dt_old*vz(i, k)
         end do
      end do
      ierr = 0
      call hex8_bvectors(n, n, xe, ye, ze, bx, by, bz, vol)
      call hex8_bvectors(n, n, xm, ym, zm, fx, fy, fz, volm)
      do i = 1, n
         if (.not. (volm(i) > 0.0_wp .and. vol(i) > 0.0_wp)) then
            ierr(i) = HEX_ERR_NEGVOL; volm(i) = 1.0_wp; vol(i) = 1.0_wp
         end if
         rv(i) = vol(i)/blk%vol0(i)
         blk%relvol(i) = rv(i)
         ein(i) = blk%eint(i)/blk%vol0(i)
         alive(i) = merge(0.0_wp, 1.0_wp, blk%failed(i))
      end do
      call cube_roots(n, vol, lv)     ! V**(1/3) for the bulk viscosity
      ! mean volumetric rate: (1/V) sum_I v_I . B_I at mid-step (B held in fx, fy, fz here)
      do i = 1, n
         trd(i) = sum(vx(i, :)*fx(i, :) + vy(i, :)*fy(i, :) + vz(i, :)*fz(i, :))/volm(i)
      end do
      ein_sum = 0.0_wp
      fx = 0.0_wp; fy = 0.0_wp; fz = 0.0_wp
      pbar = 0.0_wp
      fpt = .false.
      ! geometry at t(n) per Gauss point for the forces
      do i = 1, n
         p8 = xe(i, :); q8 = ye(i, :); r8 = ze(i, :)
         call point_gradients(dn, p8, q8, r8, dng(:, :, :, i), jwg(:, i))
      end do
      do ip = 1, 8
         do i = 1, n
            p8 = xm(i, :); q8 = ym(i, :); r8 = zm(i, :)
            call point_gradients_one(dn(:, :, ip), p8, q8, r8, dnx, wm(i))
            l = 0.0_wp
            do k = 1, 8
               l(1, :) = l(1, :) + vx(i, k)*dnx(:, k)
               l(2, :) = l(2, :) + vy(i, k)*dnx(:, k)
               l(3, :) = l(3, :) + vz(i, k)*dnx(:, k)
            end do
            trp = (l(1, 1) + l(2, 2) + l(3, 3) - trd(i))/3.0_wp
            dtl = dt_old
            deps(i, 1) = (l(1, 1) - trp)*dtl
            deps(i, 2) = (l(2, 2) - trp)*dtl
            deps(i, 3) = (l(3, 3) - trp)*dtl
            deps(i, 4) = 0.5_wp*(l(1, 2) + l(2, 1))*dtl
            deps(i, 5) = 0.5_wp*(l(2, 3) + l(3, 2))*dtl
            deps(i, 6) = 0.5_wp*(l(3, 1) + l(1, 3))*dtl
            w12(i) = 0.5_wp*(l(1, 2) - l(2, 1))*dtl
            w23(i) = 0.5_wp*(l(2, 3) - l(3, 2))*dtl
            w31(i) = 0.5_wp*(l(3, 1) - l(1, 3))*dtl
         end do
         call jaumann(n, n, w12, w23, w31, blk%sig(:, :, ip))
         sold(1:n, :) = blk%sig(1:n, :, ip)
         call mat%update(n, dt_old, deps, rv, ein, blk%sig(:, :, ip), blk%hv(:, :, ip), ierr)
         call mat%fails(n, blk%hv(:, :, ip), failed)
         fpt = fpt .or. failed
         do i = 1, n
            a = 0.5_wp*wm(i)*((sold(i,1) + blk%sig(i,1,ip))*deps(i,1) &
                + (sold(i,2) + blk%sig(i,2,ip))*deps(i,2) + (sold(i,3) + blk%sig(i,3,ip))*deps(i,3) &
                + 2.0_wp*((sold(i,4) + blk%sig(i,4,ip))*deps(i,4) &
                + (sold(i,5) + blk%sig(i,5,ip))*deps(i,5) + (sold(i,6) + blk%sig(i,6,ip))*deps(i,6)))
            a = a*alive(i)
            blk%eint(i) = blk%eint(i) + a
            ein_sum = ein_sum + a
            pm = (blk%sig(i,1,ip) + blk%sig(i,2,ip) + blk%sig(i,3,ip))/3.0_wp
            pbar(i) = pbar(i) + pm*jwg(ip, i)/vol(i)
            ! deviatoric part through the point gradients
            do k = 1, 8
               fx(i, k) = fx(i, k) + jwg(ip, i)*((blk%sig(i,1,ip) - pm)*dng(1,k,ip,i) &
                          + blk%sig(i,4,ip)*dng(2,k,ip,i) + blk%sig(i,6,ip)*dng(3,k,ip,i))
               fy(i, k) = fy(i, k) + jwg(ip, i)*(blk%sig(i,4,ip)*dng(1,k,ip,i) &
                          + (blk%sig(i,2,ip) - pm)*dng(2,k,ip,i) + blk%sig(i,5,ip)*dng(3,k,ip,i))
               fz(i, k) = fz(i, k) + jwg(ip, i)*(blk%sig(i,6,ip)*dng(1,k,ip,i) &
                          + blk%sig(i,5,ip)*dng(2,k,ip,i) + (blk%sig(i,3,ip) - pm)*dng(3,k,ip,i))
            end do
         end do
      end do
      call mat%wave_speed(n, rv, blk%hv(:, :, 1), c)
      ! bulk viscosity, mean pressure through the exact mean B, erosion
      do i = 1, n
         rho = mat%ro/rv(i)
         q(i) = bulk_viscosity(part, rho, lv(i), trd(i), c(i))
         a = -q(i)*trd(i)*dt_old*vol(i)*alive(i)
         blk%eint(i) = blk%eint(i) + a
         ein_sum = ein_sum + a
         if (fpt(i)) blk%failed(i) = .true.
         if (blk%failed(i)) then
            alive(i) = 0.0_wp
            blk%sig(i, :, :) = 0.0_wp
         end if
      end do
      res%deint = ein_sum
      do k = 1, 8
         do i = 1, n
            fx(i, k) = alive(i)*(fx(i, k) + (pbar(i) - q(i))*bx(i, k))
            fy(i, k) = alive(i)*(fy(i, k) + (pbar(i) - q(i))*by(i, k))
            fz(i, k) = alive(i)*(fz(i, k) + (pbar(i) - q(i))*bz(i, k))
            nn = blk%conn(k, i)
            f(1, nn) = f(1, nn) - fx(i, k)
            f(2, nn) = f(2, nn) - fy(i, k)
            f(3, nn) = f(3, nn) - fz(i, k)
         end do
      end do
      res%dehg = 0.0_wp
      call stable_time_step(blk, part, xe, ye, ze, vol, trd, c, res)
      call first_error(n, ierr, res)
   end subroutine hex8_sri

   !> Natural derivatives dN_I/dxi_k at the 8 Gauss points (+-1/sqrt(3)), point order = node order.
   pure subroutine shape_derivs(dn)
      real(wp), intent(out) :: dn(3, 8, 8)
      real(wp) :: g(3)
      integer :: ip, k
      do ip = 1, 8
         g = XI_NODE(:, ip)/sqrt(3.0_wp)
         do k = 1, 8
            dn(1, k, ip) = XI_NODE(1,k)*(1.0_wp + XI_NODE(2,k)*g(2))*(1.0_wp + XI_NODE(3,k)*g(3))/8
            dn(2, k, ip) = XI_NODE(2,k)*(1.0_wp + XI_NODE(1,k)*g(1))*(1.0_wp + XI_NODE(3,k)*g(3))/8
            dn(3, k, ip) = XI_NODE(3,k)*(1.0_wp + XI_NODE(1,k)*g(1))*(1.0_wp + XI_NODE(2,k)*g(2))/8
         end do
      end do
   end subroutine shape_derivs

   !> Spatial gradients dN/dx and weights det(J) (unit Gauss weights) at all 8 points.
   pure subroutine point_gradients(dn, xe, ye, ze, dnx, jw)
      real(wp), intent(in) :: dn(3, 8, 8), xe(8), ye(8), ze(8)
      real(wp), intent(out) :: dnx(3, 8, 8), jw(8)
      integer :: ip
      do ip = 1, 8
         call point_gradients_one(dn(:, :, ip), xe, ye, ze, dnx(:, :, ip), jw(ip))
      end do
   end subroutine point_gradients

   pure subroutine point_gradients_one(dn, xe, ye, ze, dnx, jw)
      real(wp), intent(in) :: dn(3, 8), xe(8), ye(8), ze(8)
      real(wp), intent(out) :: dnx(3, 8), jw
      real(wp) :: j(3, 3), ji(3, 3), det
      j(:, 1) = matmul(dn, xe); j(:, 2) = matmul(dn, ye); j(:, 3) = matmul(dn, ze)
      call inv3(j, ji, det)
      dnx = matmul(ji, dn)
      jw = det
   end subroutine point_gradients_one
end module dx_hex8
