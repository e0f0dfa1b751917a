!> State of the 2D contacts (*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE; dx_contact2d): per
!> interface the two passes (slave nodes against master edges, and back: symmetric), the
!> penalty per master edge, Coulomb friction, and the work of the contact forces booked one
!> cycle late (the force of t(n-1) with v(n-3/2), v(n-1/2)). Held by model_t.
module dx_contact2d_types
   use dx_kinds, only: wp
   implicit none
   private
   public :: c2d_pass_t, c2d_iface_t, contact2d_t

   !> one pass: the nodes of one side against the free edges of the other
   type :: c2d_pass_t
      integer, allocatable :: node(:)          !< (ns) slave nodes
      integer, allocatable :: edge(:, :)       !< (2, nm) master edges a -> b (outward (dy, -dx))
      real(wp), allocatable :: k(:)            !< (nm) penalty stiffness of each master edge
      !> (4, nm) single surface only: the nodes of the element each master edge bounds
      integer, allocatable :: own(:, :)
      !> tied interfaces: each slave node's master edge (0: not tied), its place xi on it
      !> and its offset from that point at t = 0 in the edge's frame (the gap the tie keeps)
      integer, allocatable :: tie_edge(:)
      real(wp), allocatable :: tie_xi(:), tie_off(:, :)   !< tie_off(2, ns): (along t, along n)
   end type c2d_pass_t

   type :: c2d_iface_t
      integer :: label = 0
      real(wp) :: fs = 0.0_wp                  !< Coulomb friction coefficient
      !> ISTIFF: 0 and 2 the segment penalty pass(:)%k; 1 the soft-constraint stiffness 0.5 SOFSCL
      !> m*/dt**2 (m* the smaller of the slave's and the edge point's mass, dt the last step)
      integer :: istiff = 0
      !> passes run: 2 (surface to surface), 1 (single surface: pass 1 is every node of the
      !> side against every edge of it; pass 2 holds the same edges for the nodal normals)
      integer :: npass = 2
      logical :: tied = .false.                !< *CONTACT_2D_AUTOMATIC_TIED(_ONE_WAY)
      real(wp) :: sofscl = 0.1_wp              !< 0.1 SFACT (ISTIFF = 1)
      type(c2d_pass_t) :: pass(2)
   end type c2d_iface_t

   type :: contact2d_t
      type(c2d_iface_t), allocatable :: iface(:)
      real(wp), allocatable :: fc(:, :)        !< (2, nn) contact force of this cycle
      real(wp), allocatable :: fold(:, :)      !< (2, nn) of the last cycle
      real(wp), allocatable :: vold(:, :)      !< (2, nn) v(n-3/2)
      real(wp) :: dtold = 0.0_wp               !< dt_old of the last cycle
      real(wp) :: dtsoft = 0.0_wp              !< the step of the soft constraint (ISTIFF 1)
      real(wp) :: work = 0.0_wp                !< work of the contact forces (one cycle late)
      integer :: ncontact = 0                  !< slave nodes in contact, this cycle
   end type contact2d_t
end module dx_contact2d_types
