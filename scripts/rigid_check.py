#!/usr/bin/python3
"""Checks of rigid-body runs against analytic or reference solutions (reads OUTDIR/rbdout and
OUTDIR/glstat; numpy only). Each prints what it measured and exits 1 when a check fails.

  rigid_check.py spin OUTDIR --ip I1 I2 I3 [--mass M] --tol-l T --tol-ke T --tol-w T
      torque-free body: spatial angular momentum constant (relative), R orthogonal, kinetic
      energy within a relative band, body-frame angular velocity against an RK4 solution of
      Euler's equations (step = output interval/200) started from the first output row;
      principal moments from the rbdout header against --ip.
  rigid_check.py top OUTDIR --ip I1 I2 I3 --tol-rate T
      symmetric top (I2 = I3 in ascending principal order, symmetry axis = body axis 1):
      body-frame angular velocity turns about axis 1 at (I1 - I3)/I3 * w1 (least-squares slope
      of the unwrapped phase of (w2, w3)).
  rigid_check.py fall OUTDIR --g G --x0 X Y Z --v0 X Y Z --tol T
      x_c(t) = x0 + v0 t - g t^2/2 e_z and v_c(t + dt/2) = v0 - g (t + dt/2) e_z;
      with --node-x0 X Y Z also the nodout coordinates of the (deformable) history node.
  rigid_check.py momentum OUTDIR --axis K --force-curve T0 F0 T1 F1 ... --tol T
      glstat momentum component K against the impulse of a piecewise-linear force.
  rigid_check.py energy OUTDIR --band B [--after T]
      glstat energy ratio within 1 +- B (after time T).
  rigid_check.py punch OUTDIR --z0 Z --v V --ramp T --tol T
      prescribed rigid motion (velocity ramp to V over T, then constant) on the centre.
  rigid_check.py rotation OUTDIR --body ID --axis K --rate W --tol T
      prescribed rotation about global axis K by the angle W t, centre fixed.
  rigid_check.py mass OUTDIR --body ID --mass M --xc X Y Z --inertia XX XY XZ YY YZ ZZ --tol T
      mass properties in the rbdout header (relative to the largest value of each group);
      with --v0 VX VY VZ --w0 WX WY WZ also the first-row velocity and angular velocity.
"""
import argparse
import sys

import numpy as np


def read_rbdout(d):
    hdr, rows = {}, []
    for line in open(d + '/rbdout'):
        if line.startswith('# body'):
            p = line.split()
            hdr[int(p[2])] = dict(nodes=int(p[4]), mass=float(p[6]),
                                  xc=np.array([float(v) for v in p[8:11]]),
                                  inertia=np.array([float(v) for v in p[-6:]]))
        elif line.lstrip()[:1] in tuple('+-.0123456789'):
            rows.append([float(v) for v in line.split()])
    return hdr, np.array(rows)


def read_glstat(d):
    return np.array([[float(v) for v in l.split()] for l in open(d + '/glstat')
                     if l.lstrip()[:1] in tuple('+-.0123456789')])


def result(name, value, tol, ok):
    print('%-44s %.6e  (tolerance %.3e)  %s' % (name, value, tol, 'ok' if ok else 'FAIL'))
    return ok


def euler_rhs(w, ip):
    i1, i2, i3 = ip
    return np.array([(i2 - i3) * w[1] * w[2] / i1, (i3 - i1) * w[2] * w[0] / i2,
                     (i1 - i2) * w[0] * w[1] / i3])


