#!/usr/bin/python3
"""Run the public LS-DYNA deck corpus (tests/public/) through bin/dynx and classify each deck.

    make public-decks                 (or: /usr/bin/python3 scripts/public_decks.py [options])

For every deck listed in tests/public/index.tsv (path, source, licence, writer, what it models,
expected outcome class):

1. `bin/dynx --check -i DECK`: the strict read, exactly what a new user gets.
2. `bin/dynx --check --ignore-unknown -i DECK`: the read with unknown keywords skipped; it tells
   what stops the deck once the unknown keywords are dealt with, and its warnings list unknown
   keywords past the first.
3. The deck's keyword lines (with its *INCLUDE files) are scanned against the keywords dynx
   documents (docs/keywords.md headings and the registry's add('NAME') calls): the tally of
   unknown keywords over the corpus (keyword -> number of decks) comes from this scan joined with
   what dynx itself reported, so it does not depend on dynx stopping at the first unknown keyword.
4. When the strict check passes: a real run, capped with dynx's own `--walltime S` option (dynx
   stops with a restart dump and exit 5 at the cap, so a long deck is a capped run, not a hang);
   an outer timeout of S + 60 s catches a real hang.

Classes (the issue-16 acceptance classes):
- runs   exit 0 (normal termination) or 5 at the wall-time cap, and the physics check passes;
- exit-2 exit 2 with a message that names the unsupported keyword/option, or the deck's own defect
         (a missing include file, an undefined id, a value overflowing its field);
- wrong  a crash (any other exit code or a signal), a hang (outer timeout), exit 2 whose message
         does not name a missing feature (a symptom), exit 2 on a construct LS-DYNA reads (a
         "missing card" for a blank card of defaults, an "unexpected card" for an optional card,
         an include file LS-DYNA finds on its include path), exit 3 (numerical failure)
         on a deck LS-DYNA runs, or exit 0 with a failed physics check (nonsense energies).

Physics check of a deck that runs (tolerances and where they come from):
- glstat (when the deck asks for it): every value finite; the energy ratio (total / (initial +
  external work)) within 1 +- 0.10 on every line once the total energy is non-zero, the usual
  LS-DYNA acceptance band for an energy balance (the band dynx's energy guard warns at, issue 15),
  lines inside a loading transient skipped as the guard skips them, the last line always judged;
  hourglass energy at most 10 % of internal energy at the end (the common LS-DYNA guideline).
  A deck that loads the model (initial velocity, loads, prescribed motion) must show a non-zero
  total energy (a loaded model with zero energy throughout is the silent failure of issue 16).
- An unloaded deck (no initial velocity, load or prescribed motion): analytic answer zero
  motion, so kinetic energy (glstat) and displacement (d3plot.h5) must stay exactly 0.
- No glstat: displacements in d3plot.h5 finite.

Output: a table on stdout and the generated docs/public-decks.md (date, commit, table, unknown
keyword tally, trend over runs). Not part of `make test`; the total run takes a few minutes at
most (each real run is capped; past --budget seconds decks are only checked).

`--self-test` runs the classifier against stub dynx programs (a crash, a hang, an exit 2 that
names a symptom, a blow-up, a loaded model with zero energy, an unloaded model that moves...)
and fails if any verdict is not the expected one; `make public-decks` runs it first.
"""
import argparse
import datetime
import math
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, 'tests', 'public')
INDEX = os.path.join(CORPUS, 'index.tsv')
DOC = os.path.join(ROOT, 'docs', 'public-decks.md')
TREND_BEGIN = '<!-- trend-begin -->'
TREND_END = '<!-- trend-end -->'
LOAD_PREFIXES = ('INITIAL_VELOCITY', 'LOAD_', 'BOUNDARY_PRESCRIBED_MOTION')
# an exit-2 message that names what is missing: an unsupported keyword or option, or (in the
# strict read, where every keyword is known) the deck's own defect
NAMING = re.compile(r'unknown keyword|not supported|unsupported|not implemented|cannot open|'
                    r'no such file|not found|does not exist|overflows its|is not defined', re.I)

# messages that mean dynx rejects a construct LS-DYNA reads: an optional card it does not know,
# a blank or absent card LS-DYNA takes as defaults (the reader defects of issue 16); the corpus
# decks are LS-DYNA input as published, so these count as wrong, not as naming a missing feature
READER_DEFECT = re.compile(r'missing card|unexpected card', re.I)


def sh(cmd, cwd=None):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True).stdout.strip()


def read_index():
    rows = []
    with open(INDEX) as f:
        header = f.readline().rstrip('\n').split('\t')
        for line in f:
            if not line.strip():
                continue
            rows.append(dict(zip(header, line.rstrip('\n').split('\t'))))
    return rows


