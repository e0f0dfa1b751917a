!> The implicit Newton solver for statics (*CONTROL_IMPLICIT_GENERAL IMFLAG = 1 without
!> *DYNX_CONSERVING_CONTACT; issue 20), an integrator_t behind dx_solver's run_driver.
!> Load steps of DT0 from 0 to ENDTIM (the loads and prescribed displacements ramped by
!> their curves); in each step Newton-Raphson on the residual r(u) = f_ext(t) - f_int(u)
!> over the free equations (NIKE3D: Maker, Ferencz & Hallquist, NIKE3D User's Manual,
!> UCRL-MA-105268 rev. 1, 1995, "Solution of the nonlinear equations"):
!>   K(u_k) du = r(u_k),  u_(k+1) = u_k + eta du,
!> K the consistent tangent (material tangent + geometric stiffness, dx_hex8_stiffness) from
!> the sparse assembly (dx_sparse, pattern once) factored by MUMPS (dx_mumps, analysis once).
!> Line search (Crisfield, "Non-linear Finite Element Analysis of Solids and Structures",
!> vol. 1, 1991, ch. 9.3): with s(eta) = du . r(u_k + eta du), a step whose |s(1)| exceeds
!> LSTOL |s(0)| is cut by up to 4 secant (regula falsi) steps on s, eta in [0.1, 1].
!> Convergence (the LS-DYNA *CONTROL_IMPLICIT_SOLUTION tolerances, dynx's norms):
!>   displacement ratio  |eta du| / |u - u_n|              <= DCTOL
!>   energy ratio        |eta du . r_k| / |du_1 . r_0|      <= ECTOL
!>   residual ratio      |r_(k+1)| / |r_0|                  <= RCTOL
!> all three, or |r_(k+1)| <= ABSTOL; the log prints the three ratios per iteration (the
!> residual ratio squares near the solution: quadratic convergence). MAXREF iterations
!> without convergence fail the step: with *CONTROL_IMPLICIT_AUTO IAUTO = 1 the step is
!> retried at half the length (down to DTMIN) and later steps grow back toward ITEOPT
!> iterations; else exit 3 with the step's residual history. NSOLVR = 1 (linear): one
!> solve per step on the small-displacement element. A singular stiffness (MUMPS null
!> pivots) names the free nodes and the rigid-body modes the stiffness does not resist.
!> Energies (glstat): internal = the elements' stress work (trapezoid per step), external
!> work = the trapezoid of the internal force (= the applied loads and reactions) over the
!> step's displacement, kinetic 0. No restart dumps of the implicit state.
!> MPI runs (mpirun -np N): every rank repeats the Newton decisions on the same residual;
!> each assembles its own elements and MUMPS factorizes on all ranks (dx_implicit_par);
!> a failure is agreed after every step, stop/dump requests are reduced (replicated run).
module dx_implicit
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC, EXIT_INPUT
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_timer, only: wall_time, peak_memory_kb
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_checkpoint, only: checkpoint_t, checkpoint_requests
   use dx_domain, only: domain_t
   use dx_integrator, only: integrator_t, run_options_t, END_NORMAL, END_FAILED, END_STOPPED, &
                            serial_fresh_only, close_files
   use dx_explicit, only: init_state
   use dx_sparse, only: sparse_matvec
   use dx_mumps, only: mumps_t
   use dx_implicit_system, only: implicit_system_t, isys_setup, isys_assemble, isys_commit, &
                                 isys_external, isys_prescribe, isys_comm, isys_gather, &
                                 isys_scatter, isys_null_names, isys_fix, isys_refind, &
                                 isys_reset, isys_root, isys_mpi, isys_analyse_entries, &
                                 isys_bcast, isys_bcast_int, isys_agree, isys_agreed, &
                                 isys_max_flags, isys_global, isys_sum_entries, isys_per_rank
   use dx_implicit_rigid, only: irig_geo, irig_inertia, irig_start_dyn, irig_kinetic, &
                                irig_velocity
   implicit none
   private
   public :: implicit_t

   type, extends(integrator_t) :: implicit_t
      type(implicit_system_t) :: sys
      type(mumps_t) :: ms
      real(wp), allocatable :: u(:, :), uc(:, :), fint(:, :), fintc(:, :), fext(:, :)
      real(wp), allocatable :: r(:), du(:), rk(:)
      !> dynamics (*CONTROL_IMPLICIT_DYNAMICS): committed velocity and acceleration, the
      !> committed out-of-balance force f_ext - f_int (HHT), the trial acceleration, the
      !> lumped mass per equation
      real(wp), allocatable :: vc(:, :), ac(:, :), rsc(:, :), at(:, :), meq(:)
      real(wp), allocatable :: m3(:, :)    !< nodal lumped mass (0 on rigid bodies' nodes)
      logical :: dyn = .false.
      real(wp) :: kin = 0.0_wp             !< kinetic energy of the committed state
      real(wp) :: wext = 0.0_wp            !< external work so far
      real(wp) :: h = 0.0_wp               !< the next step's length
      real(wp) :: t0wall = 0.0_wp
      logical :: first = .true.            !< the first call reports the initial state
      integer :: nfactor = 0, niter = 0, nsteps = 0, ncut = 0
      real(wp) :: tfac = 0.0_wp, tasm = 0.0_wp, tana = 0.0_wp   !< wall seconds: factor+solve, assembly, analysis
      real(wp) :: hfac = -1.0_wp           !< linear runs: the step of the factorization kept
      real(wp) :: cfac = 0.0_wp            !< CPU seconds of this process in the factorizations
   contains
      procedure :: start => i_start_agreed
      procedure :: step => i_step_agreed
      procedure :: advance => i_advance
      procedure :: close => i_close
   end type implicit_t

contains

   subroutine i_start(self, model, dom, opts, ck, out, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(run_options_t), intent(in) :: opts
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      if (.not. (model%ctrl%endtim > 0.0_wp)) then
         call set_error(error, '*CONTROL_TERMINATION: field ENDTIM: the implicit solver '// &
            '(IMFLAG = 1) steps the loads from 0 to ENDTIM, which must be > 0, got '// &
            rstr(model%ctrl%endtim), EXIT_INPUT)
         return
      end if
      call serial_fresh_only(model, dom, 'implicit solver', ' (its element state is not '// &
                             'in the dump)', error)
      if (allocated(error)) return
      if (.not. allocated(model%x)) call init_state(model, dom)
      model%v = 0.0_wp
      call isys_setup(model, self%sys, error, rigid_ok=.true.)
      if (allocated(error)) return
      allocate(self%u(3, model%nn), self%uc(3, model%nn), self%fint(3, model%nn), &
               self%fintc(3, model%nn), self%fext(3, model%nn))
      self%u = 0.0_wp; self%uc = 0.0_wp; self%fint = 0.0_wp; self%fintc = 0.0_wp
      allocate(self%r(self%sys%neq), self%du(self%sys%neq), self%rk(self%sys%neq))
      self%dyn = model%ctrl%imp%dynamic
      if (self%dyn) then
         allocate(self%vc(3, model%nn), self%ac(3, model%nn), self%rsc(3, model%nn), &
                  self%at(3, model%nn), self%meq(self%sys%neq), self%m3(3, model%nn))
         self%vc = model%v0
         self%m3 = spread(model%mass, 1, 3)
         where (spread(self%sys%rig%nbody, 1, 3) > 0) self%m3 = 0.0_wp   ! (the bodies' own)
         call isys_gather(self%sys, self%m3, self%meq)
         associate (m3 => self%m3)
         ! a(0) = M^-1 (f_ext(0) - f_int(0)), u = 0 (f_int = 0)
         model%x = model%x0
         call isys_external(model, 0.0_wp, self%rsc)
         self%ac = 0.0_wp
         where (m3 > 0.0_wp) self%ac = self%rsc/m3
         self%at = self%ac
         call irig_start_dyn(self%sys%rig, model, self%rsc)
         self%kin = 0.5_wp*sum(m3*self%vc**2) + irig_kinetic(self%sys%rig)
         model%v = self%vc
         call irig_velocity(self%sys%rig, model, model%v)
         end associate
         call log_info('dynx: implicit: dynamics (*CONTROL_IMPLICIT_DYNAMICS): Newmark GAMMA '// &
            rstr(model%ctrl%imp%gamma, 6)//', BETA '//rstr(model%ctrl%imp%beta, 6)// &
            ', HHT ALPHA '//rstr(model%ctrl%imp%alpha, 6)//', lumped mass')
      end if
      ck%replicated = isys_mpi(self%sys)   ! MPI: stop/dump requests reduced over the ranks
      t0 = wall_time()
      call analyse(self, error)
      self%tana = wall_time() - t0
      if (allocated(error)) return
      call log_info('dynx: implicit: '//str(self%sys%neq)//' equations, '// &
         str(self%sys%k%nnz)//' stored entries (upper triangle), MUMPS analysis (METIS) '// &
         rstr(wall_time() - t0, 3)//' s')
      associate (imp => model%ctrl%imp)
         if (imp%nsolvr == 1) then
            call log_info('dynx: implicit: NSOLVR = 1, linear: one solve per step (small '// &
                          'displacements)')
         else
            call log_info('dynx: implicit: full Newton (NSOLVR '//str(imp%nsolvr)// &
               '; a new tangent every iteration), line search LSTOL '//rstr(imp%lstol, 3)// &
               ', MAXREF '//str(imp%maxref)//', DCTOL '//rstr(imp%dctol, 3)//', ECTOL '// &
               rstr(imp%ectol, 3)//', RCTOL '//rstr(imp%rctol, 3)//', ABSTOL '// &
               rstr(imp%abstol, 3))
            if (imp%ilimit > 1 .and. imp%ilimit /= 11) call log_info('dynx: implicit: '// &
               'note: ILIMIT '//str(imp%ilimit)//' (BFGS updates between reformations) is '// &
               'replaced by full Newton (same converged answer)')
         end if
         if (imp%iauto == 1) call log_info('dynx: implicit: automatic steps (IAUTO 1): '// &
            'ITEOPT '//str(imp%iteopt)//', ITEWIN '//str(imp%itewin)//', DTMIN '// &
            rstr(dtmin_of(model), 4)//', DTMAX '//rstr(dtmax_of(model), 4))
      end associate
      self%tend = model%ctrl%endtim
      self%h = model%ctrl%imp%dt0
      self%histories = .true.
      self%energies = .false.
      self%first = .true.
      model%energy%initial = self%kin
      self%t0wall = wall_time()
      if (ck%wall0 <= 0.0_wp) ck%wall0 = self%t0wall
   end subroutine i_start

   !> The sparse solver's analysis of the pattern (MPI: this rank's entries, every rank).
   subroutine analyse(self, error)
      class(implicit_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      integer :: comm
      integer, allocatable :: loc(:)
      if (isys_mpi(self%sys)) then
         call isys_analyse_entries(self%sys, comm, loc)
         call self%ms%analyse(self%sys%k, comm, error, loc)
      else
         call self%ms%analyse(self%sys%k, isys_comm(), error)
      end if
   end subroutine analyse

   !> The start, then (MPI) a failure known to every rank: each rank found the same.
   subroutine i_start_agreed(self, model, dom, opts, ck, out, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(run_options_t), intent(in) :: opts
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      call i_start(self, model, dom, opts, ck, out, error)
      call isys_agree(error)
   end subroutine i_start_agreed

   !> One step, then (MPI) a failure known to every rank: each rank found the same.
   subroutine i_step_agreed(self, model, dom, ck, out, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      call i_step(self, model, dom, ck, out, error)
      call isys_agree(error)
   end subroutine i_step_agreed

   real(wp) function dtmin_of(model)
      type(model_t), intent(in) :: model
      dtmin_of = model%ctrl%imp%dtmin
      if (dtmin_of <= 0.0_wp) dtmin_of = 1.0e-3_wp*model%ctrl%imp%dt0
   end function dtmin_of

   real(wp) function dtmax_of(model)
      type(model_t), intent(in) :: model
      dtmax_of = model%ctrl%imp%dtmax
      if (dtmax_of <= 0.0_wp) dtmax_of = 10.0_wp*model%ctrl%imp%dt0
   end function dtmax_of

   !> One load step (the first call: the initial state at t = 0).
   subroutine i_step(self, model, dom, ck, out, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tn, h
      integer :: nit
      logical :: ok, changed
      if (self%first) then
         self%first = .false.
         self%t = 0.0_wp
         self%dt = 0.0_wp
         self%done = .false.
         call dom%energies(model, self%kin, model%v, 0.0_wp, 0.0_wp, 0.0_wp, &
            .not. allocated(model%rigid))   ! (rigid: the bodies' own kinetic energy, kin)
         model%energy%ratio = 1.0_wp
         return
      end if
      h = self%h
      do
         tn = self%t + h
         if (tn >= self%tend - 1.0e-9_wp*h) tn = self%tend
         call newton(self, model, tn, tn - self%t, nit, ok, error)
         if (ok) exit
         if (.not. allocated(error)) call set_error(error, 'no convergence', EXIT_NUMERIC)
         if (model%ctrl%imp%iauto /= 1 .or. 0.5_wp*h < dtmin_of(model) .or. &
             error%code == EXIT_INPUT) return
         call log_info('dynx: implicit: '//first_line(error%message)//' (iterations above): '// &
                       'retried at half the step, '//rstr(0.5_wp*h, 4))
         deallocate(error)
         self%ncut = self%ncut + 1
         h = 0.5_wp*h
         self%u = self%uc
      end do
      ! ---- converged: commit, energies, the next step's length
      if (self%dyn) then
         call isys_commit(model, self%sys, tn - self%t, model%ctrl%imp%gamma)
      else
         call isys_commit(model, self%sys, 0.0_wp, 0.0_wp)
      end if
      if (self%dyn) then
         ! work of the applied forces (trapezoid; reactions of SPCs do no work)
         self%wext = self%wext + 0.5_wp*sum((self%rsc + self%fext)*(self%u - self%uc))
         self%vc = self%vc + (tn - self%t)*((1.0_wp - model%ctrl%imp%gamma)*self%ac + &
                                            model%ctrl%imp%gamma*self%at)
         self%ac = self%at
         self%rsc = self%fext
         call isys_fix(self%sys, self%vc)
         self%kin = 0.5_wp*sum(self%m3*self%vc**2) + irig_kinetic(self%sys%rig)
      else
         self%wext = self%wext + 0.5_wp*sum((self%fintc + self%fint)*(self%u - self%uc))
      end if
      self%uc = self%u
      self%fintc = self%fint
      changed = .false.
      if (tn < self%tend) call isys_refind(model, self%sys, self%u, changed, error)
      if (allocated(error)) return
      if (changed) then        ! new contact candidates: the pattern analysed again
         call analyse(self, error)
         if (allocated(error)) return
         call log_info('dynx: implicit: contact candidates re-found: '// &
            str(self%sys%con%np)//' pairs, '//str(self%sys%k%nnz)//' stored entries')
      end if
      model%f = self%fext - self%fint    ! (spcforc: the reactions are -f on the SPC dofs)
      model%x = model%x0 + self%u
      model%v = 0.0_wp
      if (self%dyn) then
         model%v = self%vc
         call irig_velocity(self%sys%rig, model, model%v)
      end if
      self%dt = tn - self%t
      self%t = tn
      self%done = tn >= self%tend
      self%nsteps = self%nsteps + 1
      model%time = tn
      model%cycle = self%nsteps
      model%dt = self%dt
      call dom%energies(model, self%kin, model%v, self%wext, 0.0_wp, 0.0_wp, &
                        .not. allocated(model%rigid))
      if (model%ctrl%imp%iauto == 1) then
         if (nit < model%ctrl%imp%iteopt - model%ctrl%imp%itewin) then
            h = 1.25_wp*h
         else if (nit > model%ctrl%imp%iteopt + model%ctrl%imp%itewin) then
            h = 0.8_wp*h
         end if
         h = min(max(h, dtmin_of(model)), dtmax_of(model))
      end if
      self%h = h
   end subroutine i_step

   function first_line(s) result(l)
      character(*), intent(in) :: s
      character(:), allocatable :: l
      integer :: k
      k = index(s, '; residual history:')
      if (k == 0) k = index(s, new_line('a'))
      if (k == 0) then
         l = s
      else
         l = s(1:k - 1)
      end if
   end function first_line

   !> Newton iterations from the committed state to equilibrium at time tn (step h).
   !> ok: converged; else error holds why (with the residual history).
   subroutine newton(self, model, tn, h, nit, ok, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: tn, h
      integer, intent(out) :: nit
      logical, intent(out) :: ok
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: r0, rn, dn, en, e1, s0, s1, eta, etap, sp, un, eta_new
      integer :: it, ls
      character(:), allocatable :: hist
      character(160) :: line
      character(:), allocatable :: ctxt
      ok = .false.
      nit = 0
      associate (sys => self%sys, imp => model%ctrl%imp)
         self%u = self%uc
         call isys_reset(sys)
         call isys_prescribe(model, sys, tn, self%u)
         call residual(.true.)
         if (allocated(error)) return
         r0 = norm2(self%r)
         e1 = 0.0_wp
         hist = ''
         write(line, '(a,i0,a,es12.5,a,es11.4)') 'dynx: implicit step ', self%nsteps + 1, &
            ', time ', tn, ': |r0| = ', r0
         call log_info(trim(line))
         if (imp%nsolvr /= 1 .and. r0 <= imp%abstol) then
            ok = .true.; return
         end if
         do it = 1, max(1, imp%maxref)
            nit = it
            call factor_solve()
            if (allocated(error)) return
            s0 = dot_product(self%du, self%r)
            if (imp%nsolvr == 1) then       ! linear: one solve, then the stresses
               call isys_scatter(sys, self%du, 1.0_wp, self%u, model)
               call residual(.false.)
               if (allocated(error)) return
               rn = norm2(self%r)
               self%niter = self%niter + 1
               write(line, '(a,es10.3)') '    linear solve: |r|/|r0| after = ', &
                  rn/max(r0, tiny(1.0_wp))
               call log_info(trim(line))
               ok = .true.; return
            end if
            ! ---- line search on s(eta) = du . r(u + eta du)
            eta = 1.0_wp
            call isys_scatter(sys, self%du, eta, self%u, model)
            call residual(.true.)
            if (allocated(error)) return
            s1 = dot_product(self%du, self%r)
            etap = 0.0_wp; sp = s0
            ls = 0
            do while (abs(s1) > imp%lstol*abs(s0) .and. ls < 4)
               ls = ls + 1
               if (sp == s1) exit
               eta_new = eta - s1*(eta - etap)/(s1 - sp)
               eta_new = min(max(eta_new, 0.1_wp), 1.0_wp)
               if (eta_new == eta) exit
               call isys_scatter(sys, self%du, eta_new - eta, self%u, model)
               etap = eta; sp = s1
               eta = eta_new
               call residual(.true.)
               if (allocated(error)) return
               s1 = dot_product(self%du, self%r)
            end do
            ! ---- norms
            rn = norm2(self%r)
            un = norm2(self%u - self%uc)
            dn = eta*norm2(self%du)/max(un, tiny(1.0_wp))
            if (it == 1) e1 = abs(s0)
            en = eta*abs(s0)/max(e1, tiny(1.0_wp))
            write(line, '(a,i3,a,es10.3,a,es10.3,a,es10.3,a,f6.3)') '    iteration', it, &
               ': residual ratio ', rn/max(r0, tiny(1.0_wp)), ', displacement ratio ', dn, &
               ', energy ratio ', en, ', eta ', eta
            ctxt = ''
            if (sys%has_contact) ctxt = ', contact nodes '//str(sys%con%nactive)//' ('// &
                                        str(sys%con%nchanged)//' changed)'
            call log_info(trim(line)//ctxt)
            hist = hist//new_line('a')//trim(line)//ctxt
            self%niter = self%niter + 1
            if ((dn <= imp%dctol .and. en <= imp%ectol .and. rn/max(r0, tiny(1.0_wp)) <= &
                 imp%rctol) .or. rn <= imp%abstol) then
               ok = .true.; return
            end if
         end do
         call set_error(error, 'implicit step at time '//rstr(tn)//' (length '//rstr(h)// &
            ') did not converge in MAXREF = '//str(imp%maxref)//' iterations; residual '// &
            'history:'//hist, EXIT_NUMERIC)
      end associate
   contains
      !> r = f_ext - f_int at self%u over the equations (with want_k: K at u too).
      subroutine residual(want_k)
         logical, intent(in) :: want_k
         real(wp) :: t0
         real(wp), allocatable :: vnet(:, :)
         if (self%sys%linear) then
            model%x = model%x0
         else
            model%x = model%x0 + self%u
         end if
         t0 = wall_time()
         call isys_external(model, tn, self%fext)
         call isys_assemble(model, self%sys, self%u, h, want_k, self%fint, error)
         self%tasm = self%tasm + (wall_time() - t0)
         if (allocated(error)) return
         if (.not. self%dyn) then
            call isys_gather(self%sys, self%fext - self%fint, self%r, model)
            if (want_k .and. isys_root(self%sys)) &     ! (MPI: rank 0 adds it once)
               call irig_geo(self%sys%rig, model, self%fext - self%fint, self%sys%k)
            return
         end if
         ! Newmark: a(n+1) from u(n+1); HHT: r = (1 + alpha)(f_ext - f_int)(n+1)
         ! - alpha (f_ext - f_int)(n) - M a(n+1); K_eff = (1 + alpha) K + M/(beta h^2)
         associate (al => model%ctrl%imp%alpha, be => model%ctrl%imp%beta)
            self%at = (self%u - self%uc - h*self%vc)/(be*h*h) - (0.5_wp/be - 1.0_wp)*self%ac
            vnet = (1.0_wp + al)*(self%fext - self%fint) - al*(self%rsc - self%fintc) - &
                   self%m3*self%at
            call isys_gather(self%sys, vnet, self%r, model)
            if (want_k) then
               self%sys%k%a = (1.0_wp + al)*self%sys%k%a
               if (isys_root(self%sys)) then     ! (MPI: rank 0 adds them once)
                  self%sys%k%a(self%sys%k%dg) = &
                     self%sys%k%a(self%sys%k%dg) + self%meq/(be*h*h)
                  call irig_geo(self%sys%rig, model, vnet, self%sys%k)
               end if
            end if
            call irig_inertia(self%sys%rig, h, be, want_k .and. isys_root(self%sys), self%r, &
                              self%sys%k)
         end associate
      end subroutine residual

      !> du = K^-1 r (a singular K: the free nodes and modes).
      subroutine factor_solve()
         real(wp) :: t0, c0, c1
         t0 = wall_time()
         ! NSOLVR 1 takes elastic materials only: K (and K_eff at the same step) is the same
         ! matrix every step, so its factorization is kept
         if (.not. (self%sys%linear .and. h == self%hfac)) then
            call isys_sum_entries(self%sys)        ! (MPI: each entry on its owner)
            call cpu_time(c0)
            call self%ms%factor(self%sys%k, error)
            call cpu_time(c1)
            self%cfac = self%cfac + (c1 - c0)
            if (allocated(error)) return
            self%nfactor = self%nfactor + 1
            if (self%sys%linear .and. self%ms%nnull == 0) self%hfac = h
         end if
         if (self%ms%nnull > 0) then
            call singular(self, model, tn, error)
            return
         end if
         self%du = self%r
         call self%ms%solve(self%du, error)
         call isys_bcast(self%sys, self%du)     ! (MPI: the host's solution)
         self%tfac = self%tfac + (wall_time() - t0)
      end subroutine factor_solve
   end subroutine newton

   !> The singular-stiffness message: the null pivots' nodes and the rigid-body modes
   !> (3 translations, 3 rotations about the centroid) that K does not resist,
   !> |K m| <= 1e-8 max|diag K| |m| on the free equations. Exit 2 at the first step (the
   !> deck lacks constraints), 3 later (a material or geometry lost its stiffness).
   subroutine singular(self, model, tn, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: tn
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: m(:, :), mv(:), km(:)
      real(wp) :: xc(3), kmax, x(3)
      integer :: k, i, code
      character(:), allocatable :: modes, nodes, hint
      character(16), parameter :: names(6) = [character(16) :: 'translation x', 'translation y', &
         'translation z', 'rotation about x', 'rotation about y', 'rotation about z']
      allocate(m(3, model%nn), mv(self%sys%neq), km(self%sys%neq))
      call isys_global(self%sys)                        ! (MPI: the whole K, the host's
      call isys_bcast_int(self%sys, self%ms%null_eq)    ! null pivots on every rank)
      xc = sum(model%x0, dim=2)/real(max(1, model%nn), wp)
      kmax = 0.0_wp
      do i = 1, self%sys%neq
         kmax = max(kmax, abs(self%sys%k%a(self%sys%k%dg(i))))
      end do
      modes = ''
      do k = 1, 6
         m = 0.0_wp
         do i = 1, model%nn
            x = model%x0(:, i) - xc
            select case (k)
            case (1:3)
               m(k, i) = 1.0_wp
            case (4)
               m(:, i) = [0.0_wp, -x(3), x(2)]
            case (5)
               m(:, i) = [x(3), 0.0_wp, -x(1)]
            case default
               m(:, i) = [-x(2), x(1), 0.0_wp]
            end select
         end do
         call isys_gather(self%sys, m, mv)
         if (norm2(mv) == 0.0_wp) cycle
         call sparse_matvec(self%sys%k, mv, km)
         if (norm2(km) <= 1.0e-8_wp*kmax*norm2(mv)) then
            if (len(modes) > 0) modes = modes//', '
            modes = modes//trim(names(k))
         end if
      end do
      nodes = isys_null_names(model, self%sys, self%ms%null_eq(1:self%ms%nnull))
      if (len(modes) == 0) modes = 'none of the whole model''s rigid-body modes (a part '// &
         'or a node is free on its own)'
      code = EXIT_NUMERIC
      if (self%nsteps == 0 .and. self%niter == 0) code = EXIT_INPUT
      hint = ' (missing *BOUNDARY_SPC constraints?)'
      if (self%sys%has_contact) hint = ' (missing *BOUNDARY_SPC constraints? With contact: '// &
         'a body held only by contact that lost it, or whose contact nodes all slip, has no '// &
         'stiffness along the slip: a load above the friction has no static equilibrium)'
      call set_error(error, 'singular stiffness at time '//rstr(tn)//': '// &
         str(self%ms%nnull)//' zero pivot(s) at '//nodes//'; free rigid-body modes: '// &
         modes//hint, code)
   end subroutine singular

   !> The factorizations' CPU time and elimination flops (MUMPS RINFO(3)) of each process
   !> (the MPI balance; noisy wall times on a shared machine are not needed to read it).
   subroutine factor_report(self)
      class(implicit_t), intent(in) :: self
      real(wp), allocatable :: c(:), f(:)
      character(:), allocatable :: t
      integer :: r
      c = isys_per_rank(self%cfac)
      f = isys_per_rank(self%ms%flops)
      t = ''
      do r = 1, min(size(c), 16)
         if (r > 1) t = t//'; '
         t = t//'rank '//str(r - 1)//' '//rstr(c(r), 3)//' s, '//rstr(f(r), 3)//' flops'
      end do
      call log_info('dynx: implicit: factorizations, CPU time and elimination flops per '// &
         'process: '//t//' (largest CPU '//rstr(maxval(c), 3)//' s, total '// &
         rstr(sum(c), 3)//' s)')
   end subroutine factor_report

   !> The cycle boundary: the converged step's time.
   subroutine i_advance(self, model, ck)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      type(checkpoint_t), intent(inout) :: ck
      model%time = self%t
      model%cycle = self%nsteps
      call checkpoint_requests(ck, model, isys_max_flags)   ! (MPI: reduced; else no-op)
   end subroutine i_advance

   subroutine i_close(self, model, dom, ck, out, how, error)
      class(implicit_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      integer, intent(in) :: how
      type(error_t), allocatable, intent(inout) :: error
      type(error_t), allocatable :: ioerr
      ! (MPI: a failure of one rank alone aborts the run: no collective call then)
      if (how /= END_FAILED .or. isys_agreed(self%sys)) call self%ms%finish()
      if (how == END_STOPPED) return
      if (how == END_NORMAL) call factor_report(self)
      model%time = self%t
      if (how == END_FAILED) then
         if (allocated(self%uc)) model%x = model%x0 + self%uc   ! the last converged state
         if (allocated(self%vc)) model%v = self%vc
         call dom%write_plot(model, out, ioerr)
         if (allocated(ioerr)) deallocate(ioerr)
         if (dom%writer()) call out%close(ioerr)
         if (allocated(ioerr)) deallocate(ioerr)
         if (allocated(error)) error%message = error%message//new_line('a')// &
            'dynx: the last converged state (time '//rstr(self%t)//') was written to the plot file'
         return
      end if
      call log_info('dynx: normal termination at step '//str(self%nsteps)//', time '// &
         rstr(self%t)//': '//str(self%niter)//' iterations (solves), '//str(self%nfactor)// &
         ' factorizations, '//str(self%ncut)//' step cuts')
      call log_info('dynx: wall time '//rstr(wall_time() - self%t0wall, 4)//' s (MUMPS '// &
         'analysis '//rstr(self%tana, 3)//' s before it, factorizations and solves '// &
         rstr(self%tfac, 3)//' s, assembly '//rstr(self%tasm, 3)//' s), peak memory '// &
         str(peak_memory_kb())//' KiB')
      call close_files(dom, out, error)
   end subroutine i_close
end module dx_implicit
