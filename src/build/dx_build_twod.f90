!> Model build of the 2D solids (*SECTION_SHELL ELFORM 13, 14, 15; dx_quad2d): whether a
!> part is 2D, the rule that a deck's parts are all 2D of one kind or all 3D, and the checks
!> and initial volume of one 2D element (nodes in the x-y plane, r = x >= 0 in axisymmetry,
!> counter-clockwise). Split from dx_model_build (which calls it) to keep that module short.
!> *BOUNDARY_NON_REFLECTING_2D: the free edges of the 2D elements whose two nodes are in the
!> node set, each a viscous boundary sigma_n = -rho c_d v_n, tau = -rho c_s v_t (Lysmer &
!> Kuhlemeyer 1969, Finite dynamic model for infinite media, J. Eng. Mech. Div. ASCE 95:
!> 859-877), lumped per node with the edge load's weights (dx_loads: L/2 per unit thickness,
!> L (2 r1 + r2)/6 and L (r1 + 2 r2)/6 per radian in axisymmetry) and the normal and tangent
!> of the edge at t = 0 (small motion of the boundary): C_I = sum w_I rho (c_d n n + c_s t t),
!> rho, c_d = sqrt((K + 4G/3)/rho), c_s = sqrt(G/rho) of the element's material at t = 0.
module dx_build_twod
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_model, only: model_t, family_t, element_family, elem_volume
   use dx_model_input, only: model_input_t, origin_t
   use dx_element_types, only: etype_of_shell_elform, quad2d_area, ETYPE_QUAD2D_PSS, ES_THK
   use dx_build_common, only: at, at_line, maps_t, set_nodes
   use dx_sort, only: sort_index
   use dx_log, only: log_warn, log_info
   use dx_contact2d_types, only: c2d_iface_t
   implicit none
   private
   public :: part_dim, check_dimension, twod_element, build_twod_extras

