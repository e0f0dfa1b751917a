!> Mass scaling of the explicit step: *CONTROL_TIMESTEP DT2MS and MS1ST, *CONTROL_TERMINATION
!> ENDMAS, with their LS-DYNA meaning (LS-DYNA Keyword User's Manual Vol. I, *CONTROL_TIMESTEP
!> and *CONTROL_TERMINATION; the LSTC/Ansys support note "Mass scaling",
!> lsdyna.ansys.com/mass-scaling and ftp.lstc.com/anonymous/outgoing/support/FAQ/mass_scaling;
!> "Overview of mass-scaling in LS-DYNA", d3view blog, 2006; glstat lines: LS-DYNA l2a):
!>  - DT2MS < 0: TSSFAC*|DT2MS| is the smallest step. An element whose step dt_e is below
!>    |DT2MS| gets just the mass that lifts it to |DT2MS|; its step goes as sqrt(mass) (the
!>    wave speed as 1/sqrt(rho)), so dm_e = m_e ((|DT2MS|/dt_e)**2 - 1), m_e = rho V0. Other
!>    elements keep their mass; the run's step is TSSFAC*|DT2MS| while some element needs
!>    mass, its natural step otherwise.
!>  - DT2MS > 0: every element is brought to DT2MS at the first cycle, mass added where
!>    dt_e < DT2MS and removed where dt_e > DT2MS (d3view: LS-DYNA "removes" mass from
!>    elements above it), so the run starts at TSSFAC*DT2MS.
!>  - Scaling is checked every cycle (MS1ST = 0) or at the first cycle only (MS1ST = 1). Mass
!>    once added stays (an element's added mass never decreases), as LS-DYNA's glstat shows
!>    it: a non-decreasing curve. An element's step with its added mass is
!>    dt_e sqrt(1 + dm_e/m_e).
!>  - Rigid parts are never scaled (their blocks are not in the element pass).
!>  - ENDMAS: the run ends (normal termination, as LS-DYNA) at the cycle where the added mass
!>    passes ENDMAS percent of the model's mass, naming the nodes with the most added mass
!>    (LS-DYNA prints up to 20). A warning (once) when the mass has changed by more than 5
!>    percent (the usual limit, d3view ibid.; a removal under DT2MS > 0 counts too).
!> The added mass is the element's (model%added_mass, by dense global element: per-part sums
!> for matsum read it there); the nodal mass is the lumped mass of rho V0 + dm_e per
!> element, spread with the family's mass share and summed element-major from zero, as
!> init_state lumps it, so the scaled nodal mass does not depend on when mass was added (a
!> restart rebuilds it bit for bit from the dumped added_mass).
!> glstat: "added mass" and "percentage increase" (LS-DYNA's l2a: added_mass,
!> percent_increase), 100*added/model mass (rigid bodies included, as LS-DYNA).
module dx_mass_scaling
   use dx_kinds, only: wp, huge_wp
   use dx_strings, only: str, rstr
   use dx_log, only: log_info, log_warn
   use dx_model, only: model_t, family_t, element_family
   use dx_element, only: block_result_t
   implicit none
   private
   public :: mass_scaling_on, lump_mass, ms_init, ms_block, ms_added_total, ms_log_start, &
             ms_percent, ms_endmas_report, MS_WARN_PERCENT

   !> the warning threshold of the mass increase, percent
   real(wp), parameter :: MS_WARN_PERCENT = 5.0_wp

