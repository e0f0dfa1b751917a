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
!>    one-step return takes radial scaling, 5e-3 off here) and the trial shear direction kept.
program test_beam_hl
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_beam_hl, only: beam_hl_rule, beam_hl_nip, beam_hl_section
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
end program test_beam_hl
