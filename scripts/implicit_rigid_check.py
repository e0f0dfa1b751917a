#!/usr/bin/python3
"""Checks of the implicit rigid-body cases (issue 20; decks from scripts/gen_implicit_rigid.py);
one line per quantity, exit 1 when a check fails. Usage:
implicit_rigid_check.py punch|twist|torsion OUTDIR (OUTDIR holds the case deck's run; the
companion decks of the case run into OUTDIR/<name>)."""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dxpost import report, columns  # noqa: E402
from implicit_check import run, nodout, newton_ratios, fit_recurrence, hht_roots, CASES  # noqa: E402
from contact_implicit_check import resultants  # noqa: E402


def companions(case, out, names):
    """Run the case's companion decks NAME.k into OUT/NAME; their output directories."""
    dirs = []
    for n in names:
        d = os.path.join(out, n)
        run(os.path.join(CASES, case, n + '.k'), d)
        dirs.append(d)
    return dirs


def log_of(out):
    for n in ('stdout', 'log'):
        p = os.path.join(out, n)
        if os.path.exists(p):
            return p
    raise SystemExit('implicit_rigid_check: no log in %s' % out)


def iterations(out):
    return sum(len(q) for q in newton_ratios(log_of(out)))


def quadratic(out, cap=10.0, floor=1e-13):
    """Every pair of successive residual ratios with q_k <= 1e-2 and q_(k+1) above the
    round-off floor has q_(k+1) <= cap q_k^2, at least one pair a step (a linear rate of 0.1
    or slower fails for every q_k <= 1e-2)."""
    ok = True
    for i, q in enumerate(newton_ratios(log_of(out))):
        pairs = [(q[k], q[k + 1]) for k in range(len(q) - 1) if q[k] <= 1e-2 and q[k + 1] > floor]
        worst = max(b/(a*a) for a, b in pairs) if pairs else float('inf')
        good = len(pairs) >= 1 and worst <= cap
        print('step %d: residual ratios %s  max q(k+1)/q(k)^2 %.3g  %s'
              % (i + 1, ' '.join('%.2e' % x for x in q), worst, 'PASS' if good else 'FAIL'))
        ok &= good
    return ok


def punch(out):
    """A rigid punch (*MAT_RIGID, CON1 = 4, CON2 = 7, *BOUNDARY_PRESCRIBED_MOTION_RIGID VAD 2
    along z) pressed 0.05 into an elastic block through NODES_TO_SURFACE penalty contact (the
    punch's nodes slaves: pairs with a rigid slave node and deformable master nodes).
    (1) the base's reaction Fz (spcforc) against the same punch made elastic with E x 1e3
    (stiff.k) and x 1e5 (stiffer.k), pushed by its top nodes: the elastic punch's force
    tends to the rigid one as 1/E_punch (its own compliance): the difference must shrink by
    at least 30x (measured 97x: -0.70 % then -0.0072 %) and end below 1e-3 relative.
    (2) the punch's bottom nodes move by exactly the prescribed -0.05 (1e-12).
    (3) Newton: no more iterations than the stiff elastic punch's + 2 (measured 23 against
    21; the linear tail of the last steps is the faceted contact's, the elastic punch has it
    too)."""
    st, sr = companions('implicit_rigid_punch', out, ['stiff', 'stiffer'])
    fr, f1, f2 = [resultants(d)[-1][2] for d in (out, st, sr)]
    d1, d2 = f1 - fr, f2 - fr
    print('Fz rigid %.8g, E x 1e3 %.8g (%+.3e), E x 1e5 %.8g (%+.3e), ratio %.1f'
          % (fr, f1, d1/fr, f2, d2/fr, abs(d1/d2) if d2 else float('inf')))
    ratio = abs(d1/d2) if d2 else math.inf
    ok = ratio >= 30
    print('difference ratio %.1f >= 30: %s' % (ratio, 'PASS' if ok else 'FAIL'))
    ok &= report('(F(1e5) - F)/F', d2/fr, 0.0, 1e-3, 0.0)
    hist = nodout(out)
    worst = max(abs(r[3] + 0.05*r[0]) for n, rec in hist.items() if n > 1000 for r in rec)
    ok &= report('punch node z displacement - (-0.05 t) (max over steps)', worst, 0.0, 1e-12, 0.0)
    ni, ns = iterations(out), iterations(st)
    print('Newton iterations: rigid %d, stiff elastic %d' % (ni, ns))
    ok &= ni <= ns + 2
    return ok


