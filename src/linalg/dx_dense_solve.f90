!> Dense linear solves through LAPACK (dgesv: LU with partial pivoting; Anderson et al.,
!> LAPACK Users' Guide, 3rd ed., SIAM 1999). The only place the conserving rigid-body solver
!> calls LAPACK; LAPACK's info becomes a message.
module dx_dense_solve
   use dx_kinds, only: wp
   implicit none
   private
   public :: dense_solve

   interface
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
   end interface

contains

   !> Solve A x = b in place (b becomes x); msg is '' on success, else why it failed.
   subroutine dense_solve(a, b, msg)
      real(wp), intent(inout) :: a(:, :), b(:)
      character(:), allocatable, intent(out) :: msg
      integer :: n, info
      integer, allocatable :: ipiv(:)
      character(16) :: s
      n = size(b)
      allocate(ipiv(n))
      call dgesv(n, 1, a, n, ipiv, b, n, info)
      msg = ''
      if (info < 0) then
         write(s, '(i0)') -info
         msg = 'dgesv: argument '//trim(s)//' is invalid'
      else if (info > 0) then
         write(s, '(i0)') info
         msg = 'dgesv: the matrix is singular (U('//trim(s)//','//trim(s)//') = 0)'
      end if
   end subroutine dense_solve
end module dx_dense_solve
