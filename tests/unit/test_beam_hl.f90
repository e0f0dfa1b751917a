!> Unit tests of the Hughes-Liu beam's pieces (dx_beam_hl, dx_plane_stress's fibre form):
!>  - the section rules: weights sum to 1; the rectangle's rules QR 2-5 integrate s**2 and t**2
!>    exactly (1/3 of the half-width squared; Gauss n points: degree 2n - 1, Lobatto 3:
!>    degree 3); the tube ring integrates them exactly (1/2 of the ring radius squared, whose
!>    square is (R**2 + r**2)/2: the tube's I/A); the section values of beam_hl_section
!>    (A, ISS, ITT of a 2 x 1 rectangle and a D = 2, d = 1 tube, closed forms);
!>  - the fibre form of the lamina update (uniaxial stress plus two shears): elastic
!>    increments give E de11, G dg12, G dg13 (within a few ulps); a plastic step of *MAT_003
!>    with linear hardening by the full return (MITER 2) and the one-step return (4) lands on
!>    x**2 + 3 t2**2 + 3 t3**2 = Y(epsp)**2 (round-off; the one-step return is exact for linear
!>    hardening), with the uniaxial bilinear answer sigma = sy + Et (e - sy/E) for a pure
!>    axial step (5 and 1.5 times the yield strain: beyond a trial radius of 1.75 Y the
!>    one-step return takes radial scaling, 5e-3 off here) and the trial shear direction kept;
!>  - a user rule (*INTEGRATION_BEAM: part%brule, RA): beam_hl_section's A = RA TS TT and
!>    the rule's own second moments; one element of beam_hl_block bent quasi-statically (fixed
!>    nodes, end spins -w, +w about s: no shear, no axial strain) to 12.6 times the web's yield
!>    strain in 100 steps of 0.38 times it, *MAT_003 elastic-perfectly plastic: the moment
!>    equals the rule's own fully plastic sum SIGY A (TT/2) sum WF |T| to round-off (1e-13)
!>    with the full (MITER 2), radial (3) and one-step (4) returns, and N = 0; the fixed
!>    three-iteration secant (1, the default) within 1e-4 (measured +1.5e-5: three secant
!>    iterations do not land exactly on the surface at these step sizes).
program test_beam_hl
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_beam_hl, only: beam_hl_rule, beam_hl_nip, beam_hl_section, beam_hl_block
   use dx_element_types, only: elem_block_t, block_result_t, part_t, ES_BEAM, ES_WORK, &
                               ETYPE_BEAM_HL, element_family, family_t, BM_TH, BM_RES
   use dx_beam_bs, only: beam_bs_init
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: ey = 210.0_wp, pr = 0.3_wp, sy = 0.25_wp, et = 2.1_wp
   real(wp), parameter :: PI = acos(-1.0_wp)
   real(wp) :: ps(20), pt(20), wf(20), sec(5), hs, ht, g
   integer :: qr, np
   type(mat_plastic_kinematic_t) :: pk
   type(error_t), allocatable :: err

   ! ---- section rules
   do qr = 1, 5
      call beam_hl_rule(qr, 0, ps, pt, wf, np)
      call check(np == beam_hl_nip(qr, 0), 'rectangle rule: point count')
      call check_close(sum(wf(1:np)), 1.0_wp, 0.0_wp, 1.0e-14_wp, 'rectangle rule: weights')
      if (qr >= 2) then
         call check_close(sum(wf(1:np)*ps(1:np)**2), 1.0_wp/3.0_wp, 0.0_wp, 1.0e-14_wp, &
                          'rectangle rule: int s**2')
         call check_close(sum(wf(1:np)*pt(1:np)**2), 1.0_wp/3.0_wp, 0.0_wp, 1.0e-14_wp, &
                          'rectangle rule: int t**2')
      end if
      call beam_hl_rule(qr, 1, ps, pt, wf, np)
      call check(np == 4*qr, 'tube rule: 4 QR points')
      call check_close(sum(wf(1:np)*ps(1:np)**2), 0.5_wp, 0.0_wp, 1.0e-14_wp, 'tube: int s**2')
      call check_close(sum(wf(1:np)*pt(1:np)**2), 0.5_wp, 0.0_wp, 1.0e-14_wp, 'tube: int t**2')
   end do
   call check(beam_hl_nip(6, 0) == 0 .and. beam_hl_nip(2, 2) == 0, 'unsupported rules: 0')
   call beam_hl_section(0, 2.0_wp, 1.0_wp, sec, hs, ht)
   call check_close(sec(1), 2.0_wp, 0.0_wp, 1.0e-15_wp, 'rectangle A')
   call check_close(sec(2), 1.0_wp/6.0_wp, 0.0_wp, 1.0e-15_wp, 'rectangle ISS = TS TT**3/12')
   call check_close(sec(3), 2.0_wp/3.0_wp, 0.0_wp, 1.0e-15_wp, 'rectangle ITT = TT TS**3/12')
   call beam_hl_section(1, 2.0_wp, 1.0_wp, sec, hs, ht)
   call check_close(sec(1), 0.75_wp*PI, 0.0_wp, 1.0e-15_wp, 'tube A')
   call check_close(sec(2), 15.0_wp*PI/64.0_wp, 0.0_wp, 1.0e-15_wp, 'tube I')
   call check_close(sec(1)*hs*hs*0.5_wp, sec(2), 0.0_wp, 1.0e-14_wp, 'tube ring: A r**2/2 = I')

   ! ---- the fibre form of the lamina update
   pk%ro = 7.85e-6_wp; pk%e = ey; pk%pr = pr; pk%sigy = sy; pk%etan = et; pk%beta = 1.0_wp
   call pk%setup(err)
   call check(.not. allocated(err), 'MAT_003 setup')
   g = ey/(2.0_wp*(1.0_wp + pr))
   call elastic_step()
   pk%ps_alg = 2
   call plastic_step('full return', 5.0_wp)
   pk%ps_alg = 4
   call plastic_step('one-step return', 1.5_wp)
   call user_rule_plastic_moment(2, 1.0e-13_wp)
   call user_rule_plastic_moment(3, 1.0e-13_wp)
   call user_rule_plastic_moment(4, 1.0e-13_wp)
   call user_rule_plastic_moment(1, 1.0e-4_wp)
   call assert_summary()

