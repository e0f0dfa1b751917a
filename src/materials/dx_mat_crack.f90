!> *DYNX_BRITTLE_CRACK: a crack model after the modified Rubin-Attia 3-D crack damage model of
!> the DYNA2D glass work (seed article 3): up to three orthogonal fracture surfaces normal to a
!> right-handed fracture triad, a symmetric void-strain tensor found by restricting the traction
!> on the open surfaces, compressive yielding with a scalar damage treated separately. The
!> Rubin-Attia brittle-fracture paper and the LLNL modification were not found (shared
!> damage-and-plane-stress.md), so the rules below are the closest documented ones and dynx's
!> own, written out in docs/damage.md: the triad and crack rules of DYNA3D material 17
!> (*MAT_ORIENTED_CRACK: a crack opens normal to sigma1 when sigma1 > FS, later cracks
!> orthogonal, an open crack carries no normal tension or face shear, it recloses in
!> compression) and the operator split of Govindjee, Kay & Simo 1995 (IJNME 38:3611, LS-DYNA
!> *MAT_BRITTLE_DAMAGE: a J2 check for compression beside the crack step).
!> Step (hypoelastic, Jaumann-rotated stress from the element; lambda = K - 2G/3):
!>  1. trial sigma = sigma(n) + lambda tr(de) I + 2G de;
!>  2. compressive yield: J2 radial return onto Yc = (1 - Dc) SIGC + Dc YCF, Dc += deps_p/EPSC
!>     (capped at 1);
!>  3. first crack: sigma1 > FT fixes the triad to the principal directions (e1 = that of
!>     sigma1, e3 = e1 x e2); later, crack k opens when e_k.sigma.e_k > FT;
!>  4. in the triad frame, an open crack k (void strain ev_kk > 0, or opening now) carries
!>     sigma'_kk = 0: the normal void-strain increments solve (lambda 1 1^T + 2G I) dev = sigma'
!>     on the open set with ev_kk + dev_k >= 0 (a crack whose void strain would go negative
!>     closes: dev_k = -ev_kk, and it carries compression); the face shears of an open crack
!>     are released into the shear void strain (dev_kj = sigma'_kj/(2G), sigma'_kj = 0).
!> The triad is fixed in the material after it forms: before each update the element hands the
!> spin increments W dt of its Jaumann rotation of sigma (rotate_history, hv_frame), and the
!> triad turns by the Hughes-Winget rotation R = (I - W dt/2)**-1 (I + W dt/2) (Hughes &
!> Winget 1980, IJNME 15:1862), orthogonal to round-off, so the triad stays orthonormal; with
!> the mid-step spin of the central-difference element it is the exact rotation of a rigid
!> turn (W dt = 2 tan(theta/2) about the axis). The void strain is held in the triad frame and
!> turns with it. D for the plot = max(Dc, cracks opened/3).
!> Cards: MID RO E PR FT; SIGC YCF EPSC.
!> History: 1-3 crack k opened (0/1), 4-12 triad (columns e1 e2 e3; 0 before the first crack),
!> 13-18 void strain in the triad frame (11 22 33 12 23 31, tensor components), 19 eps_p,
!> 20 Dc, 21 D.
!> Eigenvectors: cyclic Jacobi rotations (Golub & Van Loan, Matrix Computations, 8.5).
module dx_mat_crack
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_field_error
   use dx_strings, only: rstr
   use dx_card, only: card_t
   use dx_vec3, only: cross
   use dx_material, only: material_t, read_mid_ro
   use dx_mat_elastic, only: check_elastic_constants
   use dx_mat_hydro_common, only: max_principal
   use dx_mat_brittle, only: radial_return
   implicit none
   private
   public :: mat_crack_t, sym_eigen

   type, extends(material_t) :: mat_crack_t
      real(wp) :: e = 0.0_wp, pr = 0.0_wp, ft = 0.0_wp
      real(wp) :: sigc = 0.0_wp, ycf = 0.0_wp, epsc = 0.0_wp
   contains
      procedure :: read_cards => ck_read_cards
      procedure :: setup => ck_setup
      procedure :: nhist => ck_nhist
      procedure :: update => ck_update
      procedure :: rotate_history => ck_rotate_history
   end type mat_crack_t

