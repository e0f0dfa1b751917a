!> The model as the deck states it, before labels are resolved: every record keeps the deck
!> labels it refers to and where it came from (file index, line, keyword), so the build step
!> (dx_model_build) can report a bad reference at the card that made it.
!> Filled by the keyword readers in src/deck/, consumed (and emptied) by build_model.
module dx_model_input
   use dx_kinds, only: wp
   use dx_strings, only: string_t
   use dx_model, only: part_t, section_t, hourglass_t, control_t, erosion_t
   use dx_material, only: mat_holder_t
   use dx_eos, only: eos_holder_t
   use dx_curve, only: curve_t
   use dx_rigid_types, only: rigid_input_t
   use dx_load_body, only: body_load_in_t
   use dx_contact_input, only: contact_input_t
   use dx_run_state, only: restart_ctrl_t
   use dx_emc_types, only: emc_input_t
   implicit none
   private
   public :: input_add_part, input_finish
   !> node fields N1..N8 of an *ELEMENT_SOLID card (a family of fewer nodes repeats some)
   integer, parameter, public :: SOLID_CARD_NODES = 8
   public :: model_input_t, string_t, origin_t, label_list_t, segment_list_t, spc_in_t, &
             motion_in_t, ivel_in_t, out_note_t, set_step_in_t, set_gen_in_t, load_node_in_t, load_seg_in_t, wall_in_t, &
             IVEL_SET, IVEL_NODE, IVEL_GEN, add_node, add_element, origin, input_init, &
             beam_in_t, mass_in_t, nr2d_in_t, edge_press_in_t, deposit_in_t, &
             c2d_in_t, csys_in_t, beam_rule_in_t

   integer, parameter :: IVEL_SET = 1   !< *INITIAL_VELOCITY
   integer, parameter :: IVEL_NODE = 2  !< *INITIAL_VELOCITY_NODE
   integer, parameter :: IVEL_GEN = 3   !< *INITIAL_VELOCITY_GENERATION

   !> where a record came from: file index into model_input_t%files, line, keyword (no '*')
   type :: origin_t
      integer :: ifile = 0, line = 0
      character(:), allocatable :: key
   end type origin_t

   !> an output request dynx accepts but does not honour with a file (what, file:line)
   type :: out_note_t
      character(:), allocatable :: s, where
   end type out_note_t

   !> *SET_NODE_LIST / *SET_PART_LIST as read (labels)
   type :: label_list_t
      integer :: label = 0
      integer, allocatable :: ids(:)
      type(origin_t) :: src
   end type label_list_t

   !> one step of a generated set: op ALL, NODE, PART, BOX, SET or RANGE (a leading D in
   !> DNODE, DPART, DBOX, DSET: remove), ids the labels (RANGE: begin, end pairs)
   type :: set_step_in_t
      character(len=8) :: op = ''
      integer, allocatable :: ids(:)
      type(origin_t) :: src
   end type set_step_in_t

   !> *SET_NODE_GENERAL, *SET_NODE_LIST_GENERATE, *SET_PART_LIST_GENERATE as read: the
   !> steps are applied in order after the whole deck is read (dx_read_sets sets_finish)
   type :: set_gen_in_t
      integer :: label = 0
      logical :: nodes = .true.            !< a node set (else a part set)
      type(set_step_in_t), allocatable :: steps(:)
      type(origin_t) :: src
   end type set_gen_in_t

   !> *SET_SEGMENT as read: (4, nseg) node labels, a triangle repeats n3
   type :: segment_list_t
      integer :: label = 0
      integer, allocatable :: seg(:, :)
      type(origin_t) :: src
   end type segment_list_t

   !> *BOUNDARY_SPC_NODE/_SET record
   type :: spc_in_t
      integer :: id = 0               !< node label or node set label
      logical :: is_set = .false.
      logical :: dof(6) = .false.
      integer :: cid = 0              !< DOFX..DOFZ along the axes of *DEFINE_COORDINATE_SYSTEM cid
      real(wp) :: axes(3, 3) = 0.0_wp !< cid's axes (loads_finish), axes(:, k) local axis k
      type(origin_t) :: src
   end type spc_in_t

   !> *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET record
   type :: motion_in_t
      integer :: id = 0
      logical :: is_set = .false.
      integer :: dof = 0, vad = 0, lcid = 0
      real(wp) :: sf = 1.0_wp, death = 1.0e28_wp, birth = 0.0_wp
      type(origin_t) :: src
   end type motion_in_t

   !> one *INITIAL_VELOCITY* record
   type :: ivel_in_t
      integer :: kind = IVEL_SET
      integer :: id = 0                !< NSID / NID / generation ID
      integer :: nsidex = 0            !< *INITIAL_VELOCITY: excluded node set
      integer :: styp = 0              !< GENERATION: 1 part set, 2 part, 3 node set
      real(wp) :: v(3) = 0.0_wp        !< translational velocity
      real(wp) :: vr(3) = 0.0_wp       !< angular velocity VXR VYR VZR (_NODE; shell nodes)
      real(wp) :: vex(3) = 0.0_wp      !< velocity of the excluded nodes (NSIDEX)
      real(wp) :: omega = 0.0_wp
      real(wp) :: xc(3) = 0.0_wp, axis(3) = 0.0_wp
      integer :: icid = 0              !< v (vr, vex) given in *DEFINE_COORDINATE_SYSTEM icid
      type(origin_t) :: src
   end type ivel_in_t

   !> *DEFINE_COORDINATE_SYSTEM: axes(:,k) = local axis k in global components
   type :: csys_in_t
      integer :: id = 0
      real(wp) :: axes(3,3) = 0.0_wp
      real(wp) :: o(3) = 0.0_wp
      type(origin_t) :: src
   end type csys_in_t

   type :: load_node_in_t
      integer :: nid = 0, dof = 0, lcid = 0
      integer :: cid = 0               !< DOF along the axes of *DEFINE_COORDINATE_SYSTEM cid
      real(wp) :: sf = 1.0_wp
      type(origin_t) :: src
   end type load_node_in_t

   !> *LOAD_SEGMENT (n(1:4) node labels) or *LOAD_SEGMENT_SET (ssid)
   type :: load_seg_in_t
      integer :: n(4) = 0
      integer :: ssid = 0
      integer :: lcid = 0
      real(wp) :: sf = 1.0_wp, at = 0.0_wp
      type(origin_t) :: src
   end type load_seg_in_t

   !> *BOUNDARY_NON_REFLECTING_2D as read (dx_read_twod): node set, dilatational and shear
   !> dashpots on (LS-DYNA AD, AS = 0) or off (nonzero)
   type :: nr2d_in_t
      integer :: nsid = 0
      logical :: ad = .true., as = .true.
      type(origin_t) :: src
   end type nr2d_in_t

   !> *DYNX_PRESSURE_TABLE (kind 1; the data file's table) and *DYNX_PRESSURE_PULSE (kind 2)
   !> as read (dx_read_twod)
   type :: edge_press_in_t
      integer :: kind = 0, nsid = 0
      real(wp) :: sf = 1.0_wp
      real(wp), allocatable :: r(:), t(:), p(:, :)
      real(wp) :: pmax = 0.0_wp, t0 = 0.0_wp, fwhm = 0.0_wp, dir(2) = 0.0_wp
      type(origin_t) :: src
   end type edge_press_in_t

   !> *CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE as read (SIDS, SIDM part sets)
   type :: c2d_in_t
      integer :: sids = 0, sidm = 0, label = 0, istiff = 0
      logical :: single = .false.              !< *CONTACT_2D_AUTOMATIC_SINGLE_SURFACE
      !> *CONTACT_2D_AUTOMATIC_TIED: 1 (both sides' nodes tied), _TIED_ONE_WAY: 2 (SIDS's);
      !> TIEDGAP (card 3: 0 1 % of the edge, > 0 a length, < 0 |TIEDGAP| % of the edge), TIETYP
      integer :: tied = 0, tietyp = 0
      real(wp) :: tiedgap = 0.0_wp
      real(wp) :: sfact = 1.0_wp, fs = 0.0_wp
      type(origin_t) :: src
   end type c2d_in_t

   !> *DYNX_ENERGY_DEPOSITION as read
   type :: deposit_in_t
      integer :: pid = 0
      real(wp) :: rate = 0.0_wp, t1 = 0.0_wp, t2 = 0.0_wp
      type(origin_t) :: src
   end type deposit_in_t

   !> *RIGIDWALL_PLANAR as read
   type :: wall_in_t
      integer :: label = 0
      integer :: nsid = 0, nsidex = 0
      real(wp) :: offset = 0.0_wp
      real(wp) :: xt(3) = 0.0_wp, xh(3) = 0.0_wp
      real(wp) :: fric = 0.0_wp
      type(origin_t) :: src
   end type wall_in_t

   !> one *ELEMENT_BEAM card (dx_read_beams): the element itself is on the element list
   !> (index e, N1 N2 in its first two node fields); the orientation node N3 (0: none) or
   !> the _ORIENTATION vector v (has_v), and the _THICKNESS section values (0: the section's)
   type :: beam_in_t
      integer :: e = 0
      integer :: n3 = 0
      logical :: has_v = .false.
      real(wp) :: v(3) = 0.0_wp
      real(wp) :: parm(5) = 0.0_wp
   end type beam_in_t

   !> one *INTEGRATION_BEAM rule IRID (dx_read_beams; ICST 0, the user's points): the relative
   !> area RA and the points pts(1:3, k) = S, T, WF (normalised s, t in [-1, 1]; area fraction)
   type :: beam_rule_in_t
      integer :: irid = 0
      real(wp) :: ra = 1.0_wp
      real(wp), allocatable :: pts(:, :)
      type(origin_t) :: src
   end type beam_rule_in_t

   !> *ELEMENT_MASS (inertia = .false.) or *ELEMENT_INERTIA card: the point mass and the
   !> inertia tensor IXX IXY IXZ IYY IYZ IZZ at node nid
   type :: mass_in_t
      integer :: eid = 0, nid = 0, pid = 0, csid = 0
      logical :: inertia = .false.
      real(wp) :: mass = 0.0_wp
      real(wp) :: ixx(6) = 0.0_wp
      type(origin_t) :: src
   end type mass_in_t

   type :: model_input_t
      type(string_t), allocatable :: files(:)      !< deck file names (index = ifile)
      character(:), allocatable :: title
      ! --- nodes (grown by add_node; arrays longer than nn)
      integer :: nn = 0
      integer, allocatable :: node_label(:)
      real(wp), allocatable :: x(:, :)               !< (3, :)
      integer, allocatable :: node_tc(:), node_rc(:)  !< *NODE TC, RC constraint codes
      integer, allocatable :: node_src(:, :)         !< (2, :) ifile, line
      ! --- solid elements (grown by add_element)
      integer :: ne = 0
      integer, allocatable :: elem_label(:), elem_pid(:)
      integer, allocatable :: elem_conn(:, :)        !< (SOLID_CARD_NODES, :) node labels
      integer, allocatable :: elem_src(:, :)         !< (2, :) ifile, line
      !> (4, :) nodal thicknesses of *ELEMENT_SHELL_THICKNESS (0: the section's); allocated
      !> once a shell card is read (dx_read_shells), a shell card has N5..N8 = 0
      real(wp), allocatable :: elem_thk(:, :)
      !> *ELEMENT_BEAM extras (allocated once a beam card is read; nbeam used)
      integer :: nbeam = 0
      type(beam_in_t), allocatable :: beams(:)
      !> *ELEMENT_MASS, *ELEMENT_INERTIA (allocated once one is read)
      type(mass_in_t), allocatable :: pmass(:)
      !> *INTEGRATION_BEAM rules (allocated once one is read; matched to QR/IRID < 0 at build)
      type(beam_rule_in_t), allocatable :: brules(:)
      ! --- definitions (parts: grown by input_add_part, cut to nparts by input_finish)
      integer :: nparts = 0
      type(part_t), allocatable :: parts(:)
      type(origin_t), allocatable :: part_src(:)
      type(section_t), allocatable :: sections(:)
      type(origin_t), allocatable :: section_src(:)
      type(hourglass_t), allocatable :: hourglasses(:)
      type(origin_t), allocatable :: hourglass_src(:)
      type(mat_holder_t), allocatable :: mats(:)
      type(origin_t), allocatable :: mat_src(:)
      type(eos_holder_t), allocatable :: eoss(:)     !< *EOS_ (attached to parts by EOSID)
      type(origin_t), allocatable :: eos_src(:)
      !> *MAT_ADD_EROSION (dx_read_erosion; attached to the parts of material MID)
      type(erosion_t), allocatable :: erosions(:)
      type(origin_t), allocatable :: erosion_src(:)
      !> *DYNX_TULER_BUTCHER (mid and lambda of each card; dx_read_erosion)
      type(erosion_t), allocatable :: tb_lambdas(:)
      type(origin_t), allocatable :: tb_src(:)
      type(curve_t), allocatable :: curves(:)
      type(origin_t), allocatable :: curve_src(:)
      type(label_list_t), allocatable :: node_sets(:), part_sets(:)
      type(segment_list_t), allocatable :: segment_sets(:)
      type(set_gen_in_t), allocatable :: set_gens(:)   !< generated sets (before sets_finish)
      ! --- boundary conditions, loads, initial conditions
      type(spc_in_t), allocatable :: spcs(:)
      type(motion_in_t), allocatable :: motions(:)
      type(ivel_in_t), allocatable :: ivels(:)
      type(csys_in_t), allocatable :: csys(:)     !< *DEFINE_COORDINATE_SYSTEM
      ! --- *NODE_MERGE(_SET, _TOLERANCE) (dx_read_merge)
      integer, allocatable :: merge_nodes(:), merge_sets(:)   !< candidates: labels, node sets
      real(wp) :: merge_tol = -1.0_wp                         !< TOLR (< 0: not given)
      type(origin_t) :: merge_src                             !< the last merge keyword
      integer, allocatable :: node_alias(:, :)   !< (2, n): merged-away label, kept label
      type(load_node_in_t), allocatable :: node_loads(:)
      type(load_node_in_t), allocatable :: node_set_loads(:)  !< *LOAD_NODE_SET (nid = NSID)
      type(load_seg_in_t), allocatable :: seg_loads(:)
      type(wall_in_t), allocatable :: walls(:)
      type(body_load_in_t), allocatable :: body_loads(:)   !< *LOAD_BODY_X/Y/Z
      type(nr2d_in_t), allocatable :: nr2d(:)              !< *BOUNDARY_NON_REFLECTING_2D
      type(edge_press_in_t), allocatable :: edge_press(:)  !< *DYNX_PRESSURE_TABLE, _PULSE
      type(deposit_in_t), allocatable :: deposits(:)       !< *DYNX_ENERGY_DEPOSITION
      type(c2d_in_t), allocatable :: contacts2d(:)         !< *CONTACT_2D_AUTOMATIC_..
      type(rigid_input_t) :: rigid                         !< rigid-body keywords
      ! --- controls and output requests
      type(control_t) :: ctrl
      logical :: has_termination = .false.
      type(origin_t) :: term_src, timestep_src
      integer :: lctm = 0                  !< *CONTROL_TIMESTEP LCTM (curve label)
      real(wp) :: d3plot_dt = 0.0_wp
      integer :: d3plot_lcdt = 0           !< curve label
      integer :: d3plot_npltc = 0
      type(origin_t) :: d3plot_src
      real(wp) :: glstat_dt = 0.0_wp, nodout_dt = 0.0_wp
      real(wp) :: matsum_dt = 0.0_wp       !< *DATABASE_MATSUM DT (0: none)
      real(wp) :: spcforc_dt = 0.0_wp      !< *DATABASE_SPCFORC DT (0: none)
      real(wp) :: sleout_dt = 0.0_wp       !< *DATABASE_SLEOUT DT (0: none)
      type(label_list_t), allocatable :: hist_nodes(:)      !< *DATABASE_HISTORY_NODE cards
      type(label_list_t), allocatable :: hist_node_sets(:)  !< *DATABASE_HISTORY_NODE_SET cards
      real(wp) :: elout_dt = 0.0_wp        !< *DATABASE_ELOUT DT (0: none)
      real(wp) :: ncforc_dt = 0.0_wp       !< *DATABASE_NCFORC DT (0: none)
      type(label_list_t), allocatable :: hist_solids(:)     !< *DATABASE_HISTORY_SOLID cards
      type(contact_input_t) :: contact     !< *CONTACT_*, *CONTROL_CONTACT, *DATABASE_RCFORC
      type(restart_ctrl_t) :: rst          !< *DATABASE_BINARY_D3DUMP/RUNRSF
      type(emc_input_t) :: emc             !< conserving rigid-body contact (dx_emc_types)
      type(out_note_t), allocatable :: out_notes(:)  !< output requests not written (a note each)
   end type model_input_t

contains

   !> Empty input: every list allocated with size 0 so readers can append.
   subroutine input_init(inp)
      type(model_input_t), intent(out) :: inp
      allocate(inp%files(0), inp%parts(0), inp%part_src(0), inp%sections(0), &
               inp%section_src(0), inp%hourglasses(0), inp%hourglass_src(0), inp%mats(0), &
               inp%mat_src(0), inp%curves(0), inp%curve_src(0), inp%node_sets(0), &
               inp%part_sets(0), inp%segment_sets(0), inp%spcs(0), inp%motions(0), &
               inp%ivels(0), inp%node_loads(0), inp%seg_loads(0), inp%walls(0), &
               inp%hist_nodes(0), inp%hist_node_sets(0), inp%eoss(0), inp%eos_src(0), &
               inp%erosions(0), inp%erosion_src(0), inp%tb_lambdas(0), inp%tb_src(0), &
               inp%out_notes(0), inp%set_gens(0), inp%node_set_loads(0), inp%hist_solids(0))
      allocate(inp%body_loads(0), inp%rigid%inertias(0), inp%rigid%nrbs(0), &
               inp%rigid%extras(0), inp%rigid%motions(0))
      allocate(inp%nr2d(0), inp%edge_press(0), inp%deposits(0), inp%contacts2d(0))
      allocate(inp%node_label(0), inp%x(3, 0), inp%node_tc(0), inp%node_rc(0), &
               inp%node_src(2, 0))
      allocate(inp%elem_label(0), inp%elem_pid(0), inp%elem_conn(SOLID_CARD_NODES, 0), &
               inp%elem_src(2, 0))
   end subroutine input_init

   !> Append part p read at src (the arrays grow by doubling: 20 000 *PART blocks took
   !> 25 s of CPU when each appended by reallocation).
   subroutine input_add_part(inp, p, src)
      type(model_input_t), intent(inout) :: inp
      type(part_t), intent(in) :: p
      type(origin_t), intent(in) :: src
      type(part_t), allocatable :: gp(:)
      type(origin_t), allocatable :: gs(:)
      integer :: k
      if (inp%nparts == size(inp%parts)) then
         allocate(gp(max(8, 2*inp%nparts)), gs(max(8, 2*inp%nparts)))
         do k = 1, inp%nparts
            gp(k) = inp%parts(k)
            gs(k) = inp%part_src(k)
         end do
         call move_alloc(gp, inp%parts)
         call move_alloc(gs, inp%part_src)
      end if
      inp%nparts = inp%nparts + 1
      inp%parts(inp%nparts) = p
      inp%part_src(inp%nparts) = src
   end subroutine input_add_part

   !> After the last keyword: the grown lists cut to their lengths.
   subroutine input_finish(inp)
      type(model_input_t), intent(inout) :: inp
      if (size(inp%parts) /= inp%nparts) then
         inp%parts = inp%parts(1:inp%nparts)
         inp%part_src = inp%part_src(1:inp%nparts)
      end if
   end subroutine input_finish

   !> An origin record for keyword key at (ifile, line).
   pure function origin(ifile, line, key) result(o)
      integer, intent(in) :: ifile, line
      character(*), intent(in) :: key
      type(origin_t) :: o
      o%ifile = ifile
      o%line = line
      o%key = key
   end function origin

   !> Append one *NODE record (capacity doubles).
   subroutine add_node(inp, label, x, tc, rc, ifile, line)
      type(model_input_t), intent(inout) :: inp
      integer, intent(in) :: label, tc, rc, ifile, line
      real(wp), intent(in) :: x(3)
      integer :: cap
      if (size(inp%node_label) == 0) then
         cap = 1024
         deallocate(inp%node_label, inp%x, inp%node_tc, inp%node_rc, inp%node_src)
         allocate(inp%node_label(cap), inp%x(3, cap), inp%node_tc(cap), inp%node_rc(cap), &
                  inp%node_src(2, cap))
      else if (inp%nn == size(inp%node_label)) then
         cap = 2*size(inp%node_label)
         call grow_i1(inp%node_label, cap)
         call grow_r2(inp%x, cap)
         call grow_i1(inp%node_tc, cap)
         call grow_i1(inp%node_rc, cap)
         call grow_i2(inp%node_src, cap)
      end if
      inp%nn = inp%nn + 1
      inp%node_label(inp%nn) = label
      inp%x(:, inp%nn) = x
      inp%node_tc(inp%nn) = tc
      inp%node_rc(inp%nn) = rc
      inp%node_src(:, inp%nn) = [ifile, line]
   end subroutine add_node

   !> Append one *ELEMENT_SOLID record (capacity doubles).
   subroutine add_element(inp, label, pid, conn, ifile, line)
      type(model_input_t), intent(inout) :: inp
      integer, intent(in) :: label, pid, conn(SOLID_CARD_NODES), ifile, line
      integer :: cap
      if (size(inp%elem_label) == 0) then
         cap = 1024
         deallocate(inp%elem_label, inp%elem_pid, inp%elem_conn, inp%elem_src)
         allocate(inp%elem_label(cap), inp%elem_pid(cap), &
                  inp%elem_conn(SOLID_CARD_NODES, cap), &
                  inp%elem_src(2, cap))
      else if (inp%ne == size(inp%elem_label)) then
         cap = 2*size(inp%elem_label)
         call grow_i1(inp%elem_label, cap)
         call grow_i1(inp%elem_pid, cap)
         call grow_i2(inp%elem_conn, cap)
         call grow_i2(inp%elem_src, cap)
      end if
      inp%ne = inp%ne + 1
      inp%elem_label(inp%ne) = label
      inp%elem_pid(inp%ne) = pid
      inp%elem_conn(:, inp%ne) = conn
      inp%elem_src(:, inp%ne) = [ifile, line]
   end subroutine add_element

   subroutine grow_i1(a, cap)
      integer, allocatable, intent(inout) :: a(:)
      integer, intent(in) :: cap
      integer, allocatable :: t(:)
      allocate(t(cap))
      t(1:size(a)) = a
      call move_alloc(t, a)
   end subroutine grow_i1

   subroutine grow_i2(a, cap)
      integer, allocatable, intent(inout) :: a(:, :)
      integer, intent(in) :: cap
      integer, allocatable :: t(:, :)
      allocate(t(size(a, 1), cap))
      t(:, 1:size(a, 2)) = a
      call move_alloc(t, a)
   end subroutine grow_i2

   subroutine grow_r2(a, cap)
      real(wp), allocatable, intent(inout) :: a(:, :)
      integer, intent(in) :: cap
      real(wp), allocatable :: t(:, :)
      allocate(t(size(a, 1), cap))
      t(:, 1:size(a, 2)) = a
      call move_alloc(t, a)
   end subroutine grow_r2
end module dx_model_input
