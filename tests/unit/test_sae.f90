!> SAE J211-1 CFC filter and linear resampling (src/tools/dx_sae.f90).
!>  * sines through CFC 60 at 10 kHz: the steady amplitude ratio (a least-squares fit of
!>    sin and cos over whole periods in the middle of a 2 s signal, far from the padded ends)
!>    equals the forward-backward gain G(f) = 1/(1 + (tan(pi f T)/tan(pi fd T))^4) derived
!>    in dx_sae's header. Tolerance 1e-9 relative: the start-up transient decays as
!>    exp(-zeta wn t) (zeta wn = 2 pi fd / sqrt(2) = 554 1/s for fd = 124.65 Hz), so 0.5 s
!>    from the ends it is below 1e-100; the rest is round-off of 2e4 recursion steps.
!>    G also lies within 4 u^2/3 (relative, u = pi f T: the bilinear warping, tan(u)/u =
!>    1 + u^2/3 + ...) of the analog 1/(1 + (f/fd)^4), G = 1/sqrt(2)
!>    (-3 dB) at 100 Hz = 5/3 CFC within 0.3 %, and every measured gain lies in the
!>    standard's corridor (cfc_corridor); the phase is the input's to 1e-9 (zero phase).
!>  * the step response: 0 before and 1 after (1e-6: 50 ms = 28 time constants from the
!>    step), 0.5 at the step (the forward-backward filter's kernel is symmetric, the step
!>    lies half-way between two samples: 1e-9), and the overshoot of the analog gain
!>    1/(1 + (w/wd)^4): its impulse response is (wd/(2 sqrt 2)) exp(-a|t|)(cos(a t) +
!>    sin(a|t|)), a = wd/sqrt 2, first zero at a t = 3 pi/4, so the step peaks at
!>    1 + exp(-3 pi/4)/(2 sqrt 2) = 1.03352; the digital filter within 2 (pi fd T)^2
!>    relative (the bilinear warping), the undershoot before the step its mirror image.
!>  * a constant through every class is the constant (a0 + a1 + a2 + b1 + b2 = 1 to
!>    round-off; the gain 4 a0/(1 - b1 - b2) sums O(1) terms to 4 a0, so the tolerance is
!>    8 eps/a0 for the two passes); a ramp stays a ramp (the point-reflected padding and the steady start).
!>  * resampling a linear function on jittered times is exact (1e-12).
program test_sae
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_assert, only: check, check_close, assert_summary
   use dx_sae, only: cfc_filter, cfc_gain, cfc_coefficients, cfc_corridor, resample_linear, &
                     cfc_design_frequency, SAE_J211, ISO_6487
   implicit none
   real(wp), parameter :: PI = 3.14159265358979323846264338327950288_wp
   call test_sine_gain()
   call test_step()
   call test_constant()
   call test_resample()
   call test_coefficients()
   call assert_summary()
