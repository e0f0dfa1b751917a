!> Readers for boundary conditions, loads, initial conditions and rigid walls:
!> *BOUNDARY_SPC_NODE/_SET, *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET, *INITIAL_VELOCITY,
!> *INITIAL_VELOCITY_NODE, *INITIAL_VELOCITY_GENERATION, *LOAD_NODE_POINT, *LOAD_SEGMENT,
!> *LOAD_SEGMENT_SET, *RIGIDWALL_PLANAR, *DEFINE_COORDINATE_SYSTEM (used by ICID of
!> *INITIAL_VELOCITY(_NODE, _GENERATION), CID of *LOAD_NODE_* and *BOUNDARY_SPC_*).
!> Layouts and defaults: LS-DYNA Keyword User's Manual, Vol. I. Options dynx cannot honour
!> (boxes, rotational velocities on solids, follower forces, ...) give an error naming the
!> field.
module dx_read_loads
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, spc_in_t, motion_in_t, ivel_in_t, &
                             load_node_in_t, load_seg_in_t, wall_in_t, IVEL_SET, IVEL_NODE, &
                             IVEL_GEN, csys_in_t, origin_t
   use dx_deck_buffers, only: spc_buffer_t, motion_buffer_t, ivel_buffer_t, &
                              load_node_buffer_t, load_seg_buffer_t
   implicit none
   private
   public :: register_loads, loads_finish, read_motion_fields

