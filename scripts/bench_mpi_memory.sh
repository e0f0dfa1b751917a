#!/bin/sh
# Peak resident memory per rank of an MPI run against the serial run (make bench; the
# numbers are recorded in docs/performance.md, "Memory per rank").
#   sh scripts/bench_mpi_memory.sh [DYNX_OTHER]
# Box of 50 x 50 x 40 = 100 000 hex8 (scripts/gen_box_deck.py, 100 cycles) with a plot
# state every 0.004 ms (6 states). Runs bin/dynx serially and with mpirun -np 2, each
# process under /usr/bin/time -v ("Maximum resident set size"), and prints one table row
# per binary: serial RSS, rank 0 and rank 1 RSS at NP 2, their ratio to the serial RSS.
# DYNX_OTHER: a second binary measured the same way (e.g. a build of an older commit).
set -u
cd "$(dirname "$0")/.."
B=build/bench/mem
mkdir -p $B
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
deck=$B/box100k.k
if [ ! -f $deck ]; then
    python3 scripts/gen_box_deck.py $deck.tmp 50 50 40 100 || exit 1
    python3 - $deck.tmp <<'PY' || exit 1
import sys
p = sys.argv[1]
s = open(p).read()
s = s.replace('*CONTROL_TIMESTEP\n', '*DATABASE_BINARY_D3PLOT\n    0.0040\n*CONTROL_TIMESTEP\n', 1)
open(p, 'w').write(s)
PY
    mv $deck.tmp $deck
fi
rss() { sed -n 's/.*Maximum resident set size (kbytes): \([0-9]*\).*/\1/p' "$1"; }
echo "| binary | serial [KiB] | NP 2 rank 0 [KiB] | NP 2 rank 1 [KiB] | rank 0 / serial | rank 1 / serial |"
echo "|---|---|---|---|---|---|"
for exe in bin/dynx ${1:-}; do
    tag=$(echo "$exe" | tr '/' '_')
    rm -rf $B/$tag.ser $B/$tag.np2
    /usr/bin/time -v -o $B/$tag.ser.time $exe -i $deck -o $B/$tag.ser --status 2 > $B/$tag.ser.log 2>&1 \
        || { echo "serial run of $exe failed"; tail $B/$tag.ser.log; exit 1; }
    mkdir -p $B/$tag.np2
    bin/dynx-part $deck -n 2 -o $B/$tag.np2 > /dev/null || exit 1
    mpirun $opts -np 2 sh -c "exec /usr/bin/time -v -o $B/$tag.np2.time.\$OMPI_COMM_WORLD_RANK $exe -i $deck -o $B/$tag.np2 --status 2" \
        > $B/$tag.np2.log 2>&1 || { echo "NP 2 run of $exe failed"; tail $B/$tag.np2.log; exit 1; }
    s=$(rss $B/$tag.ser.time); r0=$(rss $B/$tag.np2.time.0); r1=$(rss $B/$tag.np2.time.1)
    h5diff -q $B/$tag.ser/d3plot.h5 $B/$tag.np2/d3plot.h5 || echo "$exe: NP 2 d3plot.h5 differs from serial"
    echo "| $exe | $s | $r0 | $r1 | $(python3 -c "print('%.2f' % ($r0 / $s))") | $(python3 -c "print('%.2f' % ($r1 / $s))") |"
done
