!> The integrator choice (make_integrator) and the one run driver (run_driver) that steps any
!> integrator_t (dx_integrator) to the end: plot states and histories (glstat, nodout, rbdout)
!> on model%run's grid, status lines, dynx's energy guard (issue 15), restart dumps, signals
!> and the wall-clock limit (dx_checkpoint) at each cycle boundary, and the end.
!> Which integrator runs (docs/design.md): *DYNX_CONSERVING_CONTACT (with
!> *CONTROL_IMPLICIT_GENERAL IMFLAG = 1) the conserving rigid-body solver (dx_emc_solver),
!> IMFLAG = 1 without it the implicit Newton solver (dx_implicit) or, with
!> *CONTROL_IMPLICIT_EIGENVALUE, the eigenvalue run (dx_eigen), else the explicit
!> central-difference loop (dx_explicit). IMFLAG = 2 is refused when the deck is read (exit 2).
module dx_solver
   use dx_kinds, only: wp, huge_wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_warn, log_flush
   use dx_timer, only: wall_time
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_checkpoint, only: checkpoint_t, checkpoint_stage, checkpoint_failure_dump
   use dx_domain, only: domain_t
   use dx_integrator, only: integrator_t, run_options_t, energy_guard_t, END_NORMAL, &
                            END_FAILED, END_STOPPED
   use dx_explicit, only: explicit_t, elem_label, explicit_rbdout
   use dx_emc_run, only: conserving_t
   use dx_implicit, only: implicit_t
   use dx_eigen, only: eigen_t
   implicit none
   private
   public :: make_integrator, integrator_choice, run_driver

   !> The status line before, for eta_left: wall time since this run started, cycle, time,
   !> and the mean step of the interval that ended there with its mid time (0: none yet).
   type :: eta_t
      real(wp) :: el = 0.0_wp
      integer :: cycle = 0
      real(wp) :: t = 0.0_wp, dtm = 0.0_wp, tm = 0.0_wp
   end type eta_t