def known_keywords():
    """Keyword names dynx documents (docs/keywords.md headings) or registers (src/deck)."""
    names = set()

    def add_cell(text):
        """`*X_A`, `_B` in a heading or a first table cell: *X_A and *X_B."""
        full = re.findall(r'`\*([A-Z0-9_]+)`', text)
        names.update(full)
        for opt in re.findall(r'`(_[A-Z0-9_]+)`', text):
            if full and opt not in ('_TITLE', '_ID'):
                names.add(full[0].rsplit('_', 1)[0] + opt)

    with open(os.path.join(ROOT, 'docs', 'keywords.md')) as f:
        for line in f:
            if line.startswith('#'):
                add_cell(line)
            elif line.startswith('| `*'):      # a table row whose first cell names keywords
                add_cell(line.split('|')[1])
    srcdir = os.path.join(ROOT, 'src', 'deck')
    for fn in os.listdir(srcdir):
        if fn.endswith('.f90'):
            with open(os.path.join(srcdir, fn), errors='replace') as f:
                text = f.read()
            names.update(re.findall(r"add\('([A-Z0-9_]+)'", text))
            if fn == 'dx_deck_cards.f90':   # structure keywords the card reader handles itself
                names.update(re.findall(r"case \('([A-Z_]+)'\)", text))
                names.update(re.findall(r"name [=/]= '([A-Z_]+)'", text))
                # prefix tests (*CASE_BEGIN_n, *CASE_END_n: the scan drops the _n)
                names.update(n.rstrip('_') for n in
                             re.findall(r"index\(name, '([A-Z_]+)'\) == 1", text))
    # material and EOS keywords come from the model registry rows, with their *MAT_nnn aliases
    for fn in ('dx_mat_factory.f90',):
        fp = os.path.join(ROOT, 'src', 'materials', fn)
        if os.path.isfile(fp):
            with open(fp, errors='replace') as f:
                for kind, name, num in re.findall(r"(mat|eos)_row\('([A-Z0-9_]+)',\s*(\d+)",
                                                  f.read()):
                    names.add(name)
                    names.add('%s_%03d' % (kind.upper(), int(num)))
    return names


def is_known(kw, names):
    cands = [kw]
    for suf in ('_TITLE', '_ID'):
        if kw.endswith(suf):
            cands.append(kw[:-len(suf)])
    return any(c in names for c in cands)


def deck_keywords(path, seen=None, paths=None, main_dir=None, found=None):
    """Keyword names of a deck and of its *INCLUDE files, in order; missing includes listed.

    Include files are looked for as LS-DYNA does: beside the including file, in the main
    deck's directory, then in every *INCLUDE_PATH / *INCLUDE_PATH_RELATIVE directory (relative
    paths are relative to the main deck's directory). found maps include names to files."""
    seen = set() if seen is None else seen
    paths = [] if paths is None else paths
    found = {} if found is None else found
    main_dir = os.path.dirname(os.path.abspath(path)) if main_dir is None else main_dir
    kws, missing = [], []
    path = os.path.normpath(path)
    if path in seen:
        return kws, missing
    seen.add(path)
    here = os.path.dirname(path)
    cur = None
    with open(path, errors='replace') as f:
        lines = f.read().splitlines()
    for line in lines:
        if line.startswith('*'):
            cur = line[1:].split()[0].upper() if line[1:].split() else ''
            cur = norm_kw(cur)   # *CASE_BEGIN_n: one keyword
            kws.append(cur)
            continue
        if not line.strip() or line.startswith('$') or cur is None:
            continue
        if cur in ('INCLUDE_PATH', 'INCLUDE_PATH_RELATIVE'):
            p = line.strip()
            paths.append(p if os.path.isabs(p) else os.path.join(main_dir, p))
        elif cur == 'INCLUDE':
            name = line.strip()
            for d in [here, main_dir] + paths:
                cand = os.path.join(d, name)
                if os.path.isfile(cand):
                    found[name] = os.path.normpath(cand)
                    found[os.path.basename(name)] = os.path.normpath(cand)
                    k2, m2 = deck_keywords(cand, seen, paths, main_dir, found)
                    kws += k2
                    missing += m2
                    break
            else:
                missing.append(name)
    return kws, missing


def run(cmd, cwd, timeout):
    """Run cmd in its own process group; on timeout kill the whole group (a hang)."""
    t0 = time.time()
    p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, errors='replace', start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        return p.returncode, out, time.time() - t0
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, 9)
        out, _ = p.communicate()
        return None, out, time.time() - t0


