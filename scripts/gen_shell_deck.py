#!/usr/bin/python3
"""Shell test decks (mm, ms, kg, GPa): a flat rectangular plate of Belytschko-Lin-Tsay
shells, nx by ny elements, length L along x, width B along y, thickness T.

  gen_shell_deck.py cantilever NX NY [OUT]   clamped at x = 0 (all six DOF), initial
      transverse velocity in the shape of the first cantilever mode (Euler-Bernoulli,
      PR = 0 so that beam and plate theory agree), tip nodes in nodout
  gen_shell_deck.py patch|patch_tri [OUT]    membrane patch test (MacNeal-Harder 1985), its
      plane rotated out of x-y; the four corners driven with the velocity of a uniform
      velocity gradient, the four inner nodes free (patch_tri: the inner quadrilateral cut
      into two triangles N4 = N3; patch_plastic: *MAT_PLASTIC_KINEMATIC (SIGY 0.25, ETAN 0)
      stretched to 5 % with *CONTROL_SHELL ISTUPD = 1)
  gen_shell_deck.py bend [ELFORM [OUT]]     bending patch test: the MacNeal-Harder patch in
      its plane rotated out of x-y (thickness 1); the corners driven with the transverse
      velocity and angular velocities of a uniform curvature rate (no transverse shear:
      v_n = -(k1 x**2 + k2 y**2 + k12 x y)/2, w = n x grad v_n in the plate axes), the inner
      nodes free and started on the same field
  gen_shell_deck.py patch ... and cantilever ...: ELFORM from the environment variable
      SHELL_ELFORM (default 2)
  gen_shell_deck.py pressure N [OUT]        a clamped square plate 100 x 100 x 1 mm of N x N
      shells (SHELL_ELFORM), *MAT_PLASTIC_KINEMATIC, under a uniform pressure (*LOAD_SEGMENT)
      ramped to 3e-4 GPa in 20 ms: it yields at the edges, then across; the centre in nodout
  gen_shell_deck.py rotation [OUT]           a free plate spinning as a rigid body about an
      in-plane axis (initial velocity omega x r): no strain, internal energy 0
  gen_shell_deck.py mixed [OUT]              hexahedra and shells sharing nodes: a 100 x 10 mm
      plate of 10x2 shells whose root (x <= 30) lies on a 3x2x2 block of hexahedra clamped
      at its base; the free end starts with a transverse velocity and a twist rate (VXR), a
      prescribed twist rate (DOF 5, a ramp) drives the tip and DOFRY holds one tip node: the
      MPI case of shells beside solids (mpi_shell_mixed)
  gen_shell_deck.py ball SIDE KW SOFT[,MST] [OUT]  a sphere of hexahedra (R 5 mm, 4x4x4 cube mapped
      radially, steel) dropped at 5 mm/ms on a free 40 x 40 x 1 mm steel plate of 8x8 BT
      shells from above (SIDE = above: the plate's normal side) or below (SIDE = below),
      *CONTACT_KW (AUTOMATIC_SURFACE_TO_SURFACE, AUTOMATIC_NODES_TO_SURFACE,
      AUTOMATIC_SINGLE_SURFACE, SURFACE_TO_SURFACE ...) with SOFT; the first gap 0.1 mm to the
      contact surface half a thickness (or MST/2) off the mid-surface (shell_contact_* cases)
  gen_shell_deck.py plates KW [OUT]          shell on shell: a 20 x 20 x 1 mm plate of 4x4 BT
      shells (part 2) dropped flat at 5 mm/ms on the free 40 x 40 x 1 mm plate, centred; first
      gap 0.1 mm between the contact surfaces (both half a thickness off their mid-surfaces),
      *CONTACT_KW (shell_contact_plates)
  gen_shell_deck.py circle NX ELFORM [OUT]  a cantilever strip 12 x 1 x 0.1 of NX x 1 shells
      (E 1.2e6, PR 0, RHO 1: Sze, Liu and Lo 2004's benchmark, E I = 100), clamped at x = 0,
      at rest under an end moment about y (*LOAD_NODE_POINT DOF 6, M/2 on each tip node)
      M = 2 pi E I/L raised smoothly (1 - cos) over 80 (10 first periods) and held to 160:
      the strip rolls into a full circle of radius L/(2 pi), the tip back at the root; the
      middle and tip nodes of the edge y = 0 in nodout (shell_moment_circle cases); the
      other nodes held to the plane motion (y and the rotations about x, z fixed) unless the
      last argument is 'free'
"""
import math
import os
import sys

