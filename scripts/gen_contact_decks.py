#!/usr/bin/env python3
"""Deck generators for the contact scenes (units mm, ms, kg, GPa; steel unless stated).

  gen_contact_decks.py rod    [--nx 100] [--v 10] [--kw SURFACE_TO_SURFACE] [--sfs 1] out.k
      two equal elastic bars (L = 100 mm, 1 x 1 mm, nu = 0 so the bar is 1D), the striker
      (part 1) at v, the target (part 2) at rest, gap 0.01 mm; *CONTACT_<kw>.
  gen_contact_decks.py hertz  [--n 8] [--depth 0.05] out.k
      quarter model of an elastic sphere (R = 10 mm) pressed on an elastic block by a
      prescribed displacement of its top (quasi-static ramp), symmetry planes x = 0, y = 0.
  gen_contact_decks.py slide  [--n 6] [--fs 0] out.k
      a block pushed across a meshed plate (segment edges and corners crossed).
  gen_contact_decks.py cubes  [--ncube 8] [--m 3] out.k
      N elastic cubes (m^3 hexes each) with random velocities in a box of stonewalls,
      *CONTACT_AUTOMATIC_SINGLE_SURFACE (benchmark)."""
import argparse, math, random

STEEL = (7.85e-6, 210.0)


class Deck:
    def __init__(self):
        self.nodes, self.elems, self.lines = [], [], []
        self.nn = 0
        self.ne = 0

    def node(self, x, y, z):
        self.nn += 1
        self.nodes.append((self.nn, x, y, z))
        return self.nn

    def hex(self, pid, c):
        self.ne += 1
        self.elems.append((self.ne, pid, c))
        return self.ne

    def block(self, pid, x0, y0, z0, lx, ly, lz, nx, ny, nz, warp=None):
        """structured hex block; returns node-id array ids[i][j][k]"""
        ids = [[[0] * (nz + 1) for _ in range(ny + 1)] for _ in range(nx + 1)]
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    p = (x0 + lx * i / nx, y0 + ly * j / ny, z0 + lz * k / nz)
                    if warp:
                        p = warp(*p)
                    ids[i][j][k] = self.node(*p)
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    self.hex(pid, [ids[i][j][k], ids[i + 1][j][k], ids[i + 1][j + 1][k],
                                   ids[i][j + 1][k], ids[i][j][k + 1], ids[i + 1][j][k + 1],
                                   ids[i + 1][j + 1][k + 1], ids[i][j + 1][k + 1]])
        return ids

    def w(self, s):
        self.lines.append(s)

    def node_set(self, sid, ids):
        self.w('*SET_NODE_LIST\n%10d\n' % sid)
        ids = list(ids)
        for i in range(0, len(ids), 8):
            self.w(''.join('%10d' % n for n in ids[i:i + 8]) + '\n')

    def write(self, path, head):
        with open(path, 'w') as f:
            f.write('*KEYWORD\n' + head)
            f.write(''.join(self.lines))
            f.write('*NODE\n')
            for n, x, y, z in self.nodes:
                f.write('%8d%16.9g%16.9g%16.9g\n' % (n, x, y, z))
            f.write('*ELEMENT_SOLID\n')
            for e, p, c in self.elems:
                f.write('%8d%8d\n' % (e, p) + ''.join('%8d' % n for n in c) + '\n')
            f.write('*END\n')


def mat_part(d, pid, rho, e, nu, title, elform=1):
    d.w('*PART\n%s\n%10d%10d%10d\n' % (title, pid, pid, pid))
    d.w('*SECTION_SOLID\n%10d%10d\n' % (pid, elform))
    d.w('*MAT_ELASTIC\n%10d%10.4g%10.4g%10.4g\n' % (pid, rho, e, nu))


