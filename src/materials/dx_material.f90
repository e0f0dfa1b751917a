!> The abstract material interface: every constitutive model extends material_t.
!> Stress update for one chunk of nv integration points at a time (dispatch once per chunk).
!> Conventions: Voigt order xx,yy,zz,xy,yz,zx; tension positive; strain increments are
!> tensor components (deps(:,4) = d_xy*dt, not engineering shear); stress arrives already
!> rotated to the end of the step (Jaumann rate, done by the element).
!> Each model reads its own *MAT_ card(s) through the card cursor (read_cards, dx_card), after
!> the plug-in pattern of neko's run-time selectable types (ExtremeFLOW/neko, init(json)
!> factories); the registry that maps keywords to models is dx_mat_factory.
!> tangent: the consistent tangent d(sig_new)/d(deps) of one stress update; the default is
!> central finite differences of update (Miehe 1996, "Numerical computation of algorithmic
!> (consistent) tangent moduli in large-strain computational inelasticity", CMAME 134).
!> An equation of state (dx_eos) is attached by the part (EOSID) to hydro models only.
!> update_plane_stress: the lamina (shell/beam layer) update with sigma33 = 0, five components
!> xx, yy, xy, yz, zx in the lamina frame, shear strain increments engineering (gamma = 2 eps);
!> the default is plane-stress Hooke's law from K and G (transverse shears elastic, any shear
!> correction factor is the element's). Models with plastic history or an equation of state
!> that do not override it get ierr = MAT_ERR_NO_PLANE_STRESS (the caller names the type).
!> fibre (optional, .true.): the point is a beam's section point (uniaxial stress plus two
!> shears, sigma22 = sigma33 = 0) in the lamina form of dx_plane_stress's ps_fibre_constants:
!> the model uses the fibre constants in place of E and nu (the shear modulus unchanged).
!> ps_alg chooses the plane-stress plasticity algorithm (dx_plane_stress: 1 three secant
!> iterations, 2 full iteration, 3 radial scaling - *CONTROL_SHELL MITER's LS-DYNA values - and
!> 4 dynx's one-step analytic return); the shell build sets it, MAT_ERR_PS_ALG flags other values.
module dx_material
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_curve, only: curve_t
   use dx_card, only: card_t
   use dx_eos, only: eos_t
   use dx_plane_stress, only: ps_fibre_constants
   implicit none
   private
   public :: material_t, mat_holder_t, read_mid_ro, fd_step, fd_tangent
   public :: MAT_ERR_NO_PLANE_STRESS, MAT_ERR_PS_ALG, has_lamina_form

   !> ierr of update_plane_stress for a model that has no plane-stress (lamina) form
   integer, parameter :: MAT_ERR_NO_PLANE_STRESS = 90
   !> ierr of update_plane_stress for a ps_alg outside 1..4
   integer, parameter :: MAT_ERR_PS_ALG = 91

   type, abstract :: material_t
      integer :: label = 0             !< material id (MID) from the deck
      integer :: mtype = 0             !< LS-DYNA material type number (1, 3, 24, ...)
      character(:), allocatable :: title
      real(wp) :: ro = 0.0_wp          !< initial mass density
      real(wp) :: bulk = 0.0_wp        !< elastic bulk modulus K (set by setup)
      real(wp) :: shear = 0.0_wp       !< elastic shear modulus G (set by setup)
      integer :: hv_eps_p = 0          !< history offset of effective plastic strain (0: none)
      !> history offset of the model's damage variable D in [0, 1] (0: none); the plot's damage
      !> row shows it (dx_plot_hdf5), else the Tuler-Butcher D of *MAT_ADD_EROSION
      integer :: hv_damage = 0
      !> the history holds directions fixed in the material (the crack model's fracture triad):
      !> the element calls rotate_history with the spin increments before each update
      logical :: hv_frame = .false.
      logical :: is_rigid = .false.
      integer :: ps_alg = 1            !< plane-stress algorithm (MITER: 1 secant3, 2 full, 3 radial, 4 one-step)
      class(eos_t), allocatable :: eos !< equation of state from the part's EOSID (hydro models)
   contains
      procedure(setup_i), deferred :: setup          !< check parameters, derive K, G, ...
      procedure(nhist_i), deferred :: nhist          !< history variables per integration point
      procedure(update_i), deferred :: update        !< stress update for one chunk
      procedure :: wave_speed => default_wave_speed  !< dilatational wave speed per point
      procedure :: fails => default_fails            !< element erosion flag per point
      procedure :: erodes => default_erodes          !< its fails may be true: the run erodes
      procedure :: resolve_curves => default_resolve !< look up curve labels after the deck is read
      procedure :: read_cards => default_read_cards  !< its *MAT_ cards, through the card cursor
      procedure :: reads_curves => default_reads_curves !< setup must wait for the curves
      procedure :: takes_eos => default_takes_eos    !< may carry an equation of state
      procedure :: needs_eos => default_needs_eos    !< must carry one (EOSID > 0) if it may
      procedure :: eos_ready => default_eos_ready    !< derive data from the attached EOS
      procedure :: tangent => fd_tangent             !< consistent tangent of one update
      procedure :: update_plane_stress => default_update_plane_stress !< lamina update, sigma33 = 0
      procedure :: rotate_history => default_rotate_history !< turn material directions (hv_frame)
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

   !> Card 1 fields 1-2 of every *MAT_: MID (> 0) and RO.
   subroutine read_mid_ro(self, c)
      class(material_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call c%int('MID', 0, self%label)
      if (c%ok() .and. self%label <= 0) &
         call c%fail('MID', 'material id must be > 0, got '//str(self%label))
      call c%real('RO', 0.0_wp, self%ro)
      self%title = c%title()
   end subroutine read_mid_ro

   !> A model without its own reader (its keyword is read elsewhere, as *MAT_RIGID is).
   subroutine default_read_cards(self, c)
      class(material_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call c%fail_block(0, 'material type '//str(self%mtype)//' has no card reader')
   end subroutine default_read_cards

   !> Whether the parameter checks (setup) need the *DEFINE_CURVE data (default: no).
   logical function default_reads_curves(self)
      class(material_t), intent(in) :: self
      default_reads_curves = .false.
      if (.false.) default_reads_curves = self%label < 0
   end function default_reads_curves

   !> Whether the model may carry an equation of state (LS-DYNA: hydro models 9, 10, 11, 15).
   logical function default_takes_eos(self)
      class(material_t), intent(in) :: self
      default_takes_eos = .false.
      if (.false.) default_takes_eos = self%label < 0
   end function default_takes_eos

   !> Whether a model that may carry an equation of state must have one (default: yes; LS-DYNA's
   !> *MAT_JOHNSON_COOK falls back to the elastic bulk modulus when EOSID = 0).
   logical function default_needs_eos(self)
      class(material_t), intent(in) :: self
      default_needs_eos = self%takes_eos()
   end function default_needs_eos

   !> Called once the part has attached the equation of state (self%eos allocated, its rho0
   !> set): models that derive data from it (a cold-energy curve) do it here (default: none).
   subroutine default_eos_ready(self, error)
      class(material_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (.false.) self%label = 0
   end subroutine default_eos_ready

   !> Finite-difference step for the tangent at strain increment deps: h = eps**(1/3) times the
   !> strain scale max(|deps|, 1e-4), the step that balances the round-off error of a central
   !> difference (~eps |sig|/h) against its truncation error (~h**2 |sig'''|/6).
   pure real(wp) function fd_step(deps)
      real(wp), intent(in) :: deps(6)
      fd_step = epsilon(1.0_wp)**(1.0_wp/3.0_wp)*max(maxval(abs(deps)), 1.0e-4_wp)
   end function fd_step

   !> Consistent tangent d(i,j) = d sig_i/d deps_j of one update of a single point from
   !> (sig, hv) by deps (Voigt order; deps(4:6) tensor shear components, so an isotropic
   !> elastic model gives d(4,4) = 2G), by central differences with step fd_step(deps);
   !> relvol and eint are held fixed. ierr /= 0 when an update fails.
   subroutine fd_tangent(self, dt, deps, relvol, eint, sig, hv, d, ierr)
      class(material_t), intent(in) :: self
      real(wp), intent(in) :: dt, deps(6), relvol, eint, sig(6), hv(:)
      real(wp), intent(out) :: d(6, 6)
      integer, intent(out) :: ierr
      real(wp) :: h, dp(1, 6), sp(1, 6), sm(1, 6), hp(1, max(1, size(hv)))
      integer :: j, ie(1)
      h = fd_step(deps)
      ierr = 0
      ie = 0
      do j = 1, 6
         dp(1, :) = deps
         dp(1, j) = deps(j) + h
         sp(1, :) = sig
         hp = 0.0_wp
         hp(1, 1:size(hv)) = hv
         call self%update(1, dt, dp, [relvol], [eint], sp, hp, ie)
         dp(1, j) = deps(j) - h
         sm(1, :) = sig
         hp = 0.0_wp
         hp(1, 1:size(hv)) = hv
         call self%update(1, dt, dp, [relvol], [eint], sm, hp, ie)
         d(:, j) = (sp(1, :) - sm(1, :))/(2.0_wp*h)
      end do
      ierr = ie(1)
   end subroutine fd_tangent

   !> Plane-stress (sigma33 = 0) Hooke's law for nv laminae: with lambda = K - 2G/3 and the
   !> plane-stress lambda lb = 2G lambda/(lambda + 2G) (= E nu/(1 - nu**2)),
   !> dsig_xx = lb (de_xx + de_yy) + 2G de_xx, dsig_yy likewise, dsig_xy = G dgamma_xy and the
   !> transverse shears dsig_yz = G dgamma_yz, dsig_zx = G dgamma_zx (engineering increments).
   !> The thickness strain of such a point is de_zz = -lambda/(lambda + 2G) (de_xx + de_yy).
   !> A model with plastic history (hv_eps_p > 0) or an equation of state that does not override
   !> this has no plane-stress form: its points get ierr = MAT_ERR_NO_PLANE_STRESS, sig unchanged.
   !> dezz (optional): the thickness strain increment of each point.
   subroutine default_update_plane_stress(self, nv, dt, deps, sig, hv, ierr, dezz, fibre)
      class(material_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 5)
      real(wp), intent(inout) :: sig(nv, 5)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp), intent(out), optional :: dezz(nv)
      logical, intent(in), optional :: fibre
      real(wp) :: g, lam, lb, tr, ef, nuf
      integer :: i
      if (self%hv_eps_p > 0 .or. self%takes_eos() .or. self%is_rigid) then
         ierr = MAT_ERR_NO_PLANE_STRESS
         return
      end if
      g = self%shear
      lam = self%bulk - 2.0_wp*g/3.0_wp
      lb = 2.0_wp*g*lam/(lam + 2.0_wp*g)
      if (present(fibre)) then      ! a beam's section point: the fibre constants
         if (fibre) then
            call ps_fibre_constants(g*(3.0_wp*lam + 2.0_wp*g)/(lam + g), g, ef, nuf)
            lb = ef*nuf/(1.0_wp - nuf**2)
         end if
      end if
      do i = 1, nv
         tr = lb*(deps(i, 1) + deps(i, 2))
         sig(i, 1) = sig(i, 1) + tr + 2.0_wp*g*deps(i, 1)
         sig(i, 2) = sig(i, 2) + tr + 2.0_wp*g*deps(i, 2)
         sig(i, 3) = sig(i, 3) + g*deps(i, 3)
         sig(i, 4) = sig(i, 4) + g*deps(i, 4)
         sig(i, 5) = sig(i, 5) + g*deps(i, 5)
      end do
      if (present(dezz)) dezz = -lam/(lam + 2.0_wp*g)*(deps(:, 1) + deps(:, 2))
      if (.false.) sig(1, 1) = sig(1, 1) + dt*hv(1, 1)   ! dt, hv unused by the elastic default
   end subroutine default_update_plane_stress

   !> Whether material m has a lamina (sigma33 = 0) update: one probe of update_plane_stress
   !> from the zero state with a zero increment (rigid materials are the rigid
   !> build's); the shell build refuses a model without one (exit 2 naming the part).
   logical function has_lamina_form(m)
      class(material_t), intent(in) :: m
      real(wp) :: de5(1, 5), s5(1, 5), hv(1, max(1, m%nhist()))
      integer :: ierr(1)
      has_lamina_form = .true.
      if (m%is_rigid) return
      de5 = 0.0_wp
      s5 = 0.0_wp
      hv = 0.0_wp
      ierr = 0
      call m%update_plane_stress(1, 1.0_wp, de5, s5, hv, ierr)
      has_lamina_form = ierr(1) /= MAT_ERR_NO_PLANE_STRESS
   end function has_lamina_form

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

   !> Whether the model's fails can flag points, so that the run does element erosion (contact
   !> surfaces refreshed, eroded energies in glstat); default .false.: the models that fail
   !> points without it (FS, FAIL, Johnson-Cook damage) keep their outputs.
   logical function default_erodes(self)
      class(material_t), intent(in) :: self
      default_erodes = .false.
      if (.false.) default_erodes = self%label < 0
   end function default_erodes

   !> Turn the directions a model keeps in its history with the material, by the spin
   !> increments (w12, w23, w31) = W dt of the element's Jaumann rotation of the stress, for the
   !> points 1..n (called only when hv_frame is set; default: nothing to turn).
   subroutine default_rotate_history(self, n, w12, w23, w31, hv)
      class(material_t), intent(in) :: self
      integer, intent(in) :: n
      real(wp), intent(in) :: w12(:), w23(:), w31(:)
      real(wp), intent(inout) :: hv(:, :)
      if (.false.) hv(1, 1) = w12(n) + w23(n) + w31(n) + self%ro
   end subroutine default_rotate_history

   !> Materials that reference *DEFINE_CURVE ids copy the curves here (default: none).
   subroutine default_resolve(self, curves, error)
      class(material_t), intent(inout) :: self
      type(curve_t), intent(in) :: curves(:)
      type(error_t), allocatable, intent(out) :: error
      if (.false. .and. size(curves) < 0) self%label = 0
   end subroutine default_resolve
end module dx_material
