!> Restart dump and restore of the energy-momentum conserving solver (issue 5, issue 7):
!> the snapshot model%emc%snap that dx_emc_solver copies at every step boundary where a
!> dump or a stop can happen (dx_emc_types, emc_snapshot_t). Per body: centre and its
!> compensated low part, velocity, rotation, body angular velocity; the stored penalty
!> energy and the pairs in penetration with their algorithmic gaps (so the next step
!> carries them exactly); the loop state (time, cycle, next emcstat and plot times, the
!> initial invariants and the drift maxima of the log, Newton counters) and the size of
!> emcstat at the dump. The bodies' geometry, facets and spheres are rebuilt from the deck.
!> With this the continued run does the same floating-point operations as the uninterrupted
!> run: its files are identical (Simo & Wong 1991 integrator, dx_emc_solver; the dump
!> file: dx_restart_file; datasets: docs/output-format.md).
module dx_emc_restart
   use dx_kinds, only: wp
   use dx_error, only: set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_restart_file, only: rs_file_t
   use dx_emc_types, only: emc_system_t, EMC_PAIR_NI, EMC_PAIR_NR
   use dx_append_file, only: dump_bytes
   implicit none
   private
   public :: emc_dump, emc_restore

contains

   !> Write the snapshot (taken by the solver at this step boundary).
   subroutine emc_dump(rs, es)
      type(rs_file_t), intent(inout) :: rs
      type(emc_system_t), intent(in) :: es
      integer :: nact
      associate (s => es%snap)
         call rs%put('emc_nbodies', size(s%xc, 2))
         call rs%put('emc_xc', s%xc)
         call rs%put('emc_xcl', s%xcl)
         call rs%put('emc_v', s%v)
         call rs%put('emc_r', s%r)
         call rs%put('emc_w', s%w)
         nact = 0
         if (allocated(s%act_i)) nact = size(s%act_i, 2)
         call rs%put('emc_nact', nact)
         if (nact > 0) then
            call rs%put('emc_act_i', reshape(s%act_i, [EMC_PAIR_NI*nact]))
            call rs%put('emc_act_r', s%act_r)
         end if
         call rs%put('emc_reals', [s%upen, s%t, s%next_out, s%next_plot, s%e0, s%p0, s%l0, &
                                   s%ps0, s%ls0, s%de, s%dp, s%dl, s%resid, s%ediss])
         call rs%put('emc_ints', [s%cyc, s%itmax, s%ittot, s%ncut, s%iters, s%npair])
         call rs%put('emc_emcstat_bytes', dump_bytes(s%unit_open, s%unit, 0_8))
      end associate
   end subroutine emc_dump

   !> Read the snapshot back (es built from the same deck); marks it valid.
   subroutine emc_restore(rs, es)
      type(rs_file_t), intent(inout) :: rs
      type(emc_system_t), intent(inout) :: es
      integer :: nb, nact, ints(6)
      integer, allocatable :: ai(:)
      real(wp) :: reals(18)
      nb = -1
      nact = 0
      call rs%get('emc_nbodies', nb)
      if (.not. rs%ok()) return
      if (nb /= size(es%sphere)) then
         call set_error(rs%err, 'restart file '//rs%path//': '//str(nb)//' conserving '// &
            'rigid bodies, this deck has '//str(size(es%sphere))//' (a dump of another deck?)', EXIT_INPUT)
         return
      end if
      associate (s => es%snap)
         allocate(s%xc(3, nb), s%xcl(3, nb), s%v(3, nb), s%r(3, 3, nb), s%w(3, nb))
         s%xc = 0.0_wp; s%xcl = 0.0_wp; s%v = 0.0_wp; s%r = 0.0_wp; s%w = 0.0_wp
         call rs%get('emc_xc', s%xc)
         call rs%get('emc_xcl', s%xcl)
         call rs%get('emc_v', s%v)
         call rs%get('emc_r', s%r)
         call rs%get('emc_w', s%w)
         call rs%get('emc_nact', nact)
         if (.not. rs%ok()) return
         if (nact < 0 .or. nact > 100000000) then
            call set_error(rs%err, 'restart file '//rs%path//': emc_nact = '//str(nact)// &
                           ' (the file is damaged)', EXIT_INPUT)
            return
         end if
         allocate(s%act_i(EMC_PAIR_NI, nact), s%act_r(EMC_PAIR_NR, nact), ai(EMC_PAIR_NI*nact))
         ai = 0; s%act_r = 0.0_wp
         if (nact > 0) then
            call rs%get('emc_act_i', ai)
            call rs%get('emc_act_r', s%act_r)
         end if
         s%act_i = reshape(ai, [EMC_PAIR_NI, nact])
         reals = 0.0_wp
         call rs%get('emc_reals', reals)
         s%upen = reals(1); s%t = reals(2); s%next_out = reals(3); s%next_plot = reals(4)
         s%e0 = reals(5); s%p0 = reals(6:8); s%l0 = reals(9:11); s%ps0 = reals(12)
         s%ls0 = reals(13); s%de = reals(14); s%dp = reals(15); s%dl = reals(16)
         s%resid = reals(17); s%ediss = reals(18)
         ints = 0
         call rs%get('emc_ints', ints)
         s%cyc = ints(1); s%itmax = ints(2); s%ittot = ints(3); s%ncut = ints(4)
         s%iters = ints(5); s%npair = ints(6)
         s%emcstat_bytes = 0
         call rs%get('emc_emcstat_bytes', s%emcstat_bytes)
         s%valid = rs%ok()
      end associate
   end subroutine emc_restore
end module dx_emc_restart
