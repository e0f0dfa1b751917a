!> Kinematic constraints applied to the mid-step velocity v(n+1/2) each cycle:
!> *BOUNDARY_SPC_* (fixed translations), *BOUNDARY_PRESCRIBED_MOTION_* (VAD 0 velocity,
!> 1 acceleration, 2 displacement, active between BIRTH and DEATH) and *RIGIDWALL_PLANAR
!> stonewalls; a skew SPC (CID of *BOUNDARY_SPC_*) is a prescribed zero velocity along each
!> constrained local axis, dof 4 and curve 0 (Hallquist, LS-DYNA Theory Manual, "Rigid walls"): a node predicted to cross
!> the wall gets the normal velocity that puts it exactly on the wall; FRIC = 0 frictionless,
!> FRIC >= 1 no sliding after contact, 0 < FRIC < 1 Coulomb friction on the impulse.
module dx_constraints
   use dx_kinds, only: wp
   use dx_model, only: model_t
   implicit none
   private
   public :: apply_spc, apply_prescribed, apply_rigidwalls, apply_spc_rot, &
             apply_prescribed_rot

   !> The nodes the stonewalls corrected in one cycle (apply_rigidwalls), in wall order:
   !> wall(i), k(i) = the wall and the position in its node list; val(1, i) the work term,
   !> val(2:4, i) = m dv/dtavg.
   type, public :: wall_hits_t
      integer :: n = 0
      integer, allocatable :: wall(:), k(:)
      real(wp), allocatable :: val(:, :)
   end type wall_hits_t
