!> The generalized symmetric eigenproblem K phi = lambda M phi (M diagonal, >= 0) by
!> shift-invert Lanczos: the only user of ARPACK (Lehoucq, Sorensen & Yang, "ARPACK Users'
!> Guide: Solution of Large-Scale Eigenvalue Problems with Implicitly Restarted Arnoldi
!> Methods", SIAM 1998; Debian libarpack2 3.8). The implicitly restarted Lanczos iteration
!> of dsaupd in its mode 3 (section 3.2.3 of the guide: OP = (K - sigma M)^-1 M, B = M, the
!> M-inner product) on the largest |nu| of OP, nu = 1/(lambda - sigma): the modes nearest
!> the shift sigma; dseupd turns the Ritz values back to lambda and gives the eigenvectors,
!> M-orthonormal (phi_i^T M phi_j = delta_ij). The factorization of K - sigma M is the
!> caller's (a dx_mumps factor; this module only solves with it), as is the choice of sigma.
!> Reverse communication: ido -1 and 1 ask for y = OP x (with M x given for 1), 2 for
!> y = M x. ARPACK's start vector is its own (deterministic: a fixed seed), the tolerance
!> is machine precision (tol = 0), and the basis has ncv = max(2 nev + 1, nev + 20)
!> vectors (at most n).
module dx_lanczos
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str
   use dx_mumps, only: mumps_t
   implicit none
   private
   public :: lanczos_modes

   interface
      subroutine dsaupd(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, &
                        workd, workl, lworkl, info)
         import :: wp
         integer, intent(inout) :: ido
         character(1), intent(in) :: bmat
         integer, intent(in) :: n, nev, ncv, ldv, lworkl
         character(2), intent(in) :: which
         real(wp), intent(inout) :: tol      !< (0 on entry: set to machine precision)
         real(wp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11), info
      end subroutine dsaupd
      subroutine dseupd(rvec, howmny, sel, d, z, ldz, sigma, bmat, n, which, nev, tol, &
                        resid, ncv, v, ldv, iparam, ipntr, workd, workl, lworkl, info)
         import :: wp
         logical, intent(in) :: rvec
         character(1), intent(in) :: howmny, bmat
         logical, intent(inout) :: sel(ncv)
         integer, intent(in) :: ldz, n, nev, ncv, ldv, lworkl
         real(wp), intent(out) :: d(nev), z(ldz, nev)
         real(wp), intent(in) :: sigma
         real(wp), intent(inout) :: tol
         character(2), intent(in) :: which
         real(wp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11), info
      end subroutine dseupd
   end interface

contains

   !> The nev eigenpairs nearest sigma (lam ascending, phi(:, i) M-orthonormal, each with
   !> its largest-magnitude entry positive: a deterministic sign). ms holds the factorization
   !> of K - sigma M; m the diagonal of M. nev < n. maxit: ARPACK's restarts (iparam(3)).
   subroutine lanczos_modes(ms, m, sigma, nev, maxit, lam, phi, nops, error)
      type(mumps_t), intent(inout) :: ms
      real(wp), intent(in) :: m(:), sigma
      integer, intent(in) :: nev, maxit
      real(wp), allocatable, intent(out) :: lam(:), phi(:, :)
      integer, intent(out) :: nops            !< solves with the factorization
      type(error_t), allocatable, intent(out) :: error
      integer :: n, ncv, lworkl, ido, info, i, j, k
      integer :: iparam(11), ipntr(11)
      real(wp), allocatable :: resid(:), v(:, :), workd(:), workl(:), d(:), z(:, :), tmp(:)
      logical, allocatable :: sel(:)
      real(wp) :: t, tol
      n = size(m)
      nops = 0
      if (nev < 1 .or. nev >= n) then
         call set_error(error, 'eigenvalues: '//str(nev)//' modes asked of '//str(n)// &
                        ' equations (at most '//str(n - 1)//')', EXIT_NUMERIC)
         return
      end if
      ncv = min(n, max(2*nev + 1, nev + 20))
      lworkl = ncv*(ncv + 8)
      allocate(resid(n), v(n, ncv), workd(3*n), workl(lworkl), sel(ncv), d(nev), &
               z(n, nev), tmp(n))
      resid = 0.0_wp
      iparam = 0
      ipntr = 0
      iparam(1) = 1          ! exact shifts
      iparam(3) = maxit
      iparam(7) = 3          ! shift-invert, generalized
      ido = 0
      info = 0
      tol = 0.0_wp           ! machine precision (ARPACK writes it back)
      do
         call dsaupd(ido, 'G', n, 'LM', nev, tol, resid, ncv, v, n, iparam, ipntr, workd, &
                     workl, lworkl, info)
         select case (ido)
         case (-1)
            tmp = m*workd(ipntr(1):ipntr(1) + n - 1)
         case (1)
            tmp = workd(ipntr(3):ipntr(3) + n - 1)
         case (2)
            workd(ipntr(2):ipntr(2) + n - 1) = m*workd(ipntr(1):ipntr(1) + n - 1)
            cycle
         case default
            exit
         end select
         call ms%solve(tmp, error)
         if (allocated(error)) return
         nops = nops + 1
         workd(ipntr(2):ipntr(2) + n - 1) = tmp
      end do
      if (info /= 0 .and. .not. (info == 1 .and. iparam(5) >= nev)) then   ! (1: max restarts)
         call set_error(error, 'eigenvalues: the Lanczos iteration (ARPACK dsaupd) failed: '// &
            'info '//str(info)//', '//str(iparam(5))//' of '//str(nev)//' modes converged '// &
            'in '//str(iparam(3))//' restarts', EXIT_NUMERIC)
         return
      end if
      call dseupd(.true., 'A', sel, d, z, n, sigma, 'G', n, 'LM', nev, tol, resid, ncv, v, &
                  n, iparam, ipntr, workd, workl, lworkl, info)
      if (info /= 0) then
         call set_error(error, 'eigenvalues: ARPACK dseupd failed: info '//str(info), &
                        EXIT_NUMERIC)
         return
      end if
      ! ascending eigenvalues (insertion sort: nev is small), a fixed sign per vector
      do i = 2, nev
         t = d(i); tmp = z(:, i)
         j = i - 1
         do while (j >= 1)
            if (d(j) <= t) exit
            d(j + 1) = d(j); z(:, j + 1) = z(:, j)
            j = j - 1
         end do
         d(j + 1) = t; z(:, j + 1) = tmp
      end do
      do i = 1, nev
         k = maxloc(abs(z(:, i)), dim=1)
         if (z(k, i) < 0.0_wp) z(:, i) = -z(:, i)
      end do
      call move_alloc(d, lam)
      call move_alloc(z, phi)
   end subroutine lanczos_modes
end module dx_lanczos
