#!/usr/bin/python3
"""dynx's eigenvalue run beside CalculiX (Debian calculix-ccx, *FREQUENCY) on the same
cantilever meshes (issue 20: a peer side by side; not part of make test). For n in 1 2 4
(8 with --fine): the 10n x 2n x n hexahedra of scripts/gen_eigen_decks.py (L 5, b 1, h 0.5,
E 1000, nu 0, rho 1e-3, clamped at x = 0), the first 6 frequencies (cycles) of dynx ELFORM 2
(B-bar, lumped mass) and ccx C3D8 and C3D8I (consistent mass), the first bending mode against
the Timoshenko beam (eigen_check.timoshenko_w1), the axial mode against 50 exactly, and the
wall time of each run (the whole process).
Usage: scripts/calculix_eigen.py [--fine] [WORKDIR]"""
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_implicit_decks as g  # noqa: E402
import gen_eigen_decks as ge  # noqa: E402
from eigen_check import eigout, timoshenko_w1  # noqa: E402
from calculix_cantilever import timed, ccx_mesh  # noqa: E402

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
NEIG = 6


def ccx_inp(n, etype, path):
    nx, ny, nz = 10*n, 2*n, n
    nodes, elems, nid = g.box(nx, ny, nz, ge.L, ge.B, ge.H)
    with open(path, 'w') as fh:
        ccx_mesh(fh, nodes, elems, etype)
        fh.write('*MATERIAL, NAME=M\n*ELASTIC\n%g, 0.\n*DENSITY\n%g\n' % (ge.E, ge.RHO))
        fh.write('*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\n')
        for k in range(nz + 1):
            for j in range(ny + 1):
                fh.write('%d, 1, 3\n' % nid(0, j, k))
        fh.write('*STEP\n*FREQUENCY\n%d\n*END STEP\n' % NEIG)


def ccx_freqs(dat):
    """The CYCLES/TIME column of ccx's eigenvalue output table."""
    out, on = [], False
    for line in open(dat):
        if 'E I G E N V A L U E   O U T P U T' in line:
            on = True
            continue
        t = line.split()
        if on and len(t) == 5 and t[0].isdigit():
            out.append(float(t[3]))
            if len(out) == NEIG:
                break
    return out


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    work = os.path.abspath(args[0] if args else 'build/calculix_eigen')
    os.makedirs(work, exist_ok=True)
    meshes = [1, 2, 4] + ([8] if '--fine' in sys.argv else [])
    ft = timoshenko_w1(400)/(2*math.pi)
    print('first bending mode: Timoshenko beam %.6f cycles; axial mode 50 exactly' % ft)
    for n in meshes:
        deck = os.path.join(work, 'dynx_%d.k' % n)
        ge.cantilever(n, deck)
        out = os.path.join(work, 'dynx_%d' % n)
        td = timed([os.path.join(TOP, 'bin', 'dynx'), '-i', deck, '-o', out])
        cols = [('dynx B-bar lumped', [r[3] for r in eigout(out)], td)]
        for et in ('C3D8', 'C3D8I'):
            base = 'ccx_%s_%d' % (et, n)
            ccx_inp(n, et, os.path.join(work, base + '.inp'))
            tc = timed(['ccx', base], cwd=work)
            cols.append(('ccx %s consistent' % et, ccx_freqs(os.path.join(work, base + '.dat')), tc))
        print('\nmesh %dx%dx%d' % (10*n, 2*n, n))
        print('%-24s %s %9s' % ('', ' '.join('%11s' % ('mode %d' % (i + 1)) for i in range(NEIG)),
                                 'wall s'))
        for name, f, t in cols:
            print('%-24s %s %9.2f' % (name, ' '.join('%11.6f' % x for x in f), t))
        for name, f, t in cols:
            print('%-24s mode 1 error vs Timoshenko %+.3f %%, axial mode error vs 50 %+.4f %%' % (
                name, 100*(f[0] - ft)/ft, 100*(min(f, key=lambda x: abs(x - 50.0)) - 50.0)/50.0))


if __name__ == '__main__':
    main()
