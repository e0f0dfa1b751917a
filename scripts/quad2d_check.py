#!/usr/bin/python3
"""Checks of the 2D solid regression cases (tests/regression/quad2d_*/check; dx_quad2d).

  quad2d_check.py patch OUT DECK TOL_V TOL_S TOL_A
      plane-strain patch test: the free (history) nodes keep their initial velocity to TOL_V
      relative; the elements' stresses of the last plot state agree to TOL_S relative, and
      with plane-strain Hooke of the mean strain (sigma_zz = nu (sigma_xx + sigma_yy)) to TOL_A.
  quad2d_check.py patchps OUT DECK TOL_V TOL_S TOL_A
      the same for plane stress (ELFORM 12): Hooke with sigma_zz = 0.
  quad2d_check.py lame OUT1 OUT2 OUT3 T0 TOL ORDER_MIN
      thick-walled cylinder a = 10, b = 20, p = 0.1 (gen_quad2d_decks.py lame) on three meshes
      (nr = 4, 8, 16): the radial displacement of the inner and outer history nodes averaged
      over t >= T0 (the held load; the dynamic overshoot averages out) against Lame's plane-
      strain u_r; the finest error <= TOL relative, and the observed order from the inner
      errors log2(e1/e2), log2(e2/e3) >= ORDER_MIN each (printed); ORDER_MIN <= 0: the
      errors are at the floor of the time averaging, every mesh's within TOL (order printed).
  quad2d_check.py lame1 OUT T0 TOL
      one mesh of the same: both errors within TOL.
  quad2d_check.py bar OUT TOL_C YMIN
      axisymmetric bar (gen_quad2d_decks.py bar): the time the axial velocity of each axis
      history node at y >= YMIN first reaches a third of the end's 1 m/s; the speed fitted
      through them against the bar speed sqrt(E/rho) within TOL_C relative (Skalak 1957:
      far from the end, the step's head is an Airy integral centred on y = c0 t, where it has
      risen to 1/3).
  quad2d_check.py barcmp OUT2D OUT3D TOL_T YMIN
      the same bar in 2D and as 3D hexahedra (gen_quad2d_decks.py hexbar): the arrival times
      of the front (as in bar) at the axis nodes y >= YMIN differ by at most TOL_T.
  quad2d_check.py taylor OUT LF TOL_L RF TOL_R
  quad2d_check.py taylor2 OUT LF TOL_L RF TOL_R PEN  (gen_nr2d_decks.py taylor2: the mirror)
      axisymmetric Taylor bar: final length and foot radius within TOL_L, TOL_R relative of
      LF, RF (the converged 3D values).
  quad2d_check.py energy OUT BAND [AFTER]
      |energy ratio - 1| <= BAND on every glstat line at t >= AFTER, and z components of every
      nodout displacement, velocity and acceleration exactly 0.
"""
import math
import sys

from ascii_out import read_table, nodout_series, h5_dataset, h5_last_state

RHO, E, NU = 7.85e-6, 210.0, 0.3
A_IN, B_OUT, P_IN = 10.0, 20.0, 1.0e-4


def nodout(out):
    """{node: [(t, disp(3), vel(3), acc(3), coor(3))]}"""
    return nodout_series(out, 'disp', 'vel', 'acc', 'coor')


def fail(msg):
    print('FAIL:', msg)
    sys.exit(1)


def initial_velocities(deck):
    v, on = {}, False
    for line in open(deck):
        if line.startswith('*'):
            on = line.startswith('*INITIAL_VELOCITY_NODE')
            continue
        if on and line.strip():
            v[int(line[:20])] = (float(line[20:40]), float(line[40:60]))
    return v


def patch(out, deck, tol_v, tol_s, tol_a, plane_stress=False):
    v0 = initial_velocities(deck)
    dv = 0.0
    for n, rows in nodout(out).items():
        for r in rows:
            dv = max(dv, max(abs(r[2][k] - v0[n][k]) for k in range(2))/math.hypot(*v0[n]))
    print(f'free nodes: largest relative change of velocity {dv:.3e} (tol {tol_v})')
    h5 = out + '/d3plot.h5'
    st = h5_last_state(h5)
    s = h5_dataset(h5, f'/states/{st}/stress')
    ne = len(s)//6
    sig = [s[6*e:6*e + 6] for e in range(ne)]
    smax = max(abs(x) for x in sig[0])
    ds = max(abs(sig[e][k] - sig[0][k]) for e in range(ne) for k in range(6))/smax
    print(f'element stresses: largest relative spread {ds:.3e} (tol {tol_s})')
    # mean strain from the displacement of the corners: u = (F - I) x0, F from nodes 1, 2, 4
    u = h5_dataset(h5, f'/states/{st}/displacement')
    x0 = h5_dataset(h5, '/mesh/coordinates')
    ux2, uy2 = u[3], u[4]
    ux4, uy4 = u[9], u[10]
    hx, hy = x0[3], x0[10]
    exx, eyy = ux2/hx, uy4/hy
    exy = 0.5*(uy2/hx + ux4/hy)
    lam, mu = E*NU/((1 + NU)*(1 - 2*NU)), E/(2*(1 + NU))
    ref = [lam*(exx + eyy) + 2*mu*exx, lam*(exx + eyy) + 2*mu*eyy, lam*(exx + eyy),
           2*mu*exy, 0.0, 0.0]
    if plane_stress:
        e1 = E/(1 - NU*NU)
        ref = [e1*(exx + NU*eyy), e1*(eyy + NU*exx), 0.0, 2*mu*exy, 0.0, 0.0]
    da = max(abs(sig[0][k] - ref[k]) for k in range(6))/max(abs(x) for x in ref)
    print(f'stress against {"plane-stress" if plane_stress else "plane-strain"} Hooke of the mean strain: {da:.3e} (tol {tol_a}); '
          f'sigma = {[round(x, 6) for x in sig[0][:4]]}, ref {[round(x, 6) for x in ref[:4]]}')
    if dv > tol_v or ds > tol_s or da > tol_a:
        fail('patch test')


