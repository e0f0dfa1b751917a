!> Set-up of the MPI engine (ParaDyn step 5; docs/history.md; the cycle is dx_par_engine):
!> every rank reads its rank file (dynx-part; or rank 0 partitions the deck when none exists),
!> turns the serial model into its sub-model (dx_par_model) and sets up the domain's load,
!> rigid-body, contact and plot stages; at the end of set-up what of the global model the
!> run no longer needs is freed (trim_global) and the memory left is logged. Peak memory
!> (issue 22): g's element state is freed as soon as the rank's is copied from it, and for
!> a deck without contact and rigid bodies g's nodal x, v, f exist only on rank 0 and only
!> from the first history event that gathers nodal values (par_engine_output; a serial
!> dump read into g allocates them: dx_par_restart).
!> Fixed-order sums: the idea of OpenRadioss /PARITH/ON; single exchange per cycle: ParaDyn
!> (Hoover et al., LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed).
!> No module state: everything is in the par_engine_t passed in.
module dx_par_engine_setup
   use, intrinsic :: iso_fortran_env, only: int64
   use dx_kinds, only: wp, nv_chunk
   use dx_timer, only: current_memory_kb, peak_memory_kb
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_set_quiet
   use dx_model, only: model_t, elem_block_t, ES_HGS, ES_PHIM
   use dx_par, only: par_rank, par_size, par_allreduce, PAR_MAX, par_allgather_probe
   use dx_par_plan, only: par_gather_setup, par_gather_setup_root
   use dx_sort, only: sort_index
   use dx_par_model, only: par_model_t, par_model_from_file, par_model_fill_state
   use dx_rank_submodel, only: rank_spcs, rank_prescribed, rank_local_node
   use dx_partition, only: partition_t, rank_part_t, partition_model, rank_part, write_report, &
                           has_shells
   use dx_rank_file, only: read_rank_file, write_rank_file, rank_file_name, deck_content_hash
   use dx_io_sys, only: sys_mkdir_p
   use dx_energy_sums, only: constrained_nodes, part_mass_map
   use dx_par_loads, only: par_loads_t, par_loads_setup, par_loads_take_mass
   use dx_element, only: element_mass_share
   use dx_par_rigid, only: par_rigid_t, par_rigid_setup
   use dx_par_contact, only: par_contact_t, par_contact_setup, contact_groups, &
                             write_contact_report
   use dx_par_plot, only: par_plot_t, par_plot_setup
   use dx_par_agree, only: par_agree
   use dx_par_emc, only: par_emc_t, par_emc_setup
   use dx_par_engine, only: par_engine_t, serial_key, KEY_NONE, NREC_W
   implicit none
   private
   public :: par_engine_setup, par_engine_mass_share

