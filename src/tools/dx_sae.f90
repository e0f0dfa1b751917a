!> SAE J211-1 / ISO 6487 channel frequency class (CFC) filter and linear resampling of a
!> time history onto a uniform step (the tools dynx-thist and dynx-plot).
!>
!> The filter is the one the standards write in their appendix (SAE J211-1 (R) MAR95,
!> "Instrumentation for Impact Test - Part 1 - Electronic Instrumentation", Appendix C;
!> ISO 6487:2015, "Road vehicles - Measurement techniques in impact tests - Instrumentation",
!> Annex A): a 2-pole Butterworth low pass by the bilinear transform, run forward and then
!> backward over the data (zero phase, 4 poles in all):
!>    wd = 2 pi CFC 2.0775           (SAE J211; ISO 6487 writes 2 pi CFC 1.25 5/3)
!>    wa = sin(wd T/2) / cos(wd T/2)
!>    a0 = wa^2 / (1 + sqrt(2) wa + wa^2),  a1 = 2 a0,  a2 = a0
!>    b1 = -2 (wa^2 - 1) / (1 + sqrt(2) wa + wa^2)
!>    b2 = (-1 + sqrt(2) wa - wa^2) / (1 + sqrt(2) wa + wa^2)
!>    Y(t) = a0 X(t) + a1 X(t-1) + a2 X(t-2) + b1 Y(t-1) + b2 Y(t-2)
!> with T the sample period (the data must be on a uniform step: resample first).
!>
!> Magnitude (derived here, checked by tests/unit/test_sae.f90): the recursion is the bilinear
!> image s = (1 - z^-1)/(wa (1 + z^-1)) of H(s) = 1/(s^2 + sqrt(2) s + 1), so at frequency f
!> |H1|^2 = 1/(1 + (tan(pi f T)/wa)^4); the forward-backward pass multiplies H1 by its
!> conjugate, so the filter's gain is
!>    G(f) = |H1(f)|^2 = 1/(1 + (tan(pi f T)/tan(pi fd T))^4),   fd = wd/(2 pi),
!> which for f T << 1 is the analog 1/(1 + (f/fd)^4); G = 1/sqrt(2) (-3 dB) at
!> f = fd (sqrt(2) - 1)^(1/4) = 0.8022 fd = 1.667 CFC (100, 300, 1000, 1650 Hz for CFC 60,
!> 180, 600, 1000: the standards' FN).
!>
!> Start-up: J211-1 asks for at least 10 ms of pre-event data ahead of the filter. dynx
!> histories start at time 0, so the data are padded at both ends by point reflection
!> (x(1-k) = 2 x(1) - x(1+k), likewise at the end), npad = max(10 ms, 4/fd) of samples but
!> no more than n - 1 (the standard leaves the initial state open), and each pass starts in
!> the steady state of the straight line through its first two samples (one_pass), so a
!> constant passes unchanged and a ramp stays the ramp; the padding is dropped afterwards.
!>
!> The response corridor (cfc_corridor) follows J211-1's Figure 1 / ISO 6487's Figure 1 for
!> CFC 60 to 1000: FL = 0.1 Hz, FH = CFC, FN = 5/3 CFC (the standards print FN = 100, 300,
!> 1000, 1650 Hz); between FL and FH +0.5/-0.5 dB (-1 dB at FH), at FN +0.5/-4 dB, above FN
!> the upper bound falls by 9 dB/octave to -30 dB and the lower bound by 24 dB/octave (then
!> unbounded). The printed standard was not at hand when this was written: the breakpoints
!> are the commonly quoted ones and should be checked against it; the gain G(f) lies well
!> inside them (tests/unit/test_sae.f90).
!>
!> Resampling: dynx writes a history at the first cycle after each requested time, so the
!> spacing jitters by a few per cent. resample_linear puts the samples on t0 + k dt by
!> linear interpolation between the two neighbouring input samples (exact for a linear
!> signal; for a smooth signal the error is h^2/8 |x''| with h the input spacing).
module dx_sae
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT
   implicit none
   private
   public :: cfc_coefficients, cfc_filter, cfc_gain, cfc_design_frequency, cfc_corridor, &
             resample_linear, interp_linear, SAE_J211, ISO_6487

   integer, parameter :: SAE_J211 = 1, ISO_6487 = 2
   real(wp), parameter :: PI = 3.14159265358979323846264338327950288_wp

contains

   !> The design frequency fd (Hz) of a CFC: 2.0775 CFC (SAE J211) or 1.25*5/3 CFC (ISO 6487).
   pure function cfc_design_frequency(cfc, std) result(fd)
      real(wp), intent(in) :: cfc
      integer, intent(in) :: std
      real(wp) :: fd
      if (std == ISO_6487) then
         fd = cfc*1.25_wp*5.0_wp/3.0_wp
      else
         fd = cfc*2.0775_wp
      end if
   end function cfc_design_frequency

   !> a0, a1, a2, b1, b2 of the standard's recursion for class cfc and sample period dt (s).
   subroutine cfc_coefficients(cfc, dt, std, a, b, error)
      real(wp), intent(in) :: cfc, dt
      integer, intent(in) :: std
      real(wp), intent(out) :: a(0:2), b(1:2)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: wd, wa, den
      a = 0.0_wp
      b = 0.0_wp
      if (.not. (cfc > 0.0_wp) .or. .not. (dt > 0.0_wp)) then
         call set_error(error, 'CFC filter: the class and the sample period must be > 0', &
                        EXIT_INPUT)
         return
      end if
      wd = 2.0_wp*PI*cfc_design_frequency(cfc, std)
      if (wd*dt/2.0_wp >= 0.98_wp*PI/2.0_wp) then
         call set_error(error, 'CFC filter: the design frequency is above the Nyquist '// &
                        'frequency of the sample period (sample faster, or resample to a '// &
                        'smaller --dt)', EXIT_INPUT)
         return
      end if
      wa = sin(wd*dt/2.0_wp)/cos(wd*dt/2.0_wp)
      den = 1.0_wp + sqrt(2.0_wp)*wa + wa**2
      a(0) = wa**2/den
      a(1) = 2.0_wp*a(0)
      a(2) = a(0)
      b(1) = -2.0_wp*(wa**2 - 1.0_wp)/den
      b(2) = (-1.0_wp + sqrt(2.0_wp)*wa - wa**2)/den
   end subroutine cfc_coefficients

   !> The forward-backward filter's gain G(f) (see the header) at frequency f (Hz).
   pure function cfc_gain(cfc, dt, std, f) result(g)
      real(wp), intent(in) :: cfc, dt, f
      integer, intent(in) :: std
      real(wp) :: g
      g = 1.0_wp/(1.0_wp + (tan(PI*f*dt)/tan(PI*cfc_design_frequency(cfc, std)*dt))**4)
   end function cfc_gain

   !> The standard's corridor at frequency f (Hz): lower and upper gain bounds in dB.
   pure subroutine cfc_corridor(cfc, f, lo_db, hi_db)
      real(wp), intent(in) :: cfc, f
      real(wp), intent(out) :: lo_db, hi_db
      real(wp) :: fh, fn
      fh = cfc
      fn = cfc*5.0_wp/3.0_wp
      if (f <= fh) then
         hi_db = 0.5_wp
         lo_db = -0.5_wp - 0.5_wp*max(0.0_wp, log(f/0.1_wp))/log(fh/0.1_wp)
      else if (f <= fn) then
         hi_db = 0.5_wp
         lo_db = -1.0_wp - 3.0_wp*log(f/fh)/log(fn/fh)
      else
         hi_db = max(0.5_wp - 9.0_wp*log(f/fn)/log(2.0_wp), -30.0_wp)
         lo_db = -4.0_wp - 24.0_wp*log(f/fn)/log(2.0_wp)
      end if
   end subroutine cfc_corridor

   !> y = x filtered with class cfc (sample period dt in s), forward then backward, padded
   !> at both ends as the header states. std: SAE_J211 (default) or ISO_6487.
   subroutine cfc_filter(x, dt, cfc, y, error, std)
      real(wp), intent(in) :: x(:), dt, cfc
      real(wp), allocatable, intent(out) :: y(:)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in), optional :: std
      real(wp) :: a(0:2), b(1:2)
      real(wp), allocatable :: p(:)
      integer :: n, npad, k, s
      s = SAE_J211
      if (present(std)) s = std
      n = size(x)
      call cfc_coefficients(cfc, dt, s, a, b, error)
      if (allocated(error)) return
      if (n < 3) then
         call set_error(error, 'CFC filter: need at least 3 samples', EXIT_INPUT)
         return
      end if
      npad = max(ceiling(0.010_wp/dt), ceiling(4.0_wp/(cfc_design_frequency(cfc, s)*dt)))
      npad = min(npad, n - 1)
      allocate(p(1 - npad:n + npad))
      p(1:n) = x
      do k = 1, npad
         p(1 - k) = 2.0_wp*x(1) - x(1 + k)
         p(n + k) = 2.0_wp*x(n) - x(n - k)
      end do
      call one_pass(p, a, b)
      p = p(ubound(p, 1):lbound(p, 1):-1)
      call one_pass(p, a, b)
      p = p(ubound(p, 1):lbound(p, 1):-1)
      y = p(1:n)
   end subroutine cfc_filter

   !> One pass of the recursion over p in place, started in the steady state of the line
   !> through p(1) and p(2): X history p(1) - s, p(1) - 2 s and Y history X - s tau, with
   !> s = p(2) - p(1) and tau = 1 + (b1 + 2 b2)/(1 - b1 - b2) the recursion's delay at zero
   !> frequency (in samples), so a constant or a ramp passes without a start-up transient.
   pure subroutine one_pass(p, a, b)
      real(wp), intent(inout) :: p(:)
      real(wp), intent(in) :: a(0:2), b(1:2)
      real(wp) :: x1, x2, y1, y2, x0, y0, s, tau
      integer :: k
      s = p(2) - p(1)
      tau = 1.0_wp + (b(1) + 2.0_wp*b(2))/(1.0_wp - b(1) - b(2))
      x1 = p(1) - s
      x2 = p(1) - 2.0_wp*s
      y1 = x1 - s*tau
      y2 = x2 - s*tau
      do k = 1, size(p)
         x0 = p(k)
         y0 = a(0)*x0 + a(1)*x1 + a(2)*x2 + b(1)*y1 + b(2)*y2
         p(k) = y0
         x2 = x1
         x1 = x0
         y2 = y1
         y1 = y0
      end do
   end subroutine one_pass

   !> (tu, xu) = x(t) on the uniform times t(1) + k dt, k = 0 .. floor((t(n) - t(1))/dt),
   !> by linear interpolation. t must increase strictly.
   subroutine resample_linear(t, x, dt, tu, xu, error)
      real(wp), intent(in) :: t(:), x(:), dt
      real(wp), allocatable, intent(out) :: tu(:), xu(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: n, m, k
      n = size(t)
      if (n < 2 .or. .not. (dt > 0.0_wp)) then
         call set_error(error, 'resample: need at least 2 samples and a step > 0', EXIT_INPUT)
         return
      end if
      ! the last sample within round-off of t(n) counts (t(n) - t(1) a multiple of dt)
      m = max(1, floor((t(n) - t(1))/dt*(1.0_wp + 1.0e-12_wp)) + 1)
      allocate(tu(m))
      do k = 1, m
         tu(k) = min(t(1) + real(k - 1, wp)*dt, t(n))
      end do
      call interp_linear(t, x, tu, xu, error)
   end subroutine resample_linear

   !> xq = x(t) at the increasing times tq (each within [t(1), t(n)]), linear interpolation;
   !> t must increase strictly.
   subroutine interp_linear(t, x, tq, xq, error)
      real(wp), intent(in) :: t(:), x(:), tq(:)
      real(wp), allocatable, intent(out) :: xq(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: n, k, j
      real(wp) :: w
      n = size(t)
      if (n < 2) then
         call set_error(error, 'interpolation: need at least 2 samples', EXIT_INPUT)
         return
      end if
      do k = 2, n
         if (.not. (t(k) > t(k - 1))) then
            call set_error(error, 'interpolation: the times do not increase', EXIT_INPUT)
            return
         end if
      end do
      allocate(xq(size(tq)))
      j = 1
      do k = 1, size(tq)
         do while (j < n - 1 .and. t(j + 1) < tq(k))
            j = j + 1
         end do
         w = (tq(k) - t(j))/(t(j + 1) - t(j))
         xq(k) = (1.0_wp - w)*x(j) + w*x(j + 1)
      end do
   end subroutine interp_linear
end module dx_sae
