!> Restart dumps of a running model (*DATABASE_BINARY_D3DUMP, *DATABASE_BINARY_RUNRSF, and
!> the dumps written on a signal, at the wall-clock limit or on a numerical failure) and
!> their restore. A dump holds everything the explicit loop carries from one cycle to the
!> next, taken at the top of a cycle, so a continued run repeats the uninterrupted run
!> bit for bit: x, v, time, cycle, the loop state model%run (dt(n-1/2), the work sums, the
!> next output times, the output-file sizes), the energies, every element block's state
!> (sig, hv, relvol, eint, ehg, hgs, ework, failed), the elements' added mass of mass
!> scaling (added_mass, with DT2MS only), the rigid-wall forces, the rigid bodies
!> (dx_rigid_restart) and the contact interfaces (dx_contact_restart). What the deck
!> defines (mesh, mass, materials, curves, loads) is rebuilt from the deck, as LS-DYNA's
!> full-deck restart does (Keyword User's Manual Vol. I, "Restart Input Data").
!> File layout and checksums: dx_restart_file. The list of datasets: docs/output-format.md.
!>
!> Adding a model component with persistent state (rigid bodies, contact, ...): write one
!> dump routine and one restore routine next to the component (taking a rs_file_t and the
!> component, using rs%put / rs%get with names prefixed by the component, e.g.
!> 'rigid_x'), and add one line to each of dump_components and restore_components below.
module dx_restart
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_model, only: model_t, MAX_ES, ES_NAMES, ES_DUMP
   use dx_restart_file, only: rs_file_t, rs_create, rs_commit, rs_open, rs_close
   use dx_rigid_restart, only: rigid_dump, rigid_restore
   use dx_contact_restart, only: contact_dump, contact_restore
   use dx_emc_restart, only: emc_dump, emc_restore
   implicit none
   private
   public :: restart_write, restart_read

contains

   !> Write the dump of model to path (atomically). kind: 'd3dump', 'runrsf', 'signal',
   !> 'walltime', 'failure' (recorded; a 'failure' dump is not a clean cycle boundary).
   subroutine restart_write(model, path, kind, error)
      type(model_t), intent(in) :: model
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      type(rs_file_t) :: rs
      call rs_create(rs, path, 'dynx')
      call rs%put('kind_clean', merge(0, 1, kind == 'failure'))
      call rs%put('nn', model%nn)
      call rs%put('ne', model%ne)
      call rs%put('nblocks', size(model%blocks))
      call dump_components(rs, model)
      call rs_commit(rs, error)
   end subroutine restart_write

   !> Restore the state of model (built from the same deck, init_state done) from path.
   subroutine restart_read(model, path, error)
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      type(rs_file_t) :: rs
      type(error_t), allocatable :: e
      integer :: nn, ne, nb, clean
      call rs_open(rs, path, error)
      if (allocated(error)) return
      nn = -1; ne = -1; nb = -1; clean = 0
      call rs%get('nn', nn)
      call rs%get('ne', ne)
      call rs%get('nblocks', nb)
      call rs%get('kind_clean', clean)
      if (rs%ok()) then
         if (nn /= model%nn .or. ne /= model%ne .or. nb /= size(model%blocks)) then
            call set_error(error, 'restart file '//path//' is a dump of another model ('// &
               str(nn)//' nodes, '//str(ne)//' elements, '//str(nb)//' blocks; this deck has '// &
               str(model%nn)//', '//str(model%ne)//', '//str(size(model%blocks))//')', EXIT_INPUT)
         else if (clean /= 1) then
            call set_error(error, 'restart file '//path//' was written at a numerical '// &
               'failure, in the middle of a cycle; continue from the last d3dump/runrsf '// &
               'dump instead', EXIT_INPUT)
         end if
      end if
      if (.not. allocated(error)) call check_components(rs, model, path, error)
      if (allocated(error)) then
         call rs_close(rs, e); return
      end if
      call restore_components(rs, model)
      call rs_close(rs, error)
   end subroutine restart_read

   !> The dump and the deck must have the same components with state: a dump with rigid
   !> bodies or contact restored into a deck without them (or the reverse) is an input
   !> error naming both files and what differs (the mesh checks alone let it through).
   subroutine check_components(rs, model, path, error)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      call one('rigid_nbodies', allocated(model%rigid), 'rigid bodies (*MAT_RIGID, '// &
               '*CONSTRAINED_NODAL_RIGID_BODY)')
      if (.not. allocated(error)) call one('contact_ninterfaces', allocated(model%contact), &
                                            'contact interfaces (*CONTACT_...)')
   contains
      subroutine one(dataset, in_deck, what)
         character(*), intent(in) :: dataset, what
         logical, intent(in) :: in_deck
         logical :: in_dump
         in_dump = rs%has(dataset)
         if (in_dump .eqv. in_deck) return
         if (in_dump) then
            call set_error(error, 'restart file '//path//' holds the state of '//what// &
               ', but the deck '//model%deck_file//' has none; continue it with the deck '// &
               'the dump was written from', EXIT_INPUT)
         else
            call set_error(error, 'the deck '//model%deck_file//' has '//what// &
               ', but restart file '//path//' holds no state of them (a dump of a deck '// &
               'without them); continue it with the deck the dump was written from', EXIT_INPUT)
         end if
      end subroutine one
   end subroutine check_components

   !> Every component with state, in a fixed order. New components: one line each.
   subroutine dump_components(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      call dump_run(rs, model)
      call dump_nodes(rs, model)
      call dump_blocks(rs, model)
      ! mass scaling: the elements' added mass (a dump without it, as every dump before it
      ! and every run without DT2MS: none added)
      if (allocated(model%added_mass)) call rs%put('added_mass', model%added_mass)
      if (allocated(model%walls)) call dump_walls(rs, model)
      if (allocated(model%rigid)) call rigid_dump(rs, model%rigid)
      if (allocated(model%contact)) call contact_dump(rs, model%contact)
      if (allocated(model%emc)) call emc_dump(rs, model%emc)
      ! 2D contact (serial): last cycle's forces and velocities, its step, the work so far
      if (allocated(model%contact2d)) then
         if (allocated(model%contact2d%fold)) then
            call rs%put('contact2d_fold', model%contact2d%fold)
            call rs%put('contact2d_vold', model%contact2d%vold)
            call rs%put('contact2d_dtold', model%contact2d%dtold)
            call rs%put('contact2d_work', model%contact2d%work)
            ! the soft constraint's step (only with ISTIFF = 1: other dumps unchanged)
            if (any(model%contact2d%iface(:)%istiff == 1)) &
               call rs%put('contact2d_dtsoft', model%contact2d%dtsoft)
         end if
      end if
   end subroutine dump_components

   subroutine restore_components(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      call restore_run(rs, model)
      call restore_nodes(rs, model)
      call restore_blocks(rs, model)
      ! (the global model of an MPI run continuing a serial dump has none allocated yet)
      if (rs%has('added_mass') .and. .not. allocated(model%added_mass) .and. &
          model%ctrl%dt2ms /= 0.0_wp) &
         allocate(model%added_mass(model%ne))
      if (allocated(model%added_mass)) then
         model%added_mass = 0.0_wp
         if (rs%has('added_mass')) call rs%get('added_mass', model%added_mass)
      end if
      if (allocated(model%walls)) call restore_walls(rs, model)
      if (allocated(model%rigid)) call rigid_restore(rs, model%rigid)
      if (allocated(model%contact)) call contact_restore(rs, model%contact)
      if (allocated(model%emc)) call emc_restore(rs, model%emc)
      if (allocated(model%contact2d)) then
         if (rs%has('contact2d_fold')) then    ! (a dump before the first contact pass: none)
            associate (c => model%contact2d)
               if (.not. allocated(c%fold)) allocate(c%fc(2, model%nn), c%fold(2, model%nn), &
                                                     c%vold(2, model%nn))
               c%fc = 0.0_wp
               call rs%get('contact2d_fold', c%fold)
               call rs%get('contact2d_vold', c%vold)
               call rs%get('contact2d_dtold', c%dtold)
               call rs%get('contact2d_work', c%work)
               if (rs%has('contact2d_dtsoft')) call rs%get('contact2d_dtsoft', c%dtsoft)
            end associate
         end if
      end if
   end subroutine restore_components

   ! ------------------------------------------------------------- loop state
   subroutine dump_run(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      associate (r => model%run)
         call rs%put('run_dt_old', r%dt_old)
         call rs%put('run_dt_first', r%dt_first)
         call rs%put('run_tsmin', r%tsmin)
         call rs%put('run_wext', r%wext)
         call rs%put('run_wrw', r%wrw)
         call rs%put('run_wcon', r%wcon)
         call rs%put('run_wdep', r%wdep)
         call rs%put('run_next_plot', r%next_plot)
         call rs%put('run_next_glstat', r%next_glstat)
         call rs%put('run_next_nodout', r%next_nodout)
         call rs%put('run_next_status', r%next_status)
         call rs%put('run_nplot', r%nplot)
         call rs%put('run_ndump', r%ndump)
         call rs%put('run_nrunrsf', r%nrunrsf)
         call rs%put('run_glstat_bytes', r%glstat_bytes)
         call rs%put('run_nodout_bytes', r%nodout_bytes)
         ! (only when the deck asks for the file: the dumps of the other decks stay as
         ! they were; a dump without them reads as 'none written')
         call put_file(rs, 'matsum', model%db%matsum_dt, r%next_matsum, r%matsum_bytes)
         call put_file(rs, 'spcforc', model%db%spcforc_dt, r%next_spcforc, r%spcforc_bytes)
         call put_file(rs, 'sleout', model%db%sleout_dt, r%next_sleout, r%sleout_bytes)
         call put_file(rs, 'elout', model%db%elout_dt, r%next_elout, r%elout_bytes)
         call put_file(rs, 'ncforc', model%db%ncforc_dt, r%next_ncforc, r%ncforc_bytes)
         call rs%put('run_energy_guard', r%guard)
      end associate
      call rs%put('time', model%time)
      call rs%put('dt', model%dt)
      call rs%put('cycle', model%cycle)
      call rs%put('dt_elem', model%dt_elem)
      associate (en => model%energy)
         call rs%put('energy', [en%kinetic, en%internal, en%hourglass, en%external_work, &
                                en%rigidwall, en%total, en%initial, en%ratio, en%momentum, en%mass, &
                                en%sliding])
      end associate
   end subroutine dump_run

   !> An ASCII output file's next time and bytes ('run_next_<name>', 'run_<name>_bytes'),
   !> only when the deck asks for the file (dt > 0): the dumps of the other decks stay as
   !> they were.
   subroutine put_file(rs, name, dt, next, bytes)
      type(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(in) :: dt, next
      integer(8), intent(in) :: bytes
      if (.not. (dt > 0.0_wp)) return
      call rs%put('run_next_'//name, next)
      call rs%put('run_'//name//'_bytes', bytes)
   end subroutine put_file

   !> put_file's pair back; a dump without them (older, or the deck asked for none): none
   !> written (0, 0).
   subroutine get_file(rs, name, next, bytes)
      type(rs_file_t), intent(inout) :: rs
      character(*), intent(in) :: name
      real(wp), intent(out) :: next
      integer(8), intent(out) :: bytes
      next = 0.0_wp; bytes = 0
      if (rs%has('run_next_'//name)) call rs%get('run_next_'//name, next)
      if (rs%has('run_'//name//'_bytes')) call rs%get('run_'//name//'_bytes', bytes)
   end subroutine get_file

   subroutine restore_run(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      real(wp) :: en(13)
      associate (r => model%run)
         call rs%get('run_dt_old', r%dt_old)
         call rs%get('run_dt_first', r%dt_first)
         call rs%get('run_tsmin', r%tsmin)
         call rs%get('run_wext', r%wext)
         call rs%get('run_wrw', r%wrw)
         call rs%get('run_wcon', r%wcon)
         if (rs%has('run_wdep')) call rs%get('run_wdep', r%wdep)   ! (older dumps: none)
         call rs%get('run_next_plot', r%next_plot)
         call rs%get('run_next_glstat', r%next_glstat)
         call rs%get('run_next_nodout', r%next_nodout)
         call rs%get('run_next_status', r%next_status)
         call rs%get('run_nplot', r%nplot)
         call rs%get('run_ndump', r%ndump)
         call rs%get('run_nrunrsf', r%nrunrsf)
         call rs%get('run_glstat_bytes', r%glstat_bytes)
         call rs%get('run_nodout_bytes', r%nodout_bytes)
         call get_file(rs, 'matsum', r%next_matsum, r%matsum_bytes)   ! (older dumps: none)
         call get_file(rs, 'spcforc', r%next_spcforc, r%spcforc_bytes)
         call get_file(rs, 'sleout', r%next_sleout, r%sleout_bytes)
         call get_file(rs, 'elout', r%next_elout, r%elout_bytes)
         call get_file(rs, 'ncforc', r%next_ncforc, r%ncforc_bytes)
         r%guard = 0.0_wp       ! (a dump written before the guard was carried: not judged
         if (rs%has('run_energy_guard')) call rs%get('run_energy_guard', r%guard)  ! 1 cycle)
         r%started = rs%ok()
      end associate
      call rs%get('time', model%time)
      call rs%get('dt', model%dt)
      call rs%get('cycle', model%cycle)
      call rs%get('dt_elem', model%dt_elem)
      en = 0.0_wp
      call rs%get('energy', en)
      associate (e => model%energy)
         e%kinetic = en(1); e%internal = en(2); e%hourglass = en(3); e%external_work = en(4)
         e%rigidwall = en(5); e%total = en(6); e%initial = en(7); e%ratio = en(8)
         e%momentum = en(9:11); e%mass = en(12); e%sliding = en(13)
      end associate
   end subroutine restore_run

   ! ------------------------------------------------------------- nodes
   subroutine dump_nodes(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      call rs%put('x', model%x)
      call rs%put('v', model%v)
      if (allocated(model%w)) call rs%put('w', model%w)   ! shells: angular velocities
   end subroutine dump_nodes

   subroutine restore_nodes(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      call rs%get('x', model%x)
      call rs%get('v', model%v)
      if (allocated(model%w)) call rs%get('w', model%w)
   end subroutine restore_nodes

   ! ------------------------------------------------------------- element blocks
   subroutine dump_blocks(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      integer :: b, s, c
      character(:), allocatable :: p
      do b = 1, size(model%blocks)
         p = 'block'//str(b)//'_'
         associate (blk => model%blocks(b))
            call rs%put(p//'elem', blk%elem)
            call rs%put(p//'sig', blk%sig)
            if (allocated(blk%hv)) call rs%put(p//'hv', blk%hv)
            call rs%put(p//'relvol', blk%relvol)
            call rs%put(p//'eint', blk%eint)
            call rs%put(p//'ehg', blk%ehg)
            do s = 1, MAX_ES      ! the family state, one dataset per slot (hgs, ework)
               c = blk%esc(s)
               if (c > 0 .and. ES_DUMP(s)) &
                  call rs%put(p//trim(ES_NAMES(s)), blk%es(:, c:c + blk%esn(s) - 1))
            end do
            call rs%put(p//'failed', blk%failed)
         end associate
      end do
   end subroutine dump_blocks

   subroutine restore_blocks(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      integer :: b, s, c
      integer, allocatable :: elem(:)
      character(:), allocatable :: p
      do b = 1, size(model%blocks)
         p = 'block'//str(b)//'_'
         associate (blk => model%blocks(b))
            allocate(elem(blk%nel))
            elem = 0
            call rs%get(p//'elem', elem)
            if (rs%ok() .and. any(elem /= blk%elem)) call set_error(rs%err, 'restart file '// &
               rs%path//': element block '//str(b)//' holds other elements than in this deck', &
               EXIT_INPUT)
            deallocate(elem)
            call rs%get(p//'sig', blk%sig)
            if (allocated(blk%hv)) call rs%get(p//'hv', blk%hv)
            call rs%get(p//'relvol', blk%relvol)
            call rs%get(p//'eint', blk%eint)
            call rs%get(p//'ehg', blk%ehg)
            do s = 1, MAX_ES
               c = blk%esc(s)
               if (c > 0 .and. ES_DUMP(s)) &
                  call rs%get(p//trim(ES_NAMES(s)), blk%es(:, c:c + blk%esn(s) - 1))
            end do
            call rs%get(p//'failed', blk%failed)
         end associate
      end do
   end subroutine restore_blocks

   ! ------------------------------------------------------------- rigid walls
   subroutine dump_walls(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(in) :: model
      integer :: k
      real(wp), allocatable :: f(:, :)
      allocate(f(3, size(model%walls)))
      do k = 1, size(model%walls)
         f(:, k) = model%walls(k)%force
      end do
      call rs%put('rigidwall_force', f)
   end subroutine dump_walls

   subroutine restore_walls(rs, model)
      type(rs_file_t), intent(inout) :: rs
      type(model_t), intent(inout) :: model
      integer :: k
      real(wp), allocatable :: f(:, :)
      allocate(f(3, size(model%walls)))
      f = 0.0_wp
      call rs%get('rigidwall_force', f)
      do k = 1, size(model%walls)
         model%walls(k)%force = f(:, k)
      end do
   end subroutine restore_walls
end module dx_restart
