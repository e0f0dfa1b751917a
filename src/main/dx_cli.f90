!> The dynx command line: options, usage text, the SLURM wall-clock limit, and the two ways
!> the program stops on an error (a usage error before anything ran, or a run's error_t).
!> Exit codes: 0 normal, 2 input error, 3 numerical failure in the run, 4 I/O failure,
!> 5 stopped at a checkpoint (SIGTERM/SIGINT/SIGUSR2 or wall-clock limit; a restart dump was
!> written; --check: stopped by such a signal before the check ended, nothing written).
module dx_cli
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_INPUT, exit_process
   use dx_strings, only: str, rstr, command_arg, lower
   use dx_log, only: log_info, log_error
   use dx_io_sys, only: sys_epoch_seconds
   use dx_timer, only: wall_time
   use dx_signals, only: SIGTERM_NUM, SIGINT_NUM, SIGUSR1_NUM, SIGUSR2_NUM
   use dx_integrator, only: run_options_t, energy_guard_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_abort, par_barrier, &
                     par_active
   use dx_par_agree, only: par_agreed
   use dx_domain, only: domain_t
   implicit none
   private
   public :: cli_t, parse_cli, die, die_usage

   !> What the command line asks for.
   type :: cli_t
      character(:), allocatable :: deck      !< -i: the keyword deck
      character(:), allocatable :: outdir    !< -o: output directory
      character(:), allocatable :: rfile     !< -r: restart dump
      character(:), allocatable :: rdeck     !< -R: restart deck
      character(:), allocatable :: partdir   !< --part: MPI rank files
      logical :: check_only = .false.        !< --check
      logical :: ignore_unknown = .false.    !< --ignore-unknown
      integer :: raise_rank = -1             !< --raise-at-cycle @R (-1: every rank raises)
      character(:), allocatable :: csplit    !< --contact-split ('': DYNX_PAR_CONTACT, owner)
      integer :: case_id = 0                 !< --case: the *CASE to run (0: every case)
      type(run_options_t) :: opts            !< status lines, checkpoints, signals
   end type cli_t

contains

   !> Read the command line into cli; a usage error stops the program with exit 2.
   subroutine parse_cli(cli)
      type(cli_t), intent(out) :: cli
      character(:), allocatable :: arg, val
      integer :: i, n, ios
      cli%opts%ck%wall0 = wall_time()   ! the wall-clock limit counts from process start
      cli%outdir = '.'
      cli%deck = ''
      cli%rfile = ''
      cli%rdeck = ''
      cli%partdir = ''
      cli%csplit = ''
      n = command_argument_count()
      i = 0
      do while (i < n)
         i = i + 1
         arg = get_arg(i)
         select case (arg)
         case ('-h', '--help')
            call usage(); stop
         case ('-i', '--input')
            i = i + 1; cli%deck = get_arg(i)
         case ('-o', '--outdir')
            i = i + 1; cli%outdir = get_arg(i)
         case ('--status')
            i = i + 1; val = get_arg(i)
            read(val, *, iostat=ios) cli%opts%nstatus
            if (ios /= 0 .or. cli%opts%nstatus < 1) &
               call die_usage('--status needs a positive integer')
         case ('--check')
            cli%check_only = .true.
         case ('--case')
            i = i + 1; val = get_arg(i)
            read(val, *, iostat=ios) cli%case_id
            if (ios /= 0 .or. cli%case_id < 1 .or. verify(val, '0123456789') /= 0) &
               call die_usage('--case needs a positive CASEID of the deck''s *CASE, not '//val)
         case ('--part')
            i = i + 1; cli%partdir = get_arg(i)
         case ('-r', '--restart')
            i = i + 1; cli%rfile = get_arg(i)
         case ('-R', '--restart-deck')
            i = i + 1; cli%rdeck = get_arg(i)
         case ('--walltime')
            i = i + 1; val = get_arg(i)
            read(val, *, iostat=ios) cli%opts%ck%walltime
            if (ios /= 0 .or. .not. (cli%opts%ck%walltime > 0.0_wp)) &
               call die_usage('--walltime needs a positive number of seconds')
         case ('--raise-at-cycle')
            i = i + 1; val = get_arg(i)
            call parse_raise(val, cli%opts%ck%raise_cycle, cli%opts%ck%raise_sig, &
                             cli%raise_rank)
         case ('--ignore-unknown')
            cli%ignore_unknown = .true.
         case ('--energy-guard')
            i = i + 1; val = get_arg(i)
            call parse_guard(val, cli%opts%guard)
         case ('--contact-split')
            i = i + 1; val = get_arg(i)
            if (val /= 'owner' .and. val /= 'strips') &
               call die_usage('--contact-split needs owner or strips, not '//val)
            cli%csplit = val
         case default
            if (len(arg) > 15) then
               if (arg(1:15) == '--energy-guard=') then
                  call parse_guard(arg(16:), cli%opts%guard); cycle
               end if
            end if
            if (len(arg) > 2) then
               if (arg(1:2) == 'i=' .or. arg(1:2) == 'I=') then
                  cli%deck = arg(3:); cycle
               end if
               if (arg(1:2) == 'r=' .or. arg(1:2) == 'R=') then
                  cli%rfile = arg(3:); cycle
               end if
            end if
            ! LS-DYNA's own command-line tokens: ncpu= (dynx runs on the ranks mpirun
            ! starts, one thread each) and memory= / memory2= (dynx allocates what the
            ! deck needs): accepted with a note, they change nothing
            if (lskey(arg, 'ncpu=') .or. lskey(arg, 'memory=') .or. &
                lskey(arg, 'memory2=')) then
               call check_ls_token(arg)
               call log_info('dynx: note: '//arg//' accepted and not needed (dynx runs '// &
                  'on the MPI ranks mpirun starts and allocates what the deck needs)')
               cycle
            end if
            call die_usage('unknown argument '//arg)
         end select
      end do
      if (len(cli%deck) == 0) call die_usage('no input deck: use -i deck.k (or i=deck.k)')
      if (len(cli%rdeck) > 0 .and. len(cli%rfile) == 0 .and. .not. cli%check_only) &
         call die_usage('-R (restart deck) needs -r dump.h5 (or --check)')
      cli%opts%outdir = cli%outdir
      cli%opts%ck%outdir = cli%outdir
      cli%opts%ck%deck = cli%deck
      if (cli%case_id > 0) cli%opts%ck%deck = cli%deck//' --case '//str(cli%case_id)
      call slurm_limit(cli%opts%ck%walltime)
   end subroutine parse_cli

   !> whether arg starts with the LS-DYNA token key (case-insensitive, e.g. 'ncpu=')
   logical function lskey(arg, key)
      character(*), intent(in) :: arg, key
      lskey = .false.
      if (len(arg) > len(key)) lskey = lower(arg(1:len(key))) == key
   end function lskey

   !> ncpu=N (N may be negative: LS-DYNA's consistency flag) and memory=N[m|M|g|G]: a
   !> value that is no number is a usage error.
   subroutine check_ls_token(arg)
      character(*), intent(in) :: arg
      character(:), allocatable :: v
      integer :: k, n, ios
      k = index(arg, '=')
      v = arg(k + 1:)
      if (len(v) > 1) then
         if (index('mMgGkK', v(len(v):len(v))) > 0) v = v(1:len(v) - 1)
      end if
      read(v, *, iostat=ios) n
      if (ios /= 0 .or. verify(v, '+-0123456789') /= 0) &
         call die_usage(arg(1:k)//' needs an integer (LS-DYNA syntax), not '//arg(k + 1:))
   end subroutine check_ls_token

   function get_arg(k) result(a)
      integer, intent(in) :: k
      character(:), allocatable :: a
      if (k > command_argument_count()) call die_usage('missing value after the last option')
      a = command_arg(k)
   end function get_arg

   subroutine usage()
      write(output_unit, '(a)') &
         'usage: dynx -i deck.k [options]     (LS-DYNA style i=deck.k is accepted too,', &
         '                                    and ncpu=N, memory=N: noted, not needed)', &
         '', &
         'Runs an LS-DYNA style keyword deck with the explicit central-difference solver.', &
         '', &
         'options:', &
         '  -i, --input FILE     the keyword deck', &
         '  -o, --outdir DIR     output directory (default: current directory); holds', &
         '                       d3plot.h5 + d3plot.xdmf (open in ParaView), glstat, nodout', &
         '  --status N           number of status lines over the run (default 10)', &
         '  --check              read and check the deck, print a summary, do not run; lists', &
         '                       every unknown keyword and unsupported option at once,', &
         '                       grouped by family, and exits 2 if there is any', &
         '  --case ID            a multi-case deck (*CASE): run (or check) only the case', &
         '                       CASEID ID, in DIR; without it every case runs in turn, each', &
         '                       in DIR/JOBID (serial; under MPI give --case)', &
         '  --part DIR           MPI runs: the rank files (dynx-part) are DIR/rank_R.h5', &
         '                       (default: the output directory, else next to the deck;', &
         '                       rank 0 partitions into the output directory if none)', &
         '  -r, --restart FILE   continue the run from restart dump FILE (d3dumpNN.h5,', &
         '                       runrsf.h5); give the same deck and -o as the first run', &
         '  -R, --restart-deck F a small restart deck applied after the deck (new end time,', &
         '                       output intervals, curves; docs/keywords.md)', &
         '  --walltime S         write a restart dump and stop (exit 5) before S seconds of', &
         '                       wall time (SLURM_JOB_END_TIME is read when set)', &
         '  --raise-at-cycle N[:SIG][@R]  send SIG (TERM, INT, USR1, USR2; default TERM) to', &
         '                       dynx itself at cycle N (tests of the signal path); MPI:', &
         '                       @R only on rank R (default every rank)', &
         '  --ignore-unknown     skip unknown output requests and performance controls', &
         '                       with a warning (any other unknown keyword still stops)', &
         '  --energy-guard W,S   dynx''s energy guard (not ENDENG): the energy ratio', &
         '                       (glstat) is checked every cycle; a warning once when it', &
         '                       leaves 1 +- W, a stop (exit 3, failure dump) when it', &
         '                       leaves 1 +- (S - 1) (a blow-up); default 0.1,2; off: no', &
         '                       checks (docs/errors.md, "Energy guard")', &
         '  --contact-split M    MPI runs with automatic contact: which rank computes a slave', &
         '                       node: owner (default; the rank owning it) or strips (1-D', &
         '                       strips of equal node count along the longest axis, rebuilt', &
         '                       with the bucket sort; ParaDyn); the results are the', &
         '                       same bits either way', &
         '  -h, --help           this text', &
         '', &
         'exit codes: 0 normal termination, 2 input error, 3 numerical failure in the run,', &
         '            4 I/O failure, 5 stopped with a restart dump (SIGTERM, SIGINT, SIGUSR2,', &
         '            walltime)', &
         'signals: SIGTERM/SIGINT/SIGUSR2 dump and stop (exit 5); SIGUSR1 dumps and goes on;', &
         '         under mpirun send SIGUSR2 (mpirun forwards it; it kills the job on SIGTERM)'
   end subroutine usage

   !> The wall-clock limit: the smaller of --walltime and what SLURM_JOB_END_TIME (Unix
   !> seconds) leaves from now; 0 when neither is set.
   subroutine slurm_limit(walltime)
      real(wp), intent(inout) :: walltime
      character(64) :: env
      integer :: st, l
      integer(8) :: tend
      real(wp) :: left
      call get_environment_variable('SLURM_JOB_END_TIME', env, length=l, status=st)
      if (st /= 0 .or. l == 0) return
      read(env, *, iostat=st) tend
      if (st /= 0) then
         call log_info('dynx: SLURM_JOB_END_TIME='//trim(env)//' is not a number; ignored')
         return
      end if
      left = real(tend - sys_epoch_seconds(), wp)
      if (left <= 0.0_wp) left = 1.0_wp
      if (walltime <= 0.0_wp .or. left < walltime) walltime = left
      call log_info('dynx: SLURM_JOB_END_TIME leaves '//rstr(left, 6)//' s')
   end subroutine slurm_limit

   !> --energy-guard WARN,STOP or off (docs/errors.md, "Energy guard")
   subroutine parse_guard(v, guard)
      character(*), intent(in) :: v
      type(energy_guard_t), intent(inout) :: guard
      integer :: k, ios1, ios2
      if (v == 'off') then
         guard%on = .false.; return
      end if
      k = index(v, ',')
      ios1 = 1; ios2 = 1
      if (k > 1) then
         read(v(1:k - 1), *, iostat=ios1) guard%warn
         read(v(k + 1:), *, iostat=ios2) guard%stop
      end if
      if (ios1 /= 0 .or. ios2 /= 0) then
         call die_usage('--energy-guard needs WARN,STOP (e.g. 0.1,2) or off, not '//v)
      else if (.not. (guard%warn > 0.0_wp) .or. .not. (guard%stop > 1.0_wp + guard%warn)) then
         call die_usage('--energy-guard WARN,STOP needs WARN > 0 and STOP > 1 + WARN, not '//v)
      end if
      guard%on = .true.
   end subroutine parse_guard

   !> --raise-at-cycle N[:SIG][@R]
   subroutine parse_raise(vv, n, sig, rank)
      character(*), intent(in) :: vv
      integer, intent(out) :: n, sig, rank
      integer :: k, ios
      character(:), allocatable :: name, v
      v = vv
      rank = -1
      k = index(v, '@')
      if (k > 0) then
         read(v(k + 1:), *, iostat=ios) rank
         if (ios /= 0 .or. rank < 0) &
            call die_usage('--raise-at-cycle N[:SIG]@R needs a rank R >= 0')
         v = v(1:k - 1)
      end if
      k = index(v, ':')
      name = 'TERM'
      if (k > 0) name = v(k + 1:)
      if (k == 0) k = len(v) + 1
      read(v(1:k - 1), *, iostat=ios) n
      if (ios /= 0 .or. n < 1) call die_usage('--raise-at-cycle needs N[:SIG] with N > 0')
      select case (name)
      case ('TERM', 'SIGTERM'); sig = SIGTERM_NUM
      case ('INT', 'SIGINT'); sig = SIGINT_NUM
      case ('USR1', 'SIGUSR1'); sig = SIGUSR1_NUM
      case ('USR2', 'SIGUSR2'); sig = SIGUSR2_NUM
      case default
         call die_usage('--raise-at-cycle: signal '//name//' is not one of TERM, INT, USR1, USR2')
      end select
   end subroutine parse_raise

   !> A usage error: message, hint, exit 2 (under mpirun rank 0 alone speaks).
   subroutine die_usage(msg)
      character(*), intent(in) :: msg
      type(error_t), allocatable :: e
      ! under mpirun every rank gets here (before MPI_Init): start MPI so that rank 0 alone
      ! speaks and no rank exits before it has (par_init does nothing in a serial run)
      if (.not. par_active()) call par_init(e)
      if (par_rank() == 0) then
         call log_error(msg)
         write(error_unit, '(a)') 'dynx: try dynx --help'
         flush(error_unit)
      end if
      call par_barrier()
      call par_finalize()
      call exit_process(EXIT_INPUT)
   end subroutine die_usage

   !> Stop on err with its exit code (dom: the run's domain, once there is one).
   subroutine die(err, dom)
      type(error_t), intent(in) :: err
      class(domain_t), intent(in), optional :: dom
      logical :: together
      ! a failure every rank knows (it wrote the last plot state): rank 0 reports, all exit
      ! with the code; any other failure on one rank stops every rank (MPI_Abort)
      together = par_agreed()
      if (present(dom)) together = together .or. dom%together()
      if (par_size() > 1 .and. .not. together) call par_abort(err%message, err%code)
      if (par_rank() == 0) call log_error(err%message)
      flush(error_unit)
      call par_barrier()       ! every rank stops together: none exits before rank 0 printed
      call par_finalize()
      call exit_process(err%code)
   end subroutine die
end module dx_cli
