#!/usr/bin/env python3
"""Checks of the contact scenes from dynx output (standard library only).

  contact_post.py rod OUTDIR [--L 100 --v 10 --rho 7.85e-6 --E 210 --A 1 --nx 100]
      contact duration (first to last rcforc line with a force) against 2L/c, the force
      plateau against rho*c*v*A/2, the velocities after release (nodout, lumped-mass
      averages per rod: striker 0, target v) and the energy ratio (glstat).
  contact_post.py hertz OUTDIR --R R --E E --nu NU --F F ...   (see hertz())
  contact_post.py spikes OUTDIR --id ID --comp x|y|z  largest jump of a force component
Each check prints value, reference, difference and PASS/FAIL; exit 1 when one fails."""
import argparse, math, os, sys


def table(path):
    names, rows = None, []
    for line in open(path):
        if line.lstrip()[:1] not in tuple('+-.0123456789'):
            # a header line: '# time ...' or the names line without '#' (gnuplot's
            # columnhead form, docs/output-format.md)
            toks = line.lstrip('#').split()
            if toks and toks[0] == 'time':
                names = toks
            continue
        if line.strip():
            rows.append([float(x) for x in line.split()])
    return names, rows


def report(name, value, ref, abs_tol, rel_tol):
    ok = math.isfinite(value) and abs(value - ref) <= abs_tol + rel_tol * abs(ref)
    print('%-40s %14.6g   reference %14.6g   diff %10.3g   tol %.3g + %.3g*|ref|   %s'
          % (name, value, ref, value - ref, abs_tol, rel_tol, 'PASS' if ok else 'FAIL'))
    return ok


