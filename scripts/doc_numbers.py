#!/usr/bin/env python3
"""Numbers in the documents that a script writes, and the test that they still hold (issue 23).

  doc_numbers.py --update [BLOCK ...]   rerun the decks of the blocks, rewrite the blocks
  doc_numbers.py --check                rerun the cheap blocks and the cheap rows of the study
                                        tables, compare with the documents (make test)

A generated block in a markdown file sits between the lines
    <!-- doc_numbers.py BLOCK: generated, do not edit -->
    <!-- end BLOCK -->
and is written only by this script. --check compares every number of a regenerated block or
table row with the documented one: they agree when they differ by at most one unit in the
last printed digit of the documented number (serial dynx runs are bitwise reproducible on one
build; one unit allows a rounding flip from another compiler's last-bit difference). Wall
times are not compared. The text around the numbers must be identical.

Checked study rows (each under a few seconds): docs/studies/scene_orders.md (rod_impact
nx = 25 and 50, emc_bars dt = 8e-3 and 4e-3 s, sliding_block refine 1),
docs/studies/seed_scene_orders.md (the coarsest level of each seed scene), docs/studies/README.md
(the elastic wave nx = 25, 50, 100 rows; the Taylor (2,2,16) row) and docs/studies/hertz.md
against its stored table docs/studies/data/hertz.dat (no rerun: the runs take minutes).
Prints 'N passed, M failed' (scripts/test_suites.sh). Standard library only; run with
/usr/bin/python3.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'scripts'))
DYNX = os.path.join(ROOT, 'bin', 'dynx')
PY = '/usr/bin/python3'
NUM = re.compile(r'[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?')


def sh(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       cwd=ROOT)
    return p.returncode, p.stdout


def run_deck(deck, work, name):
    od = os.path.join(work, name)
    rc, log = sh([DYNX, '-i', deck, '-o', od])
    if rc != 0:
        raise SystemExit('doc_numbers: %s: exit %d\n%s' % (deck, rc, log[-1500:]))
    return od, log


def drift(log):
    m = re.search(r'drift over the run: energy (\S+), linear momentum (\S+), angular momentum '
                  r'(\S+)', log)
    return tuple(float(x.rstrip(',')) for x in m.groups())


# ---------------------------------------------------------------------------------------------
# blocks: name -> (file, cheap (rerun by --check), generator(work) -> markdown text)
def block_emc_bars(work):
    od, log = run_deck(os.path.join(ROOT, 'decks/emc_bars/deck.k'), work, 'bars_penalty')
    _, out = sh([PY, 'scripts/emc_bars_check.py', od, '--vtol', '1e-10'])
    m = re.search(r'final velocities (\S+) (\S+), max penetration (\S+) \(analytic (\S+), rel. '
                  r'diff (\S+)\)', out)
    v1, v2, pen, pan, rel = (float(x) for x in m.groups())
    e, p, _ = drift(log)
    odl, logl = run_deck(os.path.join(ROOT, 'decks/emc_bars/deck_lagrange.k'), work,
                         'bars_lagrange')
    _, outl = sh([PY, 'scripts/emc_bars_check.py', odl, '--lagrange', '--vtol', '1e-10'])
    ml = re.search(r'final velocities (\S+) (\S+),', outl)
    gmin = float(re.search(r'smallest gap (\S+)', outl).group(1))
    el, pl, _ = drift(logl)
    return ('Measured (`scripts/doc_numbers.py`, checked by `make test`): penalty (`deck.k`): '
            'largest penetration %.7f m against the analytic v0 sqrt(M/(2 N EPS)) = %.7f m '
            '(%.1e relative: the largest of the sampled steps), velocities after the impact '
            '%.3g and %.13f m/s (exchanged), largest drift over the run: energy %.1e, linear '
            'momentum %.1e (regression `emc_bars_penalty`). Lagrange multipliers (FORM 2, '
            '`deck_lagrange.k`; implemented, regression `emc_bars_lagrange`): smallest gap '
            '%.1e m over the run (no penetration: the gap closes to zero and stays there '
            'during the contact step), velocities %.3g and %.13f m/s, drift: energy %.1e, '
            'linear momentum %.1e. The displacement error against dt and its observed order: '
            '`docs/studies/scene_orders.md`.'
            % (pen, pan, rel, v1, v2, e, p, gmin, float(ml.group(1)), float(ml.group(2)),
               el, pl))


def block_emc_ball_shell(work):
    od, log = run_deck(os.path.join(ROOT, 'decks/emc_ball_shell/deck.k'), work, 'shell')
    e, p, l = drift(log)
    _, out = sh([PY, 'scripts/emc_check.py', od, '--etol', '1e-12', '--ptol', '1e-12',
                 '--ltol', '1e-12'])
    lx = float(re.search(r'body 1 Lx range (\S+)', out).group(1))
    odf, logf = run_deck(os.path.join(ROOT, 'decks/emc_ball_shell/deck_faceted.k'), work,
                         'shell_faceted')
    ef, pf, lf = drift(logf)
    rows = []
    for d in (od, odf):
        with open(os.path.join(d, 'emcstat')) as f:
            rows.append([l_.split() for l_ in f
                         if l_.strip() and l_.lstrip()[:1] in tuple('+-.0123456789')][-1])
    dist = math.sqrt(sum((float(rows[0][14 + i]) - float(rows[1][14 + i])) ** 2
                         for i in range(3)))
    return ('Measured (`scripts/doc_numbers.py`): smoothed (`deck.k`), largest drift over the '
            'run of energy, linear and angular momentum %.1e, %.1e, %.1e (every step; '
            'regression `emc_ball_shell` asserts 1e-13), the ball\'s Lx changes by %.3f; '
            'faceted (`deck_faceted.k`): %.1e, %.1e, %.1e, and the ball\'s centre after 4 s is '
            '%.3f m from the smoothed run\'s (regression `emc_ball_shell_faceted`).'
            % (e, p, l, lx, ef, pf, lf, dist))


def block_stiff_penalty(work):
    """Two elastic rods (gen_contact_decks.py rod --nx 50) at SFS 1e3, 1e4, 1e5, without and
    with contact damping VDC = 20 %: the largest contact force over the physical rho c v A/2,
    its mean over the plateau, the contact duration against 2L/c, the energy ratio band."""
    from contact_post import table
    c = math.sqrt(210.0 / 7.85e-6)
    fphys = 7.85e-6 * c * 10.0 / 2.0
    t2 = 200.0 / c
    lines = ['| SFS | VDC [%] | cycles | largest force / rho c v A/2 | plateau mean / rho c v A/2 '
             '| duration / (2L/c) - 1 | energy ratio band |', '|---|---|---|---|---|---|---|']
    for sfs in ('1e3', '1e4', '1e5'):
        for vdc in ('0', '20'):
            deck = os.path.join(work, 'rod_%s_%s.k' % (sfs, vdc))
            sh([PY, 'scripts/gen_contact_decks.py', 'rod', '--nx', '50', '--sfs', sfs,
                '--vdc', vdc, deck])
            od, log = run_deck(deck, work, 'rod_%s_%s' % (sfs, vdc))
            cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
            names, rows = table(os.path.join(od, 'rcforc'))
            fx, na = names.index('slave_x'), names.index('nactive')
            on = [r for r in rows if r[na] > 0]
            fmax = max(abs(r[fx]) for r in on)
            win = [abs(r[fx]) for r in rows if on[0][0] + 0.1 * t2 <= r[0] <= on[0][0] + 0.9 * t2]
            gn, g = table(os.path.join(od, 'glstat'))
            er = [r[gn.index('energy_ratio')] for r in g]
            lines.append('| %s | %s | %d | %.1f | %.3f | %+.3f | %.6f .. %.6f |' % (
                sfs, vdc, cyc, fmax / fphys, sum(win) / len(win) / fphys,
                (on[-1][0] - on[0][0]) / t2 - 1, min(er), max(er)))
    return '\n'.join(lines)


def block_taylor_bar(work):
    """decks/taylor_bar: both decks, final length, footprint, energy ratio (dxpost.py)."""
    lines = ['| deck | final length [mm] | footprint radius [mm] | reference | energy ratio '
             '(final; min-max) | cycles |', '|---|---|---|---|---|---|']
    for deck, l0, r0, ref in (
            ('deck.k', '32.4', '3.2', 'converged 21.45 / 7.225 mm (Foulk et al. 2021: '
             '21.42-21.48 / 7.22-7.23); Simo 7.12, Zienkiewicz 7.11 mm'),
            ('wilkins_guinan.k', '23.47', '3.81', 'experiment 14.79 mm (Lf/L0 0.630) / '
             '8.40 mm (Rf/R0 2.204)')):
        od, log = run_deck(os.path.join(ROOT, 'decks/taylor_bar', deck), work, deck[:-2])
        _, out = sh([PY, 'scripts/dxpost.py', 'taylor', od, '--L0', l0, '--R0', r0])
        lf = float(re.search(r'final length\s+(\S+)', out).group(1))
        rf = float(re.search(r'footprint radius\s+(\S+)', out).group(1))
        _, e = sh([PY, 'scripts/dxpost.py', 'energy', od])
        lo = float(re.search(r'min\s+(\S+)', e).group(1))
        hi = float(re.search(r'max\s+(\S+)', e).group(1))
        fin = float(re.search(r'final\s+(\S+)', e).group(1))
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        lines.append('| `%s` | %.3f (Lf/L0 %.4f) | %.3f (Rf/R0 %.4f) | %s | %.5f; %.5f-%.5f | %d |'
                     % (deck, lf, lf / float(l0), rf, rf / float(r0), ref, fin, lo, hi, cyc))
    return '\n'.join(lines)


def post_values(out):
    """(name, value, reference) of each line of a contact_post.py report."""
    vals = {}
    for m in re.finditer(r'^(.*?\S)\s+(\S+)\s+reference\s+(\S+)', out, re.M):
        vals[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return vals


def block_rod_impact(work):
    od, log = run_deck(os.path.join(ROOT, 'decks/rod_impact/deck.k'), work, 'rod')
    _, out = sh([PY, 'scripts/contact_post.py', 'rod', od, '--nx', '100'])
    v = post_values(out)
    dur, t2 = v['contact duration [ms] vs 2L/c']
    fp, fr = v['force plateau (median) [kN] vs rho c v A/2']
    vs = v['striker velocity after release [m/s]'][0]
    vt = v['target velocity after release [m/s]'][0]
    m = re.search(r'energy ratio min (\S+) max (\S+)', out)
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    dt = float(re.search(r'normal termination at cycle \d+, time (\S+),', log).group(1)) / cyc
    return '\n'.join([
        '| quantity | dynx | theory | error |', '|---|---|---|---|',
        '| contact duration (first to last rcforc output with a node in contact) | %.7f ms | '
        '2L/c = %.7f ms | %+.2f %% (%.1f mean time steps) |'
        % (dur, t2, 100 * (dur / t2 - 1), (dur - t2) / dt),
        '| contact force plateau (median) | %.6f kN | rho c v0 A/2 = %.6f kN | %+.2f %% |'
        % (fp, fr, 100 * (fp / fr - 1)),
        '| striker velocity after release (lumped-mass mean) | %.4f m/s | 0 | %.2f %% of v0 |'
        % (vs, 100 * vs / 10.0),
        '| target velocity after release | %.4f m/s | 10 m/s | %+.2f %% |' % (vt, 100 * (vt / 10 - 1)),
        '| energy ratio over the run (glstat, sliding energy included) | %s .. %s | 1 | |'
        % (m.group(1), m.group(2))])


def block_sliding_block(work):
    od, log = run_deck(os.path.join(ROOT, 'decks/sliding_block/deck.k'), work, 'slide')
    _, out = sh([PY, 'scripts/contact_post.py', 'slide', od, '--m', repr(8 * 7.85e-6)])
    v = post_values(out)
    deck0 = os.path.join(work, 'slide0.k')
    sh([PY, 'scripts/gen_contact_decks.py', 'slide', '--fs', '0', deck0])
    od0, log0 = run_deck(deck0, work, 'slide0')
    _, out0 = sh([PY, 'scripts/contact_post.py', 'slide', od0, '--mu', '0', '--F', '0.02',
                  '--v', '20', '--tend', '0.2'])
    v0 = post_values(out0)
    er = [float(re.search(r'normal termination at .*energy ratio\s+(\S+)', l).group(1)) for l in (log, log0)]
    a, aref = v['deceleration [m/s/ms] vs mu F/m']
    r = v['median |f_t|/f_n vs mu'][0]
    fn = v['mean normal force [kN] vs load F'][0]
    return '\n'.join([
        '| quantity | dynx | reference | error |', '|---|---|---|---|',
        '| deceleration of the block (slope of vx, block centre node) | %.3f m/s per ms | '
        'mu F/m = %.3f | %+.2f %% |' % (a, aref, 100 * (a / aref - 1)),
        '| median tangential / normal contact force | %.6f | mu = 0.2 | %+.3f %% |'
        % (r, 100 * (r / 0.2 - 1)),
        '| mean normal contact force | %.7f kN | F = 0.02 kN | %+.3f %% |' % (fn, 100 * (fn / 0.02 - 1)),
        '| frictionless: change of vx over 0.2 ms (4 mm, 5 plate segment edges crossed) | '
        '%.2e m/s | 0 | |' % v0['velocity change [m/s] (frictionless)'][0],
        '| frictionless: largest tangential force | %.1e F | 0 | |'
        % v0['largest |f_t| / F (frictionless)'][0],
        '| frictionless: largest normal force after settling | %.2f F | F | no spikes at the '
        'edges |' % v0['largest f_n / F after settling (no spikes)'][0],
        '| energy ratio at the end (friction / frictionless) | %.6f / %.6f | 1 | |' % tuple(er)])


def block_idle_contact(work):
    """What a deck pays for a contact that never acts (issue 23, "a deck pays only for what it
    uses"): two steel rods at rest (gen_contact_decks.py rod --nx 400 --v 0) with their
    *CONTACT_SURFACE_TO_SURFACE, the same with the target 50 mm away, and the same without
    the contact keyword. CPU seconds (user, children) median of 3, cycles, bucket sorts."""
    import resource
    base = os.path.join(work, 'idle_contact.k')
    sh([PY, 'scripts/gen_contact_decks.py', 'rod', '--nx', '400', '--v', '0', base])
    lines = open(base).read().split('\n')
    far, nocon, innode, skip = [], [], False, False
    nper = 4 * 401
    for l in lines:
        if l.startswith('*'):
            innode = l.startswith('*NODE')
            skip = l.startswith('*CONTACT_')
        elif innode and l.strip() and not l.startswith('$') and int(l[:8]) > nper:
            far.append(l[:8] + '%16.8f' % (float(l[8:24]) + 50.0) + l[24:])
            if not skip:
                nocon.append(l)
            continue
        far.append(l)
        if not skip:
            nocon.append(l)
    decks = [('rods at rest 0.01 mm apart, with *CONTACT', base)]
    for name, ls in (('rods 50 mm apart, with *CONTACT', far), ('no *CONTACT', nocon)):
        path = os.path.join(work, 'idle_%d.k' % len(decks))
        with open(path, 'w') as f:
            f.write('\n'.join(ls))
        decks.append((name, path))
    out = ['| deck (800 hexes, 2 rods, v = 0) | cycles | CPU [s] (median of 3) | CPU per cycle '
           '[us] | bucket sorts |', '|---|---|---|---|---|']
    for name, path in decks:
        cpu = []
        for k in range(3):
            t0 = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
            od, log = run_deck(path, work, 'idle_run')
            cpu.append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - t0)
        c = sorted(cpu)[1]
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        m = re.search(r'(\d+) bucket sorts', log)
        out.append('| %s | %d | %.2f | %.0f | %s |' % (name, cyc, c, 1e6 * c / cyc,
                                                      m.group(1) if m else '-'))
    return '\n'.join(out)


def block_extreme_incompressible(work):
    """docs/extreme-cases.md section 1: the nearly incompressible block (PR 0.4999) with
    ELFORM 1 and 2, the numbers of the regression cases extreme_incompressible_elform1/2."""
    import dxpost
    cols = []
    for elf in (1, 2):
        deck = os.path.join(work, 'incomp%d.k' % elf)
        sh([PY, 'scripts/gen_extreme_decks.py', 'incompressible', '--elform', str(elf),
            '--tend', '0.5', deck])
        od, log = run_deck(deck, work, 'incomp%d' % elf)
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        names, rows = dxpost.columns(os.path.join(od, 'glstat'))
        k = names.index('energy_ratio')
        a = [r[k] for r in rows if r[0] > 0]
        b = [r[k] for r in rows if r[0] >= 0.05]
        out = {}
        for what, extra in (('finite', []), ('volume', ['--tol', '1']),
                            ('minvol', ['--min', '0']), ('zmax', ['--ref', '5.25', '--tol', '1'])):
            _, out[what] = sh([PY, 'scripts/extreme_check.py', what, od] + extra)
        nonfin = int(re.search(r'(\d+) non-finite values', out['finite']).group(1))
        cols.append(['0, %d' % cyc, '%.4f - %.4f' % (min(a), max(a)),
                     '%.4f - %.4f' % (min(b), max(b)),
                     '%.5f' % float(re.search(r'total volume / initial\s+(\S+)',
                                              out['volume']).group(1)),
                     '%.5f' % float(re.search(r'initial (\S+)', out['minvol']).group(1)),
                     '%.4f' % float(re.search(r'last state\s+(\S+)', out['zmax']).group(1)),
                     'none' if nonfin == 0 else '%d' % nonfin])
        ngl = len(a)
    labels = ['exit, cycles', 'energy ratio, t > 0 (%d glstat rows)' % ngl,
              'energy ratio after the ramp (t >= 0.05 ms)', 'total volume, last state / initial',
              'smallest element volume ratio', 'top face z at the end (prescribed 5.25)',
              'non-finite values']
    return '\n'.join(['| measured | ELFORM 1 | ELFORM 2 |', '|---|---|---|'] +
                     ['| %s | %s | %s |' % (l, c1, c2)
                      for l, c1, c2 in zip(labels, cols[0], cols[1])])


def block_pressure_table(work):
    """decks/pressure_table/README.md: cycles, the table's work, the energy left and the
    energy ratio at 60 ns (one 123-cycle 2D run), and the same deck run to 150 ns (about 300
    cycles): the energy balance once the wave has left."""
    import dxpost
    od, log = run_deck(os.path.join(ROOT, 'decks/pressure_table/deck.k'), work, 'ptable')
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    names, rows = dxpost.columns(os.path.join(od, 'glstat'))
    w = [r[names.index('external_work')] for r in rows]
    tot, ratio = rows[-1][names.index('total')], rows[-1][names.index('energy_ratio')]
    s = open(os.path.join(ROOT, 'decks/pressure_table/deck.k')).read()
    s = re.sub(r'(\*CONTROL_TERMINATION\s*\n)\s*\S+', r'\1 1.500e-04', s, count=1)
    d150 = os.path.join(work, 'ptable150')
    os.makedirs(d150, exist_ok=True)
    shutil.copy(os.path.join(ROOT, 'decks/pressure_table/table.dat'), d150)
    with open(os.path.join(d150, 'deck.k'), 'w') as f:
        f.write(s)
    od2, _ = run_deck(os.path.join(d150, 'deck.k'), work, 'ptable150')
    n2, r2 = dxpost.columns(os.path.join(od2, 'glstat'))
    w2 = max(abs(r[n2.index('external_work')]) for r in r2)
    late = max(abs(r[n2.index('total')] - r[n2.index('external_work')]) for r in r2
               if r[0] >= 1.0e-4) / w2
    return ('Measured (`scripts/doc_numbers.py`, checked by `make test`): %d cycles. The energy '
            'put in by the table (external work %.3g J per radian, its largest value) leaves '
            'through the non-reflecting boundaries: %.2g J remain at 60 ns, half still in the '
            'block as the wave crosses the bottom. While the wave crosses the boundary the '
            'energy ratio is %.4f (at 60 ns: %.1g J of %.3g); run on to 150 ns (the wave gone '
            'through the side, the bottom and their corner) the energy balance closes again: '
            '|KE + IE + HG - external work| within %.1e of the largest external work after 100 '
            'ns (the finer and coarser meshes, and the corner instability fixed in '
            'dx_nonreflecting: docs/studies/seed_scene_orders.md, regression case nr2d_corner).'
            % (cyc, max(w), tot, ratio, tot - w[-1], max(w), late))


def block_stiff_first_touch(work):
    """docs/extreme-cases.md: the stiff penalty rods (gen_contact_decks.py rod --nx 50) over
    the first 4 us with rcforc every cycle: the largest contact force in the first 2.5 us of
    contact (the first touch) and after it, against rho c v A/2 (issue 23 item 4: what the
    stiff_penalty table's sampled largest force measures)."""
    import dxpost
    fp = 7.85e-6 * math.sqrt(210.0 / 7.85e-6) * 10.0 / 2.0
    out = ['| SFS | VDC [%] | cycles | largest force in the first 2.5 us of contact / rho c v '
           'A/2 | largest force after it / rho c v A/2 |', '|---|---|---|---|---|']
    for sfs, vdc in (('1e4', 0), ('1e4', 20), ('1e5', 0), ('1e5', 20)):
        deck = os.path.join(work, 'touch_%s_%d.k' % (sfs, vdc))
        sh([PY, 'scripts/gen_contact_decks.py', 'rod', '--nx', '50', '--sfs', sfs, '--vdc',
            str(vdc), deck])
        lines = open(deck).read().split('\n')
        for i, l in enumerate(lines):
            if l.startswith('*CONTROL_TERMINATION'):
                lines[i + 1] = ' 0.004'
            if l.startswith('*DATABASE_RCFORC'):
                lines[i + 1] = ' 1.0e-7'
        with open(deck, 'w') as f:
            f.write('\n'.join(lines))
        od, log = run_deck(deck, work, 'touch')
        cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
        names, rows = dxpost.columns(os.path.join(od, 'rcforc'))
        on = [r for r in rows if r[names.index('nactive')] > 0]
        t0 = on[0][0]
        k = names.index('slave_x')
        early = max(abs(r[k]) for r in on if r[0] <= t0 + 0.0025) / fp
        late = max(abs(r[k]) for r in on if r[0] > t0 + 0.0025) / fp
        out.append('| %s | %d | %d | %.1f | %.2f |' % (sfs, vdc, cyc, early, late))
    return '\n'.join(out)


def block_brittle_impact(work):
    """decks/brittle_impact/README.md: the scene deck's damage fringe, from the n = 16 row of
    docs/studies/seed_scene_orders.md (the same deck, run by make studies; no rerun here:
    --check compares the README with the page, whose coarsest row it reruns)."""
    row = [c for c in table_list('docs/studies/seed_scene_orders.md')
           if c[0].startswith('n = 16 ')][0]
    df, ndam, dev = float(row[3]), int(row[4]), row[5]
    return ('What it shows (docs/damage.md; numbers from the n = 16 row of '
            '[seed_scene_orders.md](../../docs/studies/seed_scene_orders.md), written by '
            '`scripts/doc_numbers.py`, checked by `make test`): a damage fringe under the '
            'contact, cracked elements out to %.3f mm from the axis at 2 us (%d of the 2048 '
            'block elements), the elements under the sphere fully cracked; the energy ratio '
            'stays within %s of 1 (the penalty contact\'s work estimate). The article\'s '
            'computed fracture diameter was 1.62 mm (experiment 1.65 mm); this coarse scene '
            'gives %.2f mm (twice %.3f) with illustrative strengths (1.63 mm while the fracture '
            'triad stayed fixed in space; it now turns with the material): not a validation '
            'either way.' % (df / 2, ndam, dev, df, df / 2))


BLOCKS = {
    # from the seed study page (no run)
    'brittle_impact': ('decks/brittle_impact/README.md', True, block_brittle_impact),
    # four 4 us rod runs (up to 3700 cycles of 100 hexes)
    'stiff_first_touch': ('docs/extreme-cases.md', True, block_stiff_first_touch),
    # one 123-cycle 2D run
    'pressure_table': ('decks/pressure_table/README.md', True, block_pressure_table),
    # two 1250-cycle runs of 64 hexes (regression extreme_incompressible_elform1/2)
    'extreme_incompressible': ('docs/extreme-cases.md', True, block_extreme_incompressible),
    'emc_bars': ('decks/emc_bars/README.md', True, block_emc_bars),
    # the faceted run takes about a minute on the shared machine: written by --update
    # (make studies), not rerun by --check
    'emc_ball_shell': ('decks/emc_ball_shell/README.md', False, block_emc_ball_shell),
    'taylor_bar': ('decks/taylor_bar/README.md', True, block_taylor_bar),
    'rod_impact': ('decks/rod_impact/README.md', True, block_rod_impact),
    'sliding_block': ('decks/sliding_block/README.md', True, block_sliding_block),
    # six rod runs up to 58,000 cycles: written by --update (make studies)
    'stiff_penalty': ('docs/extreme-cases.md', False, block_stiff_penalty),
    # CPU times (not comparable across machines: written by --update only)
    'idle_contact': ('docs/performance.md', False, block_idle_contact),
}
import doc_numbers_cases  # noqa: E402  (docs/extreme-cases.md sections 2-4)
BLOCKS.update(doc_numbers_cases.BLOCKS)
import doc_numbers_laser  # noqa: E402  (decks/laser_backside, decks/laser_subsurface)
BLOCKS.update(doc_numbers_laser.BLOCKS)
import doc_numbers_decks  # noqa: E402  (deck READMEs, round 3b)
BLOCKS.update(doc_numbers_decks.BLOCKS)



def block_re(name):
    return re.compile(r'(<!-- doc_numbers.py %s: generated, do not edit -->\n)(.*?)'
                      r'(<!-- end %s -->)' % (re.escape(name), re.escape(name)), re.S)


def read_block(name):
    path = os.path.join(ROOT, BLOCKS[name][0])
    m = block_re(name).search(open(path).read())
    if not m:
        raise SystemExit('doc_numbers: %s has no block %s' % (path, name))
    return m.group(2).rstrip('\n')


def write_block(name, text):
    path = os.path.join(ROOT, BLOCKS[name][0])
    s = open(path).read()
    s, n = block_re(name).subn(lambda m: m.group(1) + text + '\n' + m.group(3), s)
    if n != 1:
        raise SystemExit('doc_numbers: %s: block %s found %d times' % (path, name, n))
    with open(path, 'w') as f:
        f.write(s)


# ---------------------------------------------------------------------------------------------
def last_unit(tok):
    """One unit in the last printed digit of a number token."""
    mant, _, ex = tok.lower().partition('e')
    dec = len(mant.split('.')[1]) if '.' in mant else 0
    return 10.0 ** (-dec + (int(ex) if ex else 0))


def compare(doc, new, what, skip_cols=()):
    """Numbers of new against doc (strings): same text between the numbers, every number within
    one unit of the documented number's last digit. Returns a list of differences."""
    bad = []
    if NUM.sub('#', doc) != NUM.sub('#', new):
        return ['%s: text differs:\n  doc: %s\n  new: %s' % (what, doc, new)]
    for i, (a, b) in enumerate(zip(NUM.findall(doc), NUM.findall(new))):
        if i in skip_cols:
            continue
        if abs(float(a) - float(b)) > last_unit(a) * (1 + 1e-9):
            bad.append('%s: number %d: documented %s, regenerated %s' % (what, i + 1, a, b))
    return bad


def table_list(path):
    rows = []
    for line in open(os.path.join(ROOT, path)):
        if line.startswith('|') and not line.startswith('|---'):
            rows.append([c.strip() for c in line.strip().strip('|').split('|')])
    return rows


def table_rows(path):
    """The first row of each first-cell key."""
    rows = {}
    for cells in table_list(path):
        rows.setdefault(cells[0], cells)
    return rows


def cells_check(doc_cells, new_cells, what, wall_idx):
    bad = []
    for i, (a, b) in enumerate(zip(doc_cells, new_cells)):
        if i in wall_idx:
            continue
        bad += compare(a, b, '%s, column %d' % (what, i + 1))
    if len(doc_cells) != len(new_cells):
        bad.append('%s: %d columns documented, %d regenerated' % (what, len(doc_cells),
                                                                  len(new_cells)))
    return bad


def check_scene_orders():
    import studies_order as so
    doc = table_rows('docs/studies/scene_orders.md')
    res = []
    for sc in so.SCENES:
        for p in sc['check_runs']:
            r = sc['case'](p)
            what = 'scene_orders.md %s %s' % (sc['name'], r['label'])
            d = doc.get(r['label'])
            if d is None:
                res.append((what, ['row not found']))
                continue
            # the order cell needs the row before it: compared when that row is rerun too
            new = [r['label']] + r['cells']
            res.append((what, cells_check(d[:len(new)], new, what, ())))
    return res


def check_seed_orders(work):
    """seed_scene_orders.md: the cheapest level of each seed scene rerun (about 3 CPU s in
    all); its measured cells (the value and the listed columns; not the error against the
    Richardson value of the finer levels, nor the order or the time) against the page."""
    import studies_order_seed as sos
    sos.WORK = work
    doc = table_rows('docs/studies/seed_scene_orders.md')
    key = {'brittle_impact': ('Da', '%.4f'), 'pressure_table': ('W', '%.5f'),
           'shell_projectile_plate': ('w', '%.4f'), 'shell_box_post': ('v', '%.4f')}
    case = {'brittle_impact': sos.brittle_case, 'pressure_table': sos.ptable_case,
            'shell_projectile_plate': sos.plate_case, 'shell_box_post': sos.post_case}
    res = []
    for sc in sos.SCENES:
        r = case[sc['name']](sc['runs'][0])
        what = 'seed_scene_orders.md %s %s' % (sc['name'], r['label'])
        d = doc.get(r['label'])
        if d is None:
            res.append((what, ['row not found']))
            continue
        k, fmt = key[sc['name']]
        new = [r['label'], fmt % r[k]] + r['more']
        dd = d[:2] + d[3:3 + len(r['more'])]
        res.append((what, cells_check(dd, new, what, ())))
    return res


def check_wave_taylor(work):
    import studies
    doc = table_rows('docs/studies/README.md')
    res = []
    for nx in (25, 50, 100):
        name = 'nx%d_s09' % nx
        deck = os.path.join(work, name + '.k')
        studies.gen('gen_wave_deck.py', ['--nx', str(nx), '--tssfac', '0.9', '--q2', '0.06'], deck)
        r = studies.run_dynx(deck, os.path.join(work, name), os.path.join(work, name + '.log'))
        csv = os.path.join(work, name + '.csv')
        out = studies.post(['wave', os.path.join(work, name), '--csv', csv])
        pl = studies.num(r'plateau stress \[GPa\]\s+([0-9.Ee+-]+)', out)
        plref = studies.num(r'plateau stress \[GPa\]\s+\S+\s+reference\s+([0-9.Ee+-]+)', out)
        xf = studies.num(r'front position \[mm\]\s+([0-9.Ee+-]+|nan)', out)
        xfref = studies.num(r'front position \[mm\]\s+\S+\s+reference\s+([0-9.Ee+-]+)', out)
        h = studies.num(r'\bh\s+([0-9.Ee+-]+)', out)
        new = [str(nx), '0.9', '0.06', '%+.2e' % ((pl - plref) / plref), '%+.4f' % (xf - xfref),
               '%+.3f' % ((xf - xfref) / h)]
        d = [c for c in doc.get(str(nx), [])]
        what = 'studies/README.md wave nx = %d' % nx
        if not d:
            res.append((what, ['row not found']))
            continue
        dd = d[:3] + d[4:7]      # skip the Courant column (its step count is also in the row)
        res.append((what, cells_check(dd, new, what, ())))
    args = ['--L', '32.4', '--R', '3.2', '--v', '227', '--mat', 'j2', '--quarter', '--tend',
            '0.08', '--n', '2', '--m', '2', '--nz', '16', '--elform', '1', '--ihq', '1',
            '--qh', '0.1']
    r = studies.taylor_case(work, 'e1_2216', args, studies.SIMO_L0, studies.SIMO_R0)
    new = ['(2,2,16)', '1', '1 (QH 0.1)', '%.3f' % r['Lf'], '%+.3f' % (r['Lf'] - studies.LREF),
           '%.3f' % r['Rf'], '%+.3f' % (r['Rf'] - studies.RREF), '%.5f' % r['ratio_final']]
    d = doc.get('(2,2,16)')
    what = 'studies/README.md Taylor (2,2,16)'
    res.append((what, cells_check(d[:len(new)], new, what, ()) if d else ['row not found']))
    return res


def check_coverage():
    """docs/studies/README.md lists every scene under decks/ (the list of scripts/studies.py),
    and every regression case named in docs/studies/stability.md's table exists."""
    import studies
    bad = []
    listed = [l.split('|')[1].strip() for l in studies.SCENE_PAGES if l.startswith('| ')
              and not l.startswith('| scene')]
    decks = sorted(d for d in os.listdir(os.path.join(ROOT, 'decks'))
                   if os.path.isdir(os.path.join(ROOT, 'decks', d)))
    if sorted(listed) != decks:
        bad.append('scenes listed %s, decks/ has %s' % (sorted(listed), decks))
    readme = open(os.path.join(ROOT, 'docs/studies/README.md')).read()
    if '\n'.join(studies.SCENE_PAGES) not in readme:
        bad.append('docs/studies/README.md: the scene list differs from scripts/studies.py')
    cases = set(os.listdir(os.path.join(ROOT, 'tests', 'regression')))
    n = 0
    for line in open(os.path.join(ROOT, 'docs/studies/stability.md')):
        if not line.startswith('| ') or line.startswith('| case'):
            continue
        for name in re.findall(r'`([A-Za-z0-9_]+)`', line.split('|')[-2]):
            n += 1
            if name.startswith('_'):
                continue
            if name not in cases and not name.startswith('test_') and \
                    not any(c.startswith(name) for c in cases):
                bad.append('stability.md names %s: no such regression case' % name)
    if n == 0:
        bad.append('stability.md: no test named')
    return [('scene list (decks/) and stability.md tests', bad)]


def check_hertz():
    """hertz.md's table against the stored regenerated table data/hertz.dat."""
    doc = [c for c in table_list('docs/studies/hertz.md') if c[0] != 'SFS']
    dat = [l.split() for l in open(os.path.join(ROOT, 'docs/studies/data/hertz.dat'))
           if not l.startswith('#') and l.strip()]
    bad = []
    if len(doc) != len(dat):
        bad.append('%d rows documented, %d stored' % (len(doc), len(dat)))
    for d, r in zip(sorted(doc, key=lambda c: (c[0], c[1])), sorted(dat, key=lambda c: (c[0], c[1]))):
        new = r[:9] + ['%+.1f %%' % (100 * float(r[9])), '%+.1f %%' % (100 * float(r[10]))]
        bad += cells_check(d[:11], new, 'hertz.md SFS %s n %s' % (r[0], r[1]), (3,))
    return [('hertz.md against data/hertz.dat', bad)]


def main():
    ap = argparse.ArgumentParser()
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument('--update', nargs='*')
    g.add_argument('--check', action='store_true')
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix='dynx_doc_numbers_')
    try:
        if a.update is not None:
            for name in (a.update or BLOCKS):
                write_block(name, BLOCKS[name][2](work))
                print('doc_numbers: wrote block %s in %s' % (name, BLOCKS[name][0]))
            return 0
        results = []
        for name, (path, cheap, fn) in BLOCKS.items():
            if cheap:
                results.append(('block %s (%s)' % (name, path),
                                compare(read_block(name), fn(work), name)))
        results += check_scene_orders()
        results += check_seed_orders(work)
        results += check_wave_taylor(work)
        results += check_hertz()
        results += check_coverage()
        results += doc_numbers_decks.checks(compare)
        nf = 0
        for what, bad in results:
            print('%s %s' % ('FAIL' if bad else 'ok  ', what))
            for b in bad:
                print('    ' + b)
            nf += bool(bad)
        print('%d passed, %d failed' % (len(results) - nf, nf))
        return 1 if nf else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
