#!/usr/bin/python3
"""Generate the implicit solver's regression decks (issue 20): brick meshes of 8-node
hexahedra with elastic or *MAT_024 material, SPC, prescribed displacements, nodal loads and
pressure segments. Usage: gen_implicit_decks.py (writes every tests/regression/implicit_*
deck; the cases' checks say what each asserts)."""
import math
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tests', 'regression')


def box(nx, ny, nz, lx, ly, lz, perturb=None):
    """Nodes {id: (x, y, z)} and hex connectivity of a box [0,lx]x[0,ly]x[0,lz]."""
    nid = lambda i, j, k: 1 + i + (nx + 1)*(j + (ny + 1)*k)
    nodes = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                x = [lx*i/nx, ly*j/ny, lz*k/nz]
                if perturb and 0 < i < nx and 0 < j < ny and 0 < k < nz:
                    x = perturb(x)
                nodes[nid(i, j, k)] = x
    elems = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elems.append([nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                              nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                              nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)])
    return nodes, elems, nid


class Deck:
    def __init__(self, title):
        self.lines = ['*KEYWORD', '*TITLE', title]
        self.lists = {}    # keyword -> cards, written once each at the end (list keywords)

    def kw(self, name, *cards):
        self.lines.append('*' + name)
        for c in cards:
            self.lines.append(c)

    @staticmethod
    def num(v):
        """v in at most 10 characters with the most significant digits (g or e form)."""
        for p in range(9, 0, -1):
            for t in ('%.*g' % (p, v), ('%.*e' % (p - 1, v)).replace('e-0', 'e-').replace('e+0', 'e')):
                if len(t) <= 10:
                    return t
        return '%.3e' % v

    @staticmethod
    def f(*vals):
        out = ''
        for v in vals:
            if isinstance(v, float):   # the most digits that fit the 10 columns
                out += Deck.num(v).rjust(10)
            else:
                out += str(v).rjust(10)
        return out

    def controls(self, endtim, dt0, nsolvr=12, dctol=0.0, ectol=0.0, rctol=0.0, lstol=0.0,
                 abstol=0.0, maxref=0, plot_dt=None, iauto=None):
        f = self.f
        self.kw('CONTROL_TERMINATION', f(float(endtim)))
        self.kw('CONTROL_IMPLICIT_GENERAL', '$   IMFLAG       DT0', f(1, float(dt0)))
        self.kw('CONTROL_IMPLICIT_SOLUTION', '$   NSOLVR    ILIMIT    MAXREF     DCTOL     '
                'ECTOL     RCTOL     LSTOL    ABSTOL',
                f(nsolvr, 0, maxref, dctol, ectol, rctol, lstol, abstol))
        if iauto is not None:
            self.kw('CONTROL_IMPLICIT_AUTO', '$    IAUTO    ITEOPT    ITEWIN     DTMIN     DTMAX',
                    f(iauto, 0, 0, 0.0, 0.0))
        self.kw('DATABASE_GLSTAT', f(float(dt0)))
        self.kw('DATABASE_NODOUT', f(float(dt0)))
        self.kw('DATABASE_BINARY_D3PLOT', f(float(plot_dt or dt0)))

    def part(self, elform, mat):
        f = self.f
        self.kw('PART', 'block', '$      PID     SECID       MID', f(1, 1, 1))
        self.kw('SECTION_SOLID', '$    SECID    ELFORM', f(1, elform))
        if mat[0] == 'elastic':
            _, ro, e, pr = mat
            self.kw('MAT_ELASTIC', '$      MID        RO         E        PR', f(1, ro, e, pr))
        else:
            _, ro, e, pr, sigy, etan = mat
            self.kw('MAT_PIECEWISE_LINEAR_PLASTICITY', '$      MID        RO         E        '
                    'PR      SIGY      ETAN', f(1, ro, e, pr, sigy, etan))

    def mesh(self, nodes, elems):
        lines = ['%8d%16.9f%16.9f%16.9f' % (n, *nodes[n]) for n in sorted(nodes)]
        self.kw('NODE', *lines)
        el = []
        for i, c in enumerate(elems):
            el.append('%8d%8d' % (i + 1, 1))
            el.append(''.join('%8d' % n for n in c))
        self.kw('ELEMENT_SOLID', *el)

    def curve(self, lcid, pts):
        self.kw('DEFINE_CURVE', self.f(lcid), *['%20.6g%20.6g' % p for p in pts])

    def spc(self, node, dx, dy, dz):
        self.lists.setdefault('BOUNDARY_SPC_NODE', []).append(self.f(node, 0, dx, dy, dz, 0, 0, 0))

    def prescribed(self, node, dof, lcid, sf):
        if sf == 0.0:    # (SF = 0 reads as LS-DYNA's default 1: a zero value is an SPC)
            self.spc(node, *[1 if d == dof else 0 for d in (1, 2, 3)])
            return
        self.lists.setdefault('BOUNDARY_PRESCRIBED_MOTION_NODE', []).append(
            self.f(node, dof, 2, lcid, float(sf)))

    def load(self, node, dof, lcid, sf):
        self.lists.setdefault('LOAD_NODE_POINT', []).append(self.f(node, dof, lcid, float(sf)))

    def history(self, nodes):
        self.kw('DATABASE_HISTORY_NODE', *[''.join(self.f(n) for n in nodes[i:i + 8])
                                           for i in range(0, len(nodes), 8)])

    def write(self, path):
        for k, cards in self.lists.items():
            self.kw(k, *cards)
        self.lists = {}
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w') as fh:
            fh.write('\n'.join(self.lines + ['*END']) + '\n')


