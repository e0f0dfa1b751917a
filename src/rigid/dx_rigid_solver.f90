!> Rigid-body integration in the explicit cycle. Called once per cycle after all nodal forces
!> (element, external, contact) are summed into model%f and the free nodal velocities are
!> updated; it overwrites the velocities of rigid nodes.
!> Translation: central difference on the centre of mass, vc(n+1/2) = vc(n-1/2) + dtavg F/M.
!> Rotation: the symplectic splitting of Dullweber, Leimkuhler & McLachlan (1997, J Chem
!> Phys 107:5840): a kick of the spatial angular momentum, L(n+1/2) = L(n-1/2) + dtavg T(n),
!> then the free rotor over dt split into exact rotations about the principal axes,
!> R1(dt/2) R2(dt/2) R3(dt) R2(dt/2) R1(dt/2). Every sub-step is an exact rotation (cos, sin),
!> so R stays orthogonal and the spatial angular momentum is kept to round-off under zero
!> torque; the kinetic energy is not exactly conserved but stays bounded (symplectic,
!> second order, no drift). A body with constrained or prescribed rotations instead turns by
!> the exact exponential map (Rodrigues) of its constrained angular velocity.
!> Nodes follow the body, x_i(n+1) = x_c(n+1) + R(n+1) s_i; their mid-step velocities are the
!> secants (x_i(n+1) - x_i(n))/dt, so the solver's x += dt v lands on them.
!> Energy bookkeeping (docs/history.md): the body kinetic energy at t(n) is
!> 1/2 M vc(n-1/2).vc(n+1/2) + 1/2 L(n-1/2).I(n)^-1 L(n+1/2), which replaces the nodal
!> kinetic energy of its nodes (ke_corr); constraint and prescribed-motion reactions do the
!> work dP.(vc(n-1/2) + vc(n+1/2))/2 + dL.(w(n-1/2) + w(n+1/2))/2, like nodal constraints.
module dx_rigid_solver
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_strings, only: str
   use dx_model, only: model_t
   use dx_rigid_types, only: rigid_system_t, rigid_body_t
   use dx_rigid_mass, only: rotation_about
   use dx_load_body, only: base_acceleration
   use dx_append_file, only: append_from
   implicit none
   private
   public :: rigid_step, rigid_write_rbdout, rigid_close
   !> the pieces of a body's step for a caller that sums the nodal terms itself (exactly,
   !> over the ranks: dx_rigid_exact): the nodes' terms, the body's advance from the sums,
   !> the nodes' motion
   public :: rigid_begin, rigid_node_terms, rigid_body_advance, rigid_node_motion

