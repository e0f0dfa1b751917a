!> Out of memory as a clean stop (exit 4 and one line), never a segmentation fault or the
!> runtime's exit 1 (issue 22; docs/errors.md). Why ranks died by SIGSEGV when their
!> address space ran out (`ulimit -v`, the memory-limit test of scripts/bench_scaling.py
!> at NP 4): gfortran 12 checks the malloc of an ALLOCATE statement and of an array's
!> (re)allocation on assignment ("Error allocating N bytes", exit 1), but not that of a
!> deferred-length character assignment (`line = acc(1:n)` in the deck reader): it memcpy's
!> into the null pointer. A 3-line program shows it (`s = repeat('x', n)` under `ulimit -v`
!> ends by SIGSEGV); the NP 4 core dump had memcpy in dx_deck_cards%read_file. libgfortran's
!> own handler then needs memory for its backtrace and prints nothing useful.
!> What this module does (POSIX sigaction with SA_SIGINFO and SA_ONSTACK, sigaltstack,
!> getrlimit(RLIMIT_AS); IEEE Std 1003.1-2017; glibc on_exit): (1) a SIGSEGV handler on a
!> static alternate stack: with a finite address-space limit, a fault at a write near
!> address 0 (an unchecked failed allocation) or with the mapped size (/proc/self/statm)
!> within margin_of the limit (64 MiB or an eighth of it; a stack that could not grow) is
!> out of memory; any other fault goes back to the handler that was there before
!> (libgfortran's backtrace, or AddressSanitizer's): a bug stays a crash (a null-pointer
!> write under a finite limit is reported as out of memory: the one case it cannot tell). (2) an exit hook: the runtime's exit 1 after a
!> refused ALLOCATE (errno ENOMEM, or the address space within margin_of its limit) is out
!> of memory too. Out of memory: one line (what failed, the limit, the mapped size) by
!> write(2) and _exit(4), the code of a resource the system refused (as a full disk; no
!> dump: writing one needs memory). Only async-signal-safe calls in the handler (open,
!> read, close, write, getrlimit, sigaction, _exit).
module dx_memory_fault
   use, intrinsic :: iso_c_binding, only: c_int, c_long, c_size_t, c_ptr, c_funptr, &
      c_funloc, c_loc, c_null_ptr, c_f_pointer, c_int64_t, c_char, c_null_char
   use dx_libc, only: c_open, c_read, c_write, c_close, c_errno_location, c_exit_now
   implicit none
   private
   public :: memory_fault_install

   integer(c_int), parameter :: SIGSEGV_NUM = 11, RLIMIT_AS_NUM = 9
   integer(c_int), parameter :: SA_SIGINFO = 4, SA_ONSTACK = int(z'08000000', c_int)
   integer(c_int64_t), parameter :: RLIM_INFINITY = -1_c_int64_t
   integer(c_int64_t), parameter :: NULL_ZONE = 65536      !< fault addresses of a null write
   integer(c_int64_t), parameter :: MARGIN = 64*1048576    !< bytes left that count as full
   integer(c_int), parameter :: ENOMEM = 12
   integer, parameter :: ALT_BYTES = 65536                 !< the handler's own stack

   !> struct sigaction of glibc on Linux x86_64 (handler, 1024-bit mask, flags, restorer)
   type, bind(C) :: sigaction_t
      type(c_funptr) :: handler
      integer(c_long) :: mask(16) = 0
      integer(c_int) :: flags = 0
      type(c_funptr) :: restorer
   end type sigaction_t
   !> stack_t (sigaltstack)
   type, bind(C) :: stack_t
      type(c_ptr) :: sp = c_null_ptr
      integer(c_int) :: flags = 0
      integer(c_size_t) :: size = 0
   end type stack_t
   type, bind(C) :: rlimit_t
      integer(c_int64_t) :: cur = 0, max = 0
   end type rlimit_t

   type(sigaction_t), save :: previous           !< the handler before ours (chained)
   character(kind=c_char), target, save :: alt(ALT_BYTES)
   logical, save :: installed = .false.

   interface
      function c_sigaction(sig, act, old) bind(C, name='sigaction') result(r)
         import :: c_int, sigaction_t
         integer(c_int), value :: sig
         type(sigaction_t), intent(in) :: act
         type(sigaction_t), intent(out) :: old
         integer(c_int) :: r
      end function c_sigaction
      function c_sigaction_set(sig, act, old) bind(C, name='sigaction') result(r)
         import :: c_int, sigaction_t, c_ptr
         integer(c_int), value :: sig
         type(sigaction_t), intent(in) :: act
         type(c_ptr), value :: old
         integer(c_int) :: r
      end function c_sigaction_set
      function c_sigaltstack(ss, old) bind(C, name='sigaltstack') result(r)
         import :: c_int, stack_t, c_ptr
         type(stack_t), intent(in) :: ss
         type(c_ptr), value :: old
         integer(c_int) :: r
      end function c_sigaltstack
      function c_getrlimit(res, rl) bind(C, name='getrlimit') result(r)
         import :: c_int, rlimit_t
         integer(c_int), value :: res
         type(rlimit_t), intent(out) :: rl
         integer(c_int) :: r
      end function c_getrlimit
      function c_on_exit(fn, arg) bind(C, name='on_exit') result(r)
         import :: c_int, c_funptr, c_ptr
         type(c_funptr), value :: fn
         type(c_ptr), value :: arg
         integer(c_int) :: r
      end function c_on_exit
   end interface

