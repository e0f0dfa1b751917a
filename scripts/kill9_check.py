#!/usr/bin/env python3
"""Crash-safe output check (issue 7): kill -9 dynx at random moments and check what it left.

The deck is the Simo Taylor bar (tests/regression/taylor_simo) with frequent output
(plot state every 0.5 us, glstat every 0.1 us, nodout of 3 nodes) and a d3dump every
100 cycles, so kills land inside plot-state, time-history and dump writes. After each kill:
  1. h5dump reads the whole d3plot.h5 (every byte of every dataset) with exit 0, if it exists;
  2. every state the XDMF lists is readable through the XDMF: each HDF5 file its data items
     name (d3plot.h5, or during a run d3plot.states/NNNNNN.h5 and d3plot.states/mesh.h5) is
     read whole by h5dump and holds every dataset named;
  3. glstat and nodout end with a newline and every data line has all its columns as numbers;
  4. no d3dump*.h5 is damaged (a dump is either absent or complete: the .tmp name is the
     only place a half-written one can be); the newest one continues the run with -r and the
     continued run's glstat, nodout and XDMF are byte-identical to the uninterrupted run and
     h5diff finds 0 differences in d3plot.h5 (when a dump exists).

    python3 scripts/kill9_check.py --runs 20 --seed 7              (make test: first 0.02 ms)
    python3 scripts/kill9_check.py --runs 20 --endtim 0.08         (the whole impact)
    python3 scripts/kill9_check.py --runs 10 --deck tests/regression/mpi_shell_mixed/deck.k
        (another deck, e.g. shells: its own end time and histories, a plot state every
        --dplot, a d3dump every 100 cycles)
"""
import argparse, os, random, re, shutil, signal, subprocess, sys, time
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATASETS = ['coordinates', 'displacement', 'velocity', 'stress', 'von_mises', 'pressure',
            'eff_plastic_strain', 'failed']
# the schema's optional rows (dx_plot_fields): listed by the XDMF only when the deck uses them
OPTIONAL = ['damage', 'beam_force', 'beam_moment', 'thickness']


def make_deck(path, endtim):
    src = open(os.path.join(ROOT, 'tests', 'regression', 'taylor_simo', 'deck.k')).read()
    src = re.sub(r'(\*CONTROL_TERMINATION\n\$.*\n)\s*\S+', r'\g<1>%10.5f' % endtim, src)
    src = re.sub(r'\*DATABASE_GLSTAT\n\s*\S+', '*DATABASE_GLSTAT\n  0.000100', src)
    src = re.sub(r'\*DATABASE_BINARY_D3PLOT\n\s*\S+', '*DATABASE_BINARY_D3PLOT\n  0.000500', src)
    extra = ('*DATABASE_NODOUT\n  0.000100\n*DATABASE_HISTORY_NODE\n         1         5      2013\n'
             '*DATABASE_BINARY_D3DUMP\n       100\n')
    src = src.replace('*PART\n', extra + '*PART\n', 1)
    with open(path, 'w') as f:
        f.write(src)


def make_other_deck(src_path, path, dplot):
    """DECK with a plot state every dplot and a d3dump every 100 cycles."""
    src = open(src_path).read()
    src = re.sub(r'\*DATABASE_BINARY_D3PLOT\n\s*\S+', '*DATABASE_BINARY_D3PLOT\n%10.6f' % dplot, src)
    src = src.replace('*PART\n', '*DATABASE_BINARY_D3DUMP\n       100\n*PART\n', 1)
    with open(path, 'w') as f:
        f.write(src)


def h5_groups(path):
    """state groups and their datasets from h5dump -H (header only)."""
    p = subprocess.run(['h5dump', '-H', path], capture_output=True, text=True)
    if p.returncode != 0:
        return None
    groups, cur = {}, None
    for line in p.stdout.splitlines():
        m = re.match(r'\s*GROUP "(\d{6})"', line)
        if m:
            cur = m.group(1)
            groups[cur] = set()
            continue
        m = re.match(r'\s*DATASET "(\w+)"', line)
        if m and cur:
            groups[cur].add(m.group(1))
    return groups


