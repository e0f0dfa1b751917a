!> dynx: arguments -> deck -> model -> explicit solver -> finish.
!> Exit codes: 0 normal, 2 input error, 3 numerical failure in the run, 4 I/O failure.
program dynx
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_INPUT, exit_process
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_error, log_summary
   use dx_model, only: model_t
   use dx_deck, only: read_deck
   use dx_output, only: output_t
   use dx_explicit, only: run_options_t, run_explicit, init_state
   use dx_emc_solver, only: run_emc
   implicit none
   character(:), allocatable :: deck, outdir, arg, val
   type(model_t) :: model
   type(output_t) :: out
   type(run_options_t) :: opts
   type(error_t), allocatable :: error
   logical :: check_only, ignore_unknown
   integer :: i, n, ios

   check_only = .false.
   ignore_unknown = .false.
   outdir = '.'
   deck = ''
   n = command_argument_count()
   i = 0
   do while (i < n)
      i = i + 1
      arg = get_arg(i)
      select case (arg)
      case ('-h', '--help')
         call usage(); stop
      case ('-i', '--input')
         i = i + 1; deck = get_arg(i)
      case ('-o', '--outdir')
         i = i + 1; outdir = get_arg(i)
      case ('--status')
         i = i + 1; val = get_arg(i)
         read(val, *, iostat=ios) opts%nstatus
         if (ios /= 0 .or. opts%nstatus < 1) call die_usage('--status needs a positive integer')
      case ('--check')
         check_only = .true.
      case ('--ignore-unknown')
         ignore_unknown = .true.
      case default
         if (len(arg) > 2) then
            if (arg(1:2) == 'i=' .or. arg(1:2) == 'I=') then
               deck = arg(3:); cycle
            end if
         end if
         call die_usage('unknown argument '//arg)
      end select
   end do
   if (len(deck) == 0) call die_usage('no input deck: use -i deck.k (or i=deck.k)')
   opts%outdir = outdir

   call read_deck(deck, model, error, ignore_unknown)
   if (allocated(error)) call die(error)
   call log_info('dynx: read '//deck//': '//str(model%nn)//' nodes, '//str(model%ne)// &
                 ' elements, '//str(size(model%parts))//' parts, '//str(size(model%blocks))// &
                 ' element blocks, end time '//rstr(model%ctrl%endtim))
   if (check_only) then
      call log_info('dynx: deck check passed')
      call log_summary()
      stop
   end if
   call out%open(model, outdir, error)
   if (allocated(error)) call die(error)
   if (allocated(model%emc)) then
      call init_state(model)
      call run_emc(model, outdir, out, error)
   else
      call run_explicit(model, opts, out, error)
   end if
   call log_summary()
   if (allocated(error)) call die(error)
   call log_info('dynx: results in '//outdir//'/ (d3plot.h5, d3plot.xdmf'// &
      trim(merge(', glstat', '        ', model%db%glstat_dt > 0.0_wp))//')')

contains

   function get_arg(k) result(a)
      integer, intent(in) :: k
      character(:), allocatable :: a
      integer :: l
      if (k > command_argument_count()) call die_usage('missing value after the last option')
      call get_command_argument(k, length=l)
      allocate(character(l) :: a)
      call get_command_argument(k, a)
   end function get_arg

   subroutine usage()
      write(output_unit, '(a)') &
         'usage: dynx -i deck.k [options]     (LS-DYNA style i=deck.k is accepted too)', &
         '', &
         'Runs an LS-DYNA style keyword deck with the explicit central-difference solver.', &
         '', &
         'options:', &
         '  -i, --input FILE     the keyword deck', &
         '  -o, --outdir DIR     output directory (default: current directory); holds', &
         '                       d3plot.h5 + d3plot.xdmf (open in ParaView), glstat, nodout', &
         '  --status N           number of status lines over the run (default 10)', &
         '  --check              read and check the deck, print a summary, do not run', &
         '  --ignore-unknown     unknown keywords are warnings, not errors', &
         '  -h, --help           this text', &
         '', &
         'exit codes: 0 normal termination, 2 input error, 3 numerical failure in the run,', &
         '            4 I/O failure'
   end subroutine usage

   subroutine die_usage(msg)
      character(*), intent(in) :: msg
      call log_error(msg)
      write(error_unit, '(a)') 'dynx: try dynx --help'
      call exit_process(EXIT_INPUT)
   end subroutine die_usage

   subroutine die(err)
      type(error_t), intent(in) :: err
      call log_error(err%message)
      call exit_process(err%code)
   end subroutine die
end program dynx
