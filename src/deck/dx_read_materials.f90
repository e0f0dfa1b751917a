!> Readers for the material keywords: *MAT_ELASTIC (*MAT_001), *MAT_PLASTIC_KINEMATIC
!> (*MAT_003), *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024), each with the _TITLE option.
!> The object comes from the material factory (dx_mat_factory); parameters are checked by the
!> material's setup in the build step (dx_model_build), after curves are known.
!> Layouts: LS-DYNA Keyword User's Manual, Vol. II (material models).
module dx_read_materials
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str
   use dx_deck_cards, only: deck_t, block_t, get_int, get_real, field_error, block_error, &
                            std_widths, data_start, block_title, check_max_cards
   use dx_deck_registry, only: registry_t
   use dx_material, only: material_t, mat_holder_t
   use dx_mat_factory, only: new_material
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_plastic_kinematic, only: mat_plastic_kinematic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   use dx_model_input, only: model_input_t, origin
   implicit none
   private
   public :: register_materials

contains

   !> Add the material keywords and their numeric aliases to the registry.
   subroutine register_materials(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('MAT_ELASTIC', read_mat, title=.true.)
      call reg%add('MAT_001', read_mat, title=.true.)
      call reg%add('MAT_PLASTIC_KINEMATIC', read_mat, title=.true.)
      call reg%add('MAT_003', read_mat, title=.true.)
      call reg%add('MAT_PIECEWISE_LINEAR_PLASTICITY', read_mat, title=.true.)
      call reg%add('MAT_024', read_mat, title=.true.)
   end subroutine register_materials

   subroutine read_mat(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: m
      type(mat_holder_t), allocatable :: t(:)
      integer :: w(8), i0, mtype, mid, n, ncard, k
      real(wp) :: ro, v(8)
      character(:), allocatable :: msg, fname
      logical :: needs_curves
      integer :: ic
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      select case (blk%base)
      case ('MAT_ELASTIC', 'MAT_001')
         mtype = 1; ncard = 1
      case ('MAT_PLASTIC_KINEMATIC', 'MAT_003')
         mtype = 3; ncard = 2
      case default
         mtype = 24; ncard = 4
      end select
      if (blk%n < i0) then
         call block_error(deck, blk, 0, 'missing card 1 (MID RO E PR ...)', error)
         return
      end if
      call check_max_cards(deck, blk, i0 + ncard - 1, error)
      if (allocated(error)) return
      call new_material(mtype, m, error)
      if (allocated(error)) then
         msg = error%message
         call block_error(deck, blk, 0, msg, error)
         return
      end if
      call get_int(deck, blk, i0, 1, w, 'MID', 0, mid, error)
      if (allocated(error)) return
      if (mid <= 0) then
         call field_error(deck, blk, i0, 1, w, 'MID', 'material id must be > 0, got '// &
                          str(mid), error)
         return
      end if
      call get_real(deck, blk, i0, 2, w, 'RO', 0.0_wp, ro, error)
      if (allocated(error)) return
      m%label = mid
      m%ro = ro
      m%title = block_title(blk)
      select type (m)
      type is (mat_elastic_t)
         call reals(i0, 3, ['E ', 'PR', 'DA', 'DB', 'K '], [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                    0.0_wp], v)
         if (allocated(error)) return
         m%e = v(1); m%pr = v(2); m%da = v(3); m%db = v(4); m%k = v(5)
      type is (mat_plastic_kinematic_t)
         call reals(i0, 3, ['E   ', 'PR  ', 'SIGY', 'ETAN', 'BETA'], [0.0_wp, 0.0_wp, 0.0_wp, &
                    0.0_wp, 0.0_wp], v)
         if (allocated(error)) return
         m%e = v(1); m%pr = v(2); m%sigy = v(3); m%etan = v(4); m%beta = v(5)
         call reals(i0 + 1, 1, ['SRC', 'SRP', 'FS ', 'VP '], [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], v)
         if (allocated(error)) return
         m%src = v(1); m%srp = v(2); m%fs = v(3); m%vp = v(4)
      type is (mat_piecewise_linear_t)
         call reals(i0, 3, ['E   ', 'PR  ', 'SIGY', 'ETAN', 'FAIL', 'TDEL'], [0.0_wp, 0.0_wp, &
                    0.0_wp, 0.0_wp, 1.0e21_wp, 0.0_wp], v)
         if (allocated(error)) return
         m%e = v(1); m%pr = v(2); m%sigy = v(3); m%etan = v(4); m%fail = v(5); m%tdel = v(6)
         if (m%fail == 0.0_wp) m%fail = 1.0e21_wp
         call reals(i0 + 1, 1, ['C', 'P'], [0.0_wp, 0.0_wp], v)
         if (allocated(error)) return
         m%c = v(1); m%p = v(2)
         call get_int(deck, blk, i0 + 1, 3, w, 'LCSS', 0, m%lcss, error)
         if (allocated(error)) return
         call get_int(deck, blk, i0 + 1, 4, w, 'LCSR', 0, m%lcsr, error)
         if (allocated(error)) return
         call get_real(deck, blk, i0 + 1, 5, w, 'VP', 0.0_wp, m%vp, error)
         if (allocated(error)) return
         call get_int(deck, blk, i0 + 1, 6, w, 'LCF', 0, n, error)
         if (allocated(error)) return
         if (n /= 0) then
            call field_error(deck, blk, i0 + 1, 6, w, 'LCF', 'failure strain curves are '// &
                             'not supported', error)
            return
         end if
         do k = 1, 8
            call get_real(deck, blk, i0 + 2, k, w, 'EPS'//str(k), 0.0_wp, m%eps(k), error)
            if (allocated(error)) return
            call get_real(deck, blk, i0 + 3, k, w, 'ES'//str(k), 0.0_wp, m%es(k), error)
            if (allocated(error)) return
         end do
      end select
      ! materials without curve references are checked here, so a bad value points at its field
      needs_curves = .false.
      select type (m)
      type is (mat_piecewise_linear_t)
         needs_curves = m%lcss /= 0 .or. m%lcsr /= 0
      end select
      if (.not. needs_curves) then
         call m%setup(error)
         if (allocated(error)) then
            msg = error%message
            call locate_field(mtype, msg, ic, k, fname)
            if (ic >= 0) then
               call field_error(deck, blk, i0 + ic, k, w, fname, &
                                'material '//str(mid)//': '//msg(len(fname) + 9:), error)
            else
               call block_error(deck, blk, i0, 'material '//str(mid)//': '//msg, error)
            end if
            return
         end if
      end if
      n = size(inp%mats)
      allocate(t(n + 1))
      do k = 1, n
         call move_alloc(inp%mats(k)%m, t(k)%m)
      end do
      call move_alloc(m, t(n + 1)%m)
      call move_alloc(t, inp%mats)
      inp%mat_src = [inp%mat_src, origin(blk%ifile, blk%cards(i0)%line, blk%name)]
   contains
      !> real fields k0, k0+1, ... of card ic named names(:)
      subroutine reals(ic, k0, names, defs, vals)
         integer, intent(in) :: ic, k0
         character(*), intent(in) :: names(:)
         real(wp), intent(in) :: defs(:)
         real(wp), intent(out) :: vals(:)
         integer :: j
         vals = 0.0_wp
         do j = 1, size(names)
            call get_real(deck, blk, ic, k0 + j - 1, w, trim(names(j)), defs(j), vals(j), error)
            if (allocated(error)) return
         end do
      end subroutine reals
   end subroutine read_mat

   !> Card offset (from the first data card) and field of 'field NAME: ...' in a setup
   !> message of material type mtype; ic = -1 when the message names no single field.
   subroutine locate_field(mtype, msg, ic, k, fname)
      integer, intent(in) :: mtype
      character(*), intent(in) :: msg
      integer, intent(out) :: ic, k
      character(:), allocatable, intent(out) :: fname
      character(len=4), parameter :: c1(8, 3) = reshape([ &
         'MID ', 'RO  ', 'E   ', 'PR  ', 'DA  ', 'DB  ', 'K   ', '    ', &
         'MID ', 'RO  ', 'E   ', 'PR  ', 'SIGY', 'ETAN', 'BETA', '    ', &
         'MID ', 'RO  ', 'E   ', 'PR  ', 'SIGY', 'ETAN', 'FAIL', 'TDEL'], [8, 3])
      character(len=4), parameter :: c2(8, 3) = reshape([ &
         '    ', '    ', '    ', '    ', '    ', '    ', '    ', '    ', &
         'SRC ', 'SRP ', 'FS  ', 'VP  ', '    ', '    ', '    ', '    ', &
         'C   ', 'P   ', 'LCSS', 'LCSR', 'VP  ', '    ', '    ', '    '], [8, 3])
      integer :: j, col
      ic = -1
      k = 0
      fname = ''
      if (len(msg) < 7) return
      if (msg(1:6) /= 'field ') return
      col = index(msg, ':')
      if (col < 8) return
      fname = msg(7:col-1)
      j = merge(1, merge(2, 3, mtype == 3), mtype == 1)
      do k = 1, 8
         if (c1(k, j) == fname) then
            ic = 0; return
         end if
         if (c2(k, j) == fname) then
            ic = 1; return
         end if
      end do
      k = 0
   end subroutine locate_field
end module dx_read_materials
