#!/usr/bin/env python3
"""Decks for the energy-momentum conserving rigid-body contact scenes (docs/conserving-contact.md).

  gen_emc_decks.py ballbox   [--dt DT] [--steps N] [--eps EPS] [--outdt T] [--explicit] > deck.k
  gen_emc_decks.py ballshell [--dt DT] [--steps N] [--eps EPS] [--faceted] > deck.k

ballbox: a rigid ball (radius 0.3 m, cube-sphere mesh, smoothed as an exact sphere) inside a
rigid hollow box (cavity [-1, 1]^3, walls 0.5 m thick), both free, the ball at (3, 2, 1) m/s
and spinning, the box drifting and turning slowly. --explicit writes the same geometry for the
explicit solver with *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (faceted ball).
ballshell: the seed's ball in a spherical shell: solid ball (0.274 kg/m^3, radius 0.5 m) inside
a shell (0.743 kg/m^3, radii 1.0 / 1.1 m), ball touching the bottom and given 1 m/s in y, so
that it runs round the inside of the shell in the y-z plane. --faceted: no spherical smoothing
(ball nodes against shell facets).
Standard library only.
"""
import argparse
import math


def cube_ball(n, r, c, nid0, eid0, pid):
    """Cube-sphere ball: an n^3 grid of [-1,1]^3 mapped by p |p|_inf/|p|_2 (surface exact)."""
    nodes, ids = [], {}
    h = n // 2
    nid = nid0
    for k in range(-h, h + 1):
        for j in range(-h, h + 1):
            for i in range(-h, h + 1):
                p = [i / h, j / h, k / h]
                ninf = max(abs(q) for q in p)
                n2 = math.sqrt(sum(q * q for q in p))
                s = 0.0 if n2 == 0.0 else ninf / n2
                x = [c[m] + r * s * p[m] for m in range(3)]
                nid += 1
                ids[(i, j, k)] = nid
                nodes.append((nid, x))
    elems = []
    eid = eid0
    for k in range(-h, h):
        for j in range(-h, h):
            for i in range(-h, h):
                conn = [ids[(i, j, k)], ids[(i + 1, j, k)], ids[(i + 1, j + 1, k)],
                        ids[(i, j + 1, k)], ids[(i, j, k + 1)], ids[(i + 1, j, k + 1)],
                        ids[(i + 1, j + 1, k + 1)], ids[(i, j + 1, k + 1)]]
                eid += 1
                elems.append((eid, pid, conn))
    return nodes, elems


def hollow_box(a, t, ncell, nid0, eid0, pid):
    """Box with cavity [-a, a]^3 and walls t thick: a grid of cells, the cavity cells removed."""
    # coordinates: walls in one cell, cavity in ncell cells
    xs = [-a - t] + [-a + 2 * a * q / ncell for q in range(ncell + 1)] + [a + t]
    m = len(xs)
    ids, nodes, nid = {}, [], nid0
    used = set()
    cells = []
    for k in range(m - 1):
        for j in range(m - 1):
            for i in range(m - 1):
                inner = all(1 <= q <= m - 3 for q in (i, j, k))
                if inner:
                    continue
                cells.append((i, j, k))
                for dk in (0, 1):
                    for dj in (0, 1):
                        for di in (0, 1):
                            used.add((i + di, j + dj, k + dk))
    for key in sorted(used, key=lambda q: (q[2], q[1], q[0])):
        nid += 1
        ids[key] = nid
        nodes.append((nid, [xs[key[0]], xs[key[1]], xs[key[2]]]))
    elems, eid = [], eid0
    for (i, j, k) in cells:
        conn = [ids[(i, j, k)], ids[(i + 1, j, k)], ids[(i + 1, j + 1, k)], ids[(i, j + 1, k)],
                ids[(i, j, k + 1)], ids[(i + 1, j, k + 1)], ids[(i + 1, j + 1, k + 1)],
                ids[(i, j + 1, k + 1)]]
        eid += 1
        elems.append((eid, pid, conn))
    return nodes, elems


