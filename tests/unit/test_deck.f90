!> Unit tests of the deck reader (dx_deck, dx_deck_cards, dx_read_*) and the model build.
!> Writes small decks into a scratch directory ($TMPDIR or /tmp) and reads them back.
program test_deck
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_INPUT
   use dx_assert, only: check, check_close, assert_summary
   use dx_log, only: log_set_quiet
   use dx_model, only: model_t, ES_HGS
   use dx_element_types, only: ETYPE_HEX8_1PT, ETYPE_HEX8_SRI
   use dx_model_input, only: model_input_t, spc_in_t
   use dx_deck_buffers, only: spc_buffer_t
   use dx_deck, only: read_deck_input
   use dx_deck_model, only: read_deck
   use dx_deck_check, only: keyword_family, keyword_skippable
   use dx_mat_elastic, only: mat_elastic_t
   use dx_mat_piecewise_linear, only: mat_piecewise_linear_t
   implicit none
   character(:), allocatable :: dir
   character, parameter :: nl = new_line('a')

   call setup_dir()
   call test_fixed_fields()
   call test_long_format()
   call test_parameters()
   call test_include()
   call test_field_errors()
   call test_unknown_keyword()
   call test_families()
   call test_reader_defects()
   call test_generated_sets()
   call test_parameter_expression()
   call test_full_deck()
   call test_blocks()
   call test_materials()
   call test_build_errors()
   call test_record_buffer()
   call assert_summary()

