!> Readers for the rigid-body keywords: *MAT_RIGID (*MAT_020), *PART_INERTIA,
!> *CONSTRAINED_NODAL_RIGID_BODY, *CONSTRAINED_EXTRA_NODES_NODE/_SET,
!> *BOUNDARY_PRESCRIBED_MOTION_RIGID, *DATABASE_RBDOUT, and the body loads *LOAD_BODY_X/_Y/_Z.
!> Layouts, defaults and meanings: LS-DYNA Keyword User's Manual, Vol. I and II. Options dynx
!> cannot honour (local systems, *DEFINE_VECTOR directions, release flags, ...) are errors
!> naming the field. The records go to model_input_t%rigid and %body_loads; build_rigid
!> (dx_rigid_build) resolves them.
module dx_read_rigid
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            card_error, std_widths, data_start, block_title, check_max_cards
   use dx_deck_registry, only: registry_t
   use dx_material, only: material_t, mat_holder_t
   use dx_mat_factory, only: new_material
   use dx_mat_rigid, only: mat_rigid_t
   use dx_model, only: part_t
   use dx_model_input, only: model_input_t, origin, input_add_part
   use dx_rigid_types, only: inertia_in_t, nrb_in_t, extra_in_t, rmotion_in_t, rigid_origin_t
   use dx_load_body, only: body_load_in_t
   use dx_read_loads, only: read_motion_fields
   implicit none
   private
   public :: register_rigid