E, RHO = 210.0, 7.85e-6
ELFORM = int(os.environ.get('SHELL_ELFORM', '2'))


def head(title, tend, dplot, dhist, hist_nodes, pr=0.0, extra=''):
    s = ['*KEYWORD', '*TITLE', title,
         '*CONTROL_TERMINATION', f'{tend:10.4f}',
         '*CONTROL_TIMESTEP', '$   DTINIT    TSSFAC', '       0.0    0.9000',
         '*DATABASE_GLSTAT', f'{dhist:10.6f}',
         '*DATABASE_NODOUT', f'{dhist:10.6f}',
         '*DATABASE_BINARY_D3PLOT', f'{dplot:10.6f}',
         '*DATABASE_HISTORY_NODE', ''.join(f'{n:10d}' for n in hist_nodes),
         '*PART', 'plate', '         1         1         1',
         '*SECTION_SHELL',
         '$    SECID    ELFORM      SHRF       NIP',
         f'         1{ELFORM:10d}  0.833333         3',
         '$       T1',
         '       1.0',
         '*MAT_ELASTIC', '$      MID        RO         E        PR',
         f'         1{RHO:10.3e}{E:10.1f}{pr:10.3f}']
    if extra:
        s.append(extra)
    return s


def grid(nx, ny, lx, ly):
    nodes, elems = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((j*(nx + 1) + i + 1, lx*i/nx, ly*j/ny, 0.0))
    for j in range(ny):
        for i in range(nx):
            n1 = j*(nx + 1) + i + 1
            elems.append((j*nx + i + 1, n1, n1 + 1, n1 + nx + 2, n1 + nx + 1))
    return nodes, elems


def node_cards(nodes):
    out = ['*NODE']
    for n, x, y, z in nodes:
        out.append(f'{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}')
    return out


def elem_cards(elems):
    out = ['*ELEMENT_SHELL']
    for e in elems:
        out.append(''.join(f'{k:8d}' for k in (e[0], 1) + tuple(e[1:])))
    return out


