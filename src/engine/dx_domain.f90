!> The domain: what one rank owns and the stages of an explicit cycle over it (architecture,
!> "Parallel without twins"). The solver owns the loop and calls each stage once per cycle;
!> the domain decides what a stage means on this run:
!>  - serial_domain_t (this module): the whole model on one rank; each stage runs the serial
!>    procedure directly (walls, constraint work, energies, contact, rigid bodies) or does
!>    nothing (fill, exchange: there are no shared nodes). Also the domain of the conserving
!>    solver under MPI, where every rank holds the whole state (replicated: rank 0 writes).
!>  - mpi_domain_t (dx_domain_mpi): one rank's part of an MPI run (ParaDyn: Hoover et al.,
!>    LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed), the stages in
!>    fixed serial order (dx_par_engine and the dx_par_* modules).
!> So the explicit cycle has one path and no test on the rank count. The stop and dump
!> requests of the run (signals, wall-clock limit) ride in the MPI dt reduction: the solver's
!> checkpoint extends requests_t, and a domain that reduces requests calls its poll and
!> leaves the reduced flags in coll.
module dx_domain
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_elout, only: elout_values
   use dx_par, only: par_rank, par_size
   use dx_contact2d, only: contact2d_forces
   use dx_loads, only: has_external_loads
   use dx_constraints, only: apply_rigidwalls, wall_hits_t
   use dx_contact, only: contact_forces, contact_work
   use dx_rigid_exact, only: rigid_map_t, rigid_map_serial, rigid_exact_step
   use dx_element, only: element_mass_share
   use dx_mass_scaling, only: lump_mass
   use dx_restart, only: restart_write
   use dx_par_restart, only: serial_restart_read
   use dx_energy_sums, only: constraint_terms, element_energies, set_energy, part_mass_map, &
                             interface_work, rot_node_term
   use dx_energy_exact, only: energy_terms, energy_values, corner_counts, held_status, &
                              work_nsums, work_hit, work_values, added_mass_sums
   use dx_repro_sum, only: rsum_t, rs_init, rs_add, rs_value
   use dx_par_emc, only: par_emc_t, par_emc_together
   implicit none
   private
   public :: domain_t, serial_domain_t, requests_t

   !> Stop and dump requests of this rank (the solver's checkpoint extends it): poll fills
   !> flags (1: stop signal, 2: SIGUSR1, 3: wall-clock limit, 4: the run-time switches of
   !> OUT/dynx.ctl, dx_run_control, read by rank 0 alone); a domain that reduces them over
   !> the ranks stores the result in coll and sets collective.
   type, abstract :: requests_t
      integer :: coll(4) = 0                    !< the requests of every rank, reduced
      logical :: collective = .false.           !< coll holds reduced requests
   contains
      procedure(poll_i), deferred :: poll
   end type requests_t

   abstract interface
      subroutine poll_i(self, flags)
         import :: requests_t
         class(requests_t), intent(inout) :: self
         integer, intent(out) :: flags(4)
      end subroutine poll_i
   end interface

   !> One rank's part of the model and the stages of a cycle over it.
   type, abstract :: domain_t
      type(par_emc_t) :: emc    !< the conserving solver's split of the slave points (MPI)
   contains
      procedure(model_i), deferred :: sum_mass          !< after lumping: shared nodes' mass
      procedure(share_i), deferred :: mass_share        !< one-element-wide blocks' dt bound
      procedure(remass_i), deferred :: remass           !< mass scaling: masses, added total
      procedure(model_i), deferred :: initial_energy    !< after the initial KE: global sum
      procedure(ask_model_i), deferred :: has_loads     !< the deck's loads, on any rank
      procedure(ask_i), deferred :: writer              !< this rank writes the global files
      procedure(ask_i), deferred :: rigid_writer        !< this rank writes rbdout
      procedure(model_i), deferred :: fill              !< shared nodes' x, v into the slots
      procedure(ask_i), deferred :: pending             !< a failure kept, not yet known
      procedure(error_io_i), deferred :: defer          !< keep a failure (or leave it)
      procedure(dt_i), deferred :: reduce_dt            !< global critical step
      procedure(contact_i), deferred :: contact_forces
      procedure(loads_i), deferred :: loads_shared      !< shared nodes' loads, serial chain
      procedure(model_i), deferred :: exchange          !< shared-node force sums
      procedure(rigid_i), deferred :: rigid_step
      procedure(constraints_i), deferred :: constraints !< walls, constraint work
      procedure(load_work_i), deferred :: load_work     !< external work
      procedure(contact_work_i), deferred :: contact_work
      procedure(energies_i), deferred :: energies       !< glstat energies at t(n)
      procedure(plot_i), deferred :: write_plot         !< one plot state
      procedure(fail_i), deferred :: fail               !< a failure on this rank alone
      procedure(output_i), deferred :: output_model     !< glstat/nodout model at this step
      procedure(output_i), deferred :: output_target    !< the model output is opened with
      procedure(elout_i), deferred :: element_output    !< elout's values into om (MPI: rank 0)
      procedure(error_io_i), deferred :: sync_failure   !< last cycle: a kept failure
      procedure(finish_i), deferred :: plot_finish      !< end: combine the plot parts
      procedure(dump_i), deferred :: write_dump         !< a restart dump
      procedure(read_i), deferred :: read_restart       !< continue from a restart dump
      procedure(report_i), deferred :: report           !< end of run: communication times
      procedure(ask_i), deferred :: together            !< a failure every rank knows
      procedure(note_i), deferred :: plot_note          !< message on combined plot files
      procedure(note_i), deferred :: launcher           !< 'mpirun -np N ' or ''
   end type domain_t

   abstract interface
      subroutine model_i(d, model)
         import :: domain_t, model_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
      end subroutine model_i
      !> changed: this rank's elements' added mass changed (out: on any rank)
      subroutine remass_i(d, model, changed)
         import :: domain_t, model_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         logical, intent(inout) :: changed
      end subroutine remass_i
      subroutine share_i(d, model, cnodes)
         import :: domain_t, model_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         integer, intent(in) :: cnodes(:)
      end subroutine share_i
      logical function ask_model_i(d, model)
         import :: domain_t, model_t
         class(domain_t), intent(in) :: d
         type(model_t), intent(in) :: model
      end function ask_model_i
      logical function ask_i(d)
         import :: domain_t
         class(domain_t), intent(in) :: d
      end function ask_i
      subroutine error_io_i(d, error)
         import :: domain_t, error_t
         class(domain_t), intent(inout) :: d
         type(error_t), allocatable, intent(inout) :: error
      end subroutine error_io_i
      subroutine dt_i(d, model, dtcrit, ibmin, req, error)
         import :: domain_t, model_t, requests_t, error_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         real(wp), intent(inout) :: dtcrit
         integer, intent(in) :: ibmin
         class(requests_t), intent(inout) :: req
         type(error_t), allocatable, intent(inout) :: error
      end subroutine dt_i
      subroutine contact_i(d, model, dt_old, dtcrit)
         import :: domain_t, model_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         real(wp), intent(in) :: dt_old
         real(wp), intent(inout) :: dtcrit
      end subroutine contact_i
      subroutine loads_i(d, model, t, fext)
         import :: domain_t, model_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         real(wp), intent(in) :: t
         real(wp), intent(inout) :: fext(:, :)
      end subroutine loads_i
      subroutine rigid_i(d, model, t, dt, dtavg, vold)
         import :: domain_t, model_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      end subroutine rigid_i
      !> wold: w(n-1/2) of decks with rotations (shells); then the constraint moments'
      !> work enters wcon first (model%mom holds the free w), in node order
      subroutine constraints_i(d, model, cnodes, vfree, vold, dt, dtavg, wcon, wrw, need, wold)
         import :: domain_t, model_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         integer, intent(in) :: cnodes(:)
         real(wp), intent(in) :: vfree(:, :), vold(:, :), dt, dtavg
         real(wp), intent(inout) :: wcon, wrw
         logical, intent(in) :: need
         real(wp), intent(in), optional :: wold(:, :)
      end subroutine constraints_i
      subroutine load_work_i(d, fext, vold, v, dtavg, wext, need)
         import :: domain_t, wp
         class(domain_t), intent(inout) :: d
         real(wp), intent(in) :: fext(:, :), vold(:, :), v(:, :), dtavg
         real(wp), intent(inout) :: wext
         logical, intent(in) :: need
      end subroutine load_work_i
      subroutine contact_work_i(d, model, vold, dtavg, outdir, error)
         import :: domain_t, model_t, error_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         real(wp), intent(in) :: vold(:, :), dtavg
         character(*), intent(in) :: outdir
         type(error_t), allocatable, intent(out) :: error
      end subroutine contact_work_i
      !> wold: w(n-1/2) of decks with rotations (an MPI run sums their kinetic energy);
      !> parts: matsum is written at this step (its part sums are formed; default .true.)
      subroutine energies_i(d, model, ke, vold, wsum, erw, dfac, need, wold, parts)
         import :: domain_t, model_t, wp
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         real(wp), intent(in) :: ke, vold(:, :), wsum, erw, dfac
         logical, intent(in) :: need
         real(wp), intent(in), optional :: wold(:, :)
         logical, intent(in), optional :: parts
      end subroutine energies_i
      subroutine plot_i(d, model, out, error)
         import :: domain_t, model_t, output_t, error_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         type(output_t), intent(inout) :: out
         type(error_t), allocatable, intent(out) :: error
      end subroutine plot_i
      subroutine fail_i(d, error)
         import :: domain_t, error_t
         class(domain_t), intent(inout) :: d
         type(error_t), intent(in) :: error
      end subroutine fail_i
      subroutine output_i(d, model, om, writer, kind)
         import :: domain_t, model_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         type(model_t), pointer, intent(out) :: om
         logical, intent(out) :: writer
         integer, intent(in), optional :: kind   !< the history file (dx_solver histories)
      end subroutine output_i
      subroutine elout_i(d, model, om)
         import :: domain_t, model_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout), target :: model
         type(model_t), pointer, intent(in) :: om
      end subroutine elout_i
      subroutine finish_i(d, error, failure)
         import :: domain_t, error_t
         class(domain_t), intent(inout) :: d
         type(error_t), allocatable, intent(out) :: error
         logical, intent(in) :: failure
      end subroutine finish_i
      subroutine dump_i(d, model, path, kind, error)
         import :: domain_t, model_t, error_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         character(*), intent(in) :: path, kind
         type(error_t), allocatable, intent(out) :: error
      end subroutine dump_i
      subroutine report_i(d)
         import :: domain_t
         class(domain_t), intent(inout) :: d
      end subroutine report_i
      subroutine read_i(d, model, path, error)
         import :: domain_t, model_t, error_t
         class(domain_t), intent(inout) :: d
         type(model_t), intent(inout) :: model
         character(*), intent(in) :: path
         type(error_t), allocatable, intent(out) :: error
      end subroutine read_i
      function note_i(d, outdir) result(s)
         import :: domain_t
         class(domain_t), intent(in) :: d
         character(*), intent(in) :: outdir
         character(:), allocatable :: s
      end function note_i
   end interface

   !> The whole model on this rank: each stage is the serial procedure.
   type, extends(domain_t) :: serial_domain_t
      real(wp), allocatable :: cterms(:)        !< constraint work terms (work space)
      type(wall_hits_t) :: hits                 !< this cycle's rigid-wall hits
      type(rsum_t) :: wrs                       !< the cycle's work sums (s_constraints)
      type(rigid_map_t) :: rmap                 !< rigid bodies' nodes (dx_rigid_exact)
   contains
      procedure :: sum_mass => s_model_nothing
      procedure :: mass_share => s_mass_share
      procedure :: remass => s_remass
      procedure :: initial_energy => s_model_nothing
      procedure :: has_loads => s_has_loads
      procedure :: writer => s_writer
      procedure :: rigid_writer => s_writer
      procedure :: fill => s_model_nothing
      procedure :: pending => s_false
      procedure :: defer => s_error_nothing
      procedure :: reduce_dt => s_reduce_dt
      procedure :: contact_forces => s_contact_forces
      procedure :: loads_shared => s_loads_shared
      procedure :: exchange => s_model_nothing
      procedure :: rigid_step => s_rigid_step
      procedure :: constraints => s_constraints
      procedure :: load_work => s_load_work
      procedure :: contact_work => s_contact_work
      procedure :: energies => s_energies
      procedure :: write_plot => s_write_plot
      procedure :: fail => s_fail
      procedure :: output_model => s_output_model
      procedure :: output_target => s_output_model
      procedure :: element_output => s_element_output
      procedure :: sync_failure => s_error_nothing
      procedure :: plot_finish => s_plot_finish
      procedure :: write_dump => s_write_dump
      procedure :: read_restart => s_read_restart
      procedure :: report => s_report
      procedure :: together => s_together
      procedure :: plot_note => s_plot_note
      procedure :: launcher => s_launcher
   end type serial_domain_t

