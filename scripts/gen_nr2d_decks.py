#!/usr/bin/python3
"""Decks of the 2D non-reflecting boundary cases (tests/regression/nr2d_*;
*BOUNDARY_NON_REFLECTING_2D, dx_nonreflecting).

  gen_nr2d_decks.py strip DECK LENGTH NR    plane-strain strip 2 mm wide, LENGTH mm long (1 mm
                                            elements), rollers on both sides (1D strain): a
                                            half-sine pressure pulse (0.1 GPa, 4 us) on y = 0;
                                            NR = 1: the far end y = LENGTH non-reflecting,
                                            NR = 0: free
  gen_nr2d_decks.py sphere DECK ROUT NR     axisymmetric (ELFORM ELF, default 15) quarter of a
                                            spherical shell, radii 4 .. ROUT mm (1 mm rings, 24
                                            sectors over 90 deg), roller on y = 0: a half-sine
                                            pressure pulse (0.1 GPa, 2 us) in the cavity; NR = 1:
                                            the outer sphere non-reflecting
  gen_nr2d_decks.py cyl DECK ROUT NR        the same quarter ring in plane strain (ELFORM 13),
                                            rollers on x = 0 and y = 0: a cylindrical wave (regression nr2d_cylinder)
  gen_nr2d_decks.py table DECK               axisymmetric (ELFORM 15) free block r 0..20, y 0..10
                                            mm (1 mm elements) under *DYNX_PRESSURE_TABLE on
                                            its top face from the file table.dat beside DECK
                                            (written too): p = 0.01 GPa f(r) g(t), f 1 to r = 5,
                                            0 at 10; g 0, 1, 1, 0 at t = 0, 10, 20, 30 us
  gen_nr2d_decks.py pulse DECK               plane-strain free block 20 x 10 mm under
                                            *DYNX_PRESSURE_PULSE on all its sides (PMAX 0.01 GPa,
                                            T0 12 us, FWHM 4 us, light along (0.6, -0.8))
  gen_nr2d_decks.py deposit DECK ELFORM      a disc particle (radius 1 mm; *MAT_NULL + *EOS_LINEAR_
                                            POLYNOMIAL, a gas-like gamma - 1 = 0.4) in an elastic
                                            block, *DYNX_ENERGY_DEPOSITION 1 J/ms for 5 us
  gen_nr2d_decks.py backside DIR [H [TEND]] decks/pressure_table: the back-surface scene's
                                            set-up (seed article 3) in elastic silica: an
                                            axisymmetric block radius 200 um, 300 um deep (5 um
                                            elements), non-reflecting side and bottom, the
                                            example table DIR/table.dat (synthetic, not LASNEX's:
                                            100 kbar to r = 50 um, 0 at 80 um, 3 ns FWHM) on top
  gen_nr2d_decks.py blocks DECK [FS [1]]    (1: rollers on y = 0, 10) two plane-strain steel blocks 10 x 10 mm (1 mm
                                            elements), A at 10 m/s along x onto B at rest,
                                            gap 0.05 mm, *CONTACT_2D_AUTOMATIC_SURFACE_TO_
                                            SURFACE (friction FS, default 0); every node a
                                            history node
  gen_nr2d_decks.py taylor2 DECK NR NZ [SF [ISTIFF]] two copies of the axisymmetric Taylor bar of
                                            gen_quad2d_decks.py taylor (ELFORM 15, Cu 227 m/s),
                                            mirror images about y = 0 (gap 0.01 mm) meeting
                                            head on through *CONTACT_2D_AUTOMATIC_SURFACE_TO_
                                            SURFACE: by symmetry the bar on a rigid frictionless
                                            wall. History nodes: bar A's top axis node and its
                                            contact face's nodes (quad2d_check.py taylor2). ISTIFF 1: the soft-constraint
                                            stiffness (SOFSCL = 0.1 SF)
  gen_nr2d_decks.py fold DECK               plane strain: a U of steel (base 9 x 2 mm, legs 4 x
                                            10 mm, slot 1 mm) whose legs close at +-60 m/s: a
                                            single-surface contact on the one part
  gen_nr2d_decks.py slide DECK FS           plane strain: a steel block 4 x 2 mm (0.5 mm
                                            elements) at 1 m/s along x on a base 12 x 2 mm
                                            (fixed bottom), pressed by 0.01 GPa on its top
                                            (*LOAD_SEGMENT, ramped over 0.5 us), friction FS
  gen_nr2d_decks.py tiedbar DECK MODE      plane strain: a steel bar 80 x 2 mm cut at x = 40,
                                            the half x < 40 at -10 m/s, the other at rest;
                                            MODE tied, oneway (*CONTACT_2D_AUTOMATIC_TIED,
                                            _TIED_ONE_WAY; TIETYP 1, oneway blank), contact
                                            (surface to surface), uncut
Each of the wave decks writes the history nodes on the diagonal (or the axis of the strip) every 0.2 mm
of radius; the same mesh with a larger ROUT or LENGTH has the same nodes and elements inside
(the reference run without reflection, nr2d_check.py). Units: mm, ms, kg, GPa (steel).
"""
import math
import sys

