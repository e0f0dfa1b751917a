!> The output facade the solver calls: plot states (HDF5 + XDMF, *DATABASE_BINARY_D3PLOT)
!> and ASCII time histories (*DATABASE_GLSTAT, *DATABASE_NODOUT with
!> *DATABASE_HISTORY_NODE, *DATABASE_MATSUM, *DATABASE_SPCFORC, *DATABASE_SLEOUT,
!> *DATABASE_ELOUT with *DATABASE_HISTORY_SOLID, *DATABASE_NCFORC). Opens only what the deck
!> asks for: the plot file always, glstat when glstat_dt > 0, nodout when nodout_dt > 0 and
!> history nodes exist, matsum (dx_matsum), spcforc (dx_spcforc), sleout (dx_sleout), elout
!> (dx_elout) and ncforc (dx_ncforc) when their DT > 0.
!> The solver decides when output is due; each call here writes one state or line(s).
!> File formats: docs/output-format.md.
module dx_output
   use dx_error, only: error_t
   use dx_model, only: model_t
   use dx_io_sys, only: sys_mkdir_p
   use dx_log, only: log_warn
   use dx_plot_hdf5, only: plot_file_t
   use dx_thist, only: thist_file_t, glstat_run_columns, NODOUT_COLUMNS
   use dx_matsum, only: matsum_header, matsum_record
   use dx_spcforc, only: spcforc_header, spcforc_record
   use dx_sleout, only: sleout_header, sleout_record
   use dx_elout, only: elout_header, elout_record
   use dx_ncforc, only: ncforc_header, ncforc_record
   implicit none
   private
   public :: output_t

   type :: output_t
      integer :: nplot = 0                   !< plot states written
      character(:), allocatable, private :: dir
      type(plot_file_t), private :: plot
      type(thist_file_t), private :: glstat
      type(thist_file_t), private :: nodout
      type(thist_file_t), private :: matsum, spcforc, sleout, elout, ncforc
      logical, private :: glstat_on = .false., nodout_on = .false., matsum_on = .false., &
                          spcforc_on = .false., sleout_on = .false., elout_on = .false., &
                          ncforc_on = .false.
   contains
      procedure :: open => output_open
      procedure :: write_plot => output_write_plot
      procedure :: plot_by_parts => output_plot_by_parts
      procedure :: write_glstat => output_write_glstat
      procedure :: write_nodout => output_write_nodout
      procedure :: write_matsum => output_write_matsum
      procedure :: write_spcforc => output_write_spcforc
      procedure :: write_sleout => output_write_sleout
      procedure :: write_elout => output_write_elout
      procedure :: write_ncforc => output_write_ncforc
      procedure :: close => output_close
      procedure :: resume => output_resume
      procedure :: sizes => output_sizes
      procedure :: has_glstat => output_has_glstat
      procedure :: has_nodout => output_has_nodout
   end type output_t

