#!/usr/bin/env python3
"""Deck generators for the rigid-body contact scenes (SI units: m, s, kg, Pa).

  gen_scene_decks.py incline [--theta 20] [--mu 0.2] [--n 12] [--tend 0.2] out.k
      a rigid hex sphere (R = 0.05, part 2) and a rigid block (0.06 cube, part 3) resting on a
      flat elastic plate (part 1, bottom fixed) under a tilted gravity vector
      g (sin theta, 0, -cos theta) (*LOAD_BODY_X and *LOAD_BODY_Z): the same as an incline at
      theta. *CONTACT_SURFACE_TO_SURFACE (two-way) with FS = FD = mu between the bodies and
      the plate. Sphere: cube-sphere hex mesh, n elements along each cube edge.
  gen_scene_decks.py box [--n 6] [--sfs 1] [--tssfac 0.9] [--tend 1.0] out.k
      a rigid hex sphere (R = 0.05, part 2) launched at v0 = (3, 2, 1.5) m/s inside a closed
      box of rigid walls (inner 0.3 m cube, wall 0.05 m, part 1, CMO = 1, CON1 = CON2 = 7),
      no gravity, frictionless *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE with SFS = SFM = sfs.
      *MAT_RIGID E = 2e9 (a stiff polymer's modulus): it sets the step of this all-rigid model
      (rigid-element L/c times TSSFAC) and, with SFS, the penalty stiffness.
"""
import argparse
import math


def f10(v):
    if isinstance(v, int):
        return '%10d' % v
    s = '%10.4g' % v
    if len(s) > 10:
        s = '%10.3e' % v
    return s


def card(*vals):
    return ''.join(f10(v) for v in vals) + '\n'


class Mesh:
    def __init__(self):
        self.nodes, self.elems, self.index = [], [], {}

    def node(self, p, pid=0):
        # nodes are shared by coordinates within a part only (parts in contact stay apart)
        key = (pid,) + tuple(round(c, 10) for c in p)
        if key in self.index:
            return self.index[key]
        lab = len(self.nodes) + 1
        self.nodes.append((lab,) + tuple(p))
        self.index[key] = lab
        return lab

    def hexa(self, pid, pts):
        self.elems.append((len(self.elems) + 1, pid, [self.node(p, pid) for p in pts]))

    def block(self, pid, x0, lx, nx, y0, ly, ny, z0, lz, nz, keep=None):
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    if keep and not keep(i, j, k):
                        continue
                    def p(a, b, c):
                        return (x0 + lx * (i + a) / nx, y0 + ly * (j + b) / ny,
                                z0 + lz * (k + c) / nz)
                    self.hexa(pid, [p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0),
                                    p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)])

    def sphere(self, pid, c, r, n, m=None):
        """cube-sphere: inner cube of side r (n^3 hexes), six blocks of n x n x m hexes from
        its faces to the sphere (equi-angular mapping on the surface)."""
        m = m or max(2, n // 3)
        a = 0.5 * r   # half side of the inner cube
        h = 2 * a
        self.block(pid, c[0] - a, h, n, c[1] - a, h, n, c[2] - a, h, n)

        def pt(ax, sgn, u, v, t):
            # u, v in [-1, 1] on the face with normal sgn*e_ax; t in [0, 1] from cube to sphere
            tu, tv = math.tan(0.25 * math.pi * u), math.tan(0.25 * math.pi * v)
            d = [0.0, 0.0, 0.0]
            q = [0.0, 0.0, 0.0]
            o = [k for k in range(3) if k != ax]
            d[ax], d[o[0]], d[o[1]] = sgn, tu, tv
            q[ax], q[o[0]], q[o[1]] = sgn * a, u * a, v * a
            nd = math.sqrt(sum(x * x for x in d))
            s = [r * x / nd for x in d]
            return tuple(c[k] + (1 - t) * q[k] + t * s[k] for k in range(3))

        for ax in range(3):
            for sgn in (-1, 1):
                for j in range(n):
                    for i in range(n):
                        for k in range(m):
                            u0, u1 = -1 + 2 * i / n, -1 + 2 * (i + 1) / n
                            v0, v1 = -1 + 2 * j / n, -1 + 2 * (j + 1) / n
                            t0, t1 = k / m, (k + 1) / m
                            bot = [pt(ax, sgn, u0, v0, t0), pt(ax, sgn, u1, v0, t0),
                                   pt(ax, sgn, u1, v1, t0), pt(ax, sgn, u0, v1, t0)]
                            top = [pt(ax, sgn, u0, v0, t1), pt(ax, sgn, u1, v0, t1),
                                   pt(ax, sgn, u1, v1, t1), pt(ax, sgn, u0, v1, t1)]
                            pts = bot + top
                            if signed_volume(pts) < 0:
                                pts = [bot[0], bot[3], bot[2], bot[1],
                                       top[0], top[3], top[2], top[1]]
                            self.hexa(pid, pts)

    def text(self):
        out = ['*NODE\n']
        for lab, x, y, z in self.nodes:
            out.append('%8d%16.9f%16.9f%16.9f\n' % (lab, x, y, z))
        out.append('*ELEMENT_SOLID\n')
        for lab, pid, conn in self.elems:
            out.append('%8d%8d\n' % (lab, pid) + ''.join('%8d' % q for q in conn) + '\n')
        return ''.join(out)


def signed_volume(p):
    """approximate signed volume of a hex (node order 1-8): (d1 x d2).d3 at the centre"""
    def sub(a, b):
        return [a[k] - b[k] for k in range(3)]
    d1 = sub([sum(p[i][k] for i in (1, 2, 5, 6)) for k in range(3)],
             [sum(p[i][k] for i in (0, 3, 4, 7)) for k in range(3)])
    d2 = sub([sum(p[i][k] for i in (2, 3, 6, 7)) for k in range(3)],
             [sum(p[i][k] for i in (0, 1, 4, 5)) for k in range(3)])
    d3 = sub([sum(p[i][k] for i in (4, 5, 6, 7)) for k in range(3)],
             [sum(p[i][k] for i in (0, 1, 2, 3)) for k in range(3)])
    cx = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
          d1[0] * d2[1] - d1[1] * d2[0]]
    return sum(cx[k] * d3[k] for k in range(3))


