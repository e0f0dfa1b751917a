!> *MAT_ELASTIC (*MAT_001): isotropic hypoelastic material, Jaumann rate of Cauchy stress
!> (the element rotates the stress before the update). Hallquist, LS-DYNA Theory Manual, mat 1.
!> Fields: RO density, E Young's modulus, PR Poisson's ratio; DA, DB, K (fluid option) read
!> but only K = 0 (solid) is supported.
module dx_mat_elastic
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, set_field_error
   use dx_strings, only: rstr
   use dx_card, only: card_t
   use dx_material, only: material_t, read_mid_ro
   implicit none
   private
   public :: mat_elastic_t, check_elastic_constants

   type, extends(material_t) :: mat_elastic_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp
      real(wp) :: da = 0.0_wp, db = 0.0_wp, k = 0.0_wp
   contains
      procedure :: read_cards => elastic_read_cards
      procedure :: setup => elastic_setup
      procedure :: nhist => elastic_nhist
      procedure :: update => elastic_update
      procedure :: tangent => elastic_tangent
   end type mat_elastic_t

contains

   !> Check RO, E, PR shared by the elastic-plastic models; set K and G.
   subroutine check_elastic_constants(self, e, pr, error)
      class(material_t), intent(inout) :: self
      real(wp), intent(in) :: e, pr
      type(error_t), allocatable, intent(out) :: error
      if (.not. (self%ro > 0.0_wp)) then
         call set_field_error(error, 'RO', 'density must be > 0, got '//rstr(self%ro)); return
      end if
      if (.not. (e > 0.0_wp)) then
         call set_field_error(error, 'E', 'Young''s modulus must be > 0, got '//rstr(e)); return
      end if
      if (.not. (pr > -1.0_wp .and. pr < 0.5_wp)) then
         call set_field_error(error, 'PR', 'Poisson''s ratio must lie in (-1, 0.5), got '//rstr(pr))
         return
      end if
      self%bulk = e/(3.0_wp*(1.0_wp - 2.0_wp*pr))
      self%shear = e/(2.0_wp*(1.0_wp + pr))
   end subroutine check_elastic_constants

   !> Card 1: MID RO E PR DA DB K.
   subroutine elastic_read_cards(self, c)
      class(mat_elastic_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call read_mid_ro(self, c)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('DA', 0.0_wp, self%da)
      call c%real('DB', 0.0_wp, self%db)
      call c%real('K', 0.0_wp, self%k)
   end subroutine elastic_read_cards

   subroutine elastic_setup(self, error)
      class(mat_elastic_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (self%k /= 0.0_wp) then
         call set_field_error(error, 'K', 'the fluid option of *MAT_ELASTIC is not supported')
         return
      end if
      call check_elastic_constants(self, self%e, self%pr, error)
   end subroutine elastic_setup

   pure integer function elastic_nhist(self)
      class(mat_elastic_t), intent(in) :: self
      elastic_nhist = 0
   end function elastic_nhist

   !> sig += lambda*tr(deps) I + 2G deps
   subroutine elastic_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_elastic_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: g2, lam, tr
      integer :: i
      g2 = 2.0_wp*self%shear
      lam = self%bulk - g2/3.0_wp
      do i = 1, nv
         tr = lam*(deps(i, 1) + deps(i, 2) + deps(i, 3))
         sig(i, 1) = sig(i, 1) + tr + g2*deps(i, 1)
         sig(i, 2) = sig(i, 2) + tr + g2*deps(i, 2)
         sig(i, 3) = sig(i, 3) + tr + g2*deps(i, 3)
         sig(i, 4) = sig(i, 4) + g2*deps(i, 4)
         sig(i, 5) = sig(i, 5) + g2*deps(i, 5)
         sig(i, 6) = sig(i, 6) + g2*deps(i, 6)
      end do
   end subroutine elastic_update

   !> The exact tangent of the update: d(i,j) = lambda (i, j <= 3) + 2G delta_ij (Voigt,
   !> tensor shears), so the implicit solver's elastic stiffness has no difference error.
   subroutine elastic_tangent(self, dt, deps, relvol, eint, sig, hv, d, ierr)
      class(mat_elastic_t), intent(in) :: self
      real(wp), intent(in) :: dt, deps(6), relvol, eint, sig(6), hv(:)
      real(wp), intent(out) :: d(6, 6)
      integer, intent(out) :: ierr
      real(wp) :: g2
      integer :: i
      g2 = 2.0_wp*self%shear
      d = 0.0_wp
      d(1:3, 1:3) = self%bulk - g2/3.0_wp
      do i = 1, 6
         d(i, i) = d(i, i) + g2
      end do
      ierr = 0
   end subroutine elastic_tangent
end module dx_mat_elastic
