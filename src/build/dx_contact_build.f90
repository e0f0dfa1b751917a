!> Contact build: resolves the *CONTACT_... records (dx_contact_input) against the built model
!> into contact_set_t (dx_contact_types): slave and master surfaces from segment sets, parts,
!> part sets, node sets or all parts; exterior faces of solid parts (faces used by exactly one
!> element of the surface's parts, outward by the family's face node order); segment-set segments
!> oriented outward by the element face they match; *DEFINE_BOX filters; the penalty stiffness
!> of each segment k = SLSFAC*SF*K*A^2/V (LS-DYNA Theory Manual, "Standard penalty
!> formulation"; Hallquist, Goudreau & Benson 1985, CMAME 51:107), K the bulk modulus and V the
!> volume of the element owning the segment, A its area, SF = SFM for master segments and SFS
!> for slave segments (second pass of a two-way contact, and single surface).
!> Errors name the deck file, line, keyword and field (exit code 2).
module dx_contact_build
   use dx_kinds, only: wp
   use dx_sort, only: sort4
   use dx_vec3, only: cross
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_model, only: model_t, family_t, element_family, MAX_NEN, MAX_FACES
   use dx_model_input, only: model_input_t
   use dx_label_map, only: label_map_t
   use dx_contact_input, only: contact_in_t, CT_NODES_TO_SURFACE, CT_SURFACE_TO_SURFACE, &
                               CT_ONE_WAY, CT_SINGLE_SURFACE
   use dx_contact_types, only: contact_set_t, contact_iface_t, contact_pass_t
   implicit none
   private
   public :: build_contact, face_key
   ! element faces (outward by the right-hand rule) come from the family table (dx_model)

   !> a surface: segments with their owning elements
   type :: surface_t
      integer :: nseg = 0
      integer, allocatable :: seg(:, :)     !< (4, nseg), a triangle repeats node 3
      integer, allocatable :: nsn(:)
      integer, allocatable :: elem(:)       !< owning element (dense)
      !> decks that erode: the element across the face (0: exterior; an interior face of
      !> the parts is in the surface twice, once from each side, dormant until the element
      !> across it erodes)
      integer, allocatable :: nbr(:)
   end type surface_t

contains

   !> Build model%contact from inp%contact (nothing when the deck has no *CONTACT).
   subroutine build_contact(inp, model, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: i, n
      logical, allocatable :: used(:)
      if (.not. allocated(inp%contact%contacts)) return
      n = size(inp%contact%contacts)
      if (n == 0) return
      allocate(model%contact)
      allocate(model%contact%iface(n))
      do i = 1, n
         call build_iface(inp, model, inp%contact%contacts(i), i, model%contact%iface(i), error)
         if (allocated(error)) return
      end do
      allocate(used(model%nn))
      used = .false.
      do i = 1, n
         associate (f => model%contact%iface(i))
            do n = 1, size(f%pass)
               used(f%pass(n)%node) = .true.
               used(pack(f%pass(n)%seg, .true.)) = .true.
            end do
         end associate
      end do
      model%contact%node = pack([(i, i = 1, model%nn)], used)
      allocate(model%contact%fc(3, model%nn), model%contact%krow(model%nn))
      model%contact%fc = 0.0_wp
      model%contact%krow = 0.0_wp
      model%contact%rcforc_dt = inp%contact%rcforc_dt
   end subroutine build_contact

   function where(inp, c) result(s)
      type(model_input_t), intent(in) :: inp
      type(contact_in_t), intent(in) :: c
      character(:), allocatable :: s
      s = inp%files(c%ifile)%s//':'//str(c%line)//': *'//c%key//': '
   end function where

   subroutine build_iface(inp, model, c, idx, f, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: idx
      type(contact_iface_t), intent(out) :: f
      type(error_t), allocatable, intent(out) :: error
      type(surface_t) :: ss, ms
      integer, allocatable :: snodes(:), mnodes(:)
      real(wp), allocatable :: tnode(:)
      real(wp) :: slsfac, ts(2), tm(2)
      slsfac = inp%contact%slsfac
      ! shells: each node's largest shell thickness (0: none); the contact thickness of
      ! each side: (SST or MST when > 0, else the shell's own thickness) times SFST or SFMT
      call shell_node_thickness(model, tnode)
      ts = [c%sst, c%sfst]
      tm = [c%mst, c%sfmt]
      f%label = c%label
      if (f%label == 0) f%label = idx
      f%name = c%key
      f%kind = c%kind
      f%fs = c%fs; f%fd = c%fd; f%dc = c%dc; f%vc = c%vc; f%vdc = c%vdc
      f%bt = c%bt; f%dt = c%dt; f%fsf = c%fsf; f%vsf = c%vsf
      f%soft = c%soft; f%sofscl = c%sofscl; f%bsort = c%bsort
      ! the implicit Newton solver (IMFLAG = 1 without *DYNX_CONSERVING_CONTACT) has the
      ! nodes-to-surface and surface-to-surface penalty contacts (dx_implicit_contact)
      if (c%kind == CT_SINGLE_SURFACE .and. inp%ctrl%imp%imflag == 1 .and. &
          .not. allocated(inp%emc%contacts)) then
         call set_error(error, where(inp, c)//'single surface contact is not yet in the '// &
            'implicit solver (IMFLAG = 1); it has *CONTACT_(AUTOMATIC_)SURFACE_TO_SURFACE '// &
            'and *CONTACT_(AUTOMATIC_)NODES_TO_SURFACE')
         return
      end if
      ! ---- slave side
      if (c%sstyp == 4) then
         call node_set_nodes(inp, model, c, c%ssid, 'SSID', snodes, error)
         if (allocated(error)) return
         call box_nodes(inp, model, c, c%sboxid, 'SBOXID', snodes, error)
         if (allocated(error)) return
      else
         call side_surface(inp, model, c, c%ssid, c%sstyp, 'SSID', ss, error)
         if (allocated(error)) return
         call box_segments(inp, model, c, c%sboxid, 'SBOXID', ss, error)
         if (allocated(error)) return
         snodes = surface_nodes(model%nn, ss)
      end if
      if (size(snodes) == 0) then
         call set_error(error, where(inp, c)//'field SSID: the slave side (set '// &
                        str(c%ssid)//', type '//str(c%sstyp)//') has no nodes')
         return
      end if
      if (c%kind == CT_SINGLE_SURFACE) then
         allocate(f%pass(1))
         call make_pass(model, snodes, ss, slsfac*c%sfs, .true., f%pass(1), ss)
         call shell_offsets(model, tnode, ss, ts, ts, f%pass(1))
         return
      end if
      ! ---- master side
      call side_surface(inp, model, c, c%msid, c%mstyp, 'MSID', ms, error)
      if (allocated(error)) return
      call box_segments(inp, model, c, c%mboxid, 'MBOXID', ms, error)
      if (allocated(error)) return
      if (ms%nseg == 0) then
         call set_error(error, where(inp, c)//'field MSID: the master side (set '// &
                        str(c%msid)//', type '//str(c%mstyp)//') has no segments')
         return
      end if
      select case (c%kind)
      case (CT_SURFACE_TO_SURFACE)
         allocate(f%pass(2))
         call make_pass(model, snodes, ms, slsfac*c%sfm, .false., f%pass(1), ss)
         call shell_offsets(model, tnode, ms, ts, tm, f%pass(1))
         mnodes = surface_nodes(model%nn, ms)
         call make_pass(model, mnodes, ss, slsfac*c%sfs, .false., f%pass(2), ms)
         call shell_offsets(model, tnode, ss, tm, ts, f%pass(2))
      case (CT_NODES_TO_SURFACE, CT_ONE_WAY)
         allocate(f%pass(1))
         if (c%sstyp == 4) then
            call make_pass(model, snodes, ms, slsfac*c%sfm, .false., f%pass(1))
         else
            call make_pass(model, snodes, ms, slsfac*c%sfm, .false., f%pass(1), ss)
         end if
         call shell_offsets(model, tnode, ms, ts, tm, f%pass(1))
      end select
   end subroutine build_iface

   !> the nodes of a surface, each once, in increasing order
   function surface_nodes(nn, s) result(nodes)
      integer, intent(in) :: nn
      type(surface_t), intent(in) :: s
      integer, allocatable :: nodes(:)
      logical, allocatable :: used(:)
      integer :: i, k
      allocate(used(nn))
      used = .false.
      do i = 1, s%nseg
         do k = 1, s%nsn(i)
            used(s%seg(k, i)) = .true.
         end do
      end do
      nodes = pack([(i, i = 1, nn)], used)
   end function surface_nodes

   !> One pass: slave nodes against the segments of s, stiffness scale sf (SLSFAC*SFx).
   subroutine make_pass(model, nodes, s, sf, single, p, own)
      type(model_t), intent(in) :: model
      integer, intent(in) :: nodes(:)
      type(surface_t), intent(in) :: s
      real(wp), intent(in) :: sf
      logical, intent(in) :: single
      type(contact_pass_t), intent(out) :: p
      type(surface_t), intent(in), optional :: own   !< the slave nodes' surface
      integer :: i, e, b, q
      real(wp) :: a, v, kb
      p%nnode = size(nodes)
      p%nseg = s%nseg
      p%node = nodes
      p%seg = s%seg(:, 1:s%nseg)
      p%nsn = s%nsn(1:s%nseg)
      p%exclude_owner = single
      allocate(p%kseg(s%nseg), p%depth(s%nseg), p%area(s%nseg), p%owner(MAX_NEN, s%nseg))
      p%owner = 0
      do i = 1, s%nseg
         e = s%elem(i)
         b = model%elem_block(e)
         q = model%elem_pos(e)
         p%owner(1:size(model%blocks(b)%conn, 1), i) = model%blocks(b)%conn(:, q)
         v = model%blocks(b)%vol0(q)
         kb = model%mats(model%parts(model%blocks(b)%ipart)%imat)%m%bulk
         a = seg_area(model%x0, s%seg(:, i), s%nsn(i))
         p%area(i) = a
         p%kseg(i) = 0.0_wp        ! a collapsed face (zero area, as degenerate solids have)
         p%depth(i) = 0.0_wp       ! or a zero-volume owner carries no contact stiffness
         if (a > 0.0_wp .and. v > 0.0_wp) then
            p%kseg(i) = sf*kb*a*a/v
            p%depth(i) = 0.5_wp*v/a
         end if
      end do
      if (present(own)) then
         p%nsseg = own%nseg
         p%sseg = own%seg(:, 1:own%nseg)
         p%ssn = own%nsn(1:own%nseg)
         allocate(p%nloc(model%nn), p%nnrm(3, p%nnode))
         p%nloc = 0
         p%nloc(p%node) = [(i, i = 1, p%nnode)]
         p%nnrm = 0.0_wp
      end if
      if (model%erodes) then       ! erosion: owners, neighbours, live masks (dx_contact)
         p%oelem = s%elem(1:s%nseg)
         allocate(p%onbr(s%nseg))
         p%onbr = 0
         if (allocated(s%nbr)) p%onbr = s%nbr(1:s%nseg)
         p%live = p%onbr == 0
         allocate(p%nlive(p%nnode))
         p%nlive = .true.
         if (present(own)) then
            p%soelem = own%elem(1:own%nseg)
            allocate(p%snbr(own%nseg))
            p%snbr = 0
            if (allocated(own%nbr)) p%snbr = own%nbr(1:own%nseg)
            p%slive = p%snbr == 0
         end if
      end if
      allocate(p%ft(3, p%nnode), p%iseg(p%nnode), p%gap(p%nnode))
      p%ft = 0.0_wp
      p%iseg = 0
      p%gap = 0.0_wp
      allocate(p%cand_ptr(p%nnode + 1), p%cand(0))
      p%cand_ptr = 1
   end subroutine make_pass

   !> Each node's largest shell thickness (initial: vol0 over the shell's area; 0 where no
   !> shell has the node). Unallocated when the model has no shells.
   subroutine shell_node_thickness(model, tnode)
      type(model_t), intent(in) :: model
      real(wp), allocatable, intent(out) :: tnode(:)
      type(family_t) :: fam
      integer :: b, q, k
      real(wp) :: t, a
      do b = 1, size(model%blocks)
         fam = element_family(model%blocks(b)%etype)
         if (.not. fam%rot) cycle
         if (.not. allocated(tnode)) then
            allocate(tnode(model%nn))
            tnode = 0.0_wp
         end if
         associate (blk => model%blocks(b))
            do q = 1, blk%nel
               a = seg_area(model%x0, blk%conn(1:4, q), merge(3, 4, blk%conn(3, q) == &
                            blk%conn(4, q)))
               if (.not. (a > 0.0_wp)) cycle
               t = blk%vol0(q)/a
               do k = 1, 4
                  tnode(blk%conn(k, q)) = max(tnode(blk%conn(k, q)), t)
               end do
            end do
         end associate
      end do
   end subroutine shell_node_thickness

   !> Shells in pass p (segments of s on shell elements, slave nodes on shells): the contact
   !> surface lies off the mid-surface by half the contact thickness, on either side
   !> (LS-DYNA's default: half the shell thickness; tn, tseg = [SST or MST, SFST or SFMT] of
   !> the nodes' and the segments' side: a thickness > 0 replaces the shell's). A shell
   !> segment's penalty stiffness is LS-DYNA's shell form SF K A / (largest diagonal)
   !> (Theory Manual, "Penalty method": K A^2 / V of a solid face would make it K A / t),
   !> its depth the offset. Nothing is allocated for a pass without shells.
   subroutine shell_offsets(model, tnode, s, tn, tseg, p)
      type(model_t), intent(in) :: model
      real(wp), allocatable, intent(in) :: tnode(:)
      type(surface_t), intent(in) :: s
      real(wp), intent(in) :: tn(2), tseg(2)
      type(contact_pass_t), intent(inout) :: p
      type(family_t) :: fam
      integer :: i, e, b, q
      real(wp) :: t, a, dmax
      if (.not. allocated(tnode)) return
      allocate(p%soff(p%nseg), p%noff(p%nnode))
      p%soff = 0.0_wp
      p%noff = 0.0_wp
      do i = 1, p%nseg
         e = s%elem(i)
         b = model%elem_block(e)
         q = model%elem_pos(e)
         fam = element_family(model%blocks(b)%etype)
         if (.not. fam%rot) cycle
         a = p%area(i)
         if (.not. (a > 0.0_wp)) cycle
         t = model%blocks(b)%vol0(q)/a
         if (tseg(1) > 0.0_wp) t = tseg(1)
         p%soff(i) = 0.5_wp*tseg(2)*t
         dmax = norm2(model%x0(:, p%seg(3, i)) - model%x0(:, p%seg(1, i)))
         if (p%nsn(i) == 4) then
            dmax = max(dmax, norm2(model%x0(:, p%seg(4, i)) - model%x0(:, p%seg(2, i))))
         else
            dmax = max(dmax, norm2(model%x0(:, p%seg(2, i)) - model%x0(:, p%seg(1, i))), &
                       norm2(model%x0(:, p%seg(3, i)) - model%x0(:, p%seg(2, i))))
         end if
         ! (the solid form's SF K A^2 / V undone: the same scale factor SF)
         p%kseg(i) = p%kseg(i)*model%blocks(b)%vol0(q)/(a*dmax)
         p%depth(i) = p%soff(i)
      end do
      do i = 1, p%nnode
         t = tnode(p%node(i))
         if (t > 0.0_wp .and. tn(1) > 0.0_wp) t = tn(1)
         p%noff(i) = 0.5_wp*tn(2)*t
      end do
      if (p%nnode > 0) p%noffmax = max(0.0_wp, maxval(p%noff))
      p%shells = any(p%soff > 0.0_wp) .or. p%noffmax > 0.0_wp
      if (.not. p%shells) deallocate(p%soff, p%noff)
   end subroutine shell_offsets

   !> area of a 3- or 4-node segment (a quad: half the cross product of its diagonals)
   pure real(wp) function seg_area(x, sg, nsn) result(a)
      real(wp), intent(in) :: x(:, :)
      integer, intent(in) :: sg(4), nsn
      if (nsn == 4) then
         a = 0.5_wp*norm2(cross(x(:, sg(3)) - x(:, sg(1)), x(:, sg(4)) - x(:, sg(2))))
      else
         a = 0.5_wp*norm2(cross(x(:, sg(2)) - x(:, sg(1)), x(:, sg(3)) - x(:, sg(1))))
      end if
   end function seg_area

   !> The surface of one side: segment set (0), part set (2), part (3) or all parts (5).
   subroutine side_surface(inp, model, c, id, typ, fname, s, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id, typ
      character(*), intent(in) :: fname
      type(surface_t), intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      logical, allocatable :: inpart(:)
      integer :: k
      allocate(inpart(size(model%parts)))
      inpart = .false.
      select case (typ)
      case (0)
         call segset_surface(inp, model, c, id, fname, s, error)
         return
      case (2)
         k = last_index(model%part_sets(:)%label, id)
         if (k == 0) call set_error(error, where(inp, c)//'field '//fname//': part set '// &
                                    str(id)//' is not defined (*SET_PART_LIST)')
         if (k > 0) inpart(model%part_sets(k)%parts) = .true.
      case (3)
         k = last_index(model%parts(:)%label, id)
         if (k == 0) call set_error(error, where(inp, c)//'field '//fname//': part '// &
                                    str(id)//' is not defined (*PART)')
         if (k > 0) inpart(k) = .true.
      case (5)
         inpart = .true.
      end select
      if (allocated(error)) return
      call part_surface(model, inpart, s)
      if (s%nseg == 0) then
         call set_error(error, where(inp, c)//'field '//fname//': '// &
            trim(merge('part set', 'part    ', typ == 2))//' '//str(id)// &
            ' has no solid elements (empty contact surface)')
      end if
   end subroutine side_surface

   !> The last position of label id in labels (0: none).
   pure integer function last_index(labels, id) result(k)
      integer, intent(in) :: labels(:), id
      integer :: j
      k = 0
      do j = 1, size(labels)
         if (labels(j) == id) k = j
      end do
   end function last_index

   !> Exterior faces of the elements of the marked parts: faces used by exactly one of them.
   subroutine part_surface(model, inpart, s)
      type(model_t), intent(in) :: model
      logical, intent(in) :: inpart(:)
      type(surface_t), intent(out) :: s
      integer, allocatable :: key(:, :), fel(:), ffc(:), idx(:)
      integer :: e, nf, k, i, j, b, q, nd(4)
      type(family_t) :: fam
      nf = MAX_FACES*count(inpart(model%elem_part))
      allocate(key(4, nf), fel(nf), ffc(nf))
      nf = 0
      do e = 1, model%ne
         if (.not. inpart(model%elem_part(e))) cycle
         b = model%elem_block(e)
         q = model%elem_pos(e)
         fam = element_family(model%blocks(b)%etype)
         do k = 1, fam%nfaces
            nd = model%blocks(b)%conn(fam%faces(:, k), q)
            if (count_unique(nd) < 3) cycle
            nf = nf + 1
            key(:, nf) = face_key(nd)
            fel(nf) = e
            ffc(nf) = k
         end do
      end do
      idx = [(i, i = 1, nf)]
      call merge_sort(key, idx)
      allocate(s%seg(4, nf), s%nsn(nf), s%elem(nf))
      if (model%erodes) then
         allocate(s%nbr(nf))
         s%nbr = 0
      end if
      s%nseg = 0
      i = 1
      do while (i <= nf)
         j = i
         do while (j < nf)
            if (any(key(:, idx(j + 1)) /= key(:, idx(i)))) exit
            j = j + 1
         end do
         if (j == i) then
            e = fel(idx(i))
            b = model%elem_block(e)
            q = model%elem_pos(e)
            s%nseg = s%nseg + 1
            fam = element_family(model%blocks(b)%etype)
            call face_segment(model%blocks(b)%conn(fam%faces(:, ffc(idx(i))), q), &
                              s%seg(:, s%nseg), s%nsn(s%nseg))
            s%elem(s%nseg) = e
         else if (j == i + 1 .and. model%erodes) then
            ! an interior face of two elements: one dormant segment from each side
            do k = i, j
               e = fel(idx(k))
               b = model%elem_block(e)
               q = model%elem_pos(e)
               s%nseg = s%nseg + 1
               fam = element_family(model%blocks(b)%etype)
               call face_segment(model%blocks(b)%conn(fam%faces(:, ffc(idx(k))), q), &
                                 s%seg(:, s%nseg), s%nsn(s%nseg))
               s%elem(s%nseg) = e
               s%nbr(s%nseg) = fel(idx(i + j - k))
            end do
         end if
         i = j + 1
      end do
   end subroutine part_surface

   !> A face's node list as a segment: drop repeated nodes (cyclically); 3 left = triangle.
   pure subroutine face_segment(nd, sg, nsn)
      integer, intent(in) :: nd(4)
      integer, intent(out) :: sg(4), nsn
      integer :: k
      nsn = 0
      do k = 1, 4
         if (nd(k) == nd(mod(k, 4) + 1)) cycle
         if (nsn > 0) then
            if (any(sg(1:nsn) == nd(k))) cycle
         end if
         nsn = nsn + 1
         sg(nsn) = nd(k)
      end do
      if (nsn == 3) sg(4) = sg(3)
   end subroutine face_segment

   !> The key of a face or segment: its nodes sorted; a triangle (three distinct nodes,
   !> whichever repeats) as its sorted nodes with the largest repeated, so a segment
   !> n1 n2 n3 n3 and an element face of the same three nodes match. A quadrilateral's key
   !> is sort4 of its nodes.
   pure function face_key(nd) result(key)
      integer, intent(in) :: nd(4)
      integer :: key(4)
      key = sort4(nd)
      if (count_unique(nd) == 3) then
         if (key(1) == key(2)) then
            key(1:3) = key(2:4)
         else if (key(2) == key(3)) then
            key(2:3) = key(3:4)
         end if
         key(4) = key(3)
      end if
   end function face_key

   pure integer function count_unique(nd) result(n)
      integer, intent(in) :: nd(4)
      integer :: k
      n = 1
      do k = 2, 4
         if (all(nd(1:k-1) /= nd(k))) n = n + 1
      end do
   end function count_unique

   !> Sort idx so that key(:, idx) is in lexicographic order (bottom-up merge sort).
   subroutine merge_sort(key, idx)
      integer, intent(in) :: key(:, :)
      integer, intent(inout) :: idx(:)
      integer, allocatable :: tmp(:)
      integer :: n, width, lo, mid, hi, i, j, k
      n = size(idx)
      allocate(tmp(n))
      width = 1
      do while (width < n)
         lo = 1
         do while (lo <= n)
            mid = min(lo + width - 1, n)
            hi = min(lo + 2*width - 1, n)
            i = lo; j = mid + 1; k = lo
            do while (i <= mid .and. j <= hi)
               if (key_le(key(:, idx(i)), key(:, idx(j)))) then
                  tmp(k) = idx(i); i = i + 1
               else
                  tmp(k) = idx(j); j = j + 1
               end if
               k = k + 1
            end do
            do while (i <= mid)
               tmp(k) = idx(i); i = i + 1; k = k + 1
            end do
            do while (j <= hi)
               tmp(k) = idx(j); j = j + 1; k = k + 1
            end do
            lo = lo + 2*width
         end do
         idx = tmp
         width = 2*width
      end do
   end subroutine merge_sort

   pure logical function key_le(a, b)
      integer, intent(in) :: a(4), b(4)
      integer :: k
      key_le = .true.
      do k = 1, 4
         if (a(k) < b(k)) return
         if (a(k) > b(k)) then
            key_le = .false.; return
         end if
      end do
   end function key_le

   !> Segments of *SET_SEGMENT id, each matched to the element face it lies on and
   !> numbered like that face (outward normal).
   subroutine segset_surface(inp, model, c, id, fname, s, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id
      character(*), intent(in) :: fname
      type(surface_t), intent(out) :: s
      type(error_t), allocatable, intent(out) :: error
      integer :: k, j, i, e, b, q, f, ns, sg(4), nsn, nd(4), key(4)
      type(family_t) :: fam
      integer, allocatable :: eptr(:), elist(:)
      character(:), allocatable :: at_set
      k = last_index(model%segment_sets(:)%label, id)
      if (k == 0) then
         call set_error(error, where(inp, c)//'field '//fname//': segment set '//str(id)// &
                        ' is not defined (*SET_SEGMENT)')
         return
      end if
      associate (src => inp%segment_sets(k)%src)
         at_set = inp%files(src%ifile)%s//':'//str(src%line)//': *'//src%key//': set '// &
                  str(id)//', '
      end associate
      ns = size(model%segment_sets(k)%seg, 2)
      if (ns == 0) then
         call set_error(error, where(inp, c)//'field '//fname//': segment set '//str(id)// &
                        ' is empty')
         return
      end if
      call node_elements(model, eptr, elist)
      allocate(s%seg(4, ns), s%nsn(ns), s%elem(ns))
      s%nseg = ns
      do i = 1, ns
         nd = model%segment_sets(k)%seg(:, i)
         if (nd(1) == nd(2) .or. nd(1) == nd(3) .or. nd(2) == nd(3) .or. nd(4) == nd(1) .or. &
             nd(4) == nd(2)) then
            call set_error(error, at_set//'segment '//str(i)//' ('//node_text(model, nd)// &
               ') repeats a node (used by *'//c%key//' at line '//str(c%line)//')')
            return
         end if
         key = face_key(nd)
         s%elem(i) = 0
         do j = eptr(nd(1)), eptr(nd(1) + 1) - 1
            e = elist(j)
            b = model%elem_block(e)
            q = model%elem_pos(e)
            fam = element_family(model%blocks(b)%etype)
            do f = 1, fam%nfaces
               call face_segment(model%blocks(b)%conn(fam%faces(:, f), q), sg, nsn)
               if (all(face_key(sg) == key)) then
                  s%elem(i) = e
                  s%seg(:, i) = sg
                  s%nsn(i) = nsn
               end if
            end do
            if (s%elem(i) > 0) exit
         end do
         if (s%elem(i) == 0) then
            call set_error(error, at_set//'segment '//str(i)//' ('//node_text(model, nd)// &
               ') is not a face of a solid element (used by *'//c%key//' at line '// &
               str(c%line)//')')
            return
         end if
      end do
   end subroutine segset_surface

   function node_text(model, nd) result(t)
      type(model_t), intent(in) :: model
      integer, intent(in) :: nd(4)
      character(:), allocatable :: t
      t = str(model%node_label(nd(1)))//' '//str(model%node_label(nd(2)))//' '// &
          str(model%node_label(nd(3)))//' '//str(model%node_label(nd(4)))
   end function node_text

   !> node -> element incidence (CSR)
   subroutine node_elements(model, eptr, elist)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: eptr(:), elist(:)
      integer :: e, k, b, q, nd
      integer, allocatable :: fill(:)
      allocate(eptr(model%nn + 1))
      eptr = 0
      do e = 1, model%ne
         b = model%elem_block(e)
         q = model%elem_pos(e)
         do k = 1, size(model%blocks(b)%conn, 1)
            nd = model%blocks(b)%conn(k, q)
            if (any(model%blocks(b)%conn(1:k-1, q) == nd)) cycle
            eptr(nd + 1) = eptr(nd + 1) + 1
         end do
      end do
      eptr(1) = 1
      do k = 1, model%nn
         eptr(k + 1) = eptr(k + 1) + eptr(k)
      end do
      allocate(elist(eptr(model%nn + 1) - 1), fill(model%nn))
      fill = eptr(1:model%nn)
      do e = 1, model%ne
         b = model%elem_block(e)
         q = model%elem_pos(e)
         do k = 1, size(model%blocks(b)%conn, 1)
            nd = model%blocks(b)%conn(k, q)
            if (any(model%blocks(b)%conn(1:k-1, q) == nd)) cycle
            elist(fill(nd)) = e
            fill(nd) = fill(nd) + 1
         end do
      end do
   end subroutine node_elements

   subroutine node_set_nodes(inp, model, c, id, fname, nodes, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id
      character(*), intent(in) :: fname
      integer, allocatable, intent(out) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      k = last_index(model%node_sets(:)%label, id)
      if (k == 0) then
         call set_error(error, where(inp, c)//'field '//fname//': node set '//str(id)// &
                        ' is not defined (*SET_NODE_LIST)')
         return
      end if
      nodes = model%node_sets(k)%nodes
      if (size(nodes) == 0) call set_error(error, where(inp, c)//'field '//fname// &
                                           ': node set '//str(id)//' is empty')
   end subroutine node_set_nodes

   !> index of *DEFINE_BOX id (0 and error when missing)
   integer function find_box(inp, c, id, fname, error) result(k)
      type(model_input_t), intent(in) :: inp
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id
      character(*), intent(in) :: fname
      type(error_t), allocatable, intent(inout) :: error
      k = 0
      if (allocated(inp%contact%boxes)) k = last_index(inp%contact%boxes(:)%label, id)
      if (k == 0) call set_error(error, where(inp, c)//'field '//fname//': box '//str(id)// &
                                 ' is not defined (*DEFINE_BOX)')
   end function find_box

   !> keep the nodes inside box id (initial coordinates); id 0: keep all
   subroutine box_nodes(inp, model, c, id, fname, nodes, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id
      character(*), intent(in) :: fname
      integer, allocatable, intent(inout) :: nodes(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, i
      logical, allocatable :: keep(:)
      if (id == 0) return
      k = find_box(inp, c, id, fname, error)
      if (k == 0) return
      associate (bx => inp%contact%boxes(k))
         allocate(keep(size(nodes)))
         do i = 1, size(nodes)
            keep(i) = all(model%x0(:, nodes(i)) >= bx%lo) .and. all(model%x0(:, nodes(i)) <= bx%hi)
         end do
      end associate
      nodes = pack(nodes, keep)
   end subroutine box_nodes

   !> keep the segments whose centroid lies inside box id (initial coordinates)
   subroutine box_segments(inp, model, c, id, fname, s, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(contact_in_t), intent(in) :: c
      integer, intent(in) :: id
      character(*), intent(in) :: fname
      type(surface_t), intent(inout) :: s
      type(error_t), allocatable, intent(out) :: error
      integer :: k, i, n
      real(wp) :: xc(3)
      if (id == 0) return
      k = find_box(inp, c, id, fname, error)
      if (k == 0) return
      n = 0
      associate (bx => inp%contact%boxes(k))
         do i = 1, s%nseg
            xc = sum(model%x0(:, s%seg(1:s%nsn(i), i)), dim=2)/real(s%nsn(i), wp)
            if (all(xc >= bx%lo) .and. all(xc <= bx%hi)) then
               n = n + 1
               s%seg(:, n) = s%seg(:, i)
               s%nsn(n) = s%nsn(i)
               s%elem(n) = s%elem(i)
               if (allocated(s%nbr)) s%nbr(n) = s%nbr(i)
            end if
         end do
      end associate
      s%nseg = n
   end subroutine box_segments
end module dx_contact_build
