!> Build of the rigid bodies and body loads: resolves the rigid-body keywords (labels) into
!> model%rigid (dense) and *LOAD_BODY_* into model%body_loads. Runs at the end of build_model,
!> when parts, blocks, sets, constraints, initial velocities and walls are known.
!> Mass properties of a *MAT_RIGID part: exact volume integrals over its elements (the
!> element-family table's elem_moments) plus, as point masses, the lumped mass deformable
!> elements and extra nodes bring to its nodes; a *CONSTRAINED_NODAL_RIGID_BODY takes the
!> lumped nodal masses (rho V0 times the family's share per node). *PART_INERTIA replaces
!> mass, centre and inertia tensor.
!> Initial motion: the rigid motion (vc, omega) closest to the nodal initial velocities in the
!> mass-weighted least-squares sense (exact when the nodal field is rigid, as
!> *INITIAL_VELOCITY_GENERATION gives), or VTX..VRZ of *PART_INERTIA.
module dx_rigid_build
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_log, only: log_warn
   use dx_label_map, only: label_map_t
   use dx_model, only: model_t, family_t, element_family, elem_moments, elem_length
   use dx_model_input, only: model_input_t
   use dx_mat_rigid, only: mat_rigid_t, rigid_code
   use dx_rigid_types, only: rigid_system_t, rigid_body_t, rigid_motion_t, rigid_origin_t
   use dx_rigid_mass, only: inertia_about, principal_axes
   use dx_load_body, only: body_load_t
   implicit none
   private
   public :: build_rigid, build_body_loads, lumped_masses

contains

   function at(inp, src) result(s)
      type(model_input_t), intent(in) :: inp
      type(rigid_origin_t), intent(in) :: src
      character(:), allocatable :: s
      s = inp%files(src%ifile)%s//':'//str(src%line)//': *'//src%key//': '
   end function at

   !> *LOAD_BODY_X/Y/Z: curve labels to indices (model%body_loads stays unallocated if none).
   subroutine build_body_loads(inp, model, curve_map, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(label_map_t), intent(in) :: curve_map
      type(error_t), allocatable, intent(out) :: error
      integer :: k, c
      if (size(inp%body_loads) == 0) return
      allocate(model%body_loads(size(inp%body_loads)))
      do k = 1, size(inp%body_loads)
         associate (b => inp%body_loads(k))
            c = curve_map%get(b%lcid)
            if (c == 0) then
               call set_error(error, inp%files(b%ifile)%s//':'//str(b%line)//': *'//b%key// &
                  ': field LCID: curve '//str(b%lcid)//' is not defined (*DEFINE_CURVE)')
               return
            end if
            model%body_loads(k) = body_load_t(dir=b%dir, curve=c, sf=b%sf)
         end associate
      end do
   end subroutine build_body_loads

   !> Lumped nodal masses rho V0 times the family's share (as the solver's init_state), and
   !> the part of them that comes from rigid elements.
   subroutine lumped_masses(model, mass, mrig)
      type(model_t), intent(in) :: model
      real(wp), allocatable, intent(out) :: mass(:), mrig(:)
      integer :: b, i, k, nd
      real(wp) :: m
      logical :: rig
      type(family_t) :: fam
      allocate(mass(model%nn), mrig(model%nn))
      mass = 0.0_wp
      mrig = 0.0_wp
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            m = model%mats(model%parts(blk%ipart)%imat)%m%ro
            rig = model%mats(model%parts(blk%ipart)%imat)%m%is_rigid
            fam = element_family(blk%etype)   ! rho V0 times the family's share per node
            do i = 1, blk%nel
               do k = 1, fam%nen
                  nd = blk%conn(k, i)
                  mass(nd) = mass(nd) + m*blk%vol0(i)*fam%mass_share
                  if (rig) mrig(nd) = mrig(nd) + m*blk%vol0(i)*fam%mass_share
               end do
            end do
         end associate
      end do
   end subroutine lumped_masses

   !> Build model%rigid from inp%rigid and the *MAT_RIGID parts (nothing when there are none).
   subroutine build_rigid(inp, model, node_map, part_map, nset_map, curve_map, deck0, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(label_map_t), intent(in) :: node_map, part_map, nset_map, curve_map
      character(*), intent(in) :: deck0
      type(error_t), allocatable, intent(out) :: error
      type(rigid_system_t), allocatable :: rs
      real(wp), allocatable :: mass(:), mrig(:), bm(:), bm1(:, :), bm2(:, :, :), xref(:, :)
      integer, allocatable :: body_of_part(:), nodes(:), inert(:)
      logical, allocatable :: inbody(:)
      type(family_t) :: fam
      integer :: nb, ip, b, k, i, e, nd, j, nrb
      real(wp) :: vol, m1(3), m2(3, 3), rho
      character(:), allocatable :: w

      ! PART_INERTIA must name a rigid part (checked before anything else)
      allocate(inert(size(model%parts)))
      inert = 0
      do k = 1, size(inp%rigid%inertias)
         associate (q => inp%rigid%inertias(k))
            ip = part_map%get(q%pid)
            if (.not. model%mats(model%parts(ip)%imat)%m%is_rigid) then
               call set_error(error, at(inp, q%src)//'part '//str(q%pid)//': *PART_INERTIA '// &
                  'needs a rigid material (*MAT_RIGID); material '//str(model%parts(ip)%mid)// &
                  ' is deformable')
               return
            end if
            inert(ip) = k
         end associate
      end do
      allocate(body_of_part(size(model%parts)))
      body_of_part = 0
      nb = 0
      do ip = 1, size(model%parts)
         if (model%mats(model%parts(ip)%imat)%m%is_rigid) then
            nb = nb + 1
            body_of_part(ip) = nb
         end if
      end do
      nrb = size(inp%rigid%nrbs)
      if (nb + nrb == 0) then
         if (size(inp%rigid%extras) > 0) then
            call set_error(error, at(inp, inp%rigid%extras(1)%src)//'field PID: part '// &
               str(inp%rigid%extras(1)%pid)//' is not a rigid part (*MAT_RIGID)')
         else if (size(inp%rigid%motions) > 0) then
            call set_error(error, at(inp, inp%rigid%motions(1)%src)//'field PID: part '// &
               str(inp%rigid%motions(1)%pid)//' is not a rigid body (*MAT_RIGID or '// &
               '*CONSTRAINED_NODAL_RIGID_BODY)')
         end if
         return
      end if
      allocate(rs)
      allocate(rs%bodies(nb + nrb), rs%node_body(model%nn))
      rs%node_body = 0
      call lumped_masses(model, mass, mrig)
      allocate(bm(nb + nrb), bm1(3, nb + nrb), bm2(3, 3, nb + nrb), xref(3, nb + nrb), &
               inbody(model%nn))
      bm = 0.0_wp; bm1 = 0.0_wp; bm2 = 0.0_wp
      ! ---- rigid parts: nodes and exact element integrals
      do ip = 1, size(model%parts)
         b = body_of_part(ip)
         if (b == 0) cycle
         associate (bd => rs%bodies(b))
            bd%label = model%parts(ip)%label
            bd%ipart = ip
            select type (mt => model%mats(model%parts(ip)%imat)%m)
            type is (mat_rigid_t)
               if (mt%cmo == 1.0_wp) then
                  bd%fix_t = rigid_code(mt%con1)
                  bd%fix_r = rigid_code(mt%con2)
               end if
            end select
            inbody = .false.
            do k = 1, size(model%blocks)
               if (model%blocks(k)%ipart /= ip) cycle
               do e = 1, model%blocks(k)%nel
                  inbody(model%blocks(k)%conn(:, e)) = .true.
               end do
            end do
            bd%nodes = pack([(i, i = 1, model%nn)], inbody)
            xref(:, b) = 0.0_wp
            if (size(bd%nodes) > 0) &
               xref(:, b) = sum(model%x0(:, bd%nodes), dim=2)/real(size(bd%nodes), wp)
            rho = model%mats(model%parts(ip)%imat)%m%ro
            do k = 1, size(model%blocks)
               if (model%blocks(k)%ipart /= ip) cycle
               fam = element_family(model%blocks(k)%etype)
               do e = 1, model%blocks(k)%nel
                  if (fam%rot) then     ! a rigid shell: its thickness from vol0
                     call shell_moments(model%x0(:, model%blocks(k)%conn(:, e)), &
                                        model%blocks(k)%vol0(e), xref(:, b), vol, m1, m2)
                  else
                     call elem_moments(model%blocks(k)%etype, &
                                       model%x0(:, model%blocks(k)%conn(:, e)), xref(:, b), &
                                       vol, m1, m2)
                  end if
                  bm(b) = bm(b) + rho*vol
                  bm1(:, b) = bm1(:, b) + rho*m1
                  bm2(:, :, b) = bm2(:, :, b) + rho*m2
               end do
            end do
         end associate
      end do
      ! ---- nodal rigid bodies
      do k = 1, nrb
         associate (r => inp%rigid%nrbs(k), bd => rs%bodies(nb + k))
            w = at(inp, r%src)
            if (part_map%get(r%pid) /= 0) then
               call set_error(error, w//'field PID: '//str(r%pid)//' is already a *PART id; '// &
                  'a nodal rigid body needs its own id')
               return
            end if
            do j = 1, k - 1
               if (inp%rigid%nrbs(j)%pid == r%pid) then
                  call set_error(error, w//'field PID: nodal rigid body '//str(r%pid)// &
                     ' is defined twice')
                  return
               end if
            end do
            j = nset_map%get(r%nsid)
            if (j == 0) then
               call set_error(error, w//'field NSID: node set '//str(r%nsid)//' is not '// &
                  'defined (*SET_NODE_LIST)')
               return
            end if
            if (size(model%node_sets(j)%nodes) == 0) then
               call set_error(error, w//'field NSID: node set '//str(r%nsid)//' is empty')
               return
            end if
            bd%label = r%pid
            bd%nodal = .true.
            inbody = .false.
            inbody(model%node_sets(j)%nodes) = .true.
            bd%nodes = pack([(i, i = 1, model%nn)], inbody)
            xref(:, nb + k) = sum(model%x0(:, bd%nodes), dim=2)/real(size(bd%nodes), wp)
         end associate
      end do
      ! ---- extra nodes
      do k = 1, size(inp%rigid%extras)
         associate (r => inp%rigid%extras(k))
            w = at(inp, r%src)
            b = find_body(rs, r%pid, w, error)
            if (allocated(error)) return
            if (r%is_set) then
               j = nset_map%get(r%id)
               if (j == 0) then
                  call set_error(error, w//'field NSID: node set '//str(r%id)//' is not '// &
                     'defined (*SET_NODE_LIST)')
                  return
               end if
               nodes = model%node_sets(j)%nodes
            else
               nodes = [node_map%get(r%id)]
               if (nodes(1) == 0) then
                  call set_error(error, w//'field NID: node '//str(r%id)//' is not defined '// &
                     '(*NODE)')
                  return
               end if
            end if
            inbody = .false.
            inbody(rs%bodies(b)%nodes) = .true.
            inbody(nodes) = .true.
            rs%bodies(b)%nodes = pack([(i, i = 1, model%nn)], inbody)
         end associate
      end do
      ! ---- every body has nodes, every node is in one body only
      do b = 1, size(rs%bodies)
         if (size(rs%bodies(b)%nodes) == 0) then
            call set_error(error, body_where(inp, rs, b, nrb, nb)//'rigid part '// &
               str(rs%bodies(b)%label)//' has no elements and no extra nodes')
            return
         end if
         do i = 1, size(rs%bodies(b)%nodes)
            nd = rs%bodies(b)%nodes(i)
            if (rs%node_body(nd) /= 0) then
               call set_error(error, body_where(inp, rs, b, nrb, nb)//'node '// &
                  str(model%node_label(nd))//' belongs to two rigid bodies (part '// &
                  str(rs%bodies(rs%node_body(nd))%label)//' and part '// &
                  str(rs%bodies(b)%label)//'); merge them into one')
               return
            end if
            rs%node_body(nd) = b
         end do
      end do
      ! ---- point masses (deformable elements, extra nodes, nodal bodies) and properties
      do b = 1, size(rs%bodies)
         associate (bd => rs%bodies(b))
            do i = 1, size(bd%nodes)
               nd = bd%nodes(i)
               m1 = model%x0(:, nd) - xref(:, b)
               vol = mass(nd)
               if (.not. bd%nodal) vol = mass(nd) - mrig(nd)
               if (vol <= 0.0_wp) cycle
               bm(b) = bm(b) + vol
               bm1(:, b) = bm1(:, b) + vol*m1
               do j = 1, 3
                  bm2(:, j, b) = bm2(:, j, b) + vol*m1*m1(j)
               end do
            end do
            if (.not. (bm(b) > 0.0_wp)) then
               call set_error(error, body_where(inp, rs, b, nrb, nb)//'rigid body '// &
                  str(bd%label)//' has no mass (its nodes belong to no element)')
               return
            end if
            call finish_body(inp, model, rs, b, inert, bm(b), bm1(:, b), bm2(:, :, b), &
                             xref(:, b), node_map, nrb, nb, mass, error)
            if (allocated(error)) return
         end associate
      end do
      ! ---- prescribed rigid motions
      do k = 1, size(inp%rigid%motions)
         associate (r => inp%rigid%motions(k))
            w = at(inp, r%src)
            b = find_body(rs, r%pid, w, error)
            if (allocated(error)) return
            j = curve_map%get(r%lcid)
            if (j == 0) then
               call set_error(error, w//'field LCID: curve '//str(r%lcid)//' is not defined '// &
                  '(*DEFINE_CURVE)')
               return
            end if
            if (.not. allocated(rs%bodies(b)%motions)) allocate(rs%bodies(b)%motions(0))
            rs%bodies(b)%motions = [rs%bodies(b)%motions, rigid_motion_t(dof=r%dof, &
               vad=r%vad, curve=j, sf=r%sf, birth=r%birth, death=r%death)]
         end associate
      end do
      ! ---- nodal constraints on rigid nodes are errors; walls skip rigid nodes
      if (allocated(model%spcs)) then
         do k = 1, size(model%spcs)
            nd = model%spcs(k)%node
            ! (DOFRX/RY/RZ count on a shell's node: it turns with its body)
            if (rs%node_body(nd) /= 0 .and. (any(model%spcs(k)%dof(1:3)) .or. &
                (any(model%spcs(k)%dof(4:6)) .and. shell_node(nd)))) then
               call set_error(error, constraint_where(inp, model, nset_map, nd, .true.)// &
                  'node '//str(model%node_label(nd))//' of rigid body '// &
                  str(rs%bodies(rs%node_body(nd))%label)//' has a nodal constraint '// &
                  '(*BOUNDARY_SPC_* or *NODE TC); constrain rigid bodies with CMO/CON1/CON2 '// &
                  'of *MAT_RIGID or *BOUNDARY_PRESCRIBED_MOTION_RIGID')
               return
            end if
         end do
      end if
      if (allocated(model%prescribed)) then
         do k = 1, size(model%prescribed)
            nd = model%prescribed(k)%node
            if (rs%node_body(nd) /= 0 .and. model%prescribed(k)%curve == 0) then  ! skew SPC
               call set_error(error, constraint_where(inp, model, nset_map, nd, .true.)// &
                  'node '//str(model%node_label(nd))//' of rigid body '// &
                  str(rs%bodies(rs%node_body(nd))%label)//' has a nodal constraint '// &
                  '(*BOUNDARY_SPC_* with CID); constrain rigid bodies with CMO/CON1/CON2 '// &
                  'of *MAT_RIGID or *BOUNDARY_PRESCRIBED_MOTION_RIGID')
               return
            else if (rs%node_body(nd) /= 0) then
               call set_error(error, constraint_where(inp, model, nset_map, nd, .false.)// &
                  'node '//str(model%node_label(nd))//' of rigid body '// &
                  str(rs%bodies(rs%node_body(nd))%label)//' has a nodal prescribed motion; '// &
                  'use *BOUNDARY_PRESCRIBED_MOTION_RIGID')
               return
            end if
         end do
      end if
      if (allocated(model%walls)) then
         do k = 1, size(model%walls)
            associate (wl => model%walls(k))
               i = count(rs%node_body(wl%nodes) /= 0)
               if (i > 0) then
                  call log_warn(deck0//': *RIGIDWALL_PLANAR '//str(wl%label)//': '//str(i)// &
                     ' nodes of rigid bodies are not checked against the wall')
                  wl%nodes = pack(wl%nodes, rs%node_body(wl%nodes) == 0)
               end if
            end associate
         end do
      end if
      ! ---- energy and momentum corrections at t = 0, critical step of the rigid elements
      rs%mass_corr = 0.0_wp
      rs%ke0_corr = 0.0_wp
      do b = 1, size(rs%bodies)
         associate (bd => rs%bodies(b))
            rs%mass_corr = rs%mass_corr + bd%mass - sum(mass(bd%nodes))
            rs%ke0_corr = rs%ke0_corr + 0.5_wp*bd%mass*dot_product(bd%vc, bd%vc) + &
                          0.5_wp*dot_product(bd%omega, bd%lsp)
            do i = 1, size(bd%nodes)
               nd = bd%nodes(i)
               rs%ke0_corr = rs%ke0_corr - 0.5_wp*mass(nd)*dot_product(model%v0(:, nd), &
                                                                       model%v0(:, nd))
            end do
         end associate
      end do
      rs%dtcrit = rigid_element_step(model)
      rs%rbdout_dt = inp%rigid%rbdout_dt
      call move_alloc(rs, model%rigid)
   contains
      !> Whether node nd is a node of a shell element (it carries rotations).
      logical function shell_node(nd)
         integer, intent(in) :: nd
         type(family_t) :: fm
         integer :: kb
         shell_node = .false.
         do kb = 1, size(model%blocks)
            fm = element_family(model%blocks(kb)%etype)
            if (.not. fm%rot) cycle
            if (any(model%blocks(kb)%conn == nd)) then
               shell_node = .true.
               return
            end if
         end do
      end function shell_node
   end subroutine build_rigid

   !> The body of part label; none is an input error at w (field PID).
   integer function find_body(rs, label, w, error) result(b)
      type(rigid_system_t), intent(in) :: rs
      integer, intent(in) :: label
      character(*), intent(in) :: w
      type(error_t), allocatable, intent(inout) :: error
      do b = 1, size(rs%bodies)
         if (rs%bodies(b)%label == label) return
      end do
      b = 0
      call set_error(error, w//'field PID: part '//str(label)//' is not a rigid '// &
                     'body (*MAT_RIGID part or *CONSTRAINED_NODAL_RIGID_BODY)')
   end function find_body

   !> "file:line: *KEY: " of the card that made body b
   function body_where(inp, rs, b, nrb, nb) result(s)
      type(model_input_t), intent(in) :: inp
      type(rigid_system_t), intent(in) :: rs
      integer, intent(in) :: b, nrb, nb
      character(:), allocatable :: s
      integer :: ip
      if (b > nb .and. b - nb <= nrb) then
         s = at(inp, inp%rigid%nrbs(b - nb)%src)
      else
         ip = rs%bodies(b)%ipart
         s = inp%files(inp%part_src(ip)%ifile)%s//':'//str(inp%part_src(ip)%line)//': *'// &
             inp%part_src(ip)%key//': '
      end if
   end function body_where

   !> "file:line: *KEY: " of the first SPC (spc) or nodal prescribed motion card on node nd
   function constraint_where(inp, model, nset_map, nd, spc) result(s)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(label_map_t), intent(in) :: nset_map
      integer, intent(in) :: nd
      logical, intent(in) :: spc
      character(:), allocatable :: s
      integer :: k, n
      logical :: is_set, hit
      integer :: id
      n = size(inp%motions)
      if (spc) n = size(inp%spcs)
      do k = 1, n
         if (spc) then
            is_set = inp%spcs(k)%is_set; id = inp%spcs(k)%id
         else
            is_set = inp%motions(k)%is_set; id = inp%motions(k)%id
         end if
         if (is_set) then
            hit = nset_map%get(id) > 0
            if (hit) hit = any(model%node_sets(nset_map%get(id))%nodes == nd)
         else
            hit = id == model%node_label(nd)
         end if
         if (hit) then
            if (spc) then
               s = inp%files(inp%spcs(k)%src%ifile)%s//':'//str(inp%spcs(k)%src%line)// &
                   ': *'//inp%spcs(k)%src%key//': '
            else
               s = inp%files(inp%motions(k)%src%ifile)%s//':'// &
                   str(inp%motions(k)%src%line)//': *'//inp%motions(k)%src%key//': '
            end if
            return
         end if
      end do
      ! *NODE TC
      s = inp%files(inp%node_src(1, nd))%s//':'//str(inp%node_src(2, nd))//': *NODE: '
   end function constraint_where

   !> centre, inertia, principal frame, body coordinates and initial motion of body b
   subroutine finish_body(inp, model, rs, b, inert, m, m1, m2, xref, node_map, nrb, nb, &
                          mass, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(rigid_system_t), intent(inout) :: rs
      integer, intent(in) :: b, inert(:), nrb, nb
      real(wp), intent(in) :: m, m1(3), m2(3, 3), xref(3), mass(:)
      type(label_map_t), intent(in) :: node_map
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: ten(3, 3), q(3, 3), ip(3), a(6, 6), rhs(6), u(6), r(3), wgt, sk(3, 3)
      integer :: k, i, nd, j
      logical :: ok
      associate (bd => rs%bodies(b))
         bd%mass = m
         bd%xc = xref + m1/m
         ten = inertia_about(m, m1, m2, xref, bd%xc)
         k = 0
         if (bd%ipart > 0) k = inert(bd%ipart)
         if (k > 0) then
            associate (qi => inp%rigid%inertias(k))
               bd%mass = qi%tm
               bd%xc = qi%xc
               if (qi%nodeid > 0) then
                  nd = node_map%get(qi%nodeid)
                  if (nd == 0) then
                     call set_error(error, at(inp, qi%src)//'field NODEID: node '// &
                        str(qi%nodeid)//' is not defined (*NODE)')
                     return
                  end if
                  bd%xc = model%x0(:, nd)
               end if
               ten(1, :) = [qi%inertia(1), qi%inertia(2), qi%inertia(3)]
               ten(2, :) = [qi%inertia(2), qi%inertia(4), qi%inertia(5)]
               ten(3, :) = [qi%inertia(3), qi%inertia(5), qi%inertia(6)]
            end associate
         end if
         call principal_axes(ten, ip, q)
         if (.not. (ip(1) > 1.0e-12_wp*ip(3)) .or. .not. (ip(3) > 0.0_wp)) then
            call set_error(error, body_where(inp, rs, b, nrb, nb)//'rigid body '// &
               str(bd%label)//': the inertia tensor is singular (principal moments '// &
               rstr(ip(1))//', '//rstr(ip(2))//', '//rstr(ip(3))//'): are its nodes collinear?')
            return
         end if
         bd%ip = ip
         bd%rot = q
         bd%rot_n = q
         bd%x0 = bd%xc
         bd%xc_n = bd%xc
         allocate(bd%s(3, size(bd%nodes)))
         do i = 1, size(bd%nodes)
            bd%s(:, i) = matmul(transpose(q), model%x0(:, bd%nodes(i)) - bd%xc)
         end do
         ! initial motion
         if (k > 0) then
            bd%vc = inp%rigid%inertias(k)%vt
            bd%omega = inp%rigid%inertias(k)%vr
         else
            a = 0.0_wp
            rhs = 0.0_wp
            do i = 1, size(bd%nodes)
               nd = bd%nodes(i)
               wgt = mass(nd)
               if (.not. (wgt > 0.0_wp)) wgt = 1.0e-6_wp*m/size(bd%nodes)
               r = model%x0(:, nd) - bd%xc
               ! v = vc + omega x r = vc - [r]x omega; rows [I, -[r]x]
               sk = reshape([0.0_wp, r(3), -r(2), -r(3), 0.0_wp, r(1), r(2), -r(1), 0.0_wp], &
                            [3, 3])
               do j = 1, 3
                  a(j, j) = a(j, j) + wgt
               end do
               a(1:3, 4:6) = a(1:3, 4:6) - wgt*sk
               a(4:6, 1:3) = a(4:6, 1:3) - wgt*transpose(sk)
               a(4:6, 4:6) = a(4:6, 4:6) + wgt*matmul(transpose(sk), sk)
               rhs(1:3) = rhs(1:3) + wgt*model%v0(:, nd)
               rhs(4:6) = rhs(4:6) - wgt*matmul(transpose(sk), model%v0(:, nd))
            end do
            call solve6(a, rhs, u, ok)
            if (.not. ok) u = 0.0_wp
            bd%vc = u(1:3)
            bd%omega = u(4:6)
         end if
         bd%lsp = matmul(ten, bd%omega)
         do i = 1, size(bd%nodes)
            nd = bd%nodes(i)
            model%v0(:, nd) = bd%vc + cross(bd%omega, model%x0(:, nd) - bd%xc)
         end do
      end associate
   end subroutine finish_body

   !> Gaussian elimination with partial pivoting for the 6x6 system a u = rhs.
   !> Moments of a shell (*MAT_RIGID on a *SECTION_SHELL part) with corners xe(3, 4) (a
   !> triangle repeats N3) and volume v0 = A t: the mid-surface's bilinear map integrated by
   !> 2x2 Gauss points (exact for a flat quadrilateral: the area element is linear there),
   !> the thickness t = v0/A spread along the normal: vol = A t, m1 = t int (x - xref) dA,
   !> m2 = t int (x - xref)(x - xref)^T dA + t^3/12 int n n^T dA.
   pure subroutine shell_moments(xe, v0, xref, vol, m1, m2)
      real(wp), intent(in) :: xe(3, 4), v0, xref(3)
      real(wp), intent(out) :: vol, m1(3), m2(3, 3)
      real(wp), parameter :: g = 0.577350269189625764509_wp
      real(wp), parameter :: xq(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
      real(wp), parameter :: eq(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]
      real(wp) :: da(4), r(3, 4), nn(3, 4), t1(3), t2(3), c(3), sh, a, t
      integer :: ia, ib, k, q, j
      q = 0
      do ib = -1, 1, 2
         do ia = -1, 1, 2
            q = q + 1
            t1 = 0.0_wp; t2 = 0.0_wp; r(:, q) = 0.0_wp
            do k = 1, 4
               sh = 0.25_wp*(1.0_wp + xq(k)*ia*g)*(1.0_wp + eq(k)*ib*g)
               r(:, q) = r(:, q) + sh*xe(:, k)
               t1 = t1 + 0.25_wp*xq(k)*(1.0_wp + eq(k)*ib*g)*xe(:, k)
               t2 = t2 + 0.25_wp*eq(k)*(1.0_wp + xq(k)*ia*g)*xe(:, k)
            end do
            c = cross(t1, t2)
            da(q) = norm2(c)
            nn(:, q) = 0.0_wp
            if (da(q) > 0.0_wp) nn(:, q) = c/da(q)
            r(:, q) = r(:, q) - xref
         end do
      end do
      a = sum(da)
      vol = 0.0_wp; m1 = 0.0_wp; m2 = 0.0_wp
      if (.not. (a > 0.0_wp)) return
      t = v0/a
      vol = v0
      do q = 1, 4
         m1 = m1 + t*da(q)*r(:, q)
         do j = 1, 3
            m2(:, j) = m2(:, j) + t*da(q)*r(:, q)*r(j, q) + &
                       t**3/12.0_wp*da(q)*nn(:, q)*nn(j, q)
         end do
      end do
   end subroutine shell_moments

   pure subroutine solve6(a, rhs, u, ok)
      real(wp), intent(in) :: a(6, 6), rhs(6)
      real(wp), intent(out) :: u(6)
      logical, intent(out) :: ok
      real(wp) :: m(6, 7), t(7), f, big
      integer :: i, k, p
      m(:, 1:6) = a
      m(:, 7) = rhs
      big = maxval(abs(a))
      ok = big > 0.0_wp
      u = 0.0_wp
      if (.not. ok) return
      do k = 1, 6
         p = k - 1 + maxloc(abs(m(k:6, k)), 1)
         if (abs(m(p, k)) <= 1.0e-14_wp*big) then
            ok = .false.; return
         end if
         if (p /= k) then
            t = m(k, :); m(k, :) = m(p, :); m(p, :) = t
         end if
         do i = k + 1, 6
            f = m(i, k)/m(k, k)
            m(i, k:7) = m(i, k:7) - f*m(k, k:7)
         end do
      end do
      do k = 6, 1, -1
         u(k) = (m(k, 7) - dot_product(m(k, k + 1:6), u(k + 1:6)))/m(k, k)
      end do
   end subroutine solve6

   !> Smallest stable step of the rigid elements, L/c with L the family's length (the
   !> element-family table's elem_length) and c = sqrt((K + 4G/3)/rho) from E and PR (used
   !> only when no deformable element sets dt).
   function rigid_element_step(model) result(dt)
      type(model_t), intent(in) :: model
      real(wp) :: dt
      integer :: b, e
      real(wp) :: c
      dt = huge(1.0_wp)
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b), &
                    mt => model%mats(model%parts(model%blocks(b)%ipart)%imat)%m)
            if (.not. mt%is_rigid) cycle
            c = sqrt((mt%bulk + 4.0_wp*mt%shear/3.0_wp)/mt%ro)
            do e = 1, blk%nel
               dt = min(dt, elem_length(blk%etype, model%x0(:, blk%conn(:, e)), blk%vol0(e))/c)
            end do
         end associate
      end do
   end function rigid_element_step
end module dx_rigid_build