def spin(a):
    hdr, r = read_rbdout(a.outdir)
    ok = True
    ip = np.array(a.ip)
    ten = list(hdr.values())[0]['inertia']
    t3 = np.array([[ten[0], ten[1], ten[2]], [ten[1], ten[3], ten[4]], [ten[2], ten[4], ten[5]]])
    ev = np.sort(np.linalg.eigvalsh(t3))
    ok &= result('principal moments vs closed form (rel)', np.max(np.abs(ev - ip)) / ip.max(),
                 1e-12, np.max(np.abs(ev - ip)) / ip.max() <= 1e-12)
    t = r[:, 0]
    wb = r[:, 11:14]
    lsp = r[:, 14:17]
    ke = r[:, 17]
    rot = r[:, 18:27].reshape(-1, 3, 3).transpose(0, 2, 1)   # rows written column-major
    dl = np.max(np.linalg.norm(lsp - lsp[0], axis=1)) / np.linalg.norm(lsp[0])
    ok &= result('spatial angular momentum drift (rel)', dl, a.tol_l, dl <= a.tol_l)
    orth = max(np.max(np.abs(q.T @ q - np.eye(3))) for q in rot)
    ok &= result('max |R^T R - I|', orth, 1e-13, orth <= 1e-13)
    dke = np.max(np.abs(ke - ke[0])) / ke[0]
    ok &= result('kinetic energy band max|KE - KE0|/KE0', dke, a.tol_ke, dke <= a.tol_ke)
    # reference: RK4 on Euler's equations from the first row
    w = wb[0].copy()
    err = 0.0
    nsub = 200
    for k in range(1, len(t)):
        h = (t[k] - t[k - 1]) / nsub
        for _ in range(nsub):
            k1 = euler_rhs(w, ip)
            k2 = euler_rhs(w + 0.5 * h * k1, ip)
            k3 = euler_rhs(w + 0.5 * h * k2, ip)
            k4 = euler_rhs(w + h * k3, ip)
            w = w + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        err = max(err, np.max(np.abs(wb[k] - w)) / np.linalg.norm(wb[0]))
    ok &= result('body angular velocity vs RK4 Euler (rel)', err, a.tol_w, err <= a.tol_w)
    print('rows %d, t = %.4g .. %.4g, sign changes of w2: %d' % (
        len(t), t[0], t[-1], int(np.sum(np.diff(np.sign(wb[:, 1])) != 0))))
    return ok


def top(a):
    hdr, r = read_rbdout(a.outdir)
    ip = a.ip
    t = r[:, 0]
    wb = r[:, 11:14]
    ph = np.unwrap(np.arctan2(wb[:, 2], wb[:, 1]))
    rate = np.polyfit(t, ph, 1)[0]
    exact = (ip[0] - ip[2]) / ip[2] * np.mean(wb[:, 0])
    rel = abs(rate - exact) / abs(exact)
    print('precession rate %.10f, analytic (I1 - I3)/I3 w1 = %.10f' % (rate, exact))
    return result('precession rate error (rel)', rel, a.tol_rate, rel <= a.tol_rate)


def fall(a):
    hdr, r = read_rbdout(a.outdir)
    g = np.array([0.0, 0.0, -a.g])
    t = r[:, 0]
    x0, v0 = np.array(a.x0), np.array(a.v0)
    xe = x0 + np.outer(t, v0) + 0.5 * np.outer(t * t, g)
    ex = np.max(np.abs(r[:, 2:5] - xe)) / np.max(np.abs(xe))
    ok = result('centre x_c(t) vs x0 + v0 t - g t^2/2 (rel)', ex, a.tol, ex <= a.tol)
    gl = read_glstat(a.outdir)
    dts = gl[:, 2]
    # vc is at t + dt/2 of the row's step; the glstat rows share the rbdout times here
    tt = dict((round(x, 12), d) for x, d in zip(gl[:, 0], dts))
    ev = 0.0
    for k in range(len(t)):
        d = tt.get(round(t[k], 12))
        if d is None:
            continue
        ve = v0 + g * (t[k] + 0.5 * d)
        ev = max(ev, np.max(np.abs(r[k, 5:8] - ve)) / np.linalg.norm(v0))
    ok &= result('velocity v_c(t + dt/2) (rel)', ev, a.tol, ev <= a.tol)
    if a.node_x0 is not None:
        rows = np.array([[float(v) for v in l.split()] for l in open(a.outdir + '/nodout')
                         if l.lstrip()[:1] in tuple('+-.0123456789')])
        tn = rows[:, 0]
        xe = np.array(a.node_x0) + np.outer(tn, v0) + 0.5 * np.outer(tn * tn, g)
        en = np.max(np.abs(rows[:, 11:14] - xe)) / np.max(np.abs(xe))
        ok &= result('deformable node x(t) (rel)', en, a.tol, en <= a.tol)
    return ok


