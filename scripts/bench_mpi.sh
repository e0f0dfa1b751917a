#!/bin/sh
# make bench: strong scaling of the MPI engine on the 100 000-element hex8 box
# (scripts/gen_box_deck.py, 50 x 50 x 40, ELFORM 1, *MAT_ELASTIC, SPC on z = 0, 200 cycles)
# at NP = 1 (serial, no mpirun), 2 and 4 (4 is oversubscribed on a 2-core machine and
# reported as such). Rank files are made by dynx-part beforehand, so the loop time is what
# is measured: the wall time of the explicit loop from dynx's last line, per cycle; the
# parallel efficiency T1 / (NP * T_NP); the time in the force exchange and the dt reduction
# (dynx's "MPI on N ranks" line, largest over the ranks). Each NP runs REPS times, in
# alternation, and the best run counts (the machine is shared). Appends to docs/performance.md.
set -e
cd "$(dirname "$0")/.."
B=build/bench/mpi
REPS=${REPS:-2}
BOX=${BOX:-50 50 40}      # elements along x, y, z (BOX="100 100 100" for the 1e6-element box)
CYC=${CYC:-200}
B=$B/$(echo $BOX | tr ' ' x)
mkdir -p $B
python3 scripts/gen_box_deck.py $B/box.k $BOX $CYC
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
for np in 2 4; do
    bin/dynx-part $B/box.k -n $np -o $B/part$np > $B/part$np.log
done
cores=$(nproc)
for r in $(seq 1 $REPS); do
    for np in 1 2 4; do
        if [ $np = 1 ]; then
            bin/dynx -i $B/box.k -o $B/out1 > $B/run1_$r.log 2>&1
        else
            mpirun $opts -np $np bin/dynx -i $B/box.k -o $B/out$np --part $B/part$np \
                > $B/run${np}_$r.log 2>&1
        fi
        echo "bench_mpi: NP $np run $r: $(grep 'wall time' $B/run${np}_$r.log)"
    done
done
python3 - "$B" "$REPS" "$cores" "$BOX" <<'PY' > $B/table.md
import re, sys, datetime, subprocess
B, reps, cores = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
box = [int(v) for v in sys.argv[4].split()]
nel = box[0] * box[1] * box[2]
def parse(np, r):
    t = open(f'{B}/run{np}_{r}.log').read()
    wall = float(re.search(r'wall time ([0-9.Ee+-]+) s', t).group(1))
    cyc = int(re.search(r'normal termination at cycle (\d+)', t).group(1))
    m = re.search(r'force exchange ([0-9.Ee+-]+) s \(mean ([0-9.Ee+-]+)\), dt reduction '
                  r'([0-9.Ee+-]+) s \(mean ([0-9.Ee+-]+)\), ordered gathers ([0-9.Ee+-]+)', t)
    ex = [float(m.group(i)) for i in (1, 3, 5)] if m else [0.0, 0.0, 0.0]
    return wall, cyc, ex
rev = subprocess.run(['git', 'rev-parse', '--short', 'HEAD'], capture_output=True,
                     text=True).stdout.strip()
cpu = [l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')][0]
load = open('/proc/loadavg').read().split()[0]
print(f'\n### make bench (MPI strong scaling), {datetime.date.today()}, commit {rev}, {cpu}, '
      f'{cores} cores, load average {load} at the end\n')
best = {}
for np in (1, 2, 4):
    runs = [parse(np, r) for r in range(1, reps + 1)]
    best[np] = min(runs, key=lambda x: x[0])
print('%s-element hex8 box (%s), %d cycles, best of %d alternating runs per NP.\n'
      % (f'{nel:,}', ' x '.join(map(str, box)), best[1][1], reps))
print('| NP | ms / cycle | speed-up | parallel efficiency | force exchange | dt reduction | gathers |')
print('|---|---|---|---|---|---|---|')
t1 = best[1][0] / best[1][1]
for np in (1, 2, 4):
    wall, cyc, ex = best[np]
    t = wall / cyc
    note = ' (oversubscribed: %d ranks on %d cores)' % (np, cores) if np > cores else ''
    frac = lambda x: '%.1f %%' % (100 * x / wall) if np > 1 else '-'
    print(f'| {np}{note} | {1e3 * t:.2f} | {t1 / t:.2f} | {t1 / t / np:.2f} | {frac(ex[0])} | '
          f'{frac(ex[1])} | {frac(ex[2])} |')
PY
cat $B/table.md >> docs/performance.md
cat $B/table.md
