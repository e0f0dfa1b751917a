!> Mass properties of rigid bodies: the elements' volume, first and second moments come from
!> the element-family table (dx_element_types, elem_moments), point masses, the inertia
!> tensor about the
!> centre of mass, and its principal axes by the cyclic Jacobi method (Golub & Van Loan,
!> Matrix Computations, 4th ed., sec. 8.5).
!> Inertia tensor: I = int rho (|r|^2 1 - r r^T) dV, r = x - x_c (positive products of
!> inertia convention of LS-DYNA's *PART_INERTIA: IXY = -int rho x y dV).
module dx_rigid_mass
   use dx_kinds, only: wp
   implicit none
   private
   public :: inertia_about, principal_axes, rotation_about

contains

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
