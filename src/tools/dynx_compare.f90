!> dynx-compare: numerical comparison of a dynx output file against a gold file, or of two
!> output folders file by file.
!>   dynx-compare [--tol tolfile] [--verbose] [--by-time] gold test
!> ASCII time histories (glstat, nodout, rcforc, ...) by column name and row order (--by-time:
!> each gold row against the test interpolated linearly to its time, dx_compare_dir); HDF5
!> plot files (*.h5) dataset by dataset and state by state. gold and test both folders: every
!> file they share that dynx-compare reads (dx_compare_dir). Rule and tolerance file format:
!> docs/output-format.md (logic in dx_compare).
!> Exit status: 0 all pass, 1 any failure, 2 usage error (bad arguments, bad tolerance file).
program dynx_compare
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use dx_error, only: error_t
   use dx_compare, only: tol_table_t, compare_report_t, read_tolerances, compare_files
   use dx_io_sys, only: sys_exit, sys_file_kind
   use dx_compare_dir, only: compare_by_time, compare_folders
   use dx_strings, only: command_arg
   implicit none
   type(tol_table_t) :: tol
   type(compare_report_t) :: report
   type(error_t), allocatable :: error
   character(:), allocatable :: arg, gold, test, tolfile
   integer :: i, n, nfail
   logical :: verbose, skip, by_time

   verbose = .false.
   by_time = .false.
   skip = .false.
   n = command_argument_count()
   do i = 1, n
      if (skip) then       ! the value of the option before
         skip = .false.
         cycle
      end if
      arg = command_arg(i)
      select case (arg)
      case ('--tol')
         if (i == n) call usage('--tol needs a file')
         tolfile = command_arg(i + 1)
         skip = .true.
      case ('--verbose', '-v')
         verbose = .true.
      case ('--by-time')
         by_time = .true.
      case ('-h', '--help')
         call usage('')
      case default
         if (arg(1:1) == '-' .and. len(arg) > 1) call usage('unknown option '//arg)
         if (.not. allocated(gold)) then
            gold = arg
         else if (.not. allocated(test)) then
            test = arg
         else
            call usage('too many arguments')
         end if
      end select
   end do
   if (.not. allocated(test)) call usage('need a gold file and a test file')
   if (allocated(tolfile)) then
      call read_tolerances(tolfile, tol, error)
      if (allocated(error)) then
         write(error_unit, '(a)') 'dynx-compare: error: '//error%message
         call sys_exit(2)
      end if
   end if
   if (sys_file_kind(gold) == 'directory' .and. sys_file_kind(test) == 'directory') then
      call compare_folders(gold, test, tol, by_time, verbose, output_unit, nfail, error)
      if (allocated(error)) then
         write(error_unit, '(a)') 'dynx-compare: error: '//error%message
         call sys_exit(2)
      end if
      if (nfail > 0) call sys_exit(1)
      call sys_exit(0)
   end if
   if (sys_file_kind(gold) == 'directory') call usage(gold//' is a folder and '//test// &
                                                     ' is not: give two files or two folders')
   if (sys_file_kind(test) == 'directory') call usage(test//' is a folder and '//gold// &
                                                     ' is not: give two files or two folders')
   n = len(gold)
   if (by_time .and. .not. (n >= 3 .and. gold(max(1, n - 2):) == '.h5')) then
      call compare_by_time(gold, test, tol, report)
   else
      call compare_files(gold, test, tol, report)
   end if
   call report%print(output_unit, verbose)
   if (.not. report%passed()) call sys_exit(1)

contains

   subroutine usage(msg)
      character(*), intent(in) :: msg
      if (len(msg) > 0) write(error_unit, '(a)') 'dynx-compare: error: '//msg
      write(error_unit, '(a)') 'usage: dynx-compare [--tol tolfile] [--verbose] [--by-time] '// &
                               'gold test   (two files or two folders)'
      if (len(msg) == 0) call sys_exit(0)
      call sys_exit(2)
   end subroutine usage
end program dynx_compare
