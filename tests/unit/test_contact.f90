!> Unit tests of the contact kernels: closest-point projection on a warped 4-node segment and
!> on a triangle (exact parametric point and gap), the on/off-segment test, the penalty force
!> of one slave node (magnitude k|g| along the normal, zero resultant over slave and master
!> nodes, shape-function split), the Coulomb limit of the friction force, and the bucket sort
!> against a brute-force search (same candidate sets for 400 random nodes).
program test_contact
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_contact_types, only: contact_pass_t, contact_iface_t
   use dx_contact_penalty, only: project_point, pass_forces
   use dx_contact_search, only: bucket_sort
   use dx_assert, only: check, check_close, assert_summary
   implicit none

   call test_projection_quad()
   call test_projection_tri()
   call test_force()
   call test_friction()
   call test_bucket_sort()
   call assert_summary()

contains

   !> x(xi, eta) and its unit normal on a bilinear quad
   subroutine quad_point(xe, xi, x, n)
      real(wp), intent(in) :: xe(3, 4), xi(2)
      real(wp), intent(out) :: x(3), n(3)
      real(wp), parameter :: a(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
      real(wp), parameter :: b(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]
      real(wp) :: t1(3), t2(3)
      integer :: k
      x = 0.0_wp; t1 = 0.0_wp; t2 = 0.0_wp
      do k = 1, 4
         x = x + 0.25_wp*(1 + a(k)*xi(1))*(1 + b(k)*xi(2))*xe(:, k)
         t1 = t1 + 0.25_wp*a(k)*(1 + b(k)*xi(2))*xe(:, k)
         t2 = t2 + 0.25_wp*b(k)*(1 + a(k)*xi(1))*xe(:, k)
      end do
      n = cross(t1, t2)
      n = n/norm2(n)
   end subroutine quad_point

   subroutine test_projection_quad()
      real(wp) :: xe(3, 4), x(3), n(3), nsh(4), xc(3), nrm(3), xi(2), g
      logical :: inside
      write(*, '(a)') 'projection on a warped 4-node segment'
      ! a warped quad (node 3 lifted by 0.3, node 2 skewed)
      xe(:, 1) = [0.0_wp, 0.0_wp, 0.0_wp]
      xe(:, 2) = [2.0_wp, 0.2_wp, 0.0_wp]
      xe(:, 3) = [2.1_wp, 1.9_wp, 0.3_wp]
      xe(:, 4) = [-0.1_wp, 2.0_wp, 0.0_wp]
      call quad_point(xe, [0.3_wp, -0.55_wp], x, n)
      ! a point at -0.05 along the normal: its closest point is (0.3, -0.55), gap -0.05
      call project_point(4, xe, x - 0.05_wp*n, nsh, xc, nrm, xi, inside)
      g = dot_product(x - 0.05_wp*n - xc, nrm)
      call check(inside, 'point over the segment is inside')
      call check_close(xi(1), 0.3_wp, 1.0e-10_wp, 0.0_wp, 'xi recovered')
      call check_close(xi(2), -0.55_wp, 1.0e-10_wp, 0.0_wp, 'eta recovered')
      call check_close(g, -0.05_wp, 1.0e-12_wp, 0.0_wp, 'gap = -0.05')
      call check_close(sum(nsh), 1.0_wp, 1.0e-14_wp, 0.0_wp, 'shape functions sum to 1')
      call quad_point(xe, [1.2_wp, 0.0_wp], x, n)
      call project_point(4, xe, x + 0.01_wp*n, nsh, xc, nrm, xi, inside)
      call check(.not. inside, 'point beyond edge xi = 1 is outside')
      call check_close(xi(1), 1.2_wp, 1.0e-8_wp, 0.0_wp, 'xi beyond the edge recovered')
   end subroutine test_projection_quad

   subroutine test_projection_tri()
      real(wp) :: xe(3, 4), xs(3), nsh(4), xc(3), nrm(3), xi(2), n(3)
      logical :: inside
      write(*, '(a)') 'projection on a 3-node segment'
      xe = 0.0_wp
      xe(:, 1) = [0.0_wp, 0.0_wp, 1.0_wp]
      xe(:, 2) = [1.0_wp, 0.0_wp, 1.2_wp]
      xe(:, 3) = [0.0_wp, 1.0_wp, 0.9_wp]
      xe(:, 4) = xe(:, 3)
      n = cross(xe(:, 2) - xe(:, 1), xe(:, 3) - xe(:, 1))
      n = n/norm2(n)
      xs = 0.5_wp*xe(:, 1) + 0.2_wp*xe(:, 2) + 0.3_wp*xe(:, 3) + 0.07_wp*n
      call project_point(3, xe, xs, nsh, xc, nrm, xi, inside)
      call check(inside, 'inside the triangle')
      call check_close(nsh(1), 0.5_wp, 1.0e-13_wp, 0.0_wp, 'N1 = 0.5')
      call check_close(nsh(2), 0.2_wp, 1.0e-13_wp, 0.0_wp, 'N2 = 0.2')
      call check_close(nsh(3), 0.3_wp, 1.0e-13_wp, 0.0_wp, 'N3 = 0.3')
      call check_close(dot_product(xs - xc, nrm), 0.07_wp, 1.0e-13_wp, 0.0_wp, 'gap = +0.07')
   end subroutine test_projection_tri

   !> one flat unit segment in z = 0 (nodes 1..4), slave node 5 over (0.5, 0.25)
   subroutine one_segment(p, x, v, mass, zs)
      type(contact_pass_t), intent(out) :: p
      real(wp), allocatable, intent(out) :: x(:, :), v(:, :), mass(:)
      real(wp), intent(in) :: zs
      allocate(x(3, 5), v(3, 5), mass(5))
      x(:, 1) = [0.0_wp, 0.0_wp, 0.0_wp]; x(:, 2) = [1.0_wp, 0.0_wp, 0.0_wp]
      x(:, 3) = [1.0_wp, 1.0_wp, 0.0_wp]; x(:, 4) = [0.0_wp, 1.0_wp, 0.0_wp]
      x(:, 5) = [0.5_wp, 0.25_wp, zs]
      v = 0.0_wp
      mass = 1.0_wp
      p%nnode = 1; p%nseg = 1
      p%node = [5]
      allocate(p%seg(4, 1)); p%seg(:, 1) = [1, 2, 3, 4]
      p%nsn = [4]
      p%kseg = [100.0_wp]
      p%depth = [0.5_wp]
      p%area = [1.0_wp]
      allocate(p%owner(8, 1)); p%owner = 0
      allocate(p%ft(3, 1), p%iseg(1), p%gap(1)); p%ft = 0.0_wp; p%iseg = 0; p%gap = 0.0_wp
      allocate(p%cand_ptr(2), p%cand(0)); p%cand_ptr = 1
   end subroutine one_segment

   subroutine test_force()
      type(contact_pass_t) :: p
      type(contact_iface_t) :: f
      real(wp), allocatable :: x(:, :), v(:, :), mass(:), fc(:, :)
      real(wp) :: fsum(3), w2(5)
      integer :: na
      write(*, '(a)') 'penalty force of one slave node'
      call one_segment(p, x, v, mass, -0.01_wp)
      call bucket_sort(p, x, 0.5_wp)
      allocate(fc(3, 5)); fc = 0.0_wp
      fsum = 0.0_wp; w2 = 0.0_wp; na = 0
      call pass_forces(f, p, x, v, mass, 1.0e-3_wp, 1.0e-3_wp, 0.0_wp, fc, fsum, w2, na)
      call check(na == 1, 'node in contact')
      call check_close(fc(3, 5), 100.0_wp*0.01_wp, 0.0_wp, 1.0e-12_wp, 'slave force k|g| along +z')
      call check_close(norm2(sum(fc, dim=2)), 0.0_wp, 1.0e-14_wp, 0.0_wp, 'zero resultant')
      ! bilinear split at (0.5, 0.25): N = (0.375, 0.375, 0.125, 0.125)
      call check_close(fc(3, 1), -0.375_wp*1.0_wp, 0.0_wp, 1.0e-12_wp, 'master node 1 share')
      call check_close(fc(3, 3), -0.125_wp*1.0_wp, 0.0_wp, 1.0e-12_wp, 'master node 3 share')
      call check_close(w2(5), 200.0_wp, 0.0_wp, 1.0e-12_wp, 'stiffness row sum 2k on the slave')
      call check_close(w2(1), 200.0_wp*0.375_wp, 0.0_wp, 1.0e-12_wp, &
                       'stiffness row sum 2k N_1 on master node 1')
      ! a node above the segment: no force
      x(3, 5) = 0.01_wp
      fc = 0.0_wp; na = 0
      call pass_forces(f, p, x, v, mass, 1.0e-3_wp, 1.0e-3_wp, 0.0_wp, fc, fsum, w2, na)
      call check(na == 0 .and. all(fc == 0.0_wp), 'no force above the segment')
   end subroutine test_force

   subroutine test_friction()
      type(contact_pass_t) :: p
      type(contact_iface_t) :: f
      real(wp), allocatable :: x(:, :), v(:, :), mass(:), fc(:, :)
      real(wp) :: fsum(3), w2(5), ft
      integer :: na
      write(*, '(a)') 'Coulomb friction'
      call one_segment(p, x, v, mass, -0.01_wp)
      call bucket_sort(p, x, 0.5_wp)
      f%fs = 0.3_wp; f%fd = 0.2_wp; f%dc = 2.0_wp
      v(:, 5) = [1.0_wp, 0.0_wp, 0.0_wp]      ! sliding at |v_t| = 1 along x
      allocate(fc(3, 5)); fc = 0.0_wp
      fsum = 0.0_wp; w2 = 0.0_wp; na = 0
      ! slip increment k*dt*v = 100*0.1*1 = 10 >> mu*fn: sliding, |f_t| = mu fn
      call pass_forces(f, p, x, v, mass, 0.1_wp, 0.1_wp, 0.0_wp, fc, fsum, w2, na)
      ft = -fc(1, 5)
      call check_close(ft, (0.2_wp + 0.1_wp*exp(-2.0_wp))*1.0_wp, 0.0_wp, 1.0e-12_wp, &
                       'sliding: f_t = (FD + (FS-FD) exp(-DC v)) f_n, against the motion')
      call check_close(norm2(sum(fc, dim=2)), 0.0_wp, 1.0e-14_wp, 0.0_wp, 'zero resultant')
      ! sticking: slip increment 100*1e-4*1 = 0.01 < mu fn: elastic trial force k du
      p%ft = 0.0_wp; fc = 0.0_wp
      call pass_forces(f, p, x, v, mass, 1.0e-4_wp, 1.0e-4_wp, 0.0_wp, fc, fsum, w2, na)
      call check_close(-fc(1, 5), 100.0_wp*1.0e-4_wp, 0.0_wp, 1.0e-12_wp, &
                       'sticking: f_t = k du below the Coulomb limit')
   end subroutine test_friction

   subroutine test_bucket_sort()
      type(contact_pass_t) :: p
      real(wp), allocatable :: x(:, :)
      real(wp) :: r(3), lo(3), hi(3), reach
      integer :: i, j, k, s, n, nbad, nnode, m
      logical, allocatable :: hit(:)
      write(*, '(a)') 'bucket sort against brute force'
      m = 12                                  ! m x m segments on a wavy surface
      nnode = 400
      allocate(x(3, (m + 1)**2 + nnode))
      do j = 0, m
         do i = 0, m
            x(:, 1 + i + (m + 1)*j) = [real(i, wp), real(j, wp), 0.3_wp*sin(0.7_wp*i)*cos(0.5_wp*j)]
         end do
      end do
      p%nseg = m*m
      allocate(p%seg(4, p%nseg), p%nsn(p%nseg), p%depth(p%nseg), p%owner(8, p%nseg))
      p%owner = 0
      s = 0
      do j = 0, m - 1
         do i = 0, m - 1
            s = s + 1
            k = 1 + i + (m + 1)*j
            p%seg(:, s) = [k, k + 1, k + m + 2, k + m + 1]
         end do
      end do
      p%nsn = 4
      p%depth = 0.4_wp
      p%nnode = nnode
      allocate(p%node(nnode), p%cand_ptr(nnode + 1), p%cand(0))
      call random_seed()
      do i = 1, nnode
         call random_number(r)
         n = (m + 1)**2 + i
         x(:, n) = [-1.0_wp + (m + 2)*r(1), -1.0_wp + (m + 2)*r(2), -1.5_wp + 3.0_wp*r(3)]
         p%node(i) = n
      end do
      call bucket_sort(p, x, 0.25_wp)
      reach = 0.25_wp + 0.4_wp
      allocate(hit(p%nseg))
      nbad = 0
      do i = 1, nnode
         hit = .false.
         hit(p%cand(p%cand_ptr(i):p%cand_ptr(i + 1) - 1)) = .true.
         do s = 1, p%nseg
            lo = minval(x(:, p%seg(:, s)), dim=2) - reach
            hi = maxval(x(:, p%seg(:, s)), dim=2) + reach
            if ((all(x(:, p%node(i)) >= lo) .and. all(x(:, p%node(i)) <= hi)) .neqv. hit(s)) &
               nbad = nbad + 1
         end do
      end do
      call check(nbad == 0, 'candidates = brute-force box test for 400 nodes x 144 segments')
      call check(size(p%cand) > 0, 'some candidates found')
      call check(p%clear < 0.0_wp, 'a sort with candidates records no clear gap')
      ! the slave nodes lifted to z = 5: no candidate, and the gap along z between the nodes
      ! and the grown segment boxes (top at the surface's highest node + margin + depth) is
      ! recorded for the idle sorts of dx_contact
      x(3, (m + 1)**2 + 1:) = 5.0_wp
      call bucket_sort(p, x, 0.25_wp)
      call check(size(p%cand) == 0, 'nodes lifted clear: no candidate')
      call check_close(p%clear, 5.0_wp - (maxval(x(3, 1:(m + 1)**2)) + reach), 1.0e-12_wp, &
                       0.0_wp, 'clear gap = 5 - (highest surface node + margin + depth)')
   end subroutine test_bucket_sort
end program test_contact
