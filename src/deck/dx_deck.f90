!> Entry point of the deck layer: read an LS-DYNA keyword deck into a model ready for the
!> solver. Tokenizes the deck (dx_deck_cards), looks every keyword up in the registry and
!> calls its reader (dx_read_* modules) into the model input; the build stage (src/build/,
!> dx_build) turns that into the model (read then build: dx_deck_model).
!> Supported keywords and fields: docs/keywords.md.
module dx_deck
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_log, only: log_warn, log_info
   use dx_deck_check, only: check_list_t, keyword_family, keyword_skippable
   use dx_deck_cards, only: deck_t, read_cards, data_start
   use dx_deck_registry, only: registry_t
   use dx_read_nodes_elements, only: register_nodes_elements
   use dx_read_shells, only: register_shells
   use dx_read_materials, only: register_materials, unknown_model_hint
   use dx_read_erosion, only: register_erosion
   use dx_read_controls, only: register_controls
   use dx_read_sets, only: register_sets, sets_finish
   use dx_read_loads, only: register_loads, loads_finish
   use dx_read_merge, only: register_merge, merge_finish
   use dx_read_curves, only: register_curves
   use dx_read_rigid, only: register_rigid
   use dx_read_contact, only: register_contact
   use dx_read_restart, only: register_restart
   use dx_read_emc, only: register_emc, emc_finish
   use dx_read_implicit, only: register_implicit
   use dx_read_output, only: register_output
   use dx_read_beams, only: register_beams
   use dx_read_twod, only: register_twod
   use dx_read_case, only: register_case, case_def_t, deck_cases, case_list_text
   use dx_model_input, only: model_input_t, input_init, input_finish
   use dx_card_echo, only: echo_t
   implicit none
   private
   public :: read_deck_input, new_registry