def rod(a):
    c = math.sqrt(a.E / a.rho)
    t2 = 2.0 * a.L / c
    names, rows = table(os.path.join(a.out, 'rcforc'))
    fx, na = names.index('slave_x'), names.index('nactive')
    on = [r[0] for r in rows if r[na] > 0]
    dur = on[-1] - on[0]
    ok = True
    ok &= report('contact duration [ms] vs 2L/c', dur, t2, 0.0, a.tol_dur)
    if not a.single:
        # the force plateau: median of the force while in contact (single surface: the
        # slave and master sides are the same surface, their resultants cancel)
        win = [r for r in rows if on[0] + 0.1 * t2 <= r[0] <= on[0] + 0.9 * t2]
        if a.force_stat == 'median':
            mid = sorted(abs(r[fx]) for r in win)
            fplat = mid[len(mid) // 2]
        else:
            # time average (trapezoid) over the window: robust against penalty ringing
            imp = sum(0.5 * (abs(p[fx]) + abs(q[fx])) * (q[0] - p[0]) for p, q in zip(win, win[1:]))
            fplat = imp / (win[-1][0] - win[0][0])
        ok &= report('force plateau (%s) [kN] vs rho c v A/2' % a.force_stat, fplat,
                     a.rho * c * a.v * a.A / 2, 0.0, 0.02)
    # velocities after release: lumped-mass average per rod (end nodes carry half weight)
    names, rows = table(os.path.join(a.out, 'nodout'))
    tcol, ncol, vcol = names.index('time'), names.index('node_id'), names.index('x_vel')
    tlast = rows[-1][tcol]
    last = {int(r[ncol]): r[vcol] for r in rows if r[tcol] == tlast}
    nper = 4 * (a.nx + 1)
    vrod = []
    for rod_i in range(2):
        num = den = 0.0
        for n in range(1 + rod_i * nper, 1 + (rod_i + 1) * nper):
            i = (n - 1 - rod_i * nper) % (a.nx + 1)
            wgt = 1.0 if i in (0, a.nx) else 2.0
            num += wgt * last[n]
            den += wgt
        vrod.append(num / den)
    ok &= report('striker velocity after release [m/s]', vrod[0], 0.0, a.tol_v * a.v, 0.0)
    ok &= report('target velocity after release [m/s]', vrod[1], a.v, 0.0, a.tol_v)
    names, rows = table(os.path.join(a.out, 'glstat'))
    r = names.index('energy_ratio')
    lo, hi = min(x[r] for x in rows), max(x[r] for x in rows)
    print('energy ratio min %.6f max %.6f final %.6f' % (lo, hi, rows[-1][r]))
    ok &= report('largest energy ratio error', max(1 - lo, hi - 1), 0.0, a.tol_e, 0.0)
    return ok


def hertz(a):
    """Contact radius a and peak pressure p0 from the last plot state: p = -sigma_zz of the
    block's top element layer (centroids at depth h/2) fitted by the Hertz ellipse
    p^2 = p0^2 (1 - r^2/a^2) (least squares of p^2 against r^2 over the elements with
    p > 0.3 max p); the force F from rcforc (mean of the last 10 % of the run, x4 for the
    quarter model), or for an implicit static run (no rcforc) the last step's spcforc z
    resultant (x4). Hertz (Johnson 1985, ch. 4): a = (3 F R/(4 E*))^(1/3), p0 = 3F/(2 pi a^2)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import dxpost
    h5 = os.path.join(a.out, 'd3plot.h5')
    times = dxpost.states(h5)
    k = len(times)
    _, xyz = dxpost.dataset(h5, dxpost.state_path(k) + '/coordinates')
    _, sig = dxpost.dataset(h5, dxpost.state_path(k) + '/stress')
    _, conn = dxpost.dataset(h5, '/mesh/hex8')
    _, pid = dxpost.dataset(h5, '/mesh/part_ids')
    ne = len(pid)
    x = dxpost.vec3(xyz)
    cents = []
    for e in range(ne):
        if pid[e] != 1:
            continue
        nodes = conn[8 * e:8 * e + 8]
        c = [sum(x[n][q] for n in nodes) / 8.0 for q in range(3)]
        ztop = max(x[n][2] for n in nodes)
        cents.append((e, c, ztop))
    zmax = max(z for _, _, z in cents)
    top = [(math.hypot(c[0], c[1]), -sig[6 * e + 2]) for e, c, z in cents
           if z > zmax - 0.2 * a.zone / a.n - 1e-9 and c[2] > zmax - a.zone / a.n]
    pmax = max(p for _, p in top)
    pts = [(r * r, p * p) for r, p in top if p > 0.3 * pmax]
    n = len(pts)
    mx = sum(u for u, _ in pts) / n
    my = sum(v for _, v in pts) / n
    sxx = sum((u - mx) ** 2 for u, _ in pts)
    sxy = sum((u - mx) * (v - my) for u, v in pts)
    slope = sxy / sxx
    p0 = math.sqrt(my - slope * mx)
    arad = math.sqrt(-(my - slope * mx) / slope)
    if os.path.exists(os.path.join(a.out, 'rcforc')):
        names, rows = table(os.path.join(a.out, 'rcforc'))
        fz = names.index('master_z')
        tl = rows[-1][0]
        last = [abs(r[fz]) for r in rows if r[0] >= 0.9 * tl]
        F = 4.0 * sum(last) / len(last)
    else:    # an implicit static run: the z resultant of the last step's SPC reactions (the
        # block's fixed bottom; the symmetry planes take no z force)
        res = [l for l in open(os.path.join(a.out, 'spcforc')) if 'force resultants' in l][-1]
        F = 4.0 * abs(float(res.split('=')[1].split()[2]))
    estar = a.E / (2.0 * (1.0 - a.nu ** 2))
    ah = (3.0 * F * a.R / (4.0 * estar)) ** (1.0 / 3.0)
    p0h = 3.0 * F / (2.0 * math.pi * ah * ah)
    print('force F = %.6g kN (full model), %d top elements in the fit, max element p %.4g GPa'
          % (F, n, pmax))
    ok = report('contact radius a [mm] vs Hertz', arad, ah, 0.0, a.tol)
    ok &= report('peak pressure p0 [GPa] vs Hertz', p0, p0h, 0.0, a.tol)
    if a.csv:
        with open(a.csv, 'a') as f:
            f.write('%s %.6g %.6g %.6g %.6g %.6g\n' % (a.out, F, arad, ah, p0, p0h))
    return ok


def slide(a):
    """Block on a plate (gen_contact_decks.py slide): with friction, the block's centre node
    decelerates at mu F/m (least-squares slope of vx over the sliding phase) and the
    tangential/normal force ratio is mu; frictionless, vx stays v0, the tangential force is
    zero and the normal force has no spikes while the nodes cross the plate's segment edges."""
    names, rows = table(os.path.join(a.out, 'nodout'))
    t, vx = names.index('time'), names.index('x_vel')
    pts = [(r[t], r[vx]) for r in rows if r[t] >= 0.1 * a.tend and r[vx] > 0.05 * a.v]
    n = len(pts)
    mt = sum(p[0] for p in pts) / n
    mv = sum(p[1] for p in pts) / n
    slope = sum((p[0] - mt) * (p[1] - mv) for p in pts) / sum((p[0] - mt) ** 2 for p in pts)
    names, rows = table(os.path.join(a.out, 'rcforc'))
    fx, fz = names.index('slave_x'), names.index('slave_z')
    late = [r for r in rows if r[0] >= 0.2 * a.tend]
    mfz = sum(r[fz] for r in late) / len(late)
    ok = report('mean normal force [kN] vs load F', mfz, a.F, 0.0, 0.02)
    if a.mu > 0:
        ok &= report('deceleration [m/s/ms] vs mu F/m', -slope, a.mu * a.F / a.m, 0.0, 0.03)
        ratio = sorted(abs(r[fx] / r[fz]) for r in late if r[fz] > 0)
        ok &= report('median |f_t|/f_n vs mu', ratio[len(ratio) // 2], a.mu, 0.0, 0.01)
    else:
        ok &= report('velocity change [m/s] (frictionless)', rows and pts[-1][1] - a.v, 0.0,
                     1e-3 * a.v, 0.0)
        ok &= report('largest |f_t| / F (frictionless)', max(abs(r[fx]) for r in rows) / a.F,
                     0.0, 1e-3, 0.0)
        ok &= report('largest f_n / F after settling (no spikes)',
                     max(r[fz] for r in late) / a.F, 1.0, 0.5, 0.0)
    return ok


def conserve(a):
    """Energy ratio band and x momentum conservation over the run (glstat)."""
    names, rows = table(os.path.join(a.out, 'glstat'))
    r, px = names.index('energy_ratio'), names.index('xmom')
    lo, hi = min(x[r] for x in rows), max(x[r] for x in rows)
    print('energy ratio min %.6f max %.6f final %.6f' % (lo, hi, rows[-1][r]))
    ok = report('largest energy ratio error', max(1 - lo, hi - 1), 0.0, a.tol_e, 0.0)
    p0 = rows[0][px]
    ok &= report('largest x momentum change / initial', max(abs(x[px] - p0) for x in rows) / abs(p0),
                 0.0, a.tol_p, 0.0)
    return ok


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('rod'); p.add_argument('out')
    p.add_argument('--L', type=float, default=100.0)
    p.add_argument('--v', type=float, default=10.0)
    p.add_argument('--rho', type=float, default=7.85e-6)
    p.add_argument('--E', type=float, default=210.0)
    p.add_argument('--A', type=float, default=1.0)
    p.add_argument('--nx', type=int, default=100)
    p.add_argument('--tol-dur', type=float, default=0.03)
    p.add_argument('--tol-v', type=float, default=0.03)
    p.add_argument('--tol-e', type=float, default=0.01)
    p.add_argument('--single', action='store_true', help='single surface: no force check')
    p.add_argument('--force-stat', choices=('median', 'mean'), default='median',
                   help='plateau statistic: median of the samples, or time average (ringing cases)')
    p = sub.add_parser('hertz'); p.add_argument('out')
    p.add_argument('--R', type=float, default=10.0)
    p.add_argument('--E', type=float, default=210.0)
    p.add_argument('--nu', type=float, default=0.3)
    p.add_argument('--n', type=int, default=12)
    p.add_argument('--zone', type=float, default=1.0)
    p.add_argument('--tol', type=float, default=0.05)
    p.add_argument('--csv')
    p = sub.add_parser('slide'); p.add_argument('out')
    p.add_argument('--mu', type=float, default=0.2)
    p.add_argument('--F', type=float, default=0.02)
    p.add_argument('--m', type=float, default=8.0 * 7.85e-6)
    p.add_argument('--v', type=float, default=20.0)
    p.add_argument('--tend', type=float, default=0.2)
    p = sub.add_parser('conserve'); p.add_argument('out')
    p.add_argument('--tol-e', type=float, default=0.01)
    p.add_argument('--tol-p', type=float, default=1e-9)
    a = ap.parse_args()
    ok = {'rod': rod, 'hertz': hertz, 'slide': slide, 'conserve': conserve}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
