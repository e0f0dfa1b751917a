!> Unit tests of the restart file layer (dx_restart_file): CRC-32 against the published
!> check values of the IEEE polynomial (zlib's crc32 of b'12345678' = 0x9AE0DAAF and of
!> b'123456789abcdefg' = 0xA2CAAFFF), a bitwise round trip of every put/get kind (NaN, -0,
!> denormals and huge values included), the atomic commit (no .tmp left), and the refusals:
!> missing dataset, wrong size, checksum mismatch, other format version, incomplete file.
program test_restart
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_negative_inf
   use dx_kinds, only: wp
   use dx_error, only: error_t, EXIT_IO, EXIT_INPUT
   use dx_io_sys, only: sys_mkdir_p
   use dx_h5, only: h5_file_t, h5_create, h5_close, h5_write_attr
   use dx_restart_file, only: rs_file_t, rs_create, rs_commit, rs_open, rs_close, crc32, &
                              RESTART_FORMAT_VERSION
   use dx_assert, only: check, assert_summary
   implicit none
   character(*), parameter :: TMP = 'build/test_restart.tmp'
   type(error_t), allocatable :: error

   call sys_mkdir_p(TMP, error)
   call check(.not. allocated(error), 'create scratch dir '//TMP)
   call test_crc()
   call test_roundtrip()
   call test_refusals()
   call assert_summary()

contains

   subroutine test_crc()
      real(wp) :: a(1), b(2)
      write(*, '(a)') 'CRC-32 (IEEE 802.3) check values'
      a = transfer('12345678', a)
      b = transfer('123456789abcdefg', b)
      call check(crc32(a) == int(z'9AE0DAAF', int64), 'crc32(12345678) = 0x9AE0DAAF')
      call check(crc32(b) == int(z'A2CAAFFF', int64), 'crc32(123456789abcdefg) = 0xA2CAAFFF')
      b(2) = b(1)
      call check(crc32(b) /= int(z'A2CAAFFF', int64), 'crc32 changes with one changed byte')
   end subroutine test_crc

   subroutine test_roundtrip()
      type(rs_file_t) :: rs
      real(wp) :: r0, r1(5), r2(3, 4), r3(2, 3, 2), q0, q1(5), q2(3, 4), q3(2, 3, 2)
      integer :: i0, i1(4), j0, j1(4), k
      integer(int64) :: i8, j8
      logical :: l1(3), m1(3), there
      character(:), allocatable :: path
      write(*, '(a)') 'round trip'
      path = TMP//'/dump.h5'
      r0 = 1.0_wp/3.0_wp
      r1 = [ieee_value(1.0_wp, ieee_quiet_nan), -0.0_wp, tiny(1.0_wp)*1.0e-10_wp, &
            huge(1.0_wp), ieee_value(1.0_wp, ieee_negative_inf)]
      r2 = reshape([(real(k, wp)*0.1_wp, k = 1, 12)], [3, 4])
      r3 = reshape([(sqrt(real(k, wp)), k = 1, 12)], [2, 3, 2])
      i0 = -2147483647; i1 = [0, -1, 2147483647, 42]; i8 = 9007199254740992_int64
      l1 = [.true., .false., .true.]
      call rs_create(rs, path, 'test_restart')
      call rs%put('r0', r0); call rs%put('r1', r1); call rs%put('r2', r2)
      call rs%put('r3', r3); call rs%put('i0', i0); call rs%put('i1', i1)
      call rs%put('i8', i8); call rs%put('l1', l1)
      call rs_commit(rs, error)
      call check(.not. allocated(error), 'commit')
      inquire(file=path//'.tmp', exist=there)
      call check(.not. there, 'no temporary file left after the commit')
      call rs_open(rs, path, error)
      call check(.not. allocated(error), 'open')
      q0 = 0; q1 = 0; q2 = 0; q3 = 0; j0 = 0; j1 = 0; j8 = 0; m1 = .false.
      call rs%get('r0', q0); call rs%get('r1', q1); call rs%get('r2', q2)
      call rs%get('r3', q3); call rs%get('i0', j0); call rs%get('i1', j1)
      call rs%get('i8', j8); call rs%get('l1', m1)
      call check(rs%ok(), 'every get succeeds')
      call check(transfer(q0, 1_int64) == transfer(r0, 1_int64), 'scalar real bitwise')
      call check(all(transfer(q1, [1_int64]) == transfer(r1, [1_int64])), &
                 'NaN, -0, denormal, huge, -Inf bitwise')
      call check(all(q2 == r2) .and. all(q3 == r3), 'rank-2 and rank-3 arrays')
      call check(j0 == i0 .and. all(j1 == i1) .and. j8 == i8, 'integers (2**53 included)')
      call check(all(m1 .eqv. l1), 'logicals')
      call check(rs%has('r2') .and. .not. rs%has('nothing'), 'has')
      call rs_close(rs, error)
      call check(.not. allocated(error), 'close')
   end subroutine test_roundtrip

   subroutine test_refusals()
      type(rs_file_t) :: rs
      type(h5_file_t) :: h5
      type(error_t), allocatable :: e
      real(wp) :: a(4), b(5)
      character(:), allocatable :: path
      write(*, '(a)') 'refusals'
      path = TMP//'/dump.h5'
      call rs_open(rs, path, error)
      call rs%get('missing', a)
      call check(.not. rs%ok(), 'missing dataset is an error')
      if (.not. rs%ok()) call check(index(rs%err%message, 'no dataset missing') > 0 .and. &
                                    rs%err%code == EXIT_INPUT, 'missing dataset message')
      call rs_close(rs, error)
      call rs_open(rs, path, error)
      call rs%get('r1', a)
      call check(.not. rs%ok(), 'wrong size is an error')
      if (.not. rs%ok()) call check(index(rs%err%message, 'has 5 values, this deck needs 4') &
                                    > 0, 'wrong size message')
      call rs_close(rs, error)
      ! a damaged dataset: its stored checksum does not match its bytes
      path = TMP//'/damaged.h5'
      b = [1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp]
      call rs_create(rs, path, 'test_restart')
      call rs%put('b', b)
      call h5_write_attr(rs%h5, '/b', 'crc32', real(crc32(b) + 1_int64, wp), e)
      call rs_commit(rs, error)
      call rs_open(rs, path, error)
      call rs%get('b', b)
      call check(.not. rs%ok(), 'checksum mismatch is an error')
      if (.not. rs%ok()) call check(index(rs%err%message, 'checksum mismatch in dataset b') > 0 &
                                    .and. rs%err%code == EXIT_IO, 'checksum message, exit 4')
      call rs_close(rs, error)
      ! another format version
      path = TMP//'/version.h5'
      call rs_create(rs, path, 'test_restart')
      call h5_write_attr(rs%h5, '/', 'format_version', 99, e)
      call rs_commit(rs, error)
      call rs_open(rs, path, error)
      call check(allocated(error), 'other format version refused')
      if (allocated(error)) call check(index(error%message, 'has format version 99') > 0, &
                                       'version message')
      ! a file whose writer stopped before the end (no 'complete' attribute)
      path = TMP//'/incomplete.h5'
      call h5_create(h5, path, e)
      call h5_write_attr(h5, '/', 'format_version', RESTART_FORMAT_VERSION, e)
      call h5_close(h5, e)
      call rs_open(rs, path, error)
      call check(allocated(error), 'incomplete file refused')
      ! (the whole-file checksum trailer is appended at rs_commit: a file whose writer
      ! stopped before the end has none, and that check comes first, exit 4)
      if (allocated(error)) call check(index(error%message, 'has no whole-file checksum '// &
         'trailer') > 0 .and. error%code == EXIT_IO, 'incomplete message, exit 4')
      call rs_open(rs, TMP//'/none.h5', error)
      call check(allocated(error), 'missing file refused')
   end subroutine test_refusals
end program test_restart
