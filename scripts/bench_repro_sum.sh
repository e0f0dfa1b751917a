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
# Writes build/bench/repro_sum.md (a dated table). The machine is shared: compare ratios.
set -e
cd "$(dirname "$0")/.."
OLD=${OLD:-/work/main/bin/dynx}
NEW=bin/dynx
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
once() {   # binary np deck -> wall time of one run
    if [ "$2" = 1 ]; then
        "$1" -i "$3" -o $B/out > $B/run.log 2>&1
    else
        $MPIRUN -np "$2" "$1" -i "$3" -o $B/out > $B/run.log 2>&1
    fi
    t=$(sed -n 's/.*dynx: wall time \([0-9.eE+-]*\) s.*/\1/p' $B/run.log | tail -1)
    [ -n "$t" ] || { echo "bench_repro_sum: no wall time ($1 np $2 $3)" >&2; cat $B/run.log >&2; exit 1; }
    echo "$t"
}
minof() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b + 0 < a + 0) print b; else print a }'; }
{
echo ""
echo "### make bench: exact reproducible sums, $(date -u +%Y-%m-%d), commit $rev, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo ""
awk '/^plain/ {p=$2} /^exact/ {e=$2} /^ratio/ {r=$2} /^value/ {v=$2}
     END { printf "deposit: plain sum %.2f ns per value, exact %.2f ns per value (%.1f x); rounding one sum %.0f ns\n\n", p, e, r, v }' $B/micro.log
echo "| deck | NP | old [s] | new [s] | new/old |"
echo "|---|---|---|---|---|"
} > $B/repro_sum.md
for deck in taylor_10k box_glstat box; do
    for np in 1 2; do
        to=""; tn=""; r=0
        while [ $r -lt "$REPS" ]; do     # old and new alternate; best of each
            to=$(minof "$to" "$(once "$OLD" $np $B/$deck.k)")
            tn=$(minof "$tn" "$(once "$NEW" $np $B/$deck.k)")
            r=$((r + 1))
        done
        case "$to:$tn" in
            :*|*:|*[!0-9.eE+:-]*) echo "bench_repro_sum: a run failed ($deck, NP $np)"; exit 1 ;;
        esac
        awk -v d=$deck -v np=$np -v o="$to" -v n="$tn" \
            'BEGIN { printf "| %s | %d | %.3f | %.3f | %.3f |\n", d, np, o, n, n/o }' >> $B/repro_sum.md
    done
done
cat $B/repro_sum.md
