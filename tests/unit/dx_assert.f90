!> A small in-house assert module for the unit tests: each check prints PASS/FAIL and a
!> summary line `N passed, N failed` closes the program (error stop 1 when any failed).
module dx_assert
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use dx_kinds, only: wp
   implicit none
   private
   public :: check, check_close, assert_summary

   integer :: npass = 0, nfail = 0
contains
   !> Pass when cond holds.
   subroutine check(cond, name)
      logical, intent(in) :: cond
      character(*), intent(in) :: name
      if (cond) then
         npass = npass + 1
         write(output_unit, '(a)') '  PASS '//name
      else
         nfail = nfail + 1
         write(output_unit, '(a)') '  FAIL '//name
      end if
   end subroutine check

   !> Pass when |a - b| <= abs_tol + rel_tol*|b| (b is the reference) and a is finite.
   subroutine check_close(a, b, abs_tol, rel_tol, name)
      real(wp), intent(in) :: a, b, abs_tol, rel_tol
      character(*), intent(in) :: name
      logical :: ok
      ok = ieee_is_finite(a) .and. abs(a - b) <= abs_tol + rel_tol*abs(b)
      if (ok) then
         npass = npass + 1
         write(output_unit, '(a,es23.15)') '  PASS '//name//': ', a
      else
         nfail = nfail + 1
         write(output_unit, '(a,es23.15,a,es23.15,a,es10.3)') '  FAIL '//name//': got ', a, &
            ' expected ', b, ' diff ', abs(a - b)
      end if
   end subroutine check_close

   !> Print `N passed, N failed`; error stop 1 if any check failed.
   subroutine assert_summary()
      write(output_unit, '(i0,a,i0,a)') npass, ' passed, ', nfail, ' failed'
      flush(output_unit)
      if (nfail > 0) error stop 1
   end subroutine assert_summary
end module dx_assert
