!> Unit test of the 2D contact's search cells (dx_contact2d_bins): for edges of random
!> lengths (0.1 to 3) and directions and 4000 random points around them, every point-edge
!> pair that the contact can accept (dx_contact2d: projection xi in [-0.1, 1.1], gap within
!> half the edge's length; here |gap| < L/2, both sides) has the edge in the point's cell, and
!> each cell lists its edges in ascending order (so a node meets them in the all-pairs order).
!> Also: points placed at the corners of the acceptance region (xi = -0.1 or 1.1, |gap| just
!> under L/2) of every edge. (The fallback for coordinates that are not finite is not
!> tested here: the debug build traps the invalid operation first.)
!> The counts are exact (a missed pair would change contact results).
program test_contact2d_bins
   use dx_kinds, only: wp
   use dx_contact2d_bins, only: c2d_bins_t, bins_build, bins_range
   use dx_assert, only: check, assert_summary
   implicit none
   integer, parameter :: ne = 60, np = 4000
   real(wp) :: x(2, 2*ne + np + 4*ne), r(4), ang, el, t(2), nv(2), xi, g
   integer :: edge(2, ne), j, k, j1, j2, nacc, nmiss, nord, q
   type(c2d_bins_t) :: bn
   call random_seed(put=[(12345 + k, k = 1, 64)])
   do j = 1, ne
      call random_number(r)
      el = 0.1_wp + 2.9_wp*r(3)
      ang = 6.283185307179586_wp*r(4)
      x(:, 2*j - 1) = 20.0_wp*r(1:2)
      x(:, 2*j) = x(:, 2*j - 1) + el*[cos(ang), sin(ang)]
      edge(:, j) = [2*j - 1, 2*j]
   end do
   do k = 1, np
      call random_number(r)
      x(:, 2*ne + k) = -2.0_wp + 24.0_wp*r(1:2)
   end do
   q = 2*ne + np
   do j = 1, ne                 ! the corners of each edge's acceptance region
      t = x(:, edge(2, j)) - x(:, edge(1, j))
      el = norm2(t)
      t = t/el
      nv = [t(2), -t(1)]
      x(:, q + 1) = x(:, edge(1, j)) - 0.1_wp*el*t + 0.4999_wp*el*nv
      x(:, q + 2) = x(:, edge(1, j)) - 0.1_wp*el*t - 0.4999_wp*el*nv
      x(:, q + 3) = x(:, edge(2, j)) + 0.1_wp*el*t + 0.4999_wp*el*nv
      x(:, q + 4) = x(:, edge(2, j)) + 0.1_wp*el*t - 0.4999_wp*el*nv
      q = q + 4
   end do
   call bins_build(bn, edge, x)
   call check(.not. bn%whole .and. bn%nx*bn%ny > 1, 'bins: a grid of several cells')
   nacc = 0; nmiss = 0; nord = 0
   do k = 2*ne + 1, size(x, 2)
      call bins_range(bn, x(:, k), j1, j2)
      if (j2 > j1) then
         if (any(bn%list(j1 + 1:j2) <= bn%list(j1:j2 - 1))) nord = nord + 1
      end if
      do j = 1, ne
         t = x(:, edge(2, j)) - x(:, edge(1, j))
         el = norm2(t)
         t = t/el
         xi = dot_product(x(:, k) - x(:, edge(1, j)), t)/el
         g = dot_product(x(:, k) - x(:, edge(1, j)), [t(2), -t(1)])
         if (xi < -0.1_wp .or. xi > 1.1_wp .or. abs(g) >= 0.5_wp*el) cycle
         nacc = nacc + 1
         if (j1 > j2) then
            nmiss = nmiss + 1
         else if (.not. any(bn%list(j1:j2) == j)) then
            nmiss = nmiss + 1
         end if
      end do
   end do
   print '(a, i0, a, i0, a, i0)', 'bins: ', nacc, ' acceptable point-edge pairs, missed ', &
      nmiss, ', cells ', bn%nx*bn%ny
   call check(nacc > 4*ne, 'bins: the points meet edges (corner points included)')
   call check(nmiss == 0, 'bins: every acceptable pair is in the point''s cell')
   call check(nord == 0, 'bins: each cell lists its edges in ascending order')
   call assert_summary()
end program test_contact2d_bins
