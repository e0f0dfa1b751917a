#!/usr/bin/python3
"""Checks of the shell regression cases (tests/regression/shell_*/check).

  shell_check.py period OUT L T E RHO TOL [OUT2 H2]
      first period of the cantilever tip (zero crossings of z in OUT/nodout, first history
      node) against Euler-Bernoulli beam theory T1 = 2 pi / (1.8751**2 sqrt(E T**2 /
      (12 RHO L**4))) (PR = 0); relative error <= TOL. With OUT2 (the same deck on a mesh
      H2 times coarser): prints the observed order log(e2/e1)/log(H2) and requires it in
      [1.5, 2.5] (the element is second-order accurate in the frequency).
  shell_check.py patch OUT DECK TOL_V TOL_S TOL_A
      membrane patch test: the free (history) nodes keep the initial velocity of the deck
      (*INITIAL_VELOCITY_NODE +) to TOL_V relative; the elements' global stresses of the
      last plot state agree with each other to TOL_S relative (round-off), and with the
      small-strain plane-stress Hooke law of the mean strain to TOL_A relative (the strain's
      own size: the finite-deformation terms; TOL_A < 0: no such comparison).
  shell_check.py rotation OUT TOL
      rigid rotation: internal + hourglass energy over the initial kinetic energy <= TOL
      at every glstat line.
  shell_check.py energy OUT TOL [T0]
      |energy ratio - 1| <= TOL at every glstat line (from t = T0 when given).
  shell_check.py yield OUT SIGY TOL
      every element's von Mises stress in the last plot state equals SIGY within TOL
      relative (a perfectly plastic membrane state).
  shell_check.py contact OUT BALL PLATE GMIN ETOL
      a body dropped on a free shell plate (gen_shell_deck.py ball): the z momentum (glstat)
      stays its initial value to glstat's 11 digits (the contact forces act in equal and
      opposite pairs: a conservation law), |energy ratio - 1| <= ETOL, the distance along z
      from history node BALL (the body's lowest/highest node) to PLATE (the plate centre)
      never below GMIN (the contact surface half a thickness off the mid-surface), and BALL
      ends moving against its initial direction (it rebounds).
  shell_check.py pressure OUT REF T1 TOL1 TOL2 PMIN
      the clamped plate under a ramped pressure (gen_shell_deck.py pressure): the centre's
      deflection (first history node) at the first nodout line at or after T1 against the
      small-deflection clamped-plate value 0.00126 q a**4 / D (Timoshenko & Woinowsky-
      Krieger, table 35; a = 100, t = 1, E 210, PR 0.3, RHO 7.85e-6, q = 3e-4 t/20) times
      the ramp's dynamic factor 1 - sin(w t)/(w t) of the first mode (w = 35.99/a**2
      sqrt(D/(RHO t)), Leissa 1969) within TOL1 relative; the final centre deflection against run REF's (the same plate of another
      formulation) within TOL2 relative; the largest effective plastic strain of the last
      plot state at least PMIN (the plate went plastic).
  shell_check.py mirror OUT1 OUT2 NODE TOL
      two runs mirrored in z (the plate struck from either side): NODE's z velocity in OUT2
      is minus that in OUT1 at every nodout line, within TOL relative to the largest.
  shell_check.py bent OUT M EI L T0 TOL_K TOL_KE
      a cantilever held bent by an end moment M (gen_shell_deck.py circle): over t >= T0
      the mean internal energy U (glstat) gives the mean curvature sqrt(2 U/(EI L)) (U =
      EI k**2 L/2 for a uniform curvature k): within TOL_K relative of M/EI; the hourglass
      energy below TOL_KE U; the largest kinetic energy over t >= T0 below TOL_KE of the
      external work (quasi-static; the largest KE/W over the whole run is printed).
"""
import math
import sys

from ascii_out import read_table, nodout_series, h5_dataset, h5_last_state


def nodout(out):
    """{node: [(t, disp(3), vel(3), coor(3))]}"""
    return nodout_series(out, 'disp', 'vel', 'coor')


def first_period(out):
    d = nodout(out)
    node = sorted(d)[0]
    rows = d[node]
    zc = []
    for (t0, u0, _, _), (t1, u1, _, _) in zip(rows, rows[1:]):
        a, b = u0[2], u1[2]
        if (a > 0.0 >= b) or (a < 0.0 <= b):
            zc.append(t0 + (t1 - t0)*a/(a - b))
    if len(zc) < 2:
        raise SystemExit(f'{out}: fewer than two zero crossings of the tip displacement')
    return 2.0*(zc[-1] - zc[0])/(len(zc) - 1)


