#!/usr/bin/env python3
"""Error against run time with observed orders for the scenes of issues 19 and 20 (issue 23,
make studies): decks/brittle_impact_2d, decks/cmc_implant, decks/ssnv104, decks/knee_insert,
decks/laser_backside, decks/laser_subsurface.

  studies_order_more.py [--only SCENE ...] [--out docs/studies]
  STUDIES_REUSE=1 studies_order_more.py   reuse the runs already in build/studies/order_more/
                                          (a run is reused when its deck is byte-identical and
                                          it ended)

Each is a mesh sweep of the scene's own generator (the scene's README names the member that is
its deck). The error column is against the Richardson extrapolation of the three finest levels
(Celik et al. 2008, J. Fluids Eng. 130, 078001: scripts/study_order.py), or the finest level
when those do not converge monotonically; the analytic or published values a scene has are
named in its paragraph (they are not the discretisation's limit: finite strain, bonded bases,
a crack model without a length scale). Run time = CPU seconds (user + system) of the dynx
process. Writes docs/studies/more_scene_orders.md, .png and data/order_<scene>.dat with the
page writer of scripts/studies_order.py and the runner of scripts/studies_order_seed.py. Run
with /usr/bin/python3 (h5py for the damage and stress fields).
"""
import argparse
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
import study_order  # noqa: E402
import studies_order as so  # noqa: E402
import studies_order_seed as sos  # noqa: E402

PY, S = so.PY, so.S
sos.WORK = os.path.join(ROOT, 'build', 'studies', 'order_more')
_richardson = study_order.richardson


def richardson_converging(h, f, fs=1.25):
    """study_order.richardson for a triple that converges: Celik's fixed point takes |ln|eC/eF||,
    so a diverging triple (the finer difference as large as the coarser one, relative to the
    refinement) still gets a positive p and a meaningless extrapolation; here it is 'no order'
    (diverging), and the error is then against the finest level. (Used on this page only: the
    other pages of make studies keep study_order's behaviour; notes/studies23.md.)"""
    e21, e32 = f[1] - f[0], f[2] - f[1]
    if e21 != 0 and e32 != 0 and (e21 > 0) == (e32 > 0) and abs(e32) >= abs(e21):
        return {'p': None, 'why': 'diverging (differences %+.3g, %+.3g)' % (e21, e32)}
    return _richardson(h, f, fs)


study_order.richardson = richardson_converging


def deck_path(name):
    return os.path.join(sos.WORK, name, 'deck.k')


def newton_its(od):
    return sum(1 for line in open(od + '.log') if 'residual ratio' in line)


