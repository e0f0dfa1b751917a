!> The cells of the plot mesh, from the element-family table (dx_element_types through
!> dx_model): a model of one family writes /mesh/<family name> as (nen, ne), 0-based node
!> indices (the layout of the single-family writer before the table), and XDMF TopologyType
!> = the family's cell type;
!> a model of several families writes /mesh/mixed, the XDMF 3 Mixed topology array: per
!> element its XDMF cell code (the family's xdmf_code) then its nodes. In memory
!> every writer keeps cells(w, ne): w = nen for one family; w = MAX_NEN + 1 for a mixed mesh
!> (code, nodes, padding -1), which is flattened when written and rebuilt when read.
!> (XDMF Model and Format, www.xdmf.org, "Topology": Mixed.)
module dx_plot_cells
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t, family_t, element_family, MAX_NEN, ETYPES
   use dx_h5, only: h5_file_t, h5_write, h5_read, h5_exists
   implicit none
   private
   public :: cell_topo_t, cells_width, cell_column, model_cells, cells_topology, write_cells, &
             read_cells

   !> XDMF cell code of a polyline: in a Mixed topology its code is followed by its node
   !> count (XDMF Model and Format, "Topology", Mixed)
   integer, parameter :: POLYLINE = 2

   !> what the XDMF file says of the cells
   type :: cell_topo_t
      character(:), allocatable :: dset    !< /mesh/<name>
      character(:), allocatable :: xdmf    !< TopologyType
      integer :: w = 0                     !< rows of cells(w, ne)
      integer :: nflat = 0                 !< mixed: length of the flat array, else 0
   end type cell_topo_t

contains

   !> Rows of cells(w, ne) for the families of model's blocks.
   integer function cells_width(model) result(w)
      type(model_t), intent(in) :: model
      integer :: b, k, code
      type(family_t) :: f0
      f0 = element_family(ETYPES(1))
      w = f0%nen
      if (.not. allocated(model%blocks)) return
      w = 0
      code = 0
      do b = 1, size(model%blocks)
         associate (f => element_family(model%blocks(b)%etype))
            if (w == 0) then
               w = f%nen
               code = f%xdmf_code
            else if (w /= f%nen .or. code /= f%xdmf_code) then
               w = MAX_NEN + 1
            end if
            if (f%xdmf_code == POLYLINE) code = POLYLINE
         end associate
      end do
      if (w == 0) w = f0%nen
      ! a polyline (beams) names its node count in a Mixed topology: always Mixed
      if (code == POLYLINE) w = MAX_NEN + 1
      ! one family that is not the first of ETYPES with its node count (the quadrilateral
      ! shell beside the tetrahedron): the Mixed topology names its cell type
      if (w <= MAX_NEN) then
         do k = 1, size(ETYPES)
            f0 = element_family(ETYPES(k))
            if (f0%nen == w) exit
         end do
         if (f0%xdmf_code /= code .and. code /= 0) w = MAX_NEN + 1
      end if
   end function cells_width

   !> The column of one element of type etype with 0-based nodes nodes0 in cells(w, :).
   pure function cell_column(w, etype, nodes0) result(col)
      integer, intent(in) :: w, etype, nodes0(:)
      integer :: col(w)
      integer :: n
      type(family_t) :: f
      if (w == MAX_NEN + 1) then
         n = size(nodes0)
         col = -1
         f = element_family(etype)
         col(1) = f%xdmf_code
         if (f%xdmf_code == POLYLINE) then    ! code, node count, nodes
            col(2) = n
            col(3:n + 2) = nodes0
            return
         end if
         col(2:n + 1) = nodes0
      else
         col = nodes0(1:w)
      end if
   end function cell_column

   !> cells(w, ne) of a built model (0-based), in global element order.
   subroutine model_cells(model, cells)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: cells(:, :)
      integer :: ib, i, w
      w = cells_width(model)
      allocate(cells(w, model%ne))
      cells = 0
      if (.not. allocated(model%blocks)) return
      do ib = 1, size(model%blocks)
         associate (blk => model%blocks(ib))
            do i = 1, blk%nel
               cells(:, blk%elem(i)) = cell_column(w, blk%etype, blk%conn(:, i) - 1)
            end do
         end associate
      end do
   end subroutine model_cells

   !> The XDMF description of cells(w, ne).
   function cells_topology(cells) result(t)
      integer, intent(in) :: cells(:, :)
      type(cell_topo_t) :: t
      integer :: k
      type(family_t) :: f
      t%w = size(cells, 1)
      if (t%w == MAX_NEN + 1) then
         t%dset = '/mesh/mixed'
         t%xdmf = 'Mixed'
         t%nflat = count(cells >= 0)
         return
      end if
      t%dset = '/mesh/unknown'
      t%xdmf = 'Unknown'
      do k = 1, size(ETYPES)
         f = element_family(ETYPES(k))
         if (f%nen == t%w) then
            t%dset = '/mesh/'//trim(f%name)
            t%xdmf = trim(f%xdmf)
            return
         end if
      end do
   end function cells_topology

   !> Write cells(w, ne) to f under its dataset (mixed: flattened).
   subroutine write_cells(f, cells, error)
      type(h5_file_t), intent(in) :: f
      integer, intent(in) :: cells(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(cell_topo_t) :: t
      t = cells_topology(cells)
      if (t%nflat > 0) then
         call h5_write(f, t%dset, pack(cells, cells >= 0), error)
      else
         call h5_write(f, t%dset, cells, error)
      end if
   end subroutine write_cells

   !> Read the cells of ne elements from f (whichever family dataset or /mesh/mixed it has).
   subroutine read_cells(f, ne, cells, error)
      type(h5_file_t), intent(in) :: f
      integer, intent(in) :: ne
      integer, allocatable, intent(out) :: cells(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: buf(:)
      type(family_t) :: fam
      integer :: k, e, p, j, n
      logical :: there
      call h5_exists(f, '/mesh/mixed', there, error)
      if (allocated(error)) return
      if (there) then
         call h5_read(f, '/mesh/mixed', buf, error)
         if (allocated(error)) return
         allocate(cells(MAX_NEN + 1, ne))
         cells = -1
         p = 1
         do e = 1, ne
            n = 0
            if (p <= size(buf)) then
               do k = 1, size(ETYPES)
                  fam = element_family(ETYPES(k))
                  if (fam%xdmf_code == nint(buf(p))) then
                     n = fam%nen
                     if (fam%xdmf_code == POLYLINE) n = n + 1   ! the node count first
                     exit
                  end if
               end do
            end if
            if (n == 0 .or. p + n > size(buf)) then
               call set_error(error, '/mesh/mixed: bad cell list at element '// &
                              trim(itoa(e)), EXIT_IO)
               return
            end if
            do j = 0, n
               cells(j + 1, e) = nint(buf(p + j))
            end do
            p = p + n + 1
         end do
         return
      end if
      do k = 1, size(ETYPES)
         fam = element_family(ETYPES(k))
         call h5_exists(f, '/mesh/'//trim(fam%name), there, error)
         if (allocated(error)) return
         if (.not. there) cycle
         call h5_read(f, '/mesh/'//trim(fam%name), buf, error)
         if (allocated(error)) return
         if (size(buf) /= fam%nen*ne) then
            call set_error(error, '/mesh/'//trim(fam%name)//': '//trim(itoa(size(buf)))// &
                           ' values for '//trim(itoa(ne))//' elements', EXIT_IO)
            return
         end if
         cells = reshape(nint(buf), [fam%nen, ne])
         return
      end do
      call set_error(error, 'no element cells in /mesh', EXIT_IO)
   end subroutine read_cells

   pure function itoa(i) result(s)
      integer, intent(in) :: i
      character(16) :: s
      write(s, '(i0)') i
   end function itoa
end module dx_plot_cells
