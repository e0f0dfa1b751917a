!> Penalty node-to-segment contact forces, one pass (slave nodes against master segments).
!> Hallquist, Goudreau & Benson 1985, "Sliding interfaces with contact-impact in large-scale
!> Lagrangian computations", CMAME 51:107-137, and the DYNA3D/LS-DYNA Theory Manual
!> ("Standard penalty formulation", "Friction"):
!>  - closest-point projection of the slave node onto each candidate segment: Newton on the
!>    bilinear 4-node map (xi, eta), exact for 3-node segments; contact when the projection
!>    lies on the segment and the normal gap g = (x_s - x_c).n < 0 with |g| <= depth;
!>    among several, the least penetrated segment;
!>  - normal force f_n = -k g (k per segment, or the SOFT = 1 soft-constraint stiffness
!>    k = max(k, SOFSCL*0.5*m*/dt^2), m* = min(slave, master mass)), plus viscous damping
!>    VDC percent of critical, 2 sqrt(k m_eff); the total stays compressive;
!>  - Coulomb friction: trial elastic tangential force f_t* = f_t(old, rotated into the
!>    tangent plane) - k du_t, limited by mu f_n (and VC*A), mu = FSF*(FD + (FS - FD)
!>    exp(-DC |v_t|));
!>  - the slave node gets f, the master nodes -N_i(xi, eta) f (momentum is conserved).
!> Symbols: x_c the contact point, n the outward unit normal of the master segment,
!> N_i the segment shape functions.
!> Shells (p%shells): a shell segment is touched from either side: the normal is turned
!> towards the slave node and the contact surface lies p%soff off the mid-surface; a slave
!> node on a shell adds its own offset p%noff (Hallquist, LS-DYNA Theory Manual, "Contact
!> with shell thickness": g = |(x_s - x_c).n| - (t_s + t_m)/2); a shell slave node meets
!> segments facing either way (it has no outward side).
!> Split in two per slave node (pass_node: its result, pass_apply: added in, in slave-node
!> order) so that MPI runs compute the nodes on their strips and add the results in the
!> serial order (dx_par_contact).
module dx_contact_penalty
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_contact_types, only: contact_pass_t, contact_iface_t, NREC, REC_NEAR, REC_NB, &
                               REC_FSL, REC_GAP, REC_FT
   implicit none
   private
   public :: project_point, pass_forces, pass_records, pass_node, pass_apply

   real(wp), parameter :: tol_inside = 1.0e-6_wp   !< parametric tolerance on the segment edges
   real(wp), parameter :: xq(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
   real(wp), parameter :: eq(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]

contains

   !> Closest point of xs on segment xe(:, 1:nsn): shape functions nsh at it (clamped to the
   !> segment), the point xc, the unit normal (right-hand rule on the node order), the
   !> parametric coordinates and whether the projection lies on the segment.
   pure subroutine project_point(nsn, xe, xs, nsh, xc, nrm, xi, inside)
      integer, intent(in) :: nsn
      real(wp), intent(in) :: xe(3, 4), xs(3)
      real(wp), intent(out) :: nsh(4), xc(3), nrm(3), xi(2)
      logical, intent(out) :: inside
      real(wp) :: t1(3), t2(3), t12(3), r(3), g1, g2, h11, h12, h22, det, d1, d2, a, b, e(2)
      integer :: it, k
      nsh = 0.0_wp; xc = 0.0_wp; nrm = 0.0_wp; xi = 0.0_wp
      inside = .false.
      select case (nsn)
      case (4)
         t12 = 0.25_wp*(xe(:, 1) - xe(:, 2) + xe(:, 3) - xe(:, 4))
         do it = 1, 12
            call quad_geom(xe, xi, nsh, xc, t1, t2)
            r = xc - xs
            g1 = dot_product(r, t1); g2 = dot_product(r, t2)
            h11 = dot_product(t1, t1); h22 = dot_product(t2, t2)
            h12 = dot_product(t1, t2) + dot_product(r, t12)
            det = h11*h22 - h12*h12
            if (det <= 1.0e-12_wp*h11*h22) then
               h12 = dot_product(t1, t2)
               det = h11*h22 - h12*h12
               if (det <= 0.0_wp) return
            end if
            d1 = -(h22*g1 - h12*g2)/det
            d2 = -(h11*g2 - h12*g1)/det
            xi = max(-3.0_wp, min(3.0_wp, xi + [d1, d2]))
            if (abs(d1) + abs(d2) < 1.0e-12_wp) exit
         end do
         inside = all(abs(xi) <= 1.0_wp + tol_inside)
         e = max(-1.0_wp, min(1.0_wp, xi))
         call quad_geom(xe, e, nsh, xc, t1, t2)
         nrm = cross(t1, t2)
      case (3)
         t1 = xe(:, 2) - xe(:, 1)
         t2 = xe(:, 3) - xe(:, 1)
         r = xs - xe(:, 1)
         h11 = dot_product(t1, t1); h22 = dot_product(t2, t2); h12 = dot_product(t1, t2)
         det = h11*h22 - h12*h12
         if (det <= 0.0_wp) return
         g1 = dot_product(r, t1); g2 = dot_product(r, t2)
         a = (h22*g1 - h12*g2)/det
         b = (h11*g2 - h12*g1)/det
         xi = [a, b]
         inside = a >= -tol_inside .and. b >= -tol_inside .and. a + b <= 1.0_wp + tol_inside
         a = max(0.0_wp, a); b = max(0.0_wp, b)
         if (a + b > 1.0_wp) then
            a = a/(a + b); b = 1.0_wp - a
         end if
         nsh(1:3) = [1.0_wp - a - b, a, b]
         xc = 0.0_wp
         do k = 1, 3
            xc = xc + nsh(k)*xe(:, k)
         end do
         nrm = cross(t1, t2)
      case default
         return    ! 2-node (2D line) segments: not in 3D
      end select
      a = norm2(nrm)
      if (a > 0.0_wp) then
         nrm = nrm/a
      else
         inside = .false.
      end if
   end subroutine project_point

   !> Shells: the gap g = (x_s - x_c).n of a slave node to a segment becomes the gap to the
   !> contact surface: on a shell segment (soff > 0) the normal turned to the node's side and
   !> g = |g| - soff; a shell slave node's own offset noff subtracted (either segment).
   pure subroutine shell_gap(soff, noff, nrm, g)
      real(wp), intent(in) :: soff, noff
      real(wp), intent(inout) :: nrm(3), g
      if (soff > 0.0_wp) then
         if (g < 0.0_wp) then
            nrm = -nrm
            g = -g
         end if
         g = g - soff
      end if
      g = g - noff
   end subroutine shell_gap

   !> whether xs lies outside the box of the n points xe grown by d
   pure logical function outside_box(xe, n, xs, d) result(out)
      real(wp), intent(in) :: xe(3, 4), xs(3), d
      integer, intent(in) :: n
      integer :: a
      real(wp) :: lo, hi
      out = .true.
      do a = 1, 3
         lo = min(xe(a, 1), xe(a, 2), xe(a, 3), xe(a, n))
         hi = max(xe(a, 1), xe(a, 2), xe(a, 3), xe(a, n))
         if (xs(a) < lo - d .or. xs(a) > hi + d) return
      end do
      out = .false.
   end function outside_box

   pure subroutine quad_geom(xe, xi, nsh, xc, t1, t2)
      real(wp), intent(in) :: xe(3, 4), xi(2)
      real(wp), intent(out) :: nsh(4), xc(3), t1(3), t2(3)
      integer :: k
      xc = 0.0_wp; t1 = 0.0_wp; t2 = 0.0_wp
      do k = 1, 4
         nsh(k) = 0.25_wp*(1.0_wp + xq(k)*xi(1))*(1.0_wp + eq(k)*xi(2))
         xc = xc + nsh(k)*xe(:, k)
         t1 = t1 + 0.25_wp*xq(k)*(1.0_wp + eq(k)*xi(2))*xe(:, k)
         t2 = t2 + 0.25_wp*eq(k)*(1.0_wp + xq(k)*xi(1))*xe(:, k)
      end do
   end subroutine quad_geom

   !> Contact forces of pass p into fc; fsum: resultant on the slave nodes of the pass;
   !> krow: Gershgorin row sums of the contact stiffness, 2k on the slave node and 2k N_i on
   !> the master nodes (max krow/m bounds the contact frequency^2, for the time step);
   !> dt_old: the last step (tangential slip increment), dt_est: the step being taken;
   !> a node closer than gtol to a segment (not yet touching) also enters krow, so that the
   !> step is already small in the cycle its contact starts.
   !> Each slave node in turn: pass_node (its result) then pass_apply (added in).
   subroutine pass_forces(f, p, x, v, mass, dt_old, dt_est, gtol, fc, fsum, krow, nactive)
      type(contact_iface_t), intent(in) :: f
      type(contact_pass_t), intent(inout) :: p
      real(wp), intent(in) :: x(:, :), v(:, :), mass(:)
      real(wp), intent(in) :: dt_old, dt_est, gtol
      real(wp), intent(inout) :: fc(:, :), fsum(3), krow(:)
      integer, intent(inout) :: nactive
      integer :: i
      call pass_records(p)
      do i = 1, p%nnode
         call pass_node(f, p, i, x, v, mass, dt_old, dt_est, gtol)
         call pass_apply(p, i, fc, fsum, krow, nactive)
      end do
   end subroutine pass_forces

   !> Allocate the per-node result arrays of pass p (once).
   subroutine pass_records(p)
      type(contact_pass_t), intent(inout) :: p
      if (allocated(p%rint)) return
      allocate(p%rint(2, p%nnode), p%rval(NREC, p%nnode))
      p%rint = 0
      p%rval = 0.0_wp
   end subroutine pass_records

   !> The result of slave node i of pass p at x, v (reads its state, writes none of it):
   !> p%rint(1, i) the segment it is near (within gtol, not touching; 0: none) with its
   !> shape functions, p%rint(2, i) the segment in contact (0: none) with the shape
   !> functions, the force on the slave node, the new gap and tangential force (p%rval,
   !> columns REC_*). pass_apply adds it in; MPI runs compute it on the node's strip.
   subroutine pass_node(f, p, i, x, v, mass, dt_old, dt_est, gtol)
      type(contact_iface_t), intent(in) :: f
      type(contact_pass_t), intent(inout) :: p
      integer, intent(in) :: i
      real(wp), intent(in) :: x(:, :), v(:, :), mass(:)
      real(wp), intent(in) :: dt_old, dt_est, gtol
      real(wp) :: xe(3, 4), nsh(4), xc(3), nrm(3), xi(2), g, gbest, nb(4), nrmb(3)
      real(wp) :: kk, fn, vrel(3), vn, vt(3), vtm, ms, mm, meff, mu, fy, ftr(3), fsl(3), fmag
      real(wp) :: inv_mm, dep
      integer :: k, c, s, sb, j, n
      logical :: inside, near, facing
      k = p%node(i)
      p%rint(:, i) = 0
      p%rval(:, i) = 0.0_wp
      if (allocated(p%nlive)) then   ! erosion: a node no living element holds
         if (.not. p%nlive(i)) return
      end if
      sb = 0
      gbest = -huge(1.0_wp)
      near = .false.
      ! (a slave node on a shell has no outward side: every facing test is off for it)
      facing = p%nsseg > 0
      if (p%shells) facing = facing .and. .not. p%noff(i) > 0.0_wp
      do c = p%cand_ptr(i), p%cand_ptr(i + 1) - 1
         s = p%cand(c)
         if (allocated(p%live)) then  ! erosion: a face that left, or a dormant one
            if (.not. p%live(s)) cycle
         end if
         n = p%nsn(s)
         xe(:, 1:n) = x(:, p%seg(1:n, s))
         dep = p%depth(s)
         if (p%shells) dep = dep + p%noff(i)
         ! cheap rejections before the projection: outside the segment's box grown by
         ! the depth, or facing away (normal at the centre)
         if (outside_box(xe, n, x(:, k), dep)) cycle
         if (facing) then
            if (n == 4) then
               nrm = cross(xe(:, 3) - xe(:, 1), xe(:, 4) - xe(:, 2))
            else
               nrm = cross(xe(:, 2) - xe(:, 1), xe(:, 3) - xe(:, 1))
            end if
            if (p%shells) then    ! a shell segment faces the node's side
               if (p%soff(s) > 0.0_wp .and. dot_product(x(:, k) - xe(:, 1), nrm) < 0.0_wp) &
                  nrm = -nrm
            end if
            if (dot_product(p%nnrm(:, i), nrm) >= 0.0_wp) cycle
         end if
         call project_point(n, xe, x(:, k), nsh, xc, nrm, xi, inside)
         if (.not. inside) cycle
         g = dot_product(x(:, k) - xc, nrm)
         if (p%shells) call shell_gap(p%soff(s), p%noff(i), nrm, g)
         ! only segments facing the node's own surface (rejects the side faces of a
         ! master edge the slave node lies on)
         if (facing) then
            if (dot_product(p%nnrm(:, i), nrm) >= 0.0_wp) cycle
         end if
         if (g >= 0.0_wp .and. g < gtol .and. .not. near) then
            near = .true.
            p%rint(1, i) = s
            p%rval(REC_NEAR + 1:REC_NEAR + n, i) = nsh(1:n)
         end if
         ! a node on the segment's plane up to round-off (an edge shared with the master
         ! body's side) is not penetrating it
         if (g >= -1.0e-8_wp*dep .or. -g > dep) cycle
         if (g > gbest) then
            gbest = g; sb = s; nb = nsh; nrmb = nrm
         end if
      end do
      ! a node in contact last cycle that now projects onto no segment (it sits over the
      ! kink of a master surface that has become concave) stays on its segment, at the
      ! clamped closest point: releasing and recapturing it would create energy
      if (sb == 0 .and. p%iseg(i) > 0) then
         s = p%iseg(i)
         n = p%nsn(s)
         xe(:, 1:n) = x(:, p%seg(1:n, s))
         call project_point(n, xe, x(:, k), nsh, xc, nrm, xi, inside)
         g = dot_product(x(:, k) - xc, nrm)
         dep = p%depth(s)
         if (p%shells) then
            call shell_gap(p%soff(s), p%noff(i), nrm, g)
            dep = dep + p%noff(i)
         end if
         if (g < -1.0e-8_wp*dep .and. -g <= dep .and. norm2(nrm) > 0.0_wp) then
            sb = s; gbest = g; nb = nsh; nrmb = nrm
         end if
      end if
      if (sb == 0) return
      n = p%nsn(sb)
      vrel = v(:, k)
      do j = 1, n
         vrel = vrel - nb(j)*v(:, p%seg(j, sb))
      end do
      vn = dot_product(vrel, nrmb)
      ! the penetration can only grow by what the node travelled in one step: a deeper
      ! first contact, or a jump onto another segment deeper than the last gap (a node
      ! coming round an edge already inside), is not taken, since its penalty force
      ! would inject energy
      dep = p%depth(sb)
      if (p%shells) dep = dep + p%noff(i)
      if (-gbest > -p%gap(i) + 2.0_wp*abs(vn)*dt_est + 0.02_wp*dep) return
      ! ---- stiffness and masses
      ms = mass(k)
      inv_mm = 0.0_wp
      mm = 0.0_wp
      do j = 1, n
         if (mass(p%seg(j, sb)) > 0.0_wp) inv_mm = inv_mm + nb(j)**2/mass(p%seg(j, sb))
         mm = mm + nb(j)*mass(p%seg(j, sb))
      end do
      kk = p%kseg(sb)
      if (f%soft == 1 .and. dt_est > 0.0_wp) &
         kk = max(kk, 0.5_wp*f%sofscl*min(ms, mm)/dt_est**2)
      fn = -kk*gbest
      if (f%vdc > 0.0_wp) then
         meff = 0.0_wp
         if (ms > 0.0_wp .and. inv_mm > 0.0_wp) meff = 1.0_wp/(1.0_wp/ms + inv_mm)
         fn = max(0.0_wp, fn - 0.01_wp*f%vdc*2.0_wp*sqrt(kk*meff)*vn)
      end if
      fsl = fn*nrmb
      ! ---- friction
      ftr = p%ft(:, i)
      if (f%fs > 0.0_wp) then
         vt = vrel - vn*nrmb
         vtm = norm2(vt)
         ftr = p%ft(:, i) - dot_product(p%ft(:, i), nrmb)*nrmb - kk*dt_old*vt
         mu = f%fsf*(f%fd + (f%fs - f%fd)*exp(-f%dc*vtm))
         fy = mu*fn
         if (f%vc > 0.0_wp) fy = min(fy, f%vsf*f%vc*p%area(sb))
         fmag = norm2(ftr)
         if (fmag > fy) ftr = ftr*(fy/fmag)
         fsl = fsl + ftr
      end if
      p%rint(2, i) = sb
      p%rval(REC_NB + 1:REC_NB + 4, i) = nb
      p%rval(REC_FSL + 1:REC_FSL + 3, i) = fsl
      p%rval(REC_GAP + 1, i) = gbest
      p%rval(REC_FT + 1:REC_FT + 3, i) = ftr
   end subroutine pass_node

   !> Add the result of slave node i (pass_node) in: its state (segment, gap, tangential
   !> force), the forces into fc (the slave node gets f, the master nodes -N_i f), the
   !> resultant fsum, the stiffness row sums krow (2k on the slave node, 2k N_i on the
   !> master nodes, for the near segment first, then for the contact segment) and the count
   !> of nodes in contact. The serial order of every sum is this call order: slave node
   !> after slave node, pass after pass.
   subroutine pass_apply(p, i, fc, fsum, krow, nactive)
      type(contact_pass_t), intent(inout) :: p
      integer, intent(in) :: i
      real(wp), intent(inout) :: fc(:, :), fsum(3), krow(:)
      integer, intent(inout) :: nactive
      real(wp) :: fsl(3), nb(4)
      integer :: k, s, sb, j, n
      k = p%node(i)
      s = p%rint(1, i)
      if (s > 0) then
         krow(k) = krow(k) + 2.0_wp*p%kseg(s)
         do j = 1, p%nsn(s)
            krow(p%seg(j, s)) = krow(p%seg(j, s)) + 2.0_wp*p%kseg(s)*p%rval(REC_NEAR + j, i)
         end do
      end if
      sb = p%rint(2, i)
      if (sb == 0) then
         p%iseg(i) = 0
         p%gap(i) = 0.0_wp
         p%ft(:, i) = 0.0_wp
         return
      end if
      n = p%nsn(sb)
      p%gap(i) = p%rval(REC_GAP + 1, i)
      nactive = nactive + 1
      p%iseg(i) = sb
      p%ft(:, i) = p%rval(REC_FT + 1:REC_FT + 3, i)
      fsl = p%rval(REC_FSL + 1:REC_FSL + 3, i)
      nb = p%rval(REC_NB + 1:REC_NB + 4, i)
      fc(:, k) = fc(:, k) + fsl
      do j = 1, n
         fc(:, p%seg(j, sb)) = fc(:, p%seg(j, sb)) - nb(j)*fsl
      end do
      fsum = fsum + fsl
      ! the time step sees the segment stiffness only: the SOFT = 1 stiffness is scaled
      ! to the step itself (w dt fixed by SOFSCL), feeding it back would shrink the step
      krow(k) = krow(k) + 2.0_wp*p%kseg(sb)
      do j = 1, n
         krow(p%seg(j, sb)) = krow(p%seg(j, sb)) + 2.0_wp*p%kseg(sb)*nb(j)
      end do
   end subroutine pass_apply
end module dx_contact_penalty