# ---------------------------------------------------------------------------------------------
# brittle_impact_2d: the axisymmetric sphere on silica (ELFORM 15, crack model, 2D contact,
# non-reflecting bottom and side), n quads per mm, the sphere's ns = n/4 with it, 2 us
def brittle2d_case(n):
    import brittle2d_check
    name = 'brittle2d_n%d' % n
    od, cpu = sos.run_dir(name, [PY, os.path.join(S, 'gen_brittle2d_deck.py'), '--n', str(n),
                                 '--ns', str(n // 4), deck_path(name)], ['deck.k'])
    m = brittle2d_check.measure(od)
    return {'label': 'n = %d (h %.4g mm)' % (n, 1.0 / n), 'h': 1.0 / n, 'Do': m['outer'],
            'd': m['depth'],
            'more': ['%.4f' % m['inner'], '%.4f' % m['depth'], '%.1f' % m['angle'],
                     '%.3f' % m['heave'], '%.3f' % m['hourglass'], '%.1e' % m['ratio_dev']],
            'wall': cpu}


B2_LEVELS = [16, 32, 64]
BRITTLE2D = {
    'name': 'brittle_impact_2d', 'deck': 'decks/brittle_impact_2d (n = 16)',
    'title': 'Sphere on silica, axisymmetric: fracture diameter against the mesh',
    'runs': B2_LEVELS, 'case': sos.sweep(brittle2d_case, B2_LEVELS, 'Do', '%.4f'),
    'check_runs': [], 'param': 'h = 1 mm / n (n quads per mm in the silica, the sphere ns = n/4)',
    'extra': sos.rich_table([('Do', '%.4f'), ('d', '%.4f')]),
    'cols': ['outer fracture diameter [mm]', 'rel. error vs Richardson',
             'inner (D >= 2/3) [mm]', 'damage depth [mm]', 'envelope angle [deg]',
             'surface heave [mm]', 'hourglass / initial KE', 'max abs(energy ratio - 1)'],
    'expected': 'none (a crack model without a length scale)',
    'reason': 'Measured at 2 us by scripts/brittle2d_check.py (definitions in its header). No '
              'analytic answer; the seed\'s experiment gives 1.65 mm outer, 0.8 mm inner, 1.0 mm '
              'deep, DYNA2D 1.62 / 0.7 / 0.5 mm. Expected no order: the smeared crack model has '
              'no fracture-energy regularisation, so the damage localises with the mesh and the '
              'damaged region need not converge (Bazant & Oh 1983, crack band theory); the '
              'fringe is also read on cells, in steps of h. What is listed is what dynx gives: '
              'the outer diameter stays at 0.91-0.95 mm (within one n 16 element), the inner '
              'diameter and the depth grow with n. Contact: card 3 ISTIFF 1, the soft '
              'constraint (ISTIFF 0\'s segment penalty created +4.1 % of the impact energy in '
              'axisymmetry: review2 C1, docs/history.md). The energy error comes with the '
              'cracking (docs/design.md), not the non-reflecting boundary (unchanged by the '
              'centred dashpot).'}


# ---------------------------------------------------------------------------------------------
# cmc_implant: the rigid CoCr ball in the polyethylene socket, key pinch 188.5 N, unbacked,
# 10 deg (implicit statics, 4 load steps); the socket's n refined
def cmc_case(n):
    import cmc_implant
    name = 'cmc_n%d' % n
    gen = 'import sys; sys.path.insert(0, %r); import cmc_implant; cmc_implant.gen(%r, n=%d)' % (
        S, deck_path(name), n)
    os.makedirs(os.path.dirname(deck_path(name)), exist_ok=True)
    od, cpu = sos.run_dir(name, [PY, '-c', gen], ['deck.k'])
    p, vm, ep, f = cmc_implant.result(od)
    return {'label': 'n = %d (h 1/%d)' % (n, n), 'h': 1.0 / n, 'P': p, 'vm': vm,
            'more': ['%.3f' % vm, '%.5f' % ep, '%.2f' % f, '%d' % newton_its(od)], 'wall': cpu}


CMC_LEVELS = [2, 3, 4, 6, 8]
CMC = {
    'name': 'cmc_implant', 'deck': 'decks/cmc_implant (n = 6)',
    'title': 'Thumb CMC implant: peak contact pressure in the socket against the mesh',
    'runs': CMC_LEVELS, 'case': sos.sweep(cmc_case, CMC_LEVELS, 'P', '%.3f'), 'check_runs': [],
    'param': 'h ~ 1/n (n elements per socket patch edge; scripts/cmc_implant.py gen --n N)',
    'extra': sos.rich_table([('P', '%.3f'), ('vm', '%.3f')]),
    'cols': ['peak pressure P [MPa]', 'rel. error vs Richardson', 'max von Mises [MPa]',
             'max plastic strain', 'reaction [N]', 'Newton iterations'],
    'expected': '1',
    'reason': 'P = the largest -n.sigma.n of the socket\'s inner-layer elements (n radial from '
              'the ball\'s centre), sampled at their centroids, h/2 below the contact surface. '
              'No published value (the article prints stress patterns only); the reaction '
              'equals the 188.5 N load. Expected order 1: the pressure falls off through the '
              'layer with a non-zero gradient, so the centroid\'s depth h/2 is a first-order '
              'sampling error on top of the element\'s O(h^2) stress error; the polyethylene '
              'yields in a small zone (plastic strain listed), which does not change the '
              'order of a sampled maximum. Observed 0.6-0.9, below 1 and not settled by n = 8 '
              '(the Richardson limit of P moves between the triples): the contact patch spans '
              'a few elements at these meshes and the element holding the peak changes with '
              'n; n = 12 (about ten times n = 8\'s CPU) is not run.'}


# ---------------------------------------------------------------------------------------------
# ssnv104: code_aster's two elastic hemispheres, crushed by h = 4 mm (implicit, 4 steps)
def ssnv_case(n):
    import ssnv104
    name = 'ssnv_n%d' % n
    od, cpu = sos.run_dir(name, [PY, os.path.join(S, 'ssnv104.py'), 'gen', '--n', str(n),
                                 deck_path(name)], ['deck.k'])
    a, p0, pole, f, _ = ssnv104.dynx_result(od)
    return {'label': 'n = %d (surface h %.3g mm)' % (n, 14.1 / n), 'h': 14.1 / n, 'pole': pole,
            'F': f,
            'more': ['%.2f' % f, '%.3f' % a, '%.4f' % p0, '%d' % newton_its(od)],
            'wall': cpu}


SS_LEVELS = [4, 6, 8]
SSNV = {
    'name': 'ssnv104', 'deck': 'decks/ssnv104 (n = 4)',
    'title': 'SSNV104, two elastic spheres: pole stress and force against the mesh',
    'runs': SS_LEVELS, 'case': sos.sweep(ssnv_case, SS_LEVELS, 'pole', '%.4f'),
    'check_runs': [], 'param': 'h = 14.1 mm / n (the contact zone\'s surface elements)',
    'extra': sos.rich_table([('pole', '%.4f'), ('F', '%.2f')]),
    'cols': ['pole -sigma_zz [GPa]', 'rel. error vs Richardson', 'F [kN]', 'a [mm]',
             'p0 fit [GPa]', 'Newton iterations'],
    'expected': '2',
    'reason': 'SSNV104\'s reference is Hertz at small strain (p0 2.7983 GPa, a 10 mm, F 586.1 '
              'kN); dynx runs finite strain (St. Venant-Kirchhoff), which at strains of 0.14 '
              'lowers the pole stress by about 13 % (decks/ssnv104/README.md: CalculiX NLGEOM '
              'on the same mesh agrees with dynx within 0.4 %), so the error is against the '
              'Richardson extrapolation, not against Hertz. The pole value is the centroid '
              'stress of the surface element at the pole, h/2 deep; on the axis Hertz\'s '
              'sigma_zz = -p0/(1 + z^2/a^2) is flat at the surface, so that sampling is an '
              'O(h^2) error like the element\'s: order 2 expected, observed near it. F, the '
              'reaction of the flat face, is converged to a few parts in 1e4 on these meshes '
              '(its differences change sign: no order); the contact zone grows by a sliver per '
              'load step on a faceted sphere, which adds that scatter.'}


# ---------------------------------------------------------------------------------------------
# knee_insert: the rigid femoral condyle in the dish of a thick elastic insert (T = W = 40 mm,
# 0 deg, d = 0.1 mm): the Hertz series of the README
def knee_case(n):
    import knee_insert
    name = 'knee_n%d' % n
    os.makedirs(os.path.dirname(deck_path(name)), exist_ok=True)
    gen = ('import sys; sys.path.insert(0, %r); import knee_insert; '
           'knee_insert.gen(%r, n=%d, elastic=True, thick=True)' % (S, deck_path(name), n))
    od, cpu = sos.run_dir(name, [PY, '-c', gen], ['deck.k'])
    f, p, _, _ = knee_insert.result(od, thick=True)
    return {'label': 'n = %d' % n, 'h': 1.0 / n, 'F': f, 'P': p,
            'more': ['%.3f' % p, '%d' % newton_its(od)], 'wall': cpu}


KN_LEVELS = [3, 4, 6]
KNEE = {
    'name': 'knee_insert', 'deck': 'decks/knee_insert (n = 4; the Hertz series: elastic, '
                                   'thick insert, 0 deg)',
    'title': 'Knee insert, elastic Hertz series: indentation force against the mesh',
    'runs': KN_LEVELS, 'case': sos.sweep(knee_case, KN_LEVELS, 'F', '%.2f'), 'check_runs': [],
    'param': 'h = 1.6 a / n (n elements over 1.6 contact radii, growing by 1.3 beyond)',
    'extra': sos.rich_table([('F', '%.2f'), ('P', '%.3f')]),
    'cols': ['force F [N]', 'rel. error vs Richardson', 'peak -sigma_zz top layer P [MPa]',
             'Newton iterations'],
    'expected': '2 for F',
    'reason': 'Hertz for a rigid sphere in a concave dish (1/Reff = 1/R - 1/RD): F 486.0 N, p0 '
              '29.01 MPa; the extrapolated force stays about 8 % above it, which is not the '
              'mesh: the insert is a finite block bonded at its base, not a half-space, with '
              'nu 0.46 in a B-bar element and a penalty contact (decks/knee_insert/README.md). '
              'Expected order 2 for the force (the integral of a smooth contact pressure over '
              'a graded mesh) and for the peak -sigma_zz P (a centroid sample h/2 deep on the '
              'axis, where sigma_zz is flat in depth). Observed for F: the apparent order of '
              'three levels with refinement ratios 1.33 and 1.5 far above 2, a pre-asymptotic '
              'triple (the GCI is the statement); finer meshes cost about four times n = 6 per '
              'step of n and are not run.'}


# ---------------------------------------------------------------------------------------------
# laser_backside: the pressure table (SF 0.5, 50 kbar) on silica with the crack model,
# axisymmetric, h refined (the scene deck is h = 5 um), 60 ns
def backside_case(hum):
    import brittle2d_check
    name = 'backside_h%g' % hum
    d = os.path.dirname(deck_path(name))
    od, cpu = sos.run_dir(name, [PY, os.path.join(S, 'gen_laser2d_decks.py'), 'backside', d,
                                 '--h', '%g' % (hum * 1e-3), '--sf', '0.5'],
                          ['deck.k', 'table.dat'])
    m = brittle2d_check.measure(od, after=2e-5)
    return {'label': 'h = %g um (%d quads)' % (hum, m['nsilica']), 'h': hum, 'D': m['outer'],
            'd': m['depth'],
            'more': ['%.4f' % m['depth'], '%d' % m['ndamaged'], '%.0f' % m['angle'],
                     '%.1e' % m['ratio_dev']],
            'wall': cpu}


LB_LEVELS = [10, 5, 2.5, 1.25]
BACKSIDE = {
    'name': 'laser_backside', 'deck': 'decks/laser_backside (h = 5 um, SF 0.5)',
    'title': 'Back-surface pressure on silica, axisymmetric: damage diameter against the mesh',
    'runs': LB_LEVELS, 'case': sos.sweep(backside_case, LB_LEVELS, 'D', '%.4f'),
    'check_runs': [],
    'param': 'h = element size in um (block 200 x 300 um of h x h quads; '
             'scripts/gen_laser2d_decks.py backside --h H --sf 0.5)',
    'extra': sos.rich_table([('D', '%.4f'), ('d', '%.4f')]),
    'cols': ['damage diameter [mm]', 'rel. error vs Richardson', 'damage depth [mm]',
             'damaged quads', 'envelope angle [deg]', 'max abs(energy ratio - 1) after 20 ns'],
    'expected': 'none (a crack model without a length scale)',
    'reason': 'Measured at 60 ns by scripts/brittle2d_check.py --scene backside --after 2e-5 '
              '(diameter: twice the largest centroid radius of a damaged quad of the surface '
              'row; depth: the deepest damaged row under it). No analytic answer; the seed '
              'gives DYNA2D 0.170 mm, and SF 0.5 was chosen to match it on h = 5 um, so the '
              'diameter is a calibration of the unknown load (decks/laser_backside/README.md). '
              'Expected no order, as for brittle_impact_2d: the smeared crack model has no '
              'fracture-energy regularisation, so the damage localises with the mesh and the '
              'damaged region need not converge (Bazant & Oh 1983, crack band theory); the '
              'fringe is read on cells, in steps of h. The depth is in addition bounded by '
              'the 0.3 mm block, which the damage reaches on the fine meshes: its Richardson '
              'triple measures the block, not a convergence. The energy error shrinks with h '
              '(the non-reflecting boundary\'s lag while the wave leaves).'}


# ---------------------------------------------------------------------------------------------
# laser_subsurface: energy deposited into a CeO2 particle 300 nm under the silica surface,
# O-grid of density M (all of it scales with M; the scene deck is M = 8), 3.5 ns
def subsurface_case(m):
    import subsurface_check
    name = 'subsurface_m%d' % m
    d = os.path.dirname(deck_path(name))
    od, cpu = sos.run_dir(name, [PY, os.path.join(S, 'gen_laser2d_decks.py'), 'subsurface', d,
                                 '--m', str(m)], ['deck.k'])
    r = subsurface_check.measure(od)

    def ns(t):
        return 'not by 3.5' if t is None else '%.1f' % (t * 1e6)
    import h5py
    with h5py.File(os.path.join(od, 'd3plot.h5'), 'r') as f:
        nq = len(f['mesh/part_ids'])
    h = math.pi * 50.0 / (4 * m)            # the arc length of the particle's rim in nm
    return {'label': 'M = %d (%d quads, rim arc %.2f nm)' % (m, nq, h), 'h': h, 'P': r['peak'],
            'tp': r['tpeak'] * 1e6,
            'more': ['%.1f' % (r['tpeak'] * 1e6), ns(r['t_crack']), ns(r['t_spall']),
                     '%.1e' % r['ratio_dev']],
            'wall': cpu}


LS_LEVELS = [6, 8, 12]
SUBSURFACE = {
    'name': 'laser_subsurface', 'deck': 'decks/laser_subsurface (M = 8)',
    'title': 'Sub-surface particle in silica: peak particle pressure against the mesh',
    'runs': LS_LEVELS, 'case': sos.sweep(subsurface_case, LS_LEVELS, 'P', '%.3f'),
    'check_runs': [],
    'param': 'h = pi 50 nm / (4 M), the particle rim\'s arc (the whole O-grid and its graded '
             'blocks scale with 1/M; scripts/gen_laser2d_decks.py subsurface --m M)',
    'extra': sos.rich_table([('P', '%.3f'), ('tp', '%.1f')]),
    'cols': ['peak particle pressure [GPa]', 'rel. error vs Richardson', 'at [ns]',
             'crack at the surface [ns]', 'first surface damage [ns]',
             'max abs(energy ratio - 1)'],
    'expected': 'none (a crack model without a length scale)',
    'reason': 'Measured by scripts/subsurface_check.py (particle pressure = its elements\' '
              'pressures weighted by initial volume; times on the plot states, 0.1 ns apart). '
              'The seed (DYNA2D) gives about 3.6 GPa at 1.8 ns and the crack at the surface at '
              '2.9 ns; the deposit rate was chosen so that M = 8 peaks near 1.8 ns, so the peak '
              'time is a calibration (decks/laser_subsurface/README.md). Expected no order: '
              'the peak ends when the glass around the particle cracks, and the smeared crack '
              'model has no length scale (Bazant & Oh 1983), so when and where it cracks moves '
              'with the mesh; the crack\'s arrival at the surface (a connected path of damaged '
              'cells) is not reached by 3.5 ns on M = 12, and the peak time does not move '
              'monotonically. The peak itself falls by about the same amount at each step of M, '
              'so the pair orders come out near 1 and the triple extrapolates far below the '
              'finest level with a GCI of the order of the value (Richardson table): a '
              'pre-asymptotic triple, not an order of the discretisation, and the error column '
              'is only as good as that extrapolation. A finer level (M = 16, about four times '
              'M = 12\'s CPU) is not run: without a regularised crack model it would not give '
              'an order either.'}


SCENES = [BRITTLE2D, CMC, SSNV, KNEE, BACKSIDE, SUBSURFACE]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--only', nargs='*', default=None)
    ap.add_argument('--out', default=os.path.join(ROOT, 'docs', 'studies'))
    a = ap.parse_args()
    intro = ('Generated by `scripts/studies_order_more.py` (`make studies`; issue 23): the '
             'scenes of issues 19 and 20 (the axisymmetric brittle impact, the implicit '
             'implant and contact scenes, and the two laser scenes: back-surface pressure and '
             'sub-surface particle). Each is a mesh sweep of the scene\'s generator, run '
             'one at a time on the shared 2-core machine; run time = CPU seconds (user + '
             'system) of the dynx process. The error column is against the Richardson '
             'extrapolation of the three finest levels (Celik et al. 2008), or the finest level '
             'when those do not converge monotonically (then its own error is 0 and the last '
             'order is -); the analytic or published values are in each paragraph. Order = '
             'ln(e_i/e_(i+1)) / ln(h_i/h_(i+1)) between successive rows (- where the error '
             'changes sign or is zero). Plot: relative |error| against CPU time, log-log.')
    so.write_page(SCENES, a.out, 'more_scene_orders',
                  '# Scenes of issues 19 and 20: error against run time and observed orders',
                  intro, a.only, tlabel='CPU')


if __name__ == '__main__':
    main()
