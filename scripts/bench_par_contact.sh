#!/bin/sh
# make bench (MPI contact part): N elastic cubes in a box of stonewalls with
# *CONTACT_AUTOMATIC_SINGLE_SURFACE (scripts/gen_contact_decks.py cubes; default N = 512:
# 13,824 hexes, 28,672 contact nodes), 200 cycles, run serially (NP 1) and with
# mpirun -np 2 (--oversubscribe) with each --contact-split (owner, strips), alternating,
# REPS times. From dynx's end-of-run lines:
# serial contact time per cycle (bucket sorts, local search + forces); MPI: search + forces
# per cycle (mean and max over the ranks, split into sorts/strips and local search/forces/
# assembly), the contact communication per cycle, numbers received per rank and cycle, and
# the slave nodes per strip; per stage (x, v exchange, bucket sorts, local search + forces,
# results exchange, assembly, work exchange, contact work) and the bytes each rank sends per
# cycle (dynx's "MPI contact stages" and "bytes sent" lines), and the time of the cycles alone
# (wall clock at the last status line less that at cycle 0: without MPI start-up, deck read,
# partition and plot combine). Checks that the NP 2 glstat and d3plot.h5 equal the serial
# ones. Appends a dated table to docs/performance.md. NCYC (default 200) cycles.
set -e
cd "$(dirname "$0")/.."
B=build/bench_par_contact
N=${NCUBE:-512}
REPS=${REPS:-2}
mkdir -p $B
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
NCYC=${NCYC:-200}
python3 scripts/gen_contact_decks.py cubes --ncube "$N" --ncyc "$NCYC" $B/cubes.k
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
{
echo ""
echo "### MPI contact (make bench, scripts/bench_par_contact.sh), $(date -u +%Y-%m-%d), commit $rev, load $(cut -d' ' -f1 /proc/loadavg)"
echo ""
echo "$N cubes, $NCYC cycles, times per cycle in microseconds (wall clock; shared machine: compare within a row pair only). Command: \`REPS=$REPS NCUBE=$N NCYC=$NCYC sh scripts/bench_par_contact.sh\`."
echo ""
echo "| run | NP | split | contact nodes | sorts / strips [us] | local search + forces (+ assembly) [us] | contact communication [us] | numbers received per rank | bytes sent per rank and cycle | slave nodes per rank | cycles [s] | whole run [s] | bitwise |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > $B/table.md
: > $B/stages.md
r=1
while [ $r -le "$REPS" ]; do
    rm -rf $B/s $B/p
    t0=$(date +%s.%N)
    bin/dynx -i $B/cubes.k -o $B/s --status 1 > $B/s.log 2>&1
    t1s=$(date +%s.%N)
    for split in owner strips; do
    rm -rf $B/p
    t1=$(date +%s.%N)
    mpirun $opts -np 2 bin/dynx -i $B/cubes.k -o $B/p --status 1 --contact-split $split > $B/p.log 2>&1
    t2=$(date +%s.%N)
    same=no
    cmp -s $B/s/glstat $B/p/glstat && h5diff -q $B/s/d3plot.h5 $B/p/d3plot.h5 >/dev/null 2>&1 && same=yes
    python3 - $B/s.log $B/p.log "$r" "$t0" "$t1" "$t2" "$same" "$split" "$t1s" $B/stages.md >> $B/table.md <<'PY'
import re, sys
s, p = open(sys.argv[1]).read(), open(sys.argv[2]).read()
r, t0, t1, t2, same = sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6]), sys.argv[7]
split, t1s = sys.argv[8], float(sys.argv[9])
m = re.search(r'contact: \d+ interface\(s\), (\d+) contact nodes, (\d+) bucket sorts[^,]*, wall time '
              r'search ([0-9.E+-]+) s, local search \+ forces ([0-9.E+-]+) s', s)
ncyc = int(re.search(r'normal termination at cycle (\d+)', s).group(1)) + 1
def loop(log):
    w = [float(x) for x in re.findall(r'^\s+\d+\s+\S+\s+\S+\s+\d+\s+([0-9.]+)\s', log, re.M)]
    return w[-1] - w[0] if len(w) > 1 else float('nan')
nn, srt, frc = m.group(1), float(m.group(3)), float(m.group(4))
if split == 'owner':
    print('| %s | 1 | - | %s | %.0f | %.0f | - | - | - | - | %.2f | %.2f | - |' % (r, nn, 1e6*srt/ncyc, 1e6*frc/ncyc, loop(s), t1s - t0))
m1 = re.search(r'per cycle: search \+ forces ([0-9.E+-]+) us \(max over ranks ([0-9.E+-]+)\), contact '
               r'communication ([0-9.E+-]+) us \(max ([0-9.E+-]+)\); of search \+ forces: bucket sorts '
               r'and strips ([0-9.E+-]+) us \(max ([0-9.E+-]+)\), local search, forces and assembly '
               r'([0-9.E+-]+) us \(max ([0-9.E+-]+)\)', p)
m2 = re.search(r'numbers received per rank and cycle .*: mean ([0-9.E+-]+), max ([0-9.E+-]+)', p)
m3 = re.findall(r'slave nodes per rank \(last sort, strip axis \d\):([ 0-9]+)', p)
m4 = re.search(r'bytes sent per rank and cycle, mean \(max\):.* total ([0-9.E+-]+) \(([0-9.E+-]+)\)', p)
g = [float(x) for x in m1.groups()]
print('| %s | 2 | %s | %s | %.0f (max %.0f) | %.0f (max %.0f) | %.0f (max %.0f) | %s | %s | %s | %.2f | %.2f | %s |'
      % (r, split, nn, g[4], g[5], g[6], g[7], g[2], g[3], '%.0f (max %.0f)' % (float(m2.group(1)), float(m2.group(2))) if m2 else '-',
         '%.0f (max %.0f)' % (float(m4.group(1)), float(m4.group(2))) if m4 else '-',
         ' / '.join(x.strip() for x in m3), loop(p), t2 - t1, same))
st = re.search(r'MPI contact stages per cycle \[us\], mean \(max\) over the ranks: (.*)', p)
if st:
    open(sys.argv[10], 'a').write('- run %s, NP 2, %s: %s\n' % (r, split, st.group(1).strip()))
PY
    done
    r=$((r + 1))
done
{ echo ""; echo "Contact stages per cycle [us] at NP 2, mean (max) over the ranks (dynx's end-of-run line):"; echo ""; cat $B/stages.md; } >> $B/table.md
cat $B/table.md
cat $B/table.md >> docs/performance.md
