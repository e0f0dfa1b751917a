!> Rigid bodies in an MPI run (ParaDyn step 5; docs/history.md, "Rigid bodies and loads under
!> MPI" and "Reproducible sums"). A body's nodes may lie on several ranks. Every rank has
!> built the serial model, so the bodies' mass properties (mass, centre, principal moments
!> and axes, body coordinates: dx_rigid_build, from the whole deck) and their initial state
!> are the same bits on every rank, and model%rigid keeps the serial (global) node numbers.
!> Per cycle, after the nodal velocity update: each rank adds the force, torque, mass and
!> first-moment terms of the body nodes it owns (x(n), f(n) after the shared-node exchange
!> and the external loads: the serial f) into exact sums (dx_rigid_exact, dx_repro_sum),
!> one int64 MPI_Allreduce sums them over the ranks, and every rank advances every body
!> from the same bits with the serial code (dx_rigid_solver rigid_body_advance), then
!> moves the body nodes it holds (owned and shared: the same secant velocity on every
!> holder); the next x = x + dt v lands them where the serial run puts them. Nothing is
!> gathered. The body kinetic-energy and momentum corrections and the constraint work are
!> global numbers (the same on every rank); the rigid nodes' own nodal terms are exact sums
!> of the owned nodes, added to the energy event's sums. rbdout is written by rank 0
!> (dx_explicit). Rigid bodies in contact: f holds the contact force (dx_par_contact adds
!> it before this stage), and the contact stage, which runs on the global model, reads the
!> bodies' centres there (dx_rigid_contact): par_rigid_centres copies them in before it
!> (docs/history.md, "Rigid bodies in contact under MPI").
module dx_par_rigid
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_par, only: par_rank
   use dx_par_model, only: par_model_t
   use dx_rigid_types, only: rigid_system_t
   use dx_rigid_exact, only: rigid_map_t, rigid_exact_step
   implicit none
   private
   public :: par_rigid_t, par_rigid_setup, par_rigid_step, par_rigid_writes, par_rigid_centres

   !> The rigid-body stage's part of a rank's domain (a component of mpi_domain_t).
   type :: par_rigid_t
      type(rigid_map_t) :: map                    !< the bodies' local nodes (owned or not)
   end type par_rigid_t

contains

   !> Called by par_engine_setup after par_model_build (nothing without rigid bodies): each
   !> body's local nodes, their positions in the body's node list and ownership.
   subroutine par_rigid_setup(pr, g, pm, owned)
      type(par_rigid_t), intent(inout) :: pr
      type(model_t), intent(inout), target :: g
      type(par_model_t), intent(in) :: pm
      logical, intent(in) :: owned(:)
      integer, allocatable :: posg(:), cnt(:), loc(:)
      integer :: i, b, nb, k, ng
      if (.not. allocated(g%rigid)) return
      nb = size(g%rigid%bodies)
      allocate(posg(g%nn), cnt(nb + 1))
      posg = 0
      do b = 1, nb
         do i = 1, size(g%rigid%bodies(b)%nodes)
            posg(g%rigid%bodies(b)%nodes(i)) = i
         end do
      end do
      loc = pack([(i, i = 1, pm%nloc)], g%rigid%node_body(pm%node_global) > 0)
      cnt = 0
      do k = 1, size(loc)
         b = g%rigid%node_body(pm%node_global(loc(k)))
         cnt(b + 1) = cnt(b + 1) + 1
      end do
      allocate(pr%map%ptr(nb + 1), pr%map%node(size(loc)), pr%map%pos(size(loc)), &
               pr%map%own(size(loc)))
      pr%map%ptr(1) = 1
      do b = 1, nb
         pr%map%ptr(b + 1) = pr%map%ptr(b) + cnt(b + 1)
      end do
      cnt(1:nb) = pr%map%ptr(1:nb)
      do k = 1, size(loc)
         ng = pm%node_global(loc(k))
         b = g%rigid%node_body(ng)
         pr%map%node(cnt(b)) = loc(k)
         pr%map%pos(cnt(b)) = posg(ng)
         pr%map%own(cnt(b)) = owned(loc(k))
         cnt(b) = cnt(b) + 1
      end do
   end subroutine par_rigid_setup

   !> The rigid-body stage of the cycle (in place of rigid_step in a serial run).
   subroutine par_rigid_step(pr, model, t, dt, dtavg, vold)
      type(par_rigid_t), intent(inout) :: pr
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      call rigid_exact_step(pr%map, model, t, dt, dtavg, vold)
   end subroutine par_rigid_step

   !> True on the rank that writes rbdout (rank 0; every rank has the same body states).
   logical function par_rigid_writes()
      par_rigid_writes = par_rank() == 0
   end function par_rigid_writes
   !> The bodies' centres x_c(n) from the state (the sub-model's rigid system, advanced on
   !> every rank) into the global model's copy, which the contact stage reads (the effective
   !> masses of the bucket sort and the contact step bound, dx_rigid_contact). Mass,
   !> principal moments and the fixed flags do not change during the run.
   subroutine par_rigid_centres(state, grs)
      type(rigid_system_t), intent(in) :: state
      type(rigid_system_t), intent(inout) :: grs
      integer :: b
      do b = 1, size(state%bodies)
         grs%bodies(b)%xc = state%bodies(b)%xc
      end do
   end subroutine par_rigid_centres
end module dx_par_rigid
