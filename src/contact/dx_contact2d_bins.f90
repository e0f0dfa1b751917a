!> The 2D contact's search cells (dx_contact2d): a uniform grid over the master edges of one
!> pass, rebuilt at each contact stage from the current coordinates; each edge is listed in
!> every cell its box grown by REACH x its length meets, in ascending edge order, so a slave
!> node visits only the edges of its own cell, in the brute-force order (the same edges pass
!> the contact tests and the same one wins: results bit for bit those of the all-pairs
!> search). An edge a -> b can hold a node only when xi in [-XTOL, 1 + XTOL] and the gap is
!> within half its length (dx_contact2d), a point no farther from the edge's box than
!> sqrt(XTOL**2 + 1/4) L = 0.51 L along either axis: REACH = 0.6 leaves 0.09 L of margin.
!> The classic bucket sort of contact searches (Benson & Hallquist 1990, A single surface
!> contact algorithm for the post-buckling analysis of shell structures, CMAME 78: 141-163),
!> here on a fixed grid whose cell is the longest edge (doubled until the cells are at most
!> 4 per edge). Coordinates that are not finite (a run blowing up): one cell holds every edge
!> and every node looks at all of them, as the all-pairs search.
module dx_contact2d_bins
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use dx_kinds, only: wp
   implicit none
   private
   public :: c2d_bins_t, bins_build, bins_range

   real(wp), parameter :: REACH = 0.6_wp

   type :: c2d_bins_t
      logical :: whole = .false.            !< one cell, every node against every edge
      real(wp) :: x0(2) = 0.0_wp, h = 1.0_wp
      integer :: nx = 1, ny = 1
      integer, allocatable :: start(:)      !< (nx ny + 1) each cell's first place in list
      integer, allocatable :: list(:)       !< the edges of each cell, ascending
   end type c2d_bins_t

contains

   !> The cells of the edges edge(2, ne) at the coordinates x.
   subroutine bins_build(bn, edge, x)
      type(c2d_bins_t), intent(inout) :: bn
      integer, intent(in) :: edge(:, :)
      real(wp), intent(in) :: x(:, :)
      real(wp) :: lo(2), hi(2), el, hmax
      integer :: j, ne, i1, i2, k1, k2, i, k, c, ncell
      integer, allocatable :: fill(:)
      ne = size(edge, 2)
      lo = huge(1.0_wp); hi = -huge(1.0_wp); hmax = 0.0_wp
      do j = 1, ne
         associate (xa => x(1:2, edge(1, j)), xb => x(1:2, edge(2, j)))
            el = norm2(xb - xa)
            lo = min(lo, min(xa, xb) - REACH*el)
            hi = max(hi, max(xa, xb) + REACH*el)
            hmax = max(hmax, el)
         end associate
      end do
      bn%whole = .not. (all(ieee_is_finite(lo)) .and. all(ieee_is_finite(hi)) .and. &
                        ieee_is_finite(hmax) .and. hmax > 0.0_wp)
      if (bn%whole) then
         bn%nx = 1; bn%ny = 1
         bn%start = [1, ne + 1]
         bn%list = [(j, j = 1, ne)]
         return
      end if
      bn%x0 = lo
      bn%h = hmax
      do                               ! (in reals first: no integer overflow)
         if (((hi(1) - lo(1))/bn%h + 1.0_wp)*((hi(2) - lo(2))/bn%h + 1.0_wp) <= &
             4.0_wp*ne + 64.0_wp) exit
         bn%h = 2.0_wp*bn%h
      end do
      bn%nx = int((hi(1) - lo(1))/bn%h) + 1
      bn%ny = int((hi(2) - lo(2))/bn%h) + 1
      ncell = bn%nx*bn%ny
      if (allocated(bn%start)) deallocate(bn%start)
      allocate(bn%start(ncell + 1), fill(ncell))
      fill = 0
      do k = 1, 2                      ! 1: count, 2: fill (ascending edge order per cell)
         do j = 1, ne
            associate (xa => x(1:2, edge(1, j)), xb => x(1:2, edge(2, j)))
               el = REACH*norm2(xb - xa)
               call cell_of(bn, min(xa(1), xb(1)) - el, min(xa(2), xb(2)) - el, i1, k1)
               call cell_of(bn, max(xa(1), xb(1)) + el, max(xa(2), xb(2)) + el, i2, k2)
            end associate
            do c = k1, k2
               do i = i1, i2
                  if (k == 1) then
                     fill(c*bn%nx + i + 1) = fill(c*bn%nx + i + 1) + 1
                  else
                     bn%list(fill(c*bn%nx + i + 1)) = j
                     fill(c*bn%nx + i + 1) = fill(c*bn%nx + i + 1) + 1
                  end if
               end do
            end do
         end do
         if (k == 1) then
            bn%start(1) = 1
            do c = 1, ncell
               bn%start(c + 1) = bn%start(c) + fill(c)
            end do
            if (allocated(bn%list)) deallocate(bn%list)
            allocate(bn%list(bn%start(ncell + 1) - 1))
            fill = bn%start(1:ncell)
         end if
      end do
   end subroutine bins_build

   !> The places list(j1:j2) of the edges a node at p may touch (j1 > j2: none).
   subroutine bins_range(bn, p, j1, j2)
      type(c2d_bins_t), intent(in) :: bn
      real(wp), intent(in) :: p(2)
      integer, intent(out) :: j1, j2
      integer :: i, k, c
      j1 = 1; j2 = 0
      if (bn%whole) then
         j2 = size(bn%list)
         return
      end if
      ! (outside the grid, or not finite: no edge within reach)
      if (.not. (p(1) >= bn%x0(1) .and. p(2) >= bn%x0(2))) return
      if (.not. (p(1) < bn%x0(1) + bn%nx*bn%h .and. p(2) < bn%x0(2) + bn%ny*bn%h)) return
      call cell_of(bn, p(1), p(2), i, k)
      c = k*bn%nx + i + 1
      j1 = bn%start(c)
      j2 = bn%start(c + 1) - 1
   end subroutine bins_range

   !> The cell (i, k), 0-based, of a point (clamped to the grid).
   pure subroutine cell_of(bn, px, py, i, k)
      type(c2d_bins_t), intent(in) :: bn
      real(wp), intent(in) :: px, py
      integer, intent(out) :: i, k
      i = min(max(int((px - bn%x0(1))/bn%h), 0), bn%nx - 1)
      k = min(max(int((py - bn%x0(2))/bn%h), 0), bn%ny - 1)
   end subroutine cell_of
end module dx_contact2d_bins
