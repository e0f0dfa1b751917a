!> Implicit penalty contact with Coulomb friction (the NIKE3D slideline; issue 20): the
!> node-to-segment penalty of the explicit contact (the same passes, segments, penalty
!> stiffnesses k = SFS/SFM f K A^2/V and projection, dx_contact_penalty) as a term of the
!> Newton residual with its tangent. NIKE3D: Maker, Ferencz & Hallquist, UCRL-MA-105268
!> (1995), "Sliding interfaces"; the penalty node-to-segment tangent and the stick/slip
!> return after Wriggers, "Computational Contact Mechanics", 2nd ed. 2006, ch. 5.2 and 6.3
!> (Laursen & Simo's regularized Coulomb law, Int. J. Numer. Meth. Eng. 36 (1993) 3451-3485).
!> Per slave node (x_s) and its candidate segments (formed once, at the start, from the
!> undeformed geometry: small sliding, each slave node against the segments whose box grown
!> by the segment's size holds it), at the trial displacements u:
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
!> Tangent on the 15 dofs (slave, 4 master nodes), W = [I, -N_1 I, ..., -N_4 I]:
!>   k W^T n n^T W (normal) + k W^T (I - n n^T) W (stick), or in slip its symmetric part
!>   (mu f_n/|f_t*|) k W^T (I - n n^T - t t^T) W; the rotation of n and t with the geometry
!>   and slip's unsymmetric normal coupling (mu k t n^T) are left out (the symmetric MUMPS
!>   factorization): Newton then converges linearly, not quadratically, while the contact
!>   slides; in stick and frictionless contact on flat segments the tangent is exact.
!> Contact status changes between iterations are the residual's (the active set is found
!> anew at every evaluation); the count of active nodes and of changes is logged per step.
!> The sparse pattern holds one pseudo-element per candidate pair (dx_implicit_system).
module dx_implicit_contact
   use dx_kinds, only: wp
   use dx_model, only: model_t
   use dx_contact_penalty, only: project_point
   use dx_sparse, only: sparse_sym_t, sparse_add_element
   implicit none
   private
   public :: icontact_t, icon_pairs, icon_assemble, icon_commit

   integer, parameter :: NDE = 24      !< the pattern's element width (the hexahedron's)

   type :: icontact_t
      integer :: np = 0                     !< candidate pairs (pseudo-elements)
      integer :: ns = 0                     !< slave entries (iface, pass, slave node)
      integer, allocatable :: sif(:), spass(:), snode(:), sfirst(:), slast(:)
      integer, allocatable :: pseg(:)       !< (np) segment of each pair (in its pass)
      real(wp), allocatable :: ftc(:, :), ftt(:, :)   !< (3, ns) tangential force c/t
      integer, allocatable :: actc(:), actt(:)        !< (ns) active pair (0: none) c/t
      real(wp), allocatable :: uc(:, :), ut(:, :)     !< (3, nn) displacements c/t
      integer :: nactive = 0, nchanged = 0  !< of the last evaluation against committed
      real(wp) :: fnsum = 0.0_wp            !< sum of the normal forces (last evaluation)
   end type icontact_t

contains

   !> Candidate pairs from the undeformed geometry and their equation maps emap(24, np)
   !> (slave dofs, then the master nodes'; 0: none) from eqn(3, nn). Two sweeps over the
   !> (slave node, segment) products: count, then fill (no growing arrays).
   subroutine icon_pairs(model, eqn, con, emap)
      type(model_t), intent(in) :: model
      integer, intent(in) :: eqn(:, :)
      type(icontact_t), intent(inout) :: con
      integer, allocatable, intent(out) :: emap(:, :)
      integer :: sweep, f, ip, i, s, a, ns, np, nmine
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
               con%uc(3, model%nn), con%ut(3, model%nn))
      emap = 0
      con%ftc = 0.0_wp; con%ftt = 0.0_wp; con%actc = 0; con%actt = 0
      con%uc = 0.0_wp; con%ut = 0.0_wp
      do i = 1, ns
         associate (p => model%contact%iface(con%sif(i))%pass(con%spass(i)))
            do ip = con%sfirst(i), con%slast(i)
               emap(1:3, ip) = max(0, eqn(:, p%node(con%snode(i))))
               s = con%pseg(ip)
               do a = 1, p%nsn(s)
                  emap(3*a + 1:3*a + 3, ip) = max(0, eqn(:, p%seg(a, s)))
               end do
            end do
         end associate
      end do
   contains
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
            d = max(d, norm2(model%x0(:, sn(c)) - model%x0(:, sn(1))))
         end do
         do c = 1, 3
            if (model%x0(c, k) < minval(model%x0(c, sn)) - d .or. &
                model%x0(c, k) > maxval(model%x0(c, sn)) + d) return
         end do
         candidate = .true.
      end function candidate
   end subroutine icon_pairs

   !> The contact forces at u into fint (f_int - f_contact) and with want_k each active
   !> pair's tangent into kmat (the pair ip is pseudo-element e0 + ip of its pattern).
   subroutine icon_assemble(model, con, u, want_k, fint, kmat, e0)
      type(model_t), intent(in) :: model
      type(icontact_t), intent(inout) :: con
      real(wp), intent(in) :: u(:, :)
      logical, intent(in) :: want_k
      real(wp), intent(inout) :: fint(:, :)
      type(sparse_sym_t), intent(inout) :: kmat
      integer, intent(in) :: e0
      integer :: i, ip, best, s, a, nsn, b
      real(wp) :: xe(3, 4), xs(3), nsh(4), xc(3), nrm(3), xi(2), g, gbest, fn, k, mu
      real(wp) :: bn(4), bnrm(3), du(3), ftr(3), fts, f(3), w(3, 15), pn(3, 3), tt(3), c
      real(wp) :: ke(NDE, NDE)
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
               if (.not. inside) cycle
               g = dot_product(xs - xc, nrm)
               if (g >= 0.0_wp .or. -g > p%depth(s) .or. p%kseg(s) <= 0.0_wp) cycle
               if (g > gbest) then
                  gbest = g; best = ip; bn = nsh; bnrm = nrm
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
            if (mu > 0.0_wp) then
               du = matmul(w, [u(:, p%node(con%snode(i))) - con%uc(:, p%node(con%snode(i))), &
                               (u(:, p%seg(min(b, nsn), s)) - con%uc(:, p%seg(min(b, nsn), s)), &
                                b = 1, 4)])
               ftr = matmul(pn, con%ftc(:, i)) - k*matmul(pn, du)
               fts = norm2(ftr)
               if (fts > mu*fn) then       ! slip: back to the cone
                  tt = ftr/fts
                  c = mu*fn/fts
                  ftr = mu*fn*tt
                  pn = pn - outer(tt, tt)
               else
                  c = 1.0_wp
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
               ke(1:15, 1:15) = k*matmul(transpose(w), matmul(outer(bnrm, bnrm) + c*pn, w))
               call sparse_add_element(kmat, e0 + best, ke)
            end if
         end associate
      end do
   end subroutine icon_assemble

   !> The trial contact state (of the last evaluation) becomes the committed one.
   subroutine icon_commit(con)
      type(icontact_t), intent(inout) :: con
      con%ftc = con%ftt
      con%actc = con%actt
      con%uc = con%ut
   end subroutine icon_commit

   pure function outer(a, b) result(m)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: m(3, 3)
      integer :: j
      do j = 1, 3
         m(:, j) = a*b(j)
      end do
   end function outer
end module dx_implicit_contact
