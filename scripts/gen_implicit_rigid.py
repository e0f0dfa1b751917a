#!/usr/bin/python3
"""Generate the decks of the implicit rigid-body cases (issue 20, item rigid bodies):
  implicit_rigid_punch  a rigid punch (*MAT_RIGID, *BOUNDARY_PRESCRIBED_MOTION_RIGID VAD 2)
                        pressed into an elastic block through penalty contact, statically;
                        stiff.k / stiffer.k: the same punch elastic, E x 1e3 and x 1e5,
                        pushed by its top nodes;
  implicit_rigid_twist  a rigid plate merged with the top of an elastic block, turned by a
                        nodal couple to a large rotation (6 free body equations);
                        stiff.k / stiffer.k: the plate elastic, E x 1e3 and x 1e5;
  implicit_rigid_torsion the plate as a torsional oscillator in implicit dynamics (HHT
                        ALPHA -0.1; newmark.k trapezoidal), an initial spin about z, the
                        block massless (rho 1e-12 of the plate's): one rotational mode;
                        static.k: a small couple, the torsional stiffness k = M/theta.
Usage: gen_implicit_rigid.py (writes the three cases' decks)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_implicit_decks import Deck, ROOT  # noqa: E402

E, NU = 1000.0, 0.3


def grid(x0, x1, nx, y0, y1, ny, z0, z1, nz, base):
    """Nodes {id: xyz} and hexahedra of a box meshed nx x ny x nz, ids from base + 1."""
    nid = lambda i, j, k: base + 1 + i + (nx + 1)*(j + (ny + 1)*k)
    nodes = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes[nid(i, j, k)] = (x0 + (x1 - x0)*i/nx, y0 + (y1 - y0)*j/ny,
                                       z0 + (z1 - z0)*k/nz)
    elems = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elems.append([nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                              nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                              nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)])
    return nodes, elems, nid


def parts(d, second):
    """Part 1 elastic block (MAT 1); part 2 (MAT 2): ('rigid', ro, con1, con2) or
    ('elastic', ro, e)."""
    f = d.f
    d.kw('PART', 'block', '$      PID     SECID       MID', f(1, 1, 1))
    d.kw('PART', 'plate or punch', '$      PID     SECID       MID', f(2, 1, 2))
    d.kw('SECTION_SOLID', '$    SECID    ELFORM', f(1, 2))
    d.kw('MAT_ELASTIC', '$      MID        RO         E        PR', f(1, second[-1], E, NU))
    if second[0] == 'rigid':
        _, ro, con1, con2, _ = second
        d.kw('MAT_RIGID', '$      MID        RO         E        PR', f(2, ro, E, NU),
             '$      CMO      CON1      CON2', f(1.0, con1, con2))
    else:
        _, ro, e, _ = second
        d.kw('MAT_ELASTIC', '$      MID        RO         E        PR', f(2, ro, e, NU))


def nodes(d, nd):
    d.kw('NODE', *['%8d%16.9f%16.9f%16.9f' % (n, *nd[n]) for n in sorted(nd)])


def elements(d, groups):
    el = []
    k = 0
    for pid, elems in groups:
        for c in elems:
            k += 1
            el.append('%8d%8d' % (k, pid))
            el.append(''.join('%8d' % n for n in c))
    d.kw('ELEMENT_SOLID', *el)


def punch(path, kind):
    """Quarter model: block [0,2]^2 x [0,1] (4x4x2), base z = 0 held in z, symmetry planes
    x = 0, y = 0; punch [0,0.75]^2 x [1,1.5] (3x3x1, non-matching), pressed 0.05 in 4 steps.
    Frictionless NODES_TO_SURFACE, slave the punch's bottom nodes, master the block's top
    (segment set), SFS = SFM = 100."""
    bn, be, bid = grid(0.0, 2.0, 4, 0.0, 2.0, 4, 0.0, 1.0, 2, 0)
    pn, pe, pid = grid(0.0, 0.75, 3, 0.0, 0.75, 3, 1.0, 1.5, 1, 1000)
    d = Deck('implicit rigid bodies: a %s punch pressed into an elastic block (quarter)' % (
        'rigid' if kind == 'rigid' else 'stiff elastic (E x %g)' % kind))
    d.controls(1.0, 0.25, dctol=1e-6, ectol=1e-8, rctol=1e-10 if kind == 'rigid' else 1e-9,
               abstol=1e-12, maxref=30)
    d.kw('DATABASE_SPCFORC', d.f(0.25))
    if kind == 'rigid':
        parts(d, ('rigid', 1e-9, 4, 7, 1e-9))
    else:
        parts(d, ('elastic', 1e-9, E*kind, 1e-9))
    nodes(d, {**bn, **pn})
    elements(d, [(1, be), (2, pe)])
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(bn.items()):
        sx, sy, sz = abs(x[0]) < 1e-9, abs(x[1]) < 1e-9, abs(x[2]) < 1e-9
        if sx or sy or sz:
            d.spc(n, int(sx), int(sy), int(sz))
    if kind == 'rigid':
        d.kw('BOUNDARY_PRESCRIBED_MOTION_RIGID', '$      PID       DOF       VAD      LCID        SF',
             d.f(2, 3, 2, 1, -0.05))
    else:
        for n, x in sorted(pn.items()):
            if abs(x[2] - 1.5) < 1e-9:
                d.prescribed(n, 3, 1, -0.05)
                d.spc(n, 1, 1, 0)
            elif abs(x[0]) < 1e-9 or abs(x[1]) < 1e-9:
                d.spc(n, int(abs(x[0]) < 1e-9), int(abs(x[1]) < 1e-9), 0)
    # slave: the punch's bottom nodes (a node set), master: the block's top (a segment set,
    # normal +z), so that the penalty is the block's segments' in every deck (a stiff
    # elastic master's penalty grows with its E), NODES_TO_SURFACE (one way)
    d.kw('SET_SEGMENT', d.f(1), *[d.f(bid(i, j, 2), bid(i + 1, j, 2), bid(i + 1, j + 1, 2),
                                      bid(i, j + 1, 2)) for j in range(4) for i in range(4)])
    bot = [pid(i, j, 0) for j in range(4) for i in range(4)]
    d.kw('SET_NODE_LIST', d.f(2), *[''.join(d.f(n) for n in bot[k:k + 8])
                                    for k in range(0, len(bot), 8)])
    d.kw('CONTACT_NODES_TO_SURFACE', '$     SSID      MSID     SSTYP     MSTYP',
         d.f(2, 1, 4, 0), '$       FS        FD', d.f(0.0, 0.0), '$      SFS       SFM',
         d.f(100.0, 100.0))
    d.history([bid(0, 0, 2), pid(0, 0, 1)])
    d.write(path)


def plate_model(d, kind, ro_plate):
    """Block [-1,1]^2 x [0,1] (2x2x2), base fixed; plate [-1,1]^2 x [1,1.2] (2x2x1) on its top
    nodes (shared)."""
    bn, be, bid = grid(-1.0, 1.0, 2, -1.0, 1.0, 2, 0.0, 1.0, 2, 0)
    pn, pe, pid = grid(-1.0, 1.0, 2, -1.0, 1.0, 2, 1.0, 1.2, 1, 1000)
    # the plate's bottom nodes are the block's top nodes
    same = {pid(i, j, 0): bid(i, j, 2) for i in range(3) for j in range(3)}
    pe = [[same.get(n, n) for n in c] for c in pe]
    pn = {n: x for n, x in pn.items() if n not in same}
    return bn, be, bid, pn, pe, pid


def twist(path, kind, ro=1e-9):
    """The plate turned by a couple of nodal forces F = +-15 along y at (+-1, 0, 1.2), ramped
    over 5 steps to M = 30 (a rotation of about 0.35 rad): large rotation; CON1 = CON2 = 0
    (all six body equations free)."""
    d = Deck('implicit rigid bodies: a %s plate twisted on an elastic block' % (
        'rigid' if kind == 'rigid' else 'stiff elastic (E x %g)' % kind))
    # (the stiff plates' round-off floor is E_plate/E times higher: RCTOL 1e-9 there)
    d.controls(1.0, 0.2, dctol=1e-8, ectol=1e-12, rctol=1e-12 if kind == 'rigid' else 1e-9,
               abstol=1e-11, maxref=30)
    bn, be, bid, pn, pe, pid = plate_model(d, kind, ro)
    if kind == 'rigid':
        parts(d, ('rigid', 1.0, 0, 0, ro))
    else:
        parts(d, ('elastic', 1.0, E*kind, ro))
    nodes(d, {**bn, **pn})
    elements(d, [(1, be), (2, pe)])
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(bn.items()):
        if abs(x[2]) < 1e-9:
            d.spc(n, 1, 1, 1)
    d.load(pid(2, 1, 1), 2, 1, 100.0)
    d.load(pid(0, 1, 1), 2, 1, -100.0)
    d.history([pid(2, 2, 1), pid(1, 1, 1)])
    d.write(path)


def torsion(path, alpha=None, static=False):
    """The plate (rho 1, mass 0.8, J_zz = 0.8 (4 + 4)/12) on the block (rho 1e-12):
    CON1 = 7, CON2 = 4 (only the spin about z free). static: a couple M = 2e-3 in one step
    (rotation ~2e-6: the frequency's nonlinear part is O(theta^2), the system being odd in
    theta). Dynamics: an initial spin omega = 1e-4 about z (the nodes' v = omega x r; amplitude
    ~2.3e-6 rad), DT0 = 0.0035 (T = 2 pi sqrt(J/k) ~ 0.143: ~41 steps a period), 2.4
    periods; HHT ALPHA -0.1 or Newmark 1/2, 1/4."""
    d = Deck('implicit rigid bodies: %s' % ('torsional stiffness (static couple)' if static
             else 'torsional oscillator, %s' % ('Newmark trapezoidal' if alpha is None
                                                else 'HHT ALPHA %g' % alpha)))
    # tolerances: internal forces carry a round-off of ~1e-13 (the Green strain of 2e-6
    # displacements), 1e-10 of the couple: RCTOL 1e-9, ABSTOL 1e-13
    if static:
        d.controls(1.0, 1.0, dctol=1e-8, ectol=1e-14, rctol=1e-9, abstol=1e-13, maxref=20)
    else:
        d.controls(0.35, 0.0035, dctol=1e-8, ectol=1e-14, rctol=1e-9, abstol=1e-13, maxref=20)
        if alpha is None:
            d.kw('CONTROL_IMPLICIT_DYNAMICS', '$    IMASS     GAMMA      BETA', d.f(1, 0.5, 0.25))
        else:
            d.kw('CONTROL_IMPLICIT_DYNAMICS', '$    IMASS     GAMMA      BETA    TDYBIR    '
                 'TDYDTH    TDYBUR     IRATE     ALPHA', d.f(1, 0.0, 0.0, 0, 0, 0, 0, float(alpha)))
    bn, be, bid, pn, pe, pid = plate_model(d, 'rigid', 1.0)
    parts(d, ('rigid', 1.0, 7, 4, 1e-12))
    nodes(d, {**bn, **pn})
    elements(d, [(1, be), (2, pe)])
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(bn.items()):
        if abs(x[2]) < 1e-9:
            d.spc(n, 1, 1, 1)
    if static:
        d.load(pid(2, 1, 1), 2, 1, 1e-3)
        d.load(pid(0, 1, 1), 2, 1, -1e-3)
    else:
        w = 1e-4
        allp = {**{n: bn[n] for n in bn if abs(bn[n][2] - 1.0) < 1e-9}, **pn}
        d.kw('INITIAL_VELOCITY_NODE', *['%d,%.17g,%.17g,0.0' % (n, -w*x[1], w*x[0])
                                         for n, x in sorted(allp.items())])
    d.history([pid(2, 1, 1)])
    d.write(path)


def main():
    c = os.path.join(ROOT, 'implicit_rigid_punch')
    punch(os.path.join(c, 'deck.k'), 'rigid')
    punch(os.path.join(c, 'stiff.k'), 1e3)
    punch(os.path.join(c, 'stiffer.k'), 1e5)
    c = os.path.join(ROOT, 'implicit_rigid_twist')
    twist(os.path.join(c, 'deck.k'), 'rigid')
    twist(os.path.join(c, 'stiff.k'), 1e3)
    twist(os.path.join(c, 'stiffer.k'), 1e5)
    c = os.path.join(ROOT, 'implicit_rigid_torsion')
    torsion(os.path.join(c, 'deck.k'), alpha=-0.1)
    torsion(os.path.join(c, 'newmark.k'))
    torsion(os.path.join(c, 'static.k'), static=True)


if __name__ == '__main__':
    main()
