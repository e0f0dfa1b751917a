#!/usr/bin/python3
"""Measures of the axisymmetric brittle-impact scene (decks/brittle_impact_2d, issue 19 scene 1;
decks from scripts/gen_brittle2d_deck.py) and of the back-surface scene (decks/laser_backside,
scene 3; scripts/gen_laser2d_decks.py). Needs h5py and numpy (/usr/bin/python3).

  brittle2d_check.py OUTDIR [--ratio R [--after T]] [--outer LO HI] [--inner LO HI]
                     [--depth LO HI] [--angle LO HI] [--scene impact|backside]

Depths are from the silica's surface (its highest node of the initial mesh); the hourglass
energy is over the initial kinetic energy, or the largest |external work| when that is 0.

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
- the energy ratio (glstat) within 1 +- R at every output from t = T (default 0).
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


def measure(out, after=0.0):
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
    sn = np.unique(mixed[np.concatenate([np.arange(k0 + 1, k0 + 5) for k0 in starts(mixed)])]
                   [np.repeat(sil, 4)])
    surf = x[sn, 1].max()                         # the silica surface (z = 0 in the scenes)
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
        env.append((surf - zr, r[row].max()))
    env = np.array(env)
    m['depth'] = env[-1, 0] if len(env) else 0.0
    m['angle'] = 0.0
    if len(env) > 2:
        slope = np.polyfit(env[:, 0], env[:, 1], 1)[0]      # dr/d(depth)
        m['angle'] = np.degrees(np.arctan(slope))
    xs = f['states/' + ks[-1] + '/coordinates'][:]
    m['heave'] = xs[sn, 1].max() - surf           # the highest silica node over the surface
    m['ndamaged'] = int((ds > 0).sum())
    m['nsilica'] = int(sil.sum())
    lines = [l for l in open(out + '/glstat') if l.lstrip()[:1] in tuple('+-.0123456789')]
    g = np.loadtxt(lines, ndmin=2)
    cols = open(out + '/glstat').readlines()[2].lstrip('#').split()
    late = g[:, 0] >= after
    m['ratio_dev'] = abs(g[late, cols.index('energy_ratio')] - 1).max() if late.any() else 0.0
    e0 = g[0, cols.index('kinetic')]              # the impact energy, or the load's work
    e0 = e0 if e0 > 0 else abs(g[:, cols.index('external_work')]).max()
    m['hourglass'] = g[-1, cols.index('hourglass')]/e0
    m['finite'] = bool(np.isfinite(g).all() and np.isfinite(d).all())
    return m


def main():
    p = argparse.ArgumentParser()
    p.add_argument('out')
    p.add_argument('--ratio', type=float)
    p.add_argument('--after', type=float, default=0.0, help='the ratio from this time on')
    p.add_argument('--scene', choices=['impact', 'backside'], default='impact',
                   help='the seed numbers printed beside the measures')
    for q in ('outer', 'inner', 'depth', 'angle'):
        p.add_argument('--' + q, type=float, nargs=2)
    a = p.parse_args()
    m = measure(a.out, a.after)
    print('silica elements damaged %d of %d; hourglass energy / initial kinetic %.4f; '
          'surface heave %.4f mm' % (m['ndamaged'], m['nsilica'], m['hourglass'], m['heave']))
    ok = m['finite']
    print(('ok   ' if ok else 'FAIL ') + 'glstat and damage finite')
    ref = {'outer': 'experiment 1.65, DYNA2D 1.62 mm', 'inner': '0.8 / 0.7 mm',
           'depth': '1.0 / 0.5 mm', 'angle': 'cone about 30 deg'}
    if a.scene == 'backside':
        ref = {'outer': 'DYNA2D 0.170 mm', 'inner': 'not in the seed',
               'depth': 'the seed\'s is unreadable', 'angle': 'fingers at -45 deg'}
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
        print('%s energy ratio within 1 +- %g (max |ratio - 1| = %.3e from t = %g)'
              % ('ok  ' if good else 'FAIL', a.ratio, m['ratio_dev'], a.after))
    else:
        print('     max |energy ratio - 1| = %.3e from t = %g' % (m['ratio_dev'], a.after))
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
