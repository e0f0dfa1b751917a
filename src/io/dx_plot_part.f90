!> Per-rank plot files of an MPI run and their combination into the serial d3plot.h5 +
!> d3plot.xdmf (ParaDyn step 5 output; docs/output-format.md, "MPI runs"). Each rank writes
!> DIR/d3plot_rank_NNNNN.h5: the nodes it owns and the elements it holds, with their global
!> (dense) indices, and per state their coordinates, velocities and element values; no
!> element data passes through another rank. plot_combine (bin/dynx-combine, and rank 0 at
!> the end of a run) merges the files of DIR into d3plot.h5 + d3plot.xdmf with the layout,
!> the values and the XDMF text of a serial run: the element averages and the stress
!> invariants come from the serial writer's own routines (dx_plot_hdf5), so the bits agree.
!> Crash safety as in the serial state files (dx_plot_states, issue 7): no file of a part is
!> ever rewritten in place. The part file DIR/d3plot_rank_NNNNN.h5 holds the header and the
!> mesh only; state k of the rank is its own small file DIR/d3plot_rank_NNNNN.states/
!> KKKKKK.h5 (group /states/KKKKKK, the run's stamp). Each is written under NAME.tmp, closed,
!> fsynced and renamed, and never touched again, so a kill -9 at any moment leaves every
!> renamed file whole. Rank 0 joins a state (the combine, and the live view's published state
!> files) one whole-model field at a time (stream_state), with plot_state_write's calls, so
!> the bytes are the serial writer's and rank 0 never holds a whole state (issue 22).
!> A rank's states are the files 1, 2, ... up to the first missing one;
!> plot_combine takes the states every part has completed (the smallest count), so the files
!> of a run killed mid-way combine into the complete states only. plot_part_truncate is the
!> one routine that cuts a run's parts back to a state count (restarts: states after the
!> dump), removing state files from the last down. Atomic publication by temp + fsync +
!> rename: Pillai et al., "All file systems are not created equal", OSDI 2014.
!> ParaDyn's per-processor plot files joined by a post-processor: Hoover et al., LLNL
!> Engineering Thrust Area Report FY97 (article 4 of shared/seed). No MPI here: the engine
!> (dx_par_plot) passes the rank's data in.
module dx_plot_part
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_strings, only: str
   use dx_h5, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_flush, &
                    h5_create_group, h5_write, h5_write_attr, h5_read_attr, h5_read, &
                    h5_create_extendible, h5_append, h5_write_int_attrs, h5_read_int_attrs
   use dx_io_sys, only: sys_rename, sys_mkdir_p
   use dx_plot_states, only: file_remove, publish, states_write_mesh, state_file, &
                             states_remove_all, LIVE_DIR => STATES_DIR
   use dx_xdmf, only: xdmf_write, state_group
   use dx_plot_cells, only: write_cells, read_cells, cells_topology, cell_topo_t
   use dx_plot_fields, only: plot_mesh_write, field_in_part, PLOT_FIELDS, NSTATE_FIELDS, &
                             CENTRE_NODE, plot_rows_in_file, plot_field_t, stress_invariants, &
                             plot_state_t, plot_state_write, &
                             F_COORD, F_DISP, F_STRESS, F_VM, F_PRES
   implicit none
   private
   public :: plot_part_t, plot_part_name, plot_part_state_name, plot_part_count, plot_combine, &
             plot_part_truncate, PART_FORMAT, plot_live_t

   character(*), parameter :: PART_FORMAT = 'dynx plot part'
   integer, parameter :: PART_VERSION = 2
   character(*), parameter :: H5NAME = 'd3plot.h5', XMFNAME = 'd3plot.xdmf'
   !> The integer root attributes of a part file after format and version, in write order.
   character(*), parameter :: HEADER(5) = [character(9) :: 'rank', 'nprocs', 'stamp', &
                                           'nn_global', 'ne_global']

   !> Rank 0's view of a running MPI job's parts, for live viewing (plot_live_publish):
   !> the parts' node and element indices, the initial coordinates and the states' times.
   type :: part_idx_t
      integer, allocatable :: n(:), e(:)
   end type part_idx_t
   type :: plot_live_t
      type(part_idx_t), allocatable :: idx(:)
      real(wp), allocatable :: x0(:, :), times(:)
      character(:), allocatable :: title
      type(cell_topo_t) :: topo
      logical :: rows(NSTATE_FIELDS) = .false.
      integer :: np = 0, nn = 0, ne = 0
   contains
      procedure :: publish => plot_live_publish
   end type plot_live_t

   !> One rank's open part file.
   type :: plot_part_t
      logical :: active = .false.     !< header written (open) or found (resume)
      character(:), allocatable :: dir
      integer :: rank = 0, stamp = 0
      integer :: nstates = 0
      integer :: nown = 0, nel = 0
   contains
      procedure :: open => part_open
      procedure :: resume => part_resume
      procedure :: write_state => part_write_state
      procedure :: close => part_close
   end type plot_part_t

