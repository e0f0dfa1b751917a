!> Errors at the collective points of an MPI run's start-up (issue 6: bad input under
!> mpirun). Every rank reads the same deck, so a bad deck fails on every rank with the same
!> message; a rank file or the output directory may fail on one rank only. par_agree is
!> called by every rank at the same point (after the deck is read, after the rank files,
!> after the output is opened): when any rank holds an error, every rank leaves with the
!> error of the lowest failing rank, and the run then stops on every rank together - rank 0
!> prints the message once, every rank calls MPI_Finalize and exits with the code (no
!> MPI_Abort, no message per rank, no hang). The message is the serial run's when every
!> rank failed with that same message (a bad deck), else it names the failing rank
!> ("rank R of N: ..."). In a serial run (one rank) par_agree returns at once.
!> The pattern is the one of MPI codes that check input collectively before the run
!> (e.g. OpenRadioss's starter/engine split): decide together, then stop together;
!> MPI_Abort stays for failures one rank meets alone in the middle of a cycle.
module dx_par_agree
   use dx_error, only: error_t, set_error
   use dx_strings, only: str
   use dx_par, only: par_size, par_rank, par_allreduce, par_bcast_text, PAR_MIN
   implicit none
   private
   public :: par_agree, par_agreed

   logical, save :: agreed = .false.     !< an error every rank knows (stop together)

contains

   !> Collective (every rank, same point). On return error is allocated on every rank or on
   !> none; when allocated, it is the lowest failing rank's error (message as above).
   subroutine par_agree(error)
      type(error_t), allocatable, intent(inout) :: error
      character(:), allocatable :: msg
      integer :: root, code, same, np
      np = par_size()
      if (np <= 1) return
      root = huge(root)
      if (allocated(error)) root = par_rank()
      call par_allreduce(root, PAR_MIN)
      if (root == huge(root)) return
      msg = ''
      code = 0
      if (par_rank() == root) then
         msg = error%message
         code = error%code
      end if
      call par_bcast_text(msg, code, root)
      same = 0
      if (allocated(error)) then
         if (error%message == msg .and. error%code == code) same = 1
      end if
      call par_allreduce(same, PAR_MIN)
      if (allocated(error)) deallocate(error)
      if (same == 1) then
         call set_error(error, msg, code)
      else
         call set_error(error, 'rank '//str(root)//' of '//str(np)//': '//msg, code)
      end if
      agreed = .true.
   end subroutine par_agree

   !> Whether the error being handled is known to every rank (then stop without MPI_Abort).
   logical function par_agreed()
      par_agreed = agreed
   end function par_agreed
end module dx_par_agree
