!> Kernels shared by the solid families (dx_hex8, dx_tet4), per element or per block:
!> - cube_roots: V**(1/3) from exactly rounded operations only (the same bits in every SIMD
!>   lane): the cbrt start of FreeBSD's s_cbrt.c, Halley's iteration (Traub 1964, Iterative
!>   Methods for the Solution of Equations, sec. 8.4) and one Newton step;
!> - centred_work: the internal-energy increment of one element as the work of its stress and
!>   bulk-viscosity forces in the central-difference balance (the exact partner of the
!>   centred kinetic energy of dx_explicit; Simpson's rule for the volume change, exact for
!>   the cubic V(x) of the trilinear hexahedron and the linear tetrahedron; Belytschko, Liu &
!>   Moran, Nonlinear Finite Elements for Continua and Structures, 2000, sec. 6.2.3 for the
!>   energy balance of the central-difference method).
module dx_solid_kernels
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp
   implicit none
   private
   public :: cube_roots, centred_work

contains

   !> l(1:n) = x(1:n)**(1/3) from exactly rounded operations only, so a vectorized loop
   !> gives every element the same bits in every lane and in the scalar remainder. (pow not:
   !> gfortran pre-includes glibc's math-vector-fortran.h, and the vector body then calls
   !> libmvec's SIMD pow, the remainder scalar libm pow; an element's result depended on its
   !> position in its block, and an MPI rank's piece of a block changes positions.)
   !> Start: the bit pattern of x divided by 3 plus the exponent bias term (the classic
   !> cbrt start, as in FreeBSD's s_cbrt.c; within 3.3 % here), done through a double so the
   !> loop vectorizes; then two steps of Halley's iteration l <- l (l^3 + 2x)/(2 l^3 + x)
   !> (cubic convergence; Traub 1964, Iterative Methods for the Solution of Equations,
   !> sec. 8.4) and one Newton step: within 3 ulp of the correctly rounded cube root on
   !> 1e-90..1e90 (2e5 random samples; pow(x, 1/3) is itself off by up to 16 ulp at
   !> 1e+-40, 1/3 not being a double). Valid for volumes in 1e-90..1e90 (any consistent
   !> units); x <= 0 gives 0. One loop without calls, so it vectorizes; integer/real
   !> conversions, +, *, / are exact or correctly rounded in every lane.
   subroutine cube_roots(n, x, l)
      integer, intent(in) :: n
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: l(:)
      integer(int64), parameter :: CBRT_BIAS = 3071306043645493248_int64   ! 715094163*2**32
      real(wp) :: y, r, r3
      integer :: i
      do i = 1, n
         y = max(x(i), 1.0e-90_wp)
         r = transfer(int(real(transfer(y, 0_int64), wp)/3.0_wp, int64) + CBRT_BIAS, 1.0_wp)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r3 = r*r*r
         r = r*(r3 + 2.0_wp*y)/(2.0_wp*r3 + y)
         r = r - (r*r*r - y)/(3.0_wp*r*r)
         l(i) = merge(r, 0.0_wp, x(i) > 0.0_wp)
      end do
   end subroutine cube_roots

   !> Internal-energy increment de of one element at this pass: the work of its stress and
   !> bulk-viscosity nodal forces f(n) in the central-difference balance, W(n) =
   !> dtavg(n) f(n).(v(n-1/2) + v(n+1/2))/2, the exact partner of the centred kinetic energy
   !> 1/2 m v(n-1/2).v(n+1/2) (dx_explicit) for any time-step sequence. W(n) is completed at
   !> the next pass, when v(n+1/2) and dt(n+1/2) are known: the half with v(n-1/2) is booked
   !> now with dt(n-1/2)/2 and corrected then to dtavg(n)/2. With a constant step this is the
   !> trapezoid (sigma(n-1) + sigma(n)):D V dt. The stress power uses the mid-step D V
   !> (wo, wn = dt sigma_old:D V, dt sigma_new:D V); the viscosity force q B(x(n)) uses
   !> bvn = B(n).v(n-1/2) and B(n-1).v(n-1/2) from Simpson's rule, exact for the cubic V(x):
   !> V(n) - V(n-1) = dt/6 (B(n-1) + 4 B(n-1/2) + B(n)).v(n-1/2), bvm = B(n-1/2).v(n-1/2).
   !> s1..s4 = q, q bvn, dt, sigma:D V of the last pass (the element's ework row).
   pure subroutine centred_work(s1, s2, s3, s4, dt, wo, wn, q, vol, vol_old, bvn, bvm, de)
      real(wp), intent(inout) :: s1, s2, s3, s4
      real(wp), intent(in) :: dt, wo, wn, q, vol, vol_old, bvn, bvm
      real(wp), intent(out) :: de
      real(wp) :: bvp, pn
      de = 0.0_wp
      pn = 0.0_wp
      if (dt > 0.0_wp) then
         bvp = 6.0_wp*(vol - vol_old)/dt - 4.0_wp*bvm - bvn
         pn = wn/dt
         de = 0.5_wp*(wo + wn) + 0.25_wp*(dt - s3)*(s4 - wo/dt) &
              - (0.25_wp*(s3 + dt)*s1*bvp + 0.25_wp*(dt - s3)*s2 + 0.5_wp*dt*q*bvn)
      end if
      s1 = q
      s2 = q*bvn
      s3 = dt
      s4 = pn
   end subroutine centred_work

end module dx_solid_kernels
