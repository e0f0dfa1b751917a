!> One rank's domain of an MPI run (ParaDyn step 5: Hoover et al., LLNL Engineering Thrust
!> Area Report FY97, article 4 of shared/seed; fixed-order sums after OpenRadioss
!> /PARITH/ON): each stage of dx_domain's cycle as the MPI engine performs it - shared
!> nodes' slots filled before the element pass, one shared-node force exchange in serial
!> order (posted right after the element pass, before the MINLOC, so the messages travel
!> during the MINLOC, contact and loads; finished at the exchange stage: ParaDyn's overlap of
!> communication and computation), one MINLOC for the step that also carries the failure
!> flag and the stop/dump requests, work and energy sums in serial order from gathered
!> terms, plot parts per rank (dx_par_engine, dx_par_loads, dx_par_rigid, dx_par_contact,
!> dx_par_plot, dx_par_restart).
!> domain_create builds the run's domain once: serial (one rank, or the conserving solver's
!> or the implicit solver's replicated run) or MPI.
module dx_domain_mpi
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_par, only: par_size, par_rank, par_allreduce, PAR_MAX, par_traffic_line
   use dx_log, only: log_info, log_set_quiet
   use dx_par_model, only: par_exchange_post, par_exchange_drop
   use dx_mass_scaling, only: lump_mass
   use dx_domain, only: domain_t, serial_domain_t, requests_t
   use dx_par_engine_setup, only: par_engine_setup, par_engine_mass_share
   use dx_par_engine, only: par_engine_t, par_engine_on, par_engine_mass, par_engine_remass, &
                            par_engine_elout, &
                            par_engine_initial, par_engine_writer, &
                            par_engine_fill, par_engine_pending, par_engine_defer, &
                            par_engine_dt, par_engine_global, par_engine_exchange, &
                            par_engine_constraints, par_engine_energies, par_engine_plot, &
                            par_engine_fail, par_engine_output, par_engine_sync_failure, &
                            par_engine_plot_finish, par_engine_flush_work, par_engine_report, &
                            par_engine_together
   use dx_par_loads, only: par_loads_t, par_loads_any, par_loads_shared, par_loads_work, &
                           par_loads_flush, par_loads_remass
   use dx_par_rigid, only: par_rigid_t, par_rigid_step, par_rigid_writes
   use dx_par_contact, only: par_contact_t, par_contact_forces, par_contact_add, &
                             par_contact_work
   use dx_par_contact2d, only: par_contact2d_t, par_contact2d_setup, par_contact2d_forces, &
                               par_contact2d_add, par_contact2d_from_global
   use dx_par_plot, only: par_plot_t, par_plot_nstates
   use dx_par_restart, only: par_restart_parts_t, par_restart_write, par_restart_read
   implicit none
   private
   public :: mpi_domain_t, domain_create

   !> This rank's part of an MPI run: the state of every stage (the conserving solver's
   !> split, emc, is in domain_t: its MPI run is a replicated serial domain).
   type, extends(domain_t) :: mpi_domain_t
      type(par_loads_t) :: loads        !< external loads on shared nodes, external work
      type(par_rigid_t) :: rigid        !< rigid bodies spanning ranks
      type(par_plot_t) :: plot          !< this rank's plot part file
      type(par_contact_t) :: contact    !< contact nodes' plans and halo
      type(par_contact2d_t) :: c2d      !< the 2D contact, replicated (dx_par_contact2d)
      type(par_engine_t) :: eng         !< global model, plan and maps, kept work, failures
      type(par_restart_parts_t) :: parts  !< the dump parts this rank wrote or read
   contains
      procedure :: sum_mass => m_sum_mass
      procedure :: mass_share => m_mass_share
      procedure :: remass => m_remass
      procedure :: initial_energy => m_initial_energy
      procedure :: has_loads => m_has_loads
      procedure :: writer => m_writer
      procedure :: rigid_writer => m_rigid_writer
      procedure :: fill => m_fill
      procedure :: pending => m_pending
      procedure :: defer => m_defer
      procedure :: reduce_dt => m_reduce_dt
      procedure :: contact_forces => m_contact_forces
      procedure :: loads_shared => m_loads_shared
      procedure :: exchange => m_exchange
      procedure :: rigid_step => m_rigid_step
      procedure :: constraints => m_constraints
      procedure :: load_work => m_load_work
      procedure :: contact_work => m_contact_work
      procedure :: energies => m_energies
      procedure :: write_plot => m_write_plot
      procedure :: fail => m_fail
      procedure :: output_model => m_output_model
      procedure :: output_target => m_output_target
      procedure :: element_output => m_element_output
      procedure :: sync_failure => m_sync_failure
      procedure :: plot_finish => m_plot_finish
      procedure :: write_dump => m_write_dump
      procedure :: read_restart => m_read_restart
      procedure :: report => m_report
      procedure :: together => m_together
      procedure :: plot_note => m_plot_note
      procedure :: launcher => m_launcher
   end type mpi_domain_t