contains

   !> Add the rigid-body and body-load keywords to the registry.
   subroutine register_rigid(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('MAT_RIGID', read_mat_rigid, title=.true.)
      call reg%add('MAT_020', read_mat_rigid, title=.true.)
      call reg%add('PART_INERTIA', read_part_inertia)
      call reg%add('CONSTRAINED_NODAL_RIGID_BODY', read_nodal_rigid_body, title=.true.)
      call reg%add('CONSTRAINED_EXTRA_NODES_NODE', read_extra_nodes)
      call reg%add('CONSTRAINED_EXTRA_NODES_SET', read_extra_nodes)
      call reg%add('BOUNDARY_PRESCRIBED_MOTION_RIGID', read_motion_rigid, id=.true.)
      call reg%add('DATABASE_RBDOUT', read_rbdout)
      call reg%add('LOAD_BODY_X', read_load_body)
      call reg%add('LOAD_BODY_Y', read_load_body)
      call reg%add('LOAD_BODY_Z', read_load_body)
   end subroutine register_rigid

   function rorigin(blk, ic) result(o)
      type(block_t), intent(in) :: blk
      integer, intent(in) :: ic
      type(rigid_origin_t) :: o
      o%ifile = blk%ifile
      o%line = blk%cards(ic)%line
      o%key = blk%name
   end function rorigin

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

   !> card 1 MID RO E PR N COUPLE M ALIAS; card 2 CMO CON1 CON2; card 3 LCO or A1 A2 A3 V1 V2 V3
   subroutine read_mat_rigid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: m
      type(mat_holder_t), allocatable :: t(:)
      integer :: w(8), i0, n, k
      real(wp) :: r
      character(:), allocatable :: msg, fname
      character(len=3), parameter :: c3(6) = ['A1 ', 'A2 ', 'A3 ', 'V1 ', 'V2 ', 'V3 ']
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (MID RO E PR N COUPLE M ALIAS)', error)
         return
      end if
      call check_max_cards(deck, blk, i0 + 2, error)
      if (allocated(error)) return
      call new_material(20, m, error)
      if (allocated(error)) return
      select type (m)
      type is (mat_rigid_t)
         call get_int(deck, blk, i0, 1, w, 'MID', 0, m%label, error)
         if (allocated(error)) return
         if (m%label <= 0) then
            call field_error(deck, blk, i0, 1, w, 'MID', 'material id must be > 0, got '// &
                             str(m%label), error)
            return
         end if
         m%title = block_title(blk)
         call get_real(deck, blk, i0, 2, w, 'RO', 0.0_wp, m%ro, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 3, w, 'E', 0.0_wp, m%e, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 4, w, 'PR', 0.0_wp, m%pr, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 5, w, 'N', 0.0_wp, m%n, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 6, w, 'COUPLE', 0.0_wp, m%couple, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0, 7, w, 'M', 0.0_wp, m%m, error)
         if (allocated(error)) return
         if (m%n /= 0.0_wp .or. m%m /= 0.0_wp) then
            call field_error(deck, blk, i0, merge(5, 7, m%n /= 0.0_wp), w, &
               merge('N', 'M', m%n /= 0.0_wp), 'MADYMO coupling is not supported', error)
            return
         end if
         call get_real(deck, blk, i0, 8, w, 'ALIAS', 0.0_wp, m%alias, error)
         if (allocated(error)) return
         if (blk%n >= i0 + 1) then
            call get_real(deck, blk, i0 + 1, 1, w, 'CMO', 0.0_wp, m%cmo, error)
            if (allocated(error)) return
            call get_int(deck, blk, i0 + 1, 2, w, 'CON1', 0, m%con1, error)
            if (allocated(error)) return
            call get_int(deck, blk, i0 + 1, 3, w, 'CON2', 0, m%con2, error)
            if (allocated(error)) return
            if (m%cmo == 0.0_wp .and. (m%con1 /= 0 .or. m%con2 /= 0)) then
               call field_error(deck, blk, i0 + 1, 1, w, 'CMO', 'CON1/CON2 are given but '// &
                  'CMO = 0 (no constraints); set CMO = 1 for global constraints', error)
               return
            end if
         end if
         if (blk%n >= i0 + 2) then
            do k = 1, 6
               call get_real(deck, blk, i0 + 2, k, w, trim(c3(k)), 0.0_wp, r, error)
               if (allocated(error)) return
               if (r /= 0.0_wp) then
                  call field_error(deck, blk, i0 + 2, k, w, trim(merge('LCO', c3(k), k == 1)), &
                     'local output systems (LCO, A1..V3) are not supported', error)
                  return
               end if
            end do
         end if
      end select
      call m%setup(error)
      if (allocated(error)) then
         msg = error%message
         fname = ''
         if (allocated(error%field)) then
            fname = error%field
            msg = error%detail
         end if
         select case (fname)
         case ('RO'); call field_error(deck, blk, i0, 2, w, fname, msg, error)
         case ('E'); call field_error(deck, blk, i0, 3, w, fname, msg, error)
         case ('PR'); call field_error(deck, blk, i0, 4, w, fname, msg, error)
         case ('CMO'); call field_error(deck, blk, i0 + 1, 1, w, fname, msg, error)
         case ('CON1'); call field_error(deck, blk, i0 + 1, 2, w, fname, msg, error)
         case ('CON2'); call field_error(deck, blk, i0 + 1, 3, w, fname, msg, error)
         case default
            msg = error%message
            call block_error(deck, blk, i0, msg, error)
         end select
         return
      end if
      n = size(inp%mats)
      allocate(t(n + 1))
      do k = 1, n
         call move_alloc(inp%mats(k)%m, t(k)%m)
      end do
      call move_alloc(m, t(n + 1)%m)
      call move_alloc(t, inp%mats)
      inp%mat_src = [inp%mat_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_mat_rigid

   !> heading; PID SECID MID EOSID HGID GRAV ADPOPT TMID; XC YC ZC TM IRCS NODEID;
   !> IXX IXY IXZ IYY IYZ IZZ; VTX VTY VTZ VRX VRY VRZ (IRCS = 1 local axes: not supported)
   subroutine read_part_inertia(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic, k
      type(part_t) :: p
      type(inertia_in_t) :: q
      character(len=3), parameter :: cn(3) = ['XC ', 'YC ', 'ZC '], &
         inn(6) = ['IXX', 'IXY', 'IXZ', 'IYY', 'IYZ', 'IZZ'], &
         vn(6) = ['VTX', 'VTY', 'VTZ', 'VRX', 'VRY', 'VRZ']
      character(len=6), parameter :: unsup(3) = ['GRAV  ', 'ADPOPT', 'TMID  ']
      w = std_widths(blk, 8)
      if (blk%n < 5) then
         call block_error(deck, blk, 0, 'needs 5 cards: heading; PID SECID MID ...; '// &
            'XC YC ZC TM IRCS NODEID; IXX IXY IXZ IYY IYZ IZZ; VTX VTY VTZ VRX VRY VRZ', error)
         return
      end if
      p%title = trim(adjustl(blk%cards(1)%text(1:min(70, len(blk%cards(1)%text)))))
      ic = 2
      call positive_id(deck, blk, ic, 1, w, 'PID', p%label, error)
      if (allocated(error)) return
      call positive_id(deck, blk, ic, 2, w, 'SECID', p%secid, error)
      if (allocated(error)) return
      call positive_id(deck, blk, ic, 3, w, 'MID', p%mid, error)
      if (allocated(error)) return
      call zero_int(deck, blk, ic, 4, w, 'EOSID', 'equations of state', error)
      if (allocated(error)) return
      call get_int(deck, blk, ic, 5, w, 'HGID', 0, p%hgid, error)
      if (allocated(error)) return
      do k = 6, 8
         call zero_int(deck, blk, ic, k, w, trim(unsup(k - 5)), 'not supported', error)
         if (allocated(error)) return
      end do
      q%pid = p%label
      ic = 3
      do k = 1, 3
         call get_real(deck, blk, ic, k, w, trim(cn(k)), 0.0_wp, q%xc(k), error)
         if (allocated(error)) return
      end do
      call get_real(deck, blk, ic, 4, w, 'TM', 0.0_wp, q%tm, error)
      if (allocated(error)) return
      if (.not. (q%tm > 0.0_wp)) then
         call field_error(deck, blk, ic, 4, w, 'TM', 'translational mass must be > 0, got '// &
                          rstr(q%tm), error)
         return
      end if
      call get_int(deck, blk, ic, 5, w, 'IRCS', 0, q%ircs, error)
      if (allocated(error)) return
      if (q%ircs /= 0) then
         call field_error(deck, blk, ic, 5, w, 'IRCS', 'inertia in a local system (IRCS = 1) '// &
                          'is not supported; give the tensor in the global system', error)
         return
      end if
      call check_max_cards(deck, blk, 5, error)
      if (allocated(error)) return
      call get_int(deck, blk, ic, 6, w, 'NODEID', 0, q%nodeid, error)
      if (allocated(error)) return
      if (q%nodeid < 0) then
         call field_error(deck, blk, ic, 6, w, 'NODEID', 'must be >= 0', error)
         return
      end if
      ic = 4
      do k = 1, 6
         call get_real(deck, blk, ic, k, w, trim(inn(k)), 0.0_wp, q%inertia(k), error)
         if (allocated(error)) return
      end do
      ic = 5
      do k = 1, 3
         call get_real(deck, blk, ic, k, w, trim(vn(k)), 0.0_wp, q%vt(k), error)
         if (allocated(error)) return
         call get_real(deck, blk, ic, k + 3, w, trim(vn(k + 3)), 0.0_wp, q%vr(k), error)
         if (allocated(error)) return
      end do
      q%src = rorigin(blk, 3)
      call input_add_part(inp, p, origin(blk%ifile, blk%cards(2)%line, blk%name))
      inp%rigid%inertias = [inp%rigid%inertias, q]
   end subroutine read_part_inertia

   !> PID CID NSID PNODE IPRT DRFLAG RRFLAG
   subroutine read_nodal_rigid_body(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(nrb_in_t) :: r
      w = std_widths(blk, 8)
      if (blk%n < data_start(blk)) then
         call block_error(deck, blk, 0, 'missing card 1 (PID CID NSID PNODE IPRT DRFLAG '// &
                          'RRFLAG)', error)
         return
      end if
      do ic = data_start(blk), blk%n
         r = nrb_in_t()
         call positive_id(deck, blk, ic, 1, w, 'PID', r%pid, error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 2, w, 'CID', 'local output systems', error)
         if (allocated(error)) return
         call positive_id(deck, blk, ic, 3, w, 'NSID', r%nsid, error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 4, w, 'PNODE', 'a separate inertia node', error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 5, w, 'IPRT', 0, r%iprt, error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 6, w, 'DRFLAG', 'displacement release', error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 7, w, 'RRFLAG', 'rotation release', error)
         if (allocated(error)) return
         r%src = rorigin(blk, ic)
         inp%rigid%nrbs = [inp%rigid%nrbs, r]
      end do
   end subroutine read_nodal_rigid_body

   !> PID NID|NSID (IFLAG must be 0)
   subroutine read_extra_nodes(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(extra_in_t) :: r
      w = std_widths(blk, 8)
      if (blk%n < 1) then
         call block_error(deck, blk, 0, 'missing card 1 (PID NID/NSID IFLAG)', error)
         return
      end if
      do ic = 1, blk%n
         r = extra_in_t()
         r%is_set = blk%base == 'CONSTRAINED_EXTRA_NODES_SET'
         call positive_id(deck, blk, ic, 1, w, 'PID', r%pid, error)
         if (allocated(error)) return
         call positive_id(deck, blk, ic, 2, w, merge('NSID', 'NID ', r%is_set), r%id, error)
         if (allocated(error)) return
         call zero_int(deck, blk, ic, 3, w, 'IFLAG', 'mass property update flag', error)
         if (allocated(error)) return
         r%src = rorigin(blk, ic)
         inp%rigid%extras = [inp%rigid%extras, r]
      end do
   end subroutine read_extra_nodes

   !> PID DOF VAD LCID SF VID DEATH BIRTH
   subroutine read_motion_rigid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8), ic
      type(rmotion_in_t) :: m
      w = std_widths(blk, 8)
      if (blk%n < data_start(blk)) then
         call block_error(deck, blk, 0, 'missing card 1 (PID DOF VAD LCID SF VID DEATH '// &
                          'BIRTH)', error)
         return
      end if
      do ic = data_start(blk), blk%n
         m = rmotion_in_t()
         call positive_id(deck, blk, ic, 1, w, 'PID', m%pid, error)
         if (allocated(error)) return
         call get_int(deck, blk, ic, 2, w, 'DOF', 0, m%dof, error)
         if (allocated(error)) return
         if (.not. any(m%dof == [1, 2, 3, 5, 6, 7])) then
            call field_error(deck, blk, ic, 2, w, 'DOF', 'DOF '//str(m%dof)//' is not '// &
               'supported (supported: 1, 2, 3 translation along x, y, z; 5, 6, 7 rotation '// &
               'about x, y, z)', error)
            return
         end if
         call read_motion_fields(deck, blk, ic, w, m%vad, m%lcid, m%sf, m%death, m%birth, error)
         if (allocated(error)) return
         m%src = rorigin(blk, ic)
         inp%rigid%motions = [inp%rigid%motions, m]
      end do
   end subroutine read_motion_rigid

   !> DT BINARY LCUR IOOPT
   subroutine read_rbdout(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      w = std_widths(blk, 8)
      if (blk%n < 1) then
         call block_error(deck, blk, 0, 'missing card 1 (DT BINARY LCUR IOOPT)', error)
         return
      end if
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      call get_real(deck, blk, 1, 1, w, 'DT', 0.0_wp, inp%rigid%rbdout_dt, error)
      if (allocated(error)) return
      if (.not. (inp%rigid%rbdout_dt > 0.0_wp)) then
         call field_error(deck, blk, 1, 1, w, 'DT', 'output interval must be > 0, got '// &
                          rstr(inp%rigid%rbdout_dt), error)
         return
      end if
      call zero_int(deck, blk, 1, 3, w, 'LCUR', 'output interval curves', error)
   end subroutine read_rbdout

   !> LCID SF LCIDDR XC YC ZC CID
   subroutine read_load_body(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: w(8)
      type(body_load_in_t) :: b
      w = std_widths(blk, 8)
      if (blk%n < 1) then
         call block_error(deck, blk, 0, 'missing card 1 (LCID SF LCIDDR XC YC ZC CID)', error)
         return
      end if
      call check_max_cards(deck, blk, 1, error)
      if (allocated(error)) return
      select case (blk%base)
      case ('LOAD_BODY_X'); b%dir = 1
      case ('LOAD_BODY_Y'); b%dir = 2
      case default; b%dir = 3
      end select
      call positive_id(deck, blk, 1, 1, w, 'LCID', b%lcid, error)
      if (allocated(error)) return
      call get_real(deck, blk, 1, 2, w, 'SF', 1.0_wp, b%sf, error)
      if (allocated(error)) return
      if (b%sf == 0.0_wp) b%sf = 1.0_wp
      call zero_int(deck, blk, 1, 3, w, 'LCIDDR', 'dynx has no dynamic relaxation', error)
      if (allocated(error)) return
      ! XC YC ZC: centre of rotation for angular velocities, used by _RX/_RY/_RZ only
      call zero_int(deck, blk, 1, 7, w, 'CID', 'local coordinate systems', error)
      if (allocated(error)) return
      b%ifile = blk%ifile
      b%line = blk%cards(1)%line
      b%key = blk%name
      inp%body_loads = [inp%body_loads, b]
   end subroutine read_load_body
end module dx_read_rigid
