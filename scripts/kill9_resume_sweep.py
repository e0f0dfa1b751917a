#!/usr/bin/env python3
"""kill -9 inside a continued run (issue 7): the rebuild of the plot output by plot_resume.

The kill9 deck (kill9_check.py, Taylor bar to 0.005 ms, 11 states, d3dump after state 9) is
first left in one of two states:
    states  killed (strace) at the rename of state 11's file: d3plot.states/ with 10 states
    h5      stopped in order by SIGTERM at cycle 150: d3plot.h5, no state files
then continued with -r d3dumpNN.h5 under strace fault injection, killed at every rename,
unlink and fsync of the continued run and at every 7th pwrite64 and write. After each kill
kill9_check.check_killed runs (the states the XDMF lists are read whole through it; the run
continued again from the dump gives glstat, nodout, d3plot.xdmf and d3plot.h5 byte-equal to
the uninterrupted run).
    python3 scripts/kill9_resume_sweep.py states|h5        (make kill9-sweep)
"""
import os, sys, shutil, subprocess, re
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.chdir(ROOT)
sys.path.insert(0, 'scripts')
import kill9_check as k9, kill9_sweep as sw
w = 'build/kill9_resume_' + sys.argv[1]; shutil.rmtree(w, ignore_errors=True); os.makedirs(w)
dynx = os.environ.get('DYNX', 'bin/dynx')
deck = w + '/deck.k'; k9.make_deck(deck, 0.005)
ref = w + '/ref'; subprocess.run([dynx, '-i', deck, '-o', ref], capture_output=True)
mode = sys.argv[1]   # 'states' (killed run) or 'h5' (stopped run)
base = w + '/base'
if mode == 'states':
    # kill at the rename of state 11's file: states 1..10 as files, dump after state 9
    calls = sw.syscall_calls(dynx, deck, w + '/cnt', w + '/st.log', 'rename')
    n = [c[1] for c in calls if c[2] == '000011.h5.tmp'][0]
    subprocess.run(['strace', '-f', '-o', '/dev/null', '-e', 'trace=rename', '-e',
                    'inject=rename:signal=SIGKILL:when=%d' % n, dynx, '-i', deck, '-o', base],
                   capture_output=True)
else:
    subprocess.run([dynx, '-i', deck, '-o', base, '--raise-at-cycle', '150:TERM'], capture_output=True)
dump = sorted(f for f in os.listdir(base) if re.fullmatch(r'd3dump\d+\.h5', f))[-1]
print(mode, os.listdir(base), dump)
# the continued run's syscalls
cb = w + '/cb'; shutil.copytree(base, cb)
log = w + '/c.log'
subprocess.run(['strace', '-f', '-y', '-e', 'trace=' + sw.SYSCALLS, '-o', log, dynx, '-i', deck, '-o', cb,
                '-r', os.path.join(cb, dump)], capture_output=True)
calls, count = [], {}
for line in open(log):
    m = re.match(r'\s*(?:\d+\s+)?(\w+)\(', line)
    if not m or m.group(1) not in sw.SYSCALLS.split(','): continue
    count[m.group(1)] = count.get(m.group(1), 0) + 1
    calls.append((m.group(1), count[m.group(1)]))
pts = [c for c in calls if c[0] != 'pwrite64' and c[0] != 'write'] + [c for c in calls if c[0] in ('pwrite64', 'write')][::7]
fail = 0; st = {'states': 0, 'continued': 0}
for sc, n in pts:
    d = w + '/k_%s_%d' % (sc, n); shutil.copytree(base, d)
    subprocess.run(['strace', '-f', '-o', '/dev/null', '-e', 'trace=' + sc, '-e',
                    'inject=%s:signal=SIGKILL:when=%d' % (sc, n), dynx, '-i', deck, '-o', d,
                    '-r', os.path.join(d, dump)], capture_output=True)
    pr, nx, cont = k9.check_killed(d, deck, ref, dynx, st)
    if pr:
        fail += 1; print('FAIL', sc, n, nx, pr)
    else:
        shutil.rmtree(d)
print('kill9_resume_sweep', mode, ': kills in the continued run:', len(pts), 'states checked', st['states'], 'continued', st['continued'], 'failed', fail, dict(count))
sys.exit(1 if fail else 0)
