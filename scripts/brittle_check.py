#!/usr/bin/python3
"""Checks of the brittle-damage impact cases (tests/regression/brittle_*; decks from
scripts/gen_brittle_deck.py; docs/damage.md). Needs h5py and numpy (/usr/bin/python3).

  brittle_check.py impact OUTDIR --nblock N --ratio R --damaged LO HI [--rmax 0.9]
      glstat energy ratio (kinetic + internal + hourglass + sliding + eroded energies over the
      initial kinetic energy) within 1 +- R at every output; the last state's damage row:
      the number of block elements with D > 0 in [LO, HI]; no damage in the sphere (elements
      after the first N); the top-layer elements nearest the impact axis (reference
      coordinates) damaged; the fringe confined: every damaged element's centroid within
      0.9 mm of the impact axis (the block's half-width is 1 mm).
  brittle_check.py cutoff OUTDIR --ymax Y
      fully damaged elements (D = 1 at all points) exist; their pressure >= 0 (PFMIN = 0: the
      failed material carries no tension) and their von Mises stress <= Y (the largest YF of
      the failed curve), both to 1e-12 of the stresses' scale.
  brittle_check.py eroded OUTDIR --ratio R
      elements eroded (failed flags); glstat's eroded internal + kinetic energies > 0 and the
      energy ratio (with them) within 1 +- R.
Every value measured is printed; exit 1 on a failed check."""
import argparse
import sys

import h5py
import numpy as np


def glstat(out):
    g = np.loadtxt([l for l in open(out + '/glstat') if l.lstrip()[:1] in tuple('+-.0123456789')], ndmin=2)
    cols = open(out + '/glstat').readlines()[2].lstrip('#').split()   # '# time ...' or 'time ...'
    return g, (lambda n: g[:, cols.index(n)]), cols


def last_state(out):
    f = h5py.File(out + '/d3plot.h5', 'r')
    ks = sorted(k for k in f['states'] if k != 'times')
    return f, f['states/' + ks[-1]], ks


def check(ok, what):
    print(('ok   ' if ok else 'FAIL ') + what)
    return ok


def ratio_ok(out, r):
    g, c, cols = glstat(out)
    dev = abs(c('energy_ratio') - 1.0).max()
    return check(np.isfinite(g).all() and dev <= r,
                 'energy ratio within 1 +- %g (measured max |ratio - 1| = %.3e)' % (r, dev))


def centroids(f, s):
    conn = None
    for name in ('mesh/hex8',):
        if name in f:
            conn = f[name][:]
            break
    if conn is None:
        return None
    x = f['mesh/coordinates'][:]       # the reference (initial) coordinates
    conn = conn.reshape(-1, 8)
    if conn.min() == 1:
        conn = conn - 1
    return x[conn].mean(axis=1)


def impact(a):
    ok = ratio_ok(a.out, a.ratio)
    f, s, ks = last_state(a.out)
    d = s['damage'][:]
    ok &= check(np.isfinite(d).all() and d.min() >= 0.0 and d.max() <= 1.0,
                'damage finite and within [0, 1]')
    nd = int((d[:a.nblock] > 0).sum())
    ok &= check(a.damaged[0] <= nd <= a.damaged[1], '%d damaged block elements (band %d..%d)'
                % (nd, a.damaged[0], a.damaged[1]))
    ok &= check((d[a.nblock:] == 0).all(), 'no damage in the elastic sphere')
    xc = centroids(f, s)
    if xc is not None:
        blk = xc[:a.nblock]
        r = np.hypot(blk[:, 0], blk[:, 1])
        top = blk[:, 2] > blk[:, 2].max() - 1e-6 - 0.5 * (blk[:, 2].max() - blk[:, 2].min()) / 8
        axis = top & (r <= r[top].min() + 1e-9)
        ok &= check(d[:a.nblock][axis].min() > 0, 'the elements under the impact point are '
                    'damaged (D = %s)' % np.round(d[:a.nblock][axis], 3))
        rmax = r[d[:a.nblock] > 0].max() if nd else 0.0
        ok &= check(rmax <= a.rmax, 'damage fringe within %.3f mm of the axis (<= %g)'
                    % (rmax, a.rmax))
    else:
        ok &= check(False, 'element connectivity found in d3plot.h5')
    return ok


def cutoff(a):
    f, s, ks = last_state(a.out)
    d = s['damage'][:]
    full = d == 1.0
    ok = check(full.sum() > 0, '%d fully damaged elements' % full.sum())
    p = s['pressure'][:][full]
    vm = s['von_mises'][:][full]
    scale = 1e-12 * max(1.0, abs(s['pressure'][:]).max())
    ok &= check((p >= -scale).all(), 'fully damaged: pressure >= 0 (min %.3e)' % p.min())
    ok &= check((vm <= a.ymax + scale).all(), 'fully damaged: von Mises <= %g (max %.4f)'
                % (a.ymax, vm.max()))
    return ok


def eroded(a):
    ok = ratio_ok(a.out, a.ratio)
    g, c, cols = glstat(a.out)
    ero = c('eroded_internal_energy')[-1] + c('eroded_kinetic_energy')[-1]
    ok &= check(ero > 0, 'eroded energy %.4e > 0 (internal %.3e, kinetic %.3e)'
                % (ero, c('eroded_internal_energy')[-1], c('eroded_kinetic_energy')[-1]))
    f, s, ks = last_state(a.out)
    nf = int(s['failed'][:].sum())
    ok &= check(nf > 0, '%d eroded elements' % nf)
    return ok


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('impact')
    p.add_argument('out')
    p.add_argument('--nblock', type=int, required=True)
    p.add_argument('--ratio', type=float, required=True)
    p.add_argument('--damaged', type=int, nargs=2, required=True)
    p.add_argument('--rmax', type=float, default=0.9)
    p = sub.add_parser('cutoff')
    p.add_argument('out')
    p.add_argument('--ymax', type=float, required=True)
    p = sub.add_parser('eroded')
    p.add_argument('out')
    p.add_argument('--ratio', type=float, required=True)
    a = ap.parse_args()
    ok = {'impact': impact, 'cutoff': cutoff, 'eroded': eroded}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
