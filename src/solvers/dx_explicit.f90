!> The explicit central-difference solver (DYNA3D's time loop; Hallquist, DYNA3D User's
!> Manual UCRL-MA-107254, and Belytschko, Liu & Moran 2000, box 6.1):
!>   f(n) = f_ext(n) - f_int(x(n), sigma(n)),  a(n) = f(n)/m,
!>   v(n+1/2) = v(n-1/2) + (dt(n-1/2) + dt(n+1/2))/2 a(n),  x(n+1) = x(n) + dt(n+1/2) v(n+1/2),
!> lumped mass (rho*V0 times the family table's share per node), dt(n+1/2) = TSSFAC * min
!> over elements, energy balance
!> each cycle with the time-centred kinetic energy KE(n) = 1/2 m v(n-1/2).v(n+1/2) and the
!> external and constraint work W += f(n).dtavg(n) (v(n-1/2) + v(n+1/2))/2, dtavg(n) =
!> (dt(n-1/2) + dt(n+1/2))/2: KE(n) - KE(n-1) telescopes exactly into these sums for any
!> time-step sequence, impulsive starts (cycle 0, dt(-1/2) = 0) included.
!> The loop has one path for any number of ranks: each stage that depends on what a rank
!> owns (shared nodes, contact, loads, walls, rigid bodies, energies, output, failures, the
!> dt reduction) is a call into the run's domain (dx_domain; serial or MPI).
module dx_explicit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use dx_kinds, only: wp, huge_wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_warn
   use dx_timer, only: wall_time, peak_memory_kb
   use dx_model, only: model_t, elem_block_t
   use dx_run_state, only: run_state_t
   use dx_element, only: element_block_pass, block_result_t, ELEM_ERR_NEGVOL, family_t, &
                         element_family, element_rotary_inertia
   use dx_loads, only: add_external_loads, load_rows, add_nonreflecting, add_edge_pressures, &
                       deposit_energy
   use dx_constraints, only: apply_spc, apply_prescribed, apply_spc_rot, apply_prescribed_rot
   use dx_output, only: output_t
   use dx_checkpoint, only: checkpoint_t, checkpoint_failure_dump, checkpoint_energy_band
   use dx_rigid_solver, only: rigid_close, rigid_write_rbdout
   use dx_energy_sums, only: kinetic_energy, constrained_nodes, energy_bits, rotation_kinetic
   use dx_energy_exact, only: exact_mass, exact_initial_ke
   use dx_domain, only: domain_t
   use dx_mass_scaling, only: ms_init, lump_mass, ms_block, ms_percent, ms_log_start, &
                              ms_endmas_report, MS_WARN_PERCENT
   use dx_integrator, only: integrator_t, run_options_t, END_FAILED, END_STOPPED, close_files
   implicit none
   private
   public :: explicit_t, init_state, elem_label, explicit_rbdout

   !> a run whose first step needs more cycles than this to its end time is warned about
   !> (near-zero density or mass: docs/extreme-cases.md, "Summary")
   real(wp), parameter :: CYCLES_WARN = 1.0e9_wp

   !> The explicit integrator: its work arrays for one cycle (the loop state is model%run).
   type, extends(integrator_t) :: explicit_t
      real(wp), allocatable :: vold(:, :), fext(:, :), vfree(:, :)
      real(wp), allocatable :: wold(:, :)   !< w(n-1/2) (decks with shells only)
      !> nodal moments (fext has 6 rows): (v, w) at n-1/2 and n+1/2 for their work
      real(wp), allocatable :: vw_old(:, :), vw_new(:, :)
      integer, allocatable :: cnodes(:)
      logical :: loads = .false.
      logical :: ms_warned = .false.   !< mass scaling: the increase passed MS_WARN_PERCENT
      logical :: ms_stop = .false.     !< mass scaling: ENDMAS reached, this cycle is the last
      real(wp) :: t0wall = 0.0_wp
      character(:), allocatable :: outdir
   contains
      procedure :: start => x_start
      procedure :: step => x_step
      procedure :: advance => x_advance
      procedure :: close => x_close
   end type explicit_t

contains

   !> Allocate and initialize the nodal state: x = x0, v = v0, lumped mass (with dom: its
   !> shared nodes' masses summed).
   subroutine init_state(model, dom)
      type(model_t), intent(inout) :: model
      class(domain_t), intent(inout), optional :: dom
      integer :: b
      type(family_t) :: fam
      logical :: rot
      allocate(model%x(3, model%nn), model%v(3, model%nn), model%f(3, model%nn))
      allocate(model%mass(model%nn))
      model%x = model%x0
      model%v = model%v0
      model%f = 0.0_wp
      call ms_init(model)      ! mass scaling: the elements' added mass (none yet)
      call lump_mass(model)    ! rho V0 times the family's share per node
      ! rotational degrees of freedom: only when a block's family has them (shells, beams)
      ! or a node has a rotary inertia of its own (*ELEMENT_INERTIA)
      rot = allocated(model%node_rinert)
      do b = 1, size(model%blocks)
         fam = element_family(model%blocks(b)%etype)
         rot = rot .or. fam%rot
      end do
      if (rot) then
         allocate(model%w(3, model%nn), model%mom(3, model%nn), model%rinert(model%nn))
         model%w = 0.0_wp
         if (allocated(model%w0)) model%w = model%w0
         model%mom = 0.0_wp
         model%rinert = 0.0_wp
         do b = 1, size(model%blocks)
            associate (blk => model%blocks(b))
               call element_rotary_inertia(blk, model%mats(model%parts(blk%ipart)%imat)%m%ro, &
                                           model%ctrl%rotascl, model%rinert)
            end associate
         end do
         if (allocated(model%node_rinert)) model%rinert = model%rinert + model%node_rinert
      end if
      model%time = 0.0_wp
      model%cycle = 0
      model%energy%mass = exact_mass(model)   ! (MPI: dom%sum_mass sums the ranks')
      if (allocated(model%rigid)) model%energy%mass = model%energy%mass + model%rigid%mass_corr
      if (present(dom)) call dom%sum_mass(model)   ! MPI: shared nodes' mass summed
   end subroutine init_state

   !> The explicit integrator's start: the nodal state (unless a restart restored it), the
   !> loop state model%run (or the restored one), the work arrays of the cycle.
   !> Everything the loop carries from one cycle to the next is in model (x, v, time,
   !> cycle, element blocks, walls) and model%run (dt_old, work sums, next output times),
   !> so a restart dump restored into model (model%run%started) continues the run exactly.
   subroutine x_start(self, model, dom, opts, ck, out, error)
      class(explicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(run_options_t), intent(in) :: opts
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      logical :: changed
      if (.not. allocated(model%x)) call init_state(model, dom)
      self%outdir = opts%outdir
      allocate(self%vold(3, model%nn))
      if (allocated(model%w)) allocate(self%wold(3, model%nn))
      self%loads = dom%has_loads(model)      ! the deck's loads, whatever this rank holds
      if (self%loads) allocate(self%fext(load_rows(model), model%nn))   ! 6: nodal moments
      if (self%loads) then
         if (size(self%fext, 1) == 6) allocate(self%vw_old(6, model%nn), self%vw_new(6, model%nn))
      end if
      call constrained_nodes(model, self%cnodes)
      allocate(self%vfree(3, size(self%cnodes)))
      call dom%mass_share(model, self%cnodes)  ! one-element-wide blocks get the element dt bound
      self%tend = model%ctrl%endtim
      if (self%tend <= 0.0_wp) self%tend = huge_wp
      if (.not. model%run%started) then
         model%run = run_state_t()
         model%run%started = .true.
         model%energy%initial = exact_initial_ke(model)   ! (MPI: the ranks' sum next)
         call dom%initial_energy(model)
         if (allocated(model%rigid)) model%energy%initial = model%energy%initial + &
                                                           model%rigid%ke0_corr
      else
         call log_info('dynx: continuing from cycle '//str(model%cycle)//', time '// &
                       rstr(model%time))
         if (allocated(model%added_mass)) then   ! the restored added mass on the nodes
            changed = .true.
            call dom%remass(model, changed)
            self%ms_warned = abs(ms_percent(model)) > MS_WARN_PERCENT
         end if
      end if
      call ms_log_start(model)
      self%t0wall = wall_time()
      if (ck%wall0 <= 0.0_wp) ck%wall0 = self%t0wall   ! main sets it at process start
   end subroutine x_start

   !> One cycle of the explicit loop up to the state at t(n): forces, the step, v(n+1/2),
   !> constraints, work sums and the energies (the positions: x_advance).
   subroutine x_step(self, model, dom, ck, out, error)
      class(explicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: dt, dtavg, dtcrit, t, ke, wrig, tend, krot, dtfloor
      integer :: b, i, ibmin, iemin
      logical :: done, need, ms, mchanged
      type(block_result_t) :: res
      type(error_t), allocatable :: ioerr
      tend = self%tend
      associate (dt_old => model%run%dt_old, dt_first => model%run%dt_first, &
                 tsmin => model%run%tsmin, wext => model%run%wext, wrw => model%run%wrw, &
                 wcon => model%run%wcon, next_glstat => model%run%next_glstat, &
                 vold => self%vold, fext => self%fext, vfree => self%vfree, &
                 cnodes => self%cnodes, loads => self%loads)
         t = model%time
         ! ---- internal forces (element pass) and the critical step
         call dom%fill(model)   ! shared nodes' x, v into their slots
         ! *DYNX_ENERGY_DEPOSITION: the energy of [t(n-1), t(n)] into the elements first
         if (allocated(model%deposits)) call deposit_energy(model, t, dt_old, model%run%wdep)
         model%f = 0.0_wp
         if (allocated(model%mom)) model%mom = 0.0_wp
         dtcrit = huge_wp; ibmin = 0; iemin = 0
         ms = allocated(model%added_mass)
         mchanged = .false.
         ! *CONTROL_TIMESTEP ERODE = 1: an element whose step TSSFAC*dt_e falls below
         ! DTMIN * first step erodes (dx_erosion) instead of stopping the run
         dtfloor = 0.0_wp
         if (model%ctrl%erode == 1) dtfloor = tsmin/model%ctrl%tssfac
         do b = 1, size(model%blocks)
            if (dom%pending()) exit    ! MPI: a failure kept on this rank skips the pass
            if (model%mats(model%parts(model%blocks(b)%ipart)%imat)%m%is_rigid) cycle
            associate (blk => model%blocks(b), part => model%parts(model%blocks(b)%ipart))
               if (allocated(model%w) .and. model%erodes) then
                  call element_block_pass(blk, model%mats(part%imat)%m, part, model%x, &
                                          model%v, dt_old, model%f, res, model%w, model%mom, &
                                          time=t, dtfloor=dtfloor)
               else if (allocated(model%w)) then
                  call element_block_pass(blk, model%mats(part%imat)%m, part, model%x, &
                                          model%v, dt_old, model%f, res, model%w, model%mom)
               else if (model%erodes) then
                  call element_block_pass(blk, model%mats(part%imat)%m, part, model%x, &
                                          model%v, dt_old, model%f, res, time=t, &
                                          dtfloor=dtfloor)
               else
                  call element_block_pass(blk, model%mats(part%imat)%m, part, model%x, &
                                          model%v, dt_old, model%f, res)
               end if
               if (res%ibad /= 0) then
                  call element_failure(model, b, res, error)
                  call dom%defer(error)   ! MPI: every rank learns it at the dt reduction
                  if (allocated(error)) return
                  exit
               end if
               ! mass scaling: the elements' added mass, the block's step with it
               if (ms) call ms_block(model, b, res, mchanged)
               if (res%dt < dtcrit) then
                  dtcrit = res%dt; ibmin = b; iemin = res%imin
               end if
            end associate
         end do
         if (ibmin > 0) model%dt_elem = model%blocks(ibmin)%elem(iemin)
         if (ms) call dom%remass(model, mchanged)   ! (MPI: any rank's change, all ranks)
         if (mchanged) call scaled_mass(self, model, dom)
         ! global min (serial tie rule); MPI: the ranks' stop/dump requests ride in it, and
         ! a failure on any rank stops all
         call dom%reduce_dt(model, dtcrit, ibmin, ck, error)
         if (allocated(error)) return
         ! ---- contact forces (only when the deck has *CONTACT)
         if (allocated(model%contact) .or. allocated(model%contact2d)) &
            call dom%contact_forces(model, dt_old, dtcrit)   ! (2D: dx_contact2d; MPI dx_par_contact2d)
         ! ---- external forces
         if (loads) then
            fext = 0.0_wp
            call add_external_loads(model, t, fext)
            call dom%loads_shared(model, t, fext)   ! MPI: shared nodes, serial chain
         end if
         ! ---- shared-node exchange (MPI): serial-order sums at shared nodes, contact forces
         call dom%exchange(model)
         ! ---- time step
         dt = model%ctrl%tssfac*dtcrit
         if (model%cycle == 0 .and. model%ctrl%dtinit > 0.0_wp) dt = min(dt, model%ctrl%dtinit)
         if (model%ctrl%lctm > 0) dt = min(dt, model%curves(model%ctrl%lctm)%eval(t))
         ! every element eroded (nothing bounds the step): go on with the last step
         if (model%erodes .and. .not. (dtcrit < huge_wp) .and. dt_old > 0.0_wp) dt = dt_old
         if (model%cycle == 0) then
            dt_first = dt
            if (model%ctrl%dtmin > 0.0_wp) tsmin = model%ctrl%dtmin*dt
            ! near-zero mass (issue 23): the step scales as sqrt(rho), so a density typed a
            ! few decades too small asks for more cycles than any run can take; say so once
            if (tend < huge_wp .and. dt > 0.0_wp) then
               if ((tend - t)/dt > CYCLES_WARN) call log_warn('the first time step '// &
                  rstr(dt)//' (element '//str(elem_label(model))//') needs about '// &
                  rstr((tend - t)/dt, 3)//' cycles to the end time '//rstr(tend)// &
                  ': is a density or mass near zero (units)? *CONTROL_TERMINATION ENDCYC, '// &
                  '*CONTROL_TIMESTEP DTMIN or DT2MS bound such a run')
            end if
         end if
         if (.not. (dt > tsmin) .or. .not. ieee_is_finite(dt) .or. dt >= huge_wp) then
            call set_error(error, 'time step '//rstr(dt)//' at cycle '//str(model%cycle)// &
               ', time '//rstr(t)//' is below the floor '//rstr(tsmin)//' (DTMIN*first step '// &
               rstr(dt_first)//'); controlling element '//str(elem_label(model)), EXIT_NUMERIC)
            return
         end if
         dtavg = 0.5_wp*(dt_old + dt)
         if (loads) call add_edge_pressures(model, t, fext)   ! (t = 0 geometry: node by node)
         ! non-reflecting boundary: nodal dashpots on the centred velocity (v(n-1/2) +
         ! v(n+1/2))/2, solved with the node's other forces (unconditionally stable; the
         ! lagged v(n-1/2) was not), after the exchange: the same bits on every rank
         if (loads) call add_nonreflecting(model, fext, dtavg)
         if (loads) then
            if (size(fext, 1) == 3) then
               model%f = model%f + fext
            else            ! *LOAD_NODE DOF 5-7: rows 4-6 are moments
               model%f = model%f + fext(1:3, :)
               model%mom = model%mom + fext(4:6, :)
            end if
         end if
         ! ---- velocities: v(n+1/2) = v(n-1/2) + dtavg*f/m
         vold = model%v
         do i = 1, model%nn
            if (model%mass(i) > 0.0_wp) &
               model%v(:, i) = model%v(:, i) + dtavg*model%f(:, i)/model%mass(i)
         end do
         ! rigid bodies take their nodes' summed forces and overwrite their velocities
         if (allocated(model%rigid)) call dom%rigid_step(model, t, dt, dtavg, vold)
         ! ---- constraints (work of the reaction forces enters the external work)
         do i = 1, size(cnodes)
            vfree(:, i) = model%v(:, cnodes(i))
         end do
         call apply_spc(model, model%v)
         call apply_prescribed(model, t, dt, dtavg, vold, model%v)
         krot = 0.0_wp
         if (allocated(model%w)) call rotation_step(model, t, dt, dtavg, self%wold, krot)
         done = t >= tend .or. (model%ctrl%endcyc > 0 .and. model%cycle >= model%ctrl%endcyc) &
                .or. self%ms_stop
         need = done .or. model%ctrl%endeng > 0.0_wp .or. (model%db%glstat_dt > 0.0_wp .and. &
                                                          t >= next_glstat) .or. &
                (model%db%matsum_dt > 0.0_wp .and. t >= model%run%next_matsum)
         ! rigid walls; work sums (MPI: terms kept, summed in serial order when needed)
         ! (shells: the constraint moments' work first, self%wold present only with them)
         call dom%constraints(model, cnodes, vfree, vold, dt, dtavg, wcon, wrw, need, &
                              self%wold)
         if (loads) then
            if (size(fext, 1) == 3) then
               call dom%load_work(fext, vold, model%v, dtavg, wext, need)
            else            ! the moments' work M.dtavg (w(n-1/2) + w(n+1/2))/2 per node too
               call stack6(vold, self%wold, self%vw_old)
               call stack6(model%v, model%w, self%vw_new)
               call dom%load_work(fext, self%vw_old, self%vw_new, dtavg, wext, need)
            end if
         end if
         if (allocated(model%contact)) then
            call dom%contact_work(model, vold, dtavg, self%outdir, ioerr)
            if (allocated(ioerr)) then
               call move_alloc(ioerr, error); return
            end if
         end if
         ! ---- energies at t(n)
         ke = kinetic_energy(model%nn, model%mass, vold, model%v) + krot
         wrig = 0.0_wp
         if (allocated(model%rigid)) then
            ke = ke + model%rigid%ke_corr
            wrig = model%rigid%work
         end if
         if (.not. ieee_is_finite(ke)) then
            call nan_failure(model, error)
            call dom%defer(error)      ! MPI: known to all at the next dt reduction
            if (allocated(error)) return
         end if
         model%dt = dt
         ! (MPI: global sums, only when glstat, ENDENG or the end need them)
         if (allocated(model%contact2d)) wrig = wrig + model%contact2d%work   ! (a cycle late)
         call dom%energies(model, ke, vold, wext + wcon + wrig + model%run%wdep, -wrw, &
                           0.25_wp*(dt - dt_old), &
                           need, self%wold, parts=model%db%matsum_dt > 0.0_wp .and. &
                           (done .or. t >= model%run%next_matsum))
         if (model%ctrl%endeng > 0.0_wp) call checkpoint_energy_band(ck, model, t)
      end associate
      self%t = t
      self%dt = dt
      self%done = done
   end subroutine x_step

   !> Mass scaling changed an element's mass this cycle (the nodal masses and the added
   !> total are updated, dom%remass): the warning once the change passes MS_WARN_PERCENT and
   !> the ENDMAS stop; at the first cycle the initial kinetic energy with the scaled masses
   !> (the run starts with them, as in LS-DYNA).
   subroutine scaled_mass(self, model, dom)
      class(explicit_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      class(domain_t), intent(inout) :: dom
      real(wp) :: pct
      if (model%cycle == 0) then
         model%energy%initial = exact_initial_ke(model)   ! (MPI: the ranks' sum next)
         call dom%initial_energy(model)
         if (allocated(model%rigid)) model%energy%initial = model%energy%initial + &
                                                           model%rigid%ke0_corr
      end if
      pct = ms_percent(model)
      if (.not. self%ms_warned .and. abs(pct) > MS_WARN_PERCENT) then
         self%ms_warned = .true.
         call log_warn('mass scaling (DT2MS = '//rstr(model%ctrl%dt2ms)//') has changed '// &
            'the model''s mass by '//rstr(pct, 4)//' % (more than '// &
            rstr(MS_WARN_PERCENT, 3)//' %) at cycle '//str(model%cycle)//', time '// &
            rstr(model%time)//'; the inertia of the scaled parts is changed (glstat: '// &
            'added_mass, percent_increase)')
      end if
      if (.not. self%ms_stop .and. model%ctrl%endmas > 0.0_wp .and. pct > model%ctrl%endmas) &
         then
         self%ms_stop = .true.
         call ms_endmas_report(model)
      end if
   end subroutine scaled_mass

   !> Rotations of the shell nodes, the central difference as for the translations:
   !> w(n+1/2) = w(n-1/2) + dtavg m(n)/I (the lumped rotary inertia I is a scalar per node,
   !> so the update is the same in any axes), then DOFRX/RY/RZ and the prescribed rotations.
   !> krot = 1/2 I w(n-1/2).w(n+1/2), the rotational kinetic energy at t(n) (as for the
   !> translations). model%mom keeps the free w: the domain's constraint stage adds the work
   !> of the constraint moments, I (w - w_free).(w(n-1/2) + w)/2, to wcon (dx_energy_sums
   !> rotation_work; under MPI in serial order from the owned nodes' terms). (The nodes carry
   !> no rotation angle: the Belytschko-Lin-Tsay shell needs only the angular velocities.)
   subroutine rotation_step(model, t, dt, dtavg, wold, krot)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg
      real(wp), intent(inout) :: wold(:, :)
      real(wp), intent(out) :: krot
      integer :: i
      wold = model%w
      do i = 1, model%nn
         if (model%rinert(i) > 0.0_wp) &
            model%w(:, i) = model%w(:, i) + dtavg*model%mom(:, i)/model%rinert(i)
      end do
      model%mom = model%w       ! (the free w, kept for the constraint work)
      call apply_spc_rot(model, model%w)
      call apply_prescribed_rot(model, t, dt, dtavg, wold, model%w)
      krot = rotation_kinetic(model%nn, model%rinert, wold, model%w)
   end subroutine rotation_step

   !> Positions x(n+1) = x(n) + dt(n+1/2) v(n+1/2): the cycle boundary.
   subroutine x_advance(self, model, ck)
      class(explicit_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      type(checkpoint_t), intent(inout) :: ck
      model%x = model%x + self%dt*model%v
      model%time = self%t + self%dt
      model%cycle = model%cycle + 1
      model%run%dt_old = self%dt
   end subroutine x_advance

   !> The end: the summary lines and the files closed; after a failure, finish.
   subroutine x_close(self, model, dom, ck, out, how, error)
      class(explicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      integer, intent(in) :: how
      type(error_t), allocatable, intent(inout) :: error
      integer :: i
      if (how == END_STOPPED) return
      if (how == END_FAILED) then
         call finish(model, dom, out, ck, error)
         return
      end if
      call log_info('dynx: normal termination at cycle '//str(model%cycle)//', time '// &
                    rstr(model%time)//', energy ratio '//rstr(model%energy%ratio, 8))
      call get_environment_variable('DYNX_ENERGY_BITS', length=i)   ! bitwise checks
      if (i > 0) call log_info(energy_bits(model%energy))   ! (MPI: rank 0 logs)
      call log_info('dynx: wall time '//rstr(wall_time() - self%t0wall, 4)//' s, '// &
         rstr(1.0e9_wp*(wall_time() - self%t0wall)/real(max(1, model%cycle), wp)/ &
         real(max(1, model%ne), wp), 4)//' ns per element-cycle, peak memory '// &
         str(peak_memory_kb())//' KiB')
      if (allocated(model%rigid)) call rigid_close(model%rigid)
      call close_files(dom, out, error)      ! MPI: rank 0 combines the per-rank plot files
   end subroutine x_close

   !> One rbdout record of the rigid bodies at time t (MPI: rank 0 writes).
   subroutine explicit_rbdout(model, dom, outdir, t, error)
      type(model_t), intent(inout) :: model
      class(domain_t), intent(inout) :: dom
      character(*), intent(in) :: outdir
      real(wp), intent(in) :: t
      type(error_t), allocatable, intent(out) :: error
      if (dom%rigid_writer()) call rigid_write_rbdout(model%rigid, outdir, t, error)
   end subroutine explicit_rbdout

   !> The label of the element whose step controlled the last cycle (0: none).
   integer function elem_label(model)
      type(model_t), intent(in) :: model
      elem_label = 0
      if (model%dt_elem > 0) elem_label = model%elem_label(model%dt_elem)
   end function elem_label

   !> A kernel flagged an element: name it, its part, the cycle and the time.
   subroutine element_failure(model, b, res, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: b
      type(block_result_t), intent(in) :: res
      type(error_t), allocatable, intent(out) :: error
      integer :: e
      character(:), allocatable :: what
      e = model%blocks(b)%elem(res%ibad)
      if (res%errcode == ELEM_ERR_NEGVOL) then
         what = 'negative volume'
      else
         what = 'material update failed'
      end if
      call set_error(error, what//' in element '//str(model%elem_label(e))//' (part '// &
         str(model%parts(model%blocks(b)%ipart)%label)//') at cycle '//str(model%cycle)// &
         ', time '//rstr(model%time), EXIT_NUMERIC)
   end subroutine element_failure

   subroutine nan_failure(model, error)
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      do i = 1, model%nn
         if (.not. all(ieee_is_finite(model%v(:, i)))) exit
      end do
      i = min(i, model%nn)
      call set_error(error, 'non-finite velocity (NaN or Inf) at node '// &
         str(model%node_label(i))//' at cycle '//str(model%cycle)//', time '// &
         rstr(model%time), EXIT_NUMERIC)
   end subroutine nan_failure

   !> After a failure: write the last state and close the files so the output stays readable.
   subroutine finish(model, dom, out, ck, error)
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(output_t), intent(inout) :: out
      type(checkpoint_t), intent(inout) :: ck
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: ioerr
      character(:), allocatable :: dump, lost
      logical :: writer
      ! MPI: every rank gets here together (a failure all know); no failure dump
      writer = dom%writer()
      call checkpoint_failure_dump(ck, dom, model, out, dump)
      call dom%write_plot(model, out, ioerr)   ! the last state (MPI: each rank its part)
      ! the end message reports only what was written (a full disk: the states before it)
      lost = ''
      if (allocated(ioerr)) then
         lost = ioerr%message
         deallocate(ioerr)
      end if
      if (allocated(model%rigid)) call rigid_close(model%rigid)
      if (writer) call out%close(ioerr)
      if (allocated(ioerr) .and. len(lost) == 0) lost = ioerr%message
      if (allocated(ioerr)) deallocate(ioerr)
      call dom%plot_finish(ioerr, .true.)   ! MPI: rank 0 combines
      if (allocated(ioerr) .and. allocated(error)) error%message = error%message// &
         new_line('a')//'dynx: combining the plot files failed: '//ioerr%message
      if (allocated(error) .and. len(lost) == 0) then
         error%message = error%message//new_line('a')// &
            'dynx: the last state (time '//rstr(model%time)//') was written to the plot file'
      else if (allocated(error)) then
         error%message = error%message//new_line('a')//'dynx: the last state (time '// &
            rstr(model%time)//') could not be written ('//lost//'); the plot file holds '// &
            'the states written before it'
      end if
      if (allocated(error) .and. len(dump) > 0) error%message = error%message// &
         new_line('a')//'dynx: state at the failure (for inspection, not restartable) in '//dump
   end subroutine finish
   !> (6, n): the rows of a over those of b (velocities over angular velocities).
   !> r = (a; b): two (3, nn) arrays as one (6, nn), in the work array r.
   pure subroutine stack6(a, b, r)
      real(wp), intent(in) :: a(:, :), b(:, :)
      real(wp), intent(inout) :: r(:, :)
      r(1:3, :) = a
      r(4:6, :) = b
   end subroutine stack6
end module dx_explicit
