!> Strips for parallel contact (ParaDyn; Hoover et al., "ParaDyn: a parallel nonlinear explicit
!> finite-element code", LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed):
!> the slave nodes of a contact pass are cut into NSTRIP 1-D strips along the coordinate
!> direction in which they extend furthest, the cuts placed so that every strip holds the
!> same number of slave nodes (+-1): in the order of that coordinate (ties by slave index, so
!> every rank finds the same strips from the same coordinates) strip s takes positions
!> s*n/NSTRIP .. (s+1)*n/NSTRIP-1 (the cuts found by quickselect, not a full sort). Rebuilt
!> with the bucket sort (every BSORT cycles, or on motion), from that cycle's coordinates.
!> Each rank searches and computes the slave nodes of its own strip (p%mine); the segments a
!> node may touch lie within the search reach of the strip (the halo), which
!> dx_contact_search finds. No MPI here: the strips depend on x only, so every rank computes
!> all of them alike. MPI runs use them only with --contact-split strips (or
!> DYNX_PAR_CONTACT=strips); by default a rank computes the slave nodes it owns
!> (owner-computes, the mask mine_node from dx_par_contact): no sort of the slave nodes at
!> all, and the nodes a rank computes are its own (docs/history.md).
module dx_contact_strips
   use dx_kinds, only: wp
   use dx_contact_types, only: contact_pass_t
   implicit none
   private
   public :: contact_strips, strip_of

contains

   !> Strips of pass p at x: p%mine(i) for the slave nodes of strip istrip of nstrip,
   !> p%strip_axis the axis (1..3). mine_node (global node -> computed here), when given:
   !> p%mine(i) = mine_node(p%node(i)) (owner-computes; p%strip_axis 0, x not read).
   subroutine contact_strips(p, x, nstrip, istrip, mine_node)
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: nstrip, istrip
      logical, intent(in), optional :: mine_node(:)
      integer, allocatable :: strip(:)
      if (.not. allocated(p%mine)) allocate(p%mine(p%nnode))
      if (present(mine_node)) then
         p%strip_axis = 0
         if (p%nnode > 0) p%mine = mine_node(p%node)
         return
      end if
      call strip_of(p, x, nstrip, strip)
      p%mine = strip == istrip
   end subroutine contact_strips

   !> The strip (0..nstrip-1) of every slave node of pass p at x; sets p%strip_axis. The node
   !> at position i (1-based) of the order (coordinate, slave index) is in strip
   !> floor((i-1) nstrip/n), so strip s holds positions q(s)+1 .. q(s+1), q(s) =
   !> ceil(s n/nstrip). Only the cut positions are needed, not the whole order: quickselects
   !> (Hoare 1961) of the middle cut, then of the cuts on each side (O(n log nstrip)
   !> expected), instead of a heap sort of all nodes at every bucket sort.
   subroutine strip_of(p, x, nstrip, strip)
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: nstrip
      integer, allocatable, intent(out) :: strip(:)
      integer, allocatable :: idx(:)
      real(wp), allocatable :: c(:)
      real(wp) :: lo(3), hi(3)
      integer, allocatable :: q(:)
      integer :: i, n, a, s
      n = p%nnode
      allocate(strip(n), idx(n), c(n))
      if (n == 0) return
      lo = x(:, p%node(1)); hi = lo
      do i = 2, n
         lo = min(lo, x(:, p%node(i)))
         hi = max(hi, x(:, p%node(i)))
      end do
      a = maxloc(hi - lo, dim=1)
      p%strip_axis = a
      c = x(a, p%node)
      idx = [(i, i = 1, n)]
      allocate(q(0:nstrip))
      do s = 0, nstrip
         q(s) = int((int(s, 8)*int(n, 8) + int(nstrip - 1, 8))/int(nstrip, 8))
      end do
      call cuts(1, n, 1, nstrip - 1)
      do s = 0, nstrip - 1
         do i = q(s) + 1, q(s + 1)
            strip(idx(i)) = s
         end do
      end do
   contains
      !> idx(l:r) holds the elements of ranks l..r; make every cut q(s), s = slo..shi, a
      !> boundary (idx(1:q(s)) the q(s) smallest): select the middle cut, then recurse on
      !> both sides (O(n log nstrip) expected). A cut at l-1 or r is a boundary already.
      recursive subroutine cuts(l, r, slo, shi)
         integer, intent(in) :: l, r, slo, shi
         integer :: sm, a, b
         a = slo
         b = shi
         do while (a <= b)
            if (q(a) >= l) exit
            a = a + 1
         end do
         do while (b >= a)
            if (q(b) < r) exit
            b = b - 1
         end do
         if (a > b .or. r <= l) return
         sm = (a + b)/2
         call select_rank(idx, c, l, r, q(sm))
         call cuts(l, q(sm) - 1, a, sm - 1)
         call cuts(q(sm) + 1, r, sm + 1, b)
      end subroutine cuts
   end subroutine strip_of

   !> Reorder idx(l0:r0) so that idx(k) is the element of rank k (within l0..r0, in the
   !> strict order (c, index)), the smaller ones before it and the larger after it
   !> (quickselect, median-of-three pivot, Hoare partition).
   subroutine select_rank(idx, c, l0, r0, k)
      integer, intent(inout) :: idx(:)
      real(wp), intent(in) :: c(:)
      integer, intent(in) :: l0, r0, k
      integer :: l, r, m, i, j, piv
      l = l0
      r = r0
      do while (r > l)
         m = l + (r - l)/2
         if (before(idx(m), idx(l))) call swap(m, l)
         if (before(idx(r), idx(l))) call swap(r, l)
         if (before(idx(r), idx(m))) call swap(r, m)
         piv = idx(m)
         i = l
         j = r
         do
            do while (before(idx(i), piv))
               i = i + 1
            end do
            do while (before(piv, idx(j)))
               j = j - 1
            end do
            if (i <= j) then
               call swap(i, j)
               i = i + 1
               j = j - 1
            end if
            if (i > j) exit
         end do
         if (k <= j) then
            r = j
         else if (k >= i) then
            l = i
         else
            exit
         end if
      end do
   contains
      logical function before(u, v)
         integer, intent(in) :: u, v
         before = c(u) < c(v) .or. (c(u) == c(v) .and. u < v)
      end function before
      subroutine swap(u, v)
         integer, intent(in) :: u, v
         integer :: t
         t = idx(u); idx(u) = idx(v); idx(v) = t
      end subroutine swap
   end subroutine select_rank

end module dx_contact_strips