def first_error(out):
    """The message that explains a stop: the first 'error:' line, else a line naming an unknown
    keyword or a failure, else the last line. When that line opens a list (it ends with ':' and
    indented '*KEYWORD ...' lines follow, as the complete --check listing of issue 16 does), the
    listed items are appended, shortened to what precedes 'first at'. Paths are shown relative to
    tests/public/."""
    raw = [l.rstrip() for l in out.splitlines() if l.strip()]
    idx = next((i for i, l in enumerate(raw) if 'error:' in l.lower()), None)
    if idx is None:
        idx = next((i for i, l in enumerate(raw) if re.search(
            r'unknown keyword|not supported|cannot|missing', l, re.I)
            and 'warning' not in l.lower()), None)
    if idx is None:
        idx = len(raw) - 1
    if idx < 0:
        return ''
    pick = re.sub(r'^(dynx: )?error: ', '', raw[idx].strip())
    if pick.endswith(':'):
        items = []
        for l in raw[idx + 1:]:
            if not l.startswith(' '):
                break
            if l.strip().startswith('*'):
                items.append(re.split(r'\s+first at\s', l.strip())[0].strip())
        if items:
            pick += ' ' + '; '.join(items)
    return pick.replace(CORPUS + os.sep, '')


def norm_kw(kw):
    """*CASE_BEGIN_n / *CASE_END_n are one keyword each for the tally."""
    return re.sub(r'^(CASE_(BEGIN|END))_\d+$', r'\1', kw.upper())


def star_names(out):
    return {norm_kw(k) for k in re.findall(r'\*([A-Za-z][A-Za-z0-9_\-]+)', out)}


def reported_unknown(out):
    return {norm_kw(k) for k in re.findall(r'unknown keyword \*([A-Za-z0-9_\-]+)', out)}


def read_glstat(path):
    rows = []
    with open(path) as f:
        for line in f:
            tok = line.split()
            if len(tok) != 14:
                continue
            try:
                rows.append([float(t) for t in tok])
            except ValueError:
                continue
    return rows


def d3plot_states(h5):
    """State group names of a d3plot.h5 (h5ls, from hdf5-tools; no Python HDF5 module needed)."""
    try:
        out = subprocess.run(['h5ls', h5 + '/states'], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, universal_newlines=True).stdout
    except OSError:
        return None
    return sorted(l.split()[0] for l in out.splitlines() if l.split() and
                  l.split()[0].isdigit() and 'Group' in l)


def h5_values(h5, dset):
    """All numbers of one dataset, read with h5dump."""
    try:
        out = subprocess.run(['h5dump', '-y', '-w', '0', '-d', dset, h5], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, universal_newlines=True).stdout
    except OSError:
        return None
    if 'DATA {' not in out:
        return None
    body = out.split('DATA {', 1)[1].split('}', 1)[0]
    try:
        return [float(t) for t in body.replace(',', ' ').split()]
    except ValueError:
        return None


def loaded_from_d3hsp(d):
    """Whether the run of folder d is loaded, from its d3hsp (the deck as read: for a *CASE
    deck the case's own keywords): a load or prescribed motion keyword, or an initial
    velocity whose last definition per (ID, STYP) has a nonzero value (LS-DYNA's last
    definition wins: projectile.k's ZERO_VELOCITY case sets the projectile's velocity to 0).
    None when d has no d3hsp."""
    p = os.path.join(d, 'd3hsp')
    if not os.path.exists(p):
        return None
    blocks, cur = [], None
    for line in open(p, errors='replace'):
        m = re.match(r'^\*([A-Z0-9_]+)\s+\(', line)
        if m:
            cur = [m.group(1), []]
            blocks.append(cur)
            continue
        m = re.match(r'^\s+([A-Z0-9]+)\s+=\s+(\S+)', line)
        if m and cur is not None:
            cur[1].append((m.group(1), m.group(2)))
    last = {}
    for name, fields in blocks:
        if name.startswith(('LOAD_', 'BOUNDARY_PRESCRIBED_MOTION')):
            return True
        if name.startswith('INITIAL_VELOCITY'):
            f = dict(fields[:2])
            key = (name, f.get('ID', f.get('NSID', '')), f.get('STYP', ''))
            vals = []
            for k, v in fields:
                if k in ('VX', 'VY', 'VZ', 'OMEGA', 'VXR', 'VYR', 'VZR'):
                    try:
                        vals.append(float(v))
                    except ValueError:
                        pass
            last[key] = any(v != 0.0 for v in vals)
    return any(last.values())


