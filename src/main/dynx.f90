!> dynx: arguments -> deck -> model -> explicit solver -> finish (dx_cli: options, usage,
!> exit codes).
program dynx
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_CHECKPOINT, exit_process
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_summary, log_set_quiet
   use dx_model, only: model_t
   use dx_deck, only: read_deck
   use dx_output, only: output_t
   use dx_explicit, only: run_explicit, init_state
   use dx_par_restart, only: par_restart_read, par_restart_precheck
   use dx_restart_deck, only: apply_restart_deck
   use dx_signals, only: signals_install
   use dx_emc_solver, only: run_emc
   use dx_par, only: par_init, par_finalize, par_size, par_rank
   use dx_par_agree, only: par_agree
   use dx_par_engine, only: par_engine_setup, par_engine_global, par_engine_report
   use dx_cli, only: cli_t, parse_cli, die
   use dx_out_lock, only: out_lock
   implicit none
   type(cli_t) :: cli
   type(model_t) :: model
   type(output_t) :: out
   type(error_t), allocatable :: error
   integer :: lock_fd

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
   call par_engine_setup(model, deck, outdir, partdir, error)   ! MPI run: the rank's part
   call par_agree(error)
   if (allocated(error)) call die(error)
   call init_state(model)
   if (len(rfile) > 0) then
      call par_restart_read(model, rfile, error)   ! serial dump, or an MPI run's parts
      if (allocated(error)) call die(error)
      call log_info('dynx: restart from '//rfile//' at cycle '//str(model%cycle)//', time '// &
                    rstr(model%time))
      if (len(rdeck) > 0) then
         call apply_restart_deck(rdeck, model, error)
         if (.not. allocated(error) .and. par_size() > 1 .and. .not. allocated(model%emc)) &
            call apply_restart_deck(rdeck, par_engine_global(), error)
         call par_agree(error)
         if (allocated(error)) call die(error)
         call log_info('dynx: restart deck '//rdeck//' applied')
      end if
      if (par_size() == 1 .or. (par_rank() == 0 .and. allocated(model%emc))) then
         call out%resume(model, outdir, error)   ! (MPI conserving solver: rank 0, whole model)
      else if (par_rank() == 0) then  ! MPI: rank 0 writes the output (global model)
         call out%resume(par_engine_global(), outdir, error)
      end if
   else if (par_size() > 1) then       ! an MPI run writes its output from rank 0
      if (par_rank() == 0 .and. allocated(model%emc)) then   ! conserving solver: whole model
         call out%open(model, outdir, error)
      else if (par_rank() == 0) then
         call out%open(par_engine_global(), outdir, error)
      end if
   else
      call out%open(model, outdir, error)
   end if
   call par_agree(error)            ! MPI: rank 0 opened the output; its error stops all
   if (allocated(error)) call die(error)
   if (allocated(model%emc)) then
      call run_emc(model, opts%ck, out, error)
   else
      call run_explicit(model, opts, out, error)
   end if
   call log_summary()
   if (allocated(error)) then
      if (error%code == EXIT_CHECKPOINT) then
         call log_info(error%message)
         call par_finalize()
         call exit_process(EXIT_CHECKPOINT)
      end if
      call die(error)
   end if
   call log_info('dynx: results in '//outdir//'/ (d3plot.h5, d3plot.xdmf'// &
      trim(merge(', glstat', '        ', model%db%glstat_dt > 0.0_wp))//')')
   call par_engine_report()
   call par_finalize()
   end associate

end program dynx