def rod(a):
    d = Deck()
    L, W, gap = 100.0, 1.0, 0.01
    rho, E = STEEL
    c = math.sqrt(E / rho)
    tend = 2.0 * L / c * 1.6
    d.w('*CONTROL_TERMINATION\n%10.6g\n' % tend)
    d.w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    d.w('*DATABASE_GLSTAT\n%10.4g\n' % (tend / 400))
    d.w('*DATABASE_RCFORC\n%10.4g\n' % (tend / 2000))
    d.w('*DATABASE_NODOUT\n%10.4g\n' % (tend / 20))
    d.w('*DATABASE_BINARY_D3PLOT\n%10.4g\n' % (tend / 4))
    mat_part(d, 1, rho, E, 0.0, 'striker')
    mat_part(d, 2, rho, E, 0.0, 'target')
    s = d.block(1, 0.0, 0.0, 0.0, L, W, W, a.nx, 1, 1)
    t = d.block(2, L + gap, 0.0, 0.0, L, W, W, a.nx, 1, 1)
    d.node_set(1, range(1, 4 * (a.nx + 1) + 1))
    d.node_set(3, range(1, 8 * (a.nx + 1) + 1))
    d.w('*INITIAL_VELOCITY\n         1\n%10.4g       0.0       0.0\n' % a.v)
    d.w('*DATABASE_HISTORY_NODE_SET\n         3\n')
    if a.sets:
        # slave: the striker's end nodes (node set 10); master: the target's end face as a
        # segment set (20), written with the inward node order on purpose (dynx orients it)
        nx = a.nx
        d.node_set(10, [s[nx][j][k] for j in range(2) for k in range(2)])
        d.w('*SET_SEGMENT\n        20\n%10d%10d%10d%10d\n' % (t[0][0][0], t[0][0][1], t[0][1][1],
                                                            t[0][1][0]))
    if a.box:
        d.w('*DEFINE_BOX\n         5      98.0     102.0      -1.0       2.0      -1.0       2.0\n')
        d.w('*DEFINE_BOX_TITLE\nmaster end\n         6      99.0     101.0      -1.0       2.0      -1.0       2.0\n')
    cid = '_ID' if a.id else ''
    d.w('*CONTACT_%s%s\n' % (a.kw, cid))
    if a.id:
        d.w('        12rod ends\n')
    if a.box:
        d.w('$     SSID      MSID     SSTYP     MSTYP    SBOXID    MBOXID\n'
            '         1         2         3         3         5         6\n')
    elif a.sets:
        d.w('$     SSID      MSID     SSTYP     MSTYP\n        10        20         4         0\n')
    elif 'SINGLE' in a.kw:
        d.w('$     SSID      MSID     SSTYP     MSTYP\n         0         0         5\n')
    else:
        d.w('$     SSID      MSID     SSTYP     MSTYP\n         1         2         3         3\n')
    d.w('$       FS        FD        DC        VC       VDC    PENCHK        BT        DT\n'
        '       0.0       0.0       0.0       0.0%10s         0       0.0%10.4g\n'
        % ('0.0' if a.vdc == 0 else '%.4g' % a.vdc, a.death))
    d.w('$      SFS       SFM\n%10.4g%10.4g\n' % (a.sfs, a.sfs))
    if a.soft:
        d.w('$     SOFT    SOFSCL\n         1%10.4g\n' % a.sofscl)
    d.write(a.out, '*TITLE\nTwo equal elastic rods, striker at %g m/s, nx=%d, *CONTACT_%s\n'
            '$ generated by scripts/gen_contact_decks.py rod; c = %.2f m/s, 2L/c = %.6g ms\n'
            % (a.v, a.nx, a.kw, c, 2 * L / c))


