!> The conserving rigid-body solver (dx_emc_solver; Simo & Wong 1991, IJNME 31:19-52) as an
!> integrator_t for the run driver (dx_solver): one step of size DT0 (*CONTROL_IMPLICIT_GENERAL,
!> model%ctrl%imp) per call, the emcstat lines on its OUTDT grid and the plot states on the
!> d3plot grid (docs/conserving-contact.md), the snapshot a restart dump writes
!> (model%emc%snap, dx_emc_restart) when the cycle boundary may write one. Restart dumps,
!> signals, the wall-clock limit and the status lines are the driver's.
module dx_emc_run
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC, EXIT_IO
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_warn
   use dx_timer, only: wall_time
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_emc_solver, only: emc_state_t, newton_report_t, emc_init_state, emc_energy, &
                            emc_momenta, emc_step, emc_to_model, emc_pairs_pack, &
                            emc_pairs_unpack, EMC_PAIR_NI, EMC_PAIR_NR
   use dx_checkpoint, only: checkpoint_t, checkpoint_requests
   use dx_domain, only: domain_t
   use dx_signals, only: signal_stop_requested, signal_dump_pending
   use dx_append_file, only: append_from
   use dx_par_emc, only: par_emc_on, par_emc_writer, par_emc_set_together, par_emc_report, &
                         par_emc_max
   use dx_integrator, only: integrator_t, run_options_t, END_STOPPED
   implicit none
   private
   public :: conserving_t

   !> The conserving integrator: the bodies' state and the run's sums and output grids.
   type, extends(integrator_t) :: conserving_t
      type(emc_state_t) :: st
      type(newton_report_t) :: rep
      real(wp) :: dt0 = 0.0_wp, ke = 0.0_wp, e0 = 0.0_wp, p0(3) = 0.0_wp, l0(3) = 0.0_wp, &
                  p(3) = 0.0_wp, lt(3) = 0.0_wp, ps = 0.0_wp, ls = 0.0_wp, ps0 = 0.0_wp, &
                  ls0 = 0.0_wp, de = 0.0_wp, dp = 0.0_wp, dl = 0.0_wp, next_out = 0.0_wp, &
                  next_plot = 0.0_wp, t0wall = 0.0_wp
      real(wp), allocatable :: lb(:, :)
      integer :: u = -1, cyc = 0, ncut = 0, itmax = 0, ittot = 0
      integer :: ntunnel = 0                !< steps with missed contact (tunnelling) warned
      logical :: wr = .false.
      character(:), allocatable :: outdir
      type(error_t), allocatable :: ioerr   !< a plot-file error: the run ends with it
   contains
      procedure :: start => c_start
      procedure :: step => c_step
      procedure :: advance => c_advance
      procedure :: close => c_close
   end type conserving_t