def physics_check(outdir, loaded):
    """(ok, text) for a deck that ran: every output directory under outdir that holds a glstat
    or a d3plot.h5 is checked (a deck with *CASE may write one directory per case)."""
    dirs = sorted(d for d, _, files in os.walk(outdir) if 'glstat' in files or 'd3plot.h5' in files)
    if not dirs:
        return False, 'no glstat and no d3plot.h5 to check'
    notes = []
    for d in dirs:
        lc = loaded_from_d3hsp(d)
        ok, note = physics_check_dir(d, loaded if lc is None else lc)
        rel = os.path.relpath(d, outdir)
        note = note if rel == '.' else '%s: %s' % (rel, note)
        if not ok:
            return False, note
        notes.append(note)
    return True, ' | '.join(notes)


def physics_check_dir(outdir, loaded):
    """(ok, text) for one output directory."""
    g = os.path.join(outdir, 'glstat')
    notes = []
    if os.path.isfile(g):
        rows = read_glstat(g)
        if not rows:
            return False, 'glstat has no data line'
        if not all(math.isfinite(v) for r in rows for v in r):
            return False, 'glstat holds a non-finite value'
        ke = [r[3] for r in rows]
        ie = [r[4] for r in rows]
        hg = [r[5] for r in rows]
        tot = [r[8] for r in rows]
        ratio = [r[9] for r in rows]
        if not loaded:
            if max(abs(v) for v in ke) != 0.0:
                return False, 'unloaded model moves: max kinetic %.3g (analytic 0)' % max(ke)
            notes.append('unloaded: kinetic energy 0 on %d lines (analytic 0)' % len(rows))
        else:
            if max(abs(v) for v in tot) == 0.0:
                return False, 'loaded model with zero total energy throughout'
            # judged as dynx's energy guard judges (issue 15): a line whose external work moved
            # the denominator (initial total + external work) by more than 1 % since the line
            # before is a loading transient (the work leads the time-centred kinetic energy)
            wext = [r[6] for r in rows]
            live = []
            for i in range(len(rows)):
                den = tot[0] + wext[i]
                if tot[i] == 0.0 or den == 0.0:
                    continue
                if 0 < i < len(rows) - 1 and abs(wext[i] - wext[i - 1]) > 0.01 * abs(den):
                    continue   # the last line is always judged
                live.append(ratio[i])
            worst = max(abs(q - 1.0) for q in live) if live else 0.0
            if worst > 0.10:
                return False, 'energy ratio leaves 1 +- 0.10 (worst %.4f)' % (1 + worst)
            notes.append('energy ratio within 1 +- %.2e on %d of %d lines' % (
                worst, len(live), len(rows)))
            # (an internal energy below 1e-9 of the total is round-off of a rigid motion, as
            # is its hourglass share: projectile.k's LOW_VELOCITY case, IE 1e-29 of KE 7e-2)
            if ie[-1] > 1e-9 * abs(tot[-1]) and hg[-1] > 0.10 * ie[-1]:
                return False, 'hourglass energy %.3g > 10%% of internal %.3g' % (hg[-1], ie[-1])
            notes.append('t=%.4g: KE %.4g IE %.4g HG %.3g' % (rows[-1][0], ke[-1], ie[-1], hg[-1]))
    h5 = os.path.join(outdir, 'd3plot.h5')
    if os.path.isfile(h5):
        states = d3plot_states(h5)
        if states is None:
            notes.append('d3plot not checked (h5ls/h5dump missing or failed)')
        else:
            dmax = 0.0
            for st in states:
                vals = h5_values(h5, '/states/%s/displacement' % st)
                if vals is None or not all(math.isfinite(v) for v in vals):
                    return False, 'non-finite or unreadable displacement in state %s' % st
                dmax = max([dmax] + [abs(v) for v in vals])
            if not loaded and dmax != 0.0:
                return False, 'unloaded model moves: max |u| %.3g (analytic 0)' % dmax
            notes.append('d3plot: %d states, max |u| = %.4g%s' % (
                len(states), dmax, ' (unloaded: analytic 0)' if not loaded else ''))
    if not notes:
        return False, 'no glstat and no d3plot.h5 to check'
    return True, '; '.join(notes)