contains

   !> Add this family's keywords to the registry.
   subroutine register_loads(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('BOUNDARY_SPC_NODE', read_spc, id=.true.)
      call reg%add('BOUNDARY_SPC_SET', read_spc, id=.true.)
      call reg%add('BOUNDARY_PRESCRIBED_MOTION_NODE', read_motion, id=.true.)
      call reg%add('BOUNDARY_PRESCRIBED_MOTION_SET', read_motion, id=.true.)
      call reg%add('INITIAL_VELOCITY', read_initial_velocity)
      call reg%add('INITIAL_VELOCITY_NODE', read_initial_velocity_node)
      call reg%add('INITIAL_VELOCITY_GENERATION', read_initial_velocity_generation)
      call reg%add('LOAD_NODE_POINT', read_load_node, id=.true.)
      call reg%add('LOAD_NODE_SET', read_load_node, id=.true.)
      call reg%add('LOAD_SEGMENT', read_load_segment, id=.true.)
      call reg%add('LOAD_SEGMENT_SET', read_load_segment, id=.true.)
      call reg%add('RIGIDWALL_PLANAR', read_rigidwall_planar, id=.true.)
      call reg%add('DEFINE_COORDINATE_SYSTEM', read_define_csys, title=.true.)
   end subroutine register_loads

   !> NID|NSID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ
   subroutine read_spc(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k, d
      type(spc_in_t) :: s
      type(spc_buffer_t) :: buf
      type(card_t) :: c
      character(len=5), parameter :: dn(6) = ['DOFX ', 'DOFY ', 'DOFZ ', 'DOFRX', 'DOFRY', &
                                              'DOFRZ']
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card '//str(data_start(blk))//' (NID CID DOFX '// &
                  'DOFY DOFZ DOFRX DOFRY DOFRZ)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         s = spc_in_t()
         s%is_set = blk%base == 'BOUNDARY_SPC_SET'
         call c%id(trim(merge('NSID', 'NID ', s%is_set)), s%id)
         call c%int('CID', 0, s%cid, min=0)
         do k = 1, 6
            call c%int(trim(dn(k)), 0, d)
            if (c%ok() .and. d /= 0 .and. d /= 1) call c%fail(trim(dn(k)), 'must be 0 '// &
               '(free) or 1 (constrained), got '//str(d))
            s%dof(k) = d == 1
            if (c%ok() .and. k > 3 .and. s%dof(k) .and. s%cid /= 0) call c%fail(trim(dn(k)), &
               'a rotation constrained in a local system (CID /= 0) is not implemented '// &
               '(translations DOFX DOFY DOFZ along the local axes are)')
         end do
         if (c%halt()) exit
         s%src = origin(blk%ifile, c%card_line(), blk%name)
         call buf%push(s)
      end do
      call buf%flush(inp%spcs)
      call c%done(error)
   end subroutine read_spc

   !> NID|NSID DOF VAD LCID SF VID DEATH BIRTH
   subroutine read_motion(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(motion_in_t) :: m
      type(motion_buffer_t) :: buf
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card '//str(data_start(blk))//' (NID DOF VAD '// &
                  'LCID SF VID DEATH BIRTH)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         call c%seek(ic)
         m = motion_in_t()
         m%is_set = blk%base == 'BOUNDARY_PRESCRIBED_MOTION_SET'
         call c%id(trim(merge('NSID', 'NID ', m%is_set)), m%id)
         call c%int('DOF', 0, m%dof)
         if (c%ok() .and. (m%dof < 1 .or. m%dof > 7 .or. m%dof == 4)) call c%fail('DOF', &
            'DOF '//str(m%dof)//' is not supported (supported: 1 x, 2 y, 3 z translation; '// &
            '5, 6, 7 rotation about x, y, z on shell and beam nodes)')
         call read_motion_fields(c, m%vad, m%lcid, m%sf, m%death, m%birth)
         if (c%halt()) exit
         m%src = origin(blk%ifile, c%card_line(), blk%name)
         call buf%push(m)
      end do
      call buf%flush(inp%motions)
      call c%done(error)
   end subroutine read_motion

   !> the next three fields: a translational velocity; the three after them (rotational
   !> velocities) into vr when present (shell nodes), else blank or zero
   subroutine velocity(c, names, v, vr)
      type(card_t), intent(inout) :: c
      character(*), intent(in) :: names(6)
      real(wp), intent(out) :: v(3)
      real(wp), intent(out), optional :: vr(3)   !< the rotational fields (shell nodes)
      integer :: k
      do k = 1, 3
         call c%real(trim(names(k)), 0.0_wp, v(k))
      end do
      if (present(vr)) then
         do k = 1, 3
            call c%real(trim(names(k + 3)), 0.0_wp, vr(k))
         end do
         return
      end if
      do k = 4, 6
         call c%zero_real(trim(names(k)), 'solid elements have no rotational degrees of '// &
                          'freedom')
      end do
   end subroutine velocity

   !> card 1 NSID NSIDEX BOXID IRIGID ICID; card 2 VX VY VZ VXR VYR VZR;
   !> card 3 (NSIDEX > 0) VXE VYE VZE VXRE VYRE VZRE
   subroutine read_initial_velocity(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(ivel_in_t) :: r
      type(ivel_buffer_t) :: buf
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (NSID NSIDEX BOXID IRIGID ICID)')
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         r = ivel_in_t()
         r%kind = IVEL_SET
         call c%seek(ic)
         call c%int('NSID', 0, r%id)
         call c%int('NSIDEX', 0, r%nsidex)
         if (c%ok() .and. (r%id < 0 .or. r%nsidex < 0)) &
            call c%fail_card(ic, 'NSID and NSIDEX must be >= 0')
         call c%zero_int('BOXID', 'boxes')
         call c%zero_int('IRIGID', 'rigid bodies')
         call c%int('ICID', 0, r%icid, min=0)
         r%src = origin(blk%ifile, c%card_line(), blk%name)
         if (c%ok() .and. ic + 1 > blk%n) &
            call c%fail_card(ic, 'missing card 2 (VX VY VZ VXR VYR VZR)')
         call c%seek(ic + 1)
         call velocity(c, ['VX ', 'VY ', 'VZ ', 'VXR', 'VYR', 'VZR'], r%v)
         ic = ic + 2
         if (r%nsidex > 0) then
            call c%seek(ic)
            call velocity(c, ['VXE ', 'VYE ', 'VZE ', 'VXRE', 'VYRE', 'VZRE'], r%vex)
            ic = ic + 1
         end if
         if (c%halt()) exit
         call buf%push(r)
      end do
      call buf%flush(inp%ivels)
      call c%done(error)
   end subroutine read_initial_velocity

   !> NID VX VY VZ VXR VYR VZR ICID
   subroutine read_initial_velocity_node(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(ivel_in_t) :: r
      type(ivel_buffer_t) :: buf
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      do ic = 1, blk%n
         r = ivel_in_t()
         r%kind = IVEL_NODE
         call c%seek(ic)
         call c%id('NID', r%id)
         call velocity(c, ['VX ', 'VY ', 'VZ ', 'VXR', 'VYR', 'VZR'], r%v, r%vr)
         call c%int('ICID', 0, r%icid, min=0)
         if (c%halt()) exit
         r%src = origin(blk%ifile, c%card_line(), blk%name)
         call buf%push(r)
      end do
      call buf%flush(inp%ivels)
      call c%done(error)
   end subroutine read_initial_velocity_node

   !> card 1 ID STYP OMEGA VX VY VZ IVATN ICID; card 2 XC YC ZC NX NY NZ PHASE IRIGID
   subroutine read_initial_velocity_generation(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k
      real(wp) :: nrm
      type(ivel_in_t) :: r
      type(ivel_buffer_t) :: buf
      type(card_t) :: c
      character(len=2), parameter :: cn(3) = ['XC', 'YC', 'ZC'], an(3) = ['NX', 'NY', 'NZ'], &
                                     vn(3) = ['VX', 'VY', 'VZ']
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (ID STYP OMEGA VX VY VZ IVATN ICID)')
      ic = 1
      do while (ic <= blk%n .and. .not. c%halt())
         r = ivel_in_t()
         r%kind = IVEL_GEN
         call c%seek(ic)
         call c%int('ID', 0, r%id, min=0)
         call c%int('STYP', 0, r%styp)
         if (c%ok() .and. r%id > 0 .and. (r%styp < 1 .or. r%styp > 3)) call c%fail('STYP', &
            'must be 1 (part set), 2 (part) or 3 (node set), got '//str(r%styp))
         call c%real('OMEGA', 0.0_wp, r%omega)
         do k = 1, 3
            call c%real(vn(k), 0.0_wp, r%v(k))
         end do
         call c%zero_int('IVATN', 'rigid body slave parts')
         call c%int('ICID', 0, r%icid, min=0)
         if (c%ok() .and. r%icid /= 0 .and. r%omega /= 0.0_wp) call c%fail('ICID', &
            'a local system with a rotation (OMEGA /= 0) is not implemented (only VX VY VZ '// &
            'in the local system, OMEGA = 0)')
         if (c%halt()) exit
         r%src = origin(blk%ifile, c%card_line(), blk%name)
         if (ic + 1 > blk%n) then
            ! the last record's card 2 left blank (stripped as layout: a blank line before
            ! the next keyword) is a card of defaults in LS-DYNA; without a rotation
            ! (OMEGA = 0) none of its fields matters
            if (r%omega == 0.0_wp) then
               call buf%push(r)
               exit
            end if
            call c%fail_card(ic, 'missing card 2 (XC YC ZC NX NY NZ PHASE IRIGID)')
            exit
         end if
         ic = ic + 1
         call c%seek(ic)
         do k = 1, 3
            call c%real(cn(k), 0.0_wp, r%xc(k))
         end do
         do k = 1, 3
            call c%real(an(k), 0.0_wp, r%axis(k))
         end do
         call c%zero_int('PHASE', 'dynx has no dynamic relaxation')
         call c%zero_int('IRIGID', 'rigid bodies')
         nrm = norm2(r%axis)
         if (c%ok() .and. r%omega /= 0.0_wp) then
            if (nrm > 0.0_wp) then
               r%axis = r%axis/nrm
            else
               call c%fail('NX', 'OMEGA is nonzero but the rotation axis (NX, NY, NZ) is zero')
            end if
         end if
         if (c%halt()) exit
         call buf%push(r)
         ic = ic + 1
      end do
      call buf%flush(inp%ivels)
      call c%done(error)
   end subroutine read_initial_velocity_generation

   !> NID DOF LCID SF CID M1 M2 M3
   subroutine read_load_node(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k
      logical :: is_set
      type(load_node_in_t) :: l
      type(load_node_buffer_t) :: buf
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      is_set = blk%base == 'LOAD_NODE_SET'
      do ic = data_start(blk), blk%n
         l = load_node_in_t()
         call c%seek(ic)
         call c%id(trim(merge('NSID', 'NID ', is_set)), l%nid)
         call c%int('DOF', 0, l%dof)
         if (c%ok() .and. (l%dof < 1 .or. l%dof > 7 .or. l%dof == 4)) call c%fail('DOF', &
            'DOF '//str(l%dof)//' is not supported (supported: 1, 2, 3 force along x, y, z; '// &
            '5, 6, 7 moment about x, y, z on shell and beam nodes)')
         call c%id('LCID', l%lcid)
         call c%real('SF', 1.0_wp, l%sf)
         if (l%sf == 0.0_wp) l%sf = 1.0_wp
         call c%int('CID', 0, l%cid, min=0)
         do k = 1, 3
            call c%zero_int('M'//str(k), 'follower forces')
         end do
         if (c%halt()) exit
         l%src = origin(blk%ifile, c%card_line(), blk%name)
         call buf%push(l)
      end do
      if (is_set) then
         call buf%flush(inp%node_set_loads)   ! nid holds NSID: loads_finish
      else
         call buf%flush(inp%node_loads)
      end if
      call c%done(error)
   end subroutine read_load_node

   !> *DEFINE_COORDINATE_SYSTEM(_TITLE): card 1 CID XO YO ZO XL YL ZL CIDL, card 2 XP YP ZP.
   !> O the origin, L a point on the local x axis, P a point in the local x-y plane (LS-DYNA
   !> Keyword User's Manual, Vol. I): x = (L - O)/|L - O|, z = x cross (P - O) normalised,
   !> y = z cross x (a right-handed orthonormal basis). CIDL (points given in another local
   !> system) is not implemented: an error when nonzero. Coincident points or P on the x
   !> axis are errors naming the field.
   subroutine read_define_csys(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      type(csys_in_t) :: s
      real(wp) :: xl(3), xp(3), z(3), a, b
      integer :: k, i0
      character(len=2), parameter :: on(3) = ['XO', 'YO', 'ZO'], ln(3) = ['XL', 'YL', 'ZL'], &
                                     pn(3) = ['XP', 'YP', 'ZP']
      if (.not. allocated(inp%csys)) allocate(inp%csys(0))
      call deck_cursor(deck, blk, c)
      i0 = data_start(blk)
      call c%need(i0 + 1, 'two cards expected (CID XO YO ZO XL YL ZL CIDL; XP YP ZP)')
      call c%max_cards(i0 + 1)
      if (c%halt()) then
         call c%done(error)
         return
      end if
      call c%seek(i0)
      call c%id('CID', s%id)
      do k = 1, 3
         call c%real(on(k), 0.0_wp, s%o(k))
      end do
      do k = 1, 3
         call c%real(ln(k), 0.0_wp, xl(k))
      end do
      call c%zero_int('CIDL', 'points given in another local system')
      if (c%ok()) then
         do k = 1, size(inp%csys)
            if (inp%csys(k)%id == s%id) call c%fail('CID', 'coordinate system '// &
               str(s%id)//' is defined twice')
         end do
      end if
      call c%seek(i0 + 1)
      do k = 1, 3
         call c%real(pn(k), 0.0_wp, xp(k))
      end do
      if (c%ok()) then
         xl = xl - s%o
         xp = xp - s%o
         a = norm2(xl)
         if (a == 0.0_wp) then
            call c%fail('XL', 'the x-axis point (XL, YL, ZL) coincides with the origin')
         else
            s%axes(:,1) = xl/a
            z = [s%axes(2,1)*xp(3) - s%axes(3,1)*xp(2), s%axes(3,1)*xp(1) - s%axes(1,1)*xp(3), &
                 s%axes(1,1)*xp(2) - s%axes(2,1)*xp(1)]
            b = norm2(z)
            if (b <= 1.0e-12_wp*max(a, norm2(xp))) then
               call c%fail('XP', 'the x-y plane point (XP, YP, ZP) lies on the local x axis')
            else
               s%axes(:,3) = z/b
               s%axes(:,2) = [s%axes(2,3)*s%axes(3,1) - s%axes(3,3)*s%axes(2,1), &
                              s%axes(3,3)*s%axes(1,1) - s%axes(1,3)*s%axes(3,1), &
                              s%axes(1,3)*s%axes(2,1) - s%axes(2,3)*s%axes(1,1)]
            end if
         end if
      end if
      if (c%ok()) then
         s%src = origin(blk%ifile, c%card_line(), blk%name)
         inp%csys = [inp%csys, s]
      end if
      call c%done(error)
   end subroutine read_define_csys

   !> After the whole deck (sets resolved): each *LOAD_NODE_SET card becomes the same load
   !> on every node of its set, in the set's order (LS-DYNA: each node carries SF x curve).
   !> An *INITIAL_VELOCITY(_NODE, _GENERATION) with ICID: the velocities (VX VY VZ, the
   !> rotational VXR VYR VZR, the exempted VXE VYE VZE) are components along the axes of that
   !> *DEFINE_COORDINATE_SYSTEM; they become global components v = sum_k v_k axis_k.
   !> A *BOUNDARY_SPC_* with CID gets that system's axes (dx_build_loads holds the node's
   !> velocity along each constrained one at zero). A *LOAD_NODE_* with CID: the force (moment) along local axis d becomes its global
   !> components, one nodal load per nonzero component (sf axis_d(k), same curve): the sum is
   !> the local load (LS-DYNA Keyword User's Manual, *LOAD_NODE, CID).
   subroutine loads_finish(inp, error)
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j, k
      type(load_node_in_t) :: l
      type(load_node_buffer_t) :: buf
      if (.not. allocated(inp%csys)) allocate(inp%csys(0))
      do i = 1, size(inp%spcs)              ! skew SPCs: the axes of their CID
         if (inp%spcs(i)%cid == 0) cycle
         j = csys_index(inp, inp%spcs(i)%cid, inp%spcs(i)%src, 'CID', error)
         if (j == 0) return
         inp%spcs(i)%axes = inp%csys(j)%axes
      end do
      if (allocated(inp%ivels)) then
         do i = 1, size(inp%ivels)
            if (inp%ivels(i)%icid == 0) cycle
            j = csys_index(inp, inp%ivels(i)%icid, inp%ivels(i)%src, 'ICID', error)
            if (j == 0) return
            associate (r => inp%ivels(i), a => inp%csys(j)%axes)
               r%v = matmul(a, r%v)
               r%vr = matmul(a, r%vr)
               r%vex = matmul(a, r%vex)
               r%icid = 0
            end associate
         end do
      end if
      do i = 1, size(inp%node_set_loads)
         l = inp%node_set_loads(i)
         j = 0
         do k = size(inp%node_sets), 1, -1
            if (inp%node_sets(k)%label == l%nid) then
               j = k; exit
            end if
         end do
         if (j == 0) then
            call set_error(error, inp%files(l%src%ifile)%s//':'//str(l%src%line)//': *'// &
               l%src%key//': field NSID: node set '//str(l%nid)//' is not defined')
            return
         end if
         do k = 1, size(inp%node_sets(j)%ids)
            l%nid = inp%node_sets(j)%ids(k)
            call buf%push(l)
         end do
      end do
      call buf%flush(inp%node_loads)
      deallocate(inp%node_set_loads)
      allocate(inp%node_set_loads(0))
      if (.not. any(inp%node_loads(:)%cid /= 0)) return
      do i = 1, size(inp%node_loads)
         l = inp%node_loads(i)
         if (l%cid == 0) then
            call buf%push(l)
            cycle
         end if
         j = csys_index(inp, l%cid, l%src, 'CID', error)
         if (j == 0) return
         do k = 1, 3
            if (inp%csys(j)%axes(k, mod(l%dof - 1, 4) + 1) == 0.0_wp) cycle
            call buf%push(load_node_in_t(nid=l%nid, dof=k + 4*((l%dof - 1)/4), lcid=l%lcid, &
                          cid=0, sf=l%sf*inp%csys(j)%axes(k, mod(l%dof - 1, 4) + 1), src=l%src))
         end do
      end do
      deallocate(inp%node_loads)
      allocate(inp%node_loads(0))
      call buf%flush(inp%node_loads)
   end subroutine loads_finish

   !> The index in inp%csys of coordinate system id (0 with an error naming the field when it
   !> is not defined).
   function csys_index(inp, id, src, field, error) result(j)
      type(model_input_t), intent(in) :: inp
      integer, intent(in) :: id
      type(origin_t), intent(in) :: src
      character(*), intent(in) :: field
      type(error_t), allocatable, intent(inout) :: error
      integer :: j, k
      j = 0
      do k = 1, size(inp%csys)
         if (inp%csys(k)%id == id) j = k
      end do
      if (j == 0) call set_error(error, inp%files(src%ifile)%s//':'//str(src%line)//': *'// &
         src%key//': field '//field//': coordinate system '//str(id)// &
         ' is not defined (*DEFINE_COORDINATE_SYSTEM)')
   end function csys_index

   !> *LOAD_SEGMENT: LCID SF AT N1 N2 N3 N4 (N5 must be blank: no higher-order segments);
   !> *LOAD_SEGMENT_SET: SSID LCID SF AT
   subroutine read_load_segment(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic, k
      logical :: is_set
      type(load_seg_in_t) :: l
      type(load_seg_buffer_t) :: buf
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      is_set = blk%base == 'LOAD_SEGMENT_SET'
      call c%need(data_start(blk), 'missing card '//str(data_start(blk))//' ('// &
                  trim(merge('SSID LCID SF AT        ', 'LCID SF AT N1 N2 N3 N4 ', is_set))//')')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         l = load_seg_in_t()
         call c%seek(ic)
         if (is_set) call c%id('SSID', l%ssid)
         call c%id('LCID', l%lcid)
         call c%real('SF', 1.0_wp, l%sf)
         if (l%sf == 0.0_wp) l%sf = 1.0_wp
         call c%real('AT', 0.0_wp, l%at)
         if (is_set) then
            call c%zero_real('DT', 'a death time')
         else
            do k = 1, 4
               call c%int('N'//str(k), 0, l%n(k))
               if (c%ok() .and. k <= 2 .and. l%n(k) <= 0) call c%fail('N'//str(k), &
                  'node id must be > 0')
               if (c%ok() .and. k >= 3 .and. l%n(k) < 0) call c%fail('N'//str(k), &
                  'node id must be > 0 (or N3 and N4 blank: a 2-node edge of a 2D deck)')
            end do
            ! N3 = N4 = 0: a 2-node edge (2D decks; checked at build), kept as (N1, N2, 0, 0)
            if (c%ok() .and. l%n(3) == 0 .and. l%n(4) /= 0) call c%fail('N3', &
               'node id must be > 0 (or N3 and N4 blank: a 2-node edge of a 2D deck)')
            if (l%n(4) == 0) l%n(4) = l%n(3)
            call c%zero_int('N5', 'higher-order segments')
         end if
         if (c%halt()) exit
         l%src = origin(blk%ifile, c%card_line(), blk%name)
         call buf%push(l)
      end do
      call buf%flush(inp%seg_loads)
      call c%done(error)
   end subroutine read_load_segment

   !> card 1 NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF; card 2 XT YT ZT XH YH ZH FRIC WVEL
   subroutine read_rigidwall_planar(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i0, k
      real(wp) :: death, rwksf
      type(wall_in_t) :: r
      type(card_t) :: c
      character(len=2), parameter :: tn(3) = ['XT', 'YT', 'ZT'], hn(3) = ['XH', 'YH', 'ZH']
      call deck_cursor(deck, blk, c)
      i0 = data_start(blk)
      if (blk%opt_id) then
         call c%seek(1)
         call c%int('RWID', 0, r%label)
      end if
      if (r%label == 0) r%label = size(inp%walls) + 1
      call c%need(i0, 'missing card '//str(i0)//' (NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF)')
      if (c%ok() .and. blk%n < i0 + 1) &
         call c%fail_card(i0, 'missing card 2 (XT YT ZT XH YH ZH FRIC WVEL)')
      call c%max_cards(i0 + 1)
      call c%seek(i0)
      call c%int('NSID', 0, r%nsid)
      call c%int('NSIDEX', 0, r%nsidex)
      call c%zero_int('BOXID', 'boxes')
      call c%real('OFFSET', 0.0_wp, r%offset)
      if (c%ok() .and. r%offset < 0.0_wp) call c%fail('OFFSET', 'must be >= 0')
      call c%zero_real('BIRTH', 'wall birth times')
      call c%real('DEATH', 1.0e20_wp, death)
      if (c%ok() .and. death /= 0.0_wp .and. death < 1.0e20_wp) &
         call c%fail('DEATH', 'wall death times are not supported')
      call c%real('RWKSF', 1.0_wp, rwksf)
      if (c%ok() .and. rwksf /= 0.0_wp .and. rwksf /= 1.0_wp) call c%fail('RWKSF', &
         'penalty stiffness scaling is not supported (the wall is a kinematic constraint)')
      call c%seek(i0 + 1)
      do k = 1, 3
         call c%real(tn(k), 0.0_wp, r%xt(k))
      end do
      do k = 1, 3
         call c%real(hn(k), 0.0_wp, r%xh(k))
      end do
      call c%real('FRIC', 0.0_wp, r%fric)
      if (c%ok() .and. (r%fric < 0.0_wp .or. r%fric > 1.0_wp)) call c%fail('FRIC', &
         'must lie in [0, 1], got '//rstr(r%fric))
      call c%zero_real('WVEL', 'welding of nodes to the wall')
      if (c%ok() .and. .not. (norm2(r%xh - r%xt) > 0.0_wp)) call c%fail('XH', 'the head '// &
         '(XH, YH, ZH) equals the tail (XT, YT, ZT): the wall normal is undefined')
      call c%done(error)
      if (allocated(error)) return
      r%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      inp%walls = [inp%walls, r]
   end subroutine read_rigidwall_planar

   !> Fields 3-8 of a prescribed-motion card (*BOUNDARY_PRESCRIBED_MOTION_NODE/_SET/_RIGID),
   !> read from the cursor after DOF: VAD LCID SF VID DEATH BIRTH, with LS-DYNA's defaults
   !> (SF 0 -> 1, DEATH 0 -> 1e28).
   subroutine read_motion_fields(c, vad, lcid, sf, death, birth)
      type(card_t), intent(inout) :: c
      integer, intent(out) :: vad, lcid
      real(wp), intent(out) :: sf, death, birth
      call c%int('VAD', 0, vad)
      if (c%ok() .and. (vad < 0 .or. vad > 2)) call c%fail('VAD', 'VAD '//str(vad)//' is '// &
         'not supported (supported: 0 velocity, 1 acceleration, 2 displacement)')
      call c%id('LCID', lcid)
      call c%real('SF', 1.0_wp, sf)
      if (sf == 0.0_wp) sf = 1.0_wp
      call c%zero_int('VID', '*DEFINE_VECTOR directions')
      call c%real('DEATH', 1.0e28_wp, death)
      if (death == 0.0_wp) death = 1.0e28_wp
      call c%real('BIRTH', 0.0_wp, birth)
      if (c%ok() .and. birth >= death) call c%fail('BIRTH', 'birth time '//rstr(birth)// &
                                                   ' is not before the death time '//rstr(death))
   end subroutine read_motion_fields
end module dx_read_loads
