!> Plot states in HDF5 (d3plot.h5) plus its XDMF description (d3plot.xdmf), the dynx
!> counterpart of LS-DYNA's *DATABASE_BINARY_D3PLOT. Layout (docs/output-format.md):
!>   /mesh/coordinates (3,nn) f64, node_ids (nn), the cells (dx_plot_cells: one family's
!>   (nen,ne) 0-based, or the XDMF Mixed list), element_ids (ne),
!>   part_ids (ne); file attributes title, nstates
!>   /states/NNNNNN/ (attribute time): coordinates, displacement, velocity (3,nn),
!>   stress (6,ne) averaged over the integration points, von_mises, pressure = -tr(sig)/3,
!>   eff_plastic_strain, failed (ne) int; /states/times (extendible)
!> Crash safety: the file is created as d3plot.h5.tmp and renamed once the mesh is flushed;
!> then per state its datasets first, then its time appended and nstates set, then a
!> global flush, then the XDMF rewritten (tmp + rename) listing only complete states.
!> A continued run (plot_resume) rebuilds the file: the states up to the dump are copied
!> into a new file with the same calls in the same order as the first run made them, so
!> with object times off (dx_h5) the file is byte for byte the uninterrupted run's.
!> All HDF5 calls go through dx_h5.
module dx_plot_hdf5
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_model, only: model_t, elem_block_t, family_t, element_family, elem_stress_global, &
                       ES_DMG, beam_resultants, is_beam, ES_THK, ETYPE_SHELL_BT, &
                       etype_of_shell_elform
   use dx_h5, only: h5_file_t, h5_create, h5_close, h5_flush, h5_create_group, h5_write, &
                    h5_write_attr, h5_create_extendible, h5_append, h5_open_read, h5_read, &
                    h5_read_attr, h5_close_keep
   use dx_error, only: set_error, EXIT_IO
   use dx_io_sys, only: sys_rename
   use dx_strings, only: str
   use dx_xdmf, only: xdmf_write, state_group
   use dx_plot_states, only: STATES_DIR, state_file, states_write_mesh, states_write_state, &
                             states_have, states_clear, states_remove_all, file_remove, &
                             states_link_all, is_link
   use dx_io_sys, only: sys_fsync
   use dx_plot_cells, only: cell_topo_t, model_cells, cells_topology, read_cells
   use dx_plot_fields, only: plot_state_t, plot_state_alloc, plot_state_derive, plot_state_write, &
                             plot_state_read, plot_mesh_write, plot_mesh_read, stress_invariants, F_COORD, F_VEL, &
                             F_STRESS, F_EPSP, F_FAILED, F_DAMAGE, NSTATE_FIELDS, &
                             plot_rows_in_file, F_BEAM_FORCE, F_BEAM_MOMENT, F_THICK
   implicit none
   private
   public :: plot_file_t, element_results, stress_invariants, element_average, &
             plot_merge_states, plot_rows, element_damage, block_damage_slot, element_thickness

   character(*), parameter :: H5NAME = 'd3plot.h5', XMFNAME = 'd3plot.xdmf'

   !> One open plot file and the times of the states written so far.
   type :: plot_file_t
      type(h5_file_t) :: h5
      integer :: nstates = 0
      integer :: nn = 0, ne = 0
      type(cell_topo_t) :: topo      !< the cells as the XDMF describes them
      real(wp), allocatable :: times(:)
      character(:), allocatable :: xdmf_path, title, dir
      !> .true. while the run writes its states to d3plot.states/ (dx_plot_states) and
      !> d3plot.h5.tmp; plot_close then renames d3plot.h5.tmp into place
      logical :: live = .false.
      !> the rows of the schema its states hold (the optional ones: dx_plot_fields)
      logical :: rows(NSTATE_FIELDS) = .false.
      !> an MPI run's rank 0: the parts are combined and published by dx_par_plot
      logical :: by_parts = .false.
   contains
      procedure :: set_by_parts => plot_set_by_parts
      procedure :: open => plot_open
      procedure :: resume => plot_resume
      procedure :: write_state => plot_write_state
      procedure :: close => plot_close
   end type plot_file_t

