#!/usr/bin/env python3
"""make bench: the measurements of issue 22's acceptance for the MPI engine (docs/scaling.md).

  python3 scripts/bench_scaling.py            (make bench runs it; options by environment)

Boxes of hex8 elements from scripts/gen_box_deck.py (*MAT_ELASTIC, SPC at z = 0), rank files
from bin/dynx-part, every process started through scripts/bench_rank.sh (/usr/bin/time: peak
resident set = VmHWM at exit, CPU times; or a `ulimit -v` per rank). Four parts (PARTS):
  speed  serial against mpirun -np 2 on each box, REPS alternating pairs, the load average
         before each pair; the explicit loop's wall time per cycle from dynx's "wall time"
         line; speed-up = best serial / best NP 2 (and each pair's ratio)
  mem    peak resident memory of every rank at NP 1..4 (MEM_NP) against the serial run on
         each box; the constant C = the largest rank of an MPI run of an 8-element box (MPI,
         HDF5 and dynx's own footprint, measured the same way); the issue's bound
         1.1 x serial / NP + C and whether each NP is within it
  weak   weak scaling, WEAK_NZ layers of 50 x 50 elements per rank, NP = WEAK_NP
         (oversubscribed beyond the cores): wall per cycle, the same per core (wall x
         min(NP, cores) / NP: what each rank's own core would give if the ranks shared
         nothing but the cores), bytes sent per rank per cycle (dynx's MPI traffic line),
         peak memory per rank
  fit    a model bigger than one rank's memory limit (FIT_BOX): the limit per rank is
         V0 + FIT_FRAC x (S - C) with V0 the peak virtual size (VmPeak, what ulimit -v bounds)
         of an empty MPI run's ranks, S the serial run's peak resident memory; PASS when the
         run fails at NP 1 and completes at NP FIT_NP under that limit
Environment: SMALL (default "50 50 40", 1e5 elements; "" skips it), BIG ("100 100 100",
1e6; "" skips it), CYC_SMALL (200), CYC_BIG (30), REPS (3), MEM_NP ("1 2 3 4"), WEAK_NP ("1 2 4 8"),
WEAK_NZ (10), WEAK_CYC (100), FIT_BOX ("50 50 120"), FIT_NP (4), FIT_FRAC (0.4: NP 1 needs the whole
model, 1.0; NP 4 with distributed memory about 0.25 x 1.1, plus the halo),
PARTS ("speed mem weak fit"), DOC (docs/scaling.md; "" prints only).
Prints the tables and appends them to DOC. Exit status 0 (the verdicts are in the tables)."""
import datetime
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
os.chdir(ROOT)
env = os.environ.get
SMALL = env('SMALL', '50 50 40')
BIG = env('BIG', '100 100 100')
CYC = {SMALL: int(env('CYC_SMALL', '200'))} if SMALL else {}
if BIG:
    CYC[BIG] = int(env('CYC_BIG', '30'))
REPS = int(env('REPS', '3'))
MEM_NP = [int(v) for v in env('MEM_NP', '1 2 3 4').split()]
WEAK_NP = [int(v) for v in env('WEAK_NP', '1 2 4 8').split()]
WEAK_NZ = int(env('WEAK_NZ', '10'))
WEAK_CYC = int(env('WEAK_CYC', '100'))
FIT_BOX = env('FIT_BOX', '50 50 120')
FIT_NP = int(env('FIT_NP', '4'))
FIT_FRAC = float(env('FIT_FRAC', '0.4'))
PARTS = env('PARTS', 'speed mem weak fit').split()
DOC = env('DOC', 'docs/scaling.md')
OUT = 'build/bench/scaling'
CORES = os.cpu_count() or 1
MPIRUN = ['mpirun', '--oversubscribe', '--mca', 'mpi_yield_when_idle', '1']
if os.geteuid() == 0:
    MPIRUN.append('--allow-run-as-root')


def nel(box):
    a = [int(v) for v in box.split()]
    return a[0] * a[1] * a[2]


def loadavg():
    return float(open('/proc/loadavg').read().split()[0])


def deck(box, cyc):
    tag = box.replace(' ', 'x') + '_' + str(cyc)
    path = f'{OUT}/box_{tag}.k'
    if not os.path.exists(path):
        os.makedirs(OUT, exist_ok=True)
        subprocess.run([sys.executable, 'scripts/gen_box_deck.py', path + '.tmp'] + box.split()
                       + [str(cyc)], check=True)
        os.replace(path + '.tmp', path)
    return path


