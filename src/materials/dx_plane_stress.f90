!> Plane-stress (sigma33 = 0) J2 return for shell and beam laminae, mixed hardening, four
!> algorithms (selected per material by material_t%ps_alg; docs/design.md "Plane-stress laminae"):
!>   PS_SECANT3  = 1  fixed three secant iterations on the consistency condition of the exact
!>                    return (LS-DYNA *CONTROL_SHELL MITER = 1, the default; the secant form is
!>                    recalled, physics-references.md 3.2 (U));
!>   PS_FULL     = 2  the exact (closest-point, backward Euler) return solved to round-off by a
!>                    safeguarded Newton iteration (MITER = 2, the reference);
!>   PS_RADIAL   = 3  radial stress scaling onto the updated yield radius (MITER = 3);
!>   PS_ONE_STEP = 4  the one-step analytic return of DYNA3D (LLNL FY97 Engineering Thrust Area
!>                    Report, article 5, ../shared/seed: flow direction frozen, here at the trial
!>                    state, the consistency condition then a quadratic in the plastic
!>                    multiplier; 4 is dynx's own MITER value);
!>   PS_ONE_STEP_N = 5  the same with the normal where the step enters the yield surface (study).
!> Notation: xi = sig - alpha the in-plane relative stress (xi12 the shear stress); the von Mises
!> radius sbar^2 = xi11^2 + xi22^2 - xi11 xi22 + 3 xi12^2 = xi^T M xi = s^2/4 + 3d^2/4 + 3t^2 with
!> the modes s = xi11 + xi22, d = xi11 - xi22, t = xi12. Flow depsp = lam M xi (engineering
!> shear), so the effective plastic strain increment is depbar = lam sbar.
!> Back stress by Ziegler's rule in the plane-stress space, dalpha = Hk depbar xi/sbar = Hk lam xi
!> (Hk the kinematic modulus (1 - BETA) Ep): it reproduces the 3-D Prager rule of *MAT_003 in
!> uniaxial stress (OpenRadioss law 2, m2cplr.F, uses the same form; the seed's hardening law,
!> Eq. 3, garbled by the OCR, reads dalpha ~ (1 - beta) H (sigma - alpha)/||.|| deps-bar, the same
!> direction, and its Eq. 2 d(sigma-bar) = beta H deps-bar the same split of H). Isotropic radius
!> Y(epsp) with slope Hi (rate factor included).
!> The exact return (Simo & Taylor 1986, IJNME 22:649-670; Simo & Hughes 1998, Computational
!> Inelasticity, 3.4): C M is diagonal in the modes, with eigenvalues E/(2(1 - nu)) for s and 3G
!> for d and t, so the end state is s = s*/(1 + lam a1), (d, t) = (d*, t*)/(1 + lam a2) with
!> a1 = E/(2(1 - nu)) + Hk, a2 = 3G + Hk, and lam solves sbar(lam) = Y(epsp + lam sbar(lam)).
!> The one-step return replaces 1/(1 + lam a) by 1 - lam a (the trial normal; dalpha = Hk lam xi*):
!> then A (1 - lam a1)^2 + B (1 - lam a2)^2 = (Y_n + Hi sbar* lam)^2 with A = s*^2/4,
!> B = 3d*^2/4 + 3t*^2, whose smallest positive root is taken (no iteration); the result lies on
!> the yield surface to round-off for linear hardening. When no root exists or it lies beyond
!> lam a2 = 3/4 (at 1 the deviatoric modes would change sign; trial radii above about 1.75 Y,
!> increments above ~1e-3; the threshold is measured in docs/studies/lamina.md) the point takes
!> the radial scaling below; with tabulated hardening the one-step stress is scaled radially onto
!> the curve's Y(epsp + depbar).
!> Radial scaling: depbar = (sbar* - Y_n)/(3G + Hi + Hk), xi = xi* Y(epsp + depbar)/sbar*
!> (DYNA3D's non-iterative option; it ignores the sigma33 = 0 consistency of the plastic flow).
!> Transverse shears (components 4, 5) are elastic. dezz: the thickness strain increment,
!> elastic -nu/E (dsig11 + dsig22) plus plastic -(depsp11 + depsp22).
!> Beam section points (the Hughes-Liu beam, dx_beam_hl; Hughes & Liu 1981): uniaxial stress
!> x = sig11 plus the two shears t2 = sig12, t3 = sig13 (sig22 = sig33 = sig23 = 0), von Mises
!> radius x^2 + 3 t2^2 + 3 t3^2, elastic factors E and G. The lamina with xi11 = x + t3,
!> xi22 = x - t3, xi12 = t2 has the modes s = 2x, d = 2 t3, t = t2 and the same radius; its
!> return scales s by 1/(1 + lam a1) and (d, t) by 1/(1 + lam a2). With the fibre constants
!> (ps_fibre_constants) Ef, nuf for which Ef/(2(1 - nuf)) = E and Ef/(2(1 + nuf)) = G, the
!> lamina's trial (strain increments de11/2 + dg13/2, de11/2 - dg13/2, dg12) and every one of the
!> algorithms above are the beam point's, exactly: no second return mapping (dx_beam_hl).
module dx_plane_stress
   use dx_kinds, only: wp
   use dx_curve, only: curve_t
   implicit none
   private
   public :: PS_SECANT3, PS_FULL, PS_RADIAL, PS_ONE_STEP, PS_ONE_STEP_N, ps_alg_name, ps_alg_valid
   public :: ps_update, ps_full_lambda, ps_rate, ps_fibre_constants

   integer, parameter :: PS_SECANT3 = 1, PS_FULL = 2, PS_RADIAL = 3, PS_ONE_STEP = 4
   !> the one-step return with the normal where the step enters the yield surface (the seed's
   !> Eqs. 1-4 read with a = df/dsig at the current stress): a study variant
   integer, parameter :: PS_ONE_STEP_N = 5

contains

   pure function ps_alg_name(alg) result(name)
      integer, intent(in) :: alg
      character(:), allocatable :: name
      select case (alg)
      case (PS_SECANT3); name = 'secant, 3 iterations (MITER = 1)'
      case (PS_FULL); name = 'full iteration (MITER = 2)'
      case (PS_RADIAL); name = 'radial scaling (MITER = 3)'
      case (PS_ONE_STEP); name = 'one-step analytic (MITER = 4, dynx)'
      case (PS_ONE_STEP_N); name = 'one-step, entry normal (5, dynx study)'
      case default; name = 'unknown'
      end select
   end function ps_alg_name

   pure logical function ps_alg_valid(alg)
      integer, intent(in) :: alg
      ps_alg_valid = alg >= PS_SECANT3 .and. alg <= PS_ONE_STEP_N
   end function ps_alg_valid

   !> The fibre constants of a beam section point (module header): nuf = (E - G)/(E + G),
   !> Ef = 2 G (1 + nuf), so that Ef/(2(1 - nuf)) = E and Ef/(2(1 + nuf)) = G.
   pure subroutine ps_fibre_constants(e, g, ef, nuf)
      real(wp), intent(in) :: e, g
      real(wp), intent(out) :: ef, nuf
      nuf = (e - g)/(e + g)
      ef = 2.0_wp*g*(1.0_wp + nuf)
   end subroutine ps_fibre_constants

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
   !> iteration did not converge. Points whose trial radius is inside Y keep the trial stress and
   !> their history bitwise. The loops of 1, 3 and 4 are straight-line code (every quotient is
   !> computed for every point, branches are blends with 0/1 weights), so they vectorize.
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
      ! per point: trial stress, relative-stress modes (s, d, t), mode factors of the result
      ! (fs, fd), multiplier, flow/kinematic direction modes (dirs, dird, dirt), depbar, the
      ! radial-scaling weight wfx (1: scale onto the new radius ynew)
      real(wp) :: st(nv, 3), s(nv), d(nv), t(nv), aa(nv), bb(nv), sb(nv), c0(nv)
      real(wp) :: fs(nv), fd(nv), lam(nv), dirs(nv), dird(nv), dirt(nv), depl(nv), sumdp(nv)
      real(wp) :: wfx(nv), wpl(nv), ynew(nv), so(nv)
      real(wp) :: lb, a1, a2, c3, c2, q, disc, l0, l1, p0, p1, den, sc, sn, dn, tn, lv, lr, wv, wb
      real(wp) :: xo(3), dl(3), so0, do0, to0, dls, dld, dlt, qa, qb, qc, rq, rr, se
      logical :: bad, tab
      integer :: i, it, nit
      lb = e*nu/(1.0_wp - nu**2)
      a1 = e/(2.0_wp*(1.0_wp - nu)) + hk
      a2 = 3.0_wp*g + hk
      c3 = 3.0_wp*g
      tab = present(crv)
      ! elastic trial (plane-stress Hooke, engineering shears) and its modes
      do i = 1, nv
         st(i, 1) = sig(i, 1) + lb*(deps(i, 1) + deps(i, 2)) + 2.0_wp*g*deps(i, 1)
         st(i, 2) = sig(i, 2) + lb*(deps(i, 1) + deps(i, 2)) + 2.0_wp*g*deps(i, 2)
         st(i, 3) = sig(i, 3) + g*deps(i, 3)
         s(i) = (st(i, 1) - alpha(i, 1)) + (st(i, 2) - alpha(i, 2))
         d(i) = (st(i, 1) - alpha(i, 1)) - (st(i, 2) - alpha(i, 2))
         t(i) = st(i, 3) - alpha(i, 3)
         aa(i) = 0.25_wp*s(i)*s(i)
         bb(i) = 0.75_wp*d(i)*d(i) + 3.0_wp*t(i)*t(i)
         sb(i) = sqrt(max(aa(i) + bb(i), tiny(1.0_wp)))
         c0(i) = max(aa(i) + bb(i) - y0(i)**2, 0.0_wp)
         wpl(i) = merge(1.0_wp, 0.0_wp, aa(i) + bb(i) > y0(i)**2)   ! 1: plastic
      end do
      select case (alg)
      case (PS_ONE_STEP)
         do i = 1, nv
            c2 = aa(i)*a1*a1 + bb(i)*a2*a2 - (hi(i)*sb(i))**2
            q = aa(i)*a1 + bb(i)*a2 + y0(i)*hi(i)*sb(i)
            disc = q*q - c2*c0(i)
            ! smallest positive root (stable form) c0/(q + sqrt(disc)); the vertex q/c2 (c2 > 0)
            ! when there is none: one quotient of blended numerator and denominator
            wv = merge(1.0_wp, 0.0_wp, disc < 0.0_wp)
            l1 = (c0(i) + wv*(q - c0(i)))/max(q + sqrt(max(disc, 0.0_wp)) + &
                                              wv*(c2 - q - sqrt(max(disc, 0.0_wp))), tiny(1.0_wp))
            ! outside its range (no root, or lam a2 > 3/4: docs/studies/lamina.md) radial scaling
            wb = max(wv, merge(1.0_wp, 0.0_wp, l1*a2 > 0.75_wp))
            l0 = c0(i)/((sb(i) + y0(i))*(c3 + hi(i) + hk)*sb(i))
            lam(i) = l1 + wb*(l0 - l1)
            fs(i) = 1.0_wp - (1.0_wp - wb)*l1*a1
            fd(i) = 1.0_wp - (1.0_wp - wb)*l1*a2
            dirs(i) = s(i); dird(i) = d(i); dirt(i) = t(i)
            depl(i) = lam(i)*sb(i)
            wfx(i) = wb
         end do
      case (PS_ONE_STEP_N)
         do i = 1, nv
            ! flow direction: the relative stress where the step enters the yield surface,
            ! xi_n + r dl with sbar(xi_n + r dl) = Y_n (r = 0 on the surface)
            xo = sig(i, 1:3) - alpha(i, :)
            dl = st(i, :) - sig(i, 1:3)
            so0 = xo(1) + xo(2); do0 = xo(1) - xo(2); to0 = xo(3)
            dls = dl(1) + dl(2); dld = dl(1) - dl(2); dlt = dl(3)
            qa = 0.25_wp*dls*dls + 0.75_wp*dld*dld + 3.0_wp*dlt*dlt
            qb = 0.25_wp*so0*dls + 0.75_wp*do0*dld + 3.0_wp*to0*dlt
            qc = max(y0(i)**2 - (0.25_wp*so0*so0 + 0.75_wp*do0*do0 + 3.0_wp*to0*to0), 0.0_wp)
            rq = sqrt(qb*qb + qa*qc)
            rr = merge(qc/max(qb + rq, tiny(1.0_wp)), (rq - qb)/max(qa, tiny(1.0_wp)), qb >= 0.0_wp)
            rr = min(max(rr, 0.0_wp), 1.0_wp)
            dirs(i) = so0 + rr*dls; dird(i) = do0 + rr*dld; dirt(i) = to0 + rr*dlt
            se = sqrt(max(0.25_wp*dirs(i)**2 + 0.75_wp*dird(i)**2 + 3.0_wp*dirt(i)**2, tiny(1.0_wp)))
            c2 = 0.25_wp*(a1*dirs(i))**2 + 0.75_wp*(a2*dird(i))**2 + 3.0_wp*(a2*dirt(i))**2 - &
                 (hi(i)*se)**2
            q = 0.25_wp*a1*s(i)*dirs(i) + 0.75_wp*a2*d(i)*dird(i) + 3.0_wp*a2*t(i)*dirt(i) + &
                y0(i)*hi(i)*se
            disc = q*q - c2*c0(i)
            lv = q*c2/max(c2*c2, tiny(1.0_wp))
            lr = c0(i)/max(q + sqrt(max(disc, 0.0_wp)), tiny(1.0_wp))
            l1 = merge(lv, lr, disc < 0.0_wp)
            bad = disc < 0.0_wp .or. .not. (q > 0.0_wp) .or. l1*a2*se > 0.75_wp*sb(i)
            ! the end modes s - lam a1 dirs, ...: kept in s, d, t with factors 1
            sn = s(i) - l1*a1*dirs(i); dn = d(i) - l1*a2*dird(i); tn = t(i) - l1*a2*dirt(i)
            l0 = c0(i)/((sb(i) + y0(i))*(c3 + hi(i) + hk))/sb(i)
            lam(i) = merge(l0, l1, bad)
            depl(i) = merge(l0*sb(i), l1*se, bad)
            dirs(i) = merge(s(i), dirs(i), bad); dird(i) = merge(d(i), dird(i), bad)
            dirt(i) = merge(t(i), dirt(i), bad)
            s(i) = merge(s(i), sn, bad); d(i) = merge(d(i), dn, bad); t(i) = merge(t(i), tn, bad)
            fs(i) = 1.0_wp; fd(i) = 1.0_wp
            wfx(i) = merge(1.0_wp, 0.0_wp, bad)
         end do
      case (PS_RADIAL)
         do i = 1, nv
            depl(i) = c0(i)/((sb(i) + y0(i))*(c3 + hi(i) + hk))   ! (sb - y0)/(3G + H)
            lam(i) = depl(i)/sb(i)
            fs(i) = 1.0_wp; fd(i) = 1.0_wp
            dirs(i) = s(i); dird(i) = d(i); dirt(i) = t(i)
            wfx(i) = 1.0_wp
         end do
      case (PS_SECANT3)
         ! lam0 = 0, lam1 the radial estimate, then three secant steps on phi2, no test; the
         ! linear-radius loop is straight-line code (a secant step is zero once phi repeats)
         if (tab) then
            do i = 1, nv
               l0 = 0.0_wp
               p0 = c0(i)
               l1 = c0(i)/((sb(i) + y0(i))*(c3 + hi(i) + hk)*y0(i))
               do it = 1, 3
                  p1 = phi2_tab(l1, aa(i), bb(i), a1, a2, r(i), epsp(i), crv)
                  den = p1 - p0
                  lv = p1*(l1 - l0)*den/max(den*den, tiny(1.0_wp))
                  l0 = l1; p0 = p1
                  l1 = max(0.0_wp, l1 - lv)
               end do
               lam(i) = l1
            end do
         else
            do i = 1, nv
               l0 = 0.0_wp
               p0 = c0(i)
               l1 = c0(i)/((sb(i) + y0(i))*(c3 + hi(i) + hk)*y0(i))
               do it = 1, 3
                  p1 = phi2_lin(l1, aa(i), bb(i), a1, a2, y0(i), hi(i))
                  den = p1 - p0
                  lv = p1*(l1 - l0)*den/max(den*den, tiny(1.0_wp))
                  l0 = l1; p0 = p1
                  l1 = max(0.0_wp, l1 - lv)
               end do
               lam(i) = l1
            end do
         end if
         do i = 1, nv
            fs(i) = 1.0_wp/(1.0_wp + lam(i)*a1)
            fd(i) = 1.0_wp/(1.0_wp + lam(i)*a2)
            wfx(i) = 0.0_wp
         end do
      case default   ! PS_FULL
         do i = 1, nv
            l1 = 0.0_wp
            if (aa(i) + bb(i) > y0(i)**2) then
               if (tab) then
                  l1 = ps_full_lambda(aa(i), bb(i), a1, a2, y0(i), hi(i), epsp(i), nit, crv=crv, &
                                      r=r(i))
               else
                  l1 = ps_full_lambda(aa(i), bb(i), a1, a2, y0(i), hi(i), epsp(i), nit)
               end if
               if (l1 < 0.0_wp) then
                  ierr(i) = 1
                  l1 = 0.0_wp
               end if
            end if
            lam(i) = l1
            fs(i) = 1.0_wp/(1.0_wp + l1*a1)
            fd(i) = 1.0_wp/(1.0_wp + l1*a2)
            wfx(i) = 0.0_wp
         end do
      end select
      if (alg == PS_SECANT3 .or. alg == PS_FULL .or. .not. ps_alg_valid(alg)) then
         ! exact-return form: the kinematic direction is the end state, depbar = lam sbar_end
         do i = 1, nv
            dirs(i) = s(i)*fs(i); dird(i) = d(i)*fd(i); dirt(i) = t(i)*fd(i)
            depl(i) = lam(i)*sqrt(0.25_wp*dirs(i)**2 + 0.75_wp*dird(i)**2 + 3.0_wp*dirt(i)**2)
         end do
      end if
      ! the new radius; the one-step returns are scaled onto a tabulated one
      if (tab) then
         do i = 1, nv
            ynew(i) = r(i)*crv%eval_extrap(epsp(i) + depl(i))
            if (alg == PS_ONE_STEP .or. alg == PS_ONE_STEP_N) wfx(i) = 1.0_wp
         end do
      else
         do i = 1, nv
            ynew(i) = y0(i) + hi(i)*depl(i)
         end do
      end if
      ! finish: radial scaling where wfx = 1, back stress, plastic strain, stress, blended with
      ! the weight wb = 1 (plastic) or 0: elastic points keep the trial stress and their history
      ! bitwise (x + 0 = x)
      ! (a chunk in which no point is flagged skips the square root and the quotient)
      if (any(wfx > 0.0_wp)) then
         do i = 1, nv
            sn = s(i)*fs(i); dn = d(i)*fd(i); tn = t(i)*fd(i)
            lv = ynew(i)/sqrt(max(0.25_wp*sn*sn + 0.75_wp*dn*dn + 3.0_wp*tn*tn, tiny(1.0_wp)))
            sc = wpl(i)*(1.0_wp + wfx(i)*(lv - 1.0_wp))
            s(i) = sn*sc; d(i) = dn*sc; t(i) = tn*sc
         end do
      else
         do i = 1, nv
            s(i) = s(i)*fs(i)*wpl(i); d(i) = d(i)*fd(i)*wpl(i); t(i) = t(i)*fd(i)*wpl(i)
         end do
      end if
      ! the end relative stress times the weight (above), the back-stress increment
      do i = 1, nv
         lr = wpl(i)*hk*lam(i)
         sumdp(i) = wpl(i)*0.5_wp*lam(i)*dirs(i)
         dirs(i) = lr*dirs(i); dird(i) = lr*dird(i); dirt(i) = lr*dirt(i)
      end do
      do i = 1, nv
         alpha(i, 1) = alpha(i, 1) + 0.5_wp*(dirs(i) + dird(i))
         alpha(i, 2) = alpha(i, 2) + 0.5_wp*(dirs(i) - dird(i))
         alpha(i, 3) = alpha(i, 3) + dirt(i)
      end do
      so = sig(:, 1) + sig(:, 2)
      do i = 1, nv
         sig(i, 1) = st(i, 1) + wpl(i)*(alpha(i, 1) - st(i, 1)) + 0.5_wp*(s(i) + d(i))
         sig(i, 2) = st(i, 2) + wpl(i)*(alpha(i, 2) - st(i, 2)) + 0.5_wp*(s(i) - d(i))
         sig(i, 3) = st(i, 3) + wpl(i)*(alpha(i, 3) - st(i, 3)) + t(i)
         sig(i, 4) = sig(i, 4) + g*deps(i, 4)
         sig(i, 5) = sig(i, 5) + g*deps(i, 5)
      end do
      dep = wpl*depl
      epsp = epsp + dep
      if (present(dezz)) dezz = -nu/e*(sig(:, 1) + sig(:, 2) - so) - sumdp
   end subroutine ps_update

   !> sbar(lam)^2 - Y(epsp + lam sbar(lam))^2 of the exact return, linear radius y0 + hi depbar
   pure elemental real(wp) function phi2_lin(l, aa, bb, a1, a2, y0, hi) result(phi)
      real(wp), intent(in) :: l, aa, bb, a1, a2, y0, hi
      real(wp) :: g1, g2, sbl, y
      g1 = 1.0_wp/(1.0_wp + l*a1)
      g2 = 1.0_wp/(1.0_wp + l*a2)
      sbl = sqrt(aa*g1*g1 + bb*g2*g2)
      y = y0 + hi*l*sbl
      phi = sbl*sbl - y*y
   end function phi2_lin

   !> phi2_lin with the tabulated radius r*crv(epsp + depbar)
   pure real(wp) function phi2_tab(l, aa, bb, a1, a2, r, epsp, crv) result(phi)
      real(wp), intent(in) :: l, aa, bb, a1, a2, r, epsp
      type(curve_t), intent(in) :: crv
      real(wp) :: g1, g2, sbl, y
      g1 = 1.0_wp/(1.0_wp + l*a1)
      g2 = 1.0_wp/(1.0_wp + l*a2)
      sbl = sqrt(aa*g1*g1 + bb*g2*g2)
      y = r*crv%eval_extrap(epsp + l*sbl)
      phi = sbl*sbl - y*y
   end function phi2_tab

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