def cubes(a):
    d = Deck()
    rho, E = STEEL
    side, pitch = 10.0, 14.0
    k = 1
    while k ** 3 < a.ncube:
        k += 1
    box = k * pitch + 4.0
    rng = random.Random(a.seed)
    d.w('*CONTROL_TERMINATION\n%10.4g%10d\n' % (0.0, a.ncyc))
    d.w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
    d.w('*DATABASE_GLSTAT\n%10.4g\n' % 0.02)
    mat_part(d, 1, rho, E, 0.3, 'cubes')
    cubes_nodes = []
    for c in range(a.ncube):
        i, j, l = c % k, (c // k) % k, c // (k * k)
        x0 = 4.0 + i * pitch
        n0 = d.nn
        d.block(1, x0, 4.0 + j * pitch, 4.0 + l * pitch, side, side, side, a.m, a.m, a.m)
        cubes_nodes.append(range(n0 + 1, d.nn + 1))
    for c, ids in enumerate(cubes_nodes):
        d.node_set(100 + c, ids)
    d.w('*INITIAL_VELOCITY\n')
    for c in range(a.ncube):
        v = [rng.uniform(-a.v, a.v) for _ in range(3)]
        d.w('%10d\n%10.4g%10.4g%10.4g\n' % (100 + c, v[0], v[1], v[2]))
    walls = [((0, 0, 0), (1, 0, 0)), ((box, 0, 0), (-1, 0, 0)), ((0, 0, 0), (0, 1, 0)),
             ((0, box, 0), (0, -1, 0)), ((0, 0, 0), (0, 0, 1)), ((0, 0, box), (0, 0, -1))]
    for (p0, n) in walls:
        d.w('*RIGIDWALL_PLANAR\n         0\n%10.4g%10.4g%10.4g%10.4g%10.4g%10.4g\n'
            % (p0[0], p0[1], p0[2], p0[0] + n[0], p0[1] + n[1], p0[2] + n[2]))
    if not a.nocontact:
        d.w('*CONTACT_AUTOMATIC_SINGLE_SURFACE\n$     SSID      MSID     SSTYP\n         0         0         5\n')
    d.write(a.out, '*TITLE\n%d elastic cubes (%d^3 hexes) in a stonewall box, %s\n'
            '$ generated by scripts/gen_contact_decks.py cubes\n'
            % (a.ncube, a.m, 'no contact' if a.nocontact else 'automatic single surface'))


def graded(n1, a1, w, ratio=1.3):
    """node coordinates 0 .. w: n1 uniform elements over [0, a1], then growing by ratio"""
    h = a1 / n1
    xs = [h * i for i in range(n1 + 1)]
    while xs[-1] < w - 1e-12:
        h *= ratio
        xs.append(min(w, xs[-1] + h))
        if w - xs[-1] < 0.5 * h * ratio:
            xs[-1] = w
    return xs


def hertz(a):
    """quarter model: block z in [-H, 0] (part 1), sphere-ended punch (part 2) above it"""
    d = Deck()
    rho, E = STEEL
    nu, R, W, H = 0.3, a.R, a.W, a.W
    xs = graded(a.n, a.zone, W)
    zs = graded(a.n, a.zone, H)
    c = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
    T = a.T if a.T > 0 else 40.0 * W / c
    tend = 1.25 * T
    v0 = 2.0 * a.depth / T
    if a.implicit:    # implicit statics: the approach in a.implicit load steps of 1/a.implicit
        d.w('*CONTROL_TERMINATION\n       1.0\n')
        d.w('*CONTROL_IMPLICIT_GENERAL\n$   IMFLAG       DT0\n         1%10.6g\n'
            % (1.0 / a.implicit))
        d.w('*CONTROL_IMPLICIT_SOLUTION\n$   NSOLVR    ILIMIT    MAXREF     DCTOL     ECTOL'
            '     RCTOL     LSTOL    ABSTOL\n        12         0        40    1.0e-6    1.0e-8'
            '    1.0e-8         0    1.0e-9\n')
        d.w('*DATABASE_SPCFORC\n%10.6g\n' % (1.0 / a.implicit))
        d.w('*DATABASE_BINARY_D3PLOT\n       1.0\n')
    else:
        d.w('*CONTROL_TERMINATION\n%10.4g\n' % tend)
        d.w('*CONTROL_TIMESTEP\n       0.0       0.9\n')
        d.w('*DATABASE_GLSTAT\n%10.4g\n' % (tend / 100))
        d.w('*DATABASE_RCFORC\n%10.4g\n' % (tend / 200))
        d.w('*DATABASE_BINARY_D3PLOT\n%10.4g\n' % (tend / 5))
    mat_part(d, 1, rho, E, nu, 'block (half-space)', elform=2)
    mat_part(d, 2, rho, E, nu, 'sphere (punch with a spherical end)', elform=2)
    nx = len(xs) - 1
    nz = len(zs) - 1
    ids = {}
    for body in (1, 2):
        for k in range(nz + 1):
            for j in range(nx + 1):
                for i in range(nx + 1):
                    x, y = xs[i], xs[j]
                    if body == 1:
                        z = -zs[nz - k]
                    else:
                        r2 = x * x + y * y
                        z = R - math.sqrt(R * R - r2) + a.gap + zs[k]
                    ids[body, i, j, k] = d.node(x, y, z)
        for k in range(nz):
            for j in range(nx):
                for i in range(nx):
                    g = lambda ii, jj, kk: ids[body, ii, jj, kk]
                    d.hex(body, [g(i, j, k), g(i + 1, j, k), g(i + 1, j + 1, k), g(i, j + 1, k),
                                 g(i, j, k + 1), g(i + 1, j, k + 1), g(i + 1, j + 1, k + 1),
                                 g(i, j + 1, k + 1)])
    rng = range(nx + 1)
    xsym = [ids[b, 0, j, k] for b in (1, 2) for j in rng for k in range(nz + 1)]
    ysym = [ids[b, i, 0, k] for b in (1, 2) for i in rng for k in range(nz + 1)]
    bottom = [ids[1, i, j, 0] for i in rng for j in rng]
    top = [ids[2, i, j, nz] for i in rng for j in rng]
    d.node_set(1, xsym); d.node_set(2, ysym); d.node_set(3, bottom); d.node_set(4, top)
    d.w('*BOUNDARY_SPC_SET\n         1         0         1         0         0\n')
    d.w('*BOUNDARY_SPC_SET\n         2         0         0         1         0\n')
    d.w('*BOUNDARY_SPC_SET\n         3         0         1         1         1\n')
    d.w('*DEFINE_CURVE\n         1\n')
    if a.implicit:    # the punch top's displacement (VAD = 2), linear in the load steps
        d.w('%20.8g%20.8g\n%20.8g%20.8g\n' % (0.0, 0.0, 1.0, -(a.depth + a.gap)))
        d.w('*BOUNDARY_PRESCRIBED_MOTION_SET\n         4         3         2         1       1.0\n')
    else:
        npt = 40
        for q in range(npt + 1):
            t = T * q / npt
            d.w('%20.8g%20.8g\n' % (t, -v0 * 0.5 * (1 - math.cos(2 * math.pi * t / T))))
        d.w('%20.8g%20.8g\n' % (10 * tend, 0.0))
        d.w('*BOUNDARY_PRESCRIBED_MOTION_SET\n         4         3         0         1       1.0\n')
    d.w('*CONTACT_%s_ID\n         1hertz\n' % a.kw)
    d.w('$     SSID      MSID     SSTYP     MSTYP\n         2         1         3         3\n')
    d.w('$       FS        FD\n       0.0       0.0\n')
    d.w('$      SFS       SFM\n%10.4g%10.4g\n' % (a.sfs, a.sfs))
    if a.bsort:
        d.w('$     SOFT    SOFSCL    LCIDAB    MAXPAR     SBOPT     DEPTH     BSORT\n'
            '         0       0.1         0         0         0         0%10d\n' % a.bsort)
    d.write(a.out, '*TITLE\nHertz contact, quarter model, R = %g mm, depth %g mm, %d elements\n'
            '$ generated by scripts/gen_contact_decks.py hertz --n %d --zone %g --W %g '
            '--depth %g --sfs %g; c = %.1f, T = %.5g ms\n'
            % (R, a.depth, d.ne, a.n, a.zone, W, a.depth, a.sfs, c, T))
    print('hertz: %d elements, %d nodes, smallest element %.4g mm' % (d.ne, d.nn, xs[1]))


def slide(a):
    """a 2 x 2 x 2 mm block (part 2) pressed on a 12 x 4 x 1 mm plate (part 1, bottom fixed) by
    a constant load F on its top nodes and launched at v0 along x: with Coulomb friction mu
    it decelerates at mu F/m; frictionless it keeps v0 while its nodes cross the plate's
    segment edges (the plate mesh is finer and not aligned with the block's)."""
    d = Deck()
    rho, E = STEEL
    tend = a.tend
    d.w('*CONTROL_TERMINATION\n%10.4g\n' % tend)
    d.w('*CONTROL_TIMESTEP\n       0.0%10.4g\n' % a.tssfac)
    d.w('*DATABASE_GLSTAT\n%10.4g\n' % (tend / 100))
    d.w('*DATABASE_RCFORC\n%10.4g\n' % (tend / 400))
    d.w('*DATABASE_NODOUT\n%10.4g\n' % (tend / 100))
    mat_part(d, 1, rho, E, 0.3, 'plate')
    mat_part(d, 2, rho, E, 0.3, 'block')
    k = a.refine                       # 1: the scene deck (block 2 x 2 x 2, plate 15 x 5 x 1)
    pl = d.block(1, 0.0, 0.0, 0.0, 12.0, 4.0, 1.0, 15 * k, 5 * k, k)
    nb = 2 * k
    bl = d.block(2, 1.0, 1.0, 1.0 + a.gap, 2.0, 2.0, 2.0, nb, nb, nb)
    d.node_set(1, [pl[i][j][0] for i in range(15 * k + 1) for j in range(5 * k + 1)])
    d.node_set(2, [bl[i][j][m] for i in range(nb + 1) for j in range(nb + 1)
                   for m in range(nb + 1)])
    d.w('*BOUNDARY_SPC_SET\n         1         0         1         1         1\n')
    d.w('*INITIAL_VELOCITY\n         2\n%10.4g       0.0       0.0\n' % a.v)
    # the curve carries the load (-F) when refined, so that the nodal scale factors (the
    # weights) keep their digits in a 10-character field; k = 1 writes the scene deck as it was
    cv = 1.0 if k == 1 else -a.F
    d.w('*DEFINE_CURVE\n         1\n%20.8g%20.8g\n%20.8g%20.8g\n' % (0.0, cv, 100 * tend, cv))
    # top nodes: consistent nodal loads of a uniform pressure on the nb x nb top face (for
    # nb = 2: corner 1/16, edge 1/8, centre 1/4 of the load)
    wts = [(0.5 if i in (0, nb) else 1.0) / nb for i in range(nb + 1)]
    for i in range(nb + 1):
        for j in range(nb + 1):
            d.w('*LOAD_NODE_POINT\n%10d         3         1%10s\n'
                % (bl[i][j][nb], '%.6g' % (-a.F * wts[i] * wts[j]) if k == 1 else
                   ('%.8f' % (wts[i] * wts[j]))[:10]))
    d.w('*DATABASE_HISTORY_NODE\n%10d\n' % bl[k][k][k])
    d.w('*CONTACT_SURFACE_TO_SURFACE_ID\n         7sliding block\n')
    d.w('$     SSID      MSID     SSTYP     MSTYP\n         2         1         3         3\n')
    d.w('$       FS        FD        DC        VC       VDC\n%10.4g%10.4g       0.0       0.0%10.4g\n'
        % (a.fs, a.fs, a.vdc))
    d.write(a.out, '*TITLE\nBlock sliding on a plate, FS = FD = %g, F = %g kN, v0 = %g m/s\n'
            '$ generated by scripts/gen_contact_decks.py slide; block mass %.6g kg\n'
            % (a.fs, a.F, a.v, 8.0 * rho))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('rod')
    p.add_argument('--nx', type=int, default=100)
    p.add_argument('--v', type=float, default=10.0)
    p.add_argument('--kw', default='SURFACE_TO_SURFACE')
    p.add_argument('--sfs', type=float, default=1.0)
    p.add_argument('--id', action='store_true')
    p.add_argument('--sets', action='store_true', help='node set slave, segment set master')
    p.add_argument('--box', action='store_true', help='SBOXID/MBOXID around the rod ends')
    p.add_argument('--soft', action='store_true', help='SOFT = 1 (optional card A)')
    p.add_argument('--sofscl', type=float, default=0.1)
    p.add_argument('--death', type=float, default=0.0, help='DT (death time), 0: none')
    p.add_argument('--vdc', type=float, default=0.0, help='VDC (% of critical damping)')
    p.add_argument('out')
    p = sub.add_parser('cubes')
    p.add_argument('--ncube', type=int, default=8)
    p.add_argument('--m', type=int, default=3)
    p.add_argument('--v', type=float, default=20.0)
    p.add_argument('--ncyc', type=int, default=400)
    p.add_argument('--seed', type=int, default=1)
    p.add_argument('--nocontact', action='store_true')
    p.add_argument('out')
    p = sub.add_parser('hertz')
    p.add_argument('--n', type=int, default=12, help='elements over the fine zone')
    p.add_argument('--zone', type=float, default=1.0, help='size of the uniform fine zone')
    p.add_argument('--W', type=float, default=2.5, help='size of each body (quarter)')
    p.add_argument('--R', type=float, default=10.0)
    p.add_argument('--depth', type=float, default=0.05, help='prescribed approach')
    p.add_argument('--gap', type=float, default=0.0)
    p.add_argument('--T', type=float, default=0.0, help='loading time (0: 40 W/c)')
    p.add_argument('--sfs', type=float, default=20.0)
    p.add_argument('--kw', default='AUTOMATIC_SURFACE_TO_SURFACE')
    p.add_argument('--bsort', type=int, default=0)
    p.add_argument('--implicit', type=int, default=0,
                   help='implicit statics in this many load steps (0: explicit)')
    p.add_argument('out')
    p = sub.add_parser('slide')
    p.add_argument('--fs', type=float, default=0.2)
    p.add_argument('--F', type=float, default=0.02, help='normal load [kN]')
    p.add_argument('--v', type=float, default=20.0)
    p.add_argument('--gap', type=float, default=0.0)
    p.add_argument('--vdc', type=float, default=20.0)
    p.add_argument('--tend', type=float, default=0.2)
    p.add_argument('--refine', type=int, default=1, help='mesh refinement factor (studies)')
    p.add_argument('--tssfac', type=float, default=0.9)
    p.add_argument('out')
    a = ap.parse_args()
    {'rod': rod, 'cubes': cubes, 'hertz': hertz, 'slide': slide}[a.cmd](a)


if __name__ == '__main__':
    main()
