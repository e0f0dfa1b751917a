!> Implicit penalty contact with Coulomb friction (the NIKE3D slideline; issue 20): the
!> node-to-segment penalty of the explicit contact (the same passes, segments, penalty
!> stiffnesses k = SFS/SFM f K A^2/V and projection, dx_contact_penalty) as a term of the
!> Newton residual with its tangent. NIKE3D: Maker, Ferencz & Hallquist, UCRL-MA-105268
!> (1995), "Sliding interfaces"; the penalty node-to-segment tangent and the stick/slip
!> return after Wriggers, "Computational Contact Mechanics", 2nd ed. 2006, ch. 5.2 and 6.3
!> (Laursen & Simo's regularized Coulomb law, Int. J. Numer. Meth. Eng. 36 (1993) 3451-3485).
!> Per slave node (x_s) and its candidate segments (each slave node against the segments
!> whose box grown by the segment's size holds it: formed at the start from the undeformed
!> geometry and re-found after every converged step from the committed one, so a contact
!> may slide or close by up to about a segment's size per step), at the trial displacements u:
!>   contact point x_c = sum N_a x_a (closest-point projection), outward normal n,
!>   gap g = (x_s - x_c).n; the least penetrated segment with g < 0 (and -g <= depth) is
!>   the active one, normal force f_n = -k g;
!>   friction (FS > 0; mu = FS: statics has no sliding velocity, FD/DC are not used): the
!>   tangential relative displacement of the step du_t = (I - n n)(du_s - sum N_a du_a)
!>   (du from the committed state), trial force f_t* = P f_t(committed) - k du_t (P the
!>   projection on the tangent plane); stick if |f_t*| <= mu f_n, else slip f_t = mu f_n t,
!>   t = f_t*/|f_t*| (the return to the Coulomb cone);
!>   the slave node gets f = f_n n + f_t, the master nodes -N_a f (into f_int with the
!>   opposite sign: r = f_ext - f_int).
!> Tangent on the 15 dofs (slave, 4 master nodes), W = [I, -N_1 I, ..., -N_4 I]: the
!> consistent linearization of this residual (Wriggers 2006, ch. 4.3 and 6.3: the
!> variation of the projection xi and of the normal n with the geometry; Laursen & Simo 1993
!> for the slip tangent). With a_al = x_,al the segment's tangents, m = a_al.a_be its metric,
!> h = n.x_,al be its curvature (the bilinear quadrilateral's twist; 0 for a triangle),
!> D_al = [0, N_1,al I, ..., N_4,al I], T_al = W^T a_al and V_al = D_al^T n:
!>   dxi = (m - g h)^-1 (T + g V)^T du (the projection kept orthogonal),
!>   dn = -a^al (V_al^T + h_al be dxi_be) du (a^al = m^-1 a the dual tangents), dg = n^T W du,
!>   dW = -D_al dxi_al;
!>   K = k W^T n n^T W - f_n W^T dn + D_al^T f dxi_al - W^T df_t,
!> with df_t the linearized trial force G = -(n.v) dn - n (v^T dn) - k P dDU (v = f_t(c) - k du_t
!> before projection, dDU = W - D_al (u - u_c) dxi_al) in stick, and in slip
!> df_t = -mu k t n^T W + (mu f_n/|f_t*|)(I - t t^T) G. Frictionless, K is the Hessian of the
!> penalty energy k g^2/2 (symmetric, indefinite where g h is large); with friction it is
!> unsymmetric (mu k t n^T W and the geometric terms), so a deck with FS > 0 assembles every
!> entry and MUMPS factors it unsymmetric (SYM = 0). Newton then converges quadratically once
!> the active set and the stick/slip states settle (cases implicit_friction_block,
!> implicit_hertz_coarse: the iteration log's residual ratios).
!> Contact status changes between iterations are the residual's (the active set is found
!> anew at every evaluation); the count of active nodes and of changes is logged per step.
!> The sparse pattern holds one pseudo-element per candidate pair (dx_implicit_system).
module dx_implicit_contact
   use dx_kinds, only: wp
   use dx_vec3, only: cross
   use dx_model, only: model_t
   use dx_contact_penalty, only: project_point
   use dx_sparse, only: sparse_sym_t, sparse_add_element
   use dx_implicit_rigid, only: irigid_t, irig_add
   implicit none
   private
   public :: icontact_t, icon_pairs, icon_assemble, icon_commit, icon_pair_nodes

   integer, parameter :: NDE = 24      !< the pattern's element width (the hexahedron's)
   !> the quadrilateral segment's corners in (xi, eta) (dx_contact_penalty's quad_geom)
   !> penetration (relative to the segment's size) below which the tangent has the geometric
   !> terms: deeper (a load step's predictor, far from the solution) the penalty energy's
   !> Hessian is indefinite and Newton wandered (Hertz step 1 inverted an element with them
   !> always on); at the solution of a statics-stiff penalty (SFS >= 10) it is ~1e-3
   real(wp), parameter :: GEO_DEPTH = 0.01_wp
   !> a projection up to this parametric coordinate past a free edge counts as on the
   !> segment, clamped to the edge: LS-DYNA's MAXPAR default (*CONTACT optional card A; the
   !> field is not read yet). Without it a node on a symmetry plane pressed into a curved
   !> master surface projects just past the edge on the plane (onto the mirror image's
   !> segment) and drops out of contact every other iteration (SSNV104's poles cycled so);
   !> past every edge it made the Hertz case's nodes flip between neighbouring segments
   real(wp), parameter :: MAXPAR = 1.025_wp
   real(wp), parameter :: XQ(4) = [-1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]
   real(wp), parameter :: EQ(4) = [-1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp]

   type :: icontact_t
      integer :: np = 0                     !< candidate pairs (pseudo-elements)
      integer :: ns = 0                     !< slave entries (iface, pass, slave node)
      integer, allocatable :: sif(:), spass(:), snode(:), sfirst(:), slast(:)
      integer, allocatable :: pseg(:)       !< (np) segment of each pair (in its pass)
      integer, allocatable :: pfree(:)      !< (np) bit e - 1 set: edge e (nodes e, e + 1)
                                            !< is shared with no other candidate of the node
      real(wp), allocatable :: ftc(:, :), ftt(:, :)   !< (3, ns) tangential force c/t
      integer, allocatable :: actc(:), actt(:)        !< (ns) active pair (0: none) c/t
      real(wp), allocatable :: uc(:, :), ut(:, :)     !< (3, nn) displacements c/t
      integer :: nactive = 0, nchanged = 0  !< of the last evaluation against committed
      logical :: geo = .true.               !< the geometric terms in the tangent
      real(wp) :: fnsum = 0.0_wp            !< sum of the normal forces (last evaluation)
   end type icontact_t

contains

   !> Candidate pairs from the geometry x0 (+ u when present: the committed displacements,
   !> the candidates re-found after a converged step) and their equation maps emap(24, np)
   !> (slave dofs, then the master nodes'; 0: none) from eqn(3, nn). Two sweeps over the
   !> (slave node, segment) products: count, then fill (no growing arrays). When con held
   !> pairs before, the committed state of each slave node (friction force, active or not)
   !> moves to the new list (both are in (iface, pass, node) order); changed tells whether the
   !> pairs differ from the old ones.
   subroutine icon_pairs(model, eqn, con, emap, u, changed)
      type(model_t), intent(in) :: model
      integer, intent(in) :: eqn(:, :)
      type(icontact_t), intent(inout) :: con
      integer, allocatable, intent(out) :: emap(:, :)
      real(wp), intent(in), optional :: u(:, :)
      logical, intent(out), optional :: changed
      type(icontact_t) :: old
      real(wp), allocatable :: xg(:, :)
      integer :: sweep, f, ip, i, s, a, ns, np, nmine, j
      xg = model%x0
      if (present(u)) xg = model%x0 + u
      if (allocated(con%sif)) old = con
      if (allocated(con%sif)) deallocate(con%sif, con%spass, con%snode, con%sfirst, con%slast, &
                                         con%pseg, con%pfree, con%ftc, con%ftt, con%actc, con%actt)
      do sweep = 1, 2
         ns = 0; np = 0
         do f = 1, size(model%contact%iface)
            do ip = 1, size(model%contact%iface(f)%pass)
               associate (p => model%contact%iface(f)%pass(ip))
                  do i = 1, p%nnode
                     nmine = 0
                     do s = 1, p%nseg
                        if (.not. candidate(p%node(i), p%seg(1:p%nsn(s), s))) cycle
                        nmine = nmine + 1
                        if (sweep == 2) con%pseg(np + nmine) = s
                     end do
                     if (nmine == 0) cycle
                     ns = ns + 1
                     if (sweep == 2) then
                        con%sif(ns) = f; con%spass(ns) = ip; con%snode(ns) = i
                        con%sfirst(ns) = np + 1; con%slast(ns) = np + nmine
                     end if
                     np = np + nmine
                  end do
               end associate
            end do
         end do
         if (sweep == 1) allocate(con%sif(ns), con%spass(ns), con%snode(ns), con%sfirst(ns), &
                                  con%slast(ns), con%pseg(np))
      end do
      con%np = np
      con%ns = ns
      allocate(emap(NDE, np), con%ftc(3, ns), con%ftt(3, ns), con%actc(ns), con%actt(ns), &
               con%pfree(np))
      emap = 0
      con%ftc = 0.0_wp; con%ftt = 0.0_wp; con%actc = 0; con%actt = 0
      if (.not. allocated(con%uc)) then
         allocate(con%uc(3, model%nn), con%ut(3, model%nn))
         con%uc = 0.0_wp; con%ut = 0.0_wp
      end if
      do i = 1, ns
         associate (p => model%contact%iface(con%sif(i))%pass(con%spass(i)))
            do ip = con%sfirst(i), con%slast(i)
               emap(1:3, ip) = max(0, eqn(:, p%node(con%snode(i))))
               s = con%pseg(ip)
               do a = 1, p%nsn(s)
                  emap(3*a + 1:3*a + 3, ip) = max(0, eqn(:, p%seg(a, s)))
               end do
               ! the free edges: shared with none of the node's other candidate segments
               con%pfree(ip) = 0
               do a = 1, p%nsn(s)
                  if (.not. shared(p%seg(a, s), p%seg(mod(a, p%nsn(s)) + 1, s))) &
                     con%pfree(ip) = ibset(con%pfree(ip), a - 1)
               end do
            end do
         end associate
      end do
      if (present(changed)) changed = .true.
      if (.not. allocated(old%sif)) return
      if (present(changed)) changed = old%np /= np .or. old%ns /= ns
      if (present(changed) .and. .not. changed) changed = any(old%pseg /= con%pseg) .or. &
         any(old%snode /= con%snode) .or. any(old%sif /= con%sif) .or. any(old%spass /= con%spass)
      ! the committed state of every slave node found in both lists (merge walk)
      j = 1
      do i = 1, ns
         do while (j <= old%ns)
            if (key(old%sif(j), old%spass(j), old%snode(j)) >= &
                key(con%sif(i), con%spass(i), con%snode(i))) exit
            j = j + 1
         end do
         if (j > old%ns) exit
         if (key(old%sif(j), old%spass(j), old%snode(j)) /= &
             key(con%sif(i), con%spass(i), con%snode(i))) cycle
         con%ftc(:, i) = old%ftc(:, j)
         con%ftt(:, i) = old%ftt(:, j)
         if (old%actc(j) > 0) then      ! the same segment if still a candidate, else the first
            con%actc(i) = con%sfirst(i)
            do ip = con%sfirst(i), con%slast(i)
               if (con%pseg(ip) == old%pseg(old%actc(j))) con%actc(i) = ip
            end do
         end if
         con%actt(i) = con%actc(i)
      end do
   contains
      !> another candidate segment of slave entry i (in pass p), within 60 degrees of pair
      !> ip's segment (a smooth continuation: not a corner such as a symmetry plane's face),
      !> has the edge (n1, n2)
      logical function shared(n1, n2)
         integer, intent(in) :: n1, n2
         integer :: q, t
         shared = .false.
         associate (p => model%contact%iface(con%sif(i))%pass(con%spass(i)))
            do q = con%sfirst(i), con%slast(i)
               if (q == ip) cycle
               t = con%pseg(q)
               if (any(p%seg(1:p%nsn(t), t) == n1) .and. any(p%seg(1:p%nsn(t), t) == n2)) then
                  if (dot_product(segn(p%seg(1:p%nsn(t), t)), &
                                  segn(p%seg(1:p%nsn(con%pseg(ip)), con%pseg(ip)))) > 0.5_wp) then
                     shared = .true.
                     return
                  end if
               end if
            end do
         end associate
      end function shared

      !> the unit normal of a segment (its diagonals' cross product; a triangle's sides')
      function segn(sn) result(v)
         integer, intent(in) :: sn(:)
         real(wp) :: v(3)
         if (size(sn) == 4) then
            v = cross(xg(:, sn(3)) - xg(:, sn(1)), xg(:, sn(4)) - xg(:, sn(2)))
         else
            v = cross(xg(:, sn(2)) - xg(:, sn(1)), xg(:, sn(3)) - xg(:, sn(1)))
         end if
         v = v/max(norm2(v), tiny(1.0_wp))
      end function segn

      !> an order of the slave entries: interface, pass, node
      integer(8) function key(f, ip, k)
         integer, intent(in) :: f, ip, k
         key = (int(f, 8)*4_8 + int(ip, 8))*2147483648_8 + int(k, 8)
      end function key

      !> node k is not on the segment and lies in its box grown by its largest edge from
      !> node 1
      logical function candidate(k, sn)
         integer, intent(in) :: k, sn(:)
         real(wp) :: d
         integer :: c
         candidate = .false.
         if (any(sn == k)) return
         d = 0.0_wp
         do c = 2, size(sn)
            d = max(d, norm2(xg(:, sn(c)) - xg(:, sn(1))))
         end do
         do c = 1, 3
            if (xg(c, k) < minval(xg(c, sn)) - d .or. &
                xg(c, k) > maxval(xg(c, sn)) + d) return
         end do
         candidate = .true.
      end function candidate
   end subroutine icon_pairs

   !> The contact forces at u into fint (f_int - f_contact) and with want_k each active
   !> pair's tangent into kmat (the pair ip is pseudo-element e0 + ip of its pattern).
   subroutine icon_assemble(model, con, u, want_k, fint, kmat, e0, rig)
      type(model_t), intent(in) :: model
      type(irigid_t), intent(in) :: rig   !< rigid bodies (pairs touching one: T^T k T)
      type(icontact_t), intent(inout) :: con
      real(wp), intent(in) :: u(:, :)
      logical, intent(in) :: want_k
      real(wp), intent(inout) :: fint(:, :)
      type(sparse_sym_t), intent(inout) :: kmat
      integer, intent(in) :: e0
      integer :: i, ip, best, s, a, nsn, b
      real(wp) :: xe(3, 4), xs(3), nsh(4), xc(3), nrm(3), xi(2), g, gbest, fn, k, mu
      real(wp) :: bn(4), bnrm(3), du(3), ftr(3), fts, f(3), w(3, 15), pn(3, 3), tt(3), c
      real(wp) :: ke(NDE, NDE), bxi(2), bxe(3, 4), vt(3), du15(15), pt(3, 3)
      logical :: inside
      con%ut = u
      con%nactive = 0; con%nchanged = 0; con%fnsum = 0.0_wp
      do i = 1, con%ns
         associate (iface => model%contact%iface(con%sif(i)), &
                    p => model%contact%iface(con%sif(i))%pass(con%spass(i)))
            xs = model%x0(:, p%node(con%snode(i))) + u(:, p%node(con%snode(i)))
            best = 0
            gbest = -huge(1.0_wp)
            do ip = con%sfirst(i), con%slast(i)
               s = con%pseg(ip)
               nsn = p%nsn(s)
               xe = 0.0_wp
               do a = 1, nsn
                  xe(:, a) = model%x0(:, p%seg(a, s)) + u(:, p%seg(a, s))
               end do
               if (nsn == 3) xe(:, 4) = xe(:, 3)
               call project_point(nsn, xe, xs, nsh, xc, nrm, xi, inside)
               if (.not. inside) inside = past_free_edge(nsn, xi, con%pfree(ip))
               if (.not. inside) cycle
               g = dot_product(xs - xc, nrm)
               if (g >= 0.0_wp .or. -g > p%depth(s) .or. p%kseg(s) <= 0.0_wp) cycle
               if (g > gbest) then
                  gbest = g; best = ip; bn = nsh; bnrm = nrm; bxi = xi; bxe = xe
               end if
            end do
            con%actt(i) = best
            if ((best > 0) .neqv. (con%actc(i) > 0)) con%nchanged = con%nchanged + 1
            if (best == 0) then
               con%ftt(:, i) = 0.0_wp
               cycle
            end if
            con%nactive = con%nactive + 1
            s = con%pseg(best)
            nsn = p%nsn(s)
            if (nsn == 3) bn(4) = 0.0_wp
            k = p%kseg(s)
            fn = -k*gbest
            con%fnsum = con%fnsum + fn
            ! W: the relative displacement operator on (slave, master nodes)
            w = 0.0_wp
            do a = 1, 3
               w(a, a) = 1.0_wp
               do b = 1, 4
                  w(a, 3*b + a) = -bn(b)
               end do
            end do
            f = fn*bnrm
            pn = -outer(bnrm, bnrm)
            do a = 1, 3
               pn(a, a) = pn(a, a) + 1.0_wp
            end do
            mu = iface%fs
            ftr = 0.0_wp
            c = 0.0_wp
            pt = pn
            if (mu > 0.0_wp) then
               du15 = [u(:, p%node(con%snode(i))) - con%uc(:, p%node(con%snode(i))), &
                       (u(:, p%seg(min(b, nsn), s)) - con%uc(:, p%seg(min(b, nsn), s)), b = 1, 4)]
               du = matmul(w, du15)
               vt = con%ftc(:, i) - k*du
               ftr = matmul(pn, vt)
               fts = norm2(ftr)
               if (fts > mu*fn) then       ! slip: back to the cone
                  tt = ftr/fts
                  c = mu*fn/fts
                  ftr = mu*fn*tt
                  pn = pn - outer(tt, tt)
               else
                  c = 1.0_wp
                  tt = 0.0_wp
               end if
               f = f + ftr
            end if
            con%ftt(:, i) = ftr
            fint(:, p%node(con%snode(i))) = fint(:, p%node(con%snode(i))) - f
            do a = 1, nsn
               fint(:, p%seg(a, s)) = fint(:, p%seg(a, s)) + bn(a)*f
            end do
            if (want_k) then
               ke = 0.0_wp
               ke(1:15, 1:15) = pair_tangent()
               if (mu <= 0.0_wp) ke = 0.5_wp*(ke + transpose(ke))   ! symmetric to round-off
               call irig_add(rig, model, kmat, e0 + best, [p%node(con%snode(i)), &
                  (p%seg(min(b, nsn), s), b = 1, 4)], ke)
            end if
         end associate
      end do
   contains
      !> The consistent tangent of the active pair (header): d(f_int)/du on the 15 dofs.
      function pair_tangent() result(kt)
         real(wp) :: kt(15, 15)
         real(wp) :: dns(4, 2), av(3, 2), ad(3, 2), x12(3), mt(2, 2), mi(2, 2), hc(2, 2)
         real(wp) :: am(2, 2), ai(2, 2), dm(3, 15, 2), tv(15, 2), vv(15, 2), dxi(2, 15)
         real(wp) :: q(15, 2), dnm(3, 15), gm(3, 15), ddu(3, 15), dft(3, 15), wn(15), e(2)
         real(wp) :: det
         integer :: al, bb, jj
         logical :: geo
         ! the segment's parametrization at the contact point (project_point's)
         dns = 0.0_wp
         x12 = 0.0_wp
         if (nsn == 4) then
            e = max(-1.0_wp, min(1.0_wp, bxi))
            do bb = 1, 4
               dns(bb, 1) = 0.25_wp*XQ(bb)*(1.0_wp + EQ(bb)*e(2))
               dns(bb, 2) = 0.25_wp*EQ(bb)*(1.0_wp + XQ(bb)*e(1))
               x12 = x12 + 0.25_wp*XQ(bb)*EQ(bb)*bxe(:, bb)
            end do
         else
            dns(1:3, 1) = [-1.0_wp, 1.0_wp, 0.0_wp]
            dns(1:3, 2) = [-1.0_wp, 0.0_wp, 1.0_wp]
         end if
         av = matmul(bxe, dns)
         ! the geometric terms once the penetration is below GEO_DEPTH of the segment's size
         ! (its area: |a_1 x a_2| times 4, or 2 for a triangle)
         geo = con%geo .and. gbest**2 <= GEO_DEPTH**2*merge(4.0_wp, 2.0_wp, nsn == 4)* &
               norm2(cross(av(:, 1), av(:, 2)))
         kt = k*outer15(matmul(bnrm, w), matmul(bnrm, w))
         if (.not. geo) then     ! the stick tangent k W^T P W, or slip's symmetric part
            if (mu > 0.0_wp) kt = kt + k*c*matmul(transpose(w), matmul(pn, w))
            return
         end if
         mt = matmul(transpose(av), av)
         det = mt(1, 1)*mt(2, 2) - mt(1, 2)*mt(2, 1)
         mi = reshape([mt(2, 2), -mt(2, 1), -mt(1, 2), mt(1, 1)], [2, 2])/det
         hc = 0.0_wp
         hc(1, 2) = dot_product(bnrm, x12); hc(2, 1) = hc(1, 2)
         am = mt - gbest*hc
         det = am(1, 1)*am(2, 2) - am(1, 2)*am(2, 1)
         ai = reshape([am(2, 2), -am(2, 1), -am(1, 2), am(1, 1)], [2, 2])/det
         ad = matmul(av, mi)
         dm = 0.0_wp
         do al = 1, 2
            do bb = 1, 4
               do jj = 1, 3
                  dm(jj, 3*bb + jj, al) = dns(bb, al)
               end do
            end do
            tv(:, al) = matmul(av(:, al), w)
            vv(:, al) = matmul(bnrm, dm(:, :, al))
         end do
         do jj = 1, 15
            dxi(:, jj) = matmul(ai, tv(jj, :) + gbest*vv(jj, :))
         end do
         do al = 1, 2
            q(:, al) = vv(:, al) + hc(al, 1)*dxi(1, :) + hc(al, 2)*dxi(2, :)
         end do
         dnm = -(outer315(ad(:, 1), q(:, 1)) + outer315(ad(:, 2), q(:, 2)))
         kt = kt - fn*matmul(transpose(w), dnm)
         do al = 1, 2
            kt = kt + outer15(matmul(f, dm(:, :, al)), dxi(al, :))
         end do
         if (mu <= 0.0_wp) return
         ddu = w
         do al = 1, 2
            ddu = ddu - outer315(matmul(dm(:, :, al), du15), dxi(al, :))
         end do
         gm = -dot_product(bnrm, vt)*dnm - outer315(bnrm, matmul(vt, dnm)) - k*matmul(pt, ddu)
         if (c < 1.0_wp) then      ! slip (c = mu f_n/|f_t*|)
            wn = matmul(bnrm, w)
            dft = -mu*k*outer315(tt, wn) + c*(gm - outer315(tt, matmul(tt, gm)))
         else
            dft = gm
         end if
         kt = kt - matmul(transpose(w), dft)
      end function pair_tangent
   end subroutine icon_assemble

   !> A projection xi just outside the segment (up to MAXPAR) across free edges only: it
   !> counts as on the segment, clamped to the edge (an edge on a symmetry plane, a corner
   !> or the surface's border; past an edge shared with a smoothly continuing candidate that
   !> one takes the node).
   pure logical function past_free_edge(nsn, xi, free)
      integer, intent(in) :: nsn, free
      real(wp), intent(in) :: xi(2)
      logical :: out(4)
      out = .false.
      if (nsn == 4) then           ! edges 1-2: eta = -1, 2-3: xi = 1, 3-4: eta = 1, 4-1: xi = -1
         past_free_edge = all(abs(xi) <= MAXPAR)
         out = [xi(2) < -1.0_wp, xi(1) > 1.0_wp, xi(2) > 1.0_wp, xi(1) < -1.0_wp]
      else                         ! edges 1-2: b = 0, 2-3: a + b = 1, 3-1: a = 0
         past_free_edge = minval(xi) >= 1.0_wp - MAXPAR .and. sum(xi) <= MAXPAR
         out(1:3) = [xi(2) < 0.0_wp, sum(xi) > 1.0_wp, xi(1) < 0.0_wp]
      end if
      if (any(out .and. .not. [btest(free, 0), btest(free, 1), btest(free, 2), btest(free, 3)])) &
         past_free_edge = .false.
   end function past_free_edge

   !> The trial contact state (of the last evaluation) becomes the committed one.
   !> The nodes of each candidate pair: enodes(1:5, ip) = slave, the segment's corners
   !> (a triangle's fourth 0), 0 after them.
   subroutine icon_pair_nodes(model, con, enodes)
      type(model_t), intent(in) :: model
      type(icontact_t), intent(in) :: con
      integer, intent(out) :: enodes(:, :)
      integer :: i, ip, s
      enodes = 0
      do i = 1, con%ns
         associate (p => model%contact%iface(con%sif(i))%pass(con%spass(i)))
            do ip = con%sfirst(i), con%slast(i)
               s = con%pseg(ip)
               enodes(1, ip) = p%node(con%snode(i))
               enodes(2:1 + p%nsn(s), ip) = p%seg(1:p%nsn(s), s)
            end do
         end associate
      end do
   end subroutine icon_pair_nodes

   subroutine icon_commit(con)
      type(icontact_t), intent(inout) :: con
      con%ftc = con%ftt
      con%actc = con%actt
      con%uc = con%ut
   end subroutine icon_commit

   pure function outer15(a, b) result(m)
      real(wp), intent(in) :: a(15), b(15)
      real(wp) :: m(15, 15)
      integer :: j
      do j = 1, 15
         m(:, j) = a*b(j)
      end do
   end function outer15

   pure function outer315(a, b) result(m)
      real(wp), intent(in) :: a(3), b(15)
      real(wp) :: m(3, 15)
      integer :: j
      do j = 1, 15
         m(:, j) = a*b(j)
      end do
   end function outer315

   pure function outer(a, b) result(m)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: m(3, 3)
      integer :: j
      do j = 1, 3
         m(:, j) = a*b(j)
      end do
   end function outer
end module dx_implicit_contact
