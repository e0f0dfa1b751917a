!> Rigid bodies in an MPI run (ParaDyn step 5; docs/history.md, "Rigid bodies and loads under
!> MPI"). A body's nodes may lie on several ranks. Every rank has built the serial model, so
!> the bodies' mass properties (mass, centre, principal moments and axes, body coordinates:
!> dx_rigid_build, from the whole deck) and their initial state are the same bits on every
!> rank, and model%rigid keeps the serial (global) node numbers.
!> Per cycle, after the nodal velocity update: the owned rigid nodes' x(n), f(n) (after the
!> shared-node exchange and the external loads: the serial f) and v(n-1/2) are gathered into
!> the engine's global model (one MPI_Allgatherv), then every rank runs the serial
!> rigid_step (dx_rigid_solver: resultant force and moment summed over the body's nodes in
!> ascending global order, the DLM rotation integrator of Dullweber, Leimkuhler & McLachlan
!> 1997, J Chem Phys 107:5840) on the global model: same inputs, same order, same code, so
!> the same bits on every rank and as in the serial run. Each rank then copies the secant
!> velocities of the rigid nodes it holds (owned and shared) into its sub-model; the next
!> x = x + dt v lands them where the serial run puts them. The body kinetic-energy and
!> momentum corrections and the constraint work are global numbers (the same on every rank).
!> rbdout is written by rank 0 (dx_explicit). Rigid bodies in contact: f holds the contact
!> force (dx_par_contact adds it before this stage), and the contact stage, which runs on
!> the global model, reads the bodies' centres there (dx_rigid_contact): par_rigid_centres
!> copies them in before it (docs/history.md, "Rigid bodies in contact under MPI").
module dx_par_rigid
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_par, only: par_rank
   use dx_par_plan, only: gather_plan_t, par_gather_setup, par_gather_values
   use dx_par_model, only: par_model_t
   use dx_rigid_types, only: rigid_system_t
   use dx_rigid_solver, only: rigid_step
   implicit none
   private
   public :: par_rigid_t, par_rigid_setup, par_rigid_step, par_rigid_writes, par_rigid_centres

   !> The rigid-body stage's part of a rank's domain (a component of mpi_domain_t).
   type :: par_rigid_t
      type(model_t), pointer :: gp => null()     !< the engine's global model
      integer, allocatable :: r_own(:)            !< owned local rigid nodes (gathered)
      integer, allocatable :: r_loc(:), r_glob(:) !< all local rigid nodes, global index
      type(gather_plan_t) :: plan_r
      real(wp), allocatable :: gvold(:, :)        !< (3, global nn) v(n-1/2) of rigid nodes
   end type par_rigid_t

contains

   !> Called by par_engine_setup after par_model_build (nothing without rigid bodies).
   subroutine par_rigid_setup(pr, g, pm, owned)
      type(par_rigid_t), intent(inout) :: pr
      type(model_t), intent(inout), target :: g
      type(par_model_t), intent(in) :: pm
      logical, intent(in) :: owned(:)
      logical, allocatable :: rig(:)
      integer :: i
      if (.not. allocated(g%rigid)) return
      pr%gp => g
      rig = g%rigid%node_body(pm%node_global) > 0
      pr%r_own = pack([(i, i = 1, pm%nloc)], rig .and. owned)
      pr%r_loc = pack([(i, i = 1, pm%nloc)], rig)
      pr%r_glob = pm%node_global(pr%r_loc)
      call par_gather_setup(pr%plan_r, pm%node_global(pr%r_own))
      allocate(pr%gvold(3, g%nn))
      pr%gvold = 0.0_wp
   end subroutine par_rigid_setup

   !> The rigid-body stage of the cycle (in place of rigid_step in a serial run).
   subroutine par_rigid_step(pr, model, t, dt, dtavg, vold)
      type(par_rigid_t), intent(inout) :: pr
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      real(wp), allocatable :: vals(:, :), gv(:, :)
      integer :: i, n
      associate (r_own => pr%r_own, plan_r => pr%plan_r, gp => pr%gp, gvold => pr%gvold, &
                 r_loc => pr%r_loc, r_glob => pr%r_glob)
      allocate(vals(9, size(r_own)), gv(9, size(plan_r%keys)))
      do i = 1, size(r_own)
         n = r_own(i)
         vals(1:3, i) = model%x(:, n)
         vals(4:6, i) = model%f(:, n)
         vals(7:9, i) = vold(:, n)
      end do
      call par_gather_values(plan_r, vals, gv)
      associate (keys => plan_r%keys)
         gp%x(:, keys) = gv(1:3, :)
         gp%f(:, keys) = gv(4:6, :)
         gvold(:, keys) = gv(7:9, :)
      end associate
      if (allocated(model%mom)) then    ! shells: the rigid nodes' moments (summed) too
         if (.not. allocated(gp%mom)) then
            allocate(gp%mom(3, gp%nn))
            gp%mom = 0.0_wp
         end if
         deallocate(vals, gv)
         allocate(vals(3, size(r_own)), gv(3, size(plan_r%keys)))
         vals = model%mom(:, r_own)
         call par_gather_values(plan_r, vals, gv)
         gp%mom(:, plan_r%keys) = gv
      end if
      call rigid_step(model%rigid, gp, t, dt, dtavg, gvold)
      model%v(:, r_loc) = gp%v(:, r_glob)
      if (allocated(model%mom)) then    ! the body's omega, no nodal rotary inertia
         model%w(:, r_loc) = gp%w(:, r_glob)
         model%rinert(r_loc) = 0.0_wp
      end if
      ! the global model reports the momentum (set_energy) with the body correction
      gp%rigid%p_corr = model%rigid%p_corr
      gp%rigid%ke_corr = model%rigid%ke_corr
      end associate
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