contains

   !> The registry of every keyword dynx reads.
   function new_registry() result(reg)
      type(registry_t) :: reg
      call register_nodes_elements(reg)
      call register_shells(reg)
      call register_beams(reg)
      call register_materials(reg)
      call register_erosion(reg)
      call register_controls(reg)
      call register_sets(reg)
      call register_loads(reg)
      call register_curves(reg)
      call register_rigid(reg)
      call register_contact(reg)
      call register_restart(reg)
      call register_emc(reg)
      call register_implicit(reg)
      call register_output(reg)
      call register_twod(reg)
      call register_case(reg)
      call register_merge(reg)
   end function new_registry

   !> Read the deck at path into the unresolved model input (no build).
   !> An unknown keyword stops the read (with a hint to run --check). ignore_unknown: an
   !> unknown output request or performance control is skipped with a warning (any other
   !> unknown keyword still stops, naming its family). check (--check): the read goes on
   !> past unknown keywords and reader errors and the error lists all of them, grouped by
   !> family (dx_deck_check), with the output requests dynx accepts but does not write.
   !> echo (d3hsp): every keyword block and every field its reader took (dx_card_echo).
   !> case_id: the *CASE to read (its subcases' keywords and those outside any subcase);
   !> a deck with subcases read without one is an error (dynx never merges the cases).
   subroutine read_deck_input(path, inp, error, ignore_unknown, check, echo, case_id)
      character(*), intent(in) :: path
      type(model_input_t), intent(out) :: inp
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: ignore_unknown, check
      type(echo_t), intent(inout), target, optional :: echo
      integer, intent(in), optional :: case_id
      type(case_def_t), allocatable :: cases(:)
      type(deck_t) :: deck
      type(registry_t) :: reg
      type(check_list_t) :: found
      integer :: ib, k
      logical :: ignore, checking
      character(:), allocatable :: where
      ignore = .false.
      if (present(ignore_unknown)) ignore = ignore_unknown
      checking = .false.
      if (present(check)) checking = check
      call input_init(inp)
      k = 0
      if (present(case_id)) k = case_id
      if (k > 0) then
         call deck_cases(path, cases, error)
         if (allocated(error)) return
         ib = findloc(cases%id, k, 1)
         if (ib == 0) then
            if (size(cases) == 0) then
               call set_error(error, path//': --case '//str(k)//': the deck has no *CASE')
            else
               call set_error(error, path//': --case '//str(k)//': the deck has no *CASE '// &
                              'with CASEID '//str(k)//' (cases: '//case_list_text(cases)//')')
            end if
            return
         end if
         call read_cards(path, deck, error, cases(ib)%scids)
      else
         call read_cards(path, deck, error)
      end if
      if (allocated(error)) return
      if (k == 0 .and. deck%has_subcases) then
         do ib = 1, deck%nblocks
            if (deck%blocks(ib)%scid == 0) cycle
            call set_error(error, deck%files(deck%blocks(ib)%ifile)%s//':'// &
               str(deck%blocks(ib)%line)//': *'//deck%blocks(ib)%name//' belongs to *CASE '// &
               'subcase '//str(deck%blocks(ib)%scid)//': a multi-case deck is read one case '// &
               'at a time (bin/dynx runs every case in turn; --case ID runs one)')
            return
         end do
      end if
      deck%check = checking
      if (present(echo)) deck%echo => echo
      reg = new_registry()
      do ib = 1, deck%nblocks
         associate (blk => deck%blocks(ib))
            where = deck%files(blk%ifile)%s//':'//str(blk%line)
            call reg%lookup(blk%name, k, blk%base, blk%opt_title, blk%opt_id)
            if (k == 0) then
               if (checking) then
                  call found%record(blk%name, '*'//blk%name, where)
                  cycle
               end if
               if (ignore .and. keyword_skippable(blk%name)) then
                  call log_warn(where//': unknown '//keyword_family(blk%name)// &
                     ' keyword *'//blk%name//' skipped (--ignore-unknown; it cannot '// &
                     'change the mechanics)')
                  cycle
               end if
               if (ignore) then
                  call set_error(error, where//': unknown keyword *'//blk%name// &
                     unknown_model_hint(blk%name)//': a '// &
                     keyword_family(blk%name)// &
                     ' keyword is not skipped by --ignore-unknown (only output and '// &
                     'performance keywords are: skipping it would change the problem)')
               else
                  call set_error(error, where//': unknown keyword *'//blk%name// &
                     unknown_model_hint(blk%name)// &
                     ' (dynx --check lists every '// &
                     'unsupported keyword and option of the deck at once)')
               end if
               return
            end if
            if (present(echo)) call echo%block(blk%name, blk%ifile, deck%files(blk%ifile)%s, &
                                               blk%line, blk%n)
            call reg%e(k)%read(deck, blk, inp, error)
            ! a blank line standing for the first data card is a card of defaults
            ! (LS-DYNA): read again with it when the block had no data card else (the
            ! reader stopped at the missing card before it read anything)
            if (allocated(error) .and. blk%n < data_start(blk) .and. deck%trailing(ib) > 0) then
               deallocate(error)
               blk%n = min(data_start(blk), blk%n + deck%trailing(ib))
               call reg%e(k)%read(deck, blk, inp, error)
            end if
            if (allocated(error)) then
               if (.not. checking) return
               call add_reader_error(found, blk%name, error%message, where)
               if (allocated(error%more)) call add_more_errors(found, blk%name, error%more, &
                                                               where)
               do k = 1, error%ndrop     ! past MAX_MORE: counted in the keyword's last line
                  call found%record(blk%name, found%more_line(blk%name), where)
               end do
               deallocate(error)
            end if
         end associate
      end do
      do k = 1, size(inp%out_notes)
         if (checking) then
            call found%record('', inp%out_notes(k)%s, inp%out_notes(k)%where)
         else
            call log_info('dynx: note: '//inp%out_notes(k)%where//': '//inp%out_notes(k)%s)
         end if
      end do
      if (checking) then
         if (found%nproblems() > 0) then
            call set_error(error, 'deck check: '//str(found%nproblems())//' unknown '// &
               'keyword(s) or unsupported option(s) in '//path//' (first use, count):'// &
               found%report(), EXIT_INPUT)
            return
         end if
         if (found%n > 0) call log_info('dynx: deck check:'//found%report())
      end if
      call input_finish(inp)
      deallocate(inp%files)
      allocate(inp%files(deck%nfiles))
      do k = 1, deck%nfiles
         inp%files(k)%s = deck%files(k)%s
      end do
      if (allocated(deck%title)) inp%title = deck%title
      call sets_finish(inp, error)
      if (allocated(error)) return
      call merge_finish(inp, error)
      if (allocated(error)) return
      call loads_finish(inp, error)
      if (allocated(error)) return
      call emc_finish(inp, error)
   end subroutine read_deck_input

   !> The further errors of a block (error%more, one per line: every bad field, dx_card's
   !> collect mode) as --check findings, each with its own place.
   subroutine add_more_errors(found, name, more, where0)
      type(check_list_t), intent(inout) :: found
      character(*), intent(in) :: name, more, where0
      integer :: a, k
      a = 1
      do while (a <= len(more))
         k = index(more(a:), new_line('a'))
         if (k == 0) then
            call add_reader_error(found, name, more(a:), where0)
            exit
         end if
         call add_reader_error(found, name, more(a:a + k - 2), where0)
         a = a + k
      end do
   end subroutine add_more_errors

   !> A reader's error as a --check finding: its first line without the file:line:col
   !> prefix (the place is kept apart), so the same problem on many cards counts once.
   subroutine add_reader_error(found, name, msg, where0)
      type(check_list_t), intent(inout) :: found
      character(*), intent(in) :: name, msg, where0
      character(:), allocatable :: first, where
      integer :: k
      k = index(msg, new_line('a'))
      first = msg
      if (k > 0) first = msg(1:k - 1)
      where = where0
      k = index(first, ': *')
      if (k > 0) then
         where = first(1:k - 1)
         first = first(k + 2:)
      end if
      call found%record(name, first, where)
   end subroutine add_reader_error
end module dx_deck
