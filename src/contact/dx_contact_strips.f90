!> Strips for parallel contact (ParaDyn; Hoover et al., "ParaDyn: a parallel nonlinear explicit
!> finite-element code", LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed):
!> the slave nodes of a contact pass are cut into NSTRIP 1-D strips along the coordinate
!> direction in which they extend furthest, the cuts placed so that every strip holds the
!> same number of slave nodes (+-1): the nodes are ordered by that coordinate (ties by slave
!> index, so every rank finds the same strips from the same coordinates) and strip s takes
!> positions s*n/NSTRIP .. (s+1)*n/NSTRIP-1. Rebuilt with the bucket sort (every BSORT
!> cycles, or on motion), from the coordinates of that cycle. Each rank searches and
!> computes the slave nodes of its own strip (p%mine); the segments a node may touch lie
!> within the search reach of the strip (the halo), which dx_contact_search finds.
!> No MPI here: the strips depend on x only, so every rank computes all of them alike.
!> MPI runs use them only when DYNX_PAR_CONTACT=strips; by default a rank computes the slave
!> nodes it owns (owner-computes, the mask mine_node from dx_par_contact): no sort of the
!> slave nodes at all, and the nodes a rank computes are its own (docs/design.md).
module dx_contact_strips
   use dx_kinds, only: wp
   use dx_sort, only: sort_index
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

   !> The strip (0..nstrip-1) of every slave node of pass p at x; sets p%strip_axis.
   subroutine strip_of(p, x, nstrip, strip)
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: nstrip
      integer, allocatable, intent(out) :: strip(:)
      integer, allocatable :: idx(:)
      real(wp), allocatable :: c(:)
      real(wp) :: lo(3), hi(3)
      integer :: i, n, a
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
      call sort_index(idx, c)
      do i = 1, n
         strip(idx(i)) = int((int(i - 1, 8)*int(nstrip, 8))/int(n, 8))
      end do
   end subroutine strip_of

end module dx_contact_strips
