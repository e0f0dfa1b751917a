#!/bin/sh
# Old commit against new in one run: ns per element-cycle and peak memory of the Taylor bar
# at 10,368 and 82,944 hex8 elements (shared/bench/gen_taylor.py), bin/dynx of this tree
# against bin/dynx built from BENCH_BASE (default HEAD~1) in a temporary git worktree.
# Runs alternate old, new, old, new, ... (RUNS each, default 3) so that a drift of the
# machine's speed hits both alike; the median of each is reported, with the ratio old/new
# (> 1: the new code is faster; the refactor rule is >= 0.98).
#   scripts/bench_compare.sh                 # against HEAD~1
#   BENCH_BASE=0454fea RUNS=5 scripts/bench_compare.sh
set -eu
cd "$(dirname "$0")/.."
base=${BENCH_BASE:-HEAD~1}
runs=${RUNS:-3}
B=build/bench_compare
rev=$(git rev-parse --short "$base")
mkdir -p $B
if [ ! -x $B/old-$rev/bin/dynx ]; then
    rm -rf $B/old-$rev
    git worktree add -f --detach $B/old-$rev "$rev" > /dev/null 2>&1
    (cd $B/old-$rev && make -j2 bin/dynx > build.log 2>&1) || {
        echo "bench_compare: building $rev failed (see $B/old-$rev/build.log)"; exit 1; }
fi
[ -x bin/dynx ] || make -j2 bin/dynx > /dev/null
gen=../shared/bench/gen_taylor.py
[ -f $gen ] || { echo "bench_compare: $gen not found"; exit 2; }
python3 $gen 8 4 54 0.080 $B/taylor_10k.k > /dev/null
python3 $gen 16 8 108 0.020 $B/taylor_83k.k > /dev/null
field() {   # log, what: ns | kib
    case $2 in
    ns) sed -n 's/.*s, \([0-9.eE+-]*\) ns per element-cycle.*/\1/p' "$1" ;;
    kib) sed -n 's/.*peak memory \([0-9]*\) KiB.*/\1/p' "$1" ;;
    esac
}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
echo "| deck | elements | old $rev ns/el-cycle | new $(git rev-parse --short HEAD) ns/el-cycle | old/new | old KiB | new KiB |"
echo "|---|---|---|---|---|---|---|"
for case in taylor_10k:10368 taylor_83k:82944; do
    name=${case%%:*}; ne=${case#*:}
    : > $B/$name.old; : > $B/$name.new; : > $B/$name.oldm; : > $B/$name.newm
    i=0
    while [ $i -lt "$runs" ]; do
        for which in old new; do
            exe=bin/dynx; [ $which = old ] && exe=$B/old-$rev/bin/dynx
            $exe -i $B/$name.k -o $B/out_$which --status 1 > $B/$name.$which.log 2>&1 || {
                echo "bench_compare: $exe on $name failed"; tail -5 $B/$name.$which.log; exit 1; }
            field $B/$name.$which.log ns >> $B/$name.$which
            field $B/$name.$which.log kib >> $B/$name.${which}m
        done
        i=$((i + 1))
    done
    o=$(median < $B/$name.old); n=$(median < $B/$name.new)
    om=$(median < $B/$name.oldm); nm=$(median < $B/$name.newm)
    r=$(awk -v o="$o" -v n="$n" 'BEGIN {printf "%.3f", o/n}')
    echo "| $name | $ne | $o | $n | $r | $om | $nm |"
done
