#!/usr/bin/env python3
"""Error against run time with observed orders for the seed's scenes (issue 23, make studies):
decks/brittle_impact, decks/pressure_table, decks/shell_projectile_plate, decks/shell_box_post.

  studies_order_seed.py [--only SCENE ...] [--out docs/studies]
  STUDIES_REUSE=1 studies_order_seed.py   reuse the runs already in build/studies/order_seed/
                                          (a run is reused when its deck files are
                                          byte-identical and it ended)

None of the four has an analytic answer: each is a mesh sweep of 3-4 levels of the scene's own
generator, the error taken against the Richardson extrapolation of the three finest levels
(Roache 1998; Celik et al. 2008, J. Fluids Eng. 130, 078001: scripts/study_order.py), with the
GCI of the finest level; where the three finest do not converge monotonically, against the
finest level (stated on the page). Writes docs/studies/seed_scene_orders.md,
docs/studies/seed_scene_orders.png and docs/studies/data/order_<scene>.dat (the page writer of
scripts/studies_order.py). Run with /usr/bin/python3 (h5py for the brittle damage field).
"""
import argparse
import math
import os
import re
import resource
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
import dxpost  # noqa: E402
import study_order  # noqa: E402
import studies_order as so  # noqa: E402

PY, S = so.PY, so.S
WORK = os.path.join(ROOT, 'build', 'studies', 'order_seed')


def run_dir(name, gen_cmd, files, deck='deck.k'):
    """gen_cmd writes the deck files (names in files) into WORK/name; run bin/dynx on
    WORK/name/deck into WORK/name/out. Returns (outdir, CPU seconds of the run: user + system
    of the dynx process, which a loaded shared machine inflates far less than wall time)."""
    d = os.path.join(WORK, name)
    os.makedirs(d, exist_ok=True)
    def snap():
        return [open(os.path.join(d, f)).read() if os.path.exists(os.path.join(d, f)) else None
                for f in files]
    before = snap()
    rc, out = so.sh(gen_cmd)
    if rc != 0:
        raise SystemExit('studies_order_seed: %s failed:\n%s' % (' '.join(gen_cmd), out))
    od = os.path.join(d, 'out')
    if os.environ.get('STUDIES_REUSE') and before == snap() and os.path.exists(od + '.log') \
            and os.path.exists(od + '.cpu'):
        cpu = float(open(od + '.cpu').read())
    else:
        for f in (od + '.log', od + '.cpu'):
            if os.path.exists(f):
                os.remove(f)
        t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        rc, log = so.sh([so.DYNX, '-i', os.path.join(d, deck), '-o', od])
        t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime)
        if rc != 0:
            raise SystemExit('studies_order_seed: %s: dynx exit %d\n%s' % (name, rc, log[-2000:]))
        with open(od + '.log', 'w') as f:
            f.write(log)
        with open(od + '.cpu', 'w') as f:
            f.write('%.6g\n' % cpu)
    return od, cpu


def glstat_col(od, col):
    names, rows = dxpost.columns(os.path.join(od, 'glstat'))
    k = names.index(col)
    return [r[0] for r in rows], [r[k] for r in rows]


def richardson_ref(rows, key):
    """Reference of a sequence without an analytic answer: Richardson of the three finest
    rows when they converge monotonically, else the finest row (its own error 0)."""
    q = study_order.richardson([r['h'] for r in rows[-3:]], [r[key] for r in rows[-3:]])
    return (q['f_ext'], q) if q['p'] is not None else (rows[-1][key], q)


def finish(rows, key, fmt):
    """Fill each row's error and cells once the whole sequence is known."""
    ref, q = richardson_ref(rows, key)
    for r in rows:
        r['err'] = (r[key] - ref) / ref if r is not rows[-1] or q['p'] is not None else 0.0
        r['cells'] = [fmt % r[key], '%+.3e' % r['err']] + r['more']
    return rows


