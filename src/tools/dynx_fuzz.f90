!> dynx-fuzz: the persistent in-process harness of the deck-reader fuzzer (issue 15).
!> One process reads many mutated inputs through the same path as `dynx --check` (read_deck
!> with the check flag, which also builds the model and runs the geometry checks; the
!> integrator choice; a restart deck with -R), or, for a mutated restart dump, the path of
!> `dynx -i deck -r dump` up to the restored state (read_deck, the restart pre-check, the
!> initial state, the serial restart read; no cycles: the per-process mode of
!> scripts/fuzz_decks.py runs those on a sample).
!>
!> Usage: dynx-fuzz LIST [FIRST]. LIST holds one input per line, tab-separated:
!>    index  kind  directory  deck  extra
!> kind 'check' (dynx --check -i deck), 'rdeck' (dynx --check -i deck -R extra) or 'dump'
!> (dynx -i deck -r extra). The harness changes into directory for each input (the messages
!> name files as a per-process run started there does) and starts at line FIRST (default 1:
!> the driver restarts a batch after the input that crashed or hung it).
!> Per input it writes to stdout, flushed:  'B index' before, then after
!>    'E index code seconds | the error message'
!> (the message's first 4000 characters, its line ends written as the character 31)
!> (code 0: the check passed; else the error's exit code). A crash (signal, runtime error,
!> sanitizer report) or a hang leaves a 'B' without its 'E': the driver names that input.
!>
!> Independence of the inputs: every input is read into fresh local objects (model,
!> error); dynx keeps almost no module state (dx_log's warning list, which no reader
!> consults; the parallel flags, serial here). What could leak from one input to the next
!> is checked after each: an open file descriptor left behind (the lowest free descriptor
!> must not grow) and the floating-point halting modes (a reader that turned overflow
!> trapping off and did not restore it); either is reported as 'L index what' and the
!> driver counts it as a failure. The equality of the harness's verdicts with separate
!> processes' is a test (scripts/fuzz_decks.py --compare, tests/regression/fuzz_harness_equal).
!> No paper: a harness in the manner of libFuzzer's persistent mode (LLVM documentation,
!> "libFuzzer - a library for coverage-guided fuzz testing", section "Fuzz target").
program dynx_fuzz
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_invalid, ieee_divide_by_zero, &
                                            ieee_get_halting_mode, ieee_set_halting_mode
   use dx_error, only: error_t, exit_process
   use dx_model, only: model_t
   use dx_deck_model, only: read_deck
   use dx_read_case, only: case_def_t, deck_cases
   use dx_restart_deck, only: apply_restart_deck
   use dx_solver, only: integrator_choice
   use dx_par_restart, only: par_restart_precheck, serial_restart_read
   use dx_explicit, only: init_state
   use dx_log, only: log_set_quiet
   use dx_signals, only: signals_install
   use dx_libc, only: c_chdir, c_dup, c_close
   implicit none


   character(len=4096) :: listfile, arg
   character(len=:), allocatable :: line
   integer :: u, ios, first, nline, fd0, fd
   logical :: halt0(3), halt(3)

   if (command_argument_count() < 1) then
      write(error_unit, '(a)') 'usage: dynx-fuzz LIST [FIRST]  (see src/tools/dynx_fuzz.f90)'
      call exit_process(2)
   end if
   call get_command_argument(1, listfile)
   first = 1
   if (command_argument_count() >= 2) then
      call get_command_argument(2, arg)
      read(arg, *, iostat=ios) first
      if (ios /= 0) first = 1
   end if
   call signals_install()
   call log_set_quiet(.true.)       ! warnings and notes: not the verdict
   open(newunit=u, file=trim(listfile), status='old', action='read', iostat=ios)
   if (ios /= 0) then
      write(error_unit, '(a)') 'dynx-fuzz: cannot open '//trim(listfile)
      call exit_process(2)
   end if
   call halting(halt0)
   fd0 = lowest_free_fd()
   nline = 0
   do
      call read_line(u, line, ios)
      if (ios /= 0) exit
      nline = nline + 1
      if (nline < first .or. len_trim(line) == 0) cycle
      call one_input(line)
      fd = lowest_free_fd()
      if (fd /= fd0) then
         write(output_unit, '(a,i0,a,i0,a,i0)') 'L ', index_of(line), &
            ' file descriptor leak: lowest free descriptor ', fd, ', was ', fd0
         fd0 = fd
      end if
      call halting(halt)
      if (any(halt .neqv. halt0)) then
         write(output_unit, '(a,i0,a)') 'L ', index_of(line), &
            ' floating-point halting mode changed (restored for the next input)'
         call ieee_set_halting_mode(ieee_overflow, halt0(1))
         call ieee_set_halting_mode(ieee_invalid, halt0(2))
         call ieee_set_halting_mode(ieee_divide_by_zero, halt0(3))
      end if
      flush(output_unit)
   end do
   close(u)
   write(output_unit, '(a)') 'DONE'
   flush(output_unit)

