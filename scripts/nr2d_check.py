#!/usr/bin/python3
"""Checks of the 2D non-reflecting boundary cases (tests/regression/nr2d_*/check;
*BOUNDARY_NON_REFLECTING_2D, dx_nonreflecting).

  nr2d_check.py reflect OUT REF TOL [FREE]
      OUT: the run with the non-reflecting boundary; REF: the same mesh extended so far that no
      reflection comes back within the run (gen_nr2d_decks.py): the reflected wave at each
      history node is v_OUT - v_REF (in-plane speed, over every nodout line), its peak against
      the incident peak max |v_REF| at that node; the largest ratio over the nodes <= TOL.
      FREE (optional): the same with a free boundary, whose ratio is printed (the reflection
      the boundary removes) and must exceed 10 TOL.
  nr2d_check.py absorbed OUT TOL AFTER TOLK
      the energy balance of the absorbing run once the wave has left (t >= AFTER): |KE + IE -
      external work| <= TOL max |external work| on those glstat lines (the run starts at
      rest; the dashpots' work is in the external work;
      while the wave crosses the boundary the ratio is off by up to one cycle's energy flux,
      dt/duration of the pulse, as the work of a step is booked with the step), and the
      kinetic energy at the end <= TOLK times its peak (the wave has gone).
  nr2d_check.py momentum OUT XMOM YMOM TOL
      the momentum of the last glstat line against the impulse (XMOM, YMOM) of the loads
      (*DYNX_PRESSURE_PULSE, *DYNX_PRESSURE_TABLE on a free body), each within TOL of the
      larger of the two; and |energy ratio - 1| <= TOL at the end.
  nr2d_check.py tableimpulse OUT TABLE TOL
      the same for the y momentum of a body whose top face (normal +y) carries the table
      p(r, t) of the data file TABLE over r = 0 .. the last radius: the impulse per radian
      -int int p r dr dt, exact for the bilinear table (Gauss points per cell).
  nr2d_check.py deposit OUT ENERGY TOL
      *DYNX_ENERGY_DEPOSITION: kinetic + internal + hourglass energy at the end equals the
      deposited ENERGY within TOL relative, and |energy ratio - 1| <= TOL on every line.
  nr2d_check.py blocks OUT DECK V0 TOL_V TOL_E
      two blocks (parts 1 and 2 of DECK, gen_nr2d_decks.py blocks) colliding, every node a
      history node: the centre-of-mass x velocities at the end (nodal weights: the number of
      elements at each node, the lumped masses of a uniform mesh) against the exchange (0,
      V0) within TOL_V V0; the x momentum of glstat constant to 1e-12 relative; |KE + IE + HG -
      KE0| <= TOL_E KE0 at the end (the contact's penalty energy returned).
  nr2d_check.py fold OUT OUTNC PEN DEEP
      the U of gen_nr2d_decks.py fold closing its slot under a single-surface contact: the
      slot's width (the x = 5 face nodes' x minus the x = 4 ones' at the same height, every
      nodout line) never below -PEN in OUT; OUTNC, the same deck without the contact, must
      reach below -DEEP (the legs would pass through each other).
  nr2d_check.py friction OUT DECK MU P W TRAMP RHO TOL
      a block (part 2 of DECK, gen_nr2d_decks.py slide: W x 2 mm, density RHO) sliding on a
      base under the pressure P (ramped over TRAMP) with Coulomb friction MU: while it slides,
      its friction impulse is MU times the normal impulse, and the normal impulse is the
      pressure's I_p plus m dv_y (its own vertical momentum), so at every nodout line
      v_x = v_x0 - MU (I_p/m + dv_y) (centre-of-mass velocities) within TOL.
  nr2d_check.py tiedbar OUT CONTACT UNCUT V0 NODE D TOLT TOLV TOLO TOLE TOLE1
      the bar of gen_nr2d_decks.py tiedbar (plane strain, 1D strain, half A at -V0, half B at
      rest, cut and tied): the tension wave carries v_x = -V0/2 into B at the 1D-strain
      speed c = sqrt(E(1-nu)/((1+nu)(1-2nu))/rho) (steel). At history node NODE, D mm into B:
      the time v_x passes -V0/4 within TOLT of D/c; the mean v_x over the plateau (its
      arrival + 2 us to the return of the far end's reflection, (80 - 40 + 80 - 40 - D)/c -
      0.5 us) within TOLV V0/2 of -V0/2 and its largest deviation within TOLO V0/2; x momentum
      of glstat constant to 1e-12 relative; |energy ratio - 1| <= TOLE at the end and TOLE1 on
      every glstat line (the tie's work is booked a cycle late: the first cycles, when the
      tie takes up the jump in velocity, are off by a cycle's work).
      CONTACT (the same bar with a surface-to-surface contact instead): the cut opens, the
      node stays at rest (|v_x| <= 1e-6 V0). UNCUT (the bar in one piece): its arrival and
      plateau printed beside.
"""
import math
import sys

