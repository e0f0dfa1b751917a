!> *BOUNDARY_NON_REFLECTING_2D in the cycle: the viscous (Lysmer-Kuhlemeyer) boundary of a
!> 2D deck as lumped nodal dashpots f_I = -C_I v_I (C_I: dx_build_twod, per unit thickness or
!> per radian), with v = v(n-1/2), the last velocity known when the forces of t(n) are formed
!> (the explicit central-difference's usual lag for a velocity-dependent force; Lysmer &
!> Kuhlemeyer 1969, J. Eng. Mech. Div. ASCE 95: 859-877; LS-DYNA Theory Manual, "Non-
!> reflecting Boundaries"). The force depends on the node alone, so every MPI rank holding
!> a node forms the same bits after the shared-node exchange, and its work enters the
!> external work with the other loads (dx_par_loads).
module dx_nonreflecting
   use dx_kinds, only: wp
   use dx_model, only: model_t
   implicit none
   private
   public :: add_nonreflecting

contains

   !> fext(1:2, i) -= C_i v_i at the boundary nodes (model%v holds v(n-1/2))
   subroutine add_nonreflecting(model, fext)
      type(model_t), intent(in) :: model
      real(wp), intent(inout) :: fext(:, :)
      integer :: k, n
      if (.not. allocated(model%nr_node)) return
      do k = 1, size(model%nr_node)
         n = model%nr_node(k)
         associate (c => model%nr_c(:, k), v => model%v(:, n))
            fext(1, n) = fext(1, n) - (c(1)*v(1) + c(3)*v(2))
            fext(2, n) = fext(2, n) - (c(3)*v(1) + c(2)*v(2))
         end associate
      end do
   end subroutine add_nonreflecting
end module dx_nonreflecting
