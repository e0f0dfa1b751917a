#!/usr/bin/python3
"""Measures of the axisymmetric brittle-impact scene (decks/brittle_impact_2d, issue 19 scene 1;
decks from scripts/gen_brittle2d_deck.py). Needs h5py and numpy (/usr/bin/python3).

  brittle2d_check.py OUTDIR [--ratio R] [--outer LO HI] [--inner LO HI] [--depth LO HI]
                     [--angle LO HI]

On the last plot state, silica = part 1, element centroids of the initial mesh (x = r, y = z,
the surface at z = 0), D = the plot's damage (cracks opened / 3, or the compressive Dc):
- outer fracture diameter: twice the largest centroid radius of a damaged (D > 0) element of
  the surface row (the seed's experiment 1.65 mm, DYNA2D 1.62 mm);
- inner heavily fractured diameter: the same with D >= 2/3 (two or three cracks open)
  (0.8 / 0.7 mm);
- damage depth: the deepest damaged centroid under the contact (r <= the outer radius),
  counted down the connected damaged rows from the surface (1.0 / 0.5 mm);
- envelope angle: the angle from the axis of the line fitted (least squares) through the outer
  edge of the damage (largest damaged centroid r) of each row from the surface down to the
  damage depth: positive = the fringe widens with depth (a cone opening downwards, the seed's
  cone crack about 30 deg), negative = it narrows;
- the energy ratio (glstat) within 1 +- R at every output.
Every measure is printed; with a band given it is checked (exit 1 on a failure).
"""
import argparse
import sys

import h5py
import numpy as np


def starts(mixed):
    k, out = 0, []
    while k < len(mixed):
        out.append(k)
        k += 1 + {5: 4, 4: 3}[int(mixed[k])]
    return out


def measure(out):
    f = h5py.File(out + '/d3plot.h5', 'r')
    ks = sorted(k for k in f['states'] if k != 'times')
    d = f['states/' + ks[-1] + '/damage'][:]
    pid = f['mesh/part_ids'][:]
    x = f['mesh/coordinates'][:]
    mixed = f['mesh/mixed'][:]
    # XDMF mixed topology: type, then the nodes (quadrilateral = 5, 4 nodes)
    cen, k = [], 0
    while k < len(mixed):
        t = int(mixed[k])
        nn = {5: 4, 4: 3}[t]
        cen.append(x[mixed[k + 1:k + 1 + nn]].mean(axis=0))
        k += 1 + nn
    cen = np.array(cen)
    sil = pid == 1
    r, z, ds = cen[sil, 0], cen[sil, 1], d[sil]
    zs = np.unique(np.round(z, 9))[::-1]          # rows from the surface down
    top = np.isclose(z, zs[0])
    m = {}
    m['outer'] = 2*r[top & (ds > 0)].max() if (top & (ds > 0)).any() else 0.0
    m['inner'] = 2*r[top & (ds >= 2/3 - 1e-9)].max() if (top & (ds >= 2/3 - 1e-9)).any() else 0.0
    env = []
    for zr in zs:
        row = np.isclose(z, zr) & (ds > 0) & (r <= 0.5*m['outer'] + 1e-9)
        if not row.any():
            break
        env.append((-zr, r[row].max()))
    env = np.array(env)
    m['depth'] = env[-1, 0] if len(env) else 0.0
    m['angle'] = 0.0
    if len(env) > 2:
        slope = np.polyfit(env[:, 0], env[:, 1], 1)[0]      # dr/d(depth)
        m['angle'] = np.degrees(np.arctan(slope))
    xs = f['states/' + ks[-1] + '/coordinates'][:]
    sn = np.unique(mixed[np.concatenate([np.arange(k0 + 1, k0 + 5) for k0 in starts(mixed)])]
                   [np.repeat(sil, 4)])
    m['heave'] = xs[sn, 1].max()                  # the highest silica node (surface at 0)
    m['ndamaged'] = int((ds > 0).sum())
    m['nsilica'] = int(sil.sum())
    lines = [l for l in open(out + '/glstat') if l.lstrip()[:1] in tuple('+-.0123456789')]
    g = np.loadtxt(lines, ndmin=2)
    cols = open(out + '/glstat').readlines()[2].lstrip('#').split()
    m['ratio_dev'] = abs(g[:, cols.index('energy_ratio')] - 1).max()
    m['hourglass'] = g[-1, cols.index('hourglass')]/g[0, cols.index('kinetic')]
    m['finite'] = bool(np.isfinite(g).all() and np.isfinite(d).all())
    return m


def main():
    p = argparse.ArgumentParser()
    p.add_argument('out')
    p.add_argument('--ratio', type=float)
    for q in ('outer', 'inner', 'depth', 'angle'):
        p.add_argument('--' + q, type=float, nargs=2)
    a = p.parse_args()
    m = measure(a.out)
    print('silica elements damaged %d of %d; hourglass energy / initial kinetic %.4f; '
          'surface heave %.4f mm' % (m['ndamaged'], m['nsilica'], m['hourglass'], m['heave']))
    ok = m['finite']
    print(('ok   ' if ok else 'FAIL ') + 'glstat and damage finite')
    ref = {'outer': 'experiment 1.65, DYNA2D 1.62 mm', 'inner': '0.8 / 0.7 mm',
           'depth': '1.0 / 0.5 mm', 'angle': 'cone about 30 deg'}
    for q, unit in (('outer', 'mm'), ('inner', 'mm'), ('depth', 'mm'), ('angle', 'deg')):
        band = getattr(a, q)
        v = m[q]
        good = band is None or band[0] <= v <= band[1]
        ok &= good
        print('%s %-6s %8.4f %s  (%s)%s' % ('ok  ' if good else 'FAIL', q, v, unit, ref[q],
              '' if band is None else '  band %g..%g' % tuple(band)))
    if a.ratio is not None:
        good = m['ratio_dev'] <= a.ratio
        ok &= good
        print('%s energy ratio within 1 +- %g (max |ratio - 1| = %.3e)'
              % ('ok  ' if good else 'FAIL', a.ratio, m['ratio_dev']))
    else:
        print('     max |energy ratio - 1| = %.3e' % m['ratio_dev'])
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