contains

   !> Install the handler (once; the main program's start, with the batch signals).
   subroutine memory_fault_install()
      type(sigaction_t) :: act
      type(stack_t) :: ss
      integer(c_int) :: r
      if (installed) return
      installed = .true.
      r = c_on_exit(c_funloc(on_exit_status), c_null_ptr)
      ss%sp = c_loc(alt)
      ss%size = int(ALT_BYTES, c_size_t)
      r = c_sigaltstack(ss, c_null_ptr)
      if (r /= 0) return
      act%handler = c_funloc(on_segv)
      act%flags = ior(SA_SIGINFO, SA_ONSTACK)
      r = c_sigaction(SIGSEGV_NUM, act, previous)
   end subroutine memory_fault_install

   !> The SIGSEGV handler (sa_sigaction form): out of memory -> one line and exit 4; any
   !> other fault -> the previous handler is put back and the faulting instruction re-runs.
   subroutine on_segv(sig, info, ctx) bind(C)
      integer(c_int), value :: sig
      type(c_ptr), value :: info, ctx
      integer(c_int64_t), pointer :: si(:)
      integer(c_int64_t) :: addr, lim, mapped
      integer(c_int) :: r
      call c_f_pointer(info, si, [3])
      addr = si(3)                                 ! si_addr: offset 16 of siginfo_t
      call memory_state(lim, mapped)
      if (lim > 0 .and. ((addr >= 0 .and. addr < NULL_ZONE) .or. mapped > lim - margin_of(lim))) &
         call stop_out_of_memory(lim, mapped, 'a write fault at address ', addr)
      r = c_sigaction_set(SIGSEGV_NUM, previous, c_null_ptr)   ! a bug: the old handler
   end subroutine on_segv

   !> At exit (glibc on_exit): the Fortran runtime ends a refused ALLOCATE with exit 1
   !> ("Error allocating N bytes: Cannot allocate memory"; dynx itself never exits 1). When
   !> errno is ENOMEM or the address space is within margin_of the limit, that is out of
   !> memory: one line and exit 4. Any other exit status passes unchanged. (errno is not a
   !> sure sign: the runtime's message and exit path reset it, ENOENT was seen; a refused
   !> request far larger than the room left is therefore not recognised and stays exit 1.)
   subroutine on_exit_status(status, arg) bind(C)
      integer(c_int), value :: status
      type(c_ptr), value :: arg
      integer(c_int), pointer :: errno
      integer(c_int64_t) :: lim, mapped
      if (status /= 1) return
      call c_f_pointer(c_errno_location(), errno)
      call memory_state(lim, mapped)
      if (errno == ENOMEM .or. (lim > 0 .and. mapped > lim - margin_of(lim))) &
         call stop_out_of_memory(lim, mapped, 'the Fortran runtime''s exit 1 above, errno ', &
                                 int(errno, c_int64_t))
   end subroutine on_exit_status

   !> The room that counts as none left under limit lim: MARGIN or an eighth of lim.
   pure integer(c_int64_t) function margin_of(lim)
      integer(c_int64_t), intent(in) :: lim
      margin_of = max(MARGIN, lim/8)
   end function margin_of

   !> The address-space limit (RLIMIT_AS, bytes; 0 when unlimited or unknown) and the
   !> mapped size now (bytes; 0 when unknown).
   subroutine memory_state(lim, mapped)
      integer(c_int64_t), intent(out) :: lim, mapped
      type(rlimit_t) :: rl
      lim = 0
      if (c_getrlimit(RLIMIT_AS_NUM, rl) == 0) then
         if (rl%cur /= RLIM_INFINITY) lim = rl%cur
      end if
      mapped = mapped_bytes()
   end subroutine memory_state

   !> One line on stderr with write(2) (limit, mapped size, what was seen), then _exit(4).
   !> A fixed buffer filled in place: a concatenation could ask malloc for its result.
   subroutine stop_out_of_memory(lim, mapped, what, num)
      integer(c_int64_t), intent(in) :: lim, mapped, num
      character(*), intent(in) :: what
      character(kind=c_char) :: msg(400)
      integer(c_long) :: r8
      integer :: k
      k = 0
      call put('dynx: out of memory: an allocation failed (')
      call put(what)
      call putw(dec(num))
      call put('); address-space limit (ulimit -v) ')
      if (lim > 0) then
         call putw(dec(lim/1024))
         call put(' KiB')
      else
         call put('none')
      end if
      call put(', mapped ')
      call putw(dec(mapped/1024))
      call put(' KiB. Stopped with exit 4; raise the limit or run on more ranks '// &
               '(mpirun -np N dynx --part DIR)')
      call put(achar(10))
      r8 = c_write(2_c_int, msg, int(k, c_size_t))
      call c_exit_now(4_c_int)
   contains
      subroutine put(t)
         character(*), intent(in) :: t
         integer :: i
         do i = 1, len(t)
            if (k < size(msg)) then
               k = k + 1
               msg(k) = t(i:i)
            end if
         end do
      end subroutine put
      !> a number from dec, without its trailing blanks
      subroutine putw(t)
         character(*), intent(in) :: t
         call put(t(1:len_trim(t)))
      end subroutine putw
   end subroutine stop_out_of_memory

   !> The mapped size of this process in bytes (/proc/self/statm, first field x 4096), 0
   !> when unknown. No Fortran I/O (not async-signal-safe, and it allocates).
   function mapped_bytes() result(b)
      integer(c_int64_t) :: b
      character(kind=c_char) :: buf(64)
      integer(c_long) :: n
      integer(c_int) :: fd, r
      integer :: i
      b = 0
      fd = c_open('/proc/self/statm'//c_null_char, 0_c_int, 0_c_int)
      if (fd < 0) return
      n = c_read(fd, buf, int(size(buf), c_size_t))
      r = c_close(fd)
      do i = 1, int(n)
         if (buf(i) < '0' .or. buf(i) > '9') exit
         b = 10*b + (ichar(buf(i)) - ichar('0'))
      end do
      b = 4096*b
   end function mapped_bytes

   !> Decimal text of n >= 0, left-adjusted (no Fortran I/O; '?' when negative).
   pure function dec(n) result(s)
      integer(c_int64_t), intent(in) :: n
      character(20) :: s
      character(20) :: t
      integer(c_int64_t) :: m
      integer :: k
      s = '?'
      if (n < 0) return
      m = n
      k = 20
      t = ' '
      do
         t(k:k) = achar(iachar('0') + int(mod(m, 10_c_int64_t)))
         m = m/10
         k = k - 1
         if (m == 0 .or. k == 0) exit
      end do
      s = t(k + 1:)
   end function dec
end module dx_memory_fault
