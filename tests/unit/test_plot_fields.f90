!> Unit tests of the plot-field schema (dx_plot_fields) against the XDMF writer (dx_xdmf) and
!> the HDF5 datasets: one hex (8 nodes, 1 element) with x = x0 + (1, 2, 3), a uniaxial stress
!> of 100 and a failed flag is written as mesh + one state (plot_mesh_write, plot_state_write)
!> and described by xdmf_write. Checks: every labelled row of PLOT_FIELDS is exactly one XDMF
!> attribute, with the AttributeType of its component count, its centring, its dimensions
!> (nodes or elements, times components), its number type and its dataset, and that dataset in
!> the HDF5 file has that many values and rank 1 (scalar) or 2; no attribute without a row;
!> the geometry is the coordinates row; the derived fields are exact (displacement x - x0 to
!> the bit, von Mises 100 and pressure -100/3 of uniaxial stress within 4 ulps); the state
!> read back (plot_state_read) equals the one written, bit for bit. Optional rows (damage,
!> thickness): the state above has them (plot_state_alloc rows, xdmf_write rows) and reads
!> back with them; a state allocated without rows has none (not allocated, on = .false.).
program test_plot_fields
   use dx_kinds, only: wp, i8
   use dx_error, only: error_t
   use dx_h5, only: h5_file_t, h5_create, h5_open_read, h5_close, h5_read, h5_dims, &
                    h5_create_group
   use dx_io_sys, only: sys_mkdir_p
   use dx_xdmf, only: xdmf_write
   use dx_plot_cells, only: cells_topology
   use dx_plot_fields, only: plot_field_t, PLOT_FIELDS, NSTATE_FIELDS, plot_state_t, &
                             plot_state_alloc, plot_state_derive, plot_state_write, &
                             plot_state_read, plot_mesh_write, CENTRE_NODE, SRC_MESH, F_COORD, &
                             F_DISP, F_VEL, F_STRESS, F_VM, F_PRES, F_EPSP, F_FAILED, &
                             F_DAMAGE, F_BEAM_FORCE, F_BEAM_MOMENT, F_THICK, plot_rows_in_file
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   character(*), parameter :: TMP = 'build/test_plot_fields.tmp'
   integer, parameter :: NN = 8, NE = 1, MAXL = 400
   type(error_t), allocatable :: error
   type(plot_state_t) :: st, back, plain
   logical :: rows(NSTATE_FIELDS)
   type(h5_file_t) :: f
   real(wp) :: x0(3, NN)
   integer :: cells(8, NE), i, j, nlines, nattr, u, ios
   character(MAXL) :: lines(200)

   call sys_mkdir_p(TMP, error)
   call check(.not. allocated(error), 'create scratch dir '//TMP)
   do i = 1, NN
      x0(:, i) = [real(merge(1, 0, mod(i - 1, 4) == 1 .or. mod(i - 1, 4) == 2), wp), &
                  real(merge(1, 0, mod(i - 1, 4) >= 2), wp), real((i - 1)/4, wp)]
   end do
   cells(:, 1) = [(i - 1, i = 1, 8)]

   ! ---- one state
   call plot_state_alloc(plain, NN, NE)
   call check(.not. plain%on(F_DAMAGE) .and. .not. allocated(plain%f(F_DAMAGE)%r) .and. &
              all(plain%on .eqv. .not. PLOT_FIELDS(1:NSTATE_FIELDS)%opt), &
              'without rows: no optional row')
   rows = .true.
   call plot_state_alloc(st, NN, NE, rows=rows)
   call check(all(st%on), 'with rows: every row')
   st%time = 0.5_wp
   st%f(F_DAMAGE)%r(1, 1) = 0.75_wp
   st%f(F_BEAM_FORCE)%r(:, 1) = [1.5_wp, -2.0_wp, 0.25_wp]
   st%f(F_BEAM_MOMENT)%r(:, 1) = [-3.0_wp, 0.5_wp, 7.0_wp]
   st%f(F_THICK)%r(1, 1) = 1.5_wp
   st%f(F_COORD)%r = x0 + spread([1.0_wp, 2.0_wp, 3.0_wp], 2, NN)
   st%f(F_VEL)%r = spread([-1.0_wp, 0.0_wp, 4.0_wp], 2, NN)
   st%f(F_STRESS)%r(:, 1) = [100.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
   st%f(F_EPSP)%r(1, 1) = 0.25_wp
   st%f(F_FAILED)%r(1, 1) = 1.0_wp
   call plot_state_derive(st, x0)
   call check(all(st%f(F_DISP)%r == spread([1.0_wp, 2.0_wp, 3.0_wp], 2, NN) + x0 - x0), &
              'displacement = x - x0 exactly')
   call check_close(st%f(F_VM)%r(1, 1), 100.0_wp, 0.0_wp, 4*epsilon(1.0_wp), &
                    'von Mises of uniaxial 100')
   call check_close(st%f(F_PRES)%r(1, 1), -100.0_wp/3.0_wp, 0.0_wp, 4*epsilon(1.0_wp), &
                    'pressure of uniaxial 100')

   ! ---- the file and its XDMF
   call h5_create(f, TMP//'/plot.h5', error)
   call check(.not. allocated(error), 'create plot.h5')
   call plot_mesh_write(f, x0, [(100 + i, i = 1, NN)], cells, [11], [7], 'schema test', error)
   call check(.not. allocated(error), 'mesh written')
   call h5_create_group(f, '/states', error)
   call plot_state_write(f, '/states/000001', st, error)
   call check(.not. allocated(error), 'state written')
   call h5_close(f, error)
   call xdmf_write(TMP//'/plot.xdmf', 'plot.h5', 'schema test', NN, NE, cells_topology(cells), &
                   [0.5_wp], error, rows=st%on)
   call check(.not. allocated(error), 'XDMF written')

   open(newunit=u, file=TMP//'/plot.xdmf', action='read', iostat=ios)
   call check(ios == 0, 'open the XDMF')
   nlines = 0
   do
      read(u, '(a)', iostat=ios) lines(nlines + 1)
      if (ios /= 0) exit
      nlines = nlines + 1
   end do
   close(u)

   call h5_open_read(f, TMP//'/plot.h5', error)
   call check(.not. allocated(error), 'open plot.h5')
   nattr = 0
   do i = 1, size(PLOT_FIELDS)
      if (len_trim(PLOT_FIELDS(i)%label) == 0) cycle
      nattr = nattr + 1
      call check_row(PLOT_FIELDS(i))
   end do
   call check(count([(index(lines(j), '<Attribute ') > 0, j = 1, nlines)]) == nattr, &
              'one XDMF attribute per labelled row, no other')
   call check(count([(len_trim(PLOT_FIELDS(j)%label) == 0, j = 1, size(PLOT_FIELDS))]) == 1 &
              .and. len_trim(PLOT_FIELDS(F_COORD)%label) == 0, 'the geometry is one row')
   call check(any([(index(lines(j), 'plot.h5:/states/000001/coordinates</DataItem>') > 0 &
              .and. index(lines(j), 'Dimensions="8 3"') > 0, j = 1, nlines)]), &
              'the geometry is the coordinates (8 3)')

   ! ---- read back
   call plot_rows_in_file(f, '/states/000001', rows, error)
   call check(.not. allocated(error) .and. rows(F_DAMAGE) .and. rows(F_BEAM_FORCE) .and. &
              rows(F_BEAM_MOMENT) .and. rows(F_THICK) .and. &
              count(rows) == count(PLOT_FIELDS(1:NSTATE_FIELDS)%opt), &
              'the optional rows found in the file: damage, beam_force, beam_moment, thickness')
   call plot_state_read(f, '/states/000001', NN, NE, back, 'plot.h5: ', '', error)
   call check(.not. allocated(error), 'state read back')
   call check(back%time == st%time, 'time read back')
   do i = 1, NSTATE_FIELDS
      call check(all(shape(back%f(i)%r) == shape(st%f(i)%r)) .and. &
                 all(back%f(i)%r == st%f(i)%r), trim(PLOT_FIELDS(i)%name)//' read back bitwise')
   end do
   call plot_state_read(f, '/states/000001', NN + 1, NE, back, 'plot.h5: ', ' (x)', error)
   call check(allocated(error), 'a dataset of another size is an error')
   if (allocated(error)) then
      call check(index(error%message, 'plot.h5: /states/000001/coordinates has 24 values, '// &
                       'expected 27 (x)') > 0, 'the message names the dataset and sizes')
      deallocate(error)
   end if
   call h5_close(f, error)
   call assert_summary()

contains

   !> The XDMF attribute of fld and its dataset agree with the row.
   subroutine check_row(fld)
      type(plot_field_t), intent(in) :: fld
      character(:), allocatable :: name, atype, centre, dims, dset, ntype
      character(16) :: buf
      integer :: k, n, hits
      integer(i8), allocatable :: d(:)
      real(wp), allocatable :: vals(:)
      type(error_t), allocatable :: err
      name = trim(fld%label)
      select case (fld%ncomp)
      case (1); atype = 'Scalar'
      case (3); atype = 'Vector'
      case (6); atype = 'Tensor6'
      case default; atype = '?'
      end select
      centre = 'Cell'
      n = NE
      if (fld%centre == CENTRE_NODE) then
         centre = 'Node'
         n = NN
      end if
      write(buf, '(i0)') n
      dims = trim(buf)
      if (fld%ncomp > 1) then
         write(buf, '(i0)') fld%ncomp
         dims = dims//' '//trim(buf)
      end if
      ntype = 'NumberType="Float" Precision="8"'
      if (fld%int) ntype = 'NumberType="Int" Precision="4"'
      dset = '/states/000001/'//trim(fld%name)
      if (fld%source == SRC_MESH) dset = trim(fld%name)
      hits = 0
      do k = 1, nlines - 1
         if (index(lines(k), '<Attribute Name="'//name//'"') == 0) cycle
         hits = hits + 1
         call check(index(lines(k), 'AttributeType="'//atype//'"') > 0, name//': '//atype)
         call check(index(lines(k), 'Center="'//centre//'"') > 0, name//': centre '//centre)
         call check(index(lines(k + 1), 'Dimensions="'//dims//'"') > 0, name//': dims '//dims)
         call check(index(lines(k + 1), ntype) > 0, name//': '//ntype)
         call check(index(lines(k + 1), 'plot.h5:'//dset//'</DataItem>') > 0, &
                    name//': dataset '//dset)
      end do
      call check(hits == 1, name//': one attribute')
      call h5_dims(f, dset, d, err)
      call check(.not. allocated(err), name//': dataset '//dset//' exists')
      if (allocated(err)) return
      call check(size(d) == merge(1, 2, fld%ncomp == 1), name//': dataset rank')
      call h5_read(f, dset, vals, err)
      call check(.not. allocated(err) .and. size(vals) == n*fld%ncomp, &
                 name//': dataset holds '//dims//' values')
   end subroutine check_row
end program test_plot_fields
