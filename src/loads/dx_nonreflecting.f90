!> *BOUNDARY_NON_REFLECTING_2D in the cycle: the viscous (Lysmer-Kuhlemeyer) boundary of a
!> 2D deck as lumped nodal dashpots f_I = -C_I v_I (C_I: dx_build_twod, per unit thickness or
!> per radian; Lysmer & Kuhlemeyer 1969, J. Eng. Mech. Div. ASCE 95: 859-877; LS-DYNA Theory
!> Manual, "Non-reflecting Boundaries").
!> The velocity is the centred one, v_I = (v(n-1/2) + v(n+1/2))/2, solved with the node's
!> other forces F (internal, contact, loads) of the cycle: v(n+1/2) = v(n-1/2) + dt (F + f)/m
!> gives (I + k C) f = -C (v(n-1/2) + k F), k = dt/(2 m), a 2 x 2 solve per node. A damper
!> on the lagged v(n-1/2) (the explicit scheme's usual velocity) is stable only while
!> dt < (2/omega)(sqrt(1 + xi^2) - xi), xi = C/(2 m omega) (Belytschko, Liu & Moran 2000,
!> Nonlinear Finite Elements, section 6.3.4): at a corner of two boundaries (both dashpots
!> on a quarter element's mass) C dt/m = 2 (c_d + c_s) dt/h is about 1.9 at the solid's
!> step and the corner node blew up after a few hundred cycles (decks/pressure_table at
!> 60-100 ns, regression case nr2d_corner). The centred dashpot is unconditionally stable
!> for any C dt/m, and its work in the external work, f.(v(n-1/2) + v(n+1/2))/2 dt, is
!> exactly -v.C.v dt <= 0 (no energy from the boundary). The force depends on the node
!> alone (its F, mass and v after the shared-node exchange), so every MPI rank holding a
!> node forms the same bits (dx_par_loads).
module dx_nonreflecting
   use dx_kinds, only: wp
   use dx_model, only: model_t
   implicit none
   private
   public :: add_nonreflecting, centred_dashpot

contains

   !> fext(1:2, i) += f_i, the centred dashpot force at the boundary nodes: model%f holds the
   !> node's internal and contact forces, fext its other loads, model%v v(n-1/2), dtavg the
   !> step of the velocity update. A node without mass keeps the lagged form (no update).
   subroutine add_nonreflecting(model, fext, dtavg)
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: fext(:, :)
      real(wp), intent(in) :: dtavg
      integer :: k, n
      real(wp) :: fd(2), kk
      if (.not. allocated(model%nr_node)) return
      do k = 1, size(model%nr_node)
         n = model%nr_node(k)
         kk = 0.0_wp
         if (model%mass(n) > 0.0_wp) kk = 0.5_wp*dtavg/model%mass(n)
         fd = centred_dashpot(model%nr_c(:, k), model%v(1:2, n), &
                              model%f(1:2, n) + fext(1:2, n), kk)
         fext(1:2, n) = fext(1:2, n) + fd
      end do
   end subroutine add_nonreflecting

   !> The dashpot force f = -(I + k C)^-1 C (v + k F) of C = [c1 c3; c3 c2] (symmetric, >= 0)
   !> at velocity v(n-1/2) with the other forces F and k = dt/(2 m): the f for which
   !> f = -C (v + (v + 2 k (F + f)))/2. k = 0 is the lagged -C v.
   pure function centred_dashpot(c, v, f, k) result(fd)
      real(wp), intent(in) :: c(3), v(2), f(2), k
      real(wp) :: fd(2), g(2), a11, a22, a12, det, cg(2)
      g = v + k*f
      cg = [c(1)*g(1) + c(3)*g(2), c(3)*g(1) + c(2)*g(2)]
      a11 = 1.0_wp + k*c(1); a22 = 1.0_wp + k*c(2); a12 = k*c(3)
      det = a11*a22 - a12*a12          ! >= 1: C is positive semi-definite
      fd(1) = -(a22*cg(1) - a12*cg(2))/det
      fd(2) = -(a11*cg(2) - a12*cg(1))/det
   end function centred_dashpot
end module dx_nonreflecting
