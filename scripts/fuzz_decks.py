#!/usr/bin/env python3
"""Deck-reader fuzzer (issue 7): mutate the regression decks and run `dynx --check` on each.

Every run must end with exit 0, or exit 2 with a message that names the file and the line
(`path:line`). Anything else is a defect: a signal, a sanitizer or -fcheck report, a Fortran
runtime error or backtrace, exit code 1 or any other, a hang (timeout), or an exit-2 message
without file:line. Defective inputs are kept in build/fuzz/fail-*/ for replay.

The restart decks of the regression cases (restart*.k) are mutated too and checked with
`dynx --check -i <their deck> -R <mutant>`.

Mutations (1 to 3 stacked per input): byte flips, truncation, swapped fields, huge / tiny /
NaN / Inf / malformed numbers, deleted cards and keyword lines, duplicated and swapped
lines, over-long lines, random keywords, *INCLUDE recursion (self-include, deep chains).

Watchdog (issue 15): a mutant that runs longer than --watchdog seconds (default 10) counts
as a hang and fails the campaign, even when it ends by itself before the kill (--timeout).

Restart-file mutants (--restart-share, default 0.1 of the inputs): a restart dump of a short
patch-test run (cycle 10 of 11, --dump-cycle) with flipped bytes, a zeroed block or truncated, continued with
`dynx -i deck -r mutant.h5`: the run must end with exit 0 (the flipped bytes were outside
what is read), or exit 2 / 4 with a message naming the dump; never a crash, a trap or a hang.

    python3 scripts/fuzz_decks.py --count 300 --seed 7 --jobs 2     (make test)
    python3 scripts/fuzz_decks.py --count 10000 --jobs 2            (make fuzz; N=...)
    python3 scripts/fuzz_decks.py --report docs/fuzz-report.md ...  (message classes table)

The binary is bin/dynx-asan (debug + AddressSanitizer + UBSan) when present, else
bin/dynx-debug; override with --dynx. Standard library only.
"""
import argparse, collections, concurrent.futures as cf, os, random, re, resource, shutil, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NUMS = ['1e308', '1e309', '-1e400', '1e-400', '9999999999', '99999999999999999999',
        '2147483647', '2147483648', '-2147483649', 'NaN', 'nan', 'Inf', '-Infinity',
        '0x10', '1.5.5', '+-1', 'd', '1d5', '1e', '.', '-', '+', 'e5', '1e+', '0', '-0',
        '-1', '1.0e30', '-1.0e30', '3.4e38', '1,5', '1 2', '**', '&', '&x', "'"]
KEYWORDS = ['*NODE', '*ELEMENT_SOLID', '*PART', '*SECTION_SOLID', '*MAT_ELASTIC',
            '*MAT_PLASTIC_KINEMATIC', '*MAT_PIECEWISE_LINEAR_PLASTICITY', '*DEFINE_CURVE',
            '*SET_NODE_LIST', '*SET_PART_LIST', '*SET_SEGMENT', '*BOUNDARY_SPC_NODE',
            '*BOUNDARY_SPC_SET', '*BOUNDARY_PRESCRIBED_MOTION_NODE',
            '*BOUNDARY_PRESCRIBED_MOTION_SET', '*LOAD_NODE_POINT', '*LOAD_SEGMENT',
            '*LOAD_SEGMENT_SET', '*RIGIDWALL_PLANAR', '*INITIAL_VELOCITY',
            '*INITIAL_VELOCITY_NODE', '*INITIAL_VELOCITY_GENERATION', '*CONTROL_TERMINATION',
            '*CONTROL_TIMESTEP', '*CONTROL_HOURGLASS', '*CONTROL_BULK_VISCOSITY',
            '*DATABASE_BINARY_D3PLOT', '*DATABASE_GLSTAT', '*DATABASE_NODOUT',
            '*DATABASE_HISTORY_NODE', '*DATABASE_HISTORY_NODE_SET', '*DATABASE_BINARY_D3DUMP',
            '*DATABASE_BINARY_RUNRSF', '*HOURGLASS', '*PARAMETER', '*INCLUDE', '*KEYWORD',
            '*TITLE', '*END', '*PART_TITLE', '*DEFINE_CURVE_TITLE', '*KEYWORD LONG=Y']


