#!/usr/bin/env python3
"""kill -9 at chosen syscalls of the per-state plot files (issue 7; regression case
plot_kill9_state_files): the deck of kill9_check.py (Taylor bar, a plot state every 0.5 us),
killed by strace fault injection (-e inject=SYSCALL:signal=SIGKILL:when=N) at
  - before the d3dump (after state 9): a pwrite64 inside state 4's file, the rename of
    state 6's file;
  - after it: a pwrite64 inside state 10's file, its fsync and rename (written, not yet
    announced), a write of the XDMF after state 10 and the rename announcing state 11;
  - plot_close at the end of the run: the rename of d3plot.h5.tmp into place and the rename
    of state file 9's link to ../d3plot.h5 over it (issue 21: the state files become links).
After each kill:
  1. every state the XDMF lists is read through it (kill9_check.check_killed: h5dump reads each
     file named whole, every dataset named is there), and the newest d3dump continues the run
     to files byte-equal to the uninterrupted run's (d3plot.h5, d3plot.xdmf, glstat, nodout)
     when the kill came after the dump;
  2. on a copy of the killed directory, dynx-combine merges what is there into d3plot.h5 +
     d3plot.xdmf; their bytes equal those of an uninterrupted run of the same deck ended at
     the last merged state (END = (n-1) x 0.5 us), and the XDMF lists n >= the states the
     killed run had announced.
    python3 scripts/kill9_state_files.py OUTDIR
"""
import os, re, shutil, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kill9_check as k9
import kill9_sweep as sw

ROOT = k9.ROOT
DT = 0.0005          # plot interval of the kill9 deck (ms)


def nth(calls, sc, name, i=1):
    """Index (1-based among calls of sc) of the i-th call of sc on a file named name."""
    hits = [n for s, n, f in calls if s == sc and f == name]
    return hits[i - 1] if len(hits) >= i else None


def after(calls, sc, name, sc0, name0):
    """Index of the first call of sc on name after the first call of sc0 on name0."""
    seen = False
    for s, n, f in calls:
        if s == sc0 and f == name0:
            seen = True
        elif seen and s == sc and f == name:
            return n
    return None


def xdmf_states(path):
    if not os.path.exists(path):
        return 0
    return len(re.findall(r'<Grid Name="state', open(path).read()))


def not_links(d):
    """The entries of d/d3plot.states that are not symbolic links to ../d3plot.h5 (at the
    end of a run or a combine every state file becomes one: issue 21, live viewing)."""
    s = os.path.join(d, 'd3plot.states')
    if not os.path.isdir(s):
        return []
    return [f for f in sorted(os.listdir(s))
            if os.readlink(os.path.join(s, f)) != '../d3plot.h5'
            if os.path.islink(os.path.join(s, f))] + \
           [f for f in sorted(os.listdir(s)) if not os.path.islink(os.path.join(s, f))]


