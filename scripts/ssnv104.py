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

  ssnv104.py gen  [--n 6] [--steps 4] [--sfs 100] [--h 4] [--auto] OUT.k   the deck
  ssnv104.py post OUTDIR [--tol 0.1] [--h 4]                      F, a, p0 against Hertz
  ssnv104.py check OUTDIR                                         the regression case
  ssnv104.py study [--n 4,6] [--steps 4] [--h 4] [--ccx] WORKDIR  the meshes, dynx and ccx
      (ccx C3D8I with TYPE=SURFACE TO SURFACE penalty contact, slope 50 E per mm, small
      strain and NLGEOM, on the dynx deck's nodes, elements and sets; not in make test)

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


def refs(h):
    """Hertz a, p0, F at the crushing h (SSNV104: h = 4 -> 10 mm, 2.7983 GPa, 586.1 kN)"""
    a = math.sqrt(RSTAR*h)
    return a, 2.0*ESTAR*a/(math.pi*RSTAR), 4.0/3.0*ESTAR*math.sqrt(RSTAR)*h**1.5


A_REF, P0_REF, F_REF = refs(H)
TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')


def ball(s, t, w):
    """the cube-to-ball map of (s, t, w) in [0, 1]^3 onto the unit ball's octant"""
    return (s*math.sqrt(max(0.0, 1 - t*t/2 - w*w/2 + t*t*w*w/3)),
            t*math.sqrt(max(0.0, 1 - s*s/2 - w*w/2 + s*s*w*w/3)),
            w*math.sqrt(max(0.0, 1 - s*s/2 - t*t/2 + s*s*t*t/3)))


def mesh(n, zone=0.4):
    """nodes {(body, i, j, k): (x, y, z)} and hexahedra [(body, [8 keys])] of both bodies; the
    upper (slave) body has n + 1 elements over the zone: a slave node on a master node meets
    four segments with four normals of the faceted sphere and flips between them (the
    matching meshes cycled at a residual ratio of 2e-3)"""
    nodes, hexes = {}, []
    for body in (1, 2):
        nb = n if body == 1 else n + 1
        ss = graded(nb, zone, 1.0)
        ws = [1.0 - v for v in reversed(graded(nb, zone, 1.0))]
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


def gen(n, steps, sfs, out, h=H, auto=False):
    """the deck; at a crushing h other than SSNV104's 4 mm the fine zone scales with a; auto:
    *CONTROL_IMPLICIT_AUTO IAUTO = 1 (ITEOPT 11, ITEWIN 5)"""
    d = Deck()
    zone = 0.4*math.sqrt(h/H)
    nodes, hexes = mesh(n, zone)
    ids = {key: d.node(*nodes[key]) for key in sorted(nodes)}
    d.w('*CONTROL_TERMINATION\n       1.0\n')
    d.w('*CONTROL_IMPLICIT_GENERAL\n$   IMFLAG       DT0\n         1%10.6g\n' % (1.0/steps))
    if auto:
        d.w('*CONTROL_IMPLICIT_AUTO\n$    IAUTO    ITEOPT    ITEWIN     DTMIN     DTMAX\n'
            '         1        11         5         0         0\n')
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
    d.w('*DEFINE_CURVE\n         1\n%20.8g%20.8g\n%20.8g%20.8g\n' % (0.0, 0.0, 1.0, h))
    d.w('*BOUNDARY_PRESCRIBED_MOTION_SET\n         4         3         2         1      -1.0\n')
    d.w('*CONTACT_SURFACE_TO_SURFACE_ID\n         1ssnv104\n')
    d.w('$     SSID      MSID     SSTYP     MSTYP\n         2         1         3         3\n')
    d.w('$       FS        FD\n       0.0       0.0\n')
    d.w('$      SFS       SFM\n%10.4g%10.4g\n' % (sfs, sfs))
    ar, pr, fr = refs(h)
    d.write(out, '*TITLE\ncode_aster SSNV104: two hemispheres R 50, h %g mm, quarter, n = %d\n'
            '$ generated by scripts/ssnv104.py gen --n %d --steps %d --sfs %g --h %g%s; '
            'Hertz a = %.4f mm, p0 = %.5f GPa, F = %.2f kN\n'
            % (h, n, n, steps, sfs, h, ' --auto' if auto else '', ar, pr, fr))
    print('ssnv104: n = %d, %d elements, %d nodes, surface element at the pole %.3g mm'
          % (n, d.ne, d.nn, R*zone/n*math.sqrt(0.5)))


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


def post(out, tol, h=H):
    from dxpost import report
    ar, pr, fr = refs(h)
    a, p0, szz, F, k = dynx_result(out)
    print('SSNV104: F = %.5g kN (Hertz %.5g at h = %g), %d surface elements in the fit'
          % (F, fr, h, k))
    ok = report('force F [kN] vs Hertz', F, fr, 0.0, tol)
    ok &= report('contact radius a [mm] vs Hertz', a, ar, 0.0, tol)
    ok &= report('p0 (fit) [GPa] vs Hertz', p0, pr, 0.0, tol)
    ok &= report('-sigma_zz at the pole element [GPa] vs Hertz', szz, pr, 0.0, tol)
    return ok


# CalculiX 2.20 (ccx C3D8I, NLGEOM, surface-to-surface penalty 50 E/mm; `ssnv104.py study
# --n 4 --ccx`) on the regression case's mesh (n = 4, 4 load steps): F [kN], a [mm], p0 (fit)
# and the pole element's -sigma_zz [GPa]
CCX_N4_NLGEOM = (582.1668, 9.823007, 2.250547, 2.186682)


def check(out):
    """The regression case implicit_ssnv104 (n = 4): (1) beside CalculiX on the same mesh
    (CCX_N4_NLGEOM, both finite strain, St. Venant-Kirchhoff): F, a, p0 and the pole's
    sigma_zz within 3 %, 2.4x the largest difference measured (p0 1.2 %: two element
    formulations, B-bar against incompatible modes, on a mesh of 2.8 elements across a);
    (2) SSNV104's a = 10 mm within 5 % (measured -2.2 %; this coarse mesh's error, -0.5 %
    at n = 6); p0 is printed against 2.7983 GPa, not asserted: the coarse mesh and the finite
    strain put it 21 % low (README); (3) Newton converged in every step: the run's exit 0."""
    from dxpost import report
    a, p0, szz, F, k = dynx_result(out)
    cf, ca, cp, cs = CCX_N4_NLGEOM
    ok = report('F [kN] vs ccx C3D8I NLGEOM', F, cf, 0.0, 0.03)
    ok &= report('a [mm] vs ccx', a, ca, 0.0, 0.03)
    ok &= report('p0 (fit) [GPa] vs ccx', p0, cp, 0.0, 0.03)
    ok &= report('pole -sigma_zz [GPa] vs ccx', szz, cs, 0.0, 0.03)
    ok &= report('a [mm] vs SSNV104 10 mm', a, A_REF, 0.0, 0.05)
    print('p0 %.4f GPa, pole -sigma_zz %.4f GPa against SSNV104 %.4f (%+.1f %%, %+.1f %%), F %.2f '
          'kN against Hertz %.2f (%+.2f %%); %d surface elements in the fit'
          % (p0, szz, P0_REF, 100*(p0/P0_REF - 1), 100*(szz/P0_REF - 1), F, F_REF,
             100*(F/F_REF - 1), k))
    return ok


# ---- CalculiX (Debian calculix-ccx) on the same mesh
FACES = {1: (0, 1, 2, 3), 2: (4, 7, 6, 5), 3: (0, 4, 5, 1), 4: (1, 5, 6, 2), 5: (2, 6, 7, 3),
         6: (3, 7, 4, 0)}     # C3D8 faces S1..S6 (ccx = Abaqus numbering)


def read_deck(path):
    """nodes {id: (x, y, z)}, elements [(id, part, [8 ids])], node sets {sid: [ids]}"""
    nodes, elems, sets = {}, [], {}
    kw, lines = None, open(path).read().split('\n')
    i = 0
    while i < len(lines):
        l = lines[i]
        if l.startswith('*'):
            kw = l.strip()
            if kw == '*SET_NODE_LIST':
                sid = int(lines[i + 1].split()[0])
                sets[sid] = []
                i += 2
                while i < len(lines) and not lines[i].startswith('*'):
                    sets[sid] += [int(v) for v in lines[i].split()]
                    i += 1
                continue
        elif l.strip() and not l.startswith('$'):
            if kw == '*NODE':
                nodes[int(l[:8])] = (float(l[8:24]), float(l[24:40]), float(l[40:56]))
            elif kw == '*ELEMENT_SOLID':
                e, pid = int(l[:8]), int(l[8:16])
                c = [int(lines[i + 1][8*q:8*q + 8]) for q in range(8)]
                elems.append((e, pid, c))
                i += 1
        i += 1
    return nodes, elems, sets


def ccx_inp(deck, path, nlgeom, etype, steps, h):
    nodes, elems, sets = read_deck(deck)
    cen = {1: (0.0, 0.0, -R), 2: (0.0, 0.0, R)}
    surf = {1: [], 2: []}
    for e, pid, c in elems:
        for f, q in FACES.items():
            if all(abs(math.dist(nodes[c[v]], cen[pid]) - R) < 1e-6*R for v in q):
                surf[pid].append((e, f))
    with open(path, 'w') as fh:
        fh.write('*NODE, NSET=NALL\n')
        for k in sorted(nodes):
            fh.write('%d, %.9f, %.9f, %.9f\n' % (k, *nodes[k]))
        fh.write('*ELEMENT, TYPE=%s, ELSET=EALL\n' % etype)
        for e, pid, c in elems:
            fh.write('%d, %s\n' % (e, ', '.join(str(v) for v in c)))
        for sid, name in ((1, 'NX'), (2, 'NY'), (3, 'NLOW'), (4, 'NUP')):
            fh.write('*NSET, NSET=%s\n' % name)
            for i in range(0, len(sets[sid]), 8):
                fh.write(', '.join(str(v) for v in sets[sid][i:i + 8]) + '\n')
        fh.write('*ELSET, ELSET=ELOW\n')
        low = [e for e, pid, _ in elems if pid == 1]
        for i in range(0, len(low), 8):
            fh.write(', '.join(str(v) for v in low[i:i + 8]) + '\n')
        for pid, name in ((1, 'MASTER'), (2, 'SLAVE')):
            fh.write('*SURFACE, NAME=%s, TYPE=ELEMENT\n' % name)
            for e, f in surf[pid]:
                fh.write('%d, S%d\n' % (e, f))
        fh.write('*MATERIAL, NAME=EL\n*ELASTIC\n%g, %g\n' % (E, NU))
        fh.write('*SOLID SECTION, ELSET=EALL, MATERIAL=EL\n')
        fh.write('*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n'
                 '%g\n' % (50.0*E))
        fh.write('*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n')
        fh.write('*BOUNDARY\nNX, 1, 1, 0.\nNY, 2, 2, 0.\nNLOW, 3, 3, 0.\nNUP, 3, 3, %g\n' % (-h))
        fh.write('*STEP%s, INC=1000\n*STATIC\n%g, 1.0\n' % (', NLGEOM' if nlgeom else '', 1.0/steps))
        fh.write('*NODE PRINT, NSET=NLOW, TOTALS=ONLY\nRF\n*EL PRINT, ELSET=ELOW\nS\n*END STEP\n')
    return nodes, elems


def ccx_result(dat, nodes, elems):
    """F, and the surface layer's (r, p) samples and the pole element's -sigma_zz, from the
    last increment of ccx's .dat (stresses: the mean of each element's 8 points)"""
    txt = open(dat).read().split('\n')
    F, blocks, cur = None, {}, None
    for i, l in enumerate(txt):
        if l.strip().startswith('total force'):
            F = 4.0*abs(float(txt[i + 2].split()[2]))
        elif l.strip().startswith('stresses'):
            cur = {}
            blocks = cur
        elif cur is not None and l.strip():
            t = l.split()
            if len(t) == 8:
                try:
                    e = int(t[0])
                    cur.setdefault(e, []).append([float(v) for v in t[2:]])
                except ValueError:
                    pass
    c0 = (0.0, 0.0, -R)
    samples, pole = [], None
    for e, pid, c in elems:
        if pid != 1 or e not in blocks:
            continue
        on = sum(1 for q in c if abs(math.dist(nodes[q], c0) - R) < 1e-6*R)
        if on < 4:
            continue
        sv = [sum(p[j] for p in blocks[e])/len(blocks[e]) for j in range(6)]  # xx yy zz xy xz yz
        t = [[sv[0], sv[3], sv[4]], [sv[3], sv[1], sv[5]], [sv[4], sv[5], sv[2]]]
        cc = [sum(nodes[q][j] for q in c)/8.0 for j in range(3)]
        nv = [cc[j] - c0[j] for j in range(3)]
        ln = math.sqrt(sum(v*v for v in nv))
        nv = [v/ln for v in nv]
        snn = sum(nv[i]*t[i][j]*nv[j] for i in range(3) for j in range(3))
        r = math.hypot(cc[0], cc[1])
        samples.append((r, -snn))
        if pole is None or r < pole[0]:
            pole = (r, -sv[2])
    p0, a, k = fit(samples)
    return a, p0, pole[1], F, k


def timed(cmd, cwd=None):
    t0 = time.time()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.time() - t0


def study(work, ns, steps, h, ccx):
    """dynx (and ccx C3D8I small-strain and NLGEOM) on meshes ns: F, a, p0 (fit), -sigma_zz of
    the pole element, wall s"""
    os.makedirs(work, exist_ok=True)
    ar, pr, fr = refs(h)
    print('Hertz at h = %g: F %.2f kN, a %.4f mm, p0 %.4f GPa' % (h, fr, ar, pr))
    print('%-22s %4s %9s %8s %8s %8s %8s' % ('run', 'n', 'F kN', 'a mm', 'p0 GPa', 'pole', 'wall s'))
    for n in ns:
        deck = os.path.join(work, 'ssnv104_n%d.k' % n)
        gen(n, steps, 100.0, deck, h)
        out = os.path.join(work, 'dynx_n%d' % n)
        td = timed([os.path.join(TOP, 'bin', 'dynx'), '-i', deck, '-o', out])
        a, p0, szz, F, _ = dynx_result(out)
        print('%-22s %4d %9.2f %8.4f %8.4f %8.4f %8.1f' % ('dynx ELFORM 2 (TL)', n, F, a, p0, szz, td))
        if not ccx:
            continue
        for nl in (False, True):
            base = 'ccx_n%d%s' % (n, '_nlgeom' if nl else '')
            nodes, elems = ccx_inp(deck, os.path.join(work, base + '.inp'), nl, 'C3D8I', steps, h)
            tc = timed(['ccx', base], cwd=work)
            a, p0, szz, F, _ = ccx_result(os.path.join(work, base + '.dat'), nodes, elems)
            print('%-22s %4d %9.2f %8.4f %8.4f %8.4f %8.1f' % (
                'ccx C3D8I' + (' NLGEOM' if nl else ''), n, F, a, p0, szz, tc))


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
        h = opt('--h', H)
        auto = '--auto' in args
        args = [v for v in args if v != '--auto']
        gen(n, steps, sfs, args[0], h, auto)
    elif cmd == 'study':
        ns = [int(v) for v in opt('--n', '4', str).split(',')]
        steps = opt('--steps', 4, int)
        h = opt('--h', H)
        ccx = '--ccx' in args
        args = [v for v in args if v != '--ccx']
        study(os.path.abspath(args[0] if args else 'build/ssnv104'), ns, steps, h, ccx)
    elif cmd == 'check':
        sys.exit(0 if check(args[0]) else 1)
    elif cmd == 'post':
        tol = opt('--tol', 0.1)
        h = opt('--h', H)
        sys.exit(0 if post(args[0], tol, h) else 1)
    else:
        raise SystemExit(__doc__)


if __name__ == '__main__':
    main()
