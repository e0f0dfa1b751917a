"""Generated blocks of docs/extreme-cases.md sections 2-4 (scripts/doc_numbers.py; issue 23):
each reruns a regression case's deck (tests/regression/<case>/deck.k with its args), once as
it is and, where the text quotes every cycle, once with glstat every cycle (a copy of the deck
with *DATABASE_GLSTAT 1e-30), and writes the numbers the sections quote: exit code and error
line, cycles, steps, energy-ratio band, plot states (scripts/extreme_check.py, as the cases'
checks). All cheap (under a second each): rerun by --check. Standard library only."""
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DYNX = os.path.join(ROOT, 'bin', 'dynx')
PY = '/usr/bin/python3'


def sh(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       cwd=ROOT)
    return p.returncode, p.stdout


def run_case(case, work, every_cycle=False, expect_rc=None):
    """Run the case's deck (its args too): (exit code, combined log, outdir)."""
    d = os.path.join(ROOT, 'tests', 'regression', case)
    deck = os.path.join(d, 'deck.k')
    name = case + ('_cycles' if every_cycle else '')
    if every_cycle:
        s = open(deck).read()
        s, n = re.subn(r'(\*DATABASE_GLSTAT\s*\n)\s*\S+', r'\1 1.0e-30', s, count=1)
        if n != 1:
            raise SystemExit('doc_numbers_cases: %s: no *DATABASE_GLSTAT card' % case)
        deck = os.path.join(work, name + '.k')
        with open(deck, 'w') as f:
            f.write(s)
    args = open(os.path.join(d, 'args')).read().split() if os.path.exists(
        os.path.join(d, 'args')) else []
    od = os.path.join(work, name)
    rc, log = sh([DYNX, '-i', deck, '-o', od] + args)
    if expect_rc is not None and rc != expect_rc:
        raise SystemExit('doc_numbers_cases: %s: exit %d, expected %d\n%s'
                         % (case, rc, expect_rc, log[-1500:]))
    return rc, log, od


def glstat(od):
    import dxpost
    names, rows = dxpost.columns(os.path.join(od, 'glstat'))
    return {k: [r[i] for r in rows] for i, k in enumerate(names)}


def error_line(log):
    m = re.search(r'^dynx: error: .*$', log, re.M)
    return m.group(0) if m else None


def states(od):
    """(number of plot states, their times) from extreme_check.py's plot check"""
    _, out = sh([PY, 'scripts/extreme_check.py', 'states', od])
    m = re.search(r'nstates (\d+); state times (.*)', out)
    if not m:
        raise SystemExit('doc_numbers_cases: no plot states in %s:\n%s' % (od, out))
    return int(m.group(1)), m.group(2).split()


def block_taylor_10x(work):
    rc, log, od = run_case('extreme_taylor_10x', work, expect_rc=3)
    err = error_line(log)
    ns, times = states(od)
    _, _, oc = run_case('extreme_taylor_10x', work, every_cycle=True, expect_rc=3)
    g = glstat(oc)
    return ('dynx stops with exit %d (`scripts/doc_numbers.py`, checked by `make test`):\n\n'
            '```\n%s\n```\n\n'
            '- The time step falls from %.3g to %.2g ms before the failure (glstat every cycle, '
            '%d rows).\n'
            '- The energy ratio stays in %.6f - %.6f up to the failure (every cycle).\n'
            '- `d3plot.h5` holds %d states (t = %s ms), all values finite.'
            % (rc, err, g['dt'][0], g['dt'][-1], len(g['dt']), min(g['energy_ratio'][1:]),
               max(g['energy_ratio'][1:]), ns, ' and '.join(times)))


