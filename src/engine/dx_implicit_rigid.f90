!> Rigid bodies in the implicit solver (issue 20): each *MAT_RIGID part (or nodal rigid body)
!> is six equations, the translation of its centre of mass and a rotation, and its nodes are
!> slaved to them (NIKE3D: Maker, Ferencz & Hallquist, UCRL-MA-105268, "Rigid bodies"; the
!> transformation of Hughes, "The Finite Element Method", 1987, ch. 1.14 constraints):
!>   x_i = x_c + R (X_i - X_c0),   du_i = du_c + dtheta x r_i = T_i dq,  r_i = R (X_i - X_c0),
!> with dtheta a spatial (incremental) rotation, R updated by Rodrigues' formula
!> R <- exp([dtheta]x) R (Simo & Vu-Quoc, J. Appl. Mech. 53 (1986) 849: spatial increments,
!> so the tangent below is the consistent one at any rotation). The element (and contact
!> pair) matrices of elements touching a body become T^T k T on a condensed map of at most 24
!> equations (deformable nodes' three, each body's six once); the residual gathers the
!> nodal out-of-balance forces v_i of a body's nodes into F = sum v_i, M = sum r_i x v_i.
!> The rotation of the arms r_i adds K_(theta theta) += -sum [v_i]x [r_i]x (symmetric at
!> equilibrium: its symmetric part is taken when the matrix is stored symmetric).
!> CON1/CON2 of *MAT_RIGID (CMO = 1) fix body equations (eliminated); *BOUNDARY_PRESCRIBED_
!> MOTION_RIGID with VAD = 2 prescribes them (DOF 1-3 translation, 5-7 rotation about x, y, z:
!> the rotation applied as the increment about the global axis at each step's start).
!> Dynamics: Newmark on the six body coordinates q = (u_c, theta), theta the sum of the
!> spatial increments, with the mass m and the spatial inertia J = R J0 R^T (committed R) and
!> no gyroscopic term: exact for rotation about a fixed axis (the tests), an approximation
!> of O(omega x J omega) for general spinning (stated in docs/implicit.md).
module dx_implicit_rigid
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_vec3, only: cross
   use dx_model, only: model_t
   use dx_sparse, only: sparse_sym_t, sparse_add_element
   use dx_dense_solve, only: dense_solve
   implicit none
   private
   public :: irigid_t, irig_setup, irig_layouts, irig_add, irig_nodes, irig_gather, &
             irig_scatter, irig_reset, irig_commit, irig_prescribe, irig_geo, irig_inertia, &
             irig_start_dyn, irig_kinetic, irig_velocity, irig_dof_name

   integer, parameter :: NDE = 24        !< the pattern's element width

   type :: irigid_t
      integer :: nb = 0
      integer, allocatable :: nbody(:)            !< (nn) body of each node, 0 deformable
      integer, allocatable :: beq(:, :)           !< (6, nb) equation; 0 fixed; -k motion k
      integer, allocatable :: mb(:), mk(:)        !< prescribed motion k: body, its motion
      real(wp), allocatable :: xc0(:, :)          !< (3, nb) initial centre of mass
      real(wp), allocatable :: qc(:, :), qt(:, :) !< (6, nb) committed / trial coordinates
      real(wp), allocatable :: rc(:, :, :), rt(:, :, :)   !< (3, 3, nb) rotations c / t
      real(wp), allocatable :: mass(:), j0(:, :, :)       !< mass, inertia at t = 0 (global)
      real(wp), allocatable :: vc(:, :), ac(:, :), at(:, :)   !< (6, nb) dynamics
      integer, allocatable :: lay(:)              !< (ne) layout of element e, 0: no body
      integer, allocatable :: slot(:, :)          !< (8, nlay) first slot of node a (0 none)
      integer, allocatable :: lbody(:, :)         !< (8, nlay) body of node a (0 deformable)
      integer :: nlay = 0
   end type irigid_t

contains

   !> The bodies of model%rigid: their equations numbered after neq (fixed by CON1/CON2,
   !> prescribed by VAD = 2 motions), the rigid nodes' nodal equations removed from eqn.
   subroutine irig_setup(model, eqn, neq, rig, error)
      type(model_t), intent(in) :: model
      integer, intent(inout) :: eqn(:, :), neq
      type(irigid_t), intent(out) :: rig
      type(error_t), allocatable, intent(out) :: error
      integer :: b, d, k, nm
      character(*), parameter :: why = ' (the implicit solver, issue 20)'
      allocate(rig%nbody(size(eqn, 2)))
      rig%nbody = 0
      if (.not. allocated(model%rigid)) then
         allocate(rig%lay(0), rig%mb(0), rig%mk(0)); return
      end if
      rig%nb = size(model%rigid%bodies)
      rig%nbody = model%rigid%node_body
      where (spread(rig%nbody, 1, 3) > 0) eqn = 0
      allocate(rig%beq(6, rig%nb), rig%xc0(3, rig%nb), rig%qc(6, rig%nb), rig%qt(6, rig%nb), &
               rig%rc(3, 3, rig%nb), rig%rt(3, 3, rig%nb), rig%mass(rig%nb), &
               rig%j0(3, 3, rig%nb), rig%vc(6, rig%nb), rig%ac(6, rig%nb), rig%at(6, rig%nb))
      allocate(rig%mb(0), rig%mk(0))
      rig%qc = 0.0_wp; rig%vc = 0.0_wp; rig%ac = 0.0_wp; rig%at = 0.0_wp
      rig%beq = 1
      nm = 0
      do b = 1, rig%nb
         associate (bd => model%rigid%bodies(b))
            rig%xc0(:, b) = bd%x0
            rig%rc(:, :, b) = eye()
            rig%mass(b) = bd%mass
            rig%j0(:, :, b) = matmul(bd%rot, matmul(diag(bd%ip), transpose(bd%rot)))
            rig%vc(1:3, b) = bd%vc
            rig%vc(4:6, b) = bd%omega
            where (bd%fix_t) rig%beq(1:3, b) = 0
            where (bd%fix_r) rig%beq(4:6, b) = 0
            if (allocated(bd%motions)) then
               do k = 1, size(bd%motions)
                  associate (mo => bd%motions(k))
                     if (mo%vad /= 2 .or. .not. any(mo%dof == [1, 2, 3, 5, 6, 7])) then
                        call set_error(error, '*BOUNDARY_PRESCRIBED_MOTION_RIGID: part '// &
                           str(bd%label)//': field VAD/DOF: the implicit solver takes '// &
                           'displacements (VAD = 2) along or about x, y, z (DOF 1-3, 5-7), got '// &
                           'VAD = '//str(mo%vad)//', DOF = '//str(mo%dof)//why); return
                     end if
                     if (mo%birth > 0.0_wp .or. mo%death < 1.0e27_wp) then
                        call set_error(error, '*BOUNDARY_PRESCRIBED_MOTION_RIGID: part '// &
                           str(bd%label)//': fields DEATH/BIRTH: not in the implicit solver '// &
                           '(leave them blank)'//why); return
                     end if
                     d = mo%dof
                     if (d >= 5) d = d - 1
                     if (rig%beq(d, b) < 0) then
                        call set_error(error, '*BOUNDARY_PRESCRIBED_MOTION_RIGID: part '// &
                           str(bd%label)//': field DOF: '//str(mo%dof)//' is prescribed '// &
                           'twice'//why); return
                     end if
                     nm = nm + 1
                     rig%mb = [rig%mb, b]
                     rig%mk = [rig%mk, k]
                     rig%beq(d, b) = -nm
                  end associate
               end do
            end if
         end associate
      end do
      do b = 1, rig%nb
         do d = 1, 6
            if (rig%beq(d, b) > 0) then
               neq = neq + 1
               rig%beq(d, b) = neq
            end if
         end do
      end do
      rig%qt = rig%qc; rig%rt = rig%rc
   end subroutine irig_setup

   !> Condensed maps emap(:, e) of the elements (nodes enodes(:, e), 0: none) that touch a
   !> body: each deformable node its three equations, each body its six once; the layouts.
   subroutine irig_layouts(rig, eqn, enodes, emap, error)
      type(irigid_t), intent(inout) :: rig
      integer, intent(in) :: eqn(:, :), enodes(:, :)
      integer, intent(inout) :: emap(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: e, a, s, b, a2, k
      if (allocated(rig%lay)) deallocate(rig%lay)
      if (allocated(rig%slot)) deallocate(rig%slot, rig%lbody)
      allocate(rig%lay(size(enodes, 2)))
      rig%lay = 0
      rig%nlay = 0
      if (rig%nb == 0) return
      do e = 1, size(enodes, 2)
         if (any(enodes(:, e) > 0)) then
            if (any(rig%nbody(pack(enodes(:, e), enodes(:, e) > 0)) > 0)) then
               rig%nlay = rig%nlay + 1
               rig%lay(e) = rig%nlay
            end if
         end if
      end do
      allocate(rig%slot(8, rig%nlay), rig%lbody(8, rig%nlay))
      rig%slot = 0; rig%lbody = 0
      do e = 1, size(enodes, 2)
         k = rig%lay(e)
         if (k == 0) cycle
         emap(:, e) = 0
         s = 0
         do a = 1, size(enodes, 1)
            if (enodes(a, e) <= 0) cycle
            b = rig%nbody(enodes(a, e))
            rig%lbody(a, k) = b
            if (b == 0) then
               if (s + 3 > NDE) exit
               rig%slot(a, k) = s + 1
               emap(s + 1:s + 3, e) = max(0, eqn(:, enodes(a, e)))
               s = s + 3
            else
               do a2 = 1, a - 1
                  if (rig%lbody(a2, k) == b) then
                     rig%slot(a, k) = rig%slot(a2, k); exit
                  end if
               end do
               if (rig%slot(a, k) /= 0) cycle
               if (s + 6 > NDE) exit
               rig%slot(a, k) = s + 1
               emap(s + 1:s + 6, e) = max(0, rig%beq(:, b))
               s = s + 6
            end if
         end do
         if (a <= size(enodes, 1)) then
            call set_error(error, 'an element or contact pair touches rigid bodies at more '// &
               'nodes than the implicit solver''s 24 condensed equations hold (nodes of '// &
               'several rigid bodies in one element): merge the bodies or mesh between them')
            return
         end if
      end do
   end subroutine irig_layouts

   !> Add the element matrix ke (24 x 24, its first 3 m rows and columns on nodes(1:m)) of
   !> pattern element e as T^T ke T on its condensed map (as it is when it touches no body).
   subroutine irig_add(rig, model, kmat, e, nodes, ke)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      type(sparse_sym_t), intent(inout) :: kmat
      integer, intent(in) :: e, nodes(:)
      real(wp), intent(in) :: ke(:, :)
      real(wp) :: t(NDE, NDE), kc(NDE, NDE), r(3)
      integer :: k, a, s, m, i
      k = 0
      if (rig%nb > 0) k = rig%lay(e)
      if (k == 0) then
         call sparse_add_element(kmat, e, ke); return
      end if
      m = size(nodes)
      t = 0.0_wp
      do a = 1, m
         s = rig%slot(a, k)
         if (s == 0) cycle
         do i = 1, 3
            t(3*(a - 1) + i, s + i - 1) = 1.0_wp
         end do
         if (rig%lbody(a, k) > 0) then
            r = arm(rig, model, rig%lbody(a, k), nodes(a))
            t(3*a - 2:3*a, s + 3:s + 5) = -skew(r)
         end if
      end do
      kc = matmul(transpose(t(1:3*m, :)), matmul(ke(1:3*m, 1:3*m), t(1:3*m, :)))
      call sparse_add_element(kmat, e, kc)
   end subroutine irig_add

   !> r_i = R (X_i - X_c0) of node nd of body b (trial).
   pure function arm(rig, model, b, nd) result(r)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      integer, intent(in) :: b, nd
      real(wp) :: r(3)
      r = matmul(rig%rt(:, :, b), model%x0(:, nd) - rig%xc0(:, b))
   end function arm

   !> The rigid nodes' displacements u(3, nn) from the bodies' trial state.
   subroutine irig_nodes(rig, model, u)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: u(:, :)
      integer :: i, b
      if (rig%nb == 0) return
      do i = 1, size(rig%nbody)
         b = rig%nbody(i)
         if (b == 0) cycle
         u(:, i) = rig%qt(1:3, b) + arm(rig, model, b, i) - (model%x0(:, i) - rig%xc0(:, b))
      end do
   end subroutine irig_nodes

   !> The bodies' equations of r(neq): F = sum v_i, M = sum r_i x v_i over their nodes.
   subroutine irig_gather(rig, model, v, r)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: v(:, :)
      real(wp), intent(inout) :: r(:)
      real(wp) :: g(6, rig%nb)
      integer :: b, d
      if (rig%nb == 0) return
      g = resultants(rig, model, v)
      do b = 1, rig%nb
         do d = 1, 6
            if (rig%beq(d, b) > 0) r(rig%beq(d, b)) = g(d, b)
         end do
      end do
   end subroutine irig_gather

   !> Each body's resultant (sum v_i, sum r_i x v_i) of a nodal field v over its nodes.
   function resultants(rig, model, v) result(g)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: v(:, :)
      real(wp) :: g(6, rig%nb)
      integer :: i, b
      g = 0.0_wp
      do i = 1, size(rig%nbody)
         b = rig%nbody(i)
         if (b == 0) cycle
         g(1:3, b) = g(1:3, b) + v(:, i)
         g(4:6, b) = g(4:6, b) + cross(arm(rig, model, b, i), v(:, i))
      end do
   end function resultants

   !> The bodies' trial state += alpha dq (rotations composed: R <- exp(alpha [dtheta]x) R).
   subroutine irig_scatter(rig, dq, alpha)
      type(irigid_t), intent(inout) :: rig
      real(wp), intent(in) :: dq(:), alpha
      real(wp) :: d(6)
      integer :: b, k
      do b = 1, rig%nb
         d = 0.0_wp
         do k = 1, 6
            if (rig%beq(k, b) > 0) d(k) = alpha*dq(rig%beq(k, b))
         end do
         call move(rig, b, d)
      end do
   end subroutine irig_scatter

   subroutine move(rig, b, d)
      type(irigid_t), intent(inout) :: rig
      integer, intent(in) :: b
      real(wp), intent(in) :: d(6)
      rig%qt(:, b) = rig%qt(:, b) + d
      rig%rt(:, :, b) = matmul(rodrigues(d(4:6)), rig%rt(:, :, b))
   end subroutine move

   subroutine irig_reset(rig)
      type(irigid_t), intent(inout) :: rig
      if (rig%nb == 0) return
      rig%qt = rig%qc; rig%rt = rig%rc
   end subroutine irig_reset

   !> The trial state becomes the committed one; with h > 0 (dynamics) the Newmark velocity
   !> and acceleration move on too.
   subroutine irig_commit(rig, h, gamma)
      type(irigid_t), intent(inout) :: rig
      real(wp), intent(in) :: h, gamma
      if (rig%nb == 0) return
      if (h > 0.0_wp) then
         rig%vc = rig%vc + h*((1.0_wp - gamma)*rig%ac + gamma*rig%at)
         rig%ac = rig%at
         where (rig%beq == 0) rig%vc = 0.0_wp
      end if
      rig%qc = rig%qt; rig%rc = rig%rt
   end subroutine irig_commit

   !> The prescribed body coordinates at time t (trial = committed on entry): the increment
   !> sf curve(t) - q_c applied.
   subroutine irig_prescribe(rig, model, t)
      type(irigid_t), intent(inout) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp) :: d(6)
      integer :: k, b, j
      do k = 1, size(rig%mb)
         b = rig%mb(k)
         associate (mo => model%rigid%bodies(b)%motions(rig%mk(k)))
            j = mo%dof
            if (j >= 5) j = j - 1
            d = 0.0_wp
            d(j) = mo%sf*model%curves(mo%curve)%eval(t) - rig%qt(j, b)
            call move(rig, b, d)
         end associate
      end do
   end subroutine irig_prescribe

   !> The arms' rotation in the tangent: K_(theta theta) += -sum [v_i]x [r_i]x of the nodal
   !> out-of-balance forces v (the residual's, before its gather).
   subroutine irig_geo(rig, model, v, kmat)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: v(:, :)
      type(sparse_sym_t), intent(inout) :: kmat
      real(wp) :: g(3, 3, rig%nb)
      integer :: i, b
      if (rig%nb == 0) return
      g = 0.0_wp
      do i = 1, size(rig%nbody)
         b = rig%nbody(i)
         if (b == 0) cycle
         g(:, :, b) = g(:, :, b) - matmul(skew(v(:, i)), skew(arm(rig, model, b, i)))
      end do
      do b = 1, rig%nb
         if (kmat%sym) g(:, :, b) = 0.5_wp*(g(:, :, b) + transpose(g(:, :, b)))
         call add_block(kmat, rig%beq(4:6, b), g(:, :, b))
      end do
   end subroutine irig_geo

   !> Dynamics (Newmark BETA, step h): the bodies' trial acceleration from q_t - q_c, their
   !> inertia -M a into r and M/(BETA h^2) into the tangent (want_k).
   subroutine irig_inertia(rig, h, beta, want_k, r, kmat)
      type(irigid_t), intent(inout) :: rig
      real(wp), intent(in) :: h, beta
      logical, intent(in) :: want_k
      real(wp), intent(inout) :: r(:)
      type(sparse_sym_t), intent(inout) :: kmat
      real(wp) :: mb(6, 6), f(6)
      integer :: b, d
      do b = 1, rig%nb
         rig%at(:, b) = (rig%qt(:, b) - rig%qc(:, b) - h*rig%vc(:, b))/(beta*h*h) - &
                        (0.5_wp/beta - 1.0_wp)*rig%ac(:, b)
         mb = body_mass(rig, b)
         f = matmul(mb, rig%at(:, b))
         do d = 1, 6
            if (rig%beq(d, b) > 0) r(rig%beq(d, b)) = r(rig%beq(d, b)) - f(d)
         end do
         if (want_k) then
            call add_block(kmat, rig%beq(1:3, b), mb(1:3, 1:3)/(beta*h*h))
            call add_block(kmat, rig%beq(4:6, b), mb(4:6, 4:6)/(beta*h*h))
         end if
      end do
   end subroutine irig_inertia

   !> The initial accelerations M^-1 (F, M) of the nodal forces f at t = 0 (free equations).
   subroutine irig_start_dyn(rig, model, f)
      type(irigid_t), intent(inout) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: f(:, :)
      real(wp) :: g(6, rig%nb), mb(6, 6), jm(3, 3), x(3)
      character(:), allocatable :: msg
      integer :: b
      if (rig%nb == 0) return
      g = resultants(rig, model, f)
      do b = 1, rig%nb
         mb = body_mass(rig, b)
         rig%ac(1:3, b) = g(1:3, b)/mb(1, 1)
         jm = mb(4:6, 4:6)
         x = g(4:6, b)
         call dense_solve(jm, x, msg)     ! (J is positive definite: the build checks it)
         rig%ac(4:6, b) = x
         where (rig%beq(:, b) <= 0) rig%ac(:, b) = 0.0_wp
         where (rig%beq(:, b) == 0) rig%vc(:, b) = 0.0_wp
      end do
      rig%at = rig%ac
   end subroutine irig_start_dyn

   !> The bodies' kinetic energy (committed velocities).
   real(wp) function irig_kinetic(rig) result(ek)
      type(irigid_t), intent(in) :: rig
      integer :: b
      ek = 0.0_wp
      do b = 1, rig%nb
         ek = ek + 0.5_wp*dot_product(rig%vc(:, b), matmul(body_mass(rig, b), rig%vc(:, b)))
      end do
   end function irig_kinetic

   !> The rigid nodes' velocities v_c + omega x r_i (committed) into v(3, nn).
   subroutine irig_velocity(rig, model, v)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: v(:, :)
      integer :: i, b
      do i = 1, size(rig%nbody)
         b = rig%nbody(i)
         if (b == 0) cycle
         v(:, i) = rig%vc(1:3, b) + cross(rig%vc(4:6, b), arm(rig, model, b, i))
      end do
   end subroutine irig_velocity

   !> 'rigid body L rotation about y' of equation q, '' when no body has it.
   function irig_dof_name(rig, model, q) result(s)
      type(irigid_t), intent(in) :: rig
      type(model_t), intent(in) :: model
      integer, intent(in) :: q
      character(:), allocatable :: s
      character(16), parameter :: names(6) = [character(16) :: 'translation x', &
         'translation y', 'translation z', 'rotation about x', 'rotation about y', &
         'rotation about z']
      integer :: b, d
      s = ''
      do b = 1, rig%nb
         do d = 1, 6
            if (rig%beq(d, b) == q) then
               s = 'rigid body (part) '//str(model%rigid%bodies(b)%label)//' '//trim(names(d))
               return
            end if
         end do
      end do
   end function irig_dof_name

   !> diag(m, m, m, J), J = R_c J0 R_c^T.
   pure function body_mass(rig, b) result(mb)
      type(irigid_t), intent(in) :: rig
      integer, intent(in) :: b
      real(wp) :: mb(6, 6)
      integer :: k
      mb = 0.0_wp
      do k = 1, 3
         mb(k, k) = rig%mass(b)
      end do
      mb(4:6, 4:6) = matmul(rig%rc(:, :, b), matmul(rig%j0(:, :, b), transpose(rig%rc(:, :, b))))
   end function body_mass

   !> kmat(eq(i), eq(j)) += g(i, j) for the equations eq > 0 (symmetric: the upper triangle).
   subroutine add_block(kmat, eq, g)
      type(sparse_sym_t), intent(inout) :: kmat
      integer, intent(in) :: eq(3)
      real(wp), intent(in) :: g(3, 3)
      integer :: i, j, p, row, col
      do i = 1, 3
         do j = 1, 3
            if (eq(i) <= 0 .or. eq(j) <= 0) cycle
            row = eq(i); col = eq(j)
            if (kmat%sym .and. col < row) cycle
            do p = kmat%rowptr(row), kmat%rowptr(row + 1) - 1
               if (kmat%col(p) == col) then
                  kmat%a(p) = kmat%a(p) + g(i, j); exit
               end if
            end do
         end do
      end do
   end subroutine add_block

   pure function skew(r) result(s)
      real(wp), intent(in) :: r(3)
      real(wp) :: s(3, 3)
      s = reshape([0.0_wp, r(3), -r(2), -r(3), 0.0_wp, r(1), r(2), -r(1), 0.0_wp], [3, 3])
   end function skew

   pure function eye() result(a)
      real(wp) :: a(3, 3)
      a = diag([1.0_wp, 1.0_wp, 1.0_wp])
   end function eye

   pure function diag(d) result(a)
      real(wp), intent(in) :: d(3)
      real(wp) :: a(3, 3)
      a = 0.0_wp
      a(1, 1) = d(1); a(2, 2) = d(2); a(3, 3) = d(3)
   end function diag

   !> exp([w]x) by Rodrigues' formula.
   pure function rodrigues(w) result(q)
      real(wp), intent(in) :: w(3)
      real(wp) :: q(3, 3), th, s(3, 3), c1, c2
      th = norm2(w)
      s = skew(w)
      if (th < 1.0e-4_wp) then
         c1 = 1.0_wp - th*th/6.0_wp
         c2 = 0.5_wp - th*th/24.0_wp
      else
         c1 = sin(th)/th
         c2 = (1.0_wp - cos(th))/(th*th)
      end if
      q = eye() + c1*s + c2*matmul(s, s)
   end function rodrigues

end module dx_implicit_rigid
