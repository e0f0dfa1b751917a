!> ASCII time histories, the dynx counterparts of LS-DYNA's *DATABASE_GLSTAT (global
!> energies and momentum) and *DATABASE_NODOUT (nodal displacement, velocity, acceleration
!> and coordinates of *DATABASE_HISTORY_NODE nodes).
!> Format (docs/output-format.md): '#' header lines, the last one naming the columns, then
!> whitespace-separated columns in es18.10e3 (10 significant digits, 3-digit exponent) so
!> regression diffs are meaningful. Each line goes to the file in one write(2) (dx_io_sys:
!> a Fortran FLUSH does not report a failed write), so a killed run leaves only whole lines
!> and a full disk is an error naming the file and the reason, the file cut back to its
!> last whole line (no short line, no hole of NUL bytes).
module dx_thist
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t
   use dx_append_file, only: cut_back
   use dx_strings, only: str
   use dx_io_sys, only: sys_truncate, sys_open_write, sys_write_all, sys_close_fd, &
                        sys_ftruncate_fd
   implicit none
   private
   public :: thist_file_t, GLSTAT_COLUMNS, NODOUT_COLUMNS, glstat_run_columns, layout_header

   character(*), parameter :: GLSTAT_COLUMNS = 'time cycle dt kinetic internal hourglass ' // &
      'external_work rigidwall total energy_ratio xmom ymom zmom sliding_interface'
   character(*), parameter :: NODOUT_COLUMNS = 'time node_id x_disp y_disp z_disp ' // &
      'x_vel y_vel z_vel x_acc y_acc z_acc x_coor y_coor z_coor'
   character(*), parameter :: GLSTAT_FMT = '(es18.10e3, 1x, i10, 12(1x, es18.10e3))'
   !> with mass scaling (*CONTROL_TIMESTEP DT2MS /= 0) two more columns, LS-DYNA's glstat
   !> lines "added mass" and "percentage increase" (100 * added / the model's mass)
   character(*), parameter :: GLSTAT_MS_COLUMNS = ' added_mass percent_increase'
   character(*), parameter :: GLSTAT_MS_FMT = '(es18.10e3, 1x, i10, 14(1x, es18.10e3))'
   !> with element erosion (model%erodes: *MAT_ADD_EROSION, *CONTROL_TIMESTEP ERODE = 1) two
   !> more, LS-DYNA's glstat names: parts of kinetic and internal, reported apart (dx_erosion)
   character(*), parameter :: GLSTAT_ERO_COLUMNS = ' eroded_internal_energy ' // &
      'eroded_kinetic_energy'
   character(*), parameter :: NODOUT_FMT = '(es18.10e3, 1x, i10, 12(1x, es18.10e3))'

   !> One ASCII history file (unit: its file descriptor while opened).
   type :: thist_file_t
      integer :: unit = -1
      logical :: opened = .false.
      character(:), allocatable :: path
      integer(8) :: bytes = 0          !< bytes written (a restart dump records it)
   contains
      procedure :: open => thist_open
      procedure :: resume => thist_resume
      procedure :: write_glstat
      procedure :: write_nodout
      procedure :: write_text
      procedure :: close => thist_close
   end type thist_file_t

contains

   !> The glstat columns of this model's run (with the mass-scaling columns under DT2MS).
   function glstat_run_columns(model) result(cols)
      type(model_t), intent(in) :: model
      character(:), allocatable :: cols
      cols = GLSTAT_COLUMNS
      if (model%ctrl%dt2ms /= 0.0_wp) cols = cols//GLSTAT_MS_COLUMNS
      if (model%erodes) cols = cols//GLSTAT_ERO_COLUMNS
   end function glstat_run_columns

   !> Create path and write the header: '# dynx <what>', '# title: ...', '<columns>': the
   !> names line without '#', so that gnuplot's `set key autotitle columnhead` (which skips
   !> '#' lines) names the columns (issue 21; the readers take both forms:
   !> docs/output-format.md, "Column files")
   !> (header: these lines instead, for the files that keep LS-DYNA's own layout).
   subroutine thist_open(self, path, what, title, columns, error, header)
      class(thist_file_t), intent(inout) :: self
      character(*), intent(in) :: path, what, title, columns
      type(error_t), allocatable, intent(out) :: error
      character(*), intent(in), optional :: header
      self%path = path
      call sys_open_write(path, .false., self%unit, error)
      if (allocated(error)) return
      self%opened = .true.
      self%bytes = 0
      if (present(header)) then
         call self%write_text(header, error)
         return
      end if
      call put_line(self, '# dynx '//what, error)
      if (allocated(error)) return
      call put_line(self, '# title: '//trim(title), error)
      if (allocated(error)) return
      call put_line(self, columns, error)
   end subroutine thist_open

   !> Continue a file from a restart point: cut it back to its first nbytes bytes (the
   !> lines the killed run wrote after the dump go) and append. A missing file is started
   !> anew with its header; a file shorter than nbytes is an error (it is not this run's).
   subroutine thist_resume(self, path, what, title, columns, nbytes, error, header)
      class(thist_file_t), intent(inout) :: self
      character(*), intent(in) :: path, what, title, columns
      integer(8), intent(in) :: nbytes
      type(error_t), allocatable, intent(out) :: error
      character(*), intent(in), optional :: header
      integer(8) :: sz
      logical :: there
      inquire(file=path, exist=there, size=sz)
      if (.not. there) then
         call self%open(path, what, title, columns, error, header)
         return
      end if
      call cut_back(path, sz, nbytes, 'another run''s file?', error)
      if (allocated(error)) return
      self%path = path
      call sys_open_write(path, .true., self%unit, error)
      if (allocated(error)) return
      self%opened = .true.
      self%bytes = nbytes
   end subroutine thist_resume

   !> Write one whole line; on failure cut the file back to its last whole line.
   subroutine put_line(self, line, error)
      class(thist_file_t), intent(inout) :: self
      character(*), intent(in) :: line
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      call sys_write_all(self%unit, line//new_line('a'), self%path, error)
      if (allocated(error)) then
         call sys_ftruncate_fd(self%unit, self%bytes, self%path, e)
         return
      end if
      self%bytes = self%bytes + len(line) + 1
   end subroutine put_line

   !> A record of whole lines (text ends with a new line) in one write: a killed run leaves
   !> the record whole or absent; on failure the file is cut back to the last record.
   subroutine write_text(self, text, error)
      class(thist_file_t), intent(inout) :: self
      character(*), intent(in) :: text
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      call sys_write_all(self%unit, text, self%path, error)
      if (allocated(error)) then
         call sys_ftruncate_fd(self%unit, self%bytes, self%path, e)
         return
      end if
      self%bytes = self%bytes + len(text)
   end subroutine write_text

   !> One glstat line at model%time.
   subroutine write_glstat(self, model, error)
      class(thist_file_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(400) :: line
      integer :: ios
      character(256) :: msg
      real(wp) :: pct
      real(wp), allocatable :: extra(:)
      associate (en => model%energy)
         if (model%erodes) then
            ! the optional columns in the order of glstat_run_columns
            pct = 0.0_wp
            if (en%mass > 0.0_wp) pct = 100.0_wp*en%added_mass/en%mass
            if (model%ctrl%dt2ms /= 0.0_wp) then
               extra = [en%added_mass, pct, en%eroded_ie, en%eroded_ke]
            else
               extra = [en%eroded_ie, en%eroded_ke]
            end if
            write(line, '(es18.10e3, 1x, i10, '//str(12 + size(extra))// &
                  '(1x, es18.10e3))', iostat=ios, iomsg=msg) model%time, model%cycle, &
               model%dt, en%kinetic, en%internal, en%hourglass, en%external_work, &
               en%rigidwall, en%total, en%ratio, en%momentum, en%sliding, extra
         else if (model%ctrl%dt2ms /= 0.0_wp) then
            pct = 0.0_wp
            if (en%mass > 0.0_wp) pct = 100.0_wp*en%added_mass/en%mass
            write(line, GLSTAT_MS_FMT, iostat=ios, iomsg=msg) model%time, model%cycle, &
               model%dt, en%kinetic, en%internal, en%hourglass, en%external_work, &
               en%rigidwall, en%total, en%ratio, en%momentum, en%sliding, en%added_mass, pct
         else
            write(line, GLSTAT_FMT, iostat=ios, iomsg=msg) model%time, model%cycle, model%dt, &
               en%kinetic, en%internal, en%hourglass, en%external_work, en%rigidwall, &
               en%total, en%ratio, en%momentum, en%sliding
         end if
      end associate
      if (ios /= 0) then
         call set_error(error, 'cannot format a glstat line: '//trim(msg), EXIT_IO)
         return
      end if
      call put_line(self, trim(line), error)
   end subroutine write_glstat

   !> One nodout line per history node at model%time; acceleration = f/mass (0 if mass 0).
   subroutine write_nodout(self, model, error)
      class(thist_file_t), intent(inout) :: self
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(280) :: line
      integer :: ios, k, n, lab
      character(256) :: msg
      real(wp) :: x(3), v(3), a(3)
      if (.not. allocated(model%db%hist_nodes)) return
      do k = 1, size(model%db%hist_nodes)
         n = model%db%hist_nodes(k)
         x = model%x0(:, n)
         if (allocated(model%x)) x = model%x(:, n)
         v = 0.0_wp
         if (allocated(model%v)) v = model%v(:, n)
         a = 0.0_wp
         if (allocated(model%f) .and. allocated(model%mass)) then
            if (model%mass(n) > 0.0_wp) a = model%f(:, n)/model%mass(n)
         end if
         lab = n
         if (allocated(model%node_label)) lab = model%node_label(n)
         write(line, NODOUT_FMT, iostat=ios, iomsg=msg) model%time, lab, &
            x - model%x0(:, n), v, a, x
         if (ios /= 0) then
            call set_error(error, 'cannot format a nodout line: '//trim(msg), EXIT_IO)
            return
         end if
         call put_line(self, trim(line), error)
         if (allocated(error)) return
      end do
   end subroutine write_nodout

   !> Close the file if open (safe to call twice).
   subroutine thist_close(self, error)
      class(thist_file_t), intent(inout) :: self
      type(error_t), allocatable, intent(out) :: error
      if (.not. self%opened) return
      call sys_close_fd(self%unit, .true., self%path, error)
      self%opened = .false.
      self%unit = -1
   end subroutine thist_close
   !> The two heading lines of an LS-DYNA-layout ASCII file (spcforc, elout, ncforc):
   !> ' '//first//the model's title, then ' '//second.
   function layout_header(model, first, second) result(text)
      type(model_t), intent(in) :: model
      character(*), intent(in) :: first, second
      character(:), allocatable :: text
      character, parameter :: nl = new_line('a')
      character(:), allocatable :: title
      title = ''
      if (allocated(model%title)) title = trim(model%title)
      text = ' '//first//title//nl//' '//second//nl
   end function layout_header
end module dx_thist
