#!/usr/bin/python3
"""code_aster SSNV104 (V6.04.104, "Contact of two spheres") in dynx's implicit statics, and
beside CalculiX (issue 20, scene 1). Two elastic hemispheres, R = 50 mm, E = 20 000 MPa,
nu = 0.3, pressed together by prescribed displacements of their flat faces, +2 mm and -2 mm
(total crushing h = 4 mm), frictionless. Reference (Hertz, as SSNV104 states it, with
E* = E/(2(1 - nu^2)), R* = R/2): a = sqrt(R* h) = 10 mm, p0 = -sigma_zz at the contact
centre = 2 E* a/(pi R*) = 2798.3 MPa, and the force F = 4/3 E* sqrt(R*) h^1.5 = 586.1 kN.
Quarter model (symmetry planes x = 0, y = 0); units mm, ms, kg, GPa (so p0 = 2.7983 GPa).

Mesh: each hemisphere quarter (a ball octant) from the unit cube [0, 1]^3 by the cube-to-
ball map (x sqrt(1 - y^2/2 - z^2/2 + y^2 z^2/3), ...: the cube's faces x = 0, y = 0, z = 0
stay planes, its outer faces land on the sphere, and the pole (0, 0, 1) is the centre of a
cube face, so the contact zone is meshed by regular hexahedra); the cube coordinates are
graded: n uniform elements over [0, 0.4] in x and y and over [0.6, 1] in z (the contact zone
r <= 14 mm, surface element size 14.1/n mm), then growing by 1.3. Body 1 (slave is body 2):
the lower hemisphere, pole at the origin, flat face z = -R; the upper one has n + 1
elements over the zone (non-matching: see mesh()).

  ssnv104.py gen  [--n 6] [--steps 4] [--sfs 100] OUT.k     the deck
  ssnv104.py post OUTDIR [--tol 0.1]                        a, p0, F against the reference
  ssnv104.py study [--n 4 6 8] [--ccx] WORKDIR              mesh convergence (+ CalculiX)

post: p = the normal stress n.sigma.n (n radial from the sphere's centre) of the lower
body's surface layer (elements with a face on the sphere), fitted by the Hertz ellipse
p^2 = p0^2 (1 - r^2/a^2) over the elements with p > 0.3 max p (as contact_post.py hertz),
sigma_zz of the element at the pole, and F = 4 x the z resultant of the lower face's
reactions (spcforc). The lower face is held (SPC z) and the upper one moved by -h: SSNV104's
+-2 mm up to a rigid translation of both."""
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_contact_decks import Deck, graded  # noqa: E402

R, E, NU, H = 50.0, 20.0, 0.3, 4.0
ESTAR = E/(2.0*(1.0 - NU*NU))
RSTAR = R/2.0
A_REF = math.sqrt(RSTAR*H)                       # 10 mm
P0_REF = 2.0*ESTAR*A_REF/(math.pi*RSTAR)         # 2.7983 GPa
F_REF = 4.0/3.0*ESTAR*math.sqrt(RSTAR)*H**1.5    # 586.1 kN
TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')


def ball(s, t, w):
    """the cube-to-ball map of (s, t, w) in [0, 1]^3 onto the unit ball's octant"""
    return (s*math.sqrt(max(0.0, 1 - t*t/2 - w*w/2 + t*t*w*w/3)),
            t*math.sqrt(max(0.0, 1 - s*s/2 - w*w/2 + s*s*w*w/3)),
            w*math.sqrt(max(0.0, 1 - s*s/2 - t*t/2 + s*s*t*t/3)))


