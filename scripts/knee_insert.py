#!/usr/bin/python3
"""Scene 3 of issue 20: a knee tibial insert (polyethylene, the seed's Table 1: E 1016 MPa,
nu 0.46, *MAT_024 hardening) under a rigid femoral condyle at several flexion angles, in
dynx's implicit statics. Parametric and generic (the seed names the knee model, no design):
one compartment, quarter model (symmetry planes x = 0 sagittal-lateral, y = 0), the insert
a block 40 x 40 x 10 mm (quarter 20 x 20) whose top is a spherical dish of radius
RD = 80 mm, held on its base; the condyle a rigid spherical cap (*MAT_RIGID, CON1 = 4,
CON2 = 7) whose radius is the femoral J-curve's radius at the contact for the flexion angle
(an assumed generic J-curve: R = 40 mm at 0 deg, 30 at 45, 20 at 90 deg), pressed into the
dish by a prescribed rigid motion d (*BOUNDARY_PRESCRIBED_MOTION_RIGID, VAD 2) in 4 load
steps. Contact: NODES_TO_SURFACE, slave the condyle's nodes (cube-sphere cap), master the
dish's segments, SFS 100. Elastic check: a sphere in a concave dish is Hertz with
1/Reff = 1/R - 1/RD, E* = E/(1 - nu^2) (rigid indenter): F = 4/3 E* sqrt(Reff) d^1.5,
a = sqrt(Reff d), p0 = 2 E* a/(pi Reff) (Johnson 1985, ch. 4; a/t <= 0.3 here, so the
finite thickness stiffens the response by a few percent).

  knee_insert.py gen [--n 4] [--flex 0] [--d 0.1] [--elastic] [--thick] OUT.k
  knee_insert.py check OUTDIR      the regression case (elastic, thick, 0 deg, n = 4: Hertz)
  knee_insert.py study WORKDIR     flexion sweep (plastic) and the elastic Hertz series
"""
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_implicit_decks import Deck  # noqa: E402
from gen_contact_decks import graded  # noqa: E402
from cmc_implant import last_state, von_mises, PE_CURVE  # noqa: E402

E, NU, RD, W, T = 1016.0, 0.46, 80.0, 20.0, 10.0
ESTAR = E/(1 - NU*NU)
J_CURVE = {0: 40.0, 45: 30.0, 90: 20.0}


def hertz(flex, d):
    r = J_CURVE[flex]
    reff = r*RD/(RD - r)
    a = math.sqrt(reff*d)
    return reff, a, 4.0/3.0*ESTAR*math.sqrt(reff)*d**1.5, 2*ESTAR*a/(math.pi*reff)


def ztop(x, y):
    """the dish: a sphere of radius RD centred at (0, 0, T + RD), concave (rising outward)"""
    return T + RD - math.sqrt(RD*RD - x*x - y*y)


