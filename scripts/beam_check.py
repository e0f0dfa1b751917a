#!/usr/bin/python3
"""Checks of the beam regression cases (tests/regression/beam_*/check).

  beam_check.py wave OUT E RHO V0 TOL X1 [X2 ...]
      axial bar pushed at x = 0 with velocity V0: the time at which the history node at x
      first reaches V0/2 (linear interpolation between nodout lines) against x/c,
      c = sqrt(E/RHO); |t - x/c| <= TOL*x/c for every X (the nodes in nodout order).
  beam_check.py order OUT1 OUT2 OUT3 L T E RHO LO HI
      cantilever first period on three meshes (each twice as fine as the one before) against
      Euler-Bernoulli (shell_check.first_period, I/A = T**2/12): prints the errors and the
      observed orders log2(e_i/e_i+1); both orders in [LO, HI].
  beam_check.py tip OUT L T0 WREF UREF TOL_W TOL_U
      large-deflection cantilever: the tip's (first history node) mean transverse
      displacement w/L and shortening u/L over t >= T0 against the references, relative.
  beam_check.py circle OUT L N T0 TOL_TIP TOL_D TOL_POLY [OUT2 N2 LO HI]
      cantilever of N elements rolled into a full circle by an end moment 2 pi E I/L: over
      t >= T0 the tip's mean distance from the root over L <= TOL_TIP, the middle node's
      mean distance from the root (the diameter) against L/pi within TOL_D and against the
      inscribed regular N-gon's (L/N)/sin(pi/N) within TOL_POLY (relative); with OUT2 (N2
      elements) the observed order of the diameter error in [LO, HI].
  beam_check.py resultants OUT M L TOL_M TOL_F
      the plot's beam resultants (rows beam_force, beam_moment) in the last state of a beam
      under a pure end moment M about its s axis: every element's |M_s| against M within
      TOL_M relative; T, M_t (over M) and N, Q_s, Q_t (over M/L) within TOL_F.
  beam_check.py deflection OUT1 OUT2 OUT3 L T0 WREF LO HI
      small-deflection cantilever under a tip force on three meshes (each twice as fine): the
      tip's (first history node) mean transverse displacement over t >= T0 against WREF
      (relative errors printed) and the observed orders log2(e_i/e_i+1) in [LO, HI]
  beam_check.py pair OUT1 OUT2 L T E RHO TOL
      the first periods of two runs of the cantilever (two formulations on one mesh): both
      errors against Euler-Bernoulli printed, |T1/T2 - 1| <= TOL
  beam_check.py plastic OUT QR CST SIGY D1 D2 TOL_RULE TOL_MP
      Hughes-Liu beams in pure bending past the yield curvature (gen_beam_deck.py plastic):
      the section rule's fully plastic moment M_rule = SIGY sum_k w_k |t_k| (QR, CST of
      dx_beam_hl: CST 0 the rectangle TS = D1 by TT = D2, bending about s; CST 1 the tube of
      diameters D1, D2) against the exact Mp (SIGY TS TT**2/4; SIGY (D1**3 - D2**3)/6) within
      TOL_MP relative (the rule's own error, stated in the case), and every element's |M_s| in
      the last plot state against M_rule within TOL_RULE (T, M_t, N, Q below 0.02 M/L)
  beam_check.py turned OUT L ANGLE T0 TOL
      a beam of length L turned about y as a rigid body by ANGLE (its root at the origin): the
      first history node's mean position over t >= T0 within TOL L of (L cos, 0, -L sin).
  beam_check.py torsion OUT G J L I TOL
      torsion pendulum: the kinetic energy (glstat) has its minima every pi/omega; omega
      against sqrt(G J/(L I)) within TOL relative.
  beam_check.py rotation OUT OMEGA TOL_X TOL_E
      free beam spinning about y through the origin: every history node at radius r keeps
      |x| = r within TOL_X relative and turns by the angle omega t (x, z against
      r cos, -r sin of omega t) within TOL_X relative to r; internal energy over the initial
      kinetic energy <= TOL_E (the centrifugal stretch only) and |ratio - 1| <= TOL_E.
"""
import math
import sys

