#!/usr/bin/python3
"""Checks of the rigid-body contact scenes (reads OUTDIR/rbdout, OUTDIR/glstat; numpy only).
Each prints what it measured and exits 1 when a check fails.

  scene_check.py incline OUTDIR --theta DEG --mu MU --body ID --mode roll|slide|stick
                 --tol-a T [--tol-alpha T] [--t0 0.02] [--R 0.05] [--g 9.81]
      acceleration along the slope (+x) of the body's centre and the angular acceleration
      about +y, from least-squares quadratics x(t) = c0 + c1 t + a t^2/2 and
      phi(t) = ... + alpha t^2/2 (phi the trapezoidal integral of w_y) over t >= t0,
      against: roll  a = 5/7 g sin(theta), alpha = a/R (sphere, tan(theta) <= 3.5 mu);
               slide a = g (sin(theta) - mu cos(theta)), alpha = 5 mu g cos(theta)/(2R)
                     (sphere) or 0 (block, --tol-alpha absolute then);
               stick a = 0 (block, tan(theta) <= mu): |a| / (g sin(theta)) <= tol-a.
      Relative tolerances (of the reference value) except for stick and a zero alpha.
  scene_check.py energy OUTDIR --band B [--after T] [--drift D]
      glstat total energy (kinetic + internal + hourglass + rigid wall + sliding interface,
      i.e. ratio * (E0 + W_ext)) within 1 +- B of its first value after T; with --drift also
      |mean of the last quarter - mean of the first quarter| / E <= D.
  scene_check.py box OUTDIR [--body 2] [--band B] [--drift D] [--min-bounces N] [--dat FILE]
      ball in a box (frictionless, no gravity): the mechanical energy is the ball's kinetic
      energy (rbdout ke) at the output times when no node is in contact (rcforc nactive = 0;
      in contact the stored penalty energy is not separable). Reports the number of wall
      impacts (sign reversals of the centre's velocity components), max |KE/KE0 - 1| over the contact-free samples (<= B), the final
      drift KE_end/KE0 - 1 (|.| <= D), and the energy ratio band of glstat; --dat writes
      "time KE/KE0-1 in_contact" rows for plotting.
"""
import argparse
import math
import sys

import numpy as np


def read_rbdout(d):
    return np.array([[float(v) for v in l.split()] for l in open(d + '/rbdout')
                     if l.lstrip()[:1] in tuple('+-.0123456789')])


def read_glstat(d):
    return np.array([[float(v) for v in l.split()] for l in open(d + '/glstat')
                     if l.lstrip()[:1] in tuple('+-.0123456789')])


def result(name, value, tol, ok):
    print('%-52s %.6e  (tolerance %.3e)  %s' % (name, value, tol, 'ok' if ok else 'FAIL'))
    return ok


def quad_acc(t, y):
    c = np.polyfit(t, y, 2)
    return 2.0 * c[0]


def incline(a):
    th = math.radians(a.theta)
    r = read_rbdout(a.outdir)
    r = r[r[:, 1] == a.body]
    t, x, wy = r[:, 0], r[:, 2], r[:, 9]
    phi = np.concatenate([[0.0], np.cumsum(0.5 * (wy[1:] + wy[:-1]) * np.diff(t))])
    m = t >= a.t0
    acc, alpha = quad_acc(t[m], x[m]), quad_acc(t[m], phi[m])
    g = a.g
    ok = True
    if a.mode == 'stick':
        ok &= result('stick: |a| / (g sin theta)', abs(acc) / (g * math.sin(th)), a.tol_a,
                     abs(acc) / (g * math.sin(th)) <= a.tol_a)
        print('  a = %.6g m/s^2' % acc)
        return ok
    if a.mode == 'roll':
        aref = 5.0 / 7.0 * g * math.sin(th)
        alref = aref / a.R
    else:
        aref = g * (math.sin(th) - a.mu * math.cos(th))
        alref = 5.0 * a.mu * g * math.cos(th) / (2.0 * a.R) if a.sphere else 0.0
    print('  a = %.6g (reference %.6g), alpha = %.6g (reference %.6g)' % (acc, aref, alpha, alref))
    ok &= result('%s: a rel. error' % a.mode, abs(acc / aref - 1), a.tol_a,
                 abs(acc / aref - 1) <= a.tol_a)
    if a.tol_alpha is not None:
        if alref == 0.0:
            ok &= result('%s: |alpha| (rad/s^2)' % a.mode, abs(alpha), a.tol_alpha,
                         abs(alpha) <= a.tol_alpha)
        else:
            ok &= result('%s: alpha rel. error' % a.mode, abs(alpha / alref - 1), a.tol_alpha,
                         abs(alpha / alref - 1) <= a.tol_alpha)
    return ok


