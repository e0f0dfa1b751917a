!> Energy-momentum conserving (EMC) rigid-body contact: the input records the deck readers fill
!> and the state the EMC solver advances. model%emc is allocated only when the deck has
!> *DYNX_CONSERVING_CONTACT; otherwise nothing here is allocated or called.
!> Keywords: *CONTROL_IMPLICIT_GENERAL (IMFLAG, DT0), *DYNX_CONSERVING_CONTACT,
!> *DYNX_RIGID_SPHERE, *DYNX_CONSERVING_CONTROL (docs/conserving-contact.md).
!> Formulation: Simo & Wong 1991 (IJNME 31:19-52) energy-momentum midpoint rule for the bodies;
!> penalty contact with the algorithmic gap (Laursen & Chawla 1997, IJNME 40:863-886; Armero &
!> Petocz 1998, CMAME 158:269-300); LLNL FY97 Engineering Thrust Area Report, article 1.
module dx_emc_types
   use dx_kinds, only: wp
   implicit none
   private
   public :: emc_input_t, emc_contact_in_t, emc_sphere_in_t, emc_system_t, emc_pair_def_t, &
             emc_facet_t, emc_sphere_t, emc_snapshot_t, EMC_PENALTY, EMC_LAGRANGE, &
             EMC_PAIR_NI, EMC_PAIR_NR

   integer, parameter :: EMC_PENALTY = 1, EMC_LAGRANGE = 2

   !> *DYNX_CONSERVING_CONTACT as read
   type :: emc_contact_in_t
      integer :: cid = 0, spid = 0, mpid = 0, form = EMC_PENALTY
      real(wp) :: eps = 0.0_wp
      real(wp) :: fs = 0.0_wp, dfric = 0.0_wp   !< Coulomb coefficient, regularization slip
      integer :: ifile = 0, line = 0
   end type emc_contact_in_t

   !> *DYNX_RIGID_SPHERE as read
   type :: emc_sphere_in_t
      integer :: pid = 0, side = 0
      real(wp) :: tol = 1.0e-3_wp
      integer :: ifile = 0, line = 0
   end type emc_sphere_in_t

   type :: emc_input_t
      type(emc_contact_in_t), allocatable :: contacts(:)
      type(emc_sphere_in_t), allocatable :: spheres(:)
      integer :: maxit = 20            !< Newton iterations per attempt
      real(wp) :: rtol = 1.0e-16_wp    !< residual tolerance relative to the momentum scale
      integer :: nfail = 0             !< 0: stop at a Newton failure; > 0: step cuts allowed
      real(wp) :: out_dt = 0.0_wp      !< emcstat interval (0: every step)
   end type emc_input_t

   !> a planar facet of a rigid body, in the body (principal) frame: centroid, unit normal
   !> (outward from the body material) and the corner points for the inside test
   type :: emc_facet_t
      real(wp) :: c(3) = 0.0_wp, n(3) = 0.0_wp
      real(wp) :: p(3, 4) = 0.0_wp
      integer :: np = 4
      real(wp) :: rad = 0.0_wp       !< largest distance of a corner from c
   end type emc_facet_t

   !> a spherically smoothed body: centre in the body frame, radius, outer (0) or inner (1)
   type :: emc_sphere_t
      real(wp) :: c(3) = 0.0_wp, r = 0.0_wp
      integer :: side = 0
      real(wp) :: fit_err = 0.0_wp
   end type emc_sphere_t

   !> one conserving contact definition between two rigid bodies
   type :: emc_pair_def_t
      integer :: cid = 0
      integer :: sb = 0, mb = 0            !< slave and master body (dense)
      real(wp) :: eps = 0.0_wp
      integer :: form = EMC_PENALTY
      real(wp) :: fs = 0.0_wp, dfric = 0.0_wp
   end type emc_pair_def_t

   !> integers and reals of one contact pair in a snapshot (dx_emc_contact packs them)
   integer, parameter :: EMC_PAIR_NI = 8, EMC_PAIR_NR = 13

   !> The conserving solver's state at a step boundary, copied by dx_emc_solver before each
   !> checkpoint and written to / read from restart dumps by dx_emc_restart: the bodies
   !> (compensated centres, velocities, rotations, body angular velocities), the stored
   !> penalty energy, the pairs in penetration with their algorithmic gaps, and the loop
   !> state (time, cycle, next output times, initial invariants, drift maxima, counters,
   !> emcstat size). valid: restored from a dump (the run continues from it).
   type :: emc_snapshot_t
      logical :: valid = .false.
      real(wp), allocatable :: xc(:, :), xcl(:, :), v(:, :), r(:, :, :), w(:, :)
      integer, allocatable :: act_i(:, :)      !< (EMC_PAIR_NI, nact)
      real(wp), allocatable :: act_r(:, :)     !< (EMC_PAIR_NR, nact)
      real(wp) :: upen = 0.0_wp, ediss = 0.0_wp, t = 0.0_wp, next_out = 0.0_wp
      real(wp) :: next_plot = 0.0_wp
      real(wp) :: e0 = 0.0_wp, p0(3) = 0.0_wp, l0(3) = 0.0_wp, ps0 = 0.0_wp, ls0 = 0.0_wp
      real(wp) :: de = 0.0_wp, dp = 0.0_wp, dl = 0.0_wp, resid = 0.0_wp
      integer :: cyc = 0, itmax = 0, ittot = 0, ncut = 0, iters = 0, npair = 0
      integer :: unit = 0                      !< emcstat (for its size at a dump) ...
      logical :: unit_open = .false.           !< ... while open
      integer(8) :: emcstat_bytes = 0          !< emcstat size at the restored dump
   end type emc_snapshot_t

   type :: emc_system_t
      integer :: nb = 0
      type(emc_pair_def_t), allocatable :: defs(:)
      type(emc_facet_t), allocatable :: facets(:)       !< all facets of all bodies
      integer, allocatable :: fac_ptr(:)                !< (nb+1) facets of body b
      real(wp), allocatable :: snodes(:, :)             !< surface nodes, body frame
      integer, allocatable :: sn_ptr(:)                 !< (nb+1) surface nodes of body b
      integer, allocatable :: sn_node(:)                !< model node of each surface node
      type(emc_sphere_t), allocatable :: sphere(:)      !< (nb) r = 0: not spherical
      real(wp), allocatable :: w(:, :)                  !< (3, nb) body-frame angular velocity
      integer :: maxit = 20, nfail = 0
      real(wp) :: rtol = 1.0e-16_wp, out_dt = 0.0_wp
      !> algorithmic dissipation of the penalty pairs (dx_emc_contact): chi =
      !> (1 - rho_inf)/(2 (1 + rho_inf)), 0 for the conserving midpoint rule (rho_inf and
      !> the step DT0: model%ctrl%imp)
      real(wp) :: chi = 0.0_wp
      real(wp) :: upen = 0.0_wp                         !< stored penalty energy at t(n)
      integer :: newton_total = 0, newton_max = 0, npairs = 0, ncuts = 0
      real(wp) :: resid_max = 0.0_wp
      type(emc_snapshot_t) :: snap                      !< restart state (dx_emc_restart)
   end type emc_system_t
end module dx_emc_types