def momentum(a):
    gl = read_glstat(a.outdir)
    tf = np.array(a.force_curve[0::2])
    ff = np.array(a.force_curve[1::2])
    t = gl[:, 0]
    dt = gl[:, 2]
    # momentum at t(n+1/2) equals the impulse of f up to t(n) + dt/2 in the central difference
    # only for piecewise-constant f; compare with the trapezoid impulse to t(n)+dt/2
    th = t + 0.5 * dt
    imp = np.array([np.trapz(np.interp(np.linspace(0, x, 2001), tf, ff),
                             np.linspace(0, x, 2001)) for x in th])
    p = gl[:, 10 + a.axis - 1]
    err = np.max(np.abs(p - imp)) / np.max(np.abs(imp))
    return result('momentum %d vs impulse (rel)' % a.axis, err, a.tol, err <= a.tol)


def energy(a):
    gl = read_glstat(a.outdir)
    sel = gl[:, 0] >= a.after
    dev = np.max(np.abs(gl[sel, 9] - 1.0))
    return result('energy ratio max |ratio - 1|', dev, a.band, dev <= a.band)


def punch(a):
    """prescribed rigid motion: x_c,z(t) = z0 - (ramp displacement), x and y fixed (CON1 = 4),
    no rotation (CON2 = 7)"""
    hdr, r = read_rbdout(a.outdir)
    t = r[:, 0]
    tr = a.ramp
    d = np.where(t < tr, a.v * t * t / (2 * tr), a.v * (tr / 2 + (t - tr)))
    ez = np.max(np.abs(r[:, 4] - (a.z0 - d))) / np.max(np.abs(d))
    ok = result('punch z(t) vs prescribed displacement (rel)', ez, a.tol, ez <= a.tol)
    exy = np.max(np.abs(r[:, 2:4] - r[0, 2:4]))
    ok &= result('punch x, y drift (abs, CON1 = 4)', exy, 1e-12, exy <= 1e-12)
    ew = np.max(np.abs(r[:, 8:11]))
    ok &= result('punch angular velocity (abs, CON2 = 7)', ew, 0.0, ew == 0.0)
    return ok


def axis_rot(k, th):
    c, s = np.cos(th), np.sin(th)
    i, j = (k + 1) % 3, (k + 2) % 3
    r = np.eye(3)
    r[i, i] = c; r[j, j] = c; r[j, i] = s; r[i, j] = -s
    return r


def rotation(a):
    """prescribed rotation about global axis K by the angle RATE * t: R(t) R(0)^T = rot_K,
    centre fixed"""
    _, r = read_rbdout(a.outdir)
    r = r[r[:, 1] == a.body]
    rot = r[:, 18:27].reshape(-1, 3, 3).transpose(0, 2, 1)
    err = max(np.max(np.abs(q @ rot[0].T - axis_rot(a.axis - 1, a.rate * t)))
              for q, t in zip(rot, r[:, 0]))
    ok = result('body %d: R(t) R(0)^T vs rotation %g t about axis %d' % (a.body, a.rate, a.axis),
                err, a.tol, err <= a.tol)
    ex = np.max(np.abs(r[:, 2:5] - r[0, 2:5]))
    ok &= result('body %d: centre fixed (abs)' % a.body, ex, a.tol, ex <= a.tol)
    return ok


