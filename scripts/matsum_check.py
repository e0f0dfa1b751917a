#!/usr/bin/python3
"""Checks of dynx's matsum file (*DATABASE_MATSUM, issue 16) against glstat and mechanics.

    python3 scripts/matsum_check.py OUTDIR [--sum] [--conserved] [--free P VX VY VZ]
        [--mass P M] [--final P VX TOL] [--nonzero P]

--sum        at every matsum time that glstat also has, the sums over the parts of inten,
             kinen, hgeng and x/y/z-mom equal glstat's internal, kinetic, hourglass and
             x/y/z momentum. Tolerance: both files print 10 significant digits (relative
             rounding 5e-11 per number) and the sums differ only by the order of additions
             (a few ulps times the node count, below 1e-13 here), so |sum - glstat| <= 2e-10
             times the largest magnitude of that quantity over the run (for a momentum
             component: of any momentum component, part or total, since the round-off of a
             nodal velocity is relative to its whole vector).
--conserved  the sum over the parts of each momentum component stays at its first value
             (no external force; 2e-10 times the largest momentum component of any part).
--free P V   part P flies free: its rigid-body velocity is V at every time (2e-10 relative)
             and its momentum is its mass (header mass + its +mass, the added mass) times V.
--added      mass scaling: at every matsum time that glstat also has, the parts' +mass sum
             to glstat's added_mass (2e-10 of its largest value: 10 printed digits each and
             a sum over a few elements), and some part's +mass is positive at the last time.
--mass P M   the header's mass of part P is M (relative 1e-10: M is rho V0 summed in 10 digits).
--final P VX TOL   part P's x rigid-body velocity at the last time is VX within TOL (absolute).
--exchange P Q   x-momentum moves from part P to part Q: P's falls and Q's rises between the
             first and last times, by equal amounts (the 2e-10 bound) of more than 1 % of
             their total.
--nonzero P  part P's internal energy is positive at the last time (the check is not vacuous).
The matsum labels are parsed as LS-DYNA's readers do (after 'time =', the 'mat.#=' block of
4 lines, 'label= value' pairs).
"""
import re
import sys

from ascii_out import read_columns, unknown_option

PAIR = re.compile(r'([A-Za-z_+.#-]+)=\s*([-+0-9.Ee]+)')


def read_matsum(path):
    times, masses, recs = [], {}, {}
    cur = None
    for line in open(path):
        s = line.strip()
        m = re.match(r'part\s+(\d+)\s+mass=\s*(\S+)', s)
        if m:
            masses[int(m.group(1))] = float(m.group(2))
            continue
        if s.startswith('time ='):
            t = float(s.split('=')[1])
            times.append(t)
            recs[t] = {}
            continue
        if s.startswith('mat.#='):
            cur = {}
            pid = int(PAIR.findall(s)[0][1])
            recs[times[-1]][pid] = cur
        if cur is not None:
            for k, v in PAIR.findall(s):
                if k != 'mat.#':
                    cur[k] = float(v)
    return times, masses, recs


