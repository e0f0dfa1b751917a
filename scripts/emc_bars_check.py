#!/usr/bin/env python3
"""Check the two-bar impact (decks/emc_bars) from emcstat: exchange of velocities and the
largest penetration against the analytic penalty value.

  emc_bars_check.py OUTDIR --eps EPS --nodes N --mass M --v0 V --vtol T --ptol R [--lagrange]

Bars of mass M each, left at V, right at rest, N slave nodes with penalty EPS each: the
contact is a spring N*EPS on the reduced mass M/2, so the largest penetration is
V sqrt(M/(2 N EPS)) and an energy-conserving contact leaves the left bar at rest and the right
bar at V. Velocities from the last two lines' centres (constant after the contact).
Standard library only.
"""
import argparse
import math
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('outdir')
    ap.add_argument('--eps', type=float, default=1e4)
    ap.add_argument('--nodes', type=int, default=4)
    ap.add_argument('--mass', type=float, default=50.0)
    ap.add_argument('--v0', type=float, default=1.0)
    ap.add_argument('--gap0', type=float, default=0.01)
    ap.add_argument('--vtol', type=float, default=1e-12)
    ap.add_argument('--ptol', type=float, default=1e-3)
    ap.add_argument('--lagrange', action='store_true',
                    help='Lagrange multipliers: assert no penetration (gap >= 0 at every line)')
    a = ap.parse_args()
    rows = []
    with open(a.outdir + '/emcstat') as f:
        for line in f:
            if line.lstrip()[:1] in tuple('+-.0123456789') and line.strip():
                rows.append([float(x) for x in line.split()])
    x1 = [r[14] for r in rows]
    x2 = [r[20] for r in rows]
    t = [r[1] for r in rows]
    # bars 50 m long: gap = (x2 - 25) - (x1 + 25), initially gap0
    g0 = (x2[0] - x1[0]) - 50.0
    pen = -min(0.0, min((x2[i] - x1[i]) - 50.0 for i in range(len(rows))))
    dt = t[-1] - t[-2]
    v1 = (x1[-1] - x1[-2]) / dt
    v2 = (x2[-1] - x2[-2]) / dt
    pen_exact = a.v0 * math.sqrt(a.mass / (2.0 * a.nodes * a.eps))
    print('emc_bars_check: initial gap %.6g, final velocities %.16g %.16g, max penetration '
          '%.6e (analytic %.6e, rel. diff %.2e)' % (g0, v1, v2, pen, pen_exact,
                                                     abs(pen - pen_exact) / pen_exact))
    ok = abs(v1) <= a.vtol * a.v0 and abs(v2 - a.v0) <= a.vtol * a.v0
    if not ok:
        print('FAIL velocities not exchanged to %.1e' % a.vtol)
    if a.lagrange:
        gmin = min((x2[i] - x1[i]) - 50.0 for i in range(len(rows)))
        print('emc_bars_check: Lagrange: smallest gap %.6e' % gmin)
        if gmin < 0.0:
            print('FAIL penetration with Lagrange multipliers')
            ok = False
    elif not abs(pen - pen_exact) <= a.ptol * pen_exact:
        print('FAIL penetration off by more than %.1e relative' % a.ptol)
        ok = False
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
