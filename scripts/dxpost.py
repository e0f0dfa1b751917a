#!/usr/bin/env python3
"""Post-processing of dynx output with the Python standard library only: datasets are pulled
out of d3plot.h5 with h5dump (binary, little endian) and glstat/nodout are read as columns.

Commands (each prints one line per quantity and exits 1 when a check fails):
  dxpost.py taylor OUTDIR [--L0 L --R0 R]     final length and footprint radius
  dxpost.py wave OUTDIR --rho R --M M --v V   stress plateau and front against rho*cL*v, x = cL*t
  dxpost.py patch OUTDIR --mode strain|rotation   uniform exact stress / zero stress and energy
  dxpost.py energy OUTDIR                     energy ratio range over the run
Checks take --tol-... options; see each function."""
import math, os, re, struct, subprocess, sys, tempfile, argparse


def dims(h5, path):
    out = subprocess.run(['h5dump', '-H', '-d', path, h5], capture_output=True, text=True).stdout
    m = re.search(r'DATASPACE\s+SIMPLE\s*\{\s*\(([^)]*)\)', out)
    if not m:
        raise SystemExit('dxpost: no dataset %s in %s' % (path, h5))
    t = 'd' if 'H5T_IEEE_F64' in out else ('i' if 'H5T_STD_I32' in out else 'q')
    return [int(x) for x in m.group(1).split(',')], t


def dataset(h5, path):
    """(shape, flat list) of a dataset; shape as h5dump shows it (C order)."""
    shape, t = dims(h5, path)
    with tempfile.NamedTemporaryFile(delete=False) as tmp:
        name = tmp.name
    try:
        subprocess.run(['h5dump', '-d', path, '-b', 'LE', '-o', name, h5], check=True,
                       capture_output=True)
        raw = open(name, 'rb').read()
    finally:
        os.unlink(name)
    n = 1
    for d in shape:
        n *= d
    return shape, list(struct.unpack('<%d%s' % (n, t), raw[:n * struct.calcsize(t)]))


def states(h5):
    _, times = dataset(h5, '/states/times')
    return times


def state_path(k):
    return '/states/%06d' % k


def columns(path):
    """Read an ASCII history: header line starting '# time' names the columns."""
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


