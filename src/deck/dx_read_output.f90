!> Readers for the output requests and the controls whose fields change nothing in dynx's
!> formulation: each keyword is read with its full card layout and its LS-DYNA meaning; a
!> value that would change the results in LS-DYNA and that dynx does not implement is an
!> error naming the field, harmless values are accepted silently, and an output request
!> for a file dynx does not write is accepted with a one-line note naming the file (listed
!> under "output not written" at --check; dx_deck).
!>   *CONTROL_ENERGY HGEN RWEN SLNTEN RYLEN IRGEN MATEN DRLEN DISEN (which energies are
!>     computed and reported; no termination bound)
!>   *CONTROL_ACCURACY OSU INN PIDOSU IACC EXACC
!>   *CONTROL_OUTPUT (5 cards of print and output flags)
!>   *CONTROL_SOLUTION SOLN NLQ ISNAN LCINT LCACC NCDCF NOCOP
!>   *CONTROL_PARALLEL NCPU NUMRHS CONST PARA; *CONTROL_MPP_IO_NODUMP; *CONTROL_UNITS;
!>   *CONTROL_RIGID LMF JNTF ORTHMD PARTM SPARSE METALF PLOTEL RBSMS / NORBIC GJADSTF
!>     GJADVSC TJADSTF TJADVSC RCVLR2D
!>   *KEYWORD_ID (deck labels); *CONTACT_FORCE_TRANSDUCER_PENALTY/_CONSTRAINT (card 1
!>     checked; its rcforc rows are not written: a transducer applies no force)
!>   *DATABASE_EXTENT_BINARY (4 cards), *DATABASE_FORMAT IFORM IBINARY
!>   *DATABASE_<ascii> DT BINARY LCUR IOOPT for the ASCII files dynx does not write
!>     (bndout, jntforc, deforc, nodfor, secforc, rwforc, tprint),
!>     *DATABASE_BINARY_D3THDT, *DATABASE_BINARY_D3PROP
!>   *DATABASE_MATSUM, *DATABASE_SPCFORC, *DATABASE_SLEOUT, *DATABASE_ELOUT (the same card;
!>     ELOUT: + OPTION1-4, extra history variables, not written): written (src/io/
!>     dx_matsum.f90, dx_spcforc.f90, dx_sleout.f90, dx_elout.f90; sleout only with
!>     *CONTACT, elout for the *DATABASE_HISTORY_SOLID elements), *DATABASE_NCFORC (the
!>     same card: dx_ncforc.f90)
!> Layouts, defaults and meanings: LS-DYNA Keyword User's Manual, Vol. I (R13), *CONTROL
!> and *DATABASE chapters.
module dx_read_output
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr, lower
   use dx_deck_cards, only: deck_t, block_t, card_t, deck_cursor, get_text, std_widths, &
                            data_start
   use dx_deck_registry, only: registry_t
   use dx_model_input, only: model_input_t, out_note_t
   implicit none
   private
   public :: register_output, add_out_note

