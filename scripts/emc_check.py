#!/usr/bin/env python3
"""Check an emcstat file (dynx conserving rigid-body solver) against conservation laws.

  emc_check.py OUTDIR [--etol R] [--ptol R] [--ltol R] [--min-contact N] [--lx-exchange A]

Asserts over every line of OUTDIR/emcstat:
  |E - E0| / E0 <= etol                      (E = kinetic + penalty energy)
  |p - p0| / sum_b m_b |v_b(0)| <= ptol      (linear momentum)
  |L - L0| / max(|L0|, scale) <= ltol        (angular momentum about the origin)
and that at least N lines have penalty energy > 0 (the test saw contact), and with
--lx-exchange A that the x angular momentum of body 1 changed by at least A (it exchanges
momentum with body 2). Prints the measured values. Standard library only.
"""
import argparse
import math
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('outdir')
    ap.add_argument('--etol', type=float, default=1e-12)
    ap.add_argument('--ptol', type=float, default=1e-12)
    ap.add_argument('--ltol', type=float, default=1e-12)
    ap.add_argument('--min-contact', type=int, default=1)
    ap.add_argument('--lx-exchange', type=float, default=0.0)
    ap.add_argument('--dissipative', type=float, default=None, metavar='LOSS',
                    help='friction: instead of --etol, energy non-increasing at every line '
                         '(to 1e-13 E0) and E_end <= (1 - LOSS) E0')
    ap.add_argument('--plateau', type=float, default=None, metavar='TOL',
                    help='with --dissipative: |E_end - E_mid|/E0 <= TOL (rolling reached)')
    ap.add_argument('--lfloor', type=float, default=0.0,
                    help='floor of the angular momentum scale (absolute), for L0 = 0')
    a = ap.parse_args()
    rows = []
    with open(a.outdir + '/emcstat') as f:
        for line in f:
            if line.lstrip()[:1] not in tuple('+-.0123456789'):
                continue
            rows.append([float(x) for x in line.split()])
    if len(rows) < 2:
        print('emc_check: emcstat has %d lines' % len(rows))
        return 1
    r0 = rows[0]
    e0 = r0[4]
    p0 = r0[5:8]
    l0 = r0[8:11]
    nb = (len(r0) - 14) // 6
    # momentum scale: |p| of the bodies is not in emcstat; use |p0| and |L0| floored by the
    # largest |p|, |L| seen (a free system has p, L constant, so these are the same unless broken)
    pscale = max(max(math.sqrt(sum(x * x for x in r[5:8])) for r in rows), 1e-300)
    lscale = max(max(math.sqrt(sum(x * x for x in r[8:11])) for r in rows), a.lfloor, 1e-300)
    de = max(abs(r[4] - e0) / e0 for r in rows)
    dp = max(math.sqrt(sum((r[5 + i] - p0[i]) ** 2 for i in range(3))) for r in rows) / pscale
    dl = max(math.sqrt(sum((r[8 + i] - l0[i]) ** 2 for i in range(3))) for r in rows) / lscale
    ncont = sum(1 for r in rows if r[3] > 0.0)
    lx1 = [r[14 + 3] for r in rows]
    exch = max(lx1) - min(lx1)
    print('emc_check: %d lines, %d bodies, %d with contact; max rel. drift: energy %.3e, '
          'linear momentum %.3e, angular momentum %.3e; body 1 Lx range %.4e'
          % (len(rows), nb, ncont, de, dp, dl, exch))
    ok = True
    if a.dissipative is not None:
        rise = max((rows[i + 1][4] - rows[i][4]) / e0 for i in range(len(rows) - 1))
        loss = 1.0 - rows[-1][4] / e0
        print('emc_check: dissipative: largest energy rise per line %.3e, loss %.4f'
              % (rise, loss))
        if rise > 1e-13:
            print('FAIL energy rises by %.3e' % rise); ok = False
        if loss < a.dissipative:
            print('FAIL energy loss %.4f < %.4f' % (loss, a.dissipative)); ok = False
        if a.plateau is not None:
            pl = abs(rows[-1][4] - rows[len(rows) // 2][4]) / e0
            print('emc_check: energy change over the second half %.3e' % pl)
            if pl > a.plateau:
                print('FAIL no plateau: %.3e > %.1e' % (pl, a.plateau)); ok = False
        de = 0.0
    if not de <= a.etol:
        print('FAIL energy drift %.3e > %.1e' % (de, a.etol)); ok = False
    if not dp <= a.ptol:
        print('FAIL linear momentum drift %.3e > %.1e' % (dp, a.ptol)); ok = False
    if not dl <= a.ltol:
        print('FAIL angular momentum drift %.3e > %.1e' % (dl, a.ltol)); ok = False
    if ncont < a.min_contact:
        print('FAIL only %d lines with contact (< %d)' % (ncont, a.min_contact)); ok = False
    if exch < a.lx_exchange:
        print('FAIL body 1 Lx range %.3e < %.3e' % (exch, a.lx_exchange)); ok = False
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