contains

   subroutine s_model_nothing(d, model)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
   end subroutine s_model_nothing

   !> Mass scaling changed an element's mass: the lumped masses with it and the added total.
   subroutine s_remass(d, model, changed)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      logical, intent(inout) :: changed
      if (.not. changed) return
      call lump_mass(model)
      ! the added total and matsum's +mass per part: exact sums (as an MPI run's)
      call added_mass_sums(model, .false., model)
   end subroutine s_remass

   !> One-element-wide blocks get the element dt bound (element_mass_share).
   subroutine s_mass_share(d, model, cnodes)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      integer, intent(in) :: cnodes(:)
      integer :: b
      do b = 1, size(model%blocks)
         call element_mass_share(model%blocks(b), &
            model%mats(model%parts(model%blocks(b)%ipart)%imat)%m%ro, model%mass, cnodes)
      end do
      if (model%db%matsum_dt > 0.0_wp) call part_mass_map(model)   ! matsum's part shares
   end subroutine s_mass_share

   logical function s_has_loads(d, model)
      class(serial_domain_t), intent(in) :: d
      type(model_t), intent(in) :: model
      s_has_loads = has_external_loads(model)
   end function s_has_loads

   !> A serial run writes; the conserving solver's replicated MPI run writes from rank 0.
   logical function s_writer(d)
      class(serial_domain_t), intent(in) :: d
      s_writer = par_rank() == 0
   end function s_writer

   logical function s_false(d)
      class(serial_domain_t), intent(in) :: d
      s_false = .false.
   end function s_false

   !> A failure every rank knows: the conserving solver's (replicated on every rank).
   logical function s_together(d)
      class(serial_domain_t), intent(in) :: d
      s_together = par_emc_together(d%emc)
   end function s_together

   !> A failure is acted on at once: error is left as it is.
   subroutine s_error_nothing(d, error)
      class(serial_domain_t), intent(inout) :: d
      type(error_t), allocatable, intent(inout) :: error
   end subroutine s_error_nothing

   !> No deformable element: the rigid elements' step. The requests stay with the caller.
   subroutine s_reduce_dt(d, model, dtcrit, ibmin, req, error)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(inout) :: dtcrit
      integer, intent(in) :: ibmin
      class(requests_t), intent(inout) :: req
      type(error_t), allocatable, intent(inout) :: error
      if (allocated(model%rigid) .and. ibmin == 0) dtcrit = model%rigid%dtcrit
   end subroutine s_reduce_dt

   subroutine s_contact_forces(d, model, dt_old, dtcrit)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: dtcrit
      if (allocated(model%contact)) call contact_forces(model, dt_old, dtcrit)
      if (allocated(model%contact2d)) call contact2d_forces(model%contact2d, model%x, model%v, &
                                                            model%mass, dt_old, model%ctrl%tssfac, &
                                                            model%f, dtcrit)
   end subroutine s_contact_forces

   subroutine s_loads_shared(d, model, t, fext)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: fext(:, :)
   end subroutine s_loads_shared

   subroutine s_rigid_step(d, model, t, dt, dtavg, vold)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :)
      call rigid_map_serial(d%rmap, model%rigid)     ! (once)
      call rigid_exact_step(d%rmap, model, t, dt, dtavg, vold)   ! exact sums, as MPI's
   end subroutine s_rigid_step

   !> Work of the constraint reactions; rigid walls and their work.
   subroutine s_constraints(d, model, cnodes, vfree, vold, dt, dtavg, wcon, wrw, need, wold)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      integer, intent(in) :: cnodes(:)
      real(wp), intent(in) :: vfree(:, :), vold(:, :), dt, dtavg
      real(wp), intent(inout) :: wcon, wrw
      logical, intent(in) :: need
      real(wp), intent(in), optional :: wold(:, :)
      real(wp), allocatable :: fw(:, :)
      real(wp) :: term
      integer :: i, nw
      nw = 0
      if (allocated(model%walls)) nw = size(model%walls)
      ! this cycle's terms, summed exactly and added to the running sums once (as an MPI
      ! run adds each cycle's sum over the ranks: dx_energy_exact work_values)
      call rs_init(d%wrs, work_nsums(nw))
      if (present(wold)) then      ! shells' constraint moments
         do i = 1, model%nn
            if (rot_node_term(model%rinert(i), model%mom(:, i), wold(:, i), model%w(:, i), &
                              term)) call rs_add(d%wrs, 1, term)
         end do
      end if
      if (.not. allocated(d%cterms)) allocate(d%cterms(size(cnodes)))
      call constraint_terms(cnodes, model%mass, vfree, vold, model%v, dtavg, d%cterms)
      do i = 1, size(cnodes)
         call rs_add(d%wrs, 1, d%cterms(i))
      end do
      if (nw > 0) then
         call apply_rigidwalls(model, dt, dtavg, vold, model%v, d%hits)
         do i = 1, d%hits%n
            call work_hit(d%wrs, 0, d%hits%wall(i), d%hits%val(1:4, i))
         end do
      end if
      allocate(fw(3, nw))
      call work_values(d%wrs, 0, nw, wcon, wrw, fw)
      do i = 1, nw
         model%walls(i)%force = fw(:, i)
      end do
   end subroutine s_constraints

   !> W_ext += f_ext(n).dtavg (v(n-1/2) + v(n+1/2))/2: the cycle's terms, an exact sum.
   subroutine s_load_work(d, fext, vold, v, dtavg, wext, need)
      class(serial_domain_t), intent(inout) :: d
      real(wp), intent(in) :: fext(:, :), vold(:, :), v(:, :), dtavg
      real(wp), intent(inout) :: wext
      logical, intent(in) :: need
      real(wp) :: term
      integer :: i
      ! the cycle's terms summed exactly, added once (as an MPI run: dx_par_loads)
      call rs_init(d%wrs, 1)
      do i = 1, size(fext, 2)
         term = dot_product(fext(:, i), 0.5_wp*dtavg*(vold(:, i) + v(:, i)))
         if (term /= 0.0_wp) call rs_add(d%wrs, 1, term)
      end do
      wext = wext + rs_value(d%wrs, 1)
   end subroutine s_load_work

   subroutine s_contact_work(d, model, vold, dtavg, outdir, error)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      real(wp), intent(in) :: vold(:, :), dtavg
      character(*), intent(in) :: outdir
      type(error_t), allocatable, intent(out) :: error
      call contact_work(model, vold, dtavg, outdir, error)
      if (model%db%sleout_dt > 0.0_wp) &
         call interface_work(model%contact, vold, model%v, dtavg)   ! per interface (sleout)
   end subroutine s_contact_work

   !> The energies at t(n); dfac weighs the element work booked next cycle.
   subroutine s_energies(d, model, ke, vold, wsum, erw, dfac, need, wold, parts)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: ke, vold(:, :), wsum, erw, dfac
      logical, intent(in) :: need
      real(wp), intent(in), optional :: wold(:, :)
      logical, intent(in), optional :: parts
      real(wp) :: eint, ehg, epend
      real(wp), allocatable :: alive(:), all(:)
      integer(1), allocatable :: held(:)
      type(rsum_t) :: rs
      if (need) then     ! the reported sums: exact (dx_energy_exact), as an MPI run's
         if (model%erodes) then
            call corner_counts(model, alive, all)
            held = held_status(alive, all)
         end if
         if (allocated(model%rigid)) then
            call energy_terms(model, vold, size(model%mass), [integer ::], rs, wold=wold, &
                              held=held, racc=d%rmap%racc, parts=parts)
         else
            call energy_terms(model, vold, size(model%mass), [integer ::], rs, wold=wold, &
                              held=held, parts=parts)
         end if
         call energy_values(model, rs, dfac, wsum, erw, model)
         return
      end if
      ! the cycles between (energy guard, status line): plain sums in a fixed order
      call element_energies(model%blocks, eint, ehg, epend)
      eint = eint + dfac*epend   ! the part of W(n) booked next cycle
      call set_energy(model, ke, eint, ehg, wsum, erw)
   end subroutine s_energies

   subroutine s_write_plot(d, model, out, error)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      if (d%writer()) call out%write_plot(model, error)
   end subroutine s_write_plot

   !> The caller stops (one rank, or every rank alike when replicated).
   subroutine s_fail(d, error)
      class(serial_domain_t), intent(inout) :: d
      type(error_t), intent(in) :: error
   end subroutine s_fail

   subroutine s_output_model(d, model, om, writer, kind)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(model_t), pointer, intent(out) :: om
      logical, intent(out) :: writer
      integer, intent(in), optional :: kind
      om => model
      writer = d%writer()
   end subroutine s_output_model

   !> elout's values of the history solids (om is the model itself).
   subroutine s_element_output(d, model, om)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout), target :: model
      type(model_t), pointer, intent(in) :: om
      call elout_values(model)
   end subroutine s_element_output

   subroutine s_plot_finish(d, error, failure)
      class(serial_domain_t), intent(inout) :: d
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in) :: failure
   end subroutine s_plot_finish

   !> The serial dump (replicated MPI runs: rank 0 writes it).
   subroutine s_write_dump(d, model, path, kind, error)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      if (d%writer()) call restart_write(model, path, kind, error)
   end subroutine s_write_dump

   !> A serial dump (an MPI run's manifest is refused: dx_par_restart).
   subroutine s_read_restart(d, model, path, error)
      class(serial_domain_t), intent(inout) :: d
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      call serial_restart_read(model, path, error)
   end subroutine s_read_restart

   subroutine s_report(d)
      class(serial_domain_t), intent(inout) :: d
   end subroutine s_report

   function s_plot_note(d, outdir) result(s)
      class(serial_domain_t), intent(in) :: d
      character(*), intent(in) :: outdir
      character(:), allocatable :: s
      s = ''
   end function s_plot_note

   !> The command prefix that continues the run: a replicated MPI run needs the same NP.
   function s_launcher(d, outdir) result(s)
      class(serial_domain_t), intent(in) :: d
      character(*), intent(in) :: outdir
      character(:), allocatable :: s
      s = ''
      if (par_size() > 1) s = 'mpirun -np '//str(par_size())//' '
   end function s_launcher
end module dx_domain