contains

   !> Zero the constrained translational velocity components.
   subroutine apply_spc(model, v)
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: v(:, :)
      integer :: k, d
      if (.not. allocated(model%spcs)) return
      do k = 1, size(model%spcs)
         do d = 1, 3
            if (model%spcs(k)%dof(d)) v(d, model%spcs(k)%node) = 0.0_wp
         end do
      end do
   end subroutine apply_spc

   !> Zero the constrained angular velocity components (DOFRX, DOFRY, DOFRZ; *NODE RC).
   subroutine apply_spc_rot(model, w)
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: w(:, :)
      integer :: k, d
      if (.not. allocated(model%spcs)) return
      do k = 1, size(model%spcs)
         do d = 1, 3
            if (model%spcs(k)%dof(3 + d)) w(d, model%spcs(k)%node) = 0.0_wp
         end do
      end do
   end subroutine apply_spc_rot

   !> Prescribed rotations (DOF 5, 6, 7: about x, y, z) on the angular velocity w(n+1/2)
   !> (wold = w(n-1/2)): VAD 0 angular velocity at the mid-step time, 1 angular
   !> acceleration at t(n), 2 the angle: w = (angle(t + dt) - angle(t))/dt, whose steps
   !> add up to the angle's change since the birth exactly (the nodes carry no angle: the
   !> sum telescopes, so the node lands on the curve at every step as VAD 2 of a translation
   !> does).
   subroutine apply_prescribed_rot(model, t, dt, dtavg, wold, w)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t, dt, dtavg
      real(wp), intent(in) :: wold(:, :)
      real(wp), intent(inout) :: w(:, :)
      integer :: k, nd, d
      real(wp) :: val
      if (.not. allocated(model%prescribed)) return
      do k = 1, size(model%prescribed)
         associate (pm => model%prescribed(k))
            if (pm%dof < 5 .or. pm%dof > 7) cycle
            if (t < pm%birth .or. t > pm%death) cycle
            nd = pm%node
            d = pm%dof - 4
            if (pm%vad == 1) then
               val = wold(d, nd) + dtavg*pm%sf*model%curves(pm%curve)%eval(t)
            else if (pm%vad == 2) then
               val = pm%sf*(model%curves(pm%curve)%eval(t + dt) - &
                            model%curves(pm%curve)%eval(t))/dt
            else
               val = pm%sf*model%curves(pm%curve)%eval(t + 0.5_wp*dt)
            end if
            w(d, nd) = val
         end associate
      end do
   end subroutine apply_prescribed_rot

   !> Prescribed motion for the step t -> t + dt (v holds the unconstrained v(n+1/2);
   !> vold the previous v(n-1/2); dtavg = (dt_old + dt)/2).
   subroutine apply_prescribed(model, t, dt, dtavg, vold, v)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t, dt, dtavg
      real(wp), intent(in) :: vold(:, :)
      real(wp), intent(inout) :: v(:, :)
      integer :: k, nd
      real(wp) :: val, cur, d(3)
      if (.not. allocated(model%prescribed)) return
      do k = 1, size(model%prescribed)
         associate (pm => model%prescribed(k))
            if (t < pm%birth .or. t > pm%death) cycle
            if (pm%dof >= 5) cycle              ! rotations: apply_prescribed_rot
            nd = pm%node
            d = pm%dir
            select case (pm%vad)
            case (0)      ! velocity at the mid-step time (curve 0: a skew SPC, zero)
               val = 0.0_wp
               if (pm%curve > 0) val = pm%sf*model%curves(pm%curve)%eval(t + 0.5_wp*dt)
            case (1)      ! acceleration at t(n)
               val = dot_product(d, vold(:, nd)) + dtavg*pm%sf*model%curves(pm%curve)%eval(t)
            case default  ! displacement: land exactly on u(t + dt)
               cur = dot_product(d, model%x(:, nd) - model%x0(:, nd))
               val = (pm%sf*model%curves(pm%curve)%eval(t + dt) - cur)/dt
            end select
            v(:, nd) = v(:, nd) + (val - dot_product(d, v(:, nd)))*d
         end associate
      end do
   end subroutine apply_prescribed

   !> Stonewalls: correct v so no slave node crosses its wall during the step. Each node a
   !> wall corrects is a hit, recorded in wall order (walls, then the wall's node list) with
   !> its terms: the work the wall does on it, f.dtavg (v(n-1/2) + v(n+1/2))/2 = m dv.(v(n-1/2)
   !> + v(n+1/2))/2, and m dv/dtavg (the force on the wall is minus their sum). Terms and
   !> sums are separate steps: the domain adds the terms exactly (dx_energy_exact work_hit),
   !> so that an MPI run, whose ranks compute the hits of the nodes they own with this same
   !> code, gets the serial bits.
   subroutine apply_rigidwalls(model, dt, dtavg, vold, v, hits)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: dt, dtavg
      real(wp), intent(in) :: vold(:, :)
      real(wp), intent(inout) :: v(:, :)
      type(wall_hits_t), intent(inout) :: hits
      integer :: w, k, nd
      real(wp) :: dist, vn, dvn, vt(3), vtn, jt, dvel(3)
      hits%n = 0
      if (.not. allocated(model%walls)) return
      do w = 1, size(model%walls)
         associate (wall => model%walls(w))
            do k = 1, size(wall%nodes)
               nd = wall%nodes(k)
               dist = dot_product(model%x(:, nd) + dt*v(:, nd) - wall%x0, wall%n)
               if (dist >= 0.0_wp) cycle
               vn = dot_product(v(:, nd), wall%n)
               dvn = -dist/dt                      ! normal velocity change (>0)
               dvel = dvn*wall%n
               if (wall%fric > 0.0_wp) then
                  vt = v(:, nd) - vn*wall%n
                  vtn = norm2(vt)
                  if (vtn > 0.0_wp) then
                     if (wall%fric >= 1.0_wp) then
                        jt = vtn
                     else
                        jt = min(vtn, wall%fric*dvn)
                     end if
                     dvel = dvel - jt*vt/vtn
                  end if
               end if
               v(:, nd) = v(:, nd) + dvel
               call add_hit(hits, w, k, &
                            0.5_wp*model%mass(nd)*dot_product(dvel, vold(:, nd) + v(:, nd)), &
                            model%mass(nd)*dvel/dtavg)
            end do
         end associate
      end do
   end subroutine apply_rigidwalls

   !> Append one hit to hits (the arrays grow by doubling).
   subroutine add_hit(hits, w, k, work, f)
      type(wall_hits_t), intent(inout) :: hits
      integer, intent(in) :: w, k
      real(wp), intent(in) :: work, f(3)
      integer, allocatable :: iw(:), ik(:)
      real(wp), allocatable :: vv(:, :)
      integer :: m
      if (.not. allocated(hits%wall)) allocate(hits%wall(16), hits%k(16), hits%val(4, 16))
      if (hits%n == size(hits%wall)) then
         m = 2*hits%n
         allocate(iw(m), ik(m), vv(4, m))
         iw(1:hits%n) = hits%wall(1:hits%n)
         ik(1:hits%n) = hits%k(1:hits%n)
         vv(:, 1:hits%n) = hits%val(:, 1:hits%n)
         call move_alloc(iw, hits%wall)
         call move_alloc(ik, hits%k)
         call move_alloc(vv, hits%val)
      end if
      hits%n = hits%n + 1
      hits%wall(hits%n) = w
      hits%k(hits%n) = k
      hits%val(1, hits%n) = work
      hits%val(2:4, hits%n) = f
   end subroutine add_hit
end module dx_constraints