def main():
    out = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                          os.path.join(ROOT, 'build', 'kill9_state_files'))
    dynx = os.path.join(ROOT, 'bin', 'dynx')
    combine = os.path.join(ROOT, 'bin', 'dynx-combine')
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    deck = os.path.join(out, 'deck.k')
    k9.make_deck(deck, 0.005)
    ref = os.path.join(out, 'ref')
    if subprocess.run([dynx, '-i', deck, '-o', ref], capture_output=True).returncode != 0:
        print('FAIL reference run')
        return 1
    bad = [f for f in ('d3plot.h5.tmp',) if os.path.exists(os.path.join(ref, f))]
    bad += not_links(ref)
    if bad or 'd3plot.states' in open(os.path.join(ref, 'd3plot.xdmf')).read():
        print('FAIL the uninterrupted run left %s or an XDMF naming state files' % bad)
        return 1
    calls = sw.syscall_calls(dynx, deck, os.path.join(out, 'count'),
                             os.path.join(out, 'strace.log'), sw.SYSCALLS)
    # the d3dump is written after state 9: kills before it check readability and the merge,
    # kills after it also the continue from the dump (plot_resume from the state files)
    points = [('pwrite64', nth(calls, 'pwrite64', '000004.h5.tmp', 3), 'state 4 file data'),
              ('rename', nth(calls, 'rename', '000006.h5.tmp'), 'state 6 file rename'),
              ('pwrite64', nth(calls, 'pwrite64', '000010.h5.tmp', 3), 'state 10 file data'),
              ('fsync', nth(calls, 'fsync', '000010.h5.tmp'), 'state 10 file fsync'),
              ('rename', nth(calls, 'rename', '000010.h5.tmp'), 'state 10 file rename'),
              ('write', after(calls, 'write', 'd3plot.xdmf.tmp', 'rename', '000010.h5.tmp'),
               'XDMF write after state 10'),
              ('rename', nth(calls, 'rename', 'd3plot.xdmf.tmp', 12), 'XDMF rename, state 11'),
              ('rename', nth(calls, 'rename', 'd3plot.h5.tmp'), 'd3plot.h5 into place'),
              ('rename', nth(calls, 'rename', '000009.h5.lnk'),
               'state file 9 replaced by its link to d3plot.h5')]
    fail = 0
    refs = {}
    for sc, n, what in points:
        if n is None:
            print('FAIL %s: no such call in the run' % what)
            fail = 1
            continue
        d = os.path.join(out, 'run_%s_%d' % (sc, n))
        r = subprocess.run(['strace', '-f', '-o', '/dev/null', '-e', 'trace=' + sc, '-e',
                            'inject=%s:signal=SIGKILL:when=%d' % (sc, n), dynx, '-i', deck,
                            '-o', d], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        nx = xdmf_states(os.path.join(d, 'd3plot.xdmf'))
        c = d + '_combined'
        shutil.copytree(d, c)
        dumped = any(re.fullmatch(r'd3dump\d+\.h5', f) for f in os.listdir(d))
        stats = {'states': 0, 'continued': 0}
        problems, _, cont = k9.check_killed(d, deck, ref, dynx, stats)
        if r.returncode == 0:
            problems.append('the run was not killed')
        if dumped and stats['continued'] != 1:
            problems.append('not continued bitwise from a d3dump')
        p = subprocess.run([combine, c], capture_output=True, text=True)
        nm = xdmf_states(os.path.join(c, 'd3plot.xdmf'))
        if p.returncode != 0:
            problems.append('dynx-combine: exit %d: %s' % (p.returncode, p.stderr.strip()))
        elif nm < nx or nm < 1:
            problems.append('dynx-combine merged %d states, the XDMF had %d' % (nm, nx))
        else:
            if nm not in refs:
                rd = os.path.join(out, 'ref_%d' % nm)
                rk = os.path.join(out, 'deck_%d.k' % nm)
                k9.make_deck(rk, (nm - 1) * DT)
                subprocess.run([dynx, '-i', rk, '-o', rd], capture_output=True)
                refs[nm] = rd
            for f in ('d3plot.h5', 'd3plot.xdmf'):
                a = os.path.join(refs[nm], f)
                b = os.path.join(c, f)
                if not os.path.exists(a) or open(a, 'rb').read() != open(b, 'rb').read():
                    problems.append('dynx-combine: %s differs from the run ended at state %d'
                                    % (f, nm))
            if not_links(c):
                problems.append('dynx-combine left files in d3plot.states/ that are not '
                                'links to ../d3plot.h5: %s' % not_links(c))
        tag = '%s #%d (%s): %d XDMF states, combined %d' % (sc, n, what, nx, nm)
        if problems:
            fail = 1
            print('FAIL kill at ' + tag)
            for pr in problems:
                print('    ' + pr)
        else:
            print('ok kill at %s; listed states readable%s; combined bytes equal the '
                  'run ended at state %d' % (tag, cont or ' (no dump yet)', nm))
    return fail


if __name__ == '__main__':
    sys.exit(main())