def twist(out):
    """A rigid plate (CON1 = CON2 = 0: six free body equations) on the top of an elastic
    block (shared nodes), turned by a nodal couple to ~0.23 rad in 5 steps (large rotation).
    (1) rigidity: the plate's corner keeps its distance to the plate's centre node (1e-9:
    nodout prints 11 digits; measured 3.7e-11).
    (2) the corner's rotation angle against the plate made elastic with E x 1e3 / 1e5: the
    difference shrinks by >= 30x (1/E: measured 71x: -7.3e-5 then -1.0e-6) and ends below
    1e-4 relative.
    (3) quadratic convergence in every step (quadratic(); measured q(k+1)/q(k)^2 <= 0.02): the
    arms' rotation term -sum [v]x[r]x in the tangent and the spatial rotation update."""
    st, sr = companions('implicit_rigid_twist', out, ['stiff', 'stiffer'])

    def angle(d):
        rec = nodout(d)[1018][-1]
        return math.atan2(rec[5], rec[4]) - math.pi/4
    ar, a1, a2 = angle(out), angle(st), angle(sr)
    d1, d2 = a1 - ar, a2 - ar
    print('corner angle rigid %.10f rad, E x 1e3 %.10f (%+.3e), E x 1e5 %.10f (%+.3e), ratio %.1f'
          % (ar, a1, d1/ar, a2, d2/ar, abs(d1/d2)))
    ok = abs(d1/d2) >= 30
    print('difference ratio %.1f >= 30: %s' % (abs(d1/d2), 'PASS' if ok else 'FAIL'))
    ok &= report('(angle(1e5) - angle)/angle', d2/ar, 0.0, 1e-4, 0.0)
    h = nodout(out)
    c0, c1 = h[1018][0], h[1018][-1]
    m0, m1 = h[1014][0], h[1014][-1]
    l0 = math.dist(c0[4:7], m0[4:7])
    l1 = math.dist(c1[4:7], m1[4:7])
    ok &= report('plate corner to centre distance after the twist', l1, l0, 1e-9, 0.0)
    ok &= quadratic(out)
    return ok


def torsion(out, alpha=-0.1):
    """A rigid plate (J_zz = m (a^2 + b^2)/12 = 0.8 x 8/12, only the spin about z free: CON1
    = 7, CON2 = 4) on a massless elastic block: one torsional mode, omega^2 = k/J with k the
    block's torsional stiffness from a static couple (static.k, same code: k = M/theta).
    Started with a spin 1e-4, the plate's rotation samples obey a two-term recurrence whose
    root is the scheme's principal amplification root at omega dt: fitted |lambda| and theta
    against hht_roots (the bar cases' theory) to 1e-10 (measured 1.3e-12 and 5e-13; the static
    k carries O(theta^2) ~ 1e-11 of nonlinearity and ~1e-11 of round-off; the block's mass is
    1e-12 of the plate's).
    The deck: HHT ALPHA -0.1 (numerical damping: |lambda| < 1 as the theory says);
    newmark.k: trapezoidal (|lambda| = 1, period elongation (omega dt/theta - 1) as theory;
    glstat's total energy constant to 1e-9: measured 3.8e-11)."""
    st, nm = companions('implicit_rigid_torsion', out, ['static', 'newmark'])
    rec = nodout(st)[1015][-1]
    th_s = math.atan2(rec[5], rec[4])
    k = 2e-3/th_s
    J = 0.8*(4.0 + 4.0)/12.0
    w = math.sqrt(k/J)
    ok = True
    for d, a, name in ((out, alpha, 'HHT ALPHA %g' % alpha), (nm, 0.0, 'Newmark')):
        recs = nodout(d)[1015]
        t = [r[0] for r in recs]
        th = [math.atan2(r[5], r[4]) for r in recs]
        dt = t[1] - t[0]
        r_fit, ph_fit = fit_recurrence(th, 10)
        r_th, ph_th = hht_roots(w, dt, a)
        print('%s: k %.8g, omega %.8g, omega dt %.6f, steps per period %.1f'
              % (name, k, w, w*dt, 2*math.pi/(w*dt)))
        ok &= report('%s |lambda| (amplitude ratio per step)' % name, r_fit, r_th, 1e-10, 0.0)
        ok &= report('%s theta (phase per step)' % name, ph_fit, ph_th, 0.0, 1e-10)
        print('%s: period elongation %.6g (theory %.6g), amplitude decay per period %.6g '
              '(theory %.6g)' % (name, w*dt/ph_fit - 1, w*dt/ph_th - 1,
                                 1 - r_fit**(2*math.pi/ph_fit), 1 - r_th**(2*math.pi/ph_th)))
    names, rows = columns(os.path.join(nm, 'glstat'))
    e = [r[names.index('total')] for r in rows]
    ok &= report('Newmark: energy drift max|E/E0 - 1|', max(abs(x/e[0] - 1) for x in e), 0.0,
                 1e-9, 0.0)
    return ok


if __name__ == '__main__':
    what, out = sys.argv[1], sys.argv[2]
    fn = {'punch': punch, 'twist': twist, 'torsion': torsion}[what]
    sys.exit(0 if fn(out) else 1)
