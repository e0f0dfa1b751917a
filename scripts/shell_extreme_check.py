#!/usr/bin/env python3
"""Checks for the shell extreme cases (tests/regression/extreme_shell_*, bad_shell_warped;
docs/studies/stability.md). Python 3 stdlib; reads OUTDIR/glstat.

  shell_extreme_check.py dt OUTDIR --e E --rho RHO --nu NU --l L --tssfac S --tol R
        every glstat row's step equals the membrane bound S L / c, c = sqrt(E/(rho(1-nu^2)))
        (the plane-stress wave speed; L the element's characteristic length) within relative
        R: neither the thickness nor nu -> 0.5 sets the step of a shell
  shell_extreme_check.py deform OUTDIR --min F
        the largest internal energy over the run >= F times the initial kinetic energy (the
        plate deforms: an energy ratio near 1 is not that of a rigid motion)
Each prints what it measured and exits 1 when the check fails."""
import argparse, math, os, sys


def rows(out):
    cols, data = None, []
    for line in open(os.path.join(out, 'glstat')):
        if line.startswith('#'):
            continue
        f = line.split()
        if cols is None:
            cols = f
            continue
        data.append(dict(zip(cols, (float(x) for x in f))))
    if not data:
        sys.exit('%s/glstat: no rows' % out)
    return data


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('dt'); p.add_argument('out')
    for k in ('e', 'rho', 'nu', 'l', 'tssfac', 'tol'):
        p.add_argument('--' + k, type=float, required=True)
    p = sub.add_parser('deform'); p.add_argument('out')
    p.add_argument('--min', type=float, required=True)
    a = ap.parse_args()
    d = rows(a.out)
    if a.cmd == 'dt':
        ref = a.tssfac*a.l/math.sqrt(a.e/(a.rho*(1.0 - a.nu**2)))
        err = max(abs(r['dt']/ref - 1.0) for r in d)
        ok = err <= a.tol
        print('dt: %d rows, bound S L/c = %.10e, largest relative difference %.3e (tol %.1e)   %s'
              % (len(d), ref, err, a.tol, 'PASS' if ok else 'FAIL'))
    else:
        ke0 = d[0]['kinetic']
        f = max(r['internal'] for r in d)/ke0
        ok = f >= a.min
        print('deform: max internal / initial kinetic = %.4f (min %.4f)   %s'
              % (f, a.min, 'PASS' if ok else 'FAIL'))
    sys.exit(0 if ok else 1)


main()