def lame_ur(r):
    """plane-strain Lame radial displacement"""
    a2, b2 = A_IN**2, B_OUT**2
    ca = P_IN*a2/(b2 - a2)
    cb = P_IN*a2*b2/(b2 - a2)
    return (1 + NU)/E*((1 - 2*NU)*ca*r + cb/r)


def mean_ur(out, t0):
    d = nodout(out)
    res = []
    for n in sorted(d):
        rows = [r for r in d[n] if r[0] >= t0]
        x0 = rows[0][4][0] - rows[0][1][0], rows[0][4][1] - rows[0][1][1]
        r0 = math.hypot(*x0)
        ur = [(r[1][0]*x0[0] + r[1][1]*x0[1])/r0 for r in rows]
        res.append((r0, sum(ur)/len(ur)))
    return res


def lame(outs, t0, tol, order_min):
    errs = []
    for out in outs:
        (ra, ua), (rb, ub) = sorted(mean_ur(out, t0))
        ea = (ua - lame_ur(ra))/lame_ur(ra)
        eb = (ub - lame_ur(rb))/lame_ur(rb)
        errs.append((abs(ea), abs(eb)))
        print(f'{out}: u_r(a) = {ua:.6e} (Lame {lame_ur(ra):.6e}, err {ea:+.3e}); '
              f'u_r(b) = {ub:.6e} (Lame {lame_ur(rb):.6e}, err {eb:+.3e})')
    orders = [math.log(errs[k][0]/errs[k + 1][0], 2) for k in range(len(errs) - 1)]
    print('observed order (inner radius, halving h): ' + ', '.join(f'{o:.2f}' for o in orders))
    if order_min <= 0.0:      # errors at the floor of the averaging: every mesh within tol
        if max(max(e) for e in errs) > tol:
            fail(f'error {max(max(e) for e in errs):.3e} above {tol} on some mesh')
        return
    if max(errs[-1]) > tol:
        fail(f'finest error {max(errs[-1]):.3e} above {tol}')
    if min(orders) < order_min:
        fail(f'observed order {min(orders):.2f} below {order_min}')


def lame1(out, t0, tol):
    (ra, ua), (rb, ub) = sorted(mean_ur(out, t0))
    ea = (ua - lame_ur(ra))/lame_ur(ra)
    eb = (ub - lame_ur(rb))/lame_ur(rb)
    print(f'{out}: u_r(a) err {ea:+.3e}, u_r(b) err {eb:+.3e} (tol {tol})')
    if max(abs(ea), abs(eb)) > tol:
        fail('Lame error')


def bar(out, tol_c, ymin, vend=1.0):
    """front of a velocity step in a round bar: the time the axial velocity of each axis
    history node first reaches vend/2 (linear between nodout lines); its motion is the
    bar speed sqrt(E/rho) (Skalak 1957: the mid-point of the step's head travels at c0)."""
    d = nodout(out)
    c = math.sqrt(E/RHO)
    pts = []
    for n in sorted(d):
        rows = d[n]
        y0 = rows[0][4][1] - rows[0][1][1]
        if y0 < ymin:
            continue
        for r0, r1 in zip(rows, rows[1:]):
            a, b = r0[2][1] - vend/3.0, r1[2][1] - vend/3.0
            if a < 0.0 <= b:
                pts.append((y0, r0[0] + (r1[0] - r0[0])*(-a)/(b - a)))
                break
    if len(pts) < 3:
        fail('the front reached fewer than 3 history nodes')
    n = len(pts)
    my = sum(p[0] for p in pts)/n
    mt = sum(p[1] for p in pts)/n
    slope = sum((p[0] - my)*(p[1] - mt) for p in pts)/sum((p[0] - my)**2 for p in pts)
    cf = 1.0/slope
    print('front (y, t): ' + ', '.join(f'({y:.0f}, {t:.5f})' for y, t in pts))
    print(f'front speed {cf:.1f} mm/ms over {n} nodes, bar speed sqrt(E/rho) {c:.1f}: '
          f'{cf/c - 1:+.3e} (tol {tol_c})')
    if abs(cf/c - 1) > tol_c:
        fail('front speed')


