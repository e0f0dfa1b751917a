#!/usr/bin/env python3
"""Error-against-run-time studies for dynx (driven by scripts/studies.sh, `make studies`).

  studies.py wave   BUILD DOCS   elastic wave in a bar: mesh and time-step sweeps
  studies.py taylor BUILD DOCS   Taylor bar, Simo (1992) benchmark: mesh / element sweep
  studies.py wg     BUILD DOCS   Taylor bar, Wilkins-Guinan (1973) copper: mesh, rate scaling
  studies.py readme BUILD DOCS   docs/studies/README.md from the JSON results of the above

Each study generates its decks with scripts/gen_*_deck.py into BUILD/<study>/, runs bin/dynx
on them one after the other (so the wall times are not disturbed by a second run), reads the
results with scripts/dxpost.py, and writes DOCS/<study>.md (markdown table),
DOCS/data/<study>*.dat + .gp (gnuplot input; studies.sh renders the PNGs) and
BUILD/<study>.json (the numbers, for the README). Python standard library only."""
import json, math, os, re, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
import study_order  # noqa: E402  (observed orders, Richardson extrapolation)
DYNX = os.path.join(ROOT, 'bin', 'dynx')
PY = sys.executable or 'python3'

# Simo benchmark: converged reference (Foulk et al. 2021) and the classical values
SIMO_L0, SIMO_R0, SIMO_V = 32.4, 3.2, 227.0
LREF, RREF = 21.45, 7.225
# Wilkins-Guinan (1973) OFHC copper at 210 m/s
WG_L0, WG_R0, WG_V = 23.47, 3.81, 210.0
WG_LF_L0, WG_RF_R0 = 0.630, 2.204
# elastic wave (gen_wave_deck.py material)
RHO, E, NU = 7.85e-6, 210.0, 0.3
M = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
CL = math.sqrt(M / RHO)



# every scene under decks/ and its page (docs/studies/README.md; doc_numbers.py --check
# tests that the list names every deck directory)
SCENE_PAGES = ['Every scene under `decks/` and the page with its error against run time and observed order:',
               '',
               '| scene | page |',
               '|---|---|',
               '| ball_in_box | [ball_in_box.md](ball_in_box.md) (TSSFAC and SFS sweeps) |',
               '| brittle_impact | [seed_scene_orders.md](seed_scene_orders.md) |',
               '| brittle_impact_2d | [more_scene_orders.md](more_scene_orders.md) |',
               '| cmc_implant | [more_scene_orders.md](more_scene_orders.md) |',
               '| elastic_wave | section 1 below, [elastic_wave.md](elastic_wave.md) |',
               '| emc_ball_box | [emc.md](emc.md) (step sweep) |',
               '| emc_ball_shell | [emc.md](emc.md) (step sweep) |',
               '| emc_bars | [scene_orders.md](scene_orders.md), [emc.md](emc.md) |',
               '| hertz | [hertz.md](hertz.md) |',
               '| incline_friction | [scene_orders.md](scene_orders.md) |',
               '| knee_insert | [more_scene_orders.md](more_scene_orders.md) |',
               '| laser_backside | [more_scene_orders.md](more_scene_orders.md) (no order '
               'expected: crack model without a length scale) |',
               '| laser_subsurface | [more_scene_orders.md](more_scene_orders.md) (no order '
               'expected: crack model without a length scale) |',
               "| patch_test | none: constant strain is reproduced to round-off (no discretisation error to refine); the rigid rotation's residual is the prescribed curves' chords, about 1/N^2 in the curve points (decks/patch_test/README.md) |",
               '| pressure_table | [seed_scene_orders.md](seed_scene_orders.md) |',
               '| rod_impact | [scene_orders.md](scene_orders.md) |',
               '| shell_box_post | [seed_scene_orders.md](seed_scene_orders.md) |',
               '| shell_projectile_plate | [seed_scene_orders.md](seed_scene_orders.md) |',
               '| sliding_block | [scene_orders.md](scene_orders.md) |',
               '| spall_plate_impact | [spall.md](spall.md) |',
               '| ssnv104 | [more_scene_orders.md](more_scene_orders.md) |',
               "| taylor_bar | section 2 below, [taylor_simo.md](taylor_simo.md) (Richardson); Wilkins-Guinan: section 3 (no order: the material model's error) |",
               '| taylor_bar_axisym | [scene_orders.md](scene_orders.md) |',
               '| taylor_steinberg | [scene_orders.md](scene_orders.md) |']


def sh(cmd, log=None):
    """Run cmd; return (rc, stdout+stderr, elapsed s)."""
    t0 = time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    el = time.perf_counter() - t0
    if log:
        with open(log, 'w') as f:
            f.write(p.stdout)
    return p.returncode, p.stdout, el


def gen(script, args, deck):
    rc, out, _ = sh([PY, os.path.join(ROOT, 'scripts', script)] + args + [deck])
    if rc != 0:
        raise SystemExit('studies: %s failed:\n%s' % (script, out))


def run_dynx(deck, outdir, log):
    """Run one deck; parse the end-of-run lines. A numerical failure (exit 3) is a result."""
    rc, out, el = sh([DYNX, '-i', deck, '-o', outdir, '--status', '4'], log)
    r = {'rc': rc, 'elapsed': el, 'wall': None, 'ns': None, 'cycles': None, 'ratio': None,
         'message': ''}
    m = re.search(r'wall time\s+([0-9.Ee+-]+)\s*s,\s*([0-9.Ee+-]+)\s*ns per element-cycle', out)
    if m:
        r['wall'], r['ns'] = float(m.group(1)), float(m.group(2))
    m = re.search(r'normal termination at cycle\s+(\d+), time\s+([0-9.Ee+-]+), energy ratio\s+'
                  r'([0-9.Ee+-]+)', out)
    if m:
        r['cycles'], r['tend'], r['ratio'] = int(m.group(1)), float(m.group(2)), float(m.group(3))
    if rc != 0:
        errs = [l.strip() for l in out.splitlines() if 'error' in l.lower()]
        r['message'] = errs[0] if errs else out.strip().splitlines()[-1]
        m = re.search(r'cycle\s+(\d+), time\s+([0-9.Ee+-]+)', r['message'])
        if m:
            r['cycles'], r['tend'] = int(m.group(1)), float(m.group(2))
    if r['wall'] is None:          # failed runs print no wall-time line: use the process time
        r['wall'] = el
    return r


def post(args):
    rc, out, _ = sh([PY, os.path.join(ROOT, 'scripts', 'dxpost.py')] + args)
    return out


def num(pattern, text):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else float('nan')


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)


def fmt(x, f='%.4g'):
    return '-' if x is None or (isinstance(x, float) and not math.isfinite(x)) else f % x


