!> Unit tests of the fully integrated shell's strain-rate matrix (dx_shell_fi, shell_fi_bmat;
!> Bathe & Dvorkin 1985): on a distorted flat quadrilateral, (1) the six rigid motions of the
!> local dofs (translations, the in-plane spin, the rotations about x and y with their
!> transverse velocities) give zero strain rates at the four Gauss points to round-off; (2)
!> the element stiffness sum det J B^T C B (membrane, bending and transverse shear of an
!> elastic plate) has exactly six zero eigenvalues: no spurious zero-energy (hourglass)
!> mode, rank 14 of 20; (3) a linear velocity field and a constant curvature field (w_y =
!> k x, v_z = -k x**2/2: zero transverse shear) give the exact constant strain rates at
!> every point, the assumed shear included (the patch test of the element's kinematics).
program test_shell_fi
   use dx_kinds, only: wp
   use dx_shell_fi, only: shell_fi_bmat
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   real(wp), parameter :: GPT = 0.5773502691896257645_wp
   real(wp), parameter :: XI(4) = [-GPT, GPT, GPT, -GPT], ET(4) = [-GPT, -GPT, GPT, GPT]
   real(wp) :: xl(2, 4), bm(8, 20), det, u(20), k(20, 20), c(8, 8), lam(20), s(8), area
   real(wp) :: ym, nu, t, dm, worst
   integer :: g, m, nzero
   xl = reshape([0.0_wp, 0.0_wp, 2.0_wp, 0.1_wp, 2.3_wp, 1.8_wp, -0.2_wp, 1.5_wp], [2, 4])
   ! ---- rigid motions
   worst = 0.0_wp
   do m = 1, 6
      u = rigid(m)
      do g = 1, 4
         call shell_fi_bmat(xl, XI(g), ET(g), bm, det)
         worst = max(worst, maxval(abs(matmul(bm, u))))
      end do
   end do
   call check(worst < 1.0e-14_wp, 'rigid motions: zero strain rates at the 4 points')
   ! ---- stiffness: six zero eigenvalues
   ym = 1.0_wp; nu = 0.3_wp; t = 0.1_wp
   dm = ym*t/(1.0_wp - nu*nu)
   c = 0.0_wp
   c(1, 1:2) = [dm, nu*dm]; c(2, 1:2) = [nu*dm, dm]; c(3, 3) = 0.5_wp*(1.0_wp - nu)*dm
   c(4:6, 4:6) = c(1:3, 1:3)*t*t/12.0_wp
   c(7, 7) = 5.0_wp/6.0_wp*0.5_wp*ym/(1.0_wp + nu)*t; c(8, 8) = c(7, 7)
   k = 0.0_wp
   area = 0.0_wp
   do g = 1, 4
      call shell_fi_bmat(xl, XI(g), ET(g), bm, det)
      k = k + det*matmul(transpose(bm), matmul(c, bm))
      area = area + det
   end do
   call check_close(area, 0.5_wp*((xl(1, 3) - xl(1, 1))*(xl(2, 4) - xl(2, 2)) - &
                    (xl(1, 4) - xl(1, 2))*(xl(2, 3) - xl(2, 1))), 1.0e-15_wp, 0.0_wp, &
                    'sum of det J: the area')
   call jacobi_eigen(k, lam)
   nzero = count(abs(lam) < 1.0e-12_wp*maxval(abs(lam)))
   call check(nzero == 6, 'stiffness: 6 zero eigenvalues (got '//itoa(nzero)//')')
   call check(minval(lam) > -1.0e-12_wp*maxval(abs(lam)), 'stiffness: positive semi-definite')
   ! ---- linear membrane field and constant curvature: exact at every point
   worst = 0.0_wp
   do g = 1, 4
      call shell_fi_bmat(xl, XI(g), ET(g), bm, det)
      do m = 1, 4
         u(5*m - 4:5*m) = [0.3_wp*xl(1, m) - 0.2_wp*xl(2, m), 0.7_wp*xl(1, m) + 0.1_wp*xl(2, m), &
                           -0.5_wp*0.4_wp*xl(1, m)**2, 0.0_wp, 0.4_wp*xl(1, m)]
      end do
      s = matmul(bm, u)
      worst = max(worst, maxval(abs(s - [0.3_wp, 0.1_wp, 0.5_wp, 0.4_wp, 0.0_wp, 0.0_wp, &
                                         0.0_wp, 0.0_wp])))
   end do
   call check(worst < 1.0e-14_wp, 'linear membrane + constant curvature: exact strain rates')
   call assert_summary()
contains
   !> rigid motion m of the local dofs (vx vy vz wx wy per node)
   function rigid(m) result(r)
      integer, intent(in) :: m
      real(wp) :: r(20)
      integer :: q
      r = 0.0_wp
      do q = 1, 4
         select case (m)
         case (1:3)
            r(5*(q - 1) + m) = 1.0_wp
         case (4)      ! spin about z
            r(5*q - 4:5*q - 3) = [-xl(2, q), xl(1, q)]
         case (5)      ! rotation about x: vz = y, wx = 1
            r(5*q - 2) = xl(2, q); r(5*q - 1) = 1.0_wp
         case (6)      ! rotation about y: vz = -x, wy = 1
            r(5*q - 2) = -xl(1, q); r(5*q) = 1.0_wp
         end select
      end do
   end function rigid

   !> eigenvalues of the symmetric a (cyclic Jacobi; Golub & Van Loan 2013, sec. 8.5)
   subroutine jacobi_eigen(a0, lam)
      real(wp), intent(in) :: a0(:, :)
      real(wp), intent(out) :: lam(:)
      real(wp) :: a(size(a0, 1), size(a0, 1)), th, tt, cc, ss, ap(size(a0, 1)), aq(size(a0, 1))
      integer :: n, p, q, sweep
      a = a0
      n = size(a, 1)
      do sweep = 1, 60
         if (sqrt(sum(a**2) - sum([(a(p, p)**2, p = 1, n)])) < 1.0e-300_wp) exit
         do p = 1, n - 1
            do q = p + 1, n
               if (a(p, q) == 0.0_wp) cycle
               th = (a(q, q) - a(p, p))/(2.0_wp*a(p, q))
               tt = sign(1.0_wp, th)/(abs(th) + sqrt(th*th + 1.0_wp))
               cc = 1.0_wp/sqrt(tt*tt + 1.0_wp); ss = tt*cc
               ap = a(:, p); aq = a(:, q)
               a(:, p) = cc*ap - ss*aq; a(:, q) = ss*ap + cc*aq
               ap = a(p, :); aq = a(q, :)
               a(p, :) = cc*ap - ss*aq; a(q, :) = ss*ap + cc*aq
            end do
         end do
      end do
      lam = [(a(p, p), p = 1, n)]
   end subroutine jacobi_eigen

   function itoa(i) result(s)
      integer, intent(in) :: i
      character(:), allocatable :: s
      character(16) :: b
      write(b, '(i0)') i
      s = trim(b)
   end function itoa
end program test_shell_fi