contains

   !> Advance every rigid body over t(n) -> t(n+1); vold: nodal velocities v(n-1/2).
   subroutine rigid_step(rs, model, t, dt, dtavg, vold)
      type(rigid_system_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg
      real(wp), intent(in) :: vold(:, :)
      real(wp) :: grav(3)
      integer :: b
      logical :: body_loads
      call rigid_begin(rs, model, t, grav, body_loads)
      do b = 1, size(rs%bodies)
         call step_body(rs, rs%bodies(b), model, t, dt, dtavg, vold, grav, body_loads)
      end do
   end subroutine rigid_step

   !> The start of a rigid stage: the base acceleration of the body loads, the corrections
   !> zeroed.
   subroutine rigid_begin(rs, model, t, grav, body_loads)
      type(rigid_system_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(out) :: grav(3)
      logical, intent(out) :: body_loads
      body_loads = allocated(model%body_loads)
      grav = 0.0_wp
      if (body_loads) grav = base_acceleration(model%body_loads, model%curves, t)
      rs%ke_corr = 0.0_wp
      rs%p_corr = 0.0_wp
      rs%ke_body = 0.0_wp
      rs%p_body = 0.0_wp
   end subroutine rigid_begin

   !> Node nd's terms in body bd's sums at t(n): its force tf, the moment about the centre
   !> of mass r x f (tq) and its own moment tm (a node with rotations), its mass m and m r.
   subroutine rigid_node_terms(bd, model, nd, tf, tq, tm, m, mr)
      type(rigid_body_t), intent(in) :: bd
      type(model_t), intent(in) :: model
      integer, intent(in) :: nd
      real(wp), intent(out) :: tf(3), tq(3), tm(3), m, mr(3)
      real(wp) :: r(3)
      r = model%x(:, nd) - bd%xc
      tf = model%f(:, nd)
      tq = cross(r, model%f(:, nd))
      tm = 0.0_wp
      if (allocated(model%mom)) tm = model%mom(:, nd)
      m = model%mass(nd)
      mr = model%mass(nd)*r
   end subroutine rigid_node_terms

   !> Node nd (position i of the body's nodes) follows the body to x(n+1): its secant
   !> velocity (and, with rotations, w = omega, no nodal rotary inertia); ke = m
   !> v(n-1/2).v(n+1/2) and p = m v(n+1/2), the nodal terms the body's replace.
   subroutine rigid_node_motion(bd, model, i, nd, dt, vold, ke, p)
      type(rigid_body_t), intent(in) :: bd
      type(model_t), intent(inout) :: model
      integer, intent(in) :: i, nd
      real(wp), intent(in) :: dt, vold(:, :)
      real(wp), intent(out) :: ke, p(3)
      real(wp) :: xn(3)
      xn = bd%xc + matmul(bd%rot, bd%s(:, i))
      model%v(:, nd) = (xn - model%x(:, nd))/dt
      ke = model%mass(nd)*dot_product(vold(:, nd), model%v(:, nd))
      p = model%mass(nd)*model%v(:, nd)
      if (allocated(model%mom)) then
         model%w(:, nd) = bd%omega
         model%rinert(nd) = 0.0_wp
      end if
   end subroutine rigid_node_motion

   subroutine step_body(rs, bd, model, t, dt, dtavg, vold, grav, body_loads)
      type(rigid_system_t), intent(inout) :: rs
      type(rigid_body_t), intent(inout) :: bd
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: t, dt, dtavg, vold(:, :), grav(3)
      logical, intent(in) :: body_loads
      real(wp) :: f(3), tq(3), mn, sm(3), tf(3), ttq(3), tm(3), m, mr(3), ke, p(3), ke_n
      integer :: i
      ! resultant force and torque about the centre of mass at t(n); a node with rotations
      ! (a shell's, as an extra node) adds its moment
      f = 0.0_wp; tq = 0.0_wp; mn = 0.0_wp; sm = 0.0_wp
      do i = 1, size(bd%nodes)
         call rigid_node_terms(bd, model, bd%nodes(i), tf, ttq, tm, m, mr)
         f = f + tf
         tq = tq + ttq + tm
         mn = mn + m
         sm = sm + mr
      end do
      call rigid_body_advance(rs, bd, model, t, dt, dtavg, f, tq, mn, sm, grav, body_loads)
      ! nodes: secant velocities onto x(n+1); nodal KE and momentum they replace
      ke_n = 0.0_wp
      do i = 1, size(bd%nodes)
         call rigid_node_motion(bd, model, i, bd%nodes(i), dt, vold, ke, p)
         ke_n = ke_n + ke
         rs%p_corr = rs%p_corr - p
      end do
      rs%ke_corr = rs%ke_corr - 0.5_wp*ke_n
   end subroutine step_body

   !> Body bd over t(n) -> t(n+1) from the sums over its nodes at t(n): force f, torque tq
   !> about the centre (r x f plus nodal moments), nodal mass mn and first moment sm. Adds
   !> the body's kinetic energy and momentum to ke_corr, p_corr (and ke_body, p_body).
   subroutine rigid_body_advance(rs, bd, model, t, dt, dtavg, fin, tqin, mn, sm, grav, &
                                 body_loads)
      type(rigid_system_t), intent(inout) :: rs
      type(rigid_body_t), intent(inout) :: bd
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t, dt, dtavg, fin(3), tqin(3), mn, sm(3), grav(3)
      logical, intent(in) :: body_loads
      real(wp) :: f(3), tq(3), df(3), dtq(3), ten(3, 3), tinv(3, 3)
      real(wp) :: vc_old(3), l_old(3), w_old(3), vfree(3), lfree(3), vnew(3), lnew(3), w(3)
      real(wp) :: wpres(3), pimom(3), rk(3, 3), val, keb
      logical :: pres(3), rotc
      integer :: k, d
      integer, parameter :: axis(5) = [1, 2, 3, 2, 1]
      real(wp), parameter :: frac(5) = [0.5_wp, 0.5_wp, 1.0_wp, 0.5_wp, 0.5_wp]
      f = fin
      tq = tqin
      ! body loads act on the body mass at its centre, not on the lumped nodal masses
      df = 0.0_wp; dtq = 0.0_wp
      if (body_loads) then
         df = -(bd%mass - mn)*grav
         dtq = cross(sm, grav)
         f = f + df
         tq = tq + dtq
      end if
      bd%fsum = f
      bd%tsum = tq
      ten = matmul(bd%rot, matmul(diag(bd%ip), transpose(bd%rot)))
      tinv = matmul(bd%rot, matmul(diag(1.0_wp/bd%ip), transpose(bd%rot)))
      vc_old = bd%vc
      l_old = bd%lsp
      w_old = matmul(tinv, l_old)
      ! kick
      vfree = vc_old + dtavg*f/bd%mass
      lfree = l_old + dtavg*tq
      ! constraints and prescribed motion
      vnew = vfree
      where (bd%fix_t) vnew = 0.0_wp
      pres = bd%fix_r
      wpres = 0.0_wp
      if (allocated(bd%motions)) then
         do k = 1, size(bd%motions)
            associate (pm => bd%motions(k))
               if (t < pm%birth .or. t > pm%death) cycle
               d = pm%dof
               if (d >= 5) d = d - 4
               select case (pm%vad)
               case (0)
                  val = pm%sf*model%curves(pm%curve)%eval(t + 0.5_wp*dt)
               case (1)
                  if (pm%dof <= 3) then
                     val = vc_old(d) + dtavg*pm%sf*model%curves(pm%curve)%eval(t)
                  else
                     val = w_old(d) + dtavg*pm%sf*model%curves(pm%curve)%eval(t)
                  end if
               case default
                  val = (pm%sf*model%curves(pm%curve)%eval(t + dt) - pm%disp)/dt
               end select
               pm%disp = pm%disp + dt*val
               if (pm%dof <= 3) then
                  vnew(d) = val
               else
                  pres(d) = .true.
                  wpres(d) = val
               end if
            end associate
         end do
      end if
      rotc = any(pres)
      if (rotc) then
         w = constrained_omega(ten, lfree, pres, wpres)
         lnew = matmul(ten, w)
      else
         lnew = lfree
         w = matmul(tinv, lnew)
      end if
      rs%work = rs%work + bd%mass*dot_product(vnew - vfree, 0.5_wp*(vc_old + vnew)) &
                + dot_product(lnew - lfree, 0.5_wp*(w_old + w)) &
                + dtavg*(dot_product(df, 0.5_wp*(vc_old + vnew)) + &
                         dot_product(dtq, 0.5_wp*(w_old + w)))
      ! body kinetic energy at t(n), momentum at t(n+1/2)
      keb = 0.5_wp*bd%mass*dot_product(vc_old, vnew) + 0.5_wp*dot_product(l_old, w)
      rs%ke_corr = rs%ke_corr + keb
      rs%p_corr = rs%p_corr + bd%mass*vnew
      rs%ke_body = rs%ke_body + keb
      rs%p_body = rs%p_body + bd%mass*vnew
      bd%vc = vnew
      bd%lsp = lnew
      bd%omega = w
      bd%xc_n = bd%xc
      bd%rot_n = bd%rot
      ! drift
      bd%xc = bd%xc + dt*vnew
      if (rotc) then
         bd%rot = matmul(rodrigues(dt*w), bd%rot)
      else
         pimom = matmul(transpose(bd%rot), lnew)
         do k = 1, 5
            rk = rotation_about(axis(k), frac(k)*dt*pimom(axis(k))/bd%ip(axis(k)))
            pimom = matmul(transpose(rk), pimom)
            bd%rot = matmul(bd%rot, rk)
         end do
      end if
   end subroutine rigid_body_advance

   pure function diag(a) result(m)
      real(wp), intent(in) :: a(3)
      real(wp) :: m(3, 3)
      m = 0.0_wp
      m(1, 1) = a(1); m(2, 2) = a(2); m(3, 3) = a(3)
   end function diag

   !> Angular velocity with the components pres(:) prescribed to wp(:) and the others free:
   !> the reaction torque acts only about the prescribed axes, so the free rows of I w = L
   !> hold with the unconstrained momentum lfree.
   pure function constrained_omega(ten, lfree, pres, wpv) result(w)
      real(wp), intent(in) :: ten(3, 3), lfree(3), wpv(3)
      real(wp) :: w(3)
      logical, intent(in) :: pres(3)
      real(wp) :: a(3, 3), rhs(3), det
      integer :: fr(3), nf, i, j
      w = wpv
      nf = 0
      do i = 1, 3
         if (.not. pres(i)) then
            nf = nf + 1
            fr(nf) = i
         end if
      end do
      if (nf == 0) return
      do i = 1, nf
         rhs(i) = lfree(fr(i))
         do j = 1, 3
            if (pres(j)) rhs(i) = rhs(i) - ten(fr(i), j)*wpv(j)
         end do
         do j = 1, nf
            a(i, j) = ten(fr(i), fr(j))
         end do
      end do
      select case (nf)
      case (1)
         w(fr(1)) = rhs(1)/a(1, 1)
      case (2)
         det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
         w(fr(1)) = (rhs(1)*a(2, 2) - a(1, 2)*rhs(2))/det
         w(fr(2)) = (a(1, 1)*rhs(2) - a(2, 1)*rhs(1))/det
      end select
   end function constrained_omega

   !> exp([phi]x): the rotation by |phi| about phi/|phi| (Rodrigues' formula)
   pure function rodrigues(phi) result(r)
      real(wp), intent(in) :: phi(3)
      real(wp) :: r(3, 3)
      real(wp) :: th, k(3), kx(3, 3)
      integer :: i
      r = 0.0_wp
      do i = 1, 3
         r(i, i) = 1.0_wp
      end do
      th = norm2(phi)
      if (th == 0.0_wp) return
      k = phi/th
      kx = reshape([0.0_wp, k(3), -k(2), -k(3), 0.0_wp, k(1), k(2), -k(1), 0.0_wp], [3, 3])
      r = r + sin(th)*kx + (1.0_wp - cos(th))*matmul(kx, kx)
   end function rodrigues

   !> One rbdout block at time t(n): per body, centre x_c(n), velocity vc(n+1/2), spatial and
   !> body-frame angular velocity and spatial angular momentum at t(n+1/2), the kinetic energy
   !> from them, and R(n) (columns: principal axes in global components).
   subroutine rigid_write_rbdout(rs, dir, t, error)
      type(rigid_system_t), intent(inout) :: rs
      character(*), intent(in) :: dir
      real(wp), intent(in) :: t
      type(error_t), allocatable, intent(out) :: error
      integer :: b, ios
      real(wp) :: wb(3), ke, ten(3, 3)
      character(256) :: msg
      if (.not. rs%rbdout_open .and. rs%rbdout_resume > 0) then
         ! continued run (dx_rigid_restart): cut back to the dump point and append
         call append_from(dir//'/rbdout', rs%rbdout_resume, rs%rbdout_unit, error)
         if (allocated(error)) return
         rs%rbdout_open = .true.
      end if
      if (.not. rs%rbdout_open) then
         open(newunit=rs%rbdout_unit, file=dir//'/rbdout', status='replace', &
              action='write', iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call set_error(error, dir//'/rbdout: cannot open: '//trim(msg), EXIT_IO)
            return
         end if
         write(rs%rbdout_unit, '(a)') '# dynx rbdout: rigid body state (docs/output-format.md)'
         ! the names line without '#' (gnuplot's columnhead form; the '# body' lines after it
         ! are comments to gnuplot; docs/output-format.md)
         write(rs%rbdout_unit, '(a)') 'time body xc yc zc vx vy vz wx wy wz w1 w2 w3 '// &
            'lx ly lz ke r11 r21 r31 r12 r22 r32 r13 r23 r33'
         rs%rbdout_open = .true.
         do b = 1, size(rs%bodies)
            associate (bd => rs%bodies(b))
               ten = matmul(bd%rot_n, matmul(diag(bd%ip), transpose(bd%rot_n)))
               write(rs%rbdout_unit, '(a,i10,a,i8,a,es24.15e3,a,3es24.15e3,a,6es24.15e3)') &
                  '# body ', bd%label, ' nodes ', size(bd%nodes), ' mass ', bd%mass, &
                  ' xc ', bd%xc_n, ' inertia(xx xy xz yy yz zz) ', ten(1, 1), ten(1, 2), &
                  ten(1, 3), ten(2, 2), ten(2, 3), ten(3, 3)
            end associate
         end do
      end if
      do b = 1, size(rs%bodies)
         associate (bd => rs%bodies(b))
            wb = matmul(transpose(bd%rot_n), bd%omega)
            ke = 0.5_wp*bd%mass*dot_product(bd%vc, bd%vc) + 0.5_wp*dot_product(bd%omega, bd%lsp)
            write(rs%rbdout_unit, '(es23.15e3,i10,25es24.15e3)', iostat=ios) t, bd%label, &
               bd%xc_n, bd%vc, bd%omega, wb, bd%lsp, ke, bd%rot_n
            if (ios /= 0) then
               call set_error(error, dir//'/rbdout: write failed', EXIT_IO)
               return
            end if
         end associate
      end do
   end subroutine rigid_write_rbdout

   !> Close the rbdout file if open.
   subroutine rigid_close(rs)
      type(rigid_system_t), intent(inout) :: rs
      if (rs%rbdout_open) close(rs%rbdout_unit)
      rs%rbdout_open = .false.
   end subroutine rigid_close
end module dx_rigid_solver
