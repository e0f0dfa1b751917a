!> Unit tests of the shift-invert Lanczos (dx_lanczos: ARPACK mode 3 on a dx_mumps
!> factorization) on spring chains with closed-form spectra (n equal masses m, springs k;
!> e.g. Strang, "Introduction to Applied Mathematics", 1986, sec. 2.1 and 5.x):
!> 1. fixed-free chain (first mass tied to the ground): lambda_j = (4k/m) sin^2((2j - 1) pi /
!>    (2 (2n + 1))), j = 1..n; the 5 lowest with sigma = 0: each to 1e-11 relative (ARPACK's
!>    tolerance is machine precision; the factorization's condition lambda_n/lambda_1 ~ 4e3
!>    for n = 40 times eps, and the table's own sin evaluation: 1e-11 covers both),
!>    phi^T M phi = 1 and the modes M-orthogonal (1e-12);
!> 2. the same chain with the shift between lambda_3 and lambda_4: the 2 nearest it are
!>    lambda_3, lambda_4 (1e-11);
!> 3. free-free chain (no tie: K singular, a rigid translation): sigma < 0, lambda_1 = 0 to
!>    1e-12 lambda_2, then lambda_j = (4k/m) sin^2((j - 1) pi/(2n)) (1e-11).
program test_lanczos
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_sparse, only: sparse_sym_t, sparse_symbolic, sparse_add_element
   use dx_mumps, only: mumps_t
   use dx_lanczos, only: lanczos_modes
   use dx_par, only: par_self_handle, par_finalize
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   integer, parameter :: n = 40
   real(wp), parameter :: kspr = 3.0_wp, mass = 2.0_wp, pi = acos(-1.0_wp)
   real(wp), allocatable :: lam(:), phi(:, :), m(:)
   real(wp) :: ref
   integer :: j, nops
   type(error_t), allocatable :: err

   allocate(m(n))
   m = mass
   ! 1. fixed-free, sigma = 0
   call modes(.true., 0.0_wp, 5)
   do j = 1, 5
      ref = 4.0_wp*kspr/mass*sin((2*j - 1)*pi/(2.0_wp*(2*n + 1)))**2
      call check_close(lam(j), ref, 0.0_wp, 1.0e-11_wp, 'fixed-free chain lambda_'//achar(48 + j))
   end do
   call check_close(sum(m*phi(:, 1)**2), 1.0_wp, 0.0_wp, 1.0e-12_wp, 'phi_1^T M phi_1 = 1')
   call check_close(sum(m*phi(:, 1)*phi(:, 4)), 0.0_wp, 1.0e-12_wp, 0.0_wp, &
                    'phi_1^T M phi_4 = 0')
   ! 2. shift between lambda_3 and lambda_4
   call modes(.true., 2.0_wp*kspr/mass*(sin(5*pi/(2.0_wp*(2*n + 1)))**2 + &
                                        sin(7*pi/(2.0_wp*(2*n + 1)))**2), 2)
   do j = 1, 2
      ref = 4.0_wp*kspr/mass*sin((2*(j + 2) - 1)*pi/(2.0_wp*(2*n + 1)))**2
      call check_close(lam(j), ref, 0.0_wp, 1.0e-11_wp, 'shifted: lambda_'//achar(50 + j))
   end do
   ! 3. free-free, sigma < 0
   call modes(.false., -1.0e-3_wp, 4)
   call check_close(lam(1), 0.0_wp, 1.0e-12_wp*lam(2), 0.0_wp, 'free-free chain: lambda_1 = 0')
   do j = 2, 4
      ref = 4.0_wp*kspr/mass*sin((j - 1)*pi/(2.0_wp*n))**2
      call check_close(lam(j), ref, 0.0_wp, 1.0e-11_wp, 'free-free chain lambda_'//achar(48 + j))
   end do
   call par_finalize()
   call assert_summary()
contains
   !> The chain's K - sigma M (tied: spring from the ground to mass 1), factored, and nev
   !> modes nearest sigma.
   subroutine modes(tied, sigma, nev)
      logical, intent(in) :: tied
      real(wp), intent(in) :: sigma
      integer, intent(in) :: nev
      type(sparse_sym_t) :: s
      type(mumps_t) :: ms
      integer :: eq(2, n), e, i
      real(wp) :: ke(2, 2)
      do e = 1, n          ! element e: the spring between masses e - 1 and e (0: ground)
         eq(:, e) = [e - 1, e]
      end do
      if (.not. tied) eq(1, 1) = 0
      call sparse_symbolic(n, eq, s)
      s%a = 0.0_wp
      do e = 1, n
         ke = kspr*reshape([1.0_wp, -1.0_wp, -1.0_wp, 1.0_wp], [2, 2])
         if (e == 1 .and. .not. tied) ke = 0.0_wp
         call sparse_add_element(s, e, ke)
      end do
      do i = 1, n
         s%a(s%rowptr(i)) = s%a(s%rowptr(i)) - sigma*m(i)
      end do
      call ms%analyse(s, par_self_handle(), err)
      call check(.not. allocated(err), 'MUMPS analysis')
      call ms%factor(s, err)
      call check(.not. allocated(err) .and. ms%nnull == 0, 'K - sigma M factored')
      call lanczos_modes(ms, m, sigma, nev, 300, lam, phi, nops, err)
      call check(.not. allocated(err), 'Lanczos converged')
      call ms%finish()
   end subroutine modes
end program test_lanczos
