!> Bucket sort for node-to-segment contact (Benson & Hallquist 1990, CMAME 78:141-163; the
!> LS-DYNA Theory Manual, "bucket sort"): an Eulerian grid of cubic cells (cell size from the
!> mean segment size, capped so the grid has O(nseg) cells) over the pass's nodes and
!> segments. Each segment is entered into every cell its box, grown by the search reach
!> (margin + largest penetration taken as contact), overlaps; each slave node then keeps as
!> candidates the segments of its cell whose grown box contains it. The local search in
!> dx_contact_penalty only looks at these candidates until the next sort.
!> The sort is valid while no two points have closed more than the margin, i.e. while twice
!> the largest nodal travel since the sort stays below the margin (dx_contact re-sorts then,
!> and every BSORT cycles, unless the sort provably finds no candidate: p%clear).
!> Cost: O(nseg + nnode) per sort for a surface of evenly sized segments.
!> MPI runs (p%mine allocated, dx_contact_strips): candidates only for this strip's nodes.
module dx_contact_search
   use dx_kinds, only: wp
   use dx_contact_types, only: contact_pass_t
   implicit none
   private
   public :: bucket_sort, segment_box

contains

   !> Shells: slave node i of pass p meets segment s from either side (s on a shell, or i
   !> on a shell), so the facing filters do not apply.
   pure logical function both_sides(p, i, s)
      type(contact_pass_t), intent(in) :: p
      integer, intent(in) :: i, s
      both_sides = .false.
      if (.not. p%shells) return
      both_sides = p%soff(s) > 0.0_wp .or. p%noff(i) > 0.0_wp
   end function both_sides

   !> Rebuild the candidate lists of pass p from coordinates x; margin: search distance.
   !> mass (optional): nodal masses, for the frequency bound w2pot of the candidate pairs,
   !> max over slave nodes with candidates of 4 k_max/min(m_slave, m_master nodes): a pair
   !> that may touch before the next sort keeps the step small even while it is apart.
   subroutine bucket_sort(p, x, margin, mass)
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :)
      real(wp), intent(in) :: margin
      real(wp), intent(in), optional :: mass(:)
      real(wp), allocatable :: blo(:, :), bhi(:, :), snrm(:, :)
      real(wp) :: d1(3), d2(3)
      real(wp) :: lo(3), hi(3), ext, h, vol, slo3(3), shi3(3), glo(3), ghi(3), gap
      integer :: i, s, k, n, c, ic(3), jlo(3), jhi(3), i1, i2, i3, ncap, ncells, nc
      integer, allocatable :: fill(:), cand(:), tmp(:)
      logical, allocatable :: act(:)
      logical :: ok, mpi
      p%margin = margin
      p%moved = 0.0_wp
      p%nsort = p%nsort + 1
      if (p%nsseg > 0) call node_normals(p, x)
      p%clear = -1.0_wp
      p%margin_real = margin
      p%moved_real = 0.0_wp
      if (p%nseg == 0 .or. p%nnode == 0) then
         p%cand_ptr = 1
         return
      end if
      ! ---- grown segment boxes and the grid box
      allocate(blo(3, p%nseg), bhi(3, p%nseg), act(p%nseg))
      act = .true.
      ! MPI ghost sorts: only the segments whose x is current here (dx_par_contact)
      if (allocated(p%segok)) act = p%segok
      ext = 0.0_wp
      do s = 1, p%nseg
         if (.not. act(s)) then
            blo(:, s) = huge(1.0_wp); bhi(:, s) = -huge(1.0_wp)
            cycle
         end if
         call segment_box(p, x, s, blo(:, s), bhi(:, s))
         ext = ext + maxval(bhi(:, s) - blo(:, s))
         blo(:, s) = blo(:, s) - (margin + p%depth(s))
         bhi(:, s) = bhi(:, s) + (margin + p%depth(s))
         if (p%shells) then     ! the slave nodes' shell offsets
            blo(:, s) = blo(:, s) - p%noffmax
            bhi(:, s) = bhi(:, s) + p%noffmax
         end if
      end do
      ext = ext/real(max(1, count(act)), wp)
      mpi = allocated(p%mine) .or. allocated(p%segok)
      ! (MPI: the box of all the grown boxes here, for dx_par_contact_ghost idle_reduce)
      if (mpi) call act_box(p%sbox(1:3), p%sbox(4:6))
      ! MPI runs: only the segments whose grown box reaches this strip's slab (the halo) can
      ! be candidates of its nodes; the grid covers them and the strip's nodes. A node's
      ! candidates (the segments whose grown box holds it, ascending) do not depend on the
      ! grid, so every strip finds the serial candidates of its nodes.
      if (allocated(p%mine)) then    ! the box of this rank's slave nodes (any 3 axes)
         slo3 = huge(1.0_wp); shi3 = -huge(1.0_wp)
         do i = 1, p%nnode
            if (.not. p%mine(i)) cycle
            slo3 = min(slo3, x(:, p%node(i)))
            shi3 = max(shi3, x(:, p%node(i)))
         end do
         do s = 1, p%nseg
            act(s) = act(s) .and. all(bhi(:, s) >= slo3) .and. all(blo(:, s) <= shi3)
         end do
      end if
      call act_box(lo, hi)
      glo = lo; ghi = hi        ! the grown segment boxes' box
      slo3 = huge(1.0_wp); shi3 = -huge(1.0_wp)
      do i = 1, p%nnode
         if (allocated(p%mine)) then
            if (.not. p%mine(i)) cycle
         end if
         lo = min(lo, x(:, p%node(i)))
         hi = max(hi, x(:, p%node(i)))
         slo3 = min(slo3, x(:, p%node(i)))
         shi3 = max(shi3, x(:, p%node(i)))
      end do
      if (any(lo > hi)) then     ! an empty strip
         lo = 0.0_wp; hi = 0.0_wp
      end if
      h = max(ext, 1.0e-12_wp*maxval(hi - lo), tiny(1.0_wp))
      vol = product(max(hi - lo, h))
      ncap = 4*count(act) + 64
      if (vol/h**3 > real(ncap, wp)) h = (vol/real(ncap, wp))**(1.0_wp/3.0_wp)
      p%cell_h = h
      p%cell_lo = lo
      p%ncell = max(1, min(ncap, int((hi - lo)/h) + 1))
      ncells = product(p%ncell)
      ! ---- segments into cells (CSR: count, prefix sum, fill)
      if (allocated(p%cell_ptr)) deallocate(p%cell_ptr)
      allocate(p%cell_ptr(ncells + 1))
      p%cell_ptr = 0
      do s = 1, p%nseg
         if (.not. act(s)) cycle
         call cell_range(p, blo(:, s), bhi(:, s), jlo, jhi)
         do i3 = jlo(3), jhi(3)
            do i2 = jlo(2), jhi(2)
               do i1 = jlo(1), jhi(1)
                  c = cell_id(p, [i1, i2, i3])
                  p%cell_ptr(c + 1) = p%cell_ptr(c + 1) + 1
               end do
            end do
         end do
      end do
      p%cell_ptr(1) = 1
      do c = 1, ncells
         p%cell_ptr(c + 1) = p%cell_ptr(c + 1) + p%cell_ptr(c)
      end do
      if (allocated(p%cell_seg)) deallocate(p%cell_seg)
      allocate(p%cell_seg(p%cell_ptr(ncells + 1) - 1), fill(ncells))
      fill = p%cell_ptr(1:ncells)
      do s = 1, p%nseg
         if (.not. act(s)) cycle
         call cell_range(p, blo(:, s), bhi(:, s), jlo, jhi)
         do i3 = jlo(3), jhi(3)
            do i2 = jlo(2), jhi(2)
               do i1 = jlo(1), jhi(1)
                  c = cell_id(p, [i1, i2, i3])
                  p%cell_seg(fill(c)) = s
                  fill(c) = fill(c) + 1
               end do
            end do
         end do
      end do
      ! ---- unit normals of the segments (diagonal cross product)
      allocate(snrm(3, p%nseg))
      do s = 1, p%nseg
         if (.not. act(s)) cycle      ! (only grid segments become candidates)
         associate (sg => p%seg(:, s))
            if (p%nsn(s) == 4) then
               d1 = x(:, sg(3)) - x(:, sg(1)); d2 = x(:, sg(4)) - x(:, sg(2))
            else
               d1 = x(:, sg(2)) - x(:, sg(1)); d2 = x(:, sg(3)) - x(:, sg(1))
            end if
         end associate
         snrm(:, s) = [d1(2)*d2(3) - d1(3)*d2(2), d1(3)*d2(1) - d1(1)*d2(3), &
                       d1(1)*d2(2) - d1(2)*d2(1)]
         snrm(:, s) = snrm(:, s)/max(norm2(snrm(:, s)), tiny(1.0_wp))
      end do
      ! ---- candidates of each slave node
      allocate(cand(max(16, 2*p%nnode)))
      nc = 0
      do i = 1, p%nnode
         p%cand_ptr(i) = nc + 1
         if (allocated(p%mine)) then     ! MPI runs: only the slave nodes of this strip
            if (.not. p%mine(i)) cycle
         end if
         k = p%node(i)
         ic = min(p%ncell, max(1, int((x(:, k) - p%cell_lo)/h) + 1))
         c = cell_id(p, ic)
         do n = p%cell_ptr(c), p%cell_ptr(c + 1) - 1
            s = p%cell_seg(n)
            if (any(x(:, k) < blo(:, s)) .or. any(x(:, k) > bhi(:, s))) cycle
            if (any(p%seg(1:p%nsn(s), s) == k)) cycle
            if (p%exclude_owner) then
               if (any(p%owner(:, s) == k)) cycle
            end if
            ! segments clearly facing the same way as the node's surface (its own face and
            ! its neighbours on a single surface) cannot be hit before the next sort
            ! (shells: a shell segment is met from either side, a shell node has no side)
            if (p%nsseg > 0 .and. .not. both_sides(p, i, s)) then
               if (dot_product(p%nnrm(:, i), snrm(:, s)) > 0.3_wp) cycle
            end if
            if (nc == size(cand)) then
               allocate(tmp(2*nc))
               tmp(1:nc) = cand
               call move_alloc(tmp, cand)
            end if
            nc = nc + 1
            cand(nc) = s
         end do
      end do
      p%cand_ptr(p%nnode + 1) = nc + 1
      ! no candidate: the largest gap along an axis between the slave nodes' box and the
      ! grown segments' box (a node inside no grown box needs none; dx_contact's idle sorts),
      ! kept when it is well above the round-off of the coordinates' update
      ! (MPI runs: each rank holds a part of both boxes and of the candidates; the ranks'
      ! parts are reduced after the sort into this same test, dx_par_contact idle_reduce)
      if (mpi) then
         p%sbox(7:9) = slo3
         p%sbox(10:12) = shi3
         p%sbox(13) = real(nc, wp)
         p%sbox_new = .true.
      else if (nc == 0 .and. all(glo <= ghi) .and. all(slo3 <= shi3)) then
         gap = maxval(max(glo - shi3, slo3 - ghi))
         if (gap > 1.0e-9_wp*maxval(max(abs(lo), abs(hi)))) p%clear = gap
      end if
      p%w2pot = 0.0_wp
      if (present(mass)) then
         do i = 1, p%nnode
            do n = p%cand_ptr(i), nc
               if (n >= p%cand_ptr(i + 1)) exit
               s = cand(n)
               vol = min(mass(p%node(i)), minval(mass(p%seg(1:p%nsn(s), s))))
               if (vol > 0.0_wp) p%w2pot = max(p%w2pot, 4.0_wp*p%kseg(s)/vol)
            end do
         end do
      end if
      ok = .true.
      if (allocated(p%cand)) deallocate(p%cand)
      p%cand = cand(1:nc)
      if (.not. ok) p%cand_ptr = 1
   contains
      !> the box of the grown boxes of the segments in act
      subroutine act_box(a, b)
         real(wp), intent(out) :: a(3), b(3)
         integer :: q
         a = huge(1.0_wp); b = -huge(1.0_wp)
         do q = 1, p%nseg
            if (.not. act(q)) cycle
            a = min(a, blo(:, q))
            b = max(b, bhi(:, q))
         end do
      end subroutine act_box
   end subroutine bucket_sort

   !> Unit normals of the slave nodes: the area-weighted mean of their segments' normals.
   subroutine node_normals(p, x)
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :)
      real(wp) :: a(3), d1(3), d2(3), r
      integer :: s, k, i
      p%nnrm = 0.0_wp
      do s = 1, p%nsseg
         if (allocated(p%slive)) then   ! erosion: only the live faces of the slave surface
            if (.not. p%slive(s)) cycle
         end if
         associate (sg => p%sseg(:, s))
            if (allocated(p%mine)) then   ! MPI runs: a face without a node of this rank
               if (.not. any(mine_at(sg(1:p%ssn(s))))) cycle
            end if
            if (p%ssn(s) == 4) then
               d1 = x(:, sg(3)) - x(:, sg(1)); d2 = x(:, sg(4)) - x(:, sg(2))
            else
               d1 = x(:, sg(2)) - x(:, sg(1)); d2 = x(:, sg(3)) - x(:, sg(1))
            end if
            a = [d1(2)*d2(3) - d1(3)*d2(2), d1(3)*d2(1) - d1(1)*d2(3), d1(1)*d2(2) - d1(2)*d2(1)]
            do k = 1, p%ssn(s)
               i = p%nloc(sg(k))
               if (i == 0) cycle
               if (allocated(p%mine)) then    ! MPI runs: this rank's slave nodes only
                  if (.not. p%mine(i)) cycle
               end if
               p%nnrm(:, i) = p%nnrm(:, i) + a
            end do
         end associate
      end do
      do i = 1, p%nnode
         r = norm2(p%nnrm(:, i))
         if (r > 0.0_wp) p%nnrm(:, i) = p%nnrm(:, i)/r
      end do
   contains
      !> the slave nodes among these that this rank computes
      pure elemental logical function mine_at(n)
         integer, intent(in) :: n
         mine_at = .false.
         if (p%nloc(n) > 0) mine_at = p%mine(p%nloc(n))
      end function mine_at
   end subroutine node_normals

   !> The box of segment s at x (explicit loops over its 3-4 nodes: minval/maxval of
   !> x(:, p%seg(1:n, s)) made an array temporary per segment).
   pure subroutine segment_box(p, x, s, lo, hi)
      type(contact_pass_t), intent(in) :: p
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: s
      real(wp), intent(out) :: lo(3), hi(3)
      integer :: k
      lo = x(:, p%seg(1, s))
      hi = lo
      do k = 2, p%nsn(s)
         lo = min(lo, x(:, p%seg(k, s)))
         hi = max(hi, x(:, p%seg(k, s)))
      end do
   end subroutine segment_box

   pure subroutine cell_range(p, blo, bhi, jlo, jhi)
      type(contact_pass_t), intent(in) :: p
      real(wp), intent(in) :: blo(3), bhi(3)
      integer, intent(out) :: jlo(3), jhi(3)
      jlo = min(p%ncell, max(1, int((blo - p%cell_lo)/p%cell_h) + 1))
      jhi = min(p%ncell, max(1, int((bhi - p%cell_lo)/p%cell_h) + 1))
   end subroutine cell_range

   pure integer function cell_id(p, ic) result(c)
      type(contact_pass_t), intent(in) :: p
      integer, intent(in) :: ic(3)
      c = ic(1) + p%ncell(1)*((ic(2) - 1) + p%ncell(2)*(ic(3) - 1))
   end function cell_id
end module dx_contact_search
