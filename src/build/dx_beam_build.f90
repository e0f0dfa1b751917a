!> Model build of the beam and discrete-mass keywords (dx_read_beams): the parts with a
!> *SECTION_BEAM (ELFORM 2 resultant beams, dx_beam_bs: elastic *MAT_ELASTIC only; ELFORM 1
!> Hughes-Liu beams, dx_beam_hl: *MAT_ELASTIC, *MAT_003, *MAT_024 at the section points), each
!> *ELEMENT_BEAM's nodes, length, section and initial frame (the orientation node N3, the
!> _ORIENTATION vector, or the default, the global z axis: a beam along z without N3 or a
!> vector has no usable orientation and is an input error),
!> and the point masses and rotary inertias of *ELEMENT_MASS, *ELEMENT_INERTIA and the
!> section's non-structural mass NSM (model%node_mass, model%node_rinert).
!> (The default orientation when N3 = 0 and no vector is given is dynx's choice: the s axis
!> in the plane of the beam and the global z axis.)
module dx_beam_build
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_log, only: log_warn
   use dx_model, only: model_t, part_t, section_t
   use dx_model_input, only: model_input_t
   use dx_element_types, only: etype_of_beam_elform, ETYPE_BEAM_HL
   use dx_beam_bs, only: beam_bs_axes
   use dx_beam_hl, only: beam_hl_section
   use dx_material, only: has_lamina_form
   use dx_build_common, only: maps_t, at, at_line
   implicit none
   private
   public :: beam_part, beam_index, beam_element, build_point_masses, section_kind, &
             KIND_NAMES, KIND_CARDS, BEAM_NDAT

   !> section kinds (section_kind) and their keywords
   character(len=14), parameter :: KIND_NAMES(0:2) = ['*SECTION_SOLID', '*SECTION_SHELL', &
                                                      '*SECTION_BEAM ']
   character(len=14), parameter :: KIND_CARDS(0:2) = ['*ELEMENT_SOLID', '*ELEMENT_SHELL', &
                                                      '*ELEMENT_BEAM ']
   !> set-up data of one beam (bdat(:, e)): e2 (3), A ISS ITT J SA (5), the Hughes-Liu
   !> section's mean dimensions (2: TS TT or D d; 0 for ELFORM 2)
   integer, parameter :: BEAM_NDAT = 10