def mesh(n):
    """nodes {(body, i, j, k): (x, y, z)} and hexahedra [(body, [8 keys])] of both bodies; the
    upper (slave) body has n + 1 elements over the zone: a slave node on a master node meets
    four segments with four normals of the faceted sphere and flips between them (the
    matching meshes cycled at a residual ratio of 2e-3)"""
    nodes, hexes = {}, []
    for body in (1, 2):
        nb = n if body == 1 else n + 1
        ss = graded(nb, 0.4, 1.0)
        ws = [1.0 - v for v in reversed(graded(nb, 0.4, 1.0))]
        m, l = len(ss) - 1, len(ws) - 1
        sgn = 1.0 if body == 1 else -1.0
        for k in range(l + 1):
            for j in range(m + 1):
                for i in range(m + 1):
                    x, y, z = ball(ss[i], ss[j], ws[k])
                    nodes[body, i, j, k] = (R*x, R*y, sgn*(R*z - R))
        for k in range(l):
            for j in range(m):
                for i in range(m):
                    lo = [(body, i, j, k), (body, i + 1, j, k), (body, i + 1, j + 1, k),
                          (body, i, j + 1, k)]
                    hi = [(b, ii, jj, kk + 1) for b, ii, jj, kk in lo]
                    hexes.append((body, lo + hi if body == 1 else hi + lo))
    return nodes, hexes


def gen(n, steps, sfs, out):
    d = Deck()
    nodes, hexes = mesh(n)
    ids = {key: d.node(*nodes[key]) for key in sorted(nodes)}
    d.w('*CONTROL_TERMINATION\n       1.0\n')
    d.w('*CONTROL_IMPLICIT_GENERAL\n$   IMFLAG       DT0\n         1%10.6g\n' % (1.0/steps))
    d.w('*CONTROL_IMPLICIT_SOLUTION\n$   NSOLVR    ILIMIT    MAXREF     DCTOL     ECTOL'
        '     RCTOL     LSTOL    ABSTOL\n        12         0        40    1.0e-6    1.0e-8'
        '    1.0e-8         0    1.0e-9\n')
    d.w('*DATABASE_SPCFORC\n%10.6g\n' % (1.0/steps))
    d.w('*DATABASE_BINARY_D3PLOT\n       1.0\n')
    for pid, title in ((1, 'lower hemisphere'), (2, 'upper hemisphere')):
        d.w('*PART\n%s\n%10d%10d%10d\n' % (title, pid, 1, 1))
    d.w('*SECTION_SOLID\n%10d%10d\n' % (1, 2))
    d.w('*MAT_ELASTIC\n%10d%10.4g%10.4g%10.4g\n' % (1, 7.85e-6, E, NU))
    for body, c in hexes:
        d.hex(body, [ids[key] for key in c])
    xsym = [ids[key] for key in sorted(nodes) if key[1] == 0]
    ysym = [ids[key] for key in sorted(nodes) if key[2] == 0]
    low = [ids[key] for key in sorted(nodes) if key[0] == 1 and key[3] == 0]
    up = [ids[key] for key in sorted(nodes) if key[0] == 2 and key[3] == 0]
    d.node_set(1, xsym); d.node_set(2, ysym); d.node_set(3, low); d.node_set(4, up)
    d.w('*BOUNDARY_SPC_SET\n         1         0         1         0         0\n')
    d.w('*BOUNDARY_SPC_SET\n         2         0         0         1         0\n')
    # the lower face held in z (its reactions in spcforc give F), the upper one moved by -h:
    # SSNV104's +-2 mm up to a rigid translation of both bodies
    d.w('*BOUNDARY_SPC_SET\n         3         0         0         0         1\n')
    d.w('*DEFINE_CURVE\n         1\n%20.8g%20.8g\n%20.8g%20.8g\n' % (0.0, 0.0, 1.0, H))
    d.w('*BOUNDARY_PRESCRIBED_MOTION_SET\n         4         3         2         1      -1.0\n')
    d.w('*CONTACT_SURFACE_TO_SURFACE_ID\n         1ssnv104\n')
    d.w('$     SSID      MSID     SSTYP     MSTYP\n         2         1         3         3\n')
    d.w('$       FS        FD\n       0.0       0.0\n')
    d.w('$      SFS       SFM\n%10.4g%10.4g\n' % (sfs, sfs))
    d.write(out, '*TITLE\ncode_aster SSNV104: two hemispheres R 50, h 4 mm, quarter, n = %d\n'
            '$ generated by scripts/ssnv104.py gen --n %d --steps %d --sfs %g; '
            'reference a = %.4f mm, p0 = %.5f GPa, F = %.2f kN\n'
            % (n, n, steps, sfs, A_REF, P0_REF, F_REF))
    print('ssnv104: n = %d, %d elements, %d nodes, surface element at the pole %.3g mm'
          % (n, d.ne, d.nn, R*0.4/n*math.sqrt(0.5)))


