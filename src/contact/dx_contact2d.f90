!> 2D penalty contact between the free edges of two part sets (*CONTACT_2D_AUTOMATIC_SURFACE_
!> TO_SURFACE), DYNA2D's node-on-segment slideline in its symmetric penalty form (Hallquist,
!> Goudreau & Benson 1985, Sliding interfaces with contact-impact in large-scale Lagrangian
!> computations, CMAME 51: 107-137): each pass puts the slave nodes of one side against the
!> master edges of the other. A slave node s is in contact with edge a -> b (outward normal n =
!> (dy, -dx)/L) when its projection xi = (x_s - x_a).t/L is in [-XTOL, 1 + XTOL] (a node at the
!> end of an edge of an aligned mesh stays in contact as it moves by round-off), its gap g =
!> (x_s - x_a).n lies in (-L/2, 0), and the edge faces the slave surface (n . n_s < 0, n_s the
!> sum of the outward normals of the slave node's edges: a corner node is not pushed out
!> through the side it slid past); of several such edges the least penetrated. Normal force
!> k |g| n on s, minus its shares (1 - xi, xi) on a, b (xi clamped to [0, 1]; momentum is
!> conserved exactly), k = SFACT x 0.1 x K L**2/A of the master edge's element (LS-DYNA's
!> solid penalty SLSFAC K A**2/V in 2D, per unit thickness; per radian in axisymmetry: times
!> r_m**2/rbar, r_m the edge's midpoint radius, rbar = V/A the element's); with card 3's ISTIFF
!> = 1 (the manual's scaling from the segment masses and the explicit step) instead the soft-constraint stiffness of LS-DYNA's SOFT = 1 (LS-DYNA Theory Manual,
!> "Soft constraint penalty formulation"): k = 0.5 SOFSCL m*/dt**2, SOFSCL = 0.1 SFACT, m* the
!> smaller of the slave's mass and the edge point's 1/((1 - xi)**2/m_a + xi**2/m_b) (so
!> omega dt <= sqrt(2 SOFSCL) per pass, whatever the two meshes' masses), dt the elements'
!> stable step times TSSFAC, updated when it has moved by 5 % (the Taylor mirror's crushed
!> foot needs k to follow the shrinking step; cycle-to-cycle changes of k are not
!> conservative); it does not lower the step (it is scaled to it). Coulomb friction:
!> f_t = -min(FS |f_n|, m_s |v_t|/(2 dt)) along the relative sliding velocity v_t, the second
!> the force that stops the slave's sliding in one step when both passes hold the pair
!> (sticking). Positions x(n), velocities v(n-1/2). The critical step takes each contact
!> pair's spring bound 2/omega (as the 3D penalty contact, dx_contact). Every slave node
!> against the master edges of its cell of a grid rebuilt each cycle (dx_contact2d_bins:
!> the same edges in the same order as the all-pairs search, so the same results). MPI
!> runs: dx_par_contact2d runs this pass on a replicated table of the contact nodes (compact
!> numbering in the serial order), so the results are the serial ones.
!> Single surface (*CONTACT_2D_AUTOMATIC_SINGLE_SURFACE): one pass, every node of the free
!> edges of the part set against every one of those edges but its own two; the facing test
!> and the gap window (-L/2, 0) keep a node off its neighbouring edges round a convex
!> corner (the nodes there lie behind the edge's line, or face along it).
!> Tied (*CONTACT_2D_AUTOMATIC_TIED, _TIED_ONE_WAY; LS-DYNA Theory Manual, "Tied interfaces",
!> in its penalty form, TIETYP = 1): the slave nodes within TIEDGAP of a master edge at t = 0
!> are projected once (dx_build_twod tie_project) and held to that point of the edge and
!> their offset by a spring SFACT x K L**2/A (ten times the contact's), in tension and
!> compression and along the edge; both sides' nodes (TIED) or SIDS's (ONE_WAY).
module dx_contact2d
   use dx_kinds, only: wp
   use dx_contact2d_types, only: contact2d_t, c2d_pass_t
   use dx_contact2d_bins, only: c2d_bins_t, bins_build, bins_range
   implicit none
   private
   public :: contact2d_forces

   !> the edges are extended by XTOL of their length at both ends, so a node at an edge's
   !> end (aligned meshes) does not lose and regain contact as round-off moves it past
   real(wp), parameter :: XTOL = 0.1_wp
   !> an edge faces a slave node when their normals make more than acos(-NFACE) = 102 deg
   !> (a node of a flat surface is not caught by the side of a block sliding over it)
   real(wp), parameter :: NFACE = 0.2_wp
   !> relative change of the step that updates the soft constraint's stiffness (ISTIFF 1)
   real(wp), parameter :: DTHYS = 0.05_wp

contains

   !> The contact forces of t(n) into c%fc and f(1:2, :); the work of the last cycle's forces
   !> into c%work (fold . (vold + v)/2 dtavg, dtavg = the mean of the last two dt_old)
   subroutine contact2d_forces(c, x, v, mass, dt_old, tssfac, f, dtcrit)
      type(contact2d_t), intent(inout) :: c
      real(wp), intent(in) :: x(:, :), v(:, :), mass(:), dt_old, tssfac
      real(wp), intent(inout) :: f(:, :), dtcrit
      integer :: i, p, k, j, s, a, b, jbest, n, j1, j2, jj
      logical :: single
      type(c2d_bins_t) :: bn
      real(wp) :: d(2), t(2), nv(2), el, xi, g, gbest, xib, fn(2), vt, ft, vrel(2), w2, kk, &
                  dts, me, dte
      real(wp), allocatable :: ns(:, :)
      n = size(x, 2)
      dte = dtcrit                    ! (the elements' step, for the ties' bound)
      ! the step of the soft-constraint stiffness (cycle 0: the coming one) follows the
      ! step when it has moved by more than DTHYS: a k following each cycle's small changes
      ! is not conservative (the step dips while the faces are pressed: 3e-3 of the energy
      ! lost in contact2d_blocks_soft, 2e-4 with DTHYS), a k frozen at the first step too
      ! soft once the elements at the contact are crushed (the Taylor mirror's faces
      ! overlap 0.10 mm at SOFSCL 0.3, 0.04 mm with DTHYS)
      if (abs(tssfac*dtcrit - c%dtsoft) > DTHYS*c%dtsoft) c%dtsoft = tssfac*dtcrit
      dts = c%dtsoft
      if (.not. allocated(c%fc)) then
         allocate(c%fc(2, n), c%fold(2, n), c%vold(2, n))
         c%fc = 0.0_wp; c%fold = 0.0_wp; c%vold = v(1:2, :)
      end if
      ! work of the last cycle's contact forces over its step (v(n-3/2) -> v(n-1/2))
      do i = 1, n
         if (c%fold(1, i) /= 0.0_wp .or. c%fold(2, i) /= 0.0_wp) c%work = c%work + &
            dot_product(c%fold(:, i), 0.5_wp*(c%vold(:, i) + v(1:2, i)))* &
            (0.5_wp*(c%dtold + dt_old))
      end do
      c%fc = 0.0_wp
      c%ncontact = 0
      allocate(ns(2, n))
      do i = 1, size(c%iface)
         do p = 1, c%iface(i)%npass
            if (c%iface(i)%tied) then       ! (no search: the ties of t = 0)
               call tie_pass(c, c%iface(i)%pass(p), c%iface(i)%npass, x, mass, dte, dtcrit)
               cycle
            end if
            ! the slave side's nodal normals: its edges are the other pass's master edges
            ns = 0.0_wp
            associate (os => c%iface(i)%pass(3 - p))
               do j = 1, size(os%edge, 2)
                  a = os%edge(1, j); b = os%edge(2, j)
                  d = x(1:2, b) - x(1:2, a)
                  ns(:, a) = ns(:, a) + [d(2), -d(1)]
                  ns(:, b) = ns(:, b) + [d(2), -d(1)]
               end do
            end associate
            associate (ps => c%iface(i)%pass(p), fs => c%iface(i)%fs)
               call bins_build(bn, ps%edge, x)  ! (each node: the edges of its cell)
               single = allocated(ps%own)
               do k = 1, size(ps%node)
                  s = ps%node(k)
                  jbest = 0; gbest = -huge(1.0_wp); xib = 0.0_wp
                  call bins_range(bn, x(1:2, s), j1, j2)
                  do jj = j1, j2
                     j = bn%list(jj)
                     a = ps%edge(1, j); b = ps%edge(2, j)
                     if (s == a .or. s == b) cycle
                     ! single surface: not the far face of the node's own element (a part
                     ! thinner than half an edge would be pushed through itself)
                     if (single) then
                        if (any(ps%own(:, j) == s)) cycle
                     end if
                     d = x(1:2, b) - x(1:2, a)
                     el = norm2(d)
                     t = d/el
                     xi = dot_product(x(1:2, s) - x(1:2, a), t)/el
                     if (xi < -XTOL .or. xi > 1.0_wp + XTOL) cycle
                     g = dot_product(x(1:2, s) - x(1:2, a), [t(2), -t(1)])
                     if (g >= 0.0_wp .or. g <= -0.5_wp*el) cycle
                     if (dot_product(ns(:, s), [t(2), -t(1)]) > -NFACE*norm2(ns(:, s))) cycle
                     if (g > gbest) then
                        gbest = g; jbest = j; xib = min(max(xi, 0.0_wp), 1.0_wp)
                     end if
                  end do
                  if (jbest == 0) cycle
                  c%ncontact = c%ncontact + 1
                  a = ps%edge(1, jbest); b = ps%edge(2, jbest)
                  d = x(1:2, b) - x(1:2, a)
                  t = d/norm2(d)
                  nv = [t(2), -t(1)]
                  kk = ps%k(jbest)
                  if (c%iface(i)%istiff == 1) then
                     ! soft constraint: 0.5 SOFSCL m*/dt**2, m* = min(m_s, m_e), m_e the edge
                     ! point's mass 1/((1 - xi)**2/m_a + xi**2/m_b) (omega dt <= sqrt(2
                     ! SOFSCL) per pass, whatever the meshes' masses)
                     me = 1.0_wp/((1.0_wp - xib)**2/mass(a) + xib**2/mass(b))
                     kk = 0.5_wp*c%iface(i)%sofscl*min(mass(s), me)/dts**2
                  end if
                  fn = -kk*gbest*nv
                  if (fs > 0.0_wp) then          ! Coulomb, regularised (module header)
                     vrel = v(1:2, s) - ((1.0_wp - xib)*v(1:2, a) + xib*v(1:2, b))
                     vt = dot_product(vrel, t)
                     if (dt_old > 0.0_wp) then   ! (cycle 0: no step yet, the Coulomb bound)
                        ft = -sign(min(fs*norm2(fn), 0.5_wp*mass(s)*abs(vt)/dt_old), vt)
                     else
                        ft = -sign(fs*norm2(fn), vt)
                        if (vt == 0.0_wp) ft = 0.0_wp
                     end if
                     fn = fn + ft*t
                  end if
                  ! the step the contact spring allows: 2/omega, omega**2 = 2 k (1/m_s +
                  ! (1 - xi)**2/m_a + xi**2/m_b) (both passes may hold the pair); the soft
                  ! constraint is scaled to the step itself (fed back, it would shrink it)
                  if (c%iface(i)%istiff /= 1) then
                     w2 = 2.0_wp*kk*(1.0_wp/mass(s) + (1.0_wp - xib)**2/mass(a) + &
                                     xib**2/mass(b))
                     dtcrit = min(dtcrit, 2.0_wp/sqrt(w2))
                  end if
                  c%fc(:, s) = c%fc(:, s) + fn
                  c%fc(:, a) = c%fc(:, a) - (1.0_wp - xib)*fn
                  c%fc(:, b) = c%fc(:, b) - xib*fn
               end do
            end associate
         end do
      end do
      f(1:2, :) = f(1:2, :) + c%fc
      c%fold = c%fc
      c%vold = v(1:2, :)
      c%dtold = dt_old
   end subroutine contact2d_forces

   !> One pass of a tied interface: each tied slave node s is held by a spring k (the master
   !> edge's penalty) to its point xi of edge a -> b plus its t = 0 offset in the edge's
   !> turning frame; f = -k d on s, (1 - xi) k d and xi k d on a, b (momentum exact; the
   !> offset turns with the edge, so a rigid rotation leaves d = 0). The step: a tie is as
   !> stiff as the elements, so its node's frequency is the elements' and the tie's together:
   !> 1/dt**2 = 1/dte**2 + omega**2/4 (dte the elements' step, no larger than the tied
   !> nodes' own; omega**2 = npass k (1/m_s + (1 - xi)**2/m_a + xi**2/m_b): two-way ties
   !> hold a pair of coincident nodes twice). Alone, the bound 2/omega lets the bar of
   !> tiedbar (two-way ties on coincident nodes) blow up at cycle 28: the pair's mode is
   !> 2 k_e/m + 8 k/m.
   subroutine tie_pass(c, ps, npass, x, mass, dte, dtcrit)
      type(contact2d_t), intent(inout) :: c
      type(c2d_pass_t), intent(in) :: ps
      integer, intent(in) :: npass
      real(wp), intent(in) :: x(:, :), mass(:), dte
      real(wp), intent(inout) :: dtcrit
      integer :: k, j, s, a, b
      real(wp) :: t(2), nv(2), xi, dd(2), fn(2), w2
      do k = 1, size(ps%node)
         j = ps%tie_edge(k)
         if (j == 0) cycle
         s = ps%node(k); a = ps%edge(1, j); b = ps%edge(2, j)
         xi = ps%tie_xi(k)
         t = x(1:2, b) - x(1:2, a)
         t = t/norm2(t)
         nv = [t(2), -t(1)]
         dd = x(1:2, s) - ((1.0_wp - xi)*x(1:2, a) + xi*x(1:2, b)) - ps%tie_off(1, k)*t - &
              ps%tie_off(2, k)*nv
         fn = -ps%k(j)*dd
         w2 = real(npass, wp)*ps%k(j)*(1.0_wp/mass(s) + (1.0_wp - xi)**2/mass(a) + xi**2/mass(b))
         dtcrit = min(dtcrit, 1.0_wp/sqrt(1.0_wp/dte**2 + 0.25_wp*w2))
         c%ncontact = c%ncontact + 1
         c%fc(:, s) = c%fc(:, s) + fn
         c%fc(:, a) = c%fc(:, a) - (1.0_wp - xi)*fn
         c%fc(:, b) = c%fc(:, b) - xi*fn
      end do
   end subroutine tie_pass
end module dx_contact2d