contains

   subroutine setup_dir()
      character(512) :: t
      integer :: n, st
      call get_environment_variable('TMPDIR', t, n, st)
      if (st /= 0 .or. n == 0) t = '/tmp'
      dir = trim(t)//'/dx_test_deck'
      call execute_command_line('mkdir -p '//dir//'/sub', exitstat=st)
      call check(st == 0, 'scratch directory')
   end subroutine setup_dir

   subroutine write_file(name, text)
      character(*), intent(in) :: name, text
      integer :: u
      open(newunit=u, file=dir//'/'//name, status='replace', access='stream', &
           form='unformatted')
      write(u) text//nl
      close(u)
   end subroutine write_file

   !> substring test printing the message when it fails
   subroutine check_has(msg, sub, name)
      character(*), intent(in) :: msg, sub, name
      call check(index(msg, sub) > 0, name)
      if (index(msg, sub) == 0) print '(a)', '    message was: '//msg
   end subroutine check_has

   subroutine test_fixed_fields()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('fixed.k', '*KEYWORD'//nl// &
         '$ a comment'//nl// &
         '*control_termination'//nl// &
         '$   ENDTIM    ENDCYC'//nl// &
         '     0.002       100'//nl// &
         '*CONTROL_TIMESTEP'//nl// &
         '              0.67'//nl// &
         '*CONTROL_BULK_VISCOSITY'//nl// &
         '1.2,,'//nl// &
         '*NODE'//nl// &
         '       1             1.5             2.5            -3.5'//nl// &
         '       2,4.0, 5.0 ,6.0'//nl// &
         '*END'//nl// &
         '*NODE'//nl// &
         '       3             1.5             2.5             3.5')
      call read_deck_input(dir//'/fixed.k', inp, err)
      call check(.not. allocated(err), 'fixed: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check_close(inp%ctrl%endtim, 0.002_wp, 0.0_wp, 1e-14_wp, 'fixed: ENDTIM')
      call check(inp%ctrl%endcyc == 100, 'fixed: ENDCYC (lower-case keyword)')
      call check_close(inp%ctrl%dtinit, 0.0_wp, 0.0_wp, 0.0_wp, 'fixed: blank DTINIT = 0')
      call check_close(inp%ctrl%tssfac, 0.67_wp, 0.0_wp, 1e-14_wp, 'fixed: TSSFAC')
      call check_close(inp%ctrl%q1, 1.2_wp, 0.0_wp, 1e-14_wp, 'comma: Q1')
      call check_close(inp%ctrl%q2, 0.06_wp, 0.0_wp, 1e-14_wp, 'comma: blank Q2 default')
      call check(inp%nn == 2, 'fixed: *END stops reading')
      call check_close(inp%x(3, 1), -3.5_wp, 0.0_wp, 0.0_wp, 'fixed: node z (e16)')
      call check_close(inp%x(2, 2), 5.0_wp, 0.0_wp, 0.0_wp, 'comma: node y')
   end subroutine test_fixed_fields

   subroutine test_long_format()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('long.k', '*KEYWORD LONG=Y'//nl// &
         '*CONTROL_TERMINATION'//nl// &
         '               0.005                  50'//nl// &
         '*NODE'//nl// &
         '                   7                 1.5                 2.5                 3.5')
      call read_deck_input(dir//'/long.k', inp, err)
      call check(.not. allocated(err), 'long: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check_close(inp%ctrl%endtim, 0.005_wp, 0.0_wp, 1e-14_wp, 'long: ENDTIM')
      call check(inp%ctrl%endcyc == 50, 'long: ENDCYC')
      call check(inp%node_label(1) == 7, 'long: node id i20')
      call check_close(inp%x(3, 1), 3.5_wp, 0.0_wp, 0.0_wp, 'long: node z e20')
      call write_file('plus.k', '*KEYWORD'//nl// &
         '*NODE +'//nl// &
         '                   7                 1.5                 2.5                 3.5'// &
         nl//'*NODE'//nl// &
         '       8             1.5             2.5             4.5'//nl// &
         '*CONTROL_TERMINATION +'//nl// &
         '               0.005')
      call read_deck_input(dir//'/plus.k', inp, err)
      call check(.not. allocated(err), 'plus: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check(inp%nn == 2 .and. inp%node_label(1) == 7, 'plus: *NODE + long')
      call check_close(inp%x(3, 2), 4.5_wp, 0.0_wp, 0.0_wp, 'plus: next *NODE standard')
      call check_close(inp%ctrl%endtim, 0.005_wp, 0.0_wp, 1e-14_wp, 'plus: control long')
   end subroutine test_long_format

   subroutine test_parameters()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('param.k', '*KEYWORD'//nl// &
         '*PARAMETER'//nl// &
         'R     tend     0.004I    ncyc       200'//nl// &
         '*CONTROL_TERMINATION'//nl// &
         '     &tend     &NCYC    -&tend'//nl// &
         '*CONTROL_TIMESTEP'//nl// &
         '&tend,&tend')
      call read_deck_input(dir//'/param.k', inp, err)
      call check(.not. allocated(err), 'param: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check_close(inp%ctrl%endtim, 0.004_wp, 0.0_wp, 1e-14_wp, 'param: &tend')
      call check(inp%ctrl%endcyc == 200, 'param: &ncyc (integer)')
      call check_close(inp%ctrl%dtmin, -0.004_wp, 0.0_wp, 1e-14_wp, 'param: -&tend')
      call check_close(inp%ctrl%tssfac, 0.004_wp, 0.0_wp, 1e-14_wp, 'param: comma &tend')
      call write_file('param2.k', '*KEYWORD'//nl//'*CONTROL_TERMINATION'//nl//'&nothere')
      call read_deck_input(dir//'/param2.k', inp, err)
      call check(allocated(err), 'param: undefined parameter is an error')
      if (allocated(err)) call check_has(err%message, 'param2.k:3:1: *CONTROL_TERMINATION: '// &
         'field ENDTIM: parameter ''NOTHERE'' is not defined', 'param: undefined message')
   end subroutine test_parameters

   subroutine test_include()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('main.k', '*KEYWORD'//nl//'*INCLUDE'//nl//'sub/a.k'//nl// &
                      '*CONTROL_HOURGLASS'//nl//'4,0.05'//nl//'*END')
      call write_file('sub/a.k', '*INCLUDE'//nl//'b.k'//nl//'*CONTROL_TERMINATION'//nl// &
                      '0.01'//nl//'*END'//nl//'*CONTROL_TERMINATION'//nl//'99.0')
      call write_file('sub/b.k', '*KEYWORD'//nl//'*CONTROL_TIMESTEP'//nl//',0.5')
      call read_deck_input(dir//'/main.k', inp, err)
      call check(.not. allocated(err), 'include: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check_close(inp%ctrl%endtim, 0.01_wp, 0.0_wp, 1e-14_wp, 'include: nested file')
      call check_close(inp%ctrl%tssfac, 0.5_wp, 0.0_wp, 1e-14_wp, 'include: relative path')
      call check(inp%ctrl%ihq == 4, 'include: reading resumes after *INCLUDE')
      call check(size(inp%files) == 3, 'include: three files')
      call write_file('main2.k', '*KEYWORD'//nl//'*INCLUDE'//nl//'nothere.k')
      call read_deck_input(dir//'/main2.k', inp, err)
      call check(allocated(err), 'include: missing file is an error')
      if (allocated(err)) call check_has(err%message, 'main2.k:3: *INCLUDE: cannot open '// &
                                         'file', 'include: missing file message')
      call write_file('self.k', '*KEYWORD'//nl//'*INCLUDE'//nl//'self.k')
      call read_deck_input(dir//'/self.k', inp, err)
      call check(allocated(err), 'include: recursion is an error')
      if (allocated(err)) call check_has(err%message, 'include depth exceeds 20', &
                                         'include: depth message')
   end subroutine test_include

   subroutine test_field_errors()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      character(:), allocatable :: card
      integer :: k
      card = '         1    7.8e-9       abc       0.3'
      call write_file('e1.k', '*KEYWORD'//nl//'*MAT_ELASTIC'//nl//'$ MID RO E PR'//nl//card)
      call read_deck_input(dir//'/e1.k', inp, err)
      call check(allocated(err), 'error: non-numeric field')
      if (allocated(err)) then
         call check_has(err%message, 'e1.k:4:21: *MAT_ELASTIC: field E: expected a number', &
                        'error: file:line:col, keyword, field')
         call check_has(err%message, nl//card//nl//repeat(' ', 20)//'^', 'error: card and caret')
         call check(err%code == EXIT_INPUT, 'error: exit code 2')
      end if
      card = '         17.850000e-09 210000.0       0.3'
      call write_file('e2.k', '*KEYWORD'//nl//'*MAT_ELASTIC'//nl//card)
      call read_deck_input(dir//'/e2.k', inp, err)
      call check(allocated(err), 'error: overflowing field')
      if (allocated(err)) then
         call check_has(err%message, 'e2.k:3:11: *MAT_ELASTIC: field RO:', 'overflow: where')
         call check_has(err%message, 'overflows its 10 columns', 'overflow: says so')
      end if
      call write_file('e3.k', '*KEYWORD'//nl//'*NODE'//nl//'     1.5')
      call read_deck_input(dir//'/e3.k', inp, err)
      call check(allocated(err), 'error: real in integer field')
      if (allocated(err)) then
         k = index(err%message, 'e3.k:3:1: *NODE: field NID: expected an integer')
         call check(k > 0, 'error: integer field message')
      end if
      call write_file('e4.k', '*KEYWORD'//nl//'*PART'//nl//'only a heading')
      call read_deck_input(dir//'/e4.k', inp, err)
      call check(allocated(err), 'error: missing card')
      if (allocated(err)) call check_has(err%message, 'e4.k:2: *PART: missing card 2', &
                                         'error: missing card message')
      call write_file('e5.k', '*KEYWORD'//nl//'*SECTION_SOLID'//nl//'1,3')
      call read_deck_input(dir//'/e5.k', inp, err)
      call check(allocated(err), 'error: ELFORM 3')
      if (allocated(err)) call check_has(err%message, 'field ELFORM: solid formulation 3 '// &
                                         'is not supported', 'error: ELFORM message')
   end subroutine test_field_errors

   subroutine test_unknown_keyword()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('u.k', '*KEYWORD'//nl//'*DATABASE_FOO_BAR'//nl//'1,2,3'//nl// &
                      '*CONTROL_TERMINATION'//nl//'1.0')
      call read_deck_input(dir//'/u.k', inp, err)
      call check(allocated(err), 'unknown keyword is an error')
      if (allocated(err)) call check_has(err%message, 'u.k:2: unknown keyword *DATABASE_FOO_BAR', &
                                         'unknown keyword message')
      if (allocated(err)) call check_has(err%message, 'dynx --check lists every', &
                                         'unknown keyword: hint to --check')
      call log_set_quiet(.true.)
      call read_deck_input(dir//'/u.k', inp, err, ignore_unknown=.true.)
      call check(.not. allocated(err), 'unknown output keyword ignored on request')
      call check_close(inp%ctrl%endtim, 1.0_wp, 0.0_wp, 0.0_wp, 'reading goes on after it')
      ! a load, a material, a *CASE are never skipped: the deck would be another problem
      call write_file('u2.k', '*KEYWORD'//nl//'*LOAD_FOO_BAR'//nl//'1,2,3'//nl// &
                      '*CONTROL_TERMINATION'//nl//'1.0'//nl//'*CONSTRAINED_FOO_BAR'//nl// &
                      '*LOAD_FOO_BAR'//nl//'1,2,3'//nl//'*DATABASE_FOO_BAR'//nl//'1')
      call read_deck_input(dir//'/u2.k', inp, err, ignore_unknown=.true.)
      call check(allocated(err), 'unknown load keyword not skipped by ignore_unknown')
      if (allocated(err)) call check_has(err%message, 'u2.k:2: unknown keyword *LOAD_FOO_BAR: '// &
         'a load keyword is not skipped', 'unknown load: message names the family')
      ! --check: all of them at once, grouped, with first use and count
      call read_deck_input(dir//'/u2.k', inp, err, check=.true.)
      call check(allocated(err), 'check: findings are an error')
      if (allocated(err)) then
         call check_has(err%message, '3 unknown keyword(s)', 'check: count of findings')
         call check_has(err%message, 'load:', 'check: load family heading')
         call check_has(err%message, 'u2.k:2  (2 times)', 'check: first use and count')
         call check_has(err%message, '*CONSTRAINED_FOO_BAR', 'check: constraint keyword listed')
         call check_has(err%message, 'constraint:', 'check: constraint family heading')
         call check_has(err%message, 'output:', 'check: output family heading')
         call check(err%code == 2, 'check: exit code 2')
      end if
   end subroutine test_unknown_keyword

   !> The family of a keyword from its name, and which families --ignore-unknown may skip.
   subroutine test_families()
      call check(keyword_family('DATABASE_MATSUM') == 'output', 'family: *DATABASE_ output')
      call check(keyword_family('CONTROL_OUTPUT') == 'output', 'family: *CONTROL_OUTPUT output')
      call check(keyword_family('CONTROL_MPP_DECOMPOSITION_AUTOMATIC') == 'performance', &
                 'family: *CONTROL_MPP_ performance')
      call check(keyword_family('CONTROL_SHELL') == 'control', 'family: *CONTROL_SHELL control')
      call check(keyword_family('LOAD_NODE_SET') == 'load', 'family: load')
      call check(keyword_family('CASE_BEGIN_1') == 'case', 'family: *CASE_BEGIN_1 case')
      call check(keyword_family('CASE') == 'case', 'family: *CASE case')
      call check(keyword_family('MAT_JOHNSON_COOK') == 'material', 'family: material')
      call check(keyword_family('MATSUM') == 'other', 'family: MATSUM is not MAT_')
      call check(keyword_family('SECTION_SHELL') == 'section', 'family: section')
      call check(keyword_family('ELEMENT_SHELL') == 'element', 'family: element')
      call check(keyword_family('CONTACT_TIED_NODES_TO_SURFACE') == 'contact', 'family: contact')
      call check(keyword_family('CONTACT_FORCE_TRANSDUCER_PENALTY_ID') == 'output', &
                 'family: a force transducer is output (it applies no force)')
      call check(keyword_family('BOUNDARY_SPC_SET') == 'constraint', 'family: constraint')
      call check(keyword_family('INITIAL_STRESS_SOLID') == 'initial condition', &
                 'family: initial condition')
      call check(keyword_family('DYNX_NO_SUCH') == 'other', 'family: other')
      call check(keyword_skippable('DATABASE_ELOUT') .and. keyword_skippable('CONTROL_PARALLEL') &
                 .and. keyword_skippable('CONTROL_OUTPUT'), 'skippable: output, performance')
      call check(.not. (keyword_skippable('LOAD_NODE_SET') .or. keyword_skippable('CASE') .or. &
                 keyword_skippable('CONTROL_SHELL') .or. keyword_skippable('DEFINE_BOX') .or. &
                 keyword_skippable('DYNX_FOO')), 'not skippable: load, case, control, define, other')
   end subroutine test_families

   !> A blank line standing for a card; an *INCLUDE of comments only; *INCLUDE_PATH_RELATIVE;
   !> *KEYWORD tokens; RCFORC DT = 0.
   subroutine test_reader_defects()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call execute_command_line('mkdir -p '//dir//'/sub')
      call write_file('sub/inc1.k', '*CONTROL_TERMINATION'//nl//'2.5e-3')
      call write_file('rd.k', '*KEYWORD 100m NCPU=4'//nl//'*INCLUDE_PATH_RELATIVE'//nl// &
         'sub'//nl//'*INCLUDE'//nl//'$ gone.k'//nl//'*INCLUDE'//nl//'inc1.k'//nl// &
         '*CONTROL_SOLID'//nl//''//nl//'*CONTROL_BULK_VISCOSITY'//nl//''//nl//''//nl// &
         '*DATABASE_RCFORC'//nl//'0.0')
      call read_deck_input(dir//'/rd.k', inp, err)
      call check(.not. allocated(err), 'reader defects: deck read')
      if (allocated(err)) print '(a)', '    '//err%message
      call check_close(inp%ctrl%endtim, 2.5e-3_wp, 0.0_wp, 0.0_wp, &
                       'include found through *INCLUDE_PATH_RELATIVE')
      call check(inp%ctrl%esort == 0, 'blank *CONTROL_SOLID card: ESORT 0')
      call check_close(inp%ctrl%q1, 1.5_wp, 0.0_wp, 0.0_wp, 'blank bulk viscosity card: Q1 1.5')
      call check_close(inp%contact%rcforc_dt, 0.0_wp, 0.0_wp, 0.0_wp, 'RCFORC DT = 0 accepted')
      ! a missing include file still names the including line
      call write_file('rd2.k', '*KEYWORD'//nl//'*INCLUDE_PATH'//nl//dir//'/sub'//nl// &
                      '*INCLUDE'//nl//'nowhere.k')
      call read_deck_input(dir//'/rd2.k', inp, err)
      call check(allocated(err), 'missing include is an error')
      if (allocated(err)) call check_has(err%message, 'rd2.k:5: *INCLUDE: cannot open file', &
                                         'missing include: names the including line')
   end subroutine test_reader_defects

   !> *SET_PART_LIST_GENERATE over part labels; *SET_NODE_GENERAL ALL then DNODE.
   subroutine test_generated_sets()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      integer :: k
      call write_file('gs.k', '*KEYWORD'//nl//'*SET_PART_LIST_GENERATE'//nl//'5'//nl// &
         '2,3,7,7'//nl//'*SET_NODE_GENERAL'//nl//'6'//nl//'ALL'//nl//'DNODE,2'//nl// &
         '*PART'//nl//'a'//nl//'1,1,1'//nl//'*PART'//nl//'b'//nl//'3,1,1'//nl// &
         '*PART'//nl//'c'//nl//'7,1,1'//nl//'*NODE'//nl//'1,0,0,0'//nl//'2,1,0,0'//nl// &
         '3,2,0,0')
      call read_deck_input(dir//'/gs.k', inp, err)
      call check(.not. allocated(err), 'generated sets: deck read')
      if (allocated(err)) print '(a)', '    '//err%message
      if (allocated(err)) return
      k = findloc(inp%part_sets%label, 5, 1)
      call check(k > 0, 'part set 5 generated')
      if (k > 0) call check(size(inp%part_sets(k)%ids) == 2 .and. &
         all(inp%part_sets(k)%ids == [3, 7]), 'part set 5 = parts 3, 7 (2..3 and 7..7)')
      k = findloc(inp%node_sets%label, 6, 1)
      call check(k > 0, 'node set 6 generated')
      if (k > 0) call check(size(inp%node_sets(k)%ids) == 2 .and. &
         all(inp%node_sets(k)%ids == [1, 3]), 'node set 6 = ALL - DNODE 2 = 1, 3')
   end subroutine test_generated_sets

   !> *PARAMETER_EXPRESSION: precedence, functions, integer truncation, errors.
   subroutine test_parameter_expression()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('pe.k', '*KEYWORD'//nl//'*PARAMETER'//nl//'R t0      1.0e-3'//nl// &
         '*PARAMETER_EXPRESSION'//nl// &
         'R tend    2.0*t0 + &t0/2'//nl// &
         'R ang     atan(1.0)*4 - pi'//nl// &
         'I n       7/2'//nl// &
         'R p       -2**2 + 2**3**2 + (1+1)^2'//nl// &
         'R tend2,  max(tend, 1.0d-4) * sqrt(4.0) / n'//nl// &
         '*CONTROL_TERMINATION'//nl//'&tend2,&n,&ang,,&p')
      call read_deck_input(dir//'/pe.k', inp, err)
      call check(.not. allocated(err), 'parameter expressions read')
      if (allocated(err)) print '(a)', '    '//err%message
      if (allocated(err)) return
      ! tend = 2.5e-3; tend2 = 2.5e-3*2/3; n = int(3.5) = 3; ang = 0; p = -4 + 512 + 4
      call check_close(inp%ctrl%endtim, 2.5e-3_wp*2.0_wp/3.0_wp, 0.0_wp, 1.0e-15_wp, &
                       'expression: params, max, sqrt, integer parameter')
      call check(inp%ctrl%endcyc == 3, 'expression: I parameter truncated (7/2 = 3)')
      call check_close(inp%ctrl%dtmin, 0.0_wp, 1.0e-15_wp, 0.0_wp, 'expression: atan(1)*4 = pi')
      call check_close(inp%ctrl%endmas, 512.0_wp, 0.0_wp, 0.0_wp, &
                       'expression: -2**2 = -4, 2**3**2 = 512 (right-assoc), (1+1)^2 = 4')
      call write_file('pe2.k', '*KEYWORD'//nl//'*PARAMETER_EXPRESSION'//nl// &
                      'R a       2*nothere')
      call read_deck_input(dir//'/pe2.k', inp, err)
      call check(allocated(err), 'expression: undefined parameter is an error')
      if (allocated(err)) call check_has(err%message, 'pe2.k:3: *PARAMETER_EXPRESSION: field '// &
         'EXPRESSION of A: parameter ''NOTHERE'' is not defined', 'expression: error message')
      call write_file('pe3.k', '*KEYWORD'//nl//'*PARAMETER_EXPRESSION'//nl// &
                      'R a       foo(2) + 1')
      call read_deck_input(dir//'/pe3.k', inp, err)
      call check(allocated(err), 'expression: unknown function is an error')
      if (allocated(err)) call check_has(err%message, 'unknown function ''FOO''', &
                                         'expression: unknown function message')
   end subroutine test_parameter_expression

   function full_deck() result(s)
      character(:), allocatable :: s
      s = '*KEYWORD'//nl//'*TITLE'//nl//'small test'//nl// &
         '*CONTROL_TERMINATION'//nl//'0.001'//nl// &
         '*PART'//nl//'bar'//nl//'1,1,1,,1'//nl// &
         '*SECTION_SOLID_TITLE'//nl//'one point'//nl//'1,0'//nl// &
         '*HOURGLASS'//nl//'1,5,0.05'//nl// &
         '*MAT_ELASTIC_TITLE'//nl//'steel'//nl//'1,7.8e-9,210000.,0.3'//nl// &
         '*NODE'//nl//'1,0,0,0'//nl//'2,1,0,0'//nl//'3,1,1,0'//nl//'4,0,1,0'//nl// &
         '5,0,0,1'//nl//'6,1,0,1'//nl//'7,1,1,1'//nl//'8,0,1,1'//nl//'9,2,0,0'//nl// &
         '10,2,1,0'//nl//'11,2,0,1'//nl//'12,2,1,1'//nl// &
         '*ELEMENT_SOLID'//nl//'       1       1'//nl// &
         '       1       2       3       4       5       6       7       8'//nl// &
         '       2       1       2       9      10       3       6      11      12       7'// &
         nl//'*INITIAL_VELOCITY_GENERATION'//nl//'1,2,10.0,1.0,0,0'//nl//'0,0,0,0,0,2'//nl// &
         '*INITIAL_VELOCITY_NODE'//nl//'12,0,0,-5'//nl// &
         '*DEFINE_CURVE'//nl//'1'//nl//'0.0,0.0'//nl//'1.0,2.0'//nl// &
         '*DEFINE_CURVE_TITLE'//nl//'shifted'//nl//'2,,2.0,3.0,1.0,1.0'//nl//'0.0,0.0'//nl// &
         '1.0,1.0'//nl// &
         '*BOUNDARY_SPC_NODE'//nl//'1,0,1,1,1'//nl// &
         '*SET_NODE_LIST_TITLE'//nl//'right end'//nl//'1'//nl//'9,10,11,12'//nl// &
         '*BOUNDARY_PRESCRIBED_MOTION_SET'//nl//'1,1,2,1'//nl// &
         '*RIGIDWALL_PLANAR'//nl//'0'//nl//'-1,0,0,0,0,0'//nl// &
         '*LOAD_SEGMENT'//nl//'1,2.0,,5,6,7,8'//nl// &
         '*DATABASE_HISTORY_NODE'//nl//'1,12'//nl// &
         '*DATABASE_BINARY_D3PLOT'//nl//',,,10'//nl//'*END'
   end function full_deck

   subroutine test_full_deck()
      type(model_t) :: m
      type(error_t), allocatable :: err
      call write_file('full.k', full_deck())
      call read_deck(dir//'/full.k', m, err)
      call check(.not. allocated(err), 'full: builds')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check(m%title == 'small test', 'full: *TITLE')
      call check(m%deck_file == dir//'/full.k', 'full: deck_file')
      call check(m%nn == 12 .and. m%ne == 2, 'full: node and element counts')
      call check(size(m%blocks) == 1, 'full: one block')
      call check(m%blocks(1)%nel == 2 .and. m%blocks(1)%etype == ETYPE_HEX8_1PT, 'full: block')
      call check(all(m%blocks(1)%conn(:, 2) == [2, 9, 10, 3, 6, 11, 12, 7]), &
                 'full: one-line element layout')
      call check(all(m%blocks(1)%conn(:, 1) == [1, 2, 3, 4, 5, 6, 7, 8]), &
                 'full: two-card element layout')
      call check_close(m%blocks(1)%vol0(1), 1.0_wp, 1e-14_wp, 0.0_wp, 'full: vol0')
      call check(m%blocks(1)%esc(ES_HGS) > 0, 'full: hgs slot for IHQ 5')
      call check(m%parts(1)%ihq == 5, 'full: part IHQ from *HOURGLASS')
      call check_close(m%parts(1)%qh, 0.05_wp, 0.0_wp, 1e-14_wp, 'full: part QH')
      call check_close(m%parts(1)%q1, 1.5_wp, 0.0_wp, 1e-14_wp, 'full: part Q1 default')
      call check(m%sections(1)%elform == 1 .and. m%sections(1)%title == 'one point', &
                 'full: ELFORM 0 -> 1, _TITLE')
      call check(m%mats(1)%m%title == 'steel', 'full: *MAT_ELASTIC_TITLE')
      call check_close(m%v0(1, 2), 1.0_wp, 0.0_wp, 1e-14_wp, 'full: generation vx')
      call check_close(m%v0(2, 2), 10.0_wp, 0.0_wp, 1e-14_wp, 'full: generation omega x r')
      call check_close(m%v0(1, 3), -9.0_wp, 0.0_wp, 1e-14_wp, 'full: generation at node 3')
      call check_close(m%v0(3, 12), -5.0_wp, 0.0_wp, 0.0_wp, 'full: _NODE overrides')
      call check_close(m%v0(1, 12), 0.0_wp, 0.0_wp, 0.0_wp, 'full: _NODE sets all components')
      call check_close(m%curves(1)%eval(0.5_wp), 1.0_wp, 0.0_wp, 1e-14_wp, 'full: curve eval')
      call check_close(m%curves(2)%x(2), 4.0_wp, 0.0_wp, 1e-14_wp, 'full: SFA*(A+OFFA)')
      call check_close(m%curves(2)%y(2), 6.0_wp, 0.0_wp, 1e-14_wp, 'full: SFO*(O+OFFO)')
      call check(size(m%spcs) == 1, 'full: one spc')
      if (size(m%spcs) == 1) call check(all(m%spcs(1)%dof .eqv. [.true., .true., .true., &
         .false., .false., .false.]), 'full: spc dofs')
      call check(size(m%prescribed) == 4, 'full: prescribed on 4 set nodes')
      if (size(m%prescribed) == 4) then
         call check(m%prescribed(1)%node == 9 .and. m%prescribed(1)%vad == 2, &
                    'full: prescribed node, VAD')
         call check_close(m%prescribed(1)%dir(1), 1.0_wp, 0.0_wp, 0.0_wp, 'full: prescribed dir')
      end if
      call check(size(m%walls) == 1, 'full: one wall')
      if (size(m%walls) == 1) then
         call check(size(m%walls(1)%nodes) == 12, 'full: wall NSID 0 = all nodes')
         call check_close(m%walls(1)%n(1), 1.0_wp, 0.0_wp, 1e-14_wp, 'full: wall normal')
      end if
      call check(size(m%seg_loads) == 1, 'full: one segment load')
      if (size(m%seg_loads) == 1) call check(all(m%seg_loads(1)%nodes == [5, 6, 7, 8]) .and. &
         m%seg_loads(1)%sf == 2.0_wp, 'full: segment load nodes, SF')
      call check(size(m%db%hist_nodes) == 2, 'full: history nodes')
      call check_close(m%db%d3plot_dt, 1.0e-4_wp, 0.0_wp, 1e-12_wp, 'full: NPLTC -> DT')
      call check(m%elem_block(2) == 1 .and. m%elem_pos(2) == 2, 'full: elem_block, elem_pos')
   end subroutine test_full_deck

   !> 130 elements in a row of one part -> blocks of 128 and 2; ELFORM 2 -> 8 points
   subroutine test_blocks()
      type(model_t) :: m
      type(error_t), allocatable :: err
      character(:), allocatable :: s
      character(120) :: buf
      integer :: i, n
      n = 130
      s = '*KEYWORD'//nl//'*CONTROL_TERMINATION'//nl//',10'//nl//'*PART'//nl//'p'//nl// &
          '7,3,4'//nl//'*SECTION_SOLID'//nl//'3,2'//nl//'*MAT_003'//nl// &
          '4,7.8e-9,2.1e5,0.3,200.0'//nl//'*NODE'//nl
      do i = 0, n
         write(buf, '(i0,a,i0,a)') 4*i + 1, ',', i, ',0,0'
         s = s//trim(buf)//nl
         write(buf, '(i0,a,i0,a)') 4*i + 2, ',', i, ',1,0'
         s = s//trim(buf)//nl
         write(buf, '(i0,a,i0,a)') 4*i + 3, ',', i, ',1,1'
         s = s//trim(buf)//nl
         write(buf, '(i0,a,i0,a)') 4*i + 4, ',', i, ',0,1'
         s = s//trim(buf)//nl
      end do
      s = s//'*ELEMENT_SOLID'//nl
      do i = 0, n - 1
         write(buf, '(10i8)') 100 + i, 7, 4*i + 1, 4*i + 5, 4*i + 6, 4*i + 2, 4*i + 4, &
            4*i + 8, 4*i + 7, 4*i + 3
         s = s//trim(buf)//nl
      end do
      call write_file('blocks.k', s)
      call read_deck(dir//'/blocks.k', m, err)
      call check(.not. allocated(err), 'blocks: builds')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      call check(size(m%blocks) == 2, 'blocks: 130 elements -> 2 blocks')
      call check(m%blocks(1)%nel == 128 .and. m%blocks(2)%nel == 2, 'blocks: 128 + 2')
      call check(m%blocks(1)%etype == ETYPE_HEX8_SRI .and. m%blocks(1)%nip == 8, &
                 'blocks: ELFORM 2')
      call check(m%elem_block(130) == 2 .and. m%elem_pos(130) == 2, 'blocks: elem maps')
      call check(m%elem_label(130) == 229, 'blocks: labels')
      call check(m%blocks(1)%esc(ES_HGS) == 0, 'blocks: no hgs slot for IHQ 1')
      call check(size(m%blocks(1)%hv, 2) == m%blocks(1)%nhv .and. m%blocks(1)%nhv > 0, &
                 'blocks: history sized by the material')
      call check_close(sum(m%blocks(1)%vol0) + sum(m%blocks(2)%vol0), 130.0_wp, 1e-9_wp, &
                       0.0_wp, 'blocks: total volume')
   end subroutine test_blocks

   subroutine test_materials()
      type(model_input_t) :: inp
      type(error_t), allocatable :: err
      call write_file('mat.k', '*KEYWORD'//nl//'*MAT_PIECEWISE_LINEAR_PLASTICITY'//nl// &
         '1,7.8e-9,2.1e5,0.3,250.0,1000.0'//nl//',,5'//nl//'0,0.1,0.2'//nl//'250,300,320')
      call read_deck_input(dir//'/mat.k', inp, err)
      call check(.not. allocated(err), 'mat024: reads')
      if (allocated(err)) then
         print '(a)', err%message; return
      end if
      select type (m => inp%mats(1)%m)
      type is (mat_piecewise_linear_t)
         call check(m%lcss == 5, 'mat024: LCSS')
         call check_close(m%fail, 1.0e21_wp, 0.0_wp, 0.0_wp, 'mat024: FAIL default')
         call check_close(m%eps(3), 0.2_wp, 0.0_wp, 1e-14_wp, 'mat024: EPS3')
         call check_close(m%es(2), 300.0_wp, 0.0_wp, 1e-14_wp, 'mat024: ES2')
         call check(m%mtype == 24, 'mat024: mtype')
      class default
         call check(.false., 'mat024: type')
      end select
      call write_file('mat1.k', '*KEYWORD'//nl//'*MAT_001'//nl//'3,1.0,2.0,0.25')
      call read_deck_input(dir//'/mat1.k', inp, err)
      call check(.not. allocated(err), 'mat001 alias: reads')
      if (allocated(err)) return
      select type (m => inp%mats(1)%m)
      type is (mat_elastic_t)
         call check(m%label == 3 .and. m%e == 2.0_wp .and. m%pr == 0.25_wp, 'mat001: fields')
      class default
         call check(.false., 'mat001: type')
      end select
   end subroutine test_materials

   !> one defect at a time in the full deck
   subroutine test_build_errors()
      call expect_error('dup node', '5,0,0,1'//nl//'6,1,0,1', '5,0,0,1'//nl//'5,1,0,1', &
                        '*NODE: duplicate node id 5')
      call expect_error('missing node', '2,1,0,0'//nl//'3,1,1,0', '3,1,1,0', &
                        'field N2: node 2 is not defined')
      call expect_error('missing material', '1,1,1,,1', '1,1,2,,1', &
                        '*PART: part 1: field MID: material 2 is not defined')
      call expect_error('negative density', '1,7.8e-9,', '1,-7.8e-9,', &
                        '*MAT_ELASTIC_TITLE: field RO: material 1: density must be > 0')
      call expect_error('inverted', '       1       2       3       4       5       6'// &
                        '       7       8', '       5       6       7       8       1       2'// &
                        '       3       4', 'is inverted at t = 0')
      call expect_error('degenerate', '       1       2       3       4       5       6'// &
                        '       7       8', '       1       2       3       4       5       6'// &
                        '       7       7', 'degenerate solid not supported')
      call expect_error('no termination', '*CONTROL_TERMINATION'//nl//'0.001', &
                        '*CONTROL_TERMINATION'//nl//'0.0', 'the run would not end')
      call expect_error('missing curve', '1,1,2,1', '1,1,2,9', 'curve 9 is not defined')
   end subroutine test_build_errors

   subroutine expect_error(name, old, new, sub)
      character(*), intent(in) :: name, old, new, sub
      character(:), allocatable :: s
      type(model_t) :: m
      type(error_t), allocatable :: err
      integer :: k
      s = full_deck()
      k = index(s, old)
      if (k == 0) then
         call check(.false., 'build error '//name//': test setup')
         return
      end if
      s = s(1:k-1)//new//s(k+len(old):)
      call write_file('bad.k', s)
      call read_deck(dir//'/bad.k', m, err)
      call check(allocated(err), 'build error: '//name)
      if (allocated(err)) call check_has(err%message, sub, 'build error message: '//name)
   end subroutine expect_error
   !> dx_deck_buffers: 1000 pushes (past several doublings of the 16-record start) flushed
   !> after 2 records already there keep push order; a second flush of an empty buffer adds
   !> nothing.
   subroutine test_record_buffer()
      type(spc_buffer_t) :: buf
      type(spc_in_t), allocatable :: a(:)
      type(spc_in_t) :: r
      integer :: k
      allocate(a(2))
      a%id = [-1, -2]
      do k = 1, 1000
         r%id = k
         call buf%push(r)
      end do
      call buf%flush(a)
      call check(size(a) == 1002, 'buffer: 2 + 1000 records')
      call check(all(a%id == [-1, -2, [(k, k = 1, 1000)]]), 'buffer: push order kept')
      call buf%flush(a)
      call check(size(a) == 1002 .and. buf%n == 0, 'buffer: empty flush adds nothing')
   end subroutine test_record_buffer
end program test_deck