def part(pid, title, rigid=None, elastic=None, con=None):
    s = '*PART\n%s\n' % title + card(pid, pid, pid)
    s += '*SECTION_SOLID\n' + card(pid, 1)
    if rigid:
        s += '*MAT_RIGID\n' + card(pid, *rigid)
        if con:
            s += card(1, con[0], con[1])
    else:
        s += '*MAT_ELASTIC\n' + card(pid, *elastic)
    return s


def node_set(sid, ids):
    s = '*SET_NODE_LIST\n' + card(sid)
    for i in range(0, len(ids), 8):
        s += ''.join(f10(v) for v in ids[i:i + 8]) + '\n'
    return s


def incline(a):
    g, th = 9.81, math.radians(a.theta)
    R, rho_s = 0.05, 1000.0
    msh = Mesh()
    # plate 0.4 x 0.3 x 0.02 (20 x 15 x 1 hexes), top face z = 0
    msh.block(1, 0.0, 0.4, 20, 0.0, 0.3, 15, -0.02, 0.02, 1)
    nplate = len(msh.nodes)
    bottom = [lab for (lab, x, y, z) in msh.nodes if abs(z + 0.02) < 1e-9]
    msh.sphere(2, (0.1, 0.08, R + a.gap), R, a.n)
    # block 0.06 cube, 3 x 3 x 3 hexes, offset from the plate's node lines
    msh.block(3, 0.071, 0.06, 3, 0.191, 0.06, 3, a.gap, 0.06, 3)
    h = ('*KEYWORD\n*TITLE\nrigid sphere and rigid block on a plate inclined at %g deg, '
         'mu = %g\n' % (a.theta, a.mu))
    h += ('$ generated by scripts/gen_scene_decks.py incline --theta %g --mu %g --n %d; '
          'tilted gravity g = %g\n' % (a.theta, a.mu, a.n, g))
    h += '*CONTROL_TERMINATION\n' + card(a.tend)
    h += '*CONTROL_TIMESTEP\n' + card(0.0, a.tssfac)
    h += '*DATABASE_GLSTAT\n' + card(a.tend / 100)
    h += '*DATABASE_RBDOUT\n' + card(a.tend / 200)
    h += '*DATABASE_RCFORC\n' + card(a.tend / 200)
    h += part(1, 'plate (elastic, bottom fixed)', elastic=(1000.0, 1.0e8, 0.3))
    h += part(2, 'sphere (rigid)', rigid=(rho_s, 1.0e8, 0.3))
    h += part(3, 'block (rigid)', rigid=(rho_s, 1.0e8, 0.3))
    h += node_set(1, bottom)
    h += '*BOUNDARY_SPC_SET\n' + card(1, 0, 1, 1, 1, 1, 1, 1)
    h += '*DEFINE_CURVE\n' + card(1) + '%20.8g%20.8g\n%20.8g%20.8g\n' % (0.0, 1.0, 1e3, 1.0)
    # LS-DYNA sign: the body force is -m a, a = SF * curve
    h += '*LOAD_BODY_X\n' + card(1, -g * math.sin(th))
    h += '*LOAD_BODY_Z\n' + card(1, g * math.cos(th))
    h += '*SET_PART_LIST\n' + card(10) + card(2, 3)
    h += '*CONTACT_SURFACE_TO_SURFACE_ID\n' + card(1) .rstrip('\n') + 'bodies on plate\n'
    h += '$     SSID      MSID     SSTYP     MSTYP\n' + card(10, 1, 2, 3)
    h += '$       FS        FD        DC        VC       VDC\n' + card(a.mu, a.mu, 0.0, 0.0,
                                                                       a.vdc)
    h += '$      SFS       SFM\n' + card(a.sfs, a.sfs)
    with open(a.out, 'w') as f:
        f.write(h + msh.text() + '*END\n')
    print('incline: %d nodes (%d plate), %d elements' % (len(msh.nodes), nplate, len(msh.elems)))