def decks():
    """(name, text, base): base is None for a full deck, else the full deck a restart deck
    (restart*.k of a regression case) is checked against with -R."""
    out = []
    reg = os.path.join(ROOT, 'tests', 'regression')
    for c in sorted(os.listdir(reg)):
        p = os.path.join(reg, c, 'deck.k')
        if os.path.isfile(p):
            with open(p, 'rb') as f:
                out.append((c, f.read(), None))
            for r in sorted(os.listdir(os.path.join(reg, c))):
                if r.startswith('restart') and r.endswith('.k'):
                    with open(os.path.join(reg, c, r), 'rb') as f:
                        text = f.read()
                    for _ in range(4):      # restart decks are short: weight them up
                        out.append((c + '/' + r, text, p))
    return out


def data_lines(lines):
    return [i for i, l in enumerate(lines) if l and not l.startswith((b'*', b'$'))]


def mutate(rng, text, files):
    """One mutation of text (bytes); may add extra files (name -> bytes). Returns (text, tag)."""
    lines = text.split(b'\n')
    kind = rng.choice(['flip', 'flip', 'truncate', 'swap_fields', 'number', 'number', 'number',
                       'delete_card', 'delete_keyword', 'duplicate', 'swap_lines', 'long_line',
                       'keyword', 'include_self', 'include_chain', 'negate', 'blank_field',
                       'shift'])
    dl = data_lines(lines)
    if kind == 'flip' and text:
        b = bytearray(text)
        for _ in range(rng.randint(1, 4)):
            b[rng.randrange(len(b))] = rng.choice([0, 9, 10, 13, 32, 36, 42, 43, 44, 45, 46, 38,
                                                    rng.randrange(256)])
        return bytes(b), kind
    if kind == 'truncate' and text:
        return text[:rng.randrange(len(text))], kind
    if kind == 'swap_fields' and dl:
        i = rng.choice(dl)
        l = lines[i]
        f = [l[k:k + 10] for k in range(0, max(len(l), 10), 10)]
        if len(f) >= 2:
            a, b = rng.sample(range(len(f)), 2)
            f[a], f[b] = f[b], f[a]
            lines[i] = b''.join(f)
        return b'\n'.join(lines), kind
    if kind in ('number', 'negate', 'blank_field') and dl:
        i = rng.choice(dl)
        l = lines[i].decode('latin-1')
        toks = list(re.finditer(r'\S+', l))
        if toks:
            t = rng.choice(toks)
            if kind == 'number':
                new = rng.choice(NUMS)
                if rng.random() < 0.5:   # keep the field width (right-aligned in the token span)
                    w = t.end() - t.start()
                    new = new[-w:].rjust(w) if len(new) <= w or rng.random() < 0.5 else new
            elif kind == 'negate':
                new = '-' + t.group(0)
            else:
                new = ' ' * (t.end() - t.start())
            l = l[:t.start()] + new + l[t.end():]
            lines[i] = l.encode('latin-1')
        return b'\n'.join(lines), kind
    if kind == 'delete_card' and dl:
        del lines[rng.choice(dl)]
        return b'\n'.join(lines), kind
    if kind == 'delete_keyword':
        kl = [i for i, l in enumerate(lines) if l.startswith(b'*')]
        if kl:
            del lines[rng.choice(kl)]
        return b'\n'.join(lines), kind
    if kind == 'duplicate' and lines:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        return b'\n'.join(lines), kind
    if kind == 'swap_lines' and len(lines) > 2:
        a, b = rng.sample(range(len(lines)), 2)
        lines[a], lines[b] = lines[b], lines[a]
        return b'\n'.join(lines), kind
    if kind == 'long_line' and lines:
        i = rng.randrange(len(lines))
        lines[i] = lines[i] + b'1' * rng.choice([70, 200, 1000, 100000])
        return b'\n'.join(lines), kind
    if kind == 'keyword' and lines:
        i = rng.randrange(len(lines))
        kw = rng.choice(KEYWORDS).encode()
        cards = [b''.join(rng.choice(NUMS + ['1', '2', '0', '1.0']).rjust(10).encode()
                          for _ in range(rng.randint(0, 8))) for _ in range(rng.randint(0, 3))]
        lines[i:i] = [kw] + cards
        return b'\n'.join(lines), kind
    if kind == 'shift' and dl:
        i = rng.choice(dl)
        lines[i] = b' ' * rng.randint(1, 9) + lines[i]
        return b'\n'.join(lines), kind
    if kind == 'include_self':
        lines.insert(min(1, len(lines)), b'*INCLUDE')
        lines.insert(min(2, len(lines)), b'deck.k')
        return b'\n'.join(lines), kind
    if kind == 'include_chain':
        depth = rng.choice([5, 19, 20, 21, 30, 60])
        for d in range(depth):
            nxt = b'inc%d.k' % (d + 1) if d + 1 < depth else b'missing_or_last.k'
            files['inc%d.k' % d] = b'*KEYWORD\n*INCLUDE\n' + nxt + b'\n*END\n'
        if rng.random() < 0.5:
            files['missing_or_last.k'] = b'*KEYWORD\n*END\n'
        lines.insert(min(1, len(lines)), b'*INCLUDE')
        lines.insert(min(2, len(lines)), b'inc0.k')
        return b'\n'.join(lines), kind
    return text, 'none'


