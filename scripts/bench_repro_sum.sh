#!/bin/sh
# make bench: the cost of the exact reproducible sums (dx_repro_sum, docs/history.md
# "Reproducible sums").
#  1. ns per value of one exact deposit against a plain double sum (build/release/bench/
#     repro_sum_bench: 1e6 values from 1e-30 to 1e12 of both signs, best of 7 rounds).
#  2. the whole run, old binary (OLD, default /work/main/bin/dynx: the gathered fixed-order
#     sums) against new (bin/dynx), alternating in one run, best of REPS (default 2) wall
#     times ('dynx: wall time'), serial and NP 2: the Taylor bar of 10 240 elements
#     (gen_taylor.py 8 4 54, 0.080 ms: glstat 80 times), and the 1e5-element box
#     (scripts/gen_box_deck.py, 100 cycles) with glstat at every cycle (the worst case:
#     an energy event every cycle) and as generated (energies at the end only).
#     Each run's CPU time (user + system, /usr/bin/time; for NP 2 summed over the ranks,
#     which poll while they wait) is reported beside the wall time: on a shared machine the
#     CPU time of a serial run is the steadier measure.
# Writes build/bench/repro/repro_sum.md (a dated table). NEW, OLD, REPS, DECKS override.
set -e
cd "$(dirname "$0")/.."
OLD=${OLD:-/work/main/bin/dynx}
NEW=${NEW:-bin/dynx}
DECKS=${DECKS:-taylor_10k box_glstat box}
REPS=${REPS:-2}
B=build/bench/repro
mkdir -p $B
MPIRUN="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
build/release/bench/repro_sum_bench 1000000 7 > $B/micro.log
gen=../shared/bench/gen_taylor.py
[ -f $gen ] || gen=/work/shared/bench/gen_taylor.py
python3 $gen 8 4 54 0.080 $B/taylor_10k.k > /dev/null
python3 scripts/gen_box_deck.py $B/box.k 50 50 40 100 > /dev/null
sed 's/^\*END$/*DATABASE_GLSTAT\n1.0E-9\n*END/' $B/box.k > $B/box_glstat.k
once() {   # binary np deck -> "wall cpu" of one run
    rm -rf $B/out       # (an MPI run would take another deck's rank files found there)
    if [ "$2" = 1 ]; then
        /usr/bin/time -f "%e %U %S" -o $B/time.txt "$1" -i "$3" -o $B/out > $B/run.log 2>&1
    else
        /usr/bin/time -f "%e %U %S" -o $B/time.txt $MPIRUN -np "$2" "$1" -i "$3" -o $B/out \
            > $B/run.log 2>&1
    fi
    grep -q "normal termination" $B/run.log || { echo "bench_repro_sum: run failed ($1 np $2 $3)" >&2; cat $B/run.log >&2; exit 1; }
    awk '{ printf "%s %.3f\n", $1, $2 + $3 }' $B/time.txt
}
minof() {   # best (smallest) wall and cpu of two "wall cpu" pairs
    awk -v a="$1" -v b="$2" 'BEGIN { if (a == "") { print b; exit }
        split(a, x, " "); split(b, y, " ");
        printf "%s %s\n", (y[1] + 0 < x[1] + 0) ? y[1] : x[1], (y[2] + 0 < x[2] + 0) ? y[2] : x[2] }'
}
{
echo ""
echo "### make bench: exact reproducible sums, $(date -u +%Y-%m-%d), commit $rev, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo ""
awk '/^plain/ {p=$2} /^exact/ {e=$2} /^ratio/ {r=$2} /^value/ {v=$2}
     END { printf "deposit: plain sum %.2f ns per value, exact %.2f ns per value (%.1f x); rounding one sum %.0f ns\n\n", p, e, r, v }' $B/micro.log
echo "| deck | NP | old wall [s] | new wall [s] | new/old | old CPU [s] | new CPU [s] | new/old |"
echo "|---|---|---|---|---|---|---|---|"
} > $B/repro_sum.md
for deck in $DECKS; do
    for np in 1 2; do
        to=""; tn=""; r=0
        while [ $r -lt "$REPS" ]; do     # old and new alternate; best of each
            to=$(minof "$to" "$(once "$OLD" $np $B/$deck.k)")
            tn=$(minof "$tn" "$(once "$NEW" $np $B/$deck.k)")
            r=$((r + 1))
        done
        case "$to:$tn" in
            " "*|*": "*|:*|*:) echo "bench_repro_sum: a run failed ($deck, NP $np)"; exit 1 ;;
        esac
        awk -v d=$deck -v np=$np -v o="$to" -v n="$tn" 'BEGIN { split(o, a, " "); split(n, b, " ");
            printf "| %s | %d | %.2f | %.2f | %.3f | %.2f | %.2f | %.3f |\n", d, np, a[1], b[1],
                   b[1] / a[1], a[2], b[2], b[2] / a[2] }' >> $B/repro_sum.md
    done
done
cat $B/repro_sum.md