def block_distorted(work):
    rc, log, od = run_case('extreme_distorted_element', work, expect_rc=0)
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    g = glstat(od)
    _, out = sh([PY, 'scripts/extreme_check.py', 'maxdisp', od, '--max', '0.01'])
    umax = float(re.search(r'largest \|displacement\| over \d+ states (\S+)', out).group(1))
    _, out = sh([PY, 'scripts/extreme_check.py', 'minvol', od, '--min', '0.9'])
    vmin = float(re.search(r'smallest element volume / initial (\S+)', out).group(1))
    return ('Measured (`scripts/doc_numbers.py`, checked by `make test`): exit %d, %d cycles at '
            'dt = %.2g ms; energy ratio %.6f - %.6f (glstat every 5e-4 ms), %.6f at the end; '
            'largest |displacement| %.2g mm, the same in each fifth of the run (the amplitude '
            'does not grow); smallest volume ratio of the two elements %.4f; no non-finite '
            'value. Hourglass energy at the end %.3g of the total %.3g (ELFORM 1, viscous IHQ '
            '1).' % (rc, cyc, g['dt'][-1], min(g['energy_ratio']), max(g['energy_ratio']),
                     g['energy_ratio'][-1], umax, vmin, g['hourglass'][-1], g['total'][-1]))


def block_crushed(work):
    rc, log, od = run_case('extreme_crushed_element', work, expect_rc=3)
    err = error_line(log)
    ns, times = states(od)
    _, _, oc = run_case('extreme_crushed_element', work, every_cycle=True, expect_rc=3)
    g = glstat(oc)
    return ('dynx stops with exit %d (`scripts/doc_numbers.py`, checked by `make test`):\n\n'
            '```\n%s\n```\n\n'
            'The step of the last cycle written is %.2g ms (cycle %d; glstat every cycle). The '
            'plot file holds %d states (t = %s ms), all finite.'
            % (rc, err, g['dt'][-1], int(g['cycle'][-1]), ns, ', '.join(times)))


def block_dtmin(work):
    rc, log, od = run_case('extreme_dtmin_floor', work, expect_rc=3)
    err = error_line(log)
    ns, times = states(od)
    return ('dynx stops with exit %d (`scripts/doc_numbers.py`, checked by `make test`):\n\n'
            '```\n%s\n```\n\n'
            'The plot file holds %d states (t = %s ms), all finite.'
            % (rc, err, ns, ' and '.join(times)))


# name -> (file, cheap, generator), merged into doc_numbers.BLOCKS
BLOCKS = {
    'extreme_taylor_10x': ('docs/extreme-cases.md', True, block_taylor_10x),
    'extreme_distorted': ('docs/extreme-cases.md', True, block_distorted),
    'extreme_crushed': ('docs/extreme-cases.md', True, block_crushed),
    'extreme_dtmin': ('docs/extreme-cases.md', True, block_dtmin),
}


def page_rows(path, prefix):
    """Table rows of a study page whose first cell starts with prefix (cells stripped)."""
    out = []
    for line in open(os.path.join(ROOT, path)):
        if line.startswith('| ' + prefix):
            cells = [c.strip() for c in line.strip().strip('|').split('|')]
            if ',' not in cells[0]:          # not a Richardson row (three levels)
                out.append(cells)
    return out