def box(a):
    R = 0.05
    msh = Mesh()
    # walls: the cells of an 8^3 grid of 0.05 m over [-0.2, 0.2]^3 on its boundary
    msh.block(1, -0.2, 0.4, 8, -0.2, 0.4, 8, -0.2, 0.4, 8,
              keep=lambda i, j, k: min(i, j, k) == 0 or max(i, j, k) == 7)
    msh.sphere(2, (0.0, 0.0, 0.0), R, a.n)
    h = ('*KEYWORD\n*TITLE\nrigid ball in a rigid box, SFS = %g, TSSFAC = %g\n' % (a.sfs, a.tssfac))
    h += ('$ generated by scripts/gen_scene_decks.py box --n %d --sfs %g --tssfac %g '
          '--tend %g\n' % (a.n, a.sfs, a.tssfac, a.tend))
    h += '*CONTROL_TERMINATION\n' + card(a.tend)
    h += '*CONTROL_TIMESTEP\n' + card(0.0, a.tssfac)
    h += '*DATABASE_GLSTAT\n' + card(a.tend / a.nout)
    h += '*DATABASE_RBDOUT\n' + card(a.tend / a.nout)
    h += '*DATABASE_RCFORC\n' + card(a.tend / a.nout)
    h += part(1, 'box walls (rigid, fixed)', rigid=(7800.0, a.E, 0.3), con=(7, 7))
    h += part(2, 'ball (rigid)', rigid=(7800.0, a.E, 0.3))
    h += '*INITIAL_VELOCITY_GENERATION\n' + card(2, 2, 0.0, 3.0, 2.0, 1.5) + \
        card(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    h += '*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_ID\n' + card(1).rstrip('\n') + 'ball in box\n'
    h += '$     SSID      MSID     SSTYP     MSTYP\n' + card(2, 1, 3, 3)
    h += '$       FS        FD\n' + card(0.0, 0.0)
    h += '$      SFS       SFM\n' + card(a.sfs, a.sfs)
    with open(a.out, 'w') as f:
        f.write(h + msh.text() + '*END\n')
    print('box: %d nodes, %d elements' % (len(msh.nodes), len(msh.elems)))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('incline')
    p.add_argument('--theta', type=float, default=20.0)
    p.add_argument('--mu', type=float, default=0.2)
    p.add_argument('--n', type=int, default=12)
    p.add_argument('--gap', type=float, default=0.0)
    p.add_argument('--vdc', type=float, default=20.0)
    p.add_argument('--sfs', type=float, default=1.0)
    p.add_argument('--tssfac', type=float, default=0.9)
    p.add_argument('--tend', type=float, default=0.2)
    p.add_argument('out')
    p = sub.add_parser('box')
    p.add_argument('--n', type=int, default=6)
    p.add_argument('--sfs', type=float, default=1.0)
    p.add_argument('--tssfac', type=float, default=0.9)
    p.add_argument('--tend', type=float, default=1.0)
    p.add_argument('--nout', type=int, default=200)
    p.add_argument('--E', type=float, default=2.0e9,
                   help='E of *MAT_RIGID: sets the step (all-rigid model) and the penalty')
    p.add_argument('out')
    a = ap.parse_args()
    {'incline': incline, 'box': box}[a.cmd](a)


if __name__ == '__main__':
    main()