def part(dk, np):
    d = dk[:-2] + f'_part{np}'
    if not os.path.exists(d + '/partition.txt'):
        shutil.rmtree(d, ignore_errors=True)
        with open(d + '.log', 'w') as log:
            subprocess.run(['bin/dynx-part', dk, '-n', str(np), '-o', d], check=True,
                           stdout=log, stderr=subprocess.STDOUT)
    return d


def run(dk, np, tag, limit=0, mode='time'):
    """np 0: serial (no mpirun). Returns a dict of the run's numbers."""
    out = f'{OUT}/run_{tag}'
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    prefix = f'{out}/rank'
    cmd = ['bin/dynx', '-i', dk, '-o', out]
    if np >= 2:
        cmd += ['--part', part(dk, np)]
    wrap = ['sh', 'scripts/bench_rank.sh', prefix, str(limit), mode] + cmd
    if np >= 1:
        wrap = MPIRUN + ['-np', str(np)] + wrap
    with open(out + '.log', 'w') as log:
        rc = subprocess.run(wrap, stdout=log, stderr=subprocess.STDOUT).returncode
    text = open(out + '.log', errors='replace').read()
    r = {'rc': rc, 'np': np, 'log': out + '.log', 'ranks': []}
    for k in range(max(1, np)):
        try:
            v = open(f'{prefix}.{k}').read().split()
        except OSError:
            v = []
        if mode == 'time' and len(v) >= 4 and v[0].isdigit():
            r['ranks'].append({'rss': int(v[0]), 'cpu': float(v[1]) + float(v[2]),
                               'wall': float(v[3])})
        elif mode == 'vmpeak' and v:
            r['ranks'].append({'vmpeak': int(v[0])})
    m = re.search(r'wall time ([0-9.Ee+-]+) s', text)
    c = re.search(r'normal termination at cycle (\d+)', text)
    r['ok'] = rc == 0 and c is not None
    if m and c:
        r['loop'] = float(m.group(1))
        r['cycles'] = int(c.group(1))
        r['ms'] = 1e3 * r['loop'] / max(1, r['cycles'])
    t = re.search(r'bytes sent per rank per cycle[^:]*: shared-node sums (\d+), other '
                  r'point-to-point (\d+), collectives \(own payload\) (\d+)', text)
    r['bytes'] = [int(t.group(i)) for i in (1, 2, 3)] if t else None
    e = re.search(r'force exchange ([0-9.Ee+-]+) s \(mean [^)]*\), dt reduction ([0-9.Ee+-]+) s',
                  text)
    r['exch_dt'] = (float(e.group(1)), float(e.group(2))) if e else None
    r['rss'] = max((k['rss'] for k in r['ranks'] if 'rss' in k), default=0)
    r['cpu'] = max((k['cpu'] for k in r['ranks'] if 'cpu' in k), default=0.0)
    r['rss_min'] = min((k['rss'] for k in r['ranks'] if 'rss' in k), default=0)
    r['vmpeak'] = max((k['vmpeak'] for k in r['ranks'] if 'vmpeak' in k), default=0)
    errs = [ln for ln in text.splitlines() if re.search(r'error|Error|signal|killed', ln)]
    tail = errs[:2] or [ln for ln in text.splitlines() if ln.strip()][-3:]
    r['tail'] = ' | '.join(tail)[-300:]
    return r


def say(s):
    print(s, flush=True)


lines = []


def emit(s=''):
    lines.append(s)
    say(s)


def constant():
    """The 8-element box at NP 2 (C) and serially (C0: dynx and HDF5 without MPI)."""
    dk = deck('2 2 2', 10)
    r = run(dk, 2, 'const')
    r0 = run(dk, 0, 'const_serial')
    if not (r['ok'] and r0['ok']):
        say('bench_scaling: the 8-element runs failed: ' + r['tail'] + r0['tail'])
    r['rss0'] = r0['rss']
    return r


def speed(box):
    dk = deck(box, CYC[box])
    part(dk, 2)
    ser, par, loads = [], [], []
    for k in range(REPS):
        loads.append(loadavg())
        s = run(dk, 0, f'speed_{box.replace(" ", "x")}_serial_{k}')
        p = run(dk, 2, f'speed_{box.replace(" ", "x")}_np2_{k}')
        for x, lst in ((s, ser), (p, par)):
            if not x['ok']:
                say(f'bench_scaling: run failed ({x["log"]}): {x["tail"]}')
            lst.append(x)
        say(f'bench_scaling: {box} pair {k + 1}: serial {s.get("ms", 0):.2f} ms/cycle, '
            f'NP 2 {p.get("ms", 0):.2f} ms/cycle (load {loads[-1]:.2f})')
    return dk, ser, par, loads


