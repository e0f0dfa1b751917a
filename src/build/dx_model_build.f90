!> Model build: turns the deck as read (model_input_t, labels) into the model the solver runs
!> (model_t, dense indices). Resolves labels, reports duplicate ids and dangling references at
!> the card that made them, rejects degenerate and inverted solids, groups elements by part
!> into blocks of at most nv_chunk elements, resolves hourglass and bulk viscosity settings per
!> part, and expands initial velocities, constraints, loads and rigid walls onto nodes.
!> Sets and controls: dx_build_sets; constraints and loads: dx_build_loads; rigid bodies and body loads are built last
!> (dx_rigid_build); label lookups: dx_build_common.
!> Element type of a part: its section's ELFORM through the element-family table
!> (dx_element_types), which also gives the nodes per element and the exact initial volume.
module dx_model_build
   use dx_kinds, only: wp, nv_chunk
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_model, only: model_t, part_t, family_t, element_family, elem_volume, etype_of_elform, &
                       solid_shape, MAX_NEN, ES_WORK, ES_HGS, ES_DMG, ES_EPS, elem_quality, &
                       ASPECT_WARN, &
                       WARP_WARN, erosion_t
   use dx_log, only: log_warn
   use dx_material, only: has_lamina_form
   use dx_model_input, only: model_input_t, origin_t
   use dx_element_types, only: ES_THK, shell_area, etype_of_shell_elform
   use dx_build_twod, only: part_dim, check_dimension, twod_element, build_twod_extras
   use dx_element_types, only: ETYPE_SHELL_BT, ETYPE_SHELL_FI, ES_THK, shell_area, ES_BEAM, etype_of_beam_elform, &
                               ETYPE_BEAM_HL
   use dx_beam_build, only: beam_part, beam_index, beam_element, build_point_masses, &
                            section_kind, KIND_NAMES, KIND_CARDS, BEAM_NDAT
   use dx_beam_bs, only: beam_bs_init, BM_TH
   use dx_beam_hl, only: beam_hl_nip
   use dx_label_map, only: label_map_t
   use dx_build_common, only: maps_t, at, at_line, set_nodes, curve_index, node_index, &
                              dense_segments, map_labels
   use dx_build_loads, only: build_bcs, build_initial_velocity, build_loads
   use dx_build_sets, only: build_sets, build_controls
   use dx_rigid_build, only: build_rigid, build_body_loads
   implicit none
   private
   public :: build_model_data

   integer, parameter :: SHELL_MARK = 5   !< N5 = 0 on the element list: a shell card