def mass(a):
    hdr, _ = read_rbdout(a.outdir)
    h = hdr[a.body]
    ok = True
    em = abs(h['mass'] - a.mass) / a.mass
    ok &= result('mass (rel)', em, a.tol, em <= a.tol)
    ex = np.max(np.abs(h['xc'] - np.array(a.xc))) / max(np.max(np.abs(a.xc)), 1e-300)
    ok &= result('centre of mass (rel)', ex, a.tol, ex <= a.tol)
    ei = np.max(np.abs(h['inertia'] - np.array(a.inertia))) / np.max(np.abs(a.inertia))
    ok &= result('inertia tensor (rel)', ei, a.tol, ei <= a.tol)
    if a.v0 is not None:
        _, r = read_rbdout(a.outdir)
        row = r[(r[:, 0] == r[0, 0]) & (r[:, 1] == a.body)][0]
        ev = np.max(np.abs(row[5:8] - np.array(a.v0)))
        ew = np.max(np.abs(row[8:11] - np.array(a.w0)))
        ok &= result('initial velocity of the centre (abs)', ev, a.tol, ev <= a.tol)
        ok &= result('initial angular velocity (abs)', ew, a.tol, ew <= a.tol)
    return ok


def main():
    p = argparse.ArgumentParser()
    s = p.add_subparsers(dest='cmd', required=True)
    q = s.add_parser('spin'); q.add_argument('outdir')
    q.add_argument('--ip', type=float, nargs=3, required=True)
    q.add_argument('--tol-l', type=float, default=1e-12)
    q.add_argument('--tol-ke', type=float, required=True)
    q.add_argument('--tol-w', type=float, required=True)
    q = s.add_parser('top'); q.add_argument('outdir')
    q.add_argument('--ip', type=float, nargs=3, required=True)
    q.add_argument('--tol-rate', type=float, required=True)
    q = s.add_parser('fall'); q.add_argument('outdir')
    q.add_argument('--g', type=float, required=True)
    q.add_argument('--x0', type=float, nargs=3, required=True)
    q.add_argument('--v0', type=float, nargs=3, required=True)
    q.add_argument('--node-x0', type=float, nargs=3)
    q.add_argument('--tol', type=float, required=True)
    q = s.add_parser('momentum'); q.add_argument('outdir')
    q.add_argument('--axis', type=int, required=True)
    q.add_argument('--force-curve', type=float, nargs='+', required=True)
    q.add_argument('--tol', type=float, required=True)
    q = s.add_parser('energy'); q.add_argument('outdir')
    q.add_argument('--band', type=float, required=True)
    q.add_argument('--after', type=float, default=0.0)
    q = s.add_parser('punch'); q.add_argument('outdir')
    q.add_argument('--z0', type=float, required=True)
    q.add_argument('--v', type=float, required=True)
    q.add_argument('--ramp', type=float, required=True)
    q.add_argument('--tol', type=float, required=True)
    q = s.add_parser('rotation'); q.add_argument('outdir')
    q.add_argument('--body', type=int, required=True)
    q.add_argument('--axis', type=int, required=True)
    q.add_argument('--rate', type=float, required=True)
    q.add_argument('--tol', type=float, required=True)
    q = s.add_parser('mass'); q.add_argument('outdir')
    q.add_argument('--body', type=int, required=True)
    q.add_argument('--mass', type=float, required=True)
    q.add_argument('--xc', type=float, nargs=3, required=True)
    q.add_argument('--inertia', type=float, nargs=6, required=True)
    q.add_argument('--v0', type=float, nargs=3)
    q.add_argument('--w0', type=float, nargs=3)
    q.add_argument('--tol', type=float, required=True)
    a = p.parse_args()
    ok = dict(spin=spin, top=top, fall=fall, momentum=momentum, energy=energy, mass=mass,
              punch=punch, rotation=rotation)[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