def cantilever(nx, ny):
    L, B = 100.0, 10.0
    nodes, elems = grid(nx, ny, L, B)
    bl = 1.8751040687
    sig = (math.cosh(bl) + math.cos(bl))/(math.sinh(bl) + math.sin(bl))

    def phi(x):
        a = bl*x/L
        return 0.5*(math.cosh(a) - math.cos(a) - sig*(math.sinh(a) - math.sin(a)))

    tip = [j*(nx + 1) + nx + 1 for j in range(ny + 1)]
    s = head(f'Cantilever plate {nx}x{ny} BT shells, first mode', 15.0, 1.0, 0.01, tip[:1])
    s += node_cards(nodes) + elem_cards(elems)
    s += ['*INITIAL_VELOCITY_NODE']
    v0 = 1.0e-3        # mm/ms: tip velocity 1e-3 (small rotations)
    for n, x, y, z in nodes:
        if x > 0.0:
            s.append(f'{n:10d}{0.0:10.4g}{0.0:10.4g}{v0*phi(x):10.3e}')
    s += ['*SET_NODE_LIST', '         1']
    clamp = [j*(nx + 1) + 1 for j in range(ny + 1)]
    for k in range(0, len(clamp), 8):
        s.append(''.join(f'{n:10d}' for n in clamp[k:k + 8]))
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def pressure(n):
    """A clamped square steel plate 100 x 100 x 1 mm of n x n shells (n even: a centre node)
    under a uniform pressure ramped 0 -> 3e-4 GPa in 20 ms (about 3.7 times the pressure
    that first yields the clamped edges, q a**2/t**2 0.308 = SIGY) and held to 25 ms;
    *MAT_PLASTIC_KINEMATIC SIGY 0.25, ETAN 1.0; the centre node in nodout."""
    a = 100.0
    nodes, elems = grid(n, n, a, a)
    centre = (n//2)*(n + 1) + n//2 + 1
    s = head(f'Clamped plate {n}x{n} under pressure, going plastic (ELFORM {ELFORM})', 25.0,
             5.0, 0.25, [centre], pr=0.3)
    k = s.index('*MAT_ELASTIC')
    s[k:k + 3] = ['*MAT_PLASTIC_KINEMATIC',
                  '$      MID        RO         E        PR      SIGY      ETAN      BETA',
                  f'         1{RHO:10.3e}{E:10.1f}     0.300      0.25       1.0       0.0']
    s += node_cards(nodes) + elem_cards(elems)
    s += ['*DEFINE_CURVE', '         1', f'{0.0:20.4f}{0.0:20.4e}', f'{20.0:20.4f}{3.0e-4:20.4e}',
          f'{100.0:20.4f}{3.0e-4:20.4e}']
    s += ['*LOAD_SEGMENT']
    for e in elems:
        s.append(f'{1:10d}{1.0:10.3f}{0.0:10.3f}' + ''.join(f'{q:10d}' for q in e[1:]))
    edge = [m for m, x, y, z in nodes if x in (0.0, a) or y in (0.0, a)]
    s += ['*SET_NODE_LIST', '         1']
    for k in range(0, len(edge), 8):
        s.append(''.join(f'{q:10d}' for q in edge[k:k + 8]))
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def rotation_matrix(axis, deg):
    """rotation by deg degrees about axis (Rodrigues)"""
    n = math.sqrt(sum(a*a for a in axis))
    k = [a/n for a in axis]
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    kx = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[(1.0 if i == j else 0.0)*c + s*kx[i][j] + (1 - c)*k[i]*k[j] for j in range(3)]
            for i in range(3)]


def mat_vec(a, v):
    return [sum(a[i][j]*v[j] for j in range(3)) for i in range(3)]


# MacNeal & Harder (1985) membrane patch, 0.24 x 0.12 scaled to mm (x100), rotated out of
# the x-y plane; its inner quadrilateral is cut into two triangles (N4 = N3) with tri = True
PATCH_NODES = [(0, 0), (24, 0), (24, 12), (0, 12), (4, 2), (18, 3), (16, 8), (8, 8)]
PATCH_QUADS = [(1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)]
PATCH_GRAD = [[1.0e-3, 6.0e-4], [2.0e-4, -5.0e-4]]   # in-plane velocity gradient, 1/ms
PATCH_GRAD_PLASTIC = [[5.0e-2, 1.0e-2], [0.0, -1.0e-2]]   # to 5 % strain: yielding
PATCH_AXIS, PATCH_DEG = (1.0, 2.0, 3.0), 35.0


