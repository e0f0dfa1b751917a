!> Formatted output files kept by a component itself (rbdout, rcforc) across a restart:
!> the size of the file at a restart dump, and reopening it cut back to that size for
!> appending, so the continued run writes the same bytes as the uninterrupted run (what the
!> interrupted run wrote after the dump is dropped). The same rule as dx_thist for glstat
!> and nodout.
module dx_append_file
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_io_sys, only: sys_truncate
   use dx_strings, only: str
   implicit none
   private
   public :: unit_bytes, append_from, cut_back

contains

   !> Bytes of the file open on unit, after flushing what is buffered (0 on failure).
   function unit_bytes(unit) result(n)
      integer, intent(in) :: unit
      integer(8) :: n
      integer :: ios
      n = 0
      flush(unit, iostat=ios)
      if (ios /= 0) return
      inquire(unit=unit, size=n, iostat=ios)
      if (ios /= 0 .or. n < 0) n = 0
   end function unit_bytes

   !> Open path for appending after cutting it back to its first nbytes bytes.
   !> A file shorter than nbytes (or missing) is not this run's: an I/O error.
   subroutine append_from(path, nbytes, unit, error)
      character(*), intent(in) :: path
      integer(8), intent(in) :: nbytes
      integer, intent(out) :: unit
      type(error_t), allocatable, intent(out) :: error
      integer(8) :: sz
      logical :: there
      integer :: ios
      character(256) :: msg
      unit = -1
      sz = -1
      inquire(file=path, exist=there, size=sz)
      if (.not. there) sz = -1
      call cut_back(path, sz, nbytes, 'missing, or another run''s file?', error)
      if (allocated(error)) return
      open(newunit=unit, file=path, status='old', action='write', position='append', &
           form='formatted', iostat=ios, iomsg=msg)
      if (ios /= 0) call set_error(error, 'cannot open '//path//' for appending: '// &
                                   trim(msg), EXIT_IO)
   end subroutine append_from

   !> Cut the file path of sz bytes back to its first nbytes (the lines a killed run wrote
   !> after the dump go); shorter than nbytes (sz < 0: missing) is an I/O error naming the
   !> sizes and the hint.
   subroutine cut_back(path, sz, nbytes, hint, error)
      character(*), intent(in) :: path, hint
      integer(8), intent(in) :: sz, nbytes
      type(error_t), allocatable, intent(out) :: error
      if (sz < nbytes) then
         call set_error(error, 'cannot continue '//path//': it has '//str(max(sz, 0_8))// &
            ' bytes, the restart dump expects at least '//str(nbytes)//' ('//hint//')', &
            EXIT_IO)
      else if (sz > nbytes) then
         call sys_truncate(path, nbytes, error)
      end if
   end subroutine cut_back
end module dx_append_file
