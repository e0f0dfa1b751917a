!> The steps of a dynx run that the main program strings together: start (signals, MPI),
!> the --check stop, the output (restart read, restart deck, plot and history files opened
!> or resumed), the integrator, and the end. Each step stops the program through dx_cli's
!> die on an error every rank agrees on.
module dx_launch
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_CHECKPOINT, exit_process, set_error, EXIT_IO
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_summary, log_set_quiet, log_open_messages
   use dx_card_echo, only: echo_t
   use dx_d3hsp, only: write_d3hsp
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_integrator, only: integrator_t
   use dx_solver, only: make_integrator, integrator_choice, run_driver
   use dx_par_restart, only: par_restart_precheck
   use dx_restart_deck, only: apply_restart_deck
   use dx_signals, only: signal_stop_requested, signal_name
   use dx_par, only: par_init, par_finalize, par_rank
   use dx_par_agree, only: par_agree
   use dx_domain, only: domain_t
   use dx_out_lock, only: out_lock
   use dx_cli, only: cli_t, die, die_usage
   use dx_read_case, only: case_def_t, deck_cases
   use dx_strings, only: command_arg
   use dx_par, only: par_size
   implicit none
   private
   public :: launch_start, launch_check_only, launch_lock, launch_output, launch_run, &
             launch_d3hsp, launch_cases

