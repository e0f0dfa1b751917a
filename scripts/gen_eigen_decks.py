#!/usr/bin/python3
"""Generate the eigenvalue regression decks (issue 20, *CONTROL_IMPLICIT_EIGENVALUE): a
clamped cantilever L = 5, b = 1 (y), h = 0.5 (z), E = 1000, nu = 0, rho = 1e-3 on three meshes
(10x2x1, 20x4x2, 40x8x4: mesh1.k, mesh2.k, deck.k of eigen_cantilever; center.k: 10x2x1,
the two modes nearest CENTER = 20 cycles), a free-free block
(eigen_free_block) and the bad-input decks. Usage: gen_eigen_decks.py. The meshes and the
deck writer are gen_implicit_decks.py's."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_implicit_decks import Deck, box, ROOT  # noqa: E402

L, B, H, E, RHO = 5.0, 1.0, 0.5, 1000.0, 1.0e-3


def eigen_controls(d, neig, center=0.0, shfscl=0.0, extra=None):
    f = d.f
    d.kw('CONTROL_TERMINATION', f(0.0))
    d.kw('CONTROL_IMPLICIT_GENERAL', '$   IMFLAG       DT0', f(1, 0.0))
    d.kw('CONTROL_IMPLICIT_EIGENVALUE', '$     NEIG    CENTER     LFLAG    LFTEND     RFLAG    '
         'RHTEND    EIGMTH    SHFSCL', extra or f(neig, float(center), 0, 0.0, 0, 0.0, 2,
                                                  float(shfscl)))


def cantilever(n, path, neig=6, extra=None, center=0.0):
    nx, ny, nz = 10*n, 2*n, n
    nodes, elems, nid = box(nx, ny, nz, L, B, H)
    d = Deck('eigen cantilever %dx%dx%d: clamped at x = 0, b = 1, h = 0.5, L = 5' % (nx, ny, nz))
    eigen_controls(d, neig, center=center, extra=extra)
    d.kw('DATABASE_BINARY_D3PLOT', d.f(1.0))
    d.part(2, ('elastic', RHO, E, 0.0))
    d.mesh(nodes, elems)
    for k in range(nz + 1):
        for j in range(ny + 1):
            d.spc(nid(0, j, k), 1, 1, 1)
    d.write(path)


def free_block(path, extra_node=False, neig=10):
    nodes, elems, nid = box(3, 2, 2, 1.5, 1.0, 1.0)
    d = Deck('eigen free-free block 3x2x2: six rigid-body modes, then the flexible ones')
    eigen_controls(d, neig)
    d.kw('DATABASE_BINARY_D3PLOT', d.f(1.0))
    d.part(2, ('elastic', 7.85e-9, 210000.0, 0.3))
    if extra_node:    # a node in no element: neither stiffness nor mass
        nodes[1000] = [5.0, 5.0, 5.0]
    d.mesh(nodes, elems)
    d.write(path)


if __name__ == '__main__':
    c = os.path.join(ROOT, 'eigen_cantilever')
    cantilever(1, os.path.join(c, 'mesh1.k'))
    cantilever(2, os.path.join(c, 'mesh2.k'))
    cantilever(4, os.path.join(c, 'deck.k'))
    cantilever(1, os.path.join(c, 'center.k'), neig=2, center=20.0)   # the 2 modes nearest 20
    free_block(os.path.join(ROOT, 'eigen_free_block', 'deck.k'))
    free_block(os.path.join(ROOT, 'bad_eigen_free_node', 'deck.k'), extra_node=True)
    f = Deck.f
    cantilever(1, os.path.join(ROOT, 'bad_eigen_neig', 'deck.k'),
               extra=f(0, 0.0, 0, 0.0, 0, 0.0, 2, 0.0))
    cantilever(1, os.path.join(ROOT, 'bad_eigen_center', 'deck.k'),
               extra=f(6, -10.0, 0, 0.0, 0, 0.0, 2, 0.0))
    cantilever(1, os.path.join(ROOT, 'bad_eigen_interval', 'deck.k'),
               extra=f(6, 0.0, 1, 5.0, 0, 0.0, 2, 0.0))
    cantilever(1, os.path.join(ROOT, 'bad_eigen_too_many', 'deck.k'), neig=180)
