!> The conserving rigid-body contact solver (dx_emc_solver) under MPI (ParaDyn; issue 6).
!> Every rank holds the whole (small) rigid-body state and repeats the Newton update of the
!> bodies (6 unknowns per body) identically; the work that grows with the model, the contact
!> pairs of the slave points (surface nodes, or a smoothed slave's centre) against the master
!> geometry, is split: a slave point is searched (emc_select_pairs) and its pairs evaluated
!> (emc_contact_forces) by the rank that owns its node in the partition the explicit engine
!> uses (the rank files of dynx-part, dx_partition). The results are gathered keyed by their
!> serial position (par_gather_ordered: MPI_Allgatherv, then a stable sort by key) and every
!> rank adds the per-pair force/torque contributions in the serial pair order with the serial
!> code, so the sums, and every file, are those of the serial run bit for bit. Fixed-order
!> sums: the idea of OpenRadioss /PARITH/ON; one exchange of the per-pair results per
!> residual: ParaDyn (Hoover et al., LLNL Engineering Thrust Area Report FY97, article 4).
!> Output, restart dumps (serial format) and the last plot state are written by rank 0;
!> stop and dump requests are reduced over the ranks at every step (dx_checkpoint).
!> A deck without *DYNX_CONSERVING_CONTACT, or a serial run, never calls this (on = .false.).
!> No module state: the slot ownership and the exchange counters are a par_emc_t, a component
!> of the rank's domain (dx_domain), which the solver passes to the conserving contact kernel
!> (dx_emc_contact) as its emc_split_t.
module dx_par_emc
   use dx_kinds, only: wp
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_par, only: par_rank, par_size, par_wtime, par_allreduce, PAR_SUM, PAR_MAX
   use dx_par_plan, only: par_gather_ordered
   use dx_emc_types, only: emc_system_t
   use dx_emc_contact, only: emc_split_t, emc_slot_range
   implicit none
   private
   public :: par_emc_t, par_emc_setup, par_emc_on, par_emc_report, par_emc_set_together, &
             par_emc_together, par_emc_writer, par_emc_max

   !> The conserving solver's split of the slave points over the ranks, with its counters.
   type, extends(emc_split_t) :: par_emc_t
      logical :: together = .false.      !< a failure every rank found (replicated Newton)
      !> counters: gathers, values sent by this rank, values received, time in the gathers
      integer(8) :: ngath = 0, nsent = 0, nrecv = 0
      real(wp) :: tgath = 0.0_wp
   contains
      procedure :: gather => par_emc_gather
   end type par_emc_t

contains

   !> flags(:) = their maximum over the ranks (in place; no-op without MPI): the collective
   !> stop/dump requests of the replicated conserving run (dx_checkpoint%checkpoint_requests).
   subroutine par_emc_max(flags)
      integer, intent(inout) :: flags(:)
      call par_allreduce(flags, PAR_MAX)
   end subroutine par_emc_max

   !> MPI run of a conserving deck: the slot ownership from the rank's part. nodes, owner:
   !> the rank file's global nodes and their owning ranks (rank_part_t).
   subroutine par_emc_setup(pe, es, nn, nodes, owner)
      type(par_emc_t), intent(inout) :: pe
      type(emc_system_t), intent(in) :: es
      integer, intent(in) :: nn, nodes(:), owner(:)
      logical, allocatable :: owned(:)
      integer :: id, sb, n, i, i1, i2, s, me
      integer, allocatable :: cnt(:)
      character(:), allocatable :: txt
      me = par_rank()
      allocate(owned(nn))
      owned = .false.
      owned(pack(nodes, owner == me)) = .true.
      allocate(pe%base(size(es%defs)))
      n = 0
      do id = 1, size(es%defs)
         pe%base(id) = n + 1
         call emc_slot_range(es, id, i1, i2)
         n = n + (i2 - i1 + 1)
      end do
      allocate(pe%mine(n))
      pe%mine = .false.
      do id = 1, size(es%defs)
         sb = es%defs(id)%sb
         call emc_slot_range(es, id, i1, i2)
         do i = i1, i2
            s = pe%base(id) + (i - i1)
            if (i > 0) then
               pe%mine(s) = owned(es%sn_node(i))
            else if (es%sn_ptr(sb + 1) > es%sn_ptr(sb)) then
               pe%mine(s) = owned(es%sn_node(es%sn_ptr(sb)))   ! the sphere's first surface node
            else
               pe%mine(s) = me == 0
            end if
         end do
      end do
      allocate(cnt(0:par_size() - 1))
      cnt = 0
      cnt(me) = count(pe%mine)
      call par_allreduce(cnt, PAR_SUM)
      pe%on = .true.
      txt = ''
      do i = 0, par_size() - 1
         txt = txt//' '//str(cnt(i))
      end do
      call log_info('dynx: conserving solver on '//str(par_size())//' ranks: '//str(n)// &
                    ' slave points, per rank:'//txt)
   end subroutine par_emc_setup

   !> True in an MPI run (NP > 1) of a conserving deck.
   logical function par_emc_on(pe)
      type(par_emc_t), intent(in) :: pe
      par_emc_on = pe%on
   end function par_emc_on

   !> Every rank's (key, values) in serial order (a stable sort by key: equal keys keep
   !> their rank-local order); counted for the report.
   subroutine par_emc_gather(self, keys, vals, all_keys, all_vals)
      class(par_emc_t), intent(inout) :: self
      integer, intent(in) :: keys(:)
      real(wp), intent(in) :: vals(:, :)
      integer, allocatable, intent(out) :: all_keys(:)
      real(wp), allocatable, intent(out) :: all_vals(:, :)
      real(wp) :: t0
      t0 = par_wtime()
      call par_gather_ordered(keys, vals, all_keys, all_vals)
      self%tgath = self%tgath + (par_wtime() - t0)
      self%ngath = self%ngath + 1
      self%nsent = self%nsent + size(vals) + size(keys)
      self%nrecv = self%nrecv + size(all_vals) + size(all_keys)
   end subroutine par_emc_gather

   !> A failure every rank found at the same step (Newton, on identical data): a clean stop
   !> on every rank with the serial exit code, no MPI_Abort.
   subroutine par_emc_set_together(pe)
      type(par_emc_t), intent(inout) :: pe
      pe%together = .true.
   end subroutine par_emc_set_together

   logical function par_emc_together(pe)
      type(par_emc_t), intent(in) :: pe
      par_emc_together = pe%on .and. pe%together
   end function par_emc_together

   !> This rank writes the output (rank 0 of an MPI run; always in a serial run).
   logical function par_emc_writer(pe)
      type(par_emc_t), intent(in) :: pe
      par_emc_writer = .not. pe%on .or. par_rank() == 0
   end function par_emc_writer

   !> The exchange counters of the run (log, rank 0): per step when nstep > 0.
   subroutine par_emc_report(pe, nstep)
      type(par_emc_t), intent(in) :: pe
      integer, intent(in) :: nstep
      if (.not. pe%on) return
      call log_info('dynx: conserving solver MPI exchange (rank 0): '//str(int(pe%ngath))// &
         ' ordered gathers, '//str(int(pe%nrecv))//' numbers received ('// &
         rstr(real(pe%nrecv, wp)/max(nstep, 1), 5)//' per step, '// &
         rstr(real(pe%ngath, wp)/max(nstep, 1), 5)//' gathers per step), '//str(int(pe%nsent))// &
         ' sent, '//rstr(pe%tgath, 4)//' s in the gathers')
   end subroutine par_emc_report
end module dx_par_emc