contains

   subroutine test_sine_gain()
      real(wp), parameter :: dt = 1.0e-4_wp, cfc = 60.0_wp
      real(wp), parameter :: freqs(7) = [10.0_wp, 40.0_wp, 60.0_wp, 100.0_wp, 150.0_wp, &
                                        200.0_wp, 300.0_wp]
      real(wp), allocatable :: x(:), y(:)
      type(error_t), allocatable :: error
      real(wp) :: f, g, amp, fd, lo, hi, gdb, ph
      integer :: n, k, i
      character(16) :: lab
      n = 20001
      allocate(x(n))
      fd = cfc_design_frequency(cfc, SAE_J211)
      do i = 1, size(freqs)
         f = freqs(i)
         do k = 1, n
            x(k) = sin(2.0_wp*PI*f*real(k - 1, wp)*dt + 0.3_wp)
         end do
         call cfc_filter(x, dt, cfc, y, error)
         call check(.not. allocated(error), 'cfc_filter runs')
         amp = fit_amplitude(y, dt, f, 5001, 15000, ph)
         g = cfc_gain(cfc, dt, SAE_J211, f)
         write(lab, '(f6.1)') f
         call check_close(amp, g, 0.0_wp, 1.0e-9_wp, 'CFC 60 gain at '//trim(adjustl(lab))// &
                          ' Hz = G(f)')
         ! bilinear warping: tan(u)/u = 1 + u^2/3 + ..., so G departs from the analog gain
         ! by at most 4 u^2/3 relative, u = pi f T
         call check_close(g, 1.0_wp/(1.0_wp + (f/fd)**4), 0.0_wp, &
                          4.0_wp/3.0_wp*(PI*f*dt)**2, &
                          'G(f) near the analog 1/(1+(f/fd)^4) at '//trim(adjustl(lab))//' Hz')
         call check_close(ph, 0.3_wp, 1.0e-9_wp, 0.0_wp, 'CFC 60 phase at '// &
                          trim(adjustl(lab))//' Hz = the input''s (zero phase)')
         call cfc_corridor(cfc, f, lo, hi)
         gdb = 20.0_wp*log10(amp)
         call check(gdb >= lo .and. gdb <= hi, 'CFC 60 gain in the J211 corridor at '// &
                    trim(adjustl(lab))//' Hz')
      end do
      call check_close(cfc_gain(cfc, dt, SAE_J211, 100.0_wp), 1.0_wp/sqrt(2.0_wp), 0.0_wp, &
                       3.0e-3_wp, 'CFC 60: -3 dB at 100 Hz')
   end subroutine test_sine_gain

   !> Amplitude and phase of the sine of frequency f in y(i0:i1) (least squares on sin, cos).
   function fit_amplitude(y, dt, f, i0, i1, phase) result(a)
      real(wp), intent(in) :: y(:), dt, f
      integer, intent(in) :: i0, i1
      real(wp), intent(out) :: phase
      real(wp) :: a, s11, s12, s22, r1, r2, c, s, det, p, q
      integer :: k
      s11 = 0; s12 = 0; s22 = 0; r1 = 0; r2 = 0
      do k = i0, i1
         s = sin(2.0_wp*PI*f*real(k - 1, wp)*dt)
         c = cos(2.0_wp*PI*f*real(k - 1, wp)*dt)
         s11 = s11 + s*s
         s12 = s12 + s*c
         s22 = s22 + c*c
         r1 = r1 + s*y(k)
         r2 = r2 + c*y(k)
      end do
      det = s11*s22 - s12**2
      p = (r1*s22 - r2*s12)/det
      q = (s11*r2 - s12*r1)/det
      a = sqrt(p**2 + q**2)
      phase = atan2(q, p)
   end function fit_amplitude

   subroutine test_step()
      real(wp), parameter :: dt = 1.0e-4_wp
      integer, parameter :: n = 2000
      real(wp) :: x(n)
      real(wp), allocatable :: y(:)
      type(error_t), allocatable :: error
      x(1:n/2) = 0.0_wp
      x(n/2 + 1:) = 1.0_wp
      call cfc_filter(x, dt, 60.0_wp, y, error)
      call check(.not. allocated(error), 'step: cfc_filter runs')
      call check_close(y(n/2 - 500), 0.0_wp, 1.0e-6_wp, 0.0_wp, 'step: 0 50 ms before')
      call check_close(y(n/2 + 500), 1.0_wp, 1.0e-6_wp, 0.0_wp, 'step: 1 50 ms after')
      call check_close(0.5_wp*(y(n/2) + y(n/2 + 1)), 0.5_wp, 1.0e-9_wp, 0.0_wp, &
                       'step: 0.5 half-way (zero phase)')
      call check_close(y(n/2) + y(n/2 + 1), 1.0_wp, 1.0e-9_wp, 0.0_wp, &
                       'step: antisymmetric about the step')
      call check_close(maxval(y) - 1.0_wp, exp(-0.75_wp*PI)/(2.0_wp*sqrt(2.0_wp)), 0.0_wp, &
                       2.0_wp*(PI*cfc_design_frequency(60.0_wp, SAE_J211)*dt)**2, &
                       'step: overshoot = exp(-3 pi/4)/(2 sqrt 2) of the analog filter')
      call check_close(minval(y), 1.0_wp - maxval(y), 1.0e-9_wp, 0.0_wp, &
                       'step: undershoot mirrors the overshoot')
   end subroutine test_step

   subroutine test_constant()
      real(wp), parameter :: classes(4) = [60.0_wp, 180.0_wp, 600.0_wp, 1000.0_wp]
      real(wp) :: x(500), r(500), tol, a(0:2), b(1:2)
      real(wp), allocatable :: y(:)
      type(error_t), allocatable :: error
      integer :: i, k
      x = 3.7_wp
      do k = 1, size(r)
         r(k) = -2.0_wp + 0.01_wp*real(k, wp)
      end do
      do i = 1, size(classes)
         call cfc_filter(x, 1.0e-5_wp, classes(i), y, error)
         ! round-off: the DC gain is 4 a0/(1 - b1 - b2), whose denominator sums O(1) terms
         ! to 4 a0 (a few ulps of 1 each): per pass a relative error of about 2 eps/a0;
         ! tolerance 8 eps/a0 for the two passes (a0 of the smaller, ISO or SAE)
         call cfc_coefficients(classes(i), 1.0e-5_wp, SAE_J211, a, b, error)
         tol = 8.0_wp*epsilon(1.0_wp)/a(0)
         write(*, '(a,es10.3,a,es10.3)') '  constant: max error ', &
            maxval(abs(y - 3.7_wp))/3.7_wp, ' tol ', tol
         call check(maxval(abs(y - 3.7_wp)) <= tol*3.7_wp, &
                    'a constant through CFC '//trim(str(classes(i)))//' is the constant')
         call cfc_filter(x, 1.0e-5_wp, classes(i), y, error, ISO_6487)
         call check(maxval(abs(y - 3.7_wp)) <= tol*3.7_wp, &
                    'a constant through ISO CFC '//trim(str(classes(i)))//' is the constant')
         call cfc_filter(r, 1.0e-5_wp, classes(i), y, error)
         call check(maxval(abs(y - r)) <= 1.0e-11_wp, &
                    'a ramp through CFC '//trim(str(classes(i)))//' is the ramp')
      end do
      call cfc_filter(x, 1.0e-3_wp, 1000.0_wp, y, error)
      call check(allocated(error), 'CFC 1000 at 1 kHz sampling: refused (above Nyquist)')
   end subroutine test_constant

   function str(x) result(s)
      real(wp), intent(in) :: x
      character(16) :: s
      write(s, '(i0)') nint(x)
   end function str

   subroutine test_resample()
      real(wp) :: t(200), x(200)
      real(wp), allocatable :: tu(:), xu(:)
      type(error_t), allocatable :: error
      integer :: k
      do k = 1, size(t)
         ! the first cycle after each requested time: jitter of up to 5 %
         t(k) = 1.0e-3_wp*(real(k - 1, wp) + 0.05_wp*mod(real(k*7, wp), 1.0_wp + &
                real(mod(k, 3), wp)))
         x(k) = 4.0_wp - 250.0_wp*t(k)
      end do
      call resample_linear(t, x, 0.7e-3_wp, tu, xu, error)
      call check(.not. allocated(error), 'resample runs')
      call check(maxval(abs(xu - (4.0_wp - 250.0_wp*tu))) <= 1.0e-12_wp, &
                 'resampled linear function exact')
      call check_close(tu(2) - tu(1), 0.7e-3_wp, 0.0_wp, 1.0e-12_wp, 'resample: uniform step')
      call check(tu(size(tu)) <= t(size(t)), 'resample: inside the data')
      t(5) = t(4)
      call resample_linear(t, x, 0.7e-3_wp, tu, xu, error)
      call check(allocated(error), 'resample: repeated time refused')
   end subroutine test_resample

   !> The coefficients satisfy a0 + a1 + a2 + b1 + b2 = 1 (unit gain at f = 0) and the
   !> poles lie inside the unit circle (|b2| < 1, |b1| < 1 - b2).
   subroutine test_coefficients()
      real(wp) :: a(0:2), b(1:2)
      type(error_t), allocatable :: error
      call cfc_coefficients(60.0_wp, 1.0e-4_wp, SAE_J211, a, b, error)
      call check_close(sum(a) + sum(b), 1.0_wp, 0.0_wp, 4.0e-16_wp, 'unit DC gain')
      call check(abs(b(2)) < 1.0_wp .and. abs(b(1)) < 1.0_wp - b(2), 'stable poles')
      call check_close(cfc_design_frequency(60.0_wp, SAE_J211), 124.65_wp, 0.0_wp, 1.0e-14_wp, &
                       'SAE fd = 2.0775 CFC')
      call check_close(cfc_design_frequency(60.0_wp, ISO_6487), 125.0_wp, 0.0_wp, 1.0e-14_wp, &
                       'ISO fd = 1.25 5/3 CFC')
   end subroutine test_coefficients
end program test_sae