def classify(deck, names, dynx, outroot, walltime, allow_run, grace=60):
    path = os.path.join(CORPUS, deck['path'])
    cwd = os.path.dirname(path)
    slug = deck['path'].replace('/', '__').rsplit('.', 1)[0]
    out = os.path.join(outroot, slug)
    os.makedirs(out, exist_ok=True)
    found = {}
    kws, missing = deck_keywords(path, found=found)
    scan_unknown = sorted({k for k in kws if k and not is_known(k, names)})
    loaded = any(k.startswith(LOAD_PREFIXES) for k in kws)
    r = dict(deck=deck, scan_unknown=scan_unknown, missing=missing, loaded=loaded)
    rc, txt, dt = run([dynx, '--check', '-i', path, '-o', os.path.join(out, 'check')], cwd, 120)
    r['check_rc'], r['check_msg'] = rc, first_error(txt)
    # issue 16 asks --check to list every unknown keyword at once: how many of the scan's does it?
    r['check_listed'] = len(star_names(txt) & set(scan_unknown))
    rc2, txt2, _ = run([dynx, '--check', '--ignore-unknown', '-i', path,
                        '-o', os.path.join(out, 'scan')], cwd, 120)
    r['scan_rc'], r['scan_msg'] = rc2, first_error(txt2)
    # dynx's own list: 'unknown keyword *X' lines, and any *X of the scan's unknown list that a
    # grouped --check listing names (the form the complete --check list of issue 16 may take)
    named = star_names(txt + txt2) & set(scan_unknown)
    r['dynx_unknown'] = sorted(reported_unknown(txt) | reported_unknown(txt2) | named)
    # unsupported options and reader errors of known keywords: the '*X: ...' items of a grouped
    # --check listing, else the first error of the --ignore-unknown read
    items = set()
    for l in (txt + '\n' + txt2).splitlines():
        item = re.split(r'\s+first at\s', l.strip())[0].strip()
        if item.startswith('*') and ':' in item and 'accepted' not in item:
            items.add(item)
    if not items and rc2 and rc2 != 0 and 'unknown keyword' not in r['scan_msg']:
        items.add(re.sub(r'^\S+?:\d+(:\d+)?: ', '', r['scan_msg']))
    r['option_items'] = sorted({re.sub(r"'[^']*'", "'...'", re.sub(r'\b\d+\b', 'N', i))[:160]
                                for i in items})
    # keywords dynx reads but does not honour (its notes: '*X ... accepted: dynx does not ...')
    r['accepted'] = sorted(set(re.findall(r'\*([A-Z][A-Z0-9_]+)[^\n*]*\baccepted\b', txt + txt2)))
    r['physics'] = ''
    if rc is None:
        r['cls'], r['why'] = 'wrong', 'hang: --check did not finish in 120 s'
        return r
    if rc == 2:
        msg = r['check_msg']
        m = re.search(r"cannot open file '([^']+)'", msg)
        if m and os.path.basename(m.group(1)) in found:
            r['cls'] = 'wrong'
            r['why'] = ('reader defect: %s; LS-DYNA finds it as %s' % (
                msg, os.path.relpath(found[os.path.basename(m.group(1))], CORPUS)))
        elif READER_DEFECT.search(msg):
            r['cls'], r['why'] = 'wrong', 'reader defect (LS-DYNA reads this deck): ' + msg
        elif NAMING.search(msg):
            r['cls'], r['why'] = 'exit-2', msg
        else:
            r['cls'], r['why'] = 'wrong', 'exit 2 without naming a missing feature: ' + msg
        return r
    if rc != 0:
        r['cls'], r['why'] = 'wrong', '--check exit %s: %s' % (rc, r['check_msg'])
        return r
    if not allow_run:
        r['cls'], r['why'] = 'unrun', 'checked; run skipped: the corpus time budget is spent'
        return r
    rdir = os.path.join(out, 'run')
    rc, txt, dt = run([dynx, '-i', path, '-o', rdir, '--walltime', str(walltime)], cwd,
                      walltime + grace)
    r['run_rc'], r['run_s'] = rc, dt
    if rc is None:
        r['cls'], r['why'] = 'wrong', 'hang: no exit %d s after the --walltime cap' % grace
    elif rc in (0, 5):
        ok, note = physics_check(rdir, loaded)
        r['physics'] = note
        how = 'normal termination' if rc == 0 else 'stopped at the %d s wall-time cap' % walltime
        r['cls'] = 'runs' if ok else 'wrong'
        r['why'] = how + ('' if ok else '; physics check failed: ' + note)
    elif rc == 3:
        r['cls'], r['why'] = 'wrong', 'numerical failure (exit 3): ' + first_error(txt)
    else:
        r['cls'], r['why'] = 'wrong', 'run exit %s: %s' % (rc, first_error(txt))
    return r


def matches(r):
    return {'run': 'runs', 'exit2': 'exit-2'}.get(r['deck']['expected']) == r['cls']


def md_escape(s):
    return s.replace('|', '\\|').replace('\n', ' ')