MSG_RE = re.compile(r'[\w./+-]*\.k:\d+')
# a whole-deck condition (no elements, no *CONTROL_TERMINATION) has no line: 'deck.k: ...'
WHOLE_RE = re.compile(r'[\w./+-]*\.k: ')


def classify(rc, err):
    """(ok, outcome, message class, first message line)."""
    # the card echo of an over-long line can be 100k characters: keep every line short so
    # the regular expressions below stay linear
    err = '\n'.join(l[:300] for l in err.splitlines())
    first = ''
    for l in err.splitlines():
        if l.strip():
            first = l.strip()
            break
    bad = ('AddressSanitizer', 'runtime error', 'Fortran runtime error', 'Backtrace',
           'Error termination', 'LeakSanitizer', 'SUMMARY: ', 'Segmentation', 'Program received')
    if 'SIGFPE' in err or 'Floating-point exception' in err:
        return False, 'trap (SIGFPE)', '', first      # -ffpe-trap=invalid,zero,overflow
    for b in bad:
        if b in err:
            return False, 'crash (%s)' % b.strip(), '', first
    if rc == 124:
        return False, 'hang (timeout)', '', first
    if rc == 125:
        return False, 'hang (past the watchdog)', '', first
    if rc < 0 or rc >= 128:
        return False, 'signal %d' % (-rc if rc < 0 else rc - 128), '', first
    if rc == 0:
        return True, 'exit 0', '', ''
    if rc != 2:
        return False, 'exit %d' % rc, '', first
    if 'cannot open the deck file' in err and 'deck.k:' not in err:
        return False, 'driver error (deck not found)', '', first
    if not MSG_RE.search(err) and not WHOLE_RE.search(err):
        return False, 'exit 2 without file:line', '', first
    return True, 'exit 2', message_class(first), first


def message_class(m):
    m = re.sub(r'^dynx: error: ', '', m)
    m = MSG_RE.sub('FILE:LINE', m)
    m = WHOLE_RE.sub('FILE: ', m)
    m = re.sub(r'FILE:LINE:\d+', 'FILE:LINE', m)
    m = re.sub(r"'[^']*'", "'...'", m)
    m = re.sub(r'\*[A-Z][A-Z0-9_]*', '*KEYWORD', m)
    m = re.sub(r'field [A-Z][A-Z0-9_]*', 'field F', m)
    m = re.sub(r'[-+]?\d[\d.]*(?:[eE][-+]?\d+)?', 'N', m)
    m = re.sub(r'\bN( N)+\b', 'N', m)
    return m[:110]


def restart_base(workdir, dynx, cycle):
    """(deck path, dump bytes): the patch test cut to 1e-3 s (11 cycles), dumped at the given
    cycle (a mutant continues from it to cycle 11)."""
    src = os.path.join(ROOT, 'tests', 'regression', 'patch_constant_strain', 'deck.k')
    with open(src) as f:
        lines = f.read().split('\n')
    k = lines.index('*CONTROL_TERMINATION')
    lines[k + 1] = '    0.0010'
    d = os.path.join(workdir, 'restart_base')
    os.makedirs(d, exist_ok=True)
    deck = os.path.join(d, 'deck.k')
    with open(deck, 'w') as f:
        f.write('\n'.join(lines))
    subprocess.run([dynx, '-i', deck, '-o', os.path.join(d, 'out'), '--raise-at-cycle', '%d:USR1' % cycle],
                   capture_output=True, timeout=300)
    with open(os.path.join(d, 'out', 'd3dump01.h5'), 'rb') as f:
        return deck, f.read()