def block_brittle_impact_2d(work):
    """decks/brittle_impact_2d/README.md: the mesh sweep n = 16 / 32 / 64 from
    docs/studies/more_scene_orders.md (make studies; --check reruns nothing of it: the page's
    rows are compared as they are) and the SFACT 3 / 10 spread at n = 16 (two runs of about
    half a CPU second, rerun by --check)."""
    import brittle2d_check
    rows = {r[0].split()[2]: r for r in page_rows('docs/studies/more_scene_orders.md', 'n = ')
            if r[0].startswith('n = ') and '(h ' in r[0] and 'mm)' in r[0]}
    ns = ['16', '32', '64']
    if not all(n in rows for n in ns):
        raise SystemExit('doc_numbers_cases: more_scene_orders.md lacks the n 16/32/64 rows')
    sf = []
    for s in ('3', '10'):
        deck = os.path.join(work, 'b2d_sfact%s.k' % s)
        rc, out = sh([PY, 'scripts/gen_brittle2d_deck.py', '--n', '16', '--ns', '4', '--sfact',
                      s, deck])
        rc, log = sh([DYNX, '-i', deck, '-o', deck[:-2]])
        if rc != 0:
            raise SystemExit('doc_numbers_cases: %s: exit %d\n%s' % (deck, rc, log[-1500:]))
        sf.append(brittle2d_check.measure(deck[:-2]))
    # page cells: run, outer, error, inner, depth, angle, heave, hourglass, ratio, order, CPU
    col = {'outer': 1, 'inner': 3, 'depth': 4, 'angle': 5, 'heave': 6, 'hourglass': 7,
           'ratio': 8, 'cpu': 10}

    def cells(q, fmt):
        v = [rows[n][col[q]] for n in ns]
        return [fmt % float(x) for x in v]
    sfc = {'outer': '%.2f', 'inner': '%.2f', 'depth': '%.2f', 'angle': '%.0f'}
    lines = ['| quantity | experiment | DYNA2D | n 16 | n 32 | n 64 | SFACT 3 / 10 (n 16) |',
             '|---|---|---|---|---|---|---|']
    for q, name, exp, d2, fmt in (
            ('outer', 'outer fracture diameter (mm)', '1.65', '1.62', '%.2f'),
            ('inner', 'inner heavily fractured (mm)', '0.8', '0.7', '%.2f'),
            ('depth', 'damage depth (mm)', '1.0', '0.5', '%.2f'),
            ('angle', 'envelope angle (deg)', 'cone ~30', '', '%.0f'),
            ('ratio', 'max \\|energy ratio - 1\\|', '', '', '%.1e'),
            ('hourglass', 'hourglass / initial KE', '', '', '%.3f'),
            ('heave', 'surface heave (mm)', '', '', '%.2f'),
            ('cpu', 'CPU (s, user + system)', '', '', '%.3g')):
        if q in sfc:
            last = ' / '.join(sfc[q] % m[q] for m in sf)
        elif q == 'ratio':
            last = ' / '.join('%.1e' % m['ratio_dev'] for m in sf)
        else:
            last = ''
        lines.append('| %s | %s | %s | %s | %s |' % (name, exp, d2, ' | '.join(cells(q, fmt)),
                                                     last))
    return '\n'.join(lines)


BLOCKS['brittle_impact_2d'] = ('decks/brittle_impact_2d/README.md', True,
                               block_brittle_impact_2d)


HG_ROWS = [  # (deck, generator arguments, test)
    ('cube, IHQ 1, QH 0.1, TSSFAC 0.9', ['gen_hourglass_decks.py', '--qh', '0.1'],
     '`hourglass_cube_qh010`'),
    ('cube, IHQ 3, QH 0.1', ['gen_hourglass_decks.py', '--ihq', '3'], '`hourglass_cube_ihq3`'),
    ('cube, IHQ 1, QH 0.15', ['gen_hourglass_decks.py', '--qh', '0.15'],
     '`hourglass_cube_qh015`'),
    ('square 4x4, ELFORM 13, QH 0.1', ['gen_hourglass_decks.py', '--twod', '--qh', '0.1'],
     '(sweep)'),
    ('square 4x4, ELFORM 13, QH 0.2', ['gen_hourglass_decks.py', '--twod', '--qh', '0.2'],
     '`hourglass_quad2d_qh020`'),
    ('BT plate 4x4, 10 x 10 x 1 mm, centre node kicked, 10 ms',
     ['gen_hourglass_decks.py', '--plate', '--node', 'centre', '--side', '10', '--thk', '1'],
     '`hourglass_bt_plate`'),
    ('BT plate 4x4, 100 x 100 x 1 mm, corner node kicked', ['gen_hourglass_decks.py', '--plate'],
     '(sweep)'),
    ('BT plate 4x4, 40 x 40 x 1 mm, centre node',
     ['gen_hourglass_decks.py', '--plate', '--node', 'centre', '--side', '40'], '(sweep)'),
    ('thin plate 1:1 of section 5', ['thin_sweep.py', '--write-deck', '1'],
     '`thin_plate_aspect32` (1:32)'),
    ('thin plate 1:8', ['thin_sweep.py', '--write-deck', '8'], ''),
    ('needle 1:32', ['thin_sweep.py', '--shape', 'needle', '--write-deck', '32'],
     '`thin_needle_aspect64` (1:64)'),
]