contains

   !> The state from the rigid bodies (or the restored snapshot); emcstat opened (or resumed).
   subroutine c_start(self, model, dom, opts, ck, out, error)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom    !< serial (replicated under MPI: rank 0 writes)
      type(run_options_t), intent(in) :: opts
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      integer :: ios
      character(256) :: iomsg
      self%histories = .false.
      self%energies = .false.
      self%t0wall = wall_time()
      if (ck%wall0 <= 0.0_wp) ck%wall0 = self%t0wall
      self%outdir = ck%outdir
      self%wr = par_emc_writer(dom%emc)         ! MPI: rank 0 writes emcstat and the plot states
      ck%replicated = par_emc_on(dom%emc)       ! MPI: stop/dump requests reduced over the ranks
      associate (es => model%emc, st => self%st, u => self%u)
         call emc_init_state(model, st)
         allocate(self%lb(3, st%nb))
         self%tend = model%ctrl%endtim
         self%dt0 = model%ctrl%imp%dt0
         if (es%snap%valid) then
            call from_snapshot(self, model)
            if (self%wr) call append_from(self%outdir//'/emcstat', es%snap%emcstat_bytes, u, &
                                          error)
            if (allocated(error)) return
            call emc_momenta(st, self%p, self%lb, self%lt, self%ps, self%ls)
            call log_info('emc: continuing at step '//str(self%cyc)//', time '//rstr(self%t))
         else
            if (self%wr) then
               open(newunit=u, file=self%outdir//'/emcstat', status='replace', &
                    action='write', iostat=ios, iomsg=iomsg)
               if (ios /= 0) then
                  call set_error(error, self%outdir//'/emcstat: cannot open: '//trim(iomsg), &
                                 EXIT_IO)
                  return
               end if
               write(u, '(a)') '# dynx emcstat: energy-momentum conserving rigid-body '// &
                  'contact (docs/conserving-contact.md)'
               write(u, '(a,i0,a,es24.16e3)') '# bodies ', st%nb, ' dt ', self%dt0
               ! the names line without '#' (gnuplot's columnhead form): one name per
               ! column, body b's as NAME@b (dynx-thist's NAME@ID; docs/output-format.md)
               write(u, '(a)') 'cycle time ke upen etot px py pz lx ly lz iters resid '// &
                  'npair'//body_names(st%nb)
            end if
            self%t = 0.0_wp
            self%ke = emc_energy(st)
            self%e0 = self%ke + st%upen
            call emc_momenta(st, self%p0, self%lb, self%l0, self%ps0, self%ls0)
            self%cyc = 0
            self%p = self%p0; self%lt = self%l0
            self%rep%iters = 0; self%rep%resid = 0.0_wp; self%rep%npair = 0
            call write_line(self)
            self%next_out = es%out_dt
            self%next_plot = model%db%d3plot_dt
            self%de = 0.0_wp; self%dp = 0.0_wp; self%dl = 0.0_wp
            self%itmax = 0; self%ittot = 0; self%ncut = 0
         end if
         es%snap%unit = u
         es%snap%unit_open = self%wr
         call log_info('emc: conserving rigid-body solver, '//str(st%nb)//' bodies, dt '// &
                       rstr(self%dt0)//', end time '//rstr(self%tend))
      end associate
   end subroutine c_start

   !> One step (halved up to NFAIL times when Newton fails), its emcstat line and plot state
   !> when due; done once the end time (or ENDCYC) is reached.
   subroutine c_step(self, model, dom, ck, out, error)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: h
      logical :: ok
      associate (es => model%emc, st => self%st, t => self%t, cyc => self%cyc, rep => self%rep)
         self%done = .not. (t < self%tend*(1.0_wp - 1.0e-12_wp))
         if (model%ctrl%endcyc > 0 .and. cyc >= model%ctrl%endcyc) self%done = .true.
         if (self%done) return
         h = min(self%dt0, self%tend - t)
         self%dt = h
         call emc_step(es, st, h, 0, rep, ok, self%ncut, dom%emc)
         if (.not. ok) then
            call set_error(error, 'emc: step '//str(cyc + 1)//' at time '//rstr(t)// &
               ' (dt '//rstr(h)//'): '//rep%msg//'; scaled residual '//rstr(rep%resid)// &
               ' after '//str(rep%iters)//' iterations (tolerance '//rstr(es%rtol)// &
               '; *DYNX_CONSERVING_CONTROL MAXIT, NFAIL); last converged state written', &
               EXIT_NUMERIC)
            call par_emc_set_together(dom%emc)     ! every rank failed at this step (same data)
            return
         end if
         if (rep%tun_def > 0) call warn_tunnel(self, model, cyc + 1, t, h)
         cyc = cyc + 1
         t = t + h
         model%cycle = cyc   ! (the state at the end of this step; c_advance sets them too)
         model%time = t
         self%itmax = max(self%itmax, rep%iters); self%ittot = self%ittot + rep%iters
         self%ke = emc_energy(st)
         call emc_momenta(st, self%p, self%lb, self%lt, self%ps, self%ls)
         self%de = max(self%de, abs(self%ke + st%upen + st%ediss - self%e0)/ &
                       max(self%e0, tiny(1.0_wp)))
         self%dp = max(self%dp, norm2(self%p - self%p0)/max(self%ps0, tiny(1.0_wp)))
         self%dl = max(self%dl, norm2(self%lt - self%l0)/ &
                       max(self%ls0, self%ps0*1.0_wp, tiny(1.0_wp)))   ! floor: |p| x 1 m
         if (t >= self%next_out*(1.0_wp - 1.0e-9_wp) .or. &
             t >= self%tend*(1.0_wp - 1.0e-12_wp)) then
            call write_line(self)
            self%next_out = self%next_out + es%out_dt
         end if
         if (self%next_plot > 0.0_wp .and. t >= self%next_plot*(1.0_wp - 1.0e-9_wp)) then
            self%next_plot = self%next_plot + model%db%d3plot_dt
            call plot(self, model, out)
            if (allocated(self%ioerr)) self%done = .true.   ! the run ends with the error
         end if
      end associate
   end subroutine c_step

   !> The step boundary: model%time and cycle, and (when this boundary may write a dump or
   !> stop) the nodes and the snapshot brought up to date.
   subroutine c_advance(self, model, ck)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      type(checkpoint_t), intent(inout) :: ck
      model%time = self%t
      model%cycle = self%cyc
      call checkpoint_requests(ck, model, par_emc_max)   ! MPI: every rank's requests, reduced
      if (checkpoint_due(ck, model, self%cyc)) then
         call emc_to_model(self%st, model)
         call to_snapshot(self, model)
      end if
   end subroutine c_advance

   !> The end (normal, or a Newton failure: the last converged state is written either way;
   !> a stop: emcstat closed).
   subroutine c_close(self, model, dom, ck, out, how, error)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      integer, intent(in) :: how
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: ioerr
      if (self%wr) close(self%u)
      model%emc%snap%unit_open = .false.
      if (how == END_STOPPED) return
      associate (es => model%emc, st => self%st)
         call plot(self, model, out)
         call log_info('emc: '//str(self%cyc)//' steps to time '//rstr(self%t)// &
            ', Newton iterations '//str(self%ittot)//' (max '//str(self%itmax)// &
            ' per step), step cuts '//str(self%ncut)//', last scaled residual '// &
            rstr(self%rep%resid))
         if (es%chi > 0.0_wp) call log_info('emc: algorithmic dissipation (rho_inf '// &
            rstr(model%ctrl%imp%rho_inf)//', chi '//rstr(es%chi)//'): '//rstr(st%ediss)// &
            ' taken over the run, '//rstr(st%ediss/max(self%e0, tiny(1.0_wp)))//' of E0')
         call log_info('emc: max relative drift over the run: energy '//rstr(self%de)// &
            ', linear momentum '//rstr(self%dp)//', angular momentum '//rstr(self%dl))
         call log_info('emc: wall time '//rstr(wall_time() - self%t0wall, 4)//' s')
         call par_emc_report(dom%emc, self%cyc)
         call energy_bits_line(self)
      end associate
      if (allocated(self%ioerr) .and. .not. allocated(error)) call move_alloc(self%ioerr, error)
      if (self%wr) call out%close(ioerr)
      if (allocated(ioerr) .and. .not. allocated(error)) call move_alloc(ioerr, error)
   end subroutine c_close

   !> Contact missed in step cyc (t -> t + h): a slave point passed through the master
   !> surface with no pair (dx_emc_contact, emc_find_tunnel). Warned for the first 10 steps
   !> where it happens, then once that further ones are not shown.
   subroutine warn_tunnel(self, model, cyc, t, h)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      integer, intent(in) :: cyc
      real(wp), intent(in) :: t, h
      character(:), allocatable :: who, what
      associate (es => model%emc, rep => self%rep)
         self%ntunnel = self%ntunnel + 1
         if (self%ntunnel > 10) then
            if (self%ntunnel == 11) call log_warn('emc: more steps with missed contact '// &
               '(tunnelling); further warnings are not shown')
            return
         end if
         associate (d => es%defs(rep%tun_def), bodies => model%rigid%bodies)
            if (rep%tun_src > 0) then
               who = 'slave node '//str(model%node_label(es%sn_node(rep%tun_src)))// &
                     ' (part '//str(bodies(d%sb)%label)//')'
            else
               who = 'the slave sphere of part '//str(bodies(d%sb)%label)
            end if
            if (rep%tun_facet > 0) then
               what = 'through a face of master part '//str(bodies(d%mb)%label)
            else
               what = 'through the master sphere of part '//str(bodies(d%mb)%label)
            end if
            call log_warn('emc: *DYNX_CONSERVING_CONTACT '//str(d%cid)//': '//who// &
               ' passed '//what//' in step '//str(cyc)//' (time '//rstr(t)//' to '// &
               rstr(t + h)//') with no contact force: tunnelling, the step DT0 = '// &
               rstr(h)//' is too long for the approach speed (reduce DT0, '// &
               '*CONTROL_IMPLICIT_GENERAL)')
         end associate
      end associate
   end subroutine warn_tunnel

   !> Whether this step boundary may write a restart dump or stop (checkpoint_stage): only
   !> then are the model's nodes and the snapshot brought up to date.
   logical function checkpoint_due(ck, model, cyc) result(due)
      type(checkpoint_t), intent(in) :: ck
      type(model_t), intent(in) :: model
      integer, intent(in) :: cyc
      due = ck%walltime > 0.0_wp .or. ck%raise_cycle == cyc .or. &
            signal_stop_requested() /= 0 .or. signal_dump_pending() .or. any(ck%coll /= 0)
      if (model%rst%d3dump_cycl > 0) due = due .or. mod(cyc, model%rst%d3dump_cycl) == 0
      if (model%rst%runrsf_cycl > 0) due = due .or. mod(cyc, model%rst%runrsf_cycl) == 0
   end function checkpoint_due

   !> DYNX_ENERGY_BITS=1: the final energies and momenta as IEEE-754 bit patterns (the
   !> serial and MPI runs compared bitwise, scripts/mpi_bitwise_check.sh)
   subroutine energy_bits_line(self)
      class(conserving_t), intent(in) :: self
      character(8) :: env
      character(17) :: hx
      character(:), allocatable :: line
      real(wp) :: v(9)
      integer :: j, l, stat
      call get_environment_variable('DYNX_ENERGY_BITS', env, length=l, status=stat)
      if (stat /= 0 .or. l == 0) return
      if (env(1:1) == '0') return
      v = [self%ke, self%st%upen, self%st%ediss, self%p, self%lt]
      line = 'dynx: energy bits (KE UPEN EDISS PX PY PZ LX LY LZ):'
      do j = 1, size(v)
         write(hx, '(1x,z16.16)') transfer(v(j), 0_8)
         line = line//hx
      end do
      call log_info(line)
   end subroutine energy_bits_line

   subroutine write_line(self)
      class(conserving_t), intent(in) :: self
      integer :: b
      if (.not. self%wr) return
      write(self%u, '(i10,4es25.16e3,6es25.16e3,i6,es10.2e3,i6)', advance='no') self%cyc, &
         self%t, self%ke, self%st%upen, self%ke + self%st%upen, self%p, self%lt, &
         self%rep%iters, self%rep%resid, self%rep%npair
      do b = 1, self%st%nb
         write(self%u, '(6es25.16e3)', advance='no') self%st%xc(:, b), self%lb(:, b)
      end do
      write(self%u, '(a)') ''
   end subroutine write_line

   subroutine plot(self, model, out)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      call emc_to_model(self%st, model)
      model%time = self%t
      model%cycle = self%cyc
      if (self%wr) call out%write_plot(model, self%ioerr)
   end subroutine plot

   !> the state and loop variables into model%emc%snap (written by a dump)
   subroutine to_snapshot(self, model)
      class(conserving_t), intent(in) :: self
      type(model_t), intent(inout) :: model
      associate (sn => model%emc%snap, st => self%st)
         sn%xc = st%xc; sn%xcl = st%xcl; sn%v = st%v; sn%r = st%r; sn%w = st%w
         sn%upen = st%upen
         sn%ediss = st%ediss
         if (allocated(st%act)) then
            call emc_pairs_pack(st%act, sn%act_i, sn%act_r)
         else
            if (allocated(sn%act_i)) deallocate(sn%act_i, sn%act_r)
            allocate(sn%act_i(EMC_PAIR_NI, 0), sn%act_r(EMC_PAIR_NR, 0))
         end if
         sn%t = self%t; sn%next_out = self%next_out; sn%next_plot = self%next_plot
         sn%e0 = self%e0; sn%p0 = self%p0; sn%l0 = self%l0; sn%ps0 = self%ps0
         sn%ls0 = self%ls0
         sn%de = self%de; sn%dp = self%dp; sn%dl = self%dl; sn%resid = self%rep%resid
         sn%cyc = self%cyc; sn%itmax = self%itmax; sn%ittot = self%ittot
         sn%ncut = self%ncut
         sn%iters = self%rep%iters; sn%npair = self%rep%npair
      end associate
   end subroutine to_snapshot

   !> the state and loop variables from a restored snapshot
   subroutine from_snapshot(self, model)
      class(conserving_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      associate (sn => model%emc%snap, st => self%st)
         st%xc = sn%xc; st%xcl = sn%xcl; st%v = sn%v; st%r = sn%r; st%w = sn%w
         st%upen = sn%upen
         st%ediss = sn%ediss
         if (size(sn%act_i, 2) > 0) then
            call emc_pairs_unpack(sn%act_i, sn%act_r, st%act)
         else if (allocated(st%act)) then
            deallocate(st%act)
         end if
         self%t = sn%t; self%next_out = sn%next_out; self%next_plot = sn%next_plot
         self%e0 = sn%e0; self%p0 = sn%p0; self%l0 = sn%l0; self%ps0 = sn%ps0
         self%ls0 = sn%ls0
         self%de = sn%de; self%dp = sn%dp; self%dl = sn%dl
         self%cyc = sn%cyc; self%itmax = sn%itmax; self%ittot = sn%ittot
         self%ncut = sn%ncut
         self%rep%iters = sn%iters; self%rep%resid = sn%resid; self%rep%npair = sn%npair
         self%ke = emc_energy(st)
      end associate
   end subroutine from_snapshot

   !> ' xc@1 yc@1 zc@1 lx@1 ly@1 lz@1 xc@2 ...': the names of the per-body columns of emcstat
   function body_names(nb) result(t)
      integer, intent(in) :: nb
      character(:), allocatable :: t
      character(len=2), parameter :: nm(6) = ['xc', 'yc', 'zc', 'lx', 'ly', 'lz']
      character(12) :: num
      integer :: b, k
      t = ''
      do b = 1, nb
         write(num, '(i0)') b
         do k = 1, 6
            t = t//' '//nm(k)//'@'//trim(num)
         end do
      end do
   end function body_names
end module dx_emc_run
