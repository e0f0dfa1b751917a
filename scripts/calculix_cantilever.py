#!/usr/bin/python3
"""dynx's implicit solver beside CalculiX (Debian calculix-ccx) on the same cantilever meshes
(issue 20: a peer side by side; not part of make test). For n in 1 2 4 (8 with --fine): the
10n x n x n hexahedra of scripts/gen_implicit_decks.py's cantilever (L 10, 1 x 1, E 1000,
nu 0, end load 0.01), dynx ELFORM 2 (B-bar, NSOLVR 1) against ccx C3D8 (full integration)
and C3D8I (incompatible modes), linear static: tip deflection (centre node), Timoshenko's
0.04024, wall time of each run (the process, read and write included).
Usage: scripts/calculix_cantilever.py [--fine] [WORKDIR]"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_implicit_decks as g  # noqa: E402

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')


def ccx_mesh(fh, nodes, elems, etype):
    """ccx's *NODE (NSET NALL) and *ELEMENT (ELSET EALL) cards of a dynx box mesh."""
    fh.write('*NODE, NSET=NALL\n')
    for k in sorted(nodes):
        fh.write('%d, %.9f, %.9f, %.9f\n' % (k, *nodes[k]))
    fh.write('*ELEMENT, TYPE=%s, ELSET=EALL\n' % etype)
    for i, c in enumerate(elems):
        fh.write('%d, %s\n' % (i + 1, ', '.join(str(x) for x in c)))


def ccx_inp(n, etype, path):
    nx, ny, nz = 10*n, n, n
    nodes, elems, nid = g.box(nx, ny, nz, 10.0, 1.0, 1.0)
    P = 1.0e-2
    with open(path, 'w') as fh:
        ccx_mesh(fh, nodes, elems, etype)
        fh.write('*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n')
        fh.write('*NSET, NSET=TIP\n%d\n' % nid(nx, ny//2, nz//2))
        fh.write('*BOUNDARY\n')
        for k in range(nz + 1):
            for j in range(ny + 1):
                fh.write('%d, 1, 3\n' % nid(0, j, k))
        fh.write('*STEP\n*STATIC\n*CLOAD\n')
        for k in range(nz + 1):
            for j in range(ny + 1):
                wy = (0.5 if j in (0, ny) else 1.0)/ny
                wz = (0.5 if k in (0, nz) else 1.0)/nz
                fh.write('%d, 3, %.12g\n' % (nid(nx, j, k), -P*wy*wz))
        fh.write('*NODE PRINT, NSET=TIP\nU\n*END STEP\n')


def ccx_tip(dat):
    lines = open(dat).read().split('\n')
    for i, l in enumerate(lines):
        if 'displacements' in l:
            for m in lines[i + 1:]:
                t = m.split()
                if len(t) == 4:
                    return -float(t[3])
    raise SystemExit('calculix_cantilever: no displacement in %s' % dat)


def dynx_tip(out, node):
    last = None
    for line in open(os.path.join(out, 'nodout')):
        t = line.split()
        if t and line.lstrip()[:1] in tuple('+-.0123456789') and int(t[1]) == node:
            last = t
    return -float(last[4])


def timed(cmd, cwd=None):
    t0 = time.time()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.time() - t0


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    work = os.path.abspath(args[0] if args else 'build/calculix')
    os.makedirs(work, exist_ok=True)
    meshes = [1, 2, 4] + ([8] if '--fine' in sys.argv else [])
    timo = 0.04 + 0.01*10/(5.0/6.0*500.0)
    print('Timoshenko %.6f (Euler-Bernoulli 0.040000)' % timo)
    print('%-8s %12s %8s %12s %8s %12s %8s %10s' % ('mesh', 'dynx B-bar', 'wall s', 'ccx C3D8',
                                                   'wall s', 'ccx C3D8I', 'wall s', 'dynx/C3D8 t'))
    for n in meshes:
        deck = os.path.join(work, 'dynx_%d.k' % n)
        g.cantilever(n, deck)
        out = os.path.join(work, 'dynx_%d' % n)
        td = timed([os.path.join(TOP, 'bin', 'dynx'), '-i', deck, '-o', out])
        d = dynx_tip(out, 1 + 10*n + (10*n + 1)*(n//2 + (n + 1)*(n//2)))
        res = []
        for et in ('C3D8', 'C3D8I'):
            base = 'ccx_%s_%d' % (et, n)
            ccx_inp(n, et, os.path.join(work, base + '.inp'))
            tc = timed(['ccx', base], cwd=work)
            res.append((ccx_tip(os.path.join(work, base + '.dat')), tc))
        print('%-8s %12.8f %8.2f %12.8f %8.2f %12.8f %8.2f %10.2f' % (
            '%dx%dx%d' % (10*n, n, n), d, td, res[0][0], res[0][1], res[1][0], res[1][1],
            td/res[0][1]))


if __name__ == '__main__':
    main()