contains

   !> The run's domain, built once from the model every rank read: on more than one rank
   !> the rank's part (par_engine_setup: rank files, or rank 0 partitions), else serial.
   !> split: dynx --contact-split (owner, strips, or '': DYNX_PAR_CONTACT, else owner).
   subroutine domain_create(model, deck, outdir, partdir, split, dom, error)
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: deck, outdir, partdir, split
      class(domain_t), allocatable, intent(out) :: dom
      type(error_t), allocatable, intent(out) :: error
      type(mpi_domain_t), allocatable :: md
      if (par_size() > 1 .and. model%ctrl%imp%imflag == 1 .and. .not. allocated(model%emc)) then
         ! the implicit solver under MPI: the whole model on every rank (replicated, rank 0
         ! writes), its elements split by dx_implicit_par; no rank files
         if (par_rank() > 0) call log_set_quiet(.true.)
         if (len(partdir) > 0) call log_info('dynx: note: --part '//partdir//' is not used '// &
            'by the implicit solver (it splits the elements by its own METIS partition)')
         allocate(serial_domain_t :: dom)
         return
      end if
      allocate(md)
      md%contact%split_mode = split
      call par_engine_setup(md%eng, model, deck, outdir, partdir, md%loads, md%rigid, md%plot, &
                            md%contact, md%emc, error)
      if (par_engine_on(md%eng)) then
         if (.not. allocated(error) .and. allocated(model%contact2d)) &
            call par_contact2d_setup(md%c2d, model, md%eng%pm%node_global, md%eng%owned)
         call move_alloc(md, dom)
      else
         allocate(serial_domain_t :: dom)
         dom%emc = md%emc              ! a conserving deck: the slave points' split (MPI)
      end if
   end subroutine domain_create

   subroutine m_sum_mass(d, model)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      call par_engine_mass(d%eng, model)
   end subroutine m_sum_mass

   subroutine m_mass_share(d, model, cnodes)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      integer, intent(in) :: cnodes(:)
      call par_engine_mass_share(d%eng, model, cnodes, d%loads)
   end subroutine m_mass_share

   !> Mass scaling: any rank's change is every rank's (one MAX reduction per cycle), then
   !> the lumped masses summed in serial order (par_engine_remass) and the loads' masses.
   subroutine m_remass(d, model, changed)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      logical, intent(inout) :: changed
      integer :: flag
      flag = merge(1, 0, changed)
      call par_allreduce(flag, PAR_MAX)
      changed = flag == 1
      if (.not. changed) return
      call lump_mass(model)
      call par_engine_remass(d%eng, model)
      call par_loads_remass(d%loads, model)
   end subroutine m_remass

   subroutine m_initial_energy(d, model)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      call par_engine_initial(d%eng, model)
   end subroutine m_initial_energy

   logical function m_has_loads(d, model)
      class(mpi_domain_t), intent(in) :: d
      type(model_t), intent(in) :: model
      m_has_loads = par_loads_any(d%loads)
   end function m_has_loads

   logical function m_writer(d)
      class(mpi_domain_t), intent(in) :: d
      m_writer = par_engine_writer()
   end function m_writer

   logical function m_rigid_writer(d)
      class(mpi_domain_t), intent(in) :: d
      m_rigid_writer = par_rigid_writes()
   end function m_rigid_writer

   subroutine m_fill(d, model)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      call par_engine_fill(d%eng, model)
   end subroutine m_fill

   logical function m_pending(d)
      class(mpi_domain_t), intent(in) :: d
      m_pending = par_engine_pending(d%eng)
   end function m_pending

   !> Kept until the next dt reduction makes it known to every rank: error is deallocated.
   subroutine m_defer(d, error)
      class(mpi_domain_t), intent(inout) :: d
      type(error_t), allocatable, intent(inout) :: error
      call par_engine_defer(d%eng, error)
   end subroutine m_defer

   !> Global min with the serial tie rule; the ranks' stop/dump requests (req%poll) ride in
   !> it and come back reduced in req%coll; a failure on any rank stops all.
   subroutine m_reduce_dt(d, model, dtcrit, ibmin, req, error)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(inout) :: dtcrit
      integer, intent(in) :: ibmin
      class(requests_t), intent(inout) :: req
      type(error_t), allocatable, intent(inout) :: error
      integer :: flags(4)
      ! the slots' forces are final: post their exchange (finished in m_exchange)
      call par_exchange_post(d%eng%pm, model%f)
      call req%poll(flags)
      call par_engine_dt(d%eng, dtcrit, model%dt_elem, error, flags)
      if (allocated(error)) call par_exchange_drop(d%eng%pm)   ! no exchange stage follows
      req%coll = flags
      req%collective = .true.
   end subroutine m_reduce_dt

   subroutine m_contact_forces(d, model, dt_old, dtcrit)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: dtcrit
      if (allocated(model%contact)) &
         call par_contact_forces(d%contact, model, par_engine_global(d%eng), dt_old, dtcrit)
      if (d%c2d%on) call par_contact2d_forces(d%c2d, model, dt_old, dtcrit)
   end subroutine m_contact_forces

   subroutine m_loads_shared(d, model, t, fext)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
      call par_loads_shared(d%loads, model, t, fext)
   end subroutine m_loads_shared

   !> Serial-order sums at shared nodes, then the contact forces at held contact nodes.
   subroutine m_exchange(d, model)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      call par_engine_exchange(d%eng, model%f)
      if (allocated(model%mom)) call par_engine_exchange(d%eng, model%mom)   ! shells' moments
      if (allocated(model%contact)) call par_contact_add(d%contact, model, par_engine_global(d%eng))
      if (d%c2d%on) call par_contact2d_add(d%c2d, model)
   end subroutine m_exchange

   subroutine m_rigid_step(d, model, t, dt, dtavg, vold)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      call par_rigid_step(d%rigid, model, t, dt, dtavg, vold)
   end subroutine m_rigid_step

   subroutine m_constraints(d, model, cnodes, vfree, vold, dt, dtavg, wcon, wrw, need, wold)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      integer, intent(in) :: cnodes(:)
      real(wp), intent(in) :: vfree(:, :), vold(:, :), dt, dtavg
      real(wp), intent(inout) :: wcon, wrw
      logical, intent(in) :: need
      real(wp), intent(in), optional :: wold(:, :)
      call par_engine_constraints(d%eng, model, vfree, vold, dt, dtavg, wcon, wrw, need, wold)
   end subroutine m_constraints

   subroutine m_load_work(d, fext, vold, v, dtavg, wext, need)
      class(mpi_domain_t), intent(inout) :: d
      real(wp), intent(in) :: fext(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: wext
      logical, intent(in) :: need
      call par_loads_work(d%loads, fext, vold, v, dtavg, wext, need)
   end subroutine m_load_work

   subroutine m_contact_work(d, model, vold, dtavg, outdir, error)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: vold(:, :), dtavg
      character(*), intent(in) :: outdir
      type(error_t), allocatable, intent(out) :: error
      call par_contact_work(d%contact, model, par_engine_global(d%eng), vold, dtavg, outdir)
   end subroutine m_contact_work

   subroutine m_energies(d, model, ke, vold, wsum, erw, dfac, need, wold, parts)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: ke, vold(:, :), wsum, erw, dfac
      logical, intent(in) :: need
      real(wp), intent(in), optional :: wold(:, :)
      logical, intent(in), optional :: parts
      if (allocated(model%rigid)) then     ! the rigid nodes' terms of the cycle too
         call par_engine_energies(d%eng, model, vold, wsum, erw, dfac, need, wold, &
                                  d%rigid%map%racc, parts=parts)
      else
         call par_engine_energies(d%eng, model, vold, wsum, erw, dfac, need, wold, &
                                  parts=parts)
      end if
   end subroutine m_energies

   !> Every rank appends its part (no communication).
   subroutine m_write_plot(d, model, out, error)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      call par_engine_plot(d%eng, d%plot, model, error)
   end subroutine m_write_plot

   !> A failure on this rank alone that cannot wait (I/O): stop every rank, naming it.
   subroutine m_fail(d, error)
      class(mpi_domain_t), intent(inout) :: d
      type(error_t), intent(in) :: error
      call par_engine_fail(error)
   end subroutine m_fail

   !> The global model with the nodal state of this step that history file kind reads
   !> (gathered; par_engine_output); rank 0 writes.
   subroutine m_output_model(d, model, om, writer, kind)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(model_t), pointer, intent(out) :: om
      logical, intent(out) :: writer
      integer, intent(in), optional :: kind
      call par_engine_output(d%eng, model, .false., om, writer, kind)
   end subroutine m_output_model

   !> elout's values gathered into the global model om on rank 0 (par_engine_elout).
   subroutine m_element_output(d, model, om)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(model_t), pointer, intent(in) :: om
      call par_engine_elout(d%eng, model)
   end subroutine m_element_output

   !> The global model (serial numbering) rank 0 opens the output with.
   subroutine m_output_target(d, model, om, writer, kind)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(model_t), pointer, intent(out) :: om
      logical, intent(out) :: writer
      integer, intent(in), optional :: kind
      om => par_engine_global(d%eng)
      writer = par_engine_writer()
   end subroutine m_output_target

   !> The last cycle (no further dt reduction): a failure kept on any rank stops all.
   subroutine m_sync_failure(d, error)
      class(mpi_domain_t), intent(inout) :: d
      type(error_t), allocatable, intent(inout) :: error
      call par_engine_sync_failure(d%eng, error)
   end subroutine m_sync_failure

   !> Rank 0 combines the per-rank plot files (failure: every rank knows it).
   subroutine m_plot_finish(d, error, failure)
      class(mpi_domain_t), intent(inout) :: d
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: failure
      call par_engine_plot_finish(d%eng, d%plot, error, failure=failure)
   end subroutine m_plot_finish

   !> Every rank its part, rank 0 the manifest (rank 0's sizes); the kept work terms are
   !> added first so the dump holds the sums to date. No dump after a failure in a cycle
   !> (kind 'failure': the ranks' states are not one state).
   subroutine m_write_dump(d, model, path, kind, error)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      if (kind == 'failure') then
         call set_error(error, 'no failure dump in an MPI run', EXIT_NUMERIC)
         return
      end if
      model%run%nplot = par_plot_nstates(d%plot)   ! the states in each rank's plot part
      call par_engine_flush_work(d%eng, model%run%wcon, model%run%wrw)
      call par_loads_flush(d%loads, model%run%wext)   ! kept external-work terms (dx_par_loads)
      call par_restart_write(d%eng, d%parts, model, path, kind, error)
   end subroutine m_write_dump

   !> A manifest and this rank's part, or a serial dump through the global model.
   subroutine m_read_restart(d, model, path, error)
      class(mpi_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      call par_restart_read(d%eng, d%plot, d%parts, model, path, error)
      if (.not. allocated(error)) &     ! (a serial dump: read into the global model)
         call par_contact2d_from_global(d%c2d, model, par_engine_global(d%eng))
   end subroutine m_read_restart

   !> End of the run: communication times (largest over the ranks), contact statistics.
   subroutine m_report(d)
      class(mpi_domain_t), intent(inout) :: d
      call par_engine_report(d%eng, d%contact)
      call log_info(par_traffic_line())
   end subroutine m_report

   !> A failure every rank knows (each stops without MPI_Abort).
   logical function m_together(d)
      class(mpi_domain_t), intent(in) :: d
      m_together = par_engine_together(d%eng)
   end function m_together

   function m_plot_note(d, outdir) result(s)
      class(mpi_domain_t), intent(in) :: d
      character(*), intent(in) :: outdir
      character(:), allocatable :: s
      s = ' (the '//str(par_size())//' ranks'' plot files combined into '// &
          outdir//'/d3plot.h5 + d3plot.xdmf: '//str(par_plot_nstates(d%plot))//' states)'
   end function m_plot_note

   function m_launcher(d, outdir) result(s)
      class(mpi_domain_t), intent(in) :: d
      character(*), intent(in) :: outdir
      character(:), allocatable :: s
      s = 'mpirun -np '//str(par_size())//' '
   end function m_launcher
end module dx_domain_mpi
