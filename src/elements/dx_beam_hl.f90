!> Hughes-Liu beam (ELFORM 1 of *SECTION_BEAM) with cross-section integration over one element
!> block (Hughes & Liu 1981, "Nonlinear finite element analysis of shells and beams", parts I
!> and II, CMAME 26:331-362 and 27:167-181; Hallquist, LS-DYNA Theory Manual, "Hughes-Liu
!> Beam"): a 2-node beam whose fibres (the section's normals, here the s and t axes of a
!> co-rotational frame) turn with the nodal rotations; linear interpolation along the axis, one
!> integration point at mid-length (the reduced rule: no transverse-shear locking, six
!> deformation modes for the twelve nodal freedoms less six rigid ones, no spurious mode).
!> Kinematics: the frame (e1 along N1-N2, e2 = s carried and turned by the chord spin plus the
!> mean twist, e3 = t) and the six rates at the mid-step geometry are those of the resultant
!> beam dx_beam_bs (rate(1) = (v2 - v1).e1, rate(2) = (w2 - w1).e1, rate(3:6) the end rotation
!> rates about e2 at N1, N2 and about e3 at N1, N2, relative to the chord). The velocity of the
!> fibre point (s, t) at mid-length is v + w x (s e2 + t e3); its gradient along e1 gives the
!> strain rates of the point in the frame (L the mid-step length):
!>   d11 = (rate1 - s (rate6 - rate5) + t (rate4 - rate3))/L,
!>   g12 = -(rate5 + rate6)/2 - t rate2/L,   g13 = (rate3 + rate4)/2 + s rate2/L
!> (a rigid rotation gives zero: the chord terms cancel the mean nodal spin). The stress of a
!> point is sig11 with the two shears (sig22 = sig33 = sig23 = 0) updated by the material's
!> lamina update (dx_plane_stress, the fibre form: one call per section point for the block,
!> every plane-stress algorithm of the shells; *MAT_ELASTIC, *MAT_003, *MAT_024).
!> Resultants by the section rule (weights w_k A): N = sum w sig11, M_s = sum w sig11 t,
!> M_t = -sum w sig11 s, Q_s = SHRF sum w sig12, Q_t = SHRF sum w sig13 (the transverse shear
!> factor on the resultants, as the shell's), T = sum w (s sig13 - t sig12); they are the work
!> conjugates of the generalized rates, so the nodal forces and moments are dx_beam_bs's with
!> its end-moment convention r = (N, T, -M_s + L Q_t/2, M_s + L Q_t/2, -M_t - L Q_s/2,
!> M_t - L Q_s/2) (the plot's beam_resultants then read the same slot). Internal energy: the
!> centred work of the resultants on the rates (dx_beam_bs, dx_hex8's centred_work).
!> Section rules (part%bqr = QR, part%bcst = CST of *SECTION_BEAM; LS-DYNA's numbering):
!> CST 0, the rectangle TS x TT (s extent TS, t extent TT): QR 1 one point, 2 2x2 Gauss,
!> 3 3x3 Gauss, 4 3x3 Lobatto, 5 4x4 Gauss (product rules; Abramowitz & Stegun 25.4.29-30; the
!> numbering of the manual's *INITIAL_STRESS_BEAM RULE: 5 = 4x4 Gauss);
!> CST 1, the tube of outer and inner diameters D, d: 4 QR points at equal angles (the first on
!> the s axis) on the ring of radius sqrt((R**2 + r**2)/2), weights A/(4 QR), which integrates
!> the second moments exactly (dynx's rule: LS-DYNA's tube point count per QR is recalled, not
!> verified: docs/history.md "Plastic beams"); a user rule (QR/IRID = -n, *INTEGRATION_BEAM
!> n with ICST 0: part%brule) puts point k at (S TS/2, T TT/2) with the area WF A, A = RA TS TT
!> (LS-DYNA Keyword User's Manual, Vol. I, "*INTEGRATION_BEAM"). NSLOC, NTLOC (part%bloc, -1, 0
!> or 1) put the nodes' line on a side of the section, the reference surface of the manual's
!> *SECTION_BEAM: the points sit at ((S - NSLOC) TS/2, (T - NTLOC) TT/2) from the nodes' line;
!> the rates and resultants are about that line (work conjugate as above), the section's ISS,
!> ITT are about it (parallel axes) and the stable step takes the sum of the four modes' omega**2
!> (the offset couples axial and bending). Tapered sections take the mean of the end
!> dimensions (the mid-length section of the one-point rule).
!> Mass and rotary inertia as dx_beam_bs (rho A L0/2 per node, times max((ISS + ITT)/A,
!> L0**2/12)). Stable step 2/omega_max of the element with its lumped masses: the largest of
!> the axial 4 c**2/L**2, the bending mode 2 E I/(L Jn), the shear mode
!> k L (2/(m L**2) + 1/(2 Jn)) (k = SHRF G A) and the torsion mode 2 G J/(L Jn) (m the nodal
!> mass, Jn the nodal rotary inertia: closed forms of the element's decoupled modes).
module dx_beam_hl
   use dx_kinds, only: wp, huge_wp
   use dx_vec3, only: cross
   use dx_material, only: material_t
   use dx_element_types, only: elem_block_t, part_t, ES_BEAM, ES_WORK, block_result_t, &
                               ELEM_ERR_NEGVOL, ELEM_ERR_MATERIAL, BM_E2, BM_TH, BM_RES, BM_SEC
   use dx_hex8, only: centred_work
   use dx_beam_bs, only: beam_kinematics, beam_end_forces
   implicit none
   private
   public :: beam_hl_block, beam_hl_rule, beam_hl_nip, beam_hl_section, HL_QR_MAX

   integer, parameter :: HL_QR_MAX = 5   !< QR 1..5 (LS-DYNA's built-in rules)
   integer, parameter :: MAXP = 20       !< most points of a rule (tube QR 5)

contains

   !> Points of the section rule QR, CST (0 when not supported).
   pure integer function beam_hl_nip(qr, cst) result(np)
      integer, intent(in) :: qr, cst
      integer, parameter :: NRECT(HL_QR_MAX) = [1, 4, 9, 9, 16]
      np = 0
      if (qr < 1 .or. qr > HL_QR_MAX) return
      if (cst == 0) np = NRECT(qr)
      if (cst == 1) np = 4*qr
   end function beam_hl_nip

   !> The section rule in unit coordinates: point k at (ps(k) hs, pt(k) ht) with area weight
   !> wf(k) A (sum wf = 1); hs, ht = TS/2, TT/2 (rectangle) or the ring radius (tube).
   pure subroutine beam_hl_rule(qr, cst, ps, pt, wf, np)
      integer, intent(in) :: qr, cst
      real(wp), intent(out) :: ps(MAXP), pt(MAXP), wf(MAXP)
      integer, intent(out) :: np
      real(wp) :: g(4), w(4), a
      integer :: n1, i, j
      real(wp), parameter :: PI = acos(-1.0_wp)
      ps = 0.0_wp; pt = 0.0_wp; wf = 0.0_wp
      np = beam_hl_nip(qr, cst)
      if (np == 0) return
      if (cst == 1) then
         do i = 1, np
            a = 2.0_wp*PI*real(i - 1, wp)/real(np, wp)
            ps(i) = cos(a); pt(i) = sin(a)
            wf(i) = 1.0_wp/real(np, wp)
         end do
         return
      end if
      g = 0.0_wp; w = 0.0_wp
      select case (qr)
      case (1)
         n1 = 1; g(1) = 0.0_wp; w(1) = 2.0_wp
      case (2)
         n1 = 2; g(1:2) = [-1.0_wp, 1.0_wp]/sqrt(3.0_wp); w(1:2) = 1.0_wp
      case (3)
         n1 = 3; g(1:3) = [-sqrt(0.6_wp), 0.0_wp, sqrt(0.6_wp)]
         w(1:3) = [5.0_wp, 8.0_wp, 5.0_wp]/9.0_wp
      case (4)
         n1 = 3; g(1:3) = [-1.0_wp, 0.0_wp, 1.0_wp]; w(1:3) = [1.0_wp, 4.0_wp, 1.0_wp]/3.0_wp
      case default
         n1 = 4
         g(1:4) = [-sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
                   -sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
                   sqrt(3.0_wp/7.0_wp - 2.0_wp/7.0_wp*sqrt(1.2_wp)), &
                   sqrt(3.0_wp/7.0_wp + 2.0_wp/7.0_wp*sqrt(1.2_wp))]
         w(1:4) = [(18.0_wp - sqrt(30.0_wp))/36.0_wp, (18.0_wp + sqrt(30.0_wp))/36.0_wp, &
                   (18.0_wp + sqrt(30.0_wp))/36.0_wp, (18.0_wp - sqrt(30.0_wp))/36.0_wp]
      end select
      np = 0
      do j = 1, n1
         do i = 1, n1
            np = np + 1
            ps(np) = g(i); pt(np) = g(j)
            wf(np) = 0.25_wp*w(i)*w(j)
         end do
      end do
   end subroutine beam_hl_rule

   !> Section values A, ISS, ITT, J, SA and the rule's scales hs, ht of the dimensions
   !> d1, d2 (CST 0: TS, TT; CST 1: D, d). With a user rule (rule(1:3, k) = S, T, WF and its
   !> relative area ra): A = ra TS TT and the second moments are the rule's own sums,
   !> ISS = A sum WF (T TT/2)**2, ITT = A sum WF (S TS/2)**2. With the reference line loc =
   !> (NSLOC, NTLOC) the second moments are about that line (parallel axes: + A (NTLOC TT/2)**2,
   !> + A (NSLOC TS/2)**2).
   pure subroutine beam_hl_section(cst, d1, d2, sec, hs, ht, rule, ra, loc)
      integer, intent(in) :: cst
      real(wp), intent(in) :: d1, d2
      real(wp), intent(out) :: sec(5), hs, ht
      real(wp), intent(in), optional :: rule(:, :), ra, loc(2)
      real(wp), parameter :: PI = acos(-1.0_wp)
      if (present(rule)) then
         hs = 0.5_wp*d1
         ht = 0.5_wp*d2
         sec(1) = ra*(d1*d2)
         sec(2) = sec(1)*ht*ht*sum(rule(3, :)*rule(2, :)**2)
         sec(3) = sec(1)*hs*hs*sum(rule(3, :)*rule(1, :)**2)
      else if (cst == 1) then
         sec(1) = 0.25_wp*PI*(d1*d1 - d2*d2)
         sec(2) = PI*(d1**4 - d2**4)/64.0_wp
         sec(3) = sec(2)
         hs = 0.5_wp*sqrt(0.5_wp*(d1*d1 + d2*d2))
         ht = hs
      else
         sec(1) = d1*d2
         sec(2) = d1*d2**3/12.0_wp      ! about s: int t**2 dA (t extent TT = d2)
         sec(3) = d2*d1**3/12.0_wp
         hs = 0.5_wp*d1
         ht = 0.5_wp*d2
      end if
      if (present(loc)) then
         sec(2) = sec(2) + sec(1)*(loc(2)*ht)**2
         sec(3) = sec(3) + sec(1)*(loc(1)*hs)**2
      end if
      sec(4) = sec(2) + sec(3)
      sec(5) = sec(1)
   end subroutine beam_hl_section

   !> One explicit pass over a block of Hughes-Liu beams: x = x(n), v = v(n-1/2),
   !> w = w(n-1/2), dt_old = dt(n-1/2). Updates the section points to t(n), forms the
   !> resultants, subtracts the internal forces from f and moments from mom.
   subroutine beam_hl_block(blk, mat, part, x, v, w, dt_old, f, mom, res)
      type(elem_block_t), intent(inout) :: blk
      class(material_t), intent(in) :: mat
      type(part_t), intent(in) :: part
      real(wp), intent(in) :: x(:, :), v(:, :), w(:, :)
      real(wp), intent(in) :: dt_old
      real(wp), intent(inout) :: f(:, :), mom(:, :)
      type(block_result_t), intent(out) :: res
      real(wp), allocatable :: ps(:), pt(:), wf(:)
      real(wp) :: rate(blk%nel, 6), lmv(blk%nel), hs(blk%nel), ht(blk%nel), q(blk%nel, 6)
      real(wp) :: e1v(3, blk%nel), e2v(3, blk%nel), lv(blk%nel)
      real(wp) :: de5(blk%nel, 5), s5(blk%nel, 5), sec(5)
      integer :: ierr(blk%nel)
      real(wp) :: g, lam, ym, c2, hdt, de, shrf, s, t, d11, g12, g13, wa, sg1, sg2, sg3
      real(wp) :: e1(3), e2(3), e3(3), l, l0, r(6), rold(6), fl(3, 2), ml(3, 2)
      logical :: ok
      real(wp) :: a, iss, itt, tj, mn, jn, wmax2, dte, wo, wn
      integer :: i, k, c, n1, n2, cw, ip, np, n
      n = blk%nel
      c = blk%esc(ES_BEAM)
      cw = blk%esc(ES_WORK)
      hdt = 0.5_wp*dt_old
      g = mat%shear
      lam = mat%bulk - 2.0_wp*g/3.0_wp
      ym = g*(3.0_wp*lam + 2.0_wp*g)/(lam + g)
      c2 = ym/mat%ro
      shrf = part%shrf
      res%deint = 0.0_wp; res%dehg = 0.0_wp; res%pend = 0.0_wp
      if (allocated(part%brule)) then       ! a user rule (*INTEGRATION_BEAM)
         np = size(part%brule, 2)
         ps = part%brule(1, :); pt = part%brule(2, :); wf = part%brule(3, :)
      else
         allocate(ps(MAXP), pt(MAXP), wf(MAXP))
         call beam_hl_rule(part%bqr, part%bcst, ps, pt, wf, np)
      end if
      ierr = 0
      ! ---- frames and rates (dx_beam_bs's kinematics)
      do i = 1, n
         n1 = blk%conn(1, i); n2 = blk%conn(2, i)
         call beam_kinematics(x(:, n1), x(:, n2), v(:, n1), v(:, n2), w(:, n1), w(:, n2), &
                              blk%es(i, c + BM_E2:c + BM_E2 + 2), hdt, dt_old, lmv(i), &
                              rate(i, :), lv(i), e1v(:, i), e2v(:, i), ok)
         if (.not. ok) then
            res%ibad = i; res%errcode = ELEM_ERR_NEGVOL
            return
         end if
         blk%es(i, c + BM_E2:c + BM_E2 + 2) = e2v(:, i)
         call beam_hl_section(part%bcst, blk%es(i, c + BM_TH), blk%es(i, c + BM_TH + 1), &
                              sec, hs(i), ht(i))
      end do
      ! ---- section points: strain increments, the lamina (fibre) update, resultants
      ! q: N, T, M_s, M_t, Q_s, Q_t
      q = 0.0_wp
      do ip = 1, np
         do i = 1, n
            s = (ps(ip) - part%bloc(1))*hs(i); t = (pt(ip) - part%bloc(2))*ht(i)
            d11 = dt_old*(rate(i, 1) - s*(rate(i, 6) - rate(i, 5)) + t*(rate(i, 4) - rate(i, 3)))/lmv(i)
            g12 = dt_old*(-0.5_wp*(rate(i, 5) + rate(i, 6)) - t*rate(i, 2)/lmv(i))
            g13 = dt_old*(0.5_wp*(rate(i, 3) + rate(i, 4)) + s*rate(i, 2)/lmv(i))
            de5(i, 1) = 0.5_wp*(d11 + g13); de5(i, 2) = 0.5_wp*(d11 - g13)
            de5(i, 3) = g12; de5(i, 4) = 0.0_wp; de5(i, 5) = 0.0_wp
            s5(i, 1) = blk%sig(i, 1, ip) + blk%sig(i, 6, ip)
            s5(i, 2) = blk%sig(i, 1, ip) - blk%sig(i, 6, ip)
            s5(i, 3) = blk%sig(i, 4, ip); s5(i, 4) = 0.0_wp; s5(i, 5) = 0.0_wp
         end do
         call mat%update_plane_stress(n, dt_old, de5, s5, blk%hv(:, :, ip), ierr, fibre=.true.)
         do i = 1, n
            sg1 = 0.5_wp*(s5(i, 1) + s5(i, 2))
            sg3 = 0.5_wp*(s5(i, 1) - s5(i, 2))
            sg2 = s5(i, 3)
            if (blk%failed(i)) then
               sg1 = 0.0_wp; sg2 = 0.0_wp; sg3 = 0.0_wp
            end if
            blk%sig(i, 1, ip) = sg1; blk%sig(i, 4, ip) = sg2; blk%sig(i, 6, ip) = sg3
            s = (ps(ip) - part%bloc(1))*hs(i); t = (pt(ip) - part%bloc(2))*ht(i)
            wa = wf(ip)*blk%es(i, c + BM_SEC)
            q(i, 1) = q(i, 1) + wa*sg1
            q(i, 2) = q(i, 2) + wa*(s*sg3 - t*sg2)
            q(i, 3) = q(i, 3) + wa*sg1*t
            q(i, 4) = q(i, 4) - wa*sg1*s
            q(i, 5) = q(i, 5) + wa*sg2
            q(i, 6) = q(i, 6) + wa*sg3
         end do
      end do
      do i = 1, n
         if (ierr(i) /= 0) then
            res%ibad = i; res%errcode = ELEM_ERR_MATERIAL
            return
         end if
      end do
      ! ---- end-moment form, centred work, nodal forces and moments, stable step
      do i = 1, n
         n1 = blk%conn(1, i); n2 = blk%conn(2, i)
         a = blk%es(i, c + BM_SEC); iss = blk%es(i, c + BM_SEC + 1)
         itt = blk%es(i, c + BM_SEC + 2); tj = blk%es(i, c + BM_SEC + 3)
         l0 = blk%vol0(i)/a
         l = lv(i); e1 = e1v(:, i); e2 = e2v(:, i)
         e3 = cross(e1, e2)
         r(1) = q(i, 1)
         r(2) = q(i, 2)
         r(3) = -q(i, 3) + 0.5_wp*l*shrf*q(i, 6)
         r(4) = q(i, 3) + 0.5_wp*l*shrf*q(i, 6)
         r(5) = -q(i, 4) - 0.5_wp*l*shrf*q(i, 5)
         r(6) = q(i, 4) - 0.5_wp*l*shrf*q(i, 5)
         rold = blk%es(i, c + BM_RES:c + BM_RES + 5)
         blk%es(i, c + BM_RES:c + BM_RES + 5) = r
         wo = dt_old*dot_product(rold, rate(i, :))
         wn = dt_old*dot_product(r, rate(i, :))
         associate (s1 => blk%es(i, cw), s2 => blk%es(i, cw + 1), s3 => blk%es(i, cw + 2), &
                    s4 => blk%es(i, cw + 3))
            call centred_work(s1, s2, s3, s4, dt_old, wo, wn, 0.0_wp, 0.0_wp, 0.0_wp, &
                              0.0_wp, 0.0_wp, de)
         end associate
         blk%eint(i) = blk%eint(i) + de
         res%deint = res%deint + de
         blk%relvol(i) = l/l0
         call beam_end_forces(r, e1, e2, e3, l, fl, ml)
         do k = 1, 2
            f(:, blk%conn(k, i)) = f(:, blk%conn(k, i)) - fl(:, k)
            mom(:, blk%conn(k, i)) = mom(:, blk%conn(k, i)) - ml(:, k)
         end do
         ! stable step: the element's axial, bending, shear and torsion modes
         mn = 0.5_wp*mat%ro*a*l0
         jn = mn*max((iss + itt)/a, l0*l0/12.0_wp)
         wmax2 = max(4.0_wp*c2/(l*l), 2.0_wp*ym*max(iss, itt)/(l*jn), &
                     shrf*g*a*l*(2.0_wp/(mn*l*l) + 0.5_wp/jn), 2.0_wp*g*tj/(l*jn))
         if (any(part%bloc /= 0.0_wp)) then
            ! a reference line off the centre couples the modes: their sum bounds omega**2
            wmax2 = 4.0_wp*c2/(l*l) + 2.0_wp*ym*max(iss, itt)/(l*jn) + &
                    shrf*g*a*l*(2.0_wp/(mn*l*l) + 0.5_wp/jn) + 2.0_wp*g*tj/(l*jn)
         end if
         dte = 2.0_wp/sqrt(wmax2)
         if (blk%failed(i)) dte = huge_wp
         if (dte < res%dt) then
            res%dt = dte; res%imin = i
         end if
         res%dte(i) = dte
      end do
   end subroutine beam_hl_block
end module dx_beam_hl
