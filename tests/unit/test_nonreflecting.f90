!> Unit tests of the centred non-reflecting dashpot (dx_nonreflecting: centred_dashpot):
!> - the defining identity f = -C (v + k (F + f)) (the force at the mean of v(n-1/2) and
!>   v(n+1/2) = v(n-1/2) + 2 k (F + f)) for a full symmetric positive semi-definite C, to a
!>   few ulps, and its work -f.v_mean = v_mean.C.v_mean >= 0 (the boundary only takes energy);
!> - a free node with a dashpot C dt/m = 3 (beyond the lagged limit 2): the centred update
!>   multiplies v by (1 - a/2)/(1 + a/2) = -1/5 per step (the trapezoidal rule's exact factor),
!>   against 1 - a = -2 for the lagged -C v(n-1/2);
!> - a node on a spring (omega dt = 1.8, inside the undamped limit 2) with C dt/m = 1.9, the
!>   corner of decks/pressure_table: the lagged damper is unstable there (its limit omega dt <
!>   2 (sqrt(1 + xi^2) - xi), xi = C/(2 m omega), Belytschko, Liu & Moran 2000, section
!>   6.3.4: 1.21 here; the amplitude grows past 1e3 in 400 steps), the centred one decays
!>   (below 1e-3 of the start).
program test_nonreflecting
   use dx_kinds, only: wp
   use dx_nonreflecting, only: centred_dashpot
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp) :: c(3), v(2), f(2), fd(2), k, r(2), vm(2), dt, m, a, ks, x, vl, xl, vc, fsc(2)
   integer :: i

   ! ---- identity, full tensor (eigenvalues of C about 0.55 and 4.45: positive definite)
   c = [3.0_wp, 2.0_wp, 1.9_wp]
   v = [0.7_wp, -1.3_wp]
   f = [-2.5_wp, 0.4_wp]
   k = 0.37_wp
   fd = centred_dashpot(c, v, f, k)
   r = fd + [c(1)*(v(1) + k*(f(1) + fd(1))) + c(3)*(v(2) + k*(f(2) + fd(2))), &
             c(3)*(v(1) + k*(f(1) + fd(1))) + c(2)*(v(2) + k*(f(2) + fd(2)))]
   call check(maxval(abs(r)) < 64.0_wp*epsilon(1.0_wp)*maxval(abs(fd)), &
              'centred dashpot: f = -C (v + k (F + f))')
   vm = v + k*(f + fd)           ! (v(n-1/2) + v(n+1/2))/2
   call check(-dot_product(fd, vm) >= 0.0_wp, 'centred dashpot: work f.v_mean <= 0')
   fd = centred_dashpot(c, v, f, 0.0_wp)
   call check_close(fd(1), -(c(1)*v(1) + c(3)*v(2)), 0.0_wp, 4.0_wp*epsilon(1.0_wp), &
                    'centred dashpot: k = 0 is the lagged -C v')

   ! ---- free node, C dt/m = 3: factor -1/5 per step
   m = 2.0_wp; dt = 1.0e-3_wp; a = 3.0_wp
   c = [a*m/dt, a*m/dt, 0.0_wp]
   v = [1.0_wp, 0.0_wp]
   do i = 1, 20
      fsc = centred_dashpot(c, v, [0.0_wp, 0.0_wp], 0.5_wp*dt/m)
      v = v + dt*fsc/m
   end do
   call check_close(v(1), (-0.2_wp)**20, 0.0_wp, 1.0e-12_wp, &
                    'free node, C dt/m = 3: v = ((1 - a/2)/(1 + a/2))^n')

   ! ---- node on a spring: omega dt = 1.8, C dt/m = 1.9 (scalar, x direction)
   m = 1.0_wp; dt = 1.0_wp; ks = 1.8_wp**2; c = [1.9_wp, 0.0_wp, 0.0_wp]
   x = 1.0_wp; vc = 0.0_wp; xl = 1.0_wp; vl = 0.0_wp
   do i = 1, 400
      fsc = centred_dashpot(c, [vc, 0.0_wp], [-ks*x, 0.0_wp], 0.5_wp*dt/m)
      vc = vc + dt*(-ks*x + fsc(1))/m
      x = x + dt*vc
      vl = vl + dt*(-ks*xl - c(1)*vl)/m         ! the lagged damper
      xl = xl + dt*vl
   end do
   call check(abs(x) < 1.0e-3_wp .and. abs(vc) < 1.0e-3_wp, &
              'spring + dashpot, omega dt 1.8, C dt/m 1.9: centred decays')
   call check(abs(xl) > 1.0e3_wp, 'spring + dashpot: the lagged damper grows (its limit omega dt 1.21)')
   call assert_summary()
end program test_nonreflecting
