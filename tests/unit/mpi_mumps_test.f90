!> MPI test of dx_mumps's distributed assembled input (ICNTL(18) = 3; the implicit solver
!> under MPI, issue 20) with real ranks, run by scripts/run_mpi_tests.sh serially and under
!> mpirun -np 2, 3, 4. A chain of n springs (stiffness 1 + e/n, node 0 fixed, a unit load on
!> every free node; tip spring alone) as 2-equation elements; rank r assembles the elements
!> e with mod(e, NP) = r and passes the entries they touch (the diagonals shared by two
!> ranks' elements are passed by both: MUMPS adds them). Closed form: the spring e carries
!> the loads beyond it, n - e + 1, so u_i = sum_(e <= i) (n - e + 1)/(1 + e/n). Bound 1e-12
!> relative: MUMPS's backward error is ~1e-16 and this chain's condition number ~4n^2 = 4e4
!> (so ~4e-12 at worst; measured below 1e-13). Checked on the host (the centralized solution).
program mpi_mumps_test
   use, intrinsic :: iso_fortran_env, only: output_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_comm_handle, &
                     par_bcast_real
   use dx_sparse, only: sparse_sym_t, sparse_symbolic, sparse_add_element
   use dx_mumps, only: mumps_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   integer, parameter :: n = 100
   type(error_t), allocatable :: error
   type(sparse_sym_t) :: s
   type(mumps_t) :: ms
   integer :: eq(2, n), e, i, np, me, a, b
   logical, allocatable :: mark(:)
   integer, allocatable :: loc(:)
   real(wp) :: ke(2, 2), x(n), u(n), k, err

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size()
   me = par_rank()
   if (me == 0) write(output_unit, '(a,i0,a)') 'mpi_mumps_test on ', np, ' rank(s)'
   do e = 1, n
      eq(:, e) = [e - 1, e]
   end do
   call sparse_symbolic(n, eq, s)
   allocate(mark(s%nnz))
   mark = .false.
   do e = 1, n
      if (mod(e, np) /= me) cycle
      k = 1.0_wp + real(e, wp)/n
      ke = reshape([k, -k, -k, k], [2, 2])
      call sparse_add_element(s, e, ke)
      do b = 1, 2
         do a = 1, 2
            if (s%pos(a, b, e) > 0) mark(s%pos(a, b, e)) = .true.
         end do
      end do
   end do
   loc = pack([(i, i = 1, s%nnz)], mark)
   if (np > 1) then
      call ms%analyse(s, par_comm_handle(), error, loc)
   else
      call ms%analyse(s, par_comm_handle(), error)
   end if
   call check(.not. allocated(error), 'analysis (distributed entries)')
   call ms%factor(s, error)
   call check(.not. allocated(error) .and. ms%nnull == 0, 'factorization, no null pivot')
   x = 1.0_wp
   call ms%solve(x, error)
   call check(.not. allocated(error), 'solve')
   call par_bcast_real(x, 0)          ! (the host's solution)
   u(1) = real(n, wp)/(1.0_wp + 1.0_wp/n)
   do i = 2, n
      u(i) = u(i - 1) + real(n - i + 1, wp)/(1.0_wp + real(i, wp)/n)
   end do
   err = maxval(abs(x - u))/maxval(abs(u))
   call check_close(err, 0.0_wp, 1.0e-12_wp, 0.0_wp, 'spring chain against the closed form, '// &
                    'largest relative difference')
   call ms%finish()
   call par_finalize()
   call assert_summary()
end program mpi_mumps_test