def block_hourglass(work):
    """docs/extreme-cases.md section 8: the viscous-hourglass decks now (each well under a
    CPU second): largest |energy ratio - 1| over glstat and the first step."""
    out = ['| deck | max abs(energy ratio - 1) | exit | first step [ms] | test |',
           '|---|---|---|---|---|']
    for k, (label, gen, test) in enumerate(HG_ROWS):
        deck = os.path.join(work, 'hg%d.k' % k)
        cmd = [PY, os.path.join('scripts', gen[0])] + gen[1:]
        cmd = cmd + [deck] if gen[0] == 'gen_hourglass_decks.py' else cmd[:-1] + [gen[-1], deck]
        rc, log = sh(cmd)
        if rc != 0 or not os.path.exists(deck):
            raise SystemExit('doc_numbers_cases: %s failed\n%s' % (' '.join(cmd), log[-800:]))
        rc, log = sh([DYNX, '-i', deck, '-o', deck[:-2]])
        g = glstat(deck[:-2])
        out.append('| %s | %.1e | %d | %.5g | %s |'
                   % (label, max(abs(r - 1.0) for r in g['energy_ratio'][1:]), rc, g['dt'][0],
                      test))
    return '\n'.join(out)


BLOCKS['hourglass_after'] = ('docs/extreme-cases.md', True, block_hourglass)


def block_cmc_mesh(work):
    """decks/cmc_implant/README.md: the key-pinch mesh convergence, from the rows of
    docs/studies/more_scene_orders.md (no rerun; --check compares the README with the page)."""
    rows = [r for r in page_rows('docs/studies/more_scene_orders.md', 'n = ') if '(h 1/' in r[0]]
    if not rows:
        raise SystemExit('doc_numbers_cases: more_scene_orders.md has no cmc_implant rows')
    out = ['| n | peak pressure MPa | max von Mises MPa | max plastic strain | reaction N | '
           'iterations | CPU s |', '|---|---|---|---|---|---|---|']
    for r in rows:
        out.append('| %s | %s | %s | %s | %s | %s | %s |'
                   % (r[0].split()[2], r[1], r[3], r[4], r[5], r[6], r[8]))
    return '\n'.join(out)


def block_knee_mesh(work):
    """decks/knee_insert/README.md: the elastic Hertz series (thick insert, 0 deg), from the
    knee_insert rows of docs/studies/more_scene_orders.md against Hertz F 486.0 N, p0 29.01
    MPa (the README's formulas; no rerun)."""
    import knee_insert
    _, _, fh, p0 = knee_insert.hertz(0, 0.1)
    sec = open(os.path.join(ROOT, 'docs/studies/more_scene_orders.md')).read()
    sec = sec[sec.index('## Knee insert'):]
    rows = [[c.strip() for c in l.strip().strip('|').split('|')] for l in sec.split('\n')
            if l.startswith('| n = ') and ',' not in l.split('|')[1]]
    out = ['| n | F N | F vs Hertz | peak -sigma_zz (top layer) MPa | vs p0 | iterations | '
           'CPU s |', '|---|---|---|---|---|---|---|']
    for r in rows:
        if len(r) < 7:
            continue
        f, p = float(r[1]), float(r[3])
        out.append('| %s | %.1f | %+.1f %% | %.2f | %+.1f %% | %s | %s |'
                   % (r[0].split()[2], f, 100 * (f / fh - 1), p, 100 * (p / p0 - 1), r[4],
                      r[6]))
    return '\n'.join(out)


