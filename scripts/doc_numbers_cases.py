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
            out.append([c.strip() for c in line.strip().strip('|').split('|')])
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