def patch(tri, plastic=False):
    r = rotation_matrix(PATCH_AXIS, PATCH_DEG)
    lg = [[PATCH_GRAD[i][j] if i < 2 and j < 2 else 0.0 for j in range(3)] for i in range(3)]
    # v = R Lg R^T x (x: rotated coordinates)
    rt = [[r[j][i] for j in range(3)] for i in range(3)]
    l3 = [[sum(r[i][a]*lg[a][b]*rt[b][j] for a in range(3) for b in range(3))
           for j in range(3)] for i in range(3)]
    nodes = []
    for k, (x, y) in enumerate(PATCH_NODES):
        p = mat_vec(r, [x, y, 0.0])
        # the coordinates as dynx reads them (20-column fields), so that the velocity
        # field below is linear in them to round-off
        nodes.append((k + 1,) + tuple(float(f'{c:20.13e}') for c in p))
    quads = list(PATCH_QUADS)
    if tri:
        quads += [(5, 6, 7, 7), (5, 7, 8, 8)]
    else:
        quads += [(5, 6, 7, 8)]
    elems = [(k + 1,) + q for k, q in enumerate(quads)]
    kind = 'triangles' if tri else 'quadrilaterals'
    grad = PATCH_GRAD_PLASTIC if plastic else PATCH_GRAD
    lg = [[grad[i][j] if i < 2 and j < 2 else 0.0 for j in range(3)] for i in range(3)]
    l3 = [[sum(r[i][a]*lg[a][b]*rt[b][j] for a in range(3) for b in range(3))
           for j in range(3)] for i in range(3)]
    s = head(f'Membrane patch test (MacNeal-Harder, rotated; inner {kind})', 1.0, 0.5, 0.05,
             [5, 6, 7, 8], pr=0.3)
    if plastic:      # *MAT_PLASTIC_KINEMATIC, perfectly plastic, ISTUPD = 1
        k = s.index('*MAT_ELASTIC')
        s[k:k + 3] = ['*MAT_PLASTIC_KINEMATIC',
                      '$      MID        RO         E        PR      SIGY      ETAN      BETA',
                      f'         1{RHO:10.3e}{E:10.1f}     0.300      0.25       0.0       0.0',
                      '*CONTROL_SHELL', '$   WRPANG     ESORT     IRNXX    ISTUPD',
                      '        20         0        -1         1']
    s += ['*NODE +'] + [f'{n:20d}{x:20.13e}{y:20.13e}{z:20.13e}' for n, x, y, z in nodes]
    s += elem_cards(elems)
    s += ['*DEFINE_CURVE', '         1', f'{0.0:20.4f}{1.0:20.4f}', f'{100.0:20.4f}{1.0:20.4f}']
    s += ['*INITIAL_VELOCITY_NODE +']
    vel = {}
    for n, x, y, z in nodes:
        v = mat_vec(l3, [x, y, z])
        vel[n] = v
        s.append(f'{n:20d}' + ''.join(f'{c:20.13e}' for c in v))
    # a zero component is an SPC (SF = 0 means 1 on *BOUNDARY_PRESCRIBED_MOTION)
    s += ['*BOUNDARY_PRESCRIBED_MOTION_NODE +']
    fix = []
    for n in (1, 2, 3, 4):
        for d in range(3):
            if vel[n][d] == 0.0:
                fix.append((n, d))
            else:
                s.append(f'{n:20d}{d + 1:20d}{0:20d}{1:20d}{vel[n][d]:20.13e}')
    if fix:
        s += ['*BOUNDARY_SPC_NODE']
        for n, d in fix:
            s.append(f'{n:10d}         0' + ''.join('         1' if k == d else '         0'
                                                  for k in range(3)))
    s.append('*END')
    return s


BEND_RATE = (2.0e-11, -1.0e-11, 1.5e-11)   # k1, k2, k12: curvature rates, 1/(mm ms) (small:
# the residual of the free nodes is the geometric nonlinearity, proportional to the rate)