RHO, E, NU = 7.85e-6, 210.0, 0.3


def pulse(lcid, dur, p, n=16):
    s = ['*DEFINE_CURVE', f'{lcid:10d}']
    for k in range(n + 1):
        t = dur*k/n
        s.append(f'{t:20.10e}{p*math.sin(math.pi*k/n):20.10e}')
    s.append(f'{2.0*dur:20.10e}{0.0:20.10e}')
    return s


def deck(title, endtim, elform, xy, quads, load_edges, nr_nodes, spc, hist, dur):
    s = ['*KEYWORD', '*TITLE', title, '$ generated by scripts/gen_nr2d_decks.py',
         '*CONTROL_TERMINATION', f'{endtim:10.6f}', '*CONTROL_TIMESTEP',
         '$   DTINIT    TSSFAC', '       0.0    0.9000',
         '*DATABASE_GLSTAT', f'{endtim/100:10.3e}', '*DATABASE_NODOUT', f'{endtim/400:10.3e}',
         '*DATABASE_HISTORY_NODE']
    for k in range(0, len(hist), 8):
        s.append(''.join(f'{n:10d}' for n in hist[k:k + 8]))
    s += ['*PART', 'body', f'{1:10d}{1:10d}{1:10d}', '*SECTION_SHELL',
          '$    SECID    ELFORM', f'{1:10d}{elform:10d}', '$       T1', '       0.0',
          '*MAT_ELASTIC', '$      MID        RO         E        PR',
          f'{1:10d}{RHO:10.3e}{E:10.1f}{NU:10.3f}', '*NODE +']
    for i, (x, y) in enumerate(xy, 1):
        s.append(f'{i:20d}{x:20.13e}{y:20.13e}{0.0:20.13e}')
    s.append('*ELEMENT_SHELL')
    for i, q in enumerate(quads, 1):
        s.append(f'{i:8d}{1:8d}' + ''.join(f'{n:8d}' for n in q))
    s += pulse(1, dur, 0.1)
    s.append('*LOAD_SEGMENT')
    for a, b in load_edges:
        s.append(f'{1:10d}{1.0:10.3f}{0.0:10.3f}{a:10d}{b:10d}')
    for sid, (nodes, dofx, dofy) in enumerate(spc, 1):
        s += ['*SET_NODE_LIST', f'{sid:10d}']
        for k in range(0, len(nodes), 8):
            s.append(''.join(f'{n:10d}' for n in nodes[k:k + 8]))
        s += ['*BOUNDARY_SPC_SET', f'{sid:10d}{0:10d}{dofx:10d}{dofy:10d}{0:10d}']
    if nr_nodes:
        sid = len(spc) + 1
        s += ['*SET_NODE_LIST', f'{sid:10d}']
        for k in range(0, len(nr_nodes), 8):
            s.append(''.join(f'{n:10d}' for n in nr_nodes[k:k + 8]))
        s += ['*BOUNDARY_NON_REFLECTING_2D', '$     NSID        AD        AS',
              f'{sid:10d}{0:10d}{0:10d}']
    return s + ['*END']


def area(xy, q):
    x = [xy[n - 1][0] for n in q]
    y = [xy[n - 1][1] for n in q]
    return 0.5*((x[2] - x[0])*(y[3] - y[1]) - (x[3] - x[1])*(y[2] - y[0]))