def write_doc(results, tally, commit, date, elapsed, sources):
    counts = {c: sum(1 for r in results if r['cls'] == c) for c in ('runs', 'exit-2', 'wrong')}
    trend = []
    if os.path.isfile(DOC):
        with open(DOC) as f:
            text = f.read()
        if TREND_BEGIN in text and TREND_END in text:
            body = text.split(TREND_BEGIN)[1].split(TREND_END)[0]
            trend = [l for l in body.splitlines() if l.startswith('| 20')]
    m = re.search(r'\(src ([^)]+)\)', commit)
    srcc = m.group(1) if m else commit
    row = '| %s | `%s` | %d | %d | %d | %d |' % (date, srcc, len(results), counts['runs'],
                                                counts['exit-2'], counts['wrong'])
    # one row per (dynx source state, corpus size): reruns on the same sources replace it
    trend = [l for l in trend if not ('`%s`' % srcc in l and '| %d |' % len(results) in l)]
    trend.append(row)
    L = []
    L.append('# Public LS-DYNA deck corpus: results')
    L.append('')
    L.append('Generated by `make public-decks` (`scripts/public_decks.py`); do not edit by hand.')
    L.append('Run of %s at `%s` (%d decks, %.0f s). The decks, their sources and'
             % (date, commit, len(results), elapsed))
    L.append('licences: `tests/public/index.tsv` (each source\'s licence file beside its decks).')
    L.append('')
    L.append('Classes: **runs** = exit 0 or stopped at the `--walltime` cap (exit 5) with the '
             'physics check passed; **exit-2** = stops with exit 2 naming the unsupported keyword or '
             'option (or the deck\'s own defect: a missing include, an undefined id); **wrong** = crash, hang, exit 2 whose '
             'message does not name a missing feature, exit 3, or exit 0 with a failed physics '
             'check. The real run is capped with dynx\'s own `--walltime` (no end-time option '
             'exists); an outer timeout 60 s later catches hangs.')
    L.append('')
    L.append('**Tally: %d runs, %d exit-2, %d wrong** (of %d decks from %d sources).'
             % (counts['runs'], counts['exit-2'], counts['wrong'], len(results), len(sources)))
    exp_run = [r for r in results if r['deck']['expected'] == 'run']
    L.append('Decks whose physics dynx has (expected `run`): %d, running: %d. A class that '
             'differs from the expected one is marked with a `!`.'
             % (len(exp_run), sum(1 for r in exp_run if r['cls'] == 'runs')))
    L.append('')
    complete = sum(1 for r in results if r['scan_unknown'] and
                   r['check_listed'] == len(r['scan_unknown']))
    nunk = sorted(len(r['scan_unknown']) for r in results)
    median = (nunk[(len(nunk) - 1) // 2] + nunk[len(nunk) // 2]) / 2.0 if nunk else 0
    L.append('Distinct unknown keywords per deck: median %g, most %d. Decks with unknown keywords '
             'whose strict `--check` names all of them in one run: %d of %d (column "listed": '
             'named by `--check` / found by the scan).'
             % (median, nunk[-1] if nunk else 0, complete,
                sum(1 for r in results if r['scan_unknown'])))
    L.append('')
    L.append('| deck | writer | expected | class | strict `--check` (first message) | '
             'with `--ignore-unknown` | listed |')
    L.append('|---|---|---|---|---|---|---|')
    for r in results:
        d = r['deck']
        scan = 'exit %s: %s' % (r['scan_rc'], r['scan_msg']) if r['scan_rc'] else 'reads'
        L.append('| `%s` | %s | %s | **%s** | %s | %s | %d / %d |' % (
            d['path'], d['writer'], d['expected'], r['cls'] + ('' if matches(r) else ' !'),
            md_escape(r['why'][:600]),
            md_escape(scan[:160]), r['check_listed'], len(r['scan_unknown'])))
    L.append('')
    phys = [r for r in results if r['physics']]
    if phys:
        L.append('Physics checks of the decks that ran:')
        L.append('')
        for r in phys:
            L.append('- `%s`: %s' % (r['deck']['path'], r['physics']))
        L.append('')
    acc = {}
    for r in results:
        for kw in r.get('accepted', []):
            acc[kw] = acc.get(kw, 0) + 1
    if acc:
        L.append('Read but not honoured (dynx accepts the request with a note, e.g. an output file '
                 'it does not write): ' + ', '.join('`*%s` %d' % (k, n) for k, n in
                                                    sorted(acc.items(), key=lambda kv: (-kv[1], kv[0]))) + '.')
        L.append('')
    blockers = {}
    for r in results:
        for key in r.get('option_items', []):
            key = re.sub(r'^\S+\.k: ', '', key)
            blockers.setdefault(key, []).append(r['deck']['path'].split('/')[-1])
    if blockers:
        L.append('## Unsupported options and reader errors (besides unknown keywords)')
        L.append('')
        L.append('Each `*KEYWORD: message` item of the `--check` listing (numbers replaced by N; '
                 'with a dynx whose `--check` stops at the first error: the first error of '
                 '`--check --ignore-unknown`), with the decks that have it: the unsupported '
                 'options and reader defects to fix after the keywords above.')
        L.append('')
        L.append('| message | decks |')
        L.append('|---|---|')
        for key, decks in sorted(blockers.items(), key=lambda kv: (-len(kv[1]), kv[0])):
            L.append('| %s | %d: %s |' % (md_escape(key), len(decks), ', '.join(decks)))
        L.append('')
    L.append('## Sources')
    L.append('')
    L.append('| directory | repository | licence | decks |')
    L.append('|---|---|---|---|')
    for src in sorted(sources):
        rows = [r['deck'] for r in results if r['deck']['path'].split('/')[0] == src]
        m = re.match(r'(https://github\.com/[^/]+/[^/]+)', rows[0]['source'])
        L.append('| `%s/` | %s | %s | %d |' % (src, m.group(1) if m else rows[0]['source'],
                                               ', '.join(sorted({d['licence'] for d in rows})),
                                               len(rows)))
    L.append('')
    L.append('## Unknown keywords over the corpus')
    L.append('')
    L.append('Keyword -> number of decks that use it (the deck and its includes, scanned against '
             '`docs/keywords.md` and the keyword registry; a keyword dynx itself reported as '
             'unknown is marked *r*). This is the list of what to implement next, most used first.')
    L.append('')
    L.append('| keyword | decks | reported by dynx |')
    L.append('|---|---|---|')
    for kw, (n, rep) in tally:
        L.append('| `*%s` | %d | %s |' % (kw, n, 'r' if rep else ''))
    L.append('')
    fam = {}
    for kw, (n, rep) in tally:
        f = kw.split('_')[0]
        fam.setdefault(f, [0, 0])
        fam[f][0] += 1
    for r in results:
        for f in {k.split('_')[0] for k in set(r['scan_unknown']) | set(r['dynx_unknown'])}:
            fam[f][1] += 1
    L.append('By family (distinct unknown keywords; decks using at least one of them): ' +
             ', '.join('%s %d/%d' % (f, v[0], v[1])
                       for f, v in sorted(fam.items(), key=lambda kv: (-kv[1][1], kv[0]))) + '.')
    L.append('')
    L.append('## Trend')
    L.append('')
    L.append(TREND_BEGIN)
    L.append('| date | dynx src (last commit touching src/) | decks | runs | exit-2 | wrong |')
    L.append('|---|---|---|---|---|---|')
    L.extend(trend)
    L.append(TREND_END)
    L.append('')
    with open(DOC, 'w') as f:
        f.write('\n'.join(L))


STUB = r"""#!/usr/bin/python3
import os, sys, time, signal
mode = os.environ['PUBLIC_DECKS_STUB']
a = sys.argv[1:]
out = a[a.index('-o') + 1]
if '--check' in a:
    if mode == 'unknown':
        print('dynx: error: deck.k:3: unknown keyword *FOO'); sys.exit(2)
    if mode == 'symptom':
        print('dynx: error: deck.k: deck has no elements (no *ELEMENT_SOLID cards)'); sys.exit(2)
    if mode == 'defect':
        print('dynx: error: deck check: 2 unknown keyword(s) in deck.k (first use, count):')
        print('  output:')
        print('    *DATABASE_FOO                 first at deck.k:4')
        print('    *INITIAL_VELOCITY_GENERATION: missing card 2 (XC YC ZC)  first at deck.k:9')
        sys.exit(2)
    sys.exit(0)
if mode == 'crash':
    os.kill(os.getpid(), signal.SIGSEGV)
if mode == 'hang':
    time.sleep(1000)
os.makedirs(out, exist_ok=True)
ratio = {'good': 1.0, 'blowup': 1.5, 'moving': 1.0, 'zero': 0.0}[mode]
ke = 0.0 if mode in ('good', 'zero') else 2.0
tot = 0.0 if mode == 'zero' else 5.0
with open(os.path.join(out, 'glstat'), 'w') as f:
    f.write('# glstat stub\n')
    for i in range(3):
        f.write(' '.join(['%.6e' % (i * 1e-3), str(i)] + ['%.6e' % v for v in
                (1e-4, ke, tot - ke, 0.0, 0.0, 0.0, tot, ratio, 0.0, 0.0, 0.0, 0.0)]) + '\n')
sys.exit(0)
"""


def self_test(names):
    """The classifier against stub dynx programs (crash, hang, symptom, blow-up...): every
    class and every physics-check verdict is exercised; exit 1 if one comes out wrong."""
    import tempfile
    tmp = tempfile.mkdtemp(prefix='public_decks_selftest_')
    stub = os.path.join(tmp, 'dynx')
    with open(stub, 'w') as f:
        f.write(STUB)
    os.chmod(stub, 0o755)
    unloaded = {'path': 'lspp-mcp/impact.k', 'expected': 'run'}
    loaded = {'path': 'pydyna/run/case-keywords/projectile.k', 'expected': 'run'}
    cases = [('unknown', unloaded, 'exit-2'), ('symptom', unloaded, 'wrong'),
             ('defect', unloaded, 'wrong'),
             ('crash', unloaded, 'wrong'), ('hang', unloaded, 'wrong'),
             ('good', unloaded, 'runs'), ('moving', unloaded, 'wrong'),
             ('good', loaded, 'runs'),     # loaded deck, energy 5 conserved (ratio 1)
             ('blowup', loaded, 'wrong'), ('zero', loaded, 'wrong'), ('moving', loaded, 'runs')]
    bad = 0
    for mode, deck, want in cases:
        os.environ['PUBLIC_DECKS_STUB'] = mode
        r = classify(deck, names, stub, os.path.join(tmp, mode), 1, True, grace=2)
        got = r['cls']
        ok = got == want
        bad += not ok
        print('self-test %-8s %-38s want %-6s got %-6s %s' % (
            mode, deck['path'], want, got, 'ok' if ok else 'FAIL: ' + r['why']))
    del os.environ['PUBLIC_DECKS_STUB']
    import shutil
    shutil.rmtree(tmp, ignore_errors=True)
    print('self-test: %d of %d cases as expected' % (len(cases) - bad, len(cases)))
    return 1 if bad else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--dynx', default=os.path.join(ROOT, 'bin', 'dynx'))
    ap.add_argument('--walltime', type=int, default=30, help='cap of each real run (s)')
    ap.add_argument('--budget', type=int, default=540,
                    help='corpus time budget (s): past it, decks are checked but not run')
    ap.add_argument('--out', default=os.path.join(ROOT, 'build', 'public-decks'))
    ap.add_argument('--no-doc', action='store_true', help='do not rewrite docs/public-decks.md')
    ap.add_argument('--self-test', action='store_true',
                    help='check the classifier against stub dynx programs, then exit')
    ap.add_argument('decks', nargs='*', help='only these index paths')
    a = ap.parse_args()
    if a.self_test:
        return self_test(known_keywords())
    if not os.access(a.dynx, os.X_OK):
        print('public_decks: %s not found (make all first)' % a.dynx, file=sys.stderr)
        return 2
    names = known_keywords()
    decks = read_index()
    if a.decks:
        decks = [d for d in decks if d['path'] in a.decks]
    t0 = time.time()
    results = []
    print('%-58s %-7s %-6s  %s' % ('deck', 'expect', 'class', 'reason'))
    for d in decks:
        r = classify(d, names, a.dynx, a.out, a.walltime, time.time() - t0 < a.budget)
        results.append(r)
        print('%-58s %-7s %-7s %s' % (d['path'][-58:], d['expected'],
                                       r['cls'] + ('' if matches(r) else '!'), r['why'][:150]),
              flush=True)
        if r['physics']:
            print('%-58s %-7s %-6s  physics: %s' % ('', '', '', r['physics']), flush=True)
    elapsed = time.time() - t0
    tally = {}
    for r in results:
        for kw in set(r['scan_unknown']) | set(r['dynx_unknown']):
            n, rep = tally.get(kw, (0, False))
            tally[kw] = (n + 1, rep or kw in r['dynx_unknown'])
    tally = sorted(tally.items(), key=lambda kv: (-kv[1][0], kv[0]))
    counts = {c: sum(1 for r in results if r['cls'] == c) for c in ('runs', 'exit-2', 'wrong')}
    unrun = sum(1 for r in results if r['cls'] == 'unrun')
    print('\n%d decks: %d runs, %d exit-2, %d wrong%s (%.0f s)' % (
        len(results), counts['runs'], counts['exit-2'], counts['wrong'],
        ', %d not run (time budget)' % unrun if unrun else '', elapsed))
    print('unknown keywords (decks): ' + ', '.join('*%s %d' % (k, v[0]) for k, v in tally[:25]))
    sources = {d['path'].split('/')[0] for d in decks}
    if not a.no_doc and not a.decks:
        head = sh(['git', 'rev-parse', '--short', 'HEAD'], ROOT)
        srcc = sh(['git', 'log', '-1', '--format=%h', '--', 'src'], ROOT)
        if sh(['git', 'status', '--porcelain', '--untracked-files=no', '--', 'src'], ROOT):
            srcc += '+dirty'
        commit = '%s (src %s)' % (head, srcc)
        date = datetime.datetime.utcnow().strftime('%Y-%m-%d %H:%M UTC')
        write_doc(results, tally, commit, date, elapsed, sources)
        print('wrote %s' % os.path.relpath(DOC, ROOT))
    return 0


if __name__ == '__main__':
    sys.exit(main())