def bend():
    """Bending patch test (MacNeal & Harder 1985 geometry): uniform curvature rate."""
    r = rotation_matrix(PATCH_AXIS, PATCH_DEG)
    k1, k2, k12 = BEND_RATE
    nodes, vel = [], {}
    for k, (x, y) in enumerate(PATCH_NODES):
        p = tuple(float(f'{c:20.13e}') for c in mat_vec(r, [x, y, 0.0]))
        nodes.append((k + 1,) + p)
        vn = -0.5*(k1*x*x + k2*y*y + k12*x*y)
        # rotation rates in the plate axes: v_n = y w_x - x w_y for a rigid rotation, so
        # w_x = d v_n/dy, w_y = -d v_n/dx (zero transverse shear)
        wl = [-(k2*y + 0.5*k12*x), k1*x + 0.5*k12*y, 0.0]
        vel[k + 1] = [float(f'{c:20.13e}') for c in mat_vec(r, [0.0, 0.0, vn]) + mat_vec(r, wl)]
    elems = [(k + 1,) + q for k, q in enumerate(list(PATCH_QUADS) + [(5, 6, 7, 8)])]
    s = head('Bending patch test (MacNeal-Harder, rotated; uniform curvature rate)', 1.0, 0.5,
             0.05, [5, 6, 7, 8], pr=0.3)
    k = s.index('       1.0')
    s[k] = '       1.0'
    s += ['*NODE +'] + [f'{n:20d}{x:20.13e}{y:20.13e}{z:20.13e}' for n, x, y, z in nodes]
    s += elem_cards(elems)
    s += ['*DEFINE_CURVE', '         1', f'{0.0:20.4f}{1.0:20.4f}', f'{100.0:20.4f}{1.0:20.4f}']
    s += ['*INITIAL_VELOCITY_NODE +']
    for n in vel:
        s.append(f'{n:20d}' + ''.join(f'{c:20.13e}' for c in vel[n]))
    s += ['*BOUNDARY_PRESCRIBED_MOTION_NODE +']
    fix = []
    for n in (1, 2, 3, 4):
        for d in (0, 1, 2, 3, 4, 5):
            dof = d + 1 if d < 3 else d + 2     # 5, 6, 7: rotations about x, y, z
            if vel[n][d] == 0.0:        # (SF = 0 would mean 1: an SPC instead)
                fix.append((n, d))
            else:
                s.append(f'{n:20d}{dof:20d}{0:20d}{1:20d}{vel[n][d]:20.13e}')
    if fix:
        s += ['*BOUNDARY_SPC_NODE']
        for n, d in fix:
            s.append(f'{n:10d}         0' + ''.join('         1' if k == d else '         0'
                                                  for k in range(6)))
    s.append('*END')
    return s


def rotation():
    """a 4x2 plate spinning about an in-plane axis through its centre"""
    nodes, elems = grid(4, 2, 40.0, 20.0)
    om = (0.05, 0.03, 0.0)       # rad/ms, about an axis in the plane z = 0
    xc = (20.0, 10.0, 0.0)
    s = head('Free plate in rigid rotation (BT shells)', 20.0, 10.0, 0.5, [1, 15])
    s += node_cards(nodes) + elem_cards(elems)
    s += ['*INITIAL_VELOCITY_NODE +']
    for n, x, y, z in nodes:
        r = (x - xc[0], y - xc[1], z - xc[2])
        v = (om[1]*r[2] - om[2]*r[1], om[2]*r[0] - om[0]*r[2], om[0]*r[1] - om[1]*r[0])
        s.append(f'{n:20d}' + ''.join(f'{c:20.13e}' for c in v + om))
    s.append('*END')
    return s