def main():
    a = sys.argv[1:]
    out = a.pop(0)
    times, masses, recs = read_matsum(out + '/matsum')
    ok = True
    if not times:
        print('matsum: no records'); sys.exit(1)
    print('matsum: %d times, parts %s' % (len(times), sorted(recs[times[0]])))
    last = recs[times[-1]]
    while a:
        opt = a.pop(0)
        if opt == '--sum':
            g = read_columns(out + '/glstat')
            pairs = [('inten', 'internal'), ('kinen', 'kinetic'), ('hgeng', 'hourglass'),
                     ('x-mom', 'xmom'), ('y-mom', 'ymom'), ('z-mom', 'zmom')]
            n = 0
            pscale = max(abs(r[c]) for r in g.values() for c in ('xmom', 'ymom', 'zmom'))
            pscale = max([pscale] + [abs(p[c + '-mom']) for r in recs.values()
                                     for p in r.values() for c in 'xyz'])
            for mk, gk in pairs:
                scale = max(abs(r[gk]) for r in g.values())
                if mk.endswith('-mom'):
                    scale = pscale
                worst = 0.0
                for t in times:
                    if t not in g:
                        continue
                    s = sum(p[mk] for p in recs[t].values())
                    worst = max(worst, abs(s - g[t][gk]))
                    n += 1
                bound = 2e-10*scale
                good = worst <= bound
                ok &= good
                print('sum over parts of %-6s vs glstat %-9s: largest difference %.3e '
                      '(bound 2e-10 x %.6e = %.3e): %s' % (mk, gk, worst, scale, bound,
                                                          'ok' if good else 'FAIL'))
            if n == 0:
                print('no common times with glstat: FAIL'); ok = False
        elif opt == '--conserved':
            scale = max(abs(p[c + '-mom']) for r in recs.values() for p in r.values()
                        for c in 'xyz')
            for c in 'xyz':
                p0 = sum(p[c + '-mom'] for p in recs[times[0]].values())
                worst = max(abs(sum(p[c + '-mom'] for p in recs[t].values()) - p0) for t in times)
                good = worst <= 2e-10*scale
                ok &= good
                print('total %s-momentum %.10e: largest change %.3e over %d times: %s'
                      % (c, p0, worst, len(times), 'ok' if good else 'FAIL'))
        elif opt == '--free':
            pid = int(a.pop(0)); v = [float(a.pop(0)) for _ in range(3)]
            worst_v, worst_p = 0.0, 0.0
            for t in times:
                r = recs[t][pid]
                for c, vc in zip('xyz', v):
                    worst_v = max(worst_v, abs(r[c + '-rbv'] - vc))
                    worst_p = max(worst_p, abs(r[c + '-mom'] - (masses[pid] + r['+mass'])*vc))
            vmax = max(abs(x) for x in v)
            good = worst_v <= 2e-10*vmax and worst_p <= 2e-10*masses[pid]*vmax
            ok &= good
            print('free part %d: rigid-body velocity %s: largest deviation %.3e, momentum '
                  'vs mass x v %.3e: %s' % (pid, v, worst_v, worst_p, 'ok' if good else 'FAIL'))
        elif opt == '--added':
            g = read_columns(out + '/glstat')
            scale = max(abs(r['added_mass']) for r in g.values())
            worst, n = 0.0, 0
            for t in times:
                if t in g:
                    worst = max(worst, abs(sum(p['+mass'] for p in recs[t].values()) -
                                           g[t]['added_mass']))
                    n += 1
            good = n > 0 and worst <= 2e-10*scale and max(p['+mass'] for p in last.values()) > 0
            ok &= good
            print('sum over parts of +mass vs glstat added_mass: largest difference %.3e over '
                  '%d times (bound 2e-10 x %.6e): %s' % (worst, n, scale, 'ok' if good else 'FAIL'))
        elif opt == '--mass':
            pid = int(a.pop(0)); m = float(a.pop(0))
            good = abs(masses.get(pid, float('nan')) - m) <= 1e-10*abs(m)
            ok &= good
            print('part %d mass %s (expected %.10e): %s' % (pid, masses.get(pid), m,
                                                           'ok' if good else 'FAIL'))
        elif opt == '--final':
            pid = int(a.pop(0)); vx = float(a.pop(0)); tol = float(a.pop(0))
            got = last[pid]['x-rbv']
            good = abs(got - vx) <= tol
            ok &= good
            print('part %d final x-rbv %.6e (expected %g +- %g): %s'
                  % (pid, got, vx, tol, 'ok' if good else 'FAIL'))
        elif opt == '--exchange':
            p1 = int(a.pop(0)); p2 = int(a.pop(0))
            first = recs[times[0]]
            d1 = last[p1]['x-mom'] - first[p1]['x-mom']
            d2 = last[p2]['x-mom'] - first[p2]['x-mom']
            tot = abs(first[p1]['x-mom'] + first[p2]['x-mom'])
            scale = max(abs(p[c + '-mom']) for r in recs.values() for p in r.values()
                        for c in 'xyz')
            good = d1 < -0.01*tot and d2 > 0.01*tot and abs(d1 + d2) <= 2e-10*scale
            ok &= good
            print('x-momentum part %d %+.6e, part %d %+.6e (of %.6e): %s'
                  % (p1, d1, p2, d2, tot, 'ok' if good else 'FAIL'))
        elif opt == '--nonzero':
            pid = int(a.pop(0))
            good = last[pid]['inten'] > 0.0
            ok &= good
            print('part %d final inten %.6e > 0: %s' % (pid, last[pid]['inten'],
                                                        'ok' if good else 'FAIL'))
        else:
            unknown_option(opt)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
