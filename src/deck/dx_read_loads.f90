!> Readers for boundary conditions, loads, initial conditions and rigid walls:
!> *BOUNDARY_SPC_NODE/_SET, *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET, *INITIAL_VELOCITY,
!> *INITIAL_VELOCITY_NODE, *INITIAL_VELOCITY_GENERATION, *LOAD_NODE_POINT, *LOAD_SEGMENT,
!> *LOAD_SEGMENT_SET, *RIGIDWALL_PLANAR. Layouts and defaults: LS-DYNA Keyword User's
!> Manual, Vol. I. Options dynx cannot honour (local coordinate systems, boxes, rotational
!> velocities on solids, follower forces, ...) give an error naming the field.
module dx_read_loads
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            card_error, std_widths, data_start, check_max_cards
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, origin, spc_in_t, motion_in_t, ivel_in_t, &
                             load_node_in_t, load_seg_in_t, wall_in_t, IVEL_SET, IVEL_NODE, &
                             IVEL_GEN
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
   end subroutine register_loads

   !> integer field that must be blank or 0
   subroutine zero_int(deck, blk, ic, k, w, fname, why, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, why
      type(error_t), allocatable, intent(out) :: error
      integer :: v
      call get_int(deck, blk, ic, k, w, fname, 0, v, error)
      if (allocated(error)) return
      if (v /= 0) call field_error(deck, blk, ic, k, w, fname, 'nonzero value '//str(v)// &
                                   ' is not supported: '//why, error)
   end subroutine zero_int

   !> real field that must be blank or 0
   subroutine zero_real(deck, blk, ic, k, w, fname, why, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname, why
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v
      call get_real(deck, blk, ic, k, w, fname, 0.0_wp, v, error)
      if (allocated(error)) return
      if (v /= 0.0_wp) call field_error(deck, blk, ic, k, w, fname, 'nonzero value '// &
                                        rstr(v)//' is not supported: '//why, error)
   end subroutine zero_real

   !> a positive id (> 0) in field k
   subroutine positive_id(deck, blk, ic, k, w, fname, v, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k, w(:)
      character(*), intent(in) :: fname
      integer, intent(out) :: v
      type(error_t), allocatable, intent(out) :: error
      call get_int(deck, blk, ic, k, w, fname, 0, v, error)
      if (allocated(error)) return
      if (v <= 0) call field_error(deck, blk, ic, k, w, fname, 'an id > 0 is required, got '// &
                                   str(v), error)
   end subroutine positive_id

   subroutine need_data(deck, blk, i0, what, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: i0
      character(*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (blk%n < i0) call block_error(deck, blk, 0, 'missing card '//str(i0)//' ('//what// &
                                       ')', error)
   end subroutine need_data

   !> NID|NSID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ
   subroutine read_spc(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k, d
      type(spc_in_t) :: s
      character(len=5), parameter :: dn(6) = ['DOFX ', 'DOFY ', 'DOFZ ', 'DOFRX', 'DOFRY', &
                                              'DOFRZ']
      w = std_widths(blk, 8)
      call need_data(deck, blk, data_start(blk), 'NID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ', &
                     error)
      if (allocated(error)) return
      do ic = data_start(blk), blk%n
         s = spc_in_t()
         s%is_set = blk%base == 'BOUNDARY_SPC_SET'
         call positive_id(deck, blk, ic, 1, w, merge('NSID', 'NID ', s%is_set), s%id, error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 2, w, 'CID', 'local coordinate systems', error)
         if (allocated(error)) return
         do k = 1, 6
            call get_int(deck, blk, ic, k + 2, w, trim(dn(k)), 0, d, error)
            if (allocated(error)) return
            if (d /= 0 .and. d /= 1) then
               call field_error(deck, blk, ic, k + 2, w, trim(dn(k)), 'must be 0 (free) or '// &
                                '1 (constrained), got '//str(d), error)
               return
            end if
            s%dof(k) = d == 1
         end do
         s%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         inp%spcs = [inp%spcs, s]
      end do
   end subroutine read_spc

   !> NID|NSID DOF VAD LCID SF VID DEATH BIRTH
   subroutine read_motion(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(motion_in_t) :: m
      w = std_widths(blk, 8)
      call need_data(deck, blk, data_start(blk), 'NID DOF VAD LCID SF VID DEATH BIRTH', error)
      if (allocated(error)) return
      do ic = data_start(blk), blk%n
         m = motion_in_t()
         m%is_set = blk%base == 'BOUNDARY_PRESCRIBED_MOTION_SET'
         call positive_id(deck, blk, ic, 1, w, merge('NSID', 'NID ', m%is_set), m%id, error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 2, w, 'DOF', 0, m%dof, error)
         if (allocated(error)) return
         if (m%dof < 1 .or. m%dof > 7 .or. m%dof == 4) then
            call field_error(deck, blk, ic, 2, w, 'DOF', 'DOF '//str(m%dof)//' is not '// &
               'supported (supported: 1 x, 2 y, 3 z translation; 5, 6, 7 rotation about '// &
               'x, y, z on shell nodes)', error)
            return
         end if
         call read_motion_fields(deck, blk, ic, w, m%vad, m%lcid, m%sf, m%death, m%birth, error)
         if (allocated(error)) return
         if (m%dof >= 5 .and. m%vad == 2) then
            call field_error(deck, blk, ic, 3, w, 'VAD', 'VAD 2 (a prescribed rotation '// &
               'angle) on DOF '//str(m%dof)//' is not supported (supported on rotations: 0 '// &
               'angular velocity, 1 angular acceleration)', error)
            return
         end if
         m%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         inp%motions = [inp%motions, m]
      end do
   end subroutine read_motion

   !> translational velocity fields k0..k0+2 of card ic, rotational fields k0+3..k0+5 zero
   subroutine velocity(deck, blk, ic, k0, w, names, v, error, vr)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, k0, w(:)
      character(*), intent(in) :: names(6)
      real(wp), intent(out) :: v(3)
      type(error_t), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: vr(3)   !< the rotational fields (shell nodes)
      integer :: k
      do k = 1, 3
         call get_real(deck, blk, ic, k0 + k - 1, w, trim(names(k)), 0.0_wp, v(k), error)
         if (allocated(error)) return
      end do
      if (present(vr)) then
         do k = 1, 3
            call get_real(deck, blk, ic, k0 + k + 2, w, trim(names(k + 3)), 0.0_wp, vr(k), &
                          error)
            if (allocated(error)) return
         end do
         return
      end if
      do k = 4, 6
         call zero_real(deck, blk, ic, k0 + k - 1, w, trim(names(k)), 'solid elements '// &
                        'have no rotational degrees of freedom', error)
         if (allocated(error)) return
      end do
   end subroutine velocity

   !> card 1 NSID NSIDEX BOXID IRIGID ICID; card 2 VX VY VZ VXR VYR VZR;
   !> card 3 (NSIDEX > 0) VXE VYE VZE VXRE VYRE VZRE
   subroutine read_initial_velocity(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(ivel_in_t) :: r
      w = std_widths(blk, 8)
      call need_data(deck, blk, 1, 'NSID NSIDEX BOXID IRIGID ICID', error)
      if (allocated(error)) return
      ic = 1
      do while (ic <= blk%n)
         r = ivel_in_t()
         r%kind = IVEL_SET
         call get_int(deck, blk, ic, 1, w, 'NSID', 0, r%id, error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 2, w, 'NSIDEX', 0, r%nsidex, error)
         if (allocated(error)) return
         if (r%id < 0 .or. r%nsidex < 0) then
            call card_error(deck, blk, ic, 'NSID and NSIDEX must be >= 0', error)
            return
         end if
         call zero_int(deck, blk, ic, 3, w, 'BOXID', 'boxes', error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 4, w, 'IRIGID', 'rigid bodies', error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 5, w, 'ICID', 'local coordinate systems', error)
         if (allocated(error)) return
         r%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         if (ic + 1 > blk%n) then
            call card_error(deck, blk, ic, 'missing card 2 (VX VY VZ VXR VYR VZR)', error)
            return
         end if
         call velocity(deck, blk, ic + 1, 1, w, ['VX ', 'VY ', 'VZ ', 'VXR', 'VYR', 'VZR'], &
                       r%v, error)
         if (allocated(error)) return
         ic = ic + 2
         if (r%nsidex > 0) then
            call velocity(deck, blk, ic, 1, w, ['VXE ', 'VYE ', 'VZE ', 'VXRE', 'VYRE', 'VZRE'], &
                          r%vex, error)
            if (allocated(error)) return
            ic = ic + 1
         end if
         inp%ivels = [inp%ivels, r]
      end do
   end subroutine read_initial_velocity

   !> NID VX VY VZ VXR VYR VZR ICID
   subroutine read_initial_velocity_node(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(ivel_in_t) :: r
      w = std_widths(blk, 8)
      do ic = 1, blk%n
         r = ivel_in_t()
         r%kind = IVEL_NODE
         call positive_id(deck, blk, ic, 1, w, 'NID', r%id, error)
         if (allocated(error)) return
         call velocity(deck, blk, ic, 2, w, ['VX ', 'VY ', 'VZ ', 'VXR', 'VYR', 'VZR'], r%v, &
                       error, r%vr)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 8, w, 'ICID', 'local coordinate systems', error)
         if (allocated(error)) return
         r%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         inp%ivels = [inp%ivels, r]
      end do
   end subroutine read_initial_velocity_node

   !> card 1 ID STYP OMEGA VX VY VZ IVATN ICID; card 2 XC YC ZC NX NY NZ PHASE IRIGID
   subroutine read_initial_velocity_generation(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k
      real(wp) :: nrm
      type(ivel_in_t) :: r
      character(len=2), parameter :: cn(3) = ['XC', 'YC', 'ZC'], an(3) = ['NX', 'NY', 'NZ'], &
                                     vn(3) = ['VX', 'VY', 'VZ']
      w = std_widths(blk, 8)
      call need_data(deck, blk, 1, 'ID STYP OMEGA VX VY VZ IVATN ICID', error)
      if (allocated(error)) return
      ic = 1
      do while (ic <= blk%n)
         r = ivel_in_t()
         r%kind = IVEL_GEN
         call get_int(deck, blk, ic, 1, w, 'ID', 0, r%id, error)
         if (allocated(error)) return
         if (r%id < 0) then
            call field_error(deck, blk, ic, 1, w, 'ID', 'must be >= 0', error)
            return
         end if
         call get_int(deck, blk, ic, 2, w, 'STYP', 0, r%styp, error)
         if (allocated(error)) return
         if (r%id > 0 .and. (r%styp < 1 .or. r%styp > 3)) then
            call field_error(deck, blk, ic, 2, w, 'STYP', 'must be 1 (part set), 2 (part) '// &
                             'or 3 (node set), got '//str(r%styp), error)
            return
         end if
         call get_real(deck, blk, ic, 3, w, 'OMEGA', 0.0_wp, r%omega, error)
         if (allocated(error)) return
         do k = 1, 3
            call get_real(deck, blk, ic, 3 + k, w, vn(k), 0.0_wp, r%v(k), error)
            if (allocated(error)) return
         end do
         call zero_int(deck, blk, ic, 7, w, 'IVATN', 'rigid body slave parts', error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 8, w, 'ICID', 'local coordinate systems', error)
         if (allocated(error)) return
         r%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         if (ic + 1 > blk%n) then
            ! the last record's card 2 left blank (stripped as layout: a blank line before
            ! the next keyword) is a card of defaults in LS-DYNA; without a rotation
            ! (OMEGA = 0) none of its fields matters
            if (r%omega == 0.0_wp) then
               inp%ivels = [inp%ivels, r]
               exit
            end if
            call card_error(deck, blk, ic, 'missing card 2 (XC YC ZC NX NY NZ PHASE IRIGID)', &
                            error)
            return
         end if
         ic = ic + 1
         do k = 1, 3
            call get_real(deck, blk, ic, k, w, cn(k), 0.0_wp, r%xc(k), error)
            if (allocated(error)) return
            call get_real(deck, blk, ic, 3 + k, w, an(k), 0.0_wp, r%axis(k), error)
            if (allocated(error)) return
         end do
         call zero_int(deck, blk, ic, 7, w, 'PHASE', 'dynx has no dynamic relaxation', error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 8, w, 'IRIGID', 'rigid bodies', error)
         if (allocated(error)) return
         nrm = norm2(r%axis)
         if (r%omega /= 0.0_wp) then
            if (.not. (nrm > 0.0_wp)) then
               call field_error(deck, blk, ic, 4, w, 'NX', 'OMEGA is nonzero but the '// &
                                'rotation axis (NX, NY, NZ) is zero', error)
               return
            end if
            r%axis = r%axis/nrm
         end if
         inp%ivels = [inp%ivels, r]
         ic = ic + 1
      end do
   end subroutine read_initial_velocity_generation

   !> NID DOF LCID SF CID M1 M2 M3
   subroutine read_load_node(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k
      logical :: is_set
      type(load_node_in_t) :: l
      w = std_widths(blk, 8)
      is_set = blk%base == 'LOAD_NODE_SET'
      do ic = data_start(blk), blk%n
         l = load_node_in_t()
         call positive_id(deck, blk, ic, 1, w, merge('NSID', 'NID ', is_set), l%nid, error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 2, w, 'DOF', 0, l%dof, error)
         if (allocated(error)) return
         if (l%dof < 1 .or. l%dof > 3) then
            call field_error(deck, blk, ic, 2, w, 'DOF', 'DOF '//str(l%dof)//' is not '// &
               'supported (supported: 1, 2, 3 force along x, y, z)', error)
            return
         end if
         call positive_id(deck, blk, ic, 3, w, 'LCID', l%lcid, error)
         if (allocated(error)) return
         call get_real(deck, blk, ic, 4, w, 'SF', 1.0_wp, l%sf, error)
         if (allocated(error)) return
         if (l%sf == 0.0_wp) l%sf = 1.0_wp
         call zero_int(deck, blk, ic, 5, w, 'CID', 'local coordinate systems', error)
         if (allocated(error)) return
         do k = 1, 3
            call zero_int(deck, blk, ic, 5 + k, w, 'M'//str(k), 'follower forces', error)
            if (allocated(error)) return
         end do
         l%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         if (is_set) then
            inp%node_set_loads = [inp%node_set_loads, l]   ! nid holds NSID: loads_finish
         else
            inp%node_loads = [inp%node_loads, l]
         end if
      end do
   end subroutine read_load_node

   !> After the whole deck (sets resolved): each *LOAD_NODE_SET card becomes the same load
   !> on every node of its set, in the set's order (LS-DYNA: each node carries SF x curve).
   subroutine loads_finish(inp, error)
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j, k
      type(load_node_in_t) :: l
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
            inp%node_loads = [inp%node_loads, l]
         end do
      end do
      deallocate(inp%node_set_loads)
      allocate(inp%node_set_loads(0))
   end subroutine loads_finish

   !> *LOAD_SEGMENT: LCID SF AT N1 N2 N3 N4 (N5 must be blank: no higher-order segments);
   !> *LOAD_SEGMENT_SET: SSID LCID SF AT
   subroutine read_load_segment(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k, k0
      logical :: is_set
      type(load_seg_in_t) :: l
      w = std_widths(blk, 8)
      is_set = blk%base == 'LOAD_SEGMENT_SET'
      call need_data(deck, blk, data_start(blk), merge('SSID LCID SF AT        ', &
                     'LCID SF AT N1 N2 N3 N4 ', is_set), error)
      if (allocated(error)) return
      do ic = data_start(blk), blk%n
         l = load_seg_in_t()
         k0 = 0
         if (is_set) then
            call positive_id(deck, blk, ic, 1, w, 'SSID', l%ssid, error)
            if (allocated(error)) return
            k0 = 1
         end if
         call positive_id(deck, blk, ic, k0 + 1, w, 'LCID', l%lcid, error)
         if (allocated(error)) return
         call get_real(deck, blk, ic, k0 + 2, w, 'SF', 1.0_wp, l%sf, error)
         if (allocated(error)) return
         if (l%sf == 0.0_wp) l%sf = 1.0_wp
         call get_real(deck, blk, ic, k0 + 3, w, 'AT', 0.0_wp, l%at, error)
         if (allocated(error)) return
         if (is_set) then
            call zero_real(deck, blk, ic, 5, w, 'DT', 'a death time', error)
            if (allocated(error)) return
         else
            do k = 1, 4
               call get_int(deck, blk, ic, 3 + k, w, 'N'//str(k), 0, l%n(k), error)
               if (allocated(error)) return
               if (k <= 3 .and. l%n(k) <= 0) then
                  call field_error(deck, blk, ic, 3 + k, w, 'N'//str(k), 'node id must '// &
                                   'be > 0', error)
                  return
               end if
            end do
            if (l%n(4) == 0) l%n(4) = l%n(3)
            call zero_int(deck, blk, ic, 8, w, 'N5', 'higher-order segments', error)
            if (allocated(error)) return
         end if
         l%src = origin(blk%ifile, blk%cards(ic)%line, blk%name)
         inp%seg_loads = [inp%seg_loads, l]
      end do
   end subroutine read_load_segment

   !> card 1 NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF; card 2 XT YT ZT XH YH ZH FRIC WVEL
   subroutine read_rigidwall_planar(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), i0, k
      real(wp) :: death, rwksf
      type(wall_in_t) :: r
      character(len=2), parameter :: tn(3) = ['XT', 'YT', 'ZT'], hn(3) = ['XH', 'YH', 'ZH']
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      if (blk%opt_id) then
         call get_int(deck, blk, 1, 1, w, 'RWID', 0, r%label, error)
         if (allocated(error)) return
      end if
      if (r%label == 0) r%label = size(inp%walls) + 1
      call need_data(deck, blk, i0, 'NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF', error)
      if (allocated(error)) return
      if (blk%n < i0 + 1) then
         call card_error(deck, blk, i0, 'missing card 2 (XT YT ZT XH YH ZH FRIC WVEL)', error)
         return
      end if
      call check_max_cards(deck, blk, i0 + 1, error)
      if (allocated(error)) return
      call get_int(deck, blk, i0, 1, w, 'NSID', 0, r%nsid, error)
      if (allocated(error)) return
      call get_int(deck, blk, i0, 2, w, 'NSIDEX', 0, r%nsidex, error)
      if (allocated(error)) return
      call zero_int(deck, blk, i0, 3, w, 'BOXID', 'boxes', error)
      if (allocated(error)) return
      call get_real(deck, blk, i0, 4, w, 'OFFSET', 0.0_wp, r%offset, error)
      if (allocated(error)) return
      if (r%offset < 0.0_wp) then
         call field_error(deck, blk, i0, 4, w, 'OFFSET', 'must be >= 0', error)
         return
      end if
      call zero_real(deck, blk, i0, 5, w, 'BIRTH', 'wall birth times', error)
      if (allocated(error)) return
      call get_real(deck, blk, i0, 6, w, 'DEATH', 1.0e20_wp, death, error)
      if (allocated(error)) return
      if (death /= 0.0_wp .and. death < 1.0e20_wp) then
         call field_error(deck, blk, i0, 6, w, 'DEATH', 'wall death times are not supported', &
                          error)
         return
      end if
      call get_real(deck, blk, i0, 7, w, 'RWKSF', 1.0_wp, rwksf, error)
      if (allocated(error)) return
      if (rwksf /= 0.0_wp .and. rwksf /= 1.0_wp) then
         call field_error(deck, blk, i0, 7, w, 'RWKSF', 'penalty stiffness scaling is not '// &
                          'supported (the wall is a kinematic constraint)', error)
         return
      end if
      do k = 1, 3
         call get_real(deck, blk, i0 + 1, k, w, tn(k), 0.0_wp, r%xt(k), error)
         if (allocated(error)) return
         call get_real(deck, blk, i0 + 1, 3 + k, w, hn(k), 0.0_wp, r%xh(k), error)
         if (allocated(error)) return
      end do
      call get_real(deck, blk, i0 + 1, 7, w, 'FRIC', 0.0_wp, r%fric, error)
      if (allocated(error)) return
      if (r%fric < 0.0_wp .or. r%fric > 1.0_wp) then
         call field_error(deck, blk, i0 + 1, 7, w, 'FRIC', 'must lie in [0, 1], got '// &
                          rstr(r%fric), error)
         return
      end if
      call zero_real(deck, blk, i0 + 1, 8, w, 'WVEL', 'welding of nodes to the wall', error)
      if (allocated(error)) return
      if (.not. (norm2(r%xh - r%xt) > 0.0_wp)) then
         call field_error(deck, blk, i0 + 1, 4, w, 'XH', 'the head (XH, YH, ZH) equals the '// &
                          'tail (XT, YT, ZT): the wall normal is undefined', error)
         return
      end if
      r%src = origin(blk%ifile, blk%cards(i0)%line, blk%name)
      inp%walls = [inp%walls, r]
   end subroutine read_rigidwall_planar

   !> Fields 3-8 of a prescribed-motion card (*BOUNDARY_PRESCRIBED_MOTION_NODE/_SET/_RIGID):
   !> VAD LCID SF VID DEATH BIRTH, with LS-DYNA's defaults (SF 0 -> 1, DEATH 0 -> 1e28).
   subroutine read_motion_fields(deck, blk, ic, w, vad, lcid, sf, death, birth, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic, w(8)
      integer, intent(out) :: vad, lcid
      real(wp), intent(out) :: sf, death, birth
      type(error_t), allocatable, intent(out) :: error
      call get_int(deck, blk, ic, 3, w, 'VAD', 0, vad, error)
      if (allocated(error)) return
      if (vad < 0 .or. vad > 2) then
         call field_error(deck, blk, ic, 3, w, 'VAD', 'VAD '//str(vad)//' is not '// &
            'supported (supported: 0 velocity, 1 acceleration, 2 displacement)', error)
         return
      end if
      call positive_id(deck, blk, ic, 4, w, 'LCID', lcid, error)
      if (allocated(error)) return
      call get_real(deck, blk, ic, 5, w, 'SF', 1.0_wp, sf, error)
      if (allocated(error)) return
      if (sf == 0.0_wp) sf = 1.0_wp
      call zero_int(deck, blk, ic, 6, w, 'VID', '*DEFINE_VECTOR directions', error)
      if (allocated(error)) return
      call get_real(deck, blk, ic, 7, w, 'DEATH', 1.0e28_wp, death, error)
      if (allocated(error)) return
      if (death == 0.0_wp) death = 1.0e28_wp
      call get_real(deck, blk, ic, 8, w, 'BIRTH', 0.0_wp, birth, error)
      if (allocated(error)) return
      if (birth >= death) then
         call field_error(deck, blk, ic, 8, w, 'BIRTH', 'birth time '//rstr(birth)// &
                          ' is not before the death time '//rstr(death), error)
         return
      end if
   end subroutine read_motion_fields
end module dx_read_loads