contains

   !> Add the keywords of this module to the registry.
   subroutine register_output(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('CONTROL_ENERGY', read_energy)
      call reg%add('CONTROL_ACCURACY', read_accuracy)
      call reg%add('CONTROL_OUTPUT', read_control_output)
      call reg%add('CONTROL_SOLUTION', read_solution)
      call reg%add('CONTROL_PARALLEL', read_parallel)
      call reg%add('CONTROL_MPP_IO_NODUMP', read_nodump)
      call reg%add('CONTROL_UNITS', read_units)
      call reg%add('CONTROL_RIGID', read_control_rigid)
      call reg%add('DATABASE_EXTENT_BINARY', read_extent_binary)
      call reg%add('DATABASE_FORMAT', read_db_format)
      call reg%add('DATABASE_BINARY_D3THDT', read_d3thdt)
      call reg%add('DATABASE_BINARY_D3PROP', read_d3prop)
      call reg%add('KEYWORD_ID', read_keyword_id)
      call reg%add('CONTACT_FORCE_TRANSDUCER_PENALTY', read_transducer)
      call reg%add('CONTACT_FORCE_TRANSDUCER_CONSTRAINT', read_transducer)
      ! the ASCII databases dynx does not write yet (the file is named after the keyword)
      call reg%add('DATABASE_ELOUT', read_ascii_written)
      call reg%add('DATABASE_SLEOUT', read_ascii_written)
      call reg%add('DATABASE_SPCFORC', read_ascii_written)
      call reg%add('DATABASE_BNDOUT', read_ascii_not_written)
      call reg%add('DATABASE_JNTFORC', read_ascii_not_written)
      call reg%add('DATABASE_DEFORC', read_ascii_not_written)
      call reg%add('DATABASE_NCFORC', read_ascii_written)
      call reg%add('DATABASE_NODFOR', read_ascii_not_written)
      call reg%add('DATABASE_SECFORC', read_ascii_not_written)
      call reg%add('DATABASE_RWFORC', read_ascii_not_written)
      call reg%add('DATABASE_MATSUM', read_ascii_written)
      call reg%add('DATABASE_TPRINT', read_ascii_not_written)
   end subroutine register_output

   !> Note that the request of blk is accepted and not honoured: what (a file name, by
   !> default 'dynx does not write <what>'), why (the reason when given).
   subroutine add_out_note(deck, blk, inp, what, why)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      character(*), intent(in) :: what
      character(*), intent(in), optional :: why
      type(out_note_t) :: n
      if (present(why)) then
         n%s = '*'//blk%name//' '//what//' accepted: '//why
      else
         n%s = '*'//blk%name//' accepted: dynx does not write '//what
      end if
      n%where = deck%files(blk%ifile)%s//':'//str(blk%line)
      inp%out_notes = [inp%out_notes, n]
   end subroutine add_out_note

   !> x as written in a note: an integral value without exponent
   function num(x) result(t)
      real(wp), intent(in) :: x
      character(:), allocatable :: t
      if (x == anint(x) .and. abs(x) < 1.0e9_wp) then
         t = str(nint(x))
      else
         t = rstr(x)
      end if
   end function num

   !> A flag field NAME with allowed values lo..hi (0 = the default); ok otherwise
   subroutine flag(c, name, lo, hi, v)
      type(card_t), intent(inout) :: c
      character(*), intent(in) :: name
      integer, intent(in) :: lo, hi
      integer, intent(out) :: v
      call c%int(name, 0, v)
      if (c%ok() .and. (v < lo .or. v > hi)) call c%fail(name, 'must be '//str(lo)//' to '// &
         str(hi)//', got '//str(v))
   end subroutine flag

   !> HGEN RWEN SLNTEN RYLEN IRGEN MATEN DRLEN DISEN: 1 not computed, 2 computed (0:
   !> default). They choose which energies LS-DYNA computes and reports, not the motion;
   !> dynx computes what glstat lists (docs/output-format.md) whatever the flags say.
   subroutine read_energy(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v, k
      character(len=6), parameter :: names(8) = ['HGEN  ', 'RWEN  ', 'SLNTEN', 'RYLEN ', &
                                                 'IRGEN ', 'MATEN ', 'DRLEN ', 'DISEN ']
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      do k = 1, 8
         call flag(c, trim(names(k)), 0, 2, v)
      end do
      call c%done(error)
   end subroutine read_energy

   !> OSU (second-order objective stress update) INN (invariant node numbering) PIDOSU
   !> IACC (implicit accuracy) EXACC (explicit accuracy). dynx's solids update the stress
   !> with the first-order Jaumann rate and have no orthotropic material, so INN changes
   !> nothing; OSU = 1, a PIDOSU part set, IACC = 1 and EXACC > 0 would change the results
   !> and are errors.
   subroutine read_accuracy(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      real(wp) :: r
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call flag(c, 'OSU', 0, 1, v)
      if (c%ok() .and. v == 1) call c%fail('OSU', 'the second-order objective stress '// &
         'update is not implemented (dynx: first-order Jaumann rate); set OSU = 0')
      call flag(c, 'INN', -4, 4, v)
      call c%int('PIDOSU', 0, v)
      if (c%ok() .and. v /= 0) call c%fail('PIDOSU', 'the second-order objective stress '// &
         'update (on part set '//str(v)//') is not implemented')
      call flag(c, 'IACC', 0, 1, v)
      if (c%ok() .and. v == 1) call c%fail('IACC', 'the implicit accuracy option is not '// &
         'implemented; set IACC = 0')
      call c%real('EXACC', 0.0_wp, r)
      if (c%ok() .and. r /= 0.0_wp) call c%fail('EXACC', 'the explicit accuracy '// &
         'parameter is not implemented; leave it blank or 0')
      call c%done(error)
   end subroutine read_accuracy

   !> Up to 5 cards of print and output flags (NPOPT NEECHO NREFUP IACCOP OPIFS IPNINT
   !> IKEDIT IFLUSH / IPRTF IERODE TET10 MSGMAX IPCURV GMDT IP1DBLT EOCS / TOLEV NEWLEG
   !> FRFREQ MINFO SOLSIG MSGFLG CDETOL / PHSCHNG DEMDEN ICRFILE SPC2BND PENOUT SHLSIG
   !> HISOUT ENGOUT / INSF ISOLSF IBSF ISSF MLKBAG): what d3hsp, messag and the ASCII files
   !> print. None changes the mechanics; the numbers are checked, their values accepted.
   subroutine read_control_output(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: ic, k
      real(wp) :: r
      character(len=8), parameter :: names(8, 5) = reshape([character(len=8) :: &
         'NPOPT', 'NEECHO', 'NREFUP', 'IACCOP', 'OPIFS', 'IPNINT', 'IKEDIT', 'IFLUSH', &
         'IPRTF', 'IERODE', 'TET10', 'MSGMAX', 'IPCURV', 'GMDT', 'IP1DBLT', 'EOCS', &
         'TOLEV', 'NEWLEG', 'FRFREQ', 'MINFO', 'SOLSIG', 'MSGFLG', 'CDETOL', '', &
         'PHSCHNG', 'DEMDEN', 'ICRFILE', 'SPC2BND', 'PENOUT', 'SHLSIG', 'HISOUT', 'ENGOUT', &
         'INSF', 'ISOLSF', 'IBSF', 'ISSF', 'MLKBAG', '', '', ''], [8, 5])
      call deck_cursor(deck, blk, c)
      call c%max_cards(5)
      do ic = 1, 5
         do k = 1, 8
            if (len_trim(names(k, ic)) == 0) exit
            call c%real(trim(names(k, ic)), 0.0_wp, r)
         end do
         call c%next()
      end do
      call c%done(error)
   end subroutine read_control_output

   !> SOLN (0 structural; 1 thermal, 2 coupled: errors) NLQ (vector length) ISNAN (NaN
   !> check) LCINT (points of the curve discretisation: dynx evaluates curves exactly, the
   !> limit of a large LCINT; docs/keywords.md) LCACC (curve truncation to single
   !> precision: error) NCDCF (contact forces per step: only 1) NOCOP.
   subroutine read_solution(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call flag(c, 'SOLN', 0, 2, v)
      if (c%ok() .and. v /= 0) call c%fail('SOLN', 'thermal analysis (SOLN = '//str(v)// &
         ') is not implemented: dynx solves the structural problem only (SOLN = 0)')
      call c%int('NLQ', 0, v, min=0)
      call flag(c, 'ISNAN', 0, 1, v)
      call c%int('LCINT', 0, v, min=0)
      call c%int('LCACC', 0, v)
      if (c%ok() .and. v /= 0) call c%fail('LCACC', 'the truncation of curves to single '// &
         'precision is not implemented; set LCACC = 0')
      call c%int('NCDCF', 0, v)
      if (c%ok() .and. v > 1) call c%fail('NCDCF', 'contact forces are computed once per '// &
         'step (NCDCF = 1); '//str(v)//' is not implemented')
      call c%int('NOCOP', 0, v)
      call c%done(error)
   end subroutine read_solution

   !> NCPU NUMRHS CONST PARA: threads and the consistency flag of shared-memory LS-DYNA.
   !> dynx runs on the MPI ranks mpirun starts, one thread each, and its results are the
   !> same bits for any rank count (CONST = 1 always holds): every value is accepted.
   subroutine read_parallel(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%int('NCPU', 0, v)
      call c%int('NUMRHS', 0, v, min=0)
      call flag(c, 'CONST', 0, 2, v)
      call flag(c, 'PARA', 0, 2, v)
      call c%done(error)
   end subroutine read_parallel

   !> *CONTROL_RIGID, card 1 LMF JNTF ORTHMD PARTM SPARSE METALF PLOTEL RBSMS, card 2
   !> (optional) NORBIC GJADSTF GJADVSC TJADSTF TJADVSC RCVLR2D (written by pydyna; its
   !> meaning is not documented here, so only 0 is accepted). LMF (Lagrange-multiplier joints),
   !> JNTF (generalized joint stiffness update) and the added joint stiffness and damping
   !> GJADSTF..TJADVSC act on *CONSTRAINED_JOINT_* only, which dynx does not read (a deck
   !> with joints stops on them), so they cannot change a dynx run: range-checked and
   !> accepted. ORTHMD, PARTM, SPARSE act on flexible bodies (*PART_MODES), which dynx does
   !> not have: accepted. PLOTEL (plot elements for nodal rigid bodies) is output; RBSMS
   !> acts with selective mass scaling only, which dynx does not have; NORBIC skips LS-DYNA's
   !> rigid-body inertia check (dynx stops on a bad inertia either way): accepted. METALF = 1
   !> (the fast rigid-body update of metal forming, rotations suppressed) would change the
   !> motion of every rigid body and is not implemented: an error naming the field.
   subroutine read_control_rigid(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      real(wp) :: r
      call deck_cursor(deck, blk, c)
      call c%max_cards(2)
      call flag(c, 'LMF', 0, 1, v)
      call flag(c, 'JNTF', 0, 2, v)
      call flag(c, 'ORTHMD', 0, 1, v)
      call flag(c, 'PARTM', 0, 1, v)
      call flag(c, 'SPARSE', 0, 1, v)
      call c%zero_int('METALF', 'the fast rigid-body update for metal forming (rotations '// &
                      'of all rigid bodies suppressed) is not implemented')
      call flag(c, 'PLOTEL', 0, 2, v)
      call flag(c, 'RBSMS', 0, 1, v)
      call c%next()
      call flag(c, 'NORBIC', 0, 1, v)
      call c%real('GJADSTF', 0.0_wp, r, min=0.0_wp)
      call c%real('GJADVSC', 0.0_wp, r, min=0.0_wp)
      call c%real('TJADSTF', 0.0_wp, r, min=0.0_wp)
      call c%real('TJADVSC', 0.0_wp, r, min=0.0_wp)
      call c%zero_int('RCVLR2D', 'this option of later LS-DYNA versions is not implemented')
      call c%done(error)
   end subroutine read_control_rigid

   !> *CONTROL_MPP_IO_NODUMP: no restart dumps in MPP LS-DYNA. dynx writes dumps only when
   !> *DATABASE_BINARY_D3DUMP/RUNRSF asks or a signal stops the run; no cards.
   subroutine read_nodump(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%max_cards(0)
      call c%done(error)
   end subroutine read_nodump

   !> LENGTH TIME MASS TEMP (unit names: m mm cm in ft; sec ms micro-s; kg g mtrc lb slug
   !> lbf*s2/in; k c f r) and the optional card 2 (user factors). LS-DYNA uses them to
   !> convert values between included files and for a few unit-dependent features dynx
   !> does not have; dynx never converts units, so the names are checked and kept out of
   !> the mechanics.
   subroutine read_units(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: w(8), i0
      real(wp) :: r
      character(:), allocatable :: t
      w = std_widths(blk, 8)
      i0 = data_start(blk)
      call deck_cursor(deck, blk, c)
      call c%max_cards(i0 + 1)
      call get_text(deck, blk, i0, 1, w, t)
      if (verify(lower(t), 'abcdefghijklmnopqrstuvwxyz-*/0123456789 ') /= 0) &
         call c%fail_card(i0, 'LENGTH: expected a unit name (m, mm, cm, in, ft), got '''//t//'''')
      call c%next()
      call c%real('LFACTOR', 0.0_wp, r)
      call c%real('TFACTOR', 0.0_wp, r)
      call c%real('MFACTOR', 0.0_wp, r)
      call c%done(error)
   end subroutine read_units

   !> Card 1 NEIPH NEIPS MAXINT STRFLG SIGFLG EPSFLG RLTFLG ENGFLG; card 2 CMPFLG IEVERP
   !> BEAMIP DCOMP SHGE STSSZ N3THDT IALEMAT; card 3 NINTSLD PKP_SEN SCLP HYDRO MSSCL THERM
   !> INTOUT NODOUT; card 4 DTDT RESPLT NEIPB QUADSLD CUBSLD DELERES. These choose what the
   !> d3plot database holds, never the motion. dynx's d3plot.h5 holds the fields of its
   !> plot schema (docs/output-format.md): a non-default value is accepted with a note that
   !> it is not honoured (extra history variables, strains, ...), never silently.
   subroutine read_extent_binary(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: ic, k
      real(wp) :: r
      character(:), allocatable :: nondef
      character(len=8), parameter :: names(8, 4) = reshape([character(len=8) :: &
         'NEIPH', 'NEIPS', 'MAXINT', 'STRFLG', 'SIGFLG', 'EPSFLG', 'RLTFLG', 'ENGFLG', &
         'CMPFLG', 'IEVERP', 'BEAMIP', 'DCOMP', 'SHGE', 'STSSZ', 'N3THDT', 'IALEMAT', &
         'NINTSLD', 'PKP_SEN', 'SCLP', 'HYDRO', 'MSSCL', 'THERM', 'INTOUT', 'NODOUT', &
         'DTDT', 'RESPLT', 'NEIPB', 'QUADSLD', 'CUBSLD', 'DELERES', '', ''], [8, 4])
      ! LS-DYNA's defaults where they are not 0 (a 0 also means the default there)
      real(wp), parameter :: defs(8, 4) = reshape([ &
         0.0_wp, 0.0_wp, 3.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, &
         0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, &
         0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
         0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [8, 4])
      call deck_cursor(deck, blk, c)
      call c%max_cards(4)
      nondef = ''
      do ic = 1, 4
         do k = 1, 8
            if (len_trim(names(k, ic)) == 0) exit
            call c%real(trim(names(k, ic)), 0.0_wp, r)
            if (c%ok() .and. r /= 0.0_wp .and. r /= defs(k, ic)) &
               nondef = nondef//' '//trim(names(k, ic))//'='//num(r)
         end do
         call c%next()
      end do
      call c%done(error)
      if (allocated(error)) return
      if (len(nondef) > 0) call add_out_note(deck, blk, inp, nondef(2:), 'not honoured, '// &
         'd3plot.h5 holds the fields of docs/output-format.md')
   end subroutine read_extent_binary

   !> IFORM (0 LS-DYNA d3plot, 1 ANSYS, 2 both) IBINARY (0 32-bit words, 1 64-bit): dynx
   !> writes d3plot.h5 (HDF5, float64) whatever they say; a request for the ANSYS format is
   !> noted as not written.
   subroutine read_db_format(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: iform, ibin
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call flag(c, 'IFORM', 0, 2, iform)
      call flag(c, 'IBINARY', 0, 1, ibin)
      call c%done(error)
      if (allocated(error)) return
      if (iform > 0) call add_out_note(deck, blk, inp, 'IFORM='//str(iform), 'dynx does '// &
                                       'not write the ANSYS result file (only d3plot.h5)')
   end subroutine read_db_format

   !> *DATABASE_<file>: DT BINARY LCUR IOOPT. DT = 0
   !> and LCUR = 0: no output (nothing to note); else the file is noted as not written.
   subroutine read_ascii_not_written(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: binary, lcur, ioopt
      real(wp) :: dt
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%real('DT', 0.0_wp, dt, min=0.0_wp)
      call flag(c, 'BINARY', 0, 3, binary)
      call c%int('LCUR', 0, lcur, min=0)
      call flag(c, 'IOOPT', 0, 3, ioopt)
      call c%done(error)
      if (allocated(error)) return
      if (dt > 0.0_wp .or. lcur > 0) call add_out_note(deck, blk, inp, lower(blk%name(10:)))
   end subroutine read_ascii_not_written

   !> *DATABASE_<file> for the ASCII files dynx writes (matsum, spcforc, sleout): DT BINARY LCUR IOOPT, the
   !> same card. DT > 0: the file at that interval; LCUR (an output-interval curve) is not
   !> honoured: with DT > 0 a note says DT is used, with DT = 0 the file is noted as not
   !> written. BINARY = 2 (binout only) still gets the ASCII file (dynx writes no binout).
   subroutine read_ascii_written(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: binary, lcur, ioopt, k, opt(4)
      real(wp) :: dt
      character(:), allocatable :: file
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%real('DT', 0.0_wp, dt, min=0.0_wp)
      call flag(c, 'BINARY', 0, 3, binary)
      call c%int('LCUR', 0, lcur, min=0)
      call flag(c, 'IOOPT', 0, 3, ioopt)
      opt = 0
      if (blk%name == 'DATABASE_ELOUT') then   ! extra history variables per element kind
         do k = 1, 4
            call c%int('OPTION'//str(k), 0, opt(k), min=0)
         end do
      end if
      call c%done(error)
      if (allocated(error)) return
      file = lower(blk%name(10:))
      if (any(opt > 0)) call add_out_note(deck, blk, inp, 'OPTION1-4', 'the extra '// &
         'history variables are not written (elout has the stresses and the effective '// &
         'plastic strain)')
      if (lcur > 0 .and. dt > 0.0_wp) then
         call add_out_note(deck, blk, inp, file, 'written every DT = '//num(dt)// &
                           '; the output-interval curve LCUR '//str(lcur)//' is not honoured')
      else if (lcur > 0) then
         call add_out_note(deck, blk, inp, file, 'not written: output-interval curves '// &
                           '(LCUR) are not supported; give DT')
      end if
      select case (file)
      case ('matsum')
         inp%matsum_dt = dt
      case ('spcforc')
         inp%spcforc_dt = dt
      case ('sleout')
         inp%sleout_dt = dt
      case ('elout')
         inp%elout_dt = dt
      case ('ncforc')
         inp%ncforc_dt = dt
      end select
   end subroutine read_ascii_written

   !> *DATABASE_BINARY_D3THDT: DT LCDT BEAM NPLTC PSETID (time history binary database):
   !> dynx writes its histories as ASCII glstat and nodout; d3thdt is noted as not written.
   subroutine read_d3thdt(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      real(wp) :: dt
      integer :: lcdt, v
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%real('DT', 0.0_wp, dt, min=0.0_wp)
      call c%int('LCDT', 0, lcdt, min=0)
      call c%int('BEAM', 0, v)
      call c%int('NPLTC', 0, v, min=0)
      call c%int('PSETID', 0, v, min=0)
      call c%done(error)
      if (allocated(error)) return
      if (dt > 0.0_wp .or. lcdt > 0) call add_out_note(deck, blk, inp, 'd3thdt')
   end subroutine read_d3thdt

   !> *CONTACT_FORCE_TRANSDUCER_PENALTY / _CONSTRAINT: card 1 SURFA SURFB SURFATYP SURFBTYP
   !> SABOXID SBBOXID SAPR SBPR, cards 2-3 the common contact cards (unused by a
   !> transducer). A transducer applies no force: it sums the forces the other contacts
   !> put on its surface into LS-DYNA's rcforc, so it cannot change the mechanics; dynx
   !> checks card 1 and notes that its rcforc rows are not written.
   subroutine read_transducer(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: ssid, styp, v
      call deck_cursor(deck, blk, c)
      call c%max_cards(data_start(blk) + 2)
      call c%need(1, 'missing card 1 (SURFA SURFB SURFATYP SURFBTYP ...)')
      call c%int('SURFA', 0, ssid, min=0)
      call c%int('SURFB', 0, v, min=0)
      call c%int('SURFATYP', 0, styp, min=0, max=6)
      call c%int('SURFBTYP', 0, v, min=0, max=6)
      call c%int('SABOXID', 0, v)
      call c%int('SBBOXID', 0, v)
      call c%int('SAPR', 0, v, min=0, max=2)
      call c%int('SBPR', 0, v, min=0, max=2)
      if (c%ok() .and. ssid == 0) call c%fail('SURFA', 'a force transducer needs the '// &
                                              'surface it measures (SURFA > 0)')
      call c%done(error)
      if (allocated(error)) return
      call add_out_note(deck, blk, inp, 'rcforc rows', 'not written (a transducer '// &
         'measures the other contacts'' forces on its surface and applies none: the '// &
         'mechanics are unchanged)')
   end subroutine read_transducer

   !> *DATABASE_BINARY_D3PROP: IFILE IMATL IWALL (material and wall properties written to
   !> d3prop or to the d3plot files): dynx's d3plot.h5 holds the parts; d3prop is noted as
   !> not written.
   subroutine read_d3prop(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      integer :: v
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call flag(c, 'IFILE', 0, 2, v)
      call flag(c, 'IMATL', 0, 1, v)
      call flag(c, 'IWALL', 0, 1, v)
      call c%done(error)
      if (allocated(error)) return
      call add_out_note(deck, blk, inp, 'd3prop')
   end subroutine read_d3prop
   !> *KEYWORD_ID: card 1 PROJECT NUM STAGE (labels of the deck, LS-DYNA R12+): a name
   !> for the model, nothing the analysis uses; at most one card.
   subroutine read_keyword_id(deck, blk, inp, error)
      type(deck_t), intent(in) :: deck
      type(block_t), intent(in) :: blk
      type(model_input_t), intent(inout) :: inp
      type(error_t), allocatable, intent(out) :: error
      type(card_t) :: c
      call deck_cursor(deck, blk, c)
      call c%max_cards(1)
      call c%done(error)
   end subroutine read_keyword_id
end module dx_read_output
