"""Generated blocks of the deck READMEs (scripts/doc_numbers.py; issue 23, round 3b): each
either reads a study page's table or data file (no run; --check then compares the README with
the page, whose own cheap rows doc_numbers.py reruns) or reruns the deck when that is cheap
(a few CPU seconds). Standard library only."""
import math
import os
import re
import sys

from doc_numbers_cases import DYNX, PY, ROOT, sh


def run_generated(work, name, gen, **kw):
    """Write WORK/NAME.k with gen(path, **kw), run it (exit 0 required), keep its log in
    WORK/NAME.log: (outdir, log)."""
    k = os.path.join(work, name + '.k')
    o = os.path.join(work, name)
    gen(k, **kw)
    rc, log = sh([DYNX, '-i', k, '-o', o])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: %s: exit %d\n%s' % (name, rc, log[-1500:]))
    with open(os.path.join(work, name + '.log'), 'w') as f:
        f.write(log)
    return o, log


def table(path, section=None):
    """Rows (stripped cells) of the markdown tables of path (after the heading section)."""
    s = open(os.path.join(ROOT, path)).read()
    if section is not None:
        s = s[s.index(section):]
        nxt = s.find('\n#', 1)
        s = s if nxt < 0 else s[:nxt]
    return [[c.strip() for c in l.strip().strip('|').split('|')] for l in s.split('\n')
            if l.startswith('|') and not l.startswith('|---')]


def dat(path):
    return [l.split() for l in open(os.path.join(ROOT, path))
            if l.strip() and not l.startswith('#')]


# ---------------------------------------------------------------------------------------------
def block_ball_in_box(work):
    """decks/ball_in_box/README.md: the SFS = 1, TSSFAC 0.9 row of docs/studies/ball_in_box.md
    (make studies; the same deck) and the sweep summary from its other rows (no run)."""
    rows = {(r[0], r[1]): r for r in table('docs/studies/ball_in_box.md')
            if len(r) == 8 and r[0] != 'SFS'}
    r = rows[('1', '0.9')]
    fin = [rows[('1', f)][6] for f in ('0.9', '0.6', '0.3')]
    s100, s01 = rows[('100', '0.9')], rows[('0.1', '0.9')]
    return '\n'.join([
        '| quantity (t = 1 s, SFS = 1, TSSFAC 0.9; from [ball_in_box.md]'
        '(../../docs/studies/ball_in_box.md), `scripts/doc_numbers.py`) | dynx | exact | |',
        '|---|---|---|---|',
        '| cycles | %s | | |' % r[2],
        '| wall impacts (velocity reversals of the centre) | %s | | |' % r[4],
        '| ball KE between impacts, max abs(KE/KE0 - 1) | %.2e | 0 | |' % float(r[5]),
        '| ball KE at the end, KE/KE0 - 1 | %+.2e | 0 | %s |'
        % (float(r[6]), 'loss, not gain' if float(r[6]) < 0 else 'gain'),
        '| glstat energy ratio, max abs(ratio - 1) (during impacts) | %.1e | 1 | |' % float(r[7]),
        '',
        'Summary of the sweeps (same page): the energy error at the end is %.1e, %.1e, %.1e '
        'for TSSFAC 0.9, 0.6, 0.3; a stiff penalty (SFS = 100) departs by up to %.1e (%+.1e '
        'at the end); a soft one (SFS = 0.1) by %+.1e at the end, gained in impacts near an '
        'edge of the box, where a node switches between the two walls\' penalty springs.'
        % (float(fin[0]), float(fin[1]), float(fin[2]), float(s100[5]), float(s100[6]),
           float(s01[6]))])


