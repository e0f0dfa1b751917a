!> Kernels shared by the solid families (dx_hex8, dx_tet4), per element or per block:
!> - cube_roots: V**(1/3) from exactly rounded operations only (the same bits in every SIMD
!>   lane): the cbrt start of FreeBSD's s_cbrt.c, Halley's iteration (Traub 1964, Iterative
!>   Methods for the Solution of Equations, sec. 8.4) and one Newton step;
!> (centred_work, the other kernel both use, stays in dx_hex8, public: moved out of that
!> module it is no longer inlined into hex8_sri, and the FMA contraction of ELFORM 2's
!> pending work changed the last digit of its internal energy, e.g. glstat of
!> patch_rigid_rotation_elform2, 9.8628816051E-006 -> ...053E-006.)
module dx_solid_kernels
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp
   implicit none
   private
   public :: cube_roots

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

end module dx_solid_kernels
