#!/usr/bin/env python3
"""make bench: the seed's Tables 1 and 2 (LLNL FY97 Engineering Thrust Area Report, article 5)
on dynx's two shell scenes: overall and constitutive CPU time of (a) the one-step analytic
return (*CONTROL_SHELL MITER 4) against (b) the fixed three secant iterations (MITER 1),
alternated a, b, a, b, ... REPS times each, medians.

  bench_shell_scenes.py [--plate N] [--post N] [--reps R] [--out FILE]

Each run goes under `perf record -e task-clock` (sampling at 2 kHz on the CPU time of the
process: a shared machine's waits for a core are not counted). Overall: the task-clock total.
Constitutive: the share of the samples in the lamina update (symbols of dx_plane_stress and the
materials' update_plane_stress wrappers: the material routine the shell kernel calls per
lamina, as the seed's "constitutive evaluation"). Contact: the share in dx_contact*. A clock
inside the shell kernel was tried and left out: it changed the kernel's code (fused
multiply-adds, 491 -> 507) and the last digits of shell results. Without perf the script stops.
ns per shell element-cycle: CPU time over cycles times deformable (part 1) shells, for the
run, the run less contact, and the constitutive part alone.
Appends a table to FILE (default: print only)."""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED = {'plate': ('Table 1, projectile on a plate', 941, 1093, 120, 256),
        'post': ('Table 2, vehicle on a U post', 8337, 9316, 1070, 2046)}
CONSTITUTIVE = re.compile(r'dx_plane_stress_MOD|update_plane_stress')
CONTACT = re.compile(r'dx_contact|dx_par_contact')


def run(deck, out):
    data = out + '.perf'
    p = subprocess.run(['perf', 'record', '-q', '-e', 'task-clock', '-F', '2000', '-o', data,
                        os.path.join(TOP, 'bin/dynx'), '-i', deck, '-o', out],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f'bench_shell_scenes: {deck} failed (exit {p.returncode}):\n{p.stderr[-2000:]}')
    log = p.stdout + p.stderr
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    rep = subprocess.run(['perf', 'report', '-i', data, '--stdio', '--no-children', '--sort',
                          'symbol', '--percent-limit', '0'], capture_output=True,
                         text=True).stdout
    total = float(re.search(r'Event count \(approx\.\): (\d+)', rep).group(1))*1e-9
    con = ctc = 0.0
    for line in rep.splitlines():
        m = re.match(r'\s*([0-9.]+)%\s+\[\.\]\s+(\S+)', line)
        if m:
            if CONSTITUTIVE.search(m.group(2)):
                con += float(m.group(1))
            elif CONTACT.search(m.group(2)):
                ctc += float(m.group(1))
    os.unlink(data)
    return total, total*con/100.0, total*ctc/100.0, cyc


def shells(mesh):
    """deformable shells (part 1) of a generated mesh.k"""
    n, kw = 0, ''
    for line in open(mesh):
        if line.startswith('*'):
            kw = line.strip()
        elif kw == '*ELEMENT_SHELL' and not line.startswith('$') and int(line[8:16]) == 1:
            n += 1
    return n


def main():
    ap = argparse.ArgumentParser()
    for name, default in (('plate', 40), ('post', 12), ('reps', 3)):
        ap.add_argument('--' + name, type=int, default=default)
    ap.add_argument('--out')
    a = ap.parse_args()
    if not shutil.which('perf'):
        sys.exit('bench_shell_scenes: perf not found (apt-get install linux-perf): no CPU profile')
    base = os.path.join(TOP, 'build/bench/shell_scenes')
    rows = []
    for scene, n, tend in (('plate', a.plate, 1.0), ('post', a.post, 4.0)):
        d = os.path.join(base, f'{scene}_{n}')
        subprocess.run([sys.executable, os.path.join(TOP, 'scripts/gen_shell_scenes.py'), scene,
                        str(n), d, '--tend', str(tend), '--dplot', '0'], check=True)
        ns = shells(os.path.join(d, 'mesh.k'))
        res = {'a': [], 'b': []}
        for k in range(a.reps):
            for alg, deck in (('a', 'deck.k'), ('b', 'deck_miter1.k')):
                r = run(os.path.join(d, deck), os.path.join(d, f'out_{alg}'))
                res[alg].append(r)
                print(f'bench_shell_scenes: {scene} N {n} ({alg}) run {k + 1}: cpu {r[0]:.3f} s,'
                      f' constitutive {r[1]:.3f} s, contact {r[2]:.3f} s, {r[3]} cycles',
                      flush=True)
        med = {g: [statistics.median(r[i] for r in res[g]) for i in range(4)] for g in res}
        rows.append((scene, n, ns, med))
    t = [f'\n### Shell scenes: one-step (a, MITER 4) against secant x 3 (b, MITER 1), '
         f'{time.strftime("%Y-%m-%d", time.gmtime())}, median of {a.reps} alternated runs, '
         f'perf task-clock, load average {os.getloadavg()[0]:.1f}\n',
         '| scene | shells | cycles | alg | CPU [s] | constitutive CPU [s] | share | contact CPU '
         '[s] | ns / shell element-cycle: run, less contact, constitutive |',
         '|---|---|---|---|---|---|---|---|---|']
    for scene, n, ns, med in rows:
        for g in ('a', 'b'):
            cpu, con, ctc, cyc = med[g]
            t.append(f'| {scene} N {n} | {ns} | {cyc:.0f} | ({g}) | {cpu:.3f} | {con:.3f} | '
                     f'{100*con/cpu:.1f} % | {ctc:.3f} | {1e9*cpu/cyc/ns:.0f}, '
                     f'{1e9*(cpu - ctc)/cyc/ns:.0f}, {1e9*con/cyc/ns:.1f} |')
    t += ['', '| scene | overall CPU saving | constitutive CPU saving | seed: overall | '
          'seed: constitutive |', '|---|---|---|---|---|']
    for scene, n, ns, med in rows:
        sa, sb = med['a'], med['b']
        name, oa, ob, ca, cb = SEED[scene]
        t.append(f'| {scene} N {n} | {100*(1 - sa[0]/sb[0]):.1f} % | '
                 f'{100*(1 - sa[1]/sb[1]):.1f} % | {100*(1 - oa/ob):.0f} % ({ob} -> {oa} s) | '
                 f'{100*(1 - ca/cb):.0f} % ({cb} -> {ca} s) ({name}) |')
    text = '\n'.join(t) + '\n'
    print(text)
    if a.out:
        with open(a.out, 'a') as f:
            f.write(text)


if __name__ == '__main__':
    main()