def block_taylor_steinberg(work):
    """decks/taylor_steinberg/README.md: both decks rerun (about 1-2 CPU s each; dxpost.py
    taylor and energy, as the taylor_bar block), the static-curve row from the generated
    table of decks/taylor_bar/README.md (rerun by its own block), and the mesh sentence from
    the three meshes of docs/studies/data/hirate_taylor.dat (make studies, hirate.md section 3;
    its (4,4,24) rows are these decks)."""
    L0, R0, LX, RX = 23.47, 3.81, 14.79, 8.40
    out = ['| deck | final length | footprint radius | against the experiment | energy ratio '
           '(final; min-max) | cycles |', '|---|---|---|---|---|---|']
    for deck in ('deck_steinberg.k', 'deck_johnson_cook.k'):
        od = os.path.join(work, 'tsg_' + deck[:-2])
        rc, log = sh([DYNX, '-i', os.path.join(ROOT, 'decks/taylor_steinberg', deck), '-o', od])
        if rc != 0:
            raise SystemExit('doc_numbers_decks: %s: exit %d\n%s' % (deck, rc, log[-1500:]))
        _, post = sh([PY, 'scripts/dxpost.py', 'taylor', od, '--L0', str(L0), '--R0', str(R0)])
        lf = float(re.search(r'final length\s+(\S+)', post).group(1))
        rf = float(re.search(r'footprint radius\s+(\S+)', post).group(1))
        _, e = sh([PY, 'scripts/dxpost.py', 'energy', od])
        lo, hi, fin = (float(re.search(k + r'\s+(\S+)', e).group(1))
                       for k in ('min', 'max', 'final'))
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        out.append('| `%s` | %.3f mm (Lf/L0 %.3f) | %.3f mm (Rf/R0 %.3f) | %+.2f %% / %+.1f %% '
                   '| %.5f; %.5f-%.5f | %d |' % (deck, lf, lf / L0, rf, rf / R0,
                                                 100 * (lf / LX - 1), 100 * (rf / RX - 1),
                                                 fin, lo, hi, cyc))
    wg = [r for r in table('decks/taylor_bar/README.md') if r[0] == '`wilkins_guinan.k`'
          and r[1][:1].isdigit()][0]
    lf = float(wg[1].split()[0])
    rf = float(wg[2].split()[0])
    out.append('| (for comparison) `decks/taylor_bar/wilkins_guinan.k`, `*MAT_024` static JC '
               'curve | %.3f mm | %.3f mm | %+.1f %% / %+.1f %% | %s | %s |'
               % (lf, rf, 100 * (lf / LX - 1), 100 * (rf / RX - 1), wg[4], wg[5]))
    d = {(r[0], int(r[1])): r for r in dat('docs/studies/data/hirate_taylor.dat')}
    sg = [float(d[('steinberg', n)][3]) for n in (3, 4, 6)]
    jc = [float(d[('johnson_cook', n)][3]) for n in (3, 4, 6)]
    spread = max(abs(v[2] - v[0]) / v[1] for v in (sg, jc))
    out += ['', 'The three meshes of hirate.md ((3,3,18), (4,4,24), (6,6,36)): the lengths '
            'change by at most %.2f %% (SG %.3f, %.3f, %.3f mm; JC %.3f, %.3f, %.3f mm).'
            % ((100 * spread,) + tuple(sg) + tuple(jc))]
    return '\n'.join(out)


def block_cmc_loads(work):
    """decks/cmc_implant/README.md: the three loads, unbacked and Ti-backed, at n = 6 (10 deg),
    and the axial key pinch (0 deg) beside the thin-layer estimate: seven implicit runs of
    about 0.8 CPU s each (cmc_implant.py gen and result, as its study)."""
    sys.path.insert(0, os.path.join(ROOT, 'scripts'))
    import cmc_implant as ci

    def one(name, **kw):
        o, _ = run_generated(work, name, ci.gen, n=6, **kw)
        its = sum(len(q) for q in ci.newton_log(os.path.join(work, name + '.log')))
        return ci.result(o) + (its,)
    out = ['| load | socket | peak pressure MPa | max von Mises MPa | max plastic strain | '
           'iterations |', '|---|---|---|---|---|---|']
    res = {}
    for lname, load in ci.LOADS:
        for backed in (False, True):
            p, vm, ep, f, its = one('%s_%d' % (lname.replace(' ', '_'), backed), load=load,
                                    backed=backed)
            res[(lname, backed)] = (p, vm, ep)
            if (lname, backed) == ('key pinch', False):
                steps = ci.newton_log(os.path.join(work, 'key_pinch_0.log'))
            out.append('| %s %.1f N | %s | %.2f | %.2f | %s | %d |'
                       % (lname, load, 'Ti-backed' if backed else 'unbacked', p, vm,
                          '%.4f' % ep if ep > 0 else '0 (elastic)', its))
    dp = [100 * (res[(l, True)][0] / res[(l, False)][0] - 1) for l, _ in ci.LOADS]
    dv = [100 * (res[(l, True)][1] / res[(l, False)][1] - 1) for l, _ in ci.LOADS]
    de = [100 * (res[(l, True)][2] / res[(l, False)][2] - 1) for l, _ in ci.LOADS
          if res[(l, False)][2] > 0]
    pa = one('axial', load=188.5, angle=0.0)[0]
    pw = 3 * 188.5 / (2 * math.pi * ci.R * ci.R * (1 - math.cos(math.radians(40.0)) ** 3))
    out += ['', 'Metal backing (the polyethylene 1.2 mm thick on Ti instead of 2 mm) changes '
            'the peak contact pressure by %+.1f to %+.1f %%, the von Mises maximum by %+.1f '
            'to %+.1f %% and the plastic strain (where it yields) by %+.0f to %+.0f %%. The '
            'key pinch applied axially (0 deg, n = 6): peak pressure %.2f MPa, against the '
            'thin-layer (Winkler) estimate of an axial load 3F/(2 pi R^2 (1 - cos^3 40 deg)) '
            '= %.2f MPa.' % (min(dp), max(dp), min(dv), max(dv), min(de), max(de), pa, pw)]
    rate = [b / (a * a) for q in steps for a, b in zip(q, q[1:]) if a <= 2e-2 and b > 1e-10]
    quad = [r for r in rate if r <= 10.0]
    out += ['', 'Newton (key pinch, n = 6, unbacked, residual ratios per step): %s; q(k+1)/q(k)^2 '
            'over the pairs with q(k) <= 2e-2 (above round-off, as the regression check): '
            '%.2g-%.2g in %d pairs, above 10 in %d (%s).'
            % (' / '.join(' '.join('%.1e' % v for v in q) for q in steps), min(quad), max(quad),
               len(quad), len(rate) - len(quad),
               ', '.join('%.0f' % r for r in rate if r > 10.0) or 'none')]
    return '\n'.join(out)


