!> The plot-field schema: one table of the fields of a plot state (name, centring, components,
!> number type, source), used by every plot writer (the serial d3plot.h5 and its state files,
!> dx_plot_hdf5 and dx_plot_states; the per-rank parts and their combiner, dx_plot_part,
!> dx_par_plot, dynx-combine) and by the XDMF writer (dx_xdmf), so that a new field is one
!> row of PLOT_FIELDS plus the line that fills its values (plot_state_t, by its index).
!> Layout (docs/output-format.md): state k is the group /states/NNNNNN; a field of ncomp
!> components is the dataset NAME of shape (ncomp, n) in Fortran order, or (n) when ncomp = 1;
!> n is the node count (centring node) or the element count (centring cell).
!> Sources: SRC_NODAL, the model's nodal arrays; SRC_ELEMENT, an element's value averaged over
!> its integration points (dx_plot_hdf5: element_average); both are what each rank writes to
!> its part. SRC_DERIVED fields are computed from those (plot_state_derive) by the serial
!> writer and the combiner alike, so the bits agree. SRC_MESH rows are /mesh datasets that
!> the XDMF lists as attributes. The row order is the order of the writes (HDF5 lays a file
!> out by its sequence of calls) and of the XDMF attributes.
!> Optional rows (opt = .true.): a field present only when the model uses it (the damage D of
!> the Tuler-Butcher erosion, dx_erosion: when some part has it; the beams' resultants
!> beam_force = (N, Q_s, Q_t) and beam_moment = (T, M_s, M_t) in each beam's own frame,
!> zero on the other cells: when the deck has a beam part; the shell thickness, when some
!> part is a BT shell part, 0 on the other elements); a state's rows in use are
!> plot_state_t%on (set by plot_state_alloc's rows, found in a file by plot_state_read), the
!> XDMF lists the rows in use (xdmf_write's rows), so a deck that uses no optional row writes
!> the very files it wrote before the row existed.
!> Von Mises stress and pressure: Malvern, "Introduction to the Mechanics of a Continuous
!> Medium" (1969), sec. 6.5 (J2 = s:s/2, sigma_vm = sqrt(3 J2), p = -tr(sigma)/3).
module dx_plot_fields
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_strings, only: str
   use dx_h5, only: h5_file_t, h5_write, h5_read, h5_create_group, h5_write_attr, h5_read_attr, &
                    h5_exists
   use dx_plot_cells, only: write_cells, read_cells
   implicit none
   private
   public :: plot_field_t, PLOT_FIELDS, NSTATE_FIELDS, plot_state_t, CENTRE_NODE, CENTRE_CELL, &
             SRC_NODAL, SRC_ELEMENT, SRC_DERIVED, SRC_MESH, F_COORD, F_DISP, F_VEL, F_STRESS, &
             F_VM, F_PRES, F_EPSP, F_FAILED, F_DAMAGE, F_BEAM_FORCE, F_BEAM_MOMENT, F_THICK, &
             field_in_part, plot_rows_in_file, &
             xdmf_attribute_type, &
             plot_state_alloc, plot_state_derive, plot_state_write, plot_state_read, &
             stress_invariants, plot_mesh_write, plot_mesh_read

   integer, parameter :: CENTRE_NODE = 1, CENTRE_CELL = 2
   integer, parameter :: SRC_NODAL = 1, SRC_ELEMENT = 2, SRC_DERIVED = 3, SRC_MESH = 4

   !> One field of the plot file.
   type :: plot_field_t
      character(24) :: name = ''     !< dataset: state group member, or /mesh/ path (SRC_MESH)
      character(24) :: label = ''    !< XDMF attribute name; '' = the geometry (no attribute)
      integer :: centre = CENTRE_NODE
      integer :: ncomp = 1           !< 1 scalar, 3 vector, 6 symmetric tensor (xx yy zz xy yz zx)
      logical :: int = .false.       !< written as 4-byte integers (values are whole numbers)
      integer :: source = SRC_NODAL
      logical :: opt = .false.       !< optional row: present only when the model uses it
   end type plot_field_t

   !> The schema. State fields first (NSTATE_FIELDS rows, in write order), then the /mesh
   !> datasets the XDMF also lists.
   integer, parameter :: NSTATE_FIELDS = 12
   integer, parameter :: F_COORD = 1, F_DISP = 2, F_VEL = 3, F_STRESS = 4, F_VM = 5, &
                         F_PRES = 6, F_EPSP = 7, F_FAILED = 8, F_DAMAGE = 9, &
                         F_BEAM_FORCE = 10, F_BEAM_MOMENT = 11, F_THICK = 12
   type(plot_field_t), parameter :: PLOT_FIELDS(15) = [ &
      plot_field_t('coordinates', '', CENTRE_NODE, 3, .false., SRC_NODAL), &
      plot_field_t('displacement', 'displacement', CENTRE_NODE, 3, .false., SRC_DERIVED), &
      plot_field_t('velocity', 'velocity', CENTRE_NODE, 3, .false., SRC_NODAL), &
      plot_field_t('stress', 'stress', CENTRE_CELL, 6, .false., SRC_ELEMENT), &
      plot_field_t('von_mises', 'von_mises', CENTRE_CELL, 1, .false., SRC_DERIVED), &
      plot_field_t('pressure', 'pressure', CENTRE_CELL, 1, .false., SRC_DERIVED), &
      plot_field_t('eff_plastic_strain', 'eff_plastic_strain', CENTRE_CELL, 1, .false., &
                   SRC_ELEMENT), &
      plot_field_t('failed', 'failed', CENTRE_CELL, 1, .true., SRC_ELEMENT), &
      plot_field_t('damage', 'damage', CENTRE_CELL, 1, .false., SRC_ELEMENT, .true.), &
      plot_field_t('beam_force', 'beam_force', CENTRE_CELL, 3, .false., SRC_ELEMENT, .true.), &
      plot_field_t('beam_moment', 'beam_moment', CENTRE_CELL, 3, .false., SRC_ELEMENT, &
                   .true.), &
      plot_field_t('thickness', 'thickness', CENTRE_CELL, 1, .false., SRC_ELEMENT, .true.), &
      plot_field_t('/mesh/part_ids', 'part_id', CENTRE_CELL, 1, .true., SRC_MESH), &
      plot_field_t('/mesh/element_ids', 'element_id', CENTRE_CELL, 1, .true., SRC_MESH), &
      plot_field_t('/mesh/node_ids', 'node_id', CENTRE_NODE, 1, .true., SRC_MESH)]

   !> The values of one state: f(i)%r(ncomp, n) for state field i of PLOT_FIELDS (integer
   !> fields held as reals and rounded when written).
   type :: field_values_t
      real(wp), allocatable :: r(:, :)
   end type field_values_t
   type :: plot_state_t
      real(wp) :: time = 0.0_wp
      type(field_values_t) :: f(NSTATE_FIELDS)
      !> the rows this state has (every row but the optional ones unless asked for)
      logical :: on(NSTATE_FIELDS) = .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt
   end type plot_state_t

contains

   !> Whether field i is written by each rank to its part (the others are derived).
   pure logical function field_in_part(i)
      integer, intent(in) :: i
      field_in_part = PLOT_FIELDS(i)%source == SRC_NODAL .or. &
                      PLOT_FIELDS(i)%source == SRC_ELEMENT
   end function field_in_part

   !> XDMF AttributeType of a field by its component count.
   function xdmf_attribute_type(fld) result(t)
      type(plot_field_t), intent(in) :: fld
      character(:), allocatable :: t
      select case (fld%ncomp)
      case (1); t = 'Scalar'
      case (3); t = 'Vector'
      case default; t = 'Tensor6'
      end select
   end function xdmf_attribute_type

   !> Allocate the state fields for nn nodes and ne elements (values zero); part = .true.:
   !> only the fields a rank writes to its part; rows: the optional rows in use (default
   !> none).
   subroutine plot_state_alloc(st, nn, ne, part, rows)
      type(plot_state_t), intent(inout) :: st
      integer, intent(in) :: nn, ne
      logical, intent(in), optional :: part
      logical, intent(in), optional :: rows(NSTATE_FIELDS)
      integer :: i
      st%on = .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt
      if (present(rows)) st%on = st%on .or. rows
      do i = 1, NSTATE_FIELDS
         if (allocated(st%f(i)%r)) deallocate(st%f(i)%r)
         if (.not. st%on(i)) cycle
         if (present(part)) then
            if (part .and. .not. field_in_part(i)) cycle
         end if
         if (PLOT_FIELDS(i)%centre == CENTRE_NODE) then
            allocate(st%f(i)%r(PLOT_FIELDS(i)%ncomp, nn))
         else
            allocate(st%f(i)%r(PLOT_FIELDS(i)%ncomp, ne))
         end if
         st%f(i)%r = 0.0_wp
      end do
   end subroutine plot_state_alloc

   !> The derived fields from the others: displacement = coordinates - x0, von Mises stress
   !> and pressure of the averaged stress.
   subroutine plot_state_derive(st, x0)
      type(plot_state_t), intent(inout) :: st
      real(wp), intent(in) :: x0(:, :)
      st%f(F_DISP)%r = st%f(F_COORD)%r - x0
      call stress_invariants(st%f(F_STRESS)%r, st%f(F_VM)%r(1, :), st%f(F_PRES)%r(1, :))
   end subroutine plot_state_derive

   !> Von Mises stress and pressure -(xx + yy + zz)/3 of averaged stresses (6, ne); the one
   !> place this arithmetic lives, so a combined MPI plot file (dx_plot_part) has the bits
   !> of the serial one.
   subroutine stress_invariants(stress, vm, pres)
      real(wp), intent(in) :: stress(:, :)
      real(wp), intent(out) :: vm(:), pres(:)
      real(wp) :: s(6)
      integer :: e
      do e = 1, size(vm)
         s = stress(:, e)
         vm(e) = sqrt(max(0.0_wp, 0.5_wp*((s(1) - s(2))**2 + (s(2) - s(3))**2 &
                 + (s(3) - s(1))**2) + 3.0_wp*(s(4)**2 + s(5)**2 + s(6)**2)))
         pres(e) = -(s(1) + s(2) + s(3))/3.0_wp
      end do
   end subroutine stress_invariants

   !> Write state group g of f: the group, its time attribute, then every state field in
   !> table order (part = .true.: only the fields of a rank's part).
   subroutine plot_state_write(f, g, st, error, part)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: g
      type(plot_state_t), intent(in) :: st
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: part
      integer :: i
      logical :: only_part
      type(plot_field_t) :: fld
      only_part = .false.
      if (present(part)) only_part = part
      call h5_create_group(f, g, error)
      if (allocated(error)) return
      call h5_write_attr(f, g, 'time', st%time, error)
      if (allocated(error)) return
      do i = 1, NSTATE_FIELDS
         if (only_part .and. .not. field_in_part(i)) cycle
         if (.not. st%on(i)) cycle
         fld = PLOT_FIELDS(i)
         if (fld%int) then
            call h5_write(f, g//'/'//trim(fld%name), nint(st%f(i)%r(1, :)), error)
         else if (fld%ncomp == 1) then
            call h5_write(f, g//'/'//trim(fld%name), st%f(i)%r(1, :), error)
         else
            call h5_write(f, g//'/'//trim(fld%name), st%f(i)%r, error)
         end if
         if (allocated(error)) return
      end do
   end subroutine plot_state_write

   !> Read state group g of f (its time and the state fields; part = .true.: only those of
   !> a rank's part) for nn nodes and ne elements. A dataset of another size is an I/O error
   !> "<before><dataset> has N values, expected M<after>".
   subroutine plot_state_read(f, g, nn, ne, st, before, after, error, part)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: g, before, after
      integer, intent(in) :: nn, ne
      type(plot_state_t), intent(inout) :: st
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: part
      real(wp), allocatable :: buf(:)
      logical :: rows(NSTATE_FIELDS)
      integer :: i, n
      call plot_rows_in_file(f, g, rows, error)
      if (allocated(error)) return
      call plot_state_alloc(st, nn, ne, part, rows)
      call h5_read_attr(f, g, 'time', st%time, error)
      if (allocated(error)) return
      do i = 1, NSTATE_FIELDS
         if (.not. allocated(st%f(i)%r)) cycle
         call h5_read(f, g//'/'//trim(PLOT_FIELDS(i)%name), buf, error)
         if (allocated(error)) return
         n = size(st%f(i)%r)
         if (size(buf) /= n) then
            call set_error(error, before//g//'/'//trim(PLOT_FIELDS(i)%name)//' has '// &
                           str(size(buf))//' values, expected '//str(n)//after, EXIT_IO)
            return
         end if
         st%f(i)%r = reshape(buf, shape(st%f(i)%r))
      end do
   end subroutine plot_state_read

   !> The optional rows that state group g of f holds (a dataset of that name).
   subroutine plot_rows_in_file(f, g, rows, error)
      type(h5_file_t), intent(in) :: f
      character(*), intent(in) :: g
      logical, intent(out) :: rows(NSTATE_FIELDS)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      rows = .false.
      do i = 1, NSTATE_FIELDS
         if (.not. PLOT_FIELDS(i)%opt) cycle
         call h5_exists(f, g//'/'//trim(PLOT_FIELDS(i)%name), rows(i), error)
         if (allocated(error)) return
      end do
   end subroutine plot_rows_in_file

   !> The /mesh group of a plot file (serial d3plot.h5, its mesh file, the combined file):
   !> coordinates, node ids, cells, element ids, part ids, then the title attribute.
   subroutine plot_mesh_write(f, x0, nlab, cells, elab, ids, title, error)
      type(h5_file_t), intent(inout) :: f
      real(wp), intent(in) :: x0(:, :)
      integer, intent(in) :: nlab(:), cells(:, :), elab(:), ids(:)
      character(*), intent(in) :: title
      type(error_t), allocatable, intent(out) :: error
      call h5_create_group(f, '/mesh', error)
      if (allocated(error)) return
      call h5_write(f, '/mesh/coordinates', x0, error)
      if (allocated(error)) return
      call h5_write(f, '/mesh/node_ids', nlab, error)
      if (allocated(error)) return
      call write_cells(f, cells, error)
      if (allocated(error)) return
      call h5_write(f, '/mesh/element_ids', elab, error)
      if (allocated(error)) return
      call h5_write(f, '/mesh/part_ids', ids, error)
      if (allocated(error)) return
      call h5_write_attr(f, '/', 'title', title, error)
   end subroutine plot_mesh_write

   !> Read the /mesh group of a plot file as plot_mesh_write wrote it (the numbers as
   !> float64, flat, in Fortran order; the cells of ne elements).
   subroutine plot_mesh_read(f, x0, nlab, cells, elab, ids, title, error)
      type(h5_file_t), intent(in) :: f
      real(wp), allocatable, intent(out) :: x0(:), nlab(:), elab(:), ids(:)
      integer, allocatable, intent(out) :: cells(:, :)
      character(:), allocatable, intent(out) :: title
      type(error_t), allocatable, intent(out) :: error
      call h5_read(f, '/mesh/coordinates', x0, error)
      if (.not. allocated(error)) call h5_read(f, '/mesh/node_ids', nlab, error)
      if (.not. allocated(error)) call h5_read(f, '/mesh/element_ids', elab, error)
      if (.not. allocated(error)) call h5_read(f, '/mesh/part_ids', ids, error)
      if (.not. allocated(error)) call read_cells(f, size(ids), cells, error)
      if (.not. allocated(error)) call h5_read_attr(f, '/', 'title', title, error)
   end subroutine plot_mesh_read
end module dx_plot_fields
