!> When to write restart dumps and when to stop, called once per cycle at the cycle
!> boundary (the state a dump holds, see dx_restart):
!>  - *DATABASE_BINARY_RUNRSF every CYCL cycles: runrsf.h5 (NR > 1: runrsf01..NR.h5 in
!>    rotation), *DATABASE_BINARY_D3DUMP every CYCL cycles: d3dump01.h5, d3dump02.h5, ...
!>  - SIGUSR1: a d3dump now, and go on; SIGTERM/SIGINT: a d3dump, the last plot state,
!>    stop (exit code 5, EXIT_CHECKPOINT) with the command that continues the run;
!>  - the wall-clock limit (--walltime, or SLURM_JOB_END_TIME): stop like SIGTERM when the
!>    time left is below the safety margin 3*(time per cycle) + 2*(dump + plot-state cost),
!>    both measured as the run goes (the first dump cost is estimated from its size at
!>    100 MB/s plus 50 ms);
!>  - *CONTROL_TERMINATION ENDENG: the energy ratio left the band 1 +- ENDENG/100 (flagged
!>    by the solver), stop like SIGTERM but with exit code 3 (numerical failure).
!> A numerical failure in the middle of a cycle writes a d3dump marked as not restartable.
!> MPI runs (dx_par_restart): a signal may reach one rank or all, and each rank has its own
!> clock, so the decision is collective: each rank's requests (stop signal, SIGUSR1, its
!> wall-clock limit) ride in the cycle's dt reduction (checkpoint_par_dt: MINLOC plus the
!> largest flag, one MPI_Allreduce, no extra synchronization) and every rank acts on the
!> reduced flags at the same cycle boundary; dumps are per-rank parts plus a manifest.
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
   use dx_restart, only: restart_write
   use dx_par, only: par_rank, par_size, par_allreduce, PAR_MAX
   use dx_par_engine, only: par_engine_on, par_engine_dt, par_engine_flush_work, &
                            par_engine_plot, par_engine_plot_finish, par_engine_writer, &
                            par_engine_fail
   use dx_par_restart, only: par_restart_write
   use dx_par_plot, only: par_plot_nstates
   use dx_par_loads, only: par_loads_flush
   use dx_signals, only: signal_stop_requested, signal_dump_requested, signal_name, &
                         signal_raise
   implicit none
   private
   public :: checkpoint_t, checkpoint_stage, checkpoint_failure_dump, checkpoint_energy_band, &
             checkpoint_par_dt, checkpoint_requests

   type :: checkpoint_t
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
      integer :: raise_rank = -1                !< MPI: only this rank raises (-1: every rank)
      integer :: coll(3) = 0                    !< MPI: stop signal, SIGUSR1, wall-clock limit
                                                !< of any rank (from checkpoint_par_dt)
      logical :: replicated = .false.           !< MPI, conserving solver: every rank has the
                                                !< whole state; rank 0 writes (dx_par_emc)
      logical :: endeng_hit = .false.           !< set by the solver ...
      real(wp) :: endeng_ratio = 1.0_wp         !< ... with the ratio, cycle and time
      integer :: endeng_cycle = 0
      real(wp) :: endeng_time = 0.0_wp
   end type checkpoint_t

