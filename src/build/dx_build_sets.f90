!> Model build, sets and controls: node, part and segment sets by label, the controls and
!> output requests of the run (history nodes, output intervals, the termination checks, the
!> mass-scaling guards). Called by dx_model_build after the elements and point masses.
!> No keyword of its own; no paper.
module dx_build_sets
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_model, only: model_t
   use dx_log, only: log_warn
   use dx_model_input, only: model_input_t, origin_t
   use dx_build_twod, only: part_dim
   use dx_label_map, only: label_map_t
   use dx_build_common, only: maps_t, at, set_nodes, curve_index, node_index, dense_segments, &
                              map_labels, hist_solids, hist_nodes
   implicit none
   private
   public :: build_sets, build_controls

contains

   !> node, part and segment sets
   subroutine build_sets(inp, model, mp, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(inout) :: mp
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      integer, allocatable :: lab(:)
      type(origin_t), allocatable :: src(:)
      src = [(inp%node_sets(i)%src, i = 1, size(inp%node_sets))]
      lab = inp%node_sets(:)%label
      call map_labels(inp, mp%nset, lab, src, 'node set', error)
      if (allocated(error)) return
      allocate(model%node_sets(size(inp%node_sets)))
      do i = 1, size(inp%node_sets)
         model%node_sets(i)%label = inp%node_sets(i)%label
         call dense_ids(inp, inp%node_sets(i)%src, inp%node_sets(i)%label, inp%node_sets(i)%ids, &
                        mp%node, 'node', 'NODE', model%node_sets(i)%nodes, error)
         if (allocated(error)) return
      end do
      src = [(inp%part_sets(i)%src, i = 1, size(inp%part_sets))]
      lab = inp%part_sets(:)%label
      call map_labels(inp, mp%pset, lab, src, 'part set', error)
      if (allocated(error)) return
      allocate(model%part_sets(size(inp%part_sets)))
      do i = 1, size(inp%part_sets)
         model%part_sets(i)%label = inp%part_sets(i)%label
         call dense_ids(inp, inp%part_sets(i)%src, inp%part_sets(i)%label, inp%part_sets(i)%ids, &
                        mp%part, 'part', 'PART', model%part_sets(i)%parts, error)
         if (allocated(error)) return
      end do
      src = [(inp%segment_sets(i)%src, i = 1, size(inp%segment_sets))]
      lab = inp%segment_sets(:)%label
      call map_labels(inp, mp%sset, lab, src, 'segment set', error)
      if (allocated(error)) return
      allocate(model%segment_sets(size(inp%segment_sets)))
      do i = 1, size(inp%segment_sets)
         associate (s => inp%segment_sets(i))
            model%segment_sets(i)%label = s%label
            call dense_segments(inp, mp, s%seg, s%src, model%segment_sets(i)%seg, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine build_sets

   !> The dense indices (idmap) of the labels ids of set label (read at src); a label idmap
   !> does not hold is an error naming the set, the what ('node', 'part') and its keyword.
   subroutine dense_ids(inp, src, label, ids, idmap, what, key, dense, error)
      type(model_input_t), intent(in) :: inp
      type(origin_t), intent(in) :: src
      integer, intent(in) :: label, ids(:)
      type(label_map_t), intent(in) :: idmap
      character(*), intent(in) :: what, key
      integer, allocatable, intent(out) :: dense(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      allocate(dense(size(ids)))
      do k = 1, size(ids)
         dense(k) = idmap%get(ids(k))
         if (dense(k) == 0) then
            call set_error(error, at(inp, src)//'set '//str(label)//': '//what//' '// &
                           str(ids(k))//' is not defined (*'//key//')')
            return
         end if
      end do
   end subroutine dense_ids


   !> controls and output requests; the run must end
   subroutine build_controls(inp, model, mp, deck0, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(maps_t), intent(in) :: mp
      character(*), intent(in) :: deck0
      type(error_t), allocatable, intent(out) :: error
      model%ctrl = inp%ctrl
      model%ctrl%lctm = 0
      if (inp%lctm /= 0) then
         model%ctrl%lctm = curve_index(inp, mp, inp%lctm, inp%timestep_src, 'LCTM', error)
         if (allocated(error)) return
      end if
      model%db%d3plot_dt = inp%d3plot_dt
      if (inp%d3plot_npltc > 0 .and. inp%ctrl%endtim > 0.0_wp) &
         model%db%d3plot_dt = inp%ctrl%endtim/inp%d3plot_npltc
      model%db%d3plot_lcdt = 0
      if (inp%d3plot_lcdt /= 0) then
         model%db%d3plot_lcdt = curve_index(inp, mp, inp%d3plot_lcdt, inp%d3plot_src, 'LCDT', &
                                            error)
         if (allocated(error)) return
      end if
      model%db%glstat_dt = inp%glstat_dt
      model%db%nodout_dt = inp%nodout_dt
      model%db%matsum_dt = inp%matsum_dt
      model%db%spcforc_dt = inp%spcforc_dt
      model%db%sleout_dt = inp%sleout_dt
      model%db%elout_dt = inp%elout_dt
      model%db%ncforc_dt = inp%ncforc_dt
      call hist_solids(inp, model, mp, error)
      if (allocated(error)) return
      model%rst = inp%rst
      call hist_nodes(inp, model, mp, error)
      if (allocated(error)) return
      if (.not. inp%has_termination) then
         call set_error(error, deck0//': no *CONTROL_TERMINATION: the run would not end '// &
                        '(give ENDTIM > 0 or ENDCYC > 0)')
         return
      end if
      ! (an eigenvalue run, *CONTROL_IMPLICIT_EIGENVALUE, ends after its NEIG modes)
      if (.not. (inp%ctrl%endtim > 0.0_wp) .and. inp%ctrl%endcyc <= 0 .and. &
          .not. (inp%ctrl%imp%neig > 0 .and. inp%ctrl%imp%imflag == 1)) then
         call set_error(error, at(inp, inp%term_src)//'ENDTIM <= 0 and ENDCYC <= 0: the run '// &
                        'would not end')
      end if
      if (allocated(error)) return
      ! ENDMAS acts only with mass scaling (DT2MS); 0 and LS-PrePost's default 1e8 are quiet
      if (inp%ctrl%dt2ms == 0.0_wp .and. inp%ctrl%endmas /= 0.0_wp .and. &
          inp%ctrl%endmas /= 1.0e8_wp) call log_warn(inp%files(inp%term_src%ifile)%s//':'// &
         str(inp%term_src%line)//': *CONTROL_TERMINATION ENDMAS = '//rstr(inp%ctrl%endmas)// &
         ' has no effect: it limits the mass added by mass scaling, and the deck has none '// &
         '(*CONTROL_TIMESTEP DT2MS = 0)')
      ! the conserving rigid-body integrator has no element step to scale
      if (inp%ctrl%dt2ms /= 0.0_wp .and. (allocated(inp%emc%contacts) .or. &
                                          allocated(inp%emc%spheres))) &
         call set_error(error, at(inp, inp%timestep_src)//'field DT2MS: mass scaling (DT2MS = '// &
            rstr(inp%ctrl%dt2ms)//') is not available with the conserving rigid-body '// &
            'integrator (*DYNX_CONSERVING_CONTACT); set DT2MS = 0')
      ! shells: the rotary inertia is lumped once from the unscaled mass (not yet rescaled)
      ! (the 2D solids of *SECTION_SHELL ELFORM 13-15 have no rotations: part_dim > 0)
      if (.not. allocated(error) .and. inp%ctrl%dt2ms /= 0.0_wp .and. allocated(inp%elem_thk) &
          .and. part_dim(model, 1) == 0) &
         call set_error(error, at(inp, inp%timestep_src)//'field DT2MS: mass scaling (DT2MS = '// &
            rstr(inp%ctrl%dt2ms)//') is not yet available for decks with shells '// &
            '(*ELEMENT_SHELL): their rotary inertia would not be scaled; set DT2MS = 0')
   end subroutine build_controls
end module dx_build_sets
