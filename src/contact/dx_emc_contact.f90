!> Energy- and momentum-conserving penalty contact between rigid bodies over one time step
!> t(n) -> t(n+1) of the Simo-Wong midpoint rule (dx_emc_solver).
!>
!> Penalty potential U(g) = eps/2 <-g>^2. Each contact pair has a slave material point S (a
!> surface node, or the centre of a spherically smoothed body with radius r) and a master
!> material point P found at the mid configuration x(n+1/2) = (x(n) + x(n+1))/2:
!>   facet:  nu = (n(n) + n(n+1))/2 (the master facet normal at n and n+1), P the point of the
!>           facet plane with x_S(n+1/2) - x_P(n+1/2) parallel to nu;
!>   sphere: nu = +-(d(n) + d(n+1))/(|d(n)| + |d(n+1)|), d = x_S - x_C (centres), P = C.
!> Algorithmic gap (Laursen & Chawla 1997, IJNME 40:863-886; LLNL FY97 Thrust Area Report,
!> art. 1, eq. 4): g(n+1) = g(n) + nu . ((x_S(n+1) - x_S(n)) - (x_P(n+1) - x_P(n))); with these
!> nu it equals the exact gap of the plane or sphere (the identity (n1 - n0).(n1 + n0) = 0 and
!> |d1| - |d0| = (d1 + d0).(d1 - d0)/(|d1| + |d0|)).
!> Force on the slave f = -Ubar nu, Ubar = (U(g1) - U(g0))/(g1 - g0) (discrete gradient;
!> Armero & Petocz 1998, CMAME 158:269-300), -f on the master, applied at the mid arms
!> r = (s(n) + s(n+1))/2 of S and P. With the Cayley update of dx_emc_solver the torque r x f
!> does exactly the work f . (s(n+1) - s(n)), so the contact work is -(U(g1) - U(g0)): kinetic
!> plus penalty energy is conserved; f parallel to x_S(n+1/2) - x_P(n+1/2) conserves angular
!> momentum, and +-f conserves linear momentum.
!> Lagrange multiplier pairs (FORM 2; DYNA3D style, report art. 1 eq. 7-9; Laursen & Chawla
!> 1997): f = lam nu with lam >= 0 found by the solver so that the algorithmic gap does not
!> change over the step, g(n+1) = g(n) (the discrete gap rate is zero): the contact does no
!> work (energy conserved, no stored energy) and, with g(n) >= 0, nothing penetrates.
!> Algorithmic dissipation (*CONTROL_IMPLICIT_DYNAMICS, rho_inf < 1): the penalty force gets
!> chi eps (<g1> - <g0>), <g> = min(g, 0), chi = (1 - rho_inf)/(2 (1 + rho_inf)), so a closed
!> linear pair has the high-frequency spectral radius rho_inf and the energy falls by
!> chi eps (<g1> - <g0>)(g1 - g0) >= 0 per step with the momenta exact (the energy-decaying
!> momentum-conserving idea of Armero & Romero 2001, CMAME 190:2603-2649, on the gap).
!> MPI (an emc_split_t the caller passes: dx_par_emc's par_emc_t): each rank searches and
!> evaluates the pairs of the slave points it owns; the pairs and the per-pair contributions
!> are gathered in serial order and added by the same loop as in a serial run
!> (emc_contact_forces computes every pair's contribution first, then adds them in pair
!> order), so the sums are the serial ones bit for bit. Without a split (or off): serial.
!> Missed contact (tunnelling, issue 15): the pairs are taken at the mid configuration, so a
!> step much longer than the flight time to a wall lets a slave point pass through the
!> master with no pair and no force. emc_find_tunnel checks each accepted step: a slave
!> point whose straight path from x(n) to x(n+1) in the master's body frame crosses a master
!> facet from its outer side (the crossing point inside the facet polygon) to deeper than
!> half the facet's smallest edge (where the pair selection no longer takes it), or passes
!> through a master sphere (both ends outside, the closest point of the path inside), with
!> no pair of that point and that master in the step. The caller warns (the swept-path idea of
!> continuous collision detection: Ericson 2005, Real-Time Collision Detection, sec. 5.3
!> and 9.5; Wriggers 2006, Computational Contact Mechanics, sec. 10.4, on contact missed by
!> large steps in implicit schemes).
module dx_emc_contact
   use dx_kinds, only: wp
   use dx_emc_types, only: emc_system_t, EMC_PAIR_NI, EMC_PAIR_NR
   implicit none
   private
   public :: emc_kin_t, emc_pair_t, emc_select_pairs, emc_contact_forces, emc_inv3, &
             emc_same_plane, emc_pairs_pack, emc_pairs_unpack, emc_split_t, emc_slot_range, &
             emc_find_tunnel, PAIR_FACET, PAIR_SPHERE_OUT, PAIR_SPHERE_IN

   integer, parameter :: PAIR_FACET = 1, PAIR_SPHERE_OUT = 2, PAIR_SPHERE_IN = 3
   integer, parameter :: NREC = 28   !< reals of one pair's contribution (pair_contribution)

   !> The split of the slave points over the ranks (ParaDyn): which slots this rank
   !> evaluates and the ordered gather of (key, values), given by the caller (the engine's
   !> par_emc_t), so this kernel imports neither the engine nor MPI. Slots are the slave
   !> points in serial loop order; off (on = .false.): every point is evaluated here.
   type, abstract :: emc_split_t
      logical :: on = .false.
      integer, allocatable :: base(:)    !< (ndefs) first slot of each contact definition
      logical, allocatable :: mine(:)    !< (nslots) this rank evaluates the slot
   contains
      procedure :: slot => split_slot
      procedure :: is_mine => split_mine
      procedure(gather_i), deferred :: gather   !< every rank's (key, values) in key order
   end type emc_split_t

   abstract interface
      subroutine gather_i(self, keys, vals, all_keys, all_vals)
         import :: emc_split_t, wp
         class(emc_split_t), intent(inout) :: self
         integer, intent(in) :: keys(:)
         real(wp), intent(in) :: vals(:, :)
         integer, allocatable, intent(out) :: all_keys(:)
         real(wp), allocatable, intent(out) :: all_vals(:, :)
      end subroutine gather_i
   end interface

   !> kinematics of one body over the step. The geometry is formed from differences of the
   !> centres (xc0 + xl0 of one body minus the other's) plus the small increments dxc and
   !> dr, never from absolute positions: a body 200 m from the origin would otherwise put
   !> ulp(200 m) = 3e-14 m of noise into every gap (times EPS into the force).
   type :: emc_kin_t
      real(wp) :: xc0(3), xc1(3), xm(3)
      real(wp) :: xl0(3) = 0.0_wp    !< low part of the compensated centre at t(n)
      real(wp) :: dxc(3)             !< xc1 - xc0 = dt/2 (v0 + v1)
      real(wp) :: r0(3, 3), r1(3, 3), a(3, 3), ainv(3, 3)   !< A = (R0 + R1)/2
      real(wp) :: dr(3, 3)           !< R1 - R0 = R0 (cay(Th) - I)
   end type emc_kin_t

   type :: emc_pair_t
      integer :: kind = PAIR_FACET
      integer :: def = 0, sb = 0, mb = 0
      integer :: src = 0            !< slave node index in snodes (0: sphere centre)
      integer :: facet = 0          !< master facet (PAIR_FACET)
      real(wp) :: s(3) = 0.0_wp     !< slave material point, body frame
      real(wp) :: rs = 0.0_wp       !< slave radius (0: a node)
      real(wp) :: g0 = 0.0_wp, g1 = 0.0_wp, ubar = 0.0_wp
      integer :: il = 0             !< index of its Lagrange multiplier (0: penalty pair)
      real(wp) :: lam = 0.0_wp      !< Lagrange multiplier (force along nu, >= 0)
      logical :: carried = .false.  !< g(n) is the algorithmic gap carried from the last step
      real(wp) :: g0c = 0.0_wp      !< that gap
      real(wp) :: n1(3) = 0.0_wp    !< master normal at n+1 (spatial), to match the next step
      real(wp) :: dfr = 0.0_wp      !< work of the friction force over the step (<= 0)
   end type emc_pair_t

contains

   !> The pairs as an integer and a real table (restart snapshots), column per pair.
   subroutine emc_pairs_pack(p, ai, ar)
      type(emc_pair_t), intent(in) :: p(:)
      integer, allocatable, intent(out) :: ai(:, :)
      real(wp), allocatable, intent(out) :: ar(:, :)
      integer :: i
      allocate(ai(EMC_PAIR_NI, size(p)), ar(EMC_PAIR_NR, size(p)))
      do i = 1, size(p)
         ai(:, i) = [p(i)%kind, p(i)%def, p(i)%sb, p(i)%mb, p(i)%src, p(i)%facet, p(i)%il, &
                     merge(1, 0, p(i)%carried)]
         ar(:, i) = [p(i)%s, p(i)%rs, p(i)%g0, p(i)%g1, p(i)%ubar, p(i)%lam, p(i)%g0c, &
                     p(i)%n1, p(i)%dfr]
      end do
   end subroutine emc_pairs_pack

   !> Inverse of emc_pairs_pack.
   subroutine emc_pairs_unpack(ai, ar, p)
      integer, intent(in) :: ai(:, :)
      real(wp), intent(in) :: ar(:, :)
      type(emc_pair_t), allocatable, intent(out) :: p(:)
      integer :: i
      allocate(p(size(ai, 2)))
      do i = 1, size(p)
         p(i)%kind = ai(1, i); p(i)%def = ai(2, i); p(i)%sb = ai(3, i); p(i)%mb = ai(4, i)
         p(i)%src = ai(5, i); p(i)%facet = ai(6, i); p(i)%il = ai(7, i)
         p(i)%carried = ai(8, i) /= 0
         p(i)%s = ar(1:3, i); p(i)%rs = ar(4, i); p(i)%g0 = ar(5, i); p(i)%g1 = ar(6, i)
         p(i)%ubar = ar(7, i); p(i)%lam = ar(8, i); p(i)%g0c = ar(9, i)
         p(i)%n1 = ar(10:12, i); p(i)%dfr = ar(13, i)
      end do
   end subroutine emc_pairs_unpack

   !> Inverse of a 3x3 matrix (A = (R0 + R1)/2 is well conditioned for |Theta| < 2).
   pure function emc_inv3(a) result(b)
      real(wp), intent(in) :: a(3, 3)
      real(wp) :: b(3, 3), det
      b(1, 1) = a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)
      b(1, 2) = a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3)
      b(1, 3) = a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)
      b(2, 1) = a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3)
      b(2, 2) = a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1)
      b(2, 3) = a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)
      b(3, 1) = a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1)
      b(3, 2) = a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2)
      b(3, 3) = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
      det = a(1, 1)*b(1, 1) + a(1, 2)*b(2, 1) + a(1, 3)*b(3, 1)
      b = b/det
   end function emc_inv3

   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   !> centre of body s minus centre of body m at t(n) (compensated parts included)
   pure function rel0(ks, km) result(d)
      type(emc_kin_t), intent(in) :: ks, km
      real(wp) :: d(3)
      d = (ks%xc0 - km%xc0) + (ks%xl0 - km%xl0)
   end function rel0

   !> mid centre of body s minus mid centre of body m
   pure function relm(ks, km) result(d)
      type(emc_kin_t), intent(in) :: ks, km
      real(wp) :: d(3)
      d = rel0(ks, km) + 0.5_wp*(ks%dxc - km%dxc)
   end function relm

   !> Regularized Coulomb friction at the contact point c (mid configuration; arm rc from the
   !> slave's mid centre): the slave and master material points whose mid positions are both c
   !> (X = A^-1 (c - xm) on each body) slip by d = dx_S - dx_M over the step; with the
   !> tangential part dt = d - (d.n)n, f = -mu N dt/sqrt(|dt|^2 + delta^2) on the slave and -f
   !> on the master. Both act at the same point, so linear and angular momentum are conserved;
   !> the work f.d = -mu N |dt|^2/sqrt(|dt|^2 + delta^2) <= 0 (Cayley arms make it exact), so
   !> friction only dissipates. (Regularized Coulomb law: Wriggers 2006, Computational Contact
   !> Mechanics, sec. 5.2.)
   subroutine friction(mu, delta, fn, nu, ks, km, rc, f, ts, tm, work)
      real(wp), intent(in) :: mu, delta, fn, nu(3), rc(3)
      type(emc_kin_t), intent(in) :: ks, km
      real(wp), intent(out) :: f(3), ts(3), tm(3)   !< force on the slave, torques (+ts, -tm)
      real(wp), intent(out) :: work
      real(wp) :: c(3), xs(3), xm(3), d(3), dtan(3), nh(3), rm(3), del
      c = relm(ks, km) + rc             ! the contact point, from the master's mid centre
      xs = matmul(ks%ainv, rc)
      xm = matmul(km%ainv, c)
      d = (ks%dxc + matmul(ks%dr, xs)) - (km%dxc + matmul(km%dr, xm))
      nh = nu/max(norm2(nu), tiny(1.0_wp))
      dtan = d - dot_product(d, nh)*nh
      del = max(delta, 1.0e-12_wp)
      f = -mu*fn*dtan/sqrt(dot_product(dtan, dtan) + del*del)
      rm = c
      ts = cross(rc, f)
      tm = cross(rm, f)
      work = dot_product(f, d)
   end subroutine friction

   !> U(g) = eps/2 <-g>^2
   pure real(wp) function upen(eps, g)
      real(wp), intent(in) :: eps, g
      upen = 0.5_wp*eps*min(g, 0.0_wp)**2
   end function upen

   !> The discrete derivative (U(g1) - U(g0))/(g1 - g0) of U(g) = eps/2 <-g>^2 in closed form
   !> for each sign case, so no difference quotient is formed: both gaps closed, it is
   !> eps (g0 + g1)/2 (the midpoint derivative, exact for a quadratic); one closed, eps/2
   !> times the closed gap squared over (g1 - g0), whose magnitude is at least that gap.
   !> The quotient (u1 - u0)/(g1 - g0) lost up to |g|/|g1 - g0| of its digits near the
   !> turning point of a bounce, which left Newton stagnating at 1e-13 instead of 1e-16
   !> (Armero & Petocz 1998, CMAME 158:269-300: the discrete gradient; its value is
   !> unchanged, only its rounding).
   pure real(wp) function discrete_gradient(eps, g0, g1) result(ub)
      real(wp), intent(in) :: eps, g0, g1
      if (g0 <= 0.0_wp .and. g1 <= 0.0_wp) then
         ub = 0.5_wp*eps*(g0 + g1)
      else if (g1 < 0.0_wp) then
         ub = 0.5_wp*eps*g1*(g1/(g1 - g0))
      else if (g0 < 0.0_wp) then
         ub = 0.5_wp*eps*g0*(g0/(g0 - g1))
      else
         ub = 0.0_wp
      end if
   end function discrete_gradient

   !> Gap at n and n+1, normal nu and master point P (body frame of mb) of a pair, for the
   !> kinematics k. inside: P lies inside the facet polygon (facet pairs).
   subroutine pair_geometry(es, k, p, g0, g1, nu, xp, rsm, rmm, inside)
      type(emc_system_t), intent(in) :: es
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), intent(in) :: p
      real(wp), intent(out) :: g0, g1, nu(3), xp(3), rsm(3), rmm(3)
      logical, intent(out) :: inside
      real(wp) :: xs0(3), xs1(3), xsm(3), n0(3), n1(3), u(3), q(3), alpha, pn0(3), pn1(3), &
                  d0(3), d1(3), den, e(3), c(3), sgn
      integer :: j, jn, np
      associate (ks => k(p%sb), km => k(p%mb))
         ! positions relative to the master's centre at t(n) (xs0, pn0, xsm) and increments
         ! over the step (xs1, pn1 hold x(n+1) - x(n))
         rsm = matmul(ks%a, p%s)
         xs0 = rel0(ks, km) + matmul(ks%r0, p%s)
         xs1 = ks%dxc + matmul(ks%dr, p%s)
         xsm = relm(ks, km) + rsm
         inside = .true.
         select case (p%kind)
         case (PAIR_FACET)
            associate (f => es%facets(p%facet))
               n0 = matmul(km%r0, f%n)
               n1 = matmul(km%r1, f%n)
               nu = 0.5_wp*(n0 + n1)
               u = matmul(km%ainv, xsm)
               q = matmul(km%ainv, nu)
               alpha = (dot_product(f%n, u) - dot_product(f%n, f%c))/dot_product(f%n, q)
               xp = u - alpha*q
               pn0 = matmul(km%r0, xp)
               pn1 = km%dxc + matmul(km%dr, xp)
               rmm = matmul(km%a, xp)
               g0 = dot_product(n0, xs0 - pn0) - p%rs
               if (p%carried) g0 = p%g0c
               g1 = g0 + dot_product(nu, xs1 - pn1)
               np = f%np
               do j = 1, np
                  jn = mod(j, np) + 1
                  e = f%p(:, jn) - f%p(:, j)
                  c = cross(e, xp - f%p(:, j))
                  if (dot_product(c, f%n) < -1.0e-12_wp*dot_product(e, e)) inside = .false.
               end do
            end associate
         case default
            associate (sm => es%sphere(p%mb))
               xp = sm%c
               pn0 = matmul(km%r0, xp)
               pn1 = km%dxc + matmul(km%dr, xp)
               rmm = matmul(km%a, xp)
               d0 = xs0 - pn0
               d1 = d0 + (xs1 - pn1)
               den = norm2(d0) + norm2(d1)
               sgn = 1.0_wp
               if (p%kind == PAIR_SPHERE_IN) sgn = -1.0_wp
               if (den > 0.0_wp) then
                  nu = sgn*(d0 + d1)/den
               else
                  nu = 0.0_wp
               end if
               if (p%kind == PAIR_SPHERE_IN) then
                  g0 = sm%r - p%rs - norm2(d0)
               else
                  g0 = norm2(d0) - p%rs - sm%r
               end if
               if (p%carried) g0 = p%g0c
               g1 = g0 + dot_product(nu, xs1 - pn1)
            end associate
         end select
      end associate
   end subroutine pair_geometry

   !> The candidate pairs of the step for the kinematics k: every slave point of every
   !> definition against the master facets it projects into (one facet per plane) or the
   !> master sphere, kept when g(n) or g(n+1) < 0 and g(n) > -dpen (not through the body).
   !> MPI (dx_par_emc): each rank searches its own slave points; the pairs are gathered in
   !> the serial order (by slave point; a point's pairs are found by one rank, in order).
   subroutine emc_select_pairs(es, k, pairs, npair, sp)
      type(emc_system_t), intent(in) :: es
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), allocatable, intent(inout) :: pairs(:)
      integer, intent(out) :: npair
      class(emc_split_t), intent(inout), optional :: sp   !< MPI: the rank's slave points
      integer :: id, sb, mb, i, i1, i2, f, q, nsp
      real(wp) :: g0, g1, nu(3), xp(3), rsm(3), rmm(3), dpen, xb(3), xb1(3), trav
      logical :: inside, dup, split
      type(emc_pair_t) :: p
      if (.not. allocated(pairs)) allocate(pairs(16))
      npair = 0
      split = .false.
      if (present(sp)) split = sp%on
      do id = 1, size(es%defs)
         sb = es%defs(id)%sb
         mb = es%defs(id)%mb
         if (es%sphere(sb)%r > 0.0_wp .and. es%sphere(sb)%side == 0) then
            i1 = 0; i2 = 0       ! the slave's sphere centre only
         else
            i1 = es%sn_ptr(sb); i2 = es%sn_ptr(sb + 1) - 1
         end if
         do i = i1, i2
            if (split) then
               if (.not. sp%is_mine(es, id, i)) cycle
            end if
            p%def = id; p%sb = sb; p%mb = mb; p%src = i
            if (i == 0) then
               p%s = es%sphere(sb)%c; p%rs = es%sphere(sb)%r
            else
               p%s = es%snodes(:, i); p%rs = 0.0_wp
            end if
            if (es%sphere(mb)%r > 0.0_wp) then
               p%kind = PAIR_SPHERE_OUT
               if (es%sphere(mb)%side == 1) p%kind = PAIR_SPHERE_IN
               p%facet = 0
               call pair_geometry(es, k, p, g0, g1, nu, xp, rsm, rmm, inside)
               dpen = 0.5_wp*es%sphere(mb)%r
               if (min(g0, g1) < 0.0_wp .and. g0 > -dpen) call push(p)
               cycle
            end if
            nsp = npair
            ! cheap filter in the master's frame at t(n): distance to the facet plane and to
            ! its centroid, against the travel over the step
            xb = matmul(transpose(k(mb)%r0), rel0(k(sb), k(mb)) + matmul(k(sb)%r0, p%s))
            xb1 = matmul(transpose(k(mb)%r1), rel0(k(sb), k(mb)) + (k(sb)%dxc - k(mb)%dxc) + &
                         matmul(k(sb)%r1, p%s))
            trav = norm2(xb1 - xb)
            do f = es%fac_ptr(mb), es%fac_ptr(mb + 1) - 1
               associate (fc => es%facets(f))
                  if (dot_product(fc%n, xb - fc%c) - p%rs > trav + 1.0e-9_wp*fc%rad) cycle
                  if (norm2(xb - fc%c) > 2.0_wp*fc%rad + p%rs + trav) cycle
               end associate
               p%kind = PAIR_FACET
               p%facet = f
               call pair_geometry(es, k, p, g0, g1, nu, xp, rsm, rmm, inside)
               if (.not. inside) cycle
               dpen = facet_depth(es, f)
               ! a point that only touches the plane (|g| at round-off of the facet size, e.g.
               ! a corner sliding along a coplanar side face) is no contact: as a Lagrange
               ! pair it made the Newton matrix singular (bars at 1e3 m/s)
               if (.not. (min(g0, g1) < -1.0e-12_wp*fc_rad(es, f) .and. g0 > -dpen)) cycle
               p%g0 = g0
               dup = .false.
               do q = nsp + 1, npair
                  if (emc_same_plane(es, pairs(q)%facet, f)) dup = .true.
               end do
               if (.not. dup) call push(p)
            end do
         end do
      end do
      if (split) call gather_pairs(es, pairs, npair, sp)
   contains
      subroutine push(pp)
         type(emc_pair_t), intent(in) :: pp
         type(emc_pair_t), allocatable :: t(:)
         if (npair == size(pairs)) then
            allocate(t(2*npair))
            t(1:npair) = pairs(1:npair)
            call move_alloc(t, pairs)
         end if
         npair = npair + 1
         pairs(npair) = pp
      end subroutine push
   end subroutine emc_select_pairs

   !> Tunnelling over the accepted step with kinematics k and pairs(1:npair) (module
   !> header): the first slave point (definition id, slave index src into es%snodes, 0: a
   !> sphere centre) that crossed a master facet (facet > 0) or went through a master
   !> sphere (facet = 0) with no pair; id = 0 when none did. Every rank holds all the
   !> pairs (MPI), so every rank finds the same point.
   subroutine emc_find_tunnel(es, k, pairs, npair, id, src, facet)
      type(emc_system_t), intent(in) :: es
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), intent(in) :: pairs(:)
      integer, intent(in) :: npair
      integer, intent(out) :: id, src, facet
      integer :: jd, sb, mb, i, i1, i2, f, j, jn, q
      real(wp) :: s(3), rs, xb(3), xb1(3), trav, d0, d1, xq(3), e(3), c(3), sd, tq, dm
      logical :: inside, paired
      id = 0; src = 0; facet = 0
      do jd = 1, size(es%defs)
         sb = es%defs(jd)%sb
         mb = es%defs(jd)%mb
         if (es%sphere(mb)%r > 0.0_wp .and. es%sphere(mb)%side /= 0) cycle  ! inner side
         if (es%sphere(sb)%r > 0.0_wp .and. es%sphere(sb)%side == 0) then
            i1 = 0; i2 = 0
         else
            i1 = es%sn_ptr(sb); i2 = es%sn_ptr(sb + 1) - 1
         end if
         do i = i1, i2
            if (i == 0) then
               s = es%sphere(sb)%c; rs = es%sphere(sb)%r
            else
               s = es%snodes(:, i); rs = 0.0_wp
            end if
            ! the slave point in the master's body frame at t(n) and t(n+1)
            xb = matmul(transpose(k(mb)%r0), rel0(k(sb), k(mb)) + matmul(k(sb)%r0, s))
            xb1 = matmul(transpose(k(mb)%r1), rel0(k(sb), k(mb)) + (k(sb)%dxc - k(mb)%dxc) + &
                         matmul(k(sb)%r1, s))
            trav = norm2(xb1 - xb)
            if (es%sphere(mb)%r > 0.0_wp) then
               associate (sm => es%sphere(mb))
                  d0 = norm2(xb - sm%c) - rs - sm%r
                  d1 = norm2(xb1 - sm%c) - rs - sm%r
                  if (d0 < 0.0_wp .or. d1 < 0.0_wp .or. trav == 0.0_wp) cycle
                  tq = dot_product(sm%c - xb, xb1 - xb)/(trav*trav)
                  if (tq <= 0.0_wp .or. tq >= 1.0_wp) cycle
                  dm = norm2(xb + tq*(xb1 - xb) - sm%c) - rs - sm%r
                  if (dm >= 0.0_wp) cycle
               end associate
               paired = .false.
               do q = 1, npair
                  if (pairs(q)%def == jd .and. pairs(q)%src == i) paired = .true.
               end do
               if (.not. paired) then
                  id = jd; src = i; facet = 0; return
               end if
               cycle
            end if
            do f = es%fac_ptr(mb), es%fac_ptr(mb + 1) - 1
               associate (fc => es%facets(f))
                  d0 = dot_product(fc%n, xb - fc%c) - rs
                  d1 = dot_product(fc%n, xb1 - fc%c) - rs
                  ! from the outer side to deeper behind the plane than a new pair is ever
                  ! taken (facet_depth, half the smallest edge): not a graze at an edge, where
                  ! the mid configuration projects into a neighbour facet and the next step
                  ! takes the contact
                  if (.not. (d0 >= 0.0_wp .and. d1 < -facet_depth(es, f))) cycle
                  ! where the path meets the facet plane, and whether that is on the facet
                  sd = d0/(d0 - d1)
                  xq = xb + sd*(xb1 - xb)
                  inside = .true.
                  do j = 1, fc%np
                     jn = mod(j, fc%np) + 1
                     e = fc%p(:, jn) - fc%p(:, j)
                     c = cross(e, xq - fc%p(:, j))
                     if (dot_product(c, fc%n) < -1.0e-12_wp*dot_product(e, e)) inside = .false.
                  end do
                  if (.not. inside) cycle
               end associate
               ! any pair of the point with this master is contact (near an edge the mid
               ! configuration may project into the neighbour facet of the one crossed)
               paired = .false.
               do q = 1, npair
                  if (pairs(q)%def == jd .and. pairs(q)%src == i) paired = .true.
               end do
               if (.not. paired) then
                  id = jd; src = i; facet = f; return
               end if
            end do
         end do
      end do
   end subroutine emc_find_tunnel

   pure real(wp) function fc_rad(es, f)
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: f
      fc_rad = es%facets(f)%rad
   end function fc_rad

   !> how deep a slave point may be behind a facet and still count as penetrating it:
   !> half the facet's smallest edge
   pure real(wp) function facet_depth(es, f) result(d)
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: f
      integer :: j
      d = huge(1.0_wp)
      associate (fc => es%facets(f))
         do j = 1, fc%np
            d = min(d, norm2(fc%p(:, mod(j, fc%np) + 1) - fc%p(:, j)))
         end do
      end associate
      d = 0.5_wp*d
   end function facet_depth

   !> facets f1 and f2 lie in one plane (with the same outward normal)
   pure logical function emc_same_plane(es, f1, f2) result(same_plane)
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: f1, f2
      real(wp) :: l
      associate (a => es%facets(f1), b => es%facets(f2))
         l = norm2(a%p(:, 1) - a%p(:, 2))
         same_plane = dot_product(a%n, b%n) > 1.0_wp - 1.0e-10_wp .and. &
                      abs(dot_product(a%n, a%c) - dot_product(b%n, b%c)) < 1.0e-9_wp*l
      end associate
   end function emc_same_plane

   !> MPI: every rank's pairs (pairs(1:npair)) into the full list in serial order, on every
   !> rank. Each pair travels as EMC_PAIR_NI integers (exact as reals) and EMC_PAIR_NR reals,
   !> keyed by its slave point's serial position.
   subroutine gather_pairs(es, pairs, npair, sp)
      type(emc_system_t), intent(in) :: es
      type(emc_pair_t), allocatable, intent(inout) :: pairs(:)
      integer, intent(inout) :: npair
      class(emc_split_t), intent(inout) :: sp
      integer, allocatable :: ai(:, :), keys(:), akeys(:)
      real(wp), allocatable :: ar(:, :), v(:, :), av(:, :)
      integer :: i, n
      call emc_pairs_pack(pairs(1:npair), ai, ar)
      allocate(keys(npair), v(EMC_PAIR_NI + EMC_PAIR_NR, npair))
      do i = 1, npair
         keys(i) = sp%slot(es, pairs(i)%def, pairs(i)%src)
         v(1:EMC_PAIR_NI, i) = real(ai(:, i), wp)
         v(EMC_PAIR_NI + 1:, i) = ar(:, i)
      end do
      call sp%gather(keys, v, akeys, av)
      n = size(akeys)
      deallocate(ai, ar)
      allocate(ai(EMC_PAIR_NI, n), ar(EMC_PAIR_NR, n))
      ai = nint(av(1:EMC_PAIR_NI, :))
      ar = av(EMC_PAIR_NI + 1:, :)
      call emc_pairs_unpack(ai, ar, pairs)
      npair = n
      if (n == 0) then
         deallocate(pairs)
         allocate(pairs(16))
      end if
   end subroutine gather_pairs

   !> Resultant force F and spatial torque T about each body's mid centre from the pairs
   !> (kinematics k); stores g0, g1 and the discrete derivative in the pairs; upen1 = sum
   !> U(g(n+1)), upen0 = sum U(g(n)). Two passes: each pair's contribution (rec), then the
   !> sums in pair order. MPI (unless local): a rank evaluates the pairs of its slave points
   !> and the contributions are gathered by pair index before the sums.
   subroutine emc_contact_forces(es, k, pairs, npair, fo, to, upen0, upen1, dissip, local, sp)
      type(emc_system_t), intent(in) :: es
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), intent(inout) :: pairs(:)
      integer, intent(in) :: npair
      real(wp), intent(out) :: fo(:, :), to(:, :), upen0, upen1
      real(wp), intent(out), optional :: dissip   !< energy the dissipation takes this step
      logical, intent(in), optional :: local      !< MPI: every rank evaluates every pair
      class(emc_split_t), intent(inout), optional :: sp   !< MPI: the rank's slave points
      integer :: ip, n
      real(wp) :: dis, rec(NREC, npair)
      real(wp), allocatable :: v(:, :), av(:, :)
      integer, allocatable :: keys(:), akeys(:)
      logical :: split, fric
      split = .false.
      if (present(sp)) split = sp%on
      if (present(local)) split = split .and. .not. local
      split = split .and. npair > 0     ! (every rank knows npair: nothing to gather)
      if (split) then
         n = 0
         do ip = 1, npair
            if (sp%is_mine(es, pairs(ip)%def, pairs(ip)%src)) n = n + 1
         end do
         allocate(keys(n), v(NREC, n))
         n = 0
         do ip = 1, npair
            if (.not. sp%is_mine(es, pairs(ip)%def, pairs(ip)%src)) cycle
            n = n + 1
            keys(n) = ip
            call pair_contribution(es, k, pairs(ip), v(:, n))
         end do
         call sp%gather(keys, v, akeys, av)
         rec(:, akeys) = av
      else
         do ip = 1, npair
            call pair_contribution(es, k, pairs(ip), rec(:, ip))
         end do
      end if
      fo = 0.0_wp
      to = 0.0_wp
      upen0 = 0.0_wp
      upen1 = 0.0_wp
      dis = 0.0_wp
      do ip = 1, npair
         associate (p => pairs(ip), r => rec(:, ip))
            p%g0 = r(22); p%g1 = r(23); p%ubar = r(24); p%n1 = r(25:27); p%dfr = r(28)
            upen0 = upen0 + r(19)
            upen1 = upen1 + r(20)
            if (p%il == 0 .and. es%chi > 0.0_wp) dis = dis + r(21)
            fo(:, p%sb) = fo(:, p%sb) + r(1:3)
            to(:, p%sb) = to(:, p%sb) + r(4:6)
            fo(:, p%mb) = fo(:, p%mb) - r(1:3)
            to(:, p%mb) = to(:, p%mb) - r(7:9)
            fric = es%defs(p%def)%fs > 0.0_wp .and. p%ubar < 0.0_wp
            if (fric) then
               fo(:, p%sb) = fo(:, p%sb) + r(10:12)
               to(:, p%sb) = to(:, p%sb) + r(13:15)
               fo(:, p%mb) = fo(:, p%mb) - r(10:12)
               to(:, p%mb) = to(:, p%mb) - r(16:18)
            end if
         end associate
      end do
      if (present(dissip)) dissip = dis
   end subroutine emc_contact_forces

   !> One pair's contribution (NREC reals): normal force on the slave and the torques of
   !> slave and master (1:9), the friction force and torques (10:18), U(g(n)), U(g(n+1)), the
   !> dissipated energy (19:21), then g0, g1, the discrete derivative, n1, the friction work
   !> (22:28) that the pair keeps.
   subroutine pair_contribution(es, k, p, r)
      type(emc_system_t), intent(in) :: es
      type(emc_kin_t), intent(in) :: k(:)
      type(emc_pair_t), intent(in) :: p
      real(wp), intent(out) :: r(NREC)
      real(wp) :: g0, g1, nu(3), xp(3), rsm(3), rmm(3), eps, ub, f(3), u0, u1, ubd, dfr
      logical :: inside
      call pair_geometry(es, k, p, g0, g1, nu, xp, rsm, rmm, inside)
      r = 0.0_wp
      eps = es%defs(p%def)%eps
      u0 = upen(eps, g0)
      u1 = upen(eps, g1)
      if (p%il > 0) then
         ! Lagrange multiplier: f = lam nu, no stored energy (constraint g1 = g0)
         u0 = 0.0_wp; u1 = 0.0_wp
         ub = -p%lam
      else
         ub = discrete_gradient(eps, g0, g1)
         ! algorithmic dissipation (HHT/Newmark parameters, rho_inf < 1): a force
         ! chi eps (<g1> - <g0>) against the change of the penetration; it does the
         ! work -chi eps (<g1> - <g0>)(g1 - g0) <= 0 along nu, so momenta stay exact.
         ! Clamped so that the pair never pulls (that part dissipates too).
         if (es%chi > 0.0_wp) then
            ubd = min(ub + es%chi*eps*(min(g1, 0.0_wp) - min(g0, 0.0_wp)), 0.0_wp)
            r(21) = (ubd - ub)*(g1 - g0)
            ub = ubd
         end if
      end if
      r(22) = g0; r(23) = g1; r(24) = ub
      if (p%kind == PAIR_FACET) r(25:27) = matmul(k(p%mb)%r1, es%facets(p%facet)%n)
      r(19) = u0
      r(20) = u1
      f = -ub*nu
      r(1:3) = f
      r(4:6) = cross(rsm, f)
      r(7:9) = cross(rmm, f)
      dfr = p%dfr
      if (es%defs(p%def)%fs > 0.0_wp .and. ub < 0.0_wp) &
         call friction(es%defs(p%def)%fs, es%defs(p%def)%dfric, -ub*norm2(nu), nu, &
                       k(p%sb), k(p%mb), rsm - p%rs*nu/max(norm2(nu), tiny(1.0_wp)), &
                       r(10:12), r(13:15), r(16:18), dfr)
      r(28) = dfr
   end subroutine pair_contribution

   !> The slave points of definition id: i1..i2 index es%snodes (0..0: the sphere's centre).
   pure subroutine emc_slot_range(es, id, i1, i2)
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: id
      integer, intent(out) :: i1, i2
      integer :: sb
      sb = es%defs(id)%sb
      if (es%sphere(sb)%r > 0.0_wp .and. es%sphere(sb)%side == 0) then
         i1 = 0; i2 = 0
      else
         i1 = es%sn_ptr(sb); i2 = es%sn_ptr(sb + 1) - 1
      end if
   end subroutine emc_slot_range

   !> The serial position of slave point src of definition id (slots in serial loop order).
   integer function split_slot(self, es, id, src) result(s)
      class(emc_split_t), intent(in) :: self
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: id, src
      integer :: i1, i2
      call emc_slot_range(es, id, i1, i2)
      s = self%base(id) + (src - i1)
   end function split_slot

   !> This rank searches and evaluates slave point src of definition id (always when off).
   logical function split_mine(self, es, id, src)
      class(emc_split_t), intent(in) :: self
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: id, src
      split_mine = .true.
      if (self%on) split_mine = self%mine(self%slot(es, id, src))
   end function split_mine
end module dx_emc_contact
