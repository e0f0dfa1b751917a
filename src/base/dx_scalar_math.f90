!> Elementary functions that must give the same bits for every element, wherever it sits in
!> its block. gfortran pre-includes glibc's math-vector-fortran.h, so a vectorized loop calls
!> libmvec's SIMD pow (_ZGV..._pow, up to 4 ulp) for the vector body and scalar libm pow for
!> the remainder: an element's result then depends on its position in the block, and a rank's
!> piece of a serial block (MPI engine, docs/design.md) would not reproduce the serial run.
!> Calling pow through this module (compiled separately, never inlined into the kernels)
!> keeps it scalar, correctly rounded libm pow for every element.
module dx_scalar_math
   use dx_kinds, only: wp
   implicit none
   private
   public :: scalar_pow

contains

   !> x**p with scalar libm pow.
   pure real(wp) function scalar_pow(x, p)
      real(wp), intent(in) :: x, p
      scalar_pow = x**p
   end function scalar_pow
end module dx_scalar_math