def rich_table(keys):
    """Richardson table over each three successive levels for the named quantities."""
    def extra(rows):
        out = ['', 'Richardson extrapolation over three successive levels (p observed order, '
               'GCI = 1.25 |f3 - f2|/(r^p - 1) of the finest of the three):', '',
               '| levels | ' + ' | '.join('p (%s) | %s extrapolated | GCI' % (k, k)
                                         for k, _ in keys) + ' |',
               '|---|' + '---|---|---|' * len(keys)]
        for i in range(len(rows) - 2):
            t = rows[i:i + 3]
            cells = []
            for k, fmt in keys:
                q = study_order.richardson([r['h'] for r in t], [r[k] for r in t])
                cells += (['- (%s)' % q['why'], '-', '-'] if q['p'] is None else
                          ['%.2f' % q['p'], fmt % q['f_ext'], '%.2g' % q['gci']])
            out.append('| %s | %s |' % (', '.join(r['label'] for r in t), ' | '.join(cells)))
        return out + ['']
    return extra


def sweep(case, levels, key, fmt):
    """The scene's 'case' function for write_page: runs every level, then sets errors."""
    cache = {}

    def one(p):
        if not cache:
            rows = [case(x) for x in levels]
            finish(rows, key, fmt)
            cache.update({x: r for x, r in zip(levels, rows)})
        return cache[p]
    return one


