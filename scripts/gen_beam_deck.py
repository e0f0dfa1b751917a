#!/usr/bin/python3
"""Beam test decks (mm, ms, kg, GPa) of Belytschko-Schwer resultant beams (*SECTION_BEAM
ELFORM 2), steel E = 210, RHO = 7.85e-6, a 2 x 1 rectangular section (width 2 along the s axis y,
height 1 along t = z: A = 2, ISS = 1/6, ITT = 2/3), length L = 100 along x.

  gen_beam_deck.py cantilever N [OUT]   clamped at x = 0 (all six DOF), N elements, initial
      transverse (z) velocity in the shape of the first cantilever mode (Euler-Bernoulli),
      tip node in nodout: the first period against 2 pi / (1.8751**2 sqrt(E I/(rho A L**4)))
  gen_beam_deck.py axial N [OUT]        a free-free bar of N elements, the end x = 0 pushed
      with a constant velocity: the front reaches x at t = x/c, c = sqrt(E/rho)
  gen_beam_deck.py rotation [OUT]       a free beam of 4 elements spinning as a rigid body
      about the y axis through its centre (v = omega x r, VYR = omega): no bending, energy
      conserved
  gen_beam_deck.py elastica N [OUT]     the cantilever at rest under a tip force
      P = E I/L**2 along z raised smoothly over 100 ms and held: large deflection (tip
      rotation 0.46 rad; Mattiasson 1981's elliptic-integral solution)
  gen_beam_deck.py circle N [OUT]       the cantilever at rest under an end moment about y
      (*LOAD_NODE_POINT DOF 6) M = 2 pi E I/L raised over 100 ms and held: it rolls into a
      full circle (tip back at the root, the middle node at the diameter L/pi)
  gen_beam_deck.py root_rotation N [OUT] the cantilever at rest, its root turned about y by a
      prescribed angle (VAD 2) raised to pi/2 over 100 ms and held: a rigid rotation
  gen_beam_deck.py torsion [OUT]        a torsion pendulum: 4 beams clamped at x = 0 with an
      *ELEMENT_INERTIA (100 kg mm**2, isotropic) at the tip, started with VXR = 0.01 x/L
      rad/ms: omega = sqrt(G J/(L I))
  gen_beam_deck.py --hl QR KIND ...    any kind above with Hughes-Liu beams (ELFORM 1, the same
      2 x 1 rectangle: TS = 2, TT = 1, section rule QR, SHRF 5/6) in place of ELFORM 2
  gen_beam_deck.py plastic N QR CST MAT [OUT]  the cantilever of N Hughes-Liu beams (QR, CST 0:
      the 2 x 1 rectangle; CST 1: the tube D = 2, d = 1), elastic-perfectly plastic
      (*MAT_003 or *MAT_024 by MAT, E = 210, PR = 0.3, SIGY = 0.05, ETAN = 0), at rest, its
      tip turned about y by a prescribed angle (DOF 6, VAD 2) raised monotonically (a smooth
      start over 30 ms, then a constant rate) to 0.3 rad at 150 ms (its root clamped): a pure
      bending to 12.6 times the yield curvature, the moment saturates at the fully plastic
      moment of the section
  gen_beam_deck.py tipforce N [OUT]    the elastica deck with a small tip force P = 0.01 E I/L**2
      (linear range: tip w = P L**3/(3 E I) + P L/(SHRF G A) = L/300 plus the shear term)
  gen_beam_deck.py bench N KIND [OUT]  the bench cantilever of N beams, 1000 cycles (ENDCYC):
      KIND bs (ELFORM 2, cantilever's first mode), hl (ELFORM 1, QR 2, the same), hl_plastic
      (the section and *MAT_003 of plastic N 5 0 3 on a free bar stretched at a uniform rate:
      every section point yielding from about cycle 100 on)
  gen_beam_deck.py frame [OUT]          a plate of 4x4 BT shells carried by four beam legs
      (a beam-and-shell frame, shared nodes; the plate with stiffness hourglass IHQ 4,
      which keeps its energy: the default viscous one lets a BT plate on point supports
      drift, 1.0018 here), the legs' tops share
      the plate corners; a *ELEMENT_MASS at the plate centre; the plate starts moving down
      at 0.1 mm/ms and rings on its legs
"""
import math
import sys

