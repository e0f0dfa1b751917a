!> Plane-stress (sigma33 = 0) J2 return for shell and beam laminae, mixed hardening, four
!> algorithms (selected per material by material_t%ps_alg; docs/design.md "Plane-stress laminae"):
!>   PS_SECANT3  = 1  fixed three secant iterations on the consistency condition of the exact
!>                    return (LS-DYNA *CONTROL_SHELL MITER = 1, the default; the secant form is
!>                    recalled, physics-references.md 3.2 (U));
!>   PS_FULL     = 2  the exact (closest-point, backward Euler) return solved to round-off by a
!>                    safeguarded Newton iteration (MITER = 2, the reference);
!>   PS_RADIAL   = 3  radial stress scaling onto the updated yield radius (MITER = 3);
!>   PS_ONE_STEP = 4  the one-step analytic return of Yuen/DYNA3D (LLNL FY97 Thrust Area Report,
!>                    article 5: flow direction frozen at the trial state, the consistency
!>                    condition then a quadratic in the plastic multiplier; dynx's own value).
!> Notation: xi = sig - alpha the in-plane relative stress (xi12 the shear stress); the von Mises
!> radius sbar^2 = xi11^2 + xi22^2 - xi11 xi22 + 3 xi12^2 = xi^T M xi = s^2/4 + 3d^2/4 + 3t^2 with
!> the modes s = xi11 + xi22, d = xi11 - xi22, t = xi12. Flow depsp = lam M xi (engineering
!> shear), so the effective plastic strain increment is depbar = lam sbar.
!> Back stress by Ziegler's rule in the plane-stress space, dalpha = Hk depbar xi/sbar = Hk lam xi
!> (Hk the kinematic modulus (1 - BETA) Ep): it reproduces the 3-D Prager rule of *MAT_003 in
!> uniaxial stress (OpenRadioss law 2, m2cplr.F, uses the same form). Isotropic radius Y(epsp)
!> with slope Hi (rate factor included).
!> The exact return (Simo & Taylor 1986, IJNME 22:649-670; Simo & Hughes 1998, Computational
!> Inelasticity, 3.4): C M is diagonal in the modes, with eigenvalues E/(2(1 - nu)) for s and 3G
!> for d and t, so the end state is s = s*/(1 + lam a1), (d, t) = (d*, t*)/(1 + lam a2) with
!> a1 = E/(2(1 - nu)) + Hk, a2 = 3G + Hk, and lam solves sbar(lam) = Y(epsp + lam sbar(lam)).
!> The one-step return replaces 1/(1 + lam a) by 1 - lam a (the trial normal; dalpha = Hk lam xi*):
!> then A (1 - lam a1)^2 + B (1 - lam a2)^2 = (Y_n + Hi sbar* lam)^2 with A = s*^2/4,
!> B = 3d*^2/4 + 3t*^2, whose smallest positive root is taken (no iteration); the result lies on
!> the yield surface to round-off for linear hardening. When no root exists or it lies beyond
!> lam = 1/a2 (the deviatoric modes would change sign; only for trial radii several times Y)
!> the point takes the radial scaling below; with tabulated hardening the one-step stress is
!> scaled radially onto the curve's Y(epsp + depbar).
!> Radial scaling: depbar = (sbar* - Y_n)/(3G + Hi + Hk), xi = xi* Y(epsp + depbar)/sbar*
!> (DYNA3D's non-iterative option; it ignores the sigma33 = 0 consistency of the plastic flow).
!> Transverse shears (components 4, 5) are elastic. dezz: the thickness strain increment,
!> elastic -nu/E (dsig11 + dsig22) plus plastic -(depsp11 + depsp22).
module dx_plane_stress
   use dx_kinds, only: wp
   use dx_curve, only: curve_t
   implicit none
   private
   public :: PS_SECANT3, PS_FULL, PS_RADIAL, PS_ONE_STEP, ps_alg_name, ps_alg_valid
   public :: ps_update, ps_full_lambda, ps_rate

   integer, parameter :: PS_SECANT3 = 1, PS_FULL = 2, PS_RADIAL = 3, PS_ONE_STEP = 4

contains

   pure function ps_alg_name(alg) result(name)
      integer, intent(in) :: alg
      character(:), allocatable :: name
      select case (alg)
      case (PS_SECANT3); name = 'secant, 3 iterations (MITER = 1)'
      case (PS_FULL); name = 'full iteration (MITER = 2)'
      case (PS_RADIAL); name = 'radial scaling (MITER = 3)'
      case (PS_ONE_STEP); name = 'one-step analytic (MITER = 4, dynx)'
      case default; name = 'unknown'
      end select
   end function ps_alg_name

   pure logical function ps_alg_valid(alg)
      integer, intent(in) :: alg
      ps_alg_valid = alg >= PS_SECANT3 .and. alg <= PS_ONE_STEP
   end function ps_alg_valid

   !> Effective strain rate of a lamina step (U: LS-DYNA's exact shell measure not confirmed):
   !> sqrt(2/3 e':e')/dt with the thickness strain of incompressible flow, e33 = -(e11 + e22),
   !> so 2/3 e':e' = 4/3 (e11^2 + e22^2 + e11 e22) + (gamxy^2 + gamyz^2 + gamzx^2)/3.
   pure real(wp) function ps_rate(dt, de) result(rate)
      real(wp), intent(in) :: dt, de(5)
      rate = 0.0_wp
      if (dt > 0.0_wp) rate = sqrt((4.0_wp/3.0_wp)*(de(1)**2 + de(2)**2 + de(1)*de(2)) + &
                                   (de(3)**2 + de(4)**2 + de(5)**2)/3.0_wp)/dt
   end function ps_rate

   !> One plane-stress update of nv laminae by algorithm alg.
   !> sig(nv,5) xx yy xy yz zx, deps(nv,5) with engineering shears; alpha(nv,3) the in-plane back
   !> stress (xx, yy, xy); epsp(nv) effective plastic strain. The isotropic radius at the start,
   !> y0 > 0 (rate factor included), and its slope hi >= 0 per point; hk the kinematic modulus.
   !> With crv present the radius is r(i)*crv(epsp) (tabulated hardening; y0, hi its value and
   !> slope at epsp), else y0 + hi*depbar. dep: depbar of the step. ierr(i) = 1 where the full
   !> iteration did not converge. Points whose trial radius is inside Y keep the trial stress
   !> exactly.
   subroutine ps_update(alg, nv, e, nu, g, deps, sig, alpha, epsp, y0, hi, hk, dep, ierr, &
                        crv, r, dezz)
      integer, intent(in) :: alg, nv
      real(wp), intent(in) :: e, nu, g, deps(nv, 5), y0(nv), hi(nv), hk
      real(wp), intent(inout) :: sig(nv, 5), alpha(nv, 3), epsp(nv)
      real(wp), intent(out) :: dep(nv)
      integer, intent(inout) :: ierr(nv)
      type(curve_t), intent(in), optional :: crv
      real(wp), intent(in), optional :: r(nv)
      real(wp), intent(out), optional :: dezz(nv)
      real(wp) :: lb, a1, a2, c3
      real(wp) :: st(3), xs(3), s, d, t, aa, bb, sb2, sb, c0, c2, q, disc, lam, f1, f2
      real(wp) :: l0, l1, l2, p0, p1, den, so, ynew, sc, xn(3), sn, dn, tn, da(3), depl, sumdp
      logical :: pl, fix
      integer :: i, it, nit
      lb = e*nu/(1.0_wp - nu**2)
      a1 = e/(2.0_wp*(1.0_wp - nu)) + hk
      a2 = 3.0_wp*g + hk
      c3 = 3.0_wp*g
      do i = 1, nv
         so = sig(i, 1) + sig(i, 2)
         ! elastic trial (plane-stress Hooke, engineering shears)
         st(1) = sig(i, 1) + lb*(deps(i, 1) + deps(i, 2)) + 2.0_wp*g*deps(i, 1)
         st(2) = sig(i, 2) + lb*(deps(i, 1) + deps(i, 2)) + 2.0_wp*g*deps(i, 2)
         st(3) = sig(i, 3) + g*deps(i, 3)
         sig(i, 4) = sig(i, 4) + g*deps(i, 4)
         sig(i, 5) = sig(i, 5) + g*deps(i, 5)
         xs = st - alpha(i, :)
         s = xs(1) + xs(2)
         d = xs(1) - xs(2)
         t = xs(3)
         aa = 0.25_wp*s*s
         bb = 0.75_wp*d*d + 3.0_wp*t*t
         sb2 = aa + bb
         pl = sb2 > y0(i)**2
         sb = sqrt(max(sb2, tiny(1.0_wp)))
         c0 = max(sb2 - y0(i)**2, 0.0_wp)
         select case (alg)
         case (PS_ONE_STEP)
            c2 = aa*a1*a1 + bb*a2*a2 - (hi(i)*sb)**2
            q = aa*a1 + bb*a2 + y0(i)*hi(i)*sb
            disc = q*q - c2*c0
            fix = disc < 0.0_wp
            ! smallest positive root (stable form); the vertex q/c2 (c2 > 0) when none
            lam = merge(q/merge(c2, 1.0_wp, fix), c0/max(q + sqrt(max(disc, 0.0_wp)), tiny(1.0_wp)), &
                        fix)
            fix = fix .or. lam*a2 > 1.0_wp
            ! outside its range (no root, or the deviatoric modes past zero) the radial scaling
            depl = merge(c0/((sb + y0(i))*(c3 + hi(i) + hk)), lam*sb, fix)
            lam = merge(depl/sb, lam, fix)
            f1 = merge(1.0_wp, 1.0_wp - lam*a1, fix)
            f2 = merge(1.0_wp, 1.0_wp - lam*a2, fix)
            sn = s*f1; dn = d*f2; tn = t*f2
            da = hk*lam*xs
            sumdp = 0.5_wp*lam*s
         case (PS_RADIAL)
            depl = c0/((sb + y0(i))*(c3 + hi(i) + hk))     ! (sb - y0)/(3G + H), without cancellation
            fix = .true.
            sn = s; dn = d; tn = t
            da = hk*(depl/sb)*xs
            sumdp = 0.5_wp*(depl/sb)*s
            lam = depl/sb
         case (PS_SECANT3)
            l0 = 0.0_wp
            p0 = c0
            l1 = c0/((sb + y0(i))*(c3 + hi(i) + hk)*y0(i))
            p1 = phi2(l1)
            do it = 1, 3
               den = p1 - p0
               l2 = max(0.0_wp, merge(l1 - p1*(l1 - l0)/merge(den, 1.0_wp, den /= 0.0_wp), l1, &
                                      den /= 0.0_wp))
               l0 = l1; p0 = p1; l1 = l2
               if (it < 3) p1 = phi2(l1)
            end do
            lam = l1
            f1 = 1.0_wp/(1.0_wp + lam*a1)
            f2 = 1.0_wp/(1.0_wp + lam*a2)
            sn = s*f1; dn = d*f2; tn = t*f2
            depl = lam*sqrt(0.25_wp*sn*sn + 0.75_wp*dn*dn + 3.0_wp*tn*tn)
            fix = .false.
            da = hk*lam*[0.5_wp*(sn + dn), 0.5_wp*(sn - dn), tn]
            sumdp = 0.5_wp*lam*sn
         case default   ! PS_FULL
            lam = 0.0_wp
            if (pl) then
               if (present(crv)) then
                  lam = ps_full_lambda(aa, bb, a1, a2, y0(i), hi(i), epsp(i), nit, crv=crv, r=r(i))
               else
                  lam = ps_full_lambda(aa, bb, a1, a2, y0(i), hi(i), epsp(i), nit)
               end if
               if (lam < 0.0_wp) then
                  ierr(i) = 1
                  lam = 0.0_wp
               end if
            end if
            f1 = 1.0_wp/(1.0_wp + lam*a1)
            f2 = 1.0_wp/(1.0_wp + lam*a2)
            sn = s*f1; dn = d*f2; tn = t*f2
            depl = lam*sqrt(0.25_wp*sn*sn + 0.75_wp*dn*dn + 3.0_wp*tn*tn)
            fix = .false.
            da = hk*lam*[0.5_wp*(sn + dn), 0.5_wp*(sn - dn), tn]
            sumdp = 0.5_wp*lam*sn
         end select
         xn = [0.5_wp*(sn + dn), 0.5_wp*(sn - dn), tn]
         ! the one-step fallback, the radial scaling and tabulated hardening: radius onto Y
         if (present(crv)) then
            ynew = r(i)*crv%eval_extrap(epsp(i) + depl)
            fix = fix .or. alg == PS_ONE_STEP
         else
            ynew = y0(i) + hi(i)*depl
         end if
         if (fix) then
            sc = ynew/sqrt(max(0.25_wp*sn*sn + 0.75_wp*dn*dn + 3.0_wp*tn*tn, tiny(1.0_wp)))
            xn = xn*sc
         end if
         if (pl) then
            alpha(i, :) = alpha(i, :) + da
            sig(i, 1:3) = alpha(i, :) + xn
            epsp(i) = epsp(i) + depl
            dep(i) = depl
         else
            sig(i, 1:3) = st
            dep(i) = 0.0_wp
            sumdp = 0.0_wp
         end if
         if (present(dezz)) dezz(i) = -nu/e*(sig(i, 1) + sig(i, 2) - so) - sumdp
      end do
   contains
      !> sigma-bar(lam)^2 - Y(epsp + lam sigma-bar(lam))^2 of the exact return at multiplier l
      pure real(wp) function phi2(l)
         real(wp), intent(in) :: l
         real(wp) :: g1, g2, sbl, y
         g1 = 1.0_wp/(1.0_wp + l*a1)
         g2 = 1.0_wp/(1.0_wp + l*a2)
         sbl = sqrt(aa*g1*g1 + bb*g2*g2)
         if (present(crv)) then
            y = r(i)*crv%eval_extrap(epsp(i) + l*sbl)
         else
            y = y0(i) + hi(i)*l*sbl
         end if
         phi2 = sbl*sbl - y*y
      end function phi2
   end subroutine ps_update

   !> The exact return's multiplier: sbar(lam) = Y(epsp + lamsbar(lam)) with sbar(lam)^2 = A/(1 + lama1)^2 +
   !> B/(1 + lama2)^2, by Newton's method safeguarded by bisection on [0, sbar*/(y0 a1)] (where
   !> sbar < y0 <= Y for a non-softening radius). Stops when |residual| <= 4 eps Y or the bracket
   !> is 4 eps wide; nit: Newton steps taken; res(k): |residual|/Y after step k (optional).
   !> Returns -1 when 100 steps do not converge.
   function ps_full_lambda(aa, bb, a1, a2, y0, hi, epsp, nit, crv, r, res) result(lam)
      real(wp), intent(in) :: aa, bb, a1, a2, y0, hi, epsp
      integer, intent(out) :: nit
      type(curve_t), intent(in), optional :: crv
      real(wp), intent(in), optional :: r
      real(wp), intent(out), optional :: res(:)
      real(wp) :: lam
      real(wp) :: lo, hi_l, g1, g2, sbl, dsb, y, dy, f, df, tol
      integer :: it
      lo = 0.0_wp
      hi_l = sqrt(aa + bb)/(y0*a1)
      ! start from the radial estimate (exact for pure shear with linear hardening)
      lam = min(max(0.0_wp, (sqrt(aa + bb) - y0)/((a2 + hi)*y0)), hi_l)
      nit = 0
      if (present(res)) res = 0.0_wp
      do it = 1, 100
         g1 = 1.0_wp/(1.0_wp + lam*a1)
         g2 = 1.0_wp/(1.0_wp + lam*a2)
         sbl = sqrt(aa*g1*g1 + bb*g2*g2)
         dsb = -(aa*a1*g1**3 + bb*a2*g2**3)/sbl
         if (present(crv)) then
            y = r*crv%eval_extrap(epsp + lam*sbl)
            dy = r*crv%slope(epsp + lam*sbl)
         else
            y = y0 + hi*lam*sbl
            dy = hi
         end if
         f = sbl - y
         tol = 4.0_wp*epsilon(1.0_wp)*y
         if (present(res)) then
            if (it <= size(res)) res(it) = abs(f)/y
         end if
         if (abs(f) <= tol) return
         if (f > 0.0_wp) then
            lo = lam
         else
            hi_l = lam
         end if
         if (hi_l - lo <= 4.0_wp*epsilon(1.0_wp)*hi_l) return
         df = dsb - dy*(sbl + lam*dsb)
         nit = nit + 1
         if (df < 0.0_wp) then
            lam = lam - f/df
         else
            lam = 0.5_wp*(lo + hi_l)
         end if
         if (lam <= lo .or. lam >= hi_l) lam = 0.5_wp*(lo + hi_l)
      end do
      lam = -1.0_wp
   end function ps_full_lambda
end module dx_plane_stress
