!> What the explicit loop carries from one cycle to the next besides the nodal and element
!> arrays of model_t, and the restart requests of the deck. Both are held by model_t
!> (model%run, model%rst) so a restart dump (src/io/dx_restart.f90) can write and restore
!> them: a continued run starts from exactly the numbers the uninterrupted run would have.
!> Restart keywords: LS-DYNA Keyword User's Manual Vol. I, *DATABASE_BINARY_D3DUMP and
!> *DATABASE_BINARY_RUNRSF (CYCL: cycles between dumps; NR: running restart files kept).
module dx_run_state
   use dx_kinds, only: wp
   implicit none
   private
   public :: run_state_t, restart_ctrl_t

   !> Loop state of run_explicit (src/solvers/dx_explicit.f90) at the top of a cycle.
   type :: run_state_t
      real(wp) :: dt_old = 0.0_wp        !< dt(n-1/2)
      real(wp) :: dt_first = 0.0_wp      !< first step (DTMIN reference)
      real(wp) :: tsmin = 0.0_wp         !< dt floor = DTMIN * dt_first
      real(wp) :: wext = 0.0_wp          !< work of the external loads
      real(wp) :: wrw = 0.0_wp           !< work of the rigid-wall forces
      real(wp) :: wcon = 0.0_wp          !< work of the constraint reactions
      real(wp) :: wdep = 0.0_wp          !< energy deposited (*DYNX_ENERGY_DEPOSITION)
      real(wp) :: next_plot = 0.0_wp     !< next plot-state time
      real(wp) :: next_glstat = 0.0_wp   !< next glstat time
      real(wp) :: next_nodout = 0.0_wp   !< next nodout time
      real(wp) :: next_matsum = 0.0_wp   !< next matsum time
      real(wp) :: next_spcforc = 0.0_wp  !< next spcforc time
      real(wp) :: next_sleout = 0.0_wp   !< next sleout time
      real(wp) :: next_elout = 0.0_wp    !< next elout time
      real(wp) :: next_ncforc = 0.0_wp   !< next ncforc time
      real(wp) :: next_status = 0.0_wp   !< next status-line time
      logical :: started = .false.       !< true once the loop state is set (restart: restored)
      ! output bookkeeping at the dump point (a restart truncates the files to these)
      integer :: nplot = 0               !< plot states written
      integer :: ndump = 0               !< d3dump files written (d3dumpNN numbering)
      integer :: nrunrsf = 0             !< running restart files written
      integer(8) :: glstat_bytes = 0     !< bytes in glstat
      integer(8) :: nodout_bytes = 0     !< bytes in nodout
      integer(8) :: matsum_bytes = 0     !< bytes in matsum
      integer(8) :: spcforc_bytes = 0    !< bytes in spcforc
      integer(8) :: sleout_bytes = 0     !< bytes in sleout
      integer(8) :: elout_bytes = 0      !< bytes in elout
      integer(8) :: ncforc_bytes = 0     !< bytes in ncforc
      !> dynx's energy guard (dx_solver): warned (0/1), the ratio's denominator and the
      !> ratio at the last judged cycle, so a continued run judges as the uninterrupted one
      real(wp) :: guard(3) = 0.0_wp
   end type run_state_t

   !> *DATABASE_BINARY_D3DUMP / *DATABASE_BINARY_RUNRSF requests (0: none)
   type :: restart_ctrl_t
      integer :: d3dump_cycl = 0         !< cycles between d3dumpNN.h5 files
      integer :: runrsf_cycl = 0         !< cycles between runrsf.h5 overwrites
      integer :: runrsf_nr = 1           !< running restart files in rotation
   end type restart_ctrl_t
end module dx_run_state
