!> dynx-combine OUTDIR: merge the per-rank plot files of an MPI run (OUTDIR/d3plot_rank_*.h5,
!> written by every rank, dx_par_plot) into OUTDIR/d3plot.h5 + OUTDIR/d3plot.xdmf, the files
!> a serial run writes (dx_plot_part: plot_combine). An MPI run does this itself at its end;
!> the tool is for a run that was killed: it combines the states every rank completed.
!> A killed serial run's state files (DIR/d3plot.states/, dx_plot_states) are merged too.
!> Exit codes: 0 done, 2 usage error, 4 I/O error (a missing, unreadable or foreign part).
program dynx_combine
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use dx_error, only: error_t, EXIT_INPUT, EXIT_IO, exit_process
   use dx_strings, only: str
   use dx_plot_part, only: plot_combine, plot_part_name
   use dx_plot_hdf5, only: plot_merge_states
   use dx_plot_states, only: state_file, is_link, states_link_all
   use dx_out_lock, only: out_lock
   implicit none
   character(:), allocatable :: dir, arg
   type(error_t), allocatable :: error
   integer :: n, l, i, nst, lock_fd
   logical :: there

   dir = ''
   n = command_argument_count()
   do i = 1, n
      call get_command_argument(i, length=l)
      allocate(character(l) :: arg)
      call get_command_argument(i, arg)
      select case (arg)
      case ('-h', '--help')
         call usage(); stop
      case default
         if (arg(1:min(1, len(arg))) == '-' .or. len(dir) > 0) then
            write(error_unit, '(a)') 'dynx-combine: error: unexpected argument '//arg
            write(error_unit, '(a)') 'dynx-combine: try dynx-combine --help'
            call exit_process(EXIT_INPUT)
         end if
         dir = arg
      end select
      deallocate(arg)
   end do
   if (len(dir) == 0) then
      write(error_unit, '(a)') 'dynx-combine: error: no output directory given'
      write(error_unit, '(a)') 'dynx-combine: try dynx-combine --help'
      call exit_process(EXIT_INPUT)
   end if
   inquire(file=dir, exist=there)
   if (there) call out_lock(dir, 'dynx-combine', lock_fd, error)   ! not while a run writes
   if (allocated(error)) then
      write(error_unit, '(a)') 'dynx-combine: error: '//error%message
      call exit_process(error%code)
   end if
   inquire(file=plot_part_name(dir, 0), exist=there)
   if (.not. there) then
      ! (a finished run's state files are links to its d3plot.h5, the mesh file last)
      inquire(file=dir//'/'//state_file(0), exist=there)
      if (there) there = .not. is_link(dir//'/'//state_file(0))
   end if
   if (there .and. .not. plot_part_exists()) then
      ! a serial run killed before its end: merge its state files (dx_plot_states)
      call plot_merge_states(dir, nst, error)
      if (allocated(error)) then
         write(error_unit, '(a)') 'dynx-combine: error: '//error%message
         call exit_process(error%code)
      end if
      write(output_unit, '(a)') 'dynx-combine: '//str(nst)//' plot states of '//dir//'/'// &
         'd3plot.states -> '//dir//'/d3plot.h5 + '//dir//'/d3plot.xdmf'
      stop
   end if
   if (.not. there) then
      write(error_unit, '(a)') 'dynx-combine: error: '//plot_part_name(dir, 0)// &
         ' does not exist: '//dir//' holds no per-rank plot files (not the output of an '// &
         'MPI run, or a serial run''s d3plot.h5 is already complete)'
      call exit_process(EXIT_IO)
   end if
   call plot_combine(dir, nst, error)
   if (allocated(error)) then
      write(error_unit, '(a)') 'dynx-combine: error: '//error%message
      call exit_process(error%code)
   end if
   ! the states an MPI run published while it ran become links to d3plot.h5 (issue 21)
   inquire(file=dir//'/'//state_file(0), exist=there)
   if (there) call states_link_all(dir, nst, error)
   if (allocated(error)) then
      write(error_unit, '(a)') 'dynx-combine: error: '//error%message
      call exit_process(error%code)
   end if
   write(output_unit, '(a)') 'dynx-combine: '//str(nst)//' complete plot states -> '// &
      dir//'/d3plot.h5 + '//dir//'/d3plot.xdmf'

contains

   logical function plot_part_exists()
      inquire(file=plot_part_name(dir, 0), exist=plot_part_exists)
   end function plot_part_exists

   subroutine usage()
      write(output_unit, '(a)') &
         'usage: dynx-combine OUTDIR', &
         '', &
         'Merges the per-rank plot files of an MPI run (OUTDIR/d3plot_rank_NNNNN.h5) into', &
         'OUTDIR/d3plot.h5 + OUTDIR/d3plot.xdmf, identical to what a serial run writes.', &
         'The run does this itself when it ends (normally or on a numerical failure); use', &
         'the tool after a run was killed: it takes the states every rank completed.', &
         'A serial run killed before its end leaves OUTDIR/d3plot.states/ (one file per', &
         'state): the tool merges those into OUTDIR/d3plot.h5 + d3plot.xdmf and removes them.', &
         '', &
         'exit codes: 0 done, 2 usage error or OUTDIR busy (a dynx run still writes it;', &
         '            the holder is named), 4 I/O error (missing, unreadable or foreign', &
         '            part file; the file is named)'
   end subroutine usage
end program dynx_combine
