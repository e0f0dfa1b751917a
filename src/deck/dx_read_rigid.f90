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
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, data_start, block_title
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

   !> card 1 MID RO E PR N COUPLE M ALIAS; card 2 CMO CON1 CON2; card 3 LCO or A1 A2 A3 V1 V2 V3
   subroutine read_mat_rigid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: m
      type(mat_holder_t), allocatable :: t(:)
      type(error_t), allocatable :: err
      type(card_t) :: c
      integer :: i0, n, k
      real(wp) :: r
      character(len=3), parameter :: c3(6) = ['A1 ', 'A2 ', 'A3 ', 'V1 ', 'V2 ', 'V3 ']
      i0 = data_start(blk)
      call deck_cursor(deck, blk, c)
      call c%need(i0, 'missing card 1 (MID RO E PR N COUPLE M ALIAS)')
      call c%max_cards(i0 + 2)
      call c%done(error)
      if (allocated(error)) return
      call new_material(20, m, error)
      if (allocated(error)) return
      select type (m)
      type is (mat_rigid_t)
         call c%id('MID', m%label, 'material id must be > 0')
         m%title = block_title(blk)
         call c%real('RO', 0.0_wp, m%ro)
         call c%real('E', 0.0_wp, m%e)
         call c%real('PR', 0.0_wp, m%pr)
         call c%real('N', 0.0_wp, m%n)
         call c%real('COUPLE', 0.0_wp, m%couple)
         call c%real('M', 0.0_wp, m%m)
         if (c%ok() .and. (m%n /= 0.0_wp .or. m%m /= 0.0_wp)) &
            call c%fail(merge('N', 'M', m%n /= 0.0_wp), 'MADYMO coupling is not supported')
         call c%real('ALIAS', 0.0_wp, m%alias)
         if (blk%n >= i0 + 1) then
            call c%next()
            call c%real('CMO', 0.0_wp, m%cmo)
            call c%int('CON1', 0, m%con1)
            call c%int('CON2', 0, m%con2)
            if (c%ok() .and. m%cmo == 0.0_wp .and. (m%con1 /= 0 .or. m%con2 /= 0)) &
               call c%fail('CMO', 'CON1/CON2 are given but CMO = 0 (no constraints); set '// &
                           'CMO = 1 for global constraints')
         end if
         if (blk%n >= i0 + 2) then
            call c%seek(i0 + 2)
            do k = 1, 6
               call c%real(trim(merge('LCO', c3(k), k == 1)), 0.0_wp, r)
               if (c%ok() .and. r /= 0.0_wp) call c%fail(trim(merge('LCO', c3(k), k == 1)), &
                  'local output systems (LCO, A1..V3) are not supported')
            end do
         end if
      end select
      if (c%ok()) then
         call m%setup(err)
         if (allocated(err)) then
            if (allocated(err%field)) then
               call c%fail(err%field, err%detail)
            else
               call c%fail_block(i0, err%message)
            end if
         end if
      end if
      call c%done(error)
      if (allocated(error)) return
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
      integer :: k
      type(part_t) :: p
      type(inertia_in_t) :: q
      type(card_t) :: c
      character(len=3), parameter :: cn(3) = ['XC ', 'YC ', 'ZC '], &
         inn(6) = ['IXX', 'IXY', 'IXZ', 'IYY', 'IYZ', 'IZZ'], &
         vn(6) = ['VTX', 'VTY', 'VTZ', 'VRX', 'VRY', 'VRZ']
      character(len=6), parameter :: unsup(3) = ['GRAV  ', 'ADPOPT', 'TMID  ']
      call deck_cursor(deck, blk, c)
      call c%need(5, 'needs 5 cards: heading; PID SECID MID ...; XC YC ZC TM IRCS NODEID; '// &
                  'IXX IXY IXZ IYY IYZ IZZ; VTX VTY VTZ VRX VRY VRZ')
      call c%done(error)
      if (allocated(error)) return
      p%title = trim(adjustl(blk%cards(1)%text(1:min(70, len(blk%cards(1)%text)))))
      call c%seek(2)
      call c%id('PID', p%label)
      call c%id('SECID', p%secid)
      call c%id('MID', p%mid)
      call c%zero_int('EOSID', 'equations of state')
      call c%int('HGID', 0, p%hgid)
      do k = 1, 3
         call c%zero_int(trim(unsup(k)), 'not supported')
      end do
      q%pid = p%label
      call c%seek(3)
      do k = 1, 3
         call c%real(trim(cn(k)), 0.0_wp, q%xc(k))
      end do
      call c%real('TM', 0.0_wp, q%tm)
      if (c%ok() .and. .not. (q%tm > 0.0_wp)) call c%fail('TM', 'translational mass must '// &
                                                          'be > 0, got '//rstr(q%tm))
      call c%int('IRCS', 0, q%ircs)
      if (c%ok() .and. q%ircs /= 0) call c%fail('IRCS', 'inertia in a local system '// &
         '(IRCS = 1) is not supported; give the tensor in the global system')
      call c%max_cards(5)
      call c%int('NODEID', 0, q%nodeid, min=0)
      call c%seek(4)
      do k = 1, 6
         call c%real(trim(inn(k)), 0.0_wp, q%inertia(k))
      end do
      call c%seek(5)
      do k = 1, 3
         call c%real(trim(vn(k)), 0.0_wp, q%vt(k))
      end do
      do k = 1, 3
         call c%real(trim(vn(k + 3)), 0.0_wp, q%vr(k))
      end do
      call c%done(error)
      if (allocated(error)) return
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
      integer :: ic
      type(nrb_in_t) :: r
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (PID CID NSID PNODE IPRT DRFLAG RRFLAG)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         r = nrb_in_t()
         call c%seek(ic)
         call c%id('PID', r%pid)
         call c%zero_int('CID', 'local output systems')
         call c%id('NSID', r%nsid)
         call c%zero_int('PNODE', 'a separate inertia node')
         call c%int('IPRT', 0, r%iprt)
         call c%zero_int('DRFLAG', 'displacement release')
         call c%zero_int('RRFLAG', 'rotation release')
         if (c%halt()) exit
         r%src = rorigin(blk, ic)
         inp%rigid%nrbs = [inp%rigid%nrbs, r]
      end do
      call c%done(error)
   end subroutine read_nodal_rigid_body

   !> PID NID|NSID (IFLAG must be 0)
   subroutine read_extra_nodes(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(extra_in_t) :: r
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (PID NID/NSID IFLAG)')
      do ic = 1, blk%n
         if (c%halt()) exit
         r = extra_in_t()
         r%is_set = blk%base == 'CONSTRAINED_EXTRA_NODES_SET'
         call c%seek(ic)
         call c%id('PID', r%pid)
         call c%id(trim(merge('NSID', 'NID ', r%is_set)), r%id)
         call c%zero_int('IFLAG', 'mass property update flag')
         if (c%halt()) exit
         r%src = rorigin(blk, ic)
         inp%rigid%extras = [inp%rigid%extras, r]
      end do
      call c%done(error)
   end subroutine read_extra_nodes

   !> PID DOF VAD LCID SF VID DEATH BIRTH
   subroutine read_motion_rigid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      integer :: ic
      type(rmotion_in_t) :: m
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(data_start(blk), 'missing card 1 (PID DOF VAD LCID SF VID DEATH BIRTH)')
      do ic = data_start(blk), blk%n
         if (c%halt()) exit
         m = rmotion_in_t()
         call c%seek(ic)
         call c%id('PID', m%pid)
         call c%int('DOF', 0, m%dof)
         if (c%ok() .and. .not. any(m%dof == [1, 2, 3, 5, 6, 7])) call c%fail('DOF', 'DOF '// &
            str(m%dof)//' is not supported (supported: 1, 2, 3 translation along x, y, z; '// &
            '5, 6, 7 rotation about x, y, z)')
         call read_motion_fields(c, m%vad, m%lcid, m%sf, m%death, m%birth)
         if (c%halt()) exit
         m%src = rorigin(blk, ic)
         inp%rigid%motions = [inp%rigid%motions, m]
      end do
      call c%done(error)
   end subroutine read_motion_rigid

   !> DT BINARY LCUR IOOPT
   subroutine read_rbdout(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (DT BINARY LCUR IOOPT)')
      call c%max_cards(1)
      call c%real('DT', 0.0_wp, inp%rigid%rbdout_dt)
      if (c%ok() .and. .not. (inp%rigid%rbdout_dt > 0.0_wp)) call c%fail('DT', 'output '// &
         'interval must be > 0, got '//rstr(inp%rigid%rbdout_dt))
      call c%skip(1)                 ! BINARY: which files LS-DYNA writes
      call c%zero_int('LCUR', 'output interval curves')
      call c%done(error)
   end subroutine read_rbdout

   !> LCID SF LCIDDR XC YC ZC CID
   subroutine read_load_body(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(body_load_in_t) :: b
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%need(1, 'missing card 1 (LCID SF LCIDDR XC YC ZC CID)')
      call c%max_cards(1)
      select case (blk%base)
      case ('LOAD_BODY_X'); b%dir = 1
      case ('LOAD_BODY_Y'); b%dir = 2
      case default; b%dir = 3
      end select
      call c%id('LCID', b%lcid)
      call c%real('SF', 1.0_wp, b%sf)
      if (b%sf == 0.0_wp) b%sf = 1.0_wp
      call c%zero_int('LCIDDR', 'dynx has no dynamic relaxation')
      ! XC YC ZC: centre of rotation for angular velocities, used by _RX/_RY/_RZ only
      call c%skip(3)
      call c%zero_int('CID', 'local coordinate systems')
      call c%done(error)
      if (allocated(error)) return
      b%ifile = blk%ifile
      b%line = blk%cards(1)%line
      b%key = blk%name
      inp%body_loads = [inp%body_loads, b]
   end subroutine read_load_body
end module dx_read_rigid