def tets(nodes, elems):
    """Each hexahedron as 6 tetrahedra around its 1-7 diagonal (Kuhn: conforming when every
    hexahedron is split alike), each oriented to a positive volume."""
    out = []
    for c in elems:
        for a, b in ((1, 2), (2, 3), (3, 7), (7, 4), (4, 5), (5, 1)):
            t = [c[0], c[a], c[b], c[6]]
            x = [nodes[n] for n in t]
            d = [[x[k][i] - x[0][i] for i in range(3)] for k in (1, 2, 3)]
            vol = (d[0][0]*(d[1][1]*d[2][2] - d[1][2]*d[2][1]) - d[0][1]*(d[1][0]*d[2][2] -
                   d[1][2]*d[2][0]) + d[0][2]*(d[1][0]*d[2][1] - d[1][1]*d[2][0]))
            if vol < 0:
                t[1], t[2] = t[2], t[1]
            out.append(t + [t[3]]*4)
    return out


def patch(tet=False):
    """2x2x2 cube with its interior node moved: every boundary node prescribed the linear
    field u = G x; NSOLVR 1 (one solve)."""
    pert = lambda x: [0.56, 0.46, 0.53]
    nodes, elems, nid = box(2, 2, 2, 1.0, 1.0, 1.0, pert)
    # interior face/edge nodes moved too (irregular elements), only in the face plane
    for n, x in nodes.items():
        on = [abs(c) < 1e-12 or abs(c - 1.0) < 1e-12 for c in x]
        if sum(on) == 1:     # face centre nodes
            nodes[n] = [x[d] if on[d] else x[d] + (0.04 if d == 0 else -0.03) for d in range(3)]
    g = [[1.0e-3, 2.0e-4, -3.0e-4], [4.0e-4, -5.0e-4, 1.0e-4], [-2.0e-4, 3.0e-4, 8.0e-4]]
    if tet:
        d = Deck('implicit patch test: linear field on the boundary of 48 irregular tetrahedra')
        elems = tets(nodes, elems)
    else:
        d = Deck('implicit patch test: linear field on the boundary of 8 irregular hexahedra')
    d.controls(1.0, 1.0, nsolvr=1)
    d.part(10 if tet else 2, ('elastic', 7.85e-9, 210000.0, 0.3))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(nodes.items()):
        if any(abs(c) < 1e-12 or abs(c - 1.0) < 1e-12 for c in x):
            for i in range(3):
                d.prescribed(n, i + 1, 1, sum(g[i][j]*x[j] for j in range(3)))
    d.history([nid(1, 1, 1)])
    d.write(os.path.join(ROOT, 'implicit_patch_tet' if tet else 'implicit_patch', 'deck.k'))


