!> Model build of constraints and loads: expands *NODE TC/RC, *BOUNDARY_SPC_*,
!> *BOUNDARY_PRESCRIBED_MOTION_*, *INITIAL_VELOCITY(_GENERATION, _NODE), *LOAD_NODE_*,
!> *LOAD_SEGMENT(_SET) and *RIGIDWALL_PLANAR onto dense node and segment lists. An SPC with
!> CID (a skew constraint) becomes, per node and constrained local axis e, a prescribed
!> zero velocity along e (prescribed_t dof 4, curve 0): the node moves freely in the other
!> directions (the LS-DYNA meaning of CID on *BOUNDARY_SPC) (dx_model_build
!> calls it after the sets). No paper: bookkeeping of the LS-DYNA keyword manual's fields.
module dx_build_loads
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_model, only: model_t, prescribed_t, load_segment_t, element_family, family_t
   use dx_model_input, only: model_input_t, IVEL_SET, IVEL_NODE, IVEL_GEN
   use dx_build_common, only: maps_t, at, at_line, set_nodes, curve_index, node_index, &
                              dense_segments
   implicit none
   private
   public :: build_bcs, build_initial_velocity, build_loads

contains

   !> constraints (*NODE TC/RC, *BOUNDARY_SPC_*) and prescribed motions
   subroutine build_bcs(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: fix(:, :)
      integer, allocatable :: nodes(:)
      integer :: i, k, n, c
      type(prescribed_t), allocatable :: pr(:), skew(:)
      logical, allocatable :: rot(:)
      integer :: d, m
      integer, allocatable :: skew_spc(:)
      logical, parameter :: code(3, 0:7) = reshape([.false., .false., .false., &
         .true., .false., .false., .false., .true., .false., .false., .false., .true., &
         .true., .true., .false., .false., .true., .true., .true., .false., .true., &
         .true., .true., .true.], [3, 8])
      allocate(fix(6, model%nn), skew(0), skew_spc(0))
      fix = .false.
      do i = 1, model%nn
         fix(1:3, i) = code(:, inp%node_tc(i))
         fix(4:6, i) = code(:, inp%node_rc(i))
      end do
      do i = 1, size(inp%spcs)
         associate (s => inp%spcs(i))
            if (s%is_set) then
               call set_nodes(inp, model, mp, s%id, .false., s%src, 'NSID', nodes, error)
               if (allocated(error)) return
            else
               nodes = [node_index(inp, mp, s%id, s%src, 'NID', error)]
               if (allocated(error)) return
            end if
            if (s%cid /= 0) then               ! axes resolved by dx_read_loads loads_finish
               do k = 1, size(nodes)
                  do d = 1, 3
                     if (.not. s%dof(d)) cycle
                     skew = [skew, prescribed_t(node=nodes(k), dof=4, vad=0, curve=0, &
                                                sf=0.0_wp, dir=s%axes(:, d))]
                     skew_spc = [skew_spc, i]
                  end do
               end do
               cycle
            end if
            do k = 1, size(nodes)
               fix(:, nodes(k)) = fix(:, nodes(k)) .or. s%dof
            end do
         end associate
      end do
      call twod_fixes(model, fix)
      ! a skew SPC with a global translational one on the same node, or with a skew axis of
      ! another system that is neither parallel nor orthogonal to it: the constraints are
      ! applied one after the other (apply_spc, then apply_prescribed), which holds all of
      ! them only for orthogonal axes: refused, naming CID
      do k = 1, size(skew)
         associate (s => inp%spcs(skew_spc(k)), nd => skew(k)%node)
            if (any(fix(1:3, nd))) then
               call set_error(error, at(inp, s%src)//'field CID: node '// &
                  str(model%node_label(nd))//' also has a constraint along the global '// &
                  'axes (*BOUNDARY_SPC_* with CID 0 or *NODE TC): a mix of global and '// &
                  'local constraints on one node is not implemented')
               return
            end if
            do m = 1, k - 1
               if (skew(m)%node /= nd) cycle
               if (abs(dot_product(skew(m)%dir, skew(k)%dir)) > 1.0e-12_wp .and. &
                   abs(dot_product(skew(m)%dir, skew(k)%dir)) < 1.0_wp - 1.0e-12_wp) then
                  call set_error(error, at(inp, s%src)//'field CID: node '// &
                     str(model%node_label(nd))//' is held along axes of two coordinate '// &
                     'systems that are neither parallel nor orthogonal: not implemented')
                  return
               end if
            end do
         end associate
      end do
      n = count(any(fix, dim=1))
      allocate(model%spcs(n))
      n = 0
      do i = 1, model%nn
         if (any(fix(:, i))) then
            n = n + 1
            model%spcs(n)%node = i
            model%spcs(n)%dof = fix(:, i)
         end if
      end do
      allocate(pr(0))
      do i = 1, size(inp%motions)
         associate (m => inp%motions(i))
            c = curve_index(inp, mp, m%lcid, m%src, 'LCID', error)
            if (allocated(error)) return
            if (m%is_set) then
               call set_nodes(inp, model, mp, m%id, .false., m%src, 'NSID', nodes, error)
               if (allocated(error)) return
            else
               nodes = [node_index(inp, mp, m%id, m%src, 'NID', error)]
               if (allocated(error)) return
            end if
            if (m%dof >= 5) then      ! rotations exist on shell and beam nodes only
               if (.not. allocated(rot)) call rotation_nodes(model, rot)
               do k = 1, size(nodes)
                  if (.not. rot(nodes(k))) then
                     call set_error(error, at(inp, m%src)//'field DOF: DOF '//str(m%dof)// &
                        ' (a rotation) on node '//str(model%node_label(nodes(k)))// &
                        ', which carries no rotation (not a shell or beam node)')
                     return
                  end if
               end do
            end if
            do k = 1, size(nodes)
               pr = [pr, prescribed_t(node=nodes(k), dof=m%dof, vad=m%vad, curve=c, sf=m%sf, &
                     dir=unit_axis(m%dof), death=m%death, birth=m%birth)]
            end do
         end associate
      end do
      ! skew SPCs last: the velocity along a constrained local axis is zero after the step's
      ! prescribed motions (dx_constraints apply_prescribed, curve 0)
      pr = [pr, skew]
      call move_alloc(pr, model%prescribed)
   end subroutine build_bcs

   !> A 2D deck (dx_quad2d; all its parts are 2D, dx_model_build): the z DOF of every node is
   !> fixed, so every z component of a nodal quantity stays zero whatever the loads; in
   !> axisymmetry the nodes on the axis (x = r = 0 at t = 0) also have their radial DOF fixed.
   subroutine twod_fixes(model, fix)
      type(model_t), intent(in) :: model
      logical, intent(inout) :: fix(:, :)
      type(family_t) :: fam
      integer :: i
      if (size(model%blocks) == 0) return
      fam = element_family(model%blocks(1)%etype)
      if (.not. fam%twod) return
      fix(3, :) = .true.
      if (.not. fam%axisym) return
      do i = 1, model%nn
         if (model%x0(1, i) == 0.0_wp) fix(1, i) = .true.
      end do
   end subroutine twod_fixes

   !> rot(i): node i belongs to an element of a family with rotations (shells, beams) or
   !> has a rotary inertia of its own (*ELEMENT_INERTIA)
   subroutine rotation_nodes(model, rot)
      type(model_t), intent(in) :: model
      logical, allocatable, intent(out) :: rot(:)
      integer :: b, i
      type(family_t) :: fam
      allocate(rot(model%nn))
      rot = .false.
      do b = 1, size(model%blocks)
         fam = element_family(model%blocks(b)%etype)
         if (.not. fam%rot) cycle
         do i = 1, model%blocks(b)%nel
            rot(model%blocks(b)%conn(:, i)) = .true.
         end do
      end do
      if (allocated(model%node_rinert)) rot = rot .or. model%node_rinert > 0.0_wp
   end subroutine rotation_nodes

   pure function unit_axis(d) result(a)
      integer, intent(in) :: d
      real(wp) :: a(3)
      a = 0.0_wp
      if (d >= 1 .and. d <= 3) a(d) = 1.0_wp
   end function unit_axis

   !> v0 from *INITIAL_VELOCITY and _GENERATION in deck order, then _NODE (overrides)
   subroutine build_initial_velocity(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, k, j, ip
      integer, allocatable :: nodes(:), ex(:)
      logical, allocatable :: excl(:), pmask(:), nmask(:), rot(:)
      real(wp) :: r(3)
      allocate(model%v0(3, model%nn), excl(model%nn), pmask(size(model%parts)), &
               nmask(model%nn))
      model%v0 = 0.0_wp
      do i = 1, size(inp%ivels)
         associate (q => inp%ivels(i))
            select case (q%kind)
            case (IVEL_SET)
               call set_nodes(inp, model, mp, q%id, .true., q%src, 'NSID', nodes, error)
               if (allocated(error)) return
               excl = .false.
               if (q%nsidex > 0) then
                  call set_nodes(inp, model, mp, q%nsidex, .false., q%src, 'NSIDEX', ex, error)
                  if (allocated(error)) return
                  excl(ex) = .true.
                  do k = 1, size(ex)
                     model%v0(:, ex(k)) = q%vex
                  end do
               end if
               do k = 1, size(nodes)
                  if (.not. excl(nodes(k))) model%v0(:, nodes(k)) = q%v
               end do
            case (IVEL_GEN)
               nmask = .false.
               if (q%id == 0) then
                  nmask = .true.
               else if (q%styp == 3) then
                  call set_nodes(inp, model, mp, q%id, .false., q%src, 'ID', nodes, error)
                  if (allocated(error)) return
                  nmask(nodes) = .true.
               else
                  pmask = .false.
                  if (q%styp == 2) then
                     ip = mp%part%get(q%id)
                     if (ip == 0) then
                        call set_error(error, at(inp, q%src)//'field ID: part '//str(q%id)// &
                                       ' is not defined (*PART)')
                        return
                     end if
                     pmask(ip) = .true.
                  else
                     j = mp%pset%get(q%id)
                     if (j == 0) then
                        call set_error(error, at(inp, q%src)//'field ID: part set '// &
                                       str(q%id)//' is not defined (*SET_PART_LIST)')
                        return
                     end if
                     pmask(model%part_sets(j)%parts) = .true.
                  end if
                  do j = 1, size(model%blocks)
                     if (.not. pmask(model%blocks(j)%ipart)) cycle
                     do k = 1, model%blocks(j)%nel
                        nmask(model%blocks(j)%conn(:, k)) = .true.
                     end do
                  end do
               end if
               do k = 1, model%nn
                  if (.not. nmask(k)) cycle
                  r = model%x0(:, k) - q%xc
                  model%v0(:, k) = q%v + q%omega*cross(q%axis, r)
               end do
            end select
         end associate
      end do
      do i = 1, size(inp%ivels)
         associate (q => inp%ivels(i))
            if (q%kind /= IVEL_NODE) cycle
            k = node_index(inp, mp, q%id, q%src, 'NID', error)
            if (allocated(error)) return
            model%v0(:, k) = q%v
            if (all(q%vr == 0.0_wp)) cycle
            if (.not. allocated(rot)) call rotation_nodes(model, rot)
            if (.not. rot(k)) then
               call set_error(error, at(inp, q%src)//'field VXR: node '//str(q%id)// &
                  ' carries no rotation (not a shell or beam node): VXR, VYR, VZR must be 0')
               return
            end if
            if (.not. allocated(model%w0)) then
               allocate(model%w0(3, model%nn))
               model%w0 = 0.0_wp
            end if
            model%w0(:, k) = q%vr
         end associate
      end do
   end subroutine build_initial_velocity


   !> nodal loads, segment pressures, rigid walls
   subroutine build_loads(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, k, c, s, nseg
      integer, allocatable :: seg(:, :), nodes(:), ex(:)
      logical, allocatable :: keep(:)
      real(wp) :: d
      type(family_t) :: fam
      logical, allocatable :: rot(:)
      allocate(model%node_loads(size(inp%node_loads)))
      do i = 1, size(inp%node_loads)
         associate (l => inp%node_loads(i))
            model%node_loads(i)%node = node_index(inp, mp, l%nid, l%src, 'NID', error)
            if (allocated(error)) return
            model%node_loads(i)%curve = curve_index(inp, mp, l%lcid, l%src, 'LCID', error)
            if (allocated(error)) return
            model%node_loads(i)%dof = l%dof
            model%node_loads(i)%sf = l%sf
            if (l%dof >= 5) then      ! a moment: rotations exist on shell and beam nodes only
               if (.not. allocated(rot)) call rotation_nodes(model, rot)
               if (.not. rot(model%node_loads(i)%node)) then
                  call set_error(error, at(inp, l%src)//'field DOF: DOF '//str(l%dof)// &
                     ' (a moment) on node '//str(l%nid)//', which carries no rotation '// &
                     '(not a shell or beam node)')
                  return
               end if
            end if
         end associate
      end do
      nseg = 0
      do i = 1, size(inp%seg_loads)
         if (inp%seg_loads(i)%ssid == 0) then
            nseg = nseg + 1
         else
            s = mp%sset%get(inp%seg_loads(i)%ssid)
            if (s == 0) then
               call set_error(error, at(inp, inp%seg_loads(i)%src)//'field SSID: segment '// &
                  'set '//str(inp%seg_loads(i)%ssid)//' is not defined (*SET_SEGMENT)')
               return
            end if
            nseg = nseg + size(model%segment_sets(s)%seg, 2)
         end if
      end do
      allocate(model%seg_loads(nseg))
      nseg = 0
      do i = 1, size(inp%seg_loads)
         associate (l => inp%seg_loads(i))
            c = curve_index(inp, mp, l%lcid, l%src, 'LCID', error)
            if (allocated(error)) return
            if (l%ssid == 0 .and. l%n(3) == 0) then    ! a 2-node edge of a 2D deck
               call dense_segments(inp, mp, reshape([l%n(1:2), l%n(2), l%n(2)], [4, 1]), &
                                   l%src, seg, error)
               if (allocated(error)) return
               fam = element_family(model%blocks(1)%etype)
               ! N3 = 0 marks the edge, N4 its kind: 0 plane strain, -1 axisymmetric (the
               ! load pass may see a model without blocks: the MPI loads model)
               seg(3, 1) = 0
               seg(4, 1) = merge(-1, 0, fam%axisym)
               if (.not. fam%twod) then
                  call set_error(error, at(inp, l%src)//'field N3: a 2-node segment (N3, N4 '// &
                     'blank) is an edge of a 2D deck (*SECTION_SHELL ELFORM 13-15); this '// &
                     'deck is 3D: give N3 (and N4) of the face')
                  return
               end if
            else if (l%ssid == 0) then
               call dense_segments(inp, mp, reshape(l%n, [4, 1]), l%src, seg, error)
               if (allocated(error)) return
            else
               seg = model%segment_sets(mp%sset%get(l%ssid))%seg
            end if
            do k = 1, size(seg, 2)
               nseg = nseg + 1
               model%seg_loads(nseg) = load_segment_t(nodes=seg(:, k), curve=c, sf=l%sf, &
                                                      at=l%at)
            end do
         end associate
      end do
      allocate(model%walls(size(inp%walls)), keep(model%nn))
      do i = 1, size(inp%walls)
         associate (r => inp%walls(i), wl => model%walls(i))
            wl%label = r%label
            wl%x0 = r%xt
            wl%n = (r%xh - r%xt)/norm2(r%xh - r%xt)
            wl%fric = r%fric
            call set_nodes(inp, model, mp, r%nsid, .true., r%src, 'NSID', nodes, error)
            if (allocated(error)) return
            keep = .false.
            keep(nodes) = .true.
            if (r%nsidex > 0) then
               call set_nodes(inp, model, mp, r%nsidex, .false., r%src, 'NSIDEX', ex, error)
               if (allocated(error)) return
               keep(ex) = .false.
            end if
            if (r%offset > 0.0_wp) then
               do k = 1, model%nn
                  if (.not. keep(k)) cycle
                  d = dot_product(model%x0(:, k) - wl%x0, wl%n)
                  keep(k) = abs(d) <= r%offset
               end do
            end if
            wl%nodes = pack([(k, k = 1, model%nn)], keep)
         end associate
      end do
   end subroutine build_loads

end module dx_build_loads
