!> Plot output of an MPI run (ParaDyn step 5; docs/history.md, docs/output-format.md): each
!> rank writes its owned nodes and its elements to its own part file (dx_plot_part) at every
!> plot time, with no gather (rank 0 then publishes the state for live viewing, reading the
!> ranks' state files: plot_live_t); at the end of the run (normal or after a failure) rank 0
!> combines the parts into d3plot.h5 + d3plot.xdmf, equal to the serial run's files.
!> Per-processor plot files merged after the run: ParaDyn (Hoover et al., LLNL Engineering
!> Thrust Area Report FY97, article 4 of shared/seed).
!> The part file is created at the first plot state (from the mesh kept by par_plot_setup),
!> or continued by par_plot_resume (a restart: states after the dump removed).
!> No module state: the rank's part file and its node/element maps are a par_plot_t, a
!> component of the rank's domain (dx_domain_mpi).
module dx_par_plot
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_h5, only: h5_file_t, h5_open_read, h5_close, h5_read, h5_read_attr
   use dx_xdmf, only: state_group
   use dx_strings, only: str
   use dx_log, only: log_info
   use dx_model, only: model_t, family_t, element_family, elem_stress_global, &
                       beam_resultants, is_beam
   use dx_par, only: par_rank, par_size, par_barrier, par_allreduce, PAR_MAX
   use dx_io_sys, only: sys_mkdir_p, sys_epoch_seconds
   use dx_plot_hdf5, only: element_average, plot_merge_states, plot_rows, element_damage, &
                           block_damage_slot, element_thickness
   use dx_plot_part, only: plot_part_t, plot_combine, plot_live_t
   use dx_plot_states, only: states_link_all
   use dx_plot_fields, only: plot_state_t, plot_state_alloc, plot_state_read, field_in_part, &
                             PLOT_FIELDS, NSTATE_FIELDS, CENTRE_NODE, F_COORD, F_VEL, &
                             F_STRESS, F_EPSP, F_FAILED, F_DAMAGE, F_BEAM_FORCE, F_BEAM_MOMENT, &
                             F_THICK
   use dx_plot_cells, only: cells_width, cell_column
   implicit none
   private
   public :: par_plot_t, par_plot_setup, par_plot_write, par_plot_finish, par_plot_nstates, &
             par_plot_resume, par_plot_from_serial

   !> The plot stage's part of a rank's domain (a component of mpi_domain_t).
   type :: par_plot_t
      type(plot_part_t) :: part
      type(plot_live_t) :: live               !< rank 0: the states published while running
      character(:), allocatable :: dir
      integer, allocatable :: own(:)          !< owned local nodes
      integer, allocatable :: eloc(:, :)      !< (2, nel): block and position of each element
      integer, allocatable :: khv(:)          !< per block: history index of eff. plastic strain
      logical :: finished = .false.
      !> the part's mesh until the file is created (first state): nodes, labels, elements
      integer, allocatable :: m_nodes(:), m_nids(:), m_elems(:), m_cells(:, :), m_eids(:), &
                              m_pids(:)
      real(wp), allocatable :: m_x0(:, :)
      integer :: m_stamp = 0, m_nn = 0, m_ne = 0
      character(:), allocatable :: m_title
   end type par_plot_t

contains

   !> Prepare this rank's part file in outdir (created at the first state). node_global(l) is
   !> the global node of local node l <= nloc; slot node nloc + s stands for local node
   !> slot_node(s); own are the owned local nodes; elem_loc(:, i) = (block, position) of the
   !> rank's elements. g is the global model (labels, parts, title).
   subroutine par_plot_setup(pp, model, g, nloc, node_global, slot_node, owned_nodes, &
                             elem_loc, outdir, error)
      type(par_plot_t), intent(inout) :: pp
      type(model_t), intent(in) :: model, g
      integer, intent(in) :: nloc, node_global(:), slot_node(:), owned_nodes(:), elem_loc(:, :)
      character(*), intent(in) :: outdir
      type(error_t), allocatable, intent(out) :: error
      integer, allocatable :: elems(:), cells(:, :), eids(:), pids(:), l2g(:)
      integer :: i, b, j, e, stamp, imat
      integer(8) :: clk
      character(:), allocatable :: title
      pp%dir = outdir
      pp%own = owned_nodes
      pp%eloc = elem_loc
      pp%finished = .false.
      allocate(pp%khv(size(model%blocks)))
      do b = 1, size(model%blocks)
         imat = model%parts(model%blocks(b)%ipart)%imat
         pp%khv(b) = model%mats(imat)%m%hv_eps_p
      end do
      l2g = [node_global(1:nloc), node_global(slot_node)]
      allocate(elems(size(pp%eloc, 2)), cells(cells_width(g), size(pp%eloc, 2)), &
               eids(size(pp%eloc, 2)), &
               pids(size(pp%eloc, 2)))
      do i = 1, size(pp%eloc, 2)
         b = pp%eloc(1, i); j = pp%eloc(2, i)
         e = model%blocks(b)%elem(j)
         elems(i) = e
         cells(:, i) = cell_column(size(cells, 1), model%blocks(b)%etype, &
                                   l2g(model%blocks(b)%conn(:, j)) - 1)
         eids(i) = g%elem_label(e)
         pids(i) = g%parts(g%elem_part(e))%label
      end do
      ! one stamp for all parts of this run: rank 0's clock (seconds and the fine counter)
      stamp = 0
      if (par_rank() == 0) then
         call system_clock(count=clk)
         stamp = int(modulo(sys_epoch_seconds()*1000003_8 + clk, 2147483647_8))
      end if
      call par_allreduce(stamp, PAR_MAX)
      title = ''
      if (allocated(g%title)) title = g%title
      call sys_mkdir_p(pp%dir, error)
      if (allocated(error)) return
      pp%m_stamp = stamp
      pp%m_title = title
      pp%m_nn = g%nn
      pp%m_ne = g%ne
      pp%m_nodes = node_global(pp%own)
      pp%m_x0 = model%x0(:, pp%own)
      pp%m_nids = model%node_label(pp%own)
      call move_alloc(elems, pp%m_elems)
      call move_alloc(cells, pp%m_cells)
      call move_alloc(eids, pp%m_eids)
      call move_alloc(pids, pp%m_pids)
   end subroutine par_plot_setup

   !> Create the part file with its mesh (at the first state); the kept mesh is freed.
   subroutine create_part(pp, error)
      type(par_plot_t), intent(inout) :: pp
      type(error_t), allocatable, intent(out) :: error
      call pp%part%open(pp%dir, par_rank(), par_size(), pp%m_stamp, pp%m_title, pp%m_nn, &
                        pp%m_ne, pp%m_nodes, pp%m_x0, pp%m_nids, pp%m_elems, pp%m_cells, &
                        pp%m_eids, pp%m_pids, error)
      call free_mesh(pp)
   end subroutine create_part

   subroutine free_mesh(pp)
      type(par_plot_t), intent(inout) :: pp
      if (allocated(pp%m_nodes)) deallocate(pp%m_nodes, pp%m_x0, pp%m_nids, pp%m_elems, &
                                            pp%m_cells, pp%m_eids, pp%m_pids)
   end subroutine free_mesh

   !> A restart of an MPI run: continue this rank's part after its first nkeep states (the
   !> dump's plot-state count); states written after the dump are removed
   !> (dx_plot_part: plot_part_truncate). Every rank calls it, before the first state.
   !> nkeep = 0: nothing to keep, the part is created anew at the first state.
   subroutine par_plot_resume(pp, nkeep, error)
      type(par_plot_t), intent(inout) :: pp
      integer, intent(in) :: nkeep
      type(error_t), allocatable, intent(out) :: error
      if (nkeep <= 0) return
      call pp%part%resume(pp%dir, par_rank(), nkeep, error)
      call free_mesh(pp)
   end subroutine par_plot_resume

   !> A serial run's dump continued on NP ranks: this rank's part is created and gets its
   !> nodes and elements of the first nkeep states of the serial plot file (the
   !> states written before the dump), so the combine at the end gives the file of the
   !> uninterrupted run. Stress (averaged), plastic strain and failed flag are the serial
   !> writer's values; the combine recomputes displacement and invariants from them as the
   !> serial writer did, so the bits agree. Every rank reads OUTDIR/d3plot.h5 (read-only),
   !> before rank 0 replaces it (out%resume).
   subroutine par_plot_from_serial(pp, nkeep, error)
      type(par_plot_t), intent(inout) :: pp
      integer, intent(in) :: nkeep
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      type(error_t), allocatable :: err2
      integer, allocatable :: nodes(:), elems(:)
      real(wp), allocatable :: t(:)
      type(plot_state_t) :: st, sp
      integer :: k, ndisk, nmerged, j
      logical :: there, merge_them
      character(:), allocatable :: gname, h5path
      if (nkeep <= 0) return
      h5path = pp%dir//'/d3plot.h5'
      ! a serial run killed with -9 left its states in d3plot.states/ (no d3plot.h5 yet):
      ! rank 0 merges them first, as bin/dynx-combine would (an error is reported below,
      ! when d3plot.h5 cannot be read)
      if (par_rank() == 0) then
         inquire(file=h5path, exist=there)
         merge_them = .false.
         if (.not. there) inquire(file=pp%dir//'/d3plot.states/mesh.h5', exist=merge_them)
         if (.not. there .and. merge_them) call plot_merge_states(pp%dir, nmerged, err2)
         if (allocated(err2)) deallocate(err2)
      end if
      call par_barrier()
      nodes = pp%m_nodes
      elems = pp%m_elems
      call create_part(pp, error)
      if (allocated(error)) return
      call h5_open_read(f, h5path, error)
      if (allocated(error)) return
      work: block
         call h5_read_attr(f, '/', 'nstates', ndisk, error)
         if (allocated(error)) exit work
         call h5_read(f, '/states/times', t, error)
         if (allocated(error)) exit work
         if (ndisk < nkeep .or. size(t) < nkeep) then
            call set_error(error, 'cannot continue '//h5path//': it has '//str(ndisk)// &
               ' plot states, the restart dump expects '//str(nkeep)// &
               ' (another run''s file?)', EXIT_IO)
            exit work
         end if
         do k = 1, nkeep
            gname = state_group(k)
            call plot_state_read(f, gname, pp%m_nn, pp%m_ne, st, 'cannot continue '// &
                                 h5path//': ', ' (another run''s file?)', error, part=.true.)
            if (allocated(error)) exit work
            ! this rank's nodes and elements of each part field of the schema
            sp%time = st%time
            sp%on = st%on
            do j = 1, NSTATE_FIELDS
               if (.not. field_in_part(j)) cycle
               if (.not. st%on(j)) cycle
               if (PLOT_FIELDS(j)%centre == CENTRE_NODE) then
                  sp%f(j)%r = st%f(j)%r(:, nodes)
               else
                  sp%f(j)%r = st%f(j)%r(:, elems)
               end if
            end do
            call pp%part%write_state(sp, error)
            if (allocated(error)) exit work
         end do
      end block work
      call h5_close(f, err2)
   end subroutine par_plot_from_serial

   !> Append the rank's part of the plot state at model%time; after a barrier rank 0
   !> publishes the state for viewers of the running job (plot_live_t).
   subroutine par_plot_write(pp, model, error)
      type(par_plot_t), intent(inout) :: pp
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      type(plot_state_t) :: st
      type(family_t) :: fam
      integer :: i, b, fl
      if (.not. pp%part%active) then
         call create_part(pp, error)
         if (allocated(error)) return
      end if
      ! the schema's part fields (dx_plot_fields): nodal, then element averages
      call plot_state_alloc(st, size(pp%own), size(pp%eloc, 2), part=.true., &
                            rows=plot_rows(model))
      st%time = model%time
      st%f(F_COORD)%r = model%x(:, pp%own)
      st%f(F_VEL)%r = model%v(:, pp%own)
      do i = 1, size(pp%eloc, 2)
         b = pp%eloc(1, i)
         call element_average(model%blocks(b), pp%eloc(2, i), pp%khv(b), st%f(F_STRESS)%r(:, i), &
                              st%f(F_EPSP)%r(1, i), fl)
         ! shells and beams: the stress of the co-rotational frame in global axes, as the
         ! serial writer (element_results; the slots hold this x: par_engine_plot)
         fam = element_family(model%blocks(b)%etype)
         if (fam%rot) call elem_stress_global(model%blocks(b)%etype, &
            model%x(:, model%blocks(b)%conn(:, pp%eloc(2, i))), st%f(F_STRESS)%r(:, i))
         st%f(F_FAILED)%r(1, i) = real(fl, wp)
         if (st%on(F_DAMAGE)) st%f(F_DAMAGE)%r(1, i) = element_damage(model%blocks(b), &
            pp%eloc(2, i), block_damage_slot(model, model%blocks(b)))
         if (st%on(F_BEAM_FORCE) .and. is_beam(model%blocks(b)%etype)) &
            call beam_resultants(model%blocks(b), pp%eloc(2, i), &
               model%x(:, model%blocks(b)%conn(:, pp%eloc(2, i))), &
               st%f(F_BEAM_FORCE)%r(:, i), st%f(F_BEAM_MOMENT)%r(:, i))
         if (st%on(F_THICK)) st%f(F_THICK)%r(1, i) = element_thickness(model%blocks(b), &
                                                                        pp%eloc(2, i))
      end do
      call pp%part%write_state(st, error)
      ! live viewing (issue 21): once every rank's state file is on disk, rank 0 publishes
      ! the state in the serial layout and the XDMF naming it (dx_plot_part)
      call par_barrier()
      if (allocated(error) .or. par_rank() /= 0) return
      call pp%live%publish(pp%dir, pp%part%nstates, error)
   end subroutine par_plot_write

   !> States this rank's part holds.
   integer function par_plot_nstates(pp)
      type(par_plot_t), intent(in) :: pp
      par_plot_nstates = pp%part%nstates
   end function par_plot_nstates

   !> End of the run (every rank): close the part, then rank 0 combines the parts into
   !> d3plot.h5 + d3plot.xdmf. An error is returned on the rank that had it.
   subroutine par_plot_finish(pp, error)
      type(par_plot_t), intent(inout) :: pp
      type(error_t), allocatable, intent(out) :: error
      integer :: n
      if (pp%finished) return
      pp%finished = .true.
      call pp%part%close(error)
      call par_barrier()           ! every part closed before rank 0 reads them
      if (allocated(error)) return
      if (par_rank() /= 0) return
      ! the live view's whole-model tables are done with: freed before the combine's own
      if (allocated(pp%live%idx)) deallocate(pp%live%idx)
      if (allocated(pp%live%x0)) deallocate(pp%live%x0)
      call plot_combine(pp%dir, n, error)
      if (allocated(error)) return
      ! the published state files become links to d3plot.h5 (a viewer reads on)
      call states_link_all(pp%dir, n, error)
      if (allocated(error)) return
      call log_info('dynx: combined '//str(n)//' plot states of '//str(par_size())// &
                    ' ranks into '//pp%dir//'/d3plot.h5 + d3plot.xdmf')
   end subroutine par_plot_finish
end module dx_par_plot