# ---------------------------------------------------------------------------------------------
# brittle_impact: steel sphere on fused silica, *DYNX_BRITTLE_CRACK; the block's n x n x n/2
# mesh refined (the sphere's cube-sphere, ns = 3, and everything else held), 2 us
def brittle_case(n):
    od, wall = run_dir('brittle_n%d' % n, [PY, os.path.join(S, 'gen_brittle_deck.py'), '--n',
                                           str(n), os.path.join(WORK, 'brittle_n%d' % n,
                                                                'deck.k')], ['deck.k'])
    import h5py
    import numpy as np
    nb = n * n * (n // 2)
    f = h5py.File(os.path.join(od, 'd3plot.h5'), 'r')
    ks = sorted((k for k in f['states'] if k != 'times'), key=lambda k: int(re.sub(r'\D', '', k)))
    d = f['states/' + ks[-1]]['damage'][:nb]
    x = f['mesh/coordinates'][:]
    conn = f['mesh/hex8'][:].reshape(-1, 8)
    conn = conn - conn.min() if conn.min() == 1 else conn
    xc = x[conn[:nb]].mean(axis=1)
    r = np.hypot(xc[:, 0], xc[:, 1])
    h = 2.0 / n
    top = xc[:, 2] > xc[:, 2].max() - 0.25 * h
    dam = d > 0
    dfr = 2.0 * r[dam].max()                     # the README's fracture diameter
    da = 2.0 * math.sqrt((dam & top).sum() * h * h / math.pi)  # damaged top area, as a disc
    full = int((d >= 1.0).sum())
    _, ratio = glstat_col(od, 'energy_ratio')
    return {'label': 'n = %d (h %.4g mm, %d hexes)' % (n, h, nb), 'h': h, 'Da': da, 'Df': dfr,
            'more': ['%.4f' % dfr, '%d' % int(dam.sum()), '%.1e' % max(abs(v - 1) for v in ratio)],
            'wall': wall}


BR_LEVELS = [8, 12, 16, 24]
BRITTLE = {
    'name': 'brittle_impact', 'deck': 'decks/brittle_impact (n = 16)',
    'title': 'Steel sphere on fused silica: damaged diameter on the impact face against the mesh',
    'runs': BR_LEVELS, 'case': sweep(brittle_case, BR_LEVELS, 'Da', '%.4f'), 'check_runs': [],
    'param': 'h = 2 mm / n (block n x n x n/2; the sphere (ns = 3) held)',
    'extra': rich_table([('Da', '%.4f'), ('Df', '%.4f')]),
    'cols': ['Da [mm]', 'rel. error vs Richardson', 'Df = 2 r_max [mm]', 'damaged elements',
             'max abs(energy ratio - 1)'],
    'expected': '1 at best (a threshold fringe measured on cells)',
    'reason': 'Da is the diameter of the disc whose area is that of the damaged cells of the '
              'impact face (the top layer); Df, the README\'s fracture diameter, twice the '
              'largest axis distance of a damaged cell\'s centroid. No analytic answer: the '
              'error is against the Richardson extrapolation of the three finest levels (or the '
              'finest, when they do not converge monotonically). Both measure where the '
              'largest principal stress first reached the tensile strength FT, a threshold '
              'crossing that a cell reports at its centroid: the fringe moves in steps of h/2 '
              'and a smooth O(h^2) stress field cannot show through it, so the best expected '
              'is order 1, with scatter from the cell quantisation (the pair orders change '
              'sign when a ring of cells enters or leaves). The damage is localised (a crack '
              'band) and the model has no length scale: the damaged region itself need not '
              'converge with h (Bazant & Oh 1983, crack band theory); what is listed is what '
              'dynx gives. The sphere\'s own mesh is held so that the sweep measures the '
              'block\'s.'}


# ---------------------------------------------------------------------------------------------
# pressure_table: *DYNX_PRESSURE_TABLE on elastic silica, axisymmetric, non-reflecting sides;
# element size h refined. The table's work (glstat external work once the load is over, 18 ns,
# before any wave reaches a non-reflecting boundary) and the energy left at 60 ns
def ptable_case(hum):
    d = os.path.join(WORK, 'ptable_h%g' % hum)
    od, wall = run_dir('ptable_h%g' % hum, [PY, os.path.join(S, 'gen_nr2d_decks.py'),
                                            'backside', d, '%g' % (hum * 1e-3)],
                       ['deck.k', 'table.dat'])
    t, w = glstat_col(od, 'external_work')
    w18 = [v for tt, v in zip(t, w) if tt <= 1.8e-5 + 1e-12][-1]
    _, tot = glstat_col(od, 'total')
    _, hg = glstat_col(od, 'hourglass')
    _, ratio = glstat_col(od, 'energy_ratio')
    return {'label': 'h = %g um (%d x %d)' % (hum, round(200 / hum), round(300 / hum)),
            'h': hum, 'W': w18 * 1e6, 'E60': tot[-1] * 1e6,
            'more': ['%.5f' % (tot[-1] * 1e6), '%.2f %%' % (100 * hg[-1] / tot[-1]),
                     '%.4f' % ratio[-1]], 'wall': wall}


PT_LEVELS = [10, 5, 2.5, 1.25]
PTABLE = {
    'name': 'pressure_table', 'deck': 'decks/pressure_table (h = 5 um)',
    'title': 'Back-surface pressure table: the table\'s work and the energy left against the mesh',
    'runs': PT_LEVELS, 'case': sweep(ptable_case, PT_LEVELS, 'W', '%.5f'), 'check_runs': [],
    'param': 'h [um] (element size, the block 200 x 300 um)',
    'extra': rich_table([('W', '%.5f')]),
    'cols': ['W(18 ns) [uJ per radian]', 'rel. error vs Richardson', 'E(60 ns) [uJ]',
             'hourglass share of E(60 ns)', 'energy ratio at 60 ns'],
    'expected': '2',
    'reason': 'W is the work of the table on the block once the load is over (18 ns; the '
              'table ends at 12 ns, the wave from the load\'s edge, r = 80 um, reaches the '
              'non-reflecting side at about 21 ns, so W is the table\'s alone); E(60 ns) the energy left in the block (kinetic + internal + '
              'hourglass) after the non-reflecting boundaries took part of it. No analytic '
              'answer (2D, finite strain about 0.1): error against the Richardson '
              'extrapolation of the three finest levels. Expected and observed order 2: W '
              'integrates the pressure times the surface velocity over a smooth pulse (3 ns '
              'FWHM, about 18 um of wave length against h = 10-1.25 um), whose error is the '
              'O(h^2) phase and amplitude error of the linear element with lumped mass; the '
              'bulk viscosity\'s O(h) dissipation does not show at these levels. E(60 ns) has '
              'no order: at 60 ns the front is leaving through the bottom, so the energy left '
              'depends on how sharp the front is. Found by this sweep and fixed: at h = 1.25 '
              'um the last ten cycles before 60 ns halved the step and lost half the energy '
              '(energy ratio 0.564), and every level blew up later (exit 3 at 98, 82, 70 ns '
              'for h = 10, 5, 2.5 um): the corner node where the non-reflecting side meets the '
              'bottom carries both dashpots on a quarter element\'s mass (C dt/m = 2 (c_d + '
              'c_s) dt/h = 1.9), beyond the stability limit of a dashpot on the lagged '
              'velocity v(n-1/2); the dashpots now act on the centred velocity '
              '(dx_nonreflecting; regression case nr2d_corner runs h = 10 um to 150 ns). The '
              'energy ratio at 60 ns, while the front crosses the bottom, is listed; it '
              'returns to 1 within 2e-3 once the wave has left (150 ns). ELFORM 15 (one point) '
              'with viscous hourglass control: its energy share is listed.'}


# ---------------------------------------------------------------------------------------------
# shell_projectile_plate: quarter plate N x N BT shells, rigid projectile (4 x 4 x 8 hexes
# held), 1 ms: the plate centre's peak deflection and the projectile's speed at 1 ms
def plate_case(n):
    od, wall, names, rows, hist = shell_run('plate', n, '1.0')
    centre, proj = hist[0], hist[-1]
    kz, kv = names.index('z_disp'), names.index('z_vel')
    zc = [r for r in rows if int(r[1]) == centre]
    zp = [r for r in rows if int(r[1]) == proj]
    peak = -min(r[kz] for r in zc)
    tpk = [r[0] for r in zc if -r[kz] == peak][0]
    _, ratio = glstat_col(od, 'energy_ratio')
    return {'label': '%d x %d (h %.3g mm)' % (n, n, 100.0 / n), 'h': 100.0 / n, 'w': peak,
            'v': zp[-1][kv], 'more': ['%.3f' % tpk, '%.3f' % zp[-1][kv],
                                      '%.1e' % max(abs(v - 1) for v in ratio)], 'wall': wall}


def shell_run(scene, n, tend):
    """gen_shell_scenes.py SCENE N (no plot states) run to TEND ms: outdir, CPU s, nodout
    column names and rows, the deck's history node list."""
    import shell_scene_check
    name = '%s_%d' % (scene, n)
    d = os.path.join(WORK, name)
    od, cpu = run_dir(name, [PY, os.path.join(S, 'gen_shell_scenes.py'), scene, str(n), d,
                             '--tend', tend, '--dplot', '0'], ['deck.k', 'mesh.k'])
    names, rows = dxpost.columns(os.path.join(od, 'nodout'))
    hist, _ = shell_scene_check.read_mesh(os.path.join(d, 'mesh.k'))
    return od, cpu, names, rows, hist


PL_LEVELS = [10, 20, 40, 80]
PLATE = {
    'name': 'shell_projectile_plate', 'deck': 'decks/shell_projectile_plate (40 x 40)',
    'title': 'Rigid projectile on a clamped plate: peak deflection of the centre against the mesh',
    'runs': PL_LEVELS, 'case': sweep(plate_case, PL_LEVELS, 'w', '%.4f'), 'check_runs': [],
    'param': 'h = 100 mm / N (quarter plate N x N BT shells, MITER 4)',
    'extra': rich_table([('w', '%.4f'), ('v', '%.3f')]),
    'cols': ['peak deflection w [mm]', 'rel. error vs Richardson', 'at t [ms]',
             'projectile v_z at 1 ms [m/s]', 'max abs(energy ratio - 1)'],
    'expected': '1 for the local fields',
    'reason': 'No analytic answer (large plastic deflection, ten thicknesses, under a flat '
              'rigid nose): error against the Richardson extrapolation of the three finest '
              'levels. Expected order 1: the Belytschko-Tsay shell is a one-point, '
              'constant-curvature element (its membrane and bending fields converge at O(h) in '
              'their gradients), and the plastic hinge under the nose\'s edge and along the '
              'diagonals is a strain concentration one element wide; the contact of the flat '
              'nose edge on the plate is resolved to h. Observed 2.5 on the three finest '
              'meshes (10 x 10 is outside the asymptotic range: the sequence turns): the peak '
              'deflection is a global quantity, set by the projectile\'s energy going into '
              'plastic work along the hinge lines, which integrates the local O(h) errors of '
              'the hinges and converges faster than they do. The rebound speed v (listed, '
              'positive = away from the plate) is a small difference of large work terms and '
              'has no order (its Richardson triples are oscillatory).'}


# ---------------------------------------------------------------------------------------------
# shell_box_post: the box-section front on the rigid U post, N shells per side, 2 ms: the
# vehicle's (rigid rear ring's) speed and crush at 2 ms
def post_case(n):
    od, wall, names, rows, hist = shell_run('post', n, '2.0')
    ring = hist[-1]
    kx, kv = names.index('x_disp'), names.index('x_vel')
    rr = [r for r in rows if int(r[1]) == ring]
    _, ratio = glstat_col(od, 'energy_ratio')
    fen = [r for r in rows if int(r[1]) == hist[1]]
    ky = names.index('y_disp')
    return {'label': '%d per side (h %.3g mm)' % (n, 60.0 / n), 'h': 60.0 / n,
            'v': -rr[-1][kv], 'c': -rr[-1][kx],
            'more': ['%.3f' % -rr[-1][kx], '%.2f' % max(abs(r[ky]) for r in fen),
                     '%.1e' % max(abs(v - 1) for v in ratio)], 'wall': wall}


PO_LEVELS = [6, 12, 24]
POST = {
    'name': 'shell_box_post', 'deck': 'decks/shell_box_post (12 per side, 6 ms; here 2 ms)',
    'title': 'Box-section front on a rigid post: vehicle speed at 2 ms against the mesh',
    'runs': PO_LEVELS, 'case': sweep(post_case, PO_LEVELS, 'v', '%.4f'), 'check_runs': [],
    'param': 'h = 60 mm / N (N BT shells per side of the tube, MITER 4)',
    'extra': rich_table([('v', '%.4f'), ('c', '%.3f')]),
    'cols': ['vehicle speed at 2 ms [m/s]', 'rel. error vs Richardson', 'crush c [mm]',
             'fender point largest sideways [mm]', 'max abs(energy ratio - 1)'],
    'expected': 'none guaranteed (1 while the fold pattern holds)',
    'reason': 'The speed lost by 2 ms is the impulse of the crush force over the vehicle\'s '
              '20 kg, so its error is that of the mean crush force; crush c = the rear ring\'s '
              'travel. No analytic answer: error against the Richardson extrapolation of the '
              'three levels (or the finest, when they do not converge monotonically). '
              'Progressive folding is a sequence of buckling bifurcations: while every level '
              'forms the same lobes, the crush force converges like the shell\'s bending, '
              'order 1 (one-point BT shells, fold radii resolved to h); when a level forms a '
              'different fold (a lobe more or less, another side first) the sequence has no '
              'order. 2 ms (the first lobes; 24 per side is 8 times the cost of 12) keeps the '
              'sweep affordable on the shared machine.'}

SCENES = [BRITTLE, PTABLE, PLATE, POST]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--only', nargs='*', default=None)
    ap.add_argument('--out', default=os.path.join(ROOT, 'docs', 'studies'))
    a = ap.parse_args()
    intro = ('Generated by `scripts/studies_order_seed.py` (`make studies`; issue 23): the '
             'seed\'s scenes (articles 3 and 5), none with an analytic answer. Each is a mesh '
             'sweep of the scene\'s generator, run one at a time on the shared 2-core machine; '
             'run time = CPU seconds (user + system) of the dynx process, since the machine\'s '
             'load inflates wall times several times over. The error column is '
             'against the Richardson extrapolation of the three finest levels (Celik et al. '
             '2008; or the finest level when those do not converge monotonically: then its own '
             'error is 0 and the last order is -; with three levels only, as shell_box_post, '
             'the pair orders equal the Richardson order by construction and the GCI is the '
             'statement). Order = ln(e_i/e_(i+1)) / ln(h_i/h_(i+1)) '
             'between successive rows (- where the error changes sign or is zero). Plot: '
             'relative |error| against wall time, log-log.')
    so.write_page(SCENES, a.out, 'seed_scene_orders',
                  '# Seed scenes: error against run time and observed orders', intro, a.only,
                  tlabel='CPU')


if __name__ == '__main__':
    main()