def period(argv):
    out, length, thick, e, rho, tol = argv[0], *map(float, argv[1:6])
    w1 = 1.8751040687**2*math.sqrt(e*thick**2/(12.0*rho*length**4))
    tref = 2.0*math.pi/w1
    t1 = first_period(out)
    err = abs(t1 - tref)/tref
    print(f'period {t1:.6f} beam theory {tref:.6f} relative error {err:.3e} (tol {tol:.1e})')
    ok = err <= tol
    if len(argv) > 6:
        t2 = first_period(argv[6])
        e2 = abs(t2 - tref)/tref
        order = math.log(e2/err)/math.log(float(argv[7]))
        print(f'coarse mesh: period {t2:.6f} error {e2:.3e}; observed order {order:.2f}')
        ok = ok and 1.5 <= order <= 2.5
    return ok


def deck_initial_velocity(deck):
    vel, on = {}, False
    for line in open(deck):
        if line.startswith('*'):
            on = line.strip().startswith('*INITIAL_VELOCITY_NODE')
            continue
        if on and line.strip() and not line.startswith('$'):
            n = int(line[0:20])
            vel[n] = [float(line[20 + 20*k:40 + 20*k]) for k in range(3)]
    return vel


def deck_material(deck):
    lines = [l for l in open(deck) if not l.startswith('$')]
    k = [i for i, l in enumerate(lines) if l.startswith('*MAT_ELASTIC')][0]
    c = lines[k + 1]
    return float(c[20:30]), float(c[30:40])


def patch(argv):
    out, deck, tol_v, tol_s, tol_a = argv[0], argv[1], *map(float, argv[2:5])
    v0 = deck_initial_velocity(deck)
    ok = True
    worst = 0.0
    for n, rows in nodout(out).items():
        t, u, v, x = rows[-1]
        scale = max(abs(c) for c in v0[n])
        dv = max(abs(v[k] - v0[n][k]) for k in range(3))/scale
        worst = max(worst, dv)
    print(f'free nodes: largest velocity change {worst:.3e} of the velocity (tol {tol_v:.1e})')
    ok = ok and worst <= tol_v
    if tol_s < 0.0:          # bending: the plotted (mid-surface) stress is not the test
        return ok
    h5 = out + '/d3plot.h5'
    st = h5_last_state(h5)
    s = h5_dataset(h5, f'/states/{st}/stress')
    ne = len(s)//6
    sig = [s[6*i:6*i + 6] for i in range(ne)]
    smax = max(abs(c) for r in sig for c in r)
    spread = max(abs(sig[i][k] - sig[0][k]) for i in range(ne) for k in range(6))/smax
    print(f'{ne} elements: global stresses agree to {spread:.3e} of the largest (tol {tol_s:.1e})')
    ok = ok and spread <= tol_s
    if tol_a < 0.0:          # not elastic: no Hooke comparison
        return ok
    # small strain: the mean displacement gradient from the free nodes' displacements
    # (u = t G x0 exactly for a uniform velocity gradient G: x0 = x - u)
    d = nodout(out)
    t = d[sorted(d)[0]][-1][0]
    g = [[0.0]*3 for _ in range(3)]
    n0 = sorted(v0)[0]
    # G from the deck's velocities: v = G x0 with node 1 at the origin (least squares)
    nodes = {}
    on = False
    for line in open(deck):
        if line.startswith('*'):
            on = line.strip().startswith('*NODE')
            continue
        if on and line.strip() and not line.startswith('$'):
            nodes[int(line[0:20])] = [float(line[20 + 20*k:40 + 20*k]) for k in range(3)]
    ids = sorted(v0)
    # solve for G row by row with the normal equations (3x3)
    a = [[sum(nodes[i][p]*nodes[i][q] for i in ids) for q in range(3)] for p in range(3)]
    for r in range(3):
        b = [sum(nodes[i][p]*v0[i][r] for i in ids) for p in range(3)]
        g[r] = solve3(a, b)
    eps = [[0.5*t*(g[i][j] + g[j][i]) for j in range(3)] for i in range(3)]
    e, pr = deck_material(deck)
    # plane stress in the plate's plane: sigma = E/(1+nu) (eps + nu/(1-nu) tr(eps) P)
    # with P the in-plane projector (eps has no normal component: eps_nn = 0 here, the
    # plane-stress thickness strain is not in the nodal motion)
    nrm = unit_normal(nodes)
    tr = sum(eps[i][i] for i in range(3))
    pp = [[(1.0 if i == j else 0.0) - nrm[i]*nrm[j] for j in range(3)] for i in range(3)]
    ref = [[e/(1.0 + pr)*(eps[i][j] + pr/(1.0 - pr)*tr*pp[i][j]) for j in range(3)]
           for i in range(3)]
    rv = [ref[0][0], ref[1][1], ref[2][2], ref[0][1], ref[1][2], ref[2][0]]
    dev = max(abs(sig[0][k] - rv[k]) for k in range(6))/max(abs(c) for c in rv)
    emag = max(abs(eps[i][j]) for i in range(3) for j in range(3))
    print(f'stress against small-strain plane-stress Hooke: {dev:.3e} of the largest '
          f'(strain {emag:.1e}; tol {tol_a:.1e})')
    ok = ok and dev <= tol_a
    return ok


