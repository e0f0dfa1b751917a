!> Unit tests of the 2D quadrilateral geometry (dx_quad2d, dx_element_types): the B vectors
!> B_I = dA/dx_I of a general quadrilateral sum to zero and reproduce the area, sum_I B_xI x_I
!> = sum_I B_yI y_I = A, sum_I B_xI y_I = 0 (a linear field is differentiated exactly:
!> the patch-test property), the area against the shoelace formula, the volume per radian
!> int r dA against the area times the centroid radius of the polygon (Pappus: the centroid
!> by the triangle decomposition, an independent formula), a triangle (N4 = N3) likewise,
!> and the time-step length area / diameter of a square (h/sqrt(2), DYNA2D's area over the
!> diagonal) and of a right triangle (half its smallest altitude). Tolerances: a few ulps of
!> the values (the formulas are sums of 4-8 products of O(1) numbers).
program test_quad2d
   use dx_kinds, only: wp
   use dx_element_types, only: quad2d_area, quad2d_rvol, elem_length, elem_volume, &
                               ETYPE_QUAD2D_PS, ETYPE_QUAD2D_VW
   use dx_quad2d, only: quad2d_geometry
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: tol = 16.0_wp*epsilon(1.0_wp)
   real(wp) :: x(1, 4), y(1, 4), bx(1, 4), by(1, 4), a(1), v(1), xe(3, 4), ash, cx, at, ta
   integer :: k

   ! ---- a general convex quadrilateral, counter-clockwise
   xe = reshape([1.0_wp, 0.0_wp, 0.0_wp, 4.0_wp, 1.0_wp, 0.0_wp, 3.0_wp, 3.0_wp, 0.0_wp, &
                 0.5_wp, 2.0_wp, 0.0_wp], [3, 4])
   x(1, :) = xe(1, :); y(1, :) = xe(2, :)
   call quad2d_geometry(1, .true., x, y, bx, by, a, v)
   ash = 0.0_wp
   do k = 1, 4
      ash = ash + 0.5_wp*(xe(1, k)*xe(2, mod(k, 4) + 1) - xe(1, mod(k, 4) + 1)*xe(2, k))
   end do
   call check_close(a(1), ash, tol*ash, 0.0_wp, 'quad: area = shoelace')
   call check_close(quad2d_area(xe), ash, tol*ash, 0.0_wp, 'quad: quad2d_area = shoelace')
   call check(abs(sum(bx(1, :))) < tol .and. abs(sum(by(1, :))) < tol, 'quad: sum of B = 0')
   call check_close(sum(bx(1, :)*x(1, :)), a(1), tol*a(1), 0.0_wp, 'quad: B_x.x = A')
   call check_close(sum(by(1, :)*y(1, :)), a(1), tol*a(1), 0.0_wp, 'quad: B_y.y = A')
   call check(abs(sum(bx(1, :)*y(1, :))) < tol*a(1) .and. &
              abs(sum(by(1, :)*x(1, :))) < tol*a(1), 'quad: B_x.y = B_y.x = 0')
   ! centroid radius by the two triangles 1-2-3 and 1-3-4
   at = tri_area(xe(:, 1), xe(:, 2), xe(:, 3))
   ta = tri_area(xe(:, 1), xe(:, 3), xe(:, 4))
   cx = (at*(xe(1, 1) + xe(1, 2) + xe(1, 3)) + ta*(xe(1, 1) + xe(1, 3) + xe(1, 4)))/ &
        (3.0_wp*(at + ta))
   call check_close(v(1), ash*cx, tol*ash*cx, 0.0_wp, 'quad: int r dA = A rbar (Pappus)')
   call check_close(quad2d_rvol(xe), v(1), tol*v(1), 0.0_wp, 'quad: quad2d_rvol = geometry')
   call check_close(elem_volume(ETYPE_QUAD2D_VW, xe), v(1), tol*v(1), 0.0_wp, &
                    'quad: elem_volume of ELFORM 15 = int r dA')
   call check_close(elem_volume(ETYPE_QUAD2D_PS, xe), ash, tol*ash, 0.0_wp, &
                    'quad: elem_volume of ELFORM 13 = area')

   ! ---- a triangle N4 = N3
   xe(:, 4) = xe(:, 3)
   x(1, :) = xe(1, :); y(1, :) = xe(2, :)
   call quad2d_geometry(1, .true., x, y, bx, by, a, v)
   at = tri_area(xe(:, 1), xe(:, 2), xe(:, 3))
   call check_close(a(1), at, tol*at, 0.0_wp, 'triangle: area')
   call check_close(v(1), at*(xe(1, 1) + xe(1, 2) + xe(1, 3))/3.0_wp, tol*v(1), 0.0_wp, &
                    'triangle: int r dA = A rbar')
   call check_close(sum(bx(1, :)*x(1, :)), a(1), tol*a(1), 0.0_wp, 'triangle: B_x.x = A')

   ! ---- time-step lengths
   xe = reshape([0.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 2.0_wp, 0.0_wp, &
                 0.0_wp, 2.0_wp, 0.0_wp], [3, 4])
   call check_close(elem_length(ETYPE_QUAD2D_PS, xe, 4.0_wp), sqrt(2.0_wp), tol, 0.0_wp, &
                    'square: length A/diagonal = h/sqrt(2)')
   xe(:, 3) = [0.0_wp, 2.0_wp, 0.0_wp]
   xe(:, 4) = xe(:, 3)
   ! right triangle legs 2: area 2, longest edge 2 sqrt(2): L = 1/sqrt(2) (half the altitude)
   call check_close(elem_length(ETYPE_QUAD2D_PS, xe, 2.0_wp), 1.0_wp/sqrt(2.0_wp), tol, &
                    0.0_wp, 'right triangle: length A/longest edge')
   call assert_summary()

contains

   pure real(wp) function tri_area(p, q, r)
      real(wp), intent(in) :: p(3), q(3), r(3)
      tri_area = 0.5_wp*((q(1) - p(1))*(r(2) - p(2)) - (r(1) - p(1))*(q(2) - p(2)))
   end function tri_area
end program test_quad2d