def mutate_dump(rng, data):
    b = bytearray(data)
    kind = rng.choice(['flip', 'flip', 'flips', 'zero', 'truncate', 'garbage'])
    if kind == 'flip':
        b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
    elif kind == 'flips':
        for _ in range(rng.randint(2, 40)):
            b[rng.randrange(len(b))] = rng.randrange(256)
    elif kind == 'zero':
        a = rng.randrange(len(b))
        n = rng.randint(1, 4096)
        b[a:a + n] = bytes(len(b[a:a + n]))
    elif kind == 'truncate':
        b = b[:rng.randrange(len(b))]
    else:
        a = rng.randrange(len(b))
        b[a:a + 64] = bytes(rng.randrange(256) for _ in range(64))
    return bytes(b), 'dump-' + kind


def run_one(args, idx, name, text, files, base, workdir, dynx, timeout):
    d = os.path.join(workdir, 'c%06d' % idx)
    os.makedirs(d, exist_ok=True)
    for fn, data in files.items():
        with open(os.path.join(d, fn), 'wb') as f:
            f.write(data)
    with open(os.path.join(d, 'deck.k'), 'wb') as f:
        f.write(text)
    env = dict(os.environ)
    env['ASAN_OPTIONS'] = 'detect_leaks=0:halt_on_error=1:abort_on_error=0'
    if name.startswith('restart-dump'):
        # a damaged dump's HDF5 metadata can ask the library for an absurd buffer: malloc
        # returns NULL (as without the sanitizer) and HDF5 reports an error; ASan would abort
        env['ASAN_OPTIONS'] += ':allocator_may_return_null=1'
    env['UBSAN_OPTIONS'] = 'print_stacktrace=1:halt_on_error=1'
    env['GFORTRAN_ERROR_BACKTRACE'] = '1'
    try:
        if base is None:
            cmd = [dynx, '--check', '-i', 'deck.k']
        elif name.startswith('restart-dump'):
            os.rename(os.path.join(d, 'deck.k'), os.path.join(d, 'dump.h5'))
            cmd = [dynx, '-i', base, '-o', 'out', '-r', 'dump.h5']
        else:
            cmd = [dynx, '--check', '-i', base, '-R', 'deck.k']
        t0 = time.time()
        # the kill after the timeout is subprocess's own (SIGKILL), not a timeout(1) process
        # per input: one fork and exec less
        try:
            p = subprocess.run(cmd, capture_output=True, env=env, cwd=d,
                               timeout=max(timeout, args.watchdog + 1))
            rc = p.returncode
        except subprocess.TimeoutExpired as e:
            p = subprocess.CompletedProcess(cmd, -9, e.stdout or b'', e.stderr or b'')
            rc = -9
        if time.time() - t0 > args.watchdog and rc not in (137, -9):
            rc = 125     # ended by itself, but past the watchdog: a hang all the same
        if rc == 137 or rc == -9:
            rc = 124
        err = p.stderr.decode('latin-1') + p.stdout.decode('latin-1')[-2000:]
        secs = time.time() - t0
    except Exception as e:   # pragma: no cover
        rc, err, secs = 1, 'fuzz driver: %s' % e, 0.0
    # the NULL from the allocator (above) is announced by a warning; the rest is judged
    err = re.sub(r'==\d+==WARNING: AddressSanitizer failed to allocate[^\n]*\n?', '', err)
    ok, outcome, cls, first = classify(rc, err)
    if name.startswith('restart-dump') and not ok and outcome.startswith('exit 2 without'):
        ok, outcome = True, 'exit 2'     # a dump's message names the dump, not a deck line
    if name.startswith('restart-dump') and outcome == 'exit 4' and 'dump.h5' in err:
        ok = True                        # a damaged dump is an I/O error naming it
    if ok:
        shutil.rmtree(d, ignore_errors=True)
    else:
        keep = os.path.join(workdir, 'fail-%06d' % idx)
        shutil.rmtree(keep, ignore_errors=True)
        os.rename(d, keep)
        with open(os.path.join(keep, 'why.txt'), 'w') as f:
            f.write('source %s\noutcome %s\nexit %d\n\n%s\n' % (name, outcome, rc, err[-6000:]))
    return idx, name, ok, outcome, cls, first, secs, len(text)