contains

   !> The integrator the deck asks for, and why (one line for --check and the log).
   subroutine integrator_choice(model, name, why)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: name, why
      if (allocated(model%emc)) then
         name = 'conserving rigid-body (Simo & Wong midpoint rule)'
         why = '*DYNX_CONSERVING_CONTACT with *CONTROL_IMPLICIT_GENERAL IMFLAG = 1'
      else if (model%ctrl%imp%imflag == 1 .and. model%ctrl%imp%neig > 0) then
         name = 'implicit eigenvalues (shift-invert Lanczos: ARPACK with MUMPS)'
         why = '*CONTROL_IMPLICIT_EIGENVALUE NEIG = '//str(model%ctrl%imp%neig)// &
               ' with *CONTROL_IMPLICIT_GENERAL IMFLAG = 1'
      else if (model%ctrl%imp%imflag == 1) then
         name = 'implicit Newton statics (NIKE3D: Newton-Raphson, line search, MUMPS)'
         why = '*CONTROL_IMPLICIT_GENERAL IMFLAG = 1 without *DYNX_CONSERVING_CONTACT'
      else if (model%ctrl%imp%imflag == 0 .and. model%ctrl%imp%line > 0) then
         name = 'explicit central difference'
         why = '*CONTROL_IMPLICIT_GENERAL IMFLAG = 0'
      else
         name = 'explicit central difference'
         why = 'no *CONTROL_IMPLICIT_GENERAL'
      end if
   end subroutine integrator_choice

   !> The integrator for the model (integrator_choice).
   subroutine make_integrator(model, integ)
      type(model_t), intent(in) :: model
      class(integrator_t), allocatable, intent(out) :: integ
      if (allocated(model%emc)) then
         allocate(conserving_t :: integ)
      else if (model%ctrl%imp%imflag == 1 .and. model%ctrl%imp%neig > 0) then
         allocate(eigen_t :: integ)
      else if (model%ctrl%imp%imflag == 1) then
         allocate(implicit_t :: integ)
      else
         allocate(explicit_t :: integ)
      end if
      call integrator_choice(model, integ%name, integ%why)
   end subroutine make_integrator

   !> Step integ from its start (or the restored state) to the end, writing the output the
   !> deck asks for. error: a failure (its exit code), or EXIT_CHECKPOINT after a stop.
   subroutine run_driver(integ, model, dom, opts, out, error)
      class(integrator_t), intent(inout) :: integ
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(run_options_t), intent(in) :: opts
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      type(checkpoint_t) :: ck
      type(energy_guard_t) :: guard
      type(error_t), allocatable :: ioerr
      real(wp) :: t0wall, next_status, t_line
      type(eta_t) :: eta, eta_now
      logical :: stopped, writer
      ck = opts%ck
      guard = opts%guard
      call integ%start(model, dom, opts, ck, out, error)
      if (allocated(error)) return
      if (model%cycle > 0) then       ! a restart: the guard's state too (dx_restart)
         guard%warned = model%run%guard(1) /= 0.0_wp
         guard%den_prev = model%run%guard(2)
         guard%r_prev = model%run%guard(3)
      end if
      call log_info('dynx: integrator: '//integ%name//' ('//integ%why//')')
      if (.not. integ%histories .and. max(model%db%matsum_dt, model%db%spcforc_dt, &
                                          model%db%sleout_dt, model%db%elout_dt, &
                                          model%db%ncforc_dt) > 0.0_wp) &
         call log_info('dynx: note: matsum, spcforc, sleout, elout and ncforc are not written '// &
                       'by this '// &
                       'integrator (it writes its own emcstat); their files hold the header only')
      if (integ%energies) call guard_bounds(guard)
      t0wall = wall_time()
      eta = eta_t(0.0_wp, model%cycle, model%time, 0.0_wp, 0.0_wp)   ! this run's start
      writer = dom%writer()
      next_status = model%run%next_status
      t_line = -huge_wp
      call log_info('      cycle        time          dt  dt-element   wall [s]   left [s]'// &
                    '  energy ratio')
      do
         call integ%step(model, dom, ck, out, error)
         if (allocated(error)) then
            call integ%close(model, dom, ck, out, END_FAILED, error); return
         end if
         if (integ%histories) then
            call histories(model, dom, out, opts%outdir, integ%t, integ%done, ioerr)
            if (allocated(ioerr)) then
               call move_alloc(ioerr, error)
               call dom%fail(error)   ! MPI: a rank alone: stop every rank
               call integ%close(model, dom, ck, out, END_FAILED, error); return
            end if
         end if
         ! ---- the energy guard, after this cycle's glstat record (MPI: every rank has the
         ! summed ratio and stops with the others)
         if (integ%energies) call guard_check(guard, model, integ%t, error)
         model%run%guard = [merge(1.0_wp, 0.0_wp, guard%warned), guard%den_prev, guard%r_prev]
         if (allocated(error)) then
            call integ%close(model, dom, ck, out, END_FAILED, error); return
         end if
         if ((integ%t >= next_status .or. integ%done) .and. writer .and. &
             integ%t /= t_line) then   ! (a conserving run's last call only notes the end)
            call status_line(model, integ, t0wall, eta)
            t_line = integ%t
            if (integ%tend < huge_wp) then
               next_status = next_status + integ%tend/real(max(1, opts%nstatus), wp)
            else
               next_status = huge_wp
            end if
         end if
         if (integ%histories) model%run%next_status = next_status
         if (integ%done .and. integ%histories) then   ! MPI: a failure kept in the last cycle
            call dom%sync_failure(error)
            if (allocated(error)) then
               call integ%close(model, dom, ck, out, END_FAILED, error); return
            end if
         end if
         if (integ%done) exit
         call integ%advance(model, ck)
         ! ---- cycle boundary: restart dumps, signals, wall-clock limit, ENDENG
         call checkpoint_stage(ck, dom, model, out, stopped, error)
         if (stopped) then
            call integ%close(model, dom, ck, out, END_STOPPED, error); return
         end if
         if (ck%ctl_status .and. writer) then   ! dynx.ctl 'status': a line now (on a copy
            eta_now = eta                       ! of the interval, so the regular lines'
            call status_line(model, integ, t0wall, eta_now, model%time)   ! estimates stay)
         end if
      end do
      call integ%close(model, dom, ck, out, END_NORMAL, error)
   end subroutine run_driver

   !> Plot states, glstat, nodout and rbdout at t(n) on model%run's grid (MPI runs: plot
   !> states per rank; histories by rank 0).
   subroutine histories(model, dom, out, outdir, t, done, error)
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(output_t), intent(inout) :: out
      character(*), intent(in) :: outdir
      real(wp), intent(in) :: t
      logical, intent(in) :: done
      type(error_t), allocatable, intent(out) :: error
      type(model_t), pointer :: om          ! the model output is written from
      logical :: writer
      om => model
      writer = dom%writer()
      if (t >= model%run%next_plot .or. done) then
         call dom%write_plot(model, out, error)
         if (allocated(error)) return
         if (model%db%d3plot_dt > 0.0_wp) then
            model%run%next_plot = next_output_time(model%run%next_plot, model%db%d3plot_dt, t)
         else
            model%run%next_plot = huge_wp
         end if
      end if
      call history_file(1)
      if (allocated(error)) return
      call history_file(2)
      if (allocated(error)) return
      call history_file(3)
      if (allocated(error)) return
      call history_file(4)
      if (allocated(error)) return
      call history_file(5)
      if (allocated(error)) return
      call history_file(6)
      if (allocated(error)) return
      call history_file(7)
      if (allocated(error)) return
      if (allocated(model%rigid)) then
         if (model%rigid%rbdout_dt > 0.0_wp .and. &
             (t >= model%rigid%next_rbdout .or. done)) then
            call explicit_rbdout(model, dom, outdir, t, error)   ! MPI: rank 0 writes rbdout
            if (allocated(error)) return
            model%rigid%next_rbdout = next_output_time(model%rigid%next_rbdout, &
                                                       model%rigid%rbdout_dt, t)
         end if
      end if
   contains
      !> glstat (kind 1), nodout (2), matsum (3), spcforc (4), sleout (5), elout (6) or
      !> ncforc (7) when
      !> due (MPI: the global model gathered to rank 0; matsum's part sums are formed there,
      !> elout's element values gathered there)
      subroutine history_file(kind)
         integer, intent(in) :: kind
         real(wp) :: interval, next
         select case (kind)
         case (1)
            interval = model%db%glstat_dt; next = model%run%next_glstat
         case (2)
            interval = model%db%nodout_dt; next = model%run%next_nodout
         case (3)
            interval = model%db%matsum_dt; next = model%run%next_matsum
         case (4)
            interval = model%db%spcforc_dt; next = model%run%next_spcforc
         case (5)
            interval = model%db%sleout_dt; next = model%run%next_sleout
         case (6)
            interval = model%db%elout_dt; next = model%run%next_elout
         case default
            interval = model%db%ncforc_dt; next = model%run%next_ncforc
         end select
         if (.not. (interval > 0.0_wp .and. (t >= next .or. done))) return
         call dom%output_model(model, om, writer, kind)
         if (kind == 6) call dom%element_output(model, om)
         if (writer .and. kind == 1) call out%write_glstat(om, error)
         if (writer .and. kind == 2) call out%write_nodout(om, error)
         if (writer .and. kind == 3) call out%write_matsum(om, error)
         if (writer .and. kind == 4) call out%write_spcforc(om, error)
         if (writer .and. kind == 5) call out%write_sleout(om, error)
         if (writer .and. kind == 6) call out%write_elout(om, error)
         if (writer .and. kind == 7) call out%write_ncforc(om, error)
         if (allocated(error)) return
         next = next_output_time(next, interval, t)
         select case (kind)
         case (1)
            model%run%next_glstat = next
         case (2)
            model%run%next_nodout = next
         case (3)
            model%run%next_matsum = next
         case (4)
            model%run%next_spcforc = next
         case (5)
            model%run%next_sleout = next
         case (6)
            model%run%next_elout = next
         case default
            model%run%next_ncforc = next
         end select
      end subroutine history_file
   end subroutine histories

   !> The wall time left, from the recent cycle rate and the time-step trend. Over the
   !> interval since the status line before (or since the start of this run: a restart counts
   !> from its own start, not from time 0): w = wall time per cycle and dtm = the mean step
   !> (time advanced / cycles), at the interval's mid time tm. The trend s = d(dtm)/dt is the
   !> slope between this interval's dtm and the previous one's (0 on the first interval of a
   !> run). The step is taken on that line from now to the end, floored at half its value:
   !>    d0 = max(dtm + s (t - tm), dtm/2),  d1 = max(d0 + s (tend - t), d0/2)
   !> so the cycles left are N = (tend - t) ln(d1/d0)/(d1 - d0) ((tend - t)/d0 when d1 = d0;
   !> the integral of dtau/dt(tau) for a step linear in time) and the time left N w. The
   !> floor: a trend seen over one interval is not carried into a step that falls to zero;
   !> measured on the Taylor bar and the steady bar in docs/toolbox.md. Mean steps, not the
   !> step at the line, so one small element's momentary step does not turn into a trend.
   !> The estimate before this one, elapsed wall times (tend - t)/t, assumed a constant step
   !> and a run started at time 0 (3 times too optimistic while dt fell, 15 times off after
   !> a restart: issue 21). 0 until this run has done a cycle.
   function eta_left(eta, el, cycle, t, tend) result(left)
      type(eta_t), intent(inout) :: eta
      real(wp), intent(in) :: el, t, tend
      integer, intent(in) :: cycle
      real(wp) :: left, w, s, d0, d1, rest, ncyc, dtm, tm
      left = 0.0_wp
      if (cycle <= eta%cycle .or. .not. (t > eta%t)) return
      rest = max(tend - t, 0.0_wp)
      w = (el - eta%el)/real(cycle - eta%cycle, wp)
      dtm = (t - eta%t)/real(cycle - eta%cycle, wp)
      tm = 0.5_wp*(t + eta%t)
      s = 0.0_wp
      if (eta%dtm > 0.0_wp .and. tm > eta%tm) s = (dtm - eta%dtm)/(tm - eta%tm)
      if (tend < huge(tend)) then
         d0 = max(dtm + s*(t - tm), 0.5_wp*dtm)
         d1 = max(d0 + s*rest, 0.5_wp*d0)
         if (abs(d1 - d0) > 1.0e-9_wp*d0) then
            ncyc = rest*log(d1/d0)/(d1 - d0)
         else
            ncyc = rest/d0
         end if
         left = max(ncyc*w, 0.0_wp)
      end if
      eta%el = el
      eta%cycle = cycle
      eta%t = t
      eta%dtm = dtm
      eta%tm = tm
   end function eta_left

   !> The first output time on the grid next + k*interval (k >= 1) that lies after t.
   pure real(wp) function next_output_time(next, interval, t) result(tn)
      real(wp), intent(in) :: next, interval, t
      tn = next + interval*real(max(1, ceiling((t - next)/interval + 1.0e-9_wp)), wp)
   end function next_output_time

   !> One status line: cycle, time, dt, the element setting dt, the wall time of this run
   !> (since its start or restart) and the estimated wall time left (eta_left).
   !> tnow: the time at a cycle boundary (dynx.ctl 'status'; default integ%t).
   subroutine status_line(model, integ, t0wall, eta, tnow)
      type(model_t), intent(in) :: model
      class(integrator_t), intent(in) :: integ
      real(wp), intent(in) :: t0wall
      type(eta_t), intent(inout) :: eta
      real(wp), intent(in), optional :: tnow
      character(120) :: line
      real(wp) :: el, left, t
      t = integ%t
      if (present(tnow)) t = tnow
      el = wall_time() - t0wall
      left = eta_left(eta, el, model%cycle, t, integ%tend)
      write(line, '(i11,2es12.4,i12,2f11.2)') model%cycle, t, integ%dt, &
         elem_label(model), el, left
      if (integ%energies) write(line(71:), '(f14.6)') model%energy%ratio
      call log_info(trim(line))
      call log_flush()
   end subroutine status_line

   !> The guard's bounds in force, in the log at the start.
   subroutine guard_bounds(guard)
      type(energy_guard_t), intent(in) :: guard
      if (guard%on) then
         call log_info('dynx: energy guard: warning when the energy ratio leaves 1 +- '// &
            rstr(guard%warn, 4)//', stop (exit 3) outside 1 +- '//rstr(guard%stop - 1.0_wp, 4)// &
            ' (--energy-guard WARN,STOP or off)')
      else
         call log_info('dynx: energy guard off (--energy-guard off)')
      end if
   end subroutine guard_bounds

   !> dynx's energy guard on the ratio (total energy)/(initial energy + external work) of
   !> this cycle, glstat's. The ratio lags the energy put in by about a cycle (the kinetic
   !> energy is time-centred, the work is booked at t(n)): a cycle whose external work
   !> changes the denominator by more than 1 % (a load ramping up from rest: ratio 0 at
   !> cycle 0) is not judged. MPI runs: the ratio is summed at the cycles that write glstat,
   !> ENDENG and the end; the cycles between repeat it (not judged again).
   subroutine guard_check(guard, model, t, error)
      type(energy_guard_t), intent(inout) :: guard
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: r, den
      logical :: steady
      if (.not. guard%on) return
      r = model%energy%ratio
      den = model%energy%initial + model%energy%external_work
      if (r == guard%r_prev .and. den == guard%den_prev) return   ! nothing new
      steady = abs(den - guard%den_prev) <= 0.01_wp*abs(den)
      guard%den_prev = den
      guard%r_prev = r
      if (.not. steady) return
      if (abs(r - 1.0_wp) > guard%stop - 1.0_wp) then
         call set_error(error, 'energy ratio '//rstr(r, 6)//' at cycle '//str(model%cycle)// &
            ', time '//rstr(t)//' is outside 1 +- '//rstr(guard%stop - 1.0_wp, 4)// &
            ' (energy guard: the run blew up; --energy-guard WARN,STOP or off)', EXIT_NUMERIC)
      else if (.not. guard%warned .and. abs(r - 1.0_wp) > guard%warn) then
         guard%warned = .true.
         call log_warn('energy ratio '//rstr(r, 6)//' at cycle '//str(model%cycle)// &
            ', time '//rstr(t)//' left 1 +- '//rstr(guard%warn, 4)//' (energy guard; '// &
            'further departures are not reported)')
      end if
   end subroutine guard_check
end module dx_solver