def cantilever(n, path, nsolvr=1, P=1.0e-2, dt0=1.0, tols=None):
    """L = 10, 1 x 1 section, clamped at x = 0, end load P = 1e-3 E h^2... along -z at
    x = L spread bilinearly over the end face; nu = 0; 2n x n/5... mesh (10 n/ 1 ... )."""
    nx, ny, nz = 10*n, n, n
    L, h, E = 10.0, 1.0, 1000.0
    nodes, elems, nid = box(nx, ny, nz, L, h, h)
    if tols:
        d = Deck('implicit cantilever %dx%dx%d: large deflection, elastica' % (nx, ny, nz))
        d.controls(1.0, dt0, nsolvr=nsolvr, **tols)
    else:
        d = Deck('implicit cantilever %dx%dx%d: end load, Timoshenko' % (nx, ny, nz))
        d.controls(1.0, dt0, nsolvr=nsolvr)
    d.part(2, ('elastic', 1.0e-9, E, 0.0))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for k in range(nz + 1):
        for j in range(ny + 1):
            d.spc(nid(0, j, k), 1, 1, 1)
            wy = (0.5 if j in (0, ny) else 1.0)/ny
            wz = (0.5 if k in (0, nz) else 1.0)/nz
            d.load(nid(nx, j, k), 3, 1, -P*wy*wz)
    d.history([nid(nx, 0, 0), nid(nx, ny, nz), nid(nx, ny//2, nz//2)])
    d.kw('DATABASE_SPCFORC', d.f(float(dt0)))
    d.write(path)


def lame(nr, nt, pr, path):
    """Quarter of a thick cylinder a = 1, b = 2 in plane strain (one element thick, z fixed),
    inner pressure p = 10 (E = 1000), symmetry planes x = 0 and y = 0."""
    a, b, E, p = 1.0, 2.0, 1000.0, 10.0
    nid = lambda i, j, k: 1 + i + (nr + 1)*(j + (nt + 1)*k)
    nodes = {}
    for k in range(2):
        for j in range(nt + 1):
            th = 0.5*math.pi*j/nt
            for i in range(nr + 1):
                r = a + (b - a)*i/nr
                nodes[nid(i, j, k)] = [r*math.cos(th), r*math.sin(th), 0.1*k]
    elems = []
    for j in range(nt):
        for i in range(nr):
            elems.append([nid(i, j, 0), nid(i + 1, j, 0), nid(i + 1, j + 1, 0), nid(i, j + 1, 0),
                          nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)])
    d = Deck('implicit Lame cylinder %dx%d nu %g' % (nr, nt, pr))
    d.controls(1.0, 1.0, nsolvr=1)
    d.part(2, ('elastic', 1.0e-9, E, pr))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(nodes.items()):
        fx = 1 if abs(x[0]) < 1e-9 else 0
        fy = 1 if abs(x[1]) < 1e-9 else 0
        d.spc(n, fx, fy, 1)
    segs = []
    for j in range(nt):   # inner face, normal -e_r (out of the solid): p pushes outward
        segs.append(d.f(1, p, 0.0, nid(0, j, 0), nid(0, j, 1), nid(0, j + 1, 1), nid(0, j + 1, 0)))
    d.kw('LOAD_SEGMENT', *segs)
    d.history([nid(0, 0, 0), nid(nr, 0, 0), nid(nr//2, 0, 0), nid(0, nt//2, 0)])
    d.write(path)


def stretch(path):
    """Bar 4 x 1 x 1 (4x1x1 elements), x = 0 face on symmetry rollers, x = 4 face pulled
    to 6 (50 %) in 5 steps; nu = 0 (St. Venant-Kirchhoff: uniaxial, no lateral strain)."""
    nodes, elems, nid = box(4, 1, 1, 4.0, 1.0, 1.0)
    d = Deck('implicit bar stretched 50 %: Newton, quadratic convergence')
    d.controls(1.0, 0.2, nsolvr=12, dctol=1.0e-12, ectol=1.0e-20, rctol=1.0e-12,
               abstol=1.0e-13)
    d.part(2, ('elastic', 1.0e-9, 1000.0, 0.0))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(nodes.items()):
        if abs(x[0]) < 1e-9:
            d.spc(n, 1, 1 if abs(x[1]) < 1e-9 else 0, 1 if abs(x[2]) < 1e-9 else 0)
        elif abs(x[0] - 4.0) < 1e-9:
            d.prescribed(n, 1, 1, 2.0)
    d.history([nid(4, 1, 1), nid(2, 1, 1)])
    d.write(path)


def plastic(path, auto=False, linear=False, kinematic=False):
    """The bar of stretch() in *MAT_024 (E 200000, nu 0.3, SIGY 250, ETAN 2000) pulled to
    2 % in 10 steps: the stress-strain path against the bilinear curve."""
    nodes, elems, nid = box(4, 1, 1, 4.0, 1.0, 1.0)
    if auto:
        d = Deck('implicit *MAT_024 bar, one step of 2 %, MAXREF 6, IAUTO 1: step cuts')
        d.controls(1.0, 1.0, nsolvr=12, dctol=1.0e-10, ectol=1.0e-16, rctol=1.0e-10,
                   abstol=1.0e-9, maxref=6, iauto=1)
    elif linear:
        d = Deck('implicit: NSOLVR 1 (linear) with *MAT_024 is refused')
        d.controls(1.0, 0.1, nsolvr=1)
    else:
        d = Deck('implicit *MAT_024 bar past yield: uniaxial stress against the curve')
        d.controls(1.0, 0.1, nsolvr=12, dctol=1.0e-10, ectol=1.0e-16, rctol=1.0e-10,
                   abstol=1.0e-9)
    d.part(2, ('plastic', 7.85e-9, 200000.0, 0.3, 250.0, 2000.0))
    if kinematic:   # *MAT_003 (BETA 0: kinematic hardening; the same curve in monotonic tension)
        d.lines[d.lines.index('*MAT_PIECEWISE_LINEAR_PLASTICITY')] = '*MAT_PLASTIC_KINEMATIC'
        d.lines[2] = 'implicit *MAT_003 bar past yield: uniaxial stress against the curve'
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    for n, x in sorted(nodes.items()):
        if abs(x[0]) < 1e-9:
            d.spc(n, 1, 1 if abs(x[1]) < 1e-9 else 0, 1 if abs(x[2]) < 1e-9 else 0)
        elif abs(x[0] - 4.0) < 1e-9:
            d.prescribed(n, 1, 1, 0.08)
    d.history([nid(4, 1, 1), nid(2, 1, 1)])
    d.write(path)


def bar_wave(path, alpha=0.0):
    """Bar L = 10 (20x1x1 elements, h = 0.5), E = 1000, rho = 1, nu = 0, fixed at x = 0,
    lateral motion fixed: a chain of lumped masses whose first fixed-free mode is exactly
    sin(pi x/(2L)) sampled at the nodes; started with that velocity shape (v0 = 0.01) and
    stepped by Newmark (ALPHA 0: GAMMA 1/2, BETA 1/4) or HHT (ALPHA < 0), DT0 = 0.03 (about
    T/42), two periods."""
    nodes, elems, nid = box(20, 1, 1, 10.0, 1.0, 1.0)
    d = Deck('implicit dynamics: bar in its first mode, %s' % ('HHT ALPHA %g' % alpha if alpha
                                                                 else 'Newmark trapezoidal'))
    d.controls(2.6, 0.03, nsolvr=1)
    if alpha:
        d.kw('CONTROL_IMPLICIT_DYNAMICS', '$    IMASS     GAMMA      BETA    TDYBIR    TDYDTH    '
             'TDYBUR     IRATE     ALPHA', d.f(1, 0.0, 0.0, 0, 0, 0, 0, float(alpha)))
    else:
        d.kw('CONTROL_IMPLICIT_DYNAMICS', '$    IMASS     GAMMA      BETA',
             d.f(1, 0.5, 0.25))
    d.part(2, ('elastic', 1.0, 1000.0, 0.0))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    vel = []
    for n, x in sorted(nodes.items()):
        d.spc(n, 1 if abs(x[0]) < 1e-9 else 0, 1, 1)
        if x[0] > 1e-9:
            vel.append('%d,%.17g,0.0,0.0' % (n, 0.01*math.sin(math.pi*x[0]/20.0)))  # free format
    d.kw('INITIAL_VELOCITY_NODE', *vel)
    d.history([nid(20, 1, 1)])
    d.write(path)


def singular(path):
    """One cube, a load and no constraint at all: singular stiffness."""
    nodes, elems, nid = box(1, 1, 1, 1.0, 1.0, 1.0)
    d = Deck('implicit: no constraints, singular stiffness')
    d.controls(1.0, 1.0)
    d.part(2, ('elastic', 1.0e-9, 1000.0, 0.3))
    d.mesh(nodes, elems)
    d.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    d.load(nid(1, 1, 1), 3, 1, -1.0)
    d.write(path)


if __name__ == '__main__':
    patch()
    patch(tet=True)
    c = os.path.join(ROOT, 'implicit_cantilever')
    cantilever(1, os.path.join(c, 'mesh1.k'))
    cantilever(2, os.path.join(c, 'mesh2.k'))
    cantilever(4, os.path.join(c, 'deck.k'))
    # P L^2/(E I) = 2 in 10 steps (Bisshopp & Drucker's elastica)
    cantilever(2, os.path.join(ROOT, 'implicit_elastica', 'deck.k'), nsolvr=12, P=2.0*1000.0/12.0/100.0,
               dt0=0.2, tols=dict(dctol=1.0e-8, ectol=1.0e-14, rctol=1.0e-8, abstol=1.0e-12))
    lm = os.path.join(ROOT, 'implicit_lame')
    lame(8, 12, 0.3, os.path.join(lm, 'mesh1.k'))
    lame(16, 24, 0.3, os.path.join(lm, 'deck.k'))
    lame(16, 24, 0.4999, os.path.join(lm, 'nu4999.k'))
    stretch(os.path.join(ROOT, 'implicit_bar_stretch', 'deck.k'))
    plastic(os.path.join(ROOT, 'implicit_plastic_bar', 'deck.k'))
    plastic(os.path.join(ROOT, 'implicit_auto_cut', 'deck.k'), auto=True)
    plastic(os.path.join(ROOT, 'implicit_mat003_bar', 'deck.k'), kinematic=True)
    plastic(os.path.join(ROOT, 'bad_implicit_linear_plastic', 'deck.k'), linear=True)
    singular(os.path.join(ROOT, 'bad_implicit_singular', 'deck.k'))
    bar_wave(os.path.join(ROOT, 'implicit_newmark_bar', 'deck.k'))
    bar_wave(os.path.join(ROOT, 'implicit_hht_bar', 'deck.k'), alpha=-0.1)
