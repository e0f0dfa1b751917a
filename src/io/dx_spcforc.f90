!> The *DATABASE_SPCFORC file 'spcforc': the reaction forces of the single-point constraints
!> (*BOUNDARY_SPC_NODE/_SET) at the request's DT. Per output time, a line 'output at time =
!> t', one line per constrained node (ascending node order)
!>    node= <id>  local x,y,z forces =  Rx Ry Rz  setid 0
!> and the sum over the nodes 'force resultants =  Rx Ry Rz', with the magnitude of that sum.
!> The labels follow LS-DYNA's spcforc as we know it from its users' files (LS-DYNA Keyword
!> User's Manual Vol. I, *DATABASE_SPCFORC: "SPC reaction forces"); the exact column layout
!> could not be checked against a reference file, so readers should split at the labels.
!> Numbers with 10 significant digits (es18.10e3, as glstat). Reactions are printed in the
!> global axes (also those of skew SPCs), under LS-DYNA's label 'local'; rotational SPCs carry no moment in solid-only models.
!> The reaction is what the constraint applies to hold its degrees of freedom at rest:
!> R = -f on each constrained translation, f the node's summed internal, contact and
!> external force of the step (model%f); the other components are 0. (Before the first cycle
!> a constrained degree of freedom with an initial velocity is brought to rest by an extra
!> m v0/dt, which R does not include.) A skew SPC (CID: zero velocity along local axes e)
!> reacts with R = -(f.e) e per constrained axis, in global components. Prescribed motions are not SPCs (LS-DYNA reports them
!> in bndout). In an MPI run f is gathered to rank 0 (the serial sums, bit for bit).
module dx_spcforc
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t
   use dx_thist, only: layout_header
   implicit none
   private
   public :: spcforc_header, spcforc_record, spc_reactions

   character(*), parameter :: NUM = 'es18.10e3'

contains

   !> The header: title and the constrained node count.
   function spcforc_header(model) result(text)
      type(model_t), intent(in) :: model
      character(:), allocatable :: text
      text = layout_header(model, 'single point constraint forces for ', &
                           'dynx spcforc (LS-DYNA spcforc labels; global axes; 10 significant digits)')
   end function spcforc_header

   !> The constrained nodes (ascending) and their reactions R(3, n) = -f on the constrained
   !> translations (0 elsewhere).
   subroutine spc_reactions(model, nodes, r)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: nodes(:)
      real(wp), allocatable, intent(out) :: r(:, :)
      logical, allocatable :: mask(:, :), skewed(:)
      integer :: k, i
      allocate(nodes(0), r(3, 0))
      if (.not. allocated(model%spcs) .or. .not. allocated(model%f)) return
      allocate(mask(3, model%nn), skewed(model%nn))
      mask = .false.
      skewed = .false.
      do k = 1, size(model%spcs)
         mask(:, model%spcs(k)%node) = mask(:, model%spcs(k)%node) .or. model%spcs(k)%dof(1:3)
      end do
      if (allocated(model%prescribed)) then
         do k = 1, size(model%prescribed)
            if (model%prescribed(k)%curve == 0) skewed(model%prescribed(k)%node) = .true.
         end do
      end if
      nodes = pack([(i, i = 1, model%nn)], any(mask, dim=1) .or. skewed)
      deallocate(r)
      allocate(r(3, size(nodes)))
      do i = 1, size(nodes)
         r(:, i) = merge(-model%f(:, nodes(i)), 0.0_wp, mask(:, nodes(i))) + 0.0_wp  ! (no -0)
      end do
      if (.not. any(skewed)) return
      ! skew SPCs (CID): R = -(f.e) e along each constrained local axis e, in record order
      do k = 1, size(model%prescribed)
         associate (p => model%prescribed(k))
            if (p%curve /= 0) cycle
            i = findloc(nodes, p%node, dim=1)
            r(:, i) = r(:, i) - dot_product(model%f(:, p%node), p%dir)*p%dir
         end associate
      end do
   end subroutine spc_reactions

   !> One output time: the nodes' reactions and their resultant.
   subroutine spcforc_record(model, text, error)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      character, parameter :: nl = new_line('a')
      character(200) :: line
      character(256) :: msg
      integer, allocatable :: nodes(:)
      real(wp), allocatable :: r(:, :)
      real(wp) :: tot(3)
      integer :: i, ios, lab
      call spc_reactions(model, nodes, r)
      ios = 0
      fmt: block
         write(line, '(" output at time = ",'//NUM//')', iostat=ios, iomsg=msg) model%time
         if (ios /= 0) exit fmt
         text = nl//trim(line)//nl
         tot = 0.0_wp
         do i = 1, size(nodes)
            lab = nodes(i)
            if (allocated(model%node_label)) lab = model%node_label(nodes(i))
            write(line, '(" node=",i10," local x,y,z forces =",3(1x,'//NUM//')," setid ",i9)', &
                  iostat=ios, iomsg=msg) lab, r(:, i), 0
            if (ios /= 0) exit fmt
            text = text//trim(line)//nl
            tot = tot + r(:, i)
         end do
         write(line, '(12x,"force resultants =",3(1x,'//NUM//'),"   magnitude = ",'//NUM//')', &
               iostat=ios, iomsg=msg) tot, norm2(tot)
         if (ios /= 0) exit fmt
         text = text//trim(line)//nl
      end block fmt
      if (ios /= 0) call set_error(error, 'cannot format an spcforc record: '//trim(msg), &
                                   EXIT_IO)
   end subroutine spcforc_record
end module dx_spcforc