def unit_normal(nodes):
    p = [nodes[k] for k in sorted(nodes)[:4]]
    a = [p[2][k] - p[0][k] for k in range(3)]
    b = [p[3][k] - p[1][k] for k in range(3)]
    n = [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]
    m = math.sqrt(sum(c*c for c in n))
    return [c/m for c in n]


def solve3(a, b):
    def det(m):
        return (m[0][0]*(m[1][1]*m[2][2] - m[1][2]*m[2][1])
                - m[0][1]*(m[1][0]*m[2][2] - m[1][2]*m[2][0])
                + m[0][2]*(m[1][0]*m[2][1] - m[1][1]*m[2][0]))
    d = det(a)
    if abs(d) < 1e-300:   # coplanar nodes through the origin: regularise the normal
        n = 1e-12*max(abs(c) for r in a for c in r)
        a = [[a[i][j] + (n if i == j else 0.0) for j in range(3)] for i in range(3)]
        d = det(a)
    x = []
    for k in range(3):
        m = [[b[i] if j == k else a[i][j] for j in range(3)] for i in range(3)]
        x.append(det(m)/d)
    return x


def rotation(argv):
    out, tol = argv[0], float(argv[1])
    rows = read_table(out + '/glstat')
    ke0 = rows[0][3]
    worst = max((r[4] + r[5])/ke0 for r in rows)
    print(f'rigid rotation: (internal + hourglass)/KE0 at most {worst:.3e} (tol {tol:.1e})')
    return worst <= tol


def energy(argv):
    out, tol = argv[0], float(argv[1])
    t0 = float(argv[2]) if len(argv) > 2 else None      # only the rows from t = T0
    rows = read_table(out + '/glstat')
    if t0 is not None:
        rows = [r for r in rows if r[0] >= t0]
    worst = max(abs(r[9] - 1.0) for r in rows)
    since = '' if t0 is None else f' from t = {t0:g}'
    print(f'energy ratio: largest |ratio - 1|{since} {worst:.3e} (tol {tol:.1e})')
    return worst <= tol


def yield_check(argv):
    out, sigy, tol = argv[0], float(argv[1]), float(argv[2])
    h5 = out + '/d3plot.h5'
    vm = h5_dataset(h5, f'/states/{h5_last_state(h5)}/von_mises')
    worst = max(abs(v - sigy) for v in vm)/sigy
    print(f'von Mises against SIGY {sigy}: largest relative difference {worst:.3e} (tol {tol:.1e})')
    return worst <= tol


def contact(argv):
    out, ball, plate, gmin, etol = argv[0], int(argv[1]), int(argv[2]), float(argv[3]), \
        float(argv[4])
    rows = read_table(out + '/glstat')
    p0 = rows[0][12]
    dp = max(abs(r[12] - p0) for r in rows)
    ok = dp <= 1e-10*abs(p0)
    print(f'z momentum {p0:.10e}: largest change {dp:.3e} (tol 1e-10 relative: the print)')
    worst = max(abs(r[9] - 1.0) for r in rows)
    print(f'energy ratio: largest |ratio - 1| {worst:.3e} (tol {etol:.1e})')
    ok = ok and worst <= etol
    d = nodout(out)
    gap = min(abs(b[3][2] - q[3][2]) for b, q in zip(d[ball], d[plate]))
    print(f'smallest z distance node {ball} to node {plate}: {gap:.6f} (at least {gmin})')
    ok = ok and gap >= gmin
    v0, v1 = d[ball][0][2][2], d[ball][-1][2][2]
    print(f'node {ball} z velocity {v0:.4g} -> {v1:.4g} (rebound: opposite signs)')
    return ok and v0*v1 < 0.0