def gen(path, n=4, flex=0, d=0.1, elastic=False, steps=4, thick=False):
    """thick: the insert 4x thicker and wider (T 40, quarter W 40): near Hertz's half-space
    (the elastic check); else the 10 mm insert."""
    global T, W
    T, W = (40.0, 40.0) if thick else (10.0, 20.0)
    reff, a, F, p0 = hertz(flex, d)
    R = J_CURVE[flex]
    zone = 1.6*a
    xs = graded(n, zone, W)
    zs = graded(n, zone, T)          # depth below the top
    dk = Deck('knee insert: rigid condyle R %g mm (flexion %d deg) pressed %g mm into a %s '
              'polyethylene insert %g mm thick (n = %d)' % (R, flex, d, 'elastic' if elastic
                                                          else 'Table 1', T, n))
    dk.controls(1.0, 1.0/steps, dctol=1e-6, ectol=1e-10, rctol=1e-9, abstol=1e-9, maxref=30,
                iauto=1)
    dk.kw('DATABASE_SPCFORC', dk.f(1.0/steps))
    f = dk.f
    dk.kw('PART', 'insert', '$      PID     SECID       MID', f(1, 1, 1))
    dk.kw('PART', 'condyle (rigid)', '$      PID     SECID       MID', f(2, 1, 2))
    dk.kw('SECTION_SOLID', '$    SECID    ELFORM', f(1, 2))
    if elastic:
        dk.kw('MAT_ELASTIC', '$      MID        RO         E        PR', f(1, 9.4e-10, E, NU))
    else:
        dk.kw('MAT_PIECEWISE_LINEAR_PLASTICITY', '$      MID        RO         E        PR      SIGY',
              f(1, 9.4e-10, E, NU, 0.0), '$        C         P      LCSS', f(0.0, 0.0, 10))
        dk.curve(10, PE_CURVE)
    dk.kw('MAT_RIGID', '$      MID        RO         E        PR', f(2, 8.3e-9, 210000.0, 0.3),
          '$      CMO      CON1      CON2', f(1.0, 4, 7))
    nx, nz = len(xs) - 1, len(zs) - 1
    nid = lambda i, j, k: 1 + i + (nx + 1)*(j + (nx + 1)*k)     # k = 0 base .. nz top
    nodes, elems = {}, []
    for k in range(nz + 1):
        depth = zs[nz - k]
        for j in range(nx + 1):
            for i in range(nx + 1):
                x, y = xs[i], xs[j]
                zt = ztop(x, y)
                nodes[nid(i, j, k)] = (x, y, zt - depth*zt/T)
    for k in range(nz):
        for j in range(nx):
            for i in range(nx):
                elems.append((1, [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                                  nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                                  nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]))
    # condyle: a quarter cap, cube-sphere face (u, v in [0, 1]), angle to 2.2 a on the axes,
    # 2n x 2n facets (finer than the dish: the slaves sample the patch), one layer 2 mm thick
    nc = 2*n
    A = math.asin(min(0.9, 2.2*a/R))
    cz = ztop(0, 0) + R
    bid = lambda i, j, k: 100001 + i + (nc + 1)*(j + (nc + 1)*k)
    for k, r in enumerate((R, R - 2.0)):
        for j in range(nc + 1):
            for i in range(nc + 1):
                dv = (math.tan(A*i/nc), math.tan(A*j/nc), -1.0)
                ln = math.sqrt(sum(v*v for v in dv))
                nodes[bid(i, j, k)] = (r*dv[0]/ln, r*dv[1]/ln, cz + r*dv[2]/ln)
    for j in range(nc):
        for i in range(nc):
            c = [bid(i, j, 0), bid(i + 1, j, 0), bid(i + 1, j + 1, 0), bid(i, j + 1, 0),
                 bid(i, j, 1), bid(i + 1, j, 1), bid(i + 1, j + 1, 1), bid(i, j + 1, 1)]
            elems.append((2, c))
    dk.kw('NODE', *['%8d%16.9f%16.9f%16.9f' % (q, *nodes[q]) for q in sorted(nodes)])
    el = []
    for e, (p, c) in enumerate(elems):
        el.append('%8d%8d' % (e + 1, p))
        el.append(''.join('%8d' % q for q in c))
    dk.kw('ELEMENT_SOLID', *el)
    for k in range(nz + 1):
        for j in range(nx + 1):
            for i in range(nx + 1):
                q = nid(i, j, k)
                if k == 0:
                    dk.spc(q, 1, 1, 1)
                elif i == 0 or j == 0:
                    dk.spc(q, int(i == 0), int(j == 0), 0)
    slaves = [bid(i, j, 0) for j in range(nc + 1) for i in range(nc + 1)]
    dk.kw('SET_NODE_LIST', f(1), *[''.join(f(q) for q in slaves[k:k + 8])
                                   for k in range(0, len(slaves), 8)])
    dk.kw('SET_SEGMENT', f(2), *[f(nid(i, j, nz), nid(i + 1, j, nz), nid(i + 1, j + 1, nz),
                                   nid(i, j + 1, nz)) for j in range(nx) for i in range(nx)])
    dk.kw('CONTACT_NODES_TO_SURFACE', '$     SSID      MSID     SSTYP     MSTYP',
          f(1, 2, 4, 0), '$       FS        FD', f(0.0, 0.0), '$      SFS       SFM',
          f(100.0, 100.0))
    dk.curve(1, [(0.0, 0.0), (1.0, 1.0)])
    dk.kw('BOUNDARY_PRESCRIBED_MOTION_RIGID', '$      PID       DOF       VAD      LCID        SF',
          f(2, 3, 2, 1, -d))
    dk.history([bid(0, 0, 0), nid(0, 0, nz)])
    dk.write(path)


