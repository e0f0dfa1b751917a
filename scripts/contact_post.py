#!/usr/bin/env python3
"""Checks of the contact scenes from dynx output (standard library only).

  contact_post.py rod OUTDIR [--L 100 --v 10 --rho 7.85e-6 --E 210 --A 1 --nx 100]
      contact duration (first to last rcforc line with a force) against 2L/c, the force
      plateau against rho*c*v*A/2, the velocities after release (nodout, lumped-mass
      averages per rod: striker 0, target v) and the energy ratio (glstat).
  contact_post.py hertz OUTDIR --R R --E E --nu NU --F F ...   (see hertz())
  contact_post.py spikes OUTDIR --id ID --comp x|y|z  largest jump of a force component
Each check prints value, reference, difference and PASS/FAIL; exit 1 when one fails."""
import argparse, math, os, sys


def table(path):
    names, rows = None, []
    for line in open(path):
        if line.startswith('#'):
            toks = line[1:].split()
            if toks and toks[0] == 'time':
                names = toks
            continue
        if line.strip():
            rows.append([float(x) for x in line.split()])
    return names, rows


def report(name, value, ref, abs_tol, rel_tol):
    ok = math.isfinite(value) and abs(value - ref) <= abs_tol + rel_tol * abs(ref)
    print('%-40s %14.6g   reference %14.6g   diff %10.3g   tol %.3g + %.3g*|ref|   %s'
          % (name, value, ref, value - ref, abs_tol, rel_tol, 'PASS' if ok else 'FAIL'))
    return ok


def rod(a):
    c = math.sqrt(a.E / a.rho)
    t2 = 2.0 * a.L / c
    names, rows = table(os.path.join(a.out, 'rcforc'))
    fx, na = names.index('slave_x'), names.index('nactive')
    on = [r[0] for r in rows if r[na] > 0]
    dur = on[-1] - on[0]
    ok = True
    ok &= report('contact duration [ms] vs 2L/c', dur, t2, 0.0, a.tol_dur)
    if not a.single:
        # the force plateau: median of the force while in contact (single surface: the
        # slave and master sides are the same surface, their resultants cancel)
        mid = sorted(abs(r[fx]) for r in rows if on[0] + 0.1 * t2 <= r[0] <= on[0] + 0.9 * t2)
        ok &= report('force plateau [kN] vs rho c v A/2', mid[len(mid) // 2],
                     a.rho * c * a.v * a.A / 2, 0.0, 0.02)
    # velocities after release: lumped-mass average per rod (end nodes carry half weight)
    names, rows = table(os.path.join(a.out, 'nodout'))
    tcol, ncol, vcol = names.index('time'), names.index('node_id'), names.index('x_vel')
    tlast = rows[-1][tcol]
    last = {int(r[ncol]): r[vcol] for r in rows if r[tcol] == tlast}
    nper = 4 * (a.nx + 1)
    vrod = []
    for rod_i in range(2):
        num = den = 0.0
        for n in range(1 + rod_i * nper, 1 + (rod_i + 1) * nper):
            i = (n - 1 - rod_i * nper) % (a.nx + 1)
            wgt = 1.0 if i in (0, a.nx) else 2.0
            num += wgt * last[n]
            den += wgt
        vrod.append(num / den)
    ok &= report('striker velocity after release [m/s]', vrod[0], 0.0, a.tol_v * a.v, 0.0)
    ok &= report('target velocity after release [m/s]', vrod[1], a.v, 0.0, a.tol_v)
    names, rows = table(os.path.join(a.out, 'glstat'))
    r = names.index('energy_ratio')
    lo, hi = min(x[r] for x in rows), max(x[r] for x in rows)
    print('energy ratio min %.6f max %.6f final %.6f' % (lo, hi, rows[-1][r]))
    ok &= report('largest energy ratio error', max(1 - lo, hi - 1), 0.0, a.tol_e, 0.0)
    return ok


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('rod'); p.add_argument('out')
    p.add_argument('--L', type=float, default=100.0)
    p.add_argument('--v', type=float, default=10.0)
    p.add_argument('--rho', type=float, default=7.85e-6)
    p.add_argument('--E', type=float, default=210.0)
    p.add_argument('--A', type=float, default=1.0)
    p.add_argument('--nx', type=int, default=100)
    p.add_argument('--tol-dur', type=float, default=0.03)
    p.add_argument('--tol-v', type=float, default=0.03)
    p.add_argument('--tol-e', type=float, default=0.01)
    p.add_argument('--single', action='store_true', help='single surface: no force check')
    a = ap.parse_args()
    ok = {'rod': rod}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
