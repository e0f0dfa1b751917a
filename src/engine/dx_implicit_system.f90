!> The implicit solver's system (issue 20): equation numbers, the element loop that forms
!> the internal force and the tangent stiffness, the trial/committed split of the element and
!> material state, the external loads and the prescribed displacements. The Newton iteration
!> itself is dx_implicit (solvers); this module is the engine stage it calls, so that the
!> solvers layer reaches elements, loads and MPI only through the engine.
!> Constraints by elimination (NIKE3D: Maker, Ferencz & Hallquist, UCRL-MA-105268, "Boundary
!> conditions"): a *BOUNDARY_SPC translation is no equation; a *BOUNDARY_PRESCRIBED_MOTION
!> displacement (VAD = 2, DOF 1-3) is no equation and takes its value sf*curve(t) at each
!> step, so the first residual of a step carries the imposed increment.
!> Equations are numbered node by node (x, y, z), the sparse pattern is formed once
!> (dx_sparse) and its analysis is done once by the caller.
!> MPI runs (dx_implicit_par): the whole system on every rank, each rank assembles its own
!> elements, the internal force summed in rank order; the contact is evaluated alike on
!> every rank from the summed state, its tangent added by rank 0.
module dx_implicit_system
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_NUMERIC
   use dx_strings, only: str
   use dx_log, only: log_info
   use dx_model, only: model_t
   use dx_hex8_stiffness, only: tl_solid_element, tl_supported, tl_points, TL_ERR_JAC, TL_NEN
   use dx_sparse, only: sparse_sym_t, sparse_symbolic, sparse_zero, sparse_add_element
   use dx_loads, only: add_external_loads
   use dx_par, only: par_self_handle, par_size
   use dx_implicit_par, only: ipar_t, ipar_setup, ipar_entries, ipar_sum, ipar_exact, &
                              ipar_bcast, ipar_bcast_int, ipar_first, ipar_agree, ipar_agreed, &
                              ipar_comm, ipar_max_flags, ipar_global, ipar_assemble, &
                              ipar_per_rank
   use dx_contact_input, only: CT_NODES_TO_SURFACE, CT_SURFACE_TO_SURFACE, CT_ONE_WAY
   use dx_implicit_contact, only: icontact_t, icon_pairs, icon_assemble, icon_commit, &
                                  icon_pair_nodes
   use dx_implicit_rigid, only: irigid_t, irig_setup, irig_layouts, irig_add, irig_nodes, &
                                irig_gather, irig_scatter, irig_reset, irig_commit, &
                                irig_prescribe, irig_dof_name
   implicit none
   private
   public :: implicit_system_t, isys_setup, isys_assemble, isys_commit, isys_external, &
             isys_refind, &
             isys_prescribe, isys_comm, isys_gather, isys_scatter, isys_dof_name, &
             isys_fix, isys_null_names, isys_reset, isys_root, isys_mpi, isys_analyse_entries, &
             isys_bcast, isys_bcast_int, isys_agree, isys_agreed, isys_max_flags, isys_global, &
             isys_nranks, isys_sum_entries, isys_per_rank

   !> One block's committed (c) and trial (t) point state: S, Ebar (6, 8, nel), history
   !> (nh, 8, nel); the element's stress work w (committed) and its trial increment dw.
   type :: block_state_t
      real(wp), allocatable :: sc(:, :, :), ec(:, :, :), hc(:, :, :)
      real(wp), allocatable :: st(:, :, :), et(:, :, :), ht(:, :, :)
      real(wp), allocatable :: wc(:), dw(:), cauchy(:, :), havg(:, :)
   end type block_state_t

   type :: implicit_system_t
      integer :: neq = 0
      integer, allocatable :: eqn(:, :)     !< (3, nn) equation; 0 fixed; -k prescribed k
      integer, allocatable :: pres(:)       !< model%prescribed entries taken (their index)
      integer, allocatable :: emap(:, :)    !< (24, ne) element equation maps
      integer, allocatable :: eoff(:)       !< block b's elements start at eoff(b) + 1
      type(sparse_sym_t) :: k               !< the tangent stiffness
      type(block_state_t), allocatable :: bs(:)
      logical :: linear = .false.           !< NSOLVR = 1
      integer :: nel = 0                    !< elements (contact pairs follow in the pattern)
      type(icontact_t) :: con               !< penalty contact (dx_implicit_contact)
      logical :: has_contact = .false.
      type(irigid_t) :: rig                 !< rigid bodies (dx_implicit_rigid)
      logical, allocatable :: rblock(:)     !< (blocks) a rigid part's block: not assembled
      type(ipar_t) :: par                   !< MPI: this rank's elements and entries
   end type implicit_system_t

contains

   !> Check the model for what the implicit solver has, number the equations, form the
   !> sparse pattern and the zero state. Errors are input errors (exit 2).
   subroutine isys_setup(model, sys, error, rigid_ok)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(inout) :: sys
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: rigid_ok   !< rigid bodies are taken (dx_implicit)
      integer :: b, e, a, i, k, n, nh, ne, d, ngp
      integer, allocatable :: cmap(:, :), enodes(:, :), eidx(:)
      integer :: nnode
      logical :: rok
      character(*), parameter :: why = ' (the implicit Newton solver of IMFLAG = 1, issue 20)'
      sys%linear = model%ctrl%imp%nsolvr == 1
      if (allocated(model%contact)) then
         do k = 1, size(model%contact%iface)
            associate (f => model%contact%iface(k))
               if (f%kind /= CT_SURFACE_TO_SURFACE .and. f%kind /= CT_NODES_TO_SURFACE .and. &
                   f%kind /= CT_ONE_WAY) then
                  call set_error(error, '*'//f%name//' (contact '//str(f%label)//'): the implicit '// &
                     'solver has the surface-to-surface and nodes-to-surface penalty contacts '// &
                     '(_AUTOMATIC_ or not); single surface is not yet in it'//why); return
               end if
               if (any(f%pass(:)%shells)) then
                  call set_error(error, '*'//f%name//' (contact '//str(f%label)//'): shells are '// &
                     'not yet in the implicit contact'//why); return
               end if
               if ((f%fd > 0.0_wp .and. f%fd /= f%fs) .or. f%dc > 0.0_wp .or. f%vc > 0.0_wp &
                   .or. f%vdc > 0.0_wp .or. f%soft /= 0 .or. f%bt > 0.0_wp .or. &
                   f%dt < 1.0e20_wp) call log_info('dynx: implicit: note: *'//f%name// &
                  ' (contact '//str(f%label)//'): FD, DC, VC, VDC, SOFT, BT and DT are not '// &
                  'used by the implicit contact (Coulomb mu = FS, penalty SFS/SFM, always on)')
            end associate
         end do
         sys%has_contact = size(model%contact%iface) > 0
      end if
      call ipar_setup(model, sys%par, error)
      if (allocated(error)) return
      rok = .false.
      if (present(rigid_ok)) rok = rigid_ok
      if (allocated(model%rigid) .and. .not. rok) then
         call set_error(error, 'rigid bodies (*MAT_RIGID, *CONSTRAINED_*) are not yet in '// &
                        'this implicit analysis (eigenvalues)'//why); return
      end if
      if (allocated(model%walls)) then
         if (size(model%walls) > 0) then
            call set_error(error, '*RIGIDWALL_*: not yet in the implicit solver'//why); return
         end if
      end if
      if (allocated(model%body_loads)) then
         if (size(model%body_loads) > 0) then
            call set_error(error, '*LOAD_BODY_*: not yet in the implicit solver'//why); return
         end if
      end if
      do b = 1, size(model%blocks)
         associate (p => model%parts(model%blocks(b)%ipart))
            if (model%mats(p%imat)%m%is_rigid) cycle     ! (a rigid body's elements)
            if (.not. tl_supported(model%blocks(b)%etype)) then
               call set_error(error, '*PART '//str(p%label)//': its *SECTION_* element '// &
                  'formulation is not in the implicit solver (solid ELFORM 1, 2, 10 are)'// &
                  why); return
            end if
            if (sys%linear .and. model%blocks(b)%nhv > 0) then
               call set_error(error, '*CONTROL_IMPLICIT_SOLUTION: field NSOLVR: 1 (linear, '// &
                  'one solve per step) takes elastic materials; *PART '//str(p%label)// &
                  ' has *MAT_ type '//str(model%mats(p%imat)%m%mtype)//' with history '// &
                  '(plasticity): use NSOLVR 12'); return
            end if
         end associate
      end do
      ! ---- equations: SPCs and prescribed displacements are none
      allocate(sys%eqn(3, model%nn))
      sys%eqn = 1
      if (allocated(model%spcs)) then
         do k = 1, size(model%spcs)
            do d = 1, 3
               if (model%spcs(k)%dof(d)) sys%eqn(d, model%spcs(k)%node) = 0
            end do
         end do
      end if
      allocate(sys%pres(0))
      if (allocated(model%prescribed)) then
         do k = 1, size(model%prescribed)
            associate (pr => model%prescribed(k))
               if (pr%curve == 0) then
                  call set_error(error, '*BOUNDARY_SPC_*: node '// &
                     str(model%node_label(pr%node))//': field CID: a constraint along the '// &
                     'axes of a *DEFINE_COORDINATE_SYSTEM (skew SPC) is explicit only; the '// &
                     'implicit solver takes SPCs along x, y, z (CID = 0)'); return
               end if
               if (pr%vad /= 2 .or. pr%dof < 1 .or. pr%dof > 3) then
                  call set_error(error, '*BOUNDARY_PRESCRIBED_MOTION_*: node '// &
                     str(model%node_label(pr%node))//': field VAD/DOF: the implicit solver '// &
                     'takes displacements (VAD = 2) along x, y or z (DOF 1-3), got VAD = '// &
                     str(pr%vad)//', DOF = '//str(pr%dof)); return
               end if
               sys%pres = [sys%pres, k]
               sys%eqn(pr%dof, pr%node) = -size(sys%pres)
            end associate
         end do
      end if
      if (allocated(model%rigid)) then     ! a rigid body's nodes: its six equations
         where (spread(model%rigid%node_body, 1, 3) > 0) sys%eqn = 0
      end if
      n = 0
      do i = 1, model%nn
         do d = 1, 3
            if (sys%eqn(d, i) > 0) then
               n = n + 1
               sys%eqn(d, i) = n
            end if
         end do
      end do
      ! rigid bodies: their nodes no equations, each body six after the nodes' (n grows)
      nnode = n
      call irig_setup(model, sys%eqn, n, sys%rig, error)
      if (allocated(error)) return
      sys%neq = n
      if (n == 0) then
         call set_error(error, 'the implicit solver found no free degree of freedom (every '// &
                        'node is constrained)'); return
      end if
      ! ---- element maps and pattern
      ne = 0
      allocate(sys%eoff(size(model%blocks)))
      do b = 1, size(model%blocks)
         sys%eoff(b) = ne
         ne = ne + model%blocks(b)%nel
      end do
      allocate(sys%emap(3*TL_NEN, ne), sys%rblock(size(model%blocks)))
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            sys%emap(:, sys%eoff(b) + 1:sys%eoff(b) + blk%nel) = 0
            sys%rblock(b) = model%mats(model%parts(blk%ipart)%imat)%m%is_rigid
            if (sys%rblock(b)) cycle
            do e = 1, blk%nel
               do a = 1, size(blk%conn, 1)
                  do d = 1, 3
                     sys%emap(3*(a - 1) + d, sys%eoff(b) + e) = max(0, sys%eqn(d, blk%conn(a, e)))
                  end do
               end do
            end do
         end associate
      end do
      sys%nel = ne
      if (sys%has_contact) then    ! one pseudo-element per candidate contact pair
         call icon_pairs(model, sys%eqn, sys%con, cmap)
         call rigid_layouts(model, sys, cmap, error)
         if (allocated(error)) return
         ! Coulomb friction makes the consistent contact tangent unsymmetric: every entry
         call sparse_symbolic(n, reshape([sys%emap, cmap], [3*TL_NEN, ne + sys%con%np]), sys%k, &
                              unsym=any(model%contact%iface(:)%fs > 0.0_wp))
      else
         allocate(cmap(3*TL_NEN, 0))
         call rigid_layouts(model, sys, cmap, error)
         if (allocated(error)) return
         call sparse_symbolic(n, sys%emap, sys%k)
      end if
      if (sys%par%on) then      ! MPI: the entries this rank passes to MUMPS
         allocate(eidx(model%ne))
         eidx = 0
         do b = 1, size(model%blocks)
            if (sys%rblock(b)) cycle
            do e = 1, model%blocks(b)%nel
               eidx(model%blocks(b)%elem(e)) = sys%eoff(b) + e
            end do
         end do
         call ipar_entries(sys%par, sys%k, sys%nel + 1, sys%nel + sys%con%np, eidx, nnode + 1)
      end if
      allocate(sys%bs(size(model%blocks)))
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b), s => sys%bs(b))
            nh = blk%nhv
            ngp = tl_points(blk%etype)
            allocate(s%sc(6, ngp, blk%nel), s%ec(6, ngp, blk%nel), &
                     s%hc(nh, ngp, blk%nel), s%wc(blk%nel), s%dw(blk%nel), &
                     s%cauchy(6, blk%nel), s%havg(nh, blk%nel))
            s%sc = 0.0_wp; s%ec = 0.0_wp; s%hc = 0.0_wp; s%wc = 0.0_wp; s%dw = 0.0_wp
            s%cauchy = 0.0_wp; s%havg = 0.0_wp
            s%st = s%sc; s%et = s%ec; s%ht = s%hc
         end associate
      end do
   end subroutine isys_setup

   !> Internal forces fint(3, nn) at the displacements u(3, nn) from the committed state
   !> (the trial state kept), and with want_k the tangent stiffness into sys%k.
   !> A failed element (a Jacobian <= 0, a material update that failed) is a numerical
   !> error naming it (exit 3); the caller may retry with a smaller step.
   subroutine isys_assemble(model, sys, u, dt, want_k, fint, error)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(inout) :: sys
      real(wp), intent(in) :: u(:, :), dt
      logical, intent(in) :: want_k
      real(wp), intent(out) :: fint(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer :: b, e, a, ierr, nen, kfail
      real(wp) :: xe0(3, TL_NEN), ue(3, TL_NEN), fe(3*TL_NEN), ke(3*TL_NEN, 3*TL_NEN)
      kfail = huge(kfail)
      fint = 0.0_wp
      ke = 0.0_wp
      if (want_k) call sparse_zero(sys%k)
      do b = 1, size(model%blocks)
         if (sys%rblock(b)) cycle
         associate (blk => model%blocks(b), s => sys%bs(b), &
                    mat => model%mats(model%parts(model%blocks(b)%ipart)%imat)%m)
            nen = size(blk%conn, 1)
            do e = 1, blk%nel
               if (sys%par%on) then          ! MPI: this rank's elements
                  if (.not. sys%par%own(blk%elem(e))) cycle
               end if
               do a = 1, nen
                  xe0(:, a) = model%x0(:, blk%conn(a, e))
                  ue(:, a) = u(:, blk%conn(a, e))
               end do
               call tl_solid_element(mat, xe0(:, 1:nen), ue(:, 1:nen), dt, sys%linear, &
                  s%sc(:, :, e), s%ec(:, :, e), s%hc(:, :, e), s%st(:, :, e), s%et(:, :, e), &
                  s%ht(:, :, e), fe(1:3*nen), want_k, ke(1:3*nen, 1:3*nen), s%dw(e), &
                  s%cauchy(:, e), s%havg(:, e), ierr)
               if (ierr /= 0) then      ! (MPI: the first failure in serial order over the ranks)
                  kfail = 2*(sys%eoff(b) + e) + merge(0, 1, ierr == TL_ERR_JAC)
                  exit
               end if
               do a = 1, nen
                  fint(:, blk%conn(a, e)) = fint(:, blk%conn(a, e)) + fe(3*a - 2:3*a)
               end do
               if (want_k) call irig_add(sys%rig, model, sys%k, sys%eoff(b) + e, &
                                         blk%conn(:, e), ke)
            end do
         end associate
         if (kfail < huge(kfail)) exit
      end do
      call ipar_first(sys%par, kfail)
      if (kfail < huge(kfail)) then
         call element_failed(model, sys, kfail, error)
         return
      end if
      call ipar_sum(sys%par, fint)
      ! (MPI: every rank evaluates the contact alike on the summed forces; rank 0 adds its
      ! tangent, the pairs' entries are rank 0's)
      if (sys%has_contact) call icon_assemble(model, sys%con, u, want_k .and. isys_root(sys), &
                                              fint, sys%k, sys%nel, sys%rig)
   end subroutine isys_assemble

   !> The message of the failed element of key 2 idx + (0: Jacobian, 1: material), idx its
   !> assembly index (MPI: the same on every rank).
   subroutine element_failed(model, sys, key, error)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(in) :: sys
      integer, intent(in) :: key
      type(error_t), allocatable, intent(out) :: error
      integer :: b, e, q
      q = key/2
      b = count(sys%eoff < q)
      e = q - sys%eoff(b)
      associate (blk => model%blocks(b))
         if (mod(key, 2) == 0) then
            call set_error(error, 'element '//str(model%elem_label(blk%elem(e)))// &
               ' (part '//str(model%parts(blk%ipart)%label)//'): a Jacobian <= 0 '// &
               '(inverted element)', EXIT_NUMERIC)
         else
            call set_error(error, 'element '//str(model%elem_label(blk%elem(e)))// &
               ' (part '//str(model%parts(blk%ipart)%label)//'): the material '// &
               'update failed', EXIT_NUMERIC)
         end if
      end associate
   end subroutine element_failed

   !> The contact candidates re-found from the committed displacements u (after a converged
   !> step); when they changed, the sparse pattern is formed anew (changed: the caller
   !> analyses it again).
   subroutine isys_refind(model, sys, u, changed, error)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(inout) :: sys
      real(wp), intent(in) :: u(:, :)
      logical, intent(out) :: changed
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: cmap(:, :)
      changed = .false.
      if (.not. sys%has_contact) return
      call icon_pairs(model, sys%eqn, sys%con, cmap, u, changed)
      if (.not. changed) return
      call rigid_layouts(model, sys, cmap, error)
      if (allocated(error)) return
      call sparse_symbolic(sys%neq, reshape([sys%emap, cmap], [3*TL_NEN, sys%nel + sys%con%np]), &
                           sys%k, unsym=.not. sys%k%sym)
      call ipar_entries(sys%par, sys%k, sys%nel + 1, sys%nel + sys%con%np)   ! (MPI)
   end subroutine isys_refind

   !> The condensed maps of the elements and contact pairs (cmap) that touch rigid bodies
   !> (dx_implicit_rigid's layouts); nothing without bodies.
   subroutine rigid_layouts(model, sys, cmap, error)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(inout) :: sys
      integer, intent(inout) :: cmap(:, :)
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: enodes(:, :), map(:, :)
      integer :: b, e, np
      if (sys%rig%nb == 0) return
      np = size(cmap, 2)
      allocate(enodes(8, sys%nel + np), map(3*TL_NEN, sys%nel + np))
      enodes = 0
      do b = 1, size(model%blocks)
         if (sys%rblock(b)) cycle
         associate (blk => model%blocks(b))
            do e = 1, blk%nel
               enodes(1:size(blk%conn, 1), sys%eoff(b) + e) = blk%conn(:, e)
            end do
         end associate
      end do
      if (np > 0) call icon_pair_nodes(model, sys%con, enodes(:, sys%nel + 1:))
      map(:, 1:sys%nel) = sys%emap
      map(:, sys%nel + 1:) = cmap
      call irig_layouts(sys%rig, sys%eqn, enodes, map, error)
      sys%emap = map(:, 1:sys%nel)
      cmap = map(:, sys%nel + 1:)
   end subroutine rigid_layouts

   !> The rigid bodies' trial state back to the committed one (a step's start or retry).
   subroutine isys_reset(sys)
      type(implicit_system_t), intent(inout) :: sys
      call irig_reset(sys%rig)
   end subroutine isys_reset

   !> The trial state (of the last assembly) becomes the committed one; the blocks' plot
   !> fields: Cauchy stress and history (element averages in every point slot) and the
   !> stress work (glstat's internal energy).
   subroutine isys_commit(model, sys, h, gamma)
      type(model_t), intent(inout) :: model
      type(implicit_system_t), intent(inout) :: sys
      real(wp), intent(in) :: h, gamma     !< dynamics: the step and Newmark GAMMA (h = 0: statics)
      integer :: b, ip, k
      if (sys%has_contact) call icon_commit(sys%con)
      call irig_commit(sys%rig, h, gamma)
      do b = 1, size(model%blocks)
         if (sys%rblock(b)) cycle
         associate (blk => model%blocks(b), s => sys%bs(b))
            s%sc = s%st; s%ec = s%et; s%hc = s%ht
            if (sys%par%on) call gather_fields(sys%par, blk%elem, s)
            s%wc = s%wc + s%dw
            blk%eint = s%wc
            do ip = 1, blk%nip
               do k = 1, 6
                  blk%sig(:, k, ip) = s%cauchy(k, :)
               end do
               do k = 1, blk%nhv
                  blk%hv(:, k, ip) = s%havg(k, :)
               end do
            end do
         end associate
      end do
   end subroutine isys_commit

   !> MPI: a block's plot fields and work increments from their owners (zero elsewhere).
   subroutine gather_fields(ip, elem, s)
      type(ipar_t), intent(in) :: ip
      integer, intent(in) :: elem(:)
      type(block_state_t), intent(inout) :: s
      real(wp), allocatable :: buf(:)
      integer :: n6, nh, ne, e
      ne = size(s%dw)
      n6 = size(s%cauchy)
      nh = size(s%havg)
      where (.not. ip%own(elem(1:ne))) s%dw = 0.0_wp
      do e = 1, ne
         if (ip%own(elem(e))) cycle
         s%cauchy(:, e) = 0.0_wp
         s%havg(:, e) = 0.0_wp
      end do
      buf = [reshape(s%cauchy, [n6]), reshape(s%havg, [nh]), s%dw]
      call ipar_exact(ip, buf)
      s%cauchy = reshape(buf(1:n6), shape(s%cauchy))
      s%havg = reshape(buf(n6 + 1:n6 + nh), shape(s%havg))
      s%dw = buf(n6 + nh + 1:)
   end subroutine gather_fields

   !> External forces at time t on the geometry model%x (zeroed first).
   subroutine isys_external(model, t, fext)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: t
      real(wp), intent(out) :: fext(:, :)
      fext = 0.0_wp
      call add_external_loads(model, t, fext)
   end subroutine isys_external

   !> The prescribed displacements (and rigid motions, the rigid nodes') at time t into u.
   subroutine isys_prescribe(model, sys, t, u)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(inout) :: sys
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: u(:, :)
      integer :: k
      do k = 1, size(sys%pres)
         associate (pr => model%prescribed(sys%pres(k)))
            u(pr%dof, pr%node) = pr%sf*model%curves(pr%curve)%eval(t)
         end associate
      end do
      if (sys%rig%nb == 0) return
      call irig_prescribe(sys%rig, model, t)
      call irig_nodes(sys%rig, model, u)
   end subroutine isys_prescribe

   !> The equations' entries of a nodal field v(3, nn) into r(neq): a rigid body's the
   !> resultant force and moment of its nodes' (model given; else 0: nodal fields as masses).
   subroutine isys_gather(sys, v, r, model)
      type(implicit_system_t), intent(in) :: sys
      real(wp), intent(in) :: v(:, :)
      real(wp), intent(out) :: r(:)
      type(model_t), intent(in), optional :: model
      integer :: i, d
      if (sys%rig%nb > 0) then
         r = 0.0_wp
         if (present(model)) call irig_gather(sys%rig, model, v, r)
      end if
      do i = 1, size(sys%eqn, 2)
         do d = 1, 3
            if (sys%eqn(d, i) > 0) r(sys%eqn(d, i)) = v(d, i)
         end do
      end do
   end subroutine isys_gather

   !> v(3, nn) += alpha r(neq) on the equations' entries; with model (v: the displacements)
   !> the rigid bodies move by alpha r and their nodes' v follow.
   subroutine isys_scatter(sys, r, alpha, v, model)
      type(implicit_system_t), intent(inout) :: sys
      real(wp), intent(in) :: r(:), alpha
      real(wp), intent(inout) :: v(:, :)
      type(model_t), intent(in), optional :: model
      integer :: i, d
      if (sys%rig%nb > 0 .and. present(model)) then
         call irig_scatter(sys%rig, r, alpha)
         call irig_nodes(sys%rig, model, v)
      end if
      do i = 1, size(sys%eqn, 2)
         do d = 1, 3
            if (sys%eqn(d, i) > 0) v(d, i) = v(d, i) + alpha*r(sys%eqn(d, i))
         end do
      end do
   end subroutine isys_scatter

   !> Zero the SPC-fixed components of a nodal field (velocities of a dynamic step).
   subroutine isys_fix(sys, v)
      type(implicit_system_t), intent(in) :: sys
      real(wp), intent(inout) :: v(:, :)
      where (sys%eqn == 0) v = 0.0_wp
   end subroutine isys_fix

   !> 'node L dof x' of equation q (messages).
   function isys_dof_name(model, sys, q) result(s)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(in) :: sys
      integer, intent(in) :: q
      character(:), allocatable :: s
      integer :: i, d
      character(1), parameter :: ax(3) = ['x', 'y', 'z']
      s = irig_dof_name(sys%rig, model, q)
      if (len(s) > 0) return
      s = 'equation '//str(q)
      do i = 1, size(sys%eqn, 2)
         do d = 1, 3
            if (sys%eqn(d, i) == q) then
               s = 'node '//str(model%node_label(i))//' '//ax(d); return
            end if
         end do
      end do
   end function isys_dof_name

   !> 'node L x, node M z, ...' of the first 10 of the equations eqs (a factorization's null
   !> pivots; messages), ', ...' after them when there are more.
   function isys_null_names(model, sys, eqs) result(s)
      type(model_t), intent(in) :: model
      type(implicit_system_t), intent(in) :: sys
      integer, intent(in) :: eqs(:)
      character(:), allocatable :: s
      integer :: q
      s = ''
      do q = 1, min(size(eqs), 10)
         if (q > 1) s = s//', '
         s = s//isys_dof_name(model, sys, eqs(q))
      end do
      if (size(eqs) > 10) s = s//', ...'
   end function isys_null_names

   !> The communicator handle the sparse solver takes (serial: MPI_COMM_SELF, MPI started
   !> for it).
   integer function isys_comm()
      isys_comm = par_self_handle()
   end function isys_comm

   !> This rank adds the terms the system takes once (rigid bodies' inertia and rotation
   !> terms, the mass diagonal): rank 0, or the serial run.
   logical function isys_root(sys)
      type(implicit_system_t), intent(in) :: sys
      isys_root = .not. sys%par%on .or. sys%par%me == 0
   end function isys_root

   !> An MPI run on more than one rank (dx_implicit_par).
   logical function isys_mpi(sys)
      type(implicit_system_t), intent(in) :: sys
      isys_mpi = sys%par%on
   end function isys_mpi

   !> The ranks of the run (1: serial).
   integer function isys_nranks()
      isys_nranks = par_size()
   end function isys_nranks

   !> MPI: the communicator of the run and this rank's entries (for dx_mumps's analysis).
   subroutine isys_analyse_entries(sys, comm, loc)
      type(implicit_system_t), intent(in) :: sys
      integer, intent(out) :: comm
      integer, allocatable, intent(out) :: loc(:)
      comm = ipar_comm()
      loc = sys%par%loc
   end subroutine isys_analyse_entries

   !> x from rank 0 to every rank (MPI; no-op serially).
   subroutine isys_bcast(sys, x)
      type(implicit_system_t), intent(in) :: sys
      real(wp), intent(inout) :: x(:)
      call ipar_bcast(sys%par, x)
   end subroutine isys_bcast

   subroutine isys_bcast_int(sys, iv)
      type(implicit_system_t), intent(in) :: sys
      integer, intent(inout) :: iv(:)
      call ipar_bcast_int(sys%par, iv)
   end subroutine isys_bcast_int

   !> MPI: after the start and every step, a failure known to every rank (dx_par_agree).
   subroutine isys_agree(error)
      type(error_t), allocatable, intent(inout) :: error
      call ipar_agree(error)
   end subroutine isys_agree

   logical function isys_agreed(sys)
      type(implicit_system_t), intent(in) :: sys
      isys_agreed = ipar_agreed(sys%par)
   end function isys_agreed

   !> The stop/dump requests reduced over the ranks (dx_checkpoint, replicated runs).
   subroutine isys_max_flags(flags)
      integer, intent(inout) :: flags(:)
      call ipar_max_flags(flags)
   end subroutine isys_max_flags

   !> MPI: the owned entries of the tangent summed from every rank that touches them (before
   !> each factorization; no-op serially).
   subroutine isys_sum_entries(sys)
      type(implicit_system_t), intent(inout) :: sys
      call ipar_assemble(sys%par, sys%k)
   end subroutine isys_sum_entries

   !> Every rank's x in rank order (the end-of-run report; [x] serially).
   function isys_per_rank(x) result(v)
      real(wp), intent(in) :: x
      real(wp), allocatable :: v(:)
      v = ipar_per_rank(x)
   end function isys_per_rank

   !> MPI: the whole tangent on every rank (the singular-stiffness diagnosis).
   subroutine isys_global(sys)
      type(implicit_system_t), intent(inout) :: sys
      call ipar_global(sys%par, sys%k)
   end subroutine isys_global
end module dx_implicit_system