def block_emc_ball_box(work):
    """decks/emc_ball_box/README.md: the emc_ball_box row of docs/conserving-contact.md's
    generated block emc_measured (rerun by its own block) and the largest drift of the dt
    sweep, docs/studies/data/emc_ballbox_sweep.dat (make studies; no run)."""
    row = [r for r in table('docs/conserving-contact.md') if r[0].startswith('`emc_ball_box`')][0]
    sw = dat('docs/studies/data/emc_ballbox_sweep.dat')
    big = max(max(float(v) for v in r[1:4]) for r in sw)
    return ('What it shows (`scripts/doc_numbers.py`, checked by `make test`): total energy '
            '(kinetic + penalty), linear and angular momentum stay at their initial values to '
            '1e-12 relative over the 10^5 steps (measured %s over %s output lines in contact: '
            'docs/conserving-contact.md; regression case `emc_ball_box`, asserted to 2e-13); '
            'the sweep over dt/T_f = %s ... %s (`emc_ball_box_sweep`, docs/studies/emc.md): '
            'largest %.1e.' % (row[2], row[1], sw[0][0], sw[-1][0], big))


def block_emc_roundoff(work):
    """docs/conserving-contact.md, section Round-off: the 'after' columns from
    docs/studies/data/emc_ballbox_sweep.dat (make studies: the sweep of emc_ball_box_sweep,
    every step; no run); the 'before' columns are the record of the binary before the
    round-off fixes."""
    before = {'1e-06': ('0', '1.8e-13'), '1e-05': ('0', '4.4e-13'), '0.0001': ('3.3e-13', '2.9e-12'),
              '0.001': ('2.0e-13', '7.4e-13'), '0.01': ('1.6e-12', '1.7e-12'),
              '0.1': ('2.5e-11', '1.4e-12')}
    out = ['| dt/T_f | energy | linear momentum | angular momentum | before (record): energy | '
           'before (record): angular |', '|---|---|---|---|---|---|']
    for r in dat('docs/studies/data/emc_ballbox_sweep.dat'):
        e, p, l = (float(v) for v in r[1:4])
        out.append('| %.0e | %.1e | %.1e | %.1e | %s | %s |' % ((float(r[0]), e, p, l)
                                                                + before[r[0]]))
    return '\n'.join(out)


