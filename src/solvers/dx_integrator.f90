!> The seam between the run driver (dx_solver) and an integrator: what the driver asks of
!> one (start, one step to a state at t(n) with its energies, the advance to the next cycle
!> boundary, the end) and what it reads (time, step, done, whether the driver writes the plot
!> states and histories on model%run's grid). Extensions: explicit_t (dx_explicit) and
!> conserving_t (dx_emc_solver); the factory make_integrator is in dx_solver.
module dx_integrator
   use dx_kinds, only: wp, huge_wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_checkpoint, only: checkpoint_t
   use dx_domain, only: domain_t, serial_domain_t
   implicit none
   private
   public :: run_options_t, integrator_t, energy_guard_t, END_NORMAL, END_FAILED, END_STOPPED, &
             serial_fresh_only, close_files

   integer, parameter :: END_NORMAL = 0, END_FAILED = 1, END_STOPPED = 2

   !> dynx's energy guard (issue 15; not LS-DYNA's ENDENG): the ratio total/initial energy
   !> (glstat's) is checked every cycle; a warning once when |ratio - 1| > warn, a stop (exit
   !> 3, failure dump) when |ratio - 1| > stop - 1. --energy-guard WARN,STOP or off.
   type :: energy_guard_t
      logical :: on = .true.
      real(wp) :: warn = 0.1_wp        !< band half-width around 1
      real(wp) :: stop = 2.0_wp        !< blow-up threshold on the ratio
      logical :: warned = .false.
      real(wp) :: den_prev = 0.0_wp    !< the ratio's denominator (E0 + W_ext) last cycle
      real(wp) :: r_prev = 0.0_wp      !< and the ratio
   end type energy_guard_t

   type :: run_options_t
      character(:), allocatable :: outdir
      integer :: nstatus = 10          !< status lines over the run
      type(checkpoint_t) :: ck         !< restart dumps, signals, wall-clock limit
      type(energy_guard_t) :: guard    !< the energy guard's bounds
   end type run_options_t

   type, abstract :: integrator_t
      character(:), allocatable :: name   !< for the log: which integrator
      character(:), allocatable :: why    !< and why it was chosen
      real(wp) :: t = 0.0_wp              !< time of the state the last step completed
      real(wp) :: dt = 0.0_wp             !< its step
      real(wp) :: tend = huge_wp
      logical :: done = .false.           !< the last step reached the end (no advance)
      logical :: histories = .true.       !< the driver writes plot/glstat/nodout/rbdout
      logical :: energies = .true.        !< model%energy holds glstat's ratio (energy guard)
   contains
      procedure(start_i), deferred :: start
      procedure(step_i), deferred :: step
      procedure(advance_i), deferred :: advance
      procedure(close_i), deferred :: close
   end type integrator_t

   abstract interface
      !> Initial state (or the restored one), files of its own; before the first step.
      subroutine start_i(self, model, dom, opts, ck, out, error)
         import :: integrator_t, model_t, domain_t, run_options_t, checkpoint_t, output_t, &
                   error_t
         class(integrator_t), intent(inout) :: self
         type(model_t), intent(inout), target :: model
         class(domain_t), intent(inout) :: dom
         type(run_options_t), intent(in) :: opts
         type(checkpoint_t), intent(inout) :: ck
         type(output_t), intent(inout) :: out
         type(error_t), allocatable, intent(out) :: error
      end subroutine start_i
      !> One step: the state at t(n) complete (energies), self%t, self%dt, self%done set.
      subroutine step_i(self, model, dom, ck, out, error)
         import :: integrator_t, model_t, domain_t, checkpoint_t, output_t, error_t
         class(integrator_t), intent(inout) :: self
         type(model_t), intent(inout), target :: model
         class(domain_t), intent(inout) :: dom
         type(checkpoint_t), intent(inout) :: ck
         type(output_t), intent(inout) :: out
         type(error_t), allocatable, intent(out) :: error
      end subroutine step_i
      !> To the next cycle boundary (model%time, model%cycle; what a dump must hold).
      subroutine advance_i(self, model, ck)
         import :: integrator_t, model_t, checkpoint_t
         class(integrator_t), intent(inout) :: self
         type(model_t), intent(inout) :: model
         type(checkpoint_t), intent(inout) :: ck
      end subroutine advance_i
      !> The end (how: END_NORMAL, END_FAILED with error, END_STOPPED by a checkpoint).
      subroutine close_i(self, model, dom, ck, out, how, error)
         import :: integrator_t, model_t, domain_t, checkpoint_t, output_t, error_t
         class(integrator_t), intent(inout) :: self
         type(model_t), intent(inout), target :: model
         class(domain_t), intent(inout) :: dom
         type(checkpoint_t), intent(inout) :: ck
         type(output_t), intent(inout) :: out
         integer, intent(in) :: how
         type(error_t), allocatable, intent(inout) :: error
      end subroutine close_i
   end interface

contains

   !> The refusals of an integrator that runs serially and from the start only (the
   !> implicit and eigenvalue runs): a restart (model%cycle > 0: 'the WHO has no restart'
   !> and why) or an MPI domain is an input error.
   subroutine serial_fresh_only(model, dom, who, why, error)
      type(model_t), intent(in) :: model
      class(domain_t), intent(in) :: dom
      character(*), intent(in) :: who, why
      type(error_t), allocatable, intent(out) :: error
      if (model%cycle > 0) then
         call set_error(error, 'the '//who//' has no restart'//why, EXIT_INPUT)
         return
      end if
      select type (dom)
      type is (serial_domain_t)
      class default
         call set_error(error, 'the '//who//' (IMFLAG = 1) is not supported in an MPI run '// &
                        '(it runs serially): run bin/dynx without mpirun and dynx-part', &
                        EXIT_INPUT)
      end select
   end subroutine serial_fresh_only

   !> The files at the end of a run: the writer closes the output files, then the domain
   !> finishes the plot (MPI: rank 0 combines the per-rank plot files); the first failure
   !> (one already in error included) is the one reported.
   subroutine close_files(dom, out, error)
      class(domain_t), intent(inout) :: dom
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: ioerr
      if (dom%writer()) call out%close(ioerr)
      if (allocated(ioerr) .and. .not. allocated(error)) call move_alloc(ioerr, error)
      call dom%plot_finish(ioerr, .false.)
      if (allocated(ioerr) .and. .not. allocated(error)) call move_alloc(ioerr, error)
   end subroutine close_files
end module dx_integrator