E, RHO = 210.0, 7.85e-6
B, H = 2.0, 1.0                  # section width (y) and height (z)
A = B*H
ISS = B*H**3/12.0                # about the s axis (y): bending in the x-z plane
ITT = H*B**3/12.0                # about the t axis (z): bending in the x-y plane


def head(title, tend, dplot, dhist, hist_nodes):
    return ['*KEYWORD', '*TITLE', title,
            '*CONTROL_TERMINATION', f'{tend:10.4f}',
            '*CONTROL_TIMESTEP', '$   DTINIT    TSSFAC', '       0.0    0.9000',
            '*DATABASE_GLSTAT', f'{dhist:10.6f}',
            '*DATABASE_NODOUT', f'{dhist:10.6f}',
            '*DATABASE_BINARY_D3PLOT', f'{dplot:10.6f}',
            '*DATABASE_HISTORY_NODE', ''.join(f'{n:10d}' for n in hist_nodes)]


HL = None                        # --hl: the section rule QR of ELFORM 1 beams


def beam_part(pid=1, secid=1, mid=1):
    if HL is not None:
        return ['*PART', 'beam', f'{pid:10d}{secid:10d}{mid:10d}',
                '*SECTION_BEAM',
                '$    SECID    ELFORM      SHRF   QR/IRID       CST     SCOOR       NSM',
                f'{secid:10d}         1  0.833333{HL:10.1f}         0',
                '$      TS1       TS2       TT1       TT2     NSLOC     NTLOC',
                f'{B:10.4f}{B:10.4f}{H:10.4f}{H:10.4f}',
                '*MAT_ELASTIC', '$      MID        RO         E        PR',
                f'{mid:10d}{RHO:10.3e}{E:10.1f}{0.0:10.3f}']
    return ['*PART', 'beam', f'{pid:10d}{secid:10d}{mid:10d}',
            '*SECTION_BEAM',
            '$    SECID    ELFORM      SHRF   QR/IRID       CST     SCOOR       NSM',
            f'{secid:10d}         2       1.0',
            '$        A       ISS       ITT         J        SA       IST',
            f'{A:10.4f}{ISS:10.6f}{ITT:10.4f}       0.0       0.0       0.0',
            '*MAT_ELASTIC', '$      MID        RO         E        PR',
            f'{mid:10d}{RHO:10.3e}{E:10.1f}{0.0:10.3f}']


def line_nodes(n, length, first=1):
    return [(first + i, length*i/n, 0.0, 0.0) for i in range(n + 1)]


def node_cards(nodes):
    out = ['*NODE']
    for n, x, y, z in nodes:
        out.append(f'{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}')
    return out


def beam_cards(elems, pid=1, n3=0):
    """elems: (eid, n1, n2); the orientation node n3 (0: none)"""
    out = ['*ELEMENT_BEAM', '$    EID     PID      N1      N2      N3']
    for e, a, b in elems:
        out.append(''.join(f'{k:8d}' for k in (e, pid, a, b, n3)))
    return out