from ascii_out import read_columns
from shell_check import first_period, nodout


def wave(argv):
    out, e, rho, v0, tol = argv[0], *map(float, argv[1:5])
    xs = [float(a) for a in argv[5:]]
    c = math.sqrt(e/rho)
    d = nodout(out)
    ok = True
    for x, node in zip(xs, sorted(d)):
        rows = d[node]
        t_hit = None
        for (t0, _, v0r, _), (t1, _, v1r, _) in zip(rows, rows[1:]):
            a, b = v0r[0] - 0.5*v0, v1r[0] - 0.5*v0
            if a < 0.0 <= b:
                t_hit = t0 + (t1 - t0)*(-a)/(b - a)
                break
        if t_hit is None:
            print(f'node {node}: the front (v = V0/2) never arrived')
            ok = False
            continue
        err = abs(t_hit - x/c)/(x/c)
        print(f'node {node} x {x:g}: front at {t_hit:.6e}, x/c {x/c:.6e}, relative error '
              f'{err:.2e} (tol {tol:.1e})')
        ok = ok and err <= tol
    return ok


def order(argv):
    outs = argv[0:3]
    length, thick, e, rho, lo, hi = map(float, argv[3:9])
    w1 = 1.8751040687**2*math.sqrt(e*thick**2/(12.0*rho*length**4))
    tref = 2.0*math.pi/w1
    errs = [abs(first_period(o) - tref)/tref for o in outs]
    ords = [math.log(errs[k]/errs[k + 1])/math.log(2.0) for k in range(2)]
    print('period errors ' + ' '.join(f'{x:.3e}' for x in errs) + ' observed orders ' +
          ' '.join(f'{x:.2f}' for x in ords) + f' (range [{lo}, {hi}])')
    return all(lo <= x <= hi for x in ords)


def rotation(argv):
    out, om, tol_x, tol_e = argv[0], *map(float, argv[1:4])
    d = nodout(out)
    ok = True
    worst = 0.0
    for node, rows in d.items():
        x0 = rows[0][3]
        r = math.hypot(x0[0], x0[2])
        for t, _, _, xc in rows:
            ex = math.hypot(xc[0] - r*math.copysign(1.0, x0[0])*math.cos(om*t),
                            xc[2] + r*math.copysign(1.0, x0[0])*math.sin(om*t))
            worst = max(worst, ex/r)
    print(f'largest position error against the rigid rotation: {worst:.2e} r (tol {tol_x:.1e})')
    ok = worst <= tol_x
    g = read_columns(out + '/glstat')
    ke0 = g[min(g)]['kinetic']
    ie = max(abs(row['internal']) for row in g.values())/ke0
    rat = max(abs(row['energy_ratio'] - 1.0) for row in g.values())
    print(f'internal/initial kinetic {ie:.2e}, |ratio - 1| {rat:.2e} (tol {tol_e:.1e})')
    return ok and ie <= tol_e and rat <= tol_e


def torsion(argv):
    out, g, j, length, inertia, tol = argv[0], *map(float, argv[1:6])
    rows = sorted(read_columns(out + '/glstat').items())
    t = [r[0] for r in rows]
    ke = [r[1]['kinetic'] for r in rows]
    mins = []
    for k in range(1, len(ke) - 1):
        if ke[k] < ke[k - 1] and ke[k] <= ke[k + 1]:
            # vertex of the parabola through the three samples (glstat lines fall on the
            # first cycle past each interval: unequal spacing)
            (a, fa), (b, fb), (c, fc) = (t[k - 1], ke[k - 1]), (t[k], ke[k]), (t[k + 1], ke[k + 1])
            num = (b - a)**2*(fb - fc) - (b - c)**2*(fb - fa)
            den = (b - a)*(fb - fc) - (b - c)*(fb - fa)
            mins.append(b - 0.5*num/den if den != 0.0 else b)
    if len(mins) < 2:
        print('fewer than two minima of the kinetic energy')
        return False
    omega = math.pi/((mins[-1] - mins[0])/(len(mins) - 1))
    ref = math.sqrt(g*j/(length*inertia))
    err = abs(omega - ref)/ref
    print(f'torsion: omega {omega:.6e} rad/ms, sqrt(G J/(L I)) {ref:.6e}, relative error '
          f'{err:.2e} (tol {tol:.1e}; {len(mins)} minima of the kinetic energy)')
    return err <= tol


