!> Hex8 element kernels over one element block (at most nv_chunk elements): gather nodal x and v,
!> strain increment at the mid-step geometry, Jaumann rotation, material update (one dispatch per
!> block), bulk viscosity, hourglass, internal force scatter, energies, element stable time step.
!> ELFORM 1: uniform-strain one-point hex with hourglass control (Flanagan & Belytschko 1981,
!> IJNME 17:679-706): IHQ 1 = viscous on the base vectors Gamma (Kosloff-Frasier / DYNA
!> standard), IHQ 2,3 = viscous on the FB orthogonal vectors gamma, IHQ 4,5 = stiffness on
!> gamma (B vectors are already the exact volume integrals, so 3 = 2 and 5 = 4 here).
!> ELFORM 2: 2x2x2 selectively reduced (mean-dilatation) hex, no hourglass modes
!> (Hughes 1980, IJNME 15:1413-1418; Nagtegaal, Parks & Rice 1974).
!> Bulk viscosity (DYNA form): q = rho*L*(Q1*L*e_kk**2 - Q2*c*e_kk) for e_kk < 0; time step
!> dt_e = L/(Q + sqrt(Q**2 + c**2)), Q = Q2*c + Q1*L*|e_kk| (LS-DYNA Theory Manual), with one
!> length L = V/A_max for both (issue 15; docs/design.md "One characteristic length"), and
!> for elements whose nodes carry mostly their own mass (single elements, one-element-wide
!> bars) also L <= 2V/sqrt(8 phim B_iI B_iI) (FB 1981's element bound).
!> Internal energy: the centred work of the stress and viscosity forces, the exact partner of
!> the centred kinetic energy of dx_explicit (centred_work).
!> Viscous hourglass coefficient a_h = QH*rho*c*V**(2/3)/4 (LS-DYNA Theory Manual, U), its
!> energy the trapezoid of the last and this pass's modal force (as applied, kept in ES_HGS)
!> times the rates, the centred work's summation by parts, and its explicit bound in the
!> step (stable_time_step); stiffness (IHQ 4,5): FB 1981's kappa = QH*(lambda + 2mu)*b_jJ*
!> b_jJ/(3V) on the modal rates normalized by 1/sqrt(8), i.e. f_iI = k_h (gamma_aJ u_iJ)
!> gamma_aI with k_h = QH*(K + 4G/3)*sum(B_jJ**2)/(24V) (docs/history.md, "Hourglass types").
module dx_hex8
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_material, only: material_t
   use dx_erosion, only: erosion_points, erosion_now, erosion_strain, erosion_strain_mean
   use dx_element_types, only: elem_block_t, part_t, ES_WORK, ES_HGS, ES_PHIM, block_result_t, &
                               HEX_ERR_NEGVOL => ELEM_ERR_NEGVOL, &
                               HEX_ERR_MATERIAL => ELEM_ERR_MATERIAL
   use dx_solid_kernels, only: cube_roots, hex8_mass_share   ! (the latter public here too)
   use dx_solid_point, only: gather_mid, strain_increments, volumes_now, jaumann, &
                             point_stress, bulk_viscosity, work_rates, stress_forces, &
                             scatter_forces
   use dx_hex8_geometry, only: hex8_bvectors, hex8_bvectors_chunk, hex8_char_length, &
                               GAMMA_HG, shape_derivs, point_gradients, point_gradients_one
   implicit none
   private
   !> An element whose volume falls to eps*V0 or below is collapsed (reported as a negative
   !> volume): its corner coordinates no longer resolve the volume, and with the step
   !> proportional to V (L = V/A_max) it would approach zero geometrically, never crossing it
   !> (extreme_crushed_element), until tr D = dV/(V dt) overflows.
   real(wp), parameter :: vcrush = epsilon(1.0_wp)
   public :: hex8_block, hex8_volume, hex8_mass_share, centred_work, centred_work_block
   public :: stable_time_step, first_error

contains

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
      call hex8_bvectors_chunk(n, xe, ye, ze, bx, by, bz, v)
      vol(1:n) = v(1:n)
   end subroutine hex8_volume

   !> One explicit pass over a block: x = x(n), v = v(n-1/2), dt_old = dt(n-1/2).
   !> Updates stress/history to t(n) and subtracts the internal force from f.
   subroutine hex8_block(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), intent(in), optional :: time, dtfloor   !< erosion (dx_erosion%erosion_now)
      ! blocks built elsewhere than dx_model_build (tests, restart) may lack it
      if (blk%esc(ES_WORK) == 0) call blk%es_add(ES_WORK, 4)
      if (blk%nip == 1 .and. part%qh > 0.0_wp .and. blk%esc(ES_HGS) == 0) call blk%es_add(ES_HGS, 12)
      select case (blk%nip)
      case (1)
         call hex8_1pt(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      case default
         call hex8_sri(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      end select
   end subroutine hex8_block

   subroutine hex8_1pt(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), intent(in), optional :: time, dtfloor
      ! work arrays have the compile-time leading dimension nv_chunk, so that loops that touch
      ! several columns of one array vectorize; deps is (nel, 6) as the material expects
      real(wp), dimension(nv_chunk, 8) :: xe, ye, ze, vx, vy, vz, bx, by, bz, xm, ym, zm, fx, fy, fz
      real(wp), dimension(nv_chunk) :: vol, volm, rv, c, q, trd, w12, w23, w31, ein, alive
      real(wp), dimension(nv_chunk) :: bv, vold, lcb, wo, wn, de, lc
      real(wp) :: lg(nv_chunk, 9), de6(nv_chunk, 6), so(nv_chunk, 6), sn(nv_chunk, 6)
      real(wp) :: deps(blk%nel, 6)
      real(wp) :: hdt, l1, l2, l3, l4, l5, l6, l7, l8, l9
      integer :: ierr(nv_chunk)
      integer :: i, k, n, w
      n = blk%nel
      w = blk%esc(ES_WORK)
      ! ---- gather, and the mid-step geometry x(n-1/2) = x(n) - dt/2 v(n-1/2) of the strain
      ! increment and spin
      hdt = 0.5_wp*dt_old
      call gather_mid(blk, n, nv_chunk, 8, x, v, hdt, xe, ye, ze, vx, vy, vz, xm, ym, zm)
      call hex8_bvectors_chunk(n, xm, ym, zm, bx, by, bz, volm)
      ! velocity gradient times V, L_ij V = v_iI B_jI (mid-step B)
      do i = 1, n
         l1 = 0.0_wp; l2 = 0.0_wp; l3 = 0.0_wp; l4 = 0.0_wp; l5 = 0.0_wp
         l6 = 0.0_wp; l7 = 0.0_wp; l8 = 0.0_wp; l9 = 0.0_wp
         !GCC$ unroll 8
         do k = 1, 8
            l1 = l1 + vx(i, k)*bx(i, k)
            l2 = l2 + vy(i, k)*by(i, k)
            l3 = l3 + vz(i, k)*bz(i, k)
            l4 = l4 + vx(i, k)*by(i, k)
            l5 = l5 + vy(i, k)*bx(i, k)
            l6 = l6 + vy(i, k)*bz(i, k)
            l7 = l7 + vz(i, k)*by(i, k)
            l8 = l8 + vz(i, k)*bx(i, k)
            l9 = l9 + vx(i, k)*bz(i, k)
         end do
         lg(i, 1) = l1; lg(i, 2) = l2; lg(i, 3) = l3; lg(i, 4) = l4; lg(i, 5) = l5
         lg(i, 6) = l6; lg(i, 7) = l7; lg(i, 8) = l8; lg(i, 9) = l9
      end do
      call strain_increments(blk, n, dt_old, lg, volm, ierr, alive, de6, deps, w12, w23, w31, &
                             trd)
      if (part%ero%on) call erosion_strain(blk, n, de6, w12, w23, w31)   ! strain criteria
      ! ---- geometry at t(n): forces, volume, time step; B(n).v(n-1/2) for the viscous work
      call hex8_bvectors_chunk(n, xe, ye, ze, bx, by, bz, vol)
      do i = 1, n
         l1 = 0.0_wp
         !GCC$ unroll 8
         do k = 1, 8
            l1 = l1 + bx(i, k)*vx(i, k) + by(i, k)*vy(i, k) + bz(i, k)*vz(i, k)
         end do
         bv(i) = l1
      end do
      call volumes_now(blk, n, vol, vold, rv, ein, ierr)
      call cube_roots(n, vol, lcb)    ! V**(1/3), the same bits in every SIMD lane (see cube_roots)
      ! the one characteristic length of the time step and the bulk viscosity
      call char_lengths(blk, xe, ye, ze, bx, by, bz, vol, lc)
      ! ---- stress: Jaumann rotation by the spin increment (first order), then the material
      ! (erosion: an eroded element keeps zero stress and carries no force from the pass it
      ! erodes in; the work of its last step with the forces it applied still counts)
      call point_stress(blk, mat, part, n, dt_old, w12, w23, w31, deps, rv, ein, lc, trd, c, &
                        so, sn, ierr, time, dtfloor)
      ! ---- bulk viscosity and the centred work of stress and viscosity
      do i = 1, n
         q(i) = bulk_viscosity(part, mat%ro/rv(i), lc(i), trd(i), c(i))
      end do
      call work_rates(blk, n, volm, so, sn, de6, q, wo, wn)
      de(1:n) = trd(1:n)*volm(1:n)     ! B(n-1/2).v(n-1/2)
      call centred_work_block(blk, n, w, dt_old, wo, wn, q, vol, vold, bv, de, alive, res)
      ! ---- internal force f_iI = (sig_ij - q delta_ij) B_jI
      call stress_forces(n, 8, alive, sn, q, bx, by, bz, fx, fy, fz)
      ! ---- hourglass control
      res%dehg = 0.0_wp
      if (part%qh > 0.0_wp) call hourglass(blk, mat, part, n, dt_old, xe, ye, ze, vx, vy, vz, &
                                           bx, by, bz, vol, lcb, rv, c, w12, w23, w31, &
                                           alive, fx, fy, fz, res%dehg)
      ! ---- scatter (internal force is subtracted)
      call scatter_forces(blk, n, 8, fx, fy, fz, f)
      ! ---- stable time step
      call stable_time_step(blk, part, lc, trd, c, res, lcb)
      call first_error(n, ierr, blk%failed, res)
   end subroutine hex8_1pt

   !> Hourglass forces of a block, added to fx, fy, fz; dehg = hourglass energy increment.
   !> Shape vectors: Gamma (IHQ 1) or FB's gamma = Gamma - (Gamma.x_i) B_i / V (IHQ 2-5); modal
   !> rates qdot_ia = gamma_aI v_iI; viscous forces a_h qdot (IHQ 1-3) or corotated stiffness
   !> forces Q += k_h dt qdot (IHQ 4,5); f_iI += Q_ia gamma_aI. Every loop runs over the
   !> elements of the block (unit stride), so it vectorizes.
   subroutine hourglass(blk, mat, part, n, dt, xe, ye, ze, vx, vy, vz, bx, by, bz, vol, lcb, rv, &
                        c, w12, w23, w31, alive, fx, fy, fz, dehg)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      integer, intent(in) :: n
      real(wp), intent(in) :: dt
      real(wp), dimension(nv_chunk, 8), intent(in) :: xe, ye, ze, vx, vy, vz, bx, by, bz
      real(wp), dimension(nv_chunk), intent(in) :: vol, lcb, rv, c, w12, w23, w31, alive
      real(wp), dimension(nv_chunk, 8), intent(inout) :: fx, fy, fz
      real(wp), intent(out) :: dehg
      real(wp), dimension(nv_chunk, 4) :: qx, qy, qz, hx, hy, hz
      real(wp) :: g(nv_chunk, 4, 8), ax, ay, az, rvol, coef(nv_chunk), e(nv_chunk), m, kx, ky, kz
      integer :: i, a, k, h
      if (part%ihq == 1) then
         ! DYNA's viscous form on the constant base vectors Gamma (unrolled: +-1 constants)
         call hourglass_gamma_viscous(blk, mat, part, n, dt, vx, vy, vz, lcb, rv, c, alive, &
                                      fx, fy, fz, dehg)
         return
      end if
      ! shape vectors
      if (.false.) then
      else
         do k = 1, 4
            do i = 1, n
               ax = 0.0_wp; ay = 0.0_wp; az = 0.0_wp
               do a = 1, 8
                  ax = ax + GAMMA_HG(k, a)*xe(i, a)
                  ay = ay + GAMMA_HG(k, a)*ye(i, a)
                  az = az + GAMMA_HG(k, a)*ze(i, a)
               end do
               rvol = 1.0_wp/vol(i)
               hx(i, k) = ax*rvol; hy(i, k) = ay*rvol; hz(i, k) = az*rvol
            end do
         end do
         do a = 1, 8
            do k = 1, 4
               do i = 1, n
                  g(i, k, a) = GAMMA_HG(k, a) - (hx(i, k)*bx(i, a) + hy(i, k)*by(i, a) &
                               + hz(i, k)*bz(i, a))
               end do
            end do
         end do
      end if
      ! modal rates
      qx(1:n, :) = 0.0_wp; qy(1:n, :) = 0.0_wp; qz(1:n, :) = 0.0_wp
      do a = 1, 8
         do k = 1, 4
            do i = 1, n
               qx(i, k) = qx(i, k) + g(i, k, a)*vx(i, a)
               qy(i, k) = qy(i, k) + g(i, k, a)*vy(i, a)
               qz(i, k) = qz(i, k) + g(i, k, a)*vz(i, a)
            end do
         end do
      end do
      if (part%ihq >= 4) then
         m = part%qh*(mat%bulk + 4.0_wp*mat%shear/3.0_wp)/24.0_wp
         do i = 1, n
            coef(i) = 0.0_wp
            do a = 1, 8
               coef(i) = coef(i) + bx(i, a)**2 + by(i, a)**2 + bz(i, a)**2
            end do
            coef(i) = m*coef(i)/vol(i)*dt
            e(i) = 0.0_wp
         end do
         do k = 1, 4
            ! the resisting forces of mode k: es columns h, h+1, h+2 (x, y, z)
            h = blk%esc(ES_HGS) + 3*(k - 1)
            do i = 1, n
               ! corotate the stored resisting forces, then add the stiffness increment; the
               ! energy is the trapezoid of the old and new force (exact spring energy)
               kx = blk%es(i, h) + w12(i)*blk%es(i, h + 1) - w31(i)*blk%es(i, h + 2)
               ky = blk%es(i, h + 1) - w12(i)*blk%es(i, h) + w23(i)*blk%es(i, h + 2)
               kz = blk%es(i, h + 2) + w31(i)*blk%es(i, h) - w23(i)*blk%es(i, h + 1)
               hx(i, k) = kx + coef(i)*qx(i, k)
               hy(i, k) = ky + coef(i)*qy(i, k)
               hz(i, k) = kz + coef(i)*qz(i, k)
               blk%es(i, h) = hx(i, k); blk%es(i, h + 1) = hy(i, k)
               blk%es(i, h + 2) = hz(i, k)
               e(i) = e(i) + 0.5_wp*dt*((kx + hx(i, k))*qx(i, k) + (ky + hy(i, k))*qy(i, k) &
                      + (kz + hz(i, k))*qz(i, k))
            end do
         end do
      else
         do i = 1, n
            ! a_h = QH rho c V**(2/3)/4, lcb = V**(1/3)
            coef(i) = 0.25_wp*part%qh*(mat%ro/rv(i))*c(i)*lcb(i)*lcb(i)
            e(i) = 0.0_wp
         end do
         h = blk%esc(ES_HGS)
         do k = 1, 4
            do i = 1, n
               hx(i, k) = coef(i)*qx(i, k)
               hy(i, k) = coef(i)*qy(i, k)
               hz(i, k) = coef(i)*qz(i, k)
            end do
         end do
         ! the trapezoid of the last pass's force (as applied, not turned) and this one's,
         ! the centred work of the force (hourglass_gamma_viscous)
         call hg_trapezoid(n, dt, blk%es(:, h:h + 11), hx, hy, hz, qx, qy, qz, e)
      end if
      dehg = 0.0_wp
      do i = 1, n
         e(i) = e(i)*alive(i)
         blk%ehg(i) = blk%ehg(i) + e(i)
         dehg = dehg + e(i)
      end do
      do a = 1, 8
         do k = 1, 4
            do i = 1, n
               fx(i, a) = fx(i, a) + alive(i)*hx(i, k)*g(i, k, a)
               fy(i, a) = fy(i, a) + alive(i)*hy(i, k)*g(i, k, a)
               fz(i, a) = fz(i, a) + alive(i)*hz(i, k)*g(i, k, a)
            end do
         end do
      end do
   end subroutine hourglass

   !> e += dt/2 (Q(n-1) + Q(n)).qdot over the 4 modes, Q(n-1) the forces fo (columns x, y, z
   !> of each mode), which then become Q(n) = (hx, hy, hz).
   pure subroutine hg_trapezoid(n, dt, fo, hx, hy, hz, qx, qy, qz, e)
      integer, intent(in) :: n
      real(wp), intent(in) :: dt
      real(wp), intent(inout) :: fo(:, :), e(:)
      real(wp), dimension(:, :), intent(in) :: hx, hy, hz, qx, qy, qz
      integer :: i, k
      do k = 1, 4
         do i = 1, n
            e(i) = e(i) + 0.5_wp*dt*((fo(i, 3*k - 2) + hx(i, k))*qx(i, k) &
                   + (fo(i, 3*k - 1) + hy(i, k))*qy(i, k) + (fo(i, 3*k) + hz(i, k))*qz(i, k))
            fo(i, 3*k - 2) = hx(i, k); fo(i, 3*k - 1) = hy(i, k); fo(i, 3*k) = hz(i, k)
         end do
      end do
   end subroutine hg_trapezoid

   !> IHQ 1: f_iI += a_h qdot_ia Gamma_aI with qdot_ia = Gamma_aJ v_iJ, Gamma the +-1 base
   !> vectors (Kosloff & Frasier 1978; DYNA3D), a_h = QH rho c V**(2/3)/4. Energy: dt/2
   !> (Q(n-1) + Q(n)).qdot(n-1/2) with Q = a_h qdot the modal force, the exact partner of the
   !> centred kinetic energy at a constant step (sum by parts of dtavg f(n).(v(n-1/2) +
   !> v(n+1/2))/2; a_h dt |qdot|**2 alone overcounts a mode that flips, 1/(1 - r dt/2)).
   subroutine hourglass_gamma_viscous(blk, mat, part, n, dt, vx, vy, vz, lcb, rv, c, alive, &
                                      fx, fy, fz, dehg)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      integer, intent(in) :: n
      real(wp), intent(in) :: dt
      real(wp), dimension(nv_chunk, 8), intent(in) :: vx, vy, vz
      real(wp), dimension(nv_chunk), intent(in) :: lcb, rv, c, alive
      real(wp), dimension(nv_chunk, 8), intent(inout) :: fx, fy, fz
      real(wp), intent(out) :: dehg
      real(wp) :: ah, qx(4), qy(4), qz(4), e, fo(nv_chunk, 12)
      integer :: i, a, k, h
      dehg = 0.0_wp
      h = blk%esc(ES_HGS)
      fo(1:n, :) = blk%es(1:n, h:h + 11)     ! (a local copy: the loop over i vectorizes)
      do i = 1, n
         ah = 0.25_wp*part%qh*(mat%ro/rv(i))*c(i)*lcb(i)*lcb(i)*alive(i)
         e = 0.0_wp
         !GCC$ unroll 4
         do k = 1, 4
            qx(k) = 0.0_wp; qy(k) = 0.0_wp; qz(k) = 0.0_wp
            !GCC$ unroll 8
            do a = 1, 8
               qx(k) = qx(k) + GAMMA_HG(k, a)*vx(i, a)
               qy(k) = qy(k) + GAMMA_HG(k, a)*vy(i, a)
               qz(k) = qz(k) + GAMMA_HG(k, a)*vz(i, a)
            end do
            ! the trapezoid of the last pass's and this pass's modal force (see hourglass)
            e = e + (fo(i, 3*k - 2) + ah*qx(k))*qx(k) + (fo(i, 3*k - 1) + ah*qy(k))*qy(k) &
                  + (fo(i, 3*k) + ah*qz(k))*qz(k)
            fo(i, 3*k - 2) = ah*qx(k); fo(i, 3*k - 1) = ah*qy(k); fo(i, 3*k) = ah*qz(k)
         end do
         e = 0.5_wp*dt*e
         ! e feeds two sums (ehg, dehg): "+ 0" gives the product one use, so it is rounded
         ! alike in the vectorized body and the scalar remainder rather than fused (FMA) into
         ! one sum there and not here; an element's energy must not depend on its position
         ! in the block, which MPI pieces change (docs/history.md)
         e = e + 0.0_wp
         blk%ehg(i) = blk%ehg(i) + e
         dehg = dehg + e
         !GCC$ unroll 8
         do a = 1, 8
            fx(i, a) = fx(i, a) + ah*(GAMMA_HG(1, a)*qx(1) + GAMMA_HG(2, a)*qx(2) &
                       + GAMMA_HG(3, a)*qx(3) + GAMMA_HG(4, a)*qx(4))
            fy(i, a) = fy(i, a) + ah*(GAMMA_HG(1, a)*qy(1) + GAMMA_HG(2, a)*qy(2) &
                       + GAMMA_HG(3, a)*qy(3) + GAMMA_HG(4, a)*qy(4))
            fz(i, a) = fz(i, a) + ah*(GAMMA_HG(1, a)*qz(1) + GAMMA_HG(2, a)*qz(2) &
                       + GAMMA_HG(3, a)*qz(3) + GAMMA_HG(4, a)*qz(4))
         end do
      end do
      blk%es(1:n, h:h + 11) = fo(1:n, :)
   end subroutine hourglass_gamma_viscous

   !> Sum over the nodes of B_I . v_I for each element (the volume rate V*tr(D) for B at x).
   pure subroutine bdotv(n, bx, by, bz, vx, vy, vz, bv)
      integer, intent(in) :: n
      real(wp), intent(in), dimension(:, :) :: bx, by, bz, vx, vy, vz
      real(wp), intent(out) :: bv(:)
      real(wp) :: l1
      integer :: i, k
      do i = 1, n
         l1 = 0.0_wp
         !GCC$ unroll 8
         do k = 1, 8
            l1 = l1 + bx(i, k)*vx(i, k) + by(i, k)*vy(i, k) + bz(i, k)*vz(i, k)
         end do
         bv(i) = l1
      end do
   end subroutine bdotv

   !> Internal-energy increment de of one element at this pass: the work of its stress and
   !> bulk-viscosity nodal forces f(n) in the central-difference balance, W(n) =
   !> dtavg(n) f(n).(v(n-1/2) + v(n+1/2))/2, the exact partner of the centred kinetic energy
   !> 1/2 m v(n-1/2).v(n+1/2) (dx_explicit) for any time-step sequence. W(n) is completed at
   !> the next pass, when v(n+1/2) and dt(n+1/2) are known: the half with v(n-1/2) is booked
   !> now with dt(n-1/2)/2 and corrected then to dtavg(n)/2. With a constant step this is the
   !> trapezoid (sigma(n-1) + sigma(n)):D V dt. The stress power uses the mid-step D V
   !> (wo, wn = dt sigma_old:D V, dt sigma_new:D V); the viscosity force q B(x(n)) uses
   !> bvn = B(n).v(n-1/2) and B(n-1).v(n-1/2) from Simpson's rule, exact for the cubic V(x):
   !> V(n) - V(n-1) = dt/6 (B(n-1) + 4 B(n-1/2) + B(n)).v(n-1/2), bvm = B(n-1/2).v(n-1/2).
   !> s1..s4 = q, q bvn, dt, sigma:D V of the last pass (the element's ework row). bvpx: B(n-1).
   !> v(n-1/2) itself, given where B is not dV/dx (axisymmetric quads; Simpson books the exact dV).
   pure subroutine centred_work(s1, s2, s3, s4, dt, wo, wn, q, vol, vol_old, bvn, bvm, de, bvpx)
      real(wp), intent(inout) :: s1, s2, s3, s4
      real(wp), intent(in) :: dt, wo, wn, q, vol, vol_old, bvn, bvm
      real(wp), intent(out) :: de
      real(wp), intent(in), optional :: bvpx
      real(wp) :: bvp, pn
      de = 0.0_wp
      pn = 0.0_wp
      if (dt > 0.0_wp) then
         if (present(bvpx)) bvp = bvpx
         if (.not. present(bvpx)) bvp = 6.0_wp*(vol - vol_old)/dt - 4.0_wp*bvm - bvn
         pn = wn/dt
         de = 0.5_wp*(wo + wn) + 0.25_wp*(dt - s3)*(s4 - wo/dt) &
              - (0.25_wp*(s3 + dt)*s1*bvp + 0.25_wp*(dt - s3)*s2 + 0.5_wp*dt*q*bvn)
      end if
      s1 = q
      s2 = q*bvn
      s3 = dt
      s4 = pn
   end subroutine centred_work

   !> centred_work over the n elements of a block (ELFORM 1, the 2D solids): the pending
   !> terms in es columns w..w+3 (ES_WORK), bvm = B(n-1/2).v(n-1/2); the increment times
   !> alive (0: eroded) added to eint and res%deint, the pending power to res%pend; an element
   !> that failed in this pass gets alive = 0 on return (no force from now on). (hex8_sri
   !> keeps its one loop: split in two, the pending power is no longer fused, FMA, with
   !> q B.v and its last digit changes, e.g. glstat of patch_rigid_rotation_elform2.)
   subroutine centred_work_block(blk, n, w, dt, wo, wn, q, vol, vold, bvn, bvm, alive, res, bvpx)
      type(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: n, w
      real(wp), intent(in) :: dt
      real(wp), dimension(:), intent(in) :: wo, wn, q, vol, vold, bvn, bvm
      real(wp), intent(inout) :: alive(:)
      type(block_result_t), intent(inout) :: res
      real(wp), intent(in), optional :: bvpx(:)
      real(wp), dimension(nv_chunk) :: e1, e2, e3, e4, de
      integer :: i
      e1(1:n) = blk%es(1:n, w); e2(1:n) = blk%es(1:n, w + 1)
      e3(1:n) = blk%es(1:n, w + 2); e4(1:n) = blk%es(1:n, w + 3)
      do i = 1, n
         if (present(bvpx)) call centred_work(e1(i), e2(i), e3(i), e4(i), dt, wo(i), wn(i), &
            q(i), vol(i), vold(i), bvn(i), bvm(i), de(i), bvpx(i))
         if (.not. present(bvpx)) call centred_work(e1(i), e2(i), e3(i), e4(i), dt, wo(i), &
            wn(i), q(i), vol(i), vold(i), bvn(i), bvm(i), de(i))
      end do
      blk%es(1:n, w) = e1(1:n); blk%es(1:n, w + 1) = e2(1:n)
      blk%es(1:n, w + 2) = e3(1:n); blk%es(1:n, w + 3) = e4(1:n)
      res%deint = 0.0_wp
      res%pend = 0.0_wp
      do i = 1, n
         de(i) = de(i)*alive(i)
         blk%eint(i) = blk%eint(i) + de(i)
         res%deint = res%deint + de(i)
         res%pend = res%pend + alive(i)*(e4(i) - e2(i))
         if (blk%failed(i)) alive(i) = 0.0_wp
      end do
   end subroutine centred_work_block

   !> Characteristic length lc of each element at t(n), the one length of its time step and
   !> its bulk viscosity: L = V/A_max (LS-DYNA's time-step length of a solid; a face area by
   !> the cross product of its diagonals). An element whose nodes carry mostly its own mass
   !> (phim >= 1/2: a single element, a one-element-wide bar) has a dilatational mode faster
   !> than c/L: a free unit cube's is sqrt(12 K/rho) (2.73 c for nu = 0.3, so dt = 0.9 L/c is
   !> unstable). Its L is then also bounded by FB 1981's element bound omega**2 <= 8 c**2
   !> B_iI B_iI/V**2 with the nodal masses scaled by the element's own share:
   !> L <= 2V/sqrt(8 phim B_iI B_iI) (0.577 for a free unit cube).
   subroutine char_lengths(blk, xe, ye, ze, bx, by, bz, vol, lc)
      type(elem_block_t), intent(in) :: blk
      real(wp), intent(in), contiguous :: xe(:, :), ye(:, :), ze(:, :), vol(:)
      real(wp), intent(in) :: bx(:, :), by(:, :), bz(:, :)
      real(wp), intent(out) :: lc(:)
      real(wp) :: bb
      integer :: i, n, ip
      n = blk%nel
      call hex8_char_length(n, size(xe, 1), xe, ye, ze, vol, lc)
      ip = blk%esc(ES_PHIM)
      if (ip > 0) then
         do i = 1, n
            if (blk%es(i, ip) >= 0.5_wp) then
               bb = sum(bx(i, 1:8)**2 + by(i, 1:8)**2 + bz(i, 1:8)**2)
               lc(i) = min(lc(i), 2.0_wp*vol(i)/sqrt(8.0_wp*blk%es(i, ip)*bb))
            end if
         end do
      end if
   end subroutine char_lengths

   !> Smallest element step L/(Q + sqrt(Q**2 + c**2)), L = lc (char_lengths), Q = Q2*c +
   !> Q1*L*|e_kk| (compression only; the same L as the bulk viscosity's, so Q is the
   !> viscosity's own damping rate); eroded elements do not count. With lh (the hourglass
   !> length: V**(1/3), 2D sqrt(A)) and a viscous hourglass (IHQ 1-3), also the explicit
   !> bound of its damping: the checkerboard mode has no stiffness and relaxes at the rate
   !> r = 16 QH c/lh (a_h 64/(rho V): 8 elements of 8 Gamma_I**2 on a node of mass rho V),
   !> and v(n+1/2) = (1 - r dt) v(n-1/2) is stable for r dt <= 2: dt <= lh/(8 QH c)
   !> (binding in a cube beyond QH = 1/8; docs/extreme-cases.md).
   subroutine stable_time_step(blk, part, lc, trd, c, res, lh)
      type(elem_block_t), intent(in) :: blk
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: lc(:), trd(:), c(:)
      type(block_result_t), intent(inout) :: res
      real(wp), intent(in), optional :: lh(:)
      real(wp) :: qb, trde
      integer :: i, n
      logical :: hgv
      n = blk%nel
      hgv = present(lh) .and. part%qh > 0.0_wp .and. part%ihq <= 3
      do i = 1, n
         qb = 0.0_wp
         if (trd(i) < 0.0_wp) qb = part%q2*c(i) + part%q1*lc(i)*abs(trd(i))
         trde = lc(i)/(qb + sqrt(qb*qb + c(i)*c(i)))
         if (hgv .and. c(i) > 0.0_wp) trde = min(trde, lh(i)/(8.0_wp*part%qh*c(i)))
         if (blk%failed(i)) trde = huge_wp
         if (trde < res%dt) then
            res%dt = trde; res%imin = i
         end if
         res%dte(i) = trde
      end do
   end subroutine stable_time_step

   !> The first element of a block in error (res%ibad, res%errcode: negative volume or material).
   !> An eroded element (failed) carries no stress and no force: its shape, inverted or not,
   !> is no error (LS-DYNA likewise drops eroded elements from the element loop).
   subroutine first_error(n, ierr, failed, res)
      integer, intent(in) :: n, ierr(:)
      logical, intent(in) :: failed(:)
      type(block_result_t), intent(inout) :: res
      integer :: i
      do i = 1, n
         if (ierr(i) /= 0 .and. .not. failed(i)) then
            res%ibad = i
            res%errcode = merge(HEX_ERR_NEGVOL, HEX_ERR_MATERIAL, ierr(i) == HEX_ERR_NEGVOL)
            return
         end if
      end do
   end subroutine first_error

   !> ELFORM 2: 2x2x2 Gauss points, deviatoric strain per point, volumetric strain rate
   !> replaced by the element mean (mean dilatation); pressure work through the mean B.
   subroutine hex8_sri(blk, mat, part, x, v, dt_old, f, res, time, dtfloor)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), intent(in), optional :: time, dtfloor
      real(wp), dimension(blk%nel, 8) :: xe, ye, ze, vx, vy, vz, bx, by, bz, xm, ym, zm, fx, fy, fz
      real(wp), dimension(blk%nel) :: vol, volm, rv, c, q, trd, w12, w23, w31, ein, alive, pbar
      real(wp), dimension(blk%nel) :: bv, relv_old, wold, wnew, lc
      real(wp) :: deps(blk%nel, 6), sold(blk%nel, 6), dn(3, 8, 8), dnx(3, 8), l(3, 3)
      real(wp) :: p8(8), q8(8), r8(8)
      real(wp), allocatable :: dng(:, :, :, :)
      real(wp) :: jwg(8, blk%nel), wm(blk%nel), dtl, rho, a, pend, trp, pm, ein_sum
      integer :: ierr(blk%nel)
      logical :: failed(blk%nel), fpt(blk%nel)
      integer :: nfe(blk%nel)
      integer :: i, k, n, nn, ip, w
      n = blk%nel
      w = blk%esc(ES_WORK)
      allocate(dng(3, 8, 8, n))
      call shape_derivs(dn)
      call gather_mid(blk, n, n, 8, x, v, 0.5_wp*dt_old, xe, ye, ze, vx, vy, vz, xm, ym, zm)
      ierr = 0
      call hex8_bvectors(n, n, xe, ye, ze, bx, by, bz, vol)
      call hex8_bvectors(n, n, xm, ym, zm, fx, fy, fz, volm)
      call bdotv(n, bx, by, bz, vx, vy, vz, bv)
      do i = 1, n
         relv_old(i) = blk%relvol(i)
         if (.not. (volm(i) > vcrush*blk%vol0(i) .and. vol(i) > vcrush*blk%vol0(i))) then
            ierr(i) = HEX_ERR_NEGVOL; volm(i) = 1.0_wp; vol(i) = 1.0_wp
         end if
         rv(i) = vol(i)/blk%vol0(i)
         blk%relvol(i) = rv(i)
         ein(i) = blk%eint(i)/blk%vol0(i)
         alive(i) = merge(0.0_wp, 1.0_wp, blk%failed(i))
      end do
      ! mean volumetric rate: (1/V) sum_I v_I . B_I at mid-step (B held in fx, fy, fz here)
      do i = 1, n
         trd(i) = sum(vx(i, :)*fx(i, :) + vy(i, :)*fy(i, :) + vz(i, :)*fz(i, :))/volm(i)
      end do
      if (part%ero%on) call erosion_strain_mean(blk, n, vx, vy, vz, fx, fy, fz, volm, dt_old)
      ein_sum = 0.0_wp
      pend = 0.0_wp
      fx = 0.0_wp; fy = 0.0_wp; fz = 0.0_wp
      pbar = 0.0_wp
      wold = 0.0_wp; wnew = 0.0_wp
      fpt = .false.
      nfe = 0
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
         if (mat%hv_frame) call mat%rotate_history(n, w12, w23, w31, blk%hv(:, :, ip))
         sold(1:n, :) = blk%sig(1:n, :, ip)
         call mat%update(n, dt_old, deps, rv, ein, blk%sig(:, :, ip), blk%hv(:, :, ip), ierr)
         call mat%fails(n, blk%hv(:, :, ip), failed)
         fpt = fpt .or. failed
         if (part%ero%on) call erosion_points(blk, part%ero, n, blk%sig(:, :, ip), rv, &
                                              dt_old, 0.125_wp, nfe)
         do i = 1, n
            wold(i) = wold(i) + wm(i)*(sold(i,1)*deps(i,1) + sold(i,2)*deps(i,2) &
                      + sold(i,3)*deps(i,3) + 2.0_wp*(sold(i,4)*deps(i,4) &
                      + sold(i,5)*deps(i,5) + sold(i,6)*deps(i,6)))
            wnew(i) = wnew(i) + wm(i)*(blk%sig(i,1,ip)*deps(i,1) + blk%sig(i,2,ip)*deps(i,2) &
                      + blk%sig(i,3,ip)*deps(i,3) + 2.0_wp*(blk%sig(i,4,ip)*deps(i,4) &
                      + blk%sig(i,5,ip)*deps(i,5) + blk%sig(i,6,ip)*deps(i,6)))
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
      call char_lengths(blk, xe, ye, ze, bx, by, bz, vol, lc)   ! of the step and viscosity
      if (present(time)) call erosion_now(part, n, time, dtfloor, lc, trd, c, fpt)
      do i = 1, n
         rho = mat%ro/rv(i)
         q(i) = bulk_viscosity(part, rho, lc(i), trd(i), c(i))
         if (fpt(i) .or. nfe(i) >= min(part%ero%numfip, 8)) blk%failed(i) = .true.
         if (blk%failed(i)) wnew(i) = 0.0_wp   ! eroding now: no force f(n), W(n) = 0
         if (blk%failed(i)) q(i) = 0.0_wp
         call centred_work(blk%es(i, w), blk%es(i, w + 1), blk%es(i, w + 2), blk%es(i, w + 3), &
                           dt_old, wold(i), wnew(i), q(i), vol(i), blk%vol0(i)*relv_old(i), &
                           bv(i), trd(i)*volm(i), a)
         a = alive(i)*a
         blk%eint(i) = blk%eint(i) + a
         ein_sum = ein_sum + a
         pend = pend + alive(i)*(blk%es(i, w + 3) - blk%es(i, w + 1))
         if (blk%failed(i)) then
            alive(i) = 0.0_wp
            blk%sig(i, :, :) = 0.0_wp
         end if
      end do
      res%deint = ein_sum
      res%pend = pend
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
      call stable_time_step(blk, part, lc, trd, c, res)
      call first_error(n, ierr, blk%failed, res)
   end subroutine hex8_sri

end module dx_hex8