from ascii_out import nodout_series, read_columns


def speeds(out):
    return {n: [(t, math.hypot(v[0], v[1]), v) for t, v in rows]
            for n, rows in nodout_series(out, 'vel').items()}


def at(rows, t):
    """the velocity of rows (t, speed, v) at time t, linear between the lines (the runs' steps
    part by round-off once the reflection changes the elements' lengths)"""
    lo, hi = 0, len(rows) - 1
    while hi - lo > 1:
        mid = (lo + hi)//2
        if rows[mid][0] <= t:
            lo = mid
        else:
            hi = mid
    (t0, _, v0), (t1, _, v1) = rows[lo], rows[hi]
    w = (t - t0)/(t1 - t0)
    return [a + w*(b - a) for a, b in zip(v0, v1)]


def reflect_ratio(out, ref):
    a, b = speeds(out), speeds(ref)
    worst, where = 0.0, None
    for n in sorted(a):
        ra, rb = a[n], b[n]
        inc = max(s for _, s, _ in rb)
        if inc <= 0.0:
            continue
        refl = 0.0
        for t, _, v in ra:
            if t > rb[-1][0]:          # the last line of a run that ends a step later
                break
            w = at(rb, t)
            refl = max(refl, math.hypot(v[0] - w[0], v[1] - w[1]))
        if refl/inc > worst:
            worst, where = refl/inc, n
    return worst, where


def reflect(argv):
    out, ref, tol = argv[0], argv[1], float(argv[2])
    r, n = reflect_ratio(out, ref)
    print(f'reflected/incident peak speed: {r:.4f} (node {n}), bound {tol}')
    ok = r <= tol
    if len(argv) > 3:
        rf, nf = reflect_ratio(argv[3], ref)
        print(f'free boundary: {rf:.4f} (node {nf}), must exceed {10*tol}')
        ok = ok and rf > 10*tol
    if not ok:
        raise SystemExit('FAIL')


def absorbed(argv):
    out, tol, after, tolk = argv[0], float(argv[1]), float(argv[2]), float(argv[3])
    rows = read_columns(out + '/glstat')
    wmax = max(abs(r['external_work']) for r in rows.values())
    worst = max(abs(r['total'] - r['external_work']) for t, r in rows.items() if t >= after)
    kmax = max(r['kinetic'] for r in rows.values())
    kend = rows[max(rows)]['kinetic']
    print(f'|KE + IE - external work|/max external work <= {worst/wmax:.3e} for t >= {after} '
          f'(bound {tol}); kinetic energy at the end / peak {kend/kmax:.3e} (bound {tolk})')
    if worst > tol*wmax or kend > tolk*kmax:
        raise SystemExit('FAIL')


def last(out):
    rows = read_columns(out + '/glstat')
    return rows, rows[max(rows)]


def momentum(argv):
    out, xm, ym, tol = argv[0], float(argv[1]), float(argv[2]), float(argv[3])
    _, r = last(out)
    big = max(abs(xm), abs(ym))
    ex, ey = abs(r['xmom'] - xm)/big, abs(r['ymom'] - ym)/big
    er = abs(r['energy_ratio'] - 1.0)
    print(f'momentum ({r["xmom"]:.6e}, {r["ymom"]:.6e}) against the impulse ({xm:.6e}, '
          f'{ym:.6e}): errors {ex:.2e}, {ey:.2e}; |energy ratio - 1| {er:.2e} (bound {tol})')
    if max(ex, ey, er) > tol:
        raise SystemExit('FAIL')


def read_ptable(path):
    nums = []
    for line in open(path):
        nums += [float(w) for w in line.split('#')[0].replace(',', ' ').split()]
    nr, nt = int(nums[0]), int(nums[1])
    r, t = nums[2:2 + nr], nums[2 + nr:2 + nr + nt]
    p = [nums[2 + nr + nt + j*nr:2 + nr + nt + (j + 1)*nr] for j in range(nt)]
    return r, t, p