def tip(argv):
    out, length, t0, wref, uref, tol_w, tol_u = argv[0], *map(float, argv[1:7])
    d = nodout(out)
    rows = [r for r in d[sorted(d)[0]] if r[0] >= t0]
    w = sum(r[1][2] for r in rows)/len(rows)/length
    u = -sum(r[1][0] for r in rows)/len(rows)/length
    ew, eu = abs(w - wref)/wref, abs(u - uref)/uref
    print(f'tip (mean from t = {t0:g}): w/L {w:.6f} (reference {wref}, error {ew:.2e}, tol '
          f'{tol_w:.1e}), u/L {u:.6f} (reference {uref}, error {eu:.2e}, tol {tol_u:.1e})')
    return ew <= tol_w and eu <= tol_u


def circle_fit(out, length, n, t0):
    """mean tip position (the history node of the larger id) and the middle node's distance
    from the root (the smaller id), over t >= T0"""
    d = nodout(out)
    ids = sorted(d)
    tip = [r for r in d[ids[1]] if r[0] >= t0]
    mid = [r for r in d[ids[0]] if r[0] >= t0]
    tx = sum(length + r[1][0] for r in tip)/len(tip)
    tz = sum(r[1][2] for r in tip)/len(tip)
    mx = sum(0.5*length + r[1][0] for r in mid)/len(mid)
    mz = sum(r[1][2] for r in mid)/len(mid)
    return math.hypot(tx, tz)/length, math.hypot(mx, mz)


def circle(argv):
    """OUT L N T0 TOL_TIP TOL_D TOL_POLY [OUT2 N2 LO HI]"""
    out, length, n, t0 = argv[0], float(argv[1]), int(argv[2]), float(argv[3])
    tol_tip, tol_d, tol_poly = map(float, argv[4:7])
    tip, dia = circle_fit(out, length, n, t0)
    ref = length/math.pi
    poly = (length/n)/math.sin(math.pi/n)
    ed, ep = abs(dia/ref - 1.0), abs(dia/poly - 1.0)
    print(f'circle ({n} elements, mean from t = {t0:g}): tip distance from the root / L '
          f'{tip:.2e} (tol {tol_tip:.1e}); diameter {dia:.6f} against L/pi {ref:.6f}: error '
          f'{ed:.3e} (tol {tol_d:.1e}), against the inscribed {n}-gon {poly:.6f}: {ep:.2e} '
          f'(tol {tol_poly:.1e})')
    ok = tip <= tol_tip and ed <= tol_d and ep <= tol_poly
    if len(argv) > 7:
        out2, n2, lo, hi = argv[7], int(argv[8]), float(argv[9]), float(argv[10])
        _, dia2 = circle_fit(out2, length, n2, t0)
        ed2 = abs(dia2/ref - 1.0)
        p = math.log(ed2/ed)/math.log(n/n2)
        print(f'circle ({n2} elements): diameter error {ed2:.3e}; observed order {p:.2f} '
              f'(in [{lo}, {hi}])')
        ok = ok and lo <= p <= hi
    return ok


