!> Contact springs on rigid bodies: the bound of their frequencies for the critical step.
!> The contact stage bounds w_c^2 by the Gershgorin row sums krow_i of the contact stiffness
!> over the nodal mass (dx_contact). For a node of a rigid body the lumped nodal mass is the
!> wrong inertia: the node moves with the whole body. Gershgorin gives K <= D = diag(krow)
!> (D - K is diagonally dominant), so on a body with mass M, principal moments I1 <= I2 <= I3
!> and nodes at r_i from its centre, the contact frequencies satisfy
!>    w^2 <= lambda_max(M^-1 G^T D G) <= sum_i krow_i (1/M + |r_i|^2/I1),
!> G_i = [1, -[r_i]x] mapping the body's six velocities to node i, since
!> lambda_max(G_i M^-1 G_i^T) = lambda_max(1/M + [r_i]x I^-1 [r_i]x^T) <= 1/M + |r_i|^2/I1.
!> A body with all translations fixed (CON1 = 7) drops the 1/M term, all rotations fixed
!> (CON2 = 7) the r^2/I1 term; a fully fixed body adds nothing. Deformable nodes keep their
!> own bound (krow/m), so the global bound is the largest of the blocks.
!> Reference: Gershgorin circle theorem, e.g. Golub & Van Loan, Matrix Computations (4th ed.
!> 2013), Thm 7.2.1; the rigid-body reduction is that of Benson & Hallquist (1986, CMAME 58:
!> 199, node-to-body contact force transfer) applied to the stiffness.
module dx_rigid_contact
   use dx_kinds, only: wp
   use dx_rigid_types, only: rigid_system_t
   implicit none
   private
   public :: rigid_contact_w2, rigid_effective_mass

contains

   !> max over rigid bodies of sum_i krow_i (1/M + |x_i - x_c|^2/I1) over the listed nodes
   !> that belong to a body (nodes(:) dense indices, krow and x indexed by node).
   real(wp) function rigid_contact_w2(rs, nodes, krow, x) result(w2)
      type(rigid_system_t), intent(in) :: rs
      integer, intent(in) :: nodes(:)
      real(wp), intent(in) :: krow(:), x(:, :)
      real(wp), allocatable :: acc(:)
      real(wp) :: ct, cr
      integer :: i, nd, b
      w2 = 0.0_wp
      allocate(acc(size(rs%bodies)), source=0.0_wp)
      do i = 1, size(nodes)
         nd = nodes(i)
         b = rs%node_body(nd)
         if (b <= 0) cycle
         if (krow(nd) <= 0.0_wp) cycle
         associate (bd => rs%bodies(b))
            ct = 0.0_wp
            if (.not. all(bd%fix_t)) ct = 1.0_wp/bd%mass
            cr = 0.0_wp
            if (.not. all(bd%fix_r)) cr = sum((x(:, nd) - bd%xc)**2)/minval(bd%ip)
            acc(b) = acc(b) + krow(nd)*(ct + cr)
         end associate
      end do
      if (size(acc) > 0) w2 = maxval(acc)
   end function rigid_contact_w2

   !> meff(nd) for the listed nodes of rigid bodies: 1/(1/M + |x - x_c|^2/I1), the bound above
   !> for one spring (huge for a fully fixed body); other entries are left as they are.
   subroutine rigid_effective_mass(rs, nodes, x, meff)
      type(rigid_system_t), intent(in) :: rs
      integer, intent(in) :: nodes(:)
      real(wp), intent(in) :: x(:, :)
      real(wp), intent(inout) :: meff(:)
      real(wp) :: c
      integer :: i, nd, b
      do i = 1, size(nodes)
         nd = nodes(i)
         b = rs%node_body(nd)
         if (b <= 0) cycle
         associate (bd => rs%bodies(b))
            c = 0.0_wp
            if (.not. all(bd%fix_t)) c = 1.0_wp/bd%mass
            if (.not. all(bd%fix_r)) c = c + sum((x(:, nd) - bd%xc)**2)/minval(bd%ip)
            meff(nd) = huge(1.0_wp)
            if (c > 0.0_wp) meff(nd) = 1.0_wp/c
         end associate
      end do
   end subroutine rigid_effective_mass
end module dx_rigid_contact
