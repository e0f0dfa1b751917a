"""Generated blocks of the two laser scenes' READMEs (scripts/doc_numbers.py; issue 23):
decks/laser_backside and decks/laser_subsurface. The mesh sweeps are the rows of
docs/studies/more_scene_orders.md (scripts/studies_order_more.py, make studies): --check reruns
nothing of them and compares the README with the page. The sub-surface rate sweep (M = 8, three
runs of about 8 CPU s) and the back-surface SF 1 sweep (four meshes, about 7 CPU s) rerun the
scene's generator: --update only (make studies). Standard library, plus h5py/numpy through the
scenes' checkers for the reruns."""
import os
import resource

from doc_numbers_cases import DYNX, PY, ROOT, sh

PAGE = 'docs/studies/more_scene_orders.md'


def section_rows(title, prefix):
    """Table rows (cells stripped) of the page's section starting '## title' whose first cell
    starts with prefix, Richardson rows (three levels: prefix three times) left out."""
    sec = open(os.path.join(ROOT, PAGE)).read()
    if '## ' + title not in sec:
        raise SystemExit('doc_numbers_laser: %s has no section "%s"' % (PAGE, title))
    sec = sec[sec.index('## ' + title):]
    end = sec.find('\n## ', 3)
    sec = sec if end < 0 else sec[:end]
    rows = [[c.strip() for c in l.strip().strip('|').split('|')] for l in sec.split('\n')
            if l.startswith('| ' + prefix)]
    rows = [r for r in rows if r[0].count(prefix) == 1]
    if not rows:
        raise SystemExit('doc_numbers_laser: %s, section "%s": no rows' % (PAGE, title))
    return rows


def run_gen(work, name, gen):
    """gen_laser2d_decks.py gen... into work/name, run it: (outdir, CPU s user + system)."""
    d = os.path.join(work, name)
    rc, out = sh([PY, 'scripts/gen_laser2d_decks.py'] + gen[:1] + [d] + gen[1:])
    if rc != 0:
        raise SystemExit('doc_numbers_laser: gen_laser2d_decks.py %s: exit %d\n%s'
                         % (' '.join(gen), rc, out[-1500:]))
    t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    rc, log = sh([DYNX, '-i', os.path.join(d, 'deck.k'), '-o', os.path.join(d, 'out')])
    t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if rc != 0:
        raise SystemExit('doc_numbers_laser: %s: dynx exit %d\n%s' % (name, rc, log[-1500:]))
    return os.path.join(d, 'out'), t1.ru_utime - t0.ru_utime + t1.ru_stime - t0.ru_stime


# page cells: run, diameter, error, depth, damaged quads, angle, ratio, order, CPU
def block_backside_mesh(work):
    """decks/laser_backside/README.md: the h = 10 / 5 / 2.5 / 1.25 um sweep (SF 0.5)."""
    out = ['| h (um) | quads | damage diameter (mm) | damage depth (mm) | damaged quads | '
           'envelope angle (deg) | max \\|ratio - 1\\| after 20 ns | CPU (s, user + system) |',
           '|---|---|---|---|---|---|---|---|']
    for r in section_rows('Back-surface pressure', 'h = '):
        h, quads = r[0].split()[2], r[0].split('(')[1].split()[0]
        out.append('| %s | %s | %s | %s | %s | %s | %s | %s |'
                   % (h, quads, r[1], r[3], r[4], r[5], r[6], r[8]))
    out.append('| seed (DYNA2D) | | 0.170 | unreadable | | fingers at -45 | | |')
    return '\n'.join(out)


def block_backside_sf1(work):
    """The same four meshes at SF 1 (100 kbar): diameters and depths (--update only)."""
    import brittle2d_check
    dia, dep = [], []
    for hum in (10, 5, 2.5, 1.25):
        od, _ = run_gen(work, 'bs_sf1_h%g' % hum, ['backside', '--h', '%g' % (hum * 1e-3),
                                                   '--sf', '1'])
        m = brittle2d_check.measure(od, after=2e-5)
        dia.append('%.4f' % m['outer'])
        dep.append('%.4f' % m['depth'])
    return ('At SF 1 (100 kbar), h = 10 / 5 / 2.5 / 1.25 um: diameters %s mm and depths %s mm.'
            % (' / '.join(dia), ' / '.join(dep)))


# page cells: run, peak, error, at, crack, first surface damage, ratio, order, CPU
def block_subsurface_mesh(work):
    """decks/laser_subsurface/README.md: the M = 6 / 8 / 12 sweep at RATE 2e-6."""
    out = ['| run | quads | peak pressure (GPa) | at (ns) | crack at the surface (ns) | '
           'first surface damage (ns) | max \\|ratio - 1\\| | CPU (s, user + system) |',
           '|---|---|---|---|---|---|---|---|']
    for r in section_rows('Sub-surface particle', 'M = '):
        m, quads = r[0].split()[2], r[0].split('(')[1].split()[0]
        out.append('| M %s, RATE 2e-6%s | %s | %s | %s | %s | %s | %s | %s |'
                   % (m, ' (deck)' if m == '8' else '', quads, r[1], r[3], r[4], r[5], r[6],
                      r[8]))
    out.append('| seed (DYNA2D) | | about 3.6 | 1.8 | 2.9 | 1.0-1.9 | | |')
    return '\n'.join(out)


def block_subsurface_rate(work):
    """The rate sweep on M = 8 (RATE 2e-6 is the page's row; the others rerun: --update
    only)."""
    import subsurface_check

    def ns(t):
        return 'not by 3.5' if t is None else '%.1f' % (t * 1e6)
    page = {r[0].split()[2]: r for r in section_rows('Sub-surface particle', 'M = ')}
    if '8' not in page:
        raise SystemExit('doc_numbers_laser: %s has no M = 8 row' % PAGE)
    out = ['| run | peak pressure (GPa) | at (ns) | crack at the surface (ns) | first surface '
           'damage (ns) | max \\|ratio - 1\\| | CPU (s, user + system) |',
           '|---|---|---|---|---|---|---|']
    for rate in ('1e-6', '1.5e-6', '2e-6', '4e-6'):
        if rate == '2e-6':
            r = page['8']
            out.append('| M 8, RATE 2e-6 (deck) | %s | %s | %s | %s | %s | %s |'
                       % (r[1], r[3], r[4], r[5], r[6], r[8]))
            continue
        od, cpu = run_gen(work, 'ss_rate%s' % rate, ['subsurface', '--m', '8', '--rate', rate])
        m = subsurface_check.measure(od)
        out.append('| M 8, RATE %s | %.3f | %.1f | %s | %s | %.1e | %.3g |'
                   % (rate, m['peak'], m['tpeak'] * 1e6, ns(m['t_crack']), ns(m['t_spall']),
                      m['ratio_dev'], cpu))
    return '\n'.join(out)


# name -> (file, cheap, generator), merged into doc_numbers.BLOCKS
BLOCKS = {
    'laser_backside_mesh': ('decks/laser_backside/README.md', True, block_backside_mesh),
    'laser_backside_sf1': ('decks/laser_backside/README.md', False, block_backside_sf1),
    'laser_subsurface_mesh': ('decks/laser_subsurface/README.md', True, block_subsurface_mesh),
    'laser_subsurface_rate': ('decks/laser_subsurface/README.md', False, block_subsurface_rate),
}
