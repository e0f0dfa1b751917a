!> Model build of the 2D solids (*SECTION_SHELL ELFORM 13, 14, 15; dx_quad2d): whether a
!> part is 2D, the rule that a deck's parts are all 2D of one kind or all 3D, and the checks
!> and initial volume of one 2D element (nodes in the x-y plane, r = x >= 0 in axisymmetry,
!> counter-clockwise). Split from dx_model_build (which calls it) to keep that module short.
module dx_build_twod
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_model, only: model_t, family_t, element_family, elem_volume
   use dx_model_input, only: model_input_t
   use dx_element_types, only: etype_of_shell_elform, quad2d_area
   use dx_build_common, only: at, at_line
   implicit none
   private
   public :: part_dim, check_dimension, twod_element

contains

   !> 0: part ip is 3D; 1: a 2D planar part (ELFORM 12, 13); 2: a 2D axisymmetric part (14, 15)
   integer function part_dim(model, ip)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ip
      type(family_t) :: f
      part_dim = 0
      associate (sec => model%sections(model%parts(ip)%isec))
         if (.not. sec%shell) return
         f = element_family(etype_of_shell_elform(sec%elform))
      end associate
      if (f%twod) part_dim = merge(2, 1, f%axisym)
   end function part_dim

   !> A deck is 2D when all its parts are 2D, all plane strain or all axisymmetric (x is r in
   !> one, a coordinate in the other): any mixture is an input error at the later *PART.
   subroutine check_dimension(inp, model, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(*), parameter :: kind(0:2) = [character(40) :: &
         '3D', '2D planar (ELFORM 12/13)', '2D axisymmetric (ELFORM 14/15)']
      integer :: i, d0
      if (size(model%parts) == 0) return
      d0 = part_dim(model, 1)
      do i = 2, size(model%parts)
         if (part_dim(model, i) == d0) cycle
         call set_error(error, at(inp, inp%part_src(i))//'part '// &
            str(model%parts(i)%label)//': field SECID: section '// &
            str(model%parts(i)%secid)//' makes the part '// &
            trim(kind(part_dim(model, i)))//', but part '//str(model%parts(1)%label)// &
            ' (section '//str(model%parts(1)%secid)//') is '//trim(kind(d0))// &
            ': a deck is 2D only when all its parts are, of one kind')
         return
      end do
   end subroutine check_dimension

   !> one 2D element e (*SECTION_SHELL ELFORM 13-15): its nodes in the x-y plane (z = 0),
   !> r = x >= 0 when axisymmetric, counter-clockwise with an area > 0; V0 the area or the
   !> volume per radian (elem_volume)
   subroutine twod_element(inp, model, conn, e, etype, lab, w, axi, vol, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      integer, intent(in) :: conn(4), e, etype, lab
      real(wp), intent(out) :: vol
      character(*), intent(in) :: w
      logical, intent(in) :: axi
      type(error_t), allocatable, intent(out) :: error
      integer :: kk, nd
      real(wp) :: a
      do kk = 1, 4
         nd = conn(kk)
         if (model%x0(3, nd) /= 0.0_wp) then
            call set_error(error, at_line(inp, inp%node_src(:, nd), 'NODE')//'node '// &
               str(model%node_label(nd))//': field Z: '//rstr(model%x0(3, nd))// &
               ': a node of a 2D element (element '//str(lab)//', *SECTION_SHELL ELFORM '// &
               str(model%sections(model%parts(model%elem_part(e))%isec)%elform)// &
               ') must lie in the x-y plane (z = 0)')
            return
         end if
         if (axi .and. model%x0(1, nd) < 0.0_wp) then
            call set_error(error, at_line(inp, inp%node_src(:, nd), 'NODE')//'node '// &
               str(model%node_label(nd))//': field X: r = x = '//rstr(model%x0(1, nd))// &
               ' < 0: an axisymmetric deck (element '//str(lab)//', *SECTION_SHELL '// &
               'ELFORM 14/15) has x = r >= 0 and y along the axis')
            return
         end if
      end do
      a = quad2d_area(model%x0(:, conn))
      vol = elem_volume(etype, model%x0(:, conn))
      if (.not. (a > 0.0_wp .and. vol > 0.0_wp)) then
         call set_error(error, w//'element '//str(lab)//' is inverted or has no area at '// &
            't = 0 (area '//rstr(a)//' <= 0: the nodes N1..N4 of a 2D element go '// &
            'counter-clockwise in the x-y plane)')
         return
      end if
   end subroutine twod_element
end module dx_build_twod
