#!/usr/bin/env python3
"""Checks for the extreme regression cases (tests/regression/extreme_*/check,
docs/extreme-cases.md). Python 3 stdlib + h5dump, through scripts/dxpost.py.

  extreme_check.py finite OUTDIR            every complete state of d3plot.h5 holds only finite
                                            coordinates, velocities and stresses; glstat only
                                            finite numbers
  extreme_check.py states OUTDIR [--min N] [--tlast T --ttol R]
                                            h5dump -H reads d3plot.h5; nstates >= N (default 1);
                                            the last state's time equals T within relative R
  extreme_check.py ratio OUTDIR --lo A --hi B [--after T0]
                                            glstat energy ratio within [A, B] for t >= T0
  extreme_check.py volume OUTDIR --tol R    total volume of the last state (exact trilinear hex
                                            volume) equals the initial one within relative R
  extreme_check.py minvol OUTDIR --min V    smallest element volume of the last state / its
                                            initial volume >= V (no element near collapse)
  extreme_check.py maxdisp OUTDIR --max U  largest |displacement| component over all states <= U
  extreme_check.py zmax OUTDIR --ref Z --tol T
                                            largest z coordinate of the last state = Z +- T
Each prints what it measured and exits 1 when the check fails."""
import argparse, math, os, re, subprocess, sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dxpost  # noqa: E402


def h5(out):
    return os.path.join(out, 'd3plot.h5')


def nstates(path):
    r = subprocess.run(['h5dump', '-a', '/nstates', path], capture_output=True, text=True)
    m = re.search(r'\(0\):\s*(-?\d+)', r.stdout)
    return int(m.group(1)) if r.returncode == 0 and m else None


def hexvol(p):
    """Exact volume of a trilinear hex (LS-DYNA node order), as the sum of 2x2x2 Gauss det J."""
    xi = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
          (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    g = 1.0 / math.sqrt(3.0)
    v = 0.0
    for r, s, t in [(a * g, b * g, c * g) for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)]:
        d = [[0.0] * 3 for _ in range(3)]
        for k, (a, b, c) in enumerate(xi):
            dn = (a * (1 + b * s) * (1 + c * t) / 8, b * (1 + a * r) * (1 + c * t) / 8,
                  c * (1 + a * r) * (1 + b * s) / 8)
            for i in range(3):
                for j in range(3):
                    d[i][j] += dn[i] * p[k][j]
        v += (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1])
              - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0])
              + d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]))
    return v


