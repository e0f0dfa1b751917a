!> The abstract material interface: every constitutive model extends material_t.
!> Stress update for one chunk of nv integration points at a time (dispatch once per chunk).
!> Conventions: Voigt order xx,yy,zz,xy,yz,zx; tension positive; strain increments are
!> tensor components (deps(:,4) = d_xy*dt, not engineering shear); stress arrives already
!> rotated to the end of the step (Jaumann rate, done by the element).
module dx_material
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_curve, only: curve_t
   implicit none
   private
   public :: material_t, mat_holder_t

   type, abstract :: material_t
      integer :: label = 0             !< material id (MID) from the deck
      integer :: mtype = 0             !< LS-DYNA material type number (1, 3, 24, ...)
      character(:), allocatable :: title
      real(wp) :: ro = 0.0_wp          !< initial mass density
      real(wp) :: bulk = 0.0_wp        !< elastic bulk modulus K (set by setup)
      real(wp) :: shear = 0.0_wp       !< elastic shear modulus G (set by setup)
      integer :: hv_eps_p = 0          !< history offset of effective plastic strain (0: none)
      logical :: is_rigid = .false.
   contains
      procedure(setup_i), deferred :: setup          !< check parameters, derive K, G, ...
      procedure(nhist_i), deferred :: nhist          !< history variables per integration point
      procedure(update_i), deferred :: update        !< stress update for one chunk
      procedure :: wave_speed => default_wave_speed  !< dilatational wave speed per point
      procedure :: fails => default_fails            !< element erosion flag per point
      procedure :: resolve_curves => default_resolve !< look up curve labels after the deck is read
   end type material_t

   !> A holder so models can keep an array of polymorphic materials.
   type :: mat_holder_t
      class(material_t), allocatable :: m
   end type mat_holder_t

   abstract interface
      subroutine setup_i(self, error)
         import :: material_t, error_t
         class(material_t), intent(inout) :: self
         type(error_t), allocatable, intent(out) :: error
      end subroutine setup_i

      pure integer function nhist_i(self)
         import :: material_t
         class(material_t), intent(in) :: self
      end function nhist_i

      !> Update stress sig and history hv of nv points over a step dt.
      !> relvol: V/V0 at the end of the step; eint: internal energy per unit initial volume.
      !> ierr(i) /= 0 flags a point the material could not update (caller reports it).
      subroutine update_i(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
         import :: material_t, wp
         class(material_t), intent(in) :: self
         integer, intent(in) :: nv
         real(wp), intent(in) :: dt
         real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
         real(wp), intent(inout) :: sig(nv, 6)
         real(wp), intent(inout) :: hv(:, :)
         integer, intent(inout) :: ierr(nv)
      end subroutine update_i
   end interface

contains

   !> Dilatational wave speed sqrt((K + 4G/3)/rho) with rho = ro/relvol.
   subroutine default_wave_speed(self, nv, relvol, hv, c)
      class(material_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: relvol(nv)
      real(wp), intent(in) :: hv(:, :)
      real(wp), intent(out) :: c(nv)
      real(wp) :: m
      m = self%bulk + 4.0_wp*self%shear/3.0_wp
      c = sqrt(m*relvol/self%ro)
      if (.false.) c = c + hv(1, 1)*0.0_wp   ! hv unused in the elastic default
   end subroutine default_wave_speed

   !> Elements whose points this returns .true. for are eroded (default: never).
   subroutine default_fails(self, nv, hv, failed)
      class(material_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: hv(:, :)
      logical, intent(out) :: failed(nv)
      failed = .false.
      if (.false.) failed(1) = hv(1, 1) > self%ro
   end subroutine default_fails

   !> Materials that reference *DEFINE_CURVE ids copy the curves here (default: none).
   subroutine default_resolve(self, curves, error)
      class(material_t), intent(inout) :: self
      type(curve_t), intent(in) :: curves(:)
      type(error_t), allocatable, intent(out) :: error
      if (.false. .and. size(curves) < 0) self%label = 0
   end subroutine default_resolve
end module dx_material