def edges_on(xy, quads, test):
    """the element edges (in the element's counter-clockwise order) whose nodes pass test"""
    out = []
    for q in quads:
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            if test(*xy[a - 1]) and test(*xy[b - 1]):
                out.append((a, b))
    return out


def strip(path, length, nr):
    nx, ny = 2, int(round(length))
    xy = [(float(i), float(j)) for j in range(ny + 1) for i in range(nx + 1)]
    nid = lambda i, j: j*(nx + 1) + i + 1
    quads = [(nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
             for j in range(ny) for i in range(nx)]
    load = edges_on(xy, quads, lambda x, y: y == 0.0)
    sides = [nid(i, j) for j in range(ny + 1) for i in (0, nx)]
    top = [nid(i, ny) for i in range(nx + 1)] if nr else []
    hist = [nid(1, j) for j in range(5, ny + 1, 5) if j <= 100]
    write(path, deck(f'Plane-strain strip {length:g} mm, non-reflecting end: {nr}', 0.036, 13,
                     xy, quads, load, top, [(sides, 1, 0)], hist, 0.004))


def ring(path, rout, nr, elform):
    rin, nt = 4.0, 24
    nrad = int(round(rout - rin))
    xy = []
    for i in range(nrad + 1):
        r = rin + i
        for j in range(nt + 1):
            phi = 0.5*math.pi*j/nt          # from the y axis (phi = 0) to the x axis
            x, y = r*math.sin(phi), r*math.cos(phi)
            xy.append((0.0 if j == 0 else x, 0.0 if j == nt else y))
    nid = lambda i, j: i*(nt + 1) + j + 1
    quads = []
    for i in range(nrad):
        for j in range(nt):
            q = (nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
            if area(xy, q) < 0.0:
                q = (q[0], q[3], q[2], q[1])
            quads.append(q)
    onr = lambda r0: (lambda x, y: abs(math.hypot(x, y) - r0) < 1e-9)
    load = edges_on(xy, quads, onr(rin))
    outer = [nid(nrad, j) for j in range(nt + 1)] if nr else []
    base = [nid(i, nt) for i in range(nrad + 1)]           # y = 0: v_y = 0
    spc = [(base, 0, 1)]
    if elform == 13:
        spc.append(([nid(i, 0) for i in range(nrad + 1)], 1, 0))   # x = 0: v_x = 0
    hist = [nid(i, nt//2) for i in range(2, min(nrad, 38) + 1, 4)]
    kind = 'axisymmetric sphere' if elform != 13 else 'plane-strain cylinder'
    write(path, deck(f'{kind} 4..{rout:g} mm, non-reflecting outside: {nr}', 0.0135, elform,
                     xy, quads, load, outer, spc, hist, 0.002))


def block(nx, ny, dx, dy):
    xy = [(i*dx, j*dy) for j in range(ny + 1) for i in range(nx + 1)]
    nid = lambda i, j: j*(nx + 1) + i + 1
    quads = [(nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
             for j in range(ny) for i in range(nx)]
    return xy, quads, nid


def mesh_cards(xy, quads, pids=None):
    s = ['*NODE +']
    for i, (x, y) in enumerate(xy, 1):
        s.append(f'{i:20d}{x:20.13e}{y:20.13e}{0.0:20.13e}')
    s.append('*ELEMENT_SHELL')
    for i, q in enumerate(quads, 1):
        pid = pids[i - 1] if pids else 1
        s.append(f'{i:8d}{pid:8d}' + ''.join(f'{n:8d}' for n in q))
    return s


def node_set(sid, nodes):
    s = ['*SET_NODE_LIST', f'{sid:10d}']
    for k in range(0, len(nodes), 8):
        s.append(''.join(f'{n:10d}' for n in nodes[k:k + 8]))
    return s


def head2(title, endtim, elform, parts):
    s = ['*KEYWORD', '*TITLE', title, '$ generated by scripts/gen_nr2d_decks.py',
         '*CONTROL_TERMINATION', f'{endtim:10.6f}', '*DATABASE_GLSTAT', f'{endtim/50:10.3e}',
         '*SECTION_SHELL', '$    SECID    ELFORM', f'{1:10d}{elform:10d}', '$       T1',
         '       0.0', '*MAT_ELASTIC', '$      MID        RO         E        PR',
         f'{1:10d}{RHO:10.3e}{E:10.1f}{NU:10.3f}']
    for pid, mid, eos, name in parts:
        s += ['*PART', name, f'{pid:10d}{1:10d}{mid:10d}{eos:10d}']
    return s


def table(path):
    import os
    xy, quads, nid = block(20, 10, 1.0, 1.0)
    top = [nid(i, 10) for i in range(21)]
    s = head2('Axisymmetric block under a pressure table p(r, t)', 0.035, 15,
              [(1, 1, 0, 'block')])
    s += mesh_cards(xy, quads) + node_set(1, top)
    s += ['*DYNX_PRESSURE_TABLE', '$     NSID        SF', f'{1:10d}{1.0:10.3f}',
          '$ FILE', 'table.dat', '*END']
    write(path, s)
    tab = ['# *DYNX_PRESSURE_TABLE data (LASNEX-style): NR NT, the NR radii, the NT times,',
           '# then one row of NR pressures per time (free format; "#" starts a comment).',
           '# p = 0.01 GPa f(r) g(t): f = 1, 1, 0 at r = 0, 5, 10 mm; g = 0, 1, 1, 0 at',
           '# t = 0, 0.01, 0.02, 0.03 ms (mm, ms, kg, GPa)',
           '3 4', '0.0 5.0 10.0', '0.0 0.01 0.02 0.03',
           '0.0 0.0 0.0', '0.01 0.01 0.0', '0.01 0.01 0.0', '0.0 0.0 0.0']
    write(os.path.join(os.path.dirname(path) or '.', 'table.dat'), tab)


def pulse_deck(path):
    xy, quads, nid = block(20, 10, 1.0, 1.0)
    edge = [nid(i, j) for j in range(11) for i in range(21) if i in (0, 20) or j in (0, 10)]
    s = head2('Plane-strain block under a Gaussian cos^2 pulse', 0.03, 13, [(1, 1, 0, 'block')])
    s += mesh_cards(xy, quads) + node_set(1, edge)
    s += ['*DYNX_PRESSURE_PULSE', '$     NSID      PMAX        T0      FWHM        DX        DY',
          f'{1:10d}{0.01:10.4f}{0.012:10.4f}{0.004:10.4f}{0.6:10.3f}{-0.8:10.3f}', '*END']
    write(path, s)


def deposit(path, elform):
    n, h = 8, 0.25                      # 8 x 8 elements of 0.25 mm: the particle 1 x 1 mm
    xy, quads, nid = block(2*n, 2*n, h, h)
    pids = [2 if max(xy[q[0] - 1]) < n*h - 1e-9 else 1 for q in quads]
    s = head2('Energy deposited into a particle', 0.01, elform,
              [(1, 1, 0, 'block'), (2, 2, 1, 'particle')])
    s += ['*MAT_NULL', '$      MID        RO        PC        MU', f'{2:10d}{4.0e-6:10.3e}'
          f'{-1.0e3:10.1f}{0.0:10.1f}', '*EOS_LINEAR_POLYNOMIAL',
          '$    EOSID        C0        C1        C2        C3        C4        C5        C6',
          f'{1:10d}{0.0:10.1f}{50.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.4:10.2f}{0.4:10.2f}{0.0:10.1f}',
          '$       E0        V0', f'{0.0:10.1f}{1.0:10.1f}']
    s += mesh_cards(xy, quads, pids)
    s += ['*DYNX_ENERGY_DEPOSITION', '$      PID      RATE    TSTART      TEND',
          f'{2:10d}{1.0:10.3f}{0.0:10.4f}{0.005:10.4f}', '*END']
    write(path, s)


def backside(d, h=0.005, tend=6.0e-5):
    import os
    # h: element size (mm), 5 um in the scene; other values for the mesh study
    # (scripts/studies_order_seed.py); tend: end time (ms), 60 ns in the scene (the
    # regression case nr2d_corner runs 150 ns: the wave has left through the corner)
    nx, ny = round(0.2/h), round(0.3/h)
    xy, quads, nid = block(nx, ny, h, h)
    top = [nid(i, ny) for i in range(nx + 1)]
    nrb = [nid(nx, j) for j in range(ny + 1)] + [nid(i, 0) for i in range(nx)]
    s = ['*KEYWORD', '*TITLE', 'Back-surface pressure table on silica (elastic), non-reflecting',
         '$ generated by scripts/gen_nr2d_decks.py backside', '*CONTROL_TERMINATION',
         f'{tend:10.3e}', '*DATABASE_GLSTAT', f'{1.0e-6:10.3e}', '*DATABASE_BINARY_D3PLOT',
         f'{1.0e-5:10.3e}', '*SECTION_SHELL', '$    SECID    ELFORM', f'{1:10d}{15:10d}',
         '$       T1', '       0.0', '*MAT_ELASTIC', '$      MID        RO         E        PR',
         f'{1:10d}{2.2e-6:10.3e}{72.0:10.1f}{0.17:10.3f}', '*PART', 'silica',
         f'{1:10d}{1:10d}{1:10d}']
    s += mesh_cards(xy, quads) + node_set(1, top) + node_set(2, nrb)
    s += ['*DYNX_PRESSURE_TABLE', '$     NSID        SF', f'{1:10d}{1.0:10.3f}', '$ FILE',
          'table.dat', '*BOUNDARY_NON_REFLECTING_2D', '$     NSID        AD        AS',
          f'{2:10d}{0:10d}{0:10d}', '*END']
    write(os.path.join(d, 'deck.k'), s)
    rr = [0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08]
    f = [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0/3.0, 1.0/3.0, 0.0]
    tt = [k*1.0e-6 for k in range(0, 13)]       # 0 .. 12 ns
    g = [math.exp(-4.0*math.log(2.0)*((t - 6.0e-6)/3.0e-6)**2) for t in tt]
    tab = ['# *DYNX_PRESSURE_TABLE data file, LASNEX-style (dx_read_twod):',
           '#   NR NT, then the NR radii (increasing, >= 0), the NT times (increasing), then NT',
           '#   rows of NR pressures, one row per time; free format, "#" starts a comment.',
           '# Units of the deck: mm, ms, GPa. Synthetic (not LASNEX output): 10 GPa = 100 kbar',
           '# flat to r = 50 um, linear to 0 at 80 um; 3 ns FWHM Gaussian in time, peak at 6 ns.',
           f'{len(rr)} {len(tt)}', '# radii (mm)', ' '.join(f'{r:.3f}' for r in rr),
           '# times (ms)', ' '.join(f'{t:.1e}' for t in tt), '# pressures (GPa), one row per time']
    tab += [' '.join(f'{10.0*gg*ff:.6e}' for ff in f) for gg in g]
    write(os.path.join(d, 'table.dat'), tab)


def blocks(path, fs, rollers=False):
    n, h, gap = 10, 1.0, 0.05
    xy, quads, nid = block(n, n, h, h)
    nb = len(xy)
    xy += [(x + n*h + gap, y) for x, y in xy]
    quads += [tuple(q + nb for q in qq) for qq in quads]
    pids = [1]*(n*n) + [2]*(n*n)
    s = head2('Two plane-strain blocks colliding (2D contact)', 0.012, 13,
              [(1, 1, 0, 'A'), (2, 1, 0, 'B')])
    s[6:6] = ['*DATABASE_NODOUT', f'{0.012/60:10.3e}']
    s += mesh_cards(xy, quads, pids)
    s += ['*DATABASE_HISTORY_NODE_SET', f'{3:10d}'] + node_set(3, list(range(1, 2*nb + 1)))
    if rollers:                       # v_y = 0 on y = 0 and y = 10: one-dimensional strain
        s += node_set(4, [i + 1 for i, (x, y) in enumerate(xy) if y in (0.0, n*h)])
        s += ['*BOUNDARY_SPC_SET', f'{4:10d}{0:10d}{0:10d}{1:10d}{0:10d}']
    s += ['*SET_PART_LIST', f'{1:10d}', f'{1:10d}', '*SET_PART_LIST', f'{2:10d}', f'{2:10d}',
          '*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE',
          '$     SIDS      SIDM     SFACT      FREQ        FS        FD        DC     MEMBS',
          f'{1:10d}{2:10d}{1.0:10.3f}{1:10d}{fs:10.3f}{0.0:10.3f}{0.0:10.3f}{0.0:10.3f}',
          '*INITIAL_VELOCITY_GENERATION', f'{1:10d}{2:10d}{0.0:10.1f}{10.0:10.3f}{0.0:10.3f}'
          f'{0.0:10.3f}', f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}',
          '*END']
    write(path, s)


def taylor2(path, nr, nz, sfact=1.0, istiff=0):
    l0, r0, v0, tend, gap = 32.4, 3.2, 227.0, 0.08, 0.01
    xy, quads, nid = block(nr, nz, r0/nr, l0/nz)
    nb = len(xy)
    xa = [(x, y + 0.5*gap) for x, y in xy]
    xb = [(x, -(y + 0.5*gap)) for x, y in xy]
    qa = quads
    qb = [(q[0] + nb, q[3] + nb, q[2] + nb, q[1] + nb) for q in quads]   # mirrored: reversed
    s = ['*KEYWORD', '*TITLE', f'Two Taylor bars head on (2D contact), ELFORM 15, {nr}x{nz}',
         '$ generated by scripts/gen_nr2d_decks.py taylor2', '*CONTROL_TERMINATION',
         f'{tend:10.5f}', '*CONTROL_TIMESTEP', '       0.0       0.9', '*CONTROL_HOURGLASS',
         '         1     0.100', '*CONTROL_BULK_VISCOSITY', '       1.5      0.06',
         '*DATABASE_GLSTAT', '  0.001000', '*DATABASE_NODOUT', '  0.000200',
         '*DATABASE_HISTORY_NODE', f'{nid(0, nz):10d}{nid(nr, 0):10d}']
    bottom = [nid(i, 0) for i in range(nr)]      # bar A's contact face (penetration)
    for k in range(0, nr, 8):
        s.append(''.join(f'{n:10d}' for n in bottom[k:k + 8]))
    s += [
         '*PART', 'bar A', '         1         1         1', '*PART', 'bar B',
         '         2         1         1', '*SECTION_SHELL', f'{1:10d}{15:10d}', '       0.0',
         '*MAT_PLASTIC_KINEMATIC',
         '         1   8.93E-6     117.0      0.35       0.4  0.099915       1.0',
         '       0.0       0.0       0.0       0.0']
    s += mesh_cards(xa + xb, qa + qb, [1]*len(qa) + [2]*len(qb))
    s += ['*SET_PART_LIST', f'{1:10d}', f'{1:10d}', '*SET_PART_LIST', f'{2:10d}', f'{2:10d}',
          '*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE', f'{1:10d}{2:10d}{sfact:10.3f}']
    if istiff:                                   # card 3: VC VDC IPF SLIDE ISTIFF
        s += ['$   TBIRTH', f'{0.0:10.1f}', '$       VC       VDC       IPF     SLIDE    ISTIFF',
              f'{0.0:10.1f}{0.0:10.1f}{0:10d}{0:10d}{istiff:10d}']
    s += ['*INITIAL_VELOCITY_GENERATION', f'{1:10d}{2:10d}{0.0:10.1f}{0.0:10.3f}{-v0:10.3f}'
          f'{0.0:10.3f}', f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}',
          '*INITIAL_VELOCITY_GENERATION', f'{2:10d}{2:10d}{0.0:10.1f}{0.0:10.3f}{v0:10.3f}'
          f'{0.0:10.3f}', f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}',
          '*END']
    write(path, s)


def fold(path, v0=60.0):
    """One plane-strain part shaped as a U (a base 9 x 2 mm, two legs 4 x 10 mm either side
    of a 1 mm slot; 1 mm elements), the legs at +-v0 (m/s) towards each other, one
    *CONTACT_2D_AUTOMATIC_SINGLE_SURFACE on the part: the slot's faces meet (self-contact).
    History nodes: the slot's faces, x = 4 and x = 5, y = 2 .. 12."""
    nx, ny = 9, 12
    xy, quads, nid = block(nx, ny, 1.0, 1.0)
    quads = [q for q in quads if not (xy[q[0] - 1][0] == 4.0 and xy[q[0] - 1][1] >= 2.0)]
    s = head2('A U folding onto itself (2D single-surface contact)', 0.06, 13,
              [(1, 1, 0, 'U')])
    s[6:6] = ['*DATABASE_NODOUT', f'{0.0002:10.3e}']
    s += mesh_cards(xy, quads)
    face = [nid(4, j) for j in range(2, ny + 1)] + [nid(5, j) for j in range(2, ny + 1)]
    s += ['*DATABASE_HISTORY_NODE_SET', f'{1:10d}'] + node_set(1, face)
    s += ['*SET_PART_LIST', f'{1:10d}', f'{1:10d}', '*CONTACT_2D_AUTOMATIC_SINGLE_SURFACE',
          '$     SIDS      SIDM     SFACT', f'{1:10d}{0:10d}{1.0:10.3f}',
          '*INITIAL_VELOCITY_NODE']
    for j in range(3, ny + 1):
        for i in range(nx + 1):
            vx = v0 if i <= 4 else -v0
            s.append(f'{nid(i, j):10d}{vx:10.3f}{0.0:10.3f}{0.0:10.3f}')
    s.append('*END')
    write(path, s)


def slide(path, fs):
    h = 0.5
    xb, qb, nidb = block(24, 4, h, h)                          # base 12 x 2
    xk, qk, nidk = block(8, 4, h, h)                           # block 4 x 2, on top
    nb = len(xb)
    xy = xb + [(x + 2.0, y + 2.0) for x, y in xk]
    quads = qb + [tuple(q + nb for q in qq) for qq in qk]
    pids = [1]*len(qb) + [2]*len(qk)
    s = head2('Block sliding on a base with Coulomb friction (2D contact)', 0.004, 13,
              [(1, 1, 0, 'base'), (2, 1, 0, 'block')])
    s[6:6] = ['*DATABASE_NODOUT', f'{0.004/80:10.3e}']
    s += mesh_cards(xy, quads, pids)
    s += ['*DATABASE_HISTORY_NODE_SET', f'{3:10d}'] + node_set(3, list(range(nb + 1,
                                                                        len(xy) + 1)))
    s += node_set(4, [nidb(i, 0) for i in range(25)])
    s += ['*BOUNDARY_SPC_SET', f'{4:10d}{0:10d}{1:10d}{1:10d}{0:10d}']
    s += ['*DEFINE_CURVE', f'{1:10d}', f'{0.0:20.10e}{0.0:20.10e}', f'{0.0005:20.10e}{1.0:20.10e}',
          f'{1.0:20.10e}{1.0:20.10e}', '*LOAD_SEGMENT']
    for i in range(8):                                         # top edges, right to left
        s.append(f'{1:10d}{0.01:10.4f}{0.0:10.3f}{nidk(i + 1, 4) + nb:10d}{nidk(i, 4) + nb:10d}')
    s += ['*SET_PART_LIST', f'{1:10d}', f'{2:10d}', '*SET_PART_LIST', f'{2:10d}', f'{1:10d}',
          '*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE',
          f'{1:10d}{2:10d}{1.0:10.3f}{1:10d}{fs:10.3f}',
          '*INITIAL_VELOCITY_GENERATION', f'{2:10d}{2:10d}{0.0:10.1f}{1.0:10.3f}{0.0:10.3f}'
          f'{0.0:10.3f}', f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}',
          '*END']
    write(path, s)


def tiedbar(path, mode, v0=10.0, n=40):
    """A plane-strain steel bar 2n x 2 mm (1 mm elements, rollers on y = 0 and 2: 1D strain)
    cut at x = n into part A (x < n, nodes 1..) and part B (x > n, nodes 1001..; its own
    nodes at the cut), A at -v0 along x (away from B), B at rest. mode: 'tied'
    (*CONTACT_2D_AUTOMATIC_TIED), 'oneway' (_TIED_ONE_WAY), 'contact' (_SURFACE_TO_SURFACE:
    the cut opens), 'uncut' (B's elements on A's cut nodes: one bar; the cut nodes at -v0/2,
    the momentum of the two half masses). History nodes on y = 0: x = n - 10, n (A's, B's),
    n + 10, n + 20, n + 30 (labels alike in every mode); nodout every 0.1 us."""
    xa, qa, nid = block(n, 2, 1.0, 1.0)
    xb = [(x + n, y) for x, y in xa]
    lab = list(range(1, len(xa) + 1)) + [1000 + i for i in range(1, len(xb) + 1)]
    qb = [tuple(1000 + k for k in q) for q in qa]
    xy = xa + xb
    vx = {k: -v0 for k in range(1, len(xa) + 1)}
    vx.update({1000 + k: 0.0 for k in range(1, len(xb) + 1)})
    if mode == 'uncut':                      # B's cut nodes are A's
        cut = {1000 + nid(0, j): nid(n, j) for j in range(3)}
        qb = [tuple(cut.get(k, k) for k in q) for q in qb]
        keep = [i for i, k in enumerate(lab) if k not in cut]
        xy, lab = [xy[i] for i in keep], [lab[i] for i in keep]
        for j in range(3):
            vx[nid(n, j)] = -0.5*v0
            del vx[1000 + nid(0, j)]
    kw = {'tied': '*CONTACT_2D_AUTOMATIC_TIED', 'oneway': '*CONTACT_2D_AUTOMATIC_TIED_ONE_WAY',
          'contact': '*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE'}
    s = head2(f'A bar cut in two, {mode} (2D tied contact)', 0.012, 13,
              [(1, 1, 0, 'A'), (2, 1, 0, 'B')])
    s[6:6] = ['*DATABASE_NODOUT', f'{1e-4:10.3e}']
    s += ['*NODE +'] + [f'{k:20d}{x:20.13e}{y:20.13e}{0.0:20.13e}' for k, (x, y) in zip(lab, xy)]
    s += ['*ELEMENT_SHELL']
    for i, q in enumerate(qa + qb, 1):
        s.append(f'{i:8d}{1 if i <= len(qa) else 2:8d}' + ''.join(f'{k:8d}' for k in q))
    hist = [nid(n - 10, 0), nid(n, 0), 1000 + nid(0, 0), 1000 + nid(10, 0), 1000 + nid(20, 0),
            1000 + nid(30, 0)]
    if mode == 'uncut':
        hist.remove(1000 + nid(0, 0))
    s += ['*DATABASE_HISTORY_NODE_SET', f'{3:10d}'] + node_set(3, hist)
    s += node_set(4, [k for k, (x, y) in zip(lab, xy) if y in (0.0, 2.0)])
    s += ['*BOUNDARY_SPC_SET', f'{4:10d}{0:10d}{0:10d}{1:10d}{0:10d}']
    s += ['*SET_PART_LIST', f'{1:10d}', f'{1:10d}', '*SET_PART_LIST', f'{2:10d}', f'{2:10d}']
    if mode in kw:
        s += [kw[mode], '$    SURFA     SURFB     SFACT', f'{1:10d}{2:10d}{1.0:10.3f}']
    if mode in ('tied', 'oneway'):
        s += ['$   TBIRTH', f'{0.0:10.1f}',
              '$       VC       VDC       IPF     SLIDE    ISTIFF   TIEDGAP    IGAPCL    TIETYP',
              f'{0.0:10.1f}{0.0:10.1f}{0:10d}{0:10d}{0:10d}{0.0:10.1f}{0:10d}'
              + (f'{1:10d}' if mode == 'tied' else '')]   # (oneway: TIETYP blank)
    s += ['*INITIAL_VELOCITY_NODE'] + [f'{k:10d}{v:10.3f}{0.0:10.3f}{0.0:10.3f}'
                                       for k, v in sorted(vx.items())]
    s += ['*END']
    write(path, s)


def write(path, lines):
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def main(argv):
    what, path = argv[0], argv[1]
    if what == 'strip':
        strip(path, float(argv[2]), int(argv[3]))
    elif what == 'sphere':
        ring(path, float(argv[2]), int(argv[3]), int(argv[4]) if len(argv) > 4 else 15)
    elif what == 'table':
        table(path)
    elif what == 'pulse':
        pulse_deck(path)
    elif what == 'deposit':
        deposit(path, int(argv[2]))
    elif what == 'backside':
        backside(path, *(float(x) for x in argv[2:4]))
    elif what == 'blocks':
        blocks(path, float(argv[2]) if len(argv) > 2 else 0.0, len(argv) > 3)
    elif what == 'taylor2':
        taylor2(path, int(argv[2]), int(argv[3]), float(argv[4]) if len(argv) > 4 else 1.0,
                int(argv[5]) if len(argv) > 5 else 0)
    elif what == 'slide':
        slide(path, float(argv[2]))
    elif what == 'fold':
        fold(path)
    elif what == 'tiedbar':
        tiedbar(path, argv[2])
    elif what == 'cyl':
        ring(path, float(argv[2]), int(argv[3]), 13)
    else:
        raise SystemExit(__doc__)


if __name__ == '__main__':
    main(sys.argv[1:])