contains

   subroutine ck_read_cards(self, c)
      class(mat_crack_t), intent(inout) :: self
      type(card_t), intent(inout) :: c
      call read_mid_ro(self, c)
      call c%real('E', 0.0_wp, self%e)
      call c%real('PR', 0.0_wp, self%pr)
      call c%real('FT', 0.0_wp, self%ft)
      call c%next()
      call c%real('SIGC', 0.0_wp, self%sigc)
      call c%real('YCF', 0.0_wp, self%ycf)
      call c%real('EPSC', 0.0_wp, self%epsc)
   end subroutine ck_read_cards

   subroutine ck_setup(self, error)
      class(mat_crack_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      call check_elastic_constants(self, self%e, self%pr, error)
      if (allocated(error)) return
      if (.not. (self%ft > 0.0_wp)) then
         call set_field_error(error, 'FT', 'tensile strength must be > 0, got '//rstr(self%ft)); return
      end if
      if (.not. (self%sigc > 0.0_wp)) then
         call set_field_error(error, 'SIGC', 'compressive yield must be > 0, got '// &
                              rstr(self%sigc)); return
      end if
      if (.not. (self%ycf >= 0.0_wp .and. self%ycf <= self%sigc)) then
         call set_field_error(error, 'YCF', 'the damaged yield must lie in [0, SIGC], got '// &
                              rstr(self%ycf)); return
      end if
      if (.not. (self%epsc > 0.0_wp)) then
         call set_field_error(error, 'EPSC', 'plastic strain to full compressive damage must '// &
                              'be > 0, got '//rstr(self%epsc)); return
      end if
      self%hv_eps_p = 19
      self%hv_damage = 21
      self%hv_frame = .true.
   end subroutine ck_setup

   !> Turn the fracture triad (history 4-12) of points 1..n with the material by the
   !> Hughes-Winget rotation of the spin increments (module header): with A = W dt/2 and its
   !> axial vector a, R = I + 2/(1 + a.a) (A + A A) (the Cayley transform in closed form).
   subroutine ck_rotate_history(self, n, w12, w23, w31, hv)
      class(mat_crack_t), intent(in) :: self
      integer, intent(in) :: n
      real(wp), intent(in) :: w12(:), w23(:), w31(:)
      real(wp), intent(inout) :: hv(:, :)
      real(wp) :: a(3, 3), r(3, 3), q(3, 3)
      integer :: i, k
      do i = 1, n
         if (all(hv(i, 4:12) == 0.0_wp)) cycle
         a = 0.0_wp
         a(1, 2) = 0.5_wp*w12(i); a(2, 1) = -a(1, 2)
         a(2, 3) = 0.5_wp*w23(i); a(3, 2) = -a(2, 3)
         a(3, 1) = 0.5_wp*w31(i); a(1, 3) = -a(3, 1)
         r = 2.0_wp/(1.0_wp + a(1, 2)**2 + a(2, 3)**2 + a(3, 1)**2)*(a + matmul(a, a))
         do k = 1, 3
            r(k, k) = r(k, k) + 1.0_wp
         end do
         q = reshape(hv(i, 4:12), [3, 3])
         hv(i, 4:12) = reshape(matmul(r, q), [9])
      end do
      if (.false.) hv(1, 1) = self%e
   end subroutine ck_rotate_history

   pure integer function ck_nhist(self)
      class(mat_crack_t), intent(in) :: self
      ck_nhist = 21
      if (.false.) ck_nhist = int(self%ro)
   end function ck_nhist

   !> Eigenvalues lam (descending) and eigenvectors v (columns, right-handed) of the symmetric
   !> 3x3 a, by cyclic Jacobi rotations to round-off.
   pure subroutine sym_eigen(a, lam, v)
      real(wp), intent(in) :: a(3, 3)
      real(wp), intent(out) :: lam(3), v(3, 3)
      real(wp) :: b(3, 3), th, t, cs, sn, tmp(3), off, tot
      integer :: sweep, p, q, k, idx(3)
      b = a
      v = 0.0_wp
      do k = 1, 3
         v(k, k) = 1.0_wp
      end do
      do sweep = 1, 50
         off = b(1, 2)**2 + b(2, 3)**2 + b(1, 3)**2
         tot = sum(b**2)
         if (off <= (epsilon(1.0_wp)**2)*tot*1.0e-4_wp .or. off == 0.0_wp) exit
         do p = 1, 2
            do q = p + 1, 3
               if (b(p, q) == 0.0_wp) cycle
               th = (b(q, q) - b(p, p))/(2.0_wp*b(p, q))
               t = sign(1.0_wp, th)/(abs(th) + sqrt(th**2 + 1.0_wp))
               cs = 1.0_wp/sqrt(t**2 + 1.0_wp)
               sn = t*cs
               tmp = b(:, p)
               b(:, p) = cs*tmp - sn*b(:, q)
               b(:, q) = sn*tmp + cs*b(:, q)
               tmp = b(p, :)
               b(p, :) = cs*tmp - sn*b(q, :)
               b(q, :) = sn*tmp + cs*b(q, :)
               tmp = v(:, p)
               v(:, p) = cs*tmp - sn*v(:, q)
               v(:, q) = sn*tmp + cs*v(:, q)
            end do
         end do
      end do
      lam = [b(1, 1), b(2, 2), b(3, 3)]
      idx = [1, 2, 3]
      if (lam(idx(2)) > lam(idx(1))) idx([1, 2]) = idx([2, 1])
      if (lam(idx(3)) > lam(idx(2))) idx([2, 3]) = idx([3, 2])
      if (lam(idx(2)) > lam(idx(1))) idx([1, 2]) = idx([2, 1])
      lam = lam(idx)
      v = v(:, idx)
      v(:, 3) = cross(v(:, 1), v(:, 2))
   end subroutine sym_eigen

   pure function full(s) result(a)
      real(wp), intent(in) :: s(6)
      real(wp) :: a(3, 3)
      a = reshape([s(1), s(4), s(6), s(4), s(2), s(5), s(6), s(5), s(3)], [3, 3])
   end function full

   pure function voigt(a) result(s)
      real(wp), intent(in) :: a(3, 3)
      real(wp) :: s(6)
      s = [a(1, 1), a(2, 2), a(3, 3), 0.5_wp*(a(1, 2) + a(2, 1)), 0.5_wp*(a(2, 3) + a(3, 2)), &
           0.5_wp*(a(1, 3) + a(3, 1))]
   end function voigt

   subroutine ck_update(self, nv, dt, deps, relvol, eint, sig, hv, ierr)
      class(mat_crack_t), intent(in) :: self
      integer, intent(in) :: nv
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: deps(nv, 6), relvol(nv), eint(nv)
      real(wp), intent(inout) :: sig(nv, 6)
      real(wp), intent(inout) :: hv(:, :)
      integer, intent(inout) :: ierr(nv)
      real(wp) :: g, lam, s(6), p, seq, yc, dep, dc, q(3, 3), sp(3, 3), ev(6), el(3)
      real(wp) :: de(3), rhs(3), sm, evkj
      logical :: act(3), fix(3), changed
      integer :: i, k, j, it, na, kj(2, 3)
      kj = reshape([1, 2, 2, 3, 1, 3], [2, 3])
      g = self%shear
      lam = self%bulk - 2.0_wp*g/3.0_wp
      do i = 1, nv
         ! 1. elastic trial
         s = sig(i, :) + 2.0_wp*g*deps(i, :)
         s(1:3) = s(1:3) + lam*(deps(i, 1) + deps(i, 2) + deps(i, 3))
         ! 2. compressive yield with scalar damage
         p = -(s(1) + s(2) + s(3))/3.0_wp
         s(1:3) = s(1:3) + p
         dc = hv(i, 20)
         yc = (1.0_wp - dc)*self%sigc + dc*self%ycf
         call radial_return(s, yc, seq)
         dep = max(0.0_wp, seq - yc)/(3.0_wp*g)
         dc = min(1.0_wp, dc + dep/self%epsc)
         s(1:3) = s(1:3) - p
         ! 3. fracture triad and crack initiation
         if (all(hv(i, 4:12) == 0.0_wp)) then
            if (max_principal(s) > self%ft) then
               call sym_eigen(full(s), el, q)
               hv(i, 4:12) = reshape(q, [9])
               hv(i, 1) = 1.0_wp
            end if
         end if
         if (any(hv(i, 4:12) /= 0.0_wp)) then
            q = reshape(hv(i, 4:12), [3, 3])
            sp = matmul(transpose(q), matmul(full(s), q))
            do k = 1, 3
               if (sp(k, k) > self%ft) hv(i, k) = 1.0_wp
            end do
            ! 4. open cracks carry no normal traction (active set, closure)
            ev = hv(i, 13:18)
            act = [(hv(i, k) /= 0.0_wp .and. (sp(k, k) > 0.0_wp .or. ev(k) > 0.0_wp), k = 1, 3)]
            fix = .false.
            de = 0.0_wp
            do it = 1, 8
               na = count(act)
               rhs = 0.0_wp
               sm = 0.0_wp
               do k = 1, 3
                  if (fix(k)) de(k) = -ev(k)
               end do
               do k = 1, 3
                  if (act(k)) rhs(k) = sp(k, k) - lam*sum(de, mask=fix)
               end do
               if (na > 0) sm = sum(rhs, mask=act)/(2.0_wp*g + lam*na)
               do k = 1, 3
                  if (act(k)) de(k) = (rhs(k) - lam*sm)/(2.0_wp*g)
                  if (.not. (act(k) .or. fix(k))) de(k) = 0.0_wp
               end do
               changed = .false.
               do k = 1, 3
                  if (act(k) .and. ev(k) + de(k) < 0.0_wp) then
                     act(k) = .false.
                     fix(k) = .true.
                     changed = .true.
                  else if (fix(k)) then
                     if (sp(k, k) - lam*sum(de) - 2.0_wp*g*de(k) > 0.0_wp) then
                        fix(k) = .false.
                        act(k) = .true.
                        changed = .true.
                     end if
                  end if
               end do
               if (.not. changed) exit
            end do
            do k = 1, 3
               sp(k, k) = sp(k, k) - lam*sum(de) - 2.0_wp*g*de(k)
               if (act(k)) sp(k, k) = 0.0_wp     ! exactly traction-free (the solve to round-off)
               ev(k) = max(0.0_wp, ev(k) + de(k))
            end do
            do j = 1, 3
               k = kj(1, j)
               if (ev(k) > 0.0_wp .or. ev(kj(2, j)) > 0.0_wp) then
                  evkj = sp(k, kj(2, j))/(2.0_wp*g)
                  ev(3 + j) = ev(3 + j) + evkj
                  sp(k, kj(2, j)) = 0.0_wp
                  sp(kj(2, j), k) = 0.0_wp
               end if
            end do
            s = voigt(matmul(q, matmul(sp, transpose(q))))
            hv(i, 13:18) = ev
         end if
         sig(i, :) = s
         hv(i, 19) = hv(i, 19) + dep
         hv(i, 20) = dc
         hv(i, 21) = max(dc, (hv(i, 1) + hv(i, 2) + hv(i, 3))/3.0_wp)
         if (.not. all(abs(s) < huge(1.0_wp))) ierr(i) = 2
      end do
      if (.false.) hv(1, 1) = dt + relvol(1) + eint(1)
   end subroutine ck_update
end module dx_mat_crack
