#!/bin/sh
# Old against new binary on one contact deck, alternating (issue 22, parallel contact): for
# each repetition and each NP, the old binary then the new one, each timed by /usr/bin/time
# (wall seconds; CPU = user + system of mpirun and all its ranks, or of the serial run at
# NP 1). NP 1 runs the binary without mpirun (the serial path); NP > 1 with mpirun
# --oversubscribe. Checks that every run's glstat equals the first run's (cmp). Prints a
# markdown table and, per binary and NP, the median wall and CPU over the repetitions.
#   OLD=build/old/dynx NEW=bin/dynx DECK=deck.k NPS="1 2 3" REPS=3 sh scripts/bench_contact_ab.sh
# On a shared machine compare the two columns of one row pair only; CPU is the steadier one
# (a rank waiting in MPI spins in sched_yield, which counts as system time).
set -e
cd "$(dirname "$0")/.."
OLD=${OLD:-build/old/dynx}
NEW=${NEW:-bin/dynx}
DECK=${DECK:?DECK=deck.k}
NPS=${NPS:-1 2 3}
REPS=${REPS:-3}
B=${B:-build/bench_contact_ab}
mkdir -p "$B"
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
: > "$B/runs.txt"
echo "deck $DECK, old $OLD, new $NEW, $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1 /proc/loadavg)"
echo ""
echo "| rep | NP | binary | wall [s] | CPU [s] | sorts (skipped) | contact bytes sent per rank and cycle | glstat |"
echo "|---|---|---|---|---|---|---|---|"
ref=""
r=1
while [ "$r" -le "$REPS" ]; do
    for np in $NPS; do
        for tag in old new; do
            if [ $tag = old ]; then bin=$OLD; else bin=$NEW; fi
            out=$B/$tag.np$np
            rm -rf "$out"
            if [ "$np" = 1 ]; then
                /usr/bin/time -f "%e %U %S" -o "$B/time" $bin -i "$DECK" -o "$out" > "$B/log" 2>&1
            else
                /usr/bin/time -f "%e %U %S" -o "$B/time" mpirun $opts -np "$np" $bin -i "$DECK" \
                    -o "$out" > "$B/log" 2>&1
            fi
            set -- $(tail -n 1 "$B/time")
            wall=$1
            cpu=$(echo "$2 $3" | awk '{printf "%.2f", $1 + $2}')
            srt=$(sed -n 's/.*contact nodes, \([0-9]*\) bucket sorts (\([0-9]*\) more skipped.*/\1 (\2)/p' "$B/log")
            byt=$(sed -n 's/.*bytes sent per rank and cycle, mean (max):.* total \([0-9.E+-]*\) .*/\1/p' "$B/log")
            [ -n "$ref" ] || ref=$out/glstat
            same=no
            cmp -s "$ref" "$out/glstat" && same=same
            echo "| $r | $np | $tag | $wall | $cpu | $srt | ${byt:--} | $same |"
            echo "$tag $np $wall $cpu" >> "$B/runs.txt"
        done
    done
    r=$((r + 1))
done
echo ""
echo "| NP | old wall (median) | new wall | old CPU (median) | new CPU | new/old CPU |"
echo "|---|---|---|---|---|---|"
for np in $NPS; do
    python3 - "$B/runs.txt" "$np" <<'PY'
import sys, statistics as st
runs = [l.split() for l in open(sys.argv[1])]
np_ = sys.argv[2]
m = {}
for tag in ('old', 'new'):
    w = [float(x[2]) for x in runs if x[0] == tag and x[1] == np_]
    c = [float(x[3]) for x in runs if x[0] == tag and x[1] == np_]
    m[tag] = (st.median(w), st.median(c))
print('| %s | %.2f | %.2f | %.2f | %.2f | %.2f |' % (np_, m['old'][0], m['new'][0], m['old'][1],
      m['new'][1], m['new'][1] / m['old'][1]))
PY
done
