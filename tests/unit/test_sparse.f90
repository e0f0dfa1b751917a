!> Unit tests of the sparse assembly (dx_sparse) and the sparse direct solver (dx_mumps):
!> 1. a symmetric positive definite system assembled from 40 overlapping 6x6 element
!>    matrices (ke = g^T g + 6 I, g with entries in [-1, 1]: eigenvalues of ke in [6, 42],
!>    so the assembled matrix has a condition number below 42/6 * 40 ~ 300) with 5 eliminated
!>    degrees of freedom: the CSR matrix equals the dense assembly entry by entry (the same
!>    additions in the same order: exact), the MUMPS solution equals LAPACK's dgesv solution
!>    to round-off (bound 1e-13 relative: a few ulps times the condition number ~300 times
!>    the O(10) operations per entry), and A x reproduces b to 1e-13;
!> 2. a second factorization of changed values on the same analysis (Newton's reuse);
!> 3. a chain of springs with no support (a free rigid translation): the null pivot is
!>    detected (nnull = 1) instead of a crash or a silent wrong answer;
!> 4. unsymmetric (the friction tangent's storage): the element matrices of 1 plus an
!>    antisymmetric part (g - g^T)/2 (so ke's symmetric part stays positive definite and the
!>    matrix regular), every entry stored: the CSR equals the dense assembly exactly, the
!>    diagonal index dg points at the diagonal, MUMPS (SYM = 0) equals dgesv to 1e-13 (the
!>    same argument as 1) and A x = b to 1e-13.
program test_sparse
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_sparse, only: sparse_sym_t, sparse_symbolic, sparse_zero, sparse_add_element, &
                        sparse_matvec, sparse_to_dense
   use dx_mumps, only: mumps_t
   use dx_dense_solve, only: dense_solve
   use dx_par, only: par_self_handle, par_finalize
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   integer, parameter :: n = 30, nel = 40, nde = 6
   integer :: eq(nde, nel), e, a, k, seed(64)
   real(wp) :: ke(nde, nde, nel), g(nde, nde)
   real(wp), allocatable :: dense(:, :), dsp(:, :), b(:), xl(:), xm(:), y(:)
   type(sparse_sym_t) :: s, sc
   type(mumps_t) :: ms, mc
   type(error_t), allocatable :: err
   character(:), allocatable :: msg
   integer :: comm
   real(wp) :: kc(2, 2), ku(nde, nde, nel)
   type(sparse_sym_t) :: su
   type(mumps_t) :: mu
   integer :: eqc(2, 9)

   call random_seed(size=k)
   seed = 12345
   call random_seed(put=seed(1:k))
   ! element maps: 6 distinct equations each, every 8th element with an eliminated dof
   do e = 1, nel
      do a = 1, nde
         eq(a, e) = 1 + mod(7*e + 5*a*a + e*a, n)
      end do
      do a = 2, nde          ! distinct within the element
         do while (any(eq(1:a - 1, e) == eq(a, e)))
            eq(a, e) = 1 + mod(eq(a, e), n)
         end do
      end do
      if (mod(e, 8) == 0) eq(3, e) = 0
      call random_number(g)
      g = 2.0_wp*g - 1.0_wp
      ke(:, :, e) = matmul(transpose(g), g)
      do a = 1, nde
         ke(a, a, e) = ke(a, a, e) + 6.0_wp
      end do
   end do
   allocate(dense(n, n))
   dense = 0.0_wp
   do e = 1, nel
      do a = 1, nde
         if (eq(a, e) == 0) cycle
         do k = 1, nde
            if (eq(k, e) == 0) cycle
            dense(eq(a, e), eq(k, e)) = dense(eq(a, e), eq(k, e)) + ke(a, k, e)
         end do
      end do
   end do
   call sparse_symbolic(n, eq, s)
   call check(s%nnz > 0 .and. s%nnz <= n*(n + 1)/2, 'pattern: upper triangle')
   call check(all(s%col(:) >= s%irn(:)), 'pattern: columns at or right of the diagonal')
   call sparse_zero(s)
   do e = 1, nel
      call sparse_add_element(s, e, ke(:, :, e))
   end do
   call sparse_to_dense(s, dsp)
   call check(maxval(abs(dsp - dense)) == 0.0_wp, 'CSR assembly equals the dense assembly')

   allocate(b(n), xl(n), xm(n), y(n))
   do a = 1, n
      b(a) = sin(real(a, wp))
   end do
   xl = b
   call dense_solve(dense, xl, msg)
   call check(len(msg) == 0, 'dgesv solves')
   comm = par_self_handle()
   call ms%analyse(s, comm, err)
   call check(.not. allocated(err), 'MUMPS analysis')
   call ms%factor(s, err)
   call check(.not. allocated(err) .and. ms%nnull == 0, 'MUMPS factorization, no null pivot')
   xm = b
   call ms%solve(xm, err)
   call check(.not. allocated(err), 'MUMPS solve')
   call check_close(maxval(abs(xm - xl))/maxval(abs(xl)), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                    'MUMPS x against LAPACK x (relative max difference)')
   call sparse_matvec(s, xm, y)
   call check_close(maxval(abs(y - b))/maxval(abs(b)), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                    'residual |A x - b|/|b|')

   ! 2. new values, same pattern and analysis
   s%a = 2.0_wp*s%a
   call ms%factor(s, err)
   xm = b
   call ms%solve(xm, err)
   call check_close(maxval(abs(2.0_wp*xm - xl))/maxval(abs(xl)), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                    'refactorization (2A) x = x/2')
   call ms%finish()

   ! 3. 10 nodes, 9 unit springs, no support: singular (rigid translation)
   kc = reshape([1.0_wp, -1.0_wp, -1.0_wp, 1.0_wp], [2, 2])
   do e = 1, 9
      eqc(:, e) = [e, e + 1]
   end do
   call sparse_symbolic(10, eqc, sc)
   do e = 1, 9
      call sparse_add_element(sc, e, kc)
   end do
   call mc%analyse(sc, comm, err)
   call mc%factor(sc, err)
   call check(.not. allocated(err), 'singular chain: factorization returns')
   call check(mc%nnull == 1, 'singular chain: one null pivot (the free translation)')
   if (mc%nnull > 0) call check(all(mc%null_eq >= 1 .and. mc%null_eq <= 10), &
                                'singular chain: null equation in range')
   call mc%finish()

   ! 4. unsymmetric
   dense = 0.0_wp
   do e = 1, nel
      call random_number(g)
      ku(:, :, e) = ke(:, :, e) + (g - transpose(g))
      do a = 1, nde
         if (eq(a, e) == 0) cycle
         do k = 1, nde
            if (eq(k, e) == 0) cycle
            dense(eq(a, e), eq(k, e)) = dense(eq(a, e), eq(k, e)) + ku(a, k, e)
         end do
      end do
   end do
   call sparse_symbolic(n, eq, su, unsym=.true.)
   call check(.not. su%sym .and. su%nnz == 2*s%nnz - n, 'unsymmetric pattern: both triangles')
   do e = 1, nel
      call sparse_add_element(su, e, ku(:, :, e))
   end do
   call sparse_to_dense(su, dsp)
   call check(maxval(abs(dsp - dense)) == 0.0_wp, 'unsymmetric CSR equals the dense assembly')
   call check(all([(su%col(su%dg(a)) == a .and. su%irn(su%dg(a)) == a, a = 1, n)]), &
              'dg: the diagonal entries')
   call check(maxval(abs(dense - transpose(dense))) > 0.1_wp, 'the test matrix is unsymmetric')
   xl = b
   call dense_solve(dense, xl, msg)
   call mu%analyse(su, comm, err)
   call check(.not. allocated(err), 'MUMPS unsymmetric analysis')
   call mu%factor(su, err)
   call check(.not. allocated(err) .and. mu%nnull == 0, 'MUMPS unsymmetric factorization')
   xm = b
   call mu%solve(xm, err)
   call check_close(maxval(abs(xm - xl))/maxval(abs(xl)), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                    'MUMPS unsymmetric x against LAPACK x')
   call sparse_matvec(su, xm, y)
   call check_close(maxval(abs(y - b))/maxval(abs(b)), 0.0_wp, 1.0e-13_wp, 0.0_wp, &
                    'unsymmetric residual |A x - b|/|b|')
   call mu%finish()
   call par_finalize()
   call assert_summary()
end program test_sparse