def result(out, thick=False):
    """(F = 4 x the base's z reaction, peak -sigma_zz of the insert's top layer, max von Mises,
    max plastic strain)"""
    global T, W
    T, W = (40.0, 40.0) if thick else (10.0, 20.0)
    x, sig, conn, pid, eps = last_state(out)
    p, vm, ep = 0.0, 0.0, 0.0
    for e in range(len(pid)):
        if pid[e] != 1:
            continue
        s = sig[6*e:6*e + 6]
        vm = max(vm, von_mises(s))
        ep = max(ep, eps[e])
        nd = conn[8*e:8*e + 8]
        if sum(1 for q in nd if abs(x[q][2] - ztop(x[q][0], x[q][1])) < 1e-7) >= 4:
            p = max(p, -s[2])
    res = [l for l in open(os.path.join(out, 'spcforc')) if 'force resultants' in l]
    F = 4.0*abs(float(res[-1].split('=')[1].split()[2]))
    return F, p, vm, ep


def check(out):
    """implicit_knee_insert (elastic, 0 deg: R = 40 in the RD = 80 dish, Reff = 80 mm, the
    thick insert T = W = 40 mm, d = 0.1 mm, n = 4): against Hertz (F 486.0 N, p0 29.01 MPa):
    F within 15 % (measured +10.5 %: the finite insert (a/T = 0.07) and the coarse mesh (4
    elements over 1.6 a) stiffen it), the top layer's peak -sigma_zz within 15 % of p0
    (measured -10.4 %: element centroids h/2 deep, where sigma_zz is below the surface
    pressure), both printed with the mesh series in decks/knee_insert/README.md; Newton
    converged (the run's exit 0)."""
    from dxpost import report
    reff, a, F, p0 = hertz(0, 0.1)
    f, p, vm, ep = result(out, thick=True)
    print('Hertz: Reff %.4g mm, a %.4g mm, F %.5g N, p0 %.5g MPa' % (reff, a, F, p0))
    ok = report('F [N] vs Hertz', f, F, 0.0, 0.15)
    ok &= report('peak -sigma_zz (top layer) [MPa] vs Hertz p0', p, p0, 0.0, 0.15)
    print('max von Mises %.4g MPa' % vm)
    return ok


def study(work, ns=(3, 4, 6)):
    dynx = os.environ.get('DYNX', os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                               '..', 'bin', 'dynx'))
    os.makedirs(work, exist_ok=True)

    def one(name, **kw):
        k = os.path.join(work, name + '.k')
        o = os.path.join(work, name)
        gen(k, **kw)
        t0 = time.time()
        with open(os.path.join(work, name + '.log'), 'w') as fh:
            rc = subprocess.run([dynx, '-i', k, '-o', o], stdout=fh,
                                stderr=subprocess.STDOUT).returncode
        if rc != 0:
            print('%s: exit %d' % (name, rc), flush=True)
            return
        F, p, vm, ep = result(o, kw.get('thick', False))
        its = sum(1 for l in open(os.path.join(work, name + '.log')) if 'residual ratio' in l)
        print('%-22s F %.4g N  peak p %.4g MPa  vM %.4g MPa  eps_p %.3g  its %d  wall %.1f s'
              % (name, F, p, vm, ep, its, time.time() - t0), flush=True)
    r = hertz(0, 0.1)
    print('Hertz 0 deg d 0.1: F %.5g N, p0 %.5g MPa' % (r[2], r[3]), flush=True)
    for n in ns:
        one('elastic_thick_n%d' % n, n=n, elastic=True, thick=True)
    one('elastic_n%d' % ns[1], n=ns[1], elastic=True)
    for flex in sorted(J_CURVE):
        one('plastic_flex%d' % flex, n=ns[1], flex=flex)


if __name__ == '__main__':
    args = sys.argv[1:]
    what = args.pop(0)

    def opt(name, default, conv=float):
        if name in args:
            i = args.index(name)
            v = args[i + 1]
            del args[i:i + 2]
            return conv(v)
        return default
    el = '--elastic' in args
    if el:
        args.remove('--elastic')
    if what == 'gen':
        th = '--thick' in args
        if th:
            args.remove('--thick')
        gen(args[-1], n=opt('--n', 4, int), flex=opt('--flex', 0, int), d=opt('--d', 0.1),
            elastic=el, thick=th)
    elif what == 'check':
        sys.exit(0 if check(args[0]) else 1)
    elif what == 'study':
        study(args[0], tuple(int(v) for v in opt('--n', '3,4,6', str).split(',')))