def sphere_shell(m, r1, r2, nid0, eid0, pid):
    """Spherical shell between radii r1 < r2: the m x m grid of each cube face projected."""
    h = m // 2
    pts = {}
    for i in range(-h, h + 1):
        for j in range(-h, h + 1):
            for k in range(-h, h + 1):
                if max(abs(i), abs(j), abs(k)) == h:
                    pts[(i, j, k)] = None
    ids, nodes, nid = {}, [], nid0
    for layer, r in enumerate((r1, r2)):
        for key in sorted(pts):
            p = [q / h for q in key]
            n2 = math.sqrt(sum(q * q for q in p))
            nid += 1
            ids[(key, layer)] = nid
            nodes.append((nid, [r * q / n2 for q in p]))
    quads = []
    for ax in range(3):
        for sgn in (-h, h):
            for a in range(-h, h):
                for b in range(-h, h):
                    def key(u, v):
                        kk = [0, 0, 0]
                        kk[ax] = sgn
                        kk[(ax + 1) % 3] = u
                        kk[(ax + 2) % 3] = v
                        return tuple(kk)
                    quads.append([key(a, b), key(a + 1, b), key(a + 1, b + 1), key(a, b + 1)])
    coords = {nid: x for nid, x in nodes}
    elems, eid = [], eid0
    for q in quads:
        conn = [ids[(kk, 0)] for kk in q] + [ids[(kk, 1)] for kk in q]
        if hex_volume_sign(conn, coords) < 0:
            q = q[::-1]
            conn = [ids[(kk, 0)] for kk in q] + [ids[(kk, 1)] for kk in q]
        eid += 1
        elems.append((eid, pid, conn))
    return nodes, elems


def hex_volume_sign(conn, coords):
    x = [coords[n] for n in conn]
    def sub(a, b):
        return [a[i] - b[i] for i in range(3)]
    d1 = sub(x[1], x[0]); d2 = sub(x[3], x[0]); d3 = sub(x[4], x[0])
    return (d1[0] * (d2[1] * d3[2] - d2[2] * d3[1]) - d1[1] * (d2[0] * d3[2] - d2[2] * d3[0])
            + d1[2] * (d2[0] * d3[1] - d2[1] * d3[0]))


def fmt(v):
    return '%10.4g' % v if abs(v) >= 1e-3 or v == 0 else '%10.3e' % v


def write_mesh(out, nodes, elems):
    out.append('*NODE')
    for nid, x in nodes:
        out.append('%8d%16.10f%16.10f%16.10f' % (nid, x[0], x[1], x[2]))
    out.append('*ELEMENT_SOLID')
    for eid, pid, conn in elems:
        out.append('%8d%8d' % (eid, pid))
        out.append(''.join('%8d' % c for c in conn))


def part(out, pid, title, ro):
    out += ['*PART', title, '%10d%10d%10d' % (pid, 1, pid),
            '*MAT_RIGID', '%10d%10s%10s%10s' % (pid, fmt(ro), '1e9', '0.3')]


def ivel(out, pid, omega, v, xc, axis):
    out += ['*INITIAL_VELOCITY_GENERATION',
            '%10d%10d%10s%10s%10s%10s' % (pid, 2, fmt(omega), fmt(v[0]), fmt(v[1]), fmt(v[2])),
            '%10s%10s%10s%10s%10s%10s' % tuple(fmt(q) for q in list(xc) + list(axis))]