contains

   !> One input: the fields of its list line, the reading, the verdict line.
   subroutine one_input(ln)
      character(*), intent(in) :: ln
      character(:), allocatable :: f(:)
      character(:), allocatable :: kind, dir, deck, extra, name, why, msg
      type(model_t), allocatable :: model
      type(error_t), allocatable :: error
      integer(int64) :: t0, t1, rate
      integer :: idx, code, k
      type(case_def_t), allocatable :: cases(:)
      call split_tabs(ln, f)
      idx = index_of(ln)
      kind = trim(f(2)); dir = trim(f(3)); deck = trim(f(4)); extra = trim(f(5))
      write(output_unit, '(a,i0)') 'B ', idx
      flush(output_unit)
      call system_clock(t0, rate)
      if (c_chdir(dir//c_null_char) /= 0) then
         write(output_unit, '(a,i0,a)') 'E ', idx, ' 1 0.0 | dynx-fuzz: cannot enter '//dir
         return
      end if
      allocate(model)
      ! a multi-case deck (*CASE): bin/dynx checks each case as its own run in deck order
      ! (dx_launch%launch_cases); the verdict is the first failing case's, as there
      call deck_cases(deck, cases, error)
      if (.not. allocated(error) .and. kind /= 'dump' .and. allocated(cases)) then
         do k = 1, size(cases)
            if (k > 1) then
               deallocate(model)
               allocate(model)
            end if
            call read_deck(deck, model, error, .false., .true., case_id=cases(k)%id)
            if (.not. allocated(error)) then
               call integrator_choice(model, name, why)
               if (kind == 'rdeck') call apply_restart_deck(extra, model, error)
            end if
            if (allocated(error)) exit
         end do
         if (size(cases) > 0) kind = 'done'
      end if
      if (allocated(error)) kind = 'done'
      select case (kind)
      case ('done')
      case ('check', 'rdeck')
         call read_deck(deck, model, error, .false., .true.)
         if (.not. allocated(error)) then
            call integrator_choice(model, name, why)
            if (kind == 'rdeck') call apply_restart_deck(extra, model, error)
         end if
      case ('dump')
         call read_deck(deck, model, error, .false., .false.)
         if (.not. allocated(error)) call par_restart_precheck(extra, deck, error, &
                                                               model%deck_files)
         if (.not. allocated(error)) then
            call init_state(model)
            call serial_restart_read(model, extra, error)
         end if
      case default
         write(output_unit, '(a,i0,a)') 'E ', idx, ' 1 0.0 | dynx-fuzz: unknown kind '//kind
         return
      end select
      deallocate(model)
      call system_clock(t1)
      code = 0
      msg = ''
      if (allocated(error)) then
         code = error%code
         msg = error%message
         if (len(msg) > 4000) msg = msg(1:4000)
         do k = 1, len(msg)               ! one line: its line ends as the unit separator
            if (msg(k:k) == new_line('a')) msg(k:k) = achar(31)
         end do
      end if
      write(output_unit, '(a,i0,1x,i0,1x,f0.4,a)') 'E ', idx, code, &
         real(t1 - t0) / real(max(rate, 1_int64)), ' | '//msg
   end subroutine one_input

   integer function index_of(ln)
      character(*), intent(in) :: ln
      integer :: k, ios
      k = index(ln, achar(9))
      index_of = -1
      if (k > 1) read(ln(1:k - 1), *, iostat=ios) index_of
   end function index_of

   !> The 5 tab-separated fields of a list line (missing ones blank).
   subroutine split_tabs(ln, f)
      character(*), intent(in) :: ln
      character(:), allocatable, intent(out) :: f(:)
      integer :: i, a, b
      allocate(character(len=len(ln)) :: f(5))
      f = ''
      a = 1
      do i = 1, 5
         b = index(ln(a:), achar(9))
         if (b == 0) then
            f(i) = ln(a:)
            exit
         end if
         f(i) = ln(a:a + b - 2)
         a = a + b
      end do
   end subroutine split_tabs

   !> One line of any length from unit u (ios /= 0 at the end of the file).
   subroutine read_line(u, ln, ios)
      integer, intent(in) :: u
      character(:), allocatable, intent(out) :: ln
      integer, intent(out) :: ios
      character(len=1024) :: buf
      integer :: n
      ln = ''
      do
         read(u, '(a)', advance='no', iostat=ios, size=n) buf
         ln = ln//buf(1:n)
         if (is_iostat_eor(ios)) then
            ios = 0
            return
         end if
         if (ios /= 0) return
      end do
   end subroutine read_line

   !> The lowest free file descriptor (dup returns it): grows when an input leaves one open.
   integer function lowest_free_fd() result(fd)
      integer(c_int) :: r
      fd = int(c_dup(0_c_int))
      if (fd >= 0) r = c_close(int(fd, c_int))
   end function lowest_free_fd

   subroutine halting(h)
      logical, intent(out) :: h(3)
      call ieee_get_halting_mode(ieee_overflow, h(1))
      call ieee_get_halting_mode(ieee_invalid, h(2))
      call ieee_get_halting_mode(ieee_divide_by_zero, h(3))
   end subroutine halting
end program dynx_fuzz