contains

   !> 0: part ip is 3D; 1: a 2D planar part (ELFORM 12, 13); 2: a 2D axisymmetric part (14, 15)
   integer function part_dim(model, ip)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ip
      type(family_t) :: f
      part_dim = 0
      associate (sec => model%sections(model%parts(ip)%isec))
         if (.not. sec%shell) return
         f = element_family(etype_of_shell_elform(sec%elform))
      end associate
      if (f%twod) part_dim = merge(2, 1, f%axisym)
   end function part_dim

   !> A deck is 2D when all its parts are 2D, all plane strain or all axisymmetric (x is r in
   !> one, a coordinate in the other): any mixture is an input error at the later *PART.
   subroutine check_dimension(inp, model, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(*), parameter :: kind(0:2) = [character(40) :: &
         '3D', '2D planar (ELFORM 12/13)', '2D axisymmetric (ELFORM 14/15)']
      integer :: i, d0
      if (size(model%parts) == 0) return
      d0 = part_dim(model, 1)
      do i = 2, size(model%parts)
         if (part_dim(model, i) == d0) cycle
         call set_error(error, at(inp, inp%part_src(i))//'part '// &
            str(model%parts(i)%label)//': field SECID: section '// &
            str(model%parts(i)%secid)//' makes the part '// &
            trim(kind(part_dim(model, i)))//', but part '//str(model%parts(1)%label)// &
            ' (section '//str(model%parts(1)%secid)//') is '//trim(kind(d0))// &
            ': a deck is 2D only when all its parts are, of one kind')
         return
      end do
   end subroutine check_dimension

   !> one 2D element e (*SECTION_SHELL ELFORM 13-15): its nodes in the x-y plane (z = 0),
   !> r = x >= 0 when axisymmetric, counter-clockwise with an area > 0; V0 the area or the
   !> volume per radian (elem_volume)
   subroutine twod_element(inp, model, conn, e, etype, lab, w, axi, vol, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      integer, intent(in) :: conn(4), e, etype, lab
      real(wp), intent(out) :: vol
      character(*), intent(in) :: w
      logical, intent(in) :: axi
      type(error_t), allocatable, intent(out) :: error
      integer :: kk, nd
      real(wp) :: a
      do kk = 1, 4
         nd = conn(kk)
         if (model%x0(3, nd) /= 0.0_wp) then
            call set_error(error, at_line(inp, inp%node_src(:, nd), 'NODE')//'node '// &
               str(model%node_label(nd))//': field Z: '//rstr(model%x0(3, nd))// &
               ': a node of a 2D element (element '//str(lab)//', *SECTION_SHELL ELFORM '// &
               str(model%sections(model%parts(model%elem_part(e))%isec)%elform)// &
               ') must lie in the x-y plane (z = 0)')
            return
         end if
         if (axi .and. model%x0(1, nd) < 0.0_wp) then
            call set_error(error, at_line(inp, inp%node_src(:, nd), 'NODE')//'node '// &
               str(model%node_label(nd))//': field X: r = x = '//rstr(model%x0(1, nd))// &
               ' < 0: an axisymmetric deck (element '//str(lab)//', *SECTION_SHELL '// &
               'ELFORM 14/15) has x = r >= 0 and y along the axis')
            return
         end if
      end do
      a = quad2d_area(model%x0(:, conn))
      vol = elem_volume(etype, model%x0(:, conn))
      if (.not. (a > 0.0_wp .and. vol > 0.0_wp)) then
         call set_error(error, w//'element '//str(lab)//' is inverted or has no area at '// &
            't = 0 (area '//rstr(a)//' <= 0: the nodes N1..N4 of a 2D element go '// &
            'counter-clockwise in the x-y plane)')
         return
      end if
   end subroutine twod_element

   !> The 2D boundaries, loads and contacts (after the sets and loads): *BOUNDARY_NON_
   !> REFLECTING_2D, *DYNX_PRESSURE_TABLE/_PULSE, *DYNX_ENERGY_DEPOSITION, *CONTACT_2D_..
   subroutine build_twod_extras(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      call build_nonreflecting(inp, model, mp, error)
      if (allocated(error)) return
      call build_edge_pressures(inp, model, mp, error)
      if (allocated(error)) return
      call build_deposits(inp, model, mp, error)
      if (allocated(error)) return
      call build_contact2d(inp, model, mp, error)
   end subroutine build_twod_extras

   !> *BOUNDARY_NON_REFLECTING_2D cards -> model%nr_node, model%nr_c (see the module header).
   !> An edge is free when no other element has it; a card whose set holds no free edge, a
   !> 3D or plane-stress deck, or a material without elastic moduli is an input error.
   subroutine build_nonreflecting(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ed(:, :)
      real(wp), allocatable :: c(:, :)
      logical, allocatable :: used(:)
      real(wp) :: rho, cd, cs, d(2), el, nv(2), tv(2), w(2), ten(3)
      integer :: i, m, ne, j0, j, a1, a2
      type(family_t) :: fam
      if (size(inp%nr2d) == 0) return
      fam = element_family(model%blocks(1)%etype)
      if (.not. fam%twod .or. model%blocks(1)%etype == ETYPE_QUAD2D_PSS) then
         call set_error(error, at(inp, inp%nr2d(1)%src)//'field NSID: a 2D transmitting '// &
            'boundary needs a plane-strain or axisymmetric deck (*SECTION_SHELL ELFORM 13, '// &
            '14, 15); this deck is '//trim(merge('2D plane stress (ELFORM 12)', &
            '3D                         ', fam%twod)))
         return
      end if
      if (inp%ctrl%imp%imflag /= 0) then
         call set_error(error, at(inp, inp%nr2d(1)%src)//'field NSID: the transmitting '// &
            'boundary acts in the explicit cycle only; this deck runs implicit '// &
            '(*CONTROL_IMPLICIT_GENERAL IMFLAG = '//str(inp%ctrl%imp%imflag)//')')
         return
      end if
      allocate(c(3, model%nn), used(model%nn))
      c = 0.0_wp
      used = .false.
      do i = 1, size(inp%nr2d)
         associate (r => inp%nr2d(i))
            call free_edges(inp, model, mp, r%nsid, r%src, ed, error)
            if (allocated(error)) return
            ne = size(ed, 2)
            do j = 1, ne            ! element order: the sums do not depend on the sort
               a1 = ed(1, j); a2 = ed(2, j)
               associate (m0 => model%mats(model%parts(model%blocks(ed(3, j))%ipart)%imat)%m)
                  rho = m0%ro
                  if (.not. (rho > 0.0_wp .and. m0%bulk > 0.0_wp)) then
                     call set_error(error, at(inp, r%src)//'field NSID: the edge of nodes '// &
                        str(model%node_label(a1))//', '//str(model%node_label(a2))// &
                        ' is on material '//str(m0%label)//', which has no elastic bulk '// &
                        'modulus and density for the dashpots rho c_d, rho c_s')
                     return
                  end if
                  cd = sqrt((m0%bulk + 4.0_wp*m0%shear/3.0_wp)/rho)
                  cs = sqrt(max(m0%shear, 0.0_wp)/rho)
               end associate
               d = model%x0(1:2, a2) - model%x0(1:2, a1)
               el = norm2(d)
               tv = d/el
               nv = [tv(2), -tv(1)]
               w = 0.5_wp*el
               if (fam%axisym) w = el*[2.0_wp*model%x0(1, a1) + model%x0(1, a2), &
                                        model%x0(1, a1) + 2.0_wp*model%x0(1, a2)]/6.0_wp
               ten = 0.0_wp
               if (r%ad) ten = ten + rho*cd*[nv(1)**2, nv(2)**2, nv(1)*nv(2)]
               if (r%as) ten = ten + rho*cs*[tv(1)**2, tv(2)**2, tv(1)*tv(2)]
               c(:, a1) = c(:, a1) + w(1)*ten
               c(:, a2) = c(:, a2) + w(2)*ten
               used(a1) = .true.; used(a2) = .true.
            end do
         end associate
      end do
      m = count(used)
      model%nr_node = pack([(j0, j0 = 1, model%nn)], used)
      model%nr_c = c(:, model%nr_node)
      if (m == 0) deallocate(model%nr_node, model%nr_c)
   end subroutine build_nonreflecting

   !> The free edges (sides no other element has) of the 2D elements whose two nodes are in
   !> node set nsid: ed(:, k) = (node a, node b, block, element), a -> b counter-clockwise in
   !> the element (the outward normal is (dy, -dx)), in block and element order. None: an
   !> error naming the card (src) and field NSID.
   subroutine free_edges(inp, model, mp, nsid, src, ed, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: nsid
      type(origin_t), intent(in) :: src
      integer, allocatable, intent(out) :: ed(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: nodes(:)
      logical, allocatable :: inset(:)
      integer :: j
      call set_nodes(inp, model, mp, nsid, .false., src, 'NSID', nodes, error)
      if (allocated(error)) return
      allocate(inset(model%nn))
      inset = .false.
      inset(nodes) = .true.
      call mesh_free_edges(model, ed)
      ed = ed(:, pack([(j, j = 1, size(ed, 2))], inset(ed(1, :)) .and. inset(ed(2, :))))
      if (size(ed, 2) == 0) call set_error(error, at(inp, src)//'field NSID: node set '// &
         str(nsid)//' holds no free edge of a 2D element (both nodes of an element side '// &
         'on the boundary of the mesh)')
   end subroutine free_edges

   !> Every free edge of the mesh (a side no other element has), as free_edges
   subroutine mesh_free_edges(model, ed)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: ed(:, :)
      integer, allocatable :: idx(:)
      real(wp), allocatable :: key(:)
      logical, allocatable :: free(:)
      integer :: b, e, k, j, ne, a1, a2
      ne = 0
      do b = 1, size(model%blocks)
         ne = ne + 4*model%blocks(b)%nel
      end do
      allocate(ed(4, ne), key(ne), idx(ne), free(ne))
      ne = 0
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            do e = 1, blk%nel
               do k = 1, 4
                  a1 = blk%conn(k, e); a2 = blk%conn(mod(k, 4) + 1, e)
                  if (a1 == a2) cycle                     ! a triangle's collapsed side
                  ne = ne + 1
                  ed(:, ne) = [a1, a2, b, e]
                  key(ne) = real(min(a1, a2), wp)*model%nn + max(a1, a2)
               end do
            end do
         end associate
      end do
      idx = [(j, j = 1, ne)]
      call sort_index(idx(1:ne), key(1:ne))
      free = .true.
      do j = 2, ne
         if (key(idx(j)) == key(idx(j - 1))) then
            free(idx(j)) = .false.; free(idx(j - 1)) = .false.
         end if
      end do
      ed = ed(:, pack([(j, j = 1, ne)], free(1:ne)))
   end subroutine mesh_free_edges

   !> fam: the deck's element family; an error (card src, field) when the deck is not 2D
   subroutine need_twod(inp, model, src, field, what, fam, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(origin_t), intent(in) :: src
      character(*), intent(in) :: field, what
      type(family_t), intent(out) :: fam
      type(error_t), allocatable, intent(out) :: error
      fam = element_family(model%blocks(1)%etype)
      if (.not. fam%twod) call set_error(error, at(inp, src)//'field '//field//': '//what// &
         ' needs a 2D deck (*SECTION_SHELL ELFORM 12-15); this deck is 3D')
   end subroutine need_twod

   !> *CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE -> model%contact2d: the free edges of the
   !> elements of each side's parts, their nodes, and each edge's penalty (dx_contact2d)
   subroutine build_contact2d(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ed(:, :), side(:, :)
      logical, allocatable :: inp_s(:), mark(:)
      integer :: i, p, j, k, sid, q
      real(wp) :: el, vol, rm
      type(family_t) :: fam
      character(4), parameter :: fld(2) = ['SIDS', 'SIDM']
      if (size(inp%contacts2d) == 0) return
      call need_twod(inp, model, inp%contacts2d(1)%src, 'SIDS', 'a 2D contact', fam, error)
      if (allocated(error)) return
      call mesh_free_edges(model, ed)
      allocate(model%contact2d)
      allocate(model%contact2d%iface(size(inp%contacts2d)), inp_s(size(model%parts)), &
               mark(model%nn))
      do i = 1, size(inp%contacts2d)
         associate (r => inp%contacts2d(i), ci => model%contact2d%iface(i))
            ci%label = r%label
            ci%fs = r%fs
            ci%istiff = r%istiff
            ci%tied = r%tied > 0
            if (r%tied == 2) ci%npass = 1   ! (one way: SIDS's nodes on SIDM's edges)
            if (r%tied > 0 .and. r%tietyp == 0) call log_warn(at(inp, r%src)//'TIETYP = 0: '// &
               'LS-DYNA ties by kinematic constraints where it can; dynx ties by a penalty '// &
               'spring (as TIETYP = 1), stiffness SFACT x K L**2/A of the master edge''s element')
            if (r%istiff == 0 .and. r%tied == 0) call log_warn(at(inp, r%src)// &
               'ISTIFF = 0: dynx scales the '// &
               'contact stiffness from the segment stiffness and dimensions (ISTIFF = 2); '// &
               'LS-DYNA''s explicit default is ISTIFF = 1 (segment masses and the step)')
            ci%sofscl = 0.1_wp*r%sfact
            if (r%single) ci%npass = 1
            do p = 1, 2                    ! side p: its free edges
               sid = merge(r%sids, r%sidm, p == 1)
               if (r%single) sid = r%sids  ! (single surface: both sides are SIDS)
               q = mp%pset%get(sid)
               if (q == 0) then
                  call set_error(error, at(inp, r%src)//'field '//fld(p)//': part set '// &
                     str(sid)//' is not defined (*SET_PART)')
                  return
               end if
               inp_s = .false.
               inp_s(model%part_sets(q)%parts) = .true.
               side = ed(:, pack([(j, j = 1, size(ed, 2))], &
                                 inp_s(model%blocks(ed(3, :))%ipart)))
               if (size(side, 2) == 0) then
                  call set_error(error, at(inp, r%src)//'field '//fld(p)//': the parts of '// &
                     'set '//str(sid)//' have no free edge of a 2D element')
                  return
               end if
               ! pass p: the nodes of side p against the edges of the other side; here the
               ! edges of side p go to the other pass
               associate (ps => ci%pass(3 - p))
                  ps%edge = side(1:2, :)
                  allocate(ps%k(size(side, 2)))
                  if (r%single) then
                     allocate(ps%own(4, size(side, 2)))
                     do k = 1, size(side, 2)
                        ps%own(:, k) = model%blocks(side(3, k))%conn(1:4, side(4, k))
                     end do
                  end if
                  do k = 1, size(side, 2)
                     associate (blk => model%blocks(side(3, k)), &
                                m0 => model%mats(model%parts(model%blocks(side(3, k))%ipart)%imat)%m)
                        if (.not. m0%bulk > 0.0_wp) then
                           call set_error(error, at(inp, r%src)//'field '//fld(p)//': part '// &
                              str(model%parts(blk%ipart)%label)//' has no elastic bulk '// &
                              'modulus for the contact penalty')
                           return
                        end if
                        el = norm2(model%x0(1:2, side(2, k)) - model%x0(1:2, side(1, k)))
                        vol = blk%vol0(side(4, k))
                        rm = 1.0_wp
                        if (fam%axisym) rm = 0.5_wp*(model%x0(1, side(1, k)) + &
                                                     model%x0(1, side(2, k)))
                        ! (a tie: the element's own stiffness, not a tenth of it)
                        ps%k(k) = r%sfact*merge(1.0_wp, 0.1_wp, r%tied > 0)*m0%bulk*el**2* &
                                  rm**2/vol
                     end associate
                  end do
               end associate
               associate (ps => ci%pass(p))
                  mark = .false.
                  mark(side(1, :)) = .true.; mark(side(2, :)) = .true.
                  ps%node = pack([(j, j = 1, model%nn)], mark)
               end associate
            end do
            if (ci%tied) call tie_project(ci, model%x0, r%tiedgap, at(inp, r%src))
         end associate
      end do
   end subroutine build_contact2d

   !> A tied 2D interface: each slave node of each pass is tied to the master edge it lies
   !> on at t = 0 (LS-DYNA's tied contact: the nodes within the search gap TIEDGAP of an
   !> edge, projected once): the nearest edge whose projection xi is within the gap of
   !> [0, 1] and whose normal distance is at most the gap (0: 1 % of the edge's length;
   !> > 0 that length; < 0 |TIEDGAP| % of the edge's length); xi clamped to [0, 1] and the
   !> node's offset from that point, in the edge's frame, kept (gaps remain: IGAPCL 0).
   subroutine tie_project(ci, x0, tiedgap, where)
      type(c2d_iface_t), intent(inout) :: ci
      real(wp), intent(in) :: x0(:, :), tiedgap
      character(*), intent(in) :: where
      integer :: p, k, j, s, a, b, jb, ntied
      real(wp) :: d(2), t(2), el, gap, xi, g, best, xib, gb, xb
      ntied = 0
      do p = 1, ci%npass
         associate (ps => ci%pass(p))
            allocate(ps%tie_edge(size(ps%node)), ps%tie_xi(size(ps%node)), &
                     ps%tie_off(2, size(ps%node)))
            ps%tie_edge = 0
            ps%tie_xi = 0.0_wp
            ps%tie_off = 0.0_wp
            do k = 1, size(ps%node)
               s = ps%node(k)
               jb = 0; best = huge(1.0_wp); xib = 0.0_wp; gb = 0.0_wp; xb = 0.0_wp
               do j = 1, size(ps%edge, 2)
                  a = ps%edge(1, j); b = ps%edge(2, j)
                  if (s == a .or. s == b) cycle
                  d = x0(1:2, b) - x0(1:2, a)
                  el = norm2(d)
                  t = d/el
                  gap = 0.01_wp*el
                  if (tiedgap > 0.0_wp) gap = tiedgap
                  if (tiedgap < 0.0_wp) gap = 0.01_wp*abs(tiedgap)*el
                  xi = dot_product(x0(1:2, s) - x0(1:2, a), t)/el
                  if (xi < -gap/el .or. xi > 1.0_wp + gap/el) cycle
                  g = dot_product(x0(1:2, s) - x0(1:2, a), [t(2), -t(1)])
                  if (abs(g) > gap .or. abs(g) >= best) cycle
                  best = abs(g); jb = j; xb = xi; gb = g
                  xib = min(max(xi, 0.0_wp), 1.0_wp)
               end do
               if (jb == 0) cycle
               a = ps%edge(1, jb); b = ps%edge(2, jb)
               ps%tie_edge(k) = jb
               ps%tie_xi(k) = xib
               ps%tie_off(:, k) = [(xb - xib)*norm2(x0(1:2, b) - x0(1:2, a)), gb]
               ntied = ntied + 1
            end do
         end associate
      end do
      if (ntied == 0) then
         call log_warn(where//'no node of the tied interface lies within TIEDGAP of an '// &
                       'edge of the other side at t = 0: nothing is tied')
      else
         call log_info('dynx: '//where//str(ntied)//' nodes tied')
      end if
   end subroutine tie_project

   !> *DYNX_PRESSURE_TABLE, *DYNX_PRESSURE_PULSE -> model%edge_pressures: per free edge of
   !> the set its radius (table) or cos**2 theta (pulse) and per node its share of the
   !> force at unit pressure, -w_I (dy, -dx) with the edge load's weights (dx_loads), t = 0.
   subroutine build_edge_pressures(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: ed(:, :)
      integer :: i, j, ne, a1, a2
      real(wp) :: d(2), w(2), cth
      type(family_t) :: fam
      if (size(inp%edge_press) == 0) return
      call need_twod(inp, model, inp%edge_press(1)%src, 'NSID', 'a pressure on element '// &
                     'edges', fam, error)
      if (allocated(error)) return
      allocate(model%edge_pressures(size(inp%edge_press)))
      do i = 1, size(inp%edge_press)
         associate (r => inp%edge_press(i), ep => model%edge_pressures(i))
            call free_edges(inp, model, mp, r%nsid, r%src, ed, error)
            if (allocated(error)) return
            ne = size(ed, 2)
            ep%kind = r%kind
            if (r%kind == 1) then
               ep%r = r%r; ep%t = r%t; ep%p = r%sf*r%p
            else
               ep%pmax = r%pmax; ep%t0 = r%t0; ep%fwhm = r%fwhm
            end if
            allocate(ep%re(ne), ep%ce(ne), ep%node(2*ne), ep%edge(2*ne), ep%w(2, 2*ne))
            do j = 1, ne
               a1 = ed(1, j); a2 = ed(2, j)
               d = model%x0(1:2, a2) - model%x0(1:2, a1)
               w = 0.5_wp
               if (fam%axisym) w = [2.0_wp*model%x0(1, a1) + model%x0(1, a2), &
                                    model%x0(1, a1) + 2.0_wp*model%x0(1, a2)]/6.0_wp
               if (fam%twod .and. model%blocks(1)%etype == ETYPE_QUAD2D_PSS) &
                  w = w*model%blocks(ed(3, j))%es(ed(4, j), model%blocks(ed(3, j))%esc(ES_THK))
               ep%re(j) = 0.5_wp*(model%x0(1, a1) + model%x0(1, a2))
               cth = -dot_product([d(2), -d(1)], r%dir)/norm2(d)   ! -n . light direction
               ep%ce(j) = max(cth, 0.0_wp)**2
               ep%node(2*j - 1:2*j) = [a1, a2]
               ep%edge(2*j - 1:2*j) = j
               ep%w(:, 2*j - 1) = -w(1)*[d(2), -d(1)]
               ep%w(:, 2*j) = -w(2)*[d(2), -d(1)]
            end do
         end associate
      end do
   end subroutine build_edge_pressures

   !> *DYNX_ENERGY_DEPOSITION -> model%deposits (the part's index and initial volume)
   subroutine build_deposits(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, b
      if (size(inp%deposits) == 0) return
      allocate(model%deposits(size(inp%deposits)))
      do i = 1, size(inp%deposits)
         associate (r => inp%deposits(i), dp => model%deposits(i))
            dp%ipart = mp%part%get(r%pid)
            if (dp%ipart == 0) then
               call set_error(error, at(inp, r%src)//'field PID: part '//str(r%pid)// &
                  ' is not defined (*PART)')
               return
            end if
            dp%rate = r%rate; dp%t1 = r%t1; dp%t2 = r%t2
            do b = 1, size(model%blocks)
               if (model%blocks(b)%ipart == dp%ipart) dp%vpart = dp%vpart + &
                  sum(model%blocks(b)%vol0(1:model%blocks(b)%nel))
            end do
            if (.not. dp%vpart > 0.0_wp) then
               call set_error(error, at(inp, r%src)//'field PID: part '//str(r%pid)// &
                  ' has no elements with a volume to take the energy')
               return
            end if
         end associate
      end do
   end subroutine build_deposits
end module dx_build_twod
