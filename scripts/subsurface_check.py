#!/usr/bin/python3
"""Measures of the sub-surface particle scene (decks/laser_subsurface, issue 19 scene 4;
scripts/gen_laser2d_decks.py subsurface). Needs h5py and numpy (/usr/bin/python3).

  subsurface_check.py OUTDIR [--peak LO HI] [--tpeak LO HI] [--tcrack LO HI] [--ratio R]
                      [--history]

From the plot states (silica = part 1, particle = part 2, x = r, y = z, the surface z = 0):
- the particle pressure: the mean of its elements' pressures weighted by their initial
  volume per radian (int r dA); its peak and the time of the peak (seed: about 36 kbar = 3.6
  GPa at 1.8 ns);
- the crack through to the surface: the first state at which the damaged glass (D > 0)
  connects, through elements sharing an edge, the elements touching the particle with those
  touching the surface (seed: the cone crack from the particle's 90 deg point reaches the
  surface at 2.9 ns); and the first state with damage in the surface row (spall);
- the energy ratio (glstat) within 1 +- R at every output.
--history prints the table of time, particle pressure, damaged glass elements. A band given
is checked (exit 1 on a failure).
"""
import argparse
import sys

import h5py
import numpy as np


def cells(mixed):
    out, k = [], 0
    while k < len(mixed):
        nn = {5: 4, 4: 3}[int(mixed[k])]
        out.append(list(mixed[k + 1:k + 1 + nn]))
        k += 1 + nn
    return out


def measure(out):
    f = h5py.File(out + '/d3plot.h5', 'r')
    x = f['mesh/coordinates'][:]
    pid = f['mesh/part_ids'][:]
    cs = cells(f['mesh/mixed'][:])
    vol = np.zeros(len(cs))
    for e, c in enumerate(cs):
        r, z = x[c, 0], x[c, 1]
        s = 0.0
        for k in range(len(c)):
            m = (k + 1) % len(c)
            s += (r[k] + r[m])*(r[k]*z[m] - r[m]*z[k])
        vol[e] = abs(s)/6.0
    edges = {}
    for e, c in enumerate(cs):
        for k in range(len(c)):
            key = tuple(sorted((c[k], c[(k + 1) % len(c)])))
            edges.setdefault(key, []).append(e)
    nbr = [[] for _ in cs]
    for es in edges.values():
        for a in es:
            nbr[a] += [b for b in es if b != a]
    part = pid == 2
    glass = pid == 1
    pnodes = set(n for e in np.where(part)[0] for n in cs[e])
    zsurf = x[:, 1].max()
    snodes = set(np.where(np.abs(x[:, 1] - zsurf) < 1e-12)[0])
    seeds = [e for e in np.where(glass)[0] if len(pnodes.intersection(cs[e])) >= 2]
    top = set(e for e in np.where(glass)[0] if len(snodes.intersection(cs[e])) >= 2)
    ks = sorted(k for k in f['states'] if k != 'times')
    hist = []
    t_crack = t_spall = None
    for k in ks:
        st = f['states/' + k]
        t = st.attrs['time']
        p = st['pressure'][:]
        d = st['damage'][:]
        pp = (p[part]*vol[part]).sum()/vol[part].sum()
        dam = (d > 0) & glass
        if t_spall is None and any(dam[e] for e in top):
            t_spall = t
        if t_crack is None:
            seen = set(e for e in seeds if dam[e])
            todo = list(seen)
            while todo:
                e = todo.pop()
                for b in nbr[e]:
                    if dam[b] and b not in seen:
                        seen.add(b)
                        todo.append(b)
            if seen & top:
                t_crack = t
        hist.append((t, pp, int(dam.sum())))
    hist = np.array(hist)
    i = int(hist[:, 1].argmax())
    lines = [l for l in open(out + '/glstat') if l.lstrip()[:1] in tuple('+-.0123456789')]
    g = np.loadtxt(lines, ndmin=2)
    cols = open(out + '/glstat').readlines()[2].lstrip('#').split()
    ratio = g[:, cols.index('energy_ratio')]
    return {'hist': hist, 'peak': hist[i, 1], 'tpeak': hist[i, 0], 't_crack': t_crack,
            't_spall': t_spall, 'ratio_dev': abs(ratio[g[:, 0] > 0] - 1).max(),
            'finite': bool(np.isfinite(g).all())}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('out')
    for q in ('peak', 'tpeak', 'tcrack'):
        ap.add_argument('--' + q, type=float, nargs=2)
    ap.add_argument('--ratio', type=float)
    ap.add_argument('--history', action='store_true')
    a = ap.parse_args()
    m = measure(a.out)
    if a.history:
        print('time [ns]  particle pressure [GPa]  damaged glass elements')
        for t, p, n in m['hist']:
            print('%8.3f  %10.4f  %6d' % (t*1e6, p, n))
    ok = m['finite']
    print(('ok   ' if ok else 'FAIL ') + 'glstat finite')
    tc = -1.0 if m['t_crack'] is None else m['t_crack']*1e6
    ts = -1.0 if m['t_spall'] is None else m['t_spall']*1e6
    for q, v, unit, ref in (('peak', m['peak'], 'GPa', 'seed about 3.6 GPa = 36 kbar'),
                            ('tpeak', m['tpeak']*1e6, 'ns', 'seed 1.8 ns'),
                            ('tcrack', tc, 'ns', 'seed 2.9 ns; -1: not reached')):
        band = getattr(a, q)
        good = band is None or band[0] <= v <= band[1]
        ok &= good
        print('%s %-7s %8.3f %s  (%s)%s' % ('ok  ' if good else 'FAIL', q, v, unit, ref,
              '' if band is None else '  band %g..%g' % tuple(band)))
    print('     first damage in the surface row at %.3f ns (-1: none)' % ts)
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