def check_table(path, ncol=None):
    """Whole, numeric lines only; ncol None: as many columns as the last header line names."""
    if not os.path.exists(path):
        return 'missing'
    data = open(path, 'rb').read()
    if data and not data.endswith(b'\n'):
        return 'does not end with a newline (partial line)'
    ncol_header = ncol is None
    seen_row = False
    for i, l in enumerate(data.decode().splitlines()):
        # header lines: '#' lines, and before the first row the names line without '#'
        # (gnuplot's columnhead form); after the rows, only '#' lines are not data
        if l.startswith('#') or (not seen_row and l.lstrip()[:1] not in tuple('+-.0123456789')):
            if ncol_header:
                ncol = len(l.lstrip('#').split())
            continue
        seen_row = True
        f = l.split()
        if len(f) != ncol:
            return 'line %d has %d columns, expected %d' % (i + 1, len(f), ncol)
        try:
            [float(x) for x in f]
        except ValueError:
            return 'line %d is not numeric' % (i + 1)
    return ''


def same(ref, d):
    bad = []
    for f in ('glstat', 'nodout', 'd3plot.xdmf'):
        if open(os.path.join(ref, f), 'rb').read() != open(os.path.join(d, f), 'rb').read():
            bad.append(f)
    if subprocess.run(['h5diff', '-q', os.path.join(ref, 'd3plot.h5'),
                       os.path.join(d, 'd3plot.h5')]).returncode != 0:
        bad.append('d3plot.h5')
    elif open(os.path.join(ref, 'd3plot.h5'), 'rb').read() != \
            open(os.path.join(d, 'd3plot.h5'), 'rb').read():
        bad.append('d3plot.h5 (not byte-equal)')
    return bad


def h5_paths(path):
    """Full paths of the datasets of an HDF5 file (h5dump -H), or None if h5dump fails."""
    p = subprocess.run(['h5dump', '-H', path], capture_output=True, text=True)
    if p.returncode != 0:
        return None
    stack, out = [], set()
    for line in p.stdout.splitlines():
        t = line.strip()
        m = re.match(r'(GROUP|DATASET|ATTRIBUTE|HDF5|DATATYPE|DATASPACE)\s+"?([^"]*)"?\s*\{$', t)
        if m:
            stack.append((m.group(1), m.group(2)))
            if m.group(1) == 'DATASET':
                names = [n for k, n in stack if k in ('GROUP', 'DATASET') and n != '/']
                out.add('/' + '/'.join(names))
            continue
        if t == '}' and stack:
            stack.pop()
    return out