def table_impulse(path):
    """int_t int_0^rmax p(r, t) r dr dt of the bilinear table: 3 Gauss points per r cell
    (p r is quadratic there), 2 per t cell (p is linear there): exact"""
    r, t, p = read_ptable(path)
    g3 = [(-math.sqrt(0.6), 5/9), (0.0, 8/9), (math.sqrt(0.6), 5/9)]
    g2 = [(-1/math.sqrt(3), 1.0), (1/math.sqrt(3), 1.0)]
    total = 0.0
    for j in range(len(t) - 1):
        for i in range(len(r) - 1):
            for xt, wt in g2:
                b = 0.5*(1 + xt)
                for xr, wr in g3:
                    a = 0.5*(1 + xr)
                    rr = r[i] + a*(r[i + 1] - r[i])
                    pp = (1 - b)*((1 - a)*p[j][i] + a*p[j][i + 1]) + \
                        b*((1 - a)*p[j + 1][i] + a*p[j + 1][i + 1])
                    total += 0.25*wt*wr*(t[j + 1] - t[j])*(r[i + 1] - r[i])*pp*rr
    return total


def tableimpulse(argv):
    out, path, tol = argv[0], argv[1], float(argv[2])
    momentum([out, '0.0', str(-table_impulse(path)), str(tol)])


def deposit(argv):
    out, energy, tol = argv[0], float(argv[1]), float(argv[2])
    rows, r = last(out)
    e = r['kinetic'] + r['internal'] + r['hourglass']
    er = max(abs(x['energy_ratio'] - 1.0) for x in rows.values())
    print(f'KE + IE + HG at the end {e:.9e} against the deposited {energy:.9e}: '
          f'{abs(e - energy)/energy:.2e}; |energy ratio - 1| <= {er:.2e} (bound {tol})')
    if abs(e - energy) > tol*energy or er > tol:
        raise SystemExit('FAIL')


def part_cm_velocity(out, deck, pid):
    """{t: (vx, vy)} of part pid's centre of mass (nodal weights: elements per node)"""
    wt, on = {}, False
    for line in open(deck):
        if line.startswith('*'):
            on = line.startswith('*ELEMENT_SHELL')
            continue
        if on and line.strip() and not line.startswith('$') and int(line[8:16]) == pid:
            for k in range(4):
                n = int(line[16 + 8*k:24 + 8*k])
                wt[n] = wt.get(n, 0) + 1
    rows = nodout_series(out, 'vel')
    ns = [n for n in sorted(rows) if n in wt]
    tot = sum(wt[n] for n in ns)
    return [(rows[ns[0]][i][0], sum(wt[n]*rows[n][i][1][0] for n in ns)/tot,
             sum(wt[n]*rows[n][i][1][1] for n in ns)/tot) for i in range(len(rows[ns[0]]))]


def friction(argv):
    out, deck = argv[0], argv[1]
    mu, p, w, tr, rho, tol = map(float, argv[2:8])
    cm = part_cm_velocity(out, deck, 2)
    m = rho*w*2.0
    worst = 0.0
    for t, vx, vy in cm:
        ip = p*w*(t*t/(2*tr) if t < tr else t - 0.5*tr)
        theory = cm[0][1] - mu*(ip/m + vy - cm[0][2])
        worst = max(worst, abs(vx - theory))
    print(f'block v_x at the end {cm[-1][1]:.4f} (from {cm[0][1]:.4f}); largest |v_x - v_x0 + '
          f'MU (I_p/m + dv_y)| {worst:.4f} (bound {tol})')
    if worst > tol:
        raise SystemExit('FAIL')


def blocks_check(argv):
    out, deck, v0, tolv, tole = argv[0], argv[1], float(argv[2]), float(argv[3]), \
        float(argv[4])
    wt, part, on = {}, {}, False
    for line in open(deck):
        if line.startswith('*'):
            on = line.startswith('*ELEMENT_SHELL')
            continue
        if on and line.strip() and not line.startswith('$'):
            pid = int(line[8:16])
            for k in range(4):
                n = int(line[16 + 8*k:24 + 8*k])
                wt[n] = wt.get(n, 0) + 1
                part[n] = pid
    rows = nodout_series(out, 'vel')
    vcm = {}
    for pid in (1, 2):
        num = sum(wt[n]*rows[n][-1][1][0] for n in rows if part[n] == pid)
        den = sum(wt[n] for n in rows if part[n] == pid)
        vcm[pid] = num/den
    g = read_columns(out + '/glstat')
    xm = [r['xmom'] for r in g.values()]
    dm = max(abs(x - xm[0]) for x in xm)/abs(xm[0])
    first, lastr = g[min(g)], g[max(g)]
    e = lastr['kinetic'] + lastr['internal'] + lastr['hourglass']
    de = abs(e - first['kinetic'])/first['kinetic']
    print(f'centre-of-mass x velocities at the end: A {vcm[1]:.4f}, B {vcm[2]:.4f} (exchange: 0, '
          f'{v0}; bound {tolv} V0); x momentum drift {dm:.2e}; energy {de:.2e} (bound {tole})')
    if abs(vcm[1]) > tolv*v0 or abs(vcm[2] - v0) > tolv*v0 or dm > 1e-12 or de > tole:
        raise SystemExit('FAIL')


