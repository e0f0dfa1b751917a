#!/usr/bin/env python3
"""kill -9 between every pair of writes (issue 7): a systematic form of kill9_check.py.

dynx writes d3plot.h5 (and the restart dumps) through HDF5, which issues pwrite64(2) only
(no write/writev/fsync on the plot file: strace -f -y on a run shows it; the dumps add one
fsync each, through dx_io_sys). The run is repeated under
    strace -f -e trace=pwrite64 -e inject=pwrite64:signal=SIGKILL:when=N
for N over the pwrite64 calls of the run, so the process dies on entering its N-th
pwrite64: every gap between two writes of every state flush (datasets, then the metadata
HDF5 writes at H5Fflush, the XDMF rename after it) and of every dump is hit once. After
each kill the checks of kill9_check.py run (h5dump reads the whole d3plot.h5; every state
the XDMF lists is a complete group; glstat/nodout hold whole lines; the newest d3dump
continues the run bitwise: glstat, nodout, XDMF byte-equal, h5diff 0 differences).

    python3 scripts/kill9_sweep.py                       all N (make restart-long)
    python3 scripts/kill9_sweep.py --from-state 3 --states 2   the writes of plot states
                                                          3 and 4 only
    python3 scripts/kill9_sweep.py --target d3dump --stride 5   every 5th write of the
                                                          restart dumps (make test)
Today the plot file is not safe inside H5Fflush (docs/errors.md): the full sweep fails at the
metadata writes of every state; the dumps (tmp + fsync + rename) pass at every write.
"""
import argparse, os, shutil, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kill9_check as k9

ROOT = k9.ROOT


def pwrite_calls(dynx, deck, outdir, log):
    """The pwrite64 calls of an uninterrupted run, in order: (fd path, offset, bytes)."""
    subprocess.run(['strace', '-f', '-y', '-e', 'trace=pwrite64', '-o', log, dynx, '-i', deck,
                    '-o', outdir], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True)
    calls = []
    for line in open(log):
        if 'pwrite64(' not in line or 'resumed' in line:
            continue
        fd = line.split('pwrite64(', 1)[1].split(',', 1)[0]
        path = fd[fd.find('<') + 1:fd.rfind('>')] if '<' in fd else fd
        calls.append(os.path.basename(path))
    return calls


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--dynx', default=os.path.join(ROOT, 'bin', 'dynx'))
    ap.add_argument('--workdir', default=os.path.join(ROOT, 'build', 'kill9_sweep'))
    ap.add_argument('--endtim', type=float, default=0.005,
                    help='end time of the Taylor bar (0.005: 10 plot states, 1 d3dump)')
    ap.add_argument('--from-state', type=int, default=0,
                    help='first plot state whose writes are swept (0: from the start)')
    ap.add_argument('--states', type=int, default=0,
                    help='number of plot-state flushes swept (0: to the end of the run)')
    ap.add_argument('--target', default='',
                    help='kill only at writes to files whose name contains this (e.g. d3dump)')
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
    calls = pwrite_calls(args.dynx, deck, os.path.join(w, 'count'), os.path.join(w, 'strace.log'))
    # a state flush ends with the write of the superblock/root metadata; locate states by the
    # number of plot states: first N of each state = the first pwrite after the XDMF of the
    # previous one. Simpler and exact enough: split the d3plot.h5 writes evenly by state.
    plot_idx = [i for i, f in enumerate(calls) if f.startswith('d3plot.h5')]
    nstates = int(subprocess.run(['h5dump', '-a', '/nstates', os.path.join(ref, 'd3plot.h5')],
                                 capture_output=True, text=True).stdout.split('(0): ')[-1]
                  .split()[0]) if os.path.exists(os.path.join(ref, 'd3plot.h5')) else 0
    lo, hi = 1, len(calls)
    if args.from_state > 0 and nstates > 0:
        per = len(plot_idx) / max(1, nstates)
        a = int((args.from_state - 1) * per)
        b = int((args.from_state - 1 + (args.states or nstates)) * per)
        lo = plot_idx[min(a, len(plot_idx) - 1)] + 1
        hi = plot_idx[min(b, len(plot_idx) - 1)] + 1
    points = [n for n in range(lo, hi + 1) if args.target in calls[n - 1]][::max(1, args.stride)]
    print('kill9_sweep: %d pwrite64 calls in the run (%d to d3plot.h5, %d to dumps), %d plot '
          'states; killing at %d of the calls %d..%d%s' % (
              len(calls), len(plot_idx), sum(1 for f in calls if 'd3dump' in f), nstates,
              len(points), lo, hi, (' (writes to *%s*, every %d-th)' % (args.target, args.stride))
              if args.target or args.stride > 1 else ''))
    stats = {'states': 0, 'continued': 0}
    nfail = 0
    for n in points:
        d = os.path.join(w, 'run%05d' % n)
        r = subprocess.run(['strace', '-f', '-o', '/dev/null', '-e', 'trace=pwrite64', '-e',
                            'inject=pwrite64:signal=SIGKILL:when=%d' % n, args.dynx, '-i', deck,
                            '-o', d], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        problems, nx, cont = k9.check_killed(d, deck, ref, args.dynx, stats)
        if r.returncode == 0:
            problems.append('the run was not killed (exit 0)')
        tag = calls[n - 1] if n - 1 < len(calls) else '?'
        if problems:
            nfail += 1
            print('  kill at pwrite64 #%d (%s): %d XDMF states%s FAIL' % (n, tag, nx, cont))
            for pr in problems:
                print('      ' + pr)
        else:
            shutil.rmtree(d, ignore_errors=True)
    print('kill9_sweep: %d kills (pwrite64 #%d..#%d), %d XDMF-listed states checked, %d '
          'continued bitwise from the last d3dump, %d failed' % (len(points), lo, hi,
                                                                 stats['states'],
                                                                 stats['continued'], nfail))
    return 1 if nfail else 0


if __name__ == '__main__':
    sys.exit(main())