def energy(a):
    gl = read_glstat(a.outdir)
    t = gl[:, 0]
    # total incl. sliding energy and rigid-wall energy: the numerator of the energy ratio
    tot = gl[:, 8] + gl[:, 7] + gl[:, 13]
    m = t >= a.after
    e0 = tot[m][0]
    dev = np.abs(tot[m] / e0 - 1).max()
    ok = result('energy: max |E/E0 - 1|', dev, a.band, dev <= a.band)
    if a.drift is not None:
        q = max(1, m.sum() // 4)
        d = abs(tot[m][-q:].mean() - tot[m][:q].mean()) / e0
        ok &= result('energy: |mean(last 1/4) - mean(first 1/4)| / E0', d, a.drift,
                     d <= a.drift)
    return ok


def box(a):
    r = read_rbdout(a.outdir)
    r = r[r[:, 1] == a.body]
    rc = np.array([[float(v) for v in l.split()] for l in open(a.outdir + '/rcforc')
                   if l.lstrip()[:1] in tuple('+-.0123456789')])
    t, ke = r[:, 0], r[:, 17]
    # contact state at the rbdout times: the rcforc row at the same output time
    # (nearest rcforc row; a contact between two output times is caught by either
    # neighbour being active, so the contact-free samples are free on both sides)
    i1 = np.clip(np.searchsorted(rc[:, 0], t), 0, len(rc) - 1)
    i0 = np.clip(i1 - 1, 0, len(rc) - 1)
    act = (rc[i0, 8] > 0) | (rc[i1, 8] > 0)
    free = ~act
    # wall impacts: reversals of a velocity component of the centre (a corner counts 2-3)
    v = r[:, 5:8]
    bounces = int(np.sum((v[1:] * v[:-1]) < 0.0))
    dev = ke[free] / ke[0] - 1.0
    gl = read_glstat(a.outdir)
    ratio = np.abs(gl[:, 9] - 1.0).max()
    print('  bounces %d, contact-free samples %d of %d, KE0 %.10g, KE_end %.10g'
          % (bounces, free.sum(), len(t), ke[0], ke[free][-1]))
    print('  max |KE/KE0 - 1| %.4e, final KE/KE0 - 1 %+.4e, max |energy ratio - 1| %.4e'
          % (np.abs(dev).max(), dev[-1], ratio))
    if a.dat:
        with open(a.dat, 'w') as f:
            f.write('# time KE/KE0-1 in_contact\n')
            for ti, ki, ci in zip(t, ke / ke[0] - 1.0, act):
                f.write('%.6e %.6e %d\n' % (ti, ki, ci))
    ok = True
    if a.min_bounces:
        ok &= result('box: bounces (at least)', bounces, a.min_bounces, bounces >= a.min_bounces)
    if a.band is not None:
        ok &= result('box: max |KE/KE0 - 1| out of contact', np.abs(dev).max(), a.band,
                     np.abs(dev).max() <= a.band)
    if a.drift is not None:
        ok &= result('box: |KE_end/KE0 - 1|', abs(dev[-1]), a.drift, abs(dev[-1]) <= a.drift)
    if a.ratio is not None:
        ok &= result('box: max |energy ratio - 1|', ratio, a.ratio, ratio <= a.ratio)
    return ok


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('incline')
    p.add_argument('outdir')
    p.add_argument('--theta', type=float, required=True)
    p.add_argument('--mu', type=float, required=True)
    p.add_argument('--body', type=int, required=True)
    p.add_argument('--mode', choices=['roll', 'slide', 'stick'], required=True)
    p.add_argument('--sphere', action='store_true')
    p.add_argument('--tol-a', type=float, required=True)
    p.add_argument('--tol-alpha', type=float)
    p.add_argument('--t0', type=float, default=0.02)
    p.add_argument('--R', type=float, default=0.05)
    p.add_argument('--g', type=float, default=9.81)
    p = sub.add_parser('energy')
    p.add_argument('outdir')
    p.add_argument('--band', type=float, required=True)
    p.add_argument('--after', type=float, default=0.0)
    p.add_argument('--drift', type=float)
    p = sub.add_parser('box')
    p.add_argument('outdir')
    p.add_argument('--body', type=int, default=2)
    p.add_argument('--band', type=float)
    p.add_argument('--drift', type=float)
    p.add_argument('--ratio', type=float)
    p.add_argument('--min-bounces', type=int, default=0)
    p.add_argument('--dat')
    a = ap.parse_args()
    ok = {'incline': incline, 'energy': energy, 'box': box}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
