!> The *DATABASE_NCFORC file 'ncforc': the nodal contact forces of every contact interface at
!> the request's DT (LS-DYNA Keyword User's Manual Vol. I, *DATABASE_NCFORC: "nodal interface
!> forces"). Per output time and interface, a slave-side and a master-side block, laid out as
!> LS-DYNA's ncforc readers parse it: a line 'contact forces on interface <id> slave|master
!> side (t= t)', a blank line, two lines of column heads, then per node a line 'node fx fy fz
!> pressure' and a line 'x y z' (its coordinates), and a blank line. The forces are this
!> cycle's contact pass results (dx_contact_penalty, contact_pass_t%rval): a slave node of a
!> pass gets its pass force, the nodes of its master segment minus that force times their
!> shape functions (the forces dx_contact adds into the nodes' force sums); the second pass
!> of a two-way interface has the roles the other way round. So each side's forces add up to
!> rcforc's resultant of that side, and the two sides to zero. Nodes: the first pass's slave
!> nodes (slave side) and master segment nodes (master side), ascending node order. The
!> pressure column is not computed (written 0: dynx keeps no tributary contact areas).
!> Numbers with 10 significant digits (es18.10e3). MPI: formed on rank 0's global model,
!> whose passes hold every strip's results (dx_par_contact), so byte-identical for any NP.
module dx_ncforc
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t
   use dx_contact_types, only: REC_FSL, REC_NB
   use dx_thist, only: layout_header
   implicit none
   private
   public :: ncforc_header, ncforc_record

   character(*), parameter :: NUM = 'es18.10e3'

contains

   !> The header: title and the interfaces.
   function ncforc_header(model) result(text)
      type(model_t), intent(in) :: model
      character(:), allocatable :: text
      text = layout_header(model, 'nodal contact forces, ncforc: ', &
                           'dynx ncforc (global axes; pressure not computed: 0; 10 significant digits)')
   end function ncforc_header

   !> One output time: every interface's slave side, then its master side.
   subroutine ncforc_record(model, text, error)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: f(:, :, :)       ! (3, nn, side)
      logical, allocatable :: on(:, :)          ! (nn, side) the node is listed
      character(256) :: msg
      integer :: i, ios, side
      text = ''
      ios = 0
      if (.not. allocated(model%contact)) return
      allocate(f(3, model%nn, 2), on(model%nn, 2))
      do i = 1, size(model%contact%iface)
         call iface_forces(model, i, f, on)
         do side = 1, 2
            call side_block(model, i, side, f(:, :, side), on(:, side), text, ios, msg)
            if (ios /= 0) exit
         end do
         if (ios /= 0) exit
      end do
      if (ios /= 0) call set_error(error, 'cannot format an ncforc record: '//trim(msg), &
                                   EXIT_IO)
   end subroutine ncforc_record

   !> Interface i's nodal forces f(:, :, 1) on the slave side and f(:, :, 2) on the master
   !> side, passes and slave nodes in order; on: the nodes listed.
   subroutine iface_forces(model, i, f, on)
      type(model_t), intent(in) :: model
      integer, intent(in) :: i
      real(wp), intent(out) :: f(:, :, :)
      logical, intent(out) :: on(:, :)
      integer :: j, k, n, sb, s, m
      real(wp) :: fsl(3)
      f = 0.0_wp
      on = .false.
      associate (fc => model%contact%iface(i))
         if (size(fc%pass) > 0) then
            on(fc%pass(1)%node(1:fc%pass(1)%nnode), 1) = .true.
            do sb = 1, fc%pass(1)%nseg
               on(fc%pass(1)%seg(1:fc%pass(1)%nsn(sb), sb), 2) = .true.
            end do
         end if
         do j = 1, size(fc%pass)
            s = merge(1, 2, j == 1)       ! the side of this pass's slave nodes
            m = 3 - s
            associate (p => fc%pass(j))
               do k = 1, p%nnode
                  sb = p%iseg(k)
                  if (sb == 0) cycle
                  fsl = p%rval(REC_FSL + 1:REC_FSL + 3, k)
                  f(:, p%node(k), s) = f(:, p%node(k), s) + fsl
                  do n = 1, p%nsn(sb)
                     f(:, p%seg(n, sb), m) = f(:, p%seg(n, sb), m) - p%rval(REC_NB + n, k)*fsl
                  end do
               end do
            end associate
         end do
      end associate
   end subroutine iface_forces

   !> One side's block: the heading, the column heads and two lines per listed node.
   subroutine side_block(model, i, side, f, on, text, ios, msg)
      type(model_t), intent(in) :: model
      integer, intent(in) :: i, side
      real(wp), intent(in) :: f(:, :)
      logical, intent(in) :: on(:)
      character(:), allocatable, intent(inout) :: text
      integer, intent(out) :: ios
      character(256), intent(inout) :: msg
      character, parameter :: nl = new_line('a')
      character(200) :: line
      integer :: nd, lab
      write(line, '(" contact forces on interface",i10,1x,a," side (t= ",'//NUM//',")")', &
            iostat=ios, iomsg=msg) model%contact%iface(i)%label, &
            trim(merge('slave ', 'master', side == 1)), model%time
      if (ios /= 0) return
      text = text//nl//trim(line)//nl//nl// &
         '      node           x-force           y-force           z-force          pressure'// &
         nl//'                 coordinates x                 y                 z'//nl
      do nd = 1, size(on)
         if (.not. on(nd)) cycle
         lab = nd
         if (allocated(model%node_label)) lab = model%node_label(nd)
         write(line, '(i10,4(1x,'//NUM//'))', iostat=ios, iomsg=msg) lab, f(:, nd) + 0.0_wp, &
            0.0_wp
         if (ios /= 0) return
         text = text//trim(line)//nl
         write(line, '(10x,3(1x,'//NUM//'))', iostat=ios, iomsg=msg) model%x(:, nd)
         if (ios /= 0) return
         text = text//trim(line)//nl
      end do
   end subroutine side_block
end module dx_ncforc
