!> The plot states of a running serial job, one small HDF5 file per state (issue 7):
!>   DIR/d3plot.states/mesh.h5     /mesh/... and the title attribute, as in d3plot.h5
!>   DIR/d3plot.states/NNNNNN.h5   /states/NNNNNN (attribute time, the 8 datasets), the
!>                                 group of d3plot.h5 under the same path
!> Each file is written under NAME.tmp, closed (HDF5 writes all its metadata), fsynced and
!> renamed; only then is it listed in the XDMF (itself rewritten by temp + rename), and it is
!> never written again. A kill -9 at any moment therefore leaves every listed state whole:
!> an HDF5 file is only unsafe while it is being rewritten in place (H5Fflush rewrites its
!> B-trees, heaps and superblock), and no listed file ever is. At the orderly end of the run
!> the writer (dx_plot_hdf5) renames its d3plot.h5 into place, points the XDMF at it and
!> replaces each file here by a symbolic link to ../d3plot.h5 (states_link_all; issue 21,
!> live viewing): d3plot.h5 holds the same groups under the same paths, so a reader (a
!> ParaView session) that still holds the XDMF of the running job reads on through them. The same idea as LS-DYNA's d3plot families (one file per group
!> of states); the atomic-rename discipline is the one of Pillai et al., "All file systems
!> are not created equal", OSDI 2014 (write temp, fsync, rename).
!> All HDF5 calls go through dx_h5.
module dx_plot_states
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char, c_size_t, c_long
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_h5, only: h5_file_t, h5_create, h5_close_keep, h5_create_group
   use dx_io_sys, only: sys_rename, sys_fsync, sys_mkdir_p
   use dx_libc, only: c_unlink, c_rmdir, c_symlink, c_readlink
   use dx_xdmf, only: state_group
   use dx_plot_fields, only: plot_state_t, plot_state_write, plot_mesh_write
   implicit none
   private
   public :: STATES_DIR, state_file, states_write_mesh, states_write_state, states_have, &
             states_clear, states_remove_all, file_remove, publish, states_link_all, is_link

   character(*), parameter :: STATES_DIR = 'd3plot.states'