# ---------------------------------------------------------------------------------------------
def wave(build, docs):
    b = os.path.join(build, 'wave')
    os.makedirs(b, exist_ok=True)
    repeats = 3
    # (nx, TSSFAC, linear bulk viscosity Q2); the deck default Q2 is 0.06. The two Q2 = 1e-4
    # rows (0 would mean "default") show what the linear bulk viscosity does to the front.
    cases = [(nx, 0.9, 0.06) for nx in (25, 50, 100, 200, 400)] + [(100, 0.6, 0.06),
             (100, 0.3, 0.06), (100, 0.9, 1e-4), (400, 0.9, 1e-4)]
    rows = []
    for nx, s, q2 in cases:
        name = 'nx%d_s%02d' % (nx, round(10 * s)) + ('' if q2 == 0.06 else '_q2small')
        deck = os.path.join(b, name + '.k')
        gen('gen_wave_deck.py', ['--nx', str(nx), '--tssfac', str(s), '--q2', str(q2)], deck)
        runs = []
        for k in range(repeats):          # tiny runs: best of 3 against timer noise
            r = run_dynx(deck, os.path.join(b, name), os.path.join(b, name + '.log'))
            if r['rc'] != 0:
                raise SystemExit('studies: wave %s failed: %s' % (name, r['message']))
            runs.append(r)
        r = min(runs, key=lambda x: x['wall'])
        csv = os.path.join(b, name + '.csv')
        out = post(['wave', os.path.join(b, name), '--csv', csv])
        h = num(r'\bh\s+([0-9.Ee+-]+)', out)
        t = num(r'^t\s+([0-9.Ee+-]+)', out)
        pl = num(r'plateau stress \[GPa\]\s+([0-9.Ee+-]+)', out)
        plref = num(r'plateau stress \[GPa\]\s+\S+\s+reference\s+([0-9.Ee+-]+)', out)
        xf = num(r'front position \[mm\]\s+([0-9.Ee+-]+|nan)', out)
        xfref = num(r'front position \[mm\]\s+\S+\s+reference\s+([0-9.Ee+-]+)', out)
        over = num(r'overshoot \(min/plateau - 1\)\s+([0-9.Ee+-]+)', out)
        ahead = num(r'stress ahead of front \[GPa\]\s+([0-9.Ee+-]+)', out)
        prof = [[float(v) for v in l.split()] for l in open(csv) if l.lstrip()[:1] in tuple('+-.0123456789')]
        l1 = sum(h * abs(sg - sa) for _, sg, sa in prof) / abs(plref)
        courant = CL * t / r['cycles'] / h

        def cross(fr):                     # fr * plateau crossing, searched from the far end
            for i in range(len(prof) - 1, 0, -1):
                (x1, s1, _), (x0, s0, _) = prof[i], prof[i - 1]
                if (s0 - fr * plref) * (s1 - fr * plref) <= 0 and s0 != s1:
                    return x0 + (fr * plref - s0) * (x1 - x0) / (s1 - s0)
            return float('nan')
        rise = cross(0.1) - cross(0.9)
        rows.append({'rise': rise, 'l1': l1, 'courant': courant, 'q2': q2,
                     'name': name, 'nx': nx, 'tssfac': s, 'h': h, 't': t, 'cycles': r['cycles'],
                     'plateau': pl, 'plateau_ref': plref, 'plateau_rel': (pl - plref) / plref,
                     'front': xf, 'front_ref': xfref, 'front_err': xf - xfref,
                     'front_err_el': (xf - xfref) / h, 'overshoot': over, 'ahead': ahead,
                     'wall': r['wall'], 'walls': [x['wall'] for x in runs], 'ns': r['ns'],
                     'ratio': r['ratio'], 'elapsed': r['elapsed'], 'csv': csv})
        print('wave %-9s Courant %.3f plateau err %+.2e  front err %+.4f mm (%+.3f el)  '
              'L1 %.4f mm  overshoot %.2e  wall %.3g s' % (
                  name, courant, rows[-1]['plateau_rel'], rows[-1]['front_err'],
                  rows[-1]['front_err_el'], l1, over, r['wall']), flush=True)
    # table
    L = ['# Elastic wave in a bar: error against run time', '',
         'Steel bar 100 x 1 x 1 mm on rollers (uniaxial strain), end x = 0 driven at 1 m/s; '
         'analytic step sigma_xx = -rho cL v = %.5g GPa (cL = %.5g mm/ms) at x = cL t. '
         'Read at t = %.4g ms (last plot state). Front = half-plateau crossing of the element '
         'stresses (linear interpolation between centroids). Wall = dynx solver wall time, '
         'best of %d runs. Courant = cL dt / h with the mean step dt = t / cycles: the '
         'stable step comes from the characteristic length V / (largest face area), which is '
         'the 1 mm cross-section as long as h >= 1 mm, so nx = 25, 50 and 100 all take the same '
         'step and the coarse meshes run at a small axial Courant number. L1 = sum over elements '
         'of h |sigma_e - sigma_analytic(x_e)| / |sigma_0| (mm: the width of the smeared and '
         'ringing region).' % (-RHO * CL * 1.0, CL, rows[0]['t'], repeats), '',
         '| nx | TSSFAC | Q2 | h [mm] | cycles | Courant | plateau [GPa] | plateau rel. error '
         '| cL t [mm] | front [mm] | front error [mm] | front error [elements] | 10-90%% rise [mm] | L1 [mm] '
         '| overshoot | wall [s] | ns / el-cycle |',
         '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for w in rows:
        L.append('| %d | %.1f | %g | %.4g | %s | %.3f | %.6g | %+.2e | %.4f | %.4f | %+.4f | %+.3f '
                 '| %.3f | %.4f | %.2e | %.3g | %s |'
                 % (w['nx'], w['tssfac'], w['q2'], w['h'], w['cycles'], w['courant'], w['plateau'],
                    w['plateau_rel'], w['front_ref'], w['front'], w['front_err'],
                    w['front_err_el'], w['rise'], w['l1'], w['overshoot'], w['wall'],
                    fmt(w['ns'], '%.0f')))
    L += ['', 'Overshoot = min(sigma_xx)/plateau - 1 (the largest compressive stress relative to '
          'the analytic plateau).', '']
    write(os.path.join(docs, 'elastic_wave.md'), '\n'.join(L))
    # plot data
    d = os.path.join(docs, 'data')
    mesh = [w for w in rows if w['tssfac'] == 0.9 and w['q2'] == 0.06]
    dt = sorted([w for w in rows if w['nx'] == 100 and w['q2'] == 0.06],
                key=lambda w: w['tssfac'])
    for tag, sel in (('mesh', mesh), ('dt', dt)):
        write(os.path.join(d, 'wave_%s.dat' % tag),
              '# nx tssfac wall_s |plateau_rel_err| |front_err_mm| |front_err_el| overshoot '
              'L1_mm courant\n' +
              ''.join('%d %.2f %.6g %.6g %.6g %.6g %.6g %.6g %.4f\n' % (
                  w['nx'], w['tssfac'], w['wall'], abs(w['plateau_rel']), abs(w['front_err']),
                  abs(w['front_err_el']), abs(w['overshoot']), w['l1'], w['courant'])
                  for w in sel))
    for w in mesh:
        with open(w['csv']) as f:
            txt = f.read()
        write(os.path.join(d, 'wave_profile_nx%d.dat' % w['nx']), txt)
    w100 = [w for w in mesh if w['nx'] == 100][0]
    write(os.path.join(d, 'wave_analytic.dat'), '# x sigma_xx analytic step at t = %.6g ms\n'
          '0 %.6g\n%.6f %.6g\n%.6f 0\n100 0\n' % (w100['t'], w100['plateau_ref'],
                                                   w100['front_ref'], w100['plateau_ref'],
                                                   w100['front_ref']))
    for w in rows:
        if w['q2'] != 0.06:
            with open(w['csv']) as f:
                write(os.path.join(d, 'wave_profile_nx%d_q2small.dat' % w['nx']), f.read())
    write(os.path.join(d, 'wave_error.gp'), '''set terminal pngcairo size 900,600 font ",11"
set output "wave_error.png"
set logscale xy
set format y "10^{%%L}"
set xlabel "dynx wall time [s] (best of %d)"
set ylabel "error"
set key outside right top box
set grid
set title "Elastic wave: error against run time (mesh sweep nx = 25..400 at TSSFAC 0.9;\\ntime-step sweep TSSFAC 0.3/0.6/0.9 at nx = 100)"
plot "wave_mesh.dat" u 3:5 w lp pt 7 lc rgb "#1f77b4" t "front |error| [mm], mesh", \\
     "" u 3:5:(sprintf("%%d",$1)) w labels offset 0,1 notitle, \\
     "" u 3:8 w lp pt 5 lc rgb "#2ca02c" t "L1 profile error [mm], mesh", \\
     "" u 3:4 w lp pt 9 lc rgb "#d62728" t "plateau rel. |error|, mesh", \\
     "" u 3:7 w lp pt 11 lc rgb "#9467bd" t "overshoot, mesh", \\
     "wave_dt.dat" u 3:5 w lp pt 6 dt 2 lc rgb "#1f77b4" t "front |error| [mm], TSSFAC", \\
     "" u 3:5:(sprintf("%%.1f",$2)) w labels offset 0,-1 tc rgb "#555555" notitle, \\
     "" u 3:8 w lp pt 4 dt 2 lc rgb "#2ca02c" t "L1 profile error [mm], TSSFAC", \\
     "" u 3:4 w lp pt 8 dt 2 lc rgb "#d62728" t "plateau rel. |error|, TSSFAC", \\
     "" u 3:7 w lp pt 10 dt 2 lc rgb "#9467bd" t "overshoot, TSSFAC"
''' % repeats)
    write(os.path.join(d, 'wave_profile.gp'), '''set terminal pngcairo size 900,550 font ",11"
set output "wave_profile.png"
set xlabel "x [mm]"
set ylabel "sigma_{xx} [MPa]"
set key bottom right box
set grid
set title sprintf("Elastic wave, nx = 100, TSSFAC 0.9, t = %.4g ms: element stress against analytic step")
plot [0:100] "wave_analytic.dat" u 1:($2*1000) w l lw 2 lc rgb "black" t "analytic", \\
     "" u 1:($2*1000) w lp pt 7 ps 0.6 lc rgb "#d62728" t "dynx nx = 100"
set output "wave_profile_zoom.png"
set title "Elastic wave near the front (t = %.4g ms), mesh sweep at TSSFAC 0.9"
set key top left box
plot [%.1f:%.1f] "wave_analytic.dat" u 1:($2*1000) w l lw 2 lc rgb "black" t "analytic", \\
     "wave_profile_nx25.dat" u 1:($2*1000) w lp pt 4 ps 0.7 t "nx = 25", \\
     "wave_profile_nx50.dat" u 1:($2*1000) w lp pt 6 ps 0.7 t "nx = 50", \\
     "wave_profile_nx100.dat" u 1:($2*1000) w lp pt 7 ps 0.6 t "nx = 100", \\
     "wave_profile_nx200.dat" u 1:($2*1000) w lp pt 5 ps 0.5 t "nx = 200", \\
     "wave_profile_nx400.dat" u 1:($2*1000) w l lw 1.5 t "nx = 400", \\
     "wave_profile_nx400_q2small.dat" u 1:($2*1000) w l lw 1 dt 2 lc rgb "#7f7f7f" t "nx = 400, Q2 = 1e-4"
''' % (rows[0]['t'], rows[0]['t'], rows[0]['front_ref'] - 20, rows[0]['front_ref'] + 10))
    write(os.path.join(build, 'wave.json'), json.dumps(rows, indent=1))


# ---------------------------------------------------------------------------------------------
def reused_run(deck, logf, before):
    """STUDIES_REUSE=1: an earlier run of the same deck (byte-identical) that ended normally is
    read back from its log instead of being run again (the long Taylor meshes)."""
    if not os.environ.get('STUDIES_REUSE') or before is None or not os.path.exists(logf):
        return None
    with open(deck) as f:
        if f.read() != before:
            return None
    out = open(logf).read()
    if 'normal termination' not in out:
        return None
    r = {'rc': 0, 'elapsed': None, 'wall': None, 'ns': None, 'message': '', 'reused': True}
    m = re.search(r'wall time\s+([0-9.Ee+-]+)\s*s,\s*([0-9.Ee+-]+)\s*ns per element-cycle', out)
    if m:
        r['wall'], r['ns'] = float(m.group(1)), float(m.group(2))
    m = re.search(r'normal termination at cycle\s+(\d+), time\s+([0-9.Ee+-]+), energy ratio\s+'
                  r'([0-9.Ee+-]+)', out)
    r['cycles'], r['tend'], r['ratio'] = int(m.group(1)), float(m.group(2)), float(m.group(3))
    return r


def taylor_case(b, name, gen_args, L0, R0):
    deck = os.path.join(b, name + '.k')
    before = open(deck).read() if os.path.exists(deck) else None
    gen('gen_taylor_deck.py', gen_args, deck)
    r = reused_run(deck, os.path.join(b, name + '.log'), before) or \
        run_dynx(deck, os.path.join(b, name), os.path.join(b, name + '.log'))
    out = post(['taylor', os.path.join(b, name), '--L0', str(L0), '--R0', str(R0)])
    r['time'] = num(r'^time\s+([0-9.Ee+-]+)', out)
    r['Lf'] = num(r'final length\s+([0-9.Ee+-]+)', out)
    r['Rf'] = num(r'footprint radius\s+([0-9.Ee+-]+)', out)
    r['lift'] = num(r'face lift-off\s+([0-9.Ee+-]+)', out)
    e = post(['energy', os.path.join(b, name)])
    r['ratio_min'] = num(r'min\s+([0-9.Ee+-]+)', e)
    r['ratio_max'] = num(r'max\s+([0-9.Ee+-]+)', e)
    r['ratio_final'] = num(r'final\s+([0-9.Ee+-]+)', e)
    log = open(os.path.join(b, name + '.log')).read()
    m = re.search(r'(\d+) elements', log)
    r['elements'] = int(m.group(1)) if m else None
    r['name'] = name
    return r


def taylor_richardson(rows):
    """Observed orders and three-mesh Richardson extrapolation of the ELFORM 1 IHQ 1 sequence
    (h = 1/n): pair orders of the error against the reference, and for each successive triple
    the order, extrapolated value and GCI (study_order.richardson) of Lf and Rf."""
    e1 = sorted([r for r in rows if r['elform'] == 1 and r['ihq'] == 1 and r['rc'] == 0],
                key=lambda r: r['n'])
    h = [1.0 / r['n'] for r in e1]
    out = {'e1': e1, 'pL': study_order.pair_orders(h, [r['dL'] for r in e1]),
           'pR': study_order.pair_orders(h, [r['dR'] for r in e1]), 'tri': []}
    for i in range(len(e1) - 2):
        t = e1[i:i + 3]
        hh = [1.0 / r['n'] for r in t]
        out['tri'].append({'meshes': ['(%d,%d,%d)' % (r['n'], r['m'], r['nz']) for r in t],
                           'L': study_order.richardson(hh, [r['Lf'] for r in t]),
                           'R': study_order.richardson(hh, [r['Rf'] for r in t]),
                           'wall': sum(r['wall'] for r in t)})
    return out


def taylor_order_lines(rows):
    o = taylor_richardson(rows)
    e1 = o['e1']
    L = ['## Observed orders (ELFORM 1, IHQ 1, h = 1/n)', '',
         'Between successive meshes, p = ln(e_i/e_(i+1)) / ln(h_i/h_(i+1)) of the error against '
         'the reference (none where the error changes sign: the sequence crosses the reference; '
         'negative where it grows again after the crossing). Expected: about 1. The footprint '
         'radius and the final length are set by the plastic zone at the impact face, whose '
         'boundary (elastic-plastic front, strain gradients at the rim) the one-point hex '
         'resolves to O(h); the strain there is large and not smooth, so the second order of '
         'the element on smooth solutions is not expected. Lf approaches the reference from '
         'above with orders a little above 1; Rf crosses the reference between (4,4,32) and '
         '(6,6,48) and keeps rising, so its order is measured without the reference, by the '
         'Richardson table below.', '',
         '| from | to | Lf error | order (Lf) | Rf error | order (Rf) | wall [s] (finer) |',
         '|---|---|---|---|---|---|---|']
    for i in range(len(e1) - 1):
        a, b = e1[i], e1[i + 1]
        L.append('| (%d,%d,%d) | (%d,%d,%d) | %+.4f -> %+.4f | %s | %+.4f -> %+.4f | %s | %.3g |' % (
            a['n'], a['m'], a['nz'], b['n'], b['m'], b['nz'], a['dL'], b['dL'],
            study_order.fmt_order(o['pL'][i]), a['dR'], b['dR'],
            study_order.fmt_order(o['pR'][i]), b['wall']))
    L += ['', '## Richardson extrapolation (three successive meshes, no reference used)', '',
          'Roache (1998) / Celik et al. (2008): observed order p from three solutions (unequal '
          'ratios allowed), extrapolated value f_ext = f3 + (f3 - f2)/(r32^p - 1), uncertainty '
          'of the finest mesh GCI = 1.25 |f3 - f2| / (r32^p - 1). Reference: Lf %.2f mm, Rf '
          '%.3f mm (Foulk et al. 2021: Lf 21.42-21.48, Rf 7.22-7.23).' % (LREF, RREF), '',
          '| meshes | p (Lf) | Lf extrapolated [mm] | GCI (Lf) | p (Rf) | Rf extrapolated [mm] '
          '| GCI (Rf) |', '|---|---|---|---|---|---|---|']
    for t in o['tri']:
        cells = []
        for k in ('L', 'R'):
            q = t[k]
            if q['p'] is None:
                cells += ['- (%s)' % q['why'], '-', '-']
            else:
                cells += ['%.2f' % q['p'], '%.4f' % q['f_ext'], '%.4f' % q['gci']]
        L.append('| %s | %s |' % (' '.join(t['meshes']), ' | '.join(cells)))
    L.append('')
    return L


def taylor(build, docs):
    b = os.path.join(build, 'taylor')
    os.makedirs(b, exist_ok=True)
    base = ['--L', str(SIMO_L0), '--R', str(SIMO_R0), '--v', str(SIMO_V), '--mat', 'j2',
            '--quarter', '--tend', '0.08']
    cases = []
    # ELFORM 1 IHQ 1 from (2,2,16) to TAYLOR_NMAX (default 12: (12,12,96), 41,472 hexes, about
    # 10 minutes on one core); the (8,8,64) mesh stopped with a negative volume at 52.1 us until
    # issue 15's one characteristic length (docs/design.md), it now runs to the end.
    nmax = int(os.environ.get('TAYLOR_NMAX', '12'))
    for n in (2, 3, 4, 6, 8, 10, 12):
        if n <= nmax:
            cases.append(('e1_%d%d%d' % (n, n, 8 * n), n, 8 * n, 1, 1, 0.1, ''))
    for n, nz in ((3, 24), (4, 32)):
        cases.append(('e2_%d%d%d' % (n, n, nz), n, nz, 2, 1, 0.1, ''))
    rows = []
    for name, n, nz, ef, ihq, qh, note in cases:
        args = base + ['--n', str(n), '--m', str(n), '--nz', str(nz), '--elform', str(ef),
                       '--ihq', str(ihq), '--qh', str(qh)]
        r = taylor_case(b, name, args, SIMO_L0, SIMO_R0)
        r.update({'n': n, 'm': n, 'nz': nz, 'elform': ef, 'ihq': ihq, 'qh': qh, 'note': note,
                  'dL': r['Lf'] - LREF, 'dR': r['Rf'] - RREF})
        rows.append(r)
        print('taylor %-14s rc %d  t %.4g  Lf %.4f  Rf %.4f  ratio %s  wall %.3g s %s' % (
            name, r['rc'], r['time'], r['Lf'], r['Rf'], fmt(r['ratio'], '%.5f'), r['wall'],
            r['message']), flush=True)
    L = ['# Taylor bar, Simo (1992) benchmark: error against run time', '',
         'Copper bar L0 = 32.4 mm, R0 = 3.2 mm, 227 m/s onto a rigid frictionless wall, J2 with '
         'linear hardening (E 117 GPa, nu 0.35, sigma_y 0.4 GPa, H 0.1 GPa), quarter model, '
         'end time 80 us, TSSFAC 0.9, bulk viscosity 1.5/0.06. Errors against the converged '
         'reference Lf = %.2f mm, Rf = %.3f mm (Foulk et al. 2021: Lf 21.42-21.48, Rf '
         '7.22-7.23); Simo (1992) gives Rf 7.12 mm, Zienkiewicz 7.11 mm. '
         'Rf = largest radius of the nodes of the initial impact face; lift-off = largest '
         'height of those nodes above the wall at the end. Wall = dynx solver wall time (for a '
         'run that stops: process time).' % (LREF, RREF), '',
         '| mesh (n,m,nz) | elements | ELFORM | IHQ / QH | end [us] | cycles | Lf [mm] '
         '| Lf - 21.45 | Rf [mm] | Rf - 7.225 | lift-off [mm] | energy ratio (final; min-max) '
         '| wall [s] | ns / el-cycle | status |',
         '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        status = 'normal termination' if r['rc'] == 0 else 'exit %d: %s' % (r['rc'], r['message'])
        L.append('| (%d,%d,%d) | %s | %d | %d / %g | %.1f | %s | %.4f | %+.4f | %.4f | %+.4f '
                 '| %.3g | %.5f; %.5f-%.5f | %.3g | %s | %s |' % (
                     r['n'], r['m'], r['nz'], r['elements'], r['elform'], r['ihq'], r['qh'],
                     1000 * r['time'], r['cycles'], r['Lf'], r['dL'], r['Rf'], r['dR'],
                     r['lift'], r['ratio_final'], r['ratio_min'], r['ratio_max'], r['wall'],
                     fmt(r['ns'], '%.0f'), status))
    L += ['', 'For a run that stops, Lf and Rf are those of the last state written (at the time '
          'of the failure), not final values.', '']
    L += taylor_order_lines(rows)
    write(os.path.join(docs, 'taylor_simo.md'), '\n'.join(L))
    d = os.path.join(docs, 'data')
    for ef in (1, 2):
        sel = [r for r in rows if r['elform'] == ef and r['rc'] == 0 and r['ihq'] == 1]
        write(os.path.join(d, 'taylor_e%d.dat' % ef),
              '# wall_s Lf dL Rf dR label\n' + ''.join(
                  '%.6g %.6f %.6f %.6f %.6f "(%d,%d,%d)"\n' % (r['wall'], r['Lf'], r['dL'], r['Rf'],
                                                              r['dR'], r['n'], r['m'], r['nz'])
                  for r in sel))
    write(os.path.join(d, 'taylor_error.gp'), '''set terminal pngcairo size 900,600 font ",11"
set output "taylor_error.png"
set logscale xy
set xlabel "dynx wall time [s]"
set ylabel "|error| against converged reference [mm]"
set key outside right top box
set grid
set title "Taylor bar (Simo 1992), quarter model: error against run time\\n(reference Lf = 21.45 mm, Rf = 7.225 mm; labels (n,m,nz); Rf crosses the reference)"
plot "taylor_e1.dat" u 1:(abs($5)) w lp pt 7 lc rgb "#d62728" t "|Rf - 7.225|, ELFORM 1 IHQ 1", \\
     "" u 1:(abs($5)):6 w labels offset 0,1 tc rgb "#d62728" notitle, \\
     "" u 1:(abs($3)) w lp pt 5 lc rgb "#1f77b4" t "|Lf - 21.45|, ELFORM 1 IHQ 1", \\
     "taylor_e2.dat" u 1:(abs($5)) w lp pt 6 dt 2 lc rgb "#d62728" t "|Rf - 7.225|, ELFORM 2", \\
     "" u 1:(abs($5)):6 w labels offset 0,-1 tc rgb "#555555" notitle, \\
     "" u 1:(abs($3)) w lp pt 4 dt 2 lc rgb "#1f77b4" t "|Lf - 21.45|, ELFORM 2"
''')
    write(os.path.join(build, 'taylor.json'), json.dumps(rows, indent=1))


# ---------------------------------------------------------------------------------------------
# Cowper-Symonds values: no documented copper (C, P) pair was found with the search tool, so the
# fallback of the brief is used: C = 40 1/s = 0.04 1/ms with P = 5 (the classical mild-steel
# pair of Cowper & Symonds 1957). A second pair is fitted here to the Johnson-Cook rate term of
# OFHC copper, 1 + 0.025 ln(rate / 1 s^-1) (Johnson & Cook 1983/85, the set whose static part
# the deck uses), at 1e3, 1e4 and 1e5 1/s: P = 9, C = 5.5e9 1/s (= 5.5e6 1/ms).
CS_FALLBACK = (0.04, 5.0)
CS_JCFIT = (5.5e6, 9.0)


def wg(build, docs):
    b = os.path.join(build, 'wg')
    os.makedirs(b, exist_ok=True)
    base = ['--L', str(WG_L0), '--R', str(WG_R0), '--v', str(WG_V), '--mat', 'wg', '--quarter',
            '--tend', '0.1']
    cases = [('wg_4424', 4, 24, None, 'rate independent (static JC curve)'),
             ('wg_6636', 6, 36, None, 'rate independent (static JC curve)'),
             ('wg_6636_cs40', 6, 36, CS_FALLBACK,
              'Cowper-Symonds C = 40 1/s, P = 5 (fallback: mild-steel pair)'),
             ('wg_6636_csjc', 6, 36, CS_JCFIT,
              'Cowper-Symonds C = 5.5e9 1/s, P = 9 (fit to JC 1 + 0.025 ln rate)')]
    rows = []
    for name, n, nz, cs, what in cases:
        args = base + ['--n', str(n), '--m', str(n), '--nz', str(nz)]
        if cs:
            args += ['--cs', '%g,%g' % cs]
        r = taylor_case(b, name, args, WG_L0, WG_R0)
        r.update({'n': n, 'm': n, 'nz': nz, 'cs': cs, 'what': what,
                  'LfL0': r['Lf'] / WG_L0, 'RfR0': r['Rf'] / WG_R0})
        rows.append(r)
        print('wg %-14s rc %d  Lf/L0 %.4f  Rf/R0 %.4f  wall %.3g s %s' % (
            name, r['rc'], r['LfL0'], r['RfR0'], r['wall'], r['message']), flush=True)
    L = ['# Taylor bar, Wilkins-Guinan (1973) OFHC copper', '',
         'L0 = 23.47 mm, R0 = 3.81 mm, 210 m/s onto a rigid frictionless wall, quarter model, '
         'end time 100 us, ELFORM 1 IHQ 1 QH 0.1. *MAT_024 with the static Johnson-Cook curve '
         'sigma_y = 0.090 + 0.292 eps_p^0.31 GPa (no rate or temperature term unless stated). '
         'Experiment: Lf/L0 = %.3f (%.2f mm), Rf/R0 = %.3f (%.2f mm).'
         % (WG_LF_L0, WG_LF_L0 * WG_L0, WG_RF_R0, WG_RF_R0 * WG_R0), '',
         '| mesh (n,m,nz) | elements | material | Lf [mm] | Lf/L0 | vs 0.630 | Rf [mm] | Rf/R0 '
         '| vs 2.204 | lift-off [mm] | energy ratio | wall [s] | status |',
         '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        status = 'normal termination' if r['rc'] == 0 else 'exit %d: %s' % (r['rc'], r['message'])
        L.append('| (%d,%d,%d) | %s | %s | %.3f | %.4f | %+.1f%% | %.3f | %.4f | %+.1f%% | %.3g '
                 '| %.5f | %.3g | %s |' % (
                     r['n'], r['m'], r['nz'], r['elements'], r['what'], r['Lf'], r['LfL0'],
                     100 * (r['LfL0'] / WG_LF_L0 - 1), r['Rf'], r['RfR0'],
                     100 * (r['RfR0'] / WG_RF_R0 - 1), r['lift'], r['ratio_final'], r['wall'],
                     status))
    L += ['', 'Cowper-Symonds in *MAT_024: sigma_y scaled by 1 + (rate/C)^(1/P) (C in 1/ms in '
          'the deck). No documented copper (C, P) pair was found with the search tool; the first '
          'rate case uses the fallback C = 40 1/s (0.04 1/ms), P = 5, which is the classical '
          'mild-steel pair; the second uses a pair fitted by this script to the Johnson-Cook '
          'rate term of OFHC copper, 1 + 0.025 ln(rate/1 s^-1), at 1e3, 1e4 and 1e5 1/s '
          '(factors 1.17, 1.23, 1.29): P = 9, C = 5.5e9 1/s (5.5e6 1/ms).', '']
    write(os.path.join(docs, 'taylor_wilkins_guinan.md'), '\n'.join(L))
    write(os.path.join(build, 'wg.json'), json.dumps(rows, indent=1))


# ---------------------------------------------------------------------------------------------
def readme(build, docs):
    W = json.load(open(os.path.join(build, 'wave.json')))
    T = json.load(open(os.path.join(build, 'taylor.json')))
    G = json.load(open(os.path.join(build, 'wg.json')))
    cpu = ''
    try:
        for l in open('/proc/cpuinfo'):
            if l.startswith('model name'):
                cpu = l.split(':', 1)[1].strip()
                break
    except OSError:
        pass
    rev = subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                         text=True).stdout.strip() or 'unknown'
    wm = [w for w in W if w['tssfac'] == 0.9 and w['q2'] == 0.06]
    wd = sorted([w for w in W if w['nx'] == 100 and w['q2'] == 0.06], key=lambda w: w['tssfac'])
    L = ['# Error-against-run-time studies', '',
         'Produced by `make studies` (= `sh scripts/studies.sh`), %s, commit %s, %s. '
         'Runs are sequential, one core each, on a machine shared with other jobs (load '
         'average %.1f when this page was written: compare wall times within a row group, '
         'not across studies); wall = dynx solver wall time printed at the end '
         'of the run. Tables: [elastic_wave.md](elastic_wave.md), [taylor_simo.md]'
         '(taylor_simo.md), [taylor_wilkins_guinan.md](taylor_wilkins_guinan.md). Plot data and '
         'gnuplot scripts: `data/`. Decks and raw output: `build/studies/`.'
         % (time.strftime('%Y-%m-%d', time.gmtime()), rev, cpu, os.getloadavg()[0]), '',
         'Reproduce: `make studies` (or `sh scripts/studies.sh` with bin/dynx built). One case, '
         'e.g. `python3 scripts/gen_taylor_deck.py --L 32.4 --R 3.2 --v 227 --mat j2 --quarter '
         '--n 4 --m 4 --nz 32 t.k && bin/dynx -i t.k -o t && python3 scripts/dxpost.py taylor t '
         '--L0 32.4 --R0 3.2`.', '',
         'Other pages of `make studies`, each with error against run time and observed orders: '
         '[scene_orders.md](scene_orders.md) (rod_impact, sliding_block, incline_friction, '
         'emc_bars, taylor_bar_axisym, taylor_steinberg), [seed_scene_orders.md]'
         '(seed_scene_orders.md) (brittle_impact, pressure_table, shell_projectile_plate, '
         'shell_box_post: mesh sweeps, Richardson), [more_scene_orders.md](more_scene_orders.md) '
         '(brittle_impact_2d, cmc_implant, ssnv104, knee_insert, laser_backside, '
         'laser_subsurface: mesh sweeps, Richardson), '
         '[emc.md](emc.md) (conserving contact: ball in a box, ball in a shell, '
         'bars), [hertz.md](hertz.md), [ball_in_box.md](ball_in_box.md), [spall.md](spall.md), '
         '[lamina.md](lamina.md); the stiff and extreme cases: [stability.md](stability.md). '
         'Numbers checked by `make test`: `scripts/doc_numbers.py --check`.', ''] + SCENE_PAGES + ['',
         '## 1. Elastic wave in a bar (uniaxial strain)', '',
         '![error against wall time](wave_error.png)', '',
         '![stress profile nx = 100](wave_profile.png) ![front, mesh sweep](wave_profile_zoom.png)',
         '', '| nx | TSSFAC | Q2 | Courant | plateau rel. error | front error [mm] | [elements] '
         '| 10-90% rise [mm] | L1 [mm] | order of L1 (from the coarser mesh) | overshoot '
         '| wall [s] |',
         '|---|---|---|---|---|---|---|---|---|---|---|---|']
    po = study_order.pair_orders([w['h'] for w in wm], [w['l1'] for w in wm])
    order_of = {id(w): po[i - 1] for i, w in enumerate(wm) if i > 0}
    for w in W:
        L.append('| %d | %.1f | %g | %.2f | %+.2e | %+.4f | %+.3f | %.2f | %.2f | %s | %.2e | %.3g |' % (
            w['nx'], w['tssfac'], w['q2'], w['courant'], w['plateau_rel'], w['front_err'],
            w['front_err_el'], w['rise'], w['l1'], study_order.fmt_order(order_of.get(id(w))),
            w['overshoot'], w['wall']))
    std = [w for w in W if w['q2'] == 0.06]
    maxpl = max(abs(w['plateau_rel']) for w in std)
    w100 = [w for w in wm if w['nx'] == 100][0]
    w400 = [w for w in wm if w['nx'] == 400][0]
    q100 = [w for w in W if w['q2'] != 0.06 and w['nx'] == 100]
    q400 = [w for w in W if w['q2'] != 0.06 and w['nx'] == 400]
    L += ['', '- Plateau stress: within %.1e (relative) of -rho cL v in every run with the default '
          'bulk viscosity.' % maxpl,
          '- The stable time step comes from the characteristic length V / (largest face area), '
          'i.e. the 1 mm cross-section while h >= 1 mm: nx = 25, 50 and 100 all take %d cycles, '
          'so the coarse meshes run at axial Courant numbers %s. At low Courant numbers the '
          'lumped-mass central-difference scheme is dispersive: the front lags and rings. '
          'nx = 25 and 50 lag by %.3f element (%.2f and %.2f mm) with overshoot %.0f%% and '
          '%.0f%%; nx = 100 at Courant %.2f is within %+.3f mm with overshoot %.1e.'
          % (w100['cycles'], ', '.join('%.2f' % w['courant'] for w in wm[:3]),
             abs(wm[0]['front_err_el']), wm[0]['front_err'], wm[1]['front_err'],
             100 * wm[0]['overshoot'], 100 * wm[1]['overshoot'], w100['courant'],
             w100['front_err'], w100['overshoot']),
          '- The time-step sweep at nx = 100 shows the same thing directly: TSSFAC %s gives '
          'front errors %s element and overshoot %s; the smallest step costs %.1fx the wall '
          'time of TSSFAC 0.9 and is the least accurate.'
          % ('/'.join('%.1f' % w['tssfac'] for w in wd),
             '/'.join('%+.3f' % w['front_err_el'] for w in wd),
             '/'.join('%.1e' % w['overshoot'] for w in wd), wd[0]['wall'] / wd[-1]['wall']),
          '- Above nx = 100 the front error stays below %.2f element (%.3f mm at nx = 400) but '
          'the smeared width shrinks slowly: 10-90%% rise %s mm and L1 profile error %s mm for '
          'nx = %s. Observed orders between successive meshes: L1 %s, rise %s. Expected in the '
          'asymptotic range (Courant number fixed, nx >= 100): 1/2. The width is set by the '
          'linear bulk viscosity, a diffusion coefficient nu = Q2 c L with the element length '
          'L = V/A_max = h (below h = 1 mm; above it L is the 1 mm cross-section and the Courant '
          'number changes instead), and diffusion spreads a step over sqrt(nu t), i.e. h^(1/2). '
          '(With the length V^(1/3) used before issue 15, L = h^(1/3) and the order was 1/6.) '
          'With Q2 = 1e-4 the rise is %.2f mm (nx = 100) and %.2f mm (nx = 400), but the '
          'ringing is no longer damped: overshoot %.0f%% and %.0f%%.'
          % (max(abs(w['front_err_el']) for w in wm[2:]), w400['front_err'],
             ' -> '.join('%.2f' % w['rise'] for w in wm),
             ' -> '.join('%.2f' % w['l1'] for w in wm), '/'.join(str(w['nx']) for w in wm),
             ' / '.join(study_order.fmt_order(p) for p in study_order.pair_orders(
                 [w['h'] for w in wm], [w['l1'] for w in wm])),
             ' / '.join(study_order.fmt_order(p) for p in study_order.pair_orders(
                 [w['h'] for w in wm], [w['rise'] for w in wm])),
             q100[0]['rise'], q400[0]['rise'], 100 * q100[0]['overshoot'],
             100 * q400[0]['overshoot']),
          '- Run time: these are %d-%d element runs of %d-%d cycles, %.3g-%.3g s; up to '
          'nx = 100 the fixed costs (output, set-up of the loop) dominate, so error against run '
          'time is flat there and the cheapest accurate choice is the mesh whose axial Courant '
          'number is near the TSSFAC (h = cross-section size here).'
          % (min(w['nx'] for w in W), max(w['nx'] for w in W), min(w['cycles'] for w in W),
             max(w['cycles'] for w in W), min(w['wall'] for w in W), max(w['wall'] for w in W)),
          '']
    L += ['## 2. Taylor bar, Simo (1992) benchmark', '', '![error against wall time]'
          '(taylor_error.png)', '',
          '| mesh | ELFORM | IHQ | Lf [mm] | Lf - 21.45 | Rf [mm] | Rf - 7.225 | energy ratio '
          '| wall [s] | status |', '|---|---|---|---|---|---|---|---|---|---|']
    for r in T:
        st = 'ok' if r['rc'] == 0 else 'stops at %.1f us: %s' % (1000 * r['time'], r['message'])
        L.append('| (%d,%d,%d) | %d | %d (QH %g) | %.3f | %+.3f | %.3f | %+.3f | %.5f | %.3g | %s |'
                 % (r['n'], r['m'], r['nz'], r['elform'], r['ihq'], r['qh'], r['Lf'], r['dL'],
                    r['Rf'], r['dR'], r['ratio_final'], r['wall'], st))
    L += ['', 'Reference (converged, Foulk et al. 2021): Lf 21.42-21.48 mm, Rf 7.22-7.23 mm; '
          'Simo (1992) Rf 7.12 mm, Zienkiewicz 7.11 mm. For a run that stops, the values are '
          'those of the last state written, not final values. See [taylor_simo.md]'
          '(taylor_simo.md) for cycles, lift-off and ns per element-cycle.', '']
    o = taylor_richardson(T)
    e1 = o['e1']
    e2 = [r for r in T if r['elform'] == 2 and r['rc'] == 0]
    last = o['tri'][-1] if o['tri'] else None
    L += ['- ELFORM 1 IHQ 1: Lf error %s mm and Rf error %s mm for meshes %s; wall %s s. '
          'Observed orders between successive meshes (error against the reference): Lf %s, '
          'Rf %s (- where the error changes sign).'
          % (' / '.join('%+.3f' % r['dL'] for r in e1),
             ' / '.join('%+.3f' % r['dR'] for r in e1),
             ' / '.join('(%d,%d,%d)' % (r['n'], r['m'], r['nz']) for r in e1),
             ' / '.join('%.3g' % r['wall'] for r in e1),
             ' / '.join(study_order.fmt_order(p) for p in o['pL']),
             ' / '.join(study_order.fmt_order(p) for p in o['pR']))]
    if last and last['L']['p'] is not None and last['R']['p'] is not None:
        qL, qR = last['L'], last['R']
        L.append('- Converged values by Richardson extrapolation of the three finest meshes (%s; '
                 'table in [taylor_simo.md](taylor_simo.md)): Lf = %.3f +- %.3f mm (observed '
                 'order %.2f) against the reference 21.42-21.48 mm: %s; Rf = %.3f +- %.3f mm '
                 '(order %.2f) against 7.22-7.23 mm: %s. The +- is the GCI of the finest mesh '
                 '(Fs = 1.25). The finest mesh itself: Lf %+.3f, Rf %+.3f mm from the reference. '
                 'The same extrapolation of the axisymmetric model (decks/taylor_bar_axisym) is '
                 'in [scene_orders.md](scene_orders.md). Footprint = the largest radius of the '
                 'nodes of the initial impact face (its rim lifts off the wall: lift-off in '
                 'taylor_simo.md); a reference measured on the wall would be smaller.'
                 % (' '.join(last['meshes']), qL['f_ext'], qL['gci'], qL['p'],
                    'agrees' if abs(qL['f_ext'] - LREF) <= qL['gci'] + 0.03 else
                    'differs by %+.3f mm' % (qL['f_ext'] - LREF),
                    qR['f_ext'], qR['gci'], qR['p'],
                    'agrees' if abs(qR['f_ext'] - RREF) <= qR['gci'] + 0.005 else
                    'differs by %+.3f mm (more than the uncertainty)' % (qR['f_ext'] - RREF),
                    e1[-1]['dL'], e1[-1]['dR']))
    e1m = {r['nz']: r for r in e1}
    if len(e2) == 2 and 48 in e1m and e2[-1]['nz'] in e1m:
        L.append('- ELFORM 2 (selectively reduced, 8 points): %s. Per element it is more accurate '
                 'than ELFORM 1, but it costs %.1fx the ns per element-cycle; ELFORM 1 (6,6,48) '
                 'takes %.3g s against %.3g s for ELFORM 2 (4,4,32).'
                 % ('; '.join('(%d,%d,%d): Lf %+.3f, Rf %+.3f mm, %.3g s' % (
                     r['n'], r['m'], r['nz'], r['dL'], r['dR'], r['wall']) for r in e2),
                    e2[-1]['ns'] / e1m[e2[-1]['nz']]['ns'], e1m[48]['wall'], e2[-1]['wall']))
    L += ['- Energy ratio (total / initial) at the end: %s for meshes %s (band over the run '
          '%.5f-%.5f in all completed runs).'
          % (' / '.join('%.5f' % r['ratio_final'] for r in e1),
             ' / '.join('(%d,%d,%d)' % (r['n'], r['m'], r['nz']) for r in e1),
             min(r['ratio_min'] for r in T if r['rc'] == 0),
             max(r['ratio_max'] for r in T if r['rc'] == 0)),
          '- (8,8,64) stopped with a negative volume at 52.1 us (element 385, cycle 8744) until '
          'issue 15: a stability limit of the step (TSSFAC 0.8 ran), not the hourglass control '
          '(QH 0.05 also inverted) - the bulk viscosity used the length V^(1/3) while the step '
          'used V/A_max, so the flattened impact-face elements carried more viscous damping than '
          'their step allowed for (docs/design.md, "One characteristic length"). %s'
          % ('Now: %s.' % '; '.join('(%d,%d,%d) %s' % (
              r['n'], r['m'], r['nz'], 'normal termination, %d cycles, %.3g s' % (
                  r['cycles'], r['wall']) if r['rc'] == 0 else 'exit %d: %s' % (
                  r['rc'], r['message'])) for r in T if r['elform'] == 1 and r['n'] >= 8)), '']
    L += ['## 3. Taylor bar, Wilkins-Guinan (1973) OFHC copper', '',
          '| mesh | material | Lf/L0 | experiment | Rf/R0 | experiment | wall [s] |',
          '|---|---|---|---|---|---|---|']
    for r in G:
        L.append('| (%d,%d,%d) | %s | %.4f (%+.1f%%) | 0.630 | %.4f (%+.1f%%) | 2.204 | %.3g |' % (
            r['n'], r['m'], r['nz'], r['what'], r['LfL0'], 100 * (r['LfL0'] / WG_LF_L0 - 1),
            r['RfR0'], 100 * (r['RfR0'] / WG_RF_R0 - 1), r['wall']))
    g = {r['name']: r for r in G}
    ri = [r for r in G if r['cs'] is None]
    fine = ri[-1]
    L += ['', '- Rate independent (static Johnson-Cook curve, no rate or temperature term): '
          'Lf/L0 = %s against 0.630, i.e. the bar ends %.1f%% (%.2f mm) too short on both '
          'meshes; Rf/R0 = %s against 2.204 (%+.1f%% on the finer mesh; the footprint still '
          'moves with the mesh).'
          % (' / '.join('%.4f' % r['LfL0'] for r in ri), 100 * (1 - fine['LfL0'] / WG_LF_L0),
             WG_LF_L0 * WG_L0 - fine['Lf'], ' / '.join('%.4f' % r['RfR0'] for r in ri),
             100 * (fine['RfR0'] / WG_RF_R0 - 1)),
          '- Why: the static curve is the flow stress at low strain rate, while the impact end '
          'deforms at strain rates of order 1e3-1e5 1/s (typical of Taylor tests; not measured '
          'here), where OFHC copper is stronger (the '
          'Johnson-Cook rate term 1 + 0.025 ln(rate / 1 s^-1) gives +17% to +29%). A softer '
          'bar absorbs the same kinetic energy over a larger plastic zone and ends shorter.',
          '- Cowper-Symonds C = 40 1/s, P = 5 (the fallback; no copper pair was found with the '
          'search tool, this is the classical mild-steel pair): Lf/L0 %.4f, Rf/R0 %.4f, far '
          'too stiff: at 1e4 1/s it multiplies the yield stress by 1 + (1e4/40)^(1/5) = %.2f.'
          % (g['wg_6636_cs40']['LfL0'], g['wg_6636_cs40']['RfR0'], 1 + (1e4 / 40) ** 0.2),
          '- Cowper-Symonds fitted to the Johnson-Cook copper rate term (C = 5.5e9 1/s, P = 9): '
          'Lf/L0 %.4f (%+.1f%%), Rf/R0 %.4f (%+.1f%%). The length moves from %.1f%% short to '
          '%.1f%% long. The model still has no thermal softening (adiabatic heating in the '
          'foot); that would lower the flow stress where strains and rates are largest and move '
          'both numbers toward the experiment (shorter bar, wider footprint); not tested here.'
          % (g['wg_6636_csjc']['LfL0'], 100 * (g['wg_6636_csjc']['LfL0'] / WG_LF_L0 - 1),
             g['wg_6636_csjc']['RfR0'], 100 * (g['wg_6636_csjc']['RfR0'] / WG_RF_R0 - 1),
             100 * (1 - fine['LfL0'] / WG_LF_L0), 100 * (g['wg_6636_csjc']['LfL0'] / WG_LF_L0 - 1)),
          '- No observed order for this scene (issue 23 lets it stay out): its error against '
          'the experiment is the material model\'s (rate and temperature terms, %+.1f%% in Lf/L0 '
          'on both meshes), not the discretisation\'s (the two meshes differ by %.1e in Lf/L0), '
          'and the experiment has scatter; the discretisation order of the same element on a '
          'Taylor bar is measured in section 2.'
          % (100 * (fine['LfL0'] / WG_LF_L0 - 1), abs(ri[-1]['LfL0'] - ri[0]['LfL0'])),
          '']
    write(os.path.join(docs, 'README.md'), '\n'.join(L))


if __name__ == '__main__':
    if len(sys.argv) != 4 or sys.argv[1] not in ('wave', 'taylor', 'wg', 'readme'):
        raise SystemExit(__doc__)
    build, docs = (os.path.abspath(p) for p in sys.argv[2:4])
    os.makedirs(build, exist_ok=True)
    os.makedirs(os.path.join(docs, 'data'), exist_ok=True)
    {'wave': wave, 'taylor': taylor, 'wg': wg, 'readme': readme}[sys.argv[1]](build, docs)
