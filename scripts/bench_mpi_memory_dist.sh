#!/bin/sh
# Peak resident memory (VmHWM, /usr/bin/time -v "Maximum resident set size") of every rank
# at NP 1, 2, 3, 4 against the serial run, for two builds in one run: the current one
# (bin/dynx: ranks build their sub-model from the rank file, issue 22 stage 1) and an
# older one (the replicated path), each with its own dynx-part writing the rank files
# first (mpirun ... dynx -i deck --part DIR). docs/performance.md "Distributed memory".
#   sh scripts/bench_mpi_memory_dist.sh OLD_BIN_DIR [NX NY NZ [NCYC]]
# OLD_BIN_DIR holds dynx and dynx-part of the older build (copied to build/bench/dist/old
# first, so a rebuild during the run does not touch them). Default box 50 x 50 x 40 =
# 100 000 hex8 (scripts/gen_box_deck.py), 20 cycles. Prints one markdown row per build and
# NP: serial KiB, rank 0, smallest and largest rank KiB, largest / (serial / NP).
set -u
cd "$(dirname "$0")/.."
old=${1:?usage: bench_mpi_memory_dist.sh OLD_BIN_DIR [NX NY NZ [NCYC]]}
nx=${2:-50}; ny=${3:-50}; nz=${4:-40}; nc=${5:-20}
B=build/bench/dist
mkdir -p $B/old $B/new
cp "$old/dynx" "$old/dynx-part" $B/old/ || exit 1
cp bin/dynx bin/dynx-part $B/new/ || exit 1
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
deck=$B/box_${nx}_${ny}_${nz}.k
[ -f $deck ] || python3 scripts/gen_box_deck.py $deck $nx $ny $nz $nc || exit 1
rss() { sed -n 's/.*Maximum resident set size (kbytes): \([0-9]*\).*/\1/p' "$1"; }
echo "box $nx x $ny x $nz = $((nx * ny * nz)) hex8, $nc cycles"
echo "| build | NP | serial [KiB] | rank 0 [KiB] | smallest rank [KiB] | largest rank [KiB] | largest / (serial/NP) |"
echo "|---|---|---|---|---|---|---|"
for b in old new; do
    d=$B/$b
    rm -rf $d/ser
    /usr/bin/time -v -o $d/ser.time $d/dynx -i $deck -o $d/ser > $d/ser.log 2>&1 \
        || { echo "serial run of $b failed"; tail $d/ser.log; exit 1; }
    s=$(rss $d/ser.time)
    for np in 1 2 3 4; do
        o=$d/np$np
        rm -rf $o; mkdir -p $o
        $d/dynx-part $deck -n $np -o $o/part > $o/part.log 2>&1 || { echo "dynx-part $b $np failed"; exit 1; }
        mpirun $opts -np $np sh -c "exec /usr/bin/time -v -o $o/time.\$OMPI_COMM_WORLD_RANK $d/dynx -i $deck -o $o --part $o/part" \
            > $o/log 2>&1 || { echo "NP $np run of $b failed"; tail $o/log; exit 1; }
        h5diff -q $d/ser/d3plot.h5 $o/d3plot.h5 > /dev/null 2>&1 || echo "$b NP $np: d3plot.h5 differs from serial"
        all=$(for r in $(seq 0 $((np - 1))); do rss $o/time.$r; done)
        r0=$(rss $o/time.0)
        mn=$(echo "$all" | sort -n | head -1); mx=$(echo "$all" | sort -n | tail -1)
        echo "| $b | $np | $s | $r0 | $mn | $mx | $(python3 -c "print('%.2f' % ($mx / ($s / $np)))") |"
    done
done
