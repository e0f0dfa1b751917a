!> Unit tests of the per-rank plot files and their combination (dx_plot_part), without MPI:
!> two parts (ranks 0 and 1 of 2) of a 2-hex mesh whose elements share a face; rank 0 owns
!> nodes 1-8 and element 1, rank 1 owns nodes 9-12 and element 2 (nodes 5-12). Three states
!> with x = x0 + t*(1, 2, 3) and element stresses of known invariants. Checks the combined
!> d3plot.h5 (global order, displacement x - x0 exactly, von Mises and pressure of uniaxial
!> and pure-shear stress), plot_part_truncate (states cut back, combine takes the smallest
!> count, too few states is an I/O error), a torn state .tmp (ignored, removed by truncate)
!> and the combine errors (foreign part, foreign state file, missing part).
program test_plot_part
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_IO
   use dx_h5, only: h5_file_t, h5_open_read, h5_close, h5_read, h5_read_attr
   use dx_io_sys, only: sys_mkdir_p
   use dx_plot_part, only: plot_part_t, plot_combine, plot_part_truncate, plot_part_name, &
                           plot_part_state_name, plot_part_count
   use dx_plot_fields, only: plot_state_t, plot_state_alloc, F_COORD, F_VEL, F_STRESS, F_EPSP, &
                             F_FAILED
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   character(*), parameter :: TMP = 'build/test_plot_part.tmp'
   type(error_t), allocatable :: error
   real(wp) :: x0(3, 12)
   integer :: i, n
   logical :: there

   call sys_mkdir_p(TMP, error)
   call check(.not. allocated(error), 'create scratch dir '//TMP)
   do i = 1, 12     ! three layers of 4 nodes: z = 0, 1, 2
      x0(:, i) = [real(merge(1, 0, mod(i - 1, 4) == 1 .or. mod(i - 1, 4) == 2), wp), &
                  real(merge(1, 0, mod(i - 1, 4) >= 2), wp), real((i - 1)/4, wp)]
   end do
   call write_parts(TMP, 2, 777)
   write(*, '(a)') 'combine two parts'
   call plot_combine(TMP, n, error)
   call check(.not. allocated(error), 'combine succeeds')
   call check(n == 3, 'three complete states combined')
   call check_combined(TMP, 3)

   write(*, '(a)') 'truncate'
   call plot_part_truncate(TMP, 1, 2, error)
   call check(.not. allocated(error), 'rank 1 cut back to 2 states')
   call plot_combine(TMP, n, error)
   call check(.not. allocated(error) .and. n == 2, 'combine takes the smallest count (2)')
   call check_combined(TMP, 2)
   call plot_part_truncate(TMP, 0, 5, error)
   call check(allocated(error), 'cutting 3 states back to 5 is an error')
   if (allocated(error)) then
      call check(error%code == EXIT_IO, 'exit code 4')
      call check(index(error%message, 'd3plot_rank_00000.h5') > 0, 'message names the file')
      deallocate(error)
   end if

   write(*, '(a)') 'resume'
   block
      type(plot_part_t) :: p
      integer, allocatable :: nd(:)
      nd = [(i, i = 1, 8)]
      call p%resume(TMP, 0, 2, error)
      call check(.not. allocated(error) .and. p%nstates == 2, 'rank 0 resumed after 2 states')
      call p%write_state(part_state(1.0_wp, x0(:, nd) + spread([1.0_wp, 2.0_wp, 3.0_wp], 2, &
                         8), spread([-1.0_wp, 0.0_wp, 0.0_wp], 2, 8), &
                         reshape([300.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [6, 1]), &
                         [0.03_wp], [0]), error)
      call check(.not. allocated(error) .and. p%nstates == 3, 'state 3 written again')
      call p%close(error)
      call plot_part_truncate(TMP, 1, 2, error)   ! rank 1 is at 2 already: no change
      call check(.not. allocated(error), 'cut to its own count is a no-op')
      call plot_combine(TMP, n, error)
      call check(.not. allocated(error) .and. n == 2, 'combine: 3 and 2 states give 2')
   end block

   write(*, '(a)') 'torn temporary state file'
   ! a kill -9 inside a state's writes leaves KKKKKK.h5.tmp, never KKKKKK.h5: ignored
   call execute_command_line('printf torn > '//plot_part_state_name(TMP, 1, 3)//'.tmp')
   call check(plot_part_count(TMP, 1) == 2, 'rank 1 still counts 2 states')
   call plot_combine(TMP, n, error)
   call check(.not. allocated(error) .and. n == 2, 'combine ignores the torn .tmp (2 states)')
   call plot_part_truncate(TMP, 1, 1, error)
   inquire(file=plot_part_state_name(TMP, 1, 3)//'.tmp', exist=there)
   call check(.not. allocated(error) .and. plot_part_count(TMP, 1) == 1 .and. .not. there, &
              'truncate to 1 removes state 2 and the .tmp')

   write(*, '(a)') 'combine errors'
   call write_parts(TMP//'/other', 2, 778)
   ! a state file of another run (stamp 778) in rank 1's part
   call execute_command_line('cp '//plot_part_state_name(TMP//'/other', 1, 1)//' '// &
                             plot_part_state_name(TMP, 1, 1))
   call plot_combine(TMP, n, error)
   call check(allocated(error), 'a state file of another run is refused')
   if (allocated(error)) then
      call check(error%code == EXIT_IO .and. index(error%message, 'state of another run') > 0 &
                 .and. index(error%message, '000001.h5') > 0, 'exit 4 naming the state file')
      deallocate(error)
   end if
   call copy_part(TMP//'/other', TMP, 1)
   call plot_combine(TMP, n, error)
   call check(allocated(error), 'a part of another run is refused')
   if (allocated(error)) then
      call check(error%code == EXIT_IO .and. index(error%message, 'part of another run') > 0 &
                 .and. index(error%message, 'd3plot_rank_00001.h5') > 0, &
                 'exit 4 naming the foreign part')
      deallocate(error)
   end if
   call execute_command_line('rm -f '//plot_part_name(TMP, 1))
   call plot_combine(TMP, n, error)
   call check(allocated(error), 'a missing part is an error')
   if (allocated(error)) then
      call check(error%code == EXIT_IO .and. index(error%message, 'd3plot_rank_00001.h5') > 0, &
                 'exit 4 naming the missing part')
      deallocate(error)
   end if
   call assert_summary()

contains

   !> Both parts of a run with the given stamp, three states each, in dir.
   subroutine write_parts(dir, np, stamp)
      character(*), intent(in) :: dir
      integer, intent(in) :: np, stamp
      type(plot_part_t) :: p
      type(error_t), allocatable :: err
      integer :: r, k, e1
      integer, allocatable :: nodes(:), hex(:, :)
      real(wp) :: t, s(6, 1)
      call sys_mkdir_p(dir, err)
      do r = 0, np - 1
         if (r == 0) then
            nodes = [(i, i = 1, 8)]
            hex = reshape([(i - 1, i = 1, 8)], [8, 1])
            e1 = 1
         else
            nodes = [(i, i = 9, 12)]
            hex = reshape([(i - 1, i = 5, 12)], [8, 1])
            e1 = 2
         end if
         call p%open(dir, r, np, stamp, 'two hexes', 12, 2, nodes, x0(:, nodes), 100 + nodes, &
                     [e1], hex, [10*e1], [7], err)
         call check(.not. allocated(err), 'open part '//plot_part_name(dir, r))
         do k = 1, 3
            t = 0.5_wp*(k - 1)
            if (e1 == 1) then
               s(:, 1) = [100.0_wp*k, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]   ! uniaxial
            else
               s(:, 1) = [0.0_wp, 0.0_wp, 0.0_wp, 10.0_wp*k, 0.0_wp, 0.0_wp]    ! shear
            end if
            call p%write_state(part_state(t, x0(:, nodes) + t*spread([1.0_wp, 2.0_wp, &
                               3.0_wp], 2, size(nodes)), spread([-1.0_wp, 0.0_wp, &
                               real(r, wp)], 2, size(nodes)), s, [0.01_wp*k], &
                               [merge(1, 0, k == 3 .and. e1 == 2)]), err)
            call check(.not. allocated(err), 'write state')
         end do
         call p%close(err)
         call check(.not. allocated(err), 'close part')
      end do
   end subroutine write_parts

   !> A rank's part state (the schema's part fields) from its arrays.
   function part_state(t, x, v, s, epsp, failed) result(st)
      real(wp), intent(in) :: t, x(:, :), v(:, :), s(:, :), epsp(:)
      integer, intent(in) :: failed(:)
      type(plot_state_t) :: st
      call plot_state_alloc(st, size(x, 2), size(s, 2), part=.true.)
      st%time = t
      st%f(F_COORD)%r = x
      st%f(F_VEL)%r = v
      st%f(F_STRESS)%r = s
      st%f(F_EPSP)%r(1, :) = epsp
      st%f(F_FAILED)%r(1, :) = real(failed, wp)
   end function part_state

   subroutine copy_part(from, to, r)
      character(*), intent(in) :: from, to
      integer, intent(in) :: r
      call execute_command_line('cp '//plot_part_name(from, r)//' '//plot_part_name(to, r))
   end subroutine copy_part

   !> The combined file of dir holds states 1..nst with the values written above.
   subroutine check_combined(dir, nst)
      character(*), intent(in) :: dir
      integer, intent(in) :: nst
      type(h5_file_t) :: f
      type(error_t), allocatable :: err
      real(wp), allocatable :: b(:), xs(:, :)
      integer :: ns, k
      character(14) :: g
      real(wp) :: t
      call h5_open_read(f, dir//'/d3plot.h5', err)
      call check(.not. allocated(err), 'open combined file')
      if (allocated(err)) return
      call h5_read_attr(f, '/', 'nstates', ns, err)
      call check(ns == nst, 'nstates attribute')
      call h5_read(f, '/states/times', b, err)
      call check(size(b) == nst, 'times has nstates entries')
      call h5_read(f, '/mesh/coordinates', b, err)
      call check(all(reshape(b, [3, 12]) == x0), 'mesh coordinates in global order')
      call h5_read(f, '/mesh/node_ids', b, err)
      call check(all(nint(b) == [(100 + i, i = 1, 12)]), 'node labels in global order')
      call h5_read(f, '/mesh/hex8', b, err)
      call check(all(nint(b) == [(i - 1, i = 1, 8), (i - 1, i = 5, 12)]), &
                 'connectivity 0-based, global')
      call h5_read(f, '/mesh/element_ids', b, err)
      call check(all(nint(b) == [10, 20]), 'element labels')
      do k = 1, nst
         write(g, '(a,i6.6)') '/states/', k
         t = 0.5_wp*(k - 1)
         call h5_read(f, g//'/coordinates', b, err)
         xs = reshape(b, [3, 12])
         call h5_read(f, g//'/displacement', b, err)
         call check(all(reshape(b, [3, 12]) == xs - x0), 'displacement = x - x0 exactly')
         call check_close(b(3*12), 3.0_wp*t, 1.0e-15_wp, 0.0_wp, 'z displacement of node 12')
         call h5_read(f, g//'/velocity', b, err)
         call check(all(reshape(b, [3, 12]) == reshape([([-1.0_wp, 0.0_wp, 0.0_wp], i = 1, 8), &
                    ([-1.0_wp, 0.0_wp, 1.0_wp], i = 9, 12)], [3, 12])), 'velocity by owner')
         call h5_read(f, g//'/von_mises', b, err)
         call check_close(b(1), 100.0_wp*k, 1.0e-12_wp, 1.0e-14_wp, 'von Mises uniaxial = |s|')
         call check_close(b(2), sqrt(3.0_wp)*10.0_wp*k, 1.0e-12_wp, 1.0e-14_wp, &
                          'von Mises shear = sqrt(3) tau')
         call h5_read(f, g//'/pressure', b, err)
         call check_close(b(1), -100.0_wp*k/3.0_wp, 1.0e-12_wp, 1.0e-14_wp, 'pressure -s/3')
         call check_close(b(2), 0.0_wp, 1.0e-12_wp, 0.0_wp, 'pressure of shear 0')
         call h5_read(f, g//'/failed', b, err)
         call check(all(nint(b) == [0, merge(1, 0, k == 3)]), 'failed flags')
         call h5_read(f, g//'/eff_plastic_strain', b, err)
         call check(all(b == 0.01_wp*k), 'effective plastic strain')
      end do
      call check(.not. allocated(err), 'all datasets read')
      call h5_close(f, err)
   end subroutine check_combined
end program test_plot_part