def check_killed(d, deck, ref, dynx, stats):
    """What a killed run left in d: the problems found, the XDMF states checked and a note
    on the continue (also used by kill9_sweep.py). The states are read through what the
    XDMF lists: every HDF5 file a listed state names (d3plot.h5, or during the run the
    per-state files d3plot.states/NNNNNN.h5 and the mesh file) must be read whole by
    h5dump and hold every dataset the XDMF names; a d3plot.h5 that exists must be whole."""
    problems = []
    h5 = os.path.join(d, 'd3plot.h5')
    xmf = os.path.join(d, 'd3plot.xdmf')
    nx = 0
    files = {}                     # file -> dataset paths (None: unreadable)

    def readable(f):
        if f not in files:
            ok = subprocess.run(['h5dump', f], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL).returncode == 0
            files[f] = h5_paths(f) if ok else None
        return files[f]
    if os.path.exists(h5) and readable(h5) is None:
        problems.append('h5dump cannot read d3plot.h5')
    if os.path.exists(xmf):
        try:
            root = ET.parse(xmf).getroot()
        except ET.ParseError as e:
            problems.append('d3plot.xdmf is not valid XML: %s' % e)
            root = None
        if root is not None:
            for g in root.iter('Grid'):
                name = g.get('Name', '')
                if not name.startswith('state'):
                    continue
                nx += 1
                items = [di.text.strip() for di in g.iter('DataItem')]
                nopt = sum(1 for it in items if it.rsplit('/', 1)[-1] in OPTIONAL)
                if len(items) - nopt != len(DATASETS) + 4:
                    problems.append('XDMF %s names %d data items' % (name, len(items)))
                for it in items:
                    fname, dset = it.split(':', 1)
                    f = os.path.join(d, fname)
                    if not os.path.exists(f):
                        problems.append('XDMF %s names %s, which is missing' % (name, fname))
                        continue
                    paths = readable(f)
                    if paths is None:
                        problems.append('XDMF %s names %s, which h5dump cannot read' %
                                        (name, fname))
                    elif dset not in paths:
                        problems.append('XDMF %s names %s, not in %s' % (name, dset, fname))
    stats['states'] += nx
    for f, n in (('glstat', None), ('nodout', None)):
        if os.path.exists(os.path.join(d, f)):
            msg = check_table(os.path.join(d, f), n)
            if msg:
                problems.append('%s: %s' % (f, msg))
    dumps = sorted(x for x in os.listdir(d) if re.fullmatch(r'd3dump\d+\.h5', x)) if os.path.isdir(d) else []
    cont = ''
    if dumps:
        last = os.path.join(d, dumps[-1])
        p = subprocess.run([dynx, '-i', deck, '-o', d, '-r', last], capture_output=True,
                           text=True)
        if p.returncode != 0:
            problems.append('continue from %s: exit %d: %s' % (dumps[-1], p.returncode,
                                                                 p.stderr.strip()[:300]))
        else:
            bad = same(ref, d)
            if bad:
                problems.append('continued run differs from the reference: %s' % ', '.join(bad))
            else:
                stats['continued'] += 1
                cont = ', continued from %s: identical' % dumps[-1]
    return problems, nx, cont


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--runs', type=int, default=20)
    ap.add_argument('--seed', type=int, default=None)
    ap.add_argument('--dynx', default=os.path.join(ROOT, 'bin', 'dynx'))
    ap.add_argument('--workdir', default=os.path.join(ROOT, 'build', 'kill9'))
    ap.add_argument('--endtim', type=float, default=0.02,
                    help='end time of the Taylor bar (0.08: the whole impact; make test: 0.02)')
    ap.add_argument('--deck', default='',
                    help='another deck instead of the Taylor bar (its own end time)')
    ap.add_argument('--dplot', type=float, default=0.05,
                    help='with --deck: the plot interval')
    args = ap.parse_args()
    seed = args.seed if args.seed is not None else random.randrange(1 << 30)
    rng = random.Random(seed)
    w = args.workdir
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(w)
    deck = os.path.join(w, 'deck.k')
    if args.deck:
        make_other_deck(args.deck, deck, args.dplot)
    else:
        make_deck(deck, args.endtim)
    ref = os.path.join(w, 'ref')
    t0 = time.time()
    p = subprocess.run([args.dynx, '-i', deck, '-o', ref], capture_output=True)
    tref = time.time() - t0
    if p.returncode != 0:
        print('kill9_check: reference run failed (exit %d)' % p.returncode)
        return 1
    nfail = 0
    stats = {'states': 0, 'continued': 0}
    for k in range(args.runs):
        d = os.path.join(w, 'run%02d' % k)
        delay = rng.uniform(0.02, 0.95) * tref
        proc = subprocess.Popen([args.dynx, '-i', deck, '-o', d], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        time.sleep(delay)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        problems, nx, cont = check_killed(d, deck, ref, args.dynx, stats)
        status = 'FAIL' if problems else 'ok'
        print('  run %2d: kill -9 after %.3f s: %d XDMF states readable%s %s' % (
            k, delay, nx, cont, status))
        for pr in problems:
            print('      ' + pr)
        if problems:
            nfail += 1
        else:
            shutil.rmtree(d, ignore_errors=True)
    print('kill9_check: %d runs (seed %d), %d XDMF-listed states checked, %d continued '
          'bitwise from the last d3dump, %d failed' % (args.runs, seed, stats['states'],
                                                      stats['continued'], nfail))
    return 1 if nfail else 0


if __name__ == '__main__':
    sys.exit(main())
