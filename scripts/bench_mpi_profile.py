#!/usr/bin/env python3
"""CPU time per cycle of each stage of the explicit loop, serial against every rank of an MPI
run (the profile behind docs/scaling.md "Where NP 2 loses time"):

  python3 scripts/bench_mpi_profile.py [nx ny nz] [NP]      (default 50 50 40 = 1e5 elements, 2)

Each run is sampled by `perf record -e task-clock -F 1000` (one sample per ms of CPU time of
that process, so a loaded machine changes the wall time, not the samples). Two run lengths,
C1 and C2 cycles (environment, default 100 and 300), and the difference of the sample counts
per stage divided by C2 - C1: the set-up (deck, model, rank files, output) cancels and what
remains is the cost of one cycle. Stages are groups of symbols (STAGES below; the copies and
fills of libc are counted with the element pass, where the serial profile puts them). Needs
perf and mpirun; prints a markdown table. DYNX, DYNX_PART (default bin/dynx, bin/dynx-part):
the binaries, e.g. an older build for an old/new comparison (OUT: build/bench/profile/TAG,
TAG from the environment, default 'new')."""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.chdir(ROOT)
box = sys.argv[1:4] if len(sys.argv) >= 4 else ['50', '50', '40']
NP = int(sys.argv[4]) if len(sys.argv) >= 5 else 2
C1 = int(os.environ.get('C1', '100'))
C2 = int(os.environ.get('C2', '300'))
DYNX = os.environ.get('DYNX', 'bin/dynx')
DYNX_PART = os.environ.get('DYNX_PART', 'bin/dynx-part')
OUT = 'build/bench/profile/' + os.environ.get('TAG', 'new')
MPIRUN = ['mpirun', '--oversubscribe', '--mca', 'mpi_yield_when_idle', '1']
if os.geteuid() == 0:
    MPIRUN.append('--allow-run-as-root')
# (stage, regular expression on "dso symbol"); the first match counts
STAGES = [
    ('shared-node exchange (slots, ordered sums)', r'par_shared|par_fill_slots|par_exchange'),
    ('MPI library (progress, copies)', r'libmpi|libopen-pal|libopen-rte|mca_|libucs|libuct|'
                                       r'libucp|libevent|libhwloc|libpmix'),
    ('kernel (scheduler, yield while waiting, faults)', r'\[kernel|\[k\]'),
    ('energies, work sums, gathers', r'energy_sums|flush_work|par_engine|dx_sort|par_gather|'
                                     r'par_allgather|constraint_terms|par_loads|par_rigid'),
    ('element pass', r'hex8|tet4|shell|solid_kernels|dx_mat_|element_block|dx_element_MOD|'
                     r'jaumann|stable_time|memmove|memset|memcpy|dx_vec3'),
    ('explicit loop (velocities, positions, constraints)', r'dx_explicit|dx_constraints|'
                                                           r'dx_loads|apply_spc'),
    ('other', r'.'),
]


def run(cyc, np):
    tag = f'{"x".join(box)}_{cyc}'
    deck = f'{OUT}/box_{tag}.k'
    if not os.path.exists(deck):
        subprocess.run([sys.executable, 'scripts/gen_box_deck.py', deck] + box + [str(cyc)],
                       check=True)
    out = f'{OUT}/run_{tag}_np{np}'
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    perf = ['perf', 'record', '-q', '-e', 'task-clock', '-F', '1000', '-o']
    if np == 0:
        cmd = perf + [f'{out}/perf.0', DYNX, '-i', deck, '-o', out]
    else:
        part = f'{OUT}/part_{tag}_{np}'
        if not os.path.exists(part + '/partition.txt'):
            subprocess.run([DYNX_PART, deck, '-n', str(np), '-o', part], check=True,
                           stdout=subprocess.DEVNULL)
        cmd = MPIRUN + ['-np', str(np), 'sh', '-c', 'exec ' + ' '.join(perf) + f' {out}/perf.'
                        f'$OMPI_COMM_WORLD_RANK {DYNX} -i {deck} -o {out} --part {part}']
    with open(out + '.log', 'w') as log:
        subprocess.run(cmd, check=True, stdout=log, stderr=subprocess.STDOUT)
    res = []
    for r in range(max(1, np)):
        rep = subprocess.run(['perf', 'report', '-i', f'{out}/perf.{r}', '--stdio', '-n',
                              '--sort', 'dso,symbol'], capture_output=True, text=True).stdout
        cnt = {s: 0 for s, _ in STAGES}
        for ln in rep.splitlines():
            m = re.match(r'\s*[0-9.]+%\s+(\d+)\s+(.*)$', ln)
            if not m:
                continue
            for s, rx in STAGES:
                if re.search(rx, m.group(2)):
                    cnt[s] += int(m.group(1))
                    break
        res.append(cnt)
    return res


def main():
    os.makedirs(OUT, exist_ok=True)
    ne = int(box[0]) * int(box[1]) * int(box[2])
    prof = {}
    for np in (0, NP):
        a, b = run(C1, np), run(C2, np)
        prof[np] = [{s: (b[r][s] - a[r][s]) / (C2 - C1) for s, _ in STAGES}
                    for r in range(len(a))]
    heads = ['serial'] + [f'NP {NP} rank {r}' for r in range(NP)]
    cols = [prof[0][0]] + prof[NP]
    print(f'CPU ms per cycle by stage, {"x".join(box)} box, (runs of {C2} - runs of {C1} '
          f'cycles), perf task-clock samples:\n')
    print('| stage | ' + ' | '.join(heads) + ' |')
    print('|---' * (len(heads) + 1) + '|')
    for s, _ in STAGES:
        print(f'| {s} | ' + ' | '.join(f'{c[s]:.3f}' for c in cols) + ' |')
    tot = [sum(c.values()) for c in cols]
    print('| **total** | ' + ' | '.join(f'{t:.3f}' for t in tot) + ' |')
    print('| ns per element-cycle (CPU, per rank: x NP) | ' +
          ' | '.join(f'{1e6 * t * (1 if k == 0 else NP) / ne:.0f}'
                     for k, t in enumerate(tot)) + ' |')
    print(f'\n{DYNX}: serial CPU per cycle / largest rank\'s: {tot[0] / max(tot[1:]):.2f} (the '
          f'speed-up with one core per rank and no waiting on a loaded core); serial / mean '
          f'rank: {tot[0] * NP / sum(tot[1:]):.2f}.')


main()
