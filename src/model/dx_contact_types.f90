!> Persistent contact state: every array a contact interface needs from one cycle to the next
!> (segments, penalty stiffnesses, candidate lists from the bucket sort, tangential trial
!> forces, last sort cycle, resultant forces, sliding-interface work). model_t holds one
!> allocatable contact_set_t; a deck without *CONTACT allocates nothing, so a later restart
!> feature dumps this one component.
!> Penalty node-to-segment contact after Hallquist, Goudreau & Benson 1985 (CMAME 51:107-137)
!> and the DYNA3D User's Manual (Hallquist 1982, UCRL-MA-107254 rev. 1 1991, sliding
!> interfaces); bucket sort after Benson & Hallquist 1990 ("A single surface contact
!> algorithm for the post-buckling analysis of shell structures", CMAME 78:141-163).
module dx_contact_types
   use dx_kinds, only: wp
   implicit none
   private
   public :: contact_set_t, contact_iface_t, contact_pass_t
   public :: NREC, REC_NEAR, REC_NB, REC_FSL, REC_GAP, REC_FT

   !> columns of contact_pass_t%rval: shape functions at the near point (4), at the contact
   !> point (4), the force on the slave node (3), the new gap (1) and tangential force (3)
   integer, parameter :: REC_NEAR = 0, REC_NB = 4, REC_FSL = 8, REC_GAP = 11, REC_FT = 12
   integer, parameter :: NREC = 15

   !> One pass of the node-to-segment algorithm: slave nodes against master segments.
   !> Segments are stored with 4 node slots; a triangle repeats its third node (nsn = 3).
   !> nsn = 2 (lines, for 2D later) keeps the same layout.
   type :: contact_pass_t
      integer :: nnode = 0, nseg = 0
      integer, allocatable :: node(:)          !< (nnode) slave nodes (dense)
      integer, allocatable :: seg(:, :)        !< (4, nseg) master segment nodes
      integer, allocatable :: nsn(:)           !< (nseg) nodes per segment: 3 or 4 (2: line)
      real(wp), allocatable :: kseg(:)         !< (nseg) penalty stiffness f*K*A^2/V
      real(wp), allocatable :: depth(:)        !< (nseg) largest penetration taken as contact
      real(wp), allocatable :: area(:)         !< (nseg) initial area (VC friction limit)
      integer, allocatable :: owner(:, :)      !< (MAX_NEN, nseg) owning element nodes (0: none)
      ! --- shells (allocated only when a segment or a slave node is on a shell): the
      !     contact surface lies half the contact thickness off the mid-surface on either
      !     side (LS-DYNA: the shell thickness, or SST/MST, times SFST/SFMT)
      logical :: shells = .false.
      real(wp), allocatable :: soff(:)         !< (nseg) segment offset (0: a solid's face)
      real(wp), allocatable :: noff(:)         !< (nnode) slave node offset (0: no shell)
      real(wp) :: noffmax = 0.0_wp             !< largest slave node offset
      logical :: exclude_owner = .false.       !< single surface: skip the node's own elements
      ! --- the slave nodes' own surface: a node only contacts segments facing it
      !     (n_node . n_seg < 0); none for node-set slaves
      integer :: nsseg = 0
      integer, allocatable :: sseg(:, :)       !< (4, nsseg) segments of the slave surface
      integer, allocatable :: ssn(:)           !< (nsseg) their node counts
      integer, allocatable :: nloc(:)          !< (nn) local slave index of a node (0: none)
      real(wp), allocatable :: nnrm(:, :)      !< (3, nnode) slave node normals at the sort
      ! --- bucket sort and candidate lists (rebuilt every BSORT cycles or on motion)
      real(wp) :: margin = 0.0_wp              !< search distance beyond the depth
      real(wp) :: moved = 0.0_wp               !< max nodal travel since the last sort
      integer :: last_sort = -1000000          !< cycle of the last sort
      integer :: nsort = 0
      real(wp) :: w2pot = 0.0_wp               !< contact frequency^2 bound of the candidates
      ! --- idle contact (serial runs, dx_contact): at the last bucket sort that ran, the gap
      !     along one axis between the slave nodes' box and the box of the grown segment boxes
      !     when it found no candidate (<= 0: candidates, or not known), its margin, and the
      !     largest nodal travel since it; sorts that provably find no candidate either are
      !     kept as a count (nskip) and their bookkeeping (margin, moved, last_sort) only
      real(wp) :: clear = -1.0_wp
      real(wp) :: margin_real = 0.0_wp
      real(wp) :: moved_real = 0.0_wp
      integer :: nskip = 0
      !     MPI runs: the rank's part of the sort's boxes (the grown boxes of the segments
      !     it sorted, its slave nodes; lo, hi each) and candidate count, reduced over the
      !     ranks after the sort (dx_par_contact idle_reduce) into the serial clear
      real(wp) :: sbox(13) = 0.0_wp
      logical :: sbox_new = .false.
      !     ... and whether that sort found no candidate on any rank (known to every rank)
      logical :: cand_none = .false.
      integer, allocatable :: cand_ptr(:)      !< (nnode+1) CSR into cand
      integer, allocatable :: cand(:)          !< candidate segments of each slave node
      integer :: ncell(3) = 0                  !< bucket grid
      real(wp) :: cell_lo(3) = 0.0_wp, cell_h = 0.0_wp
      integer, allocatable :: cell_ptr(:), cell_seg(:)
      ! --- per-node state
      real(wp), allocatable :: ft(:, :)        !< (3, nnode) tangential (trial) force
      integer, allocatable :: iseg(:)          !< (nnode) segment in contact (0: none)
      real(wp), allocatable :: gap(:)          !< (nnode) its normal gap (< 0), 0: none
      ! --- this cycle's result per slave node (dx_contact_penalty: pass_node computes it,
      !     pass_apply adds it in slave-node order; MPI runs exchange it between strips)
      integer, allocatable :: rint(:, :)       !< (2, nnode) near segment, contact segment
      real(wp), allocatable :: rval(:, :)      !< (NREC, nnode) see REC_* below
      ! --- strips (MPI runs, dx_contact_strips): slave node -> strip at the last sort
      logical, allocatable :: mine(:)          !< (nnode) computed by this rank (MPI only)
      integer :: strip_axis = 0                !< axis of the strips at the last sort
      logical :: sort_due = .false.            !< this cycle sorts (contact_prepare)
      ! --- MPI ghost sorts (dx_par_contact, owner-computes): which segments' node x are
      !     current on this rank at the sort (the rest lie outside the reach of its slave
      !     nodes; unallocated: all), and the mean segment extent of the whole pass summed
      !     in segment order from the ranks' parts (< 0: summed here from x). Not dumped.
      logical, allocatable :: segok(:)         !< (nseg)
      real(wp) :: mext = -1.0_wp
      ! --- element erosion (decks that erode only; dx_contact%erosion_refresh): each
      !     segment's owner element and the element across its face (0: an exterior face;
      !     interior faces are dormant until that element erodes), whether it is live now,
      !     the same for the slave surface, and whether a living element holds the slave node
      integer, allocatable :: oelem(:), onbr(:)   !< (nseg) dense element indices
      logical, allocatable :: live(:)             !< (nseg)
      integer, allocatable :: soelem(:), snbr(:)  !< (nsseg)
      logical, allocatable :: slive(:)            !< (nsseg)
      logical, allocatable :: nlive(:)            !< (nnode)
      logical :: live_set = .false.               !< masks formed (the first refresh)
   end type contact_pass_t

   !> One *CONTACT_... interface: parameters, one or two passes, resultant forces.
   type :: contact_iface_t
      integer :: label = 0
      character(:), allocatable :: name        !< keyword (for messages)
      integer :: kind = 0
      real(wp) :: fs = 0.0_wp, fd = 0.0_wp, dc = 0.0_wp, vc = 0.0_wp, vdc = 0.0_wp
      real(wp) :: bt = 0.0_wp, dt = 1.0e20_wp
      real(wp) :: fsf = 1.0_wp, vsf = 1.0_wp
      integer :: soft = 0
      real(wp) :: sofscl = 0.1_wp
      integer :: bsort = 10
      type(contact_pass_t), allocatable :: pass(:)
      real(wp) :: fslave(3) = 0.0_wp           !< resultant force on the slave side
      real(wp) :: fmaster(3) = 0.0_wp          !< resultant force on the master side
      integer :: nactive = 0                   !< slave nodes in contact, last cycle
      !> work of the contact forces on the slave and on the master nodes since t = 0
      !> (centred, as contact_set_t%work; sleout: dx_energy_sums%interface_work)
      real(wp) :: wslave = 0.0_wp, wmaster = 0.0_wp
      !> the v(n+1/2) half of this cycle's work (sleout books W - h at t(n), as glstat's
      !> sliding energy: dx_contact%contact_work); recomputed every cycle, not dumped
      real(wp) :: hslave = 0.0_wp, hmaster = 0.0_wp
      integer :: rank = -1                     !< MPI runs: the rank computing a local pair
                                               !< (-1: strips)
   end type contact_iface_t

   !> All interfaces of the model and their shared state.
   type :: contact_set_t
      type(contact_iface_t), allocatable :: iface(:)
      integer, allocatable :: node(:)          !< every node any interface touches
      real(wp), allocatable :: fc(:, :)        !< (3, nn) contact force of this cycle
      real(wp), allocatable :: krow(:)         !< (nn) contact stiffness row sums, this cycle
      real(wp) :: work = 0.0_wp                !< work of the contact forces (centred)
      real(wp) :: rcforc_dt = 0.0_wp
      real(wp) :: next_rcforc = 0.0_wp
      integer :: rcforc_unit = 0
      logical :: rcforc_open = .false.
      integer(8) :: rcforc_resume = 0          !< restart: bytes of rcforc to keep (0: anew)
      real(wp) :: t_search = 0.0_wp            !< wall time in bucket sorts [s]
      real(wp) :: t_force = 0.0_wp             !< wall time in local search + forces [s]
      real(wp) :: dt_limit = huge(1.0_wp)      !< contact bound on the critical step, last cycle
      logical :: finished = .false.
      integer :: nstrip = 1                    !< MPI runs: strips (ranks) of the search
      integer :: istrip = 0                    !< this rank's strip, 0..nstrip-1
      !> MPI runs, owner-computes (dx_par_contact): (nn) the slave nodes this rank computes
      !> (the nodes it owns); unallocated: geometric strips (dx_contact_strips)
      logical, allocatable :: mine_node(:)
   end type contact_set_t
end module dx_contact_types
