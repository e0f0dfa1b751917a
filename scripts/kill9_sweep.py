#!/usr/bin/env python3
"""kill -9 between every pair of writes (issue 7): a systematic form of kill9_check.py.

During a run dynx writes each plot state to its own file (d3plot.states/NNNNNN.h5: HDF5
pwrite64s to NNNNNN.h5.tmp, fsync, rename), then the XDMF (write to d3plot.xdmf.tmp, rename),
and at the end renames d3plot.h5.tmp into place and unlinks the state files; glstat/nodout
are written with write, the restart dumps with pwrite64 + fsync + rename. The run is repeated
under
    strace -f -e trace=SC -e inject=SC:signal=SIGKILL:when=N
for SC in pwrite64, write, rename, fsync, unlink and N over that syscall's calls in the run,
so the process dies on entering each of them once. After each kill the checks of
kill9_check.py run (every state the XDMF lists is read whole through it by h5dump; a
d3plot.h5 that exists is whole; glstat/nodout hold whole lines; the newest d3dump continues
the run to glstat, nodout, XDMF and d3plot.h5 byte-equal to the uninterrupted run's).

    python3 scripts/kill9_sweep.py                        every call (make kill9-sweep)
    python3 scripts/kill9_sweep.py --stride 23            every 23rd call (make test)
    python3 scripts/kill9_sweep.py --syscalls rename      the renames only
    python3 scripts/kill9_sweep.py --endtim 0.009 --target d3dump02 --stride 7
                                                          writes of the second dump (make test)
Result (docs/history.md, "Crash-safe plot output"): 0 failures at all 763 kill points.
"""
import argparse, os, re, shutil, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kill9_check as k9

ROOT = k9.ROOT


SYSCALLS = 'pwrite64,write,rename,fsync,unlink'


def syscall_calls(dynx, deck, outdir, log, syscalls):
    """The calls of an uninterrupted run to the syscalls given, in order: (syscall, its
    1-based count among the calls of that syscall, the file it acts on)."""
    subprocess.run(['strace', '-f', '-y', '-e', 'trace=' + syscalls, '-o', log, dynx, '-i',
                    deck, '-o', outdir], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True)
    calls, count = [], {}
    for line in open(log):
        m = re.match(r'\s*(?:\[pid\s+\d+\]\s*)?(?:\d+\s+)?(\w+)\((.*)', line)
        if not m or m.group(1) not in syscalls.split(',') or 'resumed' in line:
            continue
        sc, rest = m.group(1), m.group(2)
        if rest.startswith('"'):
            path = rest[1:rest.index('"', 1)]
        else:
            fd = rest.split(',', 1)[0].split(')', 1)[0]
            path = fd[fd.find('<') + 1:fd.rfind('>')] if '<' in fd else fd
        count[sc] = count.get(sc, 0) + 1
        calls.append((sc, count[sc], os.path.basename(path)))
    return calls


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--dynx', default=os.path.join(ROOT, 'bin', 'dynx'))
    ap.add_argument('--workdir', default=os.path.join(ROOT, 'build', 'kill9_sweep'))
    ap.add_argument('--endtim', type=float, default=0.005,
                    help='end time of the Taylor bar (0.005: 11 plot states, 1 d3dump)')
    ap.add_argument('--syscalls', default=SYSCALLS,
                    help='the syscalls killed at (default %s)' % SYSCALLS)
    ap.add_argument('--target', default='',
                    help='kill only at calls on files whose name contains this (e.g. d3dump)')
    ap.add_argument('--stride', type=int, default=1, help='every STRIDE-th kill point')
    args = ap.parse_args()
    w = args.workdir
    shutil.rmtree(w, ignore_errors=True)
    os.makedirs(w)
    deck = os.path.join(w, 'deck.k')
    k9.make_deck(deck, args.endtim)
    ref = os.path.join(w, 'ref')
    p = subprocess.run([args.dynx, '-i', deck, '-o', ref], capture_output=True)
    if p.returncode != 0:
        print('kill9_sweep: reference run failed (exit %d)' % p.returncode)
        return 1
    calls = syscall_calls(args.dynx, deck, os.path.join(w, 'count'),
                          os.path.join(w, 'strace.log'), args.syscalls)
    points = [c for c in calls if args.target in c[2]][::max(1, args.stride)]
    bysc = {}
    for c in calls:
        bysc[c[0]] = bysc.get(c[0], 0) + 1
    print('kill9_sweep: %d calls in the run (%s); killing at %d of them%s' % (
        len(calls), ', '.join('%d %s' % (n, sc) for sc, n in sorted(bysc.items())),
        len(points), (' (calls on *%s*, every %d-th)' % (args.target, args.stride))
        if args.target or args.stride > 1 else ''))
    stats = {'states': 0, 'continued': 0}
    nfail = 0
    for sc, n, tag in points:
        d = os.path.join(w, 'run_%s_%05d' % (sc, n))
        r = subprocess.run(['strace', '-f', '-o', '/dev/null', '-e', 'trace=' + sc, '-e',
                            'inject=%s:signal=SIGKILL:when=%d' % (sc, n), args.dynx, '-i', deck,
                            '-o', d], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        problems, nx, cont = k9.check_killed(d, deck, ref, args.dynx, stats)
        if r.returncode == 0:
            problems.append('the run was not killed (exit 0)')
        if problems:
            nfail += 1
            print('  kill at %s #%d (%s): %d XDMF states%s FAIL' % (sc, n, tag, nx, cont))
            for pr in problems:
                print('      ' + pr)
        else:
            shutil.rmtree(d, ignore_errors=True)
    print('kill9_sweep: %d kills, %d XDMF-listed states checked, %d '
          'continued bitwise from the last d3dump, %d failed' % (len(points),
                                                                 stats['states'],
                                                                 stats['continued'], nfail))
    return 1 if nfail else 0


if __name__ == '__main__':
    sys.exit(main())
