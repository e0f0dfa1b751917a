!> Mass properties of rigid bodies: volume, first and second moments of trilinear hexahedra
!> (3x3x3 Gauss-Legendre quadrature: the integrand x_i x_j det J is at most of degree 4 in each
!> natural coordinate of a trilinear map, which the 3-point rule integrates exactly; Hughes,
!> The Finite Element Method, 1987, sec. 3.8), point masses, the inertia tensor about the
!> centre of mass, and its principal axes by the cyclic Jacobi method (Golub & Van Loan,
!> Matrix Computations, 4th ed., sec. 8.5).
!> Inertia tensor: I = int rho (|r|^2 1 - r r^T) dV, r = x - x_c (positive products of
!> inertia convention of LS-DYNA's *PART_INERTIA: IXY = -int rho x y dV).
module dx_rigid_mass
   use dx_kinds, only: wp
   implicit none
   private
   public :: hex_moments, inertia_about, principal_axes, rotation_about

contains

   !> vol = int dV, m1 = int (x - xref) dV, m2 = int (x - xref)(x - xref)^T dV over the
   !> trilinear hexahedron with corners xe(3,8) (LS-DYNA node order); exact.
   pure subroutine hex_moments(xe, xref, vol, m1, m2)
      real(wp), intent(in) :: xe(3, 8), xref(3)
      real(wp), intent(out) :: vol, m1(3), m2(3, 3)
      real(wp), parameter :: xi(8) = [-1, 1, 1, -1, -1, 1, 1, -1]*1.0_wp
      real(wp), parameter :: et(8) = [-1, -1, 1, 1, -1, -1, 1, 1]*1.0_wp
      real(wp), parameter :: ze(8) = [-1, -1, -1, -1, 1, 1, 1, 1]*1.0_wp
      real(wp), parameter :: gp(3) = [-0.774596669241483377035853079956_wp, 0.0_wp, &
                                      0.774596669241483377035853079956_wp]
      real(wp), parameter :: gw(3) = [5.0_wp/9.0_wp, 8.0_wp/9.0_wp, 5.0_wp/9.0_wp]
      real(wp) :: jac(3, 3), dn(8, 3), sh(8), a, b, c, detj, wdet, r(3), xl(3, 8)
      integer :: ia, ib, ic, k, j
      do k = 1, 8
         xl(:, k) = xe(:, k) - xref
      end do
      vol = 0.0_wp
      m1 = 0.0_wp
      m2 = 0.0_wp
      do ia = 1, 3
         do ib = 1, 3
            do ic = 1, 3
               a = gp(ia); b = gp(ib); c = gp(ic)
               sh = 0.125_wp*(1 + xi*a)*(1 + et*b)*(1 + ze*c)
               dn(:, 1) = 0.125_wp*xi*(1 + et*b)*(1 + ze*c)
               dn(:, 2) = 0.125_wp*et*(1 + xi*a)*(1 + ze*c)
               dn(:, 3) = 0.125_wp*ze*(1 + xi*a)*(1 + et*b)
               do k = 1, 3
                  jac(:, k) = matmul(xl, dn(:, k))
               end do
               detj = jac(1, 1)*(jac(2, 2)*jac(3, 3) - jac(3, 2)*jac(2, 3)) &
                    - jac(1, 2)*(jac(2, 1)*jac(3, 3) - jac(3, 1)*jac(2, 3)) &
                    + jac(1, 3)*(jac(2, 1)*jac(3, 2) - jac(3, 1)*jac(2, 2))
               wdet = gw(ia)*gw(ib)*gw(ic)*detj
               r = matmul(xl, sh)
               vol = vol + wdet
               m1 = m1 + wdet*r
               do j = 1, 3
                  m2(:, j) = m2(:, j) + wdet*r*r(j)
               end do
            end do
         end do
      end do
   end subroutine hex_moments

   !> Inertia tensor about xc of a body with mass m, first moment m1 = int rho (x - xref) dV
   !> and second moment m2 = int rho (x - xref)(x - xref)^T dV (parallel-axis shift).
   pure function inertia_about(m, m1, m2, xref, xc) result(ten)
      real(wp), intent(in) :: m, m1(3), m2(3, 3), xref(3), xc(3)
      real(wp) :: ten(3, 3)
      real(wp) :: d(3), s(3, 3)
      integer :: i, j
      d = xc - xref
      ! second moment about xc: m2 - m1 d^T - d m1^T + m d d^T
      do j = 1, 3
         do i = 1, 3
            s(i, j) = m2(i, j) - m1(i)*d(j) - d(i)*m1(j) + m*d(i)*d(j)
         end do
      end do
      ten = -s
      do i = 1, 3
         ten(i, i) = ten(i, i) + (s(1, 1) + s(2, 2) + s(3, 3))
      end do
   end function inertia_about

   !> Eigenvalues ip (ascending) and eigenvectors q (columns, a proper rotation, det = +1) of
   !> the symmetric 3x3 matrix a, by cyclic Jacobi rotations.
   pure subroutine principal_axes(a, ip, q)
      real(wp), intent(in) :: a(3, 3)
      real(wp), intent(out) :: ip(3), q(3, 3)
      real(wp) :: b(3, 3), off, th, t, c, s, tmp(3), scale
      integer :: sweep, p, r, k, i, j
      b = 0.5_wp*(a + transpose(a))
      q = 0.0_wp
      do k = 1, 3
         q(k, k) = 1.0_wp
      end do
      scale = max(abs(b(1, 1)) + abs(b(2, 2)) + abs(b(3, 3)), tiny(1.0_wp))
      do sweep = 1, 50
         off = abs(b(1, 2)) + abs(b(1, 3)) + abs(b(2, 3))
         if (off <= 1.0e-18_wp*scale) exit
         do p = 1, 2
            do r = p + 1, 3
               if (abs(b(p, r)) <= 1.0e-18_wp*scale) then
                  b(p, r) = 0.0_wp; b(r, p) = 0.0_wp
                  cycle
               end if
               th = b(r, r) - b(p, p)
               if (abs(th) > 1.0e8_wp*abs(b(p, r))) then
                  t = b(p, r)/th          ! small rotation; avoids th**2 overflow
               else
                  th = th/(2.0_wp*b(p, r))
                  t = sign(1.0_wp, th)/(abs(th) + sqrt(th*th + 1.0_wp))
               end if
               c = 1.0_wp/sqrt(t*t + 1.0_wp)
               s = t*c
               ! b <- J^T b J with the rotation in the (p, r) plane
               do k = 1, 3
                  tmp(k) = b(k, p)
                  b(k, p) = c*b(k, p) - s*b(k, r)
                  b(k, r) = s*tmp(k) + c*b(k, r)
               end do
               do k = 1, 3
                  tmp(k) = b(p, k)
                  b(p, k) = c*b(p, k) - s*b(r, k)
                  b(r, k) = s*tmp(k) + c*b(r, k)
               end do
               do k = 1, 3
                  tmp(k) = q(k, p)
                  q(k, p) = c*q(k, p) - s*q(k, r)
                  q(k, r) = s*tmp(k) + c*q(k, r)
               end do
            end do
         end do
      end do
      do k = 1, 3
         ip(k) = b(k, k)
      end do
      ! ascending order
      do i = 1, 2
         do j = i + 1, 3
            if (ip(j) < ip(i)) then
               t = ip(i); ip(i) = ip(j); ip(j) = t
               tmp = q(:, i); q(:, i) = q(:, j); q(:, j) = tmp
            end if
         end do
      end do
      ! each axis points along its largest component; then make the frame right-handed
      do k = 1, 3
         i = maxloc(abs(q(:, k)), 1)
         if (q(i, k) < 0.0_wp) q(:, k) = -q(:, k)
      end do
      if (det3(q) < 0.0_wp) q(:, 3) = -q(:, 3)
   end subroutine principal_axes

   pure real(wp) function det3(a)
      real(wp), intent(in) :: a(3, 3)
      det3 = a(1, 1)*(a(2, 2)*a(3, 3) - a(3, 2)*a(2, 3)) &
           - a(1, 2)*(a(2, 1)*a(3, 3) - a(3, 1)*a(2, 3)) &
           + a(1, 3)*(a(2, 1)*a(3, 2) - a(3, 1)*a(2, 2))
   end function det3

   !> The rotation by angle th about coordinate axis k (1, 2, 3), exact (cos, sin).
   pure function rotation_about(k, th) result(r)
      integer, intent(in) :: k
      real(wp), intent(in) :: th
      real(wp) :: r(3, 3)
      real(wp) :: c, s
      integer :: i, j
      c = cos(th); s = sin(th)
      i = mod(k, 3) + 1
      j = mod(k + 1, 3) + 1
      r = 0.0_wp
      r(k, k) = 1.0_wp
      r(i, i) = c; r(j, j) = c
      r(j, i) = s; r(i, j) = -s
   end function rotation_about
end module dx_rigid_mass
