#!/usr/bin/python3
"""The seed's two shell scenes (LLNL FY97 Engineering Thrust Area Report, article 5, "Examples
and Comparison": a rigid blunt projectile on a frame-supported plate, quarter model; a vehicle
hitting a U-shaped rigid post). The seed gives neither dimensions nor materials: every number
below is dynx's choice, listed in decks/<scene>/README.md. Units mm, ms, kg, GPa (force kN,
energy J).

  gen_shell_scenes.py plate N OUTDIR     quarter plate of N x N BT shells (N a multiple of 5)
  gen_shell_scenes.py post N OUTDIR      box-section front, N shells per side of the tube
Options: --tend T (end time, ms), --dplot D (d3plot interval, ms; 0: none).
Writes OUTDIR/mesh.k (everything but *CONTROL_SHELL) and OUTDIR/deck.k (MITER = 4, the one-step
return) and OUTDIR/deck_miter{1,2,3}.k (secant x 3, full return, radial scaling), each a
*CONTROL_SHELL card and an *INCLUDE of mesh.k, so the four runs differ in MITER only.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_shell_deck import grid, node_cards  # noqa: E402

RHO, E, PR = 7.85e-6, 200.0, 0.3          # steel (physics-references.md 3.1)
SIGY, ETAN = 0.25, 2.0                    # 250 MPa, linear hardening 2 GPa (lamina study)


def f10(*vals):
    out = ''
    for v in vals:
        if isinstance(v, int):
            out += f'{v:10d}'
        else:
            s = f'{v:10.4g}'
            out += s if len(s) <= 10 else f'{v:10.3e}'
    return out


def shell_cards(elems, pid):
    out = ['*ELEMENT_SHELL']
    for e in elems:
        out.append(''.join(f'{k:8d}' for k in (e[0], pid) + tuple(e[1:])))
    return out


def node_set(sid, ids):
    out = ['*SET_NODE_LIST', f'{sid:10d}']
    for k in range(0, len(ids), 8):
        out.append(''.join(f'{n:10d}' for n in ids[k:k + 8]))
    return out


def spc(sid, dofs):
    """*BOUNDARY_SPC_SET: dofs = (x, y, z, rx, ry, rz) flags"""
    return ['*BOUNDARY_SPC_SET', f'{sid:10d}         0' + ''.join(f'{d:10d}' for d in dofs)]


def head(title, tend, dplot, dhist, hist):
    s = ['*KEYWORD', '*TITLE', title,
         '*CONTROL_TERMINATION', f'{tend:10.4f}',
         '*CONTROL_TIMESTEP', '$   DTINIT    TSSFAC', '       0.0    0.9000',
         '*DATABASE_GLSTAT', f'{dhist:10.6f}',
         '*DATABASE_NODOUT', f'{dhist:10.6f}',
         '*DATABASE_HISTORY_NODE']
    for k in range(0, len(hist), 8):
        s.append(''.join(f'{n:10d}' for n in hist[k:k + 8]))
    if dplot > 0.0:
        s += ['*DATABASE_BINARY_D3PLOT', f'{dplot:10.6f}']
    return s


def steel_part(pid, title, t, nip):
    return ['*PART', title, f'{pid:10d}{pid:10d}{pid:10d}',
            '*SECTION_SHELL', '$    SECID    ELFORM      SHRF       NIP',
            f'{pid:10d}         2  0.833333{nip:10d}', '$       T1', f'{t:10.4f}',
            '*MAT_PLASTIC_KINEMATIC', '$      MID        RO         E        PR      SIGY'
            '      ETAN      BETA', f'{pid:10d}' + f10(RHO, E, PR, SIGY, ETAN, 1.0)]


def rigid_mat(mid, rho, con1, con2):
    return ['*MAT_RIGID', '$      MID        RO         E        PR', f'{mid:10d}' +
            f10(rho, E, PR), '$      CMO      CON1      CON2', f'{1.0:10.1f}{con1:10d}{con2:10d}']


def contact(kw, ssid, msid, sstyp, mstyp, soft):
    return [f'*CONTACT_{kw}', '$     SSID      MSID     SSTYP     MSTYP',
            f'{ssid:10d}{msid:10d}{sstyp:10d}{mstyp:10d}',
            '$       FS        FD        DC        VC       VDC    PENCHK        BT        DT',
            '       0.0       0.0       0.0       0.0       0.0         0       0.0       0.0',
            '$      SFS       SFM       SST       MST      SFST      SFMT       FSF       VSF',
            '       1.0       1.0       0.0       0.0       1.0       1.0       1.0       1.0',
            '$     SOFT    SOFSCL', f'{soft:10d}       0.1']


# ---------------------------------------------------------------- scene 1: projectile on plate
PLATE_HALF = 100.0       # the plate is 200 x 200 mm; the quarter 100 x 100
PLATE_T = 2.0
PROJ_R, PROJ_L = 10.0, 40.0     # blunt (flat-nosed) cylinder, 20 mm diameter
PROJ_V = 100.0           # mm/ms = 100 m/s
GAP = 0.5                # first gap between the nose and the plate's contact surface
DIAG = 20.0              # the sampling point on the diagonal, (20, 20) mm: outside the nose


def plate_scene(n, tend, dplot):
    if n % 5:
        raise SystemExit('gen_shell_scenes: plate N must be a multiple of 5')
    h = PLATE_HALF/n
    nodes, elems = grid(n, n, PLATE_HALF, PLATE_HALF)
    idiag = round(DIAG/h)
    diag = idiag*(n + 1) + idiag + 1
    # projectile: a quarter cylinder of rigid hexahedra, the quarter disc mapped from the unit
    # square by (u, v) -> R (u sqrt(1 - v^2/2), v sqrt(1 - u^2/2)), 4 x 4 across, 8 along
    nq, nz = 4, 8
    z0 = GAP + 0.5*PLATE_T
    nid = len(nodes) + 1
    ids, pn = {}, []
    for k in range(nz + 1):
        for j in range(nq + 1):
            for i in range(nq + 1):
                u, v = i/nq, j/nq
                x = PROJ_R*u*math.sqrt(1.0 - 0.5*v*v)
                y = PROJ_R*v*math.sqrt(1.0 - 0.5*u*u)
                ids[(i, j, k)] = nid
                pn.append((nid, x, y, z0 + PROJ_L*k/nz))
                nid += 1
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
               (0, 1, 1)]
    cells = [(i, j, k) for k in range(nz) for j in range(nq) for i in range(nq)]
    hexes = [(100001 + q, [ids[(i + a, j + b, k + c)] for a, b, c in corners])
             for q, (i, j, k) in enumerate(cells)]
    nose = ids[(0, 0, 0)]
    s = head(f'Rigid blunt projectile on a frame-supported plate, quarter model, {n}x{n} BT '
             'shells', tend, dplot, tend/100.0, [1, diag, nose])
    s += steel_part(1, 'plate', PLATE_T, 5)
    s += ['*PART', 'projectile', '         2         2         2',
          '*SECTION_SOLID', '         2         1'] + rigid_mat(2, RHO, 4, 7)
    s += node_cards(nodes + pn) + shell_cards(elems, 1) + ['*ELEMENT_SOLID']
    for e, c in hexes:
        s.append(f'{e:8d}{2:8d}' + ''.join(f'{m:8d}' for m in c))
    s += ['*INITIAL_VELOCITY_GENERATION', f'{2:10d}{2:10d}' + f10(0.0, 0.0, 0.0, -PROJ_V),
          f10(0.0, 0.0, 0.0, 0.0, 0.0, 1.0)]
    edge = lambda pred: [m for m, x, y, z in nodes if pred(x, y)]
    tol = 1e-6*h
    s += node_set(1, edge(lambda x, y: x < tol))                  # symmetry plane x = 0
    s += spc(1, (1, 0, 0, 0, 1, 1))
    s += node_set(2, edge(lambda x, y: y < tol))                  # symmetry plane y = 0
    s += spc(2, (0, 1, 0, 1, 0, 1))
    s += node_set(3, edge(lambda x, y: x > PLATE_HALF - tol or y > PLATE_HALF - tol))
    s += spc(3, (1, 1, 1, 1, 1, 1))                               # the frame: clamped edges
    s += contact('AUTOMATIC_SURFACE_TO_SURFACE', 1, 2, 3, 3, 0)
    return s


# ---------------------------------------------------------------- scene 2: box front on a post
TUBE_A, TUBE_T, TUBE_L = 60.0, 1.5, 300.0   # square tube side, wall, length
VEH_M = 20.0             # kg carried by the rigid rear ring
VEH_V = 15.0             # mm/ms = 15 m/s (54 km/h)
POST_W, POST_D, POST_H = 40.0, 30.0, 120.0  # U post: web width, flange depth, height
POST_GAP = 1.0


def post_scene(n, tend, dplot):
    h = TUBE_A/n
    nl = round(TUBE_L/h)
    # the tube: axis along x, front at x = 0, rear at x = TUBE_L; walls at y, z = +-A/2;
    # a ring of 4n nodes per station, walked y = -A/2 .. , counter-clockwise seen from +x
    ring = []
    a2 = 0.5*TUBE_A
    for k in range(n):
        ring.append((-a2 + h*k, -a2))
    for k in range(n):
        ring.append((a2, -a2 + h*k))
    for k in range(n):
        ring.append((a2 - h*k, a2))
    for k in range(n):
        ring.append((-a2, a2 - h*k))
    m = 4*n
    nodes, tube, rear = [], [], []
    for il in range(nl + 1):
        for k, (y, z) in enumerate(ring):
            nodes.append((il*m + k + 1, h*il, y, z))
    for il in range(nl):
        for k in range(m):
            a = il*m + k + 1
            b = il*m + (k + 1) % m + 1
            e = (il*m + k + 1, a, b, b + m, a + m)
            (rear if il == nl - 1 else tube).append(e)
    # the front cap (the "bumper"): an n x n plate in x = 0 sharing the front ring's nodes
    nid = len(nodes) + 1
    cap = {}
    for j in range(n + 1):
        for i in range(n + 1):
            y, z = -a2 + h*i, -a2 + h*j
            if 0 < i < n and 0 < j < n:
                cap[(i, j)] = nid
                nodes.append((nid, 0.0, y, z))
                nid += 1
            else:
                cap[(i, j)] = 1 + ring.index(min(ring, key=lambda p: abs(p[0] - y) + abs(p[1] - z)))
    capel = []
    eid = nl*m + 1
    for j in range(n):
        for i in range(n):
            # normal along -x (outward, toward the post)
            capel.append((eid, cap[(i, j)], cap[(i, j + 1)], cap[(i + 1, j + 1)], cap[(i + 1, j)]))
            eid += 1
    # the U post: web in the plane x = -POST_GAP - t/2 across |y| <= W/2, flanges at
    # y = +-W/2 running away from the tube to x = -gap - D; its axis vertical (z), rigid, fixed
    xw = -POST_GAP - 0.5*TUBE_T
    nw, nd, nh = round(POST_W/h), round(POST_D/h), round(POST_H/h)
    prof = [(xw - POST_D + POST_D*k/nd, -0.5*POST_W) for k in range(nd)]
    prof += [(xw, -0.5*POST_W + POST_W*k/nw) for k in range(nw)]
    prof += [(xw - POST_D*k/nd, 0.5*POST_W) for k in range(nd + 1)]
    np_ = len(prof)
    p0 = nid
    for kz in range(nh + 1):
        for k, (x, y) in enumerate(prof):
            nodes.append((p0 + kz*np_ + k, x, y, -0.5*POST_H + POST_H*kz/nh))
    post = []
    for kz in range(nh):
        for k in range(np_ - 1):
            a = p0 + kz*np_ + k
            post.append((eid, a, a + 1, a + np_ + 1, a + np_))   # normal toward +x on the web
            eid += 1
    # sampling: the cap centre (bumper, direct impact) and the mid-side of a side wall a
    # third of the tube side behind the front (the fender, where the walls buckle)
    cap_c = cap[(n//2, n//2)]
    kside = n + n//2                     # ring index: wall y = +A/2 ... (z = 0 side)
    fender = (n//3)*m + kside + 1 if n >= 3 else m + kside + 1
    rear_node = (nl - 1)*m + 1
    vm = VEH_M/(len(rear)*h*h*TUBE_T)
    s = head(f'Box-section vehicle front on a U-shaped rigid post, {n} BT shells per side',
             tend, dplot, tend/100.0, [cap_c, fender, rear_node])
    s += steel_part(1, 'tube and bumper', TUBE_T, 5)
    s += ['*PART', 'vehicle mass (rigid rear ring)', '         2         2         2',
          '*SECTION_SHELL', '         2         2  0.833333         2', f'{TUBE_T:10.4f}']
    s += rigid_mat(2, vm, 5, 7)
    s += ['*PART', 'U post', '         3         3         3',
          '*SECTION_SHELL', '         3         2  0.833333         2', f'{TUBE_T:10.4f}']
    s += rigid_mat(3, RHO, 7, 7)
    s += node_cards(nodes) + shell_cards(tube + capel, 1) + shell_cards(rear, 2)
    s += shell_cards(post, 3)
    s += ['*SET_PART_LIST', '         1', '         1         2']
    s += ['*INITIAL_VELOCITY_GENERATION', f'{1:10d}{1:10d}' + f10(0.0, -VEH_V, 0.0, 0.0),
          f10(0.0, 0.0, 0.0, 0.0, 0.0, 1.0)]
    s += contact('AUTOMATIC_SINGLE_SURFACE', 0, 0, 5, 0, 0)
    return s


def write_scene(lines, outdir):
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, 'mesh.k'), 'w') as f:
        f.write('\n'.join(lines[1:]) + '\n*END\n')
    names = {4: 'deck.k', 1: 'deck_miter1.k', 2: 'deck_miter2.k', 3: 'deck_miter3.k'}
    what = {4: 'one-step analytic return (dynx MITER 4, the seed)',
            1: 'fixed three secant iterations (MITER 1, DYNA3D default)',
            2: 'full iterative return (MITER 2, reference)', 3: 'radial stress scaling (MITER 3)'}
    for miter, name in names.items():
        with open(os.path.join(outdir, name), 'w') as f:
            f.write('*KEYWORD\n$ ' + what[miter] + '\n*CONTROL_SHELL\n'
                    '$   WRPANG     ESORT     IRNXX    ISTUPD    THEORY       BWC     MITER\n'
                    f'      20.0         0         0         1         2         2{miter:10d}\n'
                    '*INCLUDE\nmesh.k\n*END\n')


def main():
    p = argparse.ArgumentParser()
    p.add_argument('scene', choices=['plate', 'post'])
    p.add_argument('n', type=int)
    p.add_argument('outdir')
    p.add_argument('--tend', type=float)
    p.add_argument('--dplot', type=float, default=-1.0)
    a = p.parse_args()
    if a.scene == 'plate':
        tend = a.tend or 1.0
        lines = plate_scene(a.n, tend, a.dplot if a.dplot >= 0.0 else tend/10.0)
    else:
        tend = a.tend or 6.0
        lines = post_scene(a.n, tend, a.dplot if a.dplot >= 0.0 else tend/10.0)
    write_scene(lines, a.outdir)


if __name__ == '__main__':
    main()