def block_emc_explicit(work):
    """docs/conserving-contact.md: the explicit comparison, decks/emc_ball_box/deck_explicit.k
    over 10 s (about 2e5 cycles, a minute or two: written by --update, make studies)."""
    import dxpost
    od = os.path.join(work, 'emc_explicit')
    rc, log = sh([DYNX, '-i', os.path.join(ROOT, 'decks/emc_ball_box/deck_explicit.k'), '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: deck_explicit.k: exit %d\n%s' % (rc, log[-1500:]))
    names, rows = dxpost.columns(os.path.join(od, 'glstat'))
    er = [r[names.index('energy_ratio')] for r in rows]
    ke = [r[names.index('kinetic')] for r in rows]
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    return ('The explicit comparison (same ball and box, faceted ball, the contact branch\'s '
            '`*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE`, `decks/emc_ball_box/deck_explicit.k`), '
            'measured over 10 s (%d cycles, dt = %.3g s; `scripts/doc_numbers.py`, written by '
            '`make studies`): the glstat energy ratio (with the sliding energy) stays within '
            '[%.6f, %.6f]; the kinetic energy drops to %.3f of its initial value during '
            'contacts and is %.6f of it at the end.'
            % (cyc, rows[-1][names.index('dt')], min(er), max(er), min(ke) / ke[0],
               ke[-1] / ke[0]))


def block_knee_flex(work):
    """decks/knee_insert/README.md: the flexion sweep (Table 1 polyethylene, 10 mm insert,
    n = 4, d = 0.1 mm) and the elastic 10 mm insert at 0 deg against the half-space Hertz
    force: four implicit runs of about 10 CPU s (knee_insert.py gen and result, as its study):
    written by --update (make studies), not rerun by --check."""
    sys.path.insert(0, os.path.join(ROOT, 'scripts'))
    import knee_insert as ki

    def one(name, **kw):
        o, log = run_generated(work, name, ki.gen, n=4, **kw)
        its = sum(1 for l in log.split('\n') if 'residual ratio' in l)
        return ki.result(o) + (its,)
    out = ['| flexion | condyle R mm | Reff mm | F N | peak -sigma_zz MPa | max von Mises MPa | '
           'max plastic strain | iterations |', '|---|---|---|---|---|---|---|---|']
    eps = []
    for flex in sorted(ki.J_CURVE):
        F, p, vm, ep, its = one('flex%d' % flex, flex=flex)
        eps.append(ep)
        out.append('| %d deg | %g | %.3g | %.1f | %.2f | %.2f | %.4f | %d |'
                   % (flex, ki.J_CURVE[flex], ki.hertz(flex, 0.1)[0], F, p, vm, ep, its))
        if flex == 45:
            steps = []
            for l in open(os.path.join(work, 'flex45.log')):
                if 'implicit step' in l:
                    steps.append([])
                m = re.search(r'residual ratio\s+([0-9.Ee+-]+)', l)
                if m and steps:
                    steps[-1].append(float(m.group(1)))
    F0 = one('elastic', elastic=True)[0]
    fh = ki.hertz(0, 0.1)[2]
    out += ['', 'Plastic strain %.1f -> %.1f %% from 0 to 90 deg. Newton (45 deg, residual ratios '
            'per step): %s. The elastic 10 mm insert at 0 deg: F %.1f N (%+.0f %% against the '
            'half-space Hertz %.1f N).'
            % (100 * eps[0], 100 * eps[-1],
               ' / '.join(' '.join('%.1e' % v for v in q) for q in steps), F0,
               100 * (F0 / fh - 1), fh)]
    return '\n'.join(out)


INCLINE = [  # (theta, body id, body, regime, alpha reported)
    (8, 2, 'sphere', 'roll', True), (8, 3, 'block', 'stick', False),
    (10.5, 2, 'sphere', 'roll', False), (10.5, 3, 'block', 'stick', False),
    (12, 2, 'sphere', 'roll', True), (12, 3, 'block', 'slide', False),
    (20, 2, 'sphere', 'roll', True), (20, 3, 'block', 'slide', False),
    (45, 2, 'sphere', 'slide', True), (45, 3, 'block', 'slide', False)]


def block_incline(work):
    """decks/incline_friction/README.md: the scene deck (gen_scene_decks.py incline, n = 12,
    0.2 s) at theta = 8, 10.5, 12, 20, 45 deg, scene_check.py incline for the sphere and the
    block (the regression cases' checks), the energy ratio at 2 ms and at the end, cycles and
    step of the 20 deg deck: five runs of several CPU s each, written by --update (make
    studies), not rerun by --check."""
    import dxpost
    out = ['| theta | body | regime | quantity | dynx | analytic | error |',
           '|---|---|---|---|---|---|---|']
    early, end = [], []
    for th in sorted(set(r[0] for r in INCLINE)):
        deck = os.path.join(work, 'incline_%g.k' % th)
        sh([PY, 'scripts/gen_scene_decks.py', 'incline', '--theta', '%g' % th, '--mu', '0.2',
            '--n', '12', deck])
        od = os.path.join(work, 'incline_%g' % th)
        rc, log = sh([DYNX, '-i', deck, '-o', od])
        if rc != 0:
            raise SystemExit('doc_numbers_decks: incline %g: exit %d\n%s' % (th, rc, log[-1500:]))
        names, rows = dxpost.columns(os.path.join(od, 'glstat'))
        k = names.index('energy_ratio')
        early.append(min(r[k] for r in rows if 0 < r[0] <= 0.0025))
        end.append(rows[-1][k])
        if th == 20:
            cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
            dt20 = rows[-1][names.index('dt')]
        for t_, bid, body, mode, with_alpha in (r for r in INCLINE if r[0] == th):
            _, o = sh([PY, 'scripts/scene_check.py', 'incline', od, '--theta', '%g' % th,
                       '--mu', '0.2', '--body', str(bid), '--mode', mode, '--tol-a', '1']
                      + (['--sphere'] if body == 'sphere' else []))
            if mode == 'stick':
                a = float(re.search(r'a = (\S+) m/s', o).group(1))
                v = abs(a) / (9.81 * math.sin(math.radians(th)))
                out.append('| %g | block | stick | a/(g sin theta) | %.1e | 0 | tan %g = %.3f < '
                           'mu |' % (th, v, th, math.tan(math.radians(th))))
                continue
            m = re.search(r'a = (\S+) \(reference (\S+)\), alpha = (\S+) \(reference '
                          r'(\S+)\)', o)
            a, aref, al, alref = (float(x) for x in m.groups())
            note = (' (tan %g = %.3f > mu)' % (th, math.tan(math.radians(th)))
                    if body == 'block' else '')
            out.append('| %g | %s | %s | a | %.6g | %.6g | %+.2g %%%s |'
                       % (th, body, mode, a, aref, 100 * (a / aref - 1), note))
            if with_alpha:
                out.append('| %g | %s | %s | alpha | %.6g | %.6g | %+.2g %% |'
                           % (th, body, mode, al, alref, 100 * (al / alref - 1)))
    out += ['', 'Energy ratio (sliding-interface energy, i.e. friction work and penalty energy, '
            'included): %.5f-%.5f at the end; %.3f-%.3f at its lowest in the first 2.5 ms, the '
            'start-up deficit of the time-centred bookkeeping when gravity is switched on with '
            'everything at rest. The 20 deg deck: %d cycles, dt = %.3g s.'
            % (min(end), max(end), min(early), max(early), cyc, dt20)]
    return '\n'.join(out)


def post_numbers(deck_dir, work, name):
    """Run deck_dir/deck.k (with its mesh.k): vehicle speed (rear ring's -v_x) and crush at the
    end, the fender point's largest sideways displacement, max |energy ratio - 1|, hourglass
    energy at the end / initial kinetic energy (as studies_order_seed.post_case)."""
    import dxpost
    import shell_scene_check
    od = os.path.join(work, name)
    rc, log = sh([DYNX, '-i', os.path.join(deck_dir, 'deck.k'), '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: %s: exit %d\n%s' % (name, rc, log[-1500:]))
    names, rows = dxpost.columns(os.path.join(od, 'nodout'))
    hist, _ = shell_scene_check.read_mesh(os.path.join(deck_dir, 'mesh.k'))
    rr = [r for r in rows if int(r[1]) == hist[-1]]
    fen = [r for r in rows if int(r[1]) == hist[1]]
    gn, g = dxpost.columns(os.path.join(od, 'glstat'))
    ratio = max(abs(r[gn.index('energy_ratio')] - 1) for r in g)
    hg = g[-1][gn.index('hourglass')] / g[0][gn.index('kinetic')]
    return (-rr[-1][names.index('x_vel')], -rr[-1][names.index('x_disp')],
            max(abs(r[names.index('y_disp')]) for r in fen), ratio, hg)


def block_post_scene(work):
    """decks/shell_box_post/README.md 'What happens': 6 per side to 2 ms and to 6 ms
    (gen_shell_scenes.py post 6) and this deck (12 per side, 6 ms): about 40 CPU s, written by
    --update (make studies), not rerun by --check (the 6 and 12 per side 2 ms rows of
    docs/studies/seed_scene_orders.md are: its coarsest row by --check)."""
    res = {}
    for n, tend in ((6, '2.0'), (6, '6.0')):
        d = os.path.join(work, 'post%d_%s' % (n, tend))
        sh([PY, 'scripts/gen_shell_scenes.py', 'post', str(n), d, '--tend', tend, '--dplot', '0'])
        res[(n, tend)] = post_numbers(d, work, 'post%d_%s_out' % (n, tend))
    res['deck'] = post_numbers(os.path.join(ROOT, 'decks/shell_box_post'), work, 'post_deck')
    a, b, c = res[(6, '2.0')], res[(6, '6.0')], res['deck']
    return '\n'.join([
        '| | 6 per side, 2 ms (regression case) | 12 per side, 6 ms (this deck) |',
        '|---|---|---|',
        '| vehicle speed at the end | %.2f m/s | %.2f m/s |' % (a[0], c[0]),
        '| crush (rear ring\'s travel) | %.1f mm | %.1f mm |' % (a[1], c[1]),
        '| fender point: largest sideways | %.1f mm | %.1f mm |' % (a[2], c[2]),
        '| energy ratio, largest departure from 1 | %.1e | %.1e |' % (a[3], c[3]),
        '| hourglass energy / initial kinetic energy | %.2f %% at 2 ms (%.2f %% at 6 ms) | '
        '%.2f %% |' % (100 * a[4], 100 * b[4], 100 * c[4])])


def block_emc_hht(work):
    """docs/conserving-contact.md: the measured values of the regression case emc_hht_bars
    (its deck, then its check script, which runs the Newmark, conserving-parameter and ball-box
    variants and a restart check: about 2 CPU s)."""
    case = os.path.join(ROOT, 'tests/regression/emc_hht_bars')
    od = os.path.join(work, 'emc_hht_bars')
    rc, log = sh([DYNX, '-i', os.path.join(case, 'deck.k'), '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: emc_hht_bars: exit %d\n%s' % (rc, log[-1500:]))
    with open(os.path.join(od, 'stdout'), 'w') as f:
        f.write(log)
    rc, out = sh(['sh', os.path.join(case, 'check'), od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: emc_hht_bars check failed\n%s' % out[-2000:])
    hc = re.findall(r'rho_inf (\S+) chi \S+, \d+ steps; KE end \S+ \(model \S+, rel (\S+)\); '
                    r'energy taken \S+ \(model \S+, diff (\S+) E0\); largest rise (\S+) E0; '
                    r'p drift (\S+)', out)
    m = re.search(r'max rel. drift: energy (\S+), linear momentum (\S+), angular momentum '
                  r'(\S+);', out)
    bal = float(re.search(r'balance drift (\S+)', out).group(1))
    ident = 'identical' if 'conserving parameters: emcstat identical' in out else 'DIFFERENT'
    lines = ['| `emc_hht_bars` part | measured |', '|---|---|']
    for (rho, rel, diff, rise, p), what in zip(hc[:2], ('bars, HHT ALPHA = -0.3',
                                                         'bars, Newmark GAMMA 0.9, BETA 0.49')):
        lines.append('| %s (rho_inf %s) | final KE against the 1-D model %.1e, energy taken %.1e '
                     'E0, largest rise %.1e E0, momentum %.1e |'
                     % (what, rho, float(rel), float(diff), float(rise), float(p)))
    lines.append('| conserving parameters written out | emcstat %s to the run without the '
                 'keyword |' % ident)
    lines.append('| ball in the box, HHT ALPHA = -1/3, 10^4 steps | energy taken %.3f of E0; '
                 'linear momentum %.1e, angular momentum %.1e, balance KE + U + taken = E0 %.1e |'
                 % (float(m.group(1)), float(m.group(2)), float(m.group(3)), bal))
    return '\n'.join(lines)


def block_emc_matrix(work):
    """docs/conserving-contact.md: scripts/emc_extreme_matrix.py's table (22 two-bar runs, the
    regression case emc_extreme_matrix's check; about 3 CPU s) and its largest values."""
    rc, out = sh([PY, 'scripts/emc_extreme_matrix.py', os.path.join(work, 'emc_matrix')])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: emc_extreme_matrix.py failed\n%s' % out[-2000:])
    tab = [l for l in out.split('\n') if l.startswith('|')]
    rows = [[c.strip() for c in l.strip('|').split('|')] for l in tab[2:]]
    e = max(float(r[5]) for r in rows)
    p = max(float(r[6]) for r in rows)
    v = max(max(abs(float(r[7])), abs(float(r[8]))) for r in rows)
    g = min(float(r[9]) for r in rows if r[0] == 'lagrange')
    return '\n'.join(tab + ['', '%s; largest: energy %.1e, momentum %.1e, velocities %.1e; '
                             'smallest Lagrange gap %g.'
                             % (out.strip().split('\n')[-1], e, p, v, g)])


def shell_miter(work, case_name, scene, nfine, tend, dplot, coarse, fine):
    """The 'four algorithms' table of a seed shell scene: the regression case's decks (MITER
    4, 1, 2, 3 on its mesh) and a finer MITER 2 run (gen_shell_scenes.py SCENE NFINE), the
    largest differences to the case's MITER 2 run as shell_scene_check.py agree measures them
    (the case's check)."""
    import contextlib
    import io
    import shell_scene_check as ssc
    case = os.path.join(ROOT, 'tests/regression', case_name)
    od = {}
    for m, deck in (('4', 'deck.k'), ('1', 'deck_miter1.k'), ('2', 'deck_miter2.k'),
                    ('3', 'deck_miter3.k')):
        od[m] = os.path.join(work, '%s_m%s' % (scene, m))
        rc, log = sh([DYNX, '-i', os.path.join(case, deck), '-o', od[m]])
        if rc != 0:
            raise SystemExit('doc_numbers_decks: %s %s: exit %d' % (case_name, deck, rc))
    df = os.path.join(work, '%s%d' % (scene, nfine))
    sh([PY, 'scripts/gen_shell_scenes.py', scene, str(nfine), df, '--tend', tend, '--dplot',
        dplot])
    rc, log = sh([DYNX, '-i', os.path.join(df, 'deck_miter2.k'), '-o', df + '_out'])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: %s %d MITER 2: exit %d' % (scene, nfine, rc))
    mesh = os.path.join(case, 'mesh.k')
    worsts = []
    with contextlib.redirect_stdout(io.StringIO()):
        ssc.cmd_agree(mesh, od['2'], [od['1'], od['4'], od['3']], {}, worsts=worsts)
        ssc.cmd_agree(mesh, od['2'], [df + '_out'], {}, omesh=os.path.join(df, 'mesh.k'),
                      worsts=worsts)
    out = ['| | displacement [mm] | velocity [mm/ms] | von Mises [GPa] |', '|---|---|---|---|']
    for w, label in zip(worsts, ('(b) secant x 3 (MITER 1)', '(a) one-step (MITER 4)',
                                 '(c) radial scaling (MITER 3)',
                                 'mesh: %s against %s (both MITER 2)' % (coarse, fine))):
        out.append('| %s | %.3g | %.3g | %.3g |' % (label, w['disp'], w['vel'], w['vm']))
    return '\n'.join(out)


def block_post_miter(work):
    """decks/shell_box_post/README.md 'The four algorithms': shell_scene_post's decks (6 per
    side, 2 ms) and a 12 per side MITER 2 run: about 20 CPU s, --update only."""
    return shell_miter(work, 'shell_scene_post', 'post', 12, '2.0', '0.2', '6', '12 per side')


def block_plate_miter(work):
    """decks/shell_projectile_plate/README.md 'The four algorithms': shell_scene_plate's decks
    (20 x 20, 1 ms) and a 40 x 40 MITER 2 run: about 12 CPU s, --update only."""
    return shell_miter(work, 'shell_scene_plate', 'plate', 40, '1.0', '0.1', '20 x 20',
                       '40 x 40')


def block_erosion_dtmin(work):
    """docs/extreme-cases.md 4b: the regression case erosion_dtmin_taylor (eroded energies, the
    energy-ratio band, finite plot values, as its check) and the same deck run longer (end
    0.01 ms) with DTMIN 0.5 and 0.9: exit code and the end or the error line (under a second
    in all)."""
    import dxpost
    deck = os.path.join(ROOT, 'tests/regression/erosion_dtmin_taylor/deck.k')
    od = os.path.join(work, 'ero')
    rc, log = sh([DYNX, '-i', deck, '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: erosion_dtmin_taylor: exit %d\n%s' % (rc, log[-1500:]))
    n, g = dxpost.columns(os.path.join(od, 'glstat'))
    er = [r[n.index('energy_ratio')] for r in g]
    _, fin = sh([PY, 'scripts/extreme_check.py', 'finite', od])
    nonfin = int(re.search(r'(\d+) non-finite values', fin).group(1))
    text = ('With ERODE = 1 the elements whose step falls below the floor erode instead '
            '(dx_erosion), and the bar runs on past the floor to its end time (t = %.4g ms, '
            'exit %d): eroded internal energy %.1f, eroded kinetic energy %.1f (impact-face '
            'nodes no element holds any more, flying on), energy ratio %.5f to %.5f with the '
            'eroded energies in it, %s.'
            % (g[-1][0], rc, g[-1][n.index('eroded_internal_energy')],
               g[-1][n.index('eroded_kinetic_energy')], min(er), max(er),
               'every plot value finite' if nonfin == 0 else '%d non-finite values' % nonfin))
    src = open(deck).read().split('\n')
    k = [j for j, l in enumerate(src) if l.startswith('*CONTROL_TERMINATION')][0] + 2
    longer = []
    for dtmin in ('0.5', '0.9'):
        src[k] = '   0.01000         0     %s' % dtmin
        path = os.path.join(work, 'ero_%s.k' % dtmin)
        with open(path, 'w') as f:
            f.write('\n'.join(src))
        rc, log = sh([DYNX, '-i', path, '-o', os.path.join(work, 'ero_%s' % dtmin)])
        m = re.search(r'normal termination at cycle (\d+), time (\S+), energy ratio (\S+)', log)
        if rc == 0 and m:
            longer.append('DTMIN %s: exit 0 at cycle %s, energy ratio %.4f at the end'
                          % (dtmin, m.group(1), float(m.group(3))))
        else:
            err = re.search(r'^dynx: error: (.*)$', log, re.M)
            longer.append('DTMIN %s: exit %d (%s)' % (dtmin, rc, err.group(1) if err else '?'))
    return text + ' Run longer (end 0.01 ms): ' + '; '.join(longer) + '.'


def block_loaded_start(work):
    """docs/extreme-cases.md 6a: decks/elastic_wave/deck.k with glstat every cycle (a copy with
    *DATABASE_GLSTAT 1e-30): the energy ratio over the first cycles of a loaded start."""
    import dxpost
    src = open(os.path.join(ROOT, 'decks/elastic_wave/deck.k')).read()
    src, n = re.subn(r'(\*DATABASE_GLSTAT\s*\n)\s*\S+', r'\1 1.0e-30', src, count=1)
    if n != 1:
        raise SystemExit('doc_numbers_decks: decks/elastic_wave/deck.k: no *DATABASE_GLSTAT')
    path = os.path.join(work, 'wave_cycles.k')
    with open(path, 'w') as f:
        f.write(src)
    od = os.path.join(work, 'wave_cycles')
    rc, log = sh([DYNX, '-i', path, '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: elastic_wave: exit %d\n%s' % (rc, log[-1500:]))
    names, rows = dxpost.columns(os.path.join(od, 'glstat'))
    ratio = {int(r[1]): r[names.index('energy_ratio')] for r in rows}
    cyc = (0, 1, 2, 3, 5, 10, 50)
    return ('Measured (`scripts/doc_numbers.py`, checked by `make test`): `decks/elastic_wave` '
            '(a prescribed velocity from t = 0) with glstat every cycle, energy ratio at cycles %s: '
            '%s.' % (', '.join(str(c) for c in cyc), ', '.join('%.3f' % ratio[c] for c in cyc)))


def block_contact_sfs(work):
    """docs/extreme-cases.md, Contact: the two rods (gen_contact_decks.py rod --nx 50 --sfs S)
    for SFS = 0.01 ... 1000 today: cycles, contact duration against 2L/c, velocities after
    release and the energy ratio band (contact_post.py rod; six runs of up to 6000 cycles of
    100 hexes, a few CPU s)."""
    from contact_post import table as rc_table
    out = ['| SFS | cycles | contact duration [ms] | striker after [m/s] | target after [m/s] | '
           'energy ratio range |', '|---|---|---|---|---|---|']
    for sfs in ('0.01', '0.1', '1', '10', '100', '1000'):
        deck = os.path.join(work, 'rod_sfs_%s.k' % sfs)
        sh([PY, 'scripts/gen_contact_decks.py', 'rod', '--nx', '50', '--sfs', sfs, deck])
        od = os.path.join(work, 'rod_sfs_%s' % sfs)
        rc, log = sh([DYNX, '-i', deck, '-o', od])
        if rc != 0:
            raise SystemExit('doc_numbers_decks: rod SFS %s: exit %d\n%s' % (sfs, rc, log[-1500:]))
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        _, post = sh([PY, 'scripts/contact_post.py', 'rod', od, '--nx', '50'])
        v = {}
        for m in re.finditer(r'^(.*?\S)\s+(\S+)\s+reference\s+(\S+)', post, re.M):
            v[m.group(1)] = (float(m.group(2)), float(m.group(3)))
        dur, t2 = v['contact duration [ms] vs 2L/c']
        names, rows = rc_table(os.path.join(od, 'rcforc'))
        held = rows[-1][names.index('nactive')] > 0
        m = re.search(r'energy ratio min (\S+) max (\S+)', post)
        out.append('| %s | %d | %s | %.3f | %.3f | %s .. %s |'
                   % (sfs, cyc, 'never released' if held else '%.5f (%+.2g %%)'
                      % (dur, 100 * (dur / t2 - 1)),
                      v['striker velocity after release [m/s]'][0],
                      v['target velocity after release [m/s]'][0], m.group(1), m.group(2)))
    return '\n'.join(out)


def block_hertz_implicit(work):
    """decks/hertz/README.md: the regression case implicit_hertz_coarse (n = 4, SFS 100, two
    Newton load steps; about 2.3 CPU s) against Hertz through contact_post.py hertz, as its
    check."""
    od = os.path.join(work, 'implicit_hertz')
    rc, log = sh([DYNX, '-i', os.path.join(ROOT, 'tests/regression/implicit_hertz_coarse/deck.k'),
                  '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers_decks: implicit_hertz_coarse: exit %d\n%s' % (rc, log[-1500:]))
    _, out = sh([PY, 'scripts/contact_post.py', 'hertz', od, '--n', '4', '--zone', '0.8'])
    a, aref = (float(x) for x in re.search(r'contact radius a \[mm\] vs Hertz\s+(\S+)\s+'
                                           r'reference\s+(\S+)', out).groups())
    p, pref = (float(x) for x in re.search(r'peak pressure p0 \[GPa\] vs Hertz\s+(\S+)\s+'
                                           r'reference\s+(\S+)', out).groups())
    f = float(re.search(r'force F = (\S+) kN', out).group(1))
    return ('Measured (`scripts/doc_numbers.py`, checked by `make test`): F = %.3f kN, a = %.4f '
            'mm (%+.1f %% against Hertz %.4f), p0 = %.3f GPa (%+.1f %% against %.3f).'
            % (f, a, 100 * (a / aref - 1), aref, p, 100 * (p / pref - 1), pref))


BLOCKS = {
    # reads docs/studies/ball_in_box.md (no run)
    'ball_in_box': ('decks/ball_in_box/README.md', True, block_ball_in_box),
    # two Taylor runs (1152 hexes, 3139 and 5028 cycles: about 1.2 and 2 CPU s)
    'taylor_steinberg': ('decks/taylor_steinberg/README.md', True, block_taylor_steinberg),
    # seven implicit runs at n = 6, about 6 CPU s in all
    'cmc_loads': ('decks/cmc_implant/README.md', True, block_cmc_loads),
    # read conserving-contact.md's emc_measured row and the emc.md sweep data (no run)
    'emc_ball_box': ('decks/emc_ball_box/README.md', True, block_emc_ball_box),
    'emc_roundoff': ('docs/conserving-contact.md', True, block_emc_roundoff),
    # four implicit runs of about 10 CPU s: --update only
    'knee_flex': ('decks/knee_insert/README.md', False, block_knee_flex),
    # five 0.2 s incline runs: --update only
    'incline': ('decks/incline_friction/README.md', False, block_incline),
    # three shell runs (6 per side 2 and 6 ms, 12 per side 6 ms), about 40 CPU s: --update only
    'post_scene': ('decks/shell_box_post/README.md', False, block_post_scene),
    # the emc_hht_bars case and its check (about 2 CPU s)
    'emc_hht': ('docs/conserving-contact.md', True, block_emc_hht),
    # 22 two-bar runs of emc_extreme_matrix.py (about 3 CPU s)
    'emc_matrix': ('docs/conserving-contact.md', True, block_emc_matrix),
    # the four MITER decks of shell_scene_post and a 12 per side run (about 20 CPU s)
    'post_miter': ('decks/shell_box_post/README.md', False, block_post_miter),
    # the four MITER decks of shell_scene_plate and a 40 x 40 run (about 12 CPU s): --update
    # only (the regression case asserts these differences' bounds and order)
    'plate_miter': ('decks/shell_projectile_plate/README.md', False, block_plate_miter),
    # three tiny erosion runs (under a second)
    'erosion_dtmin': ('docs/extreme-cases.md', True, block_erosion_dtmin),
    # the elastic wave deck, glstat every cycle (71 cycles)
    'loaded_start': ('docs/extreme-cases.md', True, block_loaded_start),
    # six rod runs (up to 6000 cycles of 100 hexes)
    'contact_sfs': ('docs/extreme-cases.md', True, block_contact_sfs),
    # one implicit Hertz run (n = 4, 2 load steps, about 2.3 CPU s)
    'hertz_implicit': ('decks/hertz/README.md', True, block_hertz_implicit),
    # 2e5 explicit cycles (a minute or two): --update only
    'emc_explicit': ('docs/conserving-contact.md', False, block_emc_explicit),
}


def checks(compare):
    """Cross-checks without a block: the dynx rows of decks/ssnv104/README.md's record table
    (beside CalculiX, which is not rerun) against the ssnv104 rows of
    docs/studies/more_scene_orders.md (F, a, p0 fit, pole; make studies). compare is
    doc_numbers.compare. Returns [(what, [differences])]."""
    page = {r[0].split()[2]: r for r in table('docs/studies/more_scene_orders.md',
                                               '## SSNV104') if r[0].startswith('n = ') and ',' not in r[0]}
    bad, n = [], 0
    for r in table('decks/ssnv104/README.md'):
        if r[0] != 'dynx':
            continue
        p = page.get(r[1])
        if p is None:
            bad.append('ssnv104 README: dynx n = %s not on more_scene_orders.md' % r[1])
            continue
        n += 1
        doc = ' '.join(r[2:6])
        bad += compare(doc, ' '.join([p[3], p[4], p[5], p[1]]), 'ssnv104 README dynx n = %s'
                       % r[1])
    if n == 0:
        bad.append('ssnv104 README: no dynx row')
    return [('decks/ssnv104/README.md dynx rows against more_scene_orders.md', bad)]