def slot_gap(out):
    """The smallest width of the U's slot (gen_nr2d_decks.py fold): x of each x = 5 face node
    minus x of the x = 4 node at the same height, over the nodout lines: (gap, t, node)."""
    d = nodout_series(out, 'coor')
    left = sorted(n for n in d if abs(d[n][0][1][0] - 4.0) < 1e-9)
    right = sorted(n for n in d if abs(d[n][0][1][0] - 5.0) < 1e-9)
    return min((d[b][k][1][0] - d[a][k][1][0], d[a][k][0], a)
               for a, b in zip(left, right) for k in range(len(d[a])))


def fold(argv):
    out, outnc, pen, deep = argv[0], argv[1], float(argv[2]), float(argv[3])
    g, gnc = slot_gap(out), slot_gap(outnc)
    print(f'slot: narrowest {g[0]:.4f} mm (t {g[1]:.4f}, node {g[2]}; bound -{pen}); without the '
          f'contact {gnc[0]:.4f} mm (t {gnc[1]:.4f}; must pass -{deep})')
    if g[0] < -pen or gnc[0] > -deep:
        raise SystemExit('FAIL')


def tied_series(out, node, v0):
    """(time v_x passes -v0/4, the v_x rows) of history node NODE in OUT"""
    rows = [(t, v[0]) for t, v in nodout_series(out, 'vel')[node]]
    for (t0, a), (t1, b) in zip(rows, rows[1:]):
        if a > -0.25*v0 >= b:
            return t0 + (t1 - t0)*(a + 0.25*v0)/(a - b), rows
    return None, rows


def tiedbar(argv):
    out, outc, outu = argv[0:3]
    v0, node, d, tolt, tolv, tolo, tole, tole1 = float(argv[3]), int(argv[4]), \
        *map(float, argv[5:11])
    c = math.sqrt(210.0*(1 - 0.3)/((1 + 0.3)*(1 - 0.6))/7.85e-6)
    ok = True
    for label, o in (('tied', out), ('uncut', outu)):
        th, rows = tied_series(o, node, v0)
        if th is None:
            print(f'{label}: v_x never passes -V0/4 at node {node}')
            ok = False
            continue
        t_end = (80.0 - d)/c - 5e-4
        pl = [v for t, v in rows if th + 2e-3 <= t <= t_end]
        mean = sum(pl)/len(pl)
        dev = max(abs(v + 0.5*v0) for v in pl)
        print(f'{label}: arrival {th*1e3:.4f} us (D/c {d/c*1e3:.4f} us, {(th - d/c)*1e3:+.4f}; '
              f'bound {tolt*1e3:.3f}), plateau mean {mean:.5f} (-V0/2 = {-0.5*v0}; rel '
              f'{abs(mean + 0.5*v0)/(0.5*v0):.2e}, bound {tolv}), largest deviation '
              f'{dev/(0.5*v0):.2e} (bound {tolo}) over {len(pl)} lines')
        if label == 'tied' and (abs(th - d/c) > tolt or abs(mean + 0.5*v0) > tolv*0.5*v0 or
                                dev > tolo*0.5*v0):
            ok = False
    g = read_columns(out + '/glstat')
    xm = [r['xmom'] for r in g.values()]
    dm = max(abs(x - xm[0]) for x in xm)/abs(xm[0])
    de = max(abs(r['energy_ratio'] - 1.0) for r in g.values())
    de1 = abs(g[max(g)]['energy_ratio'] - 1.0)
    print(f'tied: x momentum drift {dm:.2e} (bound 1e-12), |energy ratio - 1| at the end '
          f'{de1:.2e} (bound {tole}), largest {de:.2e} (bound {tole1})')
    if dm > 1e-12 or de1 > tole or de > tole1:
        ok = False
    _, rows = tied_series(outc, node, v0)
    vc = max(abs(v) for t, v in rows)
    print(f'contact instead of the tie: largest |v_x| at node {node} {vc:.2e} (the cut opens; '
          f'bound {1e-6*v0:.1e})')
    if vc > 1e-6*v0:
        ok = False
    if not ok:
        raise SystemExit('FAIL')


if __name__ == '__main__':
    {'reflect': reflect, 'absorbed': absorbed, 'momentum': momentum,
     'tableimpulse': tableimpulse, 'deposit': deposit, 'blocks': blocks_check,
     'friction': friction, 'fold': fold, 'tiedbar': tiedbar}[sys.argv[1]](sys.argv[2:])