BLOCKS['cmc_mesh'] = ('decks/cmc_implant/README.md', True, block_cmc_mesh)
BLOCKS['knee_mesh'] = ('decks/knee_insert/README.md', True, block_knee_mesh)


def block_single_cubes(work):
    """docs/extreme-cases.md, Observations 1 and 2 now: the single undistorted unit cube of
    case 3a's loading, ELFORM 1 and ELFORM 2 (gen_extreme_decks.py distorted --only N --shape
    cube), each about 420 cycles."""
    out = []
    for only, name in (('1', 'ELFORM 1 (IHQ 1)'), ('2', 'ELFORM 2')):
        deck = os.path.join(work, 'cube%s.k' % only)
        rc, log = sh([PY, 'scripts/gen_extreme_decks.py', 'distorted', '--only', only,
                      '--shape', 'cube', '--tend', '0.05', deck])
        rc, log = sh([DYNX, '-i', deck, '-o', deck[:-2]])
        m = re.search(r'normal termination at cycle (\d+)', log)
        g = glstat(deck[:-2])
        r = g['energy_ratio'][1:]
        out.append('%s: exit %d%s, energy ratio %.4f - %.4f (t > 0), %.4f at the end'
                   % (name, rc, ', %s cycles' % m.group(1) if m else '', min(r), max(r), r[-1]))
    return ('Now (`scripts/doc_numbers.py`, checked by `make test`; 0.05 ms): ' + '; '.join(out)
            + '.')


BLOCKS['single_cubes'] = ('docs/extreme-cases.md', True, block_single_cubes)


EMC_ROWS = [  # (case, emc_check arguments, label)
    ('emc_ball_box', ['--etol', '2e-13', '--ptol', '2e-13', '--ltol', '2e-13', '--min-contact',
                      '500', '--lx-exchange', '100'], '1. ball in a box'),
    ('emc_ball_shell_friction', ['--dissipative', '0.2', '--plateau', '1e-5', '--ptol', '1e-12',
                                 '--ltol', '1e-12', '--min-contact', '500'],
     '2. ball in a shell, friction FS = 0.3'),
    ('emc_extreme_corner', ['--etol', '1e-12', '--ptol', '1e-12', '--ltol', '1e-12', '--lfloor',
                            '600', '--min-contact', '100'], 'multi-point: box corner'),
    ('emc_extreme_grazing', ['--etol', '1e-12', '--ptol', '1e-12', '--ltol', '1e-12',
                             '--lfloor', '300', '--min-contact', '100'], 'grazing'),
    ('emc_extreme_stiff_cut', ['--etol', '1e-10', '--ptol', '1e-12', '--ltol', '1e-12',
                               '--min-contact', '0', '--lx-exchange', '10'],
     'stiff: EPS 1e12, dt = 1e4 x contact time'),
]


def block_emc_measured(work):
    """docs/conserving-contact.md: the measured column of the cheap conserving-contact cases
    (each run under 2 s; emc_check.py as the cases' checks run it)."""
    out = ['| case | output lines with contact | largest relative drift: energy (friction: its '
           'loss), linear momentum, angular momentum | more |', '|---|---|---|---|']
    for case, args, label in EMC_ROWS:
        rc, log, od = run_case(case, work, expect_rc=0)
        _, chk = sh([PY, 'scripts/emc_check.py', od] + args)
        m = re.search(r'(\d+) with contact; max rel. drift: energy (\S+), linear momentum '
                      r'(\S+), angular momentum (\S+);', chk)
        if not m:
            raise SystemExit('doc_numbers_cases: %s: emc_check output\n%s' % (case, chk))
        more = []
        d = re.search(r'largest energy rise per line (\S+), loss (\S+)', chk)
        if d:
            more.append('largest energy rise per line %.1e, loss %.1f %%'
                        % (float(d.group(1)), 100 * float(d.group(2))))
        d = re.search(r'energy change over the second half (\S+)', chk)
        if d:
            more.append('change over the second half %.1e' % float(d.group(1)))
        if case == 'emc_extreme_corner':
            n = max(int(float(l.split()[13])) for l in open(os.path.join(od, 'emcstat'))
                    if re.match(r'\s*[-+.0-9]', l))
            more.append('at most %d pairs in one step' % n)
        d = re.search(r'step cuts (\d+)', log)
        if d and case == 'emc_extreme_stiff_cut':
            more.append('%s step cuts' % d.group(1))
        e, p, a = (float(m.group(k)) for k in (2, 3, 4))
        out.append('| `%s` (%s) | %s | %.1e, %.1e, %.1e | %s |'
                   % (case, label, m.group(1), e, p, a, '; '.join(more)))
    return '\n'.join(out)


