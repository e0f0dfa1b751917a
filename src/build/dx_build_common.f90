!> Model build, shared pieces: the label maps of one build (maps_t) and the lookups that turn a
!> deck label into a dense index or report the card that named it ("file:line: *KEY: field
!> F: node 7 is not defined (*NODE)"). Used by dx_model_build and dx_build_loads. Also the
!> history nodes of nodout and solids of elout (*DATABASE_HISTORY_NODE(_SET), _SOLID).
!> No keyword of its own; no paper.
module dx_build_common
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_model, only: model_t, family_t, element_family
   use dx_model_input, only: model_input_t, origin_t
   use dx_label_map, only: label_map_t
   implicit none
   private
   public :: maps_t, at, at_line, set_nodes, curve_index, node_index, dense_segments, &
             map_labels, hist_solids, hist_nodes

   !> label maps of one build
   type :: maps_t
      type(label_map_t) :: node, elem, part, sec, mat, hg, curve, nset, pset, sset
   end type maps_t

contains

   !> "file:line: *KEY: " of a record
   function at(inp, src) result(s)
      type(model_input_t), intent(in) :: inp
      type(origin_t), intent(in) :: src
      character(:), allocatable :: s
      s = inp%files(src%ifile)%s//':'//str(src%line)//': *'//src%key//': '
   end function at

   function at_line(inp, isrc, key) result(s)
      type(model_input_t), intent(in) :: inp
      integer, intent(in) :: isrc(2)
      character(*), intent(in) :: key
      character(:), allocatable :: s
      s = inp%files(isrc(1))%s//':'//str(isrc(2))//': *'//key//': '
   end function at_line


   !> dense node list of node set label id (0: error unless allow_all, then all nodes)
   subroutine set_nodes(inp, model, mp, id, allow_all, src, what, nodes, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: id
      logical, intent(in) :: allow_all
      type(origin_t), intent(in) :: src
      character(*), intent(in) :: what
      integer, allocatable, intent(out) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, i
      if (id == 0 .and. allow_all) then
         nodes = [(i, i = 1, model%nn)]
         return
      end if
      k = mp%nset%get(id)
      if (k == 0) then
         call set_error(error, at(inp, src)//'field '//what//': node set '//str(id)// &
                        ' is not defined (*SET_NODE_LIST)')
         return
      end if
      nodes = model%node_sets(k)%nodes
   end subroutine set_nodes

   integer function curve_index(inp, mp, lcid, src, what, error) result(k)
      type(model_input_t), intent(in) :: inp
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: lcid
      type(origin_t), intent(in) :: src
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      k = mp%curve%get(lcid)
      if (k == 0) call set_error(error, at(inp, src)//'field '//what//': curve '//str(lcid)// &
                                 ' is not defined (*DEFINE_CURVE)')
   end function curve_index

   integer function node_index(inp, mp, nid, src, what, error) result(k)
      type(model_input_t), intent(in) :: inp
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: nid
      type(origin_t), intent(in) :: src
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(inout) :: error
      k = mp%node%get(nid)
      if (k == 0) call set_error(error, at(inp, src)//'field '//what//': node '//str(nid)// &
                                 ' is not defined (*NODE)')
   end function node_index

   !> dense node indices of segments seg(4, n); error at the first undefined node
   subroutine dense_segments(inp, mp, seg, src, dseg, error)
      type(model_input_t), intent(in) :: inp
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: seg(:, :)
      type(origin_t), intent(in) :: src
      integer, allocatable, intent(out) :: dseg(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: i, k
      allocate(dseg(4, size(seg, 2)))
      do i = 1, size(seg, 2)
         do k = 1, 4
            dseg(k, i) = mp%node%get(seg(k, i))
            if (dseg(k, i) == 0) then
               call set_error(error, at(inp, src)//'segment '//str(i)//': node '// &
                              str(seg(k, i))//' is not defined (*NODE)')
               return
            end if
         end do
      end do
   end subroutine dense_segments
   !> unique labels -> map; error naming both cards on a duplicate
   subroutine map_labels(inp, map, labels, src, what, error)
      type(model_input_t), intent(in) :: inp
      type(label_map_t), intent(inout) :: map
      integer, intent(in) :: labels(:)
      type(origin_t), intent(in) :: src(:)
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      integer :: i, old
      call map%init(size(labels))
      do i = 1, size(labels)
         call map%insert(labels(i), i, old)
         if (old /= 0) then
            call set_error(error, at(inp, src(i))//'duplicate '//what//' id '// &
               str(labels(i))//' (first defined at '//inp%files(src(old)%ifile)%s//':'// &
               str(src(old)%line)//')')
            return
         end if
      end do
   end subroutine map_labels

   !> nodout's nodes: the *DATABASE_HISTORY_NODE ids and the nodes of the
   !> *DATABASE_HISTORY_NODE_SET sets, each once, in card order (dense node indices).
   subroutine hist_nodes(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: h(:), nodes(:)
      logical, allocatable :: seen(:)
      integer :: i, k, j, nh
      allocate(h(model%nn), seen(model%nn))    ! each node once: at most nn (linear set-up)
      seen = .false.
      nh = 0
      do i = 1, size(inp%hist_nodes)
         associate (l => inp%hist_nodes(i))
            do k = 1, size(l%ids)
               j = node_index(inp, mp, l%ids(k), l%src, 'ID'//str(k), error)
               if (allocated(error)) return
               if (.not. seen(j)) call add_hist(j)
            end do
         end associate
      end do
      do i = 1, size(inp%hist_node_sets)
         associate (l => inp%hist_node_sets(i))
            do k = 1, size(l%ids)
               call set_nodes(inp, model, mp, l%ids(k), .false., l%src, 'ID'//str(k), nodes, &
                              error)
               if (allocated(error)) return
               do j = 1, size(nodes)
                  if (.not. seen(nodes(j))) call add_hist(nodes(j))
               end do
            end do
         end associate
      end do
      h = h(1:nh)
      call move_alloc(h, model%db%hist_nodes)
   contains
      subroutine add_hist(node)
         integer, intent(in) :: node
         nh = nh + 1
         h(nh) = node
         seen(node) = .true.
      end subroutine add_hist
   end subroutine hist_nodes

   !> *DATABASE_ELOUT's elements: the *DATABASE_HISTORY_SOLID ids (each once, in card
   !> order) as dense elements with their ids and part ids; an id that names no element or
   !> a shell, beam or 2D element is an error at its card and field.
   subroutine hist_solids(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: h(:)
      logical, allocatable :: seen(:)
      type(family_t) :: fam
      integer :: i, k, e, nh
      allocate(h(model%ne), seen(model%ne))
      seen = .false.
      nh = 0
      do i = 1, size(inp%hist_solids)
         associate (l => inp%hist_solids(i))
            do k = 1, size(l%ids)
               e = mp%elem%get(l%ids(k))
               if (e == 0) then
                  call set_error(error, at(inp, l%src)//'field ID'//str(k)//': element '// &
                                 str(l%ids(k))//' is not defined (*ELEMENT_SOLID)')
                  return
               end if
               fam = element_family(model%blocks(model%elem_block(e))%etype)
               if (fam%rot .or. fam%twod) then
                  call set_error(error, at(inp, l%src)//'field ID'//str(k)//': element '// &
                     str(l%ids(k))//' is not a solid element (elout history is written for '// &
                     'solids only; *DATABASE_HISTORY_SHELL and _BEAM are not supported)')
                  return
               end if
               if (seen(e)) cycle
               seen(e) = .true.
               nh = nh + 1
               h(nh) = e
            end do
         end associate
      end do
      model%db%hist_solids = h(1:nh)
      model%db%hist_solid_id = model%elem_label(h(1:nh))
      model%db%hist_solid_pid = model%parts(model%elem_part(h(1:nh)))%label
      allocate(model%db%elout_vals(7, nh))
      model%db%elout_vals = 0.0_wp
   end subroutine hist_solids
end module dx_build_common
