!> The 8-node hexahedron of the implicit solver: internal force and consistent tangent
!> stiffness in the total Lagrangian form (Bathe, "Finite Element Procedures", 1996, ch. 6.3;
!> NIKE3D's hexahedron: Maker, Ferencz & Hallquist, NIKE3D User's Manual, UCRL-MA-105268
!> rev. 1, 1995), 2x2x2 Gauss points, with the mean-dilatation strain of Hughes' B-bar
!> method (Hughes, "Generalization of selective integration procedures to anisotropic and
!> nonlinear media", IJNME 15 (1980) 1413-1418) so that nearly incompressible materials do
!> not lock (ELFORM 1 and 2 both take this element in the implicit solver; dynx's choice).
!> The 4-node tetrahedron (ELFORM 10) takes the same routine with one point (constant strain;
!> the mean dilatation is then the point's own: no B-bar, it locks as nu -> 1/2).
!> Strain: the Green-Lagrange strain E = (H + H^T + H^T H)/2 (H = Grad u) of each point with
!> its volumetric part replaced by the element's reference-volume mean,
!>    Ebar = E + (tr E_mean - tr E)/3 I,    tr E_mean = sum_g w_g tr E_g / V0,
!> so Ebar is a function of the nodal displacements and its linearization is exact:
!>    dEbar = Bbar du,  Bbar = B + (1/3) m (bv_mean - bv_g),  bv = rows 1-3 of B summed,
!>    d2Ebar contracted with S = (S_g - p_g I + p_mean I) : d2E_g  (p = tr S/3),
!> i.e. the geometric stiffness takes each point's stress with its pressure replaced by the
!> element's mean pressure. Stress: the second Piola-Kirchhoff stress S from the material's
!> own update (material_t%update) driven by the increment Ebar - Ebar(committed) from the
!> committed state, and its consistent tangent material_t%tangent (so an elastic material is
!> St. Venant-Kirchhoff, an elastoplastic one additive in Ebar: small elastic strains, any
!> rotation). linear = .true.: the small-displacement form (E = sym H, B at F = I, no
!> geometric stiffness; LS-DYNA's NSOLVR = 1).
module dx_hex8_stiffness
   use dx_kinds, only: wp
   use dx_material, only: material_t
   use dx_element_types, only: ETYPE_HEX8_1PT, ETYPE_HEX8_SRI, ETYPE_TET4
   use dx_hex8_geometry, only: inv3, XI => XI_NODE
   implicit none
   private
   public :: tl_solid_element, tl_supported, tl_points, TL_ERR_JAC, TL_ERR_MAT, TL_NGP, TL_NEN

   integer, parameter :: TL_NGP = 8   !< integration points per element (at most)
   integer, parameter :: TL_NEN = 8   !< nodes per element (at most)
   integer, parameter :: TL_ERR_JAC = 1   !< reference or current Jacobian <= 0
   integer, parameter :: TL_ERR_MAT = 2   !< the material update failed

contains

   !> Whether the implicit solver has an element for the block's element type.
   pure logical function tl_supported(etype)
      integer, intent(in) :: etype
      tl_supported = etype == ETYPE_HEX8_1PT .or. etype == ETYPE_HEX8_SRI .or. etype == ETYPE_TET4
   end function tl_supported

   !> Integration points of the implicit element of a block's type: 2x2x2 for the
   !> hexahedron, 1 for the 4-node tetrahedron (constant strain).
   pure integer function tl_points(etype)
      integer, intent(in) :: etype
      tl_points = merge(1, TL_NGP, etype == ETYPE_TET4)
   end function tl_points

   !> One element. xe0(3, 8) reference coordinates, ue(3, 8) displacements; the committed
   !> state sc(6, 8) (S, Voigt xx yy zz xy yz zx), ec(6, 8) (Ebar, tensor shears), hc(:, 8)
   !> (history); out: the trial state s, e, h, fint(24), ke(24, 24) when want_k, the
   !> element's stress work of the increment dw (trapezoid), its reference-volume average
   !> Cauchy stress cauchy(6) and eps_p-style history average havg; ierr (HEX8_TL_ERR_*).
   subroutine tl_solid_element(mat, xe0, ue, dt, linear, sc, ec, hc, s, e, h, fint, want_k, &
                              ke, dw, cauchy, havg, ierr)
      class(material_t), intent(in) :: mat
      real(wp), intent(in) :: xe0(:, :), ue(:, :), dt
      logical, intent(in) :: linear, want_k
      real(wp), intent(in) :: sc(:, :), ec(:, :), hc(:, :)
      real(wp), intent(out) :: s(:, :), e(:, :), h(:, :)
      real(wp), intent(out) :: fint(:), ke(:, :), dw, cauchy(6), havg(:)
      integer, intent(out) :: ierr
      real(wp) :: g3, dndxi(size(xe0, 2), 3), jac(3, 3), ji(3, 3), det
      real(wp) :: dndx(size(xe0, 2), 3, size(s, 2)), dv(size(s, 2)), f(3, 3, size(s, 2))
      real(wp) :: hg(3, 3), el(3, 3), tre(size(s, 2)), trem, v0
      real(wp) :: b(6, 3*size(xe0, 2), size(s, 2)), bv(3*size(xe0, 2), size(s, 2))
      real(wp) :: bvm(3*size(xe0, 2)), deps(size(s, 2), 6), sig(size(s, 2), 6)
      real(wp) :: relvol(size(s, 2)), eint(size(s, 2)), d(6, 6), st(3, 3), pm, p
      real(wp) :: hv(size(s, 2), max(1, size(hc, 1))), dsig(6), sg(3, 3), c(3, 3)
      real(wp) :: bd(3*size(xe0, 2), 6), tmp(3)
      integer :: g, a, i, col, nh, ie(size(s, 2)), ierrt, bb, nen, ngp
      ierr = 0
      nen = size(xe0, 2)
      ngp = size(s, 2)
      nh = size(hc, 1)
      g3 = 1.0_wp/sqrt(3.0_wp)
      fint = 0.0_wp
      if (want_k) ke = 0.0_wp
      ! ---- pass 1: geometry, deformation gradient and strain at each point
      do g = 1, ngp
         if (nen == 4) then      ! the tetrahedron: N = 1 - xi - eta - zeta, xi, eta, zeta
            dndxi = 0.0_wp
            dndxi(1, :) = -1.0_wp
            do a = 2, 4
               dndxi(a, a - 1) = 1.0_wp
            end do
         end if
         do a = 1, merge(8, 0, nen == 8)
            dndxi(a, 1) = 0.125_wp*XI(1, a)*(1.0_wp + XI(2, a)*XI(2, g)*g3)* &
                          (1.0_wp + XI(3, a)*XI(3, g)*g3)
            dndxi(a, 2) = 0.125_wp*XI(2, a)*(1.0_wp + XI(1, a)*XI(1, g)*g3)* &
                          (1.0_wp + XI(3, a)*XI(3, g)*g3)
            dndxi(a, 3) = 0.125_wp*XI(3, a)*(1.0_wp + XI(1, a)*XI(1, g)*g3)* &
                          (1.0_wp + XI(2, a)*XI(2, g)*g3)
         end do
         jac = matmul(xe0, dndxi)          ! dX_i/dxi_j
         call inv3(jac, ji, det)
         if (.not. (det > 0.0_wp)) then
            ierr = TL_ERR_JAC; return
         end if
         dv(g) = det
         if (nen == 4) dv(g) = det/6.0_wp
         dndx(:, :, g) = matmul(dndxi, ji)  ! dN_a/dX_j
         hg = matmul(ue, dndx(:, :, g))     ! H_ij = du_i/dX_j
         f(:, :, g) = hg
         do i = 1, 3
            f(i, i, g) = f(i, i, g) + 1.0_wp
         end do
         if (linear) then
            el = 0.5_wp*(hg + transpose(hg))
         else
            el = 0.5_wp*(hg + transpose(hg) + matmul(transpose(hg), hg))
            det = jdet(f(:, :, g))
            if (.not. (det > 0.0_wp)) then
               ierr = TL_ERR_JAC; return
            end if
         end if
         e(:, g) = [el(1, 1), el(2, 2), el(3, 3), el(1, 2), el(2, 3), el(3, 1)]
         tre(g) = el(1, 1) + el(2, 2) + el(3, 3)
         ! B: dE (engineering shears) per nodal displacement, at F (linear: at I)
         do a = 1, nen
            do i = 1, 3
               col = 3*(a - 1) + i
               if (linear) then
                  tmp = 0.0_wp
                  tmp(i) = 1.0_wp
               else
                  tmp = f(i, :, g)
               end if
               b(1, col, g) = tmp(1)*dndx(a, 1, g)
               b(2, col, g) = tmp(2)*dndx(a, 2, g)
               b(3, col, g) = tmp(3)*dndx(a, 3, g)
               b(4, col, g) = tmp(1)*dndx(a, 2, g) + tmp(2)*dndx(a, 1, g)
               b(5, col, g) = tmp(2)*dndx(a, 3, g) + tmp(3)*dndx(a, 2, g)
               b(6, col, g) = tmp(3)*dndx(a, 1, g) + tmp(1)*dndx(a, 3, g)
            end do
         end do
         bv(:, g) = b(1, :, g) + b(2, :, g) + b(3, :, g)
      end do
      ! ---- mean dilatation (B-bar)
      v0 = sum(dv)
      trem = sum(dv*tre)/v0
      bvm = matmul(bv, dv)/v0
      do g = 1, ngp
         e(1:3, g) = e(1:3, g) + (trem - tre(g))/3.0_wp
         do i = 1, 3
            b(i, :, g) = b(i, :, g) + (bvm - bv(:, g))/3.0_wp
         end do
      end do
      ! ---- pass 2: the material's update from the committed state
      do g = 1, ngp
         deps(g, :) = e(:, g) - ec(:, g)
         sig(g, :) = sc(:, g)
         hv(g, :) = 0.0_wp
         if (nh > 0) hv(g, 1:nh) = hc(:, g)
         if (linear) then
            relvol(g) = 1.0_wp
         else
            relvol(g) = jdet(f(:, :, g))
         end if
      end do
      eint = 0.0_wp
      ie = 0
      call mat%update(ngp, dt, deps, relvol, eint, sig, hv, ie)
      if (any(ie /= 0)) then
         ierr = TL_ERR_MAT; return
      end if
      dw = 0.0_wp
      do g = 1, ngp
         s(:, g) = sig(g, :)
         if (nh > 0) h(:, g) = hv(g, 1:nh)
         dsig = 0.5_wp*(s(:, g) + sc(:, g))
         dw = dw + dv(g)*(sum(dsig(1:3)*deps(g, 1:3)) + 2.0_wp*sum(dsig(4:6)*deps(g, 4:6)))
      end do
      ! ---- internal force, tangent, Cauchy stress
      pm = sum(dv*(s(1, :) + s(2, :) + s(3, :)))/(3.0_wp*v0)
      cauchy = 0.0_wp
      do g = 1, ngp
         fint = fint + dv(g)*matmul(s(:, g), b(:, :, g))
         sg = voigt_mat(s(:, g))
         if (linear) then
            c = sg
         else
            c = matmul(f(:, :, g), matmul(sg, transpose(f(:, :, g))))/jdet(f(:, :, g))
         end if
         cauchy = cauchy + dv(g)*[c(1, 1), c(2, 2), c(3, 3), c(1, 2), c(2, 3), c(3, 1)]
         if (.not. want_k) cycle
         dsig = deps(g, :)     ! (a contiguous copy of the point's increment)
         call mat%tangent(dt, dsig, relvol(g), eint(g), sc(:, g), hv_of(g), d, ierrt)
         if (ierrt /= 0) then
            ierr = TL_ERR_MAT; return
         end if
         d(:, 4:6) = 0.5_wp*d(:, 4:6)       ! per engineering shear strain
         bd = matmul(transpose(b(:, :, g)), d)
         ke = ke + dv(g)*matmul(bd, b(:, :, g))
         if (linear) cycle
         p = (s(1, g) + s(2, g) + s(3, g))/3.0_wp
         st = sg
         do i = 1, 3
            st(i, i) = st(i, i) - p + pm
         end do
         do a = 1, nen
            do bb = 1, nen
               det = dv(g)*dot_product(dndx(a, :, g), matmul(st, dndx(bb, :, g)))
               do i = 1, 3
                  ke(3*(a - 1) + i, 3*(bb - 1) + i) = ke(3*(a - 1) + i, 3*(bb - 1) + i) + det
               end do
            end do
         end do
      end do
      cauchy = cauchy/v0
      if (size(havg) > 0 .and. nh > 0) havg = matmul(h(1:size(havg), :), dv)/v0
      if (want_k) ke = 0.5_wp*(ke + transpose(ke))   ! (a tangent from differences)
   contains
      function hv_of(gp) result(r)
         integer, intent(in) :: gp
         real(wp) :: r(max(1, nh))
         r = 0.0_wp
         if (nh > 0) r(1:nh) = hc(:, gp)
      end function hv_of
   end subroutine tl_solid_element

   pure function voigt_mat(v) result(m)
      real(wp), intent(in) :: v(6)
      real(wp) :: m(3, 3)
      m = reshape([v(1), v(4), v(6), v(4), v(2), v(5), v(6), v(5), v(3)], [3, 3])
   end function voigt_mat

   !> det a (through the hexahedron's 3x3 inverse, dx_hex8_geometry%inv3)
   pure real(wp) function jdet(a)
      real(wp), intent(in) :: a(3, 3)
      real(wp) :: ai(3, 3)
      call inv3(a, ai, jdet)
   end function jdet
end module dx_hex8_stiffness