contains

   !> The deck asks for mass scaling (DT2MS /= 0).
   pure logical function mass_scaling_on(model)
      type(model_t), intent(in) :: model
      mass_scaling_on = model%ctrl%dt2ms /= 0.0_wp
   end function mass_scaling_on

   !> The lumped nodal mass into model%mass: rho V0 (+ the element's added mass, when mass
   !> scaling is on) times the family's share per node, summed element-major from zero.
   subroutine lump_mass(model)
      type(model_t), intent(inout) :: model
      integer :: b, i, k
      real(wp) :: rho, me
      type(family_t) :: fam
      logical :: added
      added = allocated(model%added_mass)
      model%mass = 0.0_wp
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            rho = model%mats(model%parts(blk%ipart)%imat)%m%ro
            fam = element_family(blk%etype)   ! rho V0 times the family's share per node
            do i = 1, blk%nel
               me = rho*blk%vol0(i)
               if (added) me = me + model%added_mass(blk%elem(i))
               do k = 1, fam%nen
                  model%mass(blk%conn(k, i)) = model%mass(blk%conn(k, i)) + me*fam%mass_share
               end do
            end do
         end associate
      end do
      ! *ELEMENT_MASS, *ELEMENT_INERTIA, beams' NSM (dx_beam_build)
      if (allocated(model%node_mass)) model%mass = model%mass + model%node_mass
   end subroutine lump_mass

   !> With mass scaling: the elements' added mass (zero; a restart restores it).
   subroutine ms_init(model)
      type(model_t), intent(inout) :: model
      if (.not. mass_scaling_on(model)) return
      if (allocated(model%added_mass)) deallocate(model%added_mass)
      allocate(model%added_mass(model%ne))
      model%added_mass = 0.0_wp
   end subroutine ms_init

   !> The log line of the scaling in force (and its target step).
   subroutine ms_log_start(model)
      type(model_t), intent(in) :: model
      real(wp) :: d
      character(:), allocatable :: when
      if (.not. mass_scaling_on(model)) return
      d = abs(model%ctrl%dt2ms)
      when = 'every cycle'
      if (model%ctrl%ms1st == 1) when = 'at the first cycle only (MS1ST = 1)'
      if (model%ctrl%dt2ms < 0.0_wp) then
         call log_info('dynx: mass scaling DT2MS = '//rstr(model%ctrl%dt2ms)//': elements '// &
            'whose step is below '//rstr(d)//' get the mass that lifts it there ('//when// &
            '): no element limits the step below TSSFAC*|DT2MS| = '// &
            rstr(model%ctrl%tssfac*d)//' (contact and LCTM still may)')
      else
         call log_info('dynx: mass scaling DT2MS = '//rstr(model%ctrl%dt2ms)//': every '// &
            'element''s mass is set for a step of '//rstr(d)//' at the first cycle (mass '// &
            'added or removed), then added where needed ('//when//'); the elements'' step '// &
            'TSSFAC*DT2MS = '//rstr(model%ctrl%tssfac*d)//' (contact and LCTM still may limit it)')
      end if
      if (model%ctrl%endmas > 0.0_wp .and. model%ctrl%endmas /= 1.0e8_wp) &
         call log_info('dynx: ENDMAS = '//rstr(model%ctrl%endmas)//' %: the run ends when '// &
                       'the added mass passes it')
      call log_info('dynx: a warning when mass scaling changes the model''s mass by more '// &
                    'than '//rstr(MS_WARN_PERCENT, 3)//' %')
   end subroutine ms_log_start

   !> After the element pass of block b (res: its elements' steps dte): the added mass the
   !> elements need (changed: some element's added mass changed), and the block's smallest
   !> step with the added masses in res%dt, res%imin.
   subroutine ms_block(model, b, res, changed)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: b
      type(block_result_t), intent(inout) :: res
      logical, intent(inout) :: changed
      real(wp) :: tgt, rho, me, need, dte, eff
      integer :: i, e
      logical :: scale, first
      first = model%cycle == 0
      scale = first .or. model%ctrl%ms1st == 0
      tgt = abs(model%ctrl%dt2ms)
      res%dt = huge_wp
      res%imin = 0
      associate (blk => model%blocks(b))
         rho = model%mats(model%parts(blk%ipart)%imat)%m%ro
         do i = 1, blk%nel
            dte = res%dte(i)
            if (dte >= huge_wp) cycle            ! eroded
            e = blk%elem(i)
            me = rho*blk%vol0(i)
            if (scale .and. me > 0.0_wp) then
               need = me*((tgt/dte)**2 - 1.0_wp)
               if (first .and. model%ctrl%dt2ms > 0.0_wp) then
                  if (need /= model%added_mass(e)) then     ! DT2MS > 0: add or remove
                     model%added_mass(e) = need
                     changed = .true.
                  end if
               else if (need > model%added_mass(e)) then    ! only ever added
                  model%added_mass(e) = need
                  changed = .true.
               end if
            end if
            eff = dte
            if (me > 0.0_wp .and. model%added_mass(e) /= 0.0_wp) &
               eff = dte*sqrt((me + model%added_mass(e))/me)
            if (eff < res%dt) then
               res%dt = eff; res%imin = i
            end if
         end do
      end associate
   end subroutine ms_block

   !> The added mass of the whole model (elements in dense order).
   pure real(wp) function ms_added_total(model) result(s)
      type(model_t), intent(in) :: model
      integer :: e
      s = 0.0_wp
      if (.not. allocated(model%added_mass)) return
      do e = 1, size(model%added_mass)
         s = s + model%added_mass(e)
      end do
   end function ms_added_total

   !> The increase of the model's mass by mass scaling, percent.
   pure real(wp) function ms_percent(model) result(p)
      type(model_t), intent(in) :: model
      p = 0.0_wp
      if (model%energy%mass > 0.0_wp) p = 100.0_wp*model%energy%added_mass/model%energy%mass
   end function ms_percent

   !> The ENDMAS stop: the message, with the (up to 20) nodes that got the most mass.
   subroutine ms_endmas_report(model)
      type(model_t), intent(in) :: model
      real(wp), allocatable :: madd(:)
      integer :: b, i, k, n, j, best
      type(family_t) :: fam
      logical, allocatable :: taken(:)
      character(:), allocatable :: line
      allocate(madd(size(model%mass)), taken(size(model%mass)))
      madd = 0.0_wp
      taken = .false.
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            fam = element_family(blk%etype)
            do i = 1, blk%nel
               do k = 1, fam%nen
                  madd(blk%conn(k, i)) = madd(blk%conn(k, i)) + &
                                         model%added_mass(blk%elem(i))*fam%mass_share
               end do
            end do
         end associate
      end do
      call log_info('dynx: ENDMAS reached: the added mass '// &
         rstr(model%energy%added_mass)//' is '//rstr(ms_percent(model), 6)// &
         ' % of the model''s mass '//rstr(model%energy%mass)//' (ENDMAS = '// &
         rstr(model%ctrl%endmas)//' %) at cycle '//str(model%cycle)//', time '//rstr(model%time))
      line = 'dynx: nodes with the most added mass (node: added mass):'
      n = min(20, count(madd > 0.0_wp))
      do j = 1, n
         best = 0
         do i = 1, size(madd)
            if (taken(i) .or. i > size(model%node_label)) cycle
            if (best == 0) then
               best = i
            else if (madd(i) > madd(best)) then
               best = i
            end if
         end do
         if (best == 0) exit
         taken(best) = .true.
         line = line//' '//str(model%node_label(best))//': '//rstr(madd(best))//';'
      end do
      call log_info(line)
   end subroutine ms_endmas_report
end module dx_mass_scaling
