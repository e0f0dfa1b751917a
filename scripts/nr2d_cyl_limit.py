#!/usr/bin/python3
"""The continuum limit of *BOUNDARY_NON_REFLECTING_2D on a plane-strain cylindrical P wave
(regression nr2d_cylinder; not a test, a reference figure for its check's comment).

  nr2d_cyl_limit.py REF R NODE

The field about a hole is purely radial: phi = A H0(1)(kr) + B H0(2)(kr) (e^{-i w t}),
u_r = phi', sigma_rr = -(lambda + 2 mu) k^2 phi - 2 mu phi'/r. The dashpot sets sigma_rr =
-rho c_d v_r at r = R (Lysmer & Kuhlemeyer 1969); with x = kR, s = (c_s/c_d)^2:
D(H) = -H0 + 2 s H1/x + i H1, B/A = -D(H(1))/D(H(2)), and the incoming/outgoing radial
velocity at R is (B H1(2))/(A H1(1)) (the plane-wave impedance is exact only as kR -> inf;
Kausel 1988). Applied to the incident radial velocity of NODE (on the 45 degree ray) in the
run REF without reflection (its nodout), frequency by frequency (FFT, zero-padded x8): prints
the peak of the reflected radial velocity at R against the incident peak. Bessel functions
from their integral representations (Watson 1944, 6.21), trapezoidal. Steel of
gen_nr2d_decks.py; mm, ms, GPa.
"""
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ascii_out import nodout_series  # noqa: E402

E, NU, RHO = 210.0, 0.3, 7.85e-6
C = math.sqrt(E*(1 - NU)/((1 + NU)*(1 - 2*NU))/RHO)
S = (1 - 2*NU)/(2*(1 - NU))
TAU = np.linspace(0.0, math.pi, 4001)
TT = np.linspace(0.0, 12.0, 24001)


def trap(y, x):
    return float(np.sum((y[1:] + y[:-1])*np.diff(x))/2)


def hankel1(n, x):
    j = trap(np.cos(n*TAU - x*np.sin(TAU)), TAU)/math.pi
    y = (trap(np.sin(x*np.sin(TAU) - n*TAU), TAU)
         - trap((np.exp(n*TT) + (-1)**n*np.exp(-n*TT))*np.exp(-x*np.sinh(TT)), TT))/math.pi
    return j + 1j*y


def velocity_ratio(x):
    h0, h1 = hankel1(0, x), hankel1(1, x)
    g0, g1 = np.conj(h0), np.conj(h1)
    d1 = -h0 + 2*S*h1/x + 1j*h1
    d2 = -g0 + 2*S*g1/x + 1j*g1
    return -d1/d2*g1/h1


def main(argv):
    ref, r, node = argv[0], float(argv[1]), int(argv[2])
    rows = nodout_series(ref, 'vel')[node]
    t = np.array([a for a, _ in rows])
    v = np.array([(b[0] + b[1])/math.sqrt(2.0) for _, b in rows])
    n = 8*len(t)
    spec = np.fft.rfft(v, n)
    w = 2*math.pi*np.fft.rfftfreq(n, t[1] - t[0])
    rv = np.array([0j] + [velocity_ratio(wi*r/C) for wi in w[1:]])
    rv[0] = rv[1]
    # numpy's synthesis is e^{+i w t}: the response there is the conjugate
    vr = np.fft.irfft(np.conj(rv)*spec, n)[:len(t)]
    print(f'kR at f = 250 1/ms (1/(2T), T = 2 us): {2*math.pi*250.0*r/C:.2f}; continuum '
          f'reflected/incident peak radial velocity at R = {r:g}: '
          f'{np.max(np.abs(vr))/np.max(np.abs(v)):.4f}')


if __name__ == '__main__':
    main(sys.argv[1:])
