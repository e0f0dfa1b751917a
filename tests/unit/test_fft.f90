!> FFTW spectra, transfer function and FFT low pass (src/tools/dx_fft.f90).
!>  * Parseval: for a pseudo-random signal, sum_k PSD(k) df equals the mean square
!>    (1/N) sum x^2 with one rectangular segment, and the Hann-windowed mean square
!>    sum (w x)^2 / sum w^2 averaged over the Welch segments; round-off tolerance 1e-12
!>    relative (N = 4096: an FFT's relative error grows as eps log2 N, about 3e-15).
!>  * a sine of amplitude A on a bin: one rectangular segment puts A^2/2 (its mean square)
!>    in that one bin (PSD df), the other bins hold round-off (1e-12 of it).
!>  * H1 of y = 2.5 x is 2.5 with zero phase and coherence 1 in every bin (round-off); H1
!>    from noise to its CFC-filtered copy is the filter's gain G(f) within 5 standard errors
!>    of the H1 estimate (Bendat & Piersol eq. 9.90).
!>  * FFT low pass against its definition (a naive O(N^2) DFT of the detrended signal,
!>    truncated above fc, plus the line; 1e-11 relative for N = 200); a line and any signal
!>    cut above Nyquist come back unchanged.
!>  * a plan is reused for the same length (rfft_t%init keeps it).
program test_fft
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_assert, only: check, check_close, assert_summary
   use dx_fft, only: rfft_t, psd_welch, transfer_h1, fft_lowpass
   use dx_sae, only: cfc_filter, cfc_gain, SAE_J211
   implicit none
   real(wp), parameter :: PI = 3.14159265358979323846264338327950288_wp
   call test_parseval()
   call test_sine_bin()
   call test_h1()
   call test_h1_cfc()
   call test_lowpass()
   call test_plan_reuse()
   call assert_summary()
contains

   !> A reproducible pseudo-random sequence in [-1, 1] (a linear congruential generator).
   subroutine noise(x)
      real(wp), intent(out) :: x(:)
      integer(8) :: s
      integer :: k
      s = 12345_8
      do k = 1, size(x)
         s = mod(1103515245_8*s + 12345_8, 2147483648_8)
         x(k) = 2.0_wp*real(s, wp)/2147483648.0_wp - 1.0_wp
      end do
   end subroutine noise

   subroutine test_parseval()
      integer, parameter :: n = 4096, nseg = 7
      real(wp) :: x(n), dt, df, ms, w(n)
      real(wp), allocatable :: f(:), p(:)
      type(error_t), allocatable :: error
      integer :: m, ns, s, i0, j
      dt = 1.0e-4_wp
      call noise(x)
      x = x + 0.3_wp
      call psd_welch(x, dt, 1, .false., f, p, error)
      call check(.not. allocated(error), 'psd one segment runs')
      df = f(1) - f(0)
      call check_close(sum(p)*df, sum(x**2)/real(n, wp), 0.0_wp, 1.0e-12_wp, &
                       'Parseval, one rectangular segment: sum PSD df = mean square')
      call psd_welch(x, dt, nseg, .true., f, p, error)
      call check(.not. allocated(error), 'psd Welch Hann runs')
      df = f(1) - f(0)
      m = 2*(size(f) - 1)
      ns = (n - m)/(m/2) + 1
      do j = 1, m
         w(j) = sin(PI*real(j - 1, wp)/real(m, wp))**2
      end do
      ms = 0.0_wp
      do s = 1, ns
         i0 = (s - 1)*(m/2)
         ms = ms + sum((w(1:m)*x(i0 + 1:i0 + m))**2)/sum(w(1:m)**2)
      end do
      ms = ms/real(ns, wp)
      call check_close(sum(p)*df, ms, 0.0_wp, 1.0e-12_wp, &
                       'Parseval, Welch Hann: sum PSD df = windowed mean square')
      call check(ns == nseg, 'Welch: the segments asked for')
      call check_close(f(1), 1.0_wp/(real(m, wp)*dt), 0.0_wp, 1.0e-14_wp, 'df = 1/(N dt)')
   end subroutine test_parseval

   subroutine test_sine_bin()
      integer, parameter :: n = 1024, kb = 37
      real(wp) :: x(n), dt
      real(wp), allocatable :: f(:), p(:)
      type(error_t), allocatable :: error
      integer :: j
      dt = 1.0e-3_wp
      do j = 1, n
         x(j) = 3.0_wp*sin(2.0_wp*PI*real(kb*(j - 1), wp)/real(n, wp) + 0.4_wp)
      end do
      call psd_welch(x, dt, 1, .false., f, p, error)
      call check_close(p(kb)*(f(1) - f(0)), 4.5_wp, 0.0_wp, 1.0e-12_wp, &
                       'sine on bin 37: PSD df = A^2/2')
      call check(maxval(p(0:kb - 1)) < 1.0e-12_wp*p(kb) .and. &
                 maxval(p(kb + 1:)) < 1.0e-12_wp*p(kb), 'sine on a bin: no leakage')
      call check_close(f(kb), real(kb, wp)/(real(n, wp)*dt), 0.0_wp, 1.0e-14_wp, &
                       'bin frequency k/(N dt)')
   end subroutine test_sine_bin

   subroutine test_h1()
      integer, parameter :: n = 2048
      real(wp) :: x(n)
      real(wp), allocatable :: f(:), coh(:)
      complex(wp), allocatable :: h(:)
      type(error_t), allocatable :: error
      call noise(x)
      call transfer_h1(x, 2.5_wp*x, 1.0e-3_wp, 8, .true., f, h, coh, error)
      call check(.not. allocated(error), 'H1 runs')
      call check(maxval(abs(h(1:) - 2.5_wp)) < 1.0e-12_wp, 'H1 of 2.5 x is 2.5 (zero phase)')
      call check(maxval(abs(coh(1:) - 1.0_wp)) < 1.0e-12_wp, 'coherence 1')
      call transfer_h1(x, x(1:n - 1), 1.0e-3_wp, 8, .true., f, h, coh, error)
      call check(allocated(error), 'H1: lengths differ refused')
   end subroutine test_h1

   !> Against the definition: the line through the end samples plus the inverse of the
   !> truncated DFT of the rest, by a naive O(N^2) DFT (relative error about N eps).
   !> H1 from white noise to its CFC-filtered copy is the filter's gain G(f) (real: the
   !> forward-backward filter has zero phase), within the random error of an H1 estimate
   !> (Bendat & Piersol, Random Data, 4th ed., eq. 9.90): |H1 - G| <= 5 |G| e with
   !> e = sqrt((1 - gamma^2)/(2 nd gamma^2)), nd the number of segments. The "noise" is the
   !> filter acting on the whole record while the window cuts each segment (coherence
   !> 1 - gamma^2 about 1e-5 to 1e-3 here); 5 standard errors over 150 bins.
   subroutine test_h1_cfc()
      integer, parameter :: n = 16384
      real(wp), parameter :: dt = 1.0e-4_wp, cfc = 240.0_wp   ! fd = 498.6 Hz = 0.05 fs
      real(wp) :: x(n), g, e, worst
      real(wp), allocatable :: y(:), f(:), coh(:)
      complex(wp), allocatable :: h(:)
      type(error_t), allocatable :: error
      integer :: k, nb, m, nd
      logical :: ok
      call noise(x)
      call cfc_filter(x, dt, cfc, y, error)
      call transfer_h1(x, y, dt, 31, .true., f, h, coh, error)
      call check(.not. allocated(error) .and. size(f) == 513, 'H1 of a CFC filter runs')
      m = 2*(size(f) - 1)
      nd = (n - m)/(m/2) + 1
      ok = .true.
      nb = 0
      worst = 0.0_wp
      do k = 1, size(f) - 1
         g = cfc_gain(cfc, dt, SAE_J211, f(k))
         if (g < 0.01_wp) cycle
         nb = nb + 1
         e = sqrt((1.0_wp - coh(k))/(2.0_wp*real(nd, wp)*coh(k)))
         worst = max(worst, abs(h(k) - g)/(g*e + 1.0e-300_wp))
         ok = ok .and. abs(h(k) - g) <= 5.0_wp*g*e + 1.0e-12_wp
      end do
      write(*, '(a,f6.2,a,i0,a,i0,a)') '  H1 vs G(f): worst |H1 - G| = ', worst, &
         ' standard errors (', nb, ' bins, ', nd, ' segments)'
      call check(ok .and. nb > 100, 'H1 of noise through CFC 240 = G(f) within 5 standard errors')
   end subroutine test_h1_cfc

   subroutine test_lowpass()
      integer, parameter :: n = 200
      real(wp) :: x(n), ref(n), line(n), r(n), dt, t, fc
      complex(wp) :: c
      real(wp), allocatable :: y(:)
      type(error_t), allocatable :: error
      integer :: j, k, kk
      dt = 1.0e-4_wp            ! 0.02 s: 50 Hz bins
      fc = 1200.0_wp
      call noise(r)
      do j = 1, n
         t = real(j - 1, wp)*dt
         x(j) = 2.0_wp*sin(2.0_wp*PI*150.0_wp*t) + 1.0_wp + 30.0_wp*t/0.02_wp + 0.5_wp*r(j)
      end do
      do j = 1, n
         line(j) = x(1) + (x(n) - x(1))*real(j - 1, wp)/real(n - 1, wp)
      end do
      ref = line
      do k = -n/2 + 1, n/2
         if (abs(real(k, wp))/(real(n, wp)*dt) > fc) cycle
         kk = modulo(k, n)
         c = (0.0_wp, 0.0_wp)
         do j = 1, n
            c = c + (x(j) - line(j))*exp(cmplx(0.0_wp, -2.0_wp*PI*real(kk*(j - 1), wp)/real(n, wp), wp))
         end do
         do j = 1, n
            ref(j) = ref(j) + real(c*exp(cmplx(0.0_wp, 2.0_wp*PI*real(kk*(j - 1), wp)/real(n, wp), &
                     wp)), wp)/real(n, wp)
         end do
      end do
      call fft_lowpass(x, dt, fc, y, error)
      call check(.not. allocated(error), 'FFT low pass runs')
      call check(maxval(abs(y - ref)) < 1.0e-11_wp*maxval(abs(x)), &
                 'FFT low pass = line + truncated DFT (naive DFT reference)')
      call check(maxval(abs(y - x)) > 0.1_wp, 'FFT low pass removes the noise above fc')
      call fft_lowpass(x, dt, 1.0e6_wp, y, error)
      call check(maxval(abs(y - x)) < 1.0e-12_wp*maxval(abs(x)), &
                 'FFT low pass above Nyquist: identity')
      call fft_lowpass(line, dt, 100.0_wp, y, error)
      call check(maxval(abs(y - line)) < 1.0e-12_wp*maxval(abs(line)), &
                 'FFT low pass of a line: the line')
   end subroutine test_lowpass

   subroutine test_plan_reuse()
      type(rfft_t) :: fft
      real(wp) :: x(64), back(64)
      complex(wp) :: xf(0:32)
      call noise(x)
      call fft%init(64)
      call fft%forward(x, xf)
      call fft%init(64)
      call fft%backward(xf, back)
      call check(maxval(abs(back - x)) < 1.0e-14_wp, 'forward then backward: identity')
      call check_close(real(xf(0), wp), sum(x), 1.0e-13_wp, 0.0_wp, 'X(0) = sum x')
      call fft%destroy()
   end subroutine test_plan_reuse
end program test_fft