def speed_table(box, ser, par, loads):
    n = nel(box)
    emit(f'Speed-up at NP 2, {n:,}-element box ({box.replace(" ", " x ")}), '
         f'{CYC[box]} cycles, {REPS} alternating pairs (serial, then NP 2):\n')
    emit('| pair | load before | serial ms/cycle | NP 2 ms/cycle | ratio | NP 2 exchange wait '
         '/ dt MINLOC wait [s, largest rank] |')
    emit('|---|---|---|---|---|---|')
    for k in range(len(ser)):
        s, p = ser[k], par[k]
        if 'ms' in s and 'ms' in p:
            ed = p['exch_dt'] or (0, 0)
            emit(f'| {k + 1} | {loads[k]:.2f} | {s["ms"]:.2f} | {p["ms"]:.2f} | '
                 f'{s["ms"] / p["ms"]:.2f} | {ed[0]:.3f} / {ed[1]:.3f} |')
    sb = min((s['ms'] for s in ser if 'ms' in s), default=0)
    pb = min((p['ms'] for p in par if 'ms' in p), default=0)
    goal = 1.9 if n < 500000 else 1.95
    if sb and pb:
        emit(f'\nBest of {REPS}: serial {sb:.2f} ms/cycle, NP 2 {pb:.2f} ms/cycle: speed-up '
             f'**{sb / pb:.2f}** (goal {goal}: {"PASS" if sb / pb >= goal else "FAIL"}; '
             f'{CORES} cores shared with other work, see the load column).\n')


def mem_table(box, ser, par, c):
    dk = deck(box, CYC[box])
    rows = {0: ser[0], 2: par[0]}
    for np in MEM_NP:
        if np not in rows:
            rows[np] = run(dk, np, f'mem_{box.replace(" ", "x")}_np{np}')
    s = rows[0]['rss']
    cst = c['rss']
    c0 = c['rss0']
    emit(f'Peak resident memory per rank (VmHWM at exit, /usr/bin/time), {nel(box):,}-element '
         f'box; serial {s} KiB; constant C = {cst} KiB (largest rank of an 8-element box at NP '
         f'2: MPI, HDF5, dynx), C0 = {c0} KiB (the same box serially). "model share x NP" = '
         '(largest - C) / (serial - C0) x NP: 1 when each rank holds 1/NP of the model:\n')
    emit('| NP | largest rank [KiB] | smallest rank [KiB] | largest / serial | '
         'model share x NP | bound 1.1 x serial / NP + C [KiB] | within |')
    emit('|---|---|---|---|---|---|---|')
    for np in [0] + MEM_NP:
        r = rows[np]
        if not r['ranks']:
            emit(f'| {np} | run failed | | | | | |')
            continue
        if np == 0:
            emit(f'| serial | {r["rss"]} | - | 1.00 | - | - | - |')
            continue
        bound = 1.1 * s / np + cst
        emit(f'| {np} | {r["rss"]} | {r["rss_min"]} | {r["rss"] / s:.2f} | '
             f'{(r["rss"] - cst) / max(1, s - c0) * np:.2f} | {bound:.0f} | '
             f'{"yes" if r["rss"] <= bound else "NO"} |')
    emit('')


def weak(c):
    emit(f'Weak scaling: 50 x 50 x {WEAK_NZ} = {2500 * WEAK_NZ:,} elements per rank, '
         f'{WEAK_CYC} cycles, {CORES} cores (NP above {CORES} is oversubscribed):\n')
    emit('| NP | elements | load before | wall ms/cycle | per core: ms/cycle x min(NP, cores) / NP '
         '| ns per element-cycle per core | bytes sent/rank/cycle: shared-node sums | '
         'other p2p | collectives | peak memory per rank [KiB] (largest) | CPU s per rank, '
         'whole run (largest) |')
    emit('|---|---|---|---|---|---|---|---|---|---|---|')
    for np in WEAK_NP:
        box = f'50 50 {WEAK_NZ * np}'
        dk = deck(box, WEAK_CYC)
        ld = loadavg()
        r = run(dk, np, f'weak_np{np}')
        if not r['ok']:
            emit(f'| {np} | {nel(box):,} | {ld:.2f} | failed: {r["tail"][:80]} | | | | | | | |')
            continue
        pc = r['ms'] * min(np, CORES) / np
        b = r['bytes'] or [0, 0, 0]
        emit(f'| {np} | {nel(box):,} | {ld:.2f} | {r["ms"]:.2f} | {pc:.2f} | '
             f'{1e6 * pc / (2500 * WEAK_NZ):.0f} | {b[0]} | {b[1]} | {b[2]} | {r["rss"]} | '
             f'{r["cpu"]:.1f} |')
    emit('')