contains

   !> Name of state k's file relative to the output directory: d3plot.states/NNNNNN.h5
   !> (k = 0: the mesh file d3plot.states/mesh.h5).
   function state_file(k) result(p)
      integer, intent(in) :: k
      character(:), allocatable :: p
      character(:), allocatable :: g
      if (k == 0) then
         p = STATES_DIR//'/mesh.h5'
      else
         g = state_group(k)
         p = STATES_DIR//'/'//g(9:)//'.h5'
      end if
   end function state_file

   !> Remove a file if it is there (unlink(2); a missing file is not an error).
   subroutine file_remove(path)
      character(*), intent(in) :: path
      integer(c_int) :: r
      r = c_unlink(path//c_null_char)
   end subroutine file_remove

   !> Write dir/d3plot.states/mesh.h5 (temp, close, fsync, rename).
   subroutine states_write_mesh(dir, x0, nlab, cells, elab, ids, title, error)
      character(*), intent(in) :: dir, title
      real(wp), intent(in) :: x0(:, :)
      integer, intent(in) :: nlab(:), cells(:, :), elab(:), ids(:)
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      character(:), allocatable :: p
      call sys_mkdir_p(dir//'/'//STATES_DIR, error)
      if (allocated(error)) return
      p = dir//'/'//state_file(0)
      call h5_create(f, p//'.tmp', error)
      if (allocated(error)) return
      call plot_mesh_write(f, x0, nlab, cells, elab, ids, title, error)
      call publish(f, p, error)
   end subroutine states_write_mesh

   !> Write state k to dir/d3plot.states/NNNNNN.h5 (temp, close, fsync, rename).
   subroutine states_write_state(dir, k, st, error)
      character(*), intent(in) :: dir
      integer, intent(in) :: k
      type(plot_state_t), intent(in) :: st
      type(error_t), allocatable, intent(out) :: error
      type(h5_file_t) :: f
      character(:), allocatable :: p
      p = dir//'/'//state_file(k)
      call h5_create(f, p//'.tmp', error)
      if (allocated(error)) return
      call h5_create_group(f, '/states', error)
      if (.not. allocated(error)) call plot_state_write(f, state_group(k), st, error)
      call publish(f, p, error)
   end subroutine states_write_state

   !> Close f (written as p.tmp), sync it to disk and rename it to p; after an error in its
   !> writes (error allocated) only close it (the .tmp is never renamed; the error is kept).
   subroutine publish(f, p, error)
      type(h5_file_t), intent(inout) :: f
      character(*), intent(in) :: p
      type(error_t), allocatable, intent(inout) :: error
      call h5_close_keep(f, error)
      if (allocated(error)) return
      call sys_fsync(p//'.tmp', error)
      if (allocated(error)) return
      call sys_rename(p//'.tmp', p, error)
   end subroutine publish

   !> Whether dir holds the mesh file and the state files 1..n.
   logical function states_have(dir, n)
      character(*), intent(in) :: dir
      integer, intent(in) :: n
      integer :: k
      logical :: there
      states_have = .false.
      do k = 0, n
         inquire(file=dir//'/'//state_file(k), exist=there)
         if (.not. there) return
      end do
      states_have = .true.
   end function states_have

   !> Remove the state files k >= kfrom of dir and a left-over temporary file after them.
   !> They are written in order, so they run from 1 to the first missing one; they are
   !> removed from the last down, so a kill here leaves them contiguous again.
   subroutine states_clear(dir, kfrom)
      character(*), intent(in) :: dir
      integer, intent(in) :: kfrom
      integer :: k, m
      logical :: there
      m = kfrom - 1
      do
         inquire(file=dir//'/'//state_file(m + 1), exist=there)
         if (.not. there) exit
         m = m + 1
      end do
      call file_remove(dir//'/'//state_file(m + 1)//'.tmp')
      do k = m, kfrom, -1
         call file_remove(dir//'/'//state_file(k))
         call file_remove(dir//'/'//state_file(k)//'.lnk')
      end do
   end subroutine states_clear

   !> Whether path is a symbolic link (readlink(2) succeeds).
   logical function is_link(path)
      character(*), intent(in) :: path
      character(kind=c_char) :: buf(8)
      is_link = c_readlink(path//c_null_char, buf, 8_c_size_t) >= 0
   end function is_link

   !> The end of a run whose d3plot.h5 (same groups, same paths) is in place: the mesh file
   !> and the state files 1..n become symbolic links to ../d3plot.h5, each made as NAME.lnk
   !> and renamed over NAME (atomic: a reader or a kill finds the whole file or the link,
   !> never nothing), so an XDMF read while the job ran stays valid. Later state files (a
   !> killed run's, none after an orderly end) are removed.
   subroutine states_link_all(dir, n, error)
      character(*), intent(in) :: dir
      integer, intent(in) :: n
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: p
      integer :: k
      call states_clear(dir, n + 1)
      do k = n, 0, -1                   ! the mesh file last: its link marks the end
         p = dir//'/'//state_file(k)
         if (is_link(p)) cycle
         call file_remove(p//'.lnk')
         if (c_symlink('../d3plot.h5'//c_null_char, p//'.lnk'//c_null_char) /= 0) then
            call set_error(error, 'cannot create the symbolic link '//p//'.lnk', EXIT_IO)
            return
         end if
         call sys_rename(p//'.lnk', p, error)
         if (allocated(error)) return
      end do
   end subroutine states_link_all

   !> Remove dir/d3plot.states entirely (state files, the mesh file, the directory).
   subroutine states_remove_all(dir)
      character(*), intent(in) :: dir
      integer(c_int) :: r
      call states_clear(dir, 1)
      call file_remove(dir//'/'//state_file(0)//'.tmp')
      call file_remove(dir//'/'//state_file(0))
      call file_remove(dir//'/'//state_file(0)//'.lnk')
      r = c_rmdir(dir//'/'//STATES_DIR//c_null_char)
   end subroutine states_remove_all
end module dx_plot_states