contains

   !> Start the plot output of a run in dir: d3plot.h5.tmp with the mesh and an empty state
   !> list (renamed to d3plot.h5 by plot_close at the end of the run), the mesh file
   !> d3plot.states/mesh.h5 and an empty d3plot.xdmf; an older run's d3plot.h5 and state
   !> files are removed. publish = .false. (plot_resume): only d3plot.h5.tmp and, when
   !> missing, the mesh file.
   subroutine plot_open(self, model, dir, error, publish)
      class(plot_file_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(*), intent(in) :: dir
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: publish
      integer, allocatable :: cells(:, :), ids(:), nlab(:), elab(:)
      integer :: i, e
      character(:), allocatable :: title
      logical :: pub

      call model_cells(model, cells)
      allocate(ids(model%ne))
      ids = 0
      do e = 1, model%ne
         ids(e) = model%parts(model%elem_part(e))%label
      end do
      ! labels default to the dense index when a hand-built model has none
      nlab = [(i, i = 1, model%nn)]
      if (allocated(model%node_label)) nlab = model%node_label
      elab = [(i, i = 1, model%ne)]
      if (allocated(model%elem_label)) elab = model%elem_label
      title = ''
      if (allocated(model%title)) title = model%title
      pub = .true.
      if (present(publish)) pub = publish
      call open_arrays(self, dir, title, model%x0, nlab, cells, elab, ids, pub, error)
   end subroutine plot_open

   !> plot_open on the mesh arrays (also used by plot_merge_states).
   subroutine open_arrays(self, dir, title, x0, nlab, cells, elab, ids, publish, error)
      class(plot_file_t), intent(inout) :: self
      character(*), intent(in) :: dir, title
      real(wp), intent(in) :: x0(:, :)
      integer, intent(in) :: nlab(:), cells(:, :), elab(:), ids(:)
      logical, intent(in) :: publish
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      logical :: there

      self%nn = size(x0, 2)
      self%ne = size(cells, 2)
      self%topo = cells_topology(cells)
      self%nstates = 0
      if (allocated(self%times)) deallocate(self%times)
      allocate(self%times(16))
      self%title = title
      self%xdmf_path = dir//'/'//XMFNAME
      self%dir = dir
      self%live = .false.
      ! written under a temporary name and renamed at the end of the run (plot_close): a
      ! reader (or a kill -9) never finds a d3plot.h5 that is being written
      call h5_create(self%h5, dir//'/'//H5NAME//'.tmp', error)
      if (allocated(error)) return

      work: block
         call plot_mesh_write(self%h5, x0, nlab, cells, elab, ids, self%title, error)
         if (allocated(error)) exit work
         call h5_write_attr(self%h5, '/', 'nstates', 0, error)
         if (allocated(error)) exit work
         call h5_create_group(self%h5, '/states', error)
         if (allocated(error)) exit work
         call h5_create_extendible(self%h5, '/states/times', error)
         if (allocated(error)) exit work
         call h5_flush(self%h5, error)
         if (allocated(error)) exit work
         if (.not. publish) then
            ! plot_resume: the mesh file, unless the killed run's is there (never rewritten)
            ! (a link to the d3plot.h5 that plot_resume removes is replaced by the file)
            inquire(file=dir//'/'//state_file(0), exist=there)
            if (there) there = .not. is_link(dir//'/'//state_file(0))
            if (.not. there) call states_write_mesh(dir, x0, nlab, cells, elab, ids, &
                                                    self%title, error)
            exit work
         end if
         ! an empty XDMF first: an older one must not list states of an older run; then
         ! the older run's files go, and the mesh file of this run is published
         call xdmf_write(self%xdmf_path, H5NAME, self%title, self%nn, self%ne, self%topo, &
                         self%times(1:0), error, states_dir=STATES_DIR, rows=self%rows)
         if (allocated(error)) exit work
         call file_remove(dir//'/'//H5NAME)
         call states_remove_all(dir)
         call states_write_mesh(dir, x0, nlab, cells, elab, ids, self%title, error)
         if (allocated(error)) exit work
         self%live = .true.
      end block work
      if (allocated(error)) call h5_close(self%h5, err2)   ! keep the first error
   end subroutine open_arrays

   !> Merge the state files a killed run left in dir (d3plot.states/mesh.h5 and the
   !> contiguous NNNNNN.h5 from 1) into dir/d3plot.h5 + d3plot.xdmf, with the writer's calls
   !> in the run's order (the bytes of the uninterrupted run's file at that state), then
   !> turn the state files into links to d3plot.h5 (bin/dynx-combine). nmerged: states
   !> merged. If d3plot.h5 is there (the run was killed while plot_close cleaned up), only
   !> the XDMF is pointed at it and the state files are linked.
   subroutine plot_merge_states(dir, nmerged, error)
      character(*), intent(in) :: dir
      integer, intent(out) :: nmerged
      type(error_t), allocatable, intent(out) :: error
      type(plot_file_t) :: self
      type(h5_file_t) :: f
      type(error_t), allocatable :: err2
      real(wp), allocatable :: x0(:), nlab(:), elab(:), ids(:), x(:)
      type(plot_state_t) :: st
      character(:), allocatable :: title, src
      integer :: k, nn, ne
      integer, allocatable :: cells(:, :)
      logical :: there
      nmerged = 0
      inquire(file=dir//'/'//H5NAME, exist=there)
      if (there) then
         ! killed in plot_close after d3plot.h5 (always whole: it is only ever renamed into
         ! place) was in place: point the XDMF at it and finish the clean-up
         src = dir//'/'//H5NAME
         call h5_open_read(f, src, error)
         if (allocated(error)) return
         call h5_read_attr(f, '/', 'nstates', nmerged, error)
         if (.not. allocated(error)) call h5_read(f, '/states/times', x, error)
      else
         src = dir//'/'//state_file(0)
         call h5_open_read(f, src, error)
         if (allocated(error)) return
      end if
      if (.not. allocated(error)) call plot_mesh_read(f, x0, nlab, cells, elab, ids, title, error)
      if (.not. allocated(error) .and. there .and. nmerged > 0) &
         call plot_rows_in_file(f, state_group(1), self%rows, error)
      call h5_close_keep(f, error)
      if (allocated(error)) return
      if (there) then
         if (size(x) < nmerged) then
            call set_error(error, src//': /states/times has '//str(size(x))// &
                           ' values, nstates is '//str(nmerged), EXIT_IO)
            return
         end if
         call xdmf_write(dir//'/'//XMFNAME, H5NAME, title, size(nlab), size(ids), &
                         cells_topology(cells), x(1:nmerged), error, rows=self%rows)
         if (allocated(error)) return
         call file_remove(dir//'/'//H5NAME//'.tmp')
         call states_link_all(dir, nmerged, error)
         return
      end if
      nn = size(nlab)
      ne = size(ids)
      if (size(x0) /= 3*nn .or. size(elab) /= ne) then
         call set_error(error, src//': mesh datasets of inconsistent sizes', EXIT_IO)
         return
      end if
      call open_arrays(self, dir, title, reshape(x0, [3, nn]), nint(nlab), &
                       cells, nint(elab), nint(ids), .false., error)
      if (allocated(error)) return
      do k = 1, huge(k) - 1
         src = dir//'/'//state_file(k)
         inquire(file=src, exist=there)
         if (.not. there) exit
         call h5_open_read(f, src, error)
         if (allocated(error)) exit
         call plot_state_read(f, state_group(k), nn, ne, st, src//': ', '', error)
         if (allocated(error)) exit
         call h5_close(f, error)
         if (allocated(error)) exit
         call write_arrays(self, st, error, xdmf=.false.)
         if (allocated(error)) exit
      end do
      if (allocated(error)) then
         call h5_close(f, err2)
         call h5_close(self%h5, err2)
         return
      end if
      nmerged = self%nstates
      self%live = .true.            ! plot_close: rename, XDMF, link the state files
      call plot_close(self, error)
   end subroutine plot_merge_states

   !> Continue the plot output from a restart point that had written nkeep states. The
   !> states 1..nkeep come from the killed or stopped run's state files (d3plot.states/,
   !> when they are all there) or else from its d3plot.h5 (a run that ended in order). A new
   !> d3plot.h5.tmp gets the mesh and those states with the calls of plot_open and
   !> plot_write_state, in their order (the same bytes as the uninterrupted run's file at
   !> that point, so the continued run's file ends up identical to it; HDF5 does not
   !> shrink a file, so cutting states in place left other bytes). Order for a kill at any
   !> moment: the XDMF is cut to nkeep states first (they are in the files it names), state
   !> files are written (from d3plot.h5) before the XDMF names them, and files the XDMF
   !> no longer names are removed last. Nothing is found: the plot file is started anew.
   subroutine plot_resume(self, model, dir, nkeep, error)
      class(plot_file_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(*), intent(in) :: dir
      integer, intent(in) :: nkeep
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      type(h5_file_t) :: old
      real(wp), allocatable :: t(:)
      type(plot_state_t) :: st
      integer, allocatable :: cells(:, :)
      integer :: ndisk, k, nn, ne
      logical :: there, from_states
      character(:), allocatable :: g, src
      ! d3plot.h5, when there, is whole and of this run (renamed into place at its orderly
      ! end; the state files may then be links to it, which are replaced below)
      inquire(file=dir//'/'//H5NAME, exist=there)
      from_states = .not. there .and. states_have(dir, nkeep)
      if (.not. there .and. .not. from_states) then
         call self%open(model, dir, error)
         return
      end if
      nn = model%nn
      ne = model%ne
      self%title = ''
      if (allocated(model%title)) self%title = model%title
      src = dir//'/'//H5NAME
      if (.not. from_states) then
         call h5_open_read(old, src, error)
         if (allocated(error)) return
      end if
      work: block
         if (.not. from_states) then
            call h5_read_attr(old, '/', 'nstates', ndisk, error)
            if (allocated(error)) exit work
            call h5_read(old, '/states/times', t, error)
            if (allocated(error)) exit work
            if (ndisk < nkeep .or. size(t) < nkeep) then
               call set_error(error, 'cannot continue '//dir//'/'//H5NAME//': it has '// &
                  str(ndisk)//' plot states, the restart dump expects '//str(nkeep)// &
                  ' (another run''s file?)', EXIT_IO)
               exit work
            end if
            call model_cells(model, cells)
            call xdmf_write(dir//'/'//XMFNAME, H5NAME, self%title, nn, ne, &
                            cells_topology(cells), t(1:nkeep), error, rows=plot_rows(model))
            if (allocated(error)) exit work
         end if
         call self%open(model, dir, error, publish=.false.)
         if (allocated(error)) exit work
         ! from d3plot.h5, the copies also go to state files; from state files, not
         self%live = .not. from_states
         do k = 1, nkeep
            g = state_group(k)
            if (from_states) then
               src = dir//'/'//state_file(k)
               call h5_open_read(old, src, error)
               if (allocated(error)) exit work
            end if
            call plot_state_read(old, g, nn, ne, st, 'cannot continue '//src//': ', &
                                 ' (another run''s file?)', error)
            if (allocated(error)) exit work
            if (from_states) then
               call h5_close(old, error)
               if (allocated(error)) exit work
            end if
            call write_arrays(self, st, error, xdmf=.false.)
            if (allocated(error)) exit work
         end do
         if (.not. from_states) then
            call h5_close(old, error)
            if (allocated(error)) exit work
         end if
         self%live = .true.
         call xdmf_write(self%xdmf_path, H5NAME, self%title, nn, ne, self%topo, &
                         self%times(1:nkeep), &
                         error, states_dir=STATES_DIR, rows=self%rows)
         if (allocated(error)) exit work
         call states_clear(dir, nkeep + 1)
         call file_remove(dir//'/'//H5NAME)
      end block work
      if (allocated(error)) then
         self%live = .false.
         call h5_close(old, err2)
         call h5_close(self%h5, err2)
      end if
   end subroutine plot_resume

   !> Element results: stress averaged over integration points, effective plastic strain
   !> (0 where the material has none) and the failed flag (1.0 = eroded), the SRC_ELEMENT
   !> fields of the schema (dx_plot_fields); the invariants are derived from the stress.
   subroutine element_results(model, stress, epsp, failed, damage)
      type(model_t), intent(in) :: model
      real(wp), intent(out) :: stress(:, :), epsp(:), failed(:)
      real(wp), intent(out), optional :: damage(:)   !< the damage D (F_DAMAGE; 0: none)
      integer :: ib, i, e, k, imat, fl, kd
      type(family_t) :: fam
      logical :: rot

      stress = 0.0_wp
      epsp = 0.0_wp
      failed = 0.0_wp
      if (present(damage)) damage = 0.0_wp
      if (allocated(model%blocks)) then
         do ib = 1, size(model%blocks)
            associate (blk => model%blocks(ib))
               k = 0
               fam = element_family(blk%etype)
               rot = fam%rot .and. allocated(model%x)
               imat = model%parts(blk%ipart)%imat
               if (imat >= 1 .and. allocated(model%mats)) then
                  if (imat <= size(model%mats)) then
                     if (allocated(model%mats(imat)%m)) k = model%mats(imat)%m%hv_eps_p
                  end if
               end if
               kd = block_damage_slot(model, blk)
               do i = 1, blk%nel
                  e = blk%elem(i)
                  call element_average(blk, i, k, stress(:, e), epsp(e), fl)
                  failed(e) = real(fl, wp)
                  if (present(damage)) damage(e) = element_damage(blk, i, kd)
                  ! shells: the mean over the laminae (the membrane stress N/t) is held
                  ! in the element's co-rotational frame; beams: the axial stress N/A; the
                  ! plot shows them in global axes
                  if (rot) call elem_stress_global(blk%etype, model%x(:, blk%conn(:, i)), &
                                                   stress(:, e))
               end do
            end associate
         end do
      end if
   end subroutine element_results

   !> One element's plot values: stress averaged over its integration points, the average
   !> of history variable k (hv_eps_p; 0 = none) and the failed flag (1 = eroded). Shared by
   !> the serial writer and the per-rank MPI writer (dx_plot_part), so both give the same bits.
   subroutine element_average(blk, i, k, stress, epsp, failed)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: i, k
      real(wp), intent(out) :: stress(6), epsp
      integer, intent(out) :: failed
      integer :: ip
      stress = 0.0_wp
      epsp = 0.0_wp
      failed = 0
      if (allocated(blk%sig)) then
         do ip = 1, blk%nip
            stress = stress + blk%sig(i, :, ip)
         end do
         stress = stress/real(blk%nip, wp)
      end if
      if (k > 0 .and. k <= blk%nhv .and. allocated(blk%hv)) &
         epsp = sum(blk%hv(i, k, 1:blk%nip))/real(blk%nip, wp)
      if (allocated(blk%failed)) then
         if (blk%failed(i)) failed = 1
      end if
   end subroutine element_average

   !> An element's damage D for the plot: the average over the integration points of the
   !> material's damage history variable kd (material_t%hv_damage; 0: none), else the
   !> Tuler-Butcher integral over IMPULSE of the erosion (dx_erosion, family-state slot
   !> ES_DMG; 1 at failure), else 0.
   real(wp) function element_damage(blk, i, kd) result(d)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: i, kd
      d = 0.0_wp
      if (kd > 0 .and. kd <= blk%nhv .and. allocated(blk%hv)) then
         d = sum(blk%hv(i, kd, 1:blk%nip))/real(blk%nip, wp)
      else if (blk%esc(ES_DMG) > 0) then
         d = blk%es(i, blk%esc(ES_DMG))
      end if
   end function element_damage

   !> An element's current shell thickness for the plot (family-state slot ES_THK; 0 for an
   !> element without one).
   real(wp) function element_thickness(blk, i) result(t)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: i
      t = 0.0_wp
      if (blk%esc(ES_THK) > 0) t = blk%es(i, blk%esc(ES_THK))
   end function element_thickness

   !> The damage history offset of block blk's material (0: none).
   integer function block_damage_slot(model, blk) result(kd)
      type(model_t), intent(in) :: model
      type(elem_block_t), intent(in) :: blk
      integer :: imat
      kd = 0
      if (.not. allocated(model%mats)) return
      imat = model%parts(blk%ipart)%imat
      if (imat < 1 .or. imat > size(model%mats)) return
      if (allocated(model%mats(imat)%m)) kd = model%mats(imat)%m%hv_damage
   end function block_damage_slot

   !> The rows of the plot schema this model uses (dx_plot_fields: the optional ones): the
   !> damage D when some part's *MAT_ADD_EROSION has the Tuler-Butcher criterion or its
   !> material a damage variable; the beam resultants when a part is a beam part; the
   !> thickness when some part is a BT shell part (from the
   !> parts, so every rank of an MPI run agrees).
   function plot_rows(model) result(rows)
      type(model_t), intent(in) :: model
      logical :: rows(NSTATE_FIELDS)
      integer :: p
      type(family_t) :: fam
      rows = .false.
      if (.not. allocated(model%parts)) return
      ! the beams' resultants when a part has a *SECTION_BEAM (its area: dx_beam_build)
      rows(F_BEAM_FORCE) = any(model%parts(:)%bsec(1) > 0.0_wp)
      rows(F_BEAM_MOMENT) = rows(F_BEAM_FORCE)
      do p = 1, size(model%parts)
         associate (is => model%parts(p)%isec)
            if (is >= 1 .and. allocated(model%sections)) then
               if (is <= size(model%sections)) then
                  if (model%sections(is)%shell) then
                     fam = element_family(etype_of_shell_elform(model%sections(is)%elform))
                     if (fam%shell) rows(F_THICK) = .true.
                  end if
               end if
            end if
         end associate
         associate (e => model%parts(p)%ero)
            if (e%on .and. e%impulse /= e%excl) rows(F_DAMAGE) = .true.
         end associate
         if (allocated(model%mats)) then
            associate (ip => model%parts(p)%imat)
               if (ip >= 1 .and. ip <= size(model%mats)) then
                  if (allocated(model%mats(ip)%m)) then
                     if (model%mats(ip)%m%hv_damage > 0) rows(F_DAMAGE) = .true.
                  end if
               end if
            end associate
         end if
      end do
   end function plot_rows

   !> Write one plot state at model%time (see the module header for the order of writes):
   !> the schema's fields (dx_plot_fields) filled from the model.
   subroutine plot_write_state(self, model, error)
      class(plot_file_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      type(plot_state_t) :: st
      integer :: ib, i
      call plot_state_alloc(st, self%nn, self%ne, rows=plot_rows(model))
      st%time = model%time
      if (allocated(model%x)) then
         st%f(F_COORD)%r = model%x
      else
         st%f(F_COORD)%r = model%x0
      end if
      if (allocated(model%v)) st%f(F_VEL)%r = model%v
      if (st%on(F_DAMAGE)) then
         call element_results(model, st%f(F_STRESS)%r, st%f(F_EPSP)%r(1, :), &
                              st%f(F_FAILED)%r(1, :), st%f(F_DAMAGE)%r(1, :))
      else
         call element_results(model, st%f(F_STRESS)%r, st%f(F_EPSP)%r(1, :), &
                              st%f(F_FAILED)%r(1, :))
      end if
      if (st%on(F_BEAM_FORCE)) call beam_rows(model, st)
      if (st%on(F_THICK) .and. allocated(model%blocks)) then
         st%f(F_THICK)%r = 0.0_wp
         do ib = 1, size(model%blocks)
            do i = 1, model%blocks(ib)%nel
               st%f(F_THICK)%r(1, model%blocks(ib)%elem(i)) = element_thickness(model%blocks(ib), i)
            end do
         end do
      end if
      call plot_state_derive(st, model%x0)
      call write_arrays(self, st, error)
   end subroutine plot_write_state

   !> The beams' resultant rows of a state (dx_element_types: beam_resultants), by global
   !> element; zero on the other cells.
   subroutine beam_rows(model, st)
      type(model_t), intent(in) :: model
      type(plot_state_t), intent(inout) :: st
      integer :: ib, i
      if (.not. allocated(model%x)) return
      do ib = 1, size(model%blocks)
         associate (blk => model%blocks(ib))
            if (.not. is_beam(blk%etype)) cycle
            do i = 1, blk%nel
               call beam_resultants(blk, i, model%x(:, blk%conn(:, i)), &
                                    st%f(F_BEAM_FORCE)%r(:, blk%elem(i)), &
                                    st%f(F_BEAM_MOMENT)%r(:, blk%elem(i)))
            end do
         end associate
      end do
   end subroutine beam_rows

   !> The writes of one state (the order of the module header), then its XDMF entry.
   !> plot_write_state and plot_resume's copy both come through here: the same calls.
   subroutine write_arrays(self, st, error, xdmf)
      class(plot_file_t), intent(inout) :: self
      type(plot_state_t), intent(in) :: st
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: xdmf     !< .false.: no XDMF entry (plot_resume)
      real(wp), allocatable :: tmp(:)
      integer :: k, n
      k = self%nstates + 1
      self%rows = st%on
      call plot_state_write(self%h5, state_group(k), st, error)
      if (allocated(error)) return
      ! the state is complete: publish it
      call h5_append(self%h5, '/states/times', st%time, n, error)
      if (allocated(error)) return
      call h5_write_attr(self%h5, '/', 'nstates', k, error)
      if (allocated(error)) return
      call h5_flush(self%h5, error)
      if (allocated(error)) return
      self%nstates = k
      if (k > size(self%times)) then
         allocate(tmp(2*size(self%times)))
         tmp(1:k - 1) = self%times(1:k - 1)
         call move_alloc(tmp, self%times)
      end if
      self%times(k) = st%time
      ! the state's own file (temp, fsync, rename: dx_plot_states), then the XDMF names it
      if (self%live) then
         call states_write_state(self%dir, k, st, error)
         if (allocated(error)) return
      end if
      if (present(xdmf)) then
         if (.not. xdmf) return
      end if
      call xdmf_write(self%xdmf_path, H5NAME, self%title, self%nn, self%ne, self%topo, &
                      self%times(1:k), error, states_dir=STATES_DIR, rows=self%rows)
   end subroutine write_arrays

   !> Mark the writer of an MPI run's rank 0 (output_plot_by_parts).
   subroutine plot_set_by_parts(self)
      class(plot_file_t), intent(inout) :: self
      self%by_parts = .true.
   end subroutine plot_set_by_parts

   !> Flush and close (safe to call twice and after errors).
   subroutine plot_close(self, error)
      class(plot_file_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: err2
      if (.not. self%h5%is_open()) return
      call h5_flush(self%h5, error)
      call h5_close(self%h5, err2)
      if (.not. allocated(error) .and. allocated(err2)) call move_alloc(err2, error)
      if (.not. self%live) return
      self%live = .false.
      if (allocated(error)) return          ! the state files stay listed and readable
      ! d3plot.h5 into place (whole, synced), the XDMF pointed at it, the state files links:
      ! a kill between any two steps leaves an XDMF whose files are all whole
      call sys_fsync(self%dir//'/'//H5NAME//'.tmp', error)
      if (allocated(error)) return
      call sys_rename(self%dir//'/'//H5NAME//'.tmp', self%dir//'/'//H5NAME, error)
      if (allocated(error)) return
      ! rank 0 of an MPI run (by_parts; no state written here, or only the states a restart
      ! kept): dx_par_plot publishes the states and the XDMF, and plot_combine replaces this
      ! d3plot.h5 after, so the XDMF and d3plot.states/ a viewer holds are left alone
      if (self%nstates == 0 .or. self%by_parts) return
      call xdmf_write(self%xdmf_path, H5NAME, self%title, self%nn, self%ne, self%topo, &
                      self%times(1:self%nstates), error, rows=self%rows)
      if (allocated(error)) return
      ! the state files become links to d3plot.h5: a viewer that read the XDMF while the
      ! job ran still finds every state it lists (live viewing, issue 21)
      call states_link_all(self%dir, self%nstates, error)
   end subroutine plot_close
end module dx_plot_hdf5