contains

   !> Turn the serial model (read by every rank) into this rank's sub-model. The rank file is
   !> partdir/rank_R.h5 when partdir is given, else outdir/rank_R.h5, else rank_R.h5 next
   !> to the deck; when rank_00000.h5 is in none of them, rank 0 partitions the deck (as
   !> dynx-part) into outdir first. Errors that concern one rank abort all ranks. loads and
   !> rigid, plot, contact: the domain's parts of the load, rigid-body, plot and contact
   !> stages (dx_par_loads, dx_par_rigid, dx_par_plot, dx_par_contact); emc: the conserving
   !> solver's split of the slave points (dx_par_emc; a conserving deck stops there).
   subroutine par_engine_setup(eng, model, deck, outdir, partdir, loads, rigid, plot, contact, &
                               emc, error)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: deck, outdir, partdir
      type(par_loads_t), intent(inout) :: loads
      type(par_rigid_t), intent(inout) :: rigid
      type(par_plot_t), intent(inout) :: plot
      type(par_contact_t), intent(inout) :: contact
      type(par_emc_t), intent(inout) :: emc
      type(error_t), allocatable, intent(out) :: error
      type(rank_part_t) :: rp
      character(16) :: hash
      character(:), allocatable :: dir, deckdir
      integer :: np, me, where, k, i
      integer, allocatable :: loc(:)
      logical :: ex
      np = par_size()
      me = par_rank()
      if (np <= 1) return
      call unsupported(model, error)
      if (allocated(error)) return
      if (me > 0) call log_set_quiet(.true.)
      call log_peak('before the MPI set-up (the whole deck read and built on every rank)')
      call deck_content_hash(model%deck_files, hash, error)   ! the files read_deck read
      if (allocated(error)) return
      eng%deck_hash = hash
      k = index(deck, '/', back=.true.)
      deckdir = '.'
      if (k > 0) deckdir = deck(1:k - 1)
      ! rank 0 decides where the files are; the others follow
      where = 0
      if (me == 0) then
         if (len(partdir) > 0) then
            where = 3
         else
            inquire(file=rank_file_name(outdir, 0), exist=ex)
            if (ex) then
               where = 1
            else
               inquire(file=rank_file_name(deckdir, 0), exist=ex)
               if (ex) where = 2
            end if
         end if
      end if
      call par_allreduce(where, PAR_MAX)
      select case (where)
      case (0)
         dir = outdir
         if (me == 0) call partition_here(model, np, hash, deck, dir, error)
         call par_agree(error)          ! rank 0's error (a bad deck, no output dir) stops all
         if (allocated(error)) return
      case (1)
         dir = outdir
      case (2)
         dir = deckdir
      case default
         dir = partdir
      end select
      call log_info('dynx: MPI run on '//str(np)//' ranks, rank files '// &
                    rank_file_name(dir, 0)//' ...')
      call read_rank_file(rank_file_name(dir, me), hash, np, me, rp, error)
      if (.not. allocated(error)) then
         if (size(rp%piece_ptr) == 0) call set_error(error, rank_file_name(dir, me)// &
            ': the rank file holds no sub-model (written without a built model); rerun '// &
            'dynx-part', EXIT_INPUT)
      end if
      call par_agree(error)             ! a missing or wrong rank file: every rank stops
      if (allocated(error)) return
      if (allocated(model%emc)) then   ! conserving solver: whole model, pairs split (dx_par_emc)
         call par_emc_setup(emc, model%emc, model%nn, rp%nodes, rp%node_owner)
         return
      end if
      ! the global model keeps the serial numbering; the rank's model becomes local. The
      ! big arrays move into g (no second copy of the serial model on any rank).
      eng%root_only = .not. (allocated(model%contact) .or. allocated(model%rigid))
      block
         type(elem_block_t), allocatable :: tb(:)
         real(wp), allocatable :: tx0(:, :), tv0(:, :)
         integer, allocatable :: tlab(:)
         call move_alloc(model%blocks, tb)
         call move_alloc(model%x0, tx0)
         call move_alloc(model%v0, tv0)
         call move_alloc(model%node_label, tlab)
         allocate(eng%g)
         eng%g = model
         call move_alloc(tb, eng%g%blocks)
         call move_alloc(tx0, eng%g%x0)
         call move_alloc(tv0, eng%g%v0)
         call move_alloc(tlab, eng%g%node_label)
      end block
      ! g's nodal state: on every rank of a deck with contact or rigid bodies (their stages
      ! read it); for a root-only deck rank 0 allocates it at the first history event that
      ! gathers nodal values (par_engine_output) and the other ranks never hold it (the
      ! masses: par_engine_mass stores them for the loads' shared nodes)
      if (.not. eng%root_only) then
         allocate(eng%g%x(3, eng%g%nn), eng%g%v(3, eng%g%nn), eng%g%f(3, eng%g%nn))
         eng%g%x = eng%g%x0
         eng%g%v = eng%g%v0
         eng%g%f = 0.0_wp
      end if
      allocate(eng%g%mass(eng%g%nn))
      eng%g%mass = 0.0_wp
      ! the sub-model from the rank file alone (format 2: topology, slots, the fixed-order
      ! sum plans, x0, v0, labels); stage 1 of issue 22 takes the element state from the deck
      call par_model_from_file(rp, eng%pm)
      call par_model_fill_state(eng%pm, eng%g, rp)
      ! g's stresses, material history and hourglass forces are the rank's now (nothing of
      ! the set-up below reads g's: freed here, before the rank's own arrays grow)
      do k = 1, size(eng%g%blocks)
         if (allocated(eng%g%blocks(k)%sig)) deallocate(eng%g%blocks(k)%sig)
         if (allocated(eng%g%blocks(k)%hv)) deallocate(eng%g%blocks(k)%hv)
         call eng%g%blocks(k)%es_drop(ES_HGS)
      end do
      call log_submodels(eng%pm, rp)
      allocate(loc(eng%g%nn))
      loc = 0
      loc(rp%nodes) = [(i, i = 1, eng%pm%nloc)]
      model%nn = eng%pm%nloc + eng%pm%nslot
      ! (filled in place: no temporaries of the whole list on the heap)
      allocate(model%node_label(model%nn), model%x0(3, model%nn), model%v0(3, model%nn))
      model%node_label(1:eng%pm%nloc) = rp%node_label
      model%x0(:, 1:eng%pm%nloc) = rp%x0
      model%v0(:, 1:eng%pm%nloc) = rp%v0
      do i = 1, eng%pm%nslot
         model%node_label(eng%pm%nloc + i) = rp%node_label(eng%pm%slot_node(i))
         model%x0(:, eng%pm%nloc + i) = rp%x0(:, eng%pm%slot_node(i))
         model%v0(:, eng%pm%nloc + i) = rp%v0(:, eng%pm%slot_node(i))
      end do
      deallocate(rp%x0, rp%v0, rp%piece_conn)
      if (allocated(eng%g%w0)) model%w0 = reshape([eng%g%w0(:, rp%nodes), &   ! VXR, VYR, VZR
         eng%g%w0(:, rp%nodes(eng%pm%slot_node))], [3, model%nn])
      if (allocated(eng%g%w0)) deallocate(eng%g%w0)   ! (the rank's own copy is enough)
      ! *ELEMENT_MASS, *ELEMENT_INERTIA, beams' NSM: on the rank's nodes (none on a slot;
      ! par_engine_mass adds them at the shared nodes after the sum, as lump_mass does)
      if (allocated(eng%g%node_mass)) model%node_mass = [eng%g%node_mass(rp%nodes), &
         spread(0.0_wp, 1, eng%pm%nslot)]
      if (allocated(eng%g%node_rinert)) model%node_rinert = [eng%g%node_rinert(rp%nodes), &
         spread(0.0_wp, 1, eng%pm%nslot)]
      ! shells and beams: rotations, moments and rotary inertia summed at shared nodes as
      ! the forces
      eng%rot = has_shells(eng%g) .or. allocated(eng%g%node_rinert)
      call move_alloc(eng%pm%blocks, model%blocks)
      ! the rank's SPCs and prescribed motions: its file's records (local nodes)
      if (allocated(model%spcs)) model%spcs = rank_spcs(rp)
      if (allocated(model%prescribed)) model%prescribed = rank_prescribed(rp)
      eng%owned = rp%node_owner == me
      eng%own = pack([(i, i = 1, eng%pm%nloc)], eng%owned)
      call par_loads_setup(loads, model, eng%g, rp, eng%pm, loc, eng%owned)   ! external loads
      call par_rigid_setup(rigid, eng%g, eng%pm, eng%owned)                   ! rigid bodies
      if (allocated(eng%g%contact)) &
         call par_contact_setup(contact, model, eng%g, eng%pm%node_global, eng%owned)
      eng%kmult = int(eng%g%ne, int64) + 1
      if (real(size(eng%g%blocks)*int(nv_chunk, int64) + 1, wp)*real(eng%kmult, wp) >= &
          real(KEY_NONE, wp)) eng%kmult = 0
      if (eng%kmult == 0) then    ! a model too large for the key to carry the element
         allocate(eng%key_elem(size(eng%g%blocks)*nv_chunk))
         eng%key_elem = 0
         do k = 1, size(eng%g%blocks)
            eng%key_elem((k - 1)*nv_chunk + 1:(k - 1)*nv_chunk + eng%g%blocks(k)%nel) = &
               eng%g%blocks(k)%elem
         end do
      end if
      block
         integer :: b, j, n
         integer, allocatable :: ids(:), idx(:)
         n = sum([(model%blocks(b)%nel, b = 1, size(model%blocks))])
         allocate(ids(n))
         n = 0
         do b = 1, size(model%blocks)
            ids(n + 1:n + model%blocks(b)%nel) = model%blocks(b)%elem(1:model%blocks(b)%nel)
            n = n + model%blocks(b)%nel
         end do
         idx = [(j, j = 1, n)]
         call sort_index(idx, ids)
         eng%lel = ids(idx)
         eng%lkey = [(serial_key(eng, eng%lel(j)), j = 1, n)]
      end block
      block
         integer, allocatable :: gcnodes(:), gcpos(:)
         integer :: nb, j, kmax
         call constrained_nodes(eng%g, gcnodes)
         allocate(gcpos(eng%g%nn))
         gcpos = 0
         gcpos(gcnodes) = [(i, i = 1, size(gcnodes))]
         call constrained_nodes(model, eng%lcn)          ! = the explicit loop's cnodes
         allocate(eng%lc_key(size(eng%lcn)), eng%lc_term(size(eng%lcn)))
         eng%lc_key = 0
         do i = 1, size(eng%lcn)
            if (eng%lcn(i) <= eng%pm%nloc) then
               if (eng%owned(eng%lcn(i))) eng%lc_key(i) = gcpos(eng%pm%node_global(eng%lcn(i)))
            end if
         end do
         kmax = size(gcnodes)
         nb = count(eng%lc_key > 0)
         if (allocated(model%walls)) then     ! the rank's wall nodes, in wall order
            allocate(eng%wall_kg(size(model%walls)))
            do k = 1, size(model%walls)
               associate (gn => eng%g%walls(k)%nodes)
                  model%walls(k)%nodes = pack(loc(gn), loc(gn) > 0)
                  eng%wall_kg(k)%p = pack([(j, j = 1, size(gn))], loc(gn) > 0)
                  kmax = max(kmax, size(gn))
                  nb = nb + size(gn)
               end associate
            end do
         end if
         if (eng%rot) then      ! the constraint moments' terms, keyed by global node
            kmax = max(kmax, eng%g%nn)
            nb = nb + 1
         end if
         call par_allreduce(nb, PAR_MAX)
         eng%have_bc = nb > 0
         eng%key_mult = real(kmax, wp) + 1.0_wp
         allocate(eng%rec(NREC_W, 64))
      end block
      if (eng%root_only) then     ! ordered sums and output on rank 0 alone
         call par_gather_setup_root(eng%plan_own, eng%pm%node_global(eng%own))
         call owned_history_nodes(eng, eng%g%db%hist_nodes)      ! nodout rows from owners
         call par_gather_setup_root(eng%plan_hist, eng%pm%node_global(eng%own_hist))
      else
         call par_gather_setup(eng%plan_own, eng%pm%node_global(eng%own))
      end if
      block
         integer :: b, j, n
         integer, allocatable :: ek(:)
         n = sum([(model%blocks(b)%nel, b = 1, size(model%blocks))])
         allocate(eng%elem_loc(2, n), ek(n))
         n = 0
         do b = 1, size(model%blocks)
            do j = 1, model%blocks(b)%nel
               n = n + 1
               eng%elem_loc(:, n) = [b, j]
               ek(n) = model%blocks(b)%elem(j)
            end do
         end do
         call par_gather_setup_root(eng%plan_elem, ek)   ! element energies: rank 0 sums them
      end block
      ! plot states: each rank its own part file (no element data in g any more)
      call par_plot_setup(plot, model, eng%g, eng%pm%nloc, eng%pm%node_global, &
                          eng%pm%slot_node, eng%own, eng%elem_loc, outdir, error)
      call par_agree(error)
      if (allocated(error)) return
      eng%on = .true.
   contains
      !> Rank 0 only: partition the deck into dir as `dynx-part deck -n np -o dir` would.
      subroutine partition_here(model, np, hash, deck, dir, err)
         type(model_t), intent(in) :: model
         integer, intent(in) :: np
         character(*), intent(in) :: hash, deck, dir
         type(error_t), allocatable, intent(out) :: err
         type(partition_t) :: part
         type(rank_part_t) :: rpr
         integer :: r, u, ios
         integer, allocatable :: grp_ptr(:), grp_elem(:), gid(:)
         call log_info('dynx: no rank files in '//dir//' or '//deckdir//': partitioning '// &
                       deck//' into '//str(np)//' ranks (as dynx-part) in '//dir)
         call contact_groups(model, grp_ptr, grp_elem, gid)   ! contact pairs kept whole
         call partition_model(model, np, grp_ptr, grp_elem, part, err)
         if (allocated(err)) return
         call sys_mkdir_p(dir, err)
         if (allocated(err)) return
         do r = 0, np - 1
            call rank_part(model, part, r, rpr, err)
            if (allocated(err)) return
            call write_rank_file(rank_file_name(dir, r), rpr, hash, err)
            if (allocated(err)) return
         end do
         open(newunit=u, file=dir//'/partition.txt', status='replace', action='write', &
              iostat=ios)
         if (ios == 0) then
            call write_report(u, part, deck, hash)
            call write_contact_report(u, part, grp_ptr, grp_elem, gid)
            close(u)
         end if
      end subroutine partition_here
   end subroutine par_engine_setup

   !> eng%own_hist: the owned local nodes (ascending) that are history nodes (hist: the
   !> deck's dense global history nodes, any order, repeats allowed; O(history nodes)).
   subroutine owned_history_nodes(eng, hist)
      type(par_engine_t), intent(inout) :: eng
      integer, allocatable, intent(in) :: hist(:)
      integer, allocatable :: h(:), idx(:)
      logical, allocatable :: keep(:)
      integer :: i
      allocate(keep(size(eng%own)))
      keep = .false.
      if (allocated(hist)) then
         idx = [(i, i = 1, size(hist))]
         call sort_index(idx, hist)
         h = hist(idx)
         do i = 1, size(eng%own)
            keep(i) = rank_local_node(h, eng%pm%node_global(eng%own(i))) > 0
         end do
      end if
      eng%own_hist = pack(eng%own, keep)
   end subroutine owned_history_nodes

   !> One log line (rank 0): the sub-model each rank built from its rank file (nodes,
   !> slot nodes, elements; the first 16 ranks), the O(NP) table rank 0 gathers for it.
   subroutine log_submodels(pm, rp)
      type(par_model_t), intent(in) :: pm
      type(rank_part_t), intent(in) :: rp
      real(wp), allocatable :: rb(:)
      integer, allocatable :: cnt(:)
      character(:), allocatable :: t
      integer :: r
      call par_allgather_probe([real(pm%nloc, wp), real(pm%nslot, wp), &
                                real(size(rp%piece_elem), wp)], rb, cnt)
      t = ''
      do r = 0, min(size(rb)/3, 16) - 1
         t = t//'; rank '//str(r)//': '//str(nint(rb(3*r + 1)))//' nodes, '// &
             str(nint(rb(3*r + 3)))//' elements, '//str(nint(rb(3*r + 2)))//' slots'
      end do
      if (size(rb)/3 > 16) t = t//'; ...'
      call log_info('dynx: distributed set-up (issue 22 stage 1): each rank''s sub-model '// &
                    'built from its rank file alone'//t)
      call log_info('dynx: still replicated (stage 2): every rank reads and builds the '// &
                    'whole deck (tables, element state, segment and body loads, walls, '// &
                    'contact, rigid bodies); energies are exact sums, nodout takes the '// &
                    'owners'' rows (decks without contact or rigid bodies), spcforc, '// &
                    'ncforc and serial restarts go through the global model')
   end subroutine log_submodels

   !> What the engine does not run across ranks yet: exit 2 naming the keyword.
   subroutine unsupported(model, error)
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: what
      what = ''   ! (the conserving solver runs under MPI: dx_par_emc)
      if (model%erodes .and. allocated(model%contact)) what = '*CONTACT_ with element '// &
         'erosion (*MAT_ADD_EROSION or *CONTROL_TIMESTEP ERODE = 1: the contact surfaces '// &
         'after erosion are formed on the serial model only)'
      if (len(what) > 0) call set_error(error, model%deck_file//': '//what// &
         ' is not supported in an MPI run yet; run this deck serially (without mpirun)', &
         EXIT_INPUT)
   end subroutine unsupported

   !> element_mass_share (the element dt bound of one-element-wide blocks) on the rank's
   !> blocks: their slot corners carry no mass (the mass is at the shared node), so each
   !> slot is given its node's mass and constraint flag, as the serial element sees them.
   subroutine par_engine_mass_share(eng, model, cnodes, loads)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(inout) :: model
      type(par_loads_t), intent(inout) :: loads
      integer, intent(in) :: cnodes(:)
      real(wp), allocatable :: mext(:)
      logical, allocatable :: con(:)
      integer, allocatable :: cext(:)
      integer :: b, i
      mext = model%mass
      mext(eng%pm%nloc + 1:eng%pm%nloc + eng%pm%nslot) = model%mass(eng%pm%slot_node)
      allocate(con(model%nn))
      con = .false.
      con(cnodes) = .true.
      con(eng%pm%nloc + 1:eng%pm%nloc + eng%pm%nslot) = con(eng%pm%slot_node)
      cext = pack([(i, i = 1, model%nn)], con)
      do b = 1, size(model%blocks)
         call element_mass_share(model%blocks(b), &
            model%mats(model%parts(model%blocks(b)%ipart)%imat)%m%ro, mext, cext)
      end do
      ! matsum's part shares of the nodal masses, on the global model that rank 0 sums
      if (par_rank() == 0 .and. eng%g%db%matsum_dt > 0.0_wp) call part_mass_map(eng%g)
      call trim_global(eng, model, loads)   ! the last set-up step (after a restart read)
   end subroutine par_engine_mass_share

   !> End of set-up (every rank, once): what of the global model g the run no longer needs
   !> is freed. Ranks other than 0 free g's element arrays (every element's energies go to
   !> rank 0 alone) and, when rank 0 alone forms the ordered sums (root_only: no contact, no
   !> rigid bodies), g's nodal arrays, constraint lists and the element labels: each keeps
   !> its own part plus the index maps of the dt reduction. Rank 0, the gather root, keeps
   !> the nodal state and the element energies it sums, and frees the rest of the elements'
   !> arrays. The sizes left are logged (mem_report).
   subroutine trim_global(eng, model, loads)
      type(par_engine_t), intent(inout) :: eng
      type(model_t), intent(in) :: model
      type(par_loads_t), intent(inout) :: loads
      integer :: k
      if (eng%trimmed) return
      eng%trimmed = .true.
      if (model%dt_elem > 0) then          ! a restart's element of the last reduction
         eng%stale_elem = model%dt_elem
         eng%stale_key = serial_key(eng, eng%stale_elem)
      end if
      do k = 1, size(eng%g%blocks)
         associate (b => eng%g%blocks(k))
            ! (a deck that erodes keeps the connectivity: rank 0 finds the nodes no living
            ! element holds for the eroded kinetic energy, dx_energy_sums)
            if (allocated(b%conn) .and. .not. eng%g%erodes) deallocate(b%conn)
            if (allocated(b%elem)) deallocate(b%elem)
            if (allocated(b%vol0)) deallocate(b%vol0)
            if (allocated(b%relvol)) deallocate(b%relvol)
            call b%es_drop(ES_PHIM)
            call b%es_drop(ES_HGS)
            if (allocated(b%sig)) deallocate(b%sig)
            if (allocated(b%hv)) deallocate(b%hv)
            if (par_rank() > 0) then          ! rank 0 sums the element energies
               if (allocated(b%eint)) deallocate(b%eint)
               if (allocated(b%ehg)) deallocate(b%ehg)
               if (allocated(b%es)) deallocate(b%es)
               b%esc = 0; b%esn = 0
               if (allocated(b%failed)) deallocate(b%failed)
            end if
         end associate
      end do
      if (par_rank() > 0) then
         if (allocated(eng%g%elem_label)) deallocate(eng%g%elem_label)
         if (allocated(eng%g%elem_part)) deallocate(eng%g%elem_part)
         if (allocated(eng%g%elem_block)) deallocate(eng%g%elem_block)   ! rank 0: energies' places
         if (allocated(eng%g%elem_pos)) deallocate(eng%g%elem_pos)
         if (eng%root_only) then
            call par_loads_take_mass(loads)      ! the loads on shared nodes keep their masses
            if (allocated(eng%g%x)) deallocate(eng%g%x)
            if (allocated(eng%g%v)) deallocate(eng%g%v)
            if (allocated(eng%g%f)) deallocate(eng%g%f)
            if (allocated(eng%g%mass)) deallocate(eng%g%mass)
            if (allocated(eng%g%x0)) deallocate(eng%g%x0)
            if (allocated(eng%g%v0)) deallocate(eng%g%v0)
            if (allocated(eng%g%node_label)) deallocate(eng%g%node_label)
            if (allocated(eng%g%spcs)) deallocate(eng%g%spcs)
            if (allocated(eng%g%prescribed)) deallocate(eng%g%prescribed)
            if (allocated(eng%g%w)) deallocate(eng%g%w)            ! shells
            if (allocated(eng%g%rinert)) deallocate(eng%g%rinert)
         end if
      end if
      call mem_report(eng)
      call log_peak('after the MPI set-up')
   end subroutine trim_global

   !> One log line (rank 0; collective): the peak resident memory (VmHWM) so far of rank 0
   !> and the largest of the other ranks, at the point named by when (docs/performance.md
   !> "Distributed memory": where the per-rank peak arises).
   subroutine log_peak(when)
      character(*), intent(in) :: when
      integer(int64) :: a(2)
      a = [peak_memory_kb(), 0_int64]
      if (par_rank() > 0) a = [0_int64, peak_memory_kb()]
      call par_allreduce_i8max(a)
      call log_info('dynx: MPI peak memory (VmHWM) '//when//': rank 0 '//str(int(a(1)))// &
                    ' KiB, the other ranks at most '//str(int(a(2)))//' KiB')
   end subroutine log_peak

   !> Bytes of the arrays this rank holds that are sized by the whole model (global
   !> elements: elem, global nodes: node), in g, the engine's maps and the gather plans.
   subroutine global_bytes(eng, elem, node)
      type(par_engine_t), intent(inout) :: eng
      integer(int64), intent(out) :: elem, node
      integer :: k
      elem = 0
      node = 0
      if (allocated(eng%g%blocks)) then
         do k = 1, size(eng%g%blocks)
            associate (b => eng%g%blocks(k))
               if (allocated(b%conn)) elem = elem + 4*size(b%conn, kind=int64)
               if (allocated(b%elem)) elem = elem + 4*size(b%elem, kind=int64)
               if (allocated(b%sig)) elem = elem + 8*size(b%sig, kind=int64)
               if (allocated(b%hv)) elem = elem + 8*size(b%hv, kind=int64)
               if (allocated(b%vol0)) elem = elem + 8*size(b%vol0, kind=int64)
               if (allocated(b%relvol)) elem = elem + 8*size(b%relvol, kind=int64)
               if (allocated(b%eint)) elem = elem + 8*size(b%eint, kind=int64)
               if (allocated(b%ehg)) elem = elem + 8*size(b%ehg, kind=int64)
               if (allocated(b%es)) elem = elem + 8*size(b%es, kind=int64)
               if (allocated(b%failed)) elem = elem + 4*size(b%failed, kind=int64)
            end associate
         end do
      end if
      if (allocated(eng%g%elem_label)) elem = elem + 4*size(eng%g%elem_label, kind=int64)
      if (allocated(eng%g%elem_part)) elem = elem + 4*size(eng%g%elem_part, kind=int64)
      if (allocated(eng%g%elem_block)) elem = elem + 4*size(eng%g%elem_block, kind=int64)
      if (allocated(eng%g%elem_pos)) elem = elem + 4*size(eng%g%elem_pos, kind=int64)
      if (allocated(eng%key_elem)) elem = elem + 4*size(eng%key_elem, kind=int64)
      if (allocated(eng%plan_elem%keys)) elem = elem + 4*size(eng%plan_elem%keys, kind=int64)
      if (allocated(eng%plan_elem%perm)) elem = elem + 4*size(eng%plan_elem%perm, kind=int64)
      if (allocated(eng%g%x0)) node = node + 8*size(eng%g%x0, kind=int64)
      if (allocated(eng%g%v0)) node = node + 8*size(eng%g%v0, kind=int64)
      if (allocated(eng%g%x)) node = node + 8*size(eng%g%x, kind=int64)
      if (allocated(eng%g%v)) node = node + 8*size(eng%g%v, kind=int64)
      if (allocated(eng%g%f)) node = node + 8*size(eng%g%f, kind=int64)
      if (allocated(eng%g%mass)) node = node + 8*size(eng%g%mass, kind=int64)
      if (allocated(eng%g%node_label)) node = node + 4*size(eng%g%node_label, kind=int64)
      if (allocated(eng%g%w)) node = node + 8*size(eng%g%w, kind=int64)
      if (allocated(eng%g%rinert)) node = node + 8*size(eng%g%rinert, kind=int64)
      if (allocated(eng%plan_own%keys)) node = node + 4*size(eng%plan_own%keys, kind=int64)
      if (allocated(eng%plan_own%perm)) node = node + 4*size(eng%plan_own%perm, kind=int64)
   end subroutine global_bytes

   !> One log line (rank 0) after set-up: the bytes of whole-model arrays on rank 0 and the
   !> largest on any other rank, per element and per node of the model, and the resident
   !> memory (VmRSS) of rank 0 and the largest of the others (docs/performance.md).
   subroutine mem_report(eng)
      type(par_engine_t), intent(inout) :: eng
      integer(int64) :: e, n, mine(4), oth(4)
      call global_bytes(eng, e, n)
      mine = [e, n, current_memory_kb(), 0_int64]
      oth = mine
      if (par_rank() == 0) oth = 0
      call par_allreduce_i8max(oth)
      call log_info('dynx: MPI memory after set-up: whole-model arrays on rank 0: '// &
         rstr(real(mine(1), wp)/max(1, eng%g%ne), 4)//' B/element, '// &
         rstr(real(mine(2), wp)/max(1, eng%g%nn), 4)//' B/node; on the other ranks at most: '// &
         rstr(real(oth(1), wp)/max(1, eng%g%ne), 4)//' B/element, '// &
         rstr(real(oth(2), wp)/max(1, eng%g%nn), 4)//' B/node ('//str(eng%g%ne)//' elements, '// &
         str(eng%g%nn)//' nodes); VmRSS rank 0 '//str(int(mine(3)))//' KiB, others at most '// &
         str(int(oth(3)))//' KiB')
   end subroutine mem_report

   !> Largest over the ranks of 64-bit counts (as doubles: exact below 2**53).
   subroutine par_allreduce_i8max(a)
      integer(int64), intent(inout) :: a(:)
      real(wp) :: r(size(a))
      r = real(a, wp)
      call par_allreduce(r, PAR_MAX)
      a = nint(r, int64)
   end subroutine par_allreduce_i8max

end module dx_par_engine_setup