contains

   !> 0 solid, 1 shell, 2 beam section
   pure integer function section_kind(s)
      type(section_t), intent(in) :: s
      section_kind = 0
      if (s%shell) section_kind = 1
      if (s%beam) section_kind = 2
   end function section_kind

   !> A part with a *SECTION_BEAM: its section values, and what beams do not have yet
   !> (other materials than *MAT_ELASTIC, rigid beams, mass scaling).
   subroutine beam_part(inp, model, p, w, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(part_t), intent(inout) :: p
      character(*), intent(in) :: w
      type(error_t), allocatable, intent(out) :: error
      integer :: k, n, first, nrule
      real(wp) :: hs, ht
      associate (sec => model%sections(p%isec), m => model%mats(p%imat)%m)
         p%bsec = sec%bprop(1:5)
         if (etype_of_beam_elform(sec%elform) == ETYPE_BEAM_HL) then
            if (sec%qr < 0) then       ! the user rule -QR of *INTEGRATION_BEAM
               nrule = 0        ! (merge would evaluate size() of an unallocated array)
               if (allocated(inp%brules)) nrule = size(inp%brules)
               do k = 1, nrule
                  if (inp%brules(k)%irid /= -sec%qr) cycle
                  p%brule = inp%brules(k)%pts
                  p%bra = inp%brules(k)%ra
                  exit
               end do
               if (.not. allocated(p%brule)) then
                  call set_error(error, at(inp, inp%section_src(p%isec))//'field QR/IRID: '// &
                     'section '//str(sec%label)//' uses the user integration rule '// &
                     str(-sec%qr)//', which no *INTEGRATION_BEAM defines')
                  return
               end if
               call beam_hl_section(sec%cst, 0.5_wp*(sec%bprop(1) + sec%bprop(2)), &
                                    0.5_wp*(sec%bprop(3) + sec%bprop(4)), p%bsec, hs, ht, &
                                    p%brule, p%bra, loc=sec%bloc)
            else
               call beam_hl_section(sec%cst, 0.5_wp*(sec%bprop(1) + sec%bprop(2)), &
                                    0.5_wp*(sec%bprop(3) + sec%bprop(4)), p%bsec, hs, ht, &
                                    loc=sec%bloc)
            end if
            p%bqr = sec%qr
            p%bloc = sec%bloc
            p%bcst = sec%cst
            p%shrf = sec%shrf
         end if
         ! the default orientation matters when the section is not symmetric: one note
         if (p%bsec(2) /= p%bsec(3)) then
            n = 0; first = 0
            do k = 1, inp%nbeam
               if (inp%beams(k)%n3 /= 0 .or. inp%beams(k)%has_v) cycle
               if (inp%elem_pid(inp%beams(k)%e) /= p%label) cycle
               n = n + 1
               if (first == 0) first = inp%elem_label(inp%beams(k)%e)
            end do
            if (n > 0) call log_warn(w//'part '//str(p%label)//': '//str(n)//' beams (the '// &
               'first: element '//str(first)//') have no orientation node (N3 = 0) nor '// &
               'vector: their s axis is taken in the plane of the beam and the global z '// &
               'axis (ISS /= ITT: the orientation matters)')
         end if
         if (etype_of_beam_elform(sec%elform) == 0) then
            call set_error(error, w//'part '//str(p%label)//': field SECID: beam formulation '// &
               str(sec%elform)//' is not supported (supported: 2)')
            return
         end if
         if (m%is_rigid) then
            call set_error(error, w//'part '//str(p%label)//': field MID: rigid beams '// &
               '(*MAT_RIGID on a *SECTION_BEAM part) are not supported yet')
            return
         end if
         if (etype_of_beam_elform(sec%elform) == ETYPE_BEAM_HL) then
            if ((m%mtype /= 1 .and. m%mtype /= 3 .and. m%mtype /= 24) .or. &
                .not. has_lamina_form(m)) then
               call set_error(error, w//'part '//str(p%label)//': field MID: material '// &
                  str(p%mid)//' (type '//str(m%mtype)//') on a *SECTION_BEAM ELFORM 1 part '// &
                  'has no beam section-point update here (supported: *MAT_ELASTIC, '// &
                  '*MAT_PLASTIC_KINEMATIC, *MAT_PIECEWISE_LINEAR_PLASTICITY without VP = 1)')
               return
            end if
         else if (m%mtype /= 1) then
            call set_error(error, w//'part '//str(p%label)//': field MID: material '// &
               str(p%mid)//' (type '//str(m%mtype)//') on a *SECTION_BEAM ELFORM 2 part: '// &
               'the resultant beam is elastic here (supported: *MAT_ELASTIC, type 1)')
            return
         end if
         if (inp%ctrl%dt2ms /= 0.0_wp) then
            call set_error(error, at(inp, inp%timestep_src)//'field DT2MS: mass scaling '// &
               '(DT2MS = '//rstr(inp%ctrl%dt2ms)//') is not yet available for decks with '// &
               'beams (part '//str(p%label)//'): their rotary inertia would not be scaled; '// &
               'set DT2MS = 0')
            return
         end if
      end associate
   end subroutine beam_part

   !> bof(e): the beam record of element e of the input list (0: not a beam card);
   !> not allocated when the deck has no beams.
   subroutine beam_index(inp, bof)
      type(model_input_t), intent(in) :: inp
      integer, allocatable, intent(out) :: bof(:)
      integer :: k
      if (inp%nbeam == 0) return
      allocate(bof(inp%ne))
      bof = 0
      do k = 1, inp%nbeam
         bof(inp%beams(k)%e) = k
      end do
   end subroutine beam_index

   !> One *ELEMENT_BEAM (element e of the input list, beam record kb): its nodes conn(1:2),
   !> the volume A L0 and the set-up data bdat (e2, the element's A ISS ITT J SA: the
   !> _THICKNESS values where given, else the section's). w: "file:line: *ELEMENT_BEAM: ".
   subroutine beam_element(inp, model, mp, e, kb, w, conn, vol, bdat, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(maps_t), intent(in) :: mp
      integer, intent(in) :: e, kb
      character(*), intent(in) :: w
      integer, intent(out) :: conn(:)
      real(wp), intent(out) :: vol, bdat(BEAM_NDAT)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, n3, lab
      real(wp) :: l0, vo(3), sec(5), e2(3), dm(4), hs, ht
      logical :: ok
      character(:), allocatable :: how
      lab = inp%elem_label(e)
      do k = 1, 2
         conn(k) = mp%node%get(inp%elem_conn(k, e))
         if (conn(k) == 0) then
            call set_error(error, w//'element '//str(lab)//': field N'//str(k)//': node '// &
                           str(inp%elem_conn(k, e))//' is not defined (*NODE)')
            return
         end if
      end do
      conn(3:) = conn(2)
      if (conn(1) == conn(2)) then
         call set_error(error, w//'element '//str(lab)//': field N2: node '// &
            str(inp%elem_conn(2, e))//' is N1 too (a beam needs two distinct nodes)')
         return
      end if
      l0 = norm2(model%x0(:, conn(2)) - model%x0(:, conn(1)))
      if (.not. (l0 > 0.0_wp)) then
         call set_error(error, w//'element '//str(lab)//' has zero length at t = 0 '// &
                        '(N1 and N2 at the same place)')
         return
      end if
      associate (b => inp%beams(kb), s => model%sections(model%parts(model%elem_part(e))%isec))
         if (b%n3 > 0) then
            n3 = mp%node%get(b%n3)
            if (n3 == 0) then
               call set_error(error, w//'element '//str(lab)//': field N3: node '// &
                              str(b%n3)//' is not defined (*NODE)')
               return
            end if
            vo = model%x0(:, n3) - model%x0(:, conn(1))
            how = 'field N3: orientation node '//str(b%n3)//' lies on the beam axis N1-N2'
         else if (b%has_v) then
            vo = b%v
            how = 'fields VX VY VZ: the orientation vector is parallel to the beam axis N1-N2'
         else
            vo = [0.0_wp, 0.0_wp, 1.0_wp]
            how = 'field N3: no orientation node (N3 = 0) and the default orientation, '// &
                  'the global z axis, is parallel to the beam axis N1-N2: give N3 or an '// &
                  '_ORIENTATION vector'
         end if
         call beam_bs_axes(model%x0(:, conn(1)), model%x0(:, conn(2)), vo, e2, ok)
         if (.not. ok) then
            call set_error(error, w//'element '//str(lab)//': '//how//' (a beam without '// &
                           'orientation)')
            return
         end if
         bdat(9:10) = 0.0_wp
         if (etype_of_beam_elform(s%elform) == ETYPE_BEAM_HL) then
            ! Hughes-Liu: the _THICKNESS values are TS1 TS2 TT1 TT2 (0: the section's)
            dm = s%bprop(1:4)
            do k = 1, 4
               if (b%parm(k) > 0.0_wp) dm(k) = b%parm(k)
            end do
            bdat(9) = 0.5_wp*(dm(1) + dm(2))
            bdat(10) = 0.5_wp*(dm(3) + dm(4))
            if (s%cst == 1 .and. .not. (bdat(10) < bdat(9))) then
               call set_error(error, w//'element '//str(lab)//': fields PARM1-PARM4: the '// &
                  'inner diameter is not below the outer one (tubular section, CST 1)')
               return
            end if
            associate (p => model%parts(model%elem_part(e)))
               if (allocated(p%brule)) then
                  call beam_hl_section(s%cst, bdat(9), bdat(10), sec, hs, ht, p%brule, p%bra, &
                                       loc=s%bloc)
               else
                  call beam_hl_section(s%cst, bdat(9), bdat(10), sec, hs, ht, loc=s%bloc)
               end if
            end associate
         else
            sec = s%bprop(1:5)
            do k = 1, 5
               if (b%parm(k) > 0.0_wp) sec(k) = b%parm(k)
            end do
         end if
      end associate
      vol = sec(1)*l0
      bdat(1:3) = e2
      bdat(4:8) = sec
   end subroutine beam_element

   !> The point masses and rotary inertias: *ELEMENT_MASS, *ELEMENT_INERTIA and the beams'
   !> non-structural mass NSM (half of NSM L0 at each end), into model%node_mass and
   !> model%node_rinert (allocated only when the deck has some). bof: beam_index.
   subroutine build_point_masses(inp, model, mp, bof, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      integer, allocatable, intent(in) :: bof(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, nd, b, i
      real(wp) :: nsm, l0
      if (allocated(inp%pmass)) then
         allocate(model%node_mass(model%nn))
         model%node_mass = 0.0_wp
         do k = 1, size(inp%pmass)
            associate (m => inp%pmass(k))
               nd = mp%node%get(m%nid)
               if (nd == 0) then
                  call set_error(error, at(inp, m%src)//'element '//str(m%eid)//': field NID: '// &
                                 'node '//str(m%nid)//' is not defined (*NODE)')
                  return
               end if
               model%node_mass(nd) = model%node_mass(nd) + m%mass
               if (m%inertia .and. m%ixx(1) > 0.0_wp) then
                  if (.not. allocated(model%node_rinert)) then
                     allocate(model%node_rinert(model%nn))
                     model%node_rinert = 0.0_wp
                  end if
                  model%node_rinert(nd) = model%node_rinert(nd) + m%ixx(1)
               end if
            end associate
         end do
      end if
      if (.not. allocated(bof)) return
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            nsm = model%sections(model%parts(blk%ipart)%isec)%nsm
            if (.not. model%sections(model%parts(blk%ipart)%isec)%beam) cycle
            if (nsm == 0.0_wp) cycle
            if (.not. allocated(model%node_mass)) then
               allocate(model%node_mass(model%nn))
               model%node_mass = 0.0_wp
            end if
            do i = 1, blk%nel
               l0 = norm2(model%x0(:, blk%conn(2, i)) - model%x0(:, blk%conn(1, i)))
               do k = 1, 2
                  model%node_mass(blk%conn(k, i)) = model%node_mass(blk%conn(k, i)) + &
                                                    0.5_wp*nsm*l0
               end do
            end do
         end associate
      end do
   end subroutine build_point_masses
end module dx_beam_build
