!> Unit tests of dx_erosion's tensor helpers and point criteria against closed forms:
!> largest_principal (Smith 1961's trigonometric solution) of diagonal tensors in any order,
!> of pure shear (tau), of a tensor rotated by 30 degrees about z (its eigenvalues back) and
!> of a hydrostatic one (the triple root); von_mises of uniaxial and pure-shear stress
!> (sqrt(3) tau); erosion_points: the Tuler-Butcher damage D accumulates
!> max(0, sigma_1 - SIGTH)^2 dt / IMPULSE and the element fails on the step it reaches 1; a
!> criterion equal to EXCL is off; NCS = 2 needs two criteria at once; MXPRES, MNPRES and VOLEPS
!> (expansion and compression) fail the point at their thresholds and not short of them. Tolerances: a few
!> ulps of the entries (acos near its ends loses some bits: 64 ulps on the rotated case).
program test_erosion
   use dx_kinds, only: wp
   use dx_element_types, only: elem_block_t, erosion_t, ES_DMG
   use dx_erosion, only: largest_principal, von_mises, erosion_points
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: eps = epsilon(1.0_wp)
   real(wp) :: s(6), c, sn, a, b, sig(1, 6), rv(1)
   type(elem_block_t) :: blk
   type(erosion_t) :: e
   integer :: nf(1), k

   call check_close(largest_principal([3.0_wp, 1.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]), &
                    3.0_wp, 0.0_wp, 4*eps, 'diagonal, largest first')
   call check_close(largest_principal([-1.0_wp, -5.0_wp, 2.5_wp, 0.0_wp, 0.0_wp, 0.0_wp]), &
                    2.5_wp, 0.0_wp, 4*eps, 'diagonal, largest last')
   call check_close(largest_principal([0.0_wp, 0.0_wp, 0.0_wp, 7.0_wp, 0.0_wp, 0.0_wp]), &
                    7.0_wp, 0.0_wp, 4*eps, 'pure shear xy: tau')
   call check_close(largest_principal([2.0_wp, 2.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]), &
                    2.0_wp, 0.0_wp, 4*eps, 'hydrostatic: the triple root')
   ! diag(5, -1, 3) turned by 30 degrees about z: xx = a c^2 + b s^2, yy = a s^2 + b c^2,
   ! xy = (a - b) c s
   a = 5.0_wp; b = -1.0_wp
   c = cos(acos(-1.0_wp)/6.0_wp); sn = sin(acos(-1.0_wp)/6.0_wp)
   s = [a*c*c + b*sn*sn, a*sn*sn + b*c*c, 3.0_wp, (a - b)*c*sn, 0.0_wp, 0.0_wp]
   call check_close(largest_principal(s), 5.0_wp, 0.0_wp, 64*eps, 'rotated diag(5,-1,3): 5')
   call check_close(-largest_principal(-s), -1.0_wp, 0.0_wp, 64*eps, &
                    'rotated diag(5,-1,3): smallest -1')
   call check_close(von_mises([100.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]), 100.0_wp, &
                    0.0_wp, 4*eps, 'von Mises of uniaxial 100')
   call check_close(von_mises([0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), &
                    sqrt(3.0_wp), 0.0_wp, 4*eps, 'von Mises of pure shear 1: sqrt(3)')

   ! ---- Tuler-Butcher: sigma_1 = 3, SIGTH 1, IMPULSE 1, dt 0.1: D += 0.4 per step
   blk%nel = 1
   allocate(blk%failed(1))
   blk%failed = .false.
   call blk%es_add(ES_DMG, 1)
   e%on = .true.; e%sigth = 1.0_wp; e%impulse = 1.0_wp
   e%mxpres = 0.0_wp; e%mnpres = 0.0_wp; e%sigp1 = 0.0_wp; e%sigvm = 0.0_wp
   e%voleps = 0.0_wp; e%excl = 0.0_wp
   sig(1, :) = [3.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
   rv = 1.0_wp
   do k = 1, 3
      nf = 0
      call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
      if (k < 3) call check(nf(1) == 0, 'Tuler-Butcher: no failure before D = 1')
   end do
   call check_close(blk%es(1, blk%esc(ES_DMG)), 1.2_wp, 0.0_wp, 8*eps, &
                    'Tuler-Butcher: D = 3 x 0.1 x (3 - 1)^2')
   call check(nf(1) == 1, 'Tuler-Butcher: fails at the step D reaches 1')
   ! ---- EXCL: a criterion equal to EXCL is off; NCS = 2 needs two at once
   deallocate(blk%es); blk%esc = 0; blk%esn = 0
   e = erosion_t()
   e%on = .true.; e%excl = -99.0_wp
   e%mxpres = -99.0_wp; e%mnpres = -99.0_wp; e%sigvm = -99.0_wp; e%voleps = -99.0_wp
   e%impulse = -99.0_wp; e%sigth = -99.0_wp; e%failtm = -99.0_wp
   e%mneps = -99.0_wp; e%effeps = -99.0_wp; e%mxeps = -99.0_wp; e%epssh = -99.0_wp
   e%sigp1 = 0.0_wp                  ! an active 0: any tension fails (EXCL is not 0)
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'EXCL = -99: SIGP1 = 0 is a criterion (sigma_1 = 3 >= 0)')
   e%ncs = 2
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 0, 'NCS = 2: one criterion is not enough')
   e%sigvm = 2.0_wp                  ! von Mises 3 >= 2: the second criterion
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'NCS = 2: two criteria at once')
   ! ---- MXPRES, MNPRES, VOLEPS one at a time (the others equal to EXCL): each fails the point
   ! at its threshold and not short of it (p = -tr(sigma)/3; VOLEPS on ln V, tension when > 0)
   e = erosion_t()
   e%on = .true.; e%excl = -99.0_wp
   e%mxpres = -99.0_wp; e%mnpres = -99.0_wp; e%sigp1 = -99.0_wp; e%sigvm = -99.0_wp
   e%voleps = -99.0_wp; e%impulse = -99.0_wp; e%sigth = -99.0_wp; e%failtm = -99.0_wp
   e%mneps = -99.0_wp; e%effeps = -99.0_wp; e%mxeps = -99.0_wp; e%epssh = -99.0_wp
   sig(1, :) = [-2.0_wp, -2.0_wp, -2.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]   ! p = 2
   e%mxpres = 2.5_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 0, 'MXPRES 2.5: p = 2 does not fail')
   e%mxpres = 1.5_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'MXPRES 1.5: p = 2 fails')
   e%mxpres = -99.0_wp
   sig(1, 1:3) = 2.0_wp                                                ! p = -2
   e%mnpres = -2.5_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 0, 'MNPRES -2.5: p = -2 does not fail')
   e%mnpres = -1.5_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'MNPRES -1.5: p = -2 fails')
   e%mnpres = -99.0_wp
   sig = 0.0_wp
   rv = 1.2_wp                                                         ! ln V = 0.1823
   e%voleps = 0.19_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 0, 'VOLEPS 0.19: ln V = 0.182 does not fail')
   e%voleps = 0.18_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'VOLEPS 0.18: ln V = 0.182 fails (expansion)')
   rv = 0.8_wp                                                         ! ln V = -0.2231
   e%voleps = -0.25_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 0, 'VOLEPS -0.25: ln V = -0.223 does not fail')
   e%voleps = -0.2_wp
   nf = 0
   call erosion_points(blk, e, 1, sig, rv, 0.1_wp, 1.0_wp, nf)
   call check(nf(1) == 1, 'VOLEPS -0.2: ln V = -0.223 fails (compression)')
   call assert_summary()
end program test_erosion