def pressure(argv):
    out, ref, t1, tol1, tol2, pmin = argv[0], argv[1], *map(float, argv[2:6])
    d = nodout(out)
    rows = d[sorted(d)[0]]
    row = [r for r in rows if r[0] >= t1][0]
    q = 3.0e-4*row[0]/20.0
    dplate = 210.0*1.0**3/(12.0*(1.0 - 0.3**2))
    w1 = 35.99/100.0**2*math.sqrt(dplate/7.85e-6)
    wref = 0.00126*q*100.0**4/dplate*(1.0 - math.sin(w1*row[0])/(w1*row[0]))
    e1 = abs(abs(row[1][2]) - wref)/wref
    print(f'centre deflection at t = {row[0]:.4f}: {abs(row[1][2]):.6f}, clamped plate '
          f'(small deflection, ramp) {wref:.6f}: relative difference {e1:.3e} (tol {tol1:.1e})')
    dr = nodout(ref)
    wa, wb = rows[-1][1][2], dr[sorted(dr)[0]][-1][1][2]
    e2 = abs(wa - wb)/abs(wb)
    print(f'final centre deflection {wa:.6f} against {wb:.6f} ({ref}): relative difference '
          f'{e2:.3e} (tol {tol2:.1e})')
    h5 = out + '/d3plot.h5'
    ep = max(h5_dataset(h5, f'/states/{h5_last_state(h5)}/eff_plastic_strain'))
    print(f'largest effective plastic strain {ep:.4e} (at least {pmin:.1e})')
    return e1 <= tol1 and e2 <= tol2 and ep >= pmin


def mirror(argv):
    a, b, node, tol = nodout(argv[0])[int(argv[2])], nodout(argv[1])[int(argv[2])], \
        int(argv[2]), float(argv[3])
    big = max(abs(r[2][2]) for r in a)
    worst = max(abs(ra[2][2] + rb[2][2]) for ra, rb in zip(a, b))/big
    print(f'mirror: node {node} z velocity, largest |v1 + v2| / max|v| {worst:.3e} '
          f'(tol {tol:.1e}) over {len(a)} lines')
    return len(a) == len(b) and worst <= tol


def bent(argv):
    out, m, ei, length, t0 = argv[0], *map(float, argv[1:5])
    tol_k, tol_ke = float(argv[5]), float(argv[6])
    rows = read_table(out + '/glstat')
    late = [r for r in rows if r[0] >= t0]
    u = sum(r[4] for r in late)/len(late)
    k, kref = math.sqrt(2.0*u/(ei*length)), m/ei
    ek = abs(k/kref - 1.0)
    hg = max(abs(r[5]) for r in late)/u
    ke = max(r[3]/r[6] for r in late)
    ke_all = max(r[3]/r[6] for r in rows if r[6] > 0.0)
    print(f'bent (from t = {t0:g}): mean internal energy {u:.6f} (M**2 L/(2 EI) '
          f'{0.5*m*m*length/ei:.6f}), curvature {k:.6f} against M/EI {kref:.6f}: error '
          f'{ek:.2e} (tol {tol_k:.1e}); hourglass/U {hg:.1e}, KE/W {ke:.2e} (tol {tol_ke:.1e}; '
          f'over the whole run {ke_all:.2e})')
    return ek <= tol_k and hg <= tol_ke and ke <= tol_ke


def main():
    kind, argv = sys.argv[1], sys.argv[2:]
    ok = {'period': period, 'patch': patch, 'rotation': rotation, 'energy': energy,
          'yield': yield_check, 'contact': contact, 'mirror': mirror,
          'pressure': pressure, 'bent': bent}[kind](argv)
    if not ok:
        print('FAILED')
        sys.exit(1)


if __name__ == '__main__':
    main()