contains

   !> The per-cycle stage: periodic dumps, SIGUSR1, stop requests. stopped: the run must
   !> end now; error then carries the exit code and the message (with how to continue).
   subroutine checkpoint_stage(ck, model, out, stopped, error)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(inout), target :: model
      type(output_t), intent(inout) :: out
      logical, intent(out) :: stopped
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: now, margin, est
      integer :: sig, nr
      character(:), allocatable :: path, why, comb
      logical :: par, dumpreq, writer, coll
      type(model_t), pointer :: om

      stopped = .false.
      par = par_engine_on()
      coll = par .or. ck%replicated     ! act on the reduced requests of every rank
      if (par .and. ck%dump_est < 0.0_wp) ck%dump_est = estimated_dump_cost(model)
      if (.not. ck%replicated .and. ck%raise_cycle > 0 .and. model%cycle == ck%raise_cycle .and. &
          (ck%raise_rank < 0 .or. ck%raise_rank == par_rank())) call signal_raise(ck%raise_sig)
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
            call write_dump(ck, model, out, path, 'runrsf', error)
            if (allocated(error)) then
               stopped = .true.; return
            end if
         end if
      end if
      if (model%rst%d3dump_cycl > 0) then
         if (mod(model%cycle, model%rst%d3dump_cycl) == 0) then
            call next_d3dump(ck, model, path)
            call write_dump(ck, model, out, path, 'd3dump', error)
            if (allocated(error)) then
               stopped = .true.; return
            end if
         end if
      end if
      if (coll) then             ! the requests of every rank, reduced with this cycle's dt
         dumpreq = ck%coll(2) /= 0
         ck%coll(2) = 0
      else
         dumpreq = signal_dump_requested()
      end if
      if (dumpreq) then
         call next_d3dump(ck, model, path)
         call write_dump(ck, model, out, path, 'signal', error)
         if (allocated(error)) then
            stopped = .true.; return
         end if
         call log_info('dynx: SIGUSR1: restart dump '//path//' written at cycle '// &
                       str(model%cycle)//', time '//rstr(model%time)//'; going on')
         call log_flush()
      end if
      ! ---- stop requests
      sig = signal_stop_requested()
      if (coll) sig = ck%coll(1)
      why = ''
      if (sig /= 0) then
         why = signal_name(sig)
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
      call write_dump(ck, model, out, path, 'signal', error)
      if (allocated(error)) return
      om => model
      writer = .true.
      if (par) then      ! MPI: each rank its part of the last state; rank 0 combines
         writer = par_engine_writer()
         call par_engine_plot(model, error)
         if (allocated(error)) call par_engine_fail(error)   ! this rank alone: stop all
      else
         writer = .not. ck%replicated .or. par_rank() == 0
         if (writer) call out%write_plot(om, error)
         if (allocated(error)) return
      end if
      if (writer) call out%close(error)
      if (allocated(error)) then
         if (par) call par_engine_fail(error)
         return
      end if
      if (par) then      ! ENDENG: every rank formed the same ratio, so all stop together
         call par_engine_plot_finish(error, failure=why == 'ENDENG')
         if (allocated(error)) call par_engine_fail(error)
         comb = ' (the '//str(par_size())//' ranks'' plot files combined into '// &
                ck%outdir//'/d3plot.h5 + d3plot.xdmf: '//str(par_plot_nstates())//' states)'
      end if
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
            launcher(coll)//'dynx -i '//ck%deck//' -o '//ck%outdir//' -r '//path, &
            EXIT_CHECKPOINT)
      end if
   end subroutine checkpoint_stage

   !> MPI runs, in place of par_engine_dt: this rank's stop signal, SIGUSR1 and wall-clock
   !> limit folded into the cycle's dt reduction; ck%coll gets the largest over the ranks,
   !> which checkpoint_stage acts on at the end of the cycle (the same cycle on every rank).
   subroutine checkpoint_par_dt(ck, dtcrit, dt_elem, error)
      type(checkpoint_t), intent(inout) :: ck
      real(wp), intent(inout) :: dtcrit
      integer, intent(inout) :: dt_elem
      type(error_t), allocatable, intent(inout) :: error
      integer :: flags(3)
      real(wp) :: est, now
      flags = 0
      flags(1) = signal_stop_requested()
      if (signal_dump_requested()) flags(2) = 1
      if (ck%walltime > 0.0_wp) then
         now = wall_time()
         est = ck%dump_cost
         if (est < 0.0_wp) est = max(ck%dump_est, 0.05_wp)
         if (now - ck%wall0 + 3.0_wp*ck%cycle_cost + 2.0_wp*est >= ck%walltime) flags(3) = 1
      end if
      flags(2) = max(flags(2), ck%coll(2))       ! a request not yet served stays
      call par_engine_dt(dtcrit, dt_elem, error, flags)
      ck%coll = flags
   end subroutine checkpoint_par_dt

   !> MPI runs of the conserving solver (ck%replicated), once per step before the
   !> checkpoint: --raise-at-cycle, then this rank's stop signal, SIGUSR1 and wall-clock
   !> limit, reduced (MAX) over the ranks into ck%coll, which checkpoint_stage acts on at the
   !> same step on every rank. No-op otherwise.
   subroutine checkpoint_requests(ck, model)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(in) :: model
      integer :: flags(3)
      real(wp) :: est, now
      if (.not. ck%replicated) return
      if (ck%raise_cycle > 0 .and. model%cycle == ck%raise_cycle .and. &
          (ck%raise_rank < 0 .or. ck%raise_rank == par_rank())) call signal_raise(ck%raise_sig)
      flags = 0
      flags(1) = signal_stop_requested()
      if (signal_dump_requested()) flags(2) = 1
      if (ck%walltime > 0.0_wp) then
         now = wall_time()
         est = ck%dump_cost
         if (est < 0.0_wp) est = estimated_dump_cost(model)
         if (now - ck%wall0 + 3.0_wp*ck%cycle_cost + 2.0_wp*est >= ck%walltime) flags(3) = 1
      end if
      flags(2) = max(flags(2), ck%coll(2))       ! a request not yet served stays
      call par_allreduce(flags, PAR_MAX)
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
   subroutine checkpoint_failure_dump(ck, model, out, path)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      character(:), allocatable, intent(out) :: path
      type(error_t), allocatable :: e
      if (.not. allocated(ck%outdir)) then
         path = ''; return
      end if
      call next_d3dump(ck, model, path)
      call write_dump(ck, model, out, path, 'failure', e)
      if (allocated(e)) path = ''
   end subroutine checkpoint_failure_dump

   subroutine next_d3dump(ck, model, path)
      type(checkpoint_t), intent(in) :: ck
      type(model_t), intent(inout) :: model
      character(:), allocatable, intent(out) :: path
      model%run%ndump = model%run%ndump + 1
      path = ck%outdir//'/d3dump'//two(model%run%ndump)//'.h5'
   end subroutine next_d3dump

   !> Record the output sizes in the loop state and write the dump, timing it.
   subroutine write_dump(ck, model, out, path, kind, error)
      type(checkpoint_t), intent(inout) :: ck
      type(model_t), intent(inout) :: model
      type(output_t), intent(in) :: out
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = wall_time()
      call out%sizes(model%run%nplot, model%run%glstat_bytes, model%run%nodout_bytes)
      if (par_engine_on()) then   ! every rank its part, rank 0 the manifest (rank 0's sizes)
         model%run%nplot = par_plot_nstates()   ! the states in each rank's plot part
         call par_engine_flush_work(model%run%wcon, model%run%wrw)
         call par_loads_flush(model%run%wext)   ! kept external-work terms (dx_par_loads)
         call par_restart_write(model, path, kind, error)
      else if (.not. ck%replicated .or. par_rank() == 0) then   ! replicated: rank 0 writes
         call restart_write(model, path, kind, error)
      end if
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

   !> 'mpirun -np N ' in an MPI run (the continue command needs the same N), else ''.
   function launcher(par) result(s)
      logical, intent(in) :: par
      character(:), allocatable :: s
      s = ''
      if (par) s = 'mpirun -np '//str(par_size())//' '
   end function launcher

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
