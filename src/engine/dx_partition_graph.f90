!> The element graph of the domain decomposition (dx_partition): "Parallel contact in
!> ParaDyn", LLNL Engineering Thrust Area Report FY97, Computational Mechanics (article 4 of
!> shared/seed/000_ada67627fd8120d3.txt: element graph, super elements for contact pairs);
!> the graph is what METIS partitions (Karypis and Kumar, SIAM J. Sci. Comput. 20(1), 1998).
!> Node -> element lists, contact groups condensed into super vertices (union-find), the
!> node-sharing dual graph weighted by the nodes shared, and proximity edges between separate
!> bodies for decks with automatic contact. Arrays in, arrays out; no module state.
module dx_partition_graph
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_sort, only: sort_index
   implicit none
   private
   public :: node_elements, condense_groups, element_graph, add_proximity_edges, sort_int

contains

   !> Node -> elements (CSR) from the connectivity conn(nen, ne).
   subroutine node_elements(conn, nn, ptr, lst)
      integer, intent(in) :: conn(:, :), nn
      integer, allocatable, intent(out) :: ptr(:), lst(:)
      integer :: e, k, n
      integer, allocatable :: fill(:)
      allocate(ptr(nn + 1), fill(nn))
      ptr = 0
      do e = 1, size(conn, 2)
         do k = 1, size(conn, 1)
            ptr(conn(k, e) + 1) = ptr(conn(k, e) + 1) + 1
         end do
      end do
      ptr(1) = 1
      do n = 1, nn
         ptr(n + 1) = ptr(n + 1) + ptr(n)
      end do
      allocate(lst(ptr(nn + 1) - 1))
      fill = 0
      do e = 1, size(conn, 2)
         do k = 1, size(conn, 1)
            n = conn(k, e)
            lst(ptr(n) + fill(n)) = e
            fill(n) = fill(n) + 1
         end do
      end do
   end subroutine node_elements

   !> Union-find root with path halving.
   integer function find_root(parent, i) result(r)
      integer, intent(inout) :: parent(:)
      integer, intent(in) :: i
      r = i
      do while (parent(r) /= r)
         parent(r) = parent(parent(r))
         r = parent(r)
      end do
   end function find_root

   !> Vertex of each element: elements of one group (groups given as CSR grp_ptr/grp_elem;
   !> overlapping groups merge) share one vertex; vertices are numbered in the order of
   !> their first element. vwgt sums the element weights of each vertex.
   subroutine condense_groups(ne, ewgt, grp_ptr, grp_elem, vtx, nv, vwgt, error)
      integer, intent(in) :: ne, ewgt(:), grp_ptr(:), grp_elem(:)
      integer, allocatable, intent(out) :: vtx(:), vwgt(:)
      integer, intent(out) :: nv
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: parent(:), rootv(:)
      integer :: g, k, e, r1, r2
      allocate(parent(ne), vtx(ne), rootv(ne))
      parent = [(e, e = 1, ne)]
      do g = 1, size(grp_ptr) - 1
         do k = grp_ptr(g), grp_ptr(g + 1) - 1
            e = grp_elem(k)
            if (e < 1 .or. e > ne) then
               call set_error(error, 'element group '//str(g)//': element index '//str(e)// &
                              ' out of range 1..'//str(ne), EXIT_INPUT)
               return
            end if
            r1 = find_root(parent, grp_elem(grp_ptr(g)))
            r2 = find_root(parent, e)
            if (r1 /= r2) parent(max(r1, r2)) = min(r1, r2)
         end do
      end do
      rootv = 0
      nv = 0
      do e = 1, ne
         r1 = find_root(parent, e)
         if (rootv(r1) == 0) then
            nv = nv + 1
            rootv(r1) = nv
         end if
         vtx(e) = rootv(r1)
      end do
      allocate(vwgt(nv))
      vwgt = 0
      do e = 1, ne
         vwgt(vtx(e)) = vwgt(vtx(e)) + ewgt(e)
      end do
   end subroutine condense_groups

   !> The weighted dual graph over vertices vtx(e): an edge between two vertices whose
   !> elements share nodes, weight = sum over element pairs of the number of shared nodes.
   !> CSR with 0-based adjncy (METIS convention), neighbours in ascending order.
   subroutine element_graph(conn, nn, vtx, nv, xadj, adjncy, adjwgt)
      integer, intent(in) :: conn(:, :), nn, vtx(:), nv
      integer, allocatable, intent(out) :: xadj(:), adjncy(:), adjwgt(:)
      integer, allocatable :: nptr(:), nlst(:), vptr(:), vel(:), cnt(:), mark(:), nb(:)
      integer :: e, v, k, j, n, w, f, nnb, tot, cap
      call node_elements(conn, nn, nptr, nlst)
      ! vertex -> elements
      allocate(vptr(nv + 1), vel(size(vtx)))
      vptr = 0
      do e = 1, size(vtx)
         vptr(vtx(e) + 1) = vptr(vtx(e) + 1) + 1
      end do
      vptr(1) = 1
      do v = 1, nv
         vptr(v + 1) = vptr(v + 1) + vptr(v)
      end do
      allocate(cnt(nv))
      cnt = 0
      do e = 1, size(vtx)
         vel(vptr(vtx(e)) + cnt(vtx(e))) = e
         cnt(vtx(e)) = cnt(vtx(e)) + 1
      end do
      cnt = 0
      allocate(mark(nv), nb(nv), xadj(nv + 1))
      mark = 0
      cap = 27*nv
      allocate(adjncy(cap), adjwgt(cap))
      xadj(1) = 0
      tot = 0
      do v = 1, nv
         nnb = 0
         do k = vptr(v), vptr(v + 1) - 1
            e = vel(k)
            do j = 1, size(conn, 1)
               n = conn(j, e)
               do f = nptr(n), nptr(n + 1) - 1
                  w = vtx(nlst(f))
                  if (w == v) cycle
                  if (mark(w) /= v) then
                     mark(w) = v
                     cnt(w) = 0
                     nnb = nnb + 1
                     nb(nnb) = w
                  end if
                  cnt(w) = cnt(w) + 1
               end do
            end do
         end do
         call sort_int(nb(1:nnb))
         if (tot + nnb > cap) then
            cap = max(2*cap, tot + nnb)
            call grow(adjncy, cap)
            call grow(adjwgt, cap)
         end if
         do k = 1, nnb
            adjncy(tot + k) = nb(k) - 1
            adjwgt(tot + k) = cnt(nb(k))
         end do
         tot = tot + nnb
         xadj(v + 1) = tot
      end do
      adjncy = adjncy(1:tot)
      adjwgt = adjwgt(1:tot)
   end subroutine element_graph

   !> Proximity edges for decks with automatic contact (ParaDyn's contact-aware partition,
   !> shared/seed article 4, in the spirit of its super elements): a mesh of separate bodies
   !> gives METIS a graph of separate components, which it may scatter over the ranks in
   !> any geometric order, so a rank's contact nodes spread over the whole model and its
   !> bucket grid, halo and sorts cover everything. When the graph has more than one
   !> component, two elements of different components whose centroids lie within
   !> 3 x the mean element extent get an edge of weight 1 (per element pair, summed per
   !> vertex pair): METIS then keeps nearby bodies together and cuts between them only
   !> where it must (a node-sharing edge weighs 1-4 per element pair, so bodies stay whole
   !> before neighbours are kept together). No node is shared by such an edge, so the
   !> exchange does not grow. Deterministic (cell order, element order).
   subroutine add_proximity_edges(conn, x, vtx, nv, xadj, adjncy, adjwgt, ncomp, nprox)
      integer, intent(in) :: conn(:, :), vtx(:), nv
      real(wp), intent(in) :: x(:, :)
      integer, allocatable, intent(inout) :: xadj(:), adjncy(:), adjwgt(:)
      integer, intent(out) :: ncomp, nprox
      integer, allocatable :: parent(:), comp(:), clst(:), pv(:), pw(:), nx(:), &
                              na(:), nw(:), cnt(:), mark(:), nbw(:)
      real(wp), allocatable :: xc(:, :), sk(:)
      real(wp) :: ext, lo(3), hi(3), d, h, hmin(3), hmax(3)
      integer :: ne, e, f, v, w, k, j, n, ncell(3), ic(3), jc(3), c, i1, i2, i3, np_, cap, a, b
      ne = size(conn, 2)
      nprox = 0
      ! components of the vertex graph (union-find over its edges)
      allocate(parent(nv))
      parent = [(v, v = 1, nv)]
      do v = 1, nv
         do k = xadj(v) + 1, xadj(v + 1)
            a = find_root(parent, v)
            b = find_root(parent, adjncy(k) + 1)
            if (a /= b) parent(max(a, b)) = min(a, b)
         end do
      end do
      allocate(comp(nv))
      do v = 1, nv
         comp(v) = find_root(parent, v)
      end do
      ncomp = count(comp == [(v, v = 1, nv)])
      if (ncomp <= 1 .or. ne == 0) return
      ! element centroids and the mean element extent
      allocate(xc(3, ne))
      ext = 0.0_wp
      do e = 1, ne
         hmin = x(:, conn(1, e)); hmax = hmin
         xc(:, e) = 0.0_wp
         do j = 1, size(conn, 1)
            hmin = min(hmin, x(:, conn(j, e)))
            hmax = max(hmax, x(:, conn(j, e)))
            xc(:, e) = xc(:, e) + x(:, conn(j, e))
         end do
         xc(:, e) = xc(:, e)/real(size(conn, 1), wp)
         ext = ext + maxval(hmax - hmin)
      end do
      d = 3.0_wp*ext/real(ne, wp)
      if (.not. (d > 0.0_wp)) return
      lo = minval(xc, dim=2)
      hi = maxval(xc, dim=2)
      ! cells of size h = d, only the occupied ones: the elements ordered by cell key
      ! (exact in a real while below 2**53; h grows only for absurd aspect ratios), a
      ! neighbour cell's elements found by binary search; a far-away small body does not
      ! coarsen the cells
      h = d
      do
         ncell = max(1, int((hi - lo)/h) + 1)
         if (product(real(ncell, wp)) < 2.0_wp**52) exit
         h = 2.0_wp*h
      end do
      allocate(clst(ne), sk(ne))
      do e = 1, ne
         ic = min(ncell, int((xc(:, e) - lo)/h) + 1)
         sk(e) = cell_key(ic)
      end do
      clst = [(e, e = 1, ne)]
      call sort_index(clst, sk)
      sk = sk(clst)
      ! element pairs of different components within d: vertex pairs, both directions
      cap = 1024
      allocate(pv(cap), pw(cap))
      np_ = 0
      do e = 1, ne
         v = vtx(e)
         ic = min(ncell, int((xc(:, e) - lo)/h) + 1)
         do i3 = max(1, ic(3) - 1), min(ncell(3), ic(3) + 1)
            do i2 = max(1, ic(2) - 1), min(ncell(2), ic(2) + 1)
               do i1 = max(1, ic(1) - 1), min(ncell(1), ic(1) + 1)
                  jc = [i1, i2, i3]
                  call key_range(cell_key(jc), c, n)
                  do k = c, n
                     f = clst(k)
                     w = vtx(f)
                     if (comp(w) == comp(v)) cycle
                     if (norm2(xc(:, f) - xc(:, e)) > d) cycle
                     if (np_ == cap) then
                        cap = 2*cap
                        call grow(pv, cap)
                        call grow(pw, cap)
                     end if
                     np_ = np_ + 1
                     pv(np_) = v
                     pw(np_) = w
                  end do
               end do
            end do
         end do
      end do
      if (np_ == 0) return
      ! merge into the CSR: per vertex its old neighbours, then the new ones summed
      allocate(na(nv + 1))
      na = 0
      do k = 1, np_
         na(pv(k) + 1) = na(pv(k) + 1) + 1
      end do
      na(1) = 1
      do v = 1, nv
         na(v + 1) = na(v + 1) + na(v)
      end do
      allocate(nbw(np_))
      allocate(cnt(nv), mark(nv), nx(xadj(nv + 1) + np_), nw(xadj(nv + 1) + np_))
      cnt = 0
      do k = 1, np_
         nbw(na(pv(k)) + cnt(pv(k))) = pw(k)
         cnt(pv(k)) = cnt(pv(k)) + 1
      end do
      mark = 0
      cnt = 0
      n = 0
      block
         integer, allocatable :: newx(:), lst(:)
         integer :: m, t
         allocate(newx(nv + 1), lst(nv))
         newx(1) = 0
         do v = 1, nv
            m = 0
            do k = na(v), na(v + 1) - 1
               w = nbw(k)
               if (mark(w) /= v) then
                  mark(w) = v
                  cnt(w) = 0
                  m = m + 1
                  lst(m) = w
               end if
               cnt(w) = cnt(w) + 1
            end do
            call sort_int(lst(1:m))
            nprox = nprox + m
            ! old neighbours (other component: never among the new ones), then the new,
            ! merged in ascending order
            a = xadj(v) + 1
            b = 1
            do while (a <= xadj(v + 1) .or. b <= m)
               if (b > m) then
                  t = adjncy(a) + 1; j = adjwgt(a); a = a + 1
               else if (a > xadj(v + 1)) then
                  t = lst(b); j = cnt(lst(b)); b = b + 1
               else if (adjncy(a) + 1 < lst(b)) then
                  t = adjncy(a) + 1; j = adjwgt(a); a = a + 1
               else
                  t = lst(b); j = cnt(lst(b)); b = b + 1
               end if
               n = n + 1
               nx(n) = t - 1
               nw(n) = j
            end do
            newx(v + 1) = n
         end do
         xadj = newx
      end block
      adjncy = nx(1:n)
      adjwgt = nw(1:n)
      nprox = nprox/2
   contains
      real(wp) function cell_key(jc)
         integer, intent(in) :: jc(3)
         cell_key = real(jc(1), wp) + real(ncell(1), wp)*(real(jc(2) - 1, wp) + &
                    real(ncell(2), wp)*real(jc(3) - 1, wp))
      end function cell_key
      !> positions i1..i2 of key in the sorted sk (i2 < i1: none)
      subroutine key_range(key, i1, i2)
         real(wp), intent(in) :: key
         integer, intent(out) :: i1, i2
         integer :: lo_, hi_, mid
         lo_ = 1; hi_ = ne + 1          ! first position with sk >= key
         do while (lo_ < hi_)
            mid = (lo_ + hi_)/2
            if (sk(mid) < key) then
               lo_ = mid + 1
            else
               hi_ = mid
            end if
         end do
         i1 = lo_
         i2 = i1 - 1
         do while (i2 < ne)
            if (sk(i2 + 1) /= key) exit
            i2 = i2 + 1
         end do
      end subroutine key_range
   end subroutine add_proximity_edges

   subroutine grow(a, n)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: n
      integer, allocatable :: t(:)
      allocate(t(n))
      t(1:size(a)) = a
      call move_alloc(t, a)
   end subroutine grow

   !> Ascending sort (insertion sort for short lists, heap sort otherwise).
   subroutine sort_int(a)
      integer, intent(inout) :: a(:)
      integer :: i, j, t, n
      n = size(a)
      if (n <= 32) then
         do i = 2, n
            t = a(i)
            j = i - 1
            do while (j >= 1)
               if (a(j) <= t) exit
               a(j + 1) = a(j)
               j = j - 1
            end do
            a(j + 1) = t
         end do
         return
      end if
      do i = n/2, 1, -1
         call sift(a, i, n)
      end do
      do i = n, 2, -1
         t = a(1); a(1) = a(i); a(i) = t
         call sift(a, 1, i - 1)
      end do
   end subroutine sort_int

   subroutine sift(a, start, n)
      integer, intent(inout) :: a(:)
      integer, intent(in) :: start, n
      integer :: r, c, t
      r = start
      do while (2*r <= n)
         c = 2*r
         if (c < n) then
            if (a(c + 1) > a(c)) c = c + 1
         end if
         if (a(r) >= a(c)) return
         t = a(r); a(r) = a(c); a(c) = t
         r = c
      end do
   end subroutine sift

end module dx_partition_graph