def ballbox(a):
    out = ['*KEYWORD', '*TITLE', 'rigid ball bouncing inside a free rigid box (conserving contact)'
           if not a.explicit else 'rigid ball inside a rigid box, explicit penalty contact',
           '$ generated by scripts/gen_emc_decks.py ballbox']
    tend = a.dt * a.steps
    out += ['*CONTROL_TERMINATION', fmt(tend)]
    if a.explicit:
        out += ['*CONTROL_TIMESTEP', '%10s%10s' % ('0', fmt(a.tssfac))]
        out += ['*DATABASE_GLSTAT', fmt(a.outdt), '*DATABASE_RBDOUT', fmt(a.outdt)]
    else:
        out += ['*CONTROL_IMPLICIT_GENERAL', '%10d%10s' % (1, fmt(a.dt))]
        out += ['*DYNX_CONSERVING_CONTROL', '%10d%10s%10d%10s' % (20, '0', 0, fmt(a.outdt))]
    out += ['*DATABASE_BINARY_D3PLOT', fmt(tend / 20.0)]
    out += ['*SECTION_SOLID', '%10d%10d' % (1, 1)]
    part(out, 1, 'ball', 1000.0)
    part(out, 2, 'box', 200.0)
    ivel(out, 1, a.spin, tuple(a.ball_v), tuple(a.ball_x), (0.0, 0.6, 0.8))
    if not a.box_still:
        ivel(out, 2, 0.2, (-0.1, 0.05, 0.0), (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    if a.explicit:
        out += ['*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE', '%10d%10d%10d%10d' % (1, 2, 3, 3),
                '%10s' % '0', '%10s%10s' % (fmt(a.sfs), fmt(a.sfs))]
    else:
        out += ['*DYNX_CONSERVING_CONTACT', '%10d%10d%10d%10d%10s' % (1, 1, 2, 1, fmt(a.eps))]
        out += ['*DYNX_RIGID_SPHERE', '%10d%10d%10s' % (1, 0, '1e-6')]
    bn, be = cube_ball(a.n, 0.3, tuple(a.ball_x), 0, 0, 1)
    xn, xe = hollow_box(1.0, 0.5, 4, len(bn), len(be), 2)
    write_mesh(out, bn + xn, be + xe)
    out.append('*END')
    return out


def ballshell(a):
    out = ['*KEYWORD', '*TITLE', 'seed ball in a spherical shell (conserving contact%s)' %
           (', faceted' if a.faceted else ', spherical smoothing'),
           '$ generated by scripts/gen_emc_decks.py ballshell']
    tend = a.dt * a.steps
    out += ['*CONTROL_TERMINATION', fmt(tend)]
    out += ['*CONTROL_IMPLICIT_GENERAL', '%10d%10s' % (1, fmt(a.dt))]
    out += ['*DYNX_CONSERVING_CONTROL', '%10d%10s%10d%10s' % (20, '0', 0, fmt(a.outdt))]
    out += ['*DATABASE_BINARY_D3PLOT', fmt(tend / 20.0)]
    out += ['*SECTION_SOLID', '%10d%10d' % (1, 1)]
    part(out, 1, 'ball', 0.274)
    part(out, 2, 'shell', 0.743)
    ivel(out, 1, 0.0, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    out += ['*DYNX_CONSERVING_CONTACT', '%10d%10d%10d%10d%10s%10s%10s' % (
        1, 1, 2, 1, fmt(a.eps), fmt(a.fs), fmt(a.dfric))]
    if not a.faceted:
        out += ['*DYNX_RIGID_SPHERE', '%10d%10d%10s' % (1, 0, '1e-6'),
                '%10d%10d%10s' % (2, 1, '1e-6')]
    bn, be = cube_ball(a.n, 0.5, (0.0, 0.0, -0.5), 0, 0, 1)
    sn, se = sphere_shell(a.m, 1.0, 1.1, len(bn), len(be), 2)
    write_mesh(out, bn + sn, be + se)
    out.append('*END')
    return out


def bar(x0, nx, L, nid0, eid0, pid):
    """A bar L x 1 x 1 from x0 along x: nx x 1 x 1 hexes."""
    nodes, ids, nid = [], {}, nid0
    for i in range(nx + 1):
        for k in range(2):
            for j in range(2):
                nid += 1
                ids[(i, j, k)] = nid
                nodes.append((nid, [x0 + L * i / nx, j - 0.5, k - 0.5]))
    elems, eid = [], eid0
    for i in range(nx):
        conn = [ids[(i, 0, 0)], ids[(i + 1, 0, 0)], ids[(i + 1, 1, 0)], ids[(i, 1, 0)],
                ids[(i, 0, 1)], ids[(i + 1, 0, 1)], ids[(i + 1, 1, 1)], ids[(i, 1, 1)]]
        eid += 1
        elems.append((eid, pid, conn))
    return nodes, elems


def bars(a):
    out = ['*KEYWORD', '*TITLE', 'two slender rigid bars impacting (seed Fig. 4), %s' %
           ('Lagrange multipliers' if a.lagrange else 'penalty'),
           '$ generated by scripts/gen_emc_decks.py bars']
    tend = a.dt * a.steps
    out += ['*CONTROL_TERMINATION', fmt(tend)]
    out += ['*CONTROL_IMPLICIT_GENERAL', '%10d%10s' % (1, fmt(a.dt))]
    out += ['*DYNX_CONSERVING_CONTROL', '%10d%10s%10d%10s' % (20, '0', a.nfail, fmt(a.outdt))]
    out += ['*DATABASE_BINARY_D3PLOT', fmt(tend / 20.0)]
    out += ['*SECTION_SOLID', '%10d%10d' % (1, 1)]
    part(out, 1, 'left bar', 1.0)
    part(out, 2, 'right bar', 1.0)
    ivel(out, 1, 0.0, (a.v0, 0.0, 0.0), (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    if a.lagrange:
        out += ['*DYNX_CONSERVING_CONTACT', '%10d%10d%10d%10d' % (1, 1, 2, 2)]
    else:
        out += ['*DYNX_CONSERVING_CONTACT', '%10d%10d%10d%10d%10s' % (1, 1, 2, 1, fmt(a.eps))]
    ln, le = bar(-50.0, 10, 50.0, 0, 0, 1)
    rn, re = bar(0.01, 10, 50.0, len(ln), len(le), 2)
    write_mesh(out, ln + rn, le + re)
    out.append('*END')
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('scene', choices=['ballbox', 'ballshell', 'bars'])
    ap.add_argument('--dt', type=float, default=1e-3)
    ap.add_argument('--steps', type=int, default=100000)
    ap.add_argument('--eps', type=float, default=1e6)
    ap.add_argument('--outdt', type=float, default=0.0)
    ap.add_argument('--n', type=int, default=4, help='ball cells per diameter (even)')
    ap.add_argument('--m', type=int, default=8, help='shell cells per cube-face edge (even)')
    ap.add_argument('--explicit', action='store_true')
    ap.add_argument('--tssfac', type=float, default=0.9)
    ap.add_argument('--sfs', type=float, default=1.0)
    ap.add_argument('--faceted', action='store_true')
    ap.add_argument('--v0', type=float, default=1.0, help='bars: impact speed')
    ap.add_argument('--nfail', type=int, default=0, help='bars: NFAIL (step halvings)')
    ap.add_argument('--lagrange', action='store_true', help='bars: FORM 2')
    ap.add_argument('--ball-x', type=float, nargs=3, default=[0.0, 0.0, 0.0],
                    help='ballbox: ball centre')
    ap.add_argument('--ball-v', type=float, nargs=3, default=[3.0, 2.0, 1.0],
                    help='ballbox: ball velocity')
    ap.add_argument('--spin', type=float, default=2.0, help='ballbox: ball spin [rad/s]')
    ap.add_argument('--box-still', action='store_true', help='ballbox: box at rest')
    ap.add_argument('--fs', type=float, default=0.0, help='ballshell: Coulomb coefficient')
    ap.add_argument('--dfric', type=float, default=0.0, help='ballshell: regularization slip')
    a = ap.parse_args()
    out = {'ballbox': ballbox, 'ballshell': ballshell, 'bars': bars}[a.scene](a)
    print('\n'.join(out))


if __name__ == '__main__':
    main()
