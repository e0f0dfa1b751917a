!> The model a deck builds and the solver advances: nodes, element blocks, parts, sets, curves,
!> boundary conditions, loads, controls, output requests, and the nodal state.
!> IDs from the deck are labels; everything here is indexed densely from 1. The label arrays
!> (node_label, elem_label, parts(:)%label, ...) are kept for messages and output.
module dx_model
   use dx_kinds, only: wp, nv_chunk
   use dx_contact2d_types, only: contact2d_t
   use dx_strings, only: string_t
   use dx_material, only: mat_holder_t
   use dx_curve, only: curve_t
   use dx_rigid_types, only: rigid_system_t
   use dx_load_body, only: body_load_t
   use dx_contact_types, only: contact_set_t
   use dx_run_state, only: run_state_t, restart_ctrl_t
   use dx_emc_types, only: emc_system_t
   use dx_element_types, only: elem_quality, ASPECT_WARN, WARP_WARN, shell_stress_global
   use dx_element_types, only: elem_stress_global, beam_resultants, ETYPE_BEAM_BS, is_beam
   use dx_element_types, only: elem_block_t, part_t, family_t, element_family, elem_volume, elem_moments, elem_length, &
                               etype_of_elform, solid_shape, MAX_NEN, MAX_FACE_NODES, &
                               MAX_FACES, ETYPE_DEFAULT, ETYPES, ES_WORK, ES_HGS, ES_PHIM, &
                               ES_DMG, ES_EPS, erosion_t, MAX_ES, ES_NAMES, ES_DUMP, WORK_Q, &
                               WORK_QBV, WORK_DT, &
                               WORK_PN, ES_THK, ETYPE_SHELL_BT, etype_of_shell_elform
   implicit none
   private
   public :: model_t, section_t, hourglass_t, node_set_t, part_set_t, &
             segment_set_t, spc_t, prescribed_t, load_node_t, load_segment_t, rigidwall_t, &
             control_t, database_t, energy_t, part_sums_t
   !> the element block and the part (dx_element_types, the kernels' types; held here)
   public :: elem_block_t, part_t, edge_pressure_t, deposit_t
   !> the element-family table (dx_element_types): what every consumer asks of a block's
   !> element type (nodes, faces, edges, volume, moments, lumped mass, plot cell, weight)
   public :: elem_quality, ASPECT_WARN, WARP_WARN, shell_stress_global, elem_stress_global
   public :: beam_resultants, ETYPE_BEAM_BS, is_beam
   public :: family_t, element_family, elem_volume, elem_moments, elem_length, etype_of_elform, &
             solid_shape, MAX_NEN, MAX_FACE_NODES, MAX_FACES, ETYPES
   !> the family-state slots of a block's es array (dx_element_types)
   public :: ES_WORK, ES_HGS, ES_PHIM, ES_DMG, ES_EPS, MAX_ES, ES_NAMES, ES_DUMP, WORK_Q, &
             WORK_QBV, &
             WORK_DT, WORK_PN, erosion_t
   !> the shell thickness slot and the BT shell type (the plot's thickness field)
   public :: ES_THK, ETYPE_SHELL_BT, etype_of_shell_elform

   !> *SECTION_SOLID or *SECTION_SHELL (shell = .true.; the shell fields of
   !> dx_read_shells with their LS-DYNA meaning)
   type :: section_t
      integer :: label = 0
      character(:), allocatable :: title
      integer :: elform = 1
      integer :: aet = 0
      logical :: shell = .false.
      real(wp) :: shrf = 1.0_wp        !< transverse shear factor
      integer :: nip = 2               !< through-thickness points
      integer :: intgrd = 0            !< 0 Gauss, 1 Lobatto (*CONTROL_SHELL INTGRD)
      real(wp) :: t(4) = 0.0_wp        !< nodal thicknesses T1..T4
      !> *SECTION_BEAM (beam = .true.; dx_read_beams): ELFORM 2's A, ISS, ITT, J, SA, IST
      logical :: beam = .false.
      real(wp) :: bprop(6) = 0.0_wp
      real(wp) :: nsm = 0.0_wp         !< non-structural mass per length (beams)
      !> ELFORM 1 (Hughes-Liu): bprop(1:4) = TS1 TS2 TT1 TT2 (CST 0) or the outer and inner
      !> diameters D1 D2 d1 d2 (CST 1); the section rule QR and the type CST
      integer :: qr = 2, cst = 0
      !> ELFORM 1: NSLOC, NTLOC, the reference line (the nodes) at s = NSLOC TS/2, t = NTLOC TT/2
      !> of the section (-1, 0, 1)
      real(wp) :: bloc(2) = 0.0_wp
   end type section_t

   !> *HOURGLASS (a negative or zero value means: take the *CONTROL_* default)
   type :: hourglass_t
      integer :: label = 0
      integer :: ihq = 0
      real(wp) :: qm = -1.0_wp
      integer :: ibq = 0
      real(wp) :: q1 = -1.0_wp, q2 = -1.0_wp
      real(wp) :: qb = -1.0_wp, qw = -1.0_wp
   end type hourglass_t

   type :: node_set_t
      integer :: label = 0
      integer, allocatable :: nodes(:)       !< dense node indices
   end type node_set_t

   type :: part_set_t
      integer :: label = 0
      integer, allocatable :: parts(:)       !< dense part indices
   end type part_set_t

   type :: segment_set_t
      integer :: label = 0
      integer, allocatable :: seg(:, :)      !< (4, nseg) dense nodes; a triangle repeats n3
   end type segment_set_t

   !> one constrained node (*BOUNDARY_SPC_*): dof(1:3) translations, dof(4:6) rotations
   type :: spc_t
      integer :: node = 0
      logical :: dof(6) = .false.
   end type spc_t

   !> *BOUNDARY_PRESCRIBED_MOTION_NODE/_SET, one per node
   type :: prescribed_t
      integer :: node = 0
      integer :: dof = 0            !< LS-DYNA DOF code: 1,2,3 = x,y,z; 4 = along dir
      integer :: vad = 0            !< 0 velocity, 1 acceleration, 2 displacement
      integer :: curve = 0          !< dense curve index
      real(wp) :: sf = 1.0_wp
      real(wp) :: dir(3) = 0.0_wp   !< unit direction (dof 1..3 give the axis)
      real(wp) :: death = 1.0e28_wp, birth = 0.0_wp
   end type prescribed_t

   !> *LOAD_NODE_POINT: force on node along dof 1..3 (4..6: moments, not on solids)
   type :: load_node_t
      integer :: node = 0
      integer :: dof = 0
      integer :: curve = 0
      real(wp) :: sf = 1.0_wp
   end type load_node_t

   !> *LOAD_SEGMENT(_SET): pressure p(t) = sf*curve(t - at) on a 3/4-node segment;
   !> positive pressure acts against the segment normal (right-hand rule on n1..n4)
   type :: load_segment_t
      integer :: nodes(4) = 0
      integer :: curve = 0
      real(wp) :: sf = 1.0_wp
      real(wp) :: at = 0.0_wp
   end type load_segment_t

   !> *DYNX_PRESSURE_TABLE (kind 1: p(r, t) bilinear in a table) and *DYNX_PRESSURE_PULSE
   !> (kind 2: pmax exp(-4 ln2 ((t - t0)/fwhm)**2) cos**2 theta) on the free edges of a 2D
   !> node set, at the edges' t = 0 geometry (dx_build_twod; applied by dx_edge_pressure):
   !> node share k gets the force p(edge(k), t) w(:, k) (w = -weight x outward normal)
   type :: edge_pressure_t
      integer :: kind = 0
      real(wp), allocatable :: r(:), t(:), p(:, :)   !< table: radii (nr), times (nt), (nr, nt)
      real(wp) :: pmax = 0.0_wp, t0 = 0.0_wp, fwhm = 1.0_wp
      real(wp), allocatable :: re(:)      !< (nedge) the edge's radius x at its midpoint (table)
      real(wp), allocatable :: ce(:)      !< (nedge) cos**2 theta of the edge (pulse)
      integer, allocatable :: node(:)     !< (nshare) node of each nodal share
      integer, allocatable :: edge(:)     !< (nshare) its edge
      real(wp), allocatable :: w(:, :)    !< (2, nshare) force per unit pressure
   end type edge_pressure_t

   !> *DYNX_ENERGY_DEPOSITION: energy into part ipart at a constant rate over [t1, t2], shared
   !> among its elements by initial volume (vpart: the part's initial volume, all ranks)
   type :: deposit_t
      integer :: ipart = 0
      real(wp) :: rate = 0.0_wp, t1 = 0.0_wp, t2 = 0.0_wp, vpart = 0.0_wp
   end type deposit_t

   !> *RIGIDWALL_PLANAR (stonewall): fixed infinite plane through x0 with unit normal n
   !> pointing into the allowed half space
   type :: rigidwall_t
      integer :: label = 0
      integer, allocatable :: nodes(:)     !< slave nodes (dense)
      real(wp) :: x0(3) = 0.0_wp, n(3) = [0.0_wp, 0.0_wp, 1.0_wp]
      real(wp) :: fric = 0.0_wp
      real(wp) :: force(3) = 0.0_wp        !< resultant force on the wall, last cycle
   end type rigidwall_t

   !> *CONTROL_IMPLICIT_GENERAL and *CONTROL_IMPLICIT_DYNAMICS, with their LS-DYNA meaning:
   !> IMFLAG (0 explicit, 1 implicit, 2 explicit then implicit springback), DT0 (the implicit
   !> step), the Newmark GAMMA, BETA and the HHT ALPHA (Hilber, Hughes & Taylor 1977,
   !> Earthq. Eng. Struct. Dyn. 5:283-292; LS-DYNA's sign, -1/3 <= ALPHA <= 0) and the
   !> high-frequency spectral radius rho_inf they ask for (1: no numerical damping).
   !> ifile, line: where IMFLAG was read (messages; line 0: no *CONTROL_IMPLICIT_GENERAL).
   !> The Newton solver's *CONTROL_IMPLICIT_SOLUTION (NSOLVR 1 linear, else full Newton;
   !> ILIMIT, MAXREF, DCTOL, ECTOL, RCTOL, LSTOL, ABSTOL with LS-DYNA's defaults) and
   !> *CONTROL_IMPLICIT_AUTO (IAUTO, ITEOPT, ITEWIN, DTMIN, DTMAX; 0: DT0/1000 and 10 DT0).
   type :: implicit_ctrl_t
      integer :: imflag = 0
      real(wp) :: dt0 = 0.0_wp
      real(wp) :: gamma = 0.5_wp, beta = 0.25_wp, alpha = 0.0_wp, rho_inf = 1.0_wp
      integer :: ifile = 0, line = 0
      integer :: nsolvr = 12, ilimit = 11, maxref = 15
      real(wp) :: dctol = 1.0e-3_wp, ectol = 1.0e-2_wp, rctol = 1.0e10_wp
      real(wp) :: lstol = 0.9_wp, abstol = 1.0e-10_wp
      integer :: iauto = 0, iteopt = 11, itewin = 5
      real(wp) :: dtmin = 0.0_wp, dtmax = 0.0_wp
      logical :: dynamic = .false.      !< *CONTROL_IMPLICIT_DYNAMICS given (IMASS = 1)
      !> *CONTROL_IMPLICIT_EIGENVALUE: NEIG modes (0: no eigenvalue run) nearest the CENTER
      !> frequency (cycles per unit time), SHFSCL the shift scale (a frequency; 0: dynx's
      !> automatic shift when the stiffness is singular); where NEIG was read
      integer :: neig = 0
      real(wp) :: center = 0.0_wp, shfscl = 0.0_wp
      integer :: eig_ifile = 0, eig_line = 0
   end type implicit_ctrl_t

   !> *CONTROL_TERMINATION, *CONTROL_TIMESTEP, *CONTROL_HOURGLASS, *CONTROL_BULK_VISCOSITY,
   !> *CONTROL_IMPLICIT_GENERAL/_DYNAMICS (imp)
   type :: control_t
      real(wp) :: endtim = 0.0_wp
      integer :: endcyc = 0
      real(wp) :: dtmin = 0.0_wp        !< fraction of the initial step below which the run stops
      real(wp) :: endeng = 0.0_wp, endmas = 0.0_wp
      real(wp) :: dtinit = 0.0_wp
      real(wp) :: tssfac = 0.9_wp
      integer :: isdo = 0
      real(wp) :: tslimt = 0.0_wp
      real(wp) :: dt2ms = 0.0_wp        !< mass scaling (dx_mass_scaling): < 0 floor, > 0 all
      integer :: ms1st = 0              !< 1: mass scaling at the first cycle only
      integer :: lctm = 0               !< dense curve index limiting dt (0: none)
      integer :: erode = 0
      integer :: ihq = 1
      real(wp) :: qh = 0.1_wp
      real(wp) :: q1 = 1.5_wp, q2 = 0.06_wp
      integer :: ibq = 1
      integer :: esort = 0              !< *CONTROL_SOLID ESORT: >= 1 sorts degenerate tetrahedra
      !> *CONTROL_SHELL (dx_read_shells): warping warning angle (degrees), thickness update
      !> (0 none, 1 membrane straining), rotary inertia scale, through-thickness rule
      !> (0 Gauss, 1 Lobatto), plane-stress plasticity option
      real(wp) :: wrpang = 20.0_wp
      integer :: istupd = 0
      real(wp) :: rotascl = 1.0_wp
      integer :: intgrd = 0
      integer :: miter = 1
      type(implicit_ctrl_t) :: imp      !< the implicit controls (integrator choice, dx_solver)
   end type control_t

   !> output requests
   type :: database_t
      real(wp) :: d3plot_dt = 0.0_wp    !< 0: no plot states beyond first and last
      integer :: d3plot_lcdt = 0
      real(wp) :: glstat_dt = 0.0_wp    !< 0: no glstat file
      real(wp) :: nodout_dt = 0.0_wp    !< 0: no nodout file
      real(wp) :: matsum_dt = 0.0_wp    !< 0: no matsum file (*DATABASE_MATSUM)
      real(wp) :: spcforc_dt = 0.0_wp   !< 0: no spcforc file (*DATABASE_SPCFORC)
      real(wp) :: sleout_dt = 0.0_wp    !< 0: no sleout file (*DATABASE_SLEOUT)
      integer, allocatable :: hist_nodes(:)   !< dense node indices for nodout
      real(wp) :: elout_dt = 0.0_wp     !< 0: no elout file (*DATABASE_ELOUT)
      real(wp) :: ncforc_dt = 0.0_wp    !< 0: no ncforc file (*DATABASE_NCFORC)
      !> *DATABASE_HISTORY_SOLID: dense elements, their ids and part ids (for elout)
      integer, allocatable :: hist_solids(:), hist_solid_id(:), hist_solid_pid(:)
      !> elout's values at the output time: (7, size(hist_solids)) the element-average
      !> stress xx yy zz xy yz zx and effective plastic strain (dx_elout elout_values)
      real(wp), allocatable :: elout_vals(:, :)
   end type database_t

   !> global energies and momentum (glstat)
   type :: energy_t
      real(wp) :: kinetic = 0.0_wp
      real(wp) :: internal = 0.0_wp
      real(wp) :: hourglass = 0.0_wp
      real(wp) :: external_work = 0.0_wp
      real(wp) :: rigidwall = 0.0_wp    !< energy taken by rigid walls (positive = absorbed)
      real(wp) :: sliding = 0.0_wp      !< sliding interface energy: -(work of contact forces)
      real(wp) :: total = 0.0_wp        !< kinetic + internal + hourglass
      real(wp) :: initial = 0.0_wp      !< total at t = 0
      real(wp) :: ratio = 1.0_wp        !< (total + rigidwall + sliding) / (initial + ext. work)
      real(wp) :: momentum(3) = 0.0_wp
      real(wp) :: mass = 0.0_wp
      real(wp) :: added_mass = 0.0_wp   !< mass added by mass scaling (DT2MS), whole model
      !> element erosion (dx_erosion): the internal energy of the eroded elements and the
      !> kinetic energy of the nodes no element holds any more; as in LS-DYNA's glstat they
      !> are parts of internal and kinetic (so of total and of the ratio), reported apart
      real(wp) :: eroded_ie = 0.0_wp
      real(wp) :: eroded_ke = 0.0_wp
   end type energy_t

   !> Per-part sums of *DATABASE_MATSUM (dx_energy_sums%part_energies): each part's share of
   !> the lumped nodal masses (CSR over parts: the nodes of part p are node(ptr(p):ptr(p+1)-1)
   !> in ascending order, m its element-mass share there), and the sums at the last energy
   !> step. An MPI run forms them on rank 0's global model only.
   type :: part_sums_t
      integer, allocatable :: ptr(:)          !< (np + 1)
      integer, allocatable :: node(:)         !< dense node indices
      real(wp), allocatable :: m(:)           !< mass share of the part at node
      real(wp), allocatable :: mass(:)        !< (np) part mass (sum of its shares)
      !> (np) mass added by mass scaling (*CONTROL_TIMESTEP DT2MS; dx_energy_sums
      !> part_added_mass); m then holds the shares of rho V0 + the added mass
      real(wp), allocatable :: added(:)
      !> with DT2MS: each part's elements (eptr (np + 1) into el, em, esh, noff), the dense
      !> element, its rho V0 and nodal share, and its nodes' entries of m (noff into ent)
      integer, allocatable :: eptr(:), el(:), noff(:), ent(:)
      real(wp), allocatable :: em(:), esh(:)
      real(wp), allocatable :: ie(:), ke(:), hge(:)   !< (np) internal, kinetic, hourglass
      real(wp), allocatable :: mom(:, :)      !< (3, np) momentum
      real(wp), allocatable :: eie(:), eke(:) !< (np) eroded internal and kinetic energy
   end type part_sums_t

   type :: model_t
      character(:), allocatable :: title
      character(:), allocatable :: deck_file
      !> every file the deck read (the deck and its includes, in order): the content hash
      !> of the MPI rank files and dumps
      type(string_t), allocatable :: deck_files(:)
      ! --- nodes
      integer :: nn = 0
      integer, allocatable :: node_label(:)
      real(wp), allocatable :: x0(:, :)        !< (3, nn) initial coordinates
      real(wp), allocatable :: v0(:, :)        !< (3, nn) initial velocity
      !> (3, nn) initial angular velocity (*INITIAL_VELOCITY_NODE VXR VYR VZR on shell
      !> nodes; allocated only when one is given)
      real(wp), allocatable :: w0(:, :)
      ! --- elements
      integer :: ne = 0
      integer, allocatable :: elem_label(:)    !< (ne) element ids
      integer, allocatable :: elem_part(:)     !< (ne) dense part index
      integer, allocatable :: elem_block(:)    !< (ne) block holding the element
      integer, allocatable :: elem_pos(:)      !< (ne) position inside that block
      type(elem_block_t), allocatable :: blocks(:)
      ! --- definitions
      type(part_t), allocatable :: parts(:)
      type(section_t), allocatable :: sections(:)
      type(hourglass_t), allocatable :: hourglasses(:)
      type(mat_holder_t), allocatable :: mats(:)
      type(curve_t), allocatable :: curves(:)
      type(node_set_t), allocatable :: node_sets(:)
      type(part_set_t), allocatable :: part_sets(:)
      type(segment_set_t), allocatable :: segment_sets(:)
      ! --- boundary conditions and loads
      type(spc_t), allocatable :: spcs(:)
      type(prescribed_t), allocatable :: prescribed(:)
      type(load_node_t), allocatable :: node_loads(:)
      type(load_segment_t), allocatable :: seg_loads(:)
      type(rigidwall_t), allocatable :: walls(:)
      type(body_load_t), allocatable :: body_loads(:)   !< *LOAD_BODY_X/Y/Z (dx_load_body)
      !> *BOUNDARY_NON_REFLECTING_2D (dx_build_twod, dx_nonreflecting): the boundary nodes
      !> and each one's lumped dashpot tensor (Cxx, Cyy, Cxy): f = -C v in the x-y plane
      integer, allocatable :: nr_node(:)
      real(wp), allocatable :: nr_c(:, :)
      type(edge_pressure_t), allocatable :: edge_pressures(:)   !< dx_edge_pressure
      type(deposit_t), allocatable :: deposits(:)               !< dx_edge_pressure
      type(contact2d_t), allocatable :: contact2d   !< *CONTACT_2D_AUTOMATIC_.. (dx_contact2d)
      type(rigid_system_t), allocatable :: rigid        !< rigid bodies (dx_rigid_types)
      type(contact_set_t), allocatable :: contact   !< *CONTACT_* state (none: not allocated)
      type(emc_system_t), allocatable :: emc        !< conserving rigid contact (dx_emc_types)
      ! --- controls and output
      type(control_t) :: ctrl
      type(database_t) :: db
      ! --- state (allocated by the solver)
      real(wp), allocatable :: x(:, :)         !< (3, nn) current coordinates
      real(wp), allocatable :: v(:, :)         !< (3, nn) velocity at t(n+1/2) after a cycle
      real(wp), allocatable :: f(:, :)         !< (3, nn) force (external - internal)
      real(wp), allocatable :: mass(:)         !< (nn) lumped mass (with added mass, if any)
      !> mass scaling (*CONTROL_TIMESTEP DT2MS; dx_mass_scaling), allocated only with it:
      !> added_mass(ne): the mass added to each element (dense global element index; < 0:
      !> removed, DT2MS > 0 at the first cycle), spread over its nodes as the lumped mass is
      real(wp), allocatable :: added_mass(:)
      !> rotational degrees of freedom (allocated only when the deck has shells): angular
      !> velocity at t(n+1/2) after a cycle, moment (external - internal), rotary inertia
      real(wp), allocatable :: w(:, :)         !< (3, nn) angular velocity (global axes)
      real(wp), allocatable :: mom(:, :)       !< (3, nn) moment
      real(wp), allocatable :: rinert(:)       !< (nn) lumped rotary inertia
      !> *ELEMENT_MASS and *ELEMENT_INERTIA (allocated only when the deck has them): the
      !> point mass and rotary inertia they add at each node (lump_mass, init_state)
      real(wp), allocatable :: node_mass(:)    !< (nn)
      real(wp), allocatable :: node_rinert(:)  !< (nn)
      real(wp) :: time = 0.0_wp
      real(wp) :: dt = 0.0_wp
      integer :: cycle = 0
      integer :: dt_elem = 0                   !< dense element controlling dt
      type(energy_t) :: energy
      !> some part can erode (*MAT_ADD_EROSION, *CONTROL_TIMESTEP ERODE): glstat's eroded
      !> energy columns and the erosion pass (dx_erosion) are on
      logical :: erodes = .false.
      type(part_sums_t) :: psum                !< matsum's per-part sums (matsum_dt > 0)
      type(run_state_t) :: run                 !< explicit loop state (restart dumps it)
      type(restart_ctrl_t) :: rst              !< *DATABASE_BINARY_D3DUMP/RUNRSF
   end type model_t

   ! keep nv_chunk visible to users of the model (block sizes)
   public :: nv_chunk
end module dx_model