def volumes(path, group):
    _, conn = dxpost.dataset(path, '/mesh/hex8')
    _, c = dxpost.dataset(path, group + '/coordinates')
    x = dxpost.vec3(c)
    return [hexvol([x[conn[8 * e + j]] for j in range(8)]) for e in range(len(conn) // 8)]


def cmd_finite(a):
    path = h5(a.out)
    n = nstates(path)
    bad = 0
    for k in range(1, (n or 0) + 1):
        for ds in ('coordinates', 'velocity', 'stress'):
            _, v = dxpost.dataset(path, dxpost.state_path(k) + '/' + ds)
            nb = sum(1 for q in v if not math.isfinite(q))
            if nb:
                print('state %d %s: %d non-finite values' % (k, ds, nb))
                bad += nb
    g = os.path.join(a.out, 'glstat')
    if os.path.exists(g):
        _, rows = dxpost.columns(g)
        nb = sum(1 for r in rows for q in r if not math.isfinite(q))
        if nb:
            print('glstat: %d non-finite values' % nb)
            bad += nb
    print('finite: %s states checked, %d non-finite values' % (n, bad))
    return n is not None and n >= 1 and bad == 0


def cmd_states(a):
    path = h5(a.out)
    r = subprocess.run(['h5dump', '-H', path], capture_output=True, text=True)
    if r.returncode != 0:
        print('h5dump -H %s failed (exit %d): %s' % (path, r.returncode, r.stderr.strip()))
        return False
    n = nstates(path)
    times = dxpost.states(path)
    print('h5dump -H ok; nstates %s; state times %s' % (n, ' '.join('%.6g' % t for t in times)))
    ok = n is not None and n >= a.min and len(times) == n
    if a.tlast is not None:
        ok &= dxpost.report('last state time', times[-1] if times else float('nan'), a.tlast,
                            0.0, a.ttol)
    return ok


def cmd_ratio(a):
    names, rows = dxpost.columns(os.path.join(a.out, 'glstat'))
    r = names.index('energy_ratio')
    sel = [x[r] for x in rows if x[0] >= a.after]
    if not sel:
        print('no glstat rows at t >= %g' % a.after)
        return False
    lo, hi = min(sel), max(sel)
    ok = all(math.isfinite(q) for q in sel) and lo >= a.lo and hi <= a.hi
    print('energy ratio for t >= %g (%d rows): min %.6f max %.6f final %.6f   band [%g, %g]   %s'
          % (a.after, len(sel), lo, hi, sel[-1], a.lo, a.hi, 'PASS' if ok else 'FAIL'))
    return ok


def cmd_volume(a):
    path = h5(a.out)
    n = len(dxpost.states(path))
    v0 = sum(volumes(path, '/mesh'))
    v1 = sum(volumes(path, dxpost.state_path(n)))
    return dxpost.report('total volume / initial', v1 / v0, 1.0, a.tol, 0.0)


def cmd_minvol(a):
    path = h5(a.out)
    n = len(dxpost.states(path))
    v0 = volumes(path, '/mesh')
    v1 = volumes(path, dxpost.state_path(n))
    rmin = min(q / p for p, q in zip(v0, v1))
    ok = math.isfinite(rmin) and rmin >= a.min
    print('smallest element volume / initial %.6f   floor %g   %s'
          % (rmin, a.min, 'PASS' if ok else 'FAIL'))
    return ok


def cmd_maxdisp(a):
    path = h5(a.out)
    n = len(dxpost.states(path))
    umax = 0.0
    for k in range(1, n + 1):
        _, d = dxpost.dataset(path, dxpost.state_path(k) + '/displacement')
        umax = max([umax] + [abs(q) if math.isfinite(q) else float('inf') for q in d])
    ok = umax <= a.max
    print('largest |displacement| over %d states %.6g   bound %g   %s'
          % (n, umax, a.max, 'PASS' if ok else 'FAIL'))
    return ok


def cmd_zmax(a):
    path = h5(a.out)
    n = len(dxpost.states(path))
    _, c = dxpost.dataset(path, dxpost.state_path(n) + '/coordinates')
    return dxpost.report('largest z, last state', max(p[2] for p in dxpost.vec3(c)), a.ref,
                         a.tol, 0.0)


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('finite'); p.add_argument('out')
    p = sub.add_parser('states'); p.add_argument('out')
    p.add_argument('--min', type=int, default=1)
    p.add_argument('--tlast', type=float); p.add_argument('--ttol', type=float, default=1e-5)
    p = sub.add_parser('ratio'); p.add_argument('out')
    p.add_argument('--lo', type=float, required=True); p.add_argument('--hi', type=float,
                                                                       required=True)
    p.add_argument('--after', type=float, default=-1.0)
    p = sub.add_parser('volume'); p.add_argument('out')
    p.add_argument('--tol', type=float, required=True)
    p = sub.add_parser('minvol'); p.add_argument('out')
    p.add_argument('--min', type=float, required=True)
    p = sub.add_parser('maxdisp'); p.add_argument('out')
    p.add_argument('--max', type=float, required=True)
    p = sub.add_parser('zmax'); p.add_argument('out')
    p.add_argument('--ref', type=float, required=True)
    p.add_argument('--tol', type=float, required=True)
    a = ap.parse_args()
    ok = {'maxdisp': cmd_maxdisp, 'zmax': cmd_zmax, 'finite': cmd_finite, 'states': cmd_states, 'ratio': cmd_ratio, 'volume': cmd_volume,
          'minvol': cmd_minvol}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
