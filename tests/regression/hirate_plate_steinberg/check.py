#!/usr/bin/python3
"""Plate impact in uniaxial strain: Steinberg-Guinan copper + *EOS_GRUNEISEN driven at up
(usage: check.py OUTDIR [G0=.. Y0=.. b=..]; the defaults are the SCG copper; hirate_plate_hydro
passes b=0 for *MAT_ELASTIC_PLASTIC_HYDRO, whose G and yield stress do not depend on p).
Checks (stress profile at the last state, nodout of node 201 at x = 50 mm):
  - elastic precursor front at cL t, cL = sqrt((K + 4 G0/3)/rho0), K = rho0 C**2;
  - its amplitude, the Hugoniot elastic limit: Y0 (1 - nu)/(1 - 2 nu) = 0.2545 GPa at the
    moduli of the reference state; with G and Y stiffened by the pressure (b p V**(1/3)) and the
    Gruneisen pressure, integrated here in small steps of a material point to first yield;
  - the particle velocity behind the precursor, u1 = sigma_HEL/(rho0 cL) (elastic jump), and
    behind the shock, up;
  - the shock: momentum jump from the precursor state (sigma1, u1, rho1) to (sigma2, up),
    sigma2 - sigma1 = rho1 (Us - u1)(up - u1), with Us from the shock front (half amplitude)
    and sigma2 the plateau behind it.
Tolerances: fronts within 3 elements (the viscous width, Q1 = 1.5, as elastic_wave); the HEL
and the particle velocities within 0.2 % and 0.5 %
(the plateaus are flat to 1e-5 and the HEL is reached in ~100 steps of the element, G(p)
lagging one step of 1/100 of the pressure: 0.01 %); the jump (the
shock front located to half an element of 74 mm at t: 0.2 % of Us, and the jump itself 0.3 %
from the strength gradient behind the front), within 0.5 %. Measured: precursor +0.49 mm
(2 elements), HEL 0.01 %, shock jump 0.14 %, u1 0.19 %, up 0.001 %."""
import math
import sys
sys.path.insert(0, 'scripts')
import dxpost as d

out = sys.argv[1]
rho, C, S1, up = 8.93e-6, 3940.0, 1.489, 100.0
G0, Y0, b = 47.7, 0.12, 0.0283
for arg in sys.argv[2:]:          # overrides for the other models: G0=, Y0=, b=
    k, v = arg.split('=')
    if k == 'G0':
        G0 = float(v)
    elif k == 'Y0':
        Y0 = float(v)
    elif k == 'b':
        b = float(v)
    else:
        sys.exit('check.py: unknown argument ' + arg)
h5 = out + '/d3plot.h5'
times = d.states(h5)
k = len(times)
t = times[-1]
_, conn = d.dataset(h5, '/mesh/hex8')
_, x0 = d.dataset(h5, '/mesh/coordinates')
_, s = d.dataset(h5, d.state_path(k) + '/stress')
x0 = d.vec3(x0)
ne = len(conn) // 8
xc = [sum(x0[conn[8 * e + j]][0] for j in range(8)) / 8 for e in range(ne)]
order = sorted(range(ne), key=lambda e: xc[e])
x = [xc[e] for e in order]
sx = [s[6 * e] for e in order]
h = x[1] - x[0]
K = rho * C * C
cl = math.sqrt((K + 4.0 * G0 / 3.0) / rho)
GAM, A = 2.02, 0.47


def gruneisen(v, e):
    mu = 1.0 / v - 1.0
    if mu <= 0:
        return K * mu + (GAM + A * mu) * e
    n = K * mu * (1 + (1 - GAM / 2) * mu - A / 2 * mu * mu)
    return n / (1 - (S1 - 1) * mu) ** 2 + (GAM + A * mu) * e


# the HEL: a material point in uniaxial strain, integrated in small steps of the logarithmic
# strain to first yield: s_xx += (4/3) G(p, V) d(ln V), G = G0 (1 + b p V**(1/3)),
# Y = Y0 (1 + b p V**(1/3)) (T - 300 K < 0.1 K and the F term < 1e-7 there), p(V, E) of the
# Gruneisen EOS with dE = -(p - s_xx) dV... (the stress power, trapezoidal)
v, e, sxx, p = 1.0, 0.0, 0.0, 0.0
dl = 1.0e-7
while True:
    v1 = v * math.exp(-dl)
    g = G0 * (1 + b * p * v1 ** (1.0 / 3.0))
    sxx1 = sxx - 4.0 / 3.0 * g * dl
    y = Y0 * (1 + b * p * v1 ** (1.0 / 3.0))
    p1 = gruneisen(v1, e)
    e += -0.5 * ((p - sxx) + (p1 - sxx1)) * (v1 - v)
    v, sxx, p = v1, sxx1, gruneisen(v1, e)
    if 1.5 * abs(sxx) >= y:
        break
hel = p - sxx


def crossing(level, lo, hi):
    """x where sigma_xx passes level, searching from x = hi down to lo."""
    for i in range(len(x) - 1, 0, -1):
        if not (lo <= x[i] <= hi):
            continue
        a, c = sx[i - 1], sx[i]
        if (a - level) * (c - level) <= 0 and a != c:
            return x[i - 1] + (level - a) * (x[i] - x[i - 1]) / (c - a)
    return float('nan')


ok = True
xp = crossing(-0.5 * hel, 0.0, x[-1])
ok &= d.report('precursor front [mm]', xp, cl * t, 3 * h, 0.0)
xs_guess = (C + S1 * up) * t
pl1 = [sx[i] for i in range(len(x)) if xs_guess + 16 * h < x[i] < xp - 16 * h]
s1 = sum(pl1) / len(pl1)
ok &= d.report('HEL sigma_xx [GPa]', -s1, hel, 0.0, 0.002)
pl2 = [sx[i] for i in range(len(x)) if 4 * h < x[i] < xs_guess - 20 * h]
s2 = sum(pl2) / len(pl2)
xs = crossing(0.5 * (s1 + s2), 0.0, xp - 4 * h)
us = xs / t
u1 = -s1 / (rho * cl)
rho1 = rho / (1 - u1 / cl)
jump = s1 - rho1 * (us - u1) * (up - u1)
print('%-34s %14.6g' % ('shock speed Us [m/s]', us))
print('%-34s %14.6g' % ('hydrodynamic C + S1 up [m/s]', C + S1 * up))
ok &= d.report('shock sigma_xx [GPa]', s2, jump, 0.0, 0.005)
# nodout: node 201 at x = 50 mm
rows = [l.split() for l in open(out + '/nodout') if l.lstrip()[:1] in tuple('+-.0123456789')]
v = [(float(r[0]), float(r[5])) for r in rows if r[1] == '201']
xn = 50.0
# window: 0.3 us after the precursor, 0.5 us before the shock (its viscous foot, ~2 mm)
mid = [vx for (tt, vx) in v if xn / cl + 3e-4 < tt < xn / us - 5e-4]
ok &= len(mid) > 0
if mid:
    ok &= d.report('u behind the precursor [m/s]', sum(mid) / len(mid), u1, 0.0, 0.005)
late = [vx for (tt, vx) in v if tt > xn / us + 1.5e-3]
ok &= len(late) > 0
if late:
    ok &= d.report('u behind the shock [m/s]', sum(late) / len(late), up, 0.0, 0.005)
sys.exit(0 if ok else 1)