def resultants(argv):
    """OUT M L TOL_M TOL_F: last plot state, every beam under the pure moment M"""
    from shell_check import h5_dataset, h5_last_state
    out, m, length, tol_m, tol_f = argv[0], *map(float, argv[1:5])
    h5 = out + '/d3plot.h5'
    g = h5_last_state(h5)
    f = h5_dataset(h5, f'/states/{g}/beam_force')
    mo = h5_dataset(h5, f'/states/{g}/beam_moment')
    ne = len(f)//3
    em = max(abs(abs(mo[3*e + 1])/m - 1.0) for e in range(ne))
    eo = max(max(abs(mo[3*e]), abs(mo[3*e + 2])) for e in range(ne))/m
    ef = max(abs(v) for v in f)*length/m
    print(f'resultants ({ne} beams, state {g}): |M_s|/M - 1 up to {em:.2e} (tol {tol_m:.1e}); '
          f'T, M_t up to {eo:.2e} M; N, Q_s, Q_t up to {ef:.2e} M/L (tol {tol_f:.1e})')
    return em <= tol_m and eo <= tol_f and ef <= tol_f


def deflection(argv):
    """OUT1 OUT2 OUT3 L T0 WREF LO HI"""
    outs = argv[0:3]
    length, t0, wref, lo, hi = map(float, argv[3:8])
    errs = []
    for out in outs:
        d = nodout(out)
        rows = [r for r in d[sorted(d)[0]] if r[0] >= t0]
        w = sum(r[1][2] for r in rows)/len(rows)
        errs.append(abs(w - wref)/wref)
    orders = [math.log2(errs[i]/errs[i + 1]) for i in range(2)]
    print(f'tip deflection errors {errs[0]:.3e} {errs[1]:.3e} {errs[2]:.3e} against {wref:.6e}; '
          f'observed orders {orders[0]:.2f} {orders[1]:.2f} (range [{lo}, {hi}])')
    return all(lo <= o <= hi for o in orders)


def pair(argv):
    """OUT1 OUT2 L T E RHO TOL"""
    o1, o2 = argv[0], argv[1]
    length, t, e, rho, tol = map(float, argv[2:7])
    iy = t*t/12.0
    tref = 2*math.pi/(1.8751040687**2*math.sqrt(e*iy/(rho*length**4)))
    p1, p2 = first_period(o1), first_period(o2)
    r = p1/p2 - 1.0
    print(f'first periods {p1:.6f} ({p1/tref - 1:+.3e}) and {p2:.6f} ({p2/tref - 1:+.3e}) '
          f'against Euler-Bernoulli {tref:.6f}: ratio - 1 = {r:+.3e} (tol {tol:.1e})')
    return abs(r) <= tol


def hl_rule(qr, cst):
    """dx_beam_hl's section rule in unit coordinates: [(s, t, weight fraction)]"""
    if cst == 1:
        n = 4*qr
        return [(math.cos(2*math.pi*k/n), math.sin(2*math.pi*k/n), 1.0/n) for k in range(n)]
    r = {1: ([0.0], [2.0]),
         2: ([-1/math.sqrt(3), 1/math.sqrt(3)], [1.0, 1.0]),
         3: ([-math.sqrt(0.6), 0.0, math.sqrt(0.6)], [5/9, 8/9, 5/9]),
         4: ([-1.0, 0.0, 1.0], [1/3, 4/3, 1/3])}
    if qr == 5:
        a, b = math.sqrt(3/7 - 2/7*math.sqrt(1.2)), math.sqrt(3/7 + 2/7*math.sqrt(1.2))
        wa, wb = (18 + math.sqrt(30))/36, (18 - math.sqrt(30))/36
        g, w = [-b, -a, a, b], [wb, wa, wa, wb]
    else:
        g, w = r[qr]
    return [(gi, gj, 0.25*wi*wj) for gj, wj in zip(g, w) for gi, wi in zip(g, w)]