def mixed():
    """shell plate on a hex block (shared nodes), initial and prescribed rotations"""
    nx, ny = 10, 2
    nodes, elems = grid(nx, ny, 100.0, 10.0)
    tip = [j*(nx + 1) + nx + 1 for j in range(ny + 1)]
    s = head('Shell plate on a block of hexahedra (shared nodes)', 3.0, 0.5, 0.02, tip)
    # the block: x 0..30 (3), y 0..10 (2), z -10..0 (2); its top layer is the plate's nodes
    hx, hy, hz = 3, 2, 2
    nid = {}
    for j in range(ny + 1):
        for i in range(hx + 1):
            nid[(i, j, hz)] = j*(nx + 1) + i + 1
    nxt = len(nodes) + 1
    hnodes = []
    for k in range(hz):
        for j in range(hy + 1):
            for i in range(hx + 1):
                nid[(i, j, k)] = nxt
                hnodes.append((nxt, 10.0*i, 5.0*j, -10.0 + 5.0*k))
                nxt += 1
    hexes = []
    for k in range(hz):
        for j in range(hy):
            for i in range(hx):
                c = [nid[(i, j, k)], nid[(i + 1, j, k)], nid[(i + 1, j + 1, k)],
                     nid[(i, j + 1, k)], nid[(i, j, k + 1)], nid[(i + 1, j, k + 1)],
                     nid[(i + 1, j + 1, k + 1)], nid[(i, j + 1, k + 1)]]
                hexes.append((100 + len(hexes) + 1, c))
    s += ['*PART', 'block', '         2         2         2',
          '*SECTION_SOLID', '         2         1',
          '*MAT_ELASTIC', '$      MID        RO         E        PR',
          f'         2{RHO:10.3e}{70.0:10.1f}{0.3:10.3f}']
    s += node_cards(nodes + hnodes) + elem_cards(elems)
    s += ['*ELEMENT_SOLID']
    for e, c in hexes:
        s.append(f'{e:8d}{2:8d}' + ''.join(f'{n:8d}' for n in c))
    s += ['*INITIAL_VELOCITY_NODE']
    for n, x, y, z in nodes:
        if x > 30.0:
            a = (x - 30.0)/70.0
            s.append(f'{n:10d}{0.0:10.4g}{0.0:10.4g}{0.02*a*a:10.3e}{0.0002*a:10.3e}'
                     f'{0.0:10.4g}{0.0:10.4g}')
    s += ['*DEFINE_CURVE', '         1', f'{0.0:20.4f}{0.0:20.4f}', f'{3.0:20.4f}{0.003:20.4f}']
    for n in tip:
        s += ['*BOUNDARY_PRESCRIBED_MOTION_NODE', f'{n:10d}         5         0         1'
              '       1.0']
    s += ['*BOUNDARY_SPC_NODE', f'{tip[1]:10d}         0         0         0         0'
          '         0         1         0']
    s += ['*SET_NODE_LIST', '         1']
    base = [nid[(i, j, 0)] for j in range(hy + 1) for i in range(hx + 1)]
    for k in range(0, len(base), 8):
        s.append(''.join(f'{n:10d}' for n in base[k:k + 8]))
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         0         0         0', '*END']
    return s


