#!/usr/bin/python3
"""Checks of a spall plate-impact run (scripts/gen_spall_deck.py) against the elastic
jump conditions and the Tuler-Butcher time (Meyers, Dynamic Behavior of Materials, 1994,
ch. 16; Tuler & Butcher 1968, Int. J. Fract. Mech. 4:431; LS-DYNA's exponent 2):
  c = sqrt(M/rho), M = E(1-nu)/((1+nu)(1-2nu)); u_p = V/2; sigma = rho c u_p;
  free-surface velocity plateau 2 u_p = V from t = 2H/c (arrival: first u_fs >= V/2);
  tension sigma at x = 2H from t = 3H/c; failure after dt_TB = IMPULSE/(sigma - SIGTH)^2;
  the free surface, pulled back at 4H/c, comes back (u_fs >= V/2) at 4H/c + dt_TB.
Tolerances: the plateau within 1 % (the elastic front rings by about +-1 % behind it with
the default bulk viscosity); times within TOLN element transit times dx/c (the front is
smeared over a few elements by the bulk viscosity); the first eroded element within one
element of x = 2H; energy ratio 1 to 1e-9 (the eroded energies are parts of internal and
kinetic energy; an eroding element applies no force at the pass it erodes in and books
no work for it, so the balance holds to round-off).
Usage: spall_check.py OUTDIR NX [--h 2] [--v 200] [--sigth 2] [--impulse 3e-4] [--toln 2]
       [--table]  (--table: print one line 'nx errors' for the study, no pass/fail)"""
import argparse, sys
import numpy as np
import h5py
ap = argparse.ArgumentParser()
ap.add_argument('out')
ap.add_argument('nx', type=int)
ap.add_argument('--h', type=float, default=2.0)
ap.add_argument('--v', type=float, default=200.0)
ap.add_argument('--sigth', type=float, default=2.0)
ap.add_argument('--impulse', type=float, default=3.0e-4)
ap.add_argument('--toln', type=float, default=2.0)
ap.add_argument('--lam', type=float, default=2.0, help='Tuler-Butcher exponent')
ap.add_argument('--table', action='store_true')
a = ap.parse_args()
rho, E, nu = 7.85e-6, 210.0, 0.3
M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
c = (M / rho) ** 0.5
H, V, nx = a.h, a.v, a.nx
dx = 3 * H / nx
sig = rho * c * V / 2
dtb = a.impulse / (sig - a.sigth) ** a.lam
t_arr, t_sp, t_ret = 2 * H / c, 3 * H / c + dtb, 4 * H / c + dtb
d = np.loadtxt([l for l in open(a.out + '/nodout') if l.lstrip()[:1] in tuple('+-.0123456789')])
fs = d[d[:, 1] == nx + 1]
t, u = fs[:, 0], fs[:, 5]
i_arr = np.nonzero(u >= V / 2)[0][0]
plateau = u[(t > t_arr + 0.25 * H / c) & (t < 4 * H / c - 0.25 * H / c)].mean()
after = np.nonzero((t > 4 * H / c) & (u < V / 2))[0]
i_ret = np.nonzero((t > t[after[0]]) & (u >= V / 2))[0][0] if len(after) else None
u_min = u[(t > 4 * H / c - 0.25 * H / c) & (t < t_ret + H / c)].min()
g = np.loadtxt([l for l in open(a.out + '/glstat') if l.lstrip()[:1] in tuple('+-.0123456789')])
j = np.nonzero(g[:, 14] > 0)[0]
f = h5py.File(a.out + '/d3plot.h5', 'r')
states = sorted(k for k in f['states'] if k != 'times')
first = None
for k in states:
    fl = np.nonzero(f['states/' + k + '/failed'][:] > 0.5)[0]
    if len(fl):
        first = fl
        break
xs = (first.min() + 0.5) * dx if first is not None else float('nan')
t_er = 0.5 * (g[j[0] - 1, 0] + g[j[0], 0]) if len(j) else float('nan')
tol_t = a.toln * dx / c
rows = [('plateau u_fs / 2u_p', plateau / V, 1.0, 0.01),
        ('arrival time 2H/c', t[i_arr], t_arr, tol_t),
        ('first erosion time 3H/c + dt_TB', t_er, t_sp, tol_t),
        ('spall signal time 4H/c + dt_TB', t[i_ret] if i_ret is not None else float('nan'),
         t_ret, tol_t),
        ('spall plane x (first eroded element)', xs, 2 * H, dx),
        ('energy ratio min', g[:, 9].min(), 1.0, 1e-9),
        ('energy ratio max', g[:, 9].max(), 1.0, 1e-9)]
if a.table:
    print('%d %.6e %.6e %.6e %.6e %.4f %.4f' % (nx, t[i_arr] - t_arr, t_er - t_sp,
          rows[3][1] - t_ret, xs - 2 * H, plateau / V - 1, 0.5 * rho * c * (V - u_min) / sig))
    sys.exit(0)
bad = 0
print('c = %.2f mm/ms, sigma = rho c u_p = %.4f GPa, dt_TB = %.4e ms, pull-back 1/2 rho c '
      'du = %.4f GPa (u_min %.2f m/s)' % (c, sig, dtb, 0.5 * rho * c * (V - u_min), u_min))
for name, got, want, tol in rows:
    ok = abs(got - want) <= tol
    bad += not ok
    print('%-4s %-40s got %.6e want %.6e tol %.2e' % ('ok' if ok else 'FAIL', name, got, want,
                                                      tol))
sys.exit(1 if bad else 0)
