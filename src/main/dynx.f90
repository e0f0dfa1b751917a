!> dynx: arguments -> deck -> model -> domain -> solver -> finish (dx_cli: options, usage,
!> exit codes; dx_domain: what this rank owns and the stages of a cycle over it).
program dynx
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_CHECKPOINT, exit_process
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_summary, log_set_quiet
   use dx_model, only: model_t
   use dx_deck_model, only: read_deck
   use dx_output, only: output_t
   use dx_explicit, only: run_explicit, init_state
   use dx_par_restart, only: par_restart_precheck
   use dx_restart_deck, only: apply_restart_deck
   use dx_signals, only: signals_install
   use dx_emc_solver, only: run_emc
   use dx_par, only: par_init, par_finalize, par_rank
   use dx_par_agree, only: par_agree
   use dx_domain, only: domain_t
   use dx_domain_mpi, only: domain_create
   use dx_cli, only: cli_t, parse_cli, die
   use dx_out_lock, only: out_lock
   implicit none
   type(cli_t) :: cli
   type(model_t), target :: model
   type(model_t), pointer :: om            ! the model output is written from
   class(domain_t), allocatable :: dom     ! what this rank owns; the stages of a cycle
   type(output_t) :: out
   type(error_t), allocatable :: error
   integer :: lock_fd
   logical :: writer

   call parse_cli(cli)
   associate (deck => cli%deck, outdir => cli%outdir, rfile => cli%rfile, &
              rdeck => cli%rdeck, partdir => cli%partdir, opts => cli%opts, &
              check_only => cli%check_only)
   ! polled once per cycle (MPI: folded into the dt reduction, every rank acts together);
   ! installed before MPI_Init so that a SIGTERM during the start-up is a request too
   if (.not. check_only) call signals_install()
   call par_init(error)             ! MPI only when started by mpirun/srun
   if (allocated(error)) call die(error)
   if (par_rank() > 0) call log_set_quiet(.true.)   ! MPI: rank 0 prints info and warnings
   opts%ck%raise_here = cli%raise_rank < 0 .or. cli%raise_rank == par_rank()

   call read_deck(deck, model, error, cli%ignore_unknown)
   call par_agree(error)            ! MPI: a bad deck stops every rank together (dx_par_agree)
   if (allocated(error)) call die(error)
   call log_info('dynx: read '//deck//': '//str(model%nn)//' nodes, '//str(model%ne)// &
                 ' elements, '//str(size(model%parts))//' parts, '//str(size(model%blocks))// &
                 ' element blocks, end time '//rstr(model%ctrl%endtim))
   if (check_only) then
      if (len(rdeck) > 0) then
         call apply_restart_deck(rdeck, model, error)
         if (allocated(error)) call die(error)
      end if
      call log_info('dynx: deck check passed')
      call log_summary()
      call par_finalize()
      stop
   end if
   if (par_rank() == 0) call out_lock(outdir, 'dynx', lock_fd, error)   ! held until exit
   call par_agree(error)
   if (allocated(error)) call die(error)
   if (len(rfile) > 0) call par_restart_precheck(rfile, deck, error, model%deck_files)   ! MPI
   if (allocated(error)) call die(error)
   call domain_create(model, deck, outdir, partdir, cli%csplit, dom, error)   ! MPI: rank's part
   call par_agree(error)
   if (allocated(error)) call die(error, dom)
   call init_state(model, dom)
   if (len(rfile) > 0) then
      call dom%read_restart(model, rfile, error)   ! serial dump, or an MPI run's parts
      if (allocated(error)) call die(error, dom)
      call log_info('dynx: restart from '//rfile//' at cycle '//str(model%cycle)//', time '// &
                    rstr(model%time))
      if (len(rdeck) > 0) then
         call apply_restart_deck(rdeck, model, error)
         call dom%output_target(model, om, writer)   ! MPI: the global model too
         if (.not. allocated(error) .and. .not. associated(om, model)) &
            call apply_restart_deck(rdeck, om, error)
         call par_agree(error)
         if (allocated(error)) call die(error, dom)
         call log_info('dynx: restart deck '//rdeck//' applied')
      end if
   end if
   ! the model output is written from: this rank's (serial; MPI conserving solver: whole
   ! model on rank 0), or the global model on rank 0 (MPI explicit)
   call dom%output_target(model, om, writer)
   if (writer .and. len(rfile) > 0) then
      call out%resume(om, outdir, error)
   else if (writer) then
      call out%open(om, outdir, error)
   end if
   call par_agree(error)            ! MPI: rank 0 opened the output; its error stops all
   if (allocated(error)) call die(error, dom)
   if (allocated(model%emc)) then
      call run_emc(model, dom, opts%ck, out, error)
   else
      call run_explicit(model, dom, opts, out, error)
   end if
   call log_summary()
   if (allocated(error)) then
      if (error%code == EXIT_CHECKPOINT) then
         call log_info(error%message)
         call par_finalize()
         call exit_process(EXIT_CHECKPOINT)
      end if
      call die(error, dom)
   end if
   call log_info('dynx: results in '//outdir//'/ (d3plot.h5, d3plot.xdmf'// &
      trim(merge(', glstat', '        ', model%db%glstat_dt > 0.0_wp))//')')
   call dom%report()
   call par_finalize()
   end associate
end program dynx