def write_input(d, text, files, name):
    """The mutant's folder: deck.k (dump mutants: dump.h5) and its extra files."""
    os.makedirs(d, exist_ok=True)
    for fn, data in files.items():
        with open(os.path.join(d, fn), 'wb') as f:
            f.write(data)
    fn = 'dump.h5' if name.startswith('restart-dump') else 'deck.k'
    with open(os.path.join(d, fn), 'wb') as f:
        f.write(text)


def list_line(idx, name, d, base):
    """The harness's list line of an input (src/tools/dynx_fuzz.f90): index, kind, folder,
    deck, extra; the same commands as run_one's per-process runs."""
    if base is None:
        return '%d\tcheck\t%s\tdeck.k\t' % (idx, d)
    if name.startswith('restart-dump'):
        return '%d\tdump\t%s\t%s\tdump.h5' % (idx, d, base)
    return '%d\trdeck\t%s\t%s\tdeck.k' % (idx, d, base)


def judge(name, rc, err):
    """classify() plus the dump rules of run_one: (ok, outcome, class, first)."""
    ok, outcome, cls, first = classify(rc, err)
    if name.startswith('restart-dump') and not ok and outcome.startswith('exit 2 without'):
        ok, outcome = True, 'exit 2'
    if name.startswith('restart-dump') and outcome == 'exit 4' and 'dump.h5' in err:
        ok = True
    return ok, outcome, cls, first


def harness_env():
    env = dict(os.environ)
    env['ASAN_OPTIONS'] = ('detect_leaks=0:halt_on_error=1:abort_on_error=0:'
                           'allocator_may_return_null=1')
    env['UBSAN_OPTIONS'] = 'print_stacktrace=1:halt_on_error=1'
    env['GFORTRAN_ERROR_BACKTRACE'] = '1'
    return env


def harness_verdicts(harness, items, workdir, tag, watchdog):
    """Run the in-process harness over items [(idx, name, folder, base)]: one process for
    the lot, restarted after an input that crashed or hung it (the watchdog: no verdict
    line within `watchdog` seconds of the input's start). Returns {idx: (rc, err, secs,
    crash)}: rc and err as a per-process run's exit code and stderr would give them for
    that input; crash: the harness died or hung on it (err is then its stderr)."""
    import select
    lst = os.path.join(workdir, 'list-%s.txt' % tag)
    with open(lst, 'w') as f:
        for idx, name, d, base in items:
            f.write(list_line(idx, name, d, base) + '\n')
    out = {}
    first = 1
    env = harness_env()
    errpath = os.path.join(workdir, 'stderr-%s.txt' % tag)
    while first <= len(items):
        with open(errpath, 'wb') as ef:
            p = subprocess.Popen([harness, lst, str(first)], stdout=subprocess.PIPE,
                                 stderr=ef, env=env, cwd=workdir)
        fd = p.stdout.fileno()
        buf = b''
        cur, t_cur, done, hung = None, None, False, False
        while True:
            wait = None if cur is None else max(0.0, watchdog + 1 - (time.time() - t_cur))
            r, _, _ = select.select([fd], [], [], wait)
            if not r:                                  # no verdict in time: a hang
                hung = True
                p.kill()
                break
            chunk = os.read(fd, 65536)
            if not chunk:
                break
            buf += chunk
            while b'\n' in buf:
                ln, buf = buf.split(b'\n', 1)
                ln = ln.decode('latin-1')
                if ln.startswith('B '):
                    cur, t_cur = int(ln[2:]), time.time()
                elif ln.startswith('E '):
                    head, _, msg = ln.partition(' | ')
                    _, i, code, secs = head.split()
                    i, code, secs = int(i), int(code), float(secs)
                    msg = msg.replace('\x1f', '\n')
                    err = ('dynx: error: ' + msg + '\n') if code != 0 else ''
                    if secs > watchdog:
                        code = 125                    # ended, but past the watchdog
                    out[i] = (code, err, secs, False)
                    cur = None
                elif ln.startswith('L '):              # state left behind by an input
                    _, i, what = ln.split(' ', 2)
                    out[int(i)] = (1, 'Error termination: harness state leak: ' + what,
                                   0.0, True)
                elif ln == 'DONE':
                    done = True
        p.wait()
        if done:
            break
        with open(errpath, 'rb') as ef:
            err = ef.read().decode('latin-1')[-6000:]
        if cur is None:                               # died between inputs: harness defect
            raise RuntimeError('dynx-fuzz died outside an input (exit %d): %s' % (
                p.returncode, err[-500:]))
        rc = 124 if hung else p.returncode
        secs = time.time() - t_cur
        out[cur] = (rc, err, secs, True)
        pos = [k for k, it in enumerate(items) if it[0] == cur][0]
        first = pos + 2                               # the next input after the culprit
    return out


