!> Hex8 geometry on chunks of elements: the Flanagan-Belytschko uniform-strain gradient
!> vectors B_iI = integral over V of dN_I/dx_i (closed form, exact for the trilinear hex),
!> the volume V = sum_I x_I B_xI, the hourglass base vectors and the characteristic length;
!> the exact volume (2x2x2 Gauss) and first/second moments (3x3x3 Gauss: x_i x_j det J has
!> degree <= 4 in each natural coordinate; Hughes, The Finite Element Method, 1987, sec. 3.8)
!> of one element, for the element-family table (dx_element_types).
!> Ref: D.P. Flanagan, T. Belytschko, "A uniform strain hexahedron and quadrilateral with
!> orthogonal hourglass control", IJNME 17 (1981) 679-706, eq. (79) and its node permutations.
!> Node order: LS-DYNA's (1-4 bottom face counter-clockwise seen from outside... i.e. the
!> natural coordinates of node I are XI_NODE(:,I)); arrays are (nv, 8): element index first.
module dx_hex8_geometry
   use dx_kinds, only: wp, nv_chunk
   implicit none
   private
   public :: hex8_bvectors, hex8_bvectors_chunk, hex8_char_length, inv3, GAMMA_HG, XI_NODE
   public :: hex_volume, hex_moments, hex_corner_jacobians
   public :: shape_derivs, point_gradients, point_gradients_one   ! hex8_sri's Gauss points

   !> natural coordinates of the 8 nodes
   real(wp), parameter :: XI_NODE(3, 8) = reshape([ &
      -1.0_wp, -1.0_wp, -1.0_wp,   1.0_wp, -1.0_wp, -1.0_wp,   1.0_wp, 1.0_wp, -1.0_wp, &
      -1.0_wp, 1.0_wp, -1.0_wp,   -1.0_wp, -1.0_wp, 1.0_wp,    1.0_wp, -1.0_wp, 1.0_wp, &
       1.0_wp, 1.0_wp, 1.0_wp,    -1.0_wp, 1.0_wp, 1.0_wp], [3, 8])
   !> hourglass base vectors Gamma(alpha, I): nodal values of eta*zeta, zeta*xi, xi*eta, xi*eta*zeta
   real(wp), parameter :: GAMMA_HG(4, 8) = reshape([ &
       1.0_wp,  1.0_wp,  1.0_wp, -1.0_wp,   1.0_wp, -1.0_wp, -1.0_wp,  1.0_wp, &
      -1.0_wp, -1.0_wp,  1.0_wp, -1.0_wp,  -1.0_wp,  1.0_wp, -1.0_wp,  1.0_wp, &
      -1.0_wp, -1.0_wp,  1.0_wp,  1.0_wp,  -1.0_wp,  1.0_wp, -1.0_wp, -1.0_wp, &
       1.0_wp,  1.0_wp,  1.0_wp,  1.0_wp,   1.0_wp, -1.0_wp, -1.0_wp, -1.0_wp], [4, 8])
   !> node permutations that carry the formula for node 1 to node I (FB 1981, table 1)
   integer, parameter :: PERM(8, 8) = reshape([ &
      1, 2, 3, 4, 5, 6, 7, 8,   2, 3, 4, 1, 6, 7, 8, 5,   3, 4, 1, 2, 7, 8, 5, 6, &
      4, 1, 2, 3, 8, 5, 6, 7,   5, 8, 7, 6, 1, 4, 3, 2,   6, 5, 8, 7, 2, 1, 4, 3, &
      7, 6, 5, 8, 3, 2, 1, 4,   8, 7, 6, 5, 4, 3, 2, 1], [8, 8])

