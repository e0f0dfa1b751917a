!> Readers for the material and equation-of-state keywords of the registry (dx_mat_factory):
!> *MAT_ELASTIC (*MAT_001), *MAT_PLASTIC_KINEMATIC (*MAT_003), *MAT_NULL (*MAT_009),
!> *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024), *EOS_LINEAR_POLYNOMIAL (*EOS_001), each with the
!> _TITLE option. The object comes from the registry and reads its own cards through a card
!> cursor (dx_card); parameters are checked by the model's setup here, or in the build step
!> (dx_model_build) when they wait for curves, and a setup error names its field (error%field),
!> which the cursor locates on the card.
!> Layouts: LS-DYNA Keyword User's Manual, Vol. II (material models, *EOS).
module dx_read_materials
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_card, only: card_t
   use dx_deck_cards, only: deck_t, block_t, block_error, data_start, check_max_cards, &
                            deck_cursor
   use dx_deck_registry, only: registry_t
   use dx_material, only: material_t, mat_holder_t
   use dx_eos, only: eos_t, eos_holder_t
   use dx_mat_factory, only: model_kind_t, material_kinds, eos_kinds, new_material, new_eos, &
                             known_materials
   use dx_model_input, only: model_input_t, origin
   implicit none
   private
   public :: register_materials, unknown_model_hint

contains

   !> Add the registry's material and EOS keywords and their numeric aliases (*MAT_001, ...).
   subroutine register_materials(reg)
      type(registry_t), intent(inout) :: reg
      type(model_kind_t), allocatable :: t(:)
      integer :: i
      character(3) :: num
      t = material_kinds()
      do i = 1, size(t)
         if (.not. t(i)%generic) cycle
         write(num, '(i3.3)') t(i)%mtype
         call reg%add(trim(t(i)%keyword), read_mat, title=.true.)
         if (t(i)%mtype < 900) call reg%add('MAT_'//num, read_mat, title=.true.)
      end do
      t = eos_kinds()
      do i = 1, size(t)
         write(num, '(i3.3)') t(i)%mtype
         call reg%add(trim(t(i)%keyword), read_eos, title=.true.)
         call reg%add('EOS_'//num, read_eos, title=.true.)
      end do
   end subroutine register_materials

   !> For an unknown *MAT_ or *EOS_ keyword: the list of the known ones ('' otherwise).
   function unknown_model_hint(name) result(s)
      character(*), intent(in) :: name
      character(:), allocatable :: s
      type(model_kind_t), allocatable :: t(:)
      integer :: i
      s = ''
      if (len(name) < 4) return
      if (name(1:4) == 'MAT_') then
         s = ' (material types dynx knows: '//known_materials()//')'
      else if (name(1:4) == 'EOS_') then
         t = eos_kinds()
         s = ' (equations of state dynx knows:'
         do i = 1, size(t)
            s = s//' '//str(t(i)%mtype)//' (*'//trim(t(i)%keyword)//')'
         end do
         s = s//')'
      end if
   end function unknown_model_hint

   !> The registry row of keyword base (its name or its *MAT_nnn / *EOS_nnn alias).
   function find_kind(t, prefix, base) result(k)
      type(model_kind_t), intent(in) :: t(:)
      character(*), intent(in) :: prefix, base
      integer :: k
      character(3) :: num
      do k = 1, size(t)
         write(num, '(i3.3)') t(k)%mtype
         if (trim(t(k)%keyword) == base) return
         if (prefix//num == base .and. t(k)%mtype < 900) return
      end do
      k = 0
   end function find_kind

   !> The registry row j of a *MAT_/*EOS_ block and its first data card i0; the block must
   !> hold card 1 (fields named by card1) and no more cards than the row's model reads.
   subroutine keyword_row(deck, blk, kinds, prefix, card1, j, i0, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_kind_t), intent(in) :: kinds(:)
      character(*), intent(in) :: prefix, card1
      integer, intent(out) :: j, i0
      type(error_t), allocatable, intent(out) :: error
      j = find_kind(kinds, prefix, blk%base)
      i0 = data_start(blk)
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 ('//card1//')', error)
         return
      end if
      call check_max_cards(deck, blk, i0 + kinds(j)%ncards - 1, error)
   end subroutine keyword_row

   subroutine read_mat(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: m
      type(mat_holder_t), allocatable :: t(:)
      type(model_kind_t), allocatable :: kinds(:)
      type(card_t) :: c
      type(error_t), allocatable :: err
      integer :: i0, n, k, j
      character(:), allocatable :: msg
      kinds = material_kinds()
      call keyword_row(deck, blk, kinds, 'MAT_', 'MID RO E PR ...', j, i0, error)
      if (allocated(error)) return
      call new_material(kinds(j)%mtype, m, error)
      if (allocated(error)) then
         msg = error%message
         call block_error(deck, blk, 0, msg, error)
         return
      end if
      call deck_cursor(deck, blk, c)
      call m%read_cards(c)
      ! models without curve references are checked here, so a bad value points at its field
      if (c%ok() .and. .not. m%reads_curves()) then
         call m%setup(err)
         if (allocated(err)) then
            if (allocated(err%field)) then
               call c%fail(err%field, 'material '//str(m%label)//': '//err%detail)
            else
               call c%fail_block(i0, 'material '//str(m%label)//': '//err%message)
            end if
         end if
      end if
      call c%done(error)
      if (allocated(error)) return
      n = size(inp%mats)
      allocate(t(n + 1))
      do k = 1, n
         call move_alloc(inp%mats(k)%m, t(k)%m)
      end do
      call move_alloc(m, t(n + 1)%m)
      call move_alloc(t, inp%mats)
      inp%mat_src = [inp%mat_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_mat

   subroutine read_eos(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      class(eos_t), allocatable :: e
      type(eos_holder_t), allocatable :: t(:)
      type(model_kind_t), allocatable :: kinds(:)
      type(card_t) :: c
      integer :: i0, n, k, j
      character(:), allocatable :: msg
      kinds = eos_kinds()
      call keyword_row(deck, blk, kinds, 'EOS_', 'EOSID ...', j, i0, error)
      if (allocated(error)) return
      call new_eos(kinds(j)%mtype, e, error)
      if (allocated(error)) then
         msg = error%message
         call block_error(deck, blk, 0, msg, error)
         return
      end if
      call deck_cursor(deck, blk, c)
      call e%read_cards(c)
      if (c%ok()) then
         do k = 1, size(inp%eoss)
            if (inp%eoss(k)%e%label == e%label) then
               call c%fail('EOSID', 'duplicate equation of state id '//str(e%label)// &
                  ' (first defined at '//deck%files(inp%eos_src(k)%ifile)%s//':'// &
                  str(inp%eos_src(k)%line)//')')
               exit
            end if
         end do
      end if
      call c%done(error)
      if (allocated(error)) return
      n = size(inp%eoss)
      allocate(t(n + 1))
      do k = 1, n
         call move_alloc(inp%eoss(k)%e, t(k)%e)
      end do
      call move_alloc(e, t(n + 1)%e)
      call move_alloc(t, inp%eoss)
      inp%eos_src = [inp%eos_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   end subroutine read_eos
end module dx_read_materials
