!> Unit tests of the hex8 kernels: exact B vectors (against 2x2x2 Gauss integration),
!> patch tests on a distorted 2x2x2 patch (uniform stress = C:eps exactly, zero force on the
!> interior node, zero FB hourglass energy), rigid rotation (no strain), Jaumann rotation of
!> an existing stress, critical time step of a cube, and the decay of an hourglass mode.
program test_hex8
   use dx_kinds, only: wp, nv_chunk
   use dx_error, only: error_t
   use dx_model, only: elem_block_t, part_t, ES_HGS
   use dx_mat_elastic, only: mat_elastic_t
   use dx_hex8_geometry, only: hex8_bvectors, inv3, XI_NODE, GAMMA_HG
   use dx_hex8, only: hex8_block
   use dx_element_types, only: block_result_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: mat
   type(error_t), allocatable :: err
   type(part_t) :: part
   type(elem_block_t) :: blk
   type(block_result_t) :: res
   real(wp), allocatable :: x(:, :), xm(:, :), v(:, :), f(:, :)
   real(wp) :: lg(3, 3), dt, eps(6), lam, g2, smax, c, w
   integer :: ihq, etype, i, k

   mat%ro = 7.8e-9_wp; mat%e = 2.0e5_wp; mat%pr = 0.3_wp
   call mat%setup(err)
   call test_bvectors()
   lg = reshape([1.0_wp, 0.3_wp, -0.2_wp, 0.5_wp, -0.7_wp, 0.1_wp, 0.4_wp, 0.2_wp, 0.6_wp], &
                [3, 3])*1.0e-3_wp
   dt = 1.0e-2_wp
   do etype = 1, 2
      do ihq = 1, 5
         if (etype == 2 .and. ihq > 1) exit
         call make_patch(etype, ihq)
         ! velocity v = L x at the mid-step geometry: the strain increment is sym(L) dt exactly
         do i = 1, size(x, 2)
            v(:, i) = matmul(lg, xm(:, i))
            x(:, i) = xm(:, i) + 0.5_wp*dt*v(:, i)
         end do
         f = 0.0_wp
         call hex8_block(blk, mat, part, x, v, dt, f, res)
         call check(res%ibad == 0, 'patch: no element error')
         eps = [lg(1,1), lg(2,2), lg(3,3), 0.5_wp*(lg(1,2) + lg(2,1)), 0.5_wp*(lg(2,3) + lg(3,2)), &
                0.5_wp*(lg(3,1) + lg(1,3))]*dt
         lam = mat%bulk - 2.0_wp*mat%shear/3.0_wp
         g2 = 2.0_wp*mat%shear
         ! rotation of the zero initial stress is zero; stress = C:eps in every element/point
         smax = 0.0_wp
         do k = 1, 6
            w = g2*eps(k)
            if (k <= 3) w = w + lam*sum(eps(1:3))
            smax = max(smax, maxval(abs(blk%sig(1:8, k, :) - w)))
         end do
         call check_close(smax, 0.0_wp, 1.0e-12_wp*g2*maxval(abs(eps)), 0.0_wp, &
            'patch elform '//achar(48 + etype)//' ihq '//achar(48 + ihq)//': uniform stress C:eps')
         ! the interior node 14 carries no net force (IHQ 1 uses the Kosloff-Frasier Gamma
         ! vectors, which are not orthogonal to linear fields on a distorted mesh: it fails the
         ! patch test by design, which is why FB's gamma vectors exist)
         if (etype == 2 .or. ihq >= 2) then
            call check_close(maxval(abs(f(:, 14))), 0.0_wp, 1.0e-12_wp*maxval(abs(f)), 0.0_wp, &
               'patch elform '//achar(48 + etype)//' ihq '//achar(48 + ihq)//': interior node force')
         else
            call check(sum(blk%ehg(1:8)) > 0.0_wp .and. maxval(abs(f(:, 14))) > &
               1.0e-6_wp*maxval(abs(f)), 'patch ihq 1: Gamma hourglass forces a linear field')
         end if
         if (etype == 1 .and. ihq >= 2) then
            call check_close(sum(abs(blk%ehg(1:8))), 0.0_wp, 1.0e-14_wp*sum(abs(blk%eint(1:8))), &
               0.0_wp, 'patch ihq '//achar(48 + ihq)//': FB hourglass energy zero on a linear field')
         end if
      end do
   end do

   ! ---- rigid rotation about a tilted axis: no strain, no stress, no energy
   do etype = 1, 2
      call make_patch(etype, 2)
      lg = reshape([0.0_wp, 0.3_wp, -0.2_wp, -0.3_wp, 0.0_wp, 0.5_wp, 0.2_wp, -0.5_wp, 0.0_wp], &
                   [3, 3])
      do i = 1, size(x, 2)
         v(:, i) = matmul(lg, xm(:, i))
         x(:, i) = xm(:, i) + 0.5_wp*dt*v(:, i)
      end do
      f = 0.0_wp
      call hex8_block(blk, mat, part, x, v, dt, f, res)
      call check_close(maxval(abs(blk%sig(1:8, :, :))), 0.0_wp, 1.0e-9_wp, 0.0_wp, &
                       'rigid rotation elform '//achar(48 + etype)//': zero stress')
      call check_close(sum(abs(blk%eint(1:8))), 0.0_wp, 1.0e-20_wp, 0.0_wp, &
                       'rigid rotation elform '//achar(48 + etype)//': zero strain energy')
   end do

   ! ---- Jaumann: uniaxial stress s along x, spin about z by angle w*dt -> sigma_xy = s w dt
   call make_patch(1, 2)
   blk%sig(1:8, :, 1) = 0.0_wp
   blk%sig(1:8, 1, 1) = 100.0_wp
   w = 0.01_wp
   do i = 1, size(x, 2)
      v(:, i) = [-w*xm(2, i), w*xm(1, i), 0.0_wp]
      x(:, i) = xm(:, i) + 0.5_wp*dt*v(:, i)
   end do
   f = 0.0_wp
   call hex8_block(blk, mat, part, x, v, dt, f, res)
   call check_close(blk%sig(1, 4, 1), 100.0_wp*w*dt, 0.0_wp, 1.0e-10_wp, &
                    'Jaumann rotation of sigma_xx into sigma_xy')

   ! ---- time step of a unit cube at rest: L = V/A_max = 1, dt = 1/c
   call make_cube()
   f = 0.0_wp
   call hex8_block(blk, mat, part, x, v, 0.0_wp, f, res)
   c = sqrt((mat%bulk + 4.0_wp*mat%shear/3.0_wp)/mat%ro)
   call check_close(res%dt, 1.0_wp/c, 0.0_wp, 1.0e-12_wp, 'unit cube time step 1/c')

   ! ---- an hourglass velocity on a cube: the resisting force opposes it (IHQ 1..5)
   do ihq = 1, 5
      call make_cube()
      part%ihq = ihq
      if (ihq >= 4) then
         call blk%es_add(ES_HGS, 12)
      end if
      do i = 1, 8
         v(:, i) = [GAMMA_HG(1, i), 0.0_wp, 0.0_wp]
      end do
      f = 0.0_wp
      call hex8_block(blk, mat, part, x, v, 1.0e-7_wp, f, res)
      call check(sum(f*v) < 0.0_wp .and. blk%ehg(1) > 0.0_wp, &
                 'hourglass mode resisted, ihq '//achar(48 + ihq))
      call check_close(maxval(abs(blk%sig(1, :, 1))), 0.0_wp, 1.0e-12_wp, 0.0_wp, &
                       'hourglass mode carries no strain, ihq '//achar(48 + ihq))
   end do

   ! ---- IHQ 4 stiffness on a unit cube, Flanagan & Belytschko (1981): after one step with
   ! v = Gamma_1 in x, u = dt Gamma_1 and gamma.u = 8 dt; f = k (gamma.u) gamma with
   ! k = QH (K + 4G/3) sum(B**2)/(24 V), sum(B**2) = 24/16 = 1.5; the stored energy is the
   ! spring's k (gamma.u)**2/2 exactly (trapezoid of old and new force)
   call make_cube()
   part%ihq = 4
   call blk%es_add(ES_HGS, 12)
   do i = 1, 8
      v(:, i) = [GAMMA_HG(1, i), 0.0_wp, 0.0_wp]
   end do
   f = 0.0_wp
   w = part%qh*(mat%bulk + 4.0_wp*mat%shear/3.0_wp)*1.5_wp/24.0_wp
   call hex8_block(blk, mat, part, x, v, 1.0e-7_wp, f, res)
   call check_close(f(1, 1), -8.0_wp*w*1.0e-7_wp, 0.0_wp, 1.0e-12_wp, &
                    'IHQ 4 force = FB stiffness QH (K+4G/3) sum(B^2)/(24V) (gamma.u) gamma')
   call check_close(blk%ehg(1), 32.0_wp*w*1.0e-14_wp, 0.0_wp, 1.0e-12_wp, &
                    'IHQ 4 energy = k (gamma.u)^2/2')

   ! ---- IHQ 1 viscous on the unit cube with v = Gamma_1 in x (qdot = 8): the modal force
   ! a_h qdot, a_h = QH rho c/4; the energy the trapezoid of the last and this pass's force,
   ! dt/2 (Q(n-1) + Q(n)).qdot: 32 a_h dt at the first pass (Q(0) = 0), 64 a_h dt more at the
   ! second (issue 23: a_h dt qdot^2 = 64 a_h dt at both). QH 0.2: the step is the viscous
   ! bound V^(1/3)/(8 QH c) = 0.625/c, below the cube's 1/c
   call make_cube()
   part%ihq = 1
   part%qh = 0.2_wp
   w = 0.25_wp*part%qh*mat%ro*c
   do i = 1, 8
      v(:, i) = [GAMMA_HG(1, i), 0.0_wp, 0.0_wp]
   end do
   f = 0.0_wp
   call hex8_block(blk, mat, part, x, v, 1.0e-7_wp, f, res)
   call check_close(blk%ehg(1), 32.0_wp*w*1.0e-7_wp, 0.0_wp, 1.0e-12_wp, &
                    'IHQ 1 energy, first pass: dt/2 a_h qdot^2')
   call check_close(res%dt, 0.625_wp/c, 0.0_wp, 1.0e-12_wp, &
                    'IHQ 1 QH 0.2 step = V^(1/3)/(8 QH c)')
   call hex8_block(blk, mat, part, x, v, 1.0e-7_wp, f, res)
   call check_close(blk%ehg(1), 96.0_wp*w*1.0e-7_wp, 0.0_wp, 1.0e-12_wp, &
                    'IHQ 1 energy, second pass: + dt (Q(1) + Q(2))/2.qdot')
   call assert_summary()

contains

   subroutine test_bvectors()
      real(wp) :: xe(1, 8), ye(1, 8), ze(1, 8), bx(1, 8), by(1, 8), bz(1, 8), vol(1)
      real(wp) :: gb(3, 8), gv, xi(3), dn(3, 8), jac(3, 3), ji(3, 3), det, r(3, 8)
      integer :: i, a, b, cc, k
      call random_seed()
      call random_number(r)
      do i = 1, 8
         xe(1, i) = 1.3_wp*XI_NODE(1, i) + 0.25_wp*r(1, i)
         ye(1, i) = 0.7_wp*XI_NODE(2, i) + 0.25_wp*r(2, i)
         ze(1, i) = XI_NODE(3, i) + 0.25_wp*r(3, i) + 0.3_wp*XI_NODE(1, i)
      end do
      call hex8_bvectors(1, 1, xe, ye, ze, bx, by, bz, vol)
      gb = 0.0_wp; gv = 0.0_wp
      do a = -1, 1, 2
         do b = -1, 1, 2
            do cc = -1, 1, 2
               xi = [real(a, wp), real(b, wp), real(cc, wp)]/sqrt(3.0_wp)
               do i = 1, 8
                  dn(1, i) = XI_NODE(1,i)*(1 + XI_NODE(2,i)*xi(2))*(1 + XI_NODE(3,i)*xi(3))/8
                  dn(2, i) = XI_NODE(2,i)*(1 + XI_NODE(1,i)*xi(1))*(1 + XI_NODE(3,i)*xi(3))/8
                  dn(3, i) = XI_NODE(3,i)*(1 + XI_NODE(1,i)*xi(1))*(1 + XI_NODE(2,i)*xi(2))/8
               end do
               do k = 1, 3
                  jac(k, :) = [sum(dn(k, :)*xe(1, :)), sum(dn(k, :)*ye(1, :)), sum(dn(k, :)*ze(1, :))]
               end do
               call inv3(jac, ji, det)
               gv = gv + det
               gb = gb + matmul(ji, dn)*det
            end do
         end do
      end do
      call check_close(vol(1), gv, 0.0_wp, 1.0e-13_wp, 'B vectors: volume = Gauss volume')
      call check_close(maxval(abs(gb(1, :) - bx(1, :)) + abs(gb(2, :) - by(1, :)) + &
                       abs(gb(3, :) - bz(1, :))), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                       'B vectors = integral of dN/dx (2x2x2 Gauss, exact)')
   end subroutine test_bvectors

   !> A 2x2x2 patch of a distorted 2x2x2 cube: 27 nodes, interior node 14 moved off-centre,
   !> outer nodes skewed; mid-step coordinates in xm.
   subroutine make_patch(et, hq)
      integer, intent(in) :: et, hq
      integer :: i, j, k, n, e, a
      integer :: id(0:2, 0:2, 0:2)
      real(wp) :: p(3)
      call reset_block(8, et, hq)
      if (allocated(x)) deallocate(x, xm, v, f)
      allocate(x(3, 27), xm(3, 27), v(3, 27), f(3, 27))
      n = 0
      do k = 0, 2
         do j = 0, 2
            do i = 0, 2
               n = n + 1
               id(i, j, k) = n
               p = [real(i, wp), real(j, wp), real(k, wp)]
               xm(:, n) = p + 0.1_wp*[p(2)*p(3), p(1) - p(3)**2, 0.5_wp*p(1)*p(2)]
            end do
         end do
      end do
      xm(:, 14) = xm(:, 14) + [0.17_wp, -0.11_wp, 0.13_wp]
      e = 0
      do k = 0, 1
         do j = 0, 1
            do i = 0, 1
               e = e + 1
               blk%conn(:, e) = [id(i,j,k), id(i+1,j,k), id(i+1,j+1,k), id(i,j+1,k), &
                                 id(i,j,k+1), id(i+1,j,k+1), id(i+1,j+1,k+1), id(i,j+1,k+1)]
            end do
         end do
      end do
      do a = 1, 8
         blk%vol0(a) = 1.0_wp
      end do
   end subroutine make_patch

   subroutine make_cube()
      integer :: i
      call reset_block(1, 1, 2)
      if (allocated(x)) deallocate(x, xm, v, f)
      allocate(x(3, 8), xm(3, 8), v(3, 8), f(3, 8))
      do i = 1, 8
         x(:, i) = 0.5_wp*(XI_NODE(:, i) + 1.0_wp)
      end do
      xm = x
      v = 0.0_wp
      blk%conn(:, 1) = [(i, i = 1, 8)]
      blk%vol0 = 1.0_wp
   end subroutine make_cube

   subroutine reset_block(nel, et, hq)
      integer, intent(in) :: nel, et, hq
      blk = elem_block_t()
      blk%nel = nel
      blk%etype = et
      blk%nip = merge(1, 8, et == 1)
      allocate(blk%conn(8, nel), blk%elem(nel), blk%sig(nel, 6, blk%nip), blk%hv(nel, 0, blk%nip))
      allocate(blk%vol0(nel), blk%relvol(nel), blk%eint(nel), blk%ehg(nel), blk%failed(nel))
      blk%sig = 0.0_wp; blk%eint = 0.0_wp; blk%ehg = 0.0_wp; blk%failed = .false.
      blk%relvol = 1.0_wp
      blk%elem = [(i, i = 1, nel)]
      if (hq >= 4) then
         call blk%es_add(ES_HGS, 12)
      end if
      part = part_t()
      part%ihq = hq; part%qh = 0.1_wp; part%q1 = 0.0_wp; part%q2 = 0.0_wp
      if (nel > nv_chunk) stop 'test block too large'
   end subroutine reset_block
end program test_hex8
