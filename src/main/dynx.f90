!> dynx: arguments -> start -> deck -> model -> domain -> output -> solver -> end.
!> dx_cli: options, usage, exit codes; dx_launch: the steps; dx_domain: what this rank owns
!> and the stages of a cycle over it.
program dynx
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_deck_model, only: read_deck
   use dx_output, only: output_t
   use dx_explicit, only: init_state
   use dx_par_agree, only: par_agree
   use dx_domain, only: domain_t
   use dx_domain_mpi, only: domain_create
   use dx_cli, only: cli_t, parse_cli, die
   use dx_signals, only: signals_install
   use dx_launch, only: launch_start, launch_check_only, launch_lock, launch_output, &
                        launch_run, launch_d3hsp, launch_cases
   use dx_card_echo, only: echo_t
   implicit none
   type(cli_t) :: cli
   type(model_t), target :: model
   class(domain_t), allocatable :: dom     ! what this rank owns; the stages of a cycle
   type(output_t) :: out
   type(error_t), allocatable :: error
   integer :: lock_fd
   type(echo_t) :: echo             ! the deck as read, for d3hsp

   call signals_install()           ! first: a SIGTERM during start-up is a request, not a kill
   call parse_cli(cli)
   call launch_start(cli)
   call launch_cases(cli)           ! *CASE: each case as its own run, then the end
   if (cli%check_only) then         ! (--check writes no d3hsp: no echo)
      call read_deck(cli%deck, model, error, cli%ignore_unknown, cli%check_only, &
                     case_id=cli%case_id)
   else
      call read_deck(cli%deck, model, error, cli%ignore_unknown, cli%check_only, echo, &
                     cli%case_id)
   end if
   call par_agree(error)            ! MPI: a bad deck stops every rank together
   if (allocated(error)) call die(error)
   call launch_check_only(cli, model)           ! --check ends here
   call launch_lock(cli, model, lock_fd)        ! the output folder is this run's
   call domain_create(model, cli%deck, cli%outdir, cli%partdir, cli%csplit, dom, error)
   call par_agree(error)
   if (allocated(error)) call die(error, dom)
   call init_state(model, dom)
   call launch_output(cli, model, dom, out)     ! restart, restart deck, output files
   call launch_d3hsp(cli, model, dom, echo)     ! d3hsp and the messages file
   call launch_run(cli, model, dom, out)        ! the integrator and the end
end program dynx