def fit(c):
    dk = deck(FIT_BOX, 10)
    e1 = run(deck('2 2 2', 10), 1, 'fit_empty1', mode='vmpeak')
    e = run(deck('2 2 2', 10), FIT_NP, 'fit_empty', mode='vmpeak')
    s = run(dk, 0, 'fit_serial')
    if not (e['ok'] and e1['ok'] and s['ok'] and e['vmpeak']):
        emit(f'Memory-limit test: FAIL (calibration runs failed: {e["tail"]} / {s["tail"]})\n')
        return
    v1, v4 = e1['vmpeak'], e['vmpeak']
    e['vmpeak'] = max(e['vmpeak'], e1['vmpeak'])
    limit = int(e['vmpeak'] + FIT_FRAC * (s['rss'] - c['rss0']))
    one = run(dk, 1, 'fit_np1', limit=limit)
    many = run(dk, FIT_NP, f'fit_np{FIT_NP}', limit=limit)
    ok = (not one['ok']) and many['ok']
    emit(f'Memory-limit test ({nel(FIT_BOX):,}-element box {FIT_BOX.replace(" ", " x ")}, 10 '
         f'cycles): `ulimit -v {limit}` KiB per rank = V0 {e["vmpeak"]} (VmPeak of an '
         f'8-element run\'s ranks, largest of NP 1: {v1} and NP {FIT_NP}: {v4}) + {FIT_FRAC} '
         f'x (serial peak resident {s["rss"]} - C0 {c["rss0"]}). NP 1: '
         f'{"completed" if one["ok"] else "failed"} (exit '
         f'{one["rc"]}); NP {FIT_NP}: {"completed" if many["ok"] else "failed"} (exit '
         f'{many["rc"]}{", " + many["tail"][-160:] if not many["ok"] else ""}). '
         f'**{"PASS" if ok else "FAIL"}** (runs at NP {FIT_NP} and not at NP 1).\n')


def main():
    if not os.path.exists('bin/dynx'):
        sys.exit('bench_scaling: bin/dynx missing (make all)')
    os.makedirs(OUT, exist_ok=True)
    rev = subprocess.run(['git', 'rev-parse', '--short', 'HEAD'], capture_output=True,
                         text=True).stdout.strip()
    dirty = subprocess.run(['git', 'status', '--porcelain', '--untracked-files=no'],
                           capture_output=True, text=True).stdout.strip()
    cpu = [ln.split(':', 1)[1].strip() for ln in open('/proc/cpuinfo')
           if ln.startswith('model name')][0]
    emit(f'\n### make bench (scaling, scripts/bench_scaling.py), {datetime.date.today()}, commit '
         f'{rev}{" + local changes" if dirty else ""}, {cpu}, {CORES} cores, load average '
         f'{loadavg():.2f} at the start\n')
    keys = ('SMALL', 'BIG', 'CYC_SMALL', 'CYC_BIG', 'REPS', 'MEM_NP', 'WEAK_NP', 'WEAK_NZ',
            'WEAK_CYC', 'FIT_BOX', 'FIT_NP', 'FIT_FRAC', 'PARTS')
    given = ''.join(f'{k}="{env(k)}" ' for k in keys if env(k) is not None)
    emit(f'Command: `{given}python3 scripts/bench_scaling.py`\n')
    c = constant()
    boxes = ([SMALL] if SMALL else []) + ([BIG] if BIG else [])
    for box in boxes:
        if 'speed' in PARTS or 'mem' in PARTS:
            dk, ser, par, loads = speed(box) if 'speed' in PARTS else (None, None, None, None)
            if 'speed' in PARTS:
                speed_table(box, ser, par, loads)
            if 'mem' in PARTS:
                if ser is None:
                    dk = deck(box, CYC[box])
                    ser = [run(dk, 0, f'mem_{box.replace(" ", "x")}_serial')]
                    par = [run(dk, 2, f'mem_{box.replace(" ", "x")}_np2')]
                mem_table(box, ser, par, c)
    if 'weak' in PARTS:
        weak(c)
    if 'fit' in PARTS:
        fit(c)
    emit(f'(load average {loadavg():.2f} at the end)')
    if DOC:
        with open(DOC, 'a') as f:
            f.write('\n'.join(lines) + '\n')


main()
