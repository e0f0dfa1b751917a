!> Rigid bodies: the input records the deck readers fill (labels) and the rigid system the
!> solver advances (dense indices). All persistent rigid-body state lives in rigid_system_t
!> (model%rigid), so a restart dumps it with the model; a deck without rigid bodies leaves
!> model%rigid unallocated.
!> Keywords: *MAT_RIGID (*MAT_020) parts, *PART_INERTIA, *CONSTRAINED_NODAL_RIGID_BODY,
!> *CONSTRAINED_EXTRA_NODES_NODE/_SET, *BOUNDARY_PRESCRIBED_MOTION_RIGID, *DATABASE_RBDOUT.
!> State per body (Dullweber, Leimkuhler & McLachlan 1997, J Chem Phys 107:5840):
!>   xc (t(n)), vc (t(n+1/2)), rot = R(n) (principal body frame -> global),
!>   lsp = spatial angular momentum about the centre of mass at t(n+1/2).
module dx_rigid_types
   use dx_kinds, only: wp
   implicit none
   private
   public :: rigid_input_t, inertia_in_t, nrb_in_t, extra_in_t, rmotion_in_t, &
             rigid_system_t, rigid_body_t, rigid_motion_t, rigid_origin_t

   !> where a record came from (file index, line, keyword without '*')
   type :: rigid_origin_t
      integer :: ifile = 0, line = 0
      character(:), allocatable :: key
   end type rigid_origin_t

   !> *PART_INERTIA extra cards (the PART card itself goes to the part list)
   type :: inertia_in_t
      integer :: pid = 0
      real(wp) :: xc(3) = 0.0_wp, tm = 0.0_wp
      integer :: ircs = 0, nodeid = 0
      real(wp) :: inertia(6) = 0.0_wp     !< IXX IXY IXZ IYY IYZ IZZ (global, about the c.o.m.)
      real(wp) :: vt(3) = 0.0_wp, vr(3) = 0.0_wp
      type(rigid_origin_t) :: src
   end type inertia_in_t

   !> *CONSTRAINED_NODAL_RIGID_BODY
   type :: nrb_in_t
      integer :: pid = 0, nsid = 0, iprt = 0
      type(rigid_origin_t) :: src
   end type nrb_in_t

   !> *CONSTRAINED_EXTRA_NODES_NODE (id = node) or _SET (id = node set)
   type :: extra_in_t
      integer :: pid = 0, id = 0
      logical :: is_set = .false.
      type(rigid_origin_t) :: src
   end type extra_in_t

   !> *BOUNDARY_PRESCRIBED_MOTION_RIGID
   type :: rmotion_in_t
      integer :: pid = 0, dof = 0, vad = 0, lcid = 0
      real(wp) :: sf = 1.0_wp, death = 1.0e28_wp, birth = 0.0_wp
      type(rigid_origin_t) :: src
   end type rmotion_in_t

   !> the rigid-body keywords as read
   type :: rigid_input_t
      type(inertia_in_t), allocatable :: inertias(:)
      type(nrb_in_t), allocatable :: nrbs(:)
      type(extra_in_t), allocatable :: extras(:)
      type(rmotion_in_t), allocatable :: motions(:)
      real(wp) :: rbdout_dt = 0.0_wp
   end type rigid_input_t

   !> one prescribed rigid motion: dof 1-3 translation along x, y, z; 5-7 rotation about x, y, z
   type :: rigid_motion_t
      integer :: dof = 0
      integer :: vad = 0            !< 0 velocity, 1 acceleration, 2 displacement
      integer :: curve = 0          !< dense curve index
      real(wp) :: sf = 1.0_wp
      real(wp) :: birth = 0.0_wp, death = 1.0e28_wp
      real(wp) :: disp = 0.0_wp     !< displacement (rotation angle) accumulated so far
   end type rigid_motion_t

   type :: rigid_body_t
      integer :: label = 0          !< part id (rigid part or nodal rigid body PID)
      integer :: ipart = 0          !< dense part index (0: nodal rigid body without elements)
      logical :: nodal = .false.    !< *CONSTRAINED_NODAL_RIGID_BODY
      integer, allocatable :: nodes(:)        !< dense node indices moving with the body
      real(wp), allocatable :: s(:, :)        !< (3, n) node positions in the principal frame
      real(wp) :: mass = 0.0_wp
      real(wp) :: ip(3) = 0.0_wp              !< principal moments of inertia
      real(wp) :: x0(3) = 0.0_wp              !< initial centre of mass
      real(wp) :: xc(3) = 0.0_wp, vc(3) = 0.0_wp
      real(wp) :: rot(3, 3) = 0.0_wp
      real(wp) :: xc_n(3) = 0.0_wp, rot_n(3, 3) = 0.0_wp   !< x_c(n), R(n) for output
      real(wp) :: lsp(3) = 0.0_wp
      real(wp) :: omega(3) = 0.0_wp           !< spatial angular velocity at t(n+1/2)
      real(wp) :: fsum(3) = 0.0_wp, tsum(3) = 0.0_wp   !< resultant force, torque at t(n)
      logical :: fix_t(3) = .false., fix_r(3) = .false.   !< *MAT_RIGID CON1, CON2
      type(rigid_motion_t), allocatable :: motions(:)
   end type rigid_body_t

   type :: rigid_system_t
      type(rigid_body_t), allocatable :: bodies(:)
      integer, allocatable :: node_body(:)    !< (nn) body of each node, 0 if deformable
      real(wp) :: dtcrit = huge(1.0_wp)       !< stable step of the rigid elements (all-rigid decks)
      real(wp) :: ke_corr = 0.0_wp            !< body KE minus the nodal KE of rigid nodes, t(n)
      real(wp) :: ke0_corr = 0.0_wp           !< the same at t = 0
      real(wp) :: p_corr(3) = 0.0_wp          !< body momentum minus nodal momentum, t(n+1/2)
      !> the bodies' own kinetic energy at t(n) and momentum at t(n+1/2) (the reported
      !> energies add the rigid nodes' nodal terms, negated, to their exact sums)
      real(wp) :: ke_body = 0.0_wp, p_body(3) = 0.0_wp
      real(wp) :: mass_corr = 0.0_wp          !< body masses minus nodal masses of rigid nodes
      real(wp) :: work = 0.0_wp               !< work of rigid constraints and prescribed motion
      real(wp) :: rbdout_dt = 0.0_wp
      real(wp) :: next_rbdout = 0.0_wp
      integer :: rbdout_unit = 0
      logical :: rbdout_open = .false.
      integer(8) :: rbdout_resume = 0         !< restart: bytes of rbdout to keep (0: anew)
   end type rigid_system_t
end module dx_rigid_types