def ball(side, kw, soft, mst=0.0):
    """hex sphere on a free shell plate (contact on shells)"""
    n, R, t, gap, v0 = 4, 5.0, 1.0, 0.1, 5.0
    tc = mst if mst > 0.0 else t        # the contact thickness of the plate
    nodes, elems = grid(8, 8, 40.0, 40.0)
    nodes = [(k, x - 20.0, y - 20.0, z) for k, x, y, z in nodes]
    sgn = 1.0 if side == 'above' else -1.0
    zc = sgn*(R + gap + 0.5*tc)
    centre = 41
    s = head(f'Sphere of hexahedra on a shell plate ({side}), *CONTACT_{kw}, SOFT {soft}'
             + (f', MST {mst:g}' if mst > 0.0 else ''),
             0.3, 0.05, 0.005, [centre])
    s[s.index('$       T1') + 1] = f'{t:10.4f}'
    ids = {}
    hn = []
    nid = len(nodes) + 1
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                q = [2.0*i/n - 1.0, 2.0*j/n - 1.0, 2.0*k/n - 1.0]
                linf = max(abs(c) for c in q)
                l2 = math.sqrt(sum(c*c for c in q))
                f = R*linf/l2 if l2 > 0.0 else 0.0
                ids[(i, j, k)] = nid
                hn.append((nid, f*q[0], f*q[1], zc + f*q[2]))
                nid += 1
    hexes = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                c = [ids[(i, j, k)], ids[(i + 1, j, k)], ids[(i + 1, j + 1, k)], ids[(i, j + 1, k)],
                     ids[(i, j, k + 1)], ids[(i + 1, j, k + 1)], ids[(i + 1, j + 1, k + 1)],
                     ids[(i, j + 1, k + 1)]]
                hexes.append((1000 + len(hexes) + 1, c))
    bottom = ids[(n//2, n//2, 0 if side == 'above' else n)]
    s[s.index('*DATABASE_HISTORY_NODE') + 1] = f'{centre:10d}{bottom:10d}'
    s += ['*PART', 'sphere', '         2         2         2',
          '*SECTION_SOLID', '         2         1',
          '*MAT_ELASTIC', '$      MID        RO         E        PR',
          f'         2{RHO:10.3e}{E:10.1f}{0.3:10.3f}']
    s += node_cards(nodes + hn) + elem_cards(elems)
    s += ['*ELEMENT_SOLID']
    for e, c in hexes:
        s.append(f'{e:8d}{2:8d}' + ''.join(f'{m:8d}' for m in c))
    s += ['*INITIAL_VELOCITY_NODE']
    for m, x, y, z in hn:
        s.append(f'{m:10d}{0.0:10.4g}{0.0:10.4g}{-sgn*v0:10.4g}')
    s += [f'*CONTACT_{kw}', '$     SSID      MSID     SSTYP     MSTYP',
          '         0         0         5' if 'SINGLE' in kw else
          '         2         1         3         3',
          '$       FS        FD        DC        VC       VDC    PENCHK        BT        DT',
          '       0.0       0.0       0.0       0.0       0.0         0       0.0       0.0',
          '$      SFS       SFM       SST       MST      SFST      SFMT       FSF       VSF',
          f'       1.0       1.0       0.0{mst:10.4g}       1.0       1.0       1.0       1.0',
          '$     SOFT    SOFSCL',
          f'{soft:10d}       0.1', '*END']
    return s


def plates(kw):
    """a small shell plate dropped on a larger one (both offsets)"""
    t, gap, v0, tilt = 1.0, 0.1, 5.0, 0.0
    nodes, elems = grid(8, 8, 40.0, 40.0)
    nodes = [(k, x - 20.0, y - 20.0, z) for k, x, y, z in nodes]
    small, selems = grid(4, 4, 20.0, 20.0)
    off = len(nodes)
    z0 = t + gap + 10.0*math.sin(tilt)     # the lowest edge (y = -10) at t + gap
    small = [(k + off, x - 10.0, (y - 10.0)*math.cos(tilt), z0 + (y - 10.0)*math.sin(tilt))
             for k, x, y, z in small]
    selems = [(e + 100, a + off, b + off, c + off, d + off) for e, a, b, c, d in selems]
    low = off + 13         # the small plate's centre
    s = head(f'Shell plate dropped on a shell plate, *CONTACT_{kw}', 0.3, 0.05, 0.005, [41, low])
    s += ['*PART', 'small plate', '         2         1         1']
    s += node_cards(nodes + small) + elem_cards(elems)
    for e in selems:
        s.append(''.join(f'{k:8d}' for k in (e[0], 2) + tuple(e[1:])))
    s += ['*INITIAL_VELOCITY_NODE']
    for m, x, y, z in small:
        s.append(f'{m:10d}{0.0:10.4g}{0.0:10.4g}{-v0:10.4g}')
    s += [f'*CONTACT_{kw}', '$     SSID      MSID     SSTYP     MSTYP',
          '         0         0         5' if 'SINGLE' in kw else
          '         2         1         3         3',
          '$       FS        FD        DC        VC       VDC    PENCHK        BT        DT',
          '       0.0       0.0       0.0       0.0       0.0         0       0.0       0.0',
          '*END']
    return s


def circle(nx, elform, planar=True):
    """the rolled-up cantilever strip of the module docstring; planar: the other nodes held
    to the x-z plane's motion (y, the rotations about x and z fixed: exact for PR = 0)"""
    L, B, T, EC, RC = 12.0, 1.0, 0.1, 1.2e6, 1.0
    nodes, elems = grid(nx, 1, L, B)
    tip = [nx + 1, 2*(nx + 1)]
    s = head(f'Cantilever strip {nx}x1 shells (ELFORM {elform}), end moment 2 pi E I/L '
             '(rolled into a circle)', 160.0, 20.0, 0.1, [nx//2 + 1, nx + 1])
    k = s.index('*SECTION_SHELL')
    s[k + 2] = f'         1{elform:10d}  0.833333         3'
    s[k + 4] = f'{T:10.4f}'
    m = s.index('*MAT_ELASTIC')
    s[m + 2] = f'         1{RC:10.3e}{EC:10.4g}{0.0:10.3f}'
    s += node_cards(nodes) + elem_cards(elems)
    s += ['*DEFINE_CURVE', '         1']
    for i in range(33):
        t = 2.5*i
        s.append(f'{t:20.8f}{0.5*(1.0 - math.cos(math.pi*t/80.0)):20.10f}')
    s.append(f'{1000.0:20.8f}{1.0:20.10f}')
    mh = 0.5*2.0*math.pi*EC*B*T**3/12.0/L
    s += ['*LOAD_NODE_POINT', '$     NID       DOF      LCID        SF']
    s += [f'{n:10d}{6:10d}{1:10d}{mh:10.6f}' for n in tip]
    s += ['*SET_NODE_LIST', '         1', f'{1:10d}{nx + 2:10d}']
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         1         1         1']
    if planar:
        free = [n for n, x, y, z in nodes if x > 0.0]
        s += ['*SET_NODE_LIST', '         2']
        for k in range(0, len(free), 8):
            s.append(''.join(f'{n:10d}' for n in free[k:k + 8]))
        s += ['*BOUNDARY_SPC_SET', '         2         0         0         1         0'
              '         1         0         1']
    return s + ['*END']


def main():
    kind = sys.argv[1]
    if kind == 'cantilever':
        lines = cantilever(int(sys.argv[2]), int(sys.argv[3]))
        out = sys.argv[4] if len(sys.argv) > 4 else None
    elif kind in ('patch', 'patch_tri', 'patch_plastic'):
        lines = patch(kind == 'patch_tri', kind == 'patch_plastic')
        out = sys.argv[2] if len(sys.argv) > 2 else None
    elif kind == 'bend':
        global ELFORM
        if len(sys.argv) > 2:
            ELFORM = int(sys.argv[2])
        lines = bend()
        out = sys.argv[3] if len(sys.argv) > 3 else None
    elif kind == 'pressure':
        lines = pressure(int(sys.argv[2]))
        out = sys.argv[3] if len(sys.argv) > 3 else None
    elif kind == 'rotation':
        lines = rotation()
        out = sys.argv[2] if len(sys.argv) > 2 else None
    elif kind == 'ball':
        sm = sys.argv[4].split(',')
        lines = ball(sys.argv[2], sys.argv[3], int(sm[0]), float(sm[1]) if len(sm) > 1 else 0.0)
        out = sys.argv[5] if len(sys.argv) > 5 else None
    elif kind == 'plates':
        lines = plates(sys.argv[2])
        out = sys.argv[3] if len(sys.argv) > 3 else None
    elif kind == 'circle':
        free = sys.argv[-1] == 'free'
        args = sys.argv[:-1] if free else sys.argv
        lines = circle(int(args[2]), int(args[3]), not free)
        out = args[4] if len(args) > 4 else None
    elif kind == 'mixed':
        lines = mixed()
        out = sys.argv[2] if len(sys.argv) > 2 else None
    else:
        raise SystemExit('unknown kind ' + kind)
    text = '\n'.join(lines) + '\n'
    if out:
        with open(out, 'w') as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == '__main__':
    main()