contains

   !> B vectors (nv,8) per direction and the volume of nv hexes with nodal coordinates x,y,z.
   pure subroutine hex8_bvectors(n, nv, x, y, z, bx, by, bz, vol)
      integer, intent(in) :: n, nv
      real(wp), intent(in) :: x(nv, 8), y(nv, 8), z(nv, 8)
      real(wp), intent(out) :: bx(nv, 8), by(nv, 8), bz(nv, 8), vol(nv)
      real(wp), dimension(nv_chunk, 8) :: xc, yc, zc, bxc, byc, bzc
      real(wp) :: vc(nv_chunk)
      integer :: i0, m
      do i0 = 0, n - 1, nv_chunk
         m = min(nv_chunk, n - i0)
         xc(1:m, :) = x(i0+1:i0+m, :); yc(1:m, :) = y(i0+1:i0+m, :); zc(1:m, :) = z(i0+1:i0+m, :)
         call hex8_bvectors_chunk(m, xc, yc, zc, bxc, byc, bzc, vc)
         bx(i0+1:i0+m, :) = bxc(1:m, :); by(i0+1:i0+m, :) = byc(1:m, :)
         bz(i0+1:i0+m, :) = bzc(1:m, :); vol(i0+1:i0+m) = vc(1:m)
      end do
   end subroutine hex8_bvectors

   !> The same for at most nv_chunk elements in arrays of the compile-time leading dimension
   !> nv_chunk: every column is a constant offset from one base address, which keeps the
   !> vectorized loop free of address-register spills (the hot path of dx_hex8).
   pure subroutine hex8_bvectors_chunk(n, x, y, z, bx, by, bz, vol)
      integer, intent(in) :: n
      real(wp), dimension(nv_chunk, 8), intent(in) :: x, y, z
      real(wp), dimension(nv_chunk, 8), intent(out) :: bx, by, bz
      real(wp), intent(out) :: vol(nv_chunk)
      integer :: ii, i
      integer :: p1, p2, p3, p4, p5, p6, p8
      real(wp), parameter :: c12 = 1.0_wp/12.0_wp
      ! element loop outside, the 8 nodes fully unrolled inside: the node permutation becomes
      ! constant column offsets and each element's 24 coordinates are loaded once (the
      ! vectorized element loop then stays in L1)
      do i = 1, n
         !GCC$ unroll 8
         do ii = 1, 8
            p1 = PERM(1, ii); p2 = PERM(2, ii); p3 = PERM(3, ii); p4 = PERM(4, ii)
            p5 = PERM(5, ii); p6 = PERM(6, ii); p8 = PERM(8, ii)
            bx(i, ii) = c12*(y(i,p2)*((z(i,p6) - z(i,p3)) - (z(i,p4) - z(i,p5))) &
                     + y(i,p3)*(z(i,p2) - z(i,p4)) &
                     + y(i,p4)*((z(i,p3) - z(i,p8)) - (z(i,p5) - z(i,p2))) &
                     + y(i,p5)*((z(i,p8) - z(i,p6)) - (z(i,p2) - z(i,p4))) &
                     + y(i,p6)*(z(i,p5) - z(i,p2)) + y(i,p8)*(z(i,p4) - z(i,p5)))
            by(i, ii) = c12*(z(i,p2)*((x(i,p6) - x(i,p3)) - (x(i,p4) - x(i,p5))) &
                     + z(i,p3)*(x(i,p2) - x(i,p4)) &
                     + z(i,p4)*((x(i,p3) - x(i,p8)) - (x(i,p5) - x(i,p2))) &
                     + z(i,p5)*((x(i,p8) - x(i,p6)) - (x(i,p2) - x(i,p4))) &
                     + z(i,p6)*(x(i,p5) - x(i,p2)) + z(i,p8)*(x(i,p4) - x(i,p5)))
            bz(i, ii) = c12*(x(i,p2)*((y(i,p6) - y(i,p3)) - (y(i,p4) - y(i,p5))) &
                     + x(i,p3)*(y(i,p2) - y(i,p4)) &
                     + x(i,p4)*((y(i,p3) - y(i,p8)) - (y(i,p5) - y(i,p2))) &
                     + x(i,p5)*((y(i,p8) - y(i,p6)) - (y(i,p2) - y(i,p4))) &
                     + x(i,p6)*(y(i,p5) - y(i,p2)) + x(i,p8)*(y(i,p4) - y(i,p5)))
         end do
      end do
      do i = 1, n
         vol(i) = x(i,1)*bx(i,1) + x(i,2)*bx(i,2) + x(i,3)*bx(i,3) + x(i,4)*bx(i,4) &
                + x(i,5)*bx(i,5) + x(i,6)*bx(i,6) + x(i,7)*bx(i,7) + x(i,8)*bx(i,8)
      end do
   end subroutine hex8_bvectors_chunk

   !> Characteristic length V / A_max (largest face area), LS-DYNA's choice for solids.
   pure subroutine hex8_char_length(n, nv, x, y, z, vol, lc)
      integer, intent(in) :: n, nv
      real(wp), intent(in) :: x(nv, 8), y(nv, 8), z(nv, 8), vol(nv)
      real(wp), intent(out) :: lc(nv)
      integer, parameter :: FACE(4, 6) = reshape([1, 2, 3, 4,  5, 6, 7, 8,  1, 2, 6, 5, &
                                                  2, 3, 7, 6,  3, 4, 8, 7,  4, 1, 5, 8], [4, 6])
      integer :: i, k
      real(wp) :: a2max, d1(3), d2(3), c(3)
      do i = 1, n
         a2max = 0.0_wp
         do k = 1, 6
            d1(1) = x(i, FACE(3,k)) - x(i, FACE(1,k))
            d1(2) = y(i, FACE(3,k)) - y(i, FACE(1,k))
            d1(3) = z(i, FACE(3,k)) - z(i, FACE(1,k))
            d2(1) = x(i, FACE(4,k)) - x(i, FACE(2,k))
            d2(2) = y(i, FACE(4,k)) - y(i, FACE(2,k))
            d2(3) = z(i, FACE(4,k)) - z(i, FACE(2,k))
            c(1) = d1(2)*d2(3) - d1(3)*d2(2)
            c(2) = d1(3)*d2(1) - d1(1)*d2(3)
            c(3) = d1(1)*d2(2) - d1(2)*d2(1)
            a2max = max(a2max, c(1)**2 + c(2)**2 + c(3)**2)
         end do
         ! face area = |d1 x d2|/2 (all faces collapsed to points: no division by zero)
         lc(i) = vol(i)/max(0.5_wp*sqrt(a2max), tiny(1.0_wp))
      end do
   end subroutine hex8_char_length

   !> Inverse ji and determinant det of a 3x3 matrix (a zero determinant is replaced by tiny).
   pure subroutine inv3(j, ji, det)
      real(wp), intent(in) :: j(3, 3)
      real(wp), intent(out) :: ji(3, 3), det
      det = j(1,1)*(j(2,2)*j(3,3) - j(2,3)*j(3,2)) - j(1,2)*(j(2,1)*j(3,3) - j(2,3)*j(3,1)) &
          + j(1,3)*(j(2,1)*j(3,2) - j(2,2)*j(3,1))
      if (det == 0.0_wp) det = tiny(1.0_wp)
      ji(1,1) = (j(2,2)*j(3,3) - j(2,3)*j(3,2))/det
      ji(1,2) = -(j(1,2)*j(3,3) - j(1,3)*j(3,2))/det
      ji(1,3) = (j(1,2)*j(2,3) - j(1,3)*j(2,2))/det
      ji(2,1) = -(j(2,1)*j(3,3) - j(2,3)*j(3,1))/det
      ji(2,2) = (j(1,1)*j(3,3) - j(1,3)*j(3,1))/det
      ji(2,3) = -(j(1,1)*j(2,3) - j(1,3)*j(2,1))/det
      ji(3,1) = (j(2,1)*j(3,2) - j(2,2)*j(3,1))/det
      ji(3,2) = -(j(1,1)*j(3,2) - j(1,2)*j(3,1))/det
      ji(3,3) = (j(1,1)*j(2,2) - j(1,2)*j(2,1))/det
   end subroutine inv3
   !> Corner Jacobians cj(I) = det[dx/dxi, dx/deta, dx/dzeta] at node I of the trilinear
   !> hexahedron xe(3,8), from the three edges leaving node I (each edge vector times the sign
   !> that points it along +xi, +eta, +zeta), in units of the element's volume: 1 at each
   !> corner of any parallelepiped, <= 0 at a folded (locally inverted) corner (Knupp 2000,
   !> "Achieving finite element mesh quality via optimization of the Jacobian matrix norm",
   !> IJNME 48:1165-1185: the corner Jacobians of the hexahedron).
   pure subroutine hex_corner_jacobians(xe, vol, cj)
      real(wp), intent(in) :: xe(3, 8), vol
      real(wp), intent(out) :: cj(8)
      real(wp) :: a(3, 3)
      integer :: i, k, j
      do i = 1, 8
         do k = 1, 3
            do j = 1, 8        ! the neighbour of node i across natural direction k
               if (all(merge(-XI_NODE(:, i), XI_NODE(:, i), [1, 2, 3] == k) == XI_NODE(:, j))) &
                  exit
            end do
            a(:, k) = (xe(:, j) - xe(:, i))*(-XI_NODE(k, i))
         end do
         cj(i) = (a(1,1)*(a(2,2)*a(3,3) - a(3,2)*a(2,3)) - a(1,2)*(a(2,1)*a(3,3) - a(3,1)*a(2,3)) &
                 + a(1,3)*(a(2,1)*a(3,2) - a(3,1)*a(2,2)))/vol
      end do
   end subroutine hex_corner_jacobians

   !> Exact volume of the trilinear hexahedron with corner coordinates xe(3,8)
   !> (LS-DYNA node order: 1-4 one face counter-clockwise seen from 5-8).
   pure function hex_volume(xe) result(vol)
      real(wp), intent(in) :: xe(3, 8)
      real(wp) :: vol
      real(wp), parameter :: xi(8) = [-1, 1, 1, -1, -1, 1, 1, -1]*1.0_wp
      real(wp), parameter :: et(8) = [-1, -1, 1, 1, -1, -1, 1, 1]*1.0_wp
      real(wp), parameter :: ze(8) = [-1, -1, -1, -1, 1, 1, 1, 1]*1.0_wp
      real(wp), parameter :: g = 0.577350269189625764509148780502_wp
      real(wp) :: jac(3, 3), dn(8, 3), a, b, c
      integer :: ia, ib, ic, k
      vol = 0.0_wp
      do ia = -1, 1, 2
         do ib = -1, 1, 2
            do ic = -1, 1, 2
               a = ia*g; b = ib*g; c = ic*g
               dn(:, 1) = 0.125_wp*xi*(1 + et*b)*(1 + ze*c)
               dn(:, 2) = 0.125_wp*et*(1 + xi*a)*(1 + ze*c)
               dn(:, 3) = 0.125_wp*ze*(1 + xi*a)*(1 + et*b)
               do k = 1, 3
                  jac(:, k) = matmul(xe, dn(:, k))
               end do
               vol = vol + jac(1, 1)*(jac(2, 2)*jac(3, 3) - jac(3, 2)*jac(2, 3)) &
                         - jac(1, 2)*(jac(2, 1)*jac(3, 3) - jac(3, 1)*jac(2, 3)) &
                         + jac(1, 3)*(jac(2, 1)*jac(3, 2) - jac(3, 1)*jac(2, 2))
            end do
         end do
      end do
   end function hex_volume

   !> Moments of the trilinear hexahedron with corners xe(3,8) (LS-DYNA node order); exact.
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
end module dx_hex8_geometry
