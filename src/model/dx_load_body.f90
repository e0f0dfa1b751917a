!> Body force loads from a prescribed base acceleration: *LOAD_BODY_X, *LOAD_BODY_Y,
!> *LOAD_BODY_Z (LS-DYNA Keyword User's Manual, Vol. I, *LOAD_BODY). The curve gives the
!> acceleration a(t) = SF*curve(t) of the base; every node feels the inertial body force
!> f = -m a e_dir, so gravity g along -z is *LOAD_BODY_Z with a positive curve value g
!> (LS-DYNA's sign convention). Rigid bodies feel M a through their nodes (the rigid solver
!> corrects for a mass given by *PART_INERTIA). The work of these forces enters the external
!> work like every other external force.
module dx_load_body
   use dx_kinds, only: wp
   use dx_curve, only: curve_t
   implicit none
   private
   public :: body_load_t, body_load_in_t, add_body_loads, base_acceleration

   !> one *LOAD_BODY_X/Y/Z as read (curve label)
   type :: body_load_in_t
      integer :: dir = 0             !< 1 x, 2 y, 3 z
      integer :: lcid = 0
      real(wp) :: sf = 1.0_wp
      integer :: ifile = 0, line = 0
      character(:), allocatable :: key
   end type body_load_in_t

   !> one body load (dense curve index)
   type :: body_load_t
      integer :: dir = 0
      integer :: curve = 0
      real(wp) :: sf = 1.0_wp
   end type body_load_t

contains

   !> The base acceleration vector sum_k SF_k curve_k(t) e_dir(k) at time t.
   function base_acceleration(loads, curves, t) result(a)
      type(body_load_t), intent(in) :: loads(:)
      type(curve_t), intent(in) :: curves(:)
      real(wp), intent(in) :: t
      real(wp) :: a(3)
      integer :: k
      a = 0.0_wp
      do k = 1, size(loads)
         a(loads(k)%dir) = a(loads(k)%dir) + loads(k)%sf*curves(loads(k)%curve)%eval(t)
      end do
   end function base_acceleration

   !> fext(:, i) -= mass(i) a(t) for every node.
   subroutine add_body_loads(loads, curves, mass, t, fext)
      type(body_load_t), intent(in) :: loads(:)
      type(curve_t), intent(in) :: curves(:)
      real(wp), intent(in) :: mass(:), t
      real(wp), intent(inout) :: fext(:, :)
      real(wp) :: a(3)
      integer :: i
      a = base_acceleration(loads, curves, t)
      do i = 1, size(mass)
         fext(1:3, i) = fext(1:3, i) - mass(i)*a
      end do
   end subroutine add_body_loads
end module dx_load_body
