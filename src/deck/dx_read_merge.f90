!> *NODE_MERGE, *NODE_MERGE_SET, *NODE_MERGE_TOLERANCE (LS-DYNA Keyword User's Manual,
!> Vol. I, *NODE_MERGE): the nodes listed (*NODE_MERGE: NID, one per card) or in the node sets
!> (*NODE_MERGE_SET: NSID, one per card) are candidates; two candidates closer than TOLR
!> (*NODE_MERGE_TOLERANCE, a physical distance) become one node. Merging is transitive (a
!> chain of close nodes becomes one); the node kept is the lowest label of its group, with
!> its own coordinates (dynx's rule: the sources at hand do not say which LS-DYNA keeps).
!> Without *NODE_MERGE_TOLERANCE dynx merges only candidates at the same position (TOLR
!> = 0) and says so in a warning (LS-DYNA's default distance is not in the sources at hand).
!> After the whole deck (merge_finish, sets resolved): the merged-away nodes leave the node
!> list and their labels become aliases of the kept node (inp%node_alias), which the build's
!> node map resolves (dx_model_build), so elements, sets, loads and constraints naming them
!> act on the kept node. A kept node takes the *NODE TC/RC of a merged-away one when its
!> own is 0. No paper: a sort along x and a sweep over the pairs within TOLR in x.
module dx_read_merge
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_log, only: log_warn
   use dx_sort, only: sort_index
   use dx_label_map, only: label_map_t
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, origin_t
   implicit none
   private
   public :: register_merge, merge_finish

contains

   !> Add this family's keywords to the registry.
   subroutine register_merge(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('NODE_MERGE', read_merge)
      call reg%add('NODE_MERGE_SET', read_merge)
      call reg%add('NODE_MERGE_TOLERANCE', read_merge_tolerance)
   end subroutine register_merge

   !> *NODE_MERGE: NID per card; *NODE_MERGE_SET: NSID per card.
   subroutine read_merge(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: ic, id
      logical :: is_set
      is_set = blk%base == 'NODE_MERGE_SET'
      if (.not. allocated(inp%merge_nodes)) allocate(inp%merge_nodes(0), inp%merge_sets(0))
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 ('//trim(merge('NSID', 'NID ', is_set))//')')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         call c%id(trim(merge('NSID', 'NID ', is_set)), id)
         if (c%halt()) exit
         if (is_set) then
            inp%merge_sets = [inp%merge_sets, id]
         else
            inp%merge_nodes = [inp%merge_nodes, id]
         end if
      end do
      if (c%ok()) inp%merge_src = origin(blk%ifile, blk%cards(data_start(blk))%line, blk%name)
      call c%done(error)
   end subroutine read_merge

   !> *NODE_MERGE_TOLERANCE: TOLR (>= 0), once per deck.
   subroutine read_merge_tolerance(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      real(wp) :: t
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (TOLR)')
      call c%max_cards(1)
      call c%real('TOLR', 0.0_wp, t, min=0.0_wp)
      if (c%ok() .and. inp%merge_tol >= 0.0_wp) call c%fail('TOLR', 'a second '// &
         '*NODE_MERGE_TOLERANCE (the first gave '//rstr(inp%merge_tol)//')')
      if (c%ok()) inp%merge_tol = t
      call c%done(error)
   end subroutine read_merge_tolerance

   !> Merge the candidate nodes (see the module header); nothing without *NODE_MERGE(_SET).
   subroutine merge_finish(inp, error)
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(label_map_t) :: map
      integer, allocatable :: cand(:), ord(:), root(:), keep(:), alias(:, :)
      real(wp), allocatable :: xs(:)
      logical, allocatable :: mark(:)
      real(wp) :: tol
      integer :: i, j, k, a, b, old, n, na
      if (.not. allocated(inp%merge_nodes)) return
      if (size(inp%merge_nodes) + size(inp%merge_sets) == 0) return
      call map%init(inp%nn)
      do i = 1, inp%nn
         call map%insert(inp%node_label(i), i, old)
      end do
      allocate(mark(inp%nn))
      mark = .false.
      do k = 1, size(inp%merge_nodes)
         i = map%get(inp%merge_nodes(k))
         if (i == 0) then
            call set_error(error, where(inp, inp%merge_src)//'field NID: node '// &
               str(inp%merge_nodes(k))//' is not defined (*NODE)')
            return
         end if
         mark(i) = .true.
      end do
      do k = 1, size(inp%merge_sets)
         j = 0
         do i = size(inp%node_sets), 1, -1
            if (inp%node_sets(i)%label == inp%merge_sets(k)) then
               j = i; exit
            end if
         end do
         if (j == 0) then
            call set_error(error, where(inp, inp%merge_src)//'field NSID: node set '// &
               str(inp%merge_sets(k))//' is not defined')
            return
         end if
         do i = 1, size(inp%node_sets(j)%ids)
            a = map%get(inp%node_sets(j)%ids(i))
            if (a > 0) mark(a) = .true.
         end do
      end do
      tol = max(inp%merge_tol, 0.0_wp)
      if (inp%merge_tol < 0.0_wp) call log_warn(where(inp, inp%merge_src)//'no '// &
         '*NODE_MERGE_TOLERANCE: only nodes at the same position are merged (TOLR = 0)')
      cand = pack([(i, i = 1, inp%nn)], mark)
      xs = inp%x(1, cand)
      ord = [(i, i = 1, size(cand))]
      call sort_index(ord, xs)
      allocate(root(inp%nn))
      root = [(i, i = 1, inp%nn)]
      ! sweep: pairs within tol in x, then in distance; union by the lower label
      do i = 1, size(cand)
         a = cand(ord(i))
         do j = i + 1, size(cand)
            b = cand(ord(j))
            if (inp%x(1, b) - inp%x(1, a) > tol) exit
            if (norm2(inp%x(:, b) - inp%x(:, a)) > tol) cycle
            call unite(a, b)
         end do
      end do
      ! the kept nodes in their *NODE order; each merged-away label an alias of its root's
      n = 0
      na = count([(find(i) /= i, i = 1, inp%nn)])
      if (na == 0) return
      allocate(keep(inp%nn), alias(2, na))
      na = 0
      do i = 1, inp%nn
         j = find(i)
         if (j == i) then
            n = n + 1
            keep(n) = i
         else
            na = na + 1
            alias(:, na) = [inp%node_label(i), inp%node_label(j)]
            if (inp%node_tc(j) == 0) inp%node_tc(j) = inp%node_tc(i)
            if (inp%node_rc(j) == 0) inp%node_rc(j) = inp%node_rc(i)
         end if
      end do
      inp%node_label(1:n) = inp%node_label(keep(1:n))
      inp%x(:, 1:n) = inp%x(:, keep(1:n))
      inp%node_tc(1:n) = inp%node_tc(keep(1:n))
      inp%node_rc(1:n) = inp%node_rc(keep(1:n))
      inp%node_src(:, 1:n) = inp%node_src(:, keep(1:n))
      inp%nn = n
      inp%node_alias = alias
      call sets_without_aliases(inp, alias)
   contains
      !> the root of node i's group (path halving)
      integer function find(i0) result(r)
         integer, intent(in) :: i0
         r = i0
         do while (root(r) /= r)
            root(r) = root(root(r))
            r = root(r)
         end do
      end function find
      !> join the groups of p and q under the lower label
      subroutine unite(p, q)
         integer, intent(in) :: p, q
         integer :: rp, rq
         rp = find(p)
         rq = find(q)
         if (rp == rq) return
         if (inp%node_label(rp) < inp%node_label(rq)) then
            root(rq) = rp
         else
            root(rp) = rq
         end if
      end subroutine unite
   end subroutine merge_finish

   !> "file:line: *KEY: " of the merge keyword
   function where(inp, src) result(s)
      type(model_input_t), intent(in) :: inp
      type(origin_t), intent(in) :: src
      character(:), allocatable :: s
      s = inp%files(src%ifile)%s//':'//str(src%line)//': *'//src%key//': '
   end function where

   !> After the merge every node set names each node once: a merged-away label becomes its
   !> kept node's label, and a repeat (a set that held both) is dropped, the first kept in
   !> order; a load, constraint, contact or history on the set then acts on the node once.
   subroutine sets_without_aliases(inp, alias)
      type(model_input_t), intent(inout) :: inp
      integer, intent(in) :: alias(:, :)
      type(label_map_t) :: amap, seen
      integer, allocatable :: ids(:)
      integer :: i, k, n, lab, old
      if (.not. allocated(inp%node_sets)) return
      call amap%init(size(alias, 2))
      do k = 1, size(alias, 2)
         call amap%insert(alias(1, k), alias(2, k), old)
      end do
      do i = 1, size(inp%node_sets)
         associate (st => inp%node_sets(i))
            if (.not. allocated(st%ids)) cycle
            call seen%init(size(st%ids))
            allocate(ids(size(st%ids)))
            n = 0
            do k = 1, size(st%ids)
               lab = st%ids(k)
               if (amap%get(lab) /= 0) lab = amap%get(lab)
               call seen%insert(lab, 1, old)
               if (old /= 0) cycle
               n = n + 1
               ids(n) = lab
            end do
            st%ids = ids(1:n)
            deallocate(ids)
         end associate
      end do
   end subroutine sets_without_aliases
end module dx_read_merge