def cantilever(n):
    L = 100.0
    nodes = line_nodes(n, L)
    orient = n + 2                               # the orientation node, off the axis in y
    bl = 1.8751040687
    sig = (math.cosh(bl) + math.cos(bl))/(math.sinh(bl) + math.sin(bl))

    def phi(x):
        a = bl*x/L
        return 0.5*(math.cosh(a) - math.cos(a) - sig*(math.sinh(a) - math.sin(a)))

    s = head(f'Cantilever beam, {n} resultant beams, first mode', 15.0, 1.0, 0.01, [n + 1])
    s += beam_part()
    s += node_cards(nodes + [(orient, 0.0, 10.0, 0.0)])
    s += beam_cards([(i + 1, i + 1, i + 2) for i in range(n)], n3=orient)
    s += ['*INITIAL_VELOCITY_NODE']
    v0 = 1.0e-3
    for k, x, y, z in nodes:
        if x > 0.0:
            s.append(f'{k:10d}{0.0:10.4g}{0.0:10.4g}{v0*phi(x):10.3e}')
    s += ['*BOUNDARY_SPC_NODE', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def axial(n):
    L = 100.0
    nodes = line_nodes(n, L)
    hist = [n//4 + 1, n//2 + 1, 3*n//4 + 1]
    s = head(f'Axial bar, {n} resultant beams, wave front', 0.02, 0.005, 0.0001, hist)
    s += beam_part()
    s += node_cards(nodes)
    s += beam_cards([(i + 1, i + 1, i + 2) for i in range(n)], n3=0)
    s += ['*DEFINE_CURVE', '         1', '                 0.0                 1.0',
          '                 1.0                 1.0',
          '*BOUNDARY_PRESCRIBED_MOTION_NODE',
          '$     NID       DOF       VAD      LCID        SF',
          '         1         1         0         1     0.001', '*END']
    return s


def rotation():
    L, n, om = 100.0, 4, 0.2                     # 0.2 rad/ms: 10 m/s at the ends
    nodes = [(i + 1, -0.5*L + L*i/n, 0.0, 0.0) for i in range(n + 1)]
    s = head('Free beam spinning about y as a rigid body', 20.0, 5.0, 0.05, [1, n + 1])
    s += beam_part()
    s += node_cards(nodes + [(n + 2, 0.0, 10.0, 0.0)])
    s += beam_cards([(i + 1, i + 1, i + 2) for i in range(n)], n3=n + 2)
    s += ['*INITIAL_VELOCITY_NODE']
    for k, x, y, z in nodes:
        # v = omega e_y x r = (omega z, 0, -omega x); the angular velocity VYR = omega
        s.append(f'{k:10d}{0.0:10.4g}{0.0:10.4g}{-om*x:10.4g}{0.0:10.4g}{om:10.4g}'
                 f'{0.0:10.4g}')
    s.append('*END')
    return s


def frame():
    """4x4 BT shells 40 x 40 at z = 20 on four beam legs from z = 0 to 20 (4 elements
    each), legs clamped at the ground, a point mass at the plate centre, a vertical kick."""
    nx, lx, hz, nl = 4, 40.0, 20.0, 4
    nodes, shells = [], []
    for j in range(nx + 1):
        for i in range(nx + 1):
            nodes.append((j*(nx + 1) + i + 1, lx*i/nx, lx*j/nx, hz))
    for j in range(nx):
        for i in range(nx):
            n1 = j*(nx + 1) + i + 1
            shells.append((j*nx + i + 1, n1, n1 + 1, n1 + nx + 2, n1 + nx + 1))
    corners = [1, nx + 1, (nx + 1)*nx + 1, (nx + 1)**2]
    nid = (nx + 1)**2
    beams, feet = [], []
    eid = 100
    for c in corners:
        xc, yc = nodes[c - 1][1], nodes[c - 1][2]
        prev = c
        for k in range(1, nl + 1):
            nid += 1
            nodes.append((nid, xc, yc, hz*(1.0 - k/nl)))
            eid += 1
            beams.append((eid, nid, prev))
            prev = nid
        feet.append(nid)
    centre = (nx + 1)*(nx//2) + nx//2 + 1
    s = head('Beam-and-shell frame: a plate on four beam legs', 10.0, 1.0, 0.01,
             [centre, corners[0]])
    s += ['*PART', 'plate', '         2         2         2         0         9',
          '*HOURGLASS', '         9         4       0.1',
          '*SECTION_SHELL', '$    SECID    ELFORM      SHRF       NIP',
          '         2         2  0.833333         3', '$       T1', '       1.0',
          '*MAT_ELASTIC', '$      MID        RO         E        PR',
          f'         2{RHO:10.3e}{E:10.1f}{0.3:10.3f}']
    s += beam_part()
    s += node_cards(nodes)
    s += ['*ELEMENT_SHELL']
    for e in shells:
        s.append(''.join(f'{k:8d}' for k in (e[0], 2) + tuple(e[1:])))
    # legs along z: the orientation by an _ORIENTATION vector (x)
    s += ['*ELEMENT_BEAM_ORIENTATION', '$    EID     PID      N1      N2      N3']
    for e, a, b in beams:
        s.append(''.join(f'{k:8d}' for k in (e, 1, a, b, 0)))
        s.append(f'{1.0:10.4f}{0.0:10.4f}{0.0:10.4f}')
    s += ['*ELEMENT_MASS', '$    EID     NID            MASS     PID',
          f'{500:8d}{centre:8d}{2.0e-4:16.6e}{0:8d}']
    s += ['*INITIAL_VELOCITY_NODE']
    for k, x, y, z in nodes[:(nx + 1)**2]:          # the plate moves down as a whole
        s.append(f'{k:10d}{0.0:10.4g}{0.0:10.4g}{-0.1:10.4g}')
    s += ['*SET_NODE_LIST', '         1', ''.join(f'{n:10d}' for n in feet)]
    s += ['*BOUNDARY_SPC_SET', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def elastica(n):
    """the cantilever of cantilever() at rest, a tip force P = E ISS/L**2 (P L**2/(E I) = 1)
    along z raised smoothly (1 - cos) over 100 ms (8 first periods) and held to 200 ms"""
    s = cantilever(n)
    i = s.index('*INITIAL_VELOCITY_NODE')
    j = [k for k, l in enumerate(s) if l.startswith('*BOUNDARY_SPC_NODE')][0]
    tr, p = 100.0, E*ISS/100.0**2
    curve = ['*DEFINE_CURVE', '         1']
    for k in range(41):
        t = tr*k/40
        curve.append(f'{t:20.8f}{0.5*(1.0 - math.cos(math.pi*t/tr)):20.10f}')
    curve.append(f'{1000.0:20.8f}{1.0:20.10f}')
    load = ['*LOAD_NODE_POINT', '$     NID       DOF      LCID        SF',
            f'{n + 1:10d}{3:10d}{1:10d}{p:10.4e}']
    s = s[:i] + curve + load + s[j:]
    s[2] = f'Cantilever beam, {n} resultant beams, tip force P L**2/(E I) = 1 (elastica)'
    k = s.index('*CONTROL_TERMINATION')
    s[k + 1] = f'{200.0:10.4f}'
    for key in ('*DATABASE_GLSTAT', '*DATABASE_NODOUT'):
        s[s.index(key) + 1] = f'{0.1:10.6f}'
    s[s.index('*DATABASE_BINARY_D3PLOT') + 1] = f'{20.0:10.6f}'
    return s


def tipforce(n):
    """elastica() with P = 0.01 E ISS/L**2: the small-deflection tip force"""
    s = elastica(n)
    i = s.index('*LOAD_NODE_POINT')
    p = 0.01*E*ISS/100.0**2
    s[i + 2] = f'{n + 1:10d}{3:10d}{1:10d}{p:10.4e}'
    s[2] = s[2].replace('P L**2/(E I) = 1 (elastica)', 'P L**2/(E I) = 0.01 (linear)')
    return s


def circle(n):
    """the cantilever of cantilever() at rest under an end moment about y (*LOAD_NODE_POINT
    DOF 6) M = 2 pi E ISS/L raised smoothly (1 - cos) over 100 ms and held to 200 ms: the
    beam rolls into a full circle of radius L/(2 pi) (tip back at the root); the history
    nodes are the tip and the middle node (diametrically opposite the root)"""
    s = elastica(n)
    i = s.index('*LOAD_NODE_POINT')
    m = 2.0*math.pi*E*ISS/100.0
    s[i + 2] = f'{n + 1:10d}{6:10d}{1:10d}{m:10.4e}'
    s[2] = f'Cantilever beam, {n} resultant beams, end moment 2 pi E I/L (rolled into a circle)'
    s[s.index('*DATABASE_HISTORY_NODE') + 1] = f'{n + 1:10d}{n//2 + 1:10d}'
    return s


def root_rotation(n):
    """the cantilever of cantilever() at rest, its root node turned about y by a prescribed
    angle (*BOUNDARY_PRESCRIBED_MOTION_NODE DOF 6, VAD 2) raised smoothly (1 - cos) to pi/2
    over 100 ms and held to 200 ms (its translations and the other rotations fixed): the
    beam turns as a rigid body, the tip to (L cos, 0, -L sin) of the angle"""
    s = elastica(n)
    i = s.index('*LOAD_NODE_POINT')
    s[i:i + 3] = ['*BOUNDARY_PRESCRIBED_MOTION_NODE',
                  '$     NID       DOF       VAD      LCID        SF',
                  f'{1:10d}{6:10d}{2:10d}{1:10d}{0.5*math.pi:10.7f}']
    j = s.index('*BOUNDARY_SPC_NODE')
    s[j + 1] = ('         1         0         1         1         1         1         0'
                '         1')
    s[2] = f'Cantilever beam, {n} resultant beams, root turned by a prescribed angle pi/2'
    return s


def torsion():
    """a torsion pendulum: 4 beams (100 mm) clamped at x = 0, an *ELEMENT_INERTIA of
    100 kg mm**2 (isotropic; with a mass) at the tip, started in the first mode's shape
    (VXR = 0.01 x/L rad/ms)"""
    n, L = 4, 100.0
    nodes = line_nodes(n, L)
    s = head('Torsion pendulum: a beam with an *ELEMENT_INERTIA at its tip', 120.0, 60.0,
             0.1, [n + 1])
    s += beam_part()
    s += node_cards(nodes + [(n + 2, 0.0, 10.0, 0.0)])
    s += beam_cards([(i + 1, i + 1, i + 2) for i in range(n)], n3=n + 2)
    s += ['*ELEMENT_INERTIA', '$    EID     NID    CSID', f'{900:8d}{n + 1:8d}{0:8d}',
          '$      IXX       IXY       IXZ       IYY       IYZ       IZZ      MASS',
          f'{100.0:10.4f}{0.0:10.4f}{0.0:10.4f}{100.0:10.4f}{0.0:10.4f}{100.0:10.4f}'
          f'{0.01:10.4f}']
    s += ['*INITIAL_VELOCITY_NODE']        # the first mode's shape: VXR linear in x
    for k, x, y, z in nodes[1:]:
        s.append(f'{k:10d}{0.0:10.4g}{0.0:10.4g}{0.0:10.4g}{0.01*x/L:10.4g}{0.0:10.4g}'
                 f'{0.0:10.4g}')
    s += ['*BOUNDARY_SPC_NODE', '         1         0         1         1         1'
          '         1         1         1', '*END']
    return s


def plastic(n, qr, cst, mat):
    """the cantilever at rest, Hughes-Liu, elastic-perfectly plastic, tip rotation 0.3 rad"""
    global HL
    HL = qr
    s = root_rotation(n)
    i = s.index('*BOUNDARY_PRESCRIBED_MOTION_NODE')
    s[i + 2] = f'{n + 1:10d}{6:10d}{2:10d}{1:10d}{0.3:10.7f}'
    j = s.index('*BOUNDARY_SPC_NODE')
    s[j + 1] = ('         1         0         1         1         1         1         1'
                '         1')
    k = s.index('*SECTION_BEAM')
    if cst == 1:
        s[k + 2] = f'{1:10d}         1  0.833333{qr:10.1f}         1'
        s[k + 4] = f'{2.0:10.4f}{2.0:10.4f}{1.0:10.4f}{1.0:10.4f}'
    m = s.index('*MAT_ELASTIC')
    if mat == 3:
        s[m:m + 3] = ['*MAT_PLASTIC_KINEMATIC',
                      '$      MID        RO         E        PR      SIGY      ETAN      BETA',
                      f'{1:10d}{RHO:10.3e}{E:10.1f}{0.3:10.3f}{0.05:10.4f}{0.0:10.4f}{1.0:10.4f}',
                      '$      SRC       SRP        FS        VP', '']
    else:
        s[m:m + 3] = ['*MAT_PIECEWISE_LINEAR_PLASTICITY',
                      '$      MID        RO         E        PR      SIGY      ETAN      FAIL'
                      '      TDEL',
                      f'{1:10d}{RHO:10.3e}{E:10.1f}{0.3:10.3f}{0.05:10.4f}{0.0:10.4f}',
                      '$        C         P      LCSS      LCSR        VP', '', '', '']
    s[2] = (f'Cantilever, {n} Hughes-Liu beams (QR {qr}, CST {cst}, *MAT_{mat:03d}), '
            'elastic-perfectly plastic, end rotation 0.3 rad')
    # monotonic: theta/0.3 = f(t)/f(150), f = t**2/(2 t0) up to t0 = 30 ms, then t - t0/2
    # (a smooth start, then a constant rate: no fibre unloads, the moment stays at Mp)
    c = s.index('*DEFINE_CURVE')
    e = s.index('*BOUNDARY_PRESCRIBED_MOTION_NODE')
    t0, tend = 30.0, 150.0
    def f(t):
        return t*t/(2.0*t0) if t < t0 else t - 0.5*t0
    curve = ['*DEFINE_CURVE', '         1']
    for k in range(31):
        t = tend*k/30
        curve.append(f'{t:20.8f}{f(t)/f(tend):20.10f}')
    curve.append(f'{1000.0:20.8f}{f(1000.0)/f(tend):20.10f}')
    s[c:e] = curve
    s[s.index('*CONTROL_TERMINATION') + 1] = f'{tend:10.4f}'
    s[s.index('*DATABASE_BINARY_D3PLOT') + 1] = f'{10.0:10.6f}'
    return s


def bench(n, kind):
    """the bench cantilevers: 1000 cycles (ENDCYC) of N elements"""
    global HL
    if kind == 'hl_plastic':
        # a free bar stretched at a uniform rate (v = rate (x - L/2)): every section point
        # yields together (SIGY/E = 2.38e-4 reached after about 100 cycles: the step is about
        # 0.0174/N ms), the release waves from the ends cover 5 % of the bar in 1000 cycles
        s = plastic(n, 5, 0, 3)
        c = s.index('*DEFINE_CURVE')
        e = s.index('*BOUNDARY_SPC_NODE')
        rate = 0.05/E*n/(100*0.0174)
        vel = ['*INITIAL_VELOCITY_NODE']
        for k in range(n + 1):
            x = 100.0*k/n
            vel.append(f'{k + 1:10d}{rate*(x - 50.0):10.4g}{0.0:10.4g}{0.0:10.4g}')
        s[c:e + 2] = vel
        tend = 1.0
    else:
        HL = 2 if kind == 'hl' else None
        s = cantilever(n)
        tend = 1000.0
    k = s.index('*CONTROL_TERMINATION')
    s[k + 1] = f'{tend:10.4f}      1000'
    for key in ('*DATABASE_GLSTAT', '*DATABASE_NODOUT', '*DATABASE_BINARY_D3PLOT'):
        s[s.index(key) + 1] = f'{1000.0:10.4f}'
    return s


def main(argv):
    global HL
    if argv[1] == '--hl':
        HL = int(argv[2])
        argv = argv[:1] + argv[3:]
    kind = argv[1]
    if kind == 'plastic':
        lines = plastic(int(argv[2]), int(argv[3]), int(argv[4]), int(argv[5]))
        out = argv[6:]
    elif kind == 'bench':
        lines, out = bench(int(argv[2]), argv[3]), argv[4:]
    elif kind == 'cantilever':
        lines, out = cantilever(int(argv[2])), argv[3:]
    elif kind == 'axial':
        lines, out = axial(int(argv[2])), argv[3:]
    elif kind == 'rotation':
        lines, out = rotation(), argv[2:]
    elif kind == 'frame':
        lines, out = frame(), argv[2:]
    elif kind == 'tipforce':
        lines, out = tipforce(int(argv[2])), argv[3:]
    elif kind == 'elastica':
        lines, out = elastica(int(argv[2])), argv[3:]
    elif kind == 'circle':
        lines, out = circle(int(argv[2])), argv[3:]
    elif kind == 'root_rotation':
        lines, out = root_rotation(int(argv[2])), argv[3:]
    elif kind == 'torsion':
        lines, out = torsion(), argv[2:]
    else:
        raise SystemExit(__doc__)
    text = '\n'.join(lines) + '\n'
    if out:
        with open(out[0], 'w') as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == '__main__':
    main(sys.argv)
