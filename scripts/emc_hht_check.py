#!/usr/bin/env python3
"""Check the dissipative (HHT / Newmark parameters) conserving solver on the two-bar impact
(decks/emc_bars) against an independent 1-D model of the same scheme.

  emc_hht_check.py OUTDIR --eps EPS --dt DT --alpha A [--gamma G --beta B] [--nodes N]
                   [--mass M] [--v0 V] [--gap0 G0] [--ktol R]

The bars (mass M each, left at V0, right at rest, gap G0, N slave nodes of penalty EPS) move
along x only, so the step is one scalar equation in the relative velocity u = v_left -
v_right: g1 = g0 - dt (u0 + u1)/2, u1 = u0 + 2 dt N f/M with
  f = min(Ubar(g0, g1) + chi EPS (<g1> - <g0>), 0),  Ubar the discrete gradient of
  U = EPS/2 <-g>^2, <g> = min(g, 0), chi = (1 - rho)/(2 (1 + rho)),
  rho = (1 + A)/(1 - A) (HHT, LS-DYNA sign A <= 0) or the Newmark root for G, B.
The model is solved per step by bisection to the last bit. Asserts over OUTDIR/emcstat:
  - final kinetic energy equals the model's to --ktol relative (default 1e-9),
  - the energy taken, E0 - (KE + U) at the end, equals the model's to 1e-9 E0,
  - energy never rises from one line to the next (1e-13 E0),
  - linear momentum constant to 1e-12 (relative to M V0),
  - with rho < 1 the energy taken is > 0 (the dissipation acts), with rho = 1 it is < 1e-12.
Standard library only.
"""
import argparse
import math
import sys


def rho_inf(alpha, gamma, beta):
    if alpha < 0.0:
        return (1.0 + alpha) / (1.0 - alpha)
    if gamma == 0.5 and beta == 0.25:
        return 1.0
    b = 0.5 + gamma - 2.0 * beta
    c = 0.5 - gamma + beta
    disc = b * b - 4.0 * beta * c
    if disc < 0.0:
        return math.sqrt(c / beta)
    return min(1.0, max(abs((-b + math.sqrt(disc)) / (2 * beta)),
                        abs((-b - math.sqrt(disc)) / (2 * beta))))


def ubar(eps, g0, g1):
    if g0 <= 0.0 and g1 <= 0.0:
        return 0.5 * eps * (g0 + g1)
    if g1 < 0.0:
        return 0.5 * eps * g1 * (g1 / (g1 - g0))
    if g0 < 0.0:
        return 0.5 * eps * g0 * (g0 / (g0 - g1))
    return 0.0


def model(a, chi, nsteps):
    g, u = a.gap0, a.v0
    ke0 = 0.5 * a.mass * a.v0 ** 2
    diss = 0.0
    vcm = 0.5 * a.v0          # centre-of-mass velocity, constant

    def res(u1):
        g1 = g - a.dt * (u + u1) / 2.0
        ub = ubar(a.eps, g, g1)
        f = min(ub + chi * a.eps * (min(g1, 0.0) - min(g, 0.0)), 0.0) if chi > 0 else ub
        return u1 - u - 2.0 * a.dt * a.nodes * f / a.mass, g1, f, ub

    for _ in range(nsteps):
        lo, hi = -abs(u) - 10.0, abs(u) + 10.0      # res is increasing in u1
        for _ in range(300):
            mid = 0.5 * (lo + hi)
            if res(mid)[0] > 0.0:
                hi = mid
            else:
                lo = mid
            if hi - lo <= 1e-17 * max(1.0, abs(mid)):
                break
        u1 = 0.5 * (lo + hi)
        _, g1, f, ub = res(u1)
        diss += a.nodes * (f - ub) * (g1 - g)
        g, u = g1, u1
    ke = a.mass * vcm ** 2 + 0.25 * a.mass * u ** 2     # two bars: M vcm^2 + mu u^2/2
    return ke0, ke, diss


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('outdir')
    ap.add_argument('--eps', type=float, required=True)
    ap.add_argument('--dt', type=float, required=True)
    ap.add_argument('--alpha', type=float, default=0.0)
    ap.add_argument('--gamma', type=float, default=0.5)
    ap.add_argument('--beta', type=float, default=0.25)
    ap.add_argument('--nodes', type=int, default=4)
    ap.add_argument('--mass', type=float, default=50.0)
    ap.add_argument('--v0', type=float, default=1.0)
    ap.add_argument('--gap0', type=float, default=0.01)
    ap.add_argument('--ktol', type=float, default=1e-9)
    a = ap.parse_args()
    rows = []
    with open(a.outdir + '/emcstat') as f:
        for line in f:
            if line.lstrip()[:1] in tuple('+-.0123456789') and line.strip():
                rows.append([float(x) for x in line.split()])
    rho = rho_inf(a.alpha, a.gamma, a.beta)
    chi = (1.0 - rho) / (2.0 * (1.0 + rho))
    nsteps = int(rows[-1][0])
    ke0, ke_m, d_m = model(a, chi, nsteps)
    e0 = rows[0][4]
    ke = rows[-1][2]
    taken = e0 - rows[-1][4]
    rise = max(rows[i + 1][4] - rows[i][4] for i in range(len(rows) - 1)) / e0
    p0 = rows[0][5:8]
    dp = max(math.sqrt(sum((r[5 + i] - p0[i]) ** 2 for i in range(3))) for r in rows) / \
        (a.mass * a.v0)
    print('emc_hht_check: rho_inf %.6f chi %.6f, %d steps; KE end %.15e (model %.15e, rel %.2e);'
          ' energy taken %.6e (model %.6e, diff %.2e E0); largest rise %.2e E0; p drift %.2e'
          % (rho, chi, nsteps, ke, ke_m, abs(ke - ke_m) / ke0, taken, d_m,
             abs(taken - d_m) / e0, rise, dp))
    ok = True
    if not abs(ke - ke_m) <= a.ktol * ke0:
        print('FAIL final kinetic energy differs from the model'); ok = False
    if not abs(taken - d_m) <= 1e-9 * e0:
        print('FAIL energy taken differs from the model'); ok = False
    if not rise <= 1e-13:
        print('FAIL energy rises'); ok = False
    if not dp <= 1e-12:
        print('FAIL linear momentum drifts'); ok = False
    if rho < 1.0 and not taken > 1e-6 * e0:
        print('FAIL no dissipation with rho_inf < 1'); ok = False
    if rho == 1.0 and not abs(taken) <= 1e-12 * e0:
        print('FAIL energy not conserved with rho_inf = 1'); ok = False
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
