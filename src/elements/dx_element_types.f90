!> The element-family table: every fact about an element family that code outside
!> src/elements/ needs, keyed by the element type (etype) of a block. Nodes per element, faces
!> (node lists, outward by the right-hand rule; a triangle repeats its third node, the
!> *SET_SEGMENT convention) and edges, volume and first/second moments (rigid-body mass
!> properties), the lumped-mass share of each node, the XDMF cell type and the partition cost
!> weight. A new family adds a row here and a kernel behind dx_element's element_block_pass;
!> consumers (model build, mass lumping, contact and rigid surfaces, rigid mass, plot writers,
!> partitioner, MPI pieces) ask this table and never name a family.
!> Uses base only (as the *_types modules of the physics folders), so dx_model can hold and
!> re-export it.
!> Hexahedron (ELFORM 1, 2): LS-DYNA node order; exact trilinear volume (2x2x2 Gauss, exact
!> for the trilinear map) and moments (3x3x3 Gauss: x_i x_j det J has degree <= 4 in each
!> natural coordinate; Hughes, The Finite Element Method, 1987, sec. 3.8).
!> Tetrahedron (ELFORM 10): linear shape functions, closed-form volume det[x2-x1,x3-x1,x4-x1]/6
!> and moments int x dV = V xbar, int x_i x_j dV = V/20 (sum_a x_ai x_aj + 16 xbar_i xbar_j)
!> (the exact integral of a quadratic over a simplex: Zienkiewicz, Taylor & Zhu, The Finite
!> Element Method: Its Basis and Fundamentals, 7th ed., 2013, eq. 6.29 / Table 6.3).
!> 2D quadrilaterals (*SECTION_SHELL ELFORM 13, 14, 15; dx_quad2d): exact area (half the cross
!> product of the diagonals) and, axisymmetric, the exact volume per radian int r dA (Green's
!> theorem over the straight edges); time-step length area / diameter (dx_quad2d).
!> Shell (ELFORM 2 of *SECTION_SHELL, 1002): 4 nodes, one face, elem_volume = the mid-surface
!> area (the caller multiplies by the thickness). Beam (ELFORM 2 of *SECTION_BEAM, 2002):
!> 2 nodes, no face, elem_volume = the length (the caller multiplies by the area), an XDMF
!> Polyline; the Hughes-Liu beam (ELFORM 1, 2001) shares that row, its nip the section rule's
!> points (dx_beam_hl). Both carry rotations (family_t%rot).
!> The fully integrated shell (ELFORM 16,
!> 1016; dx_shell_fi) is a second row of the shell family (family_t%shell): the same node,
!> face, edge, mass and plot facts as the BT shell, 2x2 in-plane points (family_t%npl).
!> Element error codes and the result record of one block pass live here too (dx_element),
!> and the element block and the part the kernels work on (elem_block_t with its family state
!> es, part_t): the model holds and re-exports them, so src/elements/ never imports src/model/
!> (no folder pair imports each other).
module dx_element_types
   use dx_kinds, only: wp, huge_wp, nv_chunk
   use dx_vec3, only: cross
   ! the hexahedron's volume and moments live in dx_hex8_geometry (a module of their own: not
   ! inlined here, so their results keep the bits they had in dx_model_build / dx_rigid_mass)
   use dx_hex8_geometry, only: hex_volume, hex_moments, hex_corner_jacobians
   implicit none
   private
   public :: family_t, element_family, elem_volume, elem_moments, elem_length, block_result_t
   public :: ETYPE_HEX8_1PT, ETYPE_HEX8_SRI, ETYPE_TET4, ETYPE_DEFAULT, ETYPE_SHELL_BT
   public :: ETYPE_SHELL_FI
   public :: etype_of_shell_elform, ES_THK, shell_area, shell_frame, shell_stress_global, &
             shell_axes
   public :: ETYPE_QUAD2D_PS, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, ETYPE_QUAD2D_PSS, quad2d_area, &
             quad2d_rvol
   public :: ETYPE_BEAM_BS, ETYPE_BEAM_HL, etype_of_beam_elform, ES_BEAM, elem_stress_global, is_beam
   public :: BM_E2, BM_TH, BM_RES, BM_SEC, beam_resultants
   public :: MAX_NEN, MAX_FACE_NODES, MAX_FACES
   public :: ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, etype_of_elform, ETYPES
   public :: solid_shape, elem_quality, ASPECT_WARN, WARP_WARN
   public :: ES_WORK, ES_HGS, ES_PHIM, ES_DMG, ES_EPS, MAX_ES, ES_NAMES, ES_DUMP
   public :: erosion_t
   public :: WORK_Q, WORK_QBV, WORK_DT, WORK_PN
   public :: elem_block_t, part_t

   !> element types (the block's etype): LS-DYNA's *SECTION_SOLID ELFORM numbers
   integer, parameter :: ETYPE_HEX8_1PT = 1   !< one-point, uniform strain, hourglass control
   integer, parameter :: ETYPE_HEX8_SRI = 2   !< 2x2x2 selectively reduced (mean dilatation)
   integer, parameter :: ETYPE_TET4 = 10      !< 4-node tetrahedron, one point, constant strain
   integer, parameter :: ETYPE_DEFAULT = ETYPE_HEX8_1PT   !< a block built without a section
   !> shells: 1000 + the *SECTION_SHELL ELFORM (the solid and shell ELFORM numbers overlap)
   integer, parameter :: ETYPE_SHELL_BT = 1002   !< Belytschko-Lin-Tsay quadrilateral (dx_shell_bt)
   integer, parameter :: ETYPE_SHELL_FI = 1016   !< fully integrated, assumed shear (dx_shell_fi)
   !> partition weight of the fully integrated shell (the hexahedron's is 1, the BT shell's 3):
   !> 3 x 3.8, its CPU per element-cycle against the BT shell's (80x16 cantilever plate, NIP
   !> 3, 9196 cycles: 2020 against 529 ns; docs/history.md, "Shells, part 2: ELFORM 16")
   integer, parameter :: FI_WEIGHT = 11
   !> 2D solids in the x-y plane (dx_quad2d): plane strain (ELFORM 13), area-weighted (14) and
   !> volume-weighted (15) axisymmetric quadrilaterals, x = r, y = z (the axis)
   integer, parameter :: ETYPE_QUAD2D_PS = 1013, ETYPE_QUAD2D_AW = 1014, ETYPE_QUAD2D_VW = 1015
   integer, parameter :: ETYPE_QUAD2D_PSS = 1012   !< plane stress (ELFORM 12), thickness t
   !> beams: 2000 + the *SECTION_BEAM ELFORM
   integer, parameter :: ETYPE_BEAM_BS = 2002    !< Belytschko-Schwer resultant beam (dx_beam_bs)
   integer, parameter :: ETYPE_BEAM_HL = 2001    !< Hughes-Liu beam, section integration (dx_beam_hl)
   !> every element type, one per family first (lookups by nen or XDMF code take the first)
   integer, parameter :: ETYPES(6) = [ETYPE_HEX8_1PT, ETYPE_TET4, ETYPE_SHELL_BT, &
                                      ETYPE_HEX8_SRI, ETYPE_BEAM_BS, ETYPE_SHELL_FI]
   integer, parameter :: MAX_NEN = 8          !< most nodes of any family (*ELEMENT_SOLID card)
   integer, parameter :: MAX_FACE_NODES = 4   !< most nodes of a face (a segment)
   integer, parameter :: MAX_FACES = 6        !< most faces of a family

   !> bounds of the geometry checks at start (elem_quality; docs/extreme-cases.md, "Geometry
   !> checks"): a warning past them, the element still runs
   real(wp), parameter :: ASPECT_WARN = 20.0_wp   !< longest edge / time-step length
   real(wp), parameter :: WARP_WARN = 20.0_wp     !< face warpage angle, degrees

   !> element error codes of a block pass
   integer, parameter :: ELEM_ERR_NEGVOL = 1, ELEM_ERR_MATERIAL = 2

   !> Family state: one array es(nel, nes) per block (as hv is for the material), made of
   !> named slots; a family lists the columns of each slot it has (family_t%es_ncol, 0: none)
   !> and a block holds the slots it uses (elem_block_t%esc: first column, 0 = absent), so a
   !> block pays only for what its part uses. Slot ids:
   integer, parameter :: ES_HGS = 1    !< hourglass resisting forces (3, hgmodes) (QH > 0)
   integer, parameter :: ES_WORK = 2   !< pending terms of the centred work (offsets WORK_*)
   integer, parameter :: ES_PHIM = 3   !< own-mass share of the element dt bound (set-up)
   !> shells: current thickness (1) and the hourglass generalized forces (8: membrane x, y,
   !> out-of-plane, bending x, y; 3 more columns spare for the warping terms)
   integer, parameter :: ES_THK = 4
   !> erosion (dx_erosion): the damage variable D of *MAT_ADD_EROSION's Tuler-Butcher
   !> criterion, the stress impulse integral over IMPULSE (1 column; parts that use it only)
   integer, parameter :: ES_DMG = 5
   !> erosion: the total strain (6: xx yy zz xy yz zx, tensor shear), the sum of the
   !> strain increments turned with the material (parts with a strain criterion only)
   integer, parameter :: ES_EPS = 6
   !> beams (dx_beam_bs): the transverse axis e2 (3), the deformational angles (5: twist,
   !> end rotations about e2 at N1, N2, about e3 at N1, N2), the resultants (6: N, T, M2 at
   !> N1, N2, M3 at N1, N2) and the element's section A, ISS, ITT, J, SA (5); beams have
   !> ES_WORK too (the centred work of the resultants)
   integer, parameter :: ES_BEAM = 7
   integer, parameter :: MAX_ES = 7
   !> column offsets inside the ES_BEAM slot (0-based from its first column)
   integer, parameter :: BM_E2 = 0     !< e2 (3)
   integer, parameter :: BM_TH = 3     !< twist, theta_s at N1, N2, theta_t at N1, N2 (5)
   integer, parameter :: BM_RES = 8    !< N, T, M_s at N1, N2, M_t at N1, N2 (6)
   integer, parameter :: BM_SEC = 14   !< A, ISS, ITT, J, SA of the element (5): 19 in all
   !> restart dataset of each slot (the columns in order, flat; ES_DUMP: phim is derived at
   !> start, not dumped); dumps write the slots in id order
   character(8), parameter :: ES_NAMES(MAX_ES) = [character(8) :: 'hgs', 'ework', 'phim', &
                                                  'shthk', 'damage', 'strain', 'beam']
   logical, parameter :: ES_DUMP(MAX_ES) = [.true., .true., .false., .true., .true., .true., &
                                            .true.]
   !> column offsets inside ES_WORK (dx_hex8's centred_work: q, q B.v, dt, sigma:D V of the
   !> last pass)
   integer, parameter :: WORK_Q = 0, WORK_QBV = 1, WORK_DT = 2, WORK_PN = 3

   !> one family: the facts its consumers need
   type :: family_t
      character(8) :: name = ''            !< plot connectivity dataset /mesh/<name>
      character(16) :: xdmf = ''           !< XDMF TopologyType of a single-family mesh
      integer :: xdmf_code = 0             !< XDMF cell code in a Mixed topology
      integer :: nen = 0                   !< nodes per element (conn(nen, nel))
      integer :: nip = 1                   !< integration points
      integer :: nfaces = 0, nedges = 0
      integer :: hgmodes = 0               !< hourglass modes (stiffness state per element)
      integer :: faces(MAX_FACE_NODES, MAX_FACES) = 0   !< local face nodes, outward normal
      integer :: edges(2, 12) = 0                       !< local edge end nodes
      real(wp) :: mass_share = 0.0_wp      !< lumped mass of each node: rho V0 * mass_share
      integer :: weight = 1                !< partition cost weight (measured ns/element-cycle)
      integer :: es_ncol(MAX_ES) = 0       !< columns of each family-state slot (0: none)
      logical :: rot = .false.             !< nodes carry rotations (shells, beams)
      !> a shell: a mid-surface quadrilateral (a triangle repeats N3) with a thickness
      !> (ES_THK column 1), stresses in its co-rotational frame (shell_frame)
      logical :: shell = .false.
      !> in-plane integration points of a shell (its block's nip = npl x the section's NIP;
      !> point (g, ip) of in-plane g and through-thickness ip is (g - 1) NIP + ip)
      integer :: npl = 1
      logical :: twod = .false.            !< a 2D family: x-y plane, the z DOF fixed
      logical :: axisym = .false.          !< 2D axisymmetric: x = r >= 0, volumes per radian
      !> the kernel scatters its forces element-major (do i; do k), not corner-major: the
      !> MPI engine keys the shared-node sums in that order (dx_par_model)
      logical :: scatter_em = .false.
   end type family_t

   !> results of one block pass
   type :: block_result_t
      real(wp) :: dt = huge_wp        !< smallest element time step (without TSSFAC)
      integer :: imin = 0             !< its position in the block
      real(wp) :: dte(nv_chunk)       !< each element's step (1:nel; huge_wp: eroded)
      integer :: ibad = 0             !< first element in error (position), 0 = none
      integer :: errcode = 0
      real(wp) :: deint = 0.0_wp      !< internal energy increment of the block
      real(wp) :: dehg = 0.0_wp       !< hourglass energy increment of the block
      !> internal power sigma:D V - q B.v at t(n) with v(n-1/2): the caller adds
      !> (dt(n+1/2) - dt(n-1/2))/4 times it to report the energy at t(n) (see centred_work)
      real(wp) :: pend = 0.0_wp
   end type block_result_t

   !> *MAT_ADD_EROSION criteria of one material (LS-DYNA Keyword User's Manual Vol. II,
   !> *MAT_ADD_EROSION, cards 1 and 2), checked by dx_erosion. A criterion whose value equals
   !> EXCL is off (EXCL default 0: a blank field is off). lambda: the Tuler-Butcher exponent
   !> (LS-DYNA: 2; dynx keyword *DYNX_TULER_BUTCHER sets another).
   type :: erosion_t
      logical :: on = .false.
      integer :: mid = 0
      real(wp) :: excl = 0.0_wp, mxpres = 0.0_wp, mneps = 0.0_wp, effeps = 0.0_wp
      real(wp) :: voleps = 0.0_wp, mnpres = 0.0_wp, sigp1 = 0.0_wp, sigvm = 0.0_wp
      real(wp) :: mxeps = 0.0_wp, epssh = 0.0_wp, sigth = 0.0_wp, impulse = 0.0_wp
      real(wp) :: failtm = 0.0_wp
      real(wp) :: lambda = 2.0_wp
      integer :: numfip = 1, ncs = 1
   end type erosion_t

   !> *PART with its resolved section, material and hourglass settings
   type :: part_t
      integer :: label = 0
      character(:), allocatable :: title
      integer :: secid = 0, mid = 0, eosid = 0, hgid = 0    !< labels as read
      integer :: isec = 0, imat = 0, ihg = 0                !< dense indices (0: none)
      integer :: ihq = 1           !< resolved hourglass type (LS-DYNA IHQ)
      real(wp) :: qh = 0.1_wp      !< resolved hourglass coefficient
      real(wp) :: q1 = 1.5_wp      !< resolved quadratic bulk viscosity coefficient
      real(wp) :: q2 = 0.06_wp     !< resolved linear bulk viscosity coefficient
      !> shell parts: the section's shear factor SHRF, the through-thickness rule
      !> (*CONTROL_SHELL INTGRD = 1: Lobatto) and the thickness update (ISTUPD)
      real(wp) :: shrf = 1.0_wp
      logical :: lobatto = .false.
      integer :: istupd = 0
      type(erosion_t) :: ero      !< *MAT_ADD_EROSION of the part's material (dx_erosion)
      !> beam parts (*SECTION_BEAM ELFORM 2): A, ISS, ITT, J, SA (SA = 0: no shear
      !> deformation, Euler-Bernoulli)
      real(wp) :: bsec(5) = 0.0_wp
      !> Hughes-Liu beam parts (*SECTION_BEAM ELFORM 1): the section rule QR (1-5) and the
      !> cross-section type CST (0 rectangle, 1 tube); the shear factor is shrf above
      integer :: bqr = 2, bcst = 0
      !> a user rule (QR/IRID < 0, *INTEGRATION_BEAM ICST 0): brule(1:3, k) = S, T, WF of
      !> point k (unallocated: the built-in rule bqr); bra its relative area RA
      real(wp), allocatable :: brule(:, :)
      real(wp) :: bra = 1.0_wp
      !> NSLOC, NTLOC of the section: the nodes' line at (NSLOC TS/2, NTLOC TT/2) of the section
      real(wp) :: bloc(2) = 0.0_wp
   end type part_t

   !> A group of at most nv_chunk elements of one part and one formulation.
   !> State arrays have the element index first (unit stride over elements).
   type :: elem_block_t
      integer :: ipart = 0          !< dense part index
      integer :: etype = ETYPE_DEFAULT   !< element type: the family table's key
      integer :: nel = 0            !< elements in this block (<= nv_chunk)
      integer :: nip = 1            !< integration points per element
      integer :: nhv = 0            !< history variables per point (from the material)
      integer, allocatable :: conn(:, :)     !< (nen, nel) dense node indices (nen: family)
      integer, allocatable :: elem(:)        !< (nel) dense global element index
      real(wp), allocatable :: sig(:, :, :)  !< (nel, 6, nip) Cauchy stress
      real(wp), allocatable :: hv(:, :, :)   !< (nel, nhv, nip) material history
      real(wp), allocatable :: vol0(:)       !< (nel) initial volume
      real(wp), allocatable :: relvol(:)     !< (nel) current V/V0
      real(wp), allocatable :: eint(:)       !< (nel) internal energy (work of stress)
      real(wp), allocatable :: ehg(:)        !< (nel) hourglass energy
      !> (nel, nes) family state: the slots ES_* of the family table that this block uses
      !> (centred-work terms, hourglass resisting forces, own-mass share), slot s in columns
      !> esc(s) .. esc(s) + esn(s) - 1 (esc(s) = 0: absent)
      real(wp), allocatable :: es(:, :)
      integer :: esc(MAX_ES) = 0
      integer :: esn(MAX_ES) = 0
      logical, allocatable :: failed(:)      !< (nel) eroded elements carry no force
   contains
      procedure :: es_add => block_es_add
      procedure :: es_drop => block_es_drop
   end type elem_block_t

   integer, parameter :: HEX_FACES(4, 6) = reshape([1, 4, 3, 2,  5, 6, 7, 8,  1, 2, 6, 5, &
                                                    2, 3, 7, 6,  3, 4, 8, 7,  4, 1, 5, 8], [4, 6])
   integer, parameter :: HEX_EDGES(2, 12) = reshape([1, 2,  2, 3,  3, 4,  4, 1,  5, 6,  6, 7, &
                                                     7, 8,  8, 5,  1, 5,  2, 6,  3, 7,  4, 8], &
                                                    [2, 12])
   !> tetrahedron faces (positive volume: node 4 on the side of (x2-x1)x(x3-x1))
   integer, parameter :: TET_FACES(4, 4) = reshape([1, 3, 2, 2,  1, 2, 4, 4,  2, 3, 4, 4, &
                                                    1, 4, 3, 3], [4, 4])
   integer, parameter :: QUAD_EDGES(2, 4) = reshape([1, 2,  2, 3,  3, 4,  4, 1], [2, 4])
   integer, parameter :: TET_EDGES(2, 6) = reshape([1, 2,  2, 3,  3, 1,  1, 4,  2, 4,  3, 4], &
                                                   [2, 6])

contains

   !> The family of element type etype (an unknown type gives nen = 0).
   pure function element_family(etype) result(f)
      integer, intent(in) :: etype
      type(family_t) :: f
      select case (etype)
      case (ETYPE_HEX8_1PT, ETYPE_HEX8_SRI)
         f%name = 'hex8'; f%xdmf = 'Hexahedron'; f%xdmf_code = 9
         f%nen = 8; f%nfaces = 6; f%nedges = 12
         f%faces(:, 1:6) = HEX_FACES
         f%edges(:, 1:12) = HEX_EDGES
         f%mass_share = 0.125_wp
         f%hgmodes = 4
         f%es_ncol = [3*f%hgmodes, 4, 1, 0, 1, 6, 0]
         f%nip = 1; f%weight = 1
         ! ELFORM 2 measured at about 8x ELFORM 1 per element-cycle (docs/history.md,
         ! "Partition weights")
         if (etype == ETYPE_HEX8_SRI) then
            f%nip = 8; f%weight = 8
            f%es_ncol(ES_HGS) = 0          ! no hourglass modes
         end if
      case (ETYPE_TET4)
         f%name = 'tet4'; f%xdmf = 'Tetrahedron'; f%xdmf_code = 6
         f%nen = 4; f%nfaces = 4; f%nedges = 6
         f%faces(:, 1:4) = TET_FACES
         f%edges(:, 1:6) = TET_EDGES
         f%mass_share = 0.25_wp
         f%es_ncol = [0, 4, 0, 0, 1, 6, 0]
         f%nip = 1; f%weight = 1
      case (ETYPE_SHELL_BT, ETYPE_SHELL_FI)
         ! one face (the mid-surface, normal by the right-hand rule on N1..N4; a triangle
         ! repeats N3), four edges; nip: the section's through-thickness points (block%nip)
         f%name = 'quad4'; f%xdmf = 'Quadrilateral'; f%xdmf_code = 5
         f%nen = 4; f%nfaces = 1; f%nedges = 4
         f%faces(:, 1) = [1, 2, 3, 4]
         f%edges(:, 1:4) = QUAD_EDGES
         f%mass_share = 0.25_wp
         f%hgmodes = 5
         f%es_ncol = [0, 0, 0, 1 + 8, 0, 0, 0]
         ! weight: 828 against the hexahedron's 263 ns of CPU per element-cycle (NIP 3,
         ! elastic; 100x80 plate and 20x20x20 cube, 300 cycles less 1, three runs each;
         ! docs/history.md, "Shells under MPI")
         f%nip = 2; f%weight = 3
         f%rot = .true.; f%scatter_em = .true.; f%shell = .true.
         if (etype == ETYPE_SHELL_FI) then
            ! 2x2 in-plane points, no hourglass modes: the thickness alone
            f%hgmodes = 0; f%npl = 4
            f%es_ncol = [0, 0, 0, 1, 0, 0, 0]
            f%weight = FI_WEIGHT
         end if
      case (ETYPE_QUAD2D_PS, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, ETYPE_QUAD2D_PSS)
         ! a 2D quadrilateral (a triangle repeats N3): no faces (its boundary is edges), one
         ! hourglass mode per direction; V0 is the area (plane strain, unit thickness) or
         ! int r dA (axisymmetric, per radian), a quarter of rho V0 per node
         f%name = 'quad4'; f%xdmf = 'Quadrilateral'; f%xdmf_code = 5
         f%nen = 4; f%nfaces = 0; f%nedges = 4
         f%edges(:, 1:4) = QUAD_EDGES
         f%mass_share = 0.25_wp
         f%hgmodes = 1
         f%es_ncol = [2*f%hgmodes, 4, 0, 0, 0, 0, 0]
         f%nip = 1; f%weight = 1
         f%twod = .true.
         f%axisym = etype == ETYPE_QUAD2D_AW .or. etype == ETYPE_QUAD2D_VW
         if (etype == ETYPE_QUAD2D_PSS) f%es_ncol(ES_THK) = 1     ! its thickness
      case (ETYPE_BEAM_BS, ETYPE_BEAM_HL)
         ! a line N1-N2 (the orientation node N3 is set-up data, not a node of the cell);
         ! no face, one edge; an XDMF Polyline of 2 nodes (written in a Mixed topology,
         ! which names the node count of a polyline cell)
         f%name = 'line2'; f%xdmf = 'Polyline'; f%xdmf_code = 2
         f%nen = 2; f%nfaces = 0; f%nedges = 1
         f%edges(:, 1) = [1, 2]
         f%mass_share = 0.5_wp
         f%es_ncol = [0, 4, 0, 0, 0, 0, 19]
         f%nip = 1; f%weight = 1
         ! forces, moments, mass and rotary inertia scattered element-major (dx_beam_bs)
         f%rot = .true.; f%scatter_em = .true.
         ! Hughes-Liu: the section points (block%nip, the QR/CST rule) call the material;
         ! weight: 434 CPU ns per element-cycle (QR 2, elastic; 901 at 4x4 plastic) against
         ! the hexahedron's 263 (BENCH_ONLY=beam make bench, docs/performance.md)
         if (etype == ETYPE_BEAM_HL) then
            f%nip = 4; f%weight = 2
         end if
      end select
   end function element_family

   !> A beam element type (either formulation of *SECTION_BEAM).
   pure logical function is_beam(etype)
      integer, intent(in) :: etype
      is_beam = etype == ETYPE_BEAM_BS .or. etype == ETYPE_BEAM_HL
   end function is_beam

   !> Element type of a *SECTION_SOLID ELFORM (0: not supported).
   pure integer function etype_of_elform(elform) result(etype)
      integer, intent(in) :: elform
      select case (elform)
      case (2)
         etype = ETYPE_HEX8_SRI
      case (10)
         etype = ETYPE_TET4
      case default
         etype = ETYPE_HEX8_1PT
      end select
   end function etype_of_elform

   !> Element type of a *SECTION_SHELL ELFORM (0: not supported).
   pure integer function etype_of_shell_elform(elform) result(etype)
      integer, intent(in) :: elform
      select case (elform)
      case (2)
         etype = ETYPE_SHELL_BT
      case (16)
         etype = ETYPE_SHELL_FI
      case (12)
         etype = ETYPE_QUAD2D_PSS
      case (13)
         etype = ETYPE_QUAD2D_PS
      case (14)
         etype = ETYPE_QUAD2D_AW
      case (15)
         etype = ETYPE_QUAD2D_VW
      case default
         etype = 0
      end select
   end function etype_of_shell_elform

   !> Signed area of a 2D quadrilateral with nodes xe(2+, 4) in the x-y plane (a triangle
   !> repeats N3): half the cross product of the diagonals, exact for the bilinear map
   !> (positive for counter-clockwise nodes).
   pure function quad2d_area(xe) result(a)
      real(wp), intent(in) :: xe(:, :)
      real(wp) :: a
      a = 0.5_wp*((xe(1, 3) - xe(1, 1))*(xe(2, 4) - xe(2, 2)) - &
                  (xe(1, 4) - xe(1, 2))*(xe(2, 3) - xe(2, 1)))
   end function quad2d_area

   !> Volume per radian int r dA of an axisymmetric quadrilateral (x = r) with nodes
   !> xe(2+, 4): the first moment of the area about the axis by Green's theorem over its four
   !> straight edges, (1/6) sum_k (r_k + r_k+1)(r_k z_k+1 - r_k+1 z_k); exact (the bilinear
   !> map's edges are straight); a repeated N3 adds a zero edge.
   pure function quad2d_rvol(xe) result(v)
      real(wp), intent(in) :: xe(:, :)
      real(wp) :: v
      integer :: k, m
      v = 0.0_wp
      do k = 1, 4
         m = mod(k, 4) + 1
         v = v + (xe(1, k) + xe(1, m))*(xe(1, k)*xe(2, m) - xe(1, m)*xe(2, k))
      end do
      v = v/6.0_wp
   end function quad2d_rvol
   !> Element type of a *SECTION_BEAM ELFORM (0: not supported).
   pure integer function etype_of_beam_elform(elform) result(etype)
      integer, intent(in) :: elform
      etype = 0
      if (elform == 2) etype = ETYPE_BEAM_BS
      if (elform == 1) etype = ETYPE_BEAM_HL
   end function etype_of_beam_elform

   !> An element's plot stress s (xx yy zz xy yz zx, held in the element's own frame by
   !> the families with rotations) in global axes: the shell's co-rotational frame, the
   !> beam's axial stress N/A along its axis e1 (s(1)); solids are already global.
   pure subroutine elem_stress_global(etype, xe, s)
      integer, intent(in) :: etype
      real(wp), intent(in) :: xe(:, :)
      real(wp), intent(inout) :: s(6)
      real(wp) :: e1(3), l, sa
      select case (etype)
      case (ETYPE_SHELL_BT, ETYPE_SHELL_FI)
         call shell_stress_global(xe(:, 1:4), s)
      case (ETYPE_BEAM_BS, ETYPE_BEAM_HL)
         e1 = xe(:, 2) - xe(:, 1)
         l = norm2(e1)
         if (l > 0.0_wp) e1 = e1/l
         sa = s(1)
         s = sa*[e1(1)**2, e1(2)**2, e1(3)**2, e1(1)*e1(2), e1(2)*e1(3), e1(3)*e1(1)]
      end select
   end subroutine elem_stress_global

   !> Beam element i's resultants for the plot (the optional rows beam_force, beam_moment),
   !> in its own frame (e1 along N1-N2, e2 = s, e3 = t): force = (N, Q_s, Q_t), the axial
   !> force and the shears (the internal force on N2: Q_s = -(M_t1 + M_t2)/L,
   !> Q_t = (M_s1 + M_s2)/L, constant along the element), moment = (T, M_s, M_t), the
   !> torque and the bending moments at mid-span ((M_2 - M_1)/2 of the end moments: the
   !> moment of a pure bending, zero for an antisymmetric one). xe: the nodes N1, N2.
   pure subroutine beam_resultants(blk, i, xe, force, moment)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: i
      real(wp), intent(in) :: xe(:, :)
      real(wp), intent(out) :: force(3), moment(3)
      real(wp) :: r(6), l
      r = blk%es(i, blk%esc(ES_BEAM) + BM_RES:blk%esc(ES_BEAM) + BM_RES + 5)
      l = norm2(xe(:, 2) - xe(:, 1))
      force = [r(1), 0.0_wp, 0.0_wp]
      if (l > 0.0_wp) force(2:3) = [-(r(5) + r(6))/l, (r(3) + r(4))/l]
      moment = [r(2), 0.5_wp*(r(4) - r(3)), 0.5_wp*(r(6) - r(5))]
   end subroutine beam_resultants

   !> Mid-surface area of a shell with nodes xe(3, 4) (a triangle repeats N3): half the
   !> norm of the cross product of the diagonals (exact for a plane quadrilateral).
   pure function shell_area(xe) result(a)
      real(wp), intent(in) :: xe(:, :)
      real(wp) :: a
      a = 0.5_wp*norm2(cross(xe(:, 3) - xe(:, 1), xe(:, 4) - xe(:, 2)))
   end function shell_area

   !> Co-rotational frame e(3, 3) (columns e1, e2, e3) of a shell with nodes xe(3, 4) (a
   !> triangle repeats N3): e3 = s31 x s42/|.|, e1 = s21 - (s21.e3) e3 normalised, e2 = e3 x
   !> e1 (sIJ = x_I - x_J; Belytschko, Lin & Tsay 1984), the local in-plane coordinates
   !> xl(2, 4) of the nodes (origin N1) and the area of the projected quadrilateral.
   pure subroutine shell_frame(xe, e, xl, area)
      real(wp), intent(in) :: xe(3, 4)
      real(wp), intent(out) :: e(3, 3), xl(2, 4), area
      integer :: k
      call shell_axes(xe, e)
      do k = 1, 4
         xl(1, k) = dot_product(e(:, 1), xe(:, k) - xe(:, 1))
         xl(2, k) = dot_product(e(:, 2), xe(:, k) - xe(:, 1))
      end do
      area = 0.5_wp*((xl(1, 3) - xl(1, 1))*(xl(2, 4) - xl(2, 2)) - &
                     (xl(1, 4) - xl(1, 2))*(xl(2, 3) - xl(2, 1)))
   end subroutine shell_frame

   !> The axes e(3, 3) of shell_frame alone (no local coordinates), the cross products
   !> written out (dx_vec3's cross is not inlined across modules: 9 % of a shell run).
   pure subroutine shell_axes(xe, e)
      real(wp), intent(in) :: xe(3, 4)
      real(wp), intent(out) :: e(3, 3)
      real(wp) :: s21(3), d31(3), d42(3), n(3), r(3), a
      s21 = xe(:, 2) - xe(:, 1)
      d31 = xe(:, 3) - xe(:, 1)
      d42 = xe(:, 4) - xe(:, 2)
      n = [d31(2)*d42(3) - d31(3)*d42(2), d31(3)*d42(1) - d31(1)*d42(3), &
           d31(1)*d42(2) - d31(2)*d42(1)]
      a = norm2(n)
      if (a > 0.0_wp) n = n/a
      e(:, 3) = n
      r = s21 - dot_product(s21, n)*n
      a = norm2(r)
      if (a > 0.0_wp) r = r/a
      e(:, 1) = r
      e(:, 2) = [n(2)*r(3) - n(3)*r(2), n(3)*r(1) - n(1)*r(3), n(1)*r(2) - n(2)*r(1)]
   end subroutine shell_axes

   !> A shell's stress s (xx yy zz xy yz zx) from its co-rotational frame (nodes xe(3, 4))
   !> to the global axes: sigma_global = E sigma_local E^T.
   pure subroutine shell_stress_global(xe, s)
      real(wp), intent(in) :: xe(3, 4)
      real(wp), intent(inout) :: s(6)
      real(wp) :: e(3, 3), xl(2, 4), a, t(3, 3)
      call shell_frame(xe, e, xl, a)
      t = reshape([s(1), s(4), s(6), s(4), s(2), s(5), s(6), s(5), s(3)], [3, 3])
      t = matmul(e, matmul(t, transpose(e)))
      s = [t(1, 1), t(2, 2), t(3, 3), t(1, 2), t(2, 3), t(3, 1)]
   end subroutine shell_stress_global

   !> Element type and nodes of one *ELEMENT_SOLID card c(1:8) (dense nodes, in place) of a
   !> part whose section gives etype; nen = nodes of the resulting family, ok = .false. for
   !> repeated nodes the family does not accept. A family of fewer nodes than the card (the
   !> tetrahedron, written N1 N2 N3 N4 N4 N4 N4 N4 or N1 N2 N3 N3 N4 N4 N4 N4) takes the
   !> distinct nodes in the order they first appear. A hexahedron card with repeated nodes is
   !> a degenerate hexahedron (LS-DYNA, *ELEMENT_SOLID): a tetrahedron N4=N3, N5=N6=N7=N8 or
   !> a pentahedron N4=N3, N8=N7; it stays a hexahedron (exact volume and B vectors of the
   !> collapsed trilinear map, mass rho V/8 per corner) unless *CONTROL_SOLID ESORT >= 1
   !> sorts the tetrahedra to ELFORM 10 (LS-DYNA Keyword User's Manual, *CONTROL_SOLID).
   !> ESORT would sort pentahedra to ELFORM 15, which dynx does not have: they stay
   !> degenerate hexahedra.
   pure subroutine solid_shape(esort, c, etype, nen, ok)
      integer, intent(in) :: esort
      integer, intent(inout) :: c(:)
      integer, intent(inout) :: etype
      integer, intent(out) :: nen
      logical, intent(out) :: ok
      type(family_t) :: fam
      integer :: u(size(c)), k, m
      m = 0
      do k = 1, size(c)
         if (m > 0) then
            if (any(u(1:m) == c(k))) cycle
         end if
         m = m + 1
         u(m) = c(k)
      end do
      fam = element_family(etype)
      nen = fam%nen
      ok = .true.
      if (m == size(c) .and. nen == size(c)) return
      if (nen < size(c)) then             ! a section of a smaller family
         ok = m == nen
         if (ok) c(1:nen) = u(1:nen)
         return
      end if
      if (m == 4 .and. c(5) == c(6) .and. c(6) == c(7) .and. c(7) == c(8)) then
         if (c(4) == c(3) .and. esort < 1) return          ! degenerate tetrahedron
         if (esort >= 1) then                              ! sorted to ELFORM 10
            etype = etype_of_elform(10)
            fam = element_family(etype)
            nen = fam%nen
            c(1:nen) = u(1:nen)
            return
         end if
      end if
      if (m == 6 .and. c(4) == c(3) .and. c(8) == c(7)) return   ! degenerate pentahedron
      ok = .false.
   end subroutine solid_shape

   !> Exact volume of one element of type etype with node coordinates xe(3, nen).
   pure function elem_volume(etype, xe) result(vol)
      integer, intent(in) :: etype
      real(wp), intent(in) :: xe(:, :)
      real(wp) :: vol
      select case (etype)
      case (ETYPE_TET4)
         vol = tet_volume(xe)
      case (ETYPE_SHELL_BT, ETYPE_SHELL_FI)      ! the mid-surface area: the caller multiplies by the thickness
         vol = shell_area(xe)
      case (ETYPE_QUAD2D_PS, ETYPE_QUAD2D_PSS)   ! per unit thickness (12: times t, by the caller)
         vol = quad2d_area(xe)
      case (ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW)   ! per radian
         vol = quad2d_rvol(xe)
      case (ETYPE_BEAM_BS, ETYPE_BEAM_HL)   ! the length: the caller multiplies by the area
         vol = norm2(xe(:, 2) - xe(:, 1))
      case default
         vol = hex_volume(xe)
      end select
   end function elem_volume

   !> vol = int dV, m1 = int (x - xref) dV, m2 = int (x - xref)(x - xref)^T dV over one element
   !> of type etype with node coordinates xe(3, nen); exact.
   pure subroutine elem_moments(etype, xe, xref, vol, m1, m2)
      integer, intent(in) :: etype
      real(wp), intent(in) :: xe(:, :), xref(3)
      real(wp), intent(out) :: vol, m1(3), m2(3, 3)
      select case (etype)
      case (ETYPE_TET4)
         call tet_moments(xe, xref, vol, m1, m2)
      case (ETYPE_SHELL_BT, ETYPE_SHELL_FI, ETYPE_QUAD2D_PS, ETYPE_QUAD2D_AW, ETYPE_QUAD2D_VW, ETYPE_QUAD2D_PSS, &
            ETYPE_BEAM_BS, ETYPE_BEAM_HL)
         ! rigid shells, rigid 2D parts and beams are refused at build: no moments yet
         vol = 0.0_wp; m1 = 0.0_wp; m2 = 0.0_wp
      case default
         call hex_moments(xe, xref, vol, m1, m2)
      end select
   end subroutine elem_moments

   !> Characteristic length of one element for its time step: V/A_max (largest face area by
   !> the cross product of the face diagonals; a triangle face repeats a node) for the
   !> hexahedron, LS-DYNA's choice for solids; the smallest altitude 3V/A_max for the
   !> tetrahedron (LS-DYNA Theory Manual, "Time Step Control").
   pure function elem_length(etype, xe, vol) result(l)
      integer, intent(in) :: etype
      real(wp), intent(in) :: xe(:, :), vol
      real(wp) :: l
      type(family_t) :: f
      real(wp) :: amax, a(3)
      integer :: k
      f = element_family(etype)
      if (f%twod) then     ! 2D: area over the element's diameter (dx_quad2d, quad2d_length)
         amax = max(norm2(xe(1:2, 3) - xe(1:2, 1)), norm2(xe(1:2, 4) - xe(1:2, 2)))
         do k = 1, f%nedges
            amax = max(amax, norm2(xe(1:2, f%edges(2, k)) - xe(1:2, f%edges(1, k))))
         end do
         l = quad2d_area(xe)/amax
         return
      end if
      if (is_beam(etype)) then     ! the beam's length (its axial wave step L/c)
         l = norm2(xe(:, 2) - xe(:, 1))
         return
      end if
      if (f%shell) then    ! the shell's length (dx_shell_bt, ISDO = 0)
         amax = 0.0_wp
         do k = 1, f%nedges
            amax = max(amax, norm2(xe(:, f%edges(2, k)) - xe(:, f%edges(1, k))))
         end do
         l = shell_area(xe)/amax
         if (all(xe(:, 3) == xe(:, 4))) l = 2.0_wp*l
         return
      end if
      amax = 0.0_wp
      do k = 1, f%nfaces
         a = 0.5_wp*cross(xe(:, f%faces(3, k)) - xe(:, f%faces(1, k)), &
                          xe(:, f%faces(4, k)) - xe(:, f%faces(2, k)))
         amax = max(amax, norm2(a))
      end do
      l = vol/amax
      if (etype == ETYPE_TET4) l = 3.0_wp*l
   end function elem_length

   !> Shape measures of one element of type etype, nodes xe(3, nen), volume vol > 0, for the
   !> geometry checks at start:
   !> aspect = longest edge / elem_length (the time-step length: V/A_max for the hexahedron,
   !> the smallest altitude for the tetrahedron): 1 for a cube, A for an h x h x h/A plate
   !> element, 1.22 for the regular tetrahedron;
   !> warp = largest warpage angle in degrees of its quadrilateral faces (4 distinct nodes):
   !> of the two ways to split the face into triangles along a diagonal, the larger angle
   !> between the two triangles' normals (0 for a plane face; the usual preprocessor measure,
   !> e.g. LS-PrePost's and HyperMesh's "warpage");
   !> cjmin = smallest corner Jacobian in units of V (hex_corner_jacobians) of a hexahedron
   !> with 8 distinct nodes (1 for a parallelepiped, <= 0: a folded corner) and its node kmin;
   !> 1 and 0 otherwise.
   pure subroutine elem_quality(etype, xe, vol, aspect, warp, cjmin, kmin)
      integer, intent(in) :: etype
      real(wp), intent(in) :: xe(:, :), vol
      real(wp), intent(out) :: aspect, warp, cjmin
      integer, intent(out) :: kmin     !< the node (1..nen) of cjmin (0: not a hexahedron)
      real(wp), parameter :: DEG = 57.29577951308232_wp
      type(family_t) :: f
      real(wp) :: emax, n1(3), n2(3), cj(8), l
      integer :: k, m, fn(4)
      f = element_family(etype)
      emax = 0.0_wp
      do k = 1, f%nedges
         emax = max(emax, norm2(xe(:, f%edges(2, k)) - xe(:, f%edges(1, k))))
      end do
      l = elem_length(etype, xe, vol)
      aspect = emax/l
      warp = 0.0_wp
      do k = 1, f%nfaces
         fn = f%faces(:, k)
         if (fn(4) == fn(3)) cycle                      ! a triangle of the family
         if (distinct(xe, fn) < 4) cycle                 ! a degenerate face
         do m = 0, 1                                     ! the two diagonals
            n1 = cross(xe(:, fn(2+m)) - xe(:, fn(1+m)), xe(:, fn(3+m)) - xe(:, fn(1+m)))
            n2 = cross(xe(:, fn(3+m)) - xe(:, fn(1+m)), xe(:, fn(mod(3+m, 4)+1)) - xe(:, fn(1+m)))
            if (norm2(n1) > 0.0_wp .and. norm2(n2) > 0.0_wp) &
               warp = max(warp, DEG*acos(max(-1.0_wp, min(1.0_wp, &
                          dot_product(n1, n2)/(norm2(n1)*norm2(n2))))))
         end do
      end do
      cjmin = 1.0_wp
      kmin = 0
      if (f%nen == 8) then
         if (distinct(xe, [1, 2, 3, 4, 5, 6, 7, 8]) == 8) then
            call hex_corner_jacobians(xe, vol, cj)
            kmin = minloc(cj, 1)
            cjmin = cj(kmin)
         end if
      end if
   end subroutine elem_quality

   !> the number of distinct node positions among xe(:, idx)
   pure integer function distinct(xe, idx) result(m)
      real(wp), intent(in) :: xe(:, :)
      integer, intent(in) :: idx(:)
      integer :: i, j
      m = 0
      do i = 1, size(idx)
         do j = 1, i - 1
            if (all(xe(:, idx(j)) == xe(:, idx(i)))) exit
         end do
         if (j == i) m = m + 1
      end do
   end function distinct

   pure function tet_volume(xe) result(vol)
      real(wp), intent(in) :: xe(:, :)
      real(wp) :: vol
      real(wp) :: a(3), b(3), c(3)
      a = xe(:, 2) - xe(:, 1); b = xe(:, 3) - xe(:, 1); c = xe(:, 4) - xe(:, 1)
      vol = (a(1)*(b(2)*c(3) - b(3)*c(2)) - a(2)*(b(1)*c(3) - b(3)*c(1)) &
             + a(3)*(b(1)*c(2) - b(2)*c(1)))/6.0_wp
   end function tet_volume

   pure subroutine tet_moments(xe, xref, vol, m1, m2)
      real(wp), intent(in) :: xe(:, :), xref(3)
      real(wp), intent(out) :: vol, m1(3), m2(3, 3)
      real(wp) :: xl(3, 4), xb(3)
      integer :: k, i, j
      do k = 1, 4
         xl(:, k) = xe(:, k) - xref
      end do
      vol = tet_volume(xl)
      xb = 0.25_wp*(xl(:, 1) + xl(:, 2) + xl(:, 3) + xl(:, 4))
      m1 = vol*xb
      do j = 1, 3
         do i = 1, 3
            m2(i, j) = vol/20.0_wp*(sum(xl(i, :)*xl(j, :)) + 16.0_wp*xb(i)*xb(j))
         end do
      end do
   end subroutine tet_moments

   !> Give the block the family-state slot `slot` with ncol columns (zero), appended to es;
   !> a slot the block has already is kept as it is.
   subroutine block_es_add(blk, slot, ncol)
      class(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: slot, ncol
      real(wp), allocatable :: t(:, :)
      integer :: nes
      if (blk%esc(slot) > 0) return
      nes = 0
      if (allocated(blk%es)) nes = size(blk%es, 2)
      allocate(t(blk%nel, nes + ncol), source=0.0_wp)
      if (nes > 0) t(:, 1:nes) = blk%es
      call move_alloc(t, blk%es)
      blk%esc(slot) = nes + 1
      blk%esn(slot) = ncol
   end subroutine block_es_add

   !> Remove the slot `slot` from the block's family state (the other slots keep their values).
   subroutine block_es_drop(blk, slot)
      class(elem_block_t), intent(inout) :: blk
      integer, intent(in) :: slot
      real(wp), allocatable :: t(:, :)
      integer :: c, m, nes, s
      c = blk%esc(slot)
      if (c == 0) return
      m = blk%esn(slot)
      nes = size(blk%es, 2)
      blk%esc(slot) = 0
      blk%esn(slot) = 0
      if (nes == m) then
         deallocate(blk%es)
         return
      end if
      allocate(t(blk%nel, nes - m))
      t(:, 1:c - 1) = blk%es(:, 1:c - 1)
      t(:, c:) = blk%es(:, c + m:)
      call move_alloc(t, blk%es)
      do s = 1, MAX_ES
         if (blk%esc(s) > c) blk%esc(s) = blk%esc(s) - m
      end do
   end subroutine block_es_drop
end module dx_element_types