def front_times(out, ymin, vend=1.0):
    """{y: time the axial velocity of the axis history node at y >= ymin reaches vend/3}"""
    res = {}
    for n, rows in nodout(out).items():
        x0 = [rows[0][4][k] - rows[0][1][k] for k in range(3)]
        if x0[1] < ymin or abs(x0[0]) + abs(x0[2]) > 0.0:
            continue
        for r0, r1 in zip(rows, rows[1:]):
            a, b = r0[2][1] - vend/3.0, r1[2][1] - vend/3.0
            if a < 0.0 <= b:
                res[round(x0[1], 6)] = r0[0] + (r1[0] - r0[0])*(-a)/(b - a)
                break
    return res


def barcmp(out2, out3, tol_t, ymin):
    t2, t3 = front_times(out2, ymin), front_times(out3, ymin)
    ys = sorted(set(t2) & set(t3))
    if len(ys) < 3:
        fail('fewer than 3 axis nodes reached by both fronts')
    dt = max(abs(t2[y] - t3[y]) for y in ys)
    print('front arrival (y: 2D, 3D): ' + ', '.join(f'{y:.0f}: {t2[y]:.5f}, {t3[y]:.5f}'
                                                   for y in ys))
    print(f'largest difference {dt:.3e} ms (tol {tol_t})')
    if dt > tol_t:
        fail('2D and 3D fronts differ')


def taylor(out, lf_ref, tol_l, rf_ref, tol_r):
    """Taylor bar (gen_quad2d_decks.py taylor): final length = y of the top axis node, foot
    radius = x of the bottom corner node (the two history nodes), last nodout line."""
    d = nodout(out)
    top, foot = sorted(d)[1], sorted(d)[0]
    lf = d[top][-1][4][1]
    rf = d[foot][-1][4][0]
    el, er = lf/lf_ref - 1.0, rf/rf_ref - 1.0
    print(f'{out}: Lf = {lf:.4f} mm ({el:+.3e} of {lf_ref}, tol {tol_l}), Rf = {rf:.4f} mm '
          f'({er:+.3e} of {rf_ref}, tol {tol_r})')
    if abs(el) > tol_l or abs(er) > tol_r:
        fail('Taylor bar')


def taylor2(out, lf_ref, tol_l, rf_ref, tol_r, pen_max):
    """Two Taylor bars head on (gen_nr2d_decks.py taylor2): bar A's final length (its top
    axis node's y, the node of largest initial y) and foot radius (x of its contact face's
    outer corner) against the rigid wall's, and the overlap of the two contact faces: by
    symmetry twice the largest depth of bar A's face nodes below y = 0 over the nodout
    records (sampled every 0.2 us); below pen_max (mm)."""
    d = nodout(out)
    y0 = {n: r[0][4][1] for n, r in d.items()}
    top = max(d, key=lambda n: y0[n])
    face = [n for n in d if y0[n] < 0.01]
    foot = max(face, key=lambda n: d[n][0][4][0])
    lf, rf = d[top][-1][4][1], d[foot][-1][4][0]
    pen = max(max(-2.0*r[4][1] for r in d[n]) for n in face)
    el, er = lf/lf_ref - 1.0, rf/rf_ref - 1.0
    print(f'{out}: Lf = {lf:.4f} mm ({el:+.3e} of {lf_ref}, tol {tol_l}), Rf = {rf:.4f} mm '
          f'({er:+.3e} of {rf_ref}, tol {tol_r}), largest overlap of the faces {pen:.4e} mm '
          f'(limit {pen_max})')
    if abs(el) > tol_l or abs(er) > tol_r or pen > pen_max:
        fail('Taylor bars head on')


def energy(out, band, after):
    worst = 0.0
    for r in read_table(out + '/glstat'):
        if r[0] >= after:
            worst = max(worst, abs(r[9] - 1.0))
    print(f'energy ratio: largest |ratio - 1| = {worst:.3e} after t = {after} (band {band})')
    zmax = 0.0
    for rows in nodout(out).values():
        for r in rows:
            zmax = max(zmax, abs(r[1][2]), abs(r[2][2]), abs(r[3][2]), abs(r[4][2]))
    print(f'z components in nodout: largest {zmax:.3e} (must be 0)')
    if worst > band or zmax != 0.0:
        fail('energy or z components')


if __name__ == '__main__':
    w = sys.argv[1]
    if w in ('patch', 'patchps'):
        patch(sys.argv[2], sys.argv[3], *map(float, sys.argv[4:7]), plane_stress=w == 'patchps')
    elif w == 'lame':
        lame(sys.argv[2:5], float(sys.argv[5]), float(sys.argv[6]), float(sys.argv[7]))
    elif w == 'lame1':
        lame1(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
    elif w == 'bar':
        bar(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
    elif w == 'barcmp':
        barcmp(sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5]))
    elif w == 'taylor2':
        taylor2(sys.argv[2], *map(float, sys.argv[3:8]))
    elif w == 'taylor':
        taylor(sys.argv[2], *map(float, sys.argv[3:7]))
    elif w == 'energy':
        energy(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]) if len(sys.argv) > 4 else 0.0)
    else:
        raise SystemExit(__doc__)