def vec3(flat):
    return [flat[3 * i:3 * i + 3] for i in range(len(flat) // 3)]


def report(name, value, ref, abs_tol, rel_tol):
    ok = math.isfinite(value) and abs(value - ref) <= abs_tol + rel_tol * abs(ref)
    print('%-34s %14.6g   reference %14.6g   diff %10.3g   %s'
          % (name, value, ref, value - ref, 'PASS' if ok else 'FAIL'))
    return ok


def taylor(a):
    h5 = os.path.join(a.out, 'd3plot.h5')
    times = states(h5)
    _, c = dataset(h5, state_path(len(times)) + '/coordinates')
    xyz = vec3(c)
    _, c0 = dataset(h5, '/mesh/coordinates')
    x0 = vec3(c0)
    zmin = min(p[2] for p in xyz)
    lf = max(p[2] for p in xyz) - zmin
    # footprint: the largest radius among the nodes of the impact face (initial z = min z0)
    z0min = min(p[2] for p in x0)
    rf = max(math.hypot(p[0], p[1]) for p, q in zip(xyz, x0) if q[2] < z0min + 1e-9)
    lift = max(p[2] - zmin for p, q in zip(xyz, x0) if q[2] < z0min + 1e-9)
    print('time %.6g  final length %.5f mm  footprint radius %.5f mm  (face lift-off %.3g mm)'
          % (times[-1], lf, rf, lift))
    ok = True
    if a.L0:
        print('Lf/L0 %.4f  Rf/R0 %.4f' % (lf / a.L0, rf / a.R0))
    if a.Lref is not None:
        ok &= report('final length [mm]', lf, a.Lref, 0.0, a.tol_L if a.tol_L else a.tol)
    if a.Rref is not None:
        ok &= report('footprint radius [mm]', rf, a.Rref, 0.0, a.tol_R if a.tol_R else a.tol)
    return ok


def wave(a):
    h5 = os.path.join(a.out, 'd3plot.h5')
    times = states(h5)
    k = len(times)
    t = times[-1]
    _, conn = dataset(h5, '/mesh/hex8')
    _, x0 = dataset(h5, '/mesh/coordinates')
    _, s = dataset(h5, state_path(k) + '/stress')
    x0 = vec3(x0)
    ne = len(conn) // 8
    xc = [sum(x0[conn[8 * e + j]][0] for j in range(8)) / 8 for e in range(ne)]
    sxx = [s[6 * e] for e in range(ne)]
    cl = math.sqrt(a.M / a.rho)
    if a.us_fit:   # a shock: Us = C + S1 up (Rankine-Hugoniot: p = rho Us up)
        cl = a.us_fit[0] + a.us_fit[1] * a.v
    sig = -a.rho * cl * a.v
    front = cl * t
    h = max(xc) / (ne - 0.5) if ne > 1 else 1.0
    # plateau: elements well behind the front
    pl = [sxx[e] for e in range(ne) if xc[e] < front - 10 * h and xc[e] > 2 * h]
    mean = sum(pl) / len(pl)
    # front: where the stress first passes half the plateau, from the far end
    order = sorted(range(ne), key=lambda e: xc[e])
    xf = None
    for i in range(len(order) - 1, 0, -1):
        e1, e0 = order[i], order[i - 1]
        if sxx[e0] <= 0.5 * sig < sxx[e1] or sxx[e0] >= 0.5 * sig > sxx[e1]:
            xf = xc[e0] + (0.5 * sig - sxx[e0]) * (xc[e1] - xc[e0]) / (sxx[e1] - sxx[e0])
            break
    ahead = max(abs(sxx[e]) for e in range(ne) if xc[e] > front + 10 * h) if any(
        xc[e] > front + 10 * h for e in range(ne)) else 0.0
    over = min(sxx) / sig - 1.0
    print('t %.6g  cL %.6g  elements %d  h %.4g' % (t, cl, ne, h))
    ok = report('plateau stress [GPa]', mean, sig, 0.0, a.tol_plateau)
    ok &= report('front position [mm]', xf if xf is not None else float('nan'), front,
                 a.tol_front * h, 0.0)
    ok &= report('stress ahead of front [GPa]', ahead, 0.0, 1e-3 * abs(sig), 0.0)
    print('%-34s %14.6g' % ('overshoot (min/plateau - 1)', over))
    if a.csv:
        with open(a.csv, 'w') as f:
            f.write('# x_centroid sigma_xx analytic\n')
            for e in order:
                f.write('%.6g %.6g %.6g\n' % (xc[e], sxx[e], sig if xc[e] < front else 0.0))
    return ok


def logm_sym(m):
    """Matrix logarithm of a symmetric positive definite 3x3 via Jacobi eigen-decomposition."""
    a = [row[:] for row in m]
    v = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    for _ in range(50):
        off = max(abs(a[0][1]), abs(a[0][2]), abs(a[1][2]))
        if off < 1e-300:
            break
        for p, q in ((0, 1), (0, 2), (1, 2)):
            if abs(a[p][q]) < 1e-300:
                continue
            th = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
            c, s = math.cos(th), math.sin(th)
            for k in range(3):
                akp, akq = a[k][p], a[k][q]
                a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
            for k in range(3):
                apk, aqk = a[p][k], a[q][k]
                a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
            for k in range(3):
                vkp, vkq = v[k][p], v[k][q]
                v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    lam = [math.log(a[i][i]) for i in range(3)]
    return [[sum(v[i][k] * lam[k] * v[j][k] for k in range(3)) for j in range(3)] for i in range(3)]


def patch(a):
    h5 = os.path.join(a.out, 'd3plot.h5')
    times = states(h5)
    ok = True
    E, nu = 1.0e6, 0.25
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    L = [[1.0e-3, 0.5e-3, 0.5e-3], [0.5e-3, 1.0e-3, 0.5e-3], [0.5e-3, 0.5e-3, 1.0e-3]]
    for k in range(1, len(times) + 1):
        t = times[k - 1]
        _, s = dataset(h5, state_path(k) + '/stress')
        ne = len(s) // 6
        if a.mode == 'strain':
            eps = logm_sym([[(1.0 if i == j else 0.0) + L[i][j] * t for j in range(3)]
                            for i in range(3)])
            tr = eps[0][0] + eps[1][1] + eps[2][2]
            ref = [lam * tr + 2 * mu * eps[0][0], lam * tr + 2 * mu * eps[1][1],
                   lam * tr + 2 * mu * eps[2][2], 2 * mu * eps[0][1], 2 * mu * eps[1][2],
                   2 * mu * eps[2][0]]
            scale = max(abs(r) for r in ref) or 1.0
            err = max(abs(s[6 * e + c] - ref[c]) for e in range(ne) for c in range(6)) / scale
            ok &= report('t=%.3g max stress error / |sigma|' % t, err, 0.0, a.tol, 0.0)
        else:
            err = max(abs(x) for x in s)
            ok &= report('t=%.3g max |stress|' % t, err, 0.0, a.tol, 0.0)
    names, rows = columns(os.path.join(a.out, 'glstat'))
    ie = names.index('internal')
    if a.mode == 'rotation':
        ok &= report('max internal energy', max(abs(r[ie]) for r in rows), 0.0, a.tol_energy, 0.0)
    else:
        # strain energy of the uniform state: V * sigma:eps / 2 (small strain) at the end
        print('%-34s %14.6g' % ('final internal energy', rows[-1][ie]))
    return ok


def energy(a):
    names, rows = columns(os.path.join(a.out, 'glstat'))
    r = names.index('energy_ratio')
    # rows where the system holds no energy yet (a body at rest driven from t = 0) have no
    # meaningful ratio: skip those whose total is below 1e-9 of the largest total
    tot = names.index('total')
    big = max(abs(x[tot]) for x in rows)
    rows = [x for x in rows if abs(x[tot]) > 1e-9 * big and x[0] >= a.after] or rows
    lo, hi = min(x[r] for x in rows), max(x[r] for x in rows)
    print('energy ratio min %.8f max %.8f final %.8f' % (lo, hi, rows[-1][r]))
    ok = lo >= 1 - a.band and hi <= 1 + a.band
    if a.ke_floor is not None:
        # the time-centred kinetic energy 1/2 m v(n-1/2).v(n+1/2) of a mode at a turning point
        # is -KE_max sin^2(omega dt/2) < 0: bounded for a stable run, not for a blow-up
        ke, e0 = names.index('kinetic'), rows[0][tot]
        kmin = min(x[ke] for x in rows)
        print('kinetic energy min %.6e = %.5f E0 (floor -%g E0)' % (kmin, kmin / e0, a.ke_floor))
        ok = ok and kmin >= -a.ke_floor * e0
    return ok


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest='cmd', required=True)
    p = sub.add_parser('taylor'); p.add_argument('out')
    p.add_argument('--L0', type=float); p.add_argument('--R0', type=float)
    p.add_argument('--Lref', type=float); p.add_argument('--Rref', type=float)
    p.add_argument('--tol', type=float, default=0.02)
    p.add_argument('--tol-L', type=float, default=None)
    p.add_argument('--tol-R', type=float, default=None)
    p = sub.add_parser('wave'); p.add_argument('out')
    p.add_argument('--rho', type=float, default=7.85e-6)
    p.add_argument('--M', type=float, default=210.0 * 0.7 / (1.3 * 0.4))
    p.add_argument('--v', type=float, default=1.0)
    p.add_argument('--tol-plateau', type=float, default=0.01)
    p.add_argument('--tol-front', type=float, default=3.0)
    p.add_argument('--us-fit', type=float, nargs=2, metavar=('C', 'S1'),
                   help='a shock of speed Us = C + S1 v instead of cL = sqrt(M/rho)')
    p.add_argument('--csv')
    p = sub.add_parser('patch'); p.add_argument('out')
    p.add_argument('--mode', choices=['strain', 'rotation'], required=True)
    p.add_argument('--tol', type=float, default=1e-6)
    p.add_argument('--tol-energy', type=float, default=1e-12)
    p = sub.add_parser('energy'); p.add_argument('out')
    p.add_argument('--band', type=float, default=0.02)
    p.add_argument('--after', type=float, default=0.0, help='ignore rows before this time')
    p.add_argument('--ke-floor', type=float, help='fail if kinetic < -KE_FLOOR x E0')
    a = ap.parse_args()
    ok = {'taylor': taylor, 'wave': wave, 'patch': patch, 'energy': energy}[a.cmd](a)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
