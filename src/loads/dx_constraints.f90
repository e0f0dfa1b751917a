!> Kinematic constraints applied to the mid-step velocity v(n+1/2) each cycle:
!> *BOUNDARY_SPC_* (fixed translations), *BOUNDARY_PRESCRIBED_MOTION_* (VAD 0 velocity,
!> 1 acceleration, 2 displacement, active between BIRTH and DEATH) and *RIGIDWALL_PLANAR
!> stonewalls (Hallquist, LS-DYNA Theory Manual, "Rigid walls"): a node predicted to cross
!> the wall gets the normal velocity that puts it exactly on the wall; FRIC = 0 frictionless,
!> FRIC >= 1 no sliding after contact, 0 < FRIC < 1 Coulomb friction on the impulse.
module dx_constraints
   use dx_kinds, only: wp
   use dx_model, only: model_t
   implicit none
   private
   public :: apply_spc, apply_prescribed, apply_rigidwalls
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
            nd = pm%node
            d = pm%dir
            select case (pm%vad)
            case (0)      ! velocity at the mid-step time
               val = pm%sf*model%curves(pm%curve)%eval(t + 0.5_wp*dt)
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

   !> Stonewalls: correct v so no slave node crosses its wall during the step; accumulate
   !> the wall's resultant force (force on the wall = - sum m*dv/dtavg).
   !> work: accumulates the work the walls do on the nodes, f.dtavg (v(n-1/2) + v(n+1/2))/2.
   subroutine apply_rigidwalls(model, dt, dtavg, vold, v, work)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: dt, dtavg
      real(wp), intent(in) :: vold(:, :)
      real(wp), intent(inout) :: v(:, :)
      real(wp), intent(inout) :: work
      integer :: w, k, nd
      real(wp) :: dist, vn, dvn, vt(3), vtn, jt, fsum(3), dvel(3)
      if (.not. allocated(model%walls)) return
      do w = 1, size(model%walls)
         fsum = 0.0_wp
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
               fsum = fsum - model%mass(nd)*dvel/dtavg
               work = work + 0.5_wp*model%mass(nd)*dot_product(dvel, vold(:, nd) + v(:, nd))
            end do
            wall%force = fsum
         end associate
      end do
   end subroutine apply_rigidwalls
end module dx_constraints
