#!/usr/bin/python3
"""Check of a skew SPC (*BOUNDARY_SPC_* with CID): a body on a frictionless plane of unit
normal n under a uniform gravity g, some of its nodes held along n (regression case
skew_spc_incline).

  skew_spc_check.py OUT --normal NX NY NZ --mass M --g GX GY GZ --nodes N1 N2 ...

1. The held nodes move in the plane: their displacement along n (nodout) stays below 1e-9
   of the largest displacement of the run (round-off of x - x0 and nodout's 11 digits).
2. The reactions are normal to the plane, so the momentum along the plane is gravity's
   impulse exactly: p - (p.n) n = M (g - (g.n) n) (t + dt/2) in every glstat row (the
   momentum is that of v(n+1/2); dt the row's step), to 1e-8 of M |g| t (11 digits).
3. spcforc: every resultant is along +n (|R x n| <= 1e-9 |R|, R.n > 0) and its mean over
   the rows after the first tenth of the run is the body's weight normal to the plane,
   -M g.n, within 10 % (the block rings elastically on its held face: the row values swing
   about the static value).
Exit 1 with the first failure named.
"""
import argparse
import math
import sys

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from ascii_out import read_table  # noqa: E402


def dot(a, b):
    return sum(x*y for x, y in zip(a, b))


def fail(msg):
    print('FAIL:', msg)
    sys.exit(1)


def spcforc_resultants(path):
    """[(t, R)] from the 'output at time' and 'force resultants' lines."""
    out, t = [], None
    for line in open(path):
        if 'output at time' in line:
            t = float(line.split('=')[1])
        elif 'force resultants' in line:
            w = line.split('=')[1].split()
            out.append((t, [float(x) for x in w[:3]]))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('out')
    ap.add_argument('--normal', type=float, nargs=3, required=True)
    ap.add_argument('--mass', type=float, required=True)
    ap.add_argument('--g', type=float, nargs=3, required=True)
    ap.add_argument('--nodes', type=int, nargs='+', required=True)
    a = ap.parse_args()
    nn = math.sqrt(dot(a.normal, a.normal))
    n = [x/nn for x in a.normal]
    gn = dot(a.g, n)
    gt = [a.g[k] - gn*n[k] for k in range(3)]
    gmag = math.sqrt(dot(a.g, a.g))

    rows = [r for r in read_table(a.out + '/nodout') if int(r[1]) in a.nodes]
    if len(rows) < 10*len(a.nodes):
        fail('nodout has %d rows of the held nodes' % len(rows))
    dmax = max(math.sqrt(dot(r[2:5], r[2:5])) for r in rows)
    worst = max(abs(dot(r[2:5], n)) for r in rows)/dmax
    if worst > 1e-9:
        fail('a held node leaves the plane: max |d.n| / max |d| = %.3e' % worst)
    print('ok: held nodes in the plane (max |d.n| = %.2e of max |d| %.4e, %d rows)'
          % (worst, dmax, len(rows)))

    worst = 0.0
    g = read_table(a.out + '/glstat')
    for r in g[1:]:
        t, p = r[0] + 0.5*r[2], r[10:13]     # glstat's momentum: v(n+1/2), dt the next step
        pn = dot(p, n)
        err = max(abs(p[k] - pn*n[k] - a.mass*gt[k]*t) for k in range(3))
        worst = max(worst, err/(a.mass*gmag*t))
    if len(g) < 10 or worst > 1e-8:
        fail('tangential momentum is not M g_t t: relative error %.3e (%d rows)' % (worst, len(g)))
    print('ok: tangential momentum = M g_t t (largest relative error %.2e over %d rows)'
          % (worst, len(g) - 1))

    res = spcforc_resultants(a.out + '/spcforc')
    tend = res[-1][0]
    worst = 0.0
    for t, rr in res:
        m = math.sqrt(dot(rr, rr))
        c = [rr[1]*n[2] - rr[2]*n[1], rr[2]*n[0] - rr[0]*n[2], rr[0]*n[1] - rr[1]*n[0]]
        worst = max(worst, math.sqrt(dot(c, c))/m)
        if dot(rr, n) <= 0.0:
            fail('reaction at t = %g does not push along +n' % t)
    if worst > 1e-9:
        fail('reaction not normal to the plane: |R x n|/|R| = %.3e' % worst)
    late = [dot(rr, n) for t, rr in res if t > 0.1*tend]
    mean = sum(late)/len(late)
    want = -a.mass*gn
    if abs(mean/want - 1.0) > 0.1:
        fail('mean normal reaction %.6e, weight normal to the plane %.6e' % (mean, want))
    print('ok: reactions normal (largest |R x n|/|R| %.2e); mean R.n %.6e = %.4f x M |g.n|'
          % (worst, mean, mean/want))


if __name__ == '__main__':
    main()