contains

   !> one point in the fibre form: beam components (x, t2, t3) and increments (e, g2, g3)
   subroutine fibre(x, de, hv, ierr)
      real(wp), intent(inout) :: x(3), hv(:, :)
      real(wp), intent(in) :: de(3)
      integer, intent(inout) :: ierr(1)
      real(wp) :: s5(1, 5), d5(1, 5)
      s5(1, :) = [x(1) + x(3), x(1) - x(3), x(2), 0.0_wp, 0.0_wp]
      d5(1, :) = [0.5_wp*(de(1) + de(3)), 0.5_wp*(de(1) - de(3)), de(2), 0.0_wp, 0.0_wp]
      call pk%update_plane_stress(1, 1.0e-3_wp, d5, s5, hv, ierr, fibre=.true.)
      x = [0.5_wp*(s5(1, 1) + s5(1, 2)), s5(1, 3), 0.5_wp*(s5(1, 1) - s5(1, 2))]
   end subroutine fibre

   subroutine elastic_step()
      real(wp) :: x(3), hv(1, 7)
      integer :: ierr(1)
      x = 0.0_wp; hv = 0.0_wp; ierr = 0
      call fibre(x, [1.0e-4_wp, 2.0e-4_wp, -1.0e-4_wp], hv, ierr)
      call check(ierr(1) == 0, 'fibre elastic: no error')
      call check_close(x(1), ey*1.0e-4_wp, 0.0_wp, 1.0e-14_wp, 'fibre elastic: E de11')
      call check_close(x(2), g*2.0e-4_wp, 0.0_wp, 1.0e-14_wp, 'fibre elastic: G dg12')
      call check_close(x(3), -g*1.0e-4_wp, 0.0_wp, 1.0e-14_wp, 'fibre elastic: G dg13')
   end subroutine elastic_step

   !> a pure axial step to fac times the yield strain, then axial plus shears from zero
   subroutine plastic_step(what, fac)
      character(*), intent(in) :: what
      real(wp), intent(in) :: fac
      real(wp) :: x(3), hv(1, 7), ep, y, de
      integer :: ierr(1)
      ep = ey*et/(ey - et)
      ! a pure axial step: the bilinear uniaxial answer (the one-step return within its range,
      ! trial radii below 1.75 Y: dx_plane_stress)
      de = fac*sy/ey
      x = 0.0_wp; hv = 0.0_wp; ierr = 0
      call fibre(x, [de, 0.0_wp, 0.0_wp], hv, ierr)
      call check(ierr(1) == 0, what//': no error')
      call check_close(x(1), sy + et*(de - sy/ey), 0.0_wp, 1.0e-12_wp, &
                       what//': uniaxial bilinear sigma = sy + Et (e - sy/E)')
      call check(x(2) == 0.0_wp .and. abs(x(3)) <= 1.0e-15_wp, what//': no shear')
      ! axial plus both shears in one step: on the yield surface, the shear direction kept
      x = 0.0_wp; hv = 0.0_wp; ierr = 0
      call fibre(x, [3.0e-3_wp, 2.0e-3_wp, 1.0e-3_wp], hv, ierr)
      y = sy + ep*hv(1, 1)
      call check(hv(1, 1) > 0.0_wp, what//': yielded')
      call check_close(sqrt(x(1)**2 + 3.0_wp*x(2)**2 + 3.0_wp*x(3)**2), y, 0.0_wp, 1.0e-12_wp, &
                       what//': x**2 + 3 t2**2 + 3 t3**2 = Y**2')
      call check_close(x(2)/x(3), 2.0_wp, 0.0_wp, 1.0e-12_wp, what//': shear direction kept')
   end subroutine plastic_step

   !> The I-like user rule of beam_hl_user_rule (flanges s +-0.6, t +-0.9, WF 0.2; web
   !> t +-0.3, WF 0.1; RA 0.5, TS 2, TT 1) on one 10 mm element bent about s.
   subroutine user_rule_plastic_moment(alg, tol)
      integer, intent(in) :: alg
      real(wp), intent(in) :: tol
      real(wp), parameter :: rule(3, 6) = reshape([-0.6_wp, -0.9_wp, 0.2_wp, &
         0.6_wp, -0.9_wp, 0.2_wp, 0.0_wp, -0.3_wp, 0.1_wp, 0.0_wp, 0.3_wp, 0.1_wp, &
         -0.6_wp, 0.9_wp, 0.2_wp, 0.6_wp, 0.9_wp, 0.2_wp], [3, 6])
      real(wp), parameter :: ra = 0.5_wp, ts = 2.0_wp, tt = 1.0_wp, l0 = 10.0_wp
      real(wp), parameter :: dt = 1.0e-3_wp, w0 = 1.0_wp, sy0 = 0.05_wp
      type(mat_plastic_kinematic_t) :: pp
      type(elem_block_t) :: blk
      type(block_result_t) :: res
      type(part_t) :: part
      type(family_t) :: fam
      real(wp) :: sec(5), hs, ht, x(3, 2), z(3, 2), w(3, 2), f(3, 2), mom(3, 2), mp, r(6)
      integer :: k, c
      call beam_hl_section(0, ts, tt, sec, hs, ht, rule, ra)
      call check_close(sec(1), ra*ts*tt, 0.0_wp, 1.0e-15_wp, 'user rule: A = RA TS TT')
      call check_close(sec(2), sec(1)*0.25_wp*tt*tt*(0.8_wp*0.81_wp + 0.2_wp*0.09_wp), 0.0_wp, &
                       1.0e-14_wp, 'user rule: ISS = A sum WF (T TT/2)**2')
      call check_close(sec(3), sec(1)*0.25_wp*ts*ts*0.8_wp*0.36_wp, 0.0_wp, 1.0e-14_wp, &
                       'user rule: ITT = A sum WF (S TS/2)**2')
      pp%ro = 7.85e-6_wp; pp%e = ey; pp%pr = pr; pp%sigy = sy0; pp%etan = 0.0_wp
      pp%beta = 1.0_wp
      call pp%setup(err)
      pp%ps_alg = alg
      call check(.not. allocated(err), 'user rule: MAT_003 setup')
      part%shrf = 5.0_wp/6.0_wp; part%bqr = -3; part%bcst = 0
      part%brule = rule; part%bra = ra
      fam = element_family(ETYPE_BEAM_HL)
      blk%etype = ETYPE_BEAM_HL
      blk%nel = 1; blk%nip = 6; blk%nhv = pp%nhist()
      allocate(blk%conn(2, 1), blk%elem(1), blk%sig(1, 6, 6), blk%hv(1, blk%nhv, 6), &
               blk%vol0(1), blk%relvol(1), blk%eint(1), blk%ehg(1), blk%failed(1))
      blk%conn(:, 1) = [1, 2]
      blk%elem = 1
      blk%sig = 0.0_wp; blk%hv = 0.0_wp
      blk%vol0 = sec(1)*l0
      blk%relvol = 1.0_wp; blk%eint = 0.0_wp; blk%ehg = 0.0_wp
      blk%failed = .false.
      call blk%es_add(ES_WORK, fam%es_ncol(ES_WORK))
      call blk%es_add(ES_BEAM, fam%es_ncol(ES_BEAM))
      call beam_bs_init(blk, 1, [0.0_wp, 1.0_wp, 0.0_wp], sec)
      c = blk%esc(ES_BEAM)
      blk%es(1, c + BM_TH:c + BM_TH + 1) = [ts, tt]
      x(:, 1) = 0.0_wp; x(:, 2) = [l0, 0.0_wp, 0.0_wp]
      z = 0.0_wp
      w(:, 1) = [0.0_wp, -w0, 0.0_wp]; w(:, 2) = [0.0_wp, w0, 0.0_wp]
      ! curvature 2 w0 dt/L0 per step: 100 steps, 2e-2/mm, the web (t = 0.15) at 3e-3 = 12.6
      ! times the yield strain 0.05/210
      do k = 1, 100
         f = 0.0_wp; mom = 0.0_wp
         call beam_hl_block(blk, pp, part, x, z, w, dt, f, mom, res)
      end do
      call check(res%ibad == 0, 'user rule: bending, no error')
      r = blk%es(1, c + BM_RES:c + BM_RES + 5)
      mp = sy0*sec(1)*0.5_wp*tt*(0.8_wp*0.9_wp + 0.2_wp*0.3_wp)
      call check_close(0.5_wp*(r(4) - r(3)), mp, 0.0_wp, tol, 'user rule, MITER '// &
                       achar(48 + alg)//': fully plastic moment = SIGY A (TT/2) sum WF |T|')
      call check_close(r(1), 0.0_wp, 1.0e-13_wp*mp/tt, 0.0_wp, 'user rule: N = 0')
   end subroutine user_rule_plastic_moment
end program test_beam_hl
