!> dynx-compare: numerical comparison of a dynx output file against a gold file.
!>   dynx-compare [--tol tolfile] [--verbose] gold_file test_file
!> ASCII time histories (glstat, nodout) by column name and row order; HDF5 plot files
!> (*.h5) dataset by dataset and state by state. Rule and tolerance file format:
!> docs/output-format.md (logic in dx_compare).
!> Exit status: 0 all pass, 1 any failure, 2 usage error (bad arguments, bad tolerance file).
program dynx_compare
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use dx_error, only: error_t
   use dx_compare, only: tol_table_t, compare_report_t, read_tolerances, compare_files
   use dx_io_sys, only: sys_exit
   use dx_strings, only: command_arg
   implicit none
   type(tol_table_t) :: tol
   type(compare_report_t) :: report
   type(error_t), allocatable :: error
   character(:), allocatable :: arg, gold, test, tolfile
   integer :: i, n
   logical :: verbose, skip

   verbose = .false.
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
   call compare_files(gold, test, tol, report)
   call report%print(output_unit, verbose)
   if (.not. report%passed()) call sys_exit(1)

contains

   subroutine usage(msg)
      character(*), intent(in) :: msg
      if (len(msg) > 0) write(error_unit, '(a)') 'dynx-compare: error: '//msg
      write(error_unit, '(a)') 'usage: dynx-compare [--tol tolfile] [--verbose] gold test'
      if (len(msg) == 0) call sys_exit(0)
      call sys_exit(2)
   end subroutine usage
end program dynx_compare