contains

   !> MPI when started by mpirun/srun; ranks > 0 print no info or warnings. The signal
   !> handlers are the main program's first statement (before MPI_Init and the deck, so a
   !> SIGTERM during the start-up is a request too, polled once per cycle; MPI: folded into
   !> the dt reduction, every rank acts together).
   subroutine launch_start(cli)
      type(cli_t), intent(inout) :: cli
      type(error_t), allocatable :: error
      call par_init(error)
      if (allocated(error)) call die(error)
      if (par_rank() > 0) call log_set_quiet(.true.)
      cli%opts%ck%raise_here = cli%raise_rank < 0 .or. cli%raise_rank == par_rank()
      cli%opts%ck%ctl_here = par_rank() == 0      ! rank 0 reads OUT/dynx.ctl for all
   end subroutine launch_start

   !> A multi-case deck (*CASE, dx_read_case) without --case: every case runs (or is
   !> checked) in deck order as its own dynx process, `<this command> -o OUTDIR/JOBID
   !> --case CASEID`, as LS-DYNA runs its cases one after another with files named after
   !> JOBID; a case that fails stops the sequence (--check: every case is checked), and the
   !> program ends here with the first nonzero exit code (0 when every case ended
   !> normally). Serial only: under mpirun each case is started with --case (ranks cannot
   !> start the children together). A deck without *CASE: returns at once.
   subroutine launch_cases(cli)
      type(cli_t), intent(in) :: cli
      type(case_def_t), allocatable :: cases(:)
      type(error_t), allocatable :: error
      character(:), allocatable :: base, cmd, dir, done, exe
      integer :: k, rc, cs, code
      if (cli%case_id > 0) return
      call deck_cases(cli%deck, cases, error)
      call par_agree(error)            ! MPI: every rank read the same deck: one message
      if (allocated(error)) call die(error)
      if (size(cases) == 0) return
      if (par_size() > 1) call set_error(error, cli%deck//': a multi-case deck (*CASE) '// &
         'is not supported in an MPI run (it runs serially, one process per case): start each '// &
         'case with --case ID (cases '//case_ids(cases)//')')
      call par_agree(error)            ! (every rank has it: one message, no abort)
      if (allocated(error)) call die(error)
      if (len(cli%rfile) > 0) call die_usage('-r: a multi-case deck restarts one case: add '// &
                                             '--case ID (cases '//case_ids(cases)//')')
      call get_command_argument(0, length=k)
      allocate(character(k) :: exe)
      call get_command_argument(0, exe)
      base = quoted(exe)
      do k = 1, command_argument_count()
         base = base//' '//quoted(command_arg(k))
      end do
      code = 0
      done = ''
      do k = 1, size(cases)
         dir = cli%outdir//'/'//cases(k)%jobid
         cmd = base//' -o '//quoted(dir)//' --case '//str(cases(k)%id)
         call log_info('dynx: *CASE '//str(cases(k)%id)//' ('//cases(k)%jobid//', '// &
                       str(k)//' of '//str(size(cases))//'): '//cmd)
         flush(6)
         call execute_command_line(cmd, exitstat=rc, cmdstat=cs)
         if (cs /= 0) rc = EXIT_IO
         done = done//new_line('a')//'  case '//str(cases(k)%id)//' '//cases(k)%jobid// &
                ': exit '//str(rc)//' ('//dir//')'
         if (rc /= 0 .and. code == 0) code = rc
         if (rc /= 0 .and. .not. cli%check_only) then
            if (k < size(cases)) done = done//new_line('a')//'  cases after '// &
               str(cases(k)%id)//' not run (start them with --case ID)'
            exit
         end if
      end do
      call log_info('dynx: '//str(size(cases))//' *CASE load cases of '//cli%deck// &
                    trim(merge(' checked', ' run    ', cli%check_only))//done)
      call par_finalize()
      call exit_process(code)
   end subroutine launch_cases

   function case_ids(cases) result(s)
      type(case_def_t), intent(in) :: cases(:)
      character(:), allocatable :: s
      integer :: k
      s = ''
      do k = 1, size(cases)
         if (k > 1) s = s//', '
         s = s//str(cases(k)%id)
      end do
   end function case_ids

   !> a word for sh: in single quotes, an inner ' as '\''
   function quoted(a) result(q)
      character(*), intent(in) :: a
      character(:), allocatable :: q
      integer :: i
      q = "'"
      do i = 1, len(a)
         if (a(i:i) == "'") then
            q = q//"'\''"
         else
            q = q//a(i:i)
         end if
      end do
      q = q//"'"
   end function quoted

   !> --check: the restart deck too when given, a summary, and the end of the program.
   subroutine launch_check_only(cli, model)
      type(cli_t), intent(in) :: cli
      type(model_t), intent(inout) :: model
      type(error_t), allocatable :: error
      character(:), allocatable :: name, why
      integer :: sig
      call log_info('dynx: read '//cli%deck//': '//str(model%nn)//' nodes, '// &
         str(model%ne)//' elements, '//str(size(model%parts))//' parts, '// &
         str(size(model%blocks))//' element blocks, end time '//rstr(model%ctrl%endtim))
      sig = signal_stop_requested()
      if (sig /= 0 .and. cli%check_only) then      ! --check: nothing to dump; say so
         call log_info('dynx: stopped by '//signal_name(sig)//' during --check (received '// &
                       'while reading the deck); the check did not finish, nothing written')
         call log_summary()
         call par_finalize()
         call exit_process(EXIT_CHECKPOINT)
      else if (sig /= 0) then
         call log_info('dynx: '//signal_name(sig)//' received during start-up (while '// &
            'reading the deck): the run stops at the end of its first cycle with a '// &
            'restart dump (exit 5)')
      end if
      if (.not. cli%check_only) return
      call integrator_choice(model, name, why)
      call log_info('dynx: integrator: '//name//' ('//why//')')
      if (len(cli%rdeck) > 0) then
         call apply_restart_deck(cli%rdeck, model, error)
         if (allocated(error)) call die(error)
      end if
      call log_info('dynx: deck check passed')
      call log_summary()
      call par_finalize()
      stop
   end subroutine launch_check_only

   !> The output-folder lock (rank 0, held until the process ends) and the restart dump's
   !> match with the deck (MPI runs: before the domain is built).
   subroutine launch_lock(cli, model, lock_fd)
      type(cli_t), intent(in) :: cli
      type(model_t), intent(in) :: model
      integer, intent(out) :: lock_fd
      type(error_t), allocatable :: error
      lock_fd = -1
      if (par_rank() == 0) call out_lock(cli%outdir, 'dynx', lock_fd, error)
      call par_agree(error)
      if (allocated(error)) call die(error)
      if (len(cli%rfile) > 0) call par_restart_precheck(cli%rfile, cli%deck, error, &
                                                        model%deck_files)
      if (allocated(error)) call die(error)
   end subroutine launch_lock

   !> A restart (dump, then restart deck) and the output files: opened, or resumed after a
   !> restart, from the model the domain names (this rank's; MPI explicit: the global model
   !> on rank 0).
   subroutine launch_output(cli, model, dom, out)
      type(cli_t), intent(in) :: cli
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(output_t), intent(inout) :: out
      type(error_t), allocatable :: error
      type(model_t), pointer :: om
      logical :: writer
      if (len(cli%rfile) > 0) then
         call dom%read_restart(model, cli%rfile, error)   ! serial dump, or an MPI run's parts
         if (allocated(error)) call die(error, dom)
         call log_info('dynx: restart from '//cli%rfile//' at cycle '//str(model%cycle)// &
                       ', time '//rstr(model%time))
         if (len(cli%rdeck) > 0) then
            call apply_restart_deck(cli%rdeck, model, error)
            call dom%output_target(model, om, writer)   ! MPI: the global model too
            if (.not. allocated(error) .and. .not. associated(om, model)) &
               call apply_restart_deck(cli%rdeck, om, error)
            call par_agree(error)
            if (allocated(error)) call die(error, dom)
            call log_info('dynx: restart deck '//cli%rdeck//' applied')
         end if
      end if
      call dom%output_target(model, om, writer)
      if (writer .and. len(cli%rfile) > 0) then
         call out%resume(om, cli%outdir, error)
      else if (writer) then
         call out%open(om, cli%outdir, error)
      end if
      ! MPI (om is the gathered global model): the ranks' parts hold the plot states
      if (writer .and. .not. associated(om, model)) call out%plot_by_parts()
      call par_agree(error)            ! MPI: rank 0 opened the output; its error stops all
      if (allocated(error)) call die(error, dom)
   end subroutine launch_output

   !> OUTDIR/d3hsp (dx_d3hsp: the deck's echo, the model summary, the smallest time steps)
   !> and OUTDIR/messages (every warning and error from here on, the deck's warnings first;
   !> a restart appends to it), by the rank that writes the global files.
   subroutine launch_d3hsp(cli, model, dom, echo)
      type(cli_t), intent(in) :: cli
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(echo_t), intent(inout) :: echo
      type(model_t), pointer :: om
      type(error_t), allocatable :: error
      logical :: writer, ok
      call dom%output_target(model, om, writer)
      if (writer) then
         call log_open_messages(cli%outdir//'/messages', len(cli%rfile) > 0, ok)
         if (.not. ok) call set_error(error, 'cannot write '//cli%outdir//'/messages', EXIT_IO)
         if (.not. allocated(error)) &
            call write_d3hsp(cli%outdir//'/d3hsp', cli%deck, echo%text(), om, error)
      end if
      call par_agree(error)
      if (allocated(error)) call die(error, dom)
   end subroutine launch_d3hsp

   !> The integrator the deck asks for (dx_solver's factory) run by the one driver, then the
   !> end: exit 5 after a checkpoint stop, the error's code after a failure, else where the
   !> results are.
   subroutine launch_run(cli, model, dom, out)
      type(cli_t), intent(inout) :: cli
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(output_t), intent(inout) :: out
      type(error_t), allocatable :: error
      class(integrator_t), allocatable :: integ
      call make_integrator(model, integ)
      call run_driver(integ, model, dom, cli%opts, out, error)
      call log_summary()
      if (allocated(error)) then
         if (error%code == EXIT_CHECKPOINT) then
            call log_info(error%message)
            call par_finalize()
            call exit_process(EXIT_CHECKPOINT)
         end if
         call die(error, dom)
      end if
      call log_info('dynx: results in '//cli%outdir//'/ ('//files_written(cli%outdir)//')')
      call dom%report()
      call par_finalize()
   end subroutine launch_run

   !> The files of a run in dir, for the end message (issue 21: every file, not glstat
   !> only): the plot, the time histories and ASCII databases, d3hsp and messages, the
   !> restart dumps, in that order, each that exists.
   function files_written(dir) result(s)
      character(*), intent(in) :: dir
      character(:), allocatable :: s
      character(len=*), parameter :: names(16) = [character(len=12) :: 'd3plot.h5', &
         'd3plot.xdmf', 'glstat', 'nodout', 'rcforc', 'rbdout', 'matsum', 'spcforc', &
         'sleout', 'elout', 'ncforc', 'emcstat', 'eigout', 'd3hsp', 'messages', 'runrsf.h5']
      character(len=2) :: nn
      logical :: there
      integer :: k
      s = ''
      do k = 1, size(names)
         inquire(file=dir//'/'//trim(names(k)), exist=there)
         if (there) s = s//', '//trim(names(k))
      end do
      do k = 1, 99
         write(nn, '(i2.2)') k
         inquire(file=dir//'/d3dump'//nn//'.h5', exist=there)
         if (there) s = s//', d3dump'//nn//'.h5'
      end do
      if (len(s) > 2) s = s(3:)
   end function files_written
end module dx_launch