contains

   !> DIR/d3plot_rank_NNNNN.h5
   function plot_part_name(dir, rank) result(p)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank
      character(:), allocatable :: p
      character(5) :: r
      write(r, '(i5.5)') rank
      p = dir//'/d3plot_rank_'//r//'.h5'
   end function plot_part_name

   !> State k of rank's part: DIR/d3plot_rank_NNNNN.states/KKKKKK.h5
   function plot_part_state_name(dir, rank, k) result(p)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank, k
      character(:), allocatable :: p
      character(6) :: c
      write(c, '(i6.6)') k
      p = states_dir(dir, rank)//'/'//c//'.h5'
   end function plot_part_state_name

   function states_dir(dir, rank) result(p)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank
      character(:), allocatable :: p
      p = plot_part_name(dir, rank)
      p = p(1:len(p) - 3)//'.states'
   end function states_dir

   !> The states rank's part has completed: its state files 1, 2, ... up to the first
   !> missing one (they are written in order and published by rename).
   integer function plot_part_count(dir, rank) result(m)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank
      logical :: there
      m = 0
      do
         inquire(file=plot_part_state_name(dir, rank, m + 1), exist=there)
         if (.not. there) exit
         m = m + 1
      end do
   end function plot_part_count

   !> Remove rank's state files k >= kfrom and a left-over temporary file, from the last
   !> down (a kill here leaves them contiguous).
   subroutine clear_states(dir, rank, kfrom)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank, kfrom
      integer :: k, m
      m = max(plot_part_count(dir, rank), kfrom - 1)
      call file_remove(plot_part_state_name(dir, rank, m + 1)//'.tmp')
      do k = m, kfrom, -1
         call file_remove(plot_part_state_name(dir, rank, k))
      end do
   end subroutine clear_states

   !> Create rank's part file with its mesh: owned nodes (global dense index, initial
   !> coordinates, label) and held elements (global dense index, connectivity as 0-based
   !> global node indices, label, part label). stamp identifies the run: all parts of one
   !> run carry the same stamp, so files of two runs are never mixed. State files left in
   !> dir by an earlier run are removed first; the file is written as NAME.tmp, closed,
   !> fsynced and renamed, and never written again.
   subroutine part_open(self, dir, rank, nprocs, stamp, title, nn, ne, nodes, x0, node_ids, &
                        elems, cells, elem_ids, part_ids, error)
      class(plot_part_t), intent(inout) :: self
      character(*), intent(in) :: dir, title
      integer, intent(in) :: rank, nprocs, stamp, nn, ne
      integer, intent(in) :: nodes(:), node_ids(:), elems(:), cells(:, :), elem_ids(:), &
                             part_ids(:)
      real(wp), intent(in) :: x0(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      character(:), allocatable :: path
      path = plot_part_name(dir, rank)
      self%active = .false.
      self%dir = dir
      self%rank = rank
      self%stamp = stamp
      self%nstates = 0
      self%nown = size(nodes)
      self%nel = size(elems)
      call sys_mkdir_p(states_dir(dir, rank), error)
      if (allocated(error)) return
      call clear_states(dir, rank, 1)
      call h5_create(f, path//'.tmp', error)
      if (allocated(error)) return
      work: block
         call h5_write_attr(f, '/', 'format', PART_FORMAT, error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'version', PART_VERSION, error)
         if (allocated(error)) exit work
         call h5_write_int_attrs(f, '/', HEADER, [rank, nprocs, stamp, nn, ne], error)
         if (allocated(error)) exit work
         call h5_write_attr(f, '/', 'title', title, error)
         if (allocated(error)) exit work
         call h5_create_group(f, '/mesh', error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/nodes', nodes, error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/coordinates', x0, error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/node_ids', node_ids, error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/elements', elems, error)
         if (allocated(error)) exit work
         call write_cells(f, cells, error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/element_ids', elem_ids, error)
         if (allocated(error)) exit work
         call h5_write(f, '/mesh/part_ids', part_ids, error)
      end block work
      call publish(f, path, error)
      if (allocated(error)) return
      self%active = .true.
   end subroutine part_open

   !> Continue rank's existing part in dir after its first nkeep states (a restart): later
   !> states are removed (plot_part_truncate); the run's stamp is read from the part file.
   subroutine part_resume(self, dir, rank, nkeep, error)
      class(plot_part_t), intent(inout) :: self
      character(*), intent(in) :: dir
      integer, intent(in) :: rank, nkeep
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      type(error_t), allocatable :: err2
      call plot_part_truncate(dir, rank, nkeep, error)
      if (allocated(error)) return
      call h5_open_read(f, plot_part_name(dir, rank), error)
      if (allocated(error)) return
      call h5_read_attr(f, '/', 'stamp', self%stamp, error)
      call h5_close(f, err2)
      if (allocated(error)) return
      self%dir = dir
      self%rank = rank
      self%nstates = nkeep
      self%active = .true.
   end subroutine part_resume

   !> Write one state to its own file: the schema's part fields (dx_plot_fields:
   !> field_in_part; coordinates and velocity (3, nown) of the owned nodes, stress (6, nel)
   !> averaged over the integration points, eff_plastic_strain and failed (nel) of the held
   !> elements), the time and the run's stamp. Temp, close, fsync, rename (crash safety).
   subroutine part_write_state(self, st, error)
      class(plot_part_t), intent(inout) :: self
      type(plot_state_t), intent(in) :: st
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      character(:), allocatable :: path
      integer :: k
      k = self%nstates + 1
      path = plot_part_state_name(self%dir, self%rank, k)
      call h5_create(f, path//'.tmp', error)
      if (allocated(error)) return
      work: block
         call h5_write_attr(f, '/', 'stamp', self%stamp, error)
         if (allocated(error)) exit work
         call h5_create_group(f, '/states', error)
         if (allocated(error)) exit work
         call plot_state_write(f, state_group(k), st, error, part=.true.)
      end block work
      call publish(f, path, error)
      if (allocated(error)) return
      self%nstates = k
   end subroutine part_write_state

   !> End of the part (every file is already on disk; safe to call twice).
   subroutine part_close(self, error)
      class(plot_part_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      self%active = .false.
   end subroutine part_close

   !> Cut rank's part in dir back to its first nkeep states (state files after them and a
   !> left-over temporary file are removed, from the last down). The routine a restart of
   !> an MPI run calls for "plot states after the dump point are removed". A missing part
   !> file or fewer than nkeep complete states is an I/O error (exit 4) naming the file.
   subroutine plot_part_truncate(dir, rank, nkeep, error)
      character(*), intent(in) :: dir
      integer, intent(in) :: rank, nkeep
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: path
      integer :: ndisk
      logical :: there
      path = plot_part_name(dir, rank)
      inquire(file=path, exist=there)
      if (.not. there) then
         call set_error(error, 'cannot cut '//path//' back to '//str(nkeep)// &
                        ' plot states: the file is missing', EXIT_IO)
         return
      end if
      ndisk = plot_part_count(dir, rank)
      if (ndisk < nkeep) then
         call set_error(error, 'cannot cut '//path//' back to '//str(nkeep)// &
                        ' plot states: it has '//str(ndisk)//' (in '// &
                        states_dir(dir, rank)//')', EXIT_IO)
         return
      end if
      call clear_states(dir, rank, nkeep + 1)
   end subroutine plot_part_truncate

   !> Merge dir/d3plot_rank_*.h5 and their state files into dir/d3plot.h5 + dir/d3plot.xdmf,
   !> as a serial run writes them: the states every part has completed (nstates_out). The result
   !> is written as d3plot.h5.tmp and renamed, then the XDMF (tmp + rename). Parts of
   !> another run (stamp), another NP or model size, a node or element missing or held
   !> twice, or differing state times: I/O error (exit 4) naming the file.
   subroutine plot_combine(dir, nstates_out, error)
      character(*), intent(in) :: dir
      integer, intent(out) :: nstates_out
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t), allocatable :: pf(:)
      type(h5_file_t) :: out
      type(error_t), allocatable :: err2
      character(:), allocatable :: title, t0
      real(wp) :: tk
      real(wp), allocatable :: times(:), buf(:), x0(:, :)
      integer, allocatable :: cnt_n(:), cnt_e(:), node_ids(:), &
                              cells(:, :), elem_ids(:), part_ids(:), rc(:, :)
      type(cell_topo_t) :: topo
      logical :: rows(NSTATE_FIELDS)
      type(part_idx_t), allocatable :: idx(:)
      integer :: np, nn, ne, stamp, r, k, ival, nst, i, n
      character(:), allocatable :: g, path
      nstates_out = 0
      ! ---- rank 0's part says how many there are
      allocate(pf(1))
      call h5_open_read(pf(1), plot_part_name(dir, 0), error)
      if (allocated(error)) return
      call read_header(pf(1), plot_part_name(dir, 0), np, stamp, nn, ne, title, error)
      call h5_close(pf(1), err2)
      if (allocated(error)) return
      deallocate(pf)
      allocate(pf(0:np - 1), idx(0:np - 1), cnt_n(nn), cnt_e(ne))
      allocate(x0(3, nn), node_ids(nn), elem_ids(ne), part_ids(ne))
      cnt_n = 0
      cnt_e = 0
      nst = huge(nst)
      work: block
         do r = 0, np - 1
            path = plot_part_name(dir, r)
            call h5_open_read(pf(r), path, error)
            if (allocated(error)) exit work
            call read_header(pf(r), path, ival, k, i, n, t0, error)
            if (allocated(error)) exit work
            if (ival /= np .or. k /= stamp .or. i /= nn .or. n /= ne) then
               call set_error(error, path//': part of another run (NP, run stamp or model '// &
                  'size differ from '//plot_part_name(dir, 0)//'); remove stale part files', &
                  EXIT_IO)
               exit work
            end if
            call h5_read_attr(pf(r), '/', 'rank', ival, error)
            if (allocated(error)) exit work
            if (ival /= r) then
               call set_error(error, path//': holds rank '//str(ival)//', expected '// &
                              str(r), EXIT_IO)
               exit work
            end if
            nst = min(nst, plot_part_count(dir, r))
            ! mesh: owned nodes and held elements, each exactly once over the parts
            call h5_read(pf(r), '/mesh/nodes', buf, error)
            if (allocated(error)) exit work
            idx(r)%n = nint(buf)
            call h5_read(pf(r), '/mesh/elements', buf, error)
            if (allocated(error)) exit work
            idx(r)%e = nint(buf)
            if (any(idx(r)%n < 1 .or. idx(r)%n > nn) .or. any(idx(r)%e < 1 .or. &
                                                               idx(r)%e > ne)) then
               call set_error(error, path//': node or element index out of range', EXIT_IO)
               exit work
            end if
            cnt_n(idx(r)%n) = cnt_n(idx(r)%n) + 1
            cnt_e(idx(r)%e) = cnt_e(idx(r)%e) + 1
            call h5_read(pf(r), '/mesh/coordinates', buf, error)
            if (allocated(error)) exit work
            x0(:, idx(r)%n) = reshape(buf, [3, size(idx(r)%n)])
            call h5_read(pf(r), '/mesh/node_ids', buf, error)
            if (allocated(error)) exit work
            node_ids(idx(r)%n) = nint(buf)
            call read_cells(pf(r), size(idx(r)%e), rc, error)
            if (allocated(error)) exit work
            if (.not. allocated(cells)) allocate(cells(size(rc, 1), ne))
            if (size(rc, 1) /= size(cells, 1)) then
               call set_error(error, path//': cells of another element family', EXIT_IO)
               exit work
            end if
            cells(:, idx(r)%e) = rc
            call h5_read(pf(r), '/mesh/element_ids', buf, error)
            if (allocated(error)) exit work
            elem_ids(idx(r)%e) = nint(buf)
            call h5_read(pf(r), '/mesh/part_ids', buf, error)
            if (allocated(error)) exit work
            part_ids(idx(r)%e) = nint(buf)
         end do
         if (any(cnt_n /= 1) .or. any(cnt_e /= 1)) then
            call set_error(error, dir//': the part files do not hold every node and '// &
               'element exactly once ('//str(count(cnt_n /= 1))//' nodes, '// &
               str(count(cnt_e /= 1))//' elements wrong)', EXIT_IO)
            exit work
         end if
         deallocate(cnt_n, cnt_e)
         do r = 0, np - 1
            call h5_close(pf(r), error)
            if (allocated(error)) exit work
         end do
         ! times: every part's first nst state files are of this run and agree in time
         allocate(times(nst))
         do k = 1, nst
            do r = 0, np - 1
               path = plot_part_state_name(dir, r, k)
               call h5_open_read(pf(r), path, error)
               if (allocated(error)) exit work
               call h5_read_attr(pf(r), '/', 'stamp', ival, error)
               if (allocated(error)) exit work
               if (ival /= stamp) then
                  call set_error(error, path//': state of another run (run stamp differs '// &
                     'from '//plot_part_name(dir, 0)//'); remove stale part files', EXIT_IO)
                  exit work
               end if
               call h5_read_attr(pf(r), state_group(k), 'time', tk, error)
               if (allocated(error)) exit work
               call h5_close(pf(r), error)
               if (allocated(error)) exit work
               if (r == 0) then
                  times(k) = tk
               else if (tk /= times(k)) then
                  call set_error(error, path//': state time differs from '// &
                                 plot_part_state_name(dir, 0, k), EXIT_IO)
                  exit work
               end if
            end do
         end do
         ! ---- the combined file, in the serial writer's layout (dx_plot_hdf5)
         call h5_create(out, dir//'/'//H5NAME//'.tmp', error)
         if (allocated(error)) exit work
         call plot_mesh_write(out, x0, node_ids, cells, elem_ids, part_ids, title, error)
         if (allocated(error)) exit work
         call h5_write_attr(out, '/', 'nstates', 0, error)
         if (allocated(error)) exit work
         call h5_create_group(out, '/states', error)
         if (allocated(error)) exit work
         call h5_create_extendible(out, '/states/times', error)
         if (allocated(error)) exit work
         ! the serial writer's flushes too (after the mesh, after each state): HDF5 lays
         ! out the file by its sequence of calls, so the same calls give the same bytes
         call h5_flush(out, error)
         if (allocated(error)) exit work
         topo = cells_topology(cells)
         deallocate(cells, elem_ids, part_ids, node_ids)
         rows = .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt
         do k = 1, nst
            g = state_group(k)
            if (k == 1) then      ! the optional rows of the schema the parts hold
               call h5_open_read(pf(0), plot_part_state_name(dir, 0, k), error)
               if (allocated(error)) exit work
               call plot_rows_in_file(pf(0), g, rows, error)
               if (allocated(error)) exit work
               call h5_close(pf(0), error)
               if (allocated(error)) exit work
               rows = rows .or. .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt
            end if
            call stream_state(out, g, times(k), dir, k, idx, x0, nn, ne, rows, error)
            if (allocated(error)) exit work
            call h5_append(out, '/states/times', times(k), i, error)
            if (allocated(error)) exit work
            call h5_write_attr(out, '/', 'nstates', k, error)
            if (allocated(error)) exit work
            call h5_flush(out, error)
            if (allocated(error)) exit work
         end do
         call h5_flush(out, error)
         if (allocated(error)) exit work
         call h5_close(out, error)
         if (allocated(error)) exit work
         call sys_rename(dir//'/'//H5NAME//'.tmp', dir//'/'//H5NAME, error)
         if (allocated(error)) exit work
         call xdmf_write(dir//'/'//XMFNAME, H5NAME, title, nn, ne, topo, times, error, &
                         rows=rows)
         if (allocated(error)) exit work
         nstates_out = nst
      end block work
      if (out%is_open()) call h5_close(out, err2)
      do r = 0, size(pf) - 1
         if (pf(r)%is_open()) call h5_close(pf(r), err2)
      end do
   end subroutine plot_combine

   !> Publish state k of a running MPI job for viewers (issue 21, live viewing; rank 0, once
   !> every rank's state-k file is on disk): the state in the serial layout as
   !> DIR/d3plot.states/KKKKKK.h5 (dx_plot_states: temp, fsync, rename), then d3plot.xdmf
   !> naming states 1..k there, as a serial run does while it runs. The first call reads the
   !> parts' meshes once, writes the mesh file and (a restart) the states before k. At the
   !> end of the run plot_combine writes d3plot.h5 and the XDMF over it, and the state
   !> files become links to it (dx_plot_states: states_link_all). d3plot.h5 and its XDMF
   !> are not touched here, so their bytes are those of plot_combine alone.
   subroutine plot_live_publish(self, dir, k, error)
      class(plot_live_t), intent(inout) :: self
      character(*), intent(in) :: dir
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      type(error_t), allocatable :: err2
      real(wp), allocatable :: buf(:)
      integer, allocatable :: node_ids(:), cells(:, :), elem_ids(:), part_ids(:), rc(:, :)
      integer :: r, stamp, j
      character(:), allocatable :: path
      if (.not. allocated(self%idx)) then
         call h5_open_read(f, plot_part_name(dir, 0), error)
         if (allocated(error)) return
         call read_header(f, plot_part_name(dir, 0), self%np, stamp, self%nn, self%ne, &
                          self%title, error)
         call h5_close(f, err2)
         if (allocated(error)) return
         allocate(self%idx(0:self%np - 1), self%x0(3, self%nn), node_ids(self%nn), &
                  elem_ids(self%ne), part_ids(self%ne), self%times(max(16, k)))
         do r = 0, self%np - 1
            path = plot_part_name(dir, r)
            call h5_open_read(f, path, error)
            if (allocated(error)) return
            mesh: block
               call h5_read(f, '/mesh/nodes', buf, error)
               if (allocated(error)) exit mesh
               self%idx(r)%n = nint(buf)
               call h5_read(f, '/mesh/elements', buf, error)
               if (allocated(error)) exit mesh
               self%idx(r)%e = nint(buf)
               call h5_read(f, '/mesh/coordinates', buf, error)
               if (allocated(error)) exit mesh
               self%x0(:, self%idx(r)%n) = reshape(buf, [3, size(self%idx(r)%n)])
               call h5_read(f, '/mesh/node_ids', buf, error)
               if (allocated(error)) exit mesh
               node_ids(self%idx(r)%n) = nint(buf)
               call read_cells(f, size(self%idx(r)%e), rc, error)
               if (allocated(error)) exit mesh
               if (.not. allocated(cells)) allocate(cells(size(rc, 1), self%ne))
               cells(:, self%idx(r)%e) = rc
               call h5_read(f, '/mesh/element_ids', buf, error)
               if (allocated(error)) exit mesh
               elem_ids(self%idx(r)%e) = nint(buf)
               call h5_read(f, '/mesh/part_ids', buf, error)
               if (allocated(error)) exit mesh
               part_ids(self%idx(r)%e) = nint(buf)
            end block mesh
            call h5_close(f, err2)
            if (allocated(error)) return
         end do
         self%topo = cells_topology(cells)
         ! an older run's state files go (their XDMF is rewritten at the first state below)
         if (k == 1) call states_remove_all(dir)
         call states_write_mesh(dir, self%x0, node_ids, cells, elem_ids, part_ids, &
                                self%title, error)
         if (allocated(error)) return
         ! the mesh's whole-model tables are written: freed before a state's (issue 22:
         ! rank 0's peak is the first publish)
         deallocate(node_ids, cells, elem_ids, part_ids)
         if (allocated(buf)) deallocate(buf)
         if (allocated(rc)) deallocate(rc)
         do j = 1, k - 1                  ! a restart: the states kept from before the dump
            call live_state(j)
            if (allocated(error)) return
         end do
      end if
      call live_state(k)
      if (allocated(error)) return
      call xdmf_write(dir//'/'//XMFNAME, H5NAME, self%title, self%nn, self%ne, self%topo, &
                      self%times(1:k), error, states_dir=LIVE_DIR, rows=self%rows)

   contains

      !> State j from the parts' state-j files, written as the serial writer's (stream_state:
      !> one whole-model field at a time) under temp, fsync and rename (dx_plot_states).
      subroutine live_state(j)
         integer, intent(in) :: j
         type(h5_file_t) :: out
         character(:), allocatable :: g, p
         real(wp) :: t
         real(wp), allocatable :: tmp(:)
         g = state_group(j)
         path = plot_part_state_name(dir, 0, j)
         call h5_open_read(f, path, error)
         if (allocated(error)) return
         call plot_rows_in_file(f, g, self%rows, error)
         if (.not. allocated(error)) call h5_read_attr(f, g, 'time', t, error)
         call h5_close(f, err2)
         if (allocated(error)) return
         self%rows = self%rows .or. .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt
         p = dir//'/'//state_file(j)
         call h5_create(out, p//'.tmp', error)
         if (allocated(error)) return
         call h5_create_group(out, '/states', error)
         if (.not. allocated(error)) call stream_state(out, g, t, dir, j, self%idx, self%x0, &
                                                       self%nn, self%ne, self%rows, error)
         call publish(out, p, error)
         if (allocated(error)) return
         if (j > size(self%times)) then
            allocate(tmp(2*j))
            tmp(1:size(self%times)) = self%times
            call move_alloc(tmp, self%times)
         end if
         self%times(j) = t
      end subroutine live_state
   end subroutine plot_live_publish

   !> State group g of out from the parts' files of state k (dir; idx: each part's global
   !> nodes and elements): the group, its time, then every state field that on names in
   !> table order with the very calls of plot_state_write, so the file's bytes are the
   !> serial writer's. One whole-model field at a time (issue 22: the whole state on rank 0
   !> was its peak memory): a part field is read from every part and scattered to the global
   !> nodes or elements; the derived ones as plot_state_derive forms them (displacement =
   !> coordinates - x0, von Mises and pressure from the stress by stress_invariants), so at
   !> most the stress and its two invariants (or two nodal vectors) are held at once. The NP
   !> state-k files are opened once for the whole state and read field by field (review D1:
   !> an open per field and part made the combine 1.7x main's CPU at NP 4).
   subroutine stream_state(out, g, time, dir, k, idx, x0, nn, ne, on, error)
      type(h5_file_t), intent(inout) :: out
      character(*), intent(in) :: g, dir
      real(wp), intent(in) :: time, x0(:, :)
      integer, intent(in) :: k, nn, ne
      type(part_idx_t), intent(in) :: idx(0:)
      logical, intent(in) :: on(NSTATE_FIELDS)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: a(:, :), keep(:, :), vm(:), pres(:)
      type(plot_field_t) :: fld
      type(h5_file_t), allocatable :: pf(:)
      type(error_t), allocatable :: err2
      integer :: i, r
      allocate(pf(0:size(idx) - 1))
      do r = 0, size(idx) - 1
         call h5_open_read(pf(r), plot_part_state_name(dir, r, k), error)
         if (allocated(error)) exit
      end do
      if (.not. allocated(error)) call fields()
      do r = 0, size(idx) - 1
         if (pf(r)%is_open()) call h5_close(pf(r), err2)
      end do
   contains
      !> the group, its time and the fields, from the open parts pf
      subroutine fields()
         call h5_create_group(out, g, error)
         if (allocated(error)) return
         call h5_write_attr(out, g, 'time', time, error)
         if (allocated(error)) return
         do i = 1, NSTATE_FIELDS
            if (.not. on(i)) cycle
            fld = PLOT_FIELDS(i)
            select case (i)
            case (F_DISP)                    ! (the coordinates come first in the table)
               a = keep - x0
               deallocate(keep)
            case (F_VM)                      ! (the stress comes first; pressure next)
               allocate(vm(ne), pres(ne))
               call stress_invariants(keep, vm, pres)
               deallocate(keep)
               a = reshape(vm, [1, ne])
               deallocate(vm)
            case (F_PRES)
               a = reshape(pres, [1, ne])
               deallocate(pres)
            case default
               call part_field(a)
               if (allocated(error)) return
            end select
            if (fld%int) then
               call h5_write(out, g//'/'//trim(fld%name), nint(a(1, :)), error)
            else if (fld%ncomp == 1) then
               call h5_write(out, g//'/'//trim(fld%name), a(1, :), error)
            else
               call h5_write(out, g//'/'//trim(fld%name), a, error)
            end if
            if (allocated(error)) return
            if ((i == F_COORD .and. on(F_DISP)) .or. (i == F_STRESS .and. on(F_VM))) &
               call move_alloc(a, keep)
         end do
      end subroutine fields

      !> field i of every part scattered to the global nodes or elements (zero elsewhere)
      subroutine part_field(v)
         real(wp), allocatable, intent(out) :: v(:, :)
         real(wp), allocatable :: buf(:)
         integer :: r, n
         n = fld%ncomp
         if (fld%centre == CENTRE_NODE) then
            allocate(v(n, nn))
         else
            allocate(v(n, ne))
         end if
         v = 0.0_wp
         do r = 0, size(idx) - 1
            call h5_read(pf(r), g//'/'//trim(fld%name), buf, error)
            if (allocated(error)) return
            if (fld%centre == CENTRE_NODE) then
               v(:, idx(r)%n) = reshape(buf, [n, size(idx(r)%n)])
            else
               v(:, idx(r)%e) = reshape(buf, [n, size(idx(r)%e)])
            end if
         end do
      end subroutine part_field
   end subroutine stream_state

   !> The root attributes of a part file (format checked).
   subroutine read_header(f, path, np, stamp, nn, ne, title, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: path
      integer, intent(out) :: np, stamp, nn, ne
      character(:), allocatable, intent(out) :: title
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: fmt
      integer :: ver, hv(size(HEADER) - 1)
      np = 0; stamp = 0; nn = 0; ne = 0
      title = ''
      call h5_read_attr(f, '/', 'format', fmt, error)
      if (allocated(error)) return
      call h5_read_attr(f, '/', 'version', ver, error)
      if (allocated(error)) return
      if (fmt /= PART_FORMAT .or. ver /= PART_VERSION) then
         call set_error(error, path//': not a dynx plot part file of version '// &
                        str(PART_VERSION), EXIT_IO)
         return
      end if
      call h5_read_int_attrs(f, '/', HEADER(2:), hv, error)
      if (allocated(error)) return
      np = hv(1); stamp = hv(2); nn = hv(3); ne = hv(4)
      call h5_read_attr(f, '/', 'title', title, error)
      if (allocated(error)) return
      if (np < 1 .or. nn < 0 .or. ne < 0) call set_error(error, path// &
         ': bad header (nprocs '//str(np)//', nodes '//str(nn)//', elements '//str(ne)//')', &
         EXIT_IO)
   end subroutine read_header
end module dx_plot_part
