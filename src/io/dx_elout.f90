!> The *DATABASE_ELOUT file 'elout': the stresses of the *DATABASE_HISTORY_SOLID elements at
!> the request's DT, in LS-DYNA's solid-element layout as its readers parse it (LS-DYNA
!> Keyword User's Manual Vol. I, *DATABASE_ELOUT and *DATABASE_HISTORY_SOLID; the labels
!> are those a public elout parser matches: the line 'e l e m e n t   s t r e s s
!> c a l c u l a t i o n s   f o r   t i m e  s t e p  N ( at time t )', the column heads
!> 'element  materl(global)' / 'ipt-shl  stress  sig-xx ... sig-zx  plastic' / 'state ...
!> strain', then per element a line 'id- part' and a line '1- elastic|plastic' with the
!> seven numbers). Per element: the stress averaged over its integration points in global
!> axes (sig-xx sig-yy sig-zz sig-xy sig-yz sig-zx, the plot file's 'stress') and the mean
!> effective plastic strain (0 for elastic materials; 'plastic' once it is > 0), as
!> d3plot.h5 holds them (dx_plot_hdf5 element_average). Numbers with 10 significant digits
!> (es18.10e3, as glstat; LS-DYNA prints 4). The values are formed where the elements are
!> (elout_values on the serial model; an MPI run gathers them to rank 0: dx_par_engine),
!> so the file is the same bit for bit for any NP.
module dx_elout
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t, elem_block_t
   use dx_plot_hdf5, only: element_average
   use dx_thist, only: layout_header
   implicit none
   private
   public :: elout_header, elout_record, elout_values, elout_element

   character(*), parameter :: NUM = 'es18.10e3'

contains

   !> The header: title and the history element count.
   function elout_header(model) result(text)
      type(model_t), intent(in) :: model
      character(:), allocatable :: text
      character(16) :: n
      n = '0'
      if (allocated(model%db%hist_solids)) write(n, '(i0)') size(model%db%hist_solids)
      text = layout_header(model, 'element stresses (solid history elements) for ', &
                           'dynx elout (LS-DYNA elout labels; global axes; element averages; '// &
                           trim(n)//' elements; 10 significant digits)')
   end function elout_header

   !> One element's seven values: the mean stress of block blk's element i and its mean
   !> effective plastic strain (history variable k of the material; 0: none).
   subroutine elout_element(blk, i, k, v)
      type(elem_block_t), intent(in) :: blk
      integer, intent(in) :: i, k
      real(wp), intent(out) :: v(7)
      integer :: fl
      call element_average(blk, i, k, v(1:6), v(7), fl)
   end subroutine elout_element

   !> The history elements' values into model%db%elout_vals (a serial model: every element
   !> is here).
   subroutine elout_values(model)
      type(model_t), intent(inout) :: model
      integer :: j, e, b
      if (.not. allocated(model%db%hist_solids)) return
      do j = 1, size(model%db%hist_solids)
         e = model%db%hist_solids(j)
         b = model%elem_block(e)
         call elout_element(model%blocks(b), model%elem_pos(e), &
            model%mats(model%parts(model%blocks(b)%ipart)%imat)%m%hv_eps_p, &
            model%db%elout_vals(:, j))
      end do
   end subroutine elout_values

   !> One output time from model%db%elout_vals.
   subroutine elout_record(model, text, error)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      character, parameter :: nl = new_line('a')
      character(300) :: line
      character(256) :: msg
      character(7) :: state
      integer :: j, ios
      ios = 0
      fmt: block
         write(line, '(" e l e m e n t   s t r e s s   c a l c u l a t i o n s   f o r   '// &
               't i m e  s t e p",i9," ( at time ",'//NUM//'," )")', iostat=ios, iomsg=msg) &
               model%cycle, model%time
         if (ios /= 0) exit fmt
         text = nl//trim(line)//nl//nl//' element  materl(global)'//nl// &
            ' ipt-shl  stress           sig-xx            sig-yy            sig-zz'// &
            '            sig-xy            sig-yz            sig-zx           plastic'//nl// &
            '           state'//repeat(' ', 109)//'strain'//nl
         if (.not. allocated(model%db%hist_solids)) exit fmt
         do j = 1, size(model%db%hist_solids)
            write(line, '(i10,"-",i8)', iostat=ios, iomsg=msg) model%db%hist_solid_id(j), &
               model%db%hist_solid_pid(j)
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
            state = merge('plastic', 'elastic', model%db%elout_vals(7, j) > 0.0_wp)
            write(line, '(4x,"1- ",a7,7(1x,'//NUM//'))', iostat=ios, iomsg=msg) state, &
               model%db%elout_vals(:, j) + 0.0_wp     ! (+ 0: no -0)
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
         end do
      end block fmt
      if (ios /= 0) call set_error(error, 'cannot format an elout record: '//trim(msg), &
                                   EXIT_IO)
   end subroutine elout_record
end module dx_elout