def run_batch(args, batch, workdir, harness, tag):
    """A batch of inputs through the harness; the same result tuples as run_one."""
    items = []
    for idx, name, text, files, base in batch:
        d = os.path.join(workdir, 'c%06d' % idx)
        write_input(d, text, files, name)
        items.append((idx, name, d, base))
    verd = harness_verdicts(harness, items, workdir, tag, args.watchdog)
    res = []
    for (idx, name, text, files, base), (_, _, d, _) in zip(batch, items):
        rc, err, secs, crash = verd[idx]
        if crash and rc > 128:
            rc = -(rc - 128) if rc < 255 else rc
        ok, outcome, cls, first = judge(name, rc, err)
        if ok:
            shutil.rmtree(d, ignore_errors=True)
        else:
            keep = os.path.join(workdir, 'fail-%06d' % idx)
            shutil.rmtree(keep, ignore_errors=True)
            os.rename(d, keep)
            with open(os.path.join(keep, 'why.txt'), 'w') as f:
                f.write('source %s\noutcome %s\nexit %d (in-process harness %s)\n'
                        'replay: %s\n\n%s\n' % (name, outcome, rc, harness,
                                                list_line(idx, name, keep, base), err[-6000:]))
        res.append((idx, name, ok, outcome, cls, first, secs, len(text)))
    if all(r[2] for r in res):
        for fn in ('list-%s.txt' % tag, 'stderr-%s.txt' % tag):
            try:
                os.remove(os.path.join(workdir, fn))
            except OSError:
                pass
    return res


def proc_verdict(dynx, d, name, base):
    """(exit code, first error line) of the per-process run of an input (as run_one)."""
    env = harness_env()
    if base is None:
        cmd = [dynx, '--check', '-i', 'deck.k']
    elif name.startswith('restart-dump'):
        cmd = [dynx, '-i', base, '-o', 'out', '-r', 'dump.h5']
    else:
        cmd = [dynx, '--check', '-i', base, '-R', 'deck.k']
    p = subprocess.run(cmd, capture_output=True, env=env, cwd=d, timeout=300)
    first = ''
    for l in p.stderr.decode('latin-1').splitlines():
        if l.startswith('dynx: error: '):
            first = l[len('dynx: error: '):]
            break
    return p.returncode, first[:300]


