#!/usr/bin/python3
"""Generate the implicit contact regression decks (issue 20: penalty contact with Coulomb
friction in Newton). A block (part 1, 2x2x2 hexahedra, 1 x 1 x 1) on a fixed base (part 2,
3x3x1, 2 x 2 x 0.5, every node fixed), *CONTACT_NODES_TO_SURFACE part 1's nodes on part 2
(one pass: every normal is the base's flat top, so the Coulomb law reads Fx = MU Fz),
FS = MU, non-matching meshes; the block starts 1e-3 into the base (so that contact holds it
from the first iteration: a block resting at zero gap has no stiffness across the
interface). Step 1: a normal load N on the block's top; then
 - implicit_friction_block: the top's x displacement prescribed from 0 to DMAX (stick, then
   slip: the tangential reaction grows to MU N and stays);
 - implicit_friction_block/stick.k: a tangential load T = 0.8 MU N (an incline flatter than
   the friction angle): equilibrium in stick;
 - bad_implicit_friction_slip: a tangential load T = RATIO*MU*N (RATIO > 1: the incline
   steeper than the friction angle, tan(theta) = T/N > MU) has no static equilibrium.
Usage: gen_contact_implicit_decks.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_implicit_decks import Deck, box, ROOT  # noqa: E402

MU, N, DMAX, E, NU = 0.3, 100.0, 0.02, 210000.0, 0.3


def block_on_base(path, title, tangential, nsteps=10):
    d = Deck(title)
    f = d.f
    d.controls(float(nsteps), 1.0, dctol=1.0e-6, ectol=1.0e-8, rctol=1.0e-8, abstol=1.0e-9,
               maxref=30)
    for pid in (1, 2):
        d.kw('PART', 'part %d' % pid, '$      PID     SECID       MID', f(pid, 1, 1))
    d.kw('SECTION_SOLID', '$    SECID    ELFORM', f(1, 2))
    d.kw('MAT_ELASTIC', '$      MID        RO         E        PR', f(1, 7.85e-9, E, NU))
    bn, be, bid = box(2, 2, 2, 1.0, 1.0, 1.0)
    gn, ge, gid = box(3, 3, 1, 2.0, 2.0, 0.5)
    nodes = {}
    for k, x in bn.items():
        nodes[k] = [x[0] + 0.5, x[1] + 0.5, x[2] - 1.0e-3]
    off = 1000
    for k, x in gn.items():
        nodes[off + k] = [x[0], x[1], x[2] - 0.5]
    d.kw('NODE', *['%8d%16.9f%16.9f%16.9f' % (n, *nodes[n]) for n in sorted(nodes)])
    el = []
    for i, c in enumerate(be):
        el += ['%8d%8d' % (i + 1, 1), ''.join('%8d' % n for n in c)]
    for i, c in enumerate(ge):
        el += ['%8d%8d' % (101 + i, 2), ''.join('%8d' % (off + n) for n in c)]
    d.kw('ELEMENT_SOLID', *el)
    d.kw('CONTACT_NODES_TO_SURFACE', '$     SSID      MSID     SSTYP     MSTYP', f(1, 2, 3, 3),
         '$       FS        FD        DC        VC       VDC    PENCHK        BT        DT',
         f(MU, MU, 0.0, 0.0, 0.0, 0, 0.0, 0.0), '$      SFS       SFM', f(1.0, 1.0))
    d.curve(1, [(0.0, 0.0), (1.0, 1.0), (100.0, 1.0)])                 # normal load: step 1
    d.curve(2, [(0.0, 0.0), (1.0, 0.0), (float(nsteps), 1.0)])        # tangential: after it
    for k in gn:
        d.spc(off + k, 1, 1, 1)
    top = [bid(i, j, 2) for j in range(3) for i in range(3)]
    for j in range(3):
        for i in range(3):
            w = (0.5 if i in (0, 2) else 1.0)*(0.5 if j in (0, 2) else 1.0)/4.0
            n = bid(i, j, 2)
            d.load(n, 3, 1, -N*w)
            if tangential == 'displacement':
                d.prescribed(n, 1, 2, DMAX)
                d.spc(n, 0, 1, 0)
            else:
                d.load(n, 1, 2, tangential*MU*N*w)
                d.spc(n, 0, 1, 0)
    d.history([bid(1, 1, 0), bid(1, 1, 2)])
    d.kw('DATABASE_SPCFORC', f(1.0))
    d.write(path)


if __name__ == '__main__':
    block_on_base(os.path.join(ROOT, 'implicit_friction_block', 'deck.k'),
                  'implicit friction: block on a base, normal load then a displacement: stick '
                  'then slip at MU N', 'displacement')
    block_on_base(os.path.join(ROOT, 'implicit_friction_block', 'stick.k'),
                  'implicit friction: tangential load 0.8 MU N: stick', 0.8, nsteps=2)
    block_on_base(os.path.join(ROOT, 'bad_implicit_friction_slip', 'deck.k'),
                  'implicit friction: tangential load 1.2 MU N: no static equilibrium', 1.2,
                  nsteps=2)
