!> The MPI engine (ParaDyn step 5; docs/history.md): what `mpirun -np NP bin/dynx` adds to the
!> serial explicit loop. Every rank reads the deck and builds the serial model, reads its rank
!> file (dynx-part; or rank 0 partitions when none exists) and turns the model into its
!> sub-model (dx_par_model: the pieces of the serial element blocks, its nodes, one slot node
!> per shared element corner, its SPCs and prescribed motions). The loop then makes, per cycle:
!> one shared-node force exchange in fixed serial order (par_shared_sum), one MINLOC for the
!> stable step. Energies, momentum, the initial kinetic energy, the total and added mass and
!> the constraint, rigid-wall and external work are exact sums (dx_repro_sum, the long
!> accumulator; dx_energy_exact): each rank adds the terms of its owned nodes and of its
!> elements, formed by the serial code, and one int64 MPI_Allreduce per output event (per
!> up to NBUF_MAX cycles for the work sums) gives every rank the exact sums rounded once, so
!> the parallel run reproduces the serial one bit for bit (NP = 1..4 regression cases,
!> zero tolerance) with nothing gathered for them (docs/history.md, "Reproducible sums").
!> Output: glstat and nodout are written by rank 0 from the nodal state gathered into the
!> global model; plot states are written by every rank into its own part file (dx_par_plot,
!> no gather) and combined by rank 0 at the end into the serial d3plot.h5 + d3plot.xdmf.
!> Failures: a failure on one rank (negative volume, NaN) is kept and folded into the next
!> dt MINLOC (dt = -1, key = the rank), so every rank learns it at no extra cost, receives
!> the message, writes the last plot state and stops with the serial run's exit code.
!> Fixed-order sums: the idea of OpenRadioss /PARITH/ON; single exchange per cycle: ParaDyn
!> (Hoover et al., LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed).
!> No module state: the global model, the rank's plan and maps are a par_engine_t, a
!> component of the rank's domain (dx_domain_mpi), passed to every procedure here.
!> Set-up (rank files, the sub-model, the end-of-set-up trim) is dx_par_engine_setup.
module dx_par_engine
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp, nv_chunk, huge_wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_model, only: model_t, ES_WORK, WORK_PN, WORK_QBV
   use dx_elout, only: elout_element
   use dx_par, only: par_rank, par_size, par_abort, par_minloc, par_allreduce, &
                     PAR_MAX, par_wtime, PAR_SUM, par_bcast_text, par_bcast_real, par_minloc8, &
                     par_allgather_probe
   use dx_par_plan, only: par_gather_ordered, gather_plan_t, par_gather_values, &
                          par_gather_values_root
   use dx_sort, only: sort_index
   use dx_par_model, only: par_model_t, par_fill_slots, par_exchange_forces, par_exchange_mass
   use dx_rank_submodel, only: rank_local_node
   use dx_energy_sums, only: constraint_terms, rot_node_term
   use dx_energy_exact, only: energy_terms, energy_values, corner_counts, held_status, &
                              exact_mass, exact_initial_ke, work_nsums, work_hit, work_values, &
                              added_mass_sums
   use dx_repro_sum, only: rsum_t, rs_reduce, rs_init, rs_add
   use dx_constraints, only: apply_rigidwalls, wall_hits_t
   use dx_par_contact, only: par_contact_t, par_contact_report
   use dx_par_plot, only: par_plot_t, par_plot_write, par_plot_finish
   implicit none
   private
   public :: par_engine_t, par_engine_on, par_engine_mass, par_engine_initial, par_engine_remass, &
             par_engine_fill, par_engine_dt, par_engine_exchange, par_engine_constraints, &
             par_engine_energies, par_engine_output, par_engine_fail, &
             par_engine_global, par_engine_report, par_engine_defer, &
             par_engine_pending, par_engine_sync_failure, par_engine_plot, &
             par_engine_plot_finish, par_engine_together, par_engine_writer, &
             par_engine_flush_work, par_engine_maps, serial_key, KEY_NONE, NREC_W, &
             par_engine_elout

   type :: int_list_t
      integer, allocatable :: p(:)
   end type int_list_t
   integer, parameter :: NREC_W = 7                   !< cycle, wall (0: constraint), position,
                                                      !< work term, m dv/dtavg (walls)
   integer, parameter :: NBUF_MAX = 32                !< cycles of work terms kept at most
   integer(int64), parameter :: KEY_NONE = 2_int64**53 - 1

   !> The engine's part of a rank's domain (a component of mpi_domain_t): the global model,
   !> the rank's plan and maps, the kept work terms, timers and the failure state.
   type :: par_engine_t
      logical :: on = .false.
      type(model_t), pointer :: g => null()      !< the global model (serial numbering)
      type(par_model_t) :: pm                    !< this rank's sub-model plan
      integer, allocatable :: own(:)             !< owned local nodes
      integer, allocatable :: key_elem(:)        !< serial order key -> global element
      logical, allocatable :: owned(:)           !< (nloc) this rank owns the node
      !> Decks with rotations (shells, beams): rotations, moments and rotary inertia summed
      !> at shared nodes as the forces
      logical :: rot = .false.
      !> Work of the constraints and stonewalls (par_engine_constraints): the rank's
      !> constrained nodes (the explicit loop's cnodes), the serial position of each owned
      !> one (0: not owned), the map of each wall's local node list to its serial positions,
      !> and the records of nonzero terms kept until a sum is needed
      integer, allocatable :: lcn(:), lc_key(:)
      real(wp), allocatable :: lc_term(:)
      type(int_list_t), allocatable :: wall_kg(:)
      type(wall_hits_t) :: hits
      logical :: have_bc = .false.               !< a constrained or wall node anywhere
      real(wp) :: key_mult = 1.0_wp              !< serial positions per (cycle, wall)
      type(rsum_t) :: wbuf                       !< (work_nsums, NBUF_MAX) kept cycle sums
      real(wp), allocatable :: rec(:, :)         !< (set-up allocates it; no longer used)
      integer, allocatable :: elem_loc(:, :)     !< (2, nel) piece and position
      type(gather_plan_t) :: plan_own, plan_elem
      !> root_only: the owned history nodes (nodout rows sent by their owners to rank 0)
      type(gather_plan_t) :: plan_hist
      integer, allocatable :: own_hist(:)        !< local numbers of the owned history nodes
      integer :: nbuf = 0
      !> wall time in the force exchange, the dt reduction, the ordered gathers
      real(wp) :: t_exch = 0.0_wp, t_dt = 0.0_wp, t_gath = 0.0_wp
      type(error_t), allocatable :: pending      !< a failure found here, not yet known to all
      logical :: together = .false.              !< a failure every rank knows (clean stop)
      character(16) :: deck_hash = ''            !< content hash of the deck (restart)
      !> Rank 0 alone holds the global model's nodal state and forms the ordered sums (the
      !> other ranks get the results by MPI_Bcast and free g after set-up): decks without
      !> contact and rigid bodies, whose stages read g's nodal arrays on every rank.
      logical :: root_only = .false.
      logical :: trimmed = .false.
      !> The dt reduction's key names its element: key = serial order key * kmult + element
      !> (kmult = ne + 1 while that stays below 2**53, else 0 and the key_elem table is
      !> kept). Each rank keys its own elements (lel ascending, lkey their serial order keys)
      !> and the element of the last reduction (stale_*: a rank without deformable elements
      !> passes the previous step's element on), so no rank holds a whole-model table for it.
      integer(int64) :: kmult = 0
      integer, allocatable :: lel(:)
      integer(int64), allocatable :: lkey(:)
      integer :: stale_elem = 0
      integer(int64) :: stale_key = 0
   end type par_engine_t

contains

   !> True in an MPI run on more than one rank (after par_engine_setup).
   logical function par_engine_on(eng)
      type(par_engine_t), intent(in) :: eng
      par_engine_on = eng%on
   end function par_engine_on

   !> After init_state's element-major mass scatter: the mass exchange (serial order), slot
   !> masses to zero, and the global mass and its sum as the serial run forms it.
   subroutine par_engine_mass(eng, model)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      integer, allocatable :: keys(:)
      real(wp), allocatable :: vals(:, :)
      if (eng%rot .and. .not. allocated(model%rinert)) then
         ! a rank without a shell or beam (an empty rank: more ranks than elements) takes
         ! part in the rotations' collective sums all the same (init_state's arrays, zero)
         allocate(model%w(3, model%nn), model%mom(3, model%nn), model%rinert(model%nn))
         model%w = 0.0_wp
         if (allocated(model%w0)) model%w = model%w0
         model%mom = 0.0_wp
         model%rinert = 0.0_wp
      end if
      call par_exchange_mass(eng%pm, model%mass)
      call add_node_terms(eng%pm, model%node_mass, model%mass)
      model%mass(eng%pm%nloc + 1:) = 0.0_wp
      call par_gather_ordered(eng%pm%node_global(eng%own), &
                              reshape(model%mass(eng%own), [1, size(eng%own)]), keys, vals)
      eng%g%mass(keys) = vals(1, :)
      if (allocated(model%rinert)) then   ! shells, beams: the rotary inertia as the mass
         call par_exchange_mass(eng%pm, model%rinert)
         call add_node_terms(eng%pm, model%node_rinert, model%rinert)
         model%rinert(eng%pm%nloc + 1:) = 0.0_wp
         call par_gather_ordered(eng%pm%node_global(eng%own), &
                                 reshape(model%rinert(eng%own), [1, size(eng%own)]), keys, vals)
         if (allocated(eng%g%rinert)) deallocate(eng%g%rinert)
         if (allocated(eng%g%w)) deallocate(eng%g%w)
         allocate(eng%g%rinert(eng%g%nn), eng%g%w(3, eng%g%nn))
         eng%g%rinert(keys) = vals(1, :)
         eng%g%w = 0.0_wp
      end if
      ! the total: an exact sum over the owned nodes and the ranks (dx_energy_exact)
      model%energy%mass = exact_mass(model, eng%own, .true.)
      if (allocated(eng%g%rigid)) model%energy%mass = model%energy%mass + eng%g%rigid%mass_corr
      eng%g%energy%mass = model%energy%mass
   end subroutine par_engine_mass

   !> The nodal masses or rotary inertias of their own (*ELEMENT_MASS, *ELEMENT_INERTIA,
   !> beams' NSM; the rank's nodes) added at the shared nodes after their elements' sum,
   !> as lump_mass adds them after the element loop (the exchange replaced the shared
   !> nodes' values, and their own term with them): the serial a = sum + term bit for bit.
   subroutine add_node_terms(pm, term, a)
      type(par_model_t), intent(in) :: pm
      real(wp), allocatable, intent(in) :: term(:)
      real(wp), intent(inout) :: a(:)
      if (.not. allocated(term)) return
      a(pm%shared_local) = a(pm%shared_local) + term(pm%shared_local)
   end subroutine add_node_terms


   !> Mass scaling changed an element's mass (every rank, together; dx_mass_scaling): the
   !> rank's lumped masses (lump_mass: a slot holds its corner's share) summed at the shared
   !> nodes in serial order as at the start, the global copy of the masses (rank 0, or every
   !> rank), and the added totals (model, parts), exact sums over the ranks: bit for bit
   !> the serial run's.
   subroutine par_engine_remass(eng, model)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      real(wp), allocatable :: vals(:, :), gv(:, :)
      call par_exchange_mass(eng%pm, model%mass)
      call add_node_terms(eng%pm, model%node_mass, model%mass)
      model%mass(eng%pm%nloc + 1:) = 0.0_wp
      allocate(vals(1, size(eng%own)), gv(1, size(eng%plan_own%keys)))
      vals(1, :) = model%mass(eng%own)
      if (eng%root_only) then
         call par_gather_values_root(eng%plan_own, vals, gv)
      else
         call par_gather_values(eng%plan_own, vals, gv)
      end if
      if (par_rank() == 0 .or. .not. eng%root_only) eng%g%mass(eng%plan_own%keys) = gv(1, :)
      ! the added total and matsum's +mass per part: exact sums of the rank's elements
      ! over the ranks (dx_energy_exact; nothing gathered), rank 0's global psum
      if (associated(eng%g)) then
         call added_mass_sums(model, .true., eng%g)
      else
         call added_mass_sums(model, .true.)
      end if
   end subroutine par_engine_remass

   !> The initial kinetic energy 1/2 sum m v.v (+ 1/2 I w.w): the owned nodes' terms, an
   !> exact sum over the ranks (dx_energy_exact; nothing gathered), the serial run's bits.
   subroutine par_engine_initial(eng, model)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      model%energy%initial = exact_initial_ke(model, eng%own, .true.)
   end subroutine par_engine_initial

   !> Before the element pass: shared nodes' x and v into their slot nodes.
   subroutine par_engine_fill(eng, model)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      call par_fill_slots(eng%pm, model%x)
      call par_fill_slots(eng%pm, model%v)
      if (allocated(model%w)) call par_fill_slots(eng%pm, model%w)   ! shells
   end subroutine par_engine_fill

   !> The global critical step and its element (the lowest serial order key among equal
   !> minima, as the serial loop's first minimum). A failure kept on a rank (pending) is
   !> folded in as dt = -1 with key = the rank: then every rank returns with error set to
   !> the lowest failing rank's message (par_bcast_text), and dtcrit is not a step.
   !> flags (optional): stop/dump requests of this rank, folded into the same reduction
   !> (largest over the ranks; dx_checkpoint).
   subroutine par_engine_dt(eng, dtcrit, dt_elem, error, flags)
      type(par_engine_t), intent(inout) :: eng
      real(wp), intent(inout) :: dtcrit
      integer, intent(inout) :: dt_elem
      type(error_t), allocatable, intent(inout) :: error
      integer, intent(inout), optional :: flags(:)
      integer(int64) :: key
      real(wp) :: t0
      key = KEY_NONE
      if (dt_elem > 0 .and. dtcrit < huge_wp) then
         key = elem_key(eng, dt_elem)
         if (eng%kmult > 0) key = key*eng%kmult + dt_elem
      end if
      if (allocated(eng%pending)) then
         dtcrit = -1.0_wp
         key = par_rank()
      end if
      t0 = par_wtime()
      call par_minloc8(dtcrit, key, flags)
      eng%t_dt = eng%t_dt + (par_wtime() - t0)
      if (dtcrit < 0.0_wp) then
         call failure_known(eng, int(key), error)
         return
      end if
      ! no deformable element anywhere: the rigid elements' step (as the serial ibmin == 0)
      if (dtcrit >= huge_wp .and. allocated(eng%g%rigid)) dtcrit = eng%g%rigid%dtcrit
      if (key >= KEY_NONE) return
      if (eng%kmult > 0) then
         dt_elem = int(mod(key, eng%kmult))
         eng%stale_key = key/eng%kmult
      else
         if (key <= 0 .or. key > size(eng%key_elem)) return
         dt_elem = eng%key_elem(key)
         eng%stale_key = key
      end if
      eng%stale_elem = dt_elem
   end subroutine par_engine_dt

   !> The serial order key (serial block - 1)*nv_chunk + position of global element e, from
   !> the global model's maps (set-up; rank 0 keeps them).
   integer(int64) function serial_key(eng, e)
      type(par_engine_t), intent(in) :: eng
      integer, intent(in) :: e
      serial_key = int(eng%g%elem_block(e) - 1, int64)*nv_chunk + eng%g%elem_pos(e)
   end function serial_key

   !> The serial order key of element e: one of this rank's elements, or the element the
   !> last reduction named (a rank whose element pass found no deformable element keeps it).
   integer(int64) function elem_key(eng, e)
      type(par_engine_t), intent(in) :: eng
      integer, intent(in) :: e
      integer :: k
      k = rank_local_node(eng%lel, e)        ! (the binary search of an ascending list)
      if (k > 0) then
         elem_key = eng%lkey(k)
      else if (e == eng%stale_elem) then
         elem_key = eng%stale_key
      else if (allocated(eng%g%elem_block)) then
         elem_key = serial_key(eng, e)
      else
         call par_abort('internal error: rank '//str(par_rank())//' has no order key for '// &
                        'element '//str(e)//' (dt reduction)', EXIT_INPUT)
      end if
   end function elem_key

   !> A failure found on this rank alone, in the middle of a cycle: kept until the next dt
   !> reduction (or par_engine_sync_failure) makes it known to every rank. error is
   !> deallocated; the caller carries on with the cycle (its collectives included).
   subroutine par_engine_defer(eng, error)
      type(par_engine_t), intent(inout) :: eng
      type(error_t), allocatable, intent(inout) :: error
      if (.not. allocated(eng%pending)) then
         call move_alloc(error, eng%pending)
      else if (allocated(error)) then
         deallocate(error)
      end if
   end subroutine par_engine_defer

   !> Whether this rank holds a failure not yet known to the others (it then skips its
   !> element pass: its state is no longer meaningful).
   logical function par_engine_pending(eng)
      type(par_engine_t), intent(in) :: eng
      par_engine_pending = allocated(eng%pending)
   end function par_engine_pending

   !> At the last cycle (no further dt reduction): one MINLOC on the failure flag alone.
   subroutine par_engine_sync_failure(eng, error)
      type(par_engine_t), intent(inout) :: eng
      type(error_t), allocatable, intent(inout) :: error
      real(wp) :: x
      integer :: key
      x = 0.0_wp
      key = par_rank()
      if (allocated(eng%pending)) x = -1.0_wp
      call par_minloc(x, key)
      if (x < 0.0_wp) call failure_known(eng, key, error)
   end subroutine par_engine_sync_failure

   !> Every rank: the failure of rank root (its message and exit code), naming the rank.
   subroutine failure_known(eng, root, error)
      type(par_engine_t), intent(inout) :: eng
      integer, intent(in) :: root
      type(error_t), allocatable, intent(inout) :: error
      character(:), allocatable :: msg
      integer :: code
      msg = ''
      code = 0
      if (par_rank() == root) then
         msg = eng%pending%message
         code = eng%pending%code
      end if
      call par_bcast_text(msg, code, root)
      if (allocated(error)) deallocate(error)
      call set_error(error, 'rank '//str(root)//' of '//str(par_size())//': '//msg, code)
      eng%together = .true.
   end subroutine failure_known

   !> Whether the run stops on a failure every rank knows (then every rank writes the last
   !> state and exits with the code after MPI_Finalize, instead of MPI_Abort).
   logical function par_engine_together(eng)
      type(par_engine_t), intent(in) :: eng
      par_engine_together = eng%together
   end function par_engine_together

   !> Whether this rank writes the global files (glstat, nodout, status lines): rank 0.
   logical function par_engine_writer()
      par_engine_writer = par_rank() == 0
   end function par_engine_writer

   !> A plot state: every rank appends its part (no communication).
   subroutine par_engine_plot(eng, plot, model, error)
      type(par_engine_t), intent(inout) :: eng
      type(par_plot_t), intent(inout) :: plot
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: t0
      t0 = par_wtime()
      ! shells turn their stresses by the element frame of x: the slots get this x
      if (allocated(model%w)) call par_fill_slots(eng%pm, model%x)
      call par_plot_write(plot, model, error)
      eng%t_gath = eng%t_gath + (par_wtime() - t0)
   end subroutine par_engine_plot

   !> End of an MPI run, normal or not (every rank): part files closed, rank 0 combines
   !> them into d3plot.h5 + d3plot.xdmf. Call after rank 0 closed its output. failure:
   !> every rank stops on a failure it knows (it then exits without MPI_Abort).
   subroutine par_engine_plot_finish(eng, plot, error, failure)
      type(par_engine_t), intent(inout) :: eng
      type(par_plot_t), intent(inout) :: plot
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: failure
      if (present(failure)) eng%together = eng%together .or. failure
      call par_plot_finish(plot, error)
   end subroutine par_engine_plot_finish

   !> The one shared-node exchange of the cycle: f at shared nodes becomes the serial sum.
   subroutine par_engine_exchange(eng, f)
      type(par_engine_t), intent(inout) :: eng
      real(wp), intent(inout) :: f(:, :)
      real(wp) :: t0
      t0 = par_wtime()
      call par_exchange_forces(eng%pm, f)
      eng%t_exch = eng%t_exch + (par_wtime() - t0)
   end subroutine par_engine_exchange

   !> Rigid walls and the work of constraint and wall forces. Each rank corrects its own
   !> wall nodes (the correction of a node depends on that node alone, and every holder of
   !> a shared node has the same x, v and mass) with the serial apply_rigidwalls, which also
   !> gives each corrected node's work term; constraint_terms gives each constrained node's,
   !> rot_node_term each shell node's constraint moment term. Both are the serial code on
   !> the serial numbers, so the terms of the nodes this rank owns are the serial terms bit
   !> for bit. They go into this cycle's exact sums (dx_energy_exact work_hit: constraint
   !> work, wall work, each wall's resultant force), kept for up to NBUF_MAX cycles; when a
   !> sum is needed (or the buffer is full) one int64 allreduce sums the kept cycles over the
   !> ranks and each cycle's sum is added to wcon, wrw in cycle order, as the serial run
   !> adds its cycle sums (s_constraints): no term travels, nothing per node and cycle.
   subroutine par_engine_constraints(eng, model, vfree, vold, dt, dtavg, wcon, wrw, needed, &
                                     wold)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: vfree(:, :), vold(:, :), dt, dtavg
      real(wp), intent(inout) :: wcon, wrw
      logical, intent(in) :: needed
      real(wp), intent(in), optional :: wold(:, :)
      integer :: i, w, k, nd, c0, ns
      real(wp) :: term
      if (.not. eng%have_bc) return     ! no constrained or wall node anywhere
      ns = work_nsums(wall_count(eng))
      if (eng%nbuf == 0) call rs_init(eng%wbuf, NBUF_MAX*ns)
      eng%nbuf = eng%nbuf + 1
      c0 = (eng%nbuf - 1)*ns
      if (present(wold)) then
         do i = 1, size(eng%own)
            nd = eng%own(i)
            if (rot_node_term(model%rinert(nd), model%mom(:, nd), wold(:, nd), model%w(:, nd), &
                              term)) call rs_add(eng%wbuf, c0 + 1, term)
         end do
      end if
      if (size(eng%lcn) > 0) then
         call constraint_terms(eng%lcn, model%mass, vfree, vold, model%v, dtavg, eng%lc_term)
         do i = 1, size(eng%lcn)
            if (eng%lc_key(i) > 0) call rs_add(eng%wbuf, c0 + 1, eng%lc_term(i))  ! owned
         end do
      end if
      if (allocated(model%walls)) then
         call apply_rigidwalls(model, dt, dtavg, vold, model%v, eng%hits)
         do i = 1, eng%hits%n
            w = eng%hits%wall(i)
            k = eng%hits%k(i)
            if (eng%owned(model%walls(w)%nodes(k))) &
               call work_hit(eng%wbuf, c0, w, eng%hits%val(1:4, i))
         end do
      end if
      if (needed .or. eng%nbuf == NBUF_MAX) call flush_work(eng, wcon, wrw)
   end subroutine par_engine_constraints

   !> The deck's number of rigid walls (the same on every rank).
   integer function wall_count(eng)
      type(par_engine_t), intent(in) :: eng
      wall_count = 0
      if (allocated(eng%g%walls)) wall_count = size(eng%g%walls)
   end function wall_count

   !> Before a restart dump: the kept cycles' work terms into wcon, wrw (the same additions
   !> in the same order as a later flush would make), so the dump holds the sums to date.
   subroutine par_engine_flush_work(eng, wcon, wrw)
      type(par_engine_t), intent(inout) :: eng
      real(wp), intent(inout) :: wcon, wrw
      if (eng%nbuf > 0) call flush_work(eng, wcon, wrw)
   end subroutine par_engine_flush_work

   !> For restart dumps (dx_par_restart): the global model, the global node of each local
   !> node (slot nodes included) and the deck's content hash.
   subroutine par_engine_maps(eng, gp, node_global, hash)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), pointer, intent(out) :: gp
      integer, allocatable, intent(out) :: node_global(:)
      character(16), intent(out) :: hash
      gp => eng%g
      node_global = [eng%pm%node_global, eng%pm%node_global(eng%pm%slot_node)]
      hash = eng%deck_hash
   end subroutine par_engine_maps

   !> The kept cycles' sums over the ranks (one int64 allreduce) into wcon, wrw in cycle
   !> order; the walls' resultant forces become those of the last kept cycle.
   subroutine flush_work(eng, wcon, wrw)
      type(par_engine_t), intent(inout) :: eng
      real(wp), intent(inout) :: wcon, wrw
      type(rsum_t) :: kept
      real(wp), allocatable :: fw(:, :)
      integer :: c, nw, ns, w
      real(wp) :: t0
      t0 = par_wtime()
      nw = wall_count(eng)
      ns = work_nsums(nw)
      kept%a = eng%wbuf%a(:, 1:eng%nbuf*ns)
      call rs_reduce(kept)
      allocate(fw(3, nw))
      do c = 1, eng%nbuf
         call work_values(kept, (c - 1)*ns, nw, wcon, wrw, fw)
      end do
      do w = 1, nw
         eng%g%walls(w)%force = fw(:, w)
      end do
      eng%nbuf = 0
      eng%t_gath = eng%t_gath + (par_wtime() - t0)
   end subroutine flush_work

   !> Energies and momentum of the step (when needed), without gathering: every rank forms
   !> the terms of its owned nodes and of its elements with the serial run's code
   !> (dx_energy_exact energy_terms), adds them exactly (dx_repro_sum), and one int64
   !> MPI_Allreduce gives every rank the exact sums, rounded once: the serial run's bits for
   !> any NP. Erosion: the corner counts of the shared nodes are summed over the ranks by
   !> the slot exchange first (which nodes only eroded elements hold). matsum's part sums
   !> go into the global model's psum where it is allocated (rank 0, which writes matsum).
   !> dfac = (dt(n+1/2) - dt(n-1/2))/4 weighs the element work still to be booked; parts:
   !> matsum is written at this step (the part sums are formed; default .true.).
   subroutine par_engine_energies(eng, model, vold, wsum, erw, dfac, needed, wold, racc, &
                                  parts)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: vold(:, :), wsum, erw, dfac
      logical, intent(in) :: needed
      real(wp), intent(in), optional :: wold(:, :)
      type(rsum_t), intent(in), optional :: racc     !< rigid nodes' terms (dx_rigid_exact)
      logical, intent(in), optional :: parts
      real(wp), allocatable :: alive(:), all(:)
      integer(1), allocatable :: held(:)
      type(rsum_t) :: rs
      real(wp) :: t0
      if (.not. needed) return
      t0 = par_wtime()
      if (model%erodes) then
         call corner_counts(model, alive, all)
         call par_exchange_mass(eng%pm, alive)
         call par_exchange_mass(eng%pm, all)
         held = held_status(alive, all)
      end if
      call energy_terms(model, vold, eng%pm%nloc, eng%pm%slot_node, rs, nodes=eng%own, &
                        wold=wold, held=held, racc=racc, parts=parts)
      call rs_reduce(rs)
      if (associated(eng%g)) then
         call energy_values(model, rs, dfac, wsum, erw, eng%g)
      else
         call energy_values(model, rs, dfac, wsum, erw)
      end if
      if (associated(eng%g)) eng%g%energy = model%energy
      eng%t_gath = eng%t_gath + (par_wtime() - t0)
   end subroutine par_engine_energies

   !> The global model for the history writers at this step; writer is true on rank 0,
   !> which writes them. kind (dx_solver's history kinds: 1 glstat, 2 nodout, 3 matsum,
   !> 4 spcforc, 5 sleout, 6 elout, 7 ncforc; absent: all nodes) says what is gathered into
   !> it when rank 0 alone writes (root_only: no contact, no rigid bodies): glstat, matsum,
   !> sleout and elout read no nodal x, v, f (energies are exact sums, dx_energy_exact), so
   !> nothing; nodout only the rows of the history nodes, each sent by its owner (plan_hist,
   !> O(history nodes)); spcforc and ncforc x, v, f of every node. Decks with contact or
   !> rigid bodies gather every node to every rank at each event as before (their global
   !> copy also serves the contact stage). Plot states do not come here (par_engine_plot:
   !> per-rank part files); plot is kept for the interface and not used.
   subroutine par_engine_output(eng, model, plot, om, writer, kind)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(in) :: model
      logical, intent(in) :: plot
      type(model_t), pointer, intent(out) :: om
      logical, intent(out) :: writer
      integer, intent(in), optional :: kind
      real(wp) :: t0
      integer :: k
      t0 = par_wtime()
      eng%g%time = model%time
      eng%g%cycle = model%cycle
      eng%g%dt = model%dt
      eng%g%dt_elem = model%dt_elem
      eng%g%energy = model%energy
      eng%g%run = model%run
      k = 0
      if (present(kind) .and. eng%root_only) k = kind   ! (contact, rigid: every node, as before)
      select case (k)
      case (1, 3, 5, 6)                 ! no nodal values read
      case (2)
         if (eng%root_only) then
            call gather_nodal(eng%plan_hist, eng%own_hist)
         else
            call gather_nodal(eng%plan_own, eng%own)
         end if
      case default
         call gather_nodal(eng%plan_own, eng%own)
      end select
      om => eng%g
      writer = par_rank() == 0
      eng%t_gath = eng%t_gath + (par_wtime() - t0)
   contains
      !> x, v, f of the local nodes nodes into g at plan's global keys (rank 0, or every
      !> rank when not root_only).
      subroutine gather_nodal(plan, nodes)
         type(gather_plan_t), intent(in) :: plan
         integer, intent(in) :: nodes(:)
         real(wp), allocatable :: vals(:, :), gv(:, :)
         integer :: i
         allocate(vals(9, size(nodes)), gv(9, size(plan%keys)))
         do i = 1, size(nodes)
            vals(1:3, i) = model%x(:, nodes(i))
            vals(4:6, i) = model%v(:, nodes(i))
            vals(7:9, i) = model%f(:, nodes(i))
         end do
         if (eng%root_only) then
            call par_gather_values_root(plan, vals, gv)
         else
            call par_gather_values(plan, vals, gv)
         end if
         if (par_rank() == 0 .or. .not. eng%root_only) then
            if (.not. allocated(eng%g%x)) then   ! (root-only decks: from the first event)
               allocate(eng%g%x(3, eng%g%nn), eng%g%v(3, eng%g%nn), eng%g%f(3, eng%g%nn))
               eng%g%x = eng%g%x0
               eng%g%v = eng%g%v0
               eng%g%f = 0.0_wp
            end if
            eng%g%x(:, plan%keys) = gv(1:3, :)
            eng%g%v(:, plan%keys) = gv(4:6, :)
            eng%g%f(:, plan%keys) = gv(7:9, :)
         end if
      end subroutine gather_nodal
   end subroutine par_engine_output

   !> elout (*DATABASE_HISTORY_SOLID): every local element's mean stress and effective
   !> plastic strain (dx_elout elout_element, the serial values' very arithmetic) gathered
   !> to rank 0 in the serial numbering, the history elements' picked into the global
   !> model's db%elout_vals. Collective: every rank calls it.
   subroutine par_engine_elout(eng, model)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(in) :: model
      real(wp), allocatable :: vals(:, :), gv(:, :), ga(:, :)
      integer :: i, j
      real(wp) :: t0
      t0 = par_wtime()
      allocate(vals(7, size(eng%elem_loc, 2)), gv(7, size(eng%plan_elem%keys)))
      do i = 1, size(eng%elem_loc, 2)
         associate (pb => model%blocks(eng%elem_loc(1, i)))
            call elout_element(pb, eng%elem_loc(2, i), &
                               model%mats(model%parts(pb%ipart)%imat)%m%hv_eps_p, vals(:, i))
         end associate
      end do
      call par_gather_values_root(eng%plan_elem, vals, gv)
      if (par_rank() == 0) then
         allocate(ga(7, model%ne))
         ga(:, eng%plan_elem%keys) = gv
         do j = 1, size(eng%g%db%hist_solids)
            eng%g%db%elout_vals(:, j) = ga(:, eng%g%db%hist_solids(j))
         end do
      end if
      eng%t_gath = eng%t_gath + (par_wtime() - t0)
   end subroutine par_engine_elout

   !> End of an MPI run: the time spent in communication (largest over the ranks).
   subroutine par_engine_report(eng, contact)
      type(par_engine_t), intent(inout) :: eng
      type(par_contact_t), intent(in) :: contact
      real(wp) :: t(3), tavg(3)
      if (.not. eng%on) return
      call par_contact_report(contact, eng%g)
      t = [eng%t_exch, eng%t_dt, eng%t_gath]
      tavg = t
      call par_allreduce(t, PAR_MAX)
      call par_allreduce(tavg, PAR_SUM)
      tavg = tavg/real(par_size(), wp)
      call log_info('dynx: MPI on '//str(par_size())//' ranks: force exchange '// &
         rstr(t(1), 4)//' s (mean '//rstr(tavg(1), 4)//'), dt reduction '//rstr(t(2), 4)// &
         ' s (mean '//rstr(tavg(2), 4)//'), ordered gathers '//rstr(t(3), 4)//' s (mean '// &
         rstr(tavg(3), 4)//'), largest over the ranks')
   end subroutine par_engine_report

   !> The global model (serial numbering) of an MPI run: what rank 0 opens the output with.
   function par_engine_global(eng) result(p)
      type(par_engine_t), intent(in) :: eng
      type(model_t), pointer :: p
      p => eng%g
   end function par_engine_global

   !> A failure on this rank alone that cannot wait (an I/O error): stop every rank, naming it.
   subroutine par_engine_fail(error)
      type(error_t), intent(in) :: error
      call par_abort(error%message, error%code)
   end subroutine par_engine_fail
end module dx_par_engine
