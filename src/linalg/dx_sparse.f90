!> Sparse matrices for the implicit solver: of a symmetric matrix the upper triangle (diagonal
!> included), of an unsymmetric one (sym = .false.: the friction tangent) every entry,
!> in compressed sparse rows (CSR) with the same entries as coordinate triples (COO: irn,
!> jcn), the input the direct solver (dx_mumps) takes. The pattern comes from a symbolic
!> pass done once per mesh (sparse_symbolic): from each element's equation map (0 for an
!> eliminated degree of freedom) the sorted unique columns of every row, the diagonal always
!> (dg: its entry; the first of the row when symmetric: an equation no element touches has a zero row that the solver reports
!> as a null pivot, and the diagonal shifts K - sigma M and K_eff find it), and for each element
!> the position of each of its (a, b) entries in the value array, so that every Newton
!> assembly is one indexed add per element entry (sparse_add_element) with no search.
!> (The classical finite-element assembly of Hughes, "The Finite Element Method", 1987,
!> ch. 1.14, with the row-by-row symbolic pass of Gilbert, Moler & Schreiber, SIAM J. Matrix
!> Anal. Appl. 13 (1992) 333-356.)
module dx_sparse
   use dx_kinds, only: wp
   implicit none
   private
   public :: sparse_sym_t, sparse_symbolic, sparse_zero, sparse_add_element, sparse_matvec, &
             sparse_to_dense

   type :: sparse_sym_t
      integer :: n = 0                        !< equations
      integer :: nnz = 0                      !< stored entries (upper triangle if sym)
      logical :: sym = .true.                 !< symmetric: the upper triangle is stored
      integer :: nde = 0                      !< equations per element (its map's length)
      integer, allocatable :: rowptr(:)       !< (n + 1) CSR row starts
      integer, allocatable :: col(:)          !< (nnz) column of each entry, sorted per row
      integer, allocatable :: irn(:)          !< (nnz) row of each entry (COO)
      integer, allocatable :: dg(:)           !< (n) entry of each row's diagonal
      integer, allocatable :: pos(:, :, :)    !< (nde, nde, nel) entry of element (a, b); 0: none
      real(wp), allocatable :: a(:)           !< (nnz) values
   end type sparse_sym_t

contains

   !> The pattern of a matrix with n equations assembled from nel elements whose equation
   !> maps are eq(1:nde, e) (0: the degree of freedom is not an equation); symmetric (the
   !> upper triangle) unless unsym is present and true (every entry).
   subroutine sparse_symbolic(n, eq, s, unsym)
      integer, intent(in) :: n
      integer, intent(in) :: eq(:, :)
      type(sparse_sym_t), intent(out) :: s
      logical, intent(in), optional :: unsym
      integer :: nde, nel, e, a, b, i, j, k, k0, k1, m, lo, hi, mid, jmin
      integer, allocatable :: cnt(:), start(:), fill(:), tmp(:)
      nde = size(eq, 1)
      nel = size(eq, 2)
      s%n = n
      s%sym = .true.
      if (present(unsym)) s%sym = .not. unsym
      s%nde = nde
      ! upper bound of each row's entries: every (a, b) pair of every element
      allocate(cnt(n), start(n + 1))
      cnt = 1                ! every row's diagonal, even of an equation in no element
      do e = 1, nel
         do a = 1, nde
            i = eq(a, e)
            if (i <= 0) cycle
            jmin = i
            if (.not. s%sym) jmin = 1
            do b = 1, nde
               if (eq(b, e) >= jmin) cnt(i) = cnt(i) + 1
            end do
         end do
      end do
      start(1) = 1
      do i = 1, n
         start(i + 1) = start(i) + cnt(i)
      end do
      allocate(tmp(start(n + 1) - 1), fill(n))
      do i = 1, n
         tmp(start(i)) = i
      end do
      fill = 1
      do e = 1, nel
         do a = 1, nde
            i = eq(a, e)
            if (i <= 0) cycle
            jmin = i
            if (.not. s%sym) jmin = 1
            do b = 1, nde
               j = eq(b, e)
               if (j >= jmin) then
                  tmp(start(i) + fill(i)) = j
                  fill(i) = fill(i) + 1
               end if
            end do
         end do
      end do
      ! sort each row, keep the unique columns
      allocate(s%rowptr(n + 1))
      s%rowptr(1) = 1
      m = 0
      do i = 1, n
         k0 = start(i)
         k1 = start(i) + fill(i) - 1
         call sort_int(tmp(k0:k1))
         do k = k0, k1
            if (k > k0) then
               if (tmp(k) == tmp(k - 1)) cycle
            end if
            m = m + 1
            tmp(m) = tmp(k)      ! m <= k: compaction in place
         end do
         s%rowptr(i + 1) = m + 1
      end do
      s%nnz = m
      allocate(s%col(m), s%irn(m), s%a(m))
      s%col = tmp(1:m)
      do i = 1, n
         s%irn(s%rowptr(i):s%rowptr(i + 1) - 1) = i
      end do
      s%a = 0.0_wp
      allocate(s%dg(n))
      do i = 1, n
         do k = s%rowptr(i), s%rowptr(i + 1) - 1
            if (s%col(k) == i) s%dg(i) = k
         end do
      end do
      ! each element entry's position (binary search in its row)
      allocate(s%pos(nde, nde, nel))
      s%pos = 0
      do e = 1, nel
         do a = 1, nde
            i = eq(a, e)
            if (i <= 0) cycle
            jmin = i
            if (.not. s%sym) jmin = 1
            do b = 1, nde
               j = eq(b, e)
               if (j < jmin) cycle
               lo = s%rowptr(i)
               hi = s%rowptr(i + 1) - 1
               do while (lo < hi)
                  mid = (lo + hi)/2
                  if (s%col(mid) < j) then
                     lo = mid + 1
                  else
                     hi = mid
                  end if
               end do
               s%pos(a, b, e) = lo
            end do
         end do
      end do
   end subroutine sparse_symbolic

   !> Zero the values (before an assembly).
   subroutine sparse_zero(s)
      type(sparse_sym_t), intent(inout) :: s
      s%a = 0.0_wp
   end subroutine sparse_zero

   !> Add element e's matrix ke(nde, nde) (of a symmetric one its upper-triangle entries).
   subroutine sparse_add_element(s, e, ke)
      type(sparse_sym_t), intent(inout) :: s
      integer, intent(in) :: e
      real(wp), intent(in) :: ke(:, :)
      integer :: a, b, p
      do b = 1, s%nde
         do a = 1, s%nde
            p = s%pos(a, b, e)
            if (p > 0) s%a(p) = s%a(p) + ke(a, b)
         end do
      end do
   end subroutine sparse_add_element

   !> y = A x (a symmetric matrix from its upper triangle).
   subroutine sparse_matvec(s, x, y)
      type(sparse_sym_t), intent(in) :: s
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: y(:)
      integer :: i, k, j
      y = 0.0_wp
      do i = 1, s%n
         do k = s%rowptr(i), s%rowptr(i + 1) - 1
            j = s%col(k)
            y(i) = y(i) + s%a(k)*x(j)
            if (j /= i .and. s%sym) y(j) = y(j) + s%a(k)*x(i)
         end do
      end do
   end subroutine sparse_matvec

   !> The full dense matrix (tests, small systems).
   subroutine sparse_to_dense(s, d)
      type(sparse_sym_t), intent(in) :: s
      real(wp), allocatable, intent(out) :: d(:, :)
      integer :: i, k
      allocate(d(s%n, s%n))
      d = 0.0_wp
      do i = 1, s%n
         do k = s%rowptr(i), s%rowptr(i + 1) - 1
            d(i, s%col(k)) = s%a(k)
            if (s%sym) d(s%col(k), i) = s%a(k)
         end do
      end do
   end subroutine sparse_to_dense

   !> Ascending sort of a short integer list (insertion sort: rows hold at most a few
   !> hundred candidates).
   pure subroutine sort_int(v)
      integer, intent(inout) :: v(:)
      integer :: i, j, t
      do i = 2, size(v)
         t = v(i)
         j = i - 1
         do while (j >= 1)
            if (v(j) <= t) exit
            v(j + 1) = v(j)
            j = j - 1
         end do
         v(j + 1) = t
      end do
   end subroutine sort_int
end module dx_sparse