def compare(args, inputs, dynx, harness):
    """--compare: every input through the harness (one process) and through its own
    dynx process; the verdicts (exit code, first error line) must be equal."""
    items = []
    for idx, name, text, files, base in inputs:
        d = os.path.join(args.workdir, 'c%06d' % idx)
        write_input(d, text, files, name)
        items.append((idx, name, d, base))
    t0 = time.time()
    verd = harness_verdicts(harness, items, args.workdir, 'cmp', args.watchdog)
    th = time.time() - t0
    t0 = time.time()
    ndiff = 0
    codes = collections.Counter()
    for idx, name, d, base in items:
        rc, first = proc_verdict(dynx, d, name, base)
        hrc, herr, _, crash = verd[idx]
        hfirst = herr[len('dynx: error: '):].split('\n')[0] if herr.startswith('dynx: error: ') else ''
        codes[rc] += 1
        if crash or rc != hrc or first != hfirst[:300]:
            ndiff += 1
            print('fuzz_decks: DIFFER %06d %s: process exit %d %r, harness exit %d %r' % (
                idx, name, rc, first[:200], hrc, hfirst[:200]))
    tp = time.time() - t0
    print('fuzz_decks: compare: %d inputs, %d equal verdicts (exit code and first error '
          'line), %d differ; exits %s; harness %.1f s, processes %.1f s' % (
              len(items), len(items) - ndiff, ndiff,
              ', '.join('%d: %d' % kv for kv in sorted(codes.items())), th, tp))
    return 1 if ndiff else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--count', type=int, default=300)
    ap.add_argument('--seed', type=int, default=None)
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--timeout', type=int, default=30)
    ap.add_argument('--watchdog', type=float, default=10.0,
                    help='a mutant running longer counts as a hang (seconds)')
    ap.add_argument('--restart-share', type=float, default=0.1,
                    help='share of the inputs that are mutated restart dumps')
    ap.add_argument('--dump-cycle', type=int, default=10,
                    help='cycle (of 11) of the restart dump that dump mutants continue from; '
                         'every dataset is read and restored at the restart whatever the cycle, '
                         'so a late dump only saves the cycles after it (before: 5)')
    ap.add_argument('--dynx', default=None)
    ap.add_argument('--harness', default=None,
                    help='the in-process harness (bin/dynx-fuzz-debug): every input through '
                         'one process per batch (src/tools/dynx_fuzz.f90); without it, one '
                         'dynx process per input (the solver part: dump mutants run cycles)')
    ap.add_argument('--batch', type=int, default=500,
                    help='inputs per harness process (--harness)')
    ap.add_argument('--compare', action='store_true',
                    help='run every input through --harness and through its own --dynx '
                         'process and compare the verdicts (restart dumps excluded: the '
                         'process runs their cycles, the harness stops at the restored state)')
    ap.add_argument('--workdir', default=os.path.join(ROOT, 'build', 'fuzz'))
    ap.add_argument('--report', default=None, help='write the message-class table (markdown)')
    ap.add_argument('--profile', default=None,
                    help='write one line per input: index, seconds of the dynx run, input bytes, '
                         'outcome, source (where a campaign spends its time)')
    ap.add_argument('--progress', type=int, default=1000,
                    help='a progress line every N inputs (0: none)')
    args = ap.parse_args()
    dynx = args.dynx
    args.workdir = os.path.abspath(args.workdir)
    if dynx is None:
        dynx = os.path.join(ROOT, 'bin', 'dynx-asan')
        if not os.access(dynx, os.X_OK):
            dynx = os.path.join(ROOT, 'bin', 'dynx-debug')
    dynx = os.path.abspath(dynx)
    if not os.access(dynx, os.X_OK) and not args.harness:
        print('fuzz_decks: %s not found (make debug or make bin/dynx-asan)' % dynx)
        return 2
    harness = os.path.abspath(args.harness) if args.harness else None
    if harness and not os.access(harness, os.X_OK):
        print('fuzz_decks: %s not found (make bin/dynx-fuzz-debug)' % harness)
        return 2
    if args.compare:
        if not harness:
            print('fuzz_decks: --compare needs --harness')
            return 2
        args.restart_share = 0.0
    seed = args.seed if args.seed is not None else random.randrange(1 << 30)
    rng = random.Random(seed)
    src = decks()
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    t0 = time.time()
    rdeck = rdump = None
    if args.restart_share > 0:
        rdeck, rdump = restart_base(args.workdir, dynx, args.dump_cycle)
    ncount = collections.Counter()
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    tm0 = time.time()

    def gen():
        """The inputs in order, made one at a time (the same sequence for a seed as a list
        would give; a 100,000-mutant campaign never holds more than a window of them)."""
        for i in range(args.count):
            if rdump is not None and rng.random() < args.restart_share:
                data, tag = mutate_dump(rng, rdump)
                ncount['dump'] += 1
                yield (i, 'restart-dump:' + tag, data, {}, rdeck)
                continue
            name, text, base = rng.choice(src)
            files, tags = {}, []
            for _ in range(rng.choice([1, 1, 1, 2, 3])):
                text, tag = mutate(rng, text, files)
                tags.append(tag)
            if base:
                ncount['rdeck'] += 1
            yield (i, name + ':' + '+'.join(tags), text, files, base)

    if args.compare:
        return compare(args, list(gen()), dynx, harness)
    outcomes = collections.Counter()
    classes = collections.OrderedDict()
    kinds = collections.Counter()
    tmax = [0.0, '']
    fails = []
    window = 8 * max(1, args.jobs)
    prof = open(args.profile, 'w') if args.profile else None
    with cf.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
        pending = set()
        it = gen()
        done_all = False
        while pending or not done_all:
            while not done_all and len(pending) < (window if not harness else
                                                    max(1, args.jobs)):
                if harness:
                    batch = []
                    for _ in range(args.batch):
                        try:
                            batch.append(next(it))
                        except StopIteration:
                            done_all = True
                            break
                    if batch:
                        pending.add(ex.submit(run_batch, args, batch, args.workdir, harness,
                                              'b%06d' % batch[0][0]))
                    continue
                try:
                    i, n, t, f, b = next(it)
                except StopIteration:
                    done_all = True
                    break
                pending.add(ex.submit(run_one, args, i, n, t, f, b, args.workdir, dynx,
                                      args.timeout))
            if not pending:
                break
            finished, pending = cf.wait(pending, return_when=cf.FIRST_COMPLETED)
            results = []
            for fu in finished:
                r = fu.result()
                results.extend(r if harness else [r])
            for idx, name, ok, outcome, cls, first, secs, nbytes in results:
                for k in name.split(':', 1)[1].split('+'):
                    kinds[k] += 1
                if secs > tmax[0]:
                    tmax[:] = [secs, '%06d %s' % (idx, name)]
                if prof is not None:
                    prof.write('%d %.4f %d %s %s\n' % (idx, secs, nbytes,
                                                       outcome.replace(' ', '_'), name))
                outcomes[outcome] += 1
                ndone = sum(outcomes.values())
                if args.progress > 0 and ndone % args.progress == 0:
                    el = time.time() - t0
                    print('fuzz_decks: progress %d of %d in %.0f s (%.2f inputs/s), %d failures'
                          ' so far: %s' % (ndone, args.count, el, ndone / max(el, 1e-9),
                                           len(fails) + (0 if ok else 1),
                                           ', '.join('%s %d' % kv for kv in
                                                     sorted(outcomes.items()))), flush=True)
                if not ok:
                    fails.append((idx, name, outcome, first))
                elif cls:
                    if cls not in classes:
                        classes[cls] = [0, first, name]
                    classes[cls][0] += 1
    dt = time.time() - t0
    if prof is not None:
        prof.close()
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    # CPU seconds of the dynx runs per input: independent of the machine's load, so the rate
    # of a campaign on J idle cores is about J / (CPU s per input)
    print('fuzz_decks: dynx CPU %.1f s (user + system) for %d inputs in %.1f s: %.4f CPU s per '
          'input, about %.1f inputs/s on %d idle cores' % (
              cpu, args.count, time.time() - tm0, cpu / max(args.count, 1),
              max(1, args.jobs) * args.count / max(cpu, 1e-9), max(1, args.jobs)))
    print('fuzz_decks: %d inputs (seed %d, %s, %d jobs) in %.1f s (%.2f inputs/s): %s' % (
        args.count, seed, os.path.basename(harness or dynx) + (' in-process' if harness else ''),
        args.jobs, dt, args.count / max(dt, 1e-9),
        ', '.join('%s %d' % kv for kv in sorted(outcomes.items()))))
    ncrash = sum(v for k, v in outcomes.items() if k.startswith('crash') or
                 k.startswith('signal') or (k.startswith('exit') and k not in
                                             ('exit 0', 'exit 2', 'exit 4')))
    nhang = sum(v for k, v in outcomes.items() if k.startswith('hang'))
    ntrap = sum(v for k, v in outcomes.items() if k.startswith('trap'))
    print('fuzz_decks: %d crashes, %d hangs (watchdog %g s), %d traps (floating-point)' % (
        ncrash, nhang, args.watchdog, ntrap))
    print('fuzz_decks: %d of the inputs were restart decks (-R), %d restart dumps (-r)' % (
        ncount['rdeck'], ncount['dump']))
    print('fuzz_decks: %d distinct exit-2 message classes' % len(classes))
    print('fuzz_decks: %d distinct mutation kinds (%s); longest input %.3f s (%s)' % (
        len(kinds), ', '.join('%s %d' % kv for kv in sorted(kinds.items())), tmax[0], tmax[1]))
    for idx, name, outcome, first in sorted(fails):
        print('  FAIL %06d %s: %s: %s (kept in %s/fail-%06d)' % (idx, name, outcome, first[:160],
                                                                  args.workdir, idx))
    if args.report:
        with open(args.report, 'w') as f:
            f.write('| count | message class | example |\n|---:|---|---|\n')
            for cls, (n, first, name) in sorted(classes.items(), key=lambda kv: -kv[1][0]):
                ex = first.replace('|', '\\|')
                ex = re.sub(r'\S*/build/fuzz/c\d+/', '', ex)
                f.write('| %d | `%s` | `%s` |\n' % (n, cls.replace('|', '\\|').replace('`', "'"),
                                                     ex[:160].replace('`', "'")))
    print('fuzz_decks: %d failures' % len(fails))
    return 1 if fails else 0


if __name__ == '__main__':
    sys.exit(main())