def plastic(argv):
    """OUT QR CST SIGY D1 D2 TOL_RULE TOL_MP"""
    out, qr, cst = argv[0], int(argv[1]), int(argv[2])
    sigy, d1, d2, tol_rule, tol_mp = map(float, argv[3:8])
    if cst == 1:
        area, ht = math.pi*(d1*d1 - d2*d2)/4, 0.5*math.sqrt(0.5*(d1*d1 + d2*d2))
        mp = sigy*(d1**3 - d2**3)/6
    else:
        area, ht = d1*d2, 0.5*d2
        mp = sigy*d1*d2*d2/4
    mrule = sigy*area*ht*sum(w*abs(t) for _, t, w in hl_rule(qr, cst))
    e = mrule/mp - 1.0
    print(f'fully plastic moment: rule QR {qr} CST {cst} {mrule:.6e}, exact {mp:.6e}: '
          f'{e:+.4e} (tol {tol_mp:.1e})')
    ok = abs(e) <= tol_mp
    return resultants([out, str(mrule), '100', str(tol_rule), '0.02']) and ok


def plastic_user(argv):
    """OUT SIGY TS TT RA TOL_M S1 T1 WF1 S2 T2 WF2 ...: a user rule's (*INTEGRATION_BEAM)
    fully plastic moment about s, the rule's own sum SIGY RA TS TT (TT/2) sum WF |T|"""
    out = argv[0]
    sigy, ts, tt, ra, tol_m = map(float, argv[1:6])
    pts = [tuple(map(float, argv[k:k + 3])) for k in range(6, len(argv), 3)]
    mrule = sigy*ra*ts*tt*0.5*tt*sum(w*abs(t) for _, t, w in pts)
    print(f'fully plastic moment of the user rule ({len(pts)} points, RA {ra:g}): {mrule:.10e}')
    return resultants([out, str(mrule), '100', str(tol_m), '0.02'])


def offset(argv):
    """OUT T0 UREF WREF TOL: the tip (first history node) mean x and z displacements over
    t >= T0 against UREF, WREF (signed), relative errors within TOL"""
    out, t0, uref, wref, tol = argv[0], *map(float, argv[1:5])
    d = nodout(out)
    rows = [r for r in d[sorted(d)[0]] if r[0] >= t0]
    u = sum(r[1][0] for r in rows)/len(rows)
    w = sum(r[1][2] for r in rows)/len(rows)
    eu, ew = abs(u/uref - 1.0), abs(w/wref - 1.0)
    print(f'offset tip (mean from t = {t0:g}): u {u:.6e} (reference {uref:.6e}, error '
          f'{eu:.2e}), w {w:.6e} (reference {wref:.6e}, error {ew:.2e}); tol {tol:.1e}')
    return eu <= tol and ew <= tol


def turned(argv):
    """OUT L ANGLE T0 TOL: the tip (first history node) after a rigid turn about y"""
    out, length, ang, t0, tol = argv[0], *map(float, argv[1:5])
    d = nodout(out)
    rows = [r for r in d[sorted(d)[0]] if r[0] >= t0]
    mx = sum(r[3][0] for r in rows)/len(rows)
    mz = sum(r[3][2] for r in rows)/len(rows)
    err = math.hypot(mx - length*math.cos(ang), mz + length*math.sin(ang))/length
    got = math.atan2(-mz, mx)
    print(f'turned tip (mean from t = {t0:g}): ({mx:.6f}, {mz:.6f}), angle {got:.8f} against '
          f'{ang:.8f}; distance from L (cos, -sin) over L {err:.2e} (tol {tol:.1e})')
    return err <= tol


def main():
    cmd, argv = sys.argv[1], sys.argv[2:]
    fn = {'wave': wave, 'order': order, 'rotation': rotation, 'torsion': torsion,
          'tip': tip, 'circle': circle, 'resultants': resultants,
          'turned': turned, 'plastic': plastic, 'plastic_user': plastic_user, 'offset': offset, 'pair': pair,
          'deflection': deflection}.get(cmd)
    if fn is None:
        raise SystemExit(__doc__)
    if not fn(argv):
        print('FAILED')
        sys.exit(1)


if __name__ == '__main__':
    main()