contains

   !> Build the model data from inp: nodes, parts, blocks, sets, constraints, loads, controls
   !> and rigid bodies; not the contact pairs nor the conserving rigid contact (dx_build:
   !> build_model does all three). inp's materials and curves are moved into model.
   subroutine build_model_data(inp, model, error)
      type(model_input_t), intent(inout) :: inp
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      type(maps_t) :: mp
      character(:), allocatable :: deck0
      integer, allocatable :: bof(:)
      call beam_index(inp, bof)
      deck0 = 'deck'
      if (size(inp%files) > 0) deck0 = inp%files(1)%s
      if (allocated(inp%title)) model%title = inp%title
      if (.not. allocated(model%title)) model%title = ''
      if (inp%ne == 0) then
         call set_error(error, deck0//': deck has no elements (no *ELEMENT_SOLID cards)')
         return
      end if
      if (inp%nn == 0) then
         call set_error(error, deck0//': deck has no elements: no *NODE cards')
         return
      end if
      call build_nodes(inp, model, mp, error)
      if (allocated(error)) return
      call build_definitions(inp, model, mp, error)
      if (allocated(error)) return
      call build_parts(inp, model, mp, error)
      if (allocated(error)) return
      call build_elements(inp, model, mp, error)
      if (allocated(error)) return
      call build_point_masses(inp, model, mp, bof, error)   ! *ELEMENT_MASS, _INERTIA, NSM
      if (allocated(error)) return
      call build_sets(inp, model, mp, error)
      if (allocated(error)) return
      call build_bcs(inp, model, mp, error)
      if (allocated(error)) return
      call build_initial_velocity(inp, model, mp, error)
      if (allocated(error)) return
      call build_loads(inp, model, mp, error)
      if (allocated(error)) return
      call build_twod_extras(inp, model, mp, error)   ! 2D boundaries, loads, contact
      if (allocated(error)) return
      call build_controls(inp, model, mp, deck0, error)
      if (allocated(error)) return
      call build_body_loads(inp, model, mp%curve, error)
      if (allocated(error)) return
      call build_rigid(inp, model, mp%node, mp%part, mp%nset, mp%curve, deck0, error)
   end subroutine build_model_data

   subroutine build_nodes(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(inout) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, old
      call mp%node%init(inp%nn)
      do i = 1, inp%nn
         call mp%node%insert(inp%node_label(i), i, old)
         if (old /= 0) then
            call set_error(error, at_line(inp, inp%node_src(:, i), 'NODE')// &
               'duplicate node id '//str(inp%node_label(i))//' (first defined at '// &
               inp%files(inp%node_src(1, old))%s//':'//str(inp%node_src(2, old))//')')
            return
         end if
      end do
      if (allocated(inp%node_alias)) then     ! *NODE_MERGE: a merged-away label names its
         do i = 1, size(inp%node_alias, 2)    ! kept node (dx_read_merge)
            call mp%node%insert(inp%node_alias(1, i), mp%node%get(inp%node_alias(2, i)), old)
         end do
      end if
      model%nn = inp%nn
      model%node_label = inp%node_label(1:inp%nn)
      model%x0 = inp%x(:, 1:inp%nn)
   end subroutine build_nodes

   !> curves, sections, hourglass definitions, materials (resolve_curves, setup)
   subroutine build_definitions(inp, model, mp, error)
      type(model_input_t), intent(inout) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(inout) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, n
      integer, allocatable :: labels(:), lab(:)
      character(:), allocatable :: msg
      lab = inp%curves(:)%label
      call map_labels(inp, mp%curve, lab, inp%curve_src, 'curve', error)
      if (allocated(error)) return
      model%curves = inp%curves
      lab = inp%sections(:)%label
      call map_labels(inp, mp%sec, lab, inp%section_src, 'section', error)
      if (allocated(error)) return
      model%sections = inp%sections
      lab = inp%hourglasses(:)%label
      call map_labels(inp, mp%hg, lab, inp%hourglass_src, 'hourglass', &
                      error)
      if (allocated(error)) return
      model%hourglasses = inp%hourglasses
      n = size(inp%mats)
      allocate(labels(n))
      do i = 1, n
         labels(i) = inp%mats(i)%m%label
      end do
      call map_labels(inp, mp%mat, labels, inp%mat_src, 'material', error)
      if (allocated(error)) return
      do i = 1, n
         call inp%mats(i)%m%resolve_curves(model%curves, error)
         if (allocated(error)) exit
         call inp%mats(i)%m%setup(error)
         if (allocated(error)) exit
      end do
      if (allocated(error)) then
         msg = at(inp, inp%mat_src(i))//'material '//str(labels(i))//': '//error%message
         call set_error(error, msg)
         return
      end if
      allocate(model%mats(n))
      do i = 1, n
         call move_alloc(inp%mats(i)%m, model%mats(i)%m)
      end do
   end subroutine build_definitions

   !> parts: references, hourglass type and coefficients, bulk viscosity
   subroutine build_parts(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(inout) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i, k
      integer, allocatable :: lab(:)
      character(:), allocatable :: w
      lab = inp%parts(:)%label
      call map_labels(inp, mp%part, lab, inp%part_src, 'part', error)
      if (allocated(error)) return
      model%parts = inp%parts
      do i = 1, size(model%parts)
         w = at(inp, inp%part_src(i))
         associate (p => model%parts(i), c => inp%ctrl)
            p%isec = mp%sec%get(p%secid)
            if (p%isec == 0) then
               call set_error(error, w//'part '//str(p%label)//': field SECID: section '// &
                              str(p%secid)//' is not defined (*SECTION_SOLID, *SECTION_SHELL or *SECTION_BEAM)')
               return
            end if
            p%imat = mp%mat%get(p%mid)
            if (p%imat == 0) then
               call set_error(error, w//'part '//str(p%label)//': field MID: material '// &
                              str(p%mid)//' is not defined (*MAT_...)')
               return
            end if
            call attach_eos(inp, model, p, w, error)
            if (allocated(error)) return
            ! *MAT_ADD_EROSION of the part's material (dx_erosion)
            do k = 1, size(inp%erosions)
               if (inp%erosions(k)%mid == p%mid) p%ero = inp%erosions(k)
            end do
            do k = 1, size(inp%tb_lambdas)     ! *DYNX_TULER_BUTCHER: the exponent
               if (inp%tb_lambdas(k)%mid /= p%mid) cycle
               if (.not. p%ero%on .or. p%ero%impulse == p%ero%excl) then
                  call set_error(error, inp%files(inp%tb_src(k)%ifile)%s//':'// &
                     str(inp%tb_src(k)%line)//': *DYNX_TULER_BUTCHER: field MID: material '// &
                     str(p%mid)//' has no *MAT_ADD_EROSION with SIGTH and IMPULSE')
                  return
               end if
               p%ero%lambda = inp%tb_lambdas(k)%lambda
            end do
            if (p%ero%on .and. model%sections(p%isec)%shell) then
               call set_error(error, w//'part '//str(p%label)//': *MAT_ADD_EROSION of '// &
                  'material '//str(p%mid)//' on a shell part is not implemented (solids only)')
               return
            end if
            if (p%ero%on .or. c%erode == 1) model%erodes = .true.
            if (model%mats(p%imat)%m%erodes()) model%erodes = .true.
            if (model%sections(p%isec)%shell) then
               call shell_part(inp, model, p, w, error)
               if (allocated(error)) return
            end if
            if (model%sections(p%isec)%beam) then
               call beam_part(inp, model, p, w, error)
               if (allocated(error)) return
            end if
            p%ihq = c%ihq
            p%qh = c%qh
            p%q1 = c%q1
            p%q2 = c%q2
            if (p%hgid > 0) then
               p%ihg = mp%hg%get(p%hgid)
               if (p%ihg == 0) then
                  call set_error(error, w//'part '//str(p%label)//': field HGID: hourglass '// &
                                 str(p%hgid)//' is not defined (*HOURGLASS)')
                  return
               end if
               associate (h => model%hourglasses(p%ihg))
                  if (h%ihq > 0) p%ihq = h%ihq
                  if (h%qm > 0.0_wp) p%qh = h%qm
                  if (h%q1 > 0.0_wp) p%q1 = h%q1
                  if (h%q2 > 0.0_wp) p%q2 = h%q2
               end associate
            end if
            if (p%ihq == 0) p%ihq = 1
            if (p%ihq < 1 .or. p%ihq > 5) then
               call set_error(error, w//'part '//str(p%label)//': hourglass type IHQ = '// &
                              str(p%ihq)//' is not supported (supported: 1 to 5)')
               return
            end if
         end associate
      end do
      call check_dimension(inp, model, error)
   end subroutine build_parts

   !> A part with a *SECTION_SHELL: its section's shell settings, and the checks of what
   !> shells do not have yet (rigid shells, ISDO, TSLIMT, the Lobatto range).
   subroutine shell_part(inp, model, p, w, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(part_t), intent(inout) :: p
      character(*), intent(in) :: w
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: ts
      associate (sec => model%sections(p%isec), c => inp%ctrl)
         p%shrf = sec%shrf
         p%lobatto = c%intgrd == 1
         p%istupd = c%istupd
         ! the plane-stress plasticity algorithm of the laminae (*CONTROL_SHELL MITER)
         model%mats(p%imat)%m%ps_alg = c%miter
         if (.not. has_lamina_form(model%mats(p%imat)%m) .and. (sec%elform <= 12 .or. sec%elform == 16)) then
            call set_error(error, w//'part '//str(p%label)//': field MID: material '// &
               str(p%mid)//' (type '//str(model%mats(p%imat)%m%mtype)//') has no plane-'// &
               'stress (shell lamina) form: use it on solids (*SECTION_SOLID or 2D ELFORM '// &
               '13-15)')
            return
         end if
         if (p%lobatto .and. (sec%nip < 3 .or. sec%nip > 5)) then
            call set_error(error, at(inp, inp%section_src(p%isec))//'section '// &
               str(sec%label)//': field NIP: '//str(sec%nip)//' Lobatto points (*CONTROL_SHELL '// &
               'INTGRD = 1) are not supported (supported: 3 to 5)')
            return
         end if
         ts = 'deck'
         if (inp%timestep_src%line > 0) ts = inp%files(inp%timestep_src%ifile)%s//':'// &
                                             str(inp%timestep_src%line)//': *CONTROL_TIMESTEP'
         if (c%isdo /= 0) then
            call set_error(error, ts//': field ISDO: shell time-step length '//str(c%isdo)// &
               ' is not supported with shells (part '//str(p%label)//'; supported: 0)')
            return
         end if
         if (c%tslimt /= 0.0_wp) then
            call set_error(error, ts//': field TSLIMT: the shell time-step floor '// &
               rstr(c%tslimt)//' (mass scaling of shells) is not supported (part '// &
               str(p%label)//'; supported: 0)')
            return
         end if
      end associate
   end subroutine shell_part

   !> EOSID of part p: the equation of state of its material. LS-DYNA attaches one only to
   !> hydro models (types 9, 10, 11, 15; dynx has 9, *MAT_NULL), which need one on solids.
   !> The material's bulk modulus becomes rho0 c0**2 of the EOS (hourglass and contact scales).
   subroutine attach_eos(inp, model, p, w, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(part_t), intent(in) :: p
      character(*), intent(in) :: w
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: who
      integer :: k
      associate (m => model%mats(p%imat)%m)
         who = w//'part '//str(p%label)//': field EOSID: material '//str(p%mid)//' (type '// &
               str(m%mtype)//')'
         if (p%eosid == 0) then
            if (m%takes_eos() .and. m%needs_eos()) call set_error(error, who//' needs an '// &
                                              'equation of state '// &
                                              '(EOSID of an *EOS_ keyword)')
            return
         end if
         if (.not. m%takes_eos()) then
            call set_error(error, who//' cannot carry an equation of state (LS-DYNA attaches '// &
                           'one to hydro types 9, 10, 11, 15 only; EOSID must be 0)')
            return
         end if
         do k = size(inp%eoss), 1, -1
            if (inp%eoss(k)%e%label == p%eosid) exit
         end do
         if (k == 0) then
            call set_error(error, w//'part '//str(p%label)//': field EOSID: equation of '// &
                           'state '//str(p%eosid)//' is not defined (*EOS_...)')
            return
         end if
         if (allocated(m%eos)) then
            if (m%eos%label /= p%eosid) call set_error(error, who//' is already used with '// &
               'equation of state '//str(m%eos%label)//' (one material per equation of state)')
            return
         end if
         allocate(m%eos, source=inp%eoss(k)%e)
         m%eos%rho0 = m%ro
         m%bulk = m%ro*m%eos%sound_speed2(m%ro, 1.0_wp, m%eos%e0)
         call m%eos_ready(error)
         if (allocated(error)) error%message = who//': '//error%message
      end associate
   end subroutine attach_eos

   !> elements: references, degenerate and inverted checks, blocks by part
   subroutine build_elements(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(inout) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: ne, e, k, j, old, ip, nb, ib, nel, pos, nip, nhv, etype, nen, nshw, kc2
      logical :: shcard
      integer, allocatable :: bof(:)
      real(wp), allocatable :: bdat(:, :)
      real(wp), allocatable :: thk(:)
      integer, allocatable :: conn(:, :), npart(:), order(:), start(:), fill(:), etyp(:), grp(:)
      type(family_t) :: fam
      logical :: ok
      real(wp), allocatable :: vol(:)
      real(wp) :: hb(3), hm, asp, warp, cj
      integer :: kc, nasp, nwarp, nfold, ncoin, kj
      integer, parameter :: NLIST = 10      ! elements named per kind of warning
      character(:), allocatable :: w
      ne = inp%ne
      nasp = 0; nwarp = 0; nfold = 0; ncoin = 0
      model%ne = ne
      allocate(conn(MAX_NEN, ne), vol(ne), etyp(ne), grp(ne), model%elem_part(ne), &
               model%elem_block(ne), model%elem_pos(ne))
      nshw = 0
      if (allocated(inp%elem_thk)) then
         allocate(thk(ne))
         thk = 0.0_wp
      end if
      model%elem_label = inp%elem_label(1:ne)
      call mp%elem%init(ne)
      call beam_index(inp, bof)       ! beams: their records and set-up data
      if (allocated(bof)) allocate(bdat(BEAM_NDAT, ne))
      do e = 1, ne
         kc2 = 0                       ! the card's kind: 0 solid, 1 shell, 2 beam
         if (allocated(bof)) then
            if (bof(e) > 0) kc2 = 2
         end if
         shcard = inp%elem_conn(SHELL_MARK, e) == 0 .and. kc2 == 0
         if (shcard) kc2 = 1
         if (kc2 == 2) then
            w = at_line(inp, inp%elem_src(:, e), 'ELEMENT_BEAM')
         else if (shcard) then
            w = at_line(inp, inp%elem_src(:, e), 'ELEMENT_SHELL')
         else
            w = at_line(inp, inp%elem_src(:, e), 'ELEMENT_SOLID')
         end if
         associate (lab => inp%elem_label(e))
            call mp%elem%insert(lab, e, old)
            if (old /= 0) then
               call set_error(error, w//'duplicate element id '//str(lab)// &
                  ' (first defined at '//inp%files(inp%elem_src(1, old))%s//':'// &
                  str(inp%elem_src(2, old))//')')
               return
            end if
            model%elem_part(e) = mp%part%get(inp%elem_pid(e))
            if (model%elem_part(e) == 0) then
               call set_error(error, w//'element '//str(lab)//': field PID: part '// &
                              str(inp%elem_pid(e))//' is not defined (*PART)')
               return
            end if
            j = section_kind(model%sections(model%parts(model%elem_part(e))%isec))
            if (j /= kc2) then
               call set_error(error, w//'element '//str(lab)//': field PID: part '// &
                  str(inp%elem_pid(e))//' has section '// &
                  str(model%sections(model%parts(model%elem_part(e))%isec)%label)//', a '// &
                  trim(KIND_NAMES(j))//' (an '//trim(KIND_CARDS(kc2))//' needs a '// &
                  trim(KIND_NAMES(kc2))//')')
               return
            end if
            if (kc2 == 2) then
               call beam_element(inp, model, mp, e, bof(e), w, conn(:, e), vol(e), &
                                 bdat(:, e), error)
               if (allocated(error)) return
               etyp(e) = etype_of_section(model%parts(model%elem_part(e))%isec)
               cycle
            end if
            if (shcard) then
               call shell_element(e, lab, w, error)
               if (allocated(error)) return
               cycle
            end if
            do k = 1, MAX_NEN
               conn(k, e) = mp%node%get(inp%elem_conn(k, e))
               if (conn(k, e) == 0) then
                  call set_error(error, w//'element '//str(lab)//': field N'//str(k)// &
                                 ': node '//str(inp%elem_conn(k, e))//' is not defined (*NODE)')
                  return
               end if
            end do
            etype = etype_of_section(model%parts(model%elem_part(e))%isec)
            call solid_shape(inp%ctrl%esort, conn(:, e), etype, nen, ok)
            if (.not. ok) then
               if (nen < MAX_NEN) then
                  call set_error(error, w//'element '//str(lab)//': ELFORM '// &
                     str(model%sections(model%parts(model%elem_part(e))%isec)%elform)// &
                     ' needs '//str(nen)//' distinct nodes')
                  return
               end if
               do k = 2, nen
                  do j = 1, k - 1
                     if (conn(k, e) == conn(j, e)) then
                        call set_error(error, w//'element '//str(lab)//': node '// &
                           str(inp%elem_conn(k, e))//' appears twice (N'//str(j)//' and N'// &
                           str(k)//'): degenerate solid not supported (supported: '// &
                           'tetrahedron N4=N3, N5=N6=N7=N8; pentahedron N4=N3, N8=N7)')
                        return
                     end if
                  end do
               end do
            end if
            etyp(e) = etype
            vol(e) = elem_volume(etype, model%x0(:, conn(1:nen, e)))
            if (.not. (vol(e) > 0.0_wp)) then
               call set_error(error, w//'element '//str(lab)//' is inverted at t = 0 '// &
                  '(volume '//rstr(vol(e))//' <= 0; check the node order N1..N8)')
               return
            end if
            ! zero volume within round-off: below 1e-12 of the cube of the element's largest
            ! extent (a plate passes up to aspect 1e12, a needle up to 1e6). Half extents hb,
            ! divided one at a time: no overflow for huge coordinates (vol > 0, so hm > 0).
            hb = 0.5_wp*maxval(model%x0(:, conn(:, e)), dim=2) - &
                 0.5_wp*minval(model%x0(:, conn(:, e)), dim=2)
            hm = maxval(hb)
            if (vol(e)/hm/hm/hm/8.0_wp <= 1.0e-12_wp) then
               call set_error(error, w//'element '//str(lab)//' has zero volume at t = 0 '// &
                  '(volume '//rstr(vol(e))//'; flat or collapsed: check its nodes N1..N8)')
               return
            end if
            ! coincident nodes: two distinct node ids at one point (within 1e-12 of the
            ! largest extent), a zero-length edge the volume check above does not see when
            ! the rest of the element keeps a volume: a warning, as the shape checks below
            ! (the element runs as a collapsed one; a repeated node id is the way to ask for
            ! a degenerate element, and the nodes may separate during the run)
            kj = 0
            do k = 2, nen
               do j = 1, k - 1
                  if (kj /= 0) exit
                  if (conn(k, e) == conn(j, e)) cycle
                  hb = abs(model%x0(:, conn(k, e)) - model%x0(:, conn(j, e)))
                  if (all(hb <= 2.0e-12_wp*hm)) kj = 100*j + k
               end do
            end do
            if (kj /= 0) then
               ncoin = ncoin + 1
               if (ncoin <= NLIST) call log_warn(w//'element '//str(lab)//': nodes '// &
                  str(model%node_label(conn(kj/100, e)))//' and '// &
                  str(model%node_label(conn(mod(kj, 100), e)))//' are at the same point '// &
                  '(distinct ids, a zero-length edge): a collapsed element; repeat one '// &
                  'node id for a degenerate element, or move the node')
            end if
            ! shape (elem_quality; bounds in docs/extreme-cases.md, "Geometry checks"): a
            ! folded corner, a thin or a warped element is a warning (one-point elements run
            ! with them, as in LS-DYNA; a negative total volume is the error above)
            call elem_quality(etype, model%x0(:, conn(1:nen, e)), vol(e), asp, warp, cj, kc)
            if (kc > 0 .and. .not. (cj > 0.0_wp)) then
               nfold = nfold + 1
               if (nfold <= NLIST) call log_warn(w//'element '//str(lab)// &
                  ' is folded at node '//str(inp%elem_conn(kc, e))//' (N'//str(kc)// &
                  ') at t = 0 (corner Jacobian '//rstr(cj)//' V <= 0: locally inverted)')
            end if
            if (asp > ASPECT_WARN) then
               nasp = nasp + 1
               if (nasp <= NLIST) call log_warn(w//'element '//str(lab)//': aspect ratio '// &
                  rstr(asp)//' (longest edge / time-step length) above '//rstr(ASPECT_WARN)// &
                  ': the thin direction sets the time step')
            end if
            if (warp > WARP_WARN) then
               nwarp = nwarp + 1
               if (nwarp <= NLIST) call log_warn(w//'element '//str(lab)//': a face is warped by '// &
                  rstr(warp)//' degrees (above '//rstr(WARP_WARN)//')')
            end if
         end associate
      end do
      if (nfold > NLIST) call log_warn('*ELEMENT_SOLID: '//str(nfold - NLIST)// &
         ' more elements folded at a corner ('//str(nfold)//' in all)')
      if (ncoin > NLIST) call log_warn('*ELEMENT_SOLID: '//str(ncoin - NLIST)// &
         ' more elements with two nodes at the same point ('//str(ncoin)//' in all)')
      if (nasp > NLIST) call log_warn('*ELEMENT_SOLID: '//str(nasp - NLIST)// &
         ' more elements with an aspect ratio above '//rstr(ASPECT_WARN)//' ('//str(nasp)//' in all)')
      if (nwarp > NLIST) call log_warn('*ELEMENT_SOLID: '//str(nwarp - NLIST)// &
         ' more elements with a face warped above '//rstr(WARP_WARN)//' degrees ('//str(nwarp)// &
         ' in all)')
      ! blocks: parts in deck order, elements of a part in deck order, nv_chunk at most; the
      ! elements of a part that ESORT sorted to another family follow in their own blocks
      ! (group 2*ip - 1: the section's family, 2*ip: sorted)
      allocate(npart(2*size(model%parts)))
      npart = 0
      do e = 1, ne
         ip = model%elem_part(e)
         grp(e) = 2*ip - 1
         if (etyp(e) /= etype_of_section(model%parts(ip)%isec)) &
            grp(e) = 2*ip
         npart(grp(e)) = npart(grp(e)) + 1
      end do
      allocate(start(size(npart) + 1), fill(size(npart)), order(ne))
      start(1) = 1
      do ip = 1, size(npart)
         start(ip + 1) = start(ip) + npart(ip)
      end do
      fill = 0
      do e = 1, ne
         ip = grp(e)
         order(start(ip) + fill(ip)) = e
         fill(ip) = fill(ip) + 1
      end do
      nb = sum((npart + nv_chunk - 1)/nv_chunk)
      allocate(model%blocks(nb))
      ib = 0
      do j = 1, size(npart)
         if (npart(j) == 0) cycle
         ip = (j + 1)/2
         associate (p => model%parts(ip))
            etype = etyp(order(start(j)))
            fam = element_family(etype)
            nip = fam%nip
            if (model%sections(p%isec)%shell) nip = fam%npl*model%sections(p%isec)%nip
            if (etype == ETYPE_BEAM_HL) nip = beam_hl_nip(p%bqr, p%bcst)   ! the section rule
            if (etype == ETYPE_BEAM_HL .and. allocated(p%brule)) nip = size(p%brule, 2)
            nhv = model%mats(p%imat)%m%nhist()
            pos = start(j)
            do while (pos < start(j + 1))
               nel = min(nv_chunk, start(j + 1) - pos)
               ib = ib + 1
               associate (b => model%blocks(ib))
                  b%ipart = ip
                  b%etype = etype
                  b%nel = nel
                  b%nip = nip
                  b%nhv = nhv
                  b%elem = order(pos:pos + nel - 1)
                  b%conn = conn(1:fam%nen, b%elem)
                  allocate(b%sig(nel, 6, nip), b%hv(nel, nhv, nip))
                  b%sig = 0.0_wp
                  b%hv = 0.0_wp
                  b%vol0 = vol(b%elem)
                  allocate(b%relvol(nel), b%eint(nel), b%ehg(nel), b%failed(nel))
                  b%relvol = 1.0_wp
                  b%eint = 0.0_wp
                  b%ehg = 0.0_wp
                  b%failed = .false.
                  ! family state: the centred-work terms; the hourglass resisting forces
                  ! (stiffness IHQ 4, 5; the last pass's viscous force of IHQ 1-3)
                  if (fam%es_ncol(ES_WORK) > 0) call b%es_add(ES_WORK, fam%es_ncol(ES_WORK))
                  if (p%qh > 0.0_wp .and. fam%es_ncol(ES_HGS) > 0) &
                     call b%es_add(ES_HGS, fam%es_ncol(ES_HGS))
                  ! erosion: the Tuler-Butcher damage (parts whose *MAT_ADD_EROSION has it)
                  if (p%ero%on .and. p%ero%impulse /= p%ero%excl .and. &
                      fam%es_ncol(ES_DMG) > 0) call b%es_add(ES_DMG, fam%es_ncol(ES_DMG))
                  ! erosion: the total strain (parts with a strain criterion)
                  if (strain_criteria(p%ero) .and. fam%es_ncol(ES_EPS) > 0) &
                     call b%es_add(ES_EPS, fam%es_ncol(ES_EPS))
                  if (fam%es_ncol(ES_THK) > 0) then   ! shells: thickness, hourglass forces
                     call b%es_add(ES_THK, fam%es_ncol(ES_THK))
                     b%es(:, b%esc(ES_THK)) = thk(b%elem)
                  end if
                  if (fam%es_ncol(ES_BEAM) > 0) then  ! beams: frame, angles, section
                     call b%es_add(ES_BEAM, fam%es_ncol(ES_BEAM))
                     do k = 1, nel
                        call beam_bs_init(b, k, bdat(1:3, b%elem(k)), bdat(4:8, b%elem(k)))
                        ! Hughes-Liu: the section's dimensions in the (unused) angle columns
                        if (etype == ETYPE_BEAM_HL) b%es(k, b%esc(ES_BEAM) + BM_TH: &
                           b%esc(ES_BEAM) + BM_TH + 1) = bdat(9:10, b%elem(k))
                     end do
                  end if
                  do k = 1, nel
                     model%elem_block(b%elem(k)) = ib
                     model%elem_pos(b%elem(k)) = k
                  end do
               end associate
               pos = pos + nel
            end do
         end associate
      end do
   contains
      !> one *ELEMENT_SHELL card e: nodes (a triangle repeats N3), area, thickness (the
      !> card's _THICKNESS values or the section's T1..T4, averaged), V0 = A t, warping
      !> warning past *CONTROL_SHELL WRPANG
      subroutine shell_element(e, lab, w, error)
         integer, intent(in) :: e, lab
         character(*), intent(in) :: w
         type(error_t), allocatable, intent(out) :: error
         real(wp) :: a, t4(4), tm
         integer :: kk, jj
         character(:), allocatable :: tf
         type(family_t) :: f2
         do kk = 1, 4
            conn(kk, e) = mp%node%get(inp%elem_conn(kk, e))
            if (conn(kk, e) == 0) then
               call set_error(error, w//'element '//str(lab)//': field N'//str(kk)// &
                              ': node '//str(inp%elem_conn(kk, e))//' is not defined (*NODE)')
               return
            end if
         end do
         conn(5:, e) = conn(4, e)
         do kk = 2, 4
            do jj = 1, kk - 1
               if (conn(kk, e) == conn(jj, e) .and. .not. (kk == 4 .and. jj == 3)) then
                  call set_error(error, w//'element '//str(lab)//': node '// &
                     str(inp%elem_conn(kk, e))//' appears twice (N'//str(jj)//' and N'// &
                     str(kk)//'): a shell is a quadrilateral or a triangle N4 = N3')
                  return
               end if
            end do
         end do
         etyp(e) = etype_of_section(model%parts(model%elem_part(e))%isec)
         f2 = element_family(etyp(e))
         if (etyp(e) == ETYPE_SHELL_FI .and. conn(4, e) == conn(3, e)) then
            ! LS-DYNA treats a degenerate quadrilateral of ELFORM 16 as a C0 triangle only
            ! with *CONTROL_SHELL ESORT = 1 (refused here): no triangle form of type 16 yet
            call set_error(error, w//'element '//str(lab)//': field N4: a triangle (N4 = '// &
               'N3) in part '//str(model%parts(model%elem_part(e))%label)//' of *SECTION_'// &
               'SHELL ELFORM 16 (fully integrated) is not supported: give the triangles a '// &
               'part of ELFORM 2 (the degenerate Belytschko-Lin-Tsay shell)')
            return
         end if
         if (f2%twod) then
            call twod_element(inp, model, conn(1:4, e), e, etyp(e), lab, w, f2%axisym, vol(e), &
                              error)
            if (allocated(thk)) thk(e) = 0.0_wp
            if (allocated(error) .or. f2%es_ncol(ES_THK) == 0) return
         end if   ! plane stress (ELFORM 12) goes on to its thickness
         t4 = inp%elem_thk(:, e)
         tf = 'THIC1'
         if (t4(1) == 0.0_wp) then
            t4 = model%sections(model%parts(model%elem_part(e))%isec)%t
            tf = 'T1 of section '//str(model%sections(model%parts(model%elem_part(e))%isec)%label)
         end if
         if (conn(4, e) == conn(3, e)) then
            tm = sum(t4(1:3))/3.0_wp
         else
            tm = 0.25_wp*sum(t4)
         end if
         if (.not. (tm > 0.0_wp)) then
            call set_error(error, w//'element '//str(lab)//': field '//tf//': the shell '// &
               'thickness must be > 0, got '//rstr(tm))
            return
         end if
         if (f2%twod) then        ! plane stress: V0 = A t
            thk(e) = tm
            vol(e) = vol(e)*tm
            return
         end if
         a = shell_area(model%x0(:, conn(1:4, e)))
         if (.not. (a > 0.0_wp)) then
            call set_error(error, w//'element '//str(lab)//' has zero area at t = 0 '// &
               '(check its nodes N1..N4)')
            return
         end if
         thk(e) = tm
         vol(e) = a*tm
         call elem_quality(etyp(e), model%x0(:, conn(1:4, e)), vol(e), asp, warp, cj, kc)
         if (warp > inp%ctrl%wrpang) then
            nshw = nshw + 1
            if (nshw <= NLIST) call log_warn(w//'shell element '//str(lab)//' is warped by '// &
               rstr(warp)//' degrees (above *CONTROL_SHELL WRPANG '//rstr(inp%ctrl%wrpang)// &
               '; the shells of ELFORM 2 and 16 have no warping correction)')
         end if
      end subroutine shell_element

      !> the element type of the part's section (dense section index isec)
      integer function etype_of_section(isec)
         integer, intent(in) :: isec
         if (model%sections(isec)%shell) then
            etype_of_section = etype_of_shell_elform(model%sections(isec)%elform)
         else if (model%sections(isec)%beam) then
            etype_of_section = etype_of_beam_elform(model%sections(isec)%elform)
         else
            etype_of_section = etype_of_elform(model%sections(isec)%elform)
         end if
      end function etype_of_section
   end subroutine build_elements



   !> Whether the erosion criteria of a part use the total strain (dx_erosion).
   pure logical function strain_criteria(e)
      type(erosion_t), intent(in) :: e
      strain_criteria = e%on .and. (e%mneps /= e%excl .or. e%effeps /= e%excl .or. &
                                    e%mxeps /= e%excl .or. e%epssh /= e%excl)
   end function strain_criteria
end module dx_model_build