def fit(samples):
    """p0, a of the Hertz ellipse p^2 = p0^2 (1 - r^2/a^2) through [(r, p)] (least squares
    of p^2 against r^2 over p > 0.3 max p)"""
    pmax = max(p for _, p in samples)
    pts = [(r*r, p*p) for r, p in samples if p > 0.3*pmax]
    k = len(pts)
    mx = sum(u for u, _ in pts)/k
    my = sum(v for _, v in pts)/k
    slope = sum((u - mx)*(v - my) for u, v in pts)/sum((u - mx)**2 for u, _ in pts)
    c0 = my - slope*mx
    return math.sqrt(c0), math.sqrt(-c0/slope), k


def dynx_result(out):
    import dxpost
    h5 = os.path.join(out, 'd3plot.h5')
    k = len(dxpost.states(h5))
    _, x0 = dxpost.dataset(h5, dxpost.state_path(1) + '/coordinates')
    _, sig = dxpost.dataset(h5, dxpost.state_path(k) + '/stress')
    _, conn = dxpost.dataset(h5, '/mesh/hex8')
    _, pid = dxpost.dataset(h5, '/mesh/part_ids')
    x = dxpost.vec3(x0)
    c0 = (0.0, 0.0, -R)
    samples, pole = [], None
    for e in range(len(pid)):
        if pid[e] != 1:
            continue
        nd = conn[8*e:8*e + 8]
        on = sum(1 for q in nd if abs(math.dist(x[q], c0) - R) < 1e-6*R)
        if on < 4:
            continue
        c = [sum(x[q][j] for q in nd)/8.0 for j in range(3)]
        nv = [c[0] - c0[0], c[1] - c0[1], c[2] - c0[2]]
        ln = math.sqrt(sum(v*v for v in nv))
        nv = [v/ln for v in nv]
        s = sig[6*e:6*e + 6]     # xx yy zz xy yz zx
        t = [[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]]
        snn = sum(nv[i]*t[i][j]*nv[j] for i in range(3) for j in range(3))
        r = math.hypot(c[0], c[1])
        samples.append((r, -snn))
        if pole is None or r < pole[0]:
            pole = (r, -s[2])
    p0, a, k = fit(samples)
    res = [l for l in open(os.path.join(out, 'spcforc')) if 'force resultants' in l]
    # the z resultant: the lower face's reactions (the symmetry planes take no z force)
    F = 4.0*abs(float(res[-1].split('=')[1].split()[2]))
    return a, p0, pole[1], F, k


def post(out, tol):
    from dxpost import report
    a, p0, szz, F, k = dynx_result(out)
    print('SSNV104: F = %.5g kN (Hertz %.5g at h = 4), %d surface elements in the fit' % (F, F_REF, k))
    ok = report('contact radius a [mm] vs SSNV104', a, A_REF, 0.0, tol)
    ok &= report('p0 (fit) [GPa] vs SSNV104', p0, P0_REF, 0.0, tol)
    ok &= report('-sigma_zz at the pole element [GPa] vs SSNV104', szz, P0_REF, 0.0, tol)
    return ok


def main():
    args = sys.argv[1:]
    cmd = args.pop(0)

    def opt(name, default, conv=float):
        if name in args:
            i = args.index(name)
            v = conv(args[i + 1])
            del args[i:i + 2]
            return v
        return default
    if cmd == 'gen':
        n = opt('--n', 6, int)
        steps = opt('--steps', 4, int)
        sfs = opt('--sfs', 100.0)
        gen(n, steps, sfs, args[0])
    elif cmd == 'post':
        tol = opt('--tol', 0.1)
        sys.exit(0 if post(args[0], tol) else 1)
    else:
        raise SystemExit(__doc__)


if __name__ == '__main__':
    main()
