!> When to write restart dumps and when to stop, called once per cycle at the cycle
!> boundary (the state a dump holds, see dx_restart):
!>  - *DATABASE_BINARY_RUNRSF every CYCL cycles: runrsf.h5 (NR > 1: runrsf01..NR.h5 in
!>    rotation), *DATABASE_BINARY_D3DUMP every CYCL cycles: d3dump01.h5, d3dump02.h5, ...
!>  - SIGUSR1: a d3dump now, and go on; SIGTERM/SIGINT/SIGUSR2: a d3dump, the last plot state,
!>    stop (exit code 5, EXIT_CHECKPOINT) with the command that continues the run;
!>  - the wall-clock limit (--walltime, or SLURM_JOB_END_TIME): stop like SIGTERM when the
!>    time left is below the safety margin 3*(time per cycle) + 2*(dump + plot-state cost),
!>    both measured as the run goes (the first dump cost is estimated from its size at
!>    100 MB/s plus 50 ms);
!>  - *CONTROL_TERMINATION ENDENG: the energy ratio left the band 1 +- ENDENG/100 (flagged
!>    by the solver), stop like SIGTERM but with exit code 3 (numerical failure).
!>  - the run-time switches of OUT/dynx.ctl (dx_run_control: status, plot, dump, stop),
!>    polled at the first cycle and then once per wall-clock second (ctl_every) by the
!>    serial run or MPI rank 0 alone; rank 0's request rides in the dt reduction (flag 4,
!>    MAX: the other ranks send 0), so every rank acts on it at the same cycle boundary.
!>    A plot state, a dump or a status line changes no result (bitwise).
!> A numerical failure in the middle of a cycle writes a d3dump marked as not restartable.
!> MPI runs (dx_par_restart): a signal may reach one rank or all, and each rank has its own
!> clock, so the decision is collective: each rank's requests (stop signal, SIGUSR1 count, its
!> wall-clock limit) ride in the cycle's dt reduction (the domain's reduce_dt calls poll:
!> MINLOC plus the largest flag, one MPI_Allreduce, no extra synchronization) and every rank
!> acts on the reduced flags at the same cycle boundary; dumps and the last plot state are
!> the domain's (MPI: per-rank parts plus a manifest).
!> MPI runs of the conserving solver (ck%replicated: every rank holds the whole state): the
!> requests are reduced once per step (checkpoint_requests, one MPI_Allreduce of 3 flags) and
!> rank 0 writes the serial dump and the last plot state.
module dx_checkpoint
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_CHECKPOINT, EXIT_NUMERIC
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_flush
   use dx_timer, only: wall_time
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_domain, only: domain_t, requests_t
   use dx_run_control, only: ctl_read, ctl_has, ctl_words, CTL_STATUS, CTL_PLOT, CTL_DUMP, &
                             CTL_STOP
   use dx_signals, only: signal_stop_requested, signal_dump_requested, signal_name, &
                         signal_raise, signal_dump_count, signal_dump_served, signal_dump_serve
   implicit none
   private
   public :: checkpoint_t, checkpoint_stage, checkpoint_failure_dump, checkpoint_energy_band, &
             checkpoint_requests

   !> Restart dumps, signals and the wall-clock limit of a run; the requests of every rank
   !> (MPI: reduced with the cycle's dt, requests_t%coll) are acted on together.
   type, extends(requests_t) :: checkpoint_t
      character(:), allocatable :: outdir       !< where dumps go (the output directory)
      character(:), allocatable :: deck         !< for the "continue with" message
      real(wp) :: walltime = 0.0_wp             !< seconds allowed from wall0 (0: no limit)
      real(wp) :: wall0 = 0.0_wp                !< wall_time() at the start of the run
      real(wp) :: last = -1.0_wp                !< wall_time() at the previous call
      real(wp) :: cycle_cost = 0.0_wp           !< smoothed seconds per cycle
      real(wp) :: dump_cost = -1.0_wp           !< seconds of the costliest dump (-1: none yet)
      real(wp) :: dump_est = -1.0_wp            !< MPI: estimated_dump_cost of the rank's model
      integer :: raise_cycle = 0                !< testing: raise raise_sig at this cycle
      integer :: raise_sig = 0                  !< (--raise-at-cycle N:SIG, real handler path)
      logical :: raise_here = .true.            !< MPI: this rank raises (--raise-at-cycle @R)
      logical :: replicated = .false.           !< MPI, conserving solver: every rank has the
                                                !< whole state; rank 0 writes (dx_par_emc)
      logical :: endeng_hit = .false.           !< set by the solver ...
      real(wp) :: endeng_ratio = 1.0_wp         !< ... with the ratio, cycle and time
      integer :: endeng_cycle = 0
      real(wp) :: endeng_time = 0.0_wp
      logical :: ctl_here = .true.              !< this rank reads OUT/dynx.ctl (MPI: rank 0)
      real(wp) :: ctl_every = 1.0_wp            !< wall seconds between two reads of it
      real(wp) :: ctl_last = -1.0_wp            !< wall_time() at the last read (-1: none)
      logical :: ctl_off = .false.              !< a control file that could not be removed
      logical :: ctl_status = .false.           !< dynx.ctl asked for a status line: the
                                                !< run driver prints it after this stage
   contains
      procedure :: poll => checkpoint_poll
   end type checkpoint_t

contains

   !> The per-cycle stage: periodic dumps, SIGUSR1, stop requests. stopped: the run must
   !> end now; error then carries the exit code and the message (with how to continue).
   subroutine checkpoint_stage(ck, dom, model, out, stopped, error)
      type(checkpoint_t), intent(inout) :: ck
      class(domain_t), intent(inout) :: dom
      type(model_t), intent(inout), target :: model
      type(output_t), intent(inout) :: out
      logical, intent(out) :: stopped
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: now, margin, est
      integer :: sig, nr, req
      character(:), allocatable :: path, why, comb
      logical :: dumpreq, writer, coll

      stopped = .false.
      coll = ck%collective .or. ck%replicated     ! act on the reduced requests of every rank
      if (ck%collective .and. ck%dump_est < 0.0_wp) ck%dump_est = estimated_dump_cost(model)
      if (.not. ck%replicated .and. ck%raise_cycle > 0 .and. model%cycle == ck%raise_cycle &
          .and. ck%raise_here) call signal_raise(ck%raise_sig)
      now = wall_time()
      if (ck%last >= 0.0_wp) then
         if (ck%cycle_cost == 0.0_wp) then
            ck%cycle_cost = now - ck%last
         else
            ck%cycle_cost = 0.9_wp*ck%cycle_cost + 0.1_wp*(now - ck%last)
         end if
      end if
      ck%last = now
      ! ---- periodic dumps
      if (model%rst%runrsf_cycl > 0) then
         if (mod(model%cycle, model%rst%runrsf_cycl) == 0) then
            nr = max(1, model%rst%runrsf_nr)
            model%run%nrunrsf = model%run%nrunrsf + 1
            if (nr == 1) then
               path = ck%outdir//'/runrsf.h5'
            else
               path = ck%outdir//'/runrsf'//two(mod(model%run%nrunrsf - 1, nr) + 1)//'.h5'
            end if
            call write_dump(ck, dom, model, out, path, 'runrsf', error)
            if (allocated(error)) then
               stopped = .true.; return
            end if
         end if
      end if
      if (model%rst%d3dump_cycl > 0) then
         if (mod(model%cycle, model%rst%d3dump_cycl) == 0) then
            call next_d3dump(ck, model, path)
            call write_dump(ck, dom, model, out, path, 'd3dump', error)
            if (allocated(error)) then
               stopped = .true.; return
            end if
         end if
      end if
      if (coll) then             ! the requests of every rank, reduced with this cycle's dt
         ! coll(2): the largest SIGUSR1 count of any rank; one signal forwarded to every
         ! rank (arriving in different cycles) raises it once, so it is one dump
         dumpreq = ck%coll(2) > signal_dump_served()
         if (dumpreq) call signal_dump_serve(ck%coll(2))
         ck%coll(2) = 0
         req = ck%coll(4)        ! rank 0's dynx.ctl, the same on every rank
         ck%coll(4) = 0
      else
         dumpreq = signal_dump_requested()
         req = ctl_poll(ck)
      end if
      if (req /= 0) call log_info('dynx: '//ck%outdir//'/dynx.ctl: '//ctl_words(req)// &
                                  ' at cycle '//str(model%cycle)//', time '//rstr(model%time))
      ck%ctl_status = ctl_has(req, CTL_STATUS)
      if (dumpreq .or. ctl_has(req, CTL_DUMP)) then
         call next_d3dump(ck, model, path)
         call write_dump(ck, dom, model, out, path, 'signal', error)
         if (allocated(error)) then
            stopped = .true.; return
         end if
         call log_info('dynx: '//trim(merge('SIGUSR1 ', 'dynx.ctl', dumpreq))//': restart dump '// &
            path//' written at cycle '//str(model%cycle)//', time '//rstr(model%time)// &
            '; going on')
         call log_flush()
      end if
      if (ctl_has(req, CTL_PLOT) .and. .not. ctl_has(req, CTL_STOP)) then
         call dom%write_plot(model, out, error)      ! every rank its part (MPI)
         if (allocated(error)) then
            call dom%fail(error)
            stopped = .true.; return
         end if
         call log_info('dynx: dynx.ctl: plot state written at cycle '//str(model%cycle)// &
                       ', time '//rstr(model%time))
         call log_flush()
      end if
      ! ---- stop requests
      sig = signal_stop_requested()
      if (coll) sig = ck%coll(1)
      why = ''
      if (sig /= 0) then
         why = signal_name(sig)
      else if (ctl_has(req, CTL_STOP)) then
         why = 'stop in '//ck%outdir//'/dynx.ctl'
      else if (ck%endeng_hit) then
         why = 'ENDENG'
      else if (coll) then
         if (ck%coll(3) /= 0) why = 'the wall-clock limit ('//rstr(ck%walltime, 4)// &
                                    ' s, on at least one rank)'
      else if (ck%walltime > 0.0_wp) then
         est = ck%dump_cost
         if (est < 0.0_wp) est = estimated_dump_cost(model)
         margin = 3.0_wp*ck%cycle_cost + 2.0_wp*est
         if (now - ck%wall0 + margin >= ck%walltime) why = 'the wall-clock limit ('// &
            rstr(ck%walltime, 4)//' s, safety margin '//rstr(margin, 3)//' s)'
      end if
      if (len(why) == 0) return
      stopped = .true.
      comb = ''
      call next_d3dump(ck, model, path)
      call write_dump(ck, dom, model, out, path, 'signal', error)
      if (allocated(error)) return
      ! the last state (MPI: each rank its part; rank 0 combines the parts)
      writer = dom%writer()
      call dom%write_plot(model, out, error)
      if (allocated(error)) then
         call dom%fail(error)   ! MPI: this rank alone: stop all
         return
      end if
      if (writer) call out%close(error)
      if (allocated(error)) then
         call dom%fail(error)
         return
      end if
      ! ENDENG: every rank formed the same ratio, so all stop together
      call dom%plot_finish(error, why == 'ENDENG')
      if (allocated(error)) call dom%fail(error)
      comb = dom%plot_note(ck%outdir)
      if (why == 'ENDENG') then
         call set_error(error, 'energy ratio '//rstr(ck%endeng_ratio, 8)//' left the '// &
            'band 1 +- ENDENG/100 = '//rstr(model%ctrl%endeng/100.0_wp, 4)// &
            ' (*CONTROL_TERMINATION ENDENG) at cycle '//str(ck%endeng_cycle)//', time '// &
            rstr(ck%endeng_time)//new_line('a')//'dynx: restart dump '//path// &
            ' (cycle '//str(model%cycle)//', time '//rstr(model%time)// &
            ') and the last plot state written'//comb, EXIT_NUMERIC)
      else
         call set_error(error, 'dynx: stopped by '//why//' at cycle '//str(model%cycle)// &
            ', time '//rstr(model%time)//'; restart dump '//path//' and the last plot '// &
            'state written'//comb//', all files closed.'//new_line('a')//'dynx: continue with: '// &
            dom%launcher(ck%outdir)//'dynx -i '//ck%deck//' -o '//ck%outdir//' -r '//path, &
            EXIT_CHECKPOINT)
      end if
   end subroutine checkpoint_stage

   !> MPI runs, called by the domain's dt reduction: this rank's stop signal, SIGUSR1 and
   !> wall-clock limit, folded into the reduction; ck%coll gets the largest over the ranks,
   !> which checkpoint_stage acts on at the end of the cycle (the same cycle on every rank).
   subroutine checkpoint_poll(self, flags)
      class(checkpoint_t), intent(inout) :: self
      integer, intent(out) :: flags(4)
      real(wp) :: est, now
      associate (ck => self)
      flags = 0
      flags(1) = signal_stop_requested()
      flags(4) = ctl_poll(ck)                    ! rank 0 alone; the others send 0
      flags(2) = signal_dump_count()             ! served when the reduced count exceeds
      if (ck%walltime > 0.0_wp) then             ! the count already served
         now = wall_time()
         est = ck%dump_cost
         if (est < 0.0_wp) est = max(ck%dump_est, 0.05_wp)
         if (now - ck%wall0 + 3.0_wp*ck%cycle_cost + 2.0_wp*est >= ck%walltime) flags(3) = 1
      end if
      end associate
   end subroutine checkpoint_poll

   !> MPI runs of the conserving solver (ck%replicated), once per step before the
   !> checkpoint: --raise-at-cycle, then this rank's stop signal, SIGUSR1 and wall-clock
   !> limit, reduced (MAX) over the ranks into ck%coll, which checkpoint_stage acts on at the
   !> same step on every rank. No-op otherwise.
   subroutine checkpoint_requests(ck, model, reduce_max)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(in) :: model
      !> the reduction (MAX over the ranks, in place) the engine provides (dx_par_emc)
      interface
         subroutine reduce_max(flags)
            integer, intent(inout) :: flags(:)
         end subroutine reduce_max
      end interface
      integer :: flags(4)
      real(wp) :: est, now
      if (.not. ck%replicated) return
      if (ck%raise_cycle > 0 .and. model%cycle == ck%raise_cycle .and. ck%raise_here) &
         call signal_raise(ck%raise_sig)
      flags = 0
      flags(1) = signal_stop_requested()
      flags(2) = signal_dump_count()
      flags(4) = ctl_poll(ck)
      if (ck%walltime > 0.0_wp) then
         now = wall_time()
         est = ck%dump_cost
         if (est < 0.0_wp) est = estimated_dump_cost(model)
         if (now - ck%wall0 + 3.0_wp*ck%cycle_cost + 2.0_wp*est >= ck%walltime) flags(3) = 1
      end if
      call reduce_max(flags)
      if (flags(2) <= signal_dump_served()) flags(2) = 0   ! every SIGUSR1 already served
      ck%coll = flags
   end subroutine checkpoint_requests

   !> *CONTROL_TERMINATION ENDENG: note (once) that abs(energy ratio - 1)*100 > ENDENG at
   !> time t of this cycle; checkpoint_stage stops the run at the end of the cycle.
   subroutine checkpoint_energy_band(ck, model, t)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      if (ck%endeng_hit) return
      if (abs(model%energy%ratio - 1.0_wp)*100.0_wp > model%ctrl%endeng) then
         ck%endeng_hit = .true.
         ck%endeng_ratio = model%energy%ratio
         ck%endeng_cycle = model%cycle
         ck%endeng_time = t
      end if
   end subroutine checkpoint_energy_band

   !> After a numerical failure in the middle of a cycle: a dump for inspection (marked not
   !> restartable). Returns its path ('' when it could not be written).
   subroutine checkpoint_failure_dump(ck, dom, model, out, path)
      type(checkpoint_t), intent(inout) :: ck
      class(domain_t), intent(inout) :: dom
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      character(:), allocatable, intent(out) :: path
      type(error_t), allocatable :: e
      if (.not. allocated(ck%outdir)) then
         path = ''; return
      end if
      call next_d3dump(ck, model, path)
      call write_dump(ck, dom, model, out, path, 'failure', e)
      if (allocated(e)) path = ''
   end subroutine checkpoint_failure_dump

   !> The requests of OUT/dynx.ctl when this rank reads it and a read is due (the first call,
   !> then once per ck%ctl_every wall seconds), else 0.
   integer function ctl_poll(ck) result(req)
      class(checkpoint_t), intent(inout) :: ck
      real(wp) :: now
      req = 0
      if (.not. ck%ctl_here .or. ck%ctl_off .or. .not. allocated(ck%outdir)) return
      now = wall_time()
      if (ck%ctl_last >= 0.0_wp .and. now - ck%ctl_last < ck%ctl_every) return
      ck%ctl_last = now
      req = ctl_read(ck%outdir//'/dynx.ctl', ck%ctl_off)
   end function ctl_poll

   subroutine next_d3dump(ck, model, path)
      type(checkpoint_t), intent(in) :: ck
      type(model_t), intent(inout) :: model
      character(:), allocatable, intent(out) :: path
      model%run%ndump = model%run%ndump + 1
      path = ck%outdir//'/d3dump'//two(model%run%ndump)//'.h5'
   end subroutine next_d3dump

   !> Record the output sizes in the loop state and write the dump, timing it.
   subroutine write_dump(ck, dom, model, out, path, kind, error)
      type(checkpoint_t), intent(inout) :: ck
      class(domain_t), intent(inout) :: dom
      type(model_t), intent(inout) :: model
      type(output_t), intent(in) :: out
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = wall_time()
      call out%sizes(model%run%nplot, model%run%glstat_bytes, model%run%nodout_bytes, &
                     model%run%matsum_bytes, model%run%spcforc_bytes, model%run%sleout_bytes, &
                     model%run%elout_bytes, model%run%ncforc_bytes)
      ! MPI: every rank its part, rank 0 the manifest; replicated: rank 0 the serial dump
      call dom%write_dump(model, path, kind, error)
      ck%dump_cost = max(ck%dump_cost, wall_time() - t0)
   end subroutine write_dump

   !> Before any dump was timed: its size (x, v and the element state) at 100 MB/s + 50 ms,
   !> doubled for the plot state written with it.
   real(wp) function estimated_dump_cost(model) result(c)
      type(model_t), intent(in) :: model
      real(wp) :: bytes
      integer :: b
      bytes = 8.0_wp*6.0_wp*real(model%nn, wp)
      do b = 1, size(model%blocks)
         bytes = bytes + 8.0_wp*real(size(model%blocks(b)%sig) + size(model%blocks(b)%hv) + &
                                     6*model%blocks(b)%nel, wp)
      end do
      c = 2.0_wp*(bytes/1.0e8_wp + 0.05_wp)
   end function estimated_dump_cost

   !> Two-digit (or wider) file number: 01, 02, ..., 99, 100.
   function two(k) result(s)
      integer, intent(in) :: k
      character(:), allocatable :: s
      character(12) :: buf
      write(buf, '(i2.2)') k
      if (k > 99) write(buf, '(i0)') k
      s = trim(buf)
   end function two
end module dx_checkpoint
