!> XDMF 3 description of the HDF5 plot file (d3plot.h5) so ParaView/VisIt can read it:
!> a temporal collection with one uniform Grid per complete state, the cells' topology
!> (dx_plot_cells: one family's cell type or Mixed), geometry from the state's current
!> coordinates, and one attribute per row of the plot-field schema (dx_plot_fields: nodal
!> vectors, cell scalars/tensors from the state group, ids from /mesh). Rewritten after every state through a
!> temporary file and rename(2), so a reader never sees a half-written file. The text is
!> built in memory and written with write(2) + fsync(2) (dx_io_sys): a full disk is an error
!> naming the file and the reason, and the good file is never replaced by a short one.
!> Dimensions: a Fortran (3,nn) dataset is (nn,3) in HDF5's C order, hence "nn 3".
module dx_xdmf
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_io_sys, only: sys_rename, sys_write_file
   use dx_plot_cells, only: cell_topo_t
   use dx_strings, only: str
   use dx_plot_fields, only: plot_field_t, PLOT_FIELDS, CENTRE_NODE, SRC_MESH, xdmf_attribute_type
   implicit none
   private
   public :: xdmf_write, state_group

   character(4), parameter :: CENTRING(2) = ['Node', 'Cell']

contains

   !> HDF5 group of state k (1-based): /states/000001, ...
   function state_group(k) result(g)
      integer, intent(in) :: k
      character(:), allocatable :: g
      character(14) :: buf
      write(buf, '(a,i6.6)') '/states/', k
      g = trim(buf)
   end function state_group

   !> Write the XDMF file path listing states 1..size(times) of h5name (relative name).
   !> With states_dir (a running job, dx_plot_states): the mesh is states_dir/mesh.h5 and
   !> state k is states_dir/NNNNNN.h5, each under the path it has in h5name.
   subroutine xdmf_write(path, h5name, title, nn, ne, topo, times, error, states_dir, rows)
      character(*), intent(in) :: path, h5name, title
      character(*), intent(in), optional :: states_dir
      !> the optional rows of the schema the states hold (dx_plot_fields; default none)
      logical, intent(in), optional :: rows(:)
      integer, intent(in) :: nn, ne
      type(cell_topo_t), intent(in) :: topo     !< the cells (dx_plot_cells)
      real(wp), intent(in) :: times(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k, nb, i
      type(plot_field_t) :: fld
      character(:), allocatable :: tmp, g, snn, sne, mfile, sfile, text, cdims, dims, dset
      character(32) :: buf

      tmp = path//'.tmp'
      write(buf, '(i0)') nn
      snn = trim(buf)
      write(buf, '(i0)') ne
      sne = trim(buf)
      write(buf, '(i0)') topo%w
      cdims = sne//' '//trim(buf)
      if (topo%nflat > 0) then
         write(buf, '(i0)') topo%nflat
         cdims = trim(buf)
      end if
      mfile = h5name
      sfile = h5name
      if (present(states_dir)) mfile = states_dir//'/mesh.h5'
      allocate(character(4096 + 2400*size(times)) :: text)
      nb = 0
      call put('<?xml version="1.0" ?>')
      call put('<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>')
      call put('<Xdmf xmlns:xi="http://www.w3.org/2001/XInclude" Version="3.0">')
      call put(' <Domain>')
      call put('  <Grid Name="dynx" GridType="Collection" CollectionType="Temporal">')
      call put('   <Information Name="title" Value="'//xml_escape(title)//'"/>')
      do k = 1, size(times)
         g = state_group(k)
         if (present(states_dir)) sfile = states_dir//'/'//g(9:)//'.h5'
         write(buf, '(es24.16e3)') times(k)
         call put('   <Grid Name="state'//g(9:)//'" GridType="Uniform">')
         call put('    <Time Value="'//trim(adjustl(buf))//'"/>')
         call put('    <Topology TopologyType="'//topo%xdmf//'" NumberOfElements="'//sne//'">')
         call item(cdims, 'Int', '4', topo%dset, mfile)
         call put('    </Topology>')
         call put('    <Geometry GeometryType="XYZ">')
         call item(snn//' 3', 'Float', '8', g//'/coordinates', sfile)
         call put('    </Geometry>')
         do i = 1, size(PLOT_FIELDS)
            fld = PLOT_FIELDS(i)
            if (len_trim(fld%label) == 0) cycle      ! the geometry
            if (fld%opt) then                        ! an optional row: only when in use
               if (.not. present(rows)) cycle
               if (.not. rows(i)) cycle
            end if
            dims = sne
            if (fld%centre == CENTRE_NODE) dims = snn
            if (fld%ncomp > 1) dims = dims//' '//str(fld%ncomp)
            dset = g//'/'//trim(fld%name)
            if (fld%source == SRC_MESH) dset = trim(fld%name)
            if (fld%int) then
               call attribute(trim(fld%label), xdmf_attribute_type(fld), &
                              CENTRING(fld%centre), dims, 'Int', '4', dset)
            else
               call attribute(trim(fld%label), xdmf_attribute_type(fld), &
                              CENTRING(fld%centre), dims, 'Float', '8', dset)
            end if
         end do
         call put('   </Grid>')
      end do
      call put('  </Grid>')
      call put(' </Domain>')
      call put('</Xdmf>')
      call sys_write_file(tmp, text(1:nb), error)
      if (.not. allocated(error)) call sys_rename(tmp, path, error)

   contains

      subroutine put(line)
         character(*), intent(in) :: line
         character(:), allocatable :: grown
         if (nb + len(line) + 1 > len(text)) then     ! grow by doubling: linear in the text
            allocate(character(2*len(text) + len(line) + 1) :: grown)
            grown(1:nb) = text(1:nb)
            call move_alloc(grown, text)
         end if
         text(nb + 1:nb + len(line)) = line
         text(nb + len(line) + 1:nb + len(line) + 1) = new_line('a')
         nb = nb + len(line) + 1
      end subroutine put

      subroutine item(dims, ntype, prec, dset, file)
         character(*), intent(in) :: dims, ntype, prec, dset, file
         call put('     <DataItem Dimensions="'//dims//'" NumberType="'//ntype// &
                  '" Precision="'//prec//'" Format="HDF">'//file//':'//dset//'</DataItem>')
      end subroutine item

      subroutine attribute(name, atype, center, dims, ntype, prec, dset)
         character(*), intent(in) :: name, atype, center, dims, ntype, prec, dset
         call put('    <Attribute Name="'//name//'" AttributeType="'//atype// &
                  '" Center="'//center//'">')
         if (dset(1:6) == '/mesh/') then
            call item(dims, ntype, prec, dset, mfile)
         else
            call item(dims, ntype, prec, dset, sfile)
         end if
         call put('    </Attribute>')
      end subroutine attribute
   end subroutine xdmf_write

   !> Escape the XML special characters of s.
   pure function xml_escape(s) result(r)
      character(*), intent(in) :: s
      character(:), allocatable :: r
      integer :: i
      r = ''
      do i = 1, len_trim(s)
         select case (s(i:i))
         case ('&'); r = r//'&amp;'
         case ('<'); r = r//'&lt;'
         case ('>'); r = r//'&gt;'
         case ('"'); r = r//'&quot;'
         case default
            if (iachar(s(i:i)) >= 32) r = r//s(i:i)
         end select
      end do
   end function xml_escape
end module dx_xdmf