contains

   !> Reopen the files of an interrupted run in dir at the restart point recorded in
   !> model%run (plot states, glstat and nodout bytes): what was written after the dump is
   !> dropped, and output continues exactly as the uninterrupted run would have written it.
   subroutine output_resume(self, model, dir, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(*), intent(in) :: dir
      type(error_t), allocatable, intent(out) :: error
      call output_open(self, model, dir, error, resume=.true.)
   end subroutine output_resume

   !> Create dir if missing and open the files the deck asks for; resume = .true.
   !> (output_resume): continue each at the restart point instead of starting it anew.
   subroutine output_open(self, model, dir, error, resume)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      character(*), intent(in) :: dir
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: resume
      type(error_t), allocatable :: err2
      character(:), allocatable :: title
      logical :: nodes, cont

      cont = .false.
      if (present(resume)) cont = resume
      self%dir = trim(dir)
      self%nplot = 0
      title = ''
      if (allocated(model%title)) title = model%title
      call sys_mkdir_p(self%dir, error)
      if (allocated(error)) return
      if (cont) then
         call self%plot%resume(model, self%dir, model%run%nplot, error)
         self%nplot = self%plot%nstates
      else
         call self%plot%open(model, self%dir, error)
      end if
      if (allocated(error)) return

      self%glstat_on = model%db%glstat_dt > 0
      if (self%glstat_on .and. cont) then
         call self%glstat%resume(self%dir//'/glstat', 'glstat', title, glstat_run_columns(model), &
                                 model%run%glstat_bytes, error)
      else if (self%glstat_on) then
         call self%glstat%open(self%dir//'/glstat', 'glstat', title, glstat_run_columns(model), &
                               error)
      end if
      nodes = .false.
      if (allocated(model%db%hist_nodes)) nodes = size(model%db%hist_nodes) > 0
      self%nodout_on = model%db%nodout_dt > 0 .and. nodes
      if (self%nodout_on .and. .not. allocated(error)) then
         if (cont) then
            call self%nodout%resume(self%dir//'/nodout', 'nodout', title, NODOUT_COLUMNS, &
                                    model%run%nodout_bytes, error)
         else
            call self%nodout%open(self%dir//'/nodout', 'nodout', title, NODOUT_COLUMNS, error)
         end if
      end if
      self%matsum_on = model%db%matsum_dt > 0
      if (self%matsum_on .and. .not. allocated(error)) &
         call open_layout_file(self%matsum, self%dir, 'matsum', title, matsum_header(model), cont, &
                               model%run%matsum_bytes, error)
      self%spcforc_on = model%db%spcforc_dt > 0
      if (self%spcforc_on .and. .not. allocated(error)) &
         call open_layout_file(self%spcforc, self%dir, 'spcforc', title, spcforc_header(model), &
                               cont, model%run%spcforc_bytes, error)
      self%sleout_on = model%db%sleout_dt > 0
      if (self%sleout_on .and. .not. allocated(error)) &
         call open_layout_file(self%sleout, self%dir, 'sleout', title, sleout_header(model), cont, &
                               model%run%sleout_bytes, error)
      self%elout_on = model%db%elout_dt > 0
      if (self%elout_on .and. .not. allocated(error)) &
         call open_layout_file(self%elout, self%dir, 'elout', title, elout_header(model), cont, &
                               model%run%elout_bytes, error)
      self%ncforc_on = model%db%ncforc_dt > 0
      if (self%ncforc_on .and. .not. allocated(error)) &
         call open_layout_file(self%ncforc, self%dir, 'ncforc', title, ncforc_header(model), &
                               cont, model%run%ncforc_bytes, error)
      if (allocated(error)) call self%close(err2)   ! keep the first error
   end subroutine output_open

   !> Open dir/what, one of the files that keep LS-DYNA's own layout (header: its lines), or
   !> with cont resume it at nbytes (output_open).
   subroutine open_layout_file(file, dir, what, title, header, cont, nbytes, error)
      type(thist_file_t), intent(inout) :: file
      character(*), intent(in) :: dir, what, title, header
      logical, intent(in) :: cont
      integer(8), intent(in) :: nbytes
      type(error_t), allocatable, intent(out) :: error
      if (cont) then
         call file%resume(dir//'/'//what, what, title, '', nbytes, error, header)
      else
         call file%open(dir//'/'//what, what, title, '', error, header)
      end if
   end subroutine open_layout_file

   !> What a restart dump records about the output: plot states, glstat, nodout, matsum,
   !> spcforc, sleout, elout and ncforc bytes.
   subroutine output_sizes(self, nplot, glstat_bytes, nodout_bytes, matsum_bytes, &
                           spcforc_bytes, sleout_bytes, elout_bytes, ncforc_bytes)
      class(output_t), intent(in) :: self
      integer, intent(out) :: nplot
      integer(8), intent(out) :: glstat_bytes, nodout_bytes, matsum_bytes, spcforc_bytes, &
                                 sleout_bytes, elout_bytes, ncforc_bytes
      nplot = self%plot%nstates
      glstat_bytes = self%glstat%bytes
      nodout_bytes = self%nodout%bytes
      matsum_bytes = self%matsum%bytes
      spcforc_bytes = self%spcforc%bytes
      sleout_bytes = self%sleout%bytes
      elout_bytes = self%elout%bytes
      ncforc_bytes = self%ncforc%bytes
   end subroutine output_sizes

   !> An MPI run: the ranks' parts hold the states, dx_par_plot publishes them while the run
   !> goes and combines them at its end; this writer's close then leaves the XDMF and the
   !> state files alone (dx_plot_hdf5: plot_close).
   subroutine output_plot_by_parts(self)
      class(output_t), intent(inout) :: self
      call self%plot%set_by_parts()
   end subroutine output_plot_by_parts

   !> Write one plot state at model%time.
   subroutine output_write_plot(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      call self%plot%write_state(model, error)
      self%nplot = self%plot%nstates
   end subroutine output_write_plot

   !> Write one glstat line (nothing when the deck asks for none).
   subroutine output_write_glstat(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      if (.not. self%glstat_on) return
      call self%glstat%write_glstat(model, error)
   end subroutine output_write_glstat

   !> Write the nodout lines of one output time (nothing when the deck asks for none).
   subroutine output_write_nodout(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      if (.not. self%nodout_on) return
      call self%nodout%write_nodout(model, error)
   end subroutine output_write_nodout

   !> Write one matsum record (nothing when the deck asks for none).
   subroutine output_write_matsum(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (.not. self%matsum_on) return
      call matsum_record(model, text, error)
      if (allocated(error) .or. len(text) == 0) return
      call self%matsum%write_text(text, error)
   end subroutine output_write_matsum

   !> Write one spcforc record (nothing when the deck asks for none).
   subroutine output_write_spcforc(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (.not. self%spcforc_on) return
      call spcforc_record(model, text, error)
      if (allocated(error) .or. len(text) == 0) return
      call self%spcforc%write_text(text, error)
   end subroutine output_write_spcforc

   !> Write one sleout record (nothing when the deck asks for none).
   subroutine output_write_sleout(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (.not. self%sleout_on) return
      call sleout_record(model, text, error)
      if (allocated(error) .or. len(text) == 0) return
      call self%sleout%write_text(text, error)
   end subroutine output_write_sleout

   !> Write one elout record from model%db%elout_vals, or one ncforc record (nothing when
   !> the deck asks for none).
   subroutine output_write_elout(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (.not. self%elout_on) return
      call elout_record(model, text, error)
      if (.not. allocated(error)) call self%elout%write_text(text, error)
   end subroutine output_write_elout

   subroutine output_write_ncforc(self, model, error)
      class(output_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (.not. self%ncforc_on) return
      call ncforc_record(model, text, error)
      if (.not. allocated(error) .and. len(text) > 0) call self%ncforc%write_text(text, error)
   end subroutine output_write_ncforc

   !> Flush and close everything; safe to call twice and after errors. Returns the first
   !> failure but still closes the other files.
   subroutine output_close(self, error)
      class(output_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e1, e2, e3, e4, e5, e6, e7, e8
      call self%plot%close(e1)
      call self%glstat%close(e2)
      call self%nodout%close(e3)
      call self%matsum%close(e4)
      call self%spcforc%close(e5)
      call self%sleout%close(e6)
      call self%elout%close(e7)
      call self%ncforc%close(e8)
      if (allocated(e1)) then
         call move_alloc(e1, error)
      else if (allocated(e2)) then
         call move_alloc(e2, error)
      else if (allocated(e3)) then
         call move_alloc(e3, error)
      else if (allocated(e4)) then
         call move_alloc(e4, error)
      else if (allocated(e5)) then
         call move_alloc(e5, error)
      else if (allocated(e6)) then
         call move_alloc(e6, error)
      else if (allocated(e7)) then
         call move_alloc(e7, error)
      else if (allocated(e8)) then
         call move_alloc(e8, error)
      end if
   end subroutine output_close

   !> Whether a glstat file is open (the deck asked for one).
   logical function output_has_glstat(self)
      class(output_t), intent(in) :: self
      output_has_glstat = self%glstat_on
   end function output_has_glstat

   !> Whether a nodout file is open (the deck asked for one and has history nodes).
   logical function output_has_nodout(self)
      class(output_t), intent(in) :: self
      output_has_nodout = self%nodout_on
   end function output_has_nodout
end module dx_output
