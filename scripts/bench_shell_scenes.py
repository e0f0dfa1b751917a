#!/usr/bin/env python3
"""make bench: the seed's Tables 1 and 2 (LLNL FY97 Engineering Thrust Area Report, article 5)
on dynx's two shell scenes: overall and constitutive time of (a) the one-step analytic return
(*CONTROL_SHELL MITER 4) against (b) the fixed three secant iterations (MITER 1), alternated
a, b, a, b, ... REPS times each, medians.

  bench_shell_scenes.py [--plate N] [--post N] [--reps R] [--out FILE]

Overall: the process CPU time (user + system, getrusage of the child) and the run's wall time
(dynx's log). Constitutive: dynx's lamina clock, the wall time inside the calls of the
material's plane-stress update (material_t%update_plane_stress, one call per lamina of a block
of up to 128 shells; a CPU clock costs 0.56 us a call here against 26 ns for the wall clock,
about as much as the update of a block it would time). On a shared machine the wall clock also
counts the time the process waits for a core; the waits fall on the lamina calls in proportion
to their share of the run, so the constitutive CPU time is estimated as CPU x lamina / wall.
ns per shell element-cycle (deformable shells): the run's CPU time, the same less the contact
(its own clocks, scaled the same way), and the constitutive estimate alone.
Appends a table to FILE (default: print only)."""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED = {'plate': ('Table 1, projectile on a plate', 941, 1093, 120, 256),
        'post': ('Table 2, vehicle on a U post', 8337, 9316, 1070, 2046)}


def run(deck, out):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([os.path.join(TOP, 'bin/dynx'), '-i', deck, '-o', out],
                       capture_output=True, text=True)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.exit(f'bench_shell_scenes: {deck} failed (exit {p.returncode}):\n{p.stderr[-2000:]}')
    log = p.stdout + p.stderr
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    wall = float(re.search(r'wall time ([0-9.eE+-]+) s, [0-9.eE+-]+ ns per', log).group(1))
    lam = float(re.search(r'lamina updates \(constitutive\) ([0-9.eE+-]+) s', log).group(1))
    cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
    m = re.search(r'wall time search ([0-9.eE+-]+) s, local search \+ forces ([0-9.eE+-]+) s', log)
    con = float(m.group(1)) + float(m.group(2)) if m else 0.0
    return cpu, wall, lam, cyc, con


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
                      f' wall {r[1]:.3f} s, lamina {r[2]:.3f} s, {r[3]} cycles', flush=True)
        med = {g: [statistics.median(r[i] for r in res[g]) for i in range(5)] for g in res}
        rows.append((scene, n, ns, med))
    t = [f'\n### Shell scenes: one-step (a, MITER 4) against secant x 3 (b, MITER 1), '
         f'{time.strftime("%Y-%m-%d", time.gmtime())}, median of {a.reps} alternated runs, '
         f'load average {os.getloadavg()[0]:.1f}\n',
         '| scene | shells | cycles | alg | CPU [s] | wall [s] | contact wall [s] | lamina wall '
         '[s] | constitutive share | constitutive CPU [s] | ns / shell element-cycle: run, '
         'less contact, constitutive |',
         '|---|---|---|---|---|---|---|---|---|---|---|']
    for scene, n, ns, med in rows:
        for g in ('a', 'b'):
            cpu, wall, lam, cyc, con = med[g]
            f = cpu/wall
            t.append(f'| {scene} N {n} | {ns} | {cyc:.0f} | ({g}) | {cpu:.3f} | {wall:.3f} | '
                     f'{con:.3f} | {lam:.3f} | {100*lam/wall:.1f} % | {f*lam:.3f} | '
                     f'{1e9*cpu/cyc/ns:.0f}, {1e9*f*(wall - con)/cyc/ns:.0f}, '
                     f'{1e9*f*lam/cyc/ns:.1f} |')
    t += ['', '| scene | overall saving, CPU | overall saving, wall | constitutive saving '
          '(CPU estimate) | seed: overall | seed: constitutive |', '|---|---|---|---|---|---|']
    for scene, n, ns, med in rows:
        sa, sb = med['a'], med['b']
        name, oa, ob, ca, cb = SEED[scene]
        ca_, cb_ = sa[0]*sa[2]/sa[1], sb[0]*sb[2]/sb[1]
        t.append(f'| {scene} N {n} | {100*(1 - sa[0]/sb[0]):.1f} % | '
                 f'{100*(1 - sa[1]/sb[1]):.1f} % | {100*(1 - ca_/cb_):.1f} % '
                 f'(wall clock alone {100*(1 - sa[2]/sb[2]):.1f} %) | '
                 f'{100*(1 - oa/ob):.0f} % ({ob} -> {oa} s) | {100*(1 - ca/cb):.0f} % '
                 f'({cb} -> {ca} s) ({name}) |')
    text = '\n'.join(t) + '\n'
    print(text)
    if a.out:
        with open(a.out, 'a') as f:
            f.write(text)


if __name__ == '__main__':
    main()
