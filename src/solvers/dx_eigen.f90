!> The eigenvalue run (*CONTROL_IMPLICIT_EIGENVALUE with *CONTROL_IMPLICIT_GENERAL IMFLAG =
!> 1; issue 20): the NEIG natural modes of the undeformed model, K phi = omega^2 M phi, an
!> integrator_t behind dx_solver's run_driver whose "steps" are the modes.
!>   K: the implicit system's tangent at u = 0 (dx_implicit_system: the linear stiffness of
!>      the B-bar hexahedron and the tetrahedron, constraints by elimination);
!>   M: the lumped (diagonal) mass of the explicit solver, model%mass (dynx's choice, stated:
!>      the consistent mass of CalculiX gives higher frequencies; both converge to the
!>      continuum at O(h^2));
!>   shift sigma = (2 pi CENTER)^2, the modes nearest it by shift-invert Lanczos (dx_lanczos:
!>      ARPACK mode 3 with the MUMPS factorization of K - sigma M, dx_mumps). LS-DYNA's
!>      block shift-and-invert Lanczos is the same idea (Grimes, Lewis & Simon, "A shifted
!>      block Lanczos algorithm for solving sparse symmetric generalized eigenproblems",
!>      SIAM J. Matrix Anal. Appl. 15 (1994) 228-272).
!>   A singular K - sigma M at CENTER = 0 (a free body: its rigid-body modes) is shifted to
!>      sigma = -(2 pi SHFSCL)^2, or with SHFSCL = 0 to -1e-5 max_i K_ii/M_ii (about 1e-5
!>      of the largest omega^2: far below the first flexible mode of any mesh, far above
!>      MUMPS's null-pivot threshold); the rigid-body modes then come out as omega^2 ~ 0.
!>      Singular still (a node with neither stiffness nor mass), or at CENTER > 0 (CENTER is
!>      an eigenfrequency): an input error naming the keyword, its line and the free dofs.
!> Output: `eigout` (LS-DYNA's layout: mode, eigenvalue omega^2, omega in radians, cycles and
!> period per unit time; written to eigout.tmp and renamed) and one plot state per mode:
!> x = x0 + phi (phi M-orthonormal, its largest entry positive), the state's time the mode's
!> frequency in cycles (LS-DYNA's d3eigv convention). Serial only, like the Newton solver.
module dx_eigen
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC, EXIT_INPUT, EXIT_IO
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_timer, only: wall_time, peak_memory_kb
   use dx_io_sys, only: sys_rename
   use dx_model, only: model_t
   use dx_output, only: output_t
   use dx_checkpoint, only: checkpoint_t
   use dx_domain, only: domain_t
   use dx_integrator, only: integrator_t, run_options_t, END_STOPPED, serial_fresh_only, &
                            close_files
   use dx_explicit, only: init_state
   use dx_mumps, only: mumps_t
   use dx_lanczos, only: lanczos_modes
   use dx_implicit_system, only: implicit_system_t, isys_setup, isys_assemble, isys_comm, &
                                 isys_gather, isys_scatter, isys_null_names, isys_nranks, &
                                 isys_agree
   implicit none
   private
   public :: eigen_t

   real(wp), parameter :: TWO_PI = 6.283185307179586476925286766559_wp

   type, extends(integrator_t) :: eigen_t
      type(implicit_system_t) :: sys
      type(mumps_t) :: ms
      real(wp), allocatable :: lam(:), phi(:, :)
      real(wp) :: sigma = 0.0_wp
      integer :: imode = 0
      real(wp) :: t0wall = 0.0_wp
   contains
      procedure :: start => e_start
      procedure :: step => e_step
      procedure :: advance => e_advance
      procedure :: close => e_close
   end type eigen_t

contains

   subroutine e_start(self, model, dom, opts, ck, out, error)
      class(eigen_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(run_options_t), intent(in) :: opts
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: u(:, :), f(:, :), meq(:), kd(:), z(:, :)
      real(wp) :: t0, tfac
      integer :: neq, nops
      character(:), allocatable :: at
      self%t0wall = wall_time()
      if (ck%wall0 <= 0.0_wp) ck%wall0 = self%t0wall
      associate (imp => model%ctrl%imp)
         at = '*CONTROL_IMPLICIT_EIGENVALUE: '
         if (imp%eig_ifile > 0 .and. allocated(model%deck_files)) at = &
            model%deck_files(imp%eig_ifile)%s//':'//str(imp%eig_line)//': '//at
         if (isys_nranks() > 1) then      ! (the domain is replicated: see dx_domain_mpi)
            call set_error(error, at//'the eigenvalue run is not yet in an MPI run (the '// &
               'implicit statics and dynamics are); run this deck serially (without mpirun)', &
               EXIT_INPUT)
            call isys_agree(error)       ! (every rank refuses: one message, no MPI_Abort)
            return
         end if
         call serial_fresh_only(model, dom, 'eigenvalue run', '', error)
         if (allocated(error)) return
         if (.not. allocated(model%x)) call init_state(model, dom)
         model%v = 0.0_wp
         call isys_setup(model, self%sys, error)
         if (allocated(error)) return
         neq = self%sys%neq
         if (imp%neig >= neq) then
            call set_error(error, at//'field NEIG: '//str(imp%neig)//' modes asked of a '// &
               'model with '//str(neq)//' free dofs (at most '//str(neq - 1)//')', EXIT_INPUT)
            return
         end if
         ! K at u = 0 and the lumped M per equation
         allocate(u(3, model%nn), f(3, model%nn), meq(neq), kd(neq))
         u = 0.0_wp
         model%x = model%x0
         call isys_assemble(model, self%sys, u, 1.0_wp, .true., f, error)
         if (allocated(error)) return
         call isys_gather(self%sys, spread(model%mass, 1, 3), meq)
         kd = self%sys%k%a(self%sys%k%dg)
         t0 = wall_time()
         call self%ms%analyse(self%sys%k, isys_comm(), error)
         if (allocated(error)) return
         self%sigma = (TWO_PI*imp%center)**2
         call factor_shifted()
         if (allocated(error)) return
         if (self%ms%nnull > 0 .and. imp%center == 0.0_wp) then
            if (imp%shfscl > 0.0_wp) then
               self%sigma = -(TWO_PI*imp%shfscl)**2
            else
               self%sigma = -1.0e-5_wp*maxval(kd/max(meq, tiny(1.0_wp)), mask=meq > 0.0_wp)
            end if
            call log_info('dynx: eigen: K is singular (a free body: '//str(self%ms%nnull)// &
               ' zero pivots); shifted to sigma = '//rstr(self%sigma, 6))
            call factor_shifted()
            if (allocated(error)) return
         end if
         if (self%ms%nnull > 0) then
            call singular_message()
            return
         end if
         call lanczos_modes(self%ms, meq, self%sigma, imp%neig, 300, self%lam, z, nops, error)
         if (allocated(error)) return
         tfac = wall_time() - t0
         allocate(self%phi(3*model%nn, imp%neig))
         block
            integer :: i
            real(wp) :: v(3, model%nn)
            do i = 1, imp%neig
               v = 0.0_wp
               call isys_scatter(self%sys, z(:, i), 1.0_wp, v)
               self%phi(:, i) = reshape(v, [3*model%nn])
            end do
         end block
         call log_info('dynx: eigen: '//str(imp%neig)//' modes of '//str(neq)//' equations '// &
            '(lumped mass) nearest sigma = '//rstr(self%sigma, 6)//' (CENTER '// &
            rstr(imp%center, 6)//'): shift-invert Lanczos (ARPACK), '//str(nops)// &
            ' solves, '//rstr(tfac, 3)//' s with the MUMPS analysis and factorization')
         if (dom%writer()) call write_eigout(opts%outdir, self%lam, self%sigma, error)
         if (allocated(error)) return
         if (model%ctrl%endtim > 0.0_wp) call log_info('dynx: eigen: note: the eigenvalue '// &
            'run ends after the modes (ENDTIM '//rstr(model%ctrl%endtim, 4)//' is not stepped)')
      end associate
      self%tend = real(model%ctrl%imp%neig, wp)
      self%histories = .false.
      self%energies = .false.
      self%imode = 0
   contains
      !> K - sigma M factored (the diagonal of the assembled K shifted)
      subroutine factor_shifted()
         self%sys%k%a(self%sys%k%dg) = kd - self%sigma*meq
         call self%ms%factor(self%sys%k, error)
      end subroutine factor_shifted

      subroutine singular_message()
         character(:), allocatable :: nodes
         nodes = isys_null_names(model, self%sys, self%ms%null_eq(1:self%ms%nnull))
         if (model%ctrl%imp%center > 0.0_wp) then
            call set_error(error, at//'field CENTER: K - sigma M is singular at the shift '// &
               'sigma = (2 pi CENTER)^2 = '//rstr(self%sigma)//' ('//str(self%ms%nnull)// &
               ' zero pivots at '//nodes//'): CENTER is an eigenfrequency, or dofs have '// &
               'neither stiffness nor mass; move CENTER', EXIT_INPUT)
         else
            call set_error(error, at//'field SHFSCL: singular stiffness even with the '// &
               'shift sigma = '//rstr(self%sigma)//': '//str(self%ms%nnull)//' zero '// &
               'pivot(s) at '//nodes//' (dofs with neither stiffness nor mass: a node '// &
               'in no element?)', EXIT_INPUT)
         end if
      end subroutine singular_message
   end subroutine e_start

   !> eigout: LS-DYNA's table (mode, eigenvalue, radians, cycles, period), frequencies of
   !> the positive eigenvalues only (a rigid-body mode's round-off omega^2 <= 0: zeros).
   subroutine write_eigout(outdir, lam, sigma, error)
      character(*), intent(in) :: outdir
      real(wp), intent(in) :: lam(:), sigma
      type(error_t), allocatable, intent(out) :: error
      integer :: u, i, ios
      real(wp) :: w, f, p
      logical :: bad
      open(newunit=u, file=outdir//'/eigout.tmp', status='replace', action='write', &
           iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'cannot write '//outdir//'/eigout.tmp', EXIT_IO); return
      end if
      bad = .false.
      write(u, '(a)', iostat=ios) ' dynx eigenvalue analysis: shift-invert Lanczos (ARPACK, '// &
         'MUMPS), lumped mass, shift sigma = '//rstr(sigma, 9)
      bad = bad .or. ios /= 0
      write(u, '(a/a/a/a/a)', iostat=ios) '', ' results of eigenvalue analysis:', &
         ' (frequencies are calculated only for positive eigenvalues.)', '', &
         '    MODE     EIGENVALUE         RADIANS          CYCLES          PERIOD'
      bad = bad .or. ios /= 0
      do i = 1, size(lam)
         w = 0.0_wp; f = 0.0_wp; p = 0.0_wp
         if (lam(i) > 0.0_wp) then
            w = sqrt(lam(i)); f = w/TWO_PI; p = 1.0_wp/f
         end if
         write(u, '(i8,4es16.8)', iostat=ios) i, lam(i), w, f, p
         bad = bad .or. ios /= 0
      end do
      close(u, iostat=ios)
      if (bad .or. ios /= 0) then   ! (a failed write never replaces a good eigout)
         call set_error(error, 'cannot write '//outdir//'/eigout.tmp', EXIT_IO); return
      end if
      call sys_rename(outdir//'/eigout.tmp', outdir//'/eigout', error)
   end subroutine write_eigout

   !> One mode: its plot state (time = its frequency in cycles).
   subroutine e_step(self, model, dom, ck, out, error)
      class(eigen_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      self%imode = self%imode + 1
      i = self%imode
      model%x = model%x0 + reshape(self%phi(:, i), [3, model%nn])
      model%v = 0.0_wp
      model%time = sqrt(max(self%lam(i), 0.0_wp))/TWO_PI
      model%cycle = i
      call dom%write_plot(model, out, error)
      self%t = real(i, wp)
      self%dt = 1.0_wp
      self%done = i >= size(self%lam)
   end subroutine e_step

   subroutine e_advance(self, model, ck)
      class(eigen_t), intent(inout) :: self
      type(model_t), intent(inout) :: model
      type(checkpoint_t), intent(inout) :: ck
   end subroutine e_advance

   subroutine e_close(self, model, dom, ck, out, how, error)
      class(eigen_t), intent(inout) :: self
      type(model_t), intent(inout), target :: model
      class(domain_t), intent(inout) :: dom
      type(checkpoint_t), intent(inout) :: ck
      type(output_t), intent(inout) :: out
      integer, intent(in) :: how
      type(error_t), allocatable, intent(inout) :: error
      call self%ms%finish()
      if (how == END_STOPPED) return
      call close_files(dom, out, error)     ! (serial only: the plot finish does nothing)
      if (allocated(error)) return
      call log_info('dynx: normal termination: '//str(self%imode)//' modes, wall time '// &
         rstr(wall_time() - self%t0wall, 4)//' s, peak memory '//str(peak_memory_kb())//' KiB')
   end subroutine e_close
end module dx_eigen