BLOCKS['emc_measured'] = ('docs/conserving-contact.md', True, block_emc_measured)


def block_thin_now(work):
    """docs/extreme-cases.md section 5: the thin-plate and needle sweeps with today's dynx
    (scripts/thin_sweep.py, 16 runs of about 94 cycles on 64 hexes)."""
    out = []
    for shape, title in (('plate', 'Plate elements 1 x 1 x 1/A, now:'),
                         ('needle', 'Needle elements 1 x 1/A x 1/A, now:')):
        rc, tab = sh([PY, 'scripts/thin_sweep.py', '--shape', shape, '--out',
                      os.path.join(work, 'thin_' + shape)])
        if rc != 0:
            raise SystemExit('doc_numbers_cases: thin_sweep.py --shape %s: exit %d\n%s'
                             % (shape, rc, tab[-1500:]))
        out += [title, ''] + [l for l in tab.split('\n') if l.startswith('|')] + ['']
    return '\n'.join(out).rstrip()


BLOCKS['thin_now'] = ('docs/extreme-cases.md', True, block_thin_now)


def taylor_axisym_rows(work, meshes, with_cpu):
    """Rows of decks/taylor_bar_axisym/README.md's table: gen_quad2d_decks.py taylor DIR
    ELFORM NR NZ, run, final length and footprint (quad2d_check.py taylor), energy ratio at the
    end, cycles, CPU seconds (user + system) of the run."""
    import resource
    rows = []
    for ef, nr, nz in meshes:
        d = os.path.join(work, 'tax_%d_%d' % (ef, nr))
        os.makedirs(d, exist_ok=True)
        rc, out = sh([PY, 'scripts/gen_quad2d_decks.py', 'taylor', d, str(ef), str(nr), str(nz)])
        t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        rc, log = sh([DYNX, '-i', os.path.join(d, 'deck.k'), '-o', os.path.join(d, 'out')])
        t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        if rc != 0:
            raise SystemExit('doc_numbers_cases: taylor axisym %d %d: exit %d' % (ef, nr, rc))
        cpu = t1.ru_utime - t0.ru_utime + t1.ru_stime - t0.ru_stime
        _, chk = sh([PY, 'scripts/quad2d_check.py', 'taylor', os.path.join(d, 'out'), '21.45',
                     '1', '7.225', '1'])
        m = re.search(r'Lf = (\S+) mm .*Rf = (\S+) mm', chk)
        c = re.search(r'normal termination at cycle (\d+), time \S+, energy ratio (\S+)', log)
        rows.append('| %d x %d | %d | %.3f mm | %.3f mm | %.5f | %s |'
                    % (nr, nz, ef, float(m.group(1)), float(m.group(2)), float(c.group(2)),
                       c.group(1)) + (' %.2g s |' % cpu if with_cpu else ''))
    return rows


def block_taylor_axisym(work):
    """The 8 x 80 rows (ELFORM 15 and 14; about 2 CPU s each): rerun by --check (no CPU
    column: --check compares every number)."""
    return '\n'.join(['| mesh (nr x nz) | ELFORM | final length | footprint radius | energy '
                      'ratio | cycles |', '|---|---|---|---|---|---|']
                     + taylor_axisym_rows(work, [(15, 8, 80), (14, 8, 80)], False))


