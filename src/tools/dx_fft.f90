!> Spectra of uniformly sampled time histories with FFTW 3: the ONE module of dynx that calls
!> FFTW (scripts/check_layers.py enforces it; only bin/dynx-thist and tests/unit/test_fft link
!> -lfftw3).
!>
!> FFTW: M. Frigo and S. G. Johnson, "The design and implementation of FFTW3", Proc. IEEE
!> 93(2) 216-231 (2005); its Fortran 2003 interface (fftw3.f03, "Calling FFTW from Modern
!> Fortran" in the FFTW 3 manual): real-to-complex and complex-to-real plans on buffers from
!> fftw_alloc_real/fftw_alloc_complex (aligned), FFTW_ESTIMATE (no timing runs: the same
!> plan, hence the same bits, on every run), one plan per length reused for every segment
!> and column (fftw_execute_dft_r2c on the plan's own buffers). FFTW's transforms are
!> unnormalised: X(k) = sum_j x(j) exp(-2 pi i j k/N), the inverse returns N x.
!>
!> Power spectral density: Welch's method (P. D. Welch, "The use of fast Fourier transform for
!> the estimation of power spectra: a method based on time averaging over short, modified
!> periodograms", IEEE Trans. Audio Electroacoust. 15(2) 70-73, 1967): segments of N samples
!> overlapping by N/2, each multiplied by the periodic Hann window w(j) = sin^2(pi j/N), the
!> one-sided periodogram P(k) = c dt |X(k)|^2 / U, U = sum w^2, c = 2 except at k = 0 and
!> k = N/2 (c = 1), averaged over the segments; f(k) = k/(N dt), df = 1/(N dt). Units: the
!> signal's unit squared per Hz when dt is in s. Parseval per segment:
!>    sum_k P(k) df = sum_j (w x)^2 / U
!> exactly (to round-off), i.e. the windowed mean square; with the rectangular window
!> (w = 1) and one segment it is the mean square (1/N) sum x^2 (tests/unit/test_fft.f90).
!>
!> Transfer function H1 = Gxy/Gxx (J. S. Bendat and A. G. Piersol, "Random Data: Analysis
!> and Measurement Procedures", 4th ed., Wiley 2010, section 9.2): cross spectrum
!> Gxy = conj(X) Y averaged over the same Welch segments, with the coherence
!> gamma^2 = |Gxy|^2/(Gxx Gyy).
!>
!> FFT low pass: the signal less the straight line through its first and last samples (so
!> the periodic extension has no jump), transformed, every bin above fc set to zero, back
!> transformed, the line added again. A brick-wall filter: no attenuation below fc, total
!> above, with long ringing near sharp events (Gibbs, about 9 % of a jump; the CFC filter of
!> dx_sae overshoots a step by 3.4 % and settles within a few 1/fd).
module dx_fft
   use, intrinsic :: iso_c_binding
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   implicit none
   include 'fftw3.f03'
   private
   public :: rfft_t, psd_welch, transfer_h1, fft_lowpass

   !> One real transform length with its forward (r2c) and backward (c2r) plans and buffers.
   type :: rfft_t
      integer :: n = 0
      type(c_ptr) :: pf = c_null_ptr, pb = c_null_ptr, pin = c_null_ptr, pout = c_null_ptr
      real(c_double), pointer :: r(:) => null()
      complex(c_double_complex), pointer :: c(:) => null()
   contains
      procedure :: init => rfft_init
      procedure :: forward => rfft_forward
      procedure :: backward => rfft_backward
      procedure :: destroy => rfft_destroy
   end type rfft_t

contains

   !> Plans for length n (an existing plan of the same length is kept: reuse).
   subroutine rfft_init(self, n)
      class(rfft_t), intent(inout) :: self
      integer, intent(in) :: n
      if (self%n == n) return
      call self%destroy()
      self%n = n
      self%pin = fftw_alloc_real(int(n, c_size_t))
      self%pout = fftw_alloc_complex(int(n/2 + 1, c_size_t))
      call c_f_pointer(self%pin, self%r, [n])
      call c_f_pointer(self%pout, self%c, [n/2 + 1])
      self%pf = fftw_plan_dft_r2c_1d(int(n, c_int), self%r, self%c, FFTW_ESTIMATE)
      self%pb = fftw_plan_dft_c2r_1d(int(n, c_int), self%c, self%r, FFTW_ESTIMATE)
   end subroutine rfft_init

   !> xf(0:n/2) = the unnormalised transform of x(1:n).
   subroutine rfft_forward(self, x, xf)
      class(rfft_t), intent(inout) :: self
      real(wp), intent(in) :: x(:)
      complex(wp), intent(out) :: xf(0:)
      self%r = x
      call fftw_execute_dft_r2c(self%pf, self%r, self%c)
      xf(0:self%n/2) = self%c
   end subroutine rfft_forward

   !> x(1:n) = the inverse of xf(0:n/2), normalised (divided by n).
   subroutine rfft_backward(self, xf, x)
      class(rfft_t), intent(inout) :: self
      complex(wp), intent(in) :: xf(0:)
      real(wp), intent(out) :: x(:)
      self%c = xf(0:self%n/2)
      call fftw_execute_dft_c2r(self%pb, self%c, self%r)
      x = self%r/real(self%n, wp)
   end subroutine rfft_backward

   subroutine rfft_destroy(self)
      class(rfft_t), intent(inout) :: self
      if (c_associated(self%pf)) call fftw_destroy_plan(self%pf)
      if (c_associated(self%pb)) call fftw_destroy_plan(self%pb)
      if (c_associated(self%pin)) call fftw_free(self%pin)
      if (c_associated(self%pout)) call fftw_free(self%pout)
      self%pf = c_null_ptr
      self%pb = c_null_ptr
      self%pin = c_null_ptr
      self%pout = c_null_ptr
      self%r => null()
      self%c => null()
      self%n = 0
   end subroutine rfft_destroy

   !> The segment length for nseg requested segments of a signal of n samples (50 % overlap):
   !> the even number nearest 2 n/(nseg + 1); nseg = 1: the whole signal (even length).
   pure function seg_length(n, nseg) result(m)
      integer, intent(in) :: n, nseg
      integer :: m
      if (nseg <= 1) then
         m = n - mod(n, 2)
      else
         m = 2*((2*n/(nseg + 1))/2)
      end if
   end function seg_length

   !> Welch PSD of x (step dt): f(0:m/2), p(0:m/2). nseg: number of half-overlapping
   !> segments wanted (the segment length follows); hann: Hann window (else rectangular).
   subroutine psd_welch(x, dt, nseg, hann, f, p, error)
      real(wp), intent(in) :: x(:), dt
      integer, intent(in) :: nseg
      logical, intent(in) :: hann
      real(wp), allocatable, intent(out) :: f(:), p(:)
      type(error_t), allocatable, intent(out) :: error
      complex(wp), allocatable :: gxy(:)
      real(wp), allocatable :: gyy(:), coh(:)
      call spectra(x, x, dt, nseg, hann, f, p, gxy, gyy, coh, error)
   end subroutine psd_welch

   !> H1 transfer function from input x to output y (same step dt): h(0:m/2) = Gxy/Gxx and
   !> the coherence; f as psd_welch. A bin with Gxx = 0 gets H = 0 and coherence 0.
   subroutine transfer_h1(x, y, dt, nseg, hann, f, h, coh, error)
      real(wp), intent(in) :: x(:), y(:), dt
      integer, intent(in) :: nseg
      logical, intent(in) :: hann
      real(wp), allocatable, intent(out) :: f(:), coh(:)
      complex(wp), allocatable, intent(out) :: h(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: gxx(:), gyy(:)
      complex(wp), allocatable :: gxy(:)
      integer :: k
      if (size(x) /= size(y)) then
         call set_error(error, 'transfer function: input and output differ in length', &
                        EXIT_INPUT)
         return
      end if
      call spectra(x, y, dt, nseg, hann, f, gxx, gxy, gyy, coh, error)
      if (allocated(error)) return
      allocate(h(0:size(f) - 1))
      do k = 0, size(f) - 1
         if (gxx(k) > 0.0_wp) then
            h(k) = gxy(k)/gxx(k)
         else
            h(k) = (0.0_wp, 0.0_wp)
         end if
      end do
   end subroutine transfer_h1

   !> The Welch auto and cross spectra (one-sided, per Hz) of x and y.
   subroutine spectra(x, y, dt, nseg, hann, f, gxx, gxy, gyy, coh, error)
      real(wp), intent(in) :: x(:), y(:), dt
      integer, intent(in) :: nseg
      logical, intent(in) :: hann
      real(wp), allocatable, intent(out) :: f(:), gxx(:), gyy(:), coh(:)
      complex(wp), allocatable, intent(out) :: gxy(:)
      type(error_t), allocatable, intent(out) :: error
      type(rfft_t) :: fft
      real(wp), allocatable :: w(:)
      complex(wp), allocatable :: xf(:), yf(:)
      real(wp) :: u, c
      integer :: n, m, s, ns, j, k, i0
      real(wp), parameter :: PI = 3.14159265358979323846264338327950288_wp
      n = size(x)
      m = seg_length(n, nseg)
      if (m < 4) then
         call set_error(error, 'spectrum: too few samples for the segments asked for', &
                        EXIT_INPUT)
         return
      end if
      if (.not. (dt > 0.0_wp)) then
         call set_error(error, 'spectrum: the step must be > 0', EXIT_INPUT)
         return
      end if
      allocate(w(m))
      if (hann) then
         do j = 1, m
            w(j) = sin(PI*real(j - 1, wp)/real(m, wp))**2
         end do
      else
         w = 1.0_wp
      end if
      u = sum(w**2)
      ns = 1
      if (nseg > 1) ns = (n - m)/(m/2) + 1
      allocate(f(0:m/2), gxx(0:m/2), gyy(0:m/2), coh(0:m/2), gxy(0:m/2), xf(0:m/2), yf(0:m/2))
      gxx = 0.0_wp
      gyy = 0.0_wp
      gxy = (0.0_wp, 0.0_wp)
      call fft%init(m)
      do s = 1, ns
         i0 = (s - 1)*(m/2)
         call fft%forward(w*x(i0 + 1:i0 + m), xf)
         call fft%forward(w*y(i0 + 1:i0 + m), yf)
         gxx = gxx + real(xf*conjg(xf), wp)
         gyy = gyy + real(yf*conjg(yf), wp)
         gxy = gxy + conjg(xf)*yf
      end do
      call fft%destroy()
      do k = 0, m/2
         c = 2.0_wp
         if (k == 0 .or. k == m/2) c = 1.0_wp
         f(k) = real(k, wp)/(real(m, wp)*dt)
         gxx(k) = c*dt*gxx(k)/(u*real(ns, wp))
         gyy(k) = c*dt*gyy(k)/(u*real(ns, wp))
         gxy(k) = c*dt*gxy(k)/(u*real(ns, wp))
         coh(k) = 0.0_wp
         if (gxx(k) > 0.0_wp .and. gyy(k) > 0.0_wp) &
            coh(k) = real(gxy(k)*conjg(gxy(k)), wp)/(gxx(k)*gyy(k))
      end do
   end subroutine spectra

   !> y = x low-passed at fc (Hz, dt in s) by zeroing the bins above fc (see the header).
   subroutine fft_lowpass(x, dt, fc, y, error)
      real(wp), intent(in) :: x(:), dt, fc
      real(wp), allocatable, intent(out) :: y(:)
      type(error_t), allocatable, intent(out) :: error
      type(rfft_t) :: fft
      complex(wp), allocatable :: xf(:)
      real(wp), allocatable :: line(:)
      integer :: n, k
      n = size(x)
      if (n < 2 .or. .not. (fc > 0.0_wp) .or. .not. (dt > 0.0_wp)) then
         call set_error(error, 'FFT low pass: need 2 samples, a cut-off > 0 and a step > 0', &
                        EXIT_INPUT)
         return
      end if
      allocate(line(n), y(n), xf(0:n/2))
      do k = 1, n
         line(k) = x(1) + (x(n) - x(1))*real(k - 1, wp)/real(n - 1, wp)
      end do
      call fft%init(n)
      call fft%forward(x - line, xf)
      do k = 0, n/2
         if (real(k, wp)/(real(n, wp)*dt) > fc) xf(k) = (0.0_wp, 0.0_wp)
      end do
      call fft%backward(xf, y)
      call fft%destroy()
      y = y + line
   end subroutine fft_lowpass
end module dx_fft