def block_taylor_axisym_fine(work):
    """The 16 x 160 rows (20-40 CPU s each): --update only (make studies)."""
    return '\n'.join(['| mesh (nr x nz) | ELFORM | final length | footprint radius | energy '
                      'ratio | cycles | CPU (user + system) |', '|---|---|---|---|---|---|---|']
                     + taylor_axisym_rows(work, [(15, 16, 160), (14, 16, 160)], True))


BLOCKS['taylor_axisym'] = ('decks/taylor_bar_axisym/README.md', True, block_taylor_axisym)
BLOCKS['taylor_axisym_fine'] = ('decks/taylor_bar_axisym/README.md', False,
                                block_taylor_axisym_fine)


def block_elastic_wave(work):
    """decks/elastic_wave/README.md: the scene deck against the analytic plateau and front
    (dxpost.py wave; 71 cycles)."""
    od, deck = os.path.join(work, 'ew'), os.path.join(ROOT, 'decks/elastic_wave/deck.k')
    rc, log = sh([DYNX, '-i', deck, '-o', od])
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    _, out = sh([PY, 'scripts/dxpost.py', 'wave', od])
    t = float(re.search(r'^t (\S+)', out, re.M).group(1))
    h = float(re.search(r'\bh (\S+)', out).group(1))
    pl, plr = (float(x) for x in re.search(r'plateau stress \[GPa\]\s+(\S+)\s+reference\s+(\S+)',
                                          out).groups())
    xf, xr = (float(x) for x in re.search(r'front position \[mm\]\s+(\S+)\s+reference\s+(\S+)',
                                          out).groups())
    ov = float(re.search(r'overshoot \(min/plateau - 1\)\s+(\S+)', out).group(1))
    return ('Numbers it reproduces (`scripts/doc_numbers.py`, checked by `make test`; %d cycles):'
            '\n\n| quantity | dynx | analytic |\n|---|---|---|\n'
            '| plateau stress [GPa] | %.7f | %.7f (relative error %+.2e) |\n'
            '| front (half-plateau crossing) [mm] at t = %.6f ms | %.4f | %.4f (%+.3f mm = '
            '%+.3f elements) |\n| overshoot min(sigma)/plateau - 1 | %.1e | 0 |'
            % (cyc, pl, plr, (pl - plr) / plr, t, xf, xr, xf - xr, (xf - xr) / h, ov))


BLOCKS['elastic_wave'] = ('decks/elastic_wave/README.md', True, block_elastic_wave)


def block_plate_scene(work):
    """decks/shell_projectile_plate/README.md: the 20 x 20 (the regression case's mesh) and
    40 x 40 (this deck) rows of docs/studies/seed_scene_orders.md (the same generator and
    deck; make studies; no rerun here, --check reruns the page's coarsest row)."""
    rows = {r[0].split(' (')[0]: r for r in page_rows('docs/studies/seed_scene_orders.md', '')
            if r[0] in ('20 x 20 (h 5 mm)', '40 x 40 (h 2.5 mm)')}
    if len(rows) != 2:
        raise SystemExit('doc_numbers_cases: seed_scene_orders.md lacks the plate rows')
    a, b = rows['20 x 20'], rows['40 x 40']
    return ('| | 20 x 20 (the regression case\'s mesh) | 40 x 40 (this deck) |\n|---|---|---|\n'
            '| peak deflection of the plate centre | %s mm at %s ms | %s mm at %s ms |\n'
            '| projectile rebound speed at 1 ms | %s m/s | %s m/s |\n'
            '| energy ratio, largest departure from 1 | %s | %s |'
            % (a[1], a[3], b[1], b[3], a[4], b[4], a[5], b[5]))


BLOCKS['plate_scene'] = ('decks/shell_projectile_plate/README.md', True, block_plate_scene)
