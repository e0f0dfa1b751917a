#!/bin/sh
# Largest-input timings of issue 15 (docs/errors.md, "Issue 15: acceptance audit"): read and
# set-up of a 2 MB line, 208 376 history nodes and 20 000 parts, each timed with
# 'DYNX -i DECK --check' (best of RUNS, wall seconds), at the full size and at half size for
# the two scalable decks (linear cost: the full/half ratio is about 2; quadratic: about 4).
# A measurement, not a test: it prints a table and always exits 0 unless a run fails.
#   scripts/large_input_timings.sh [DYNX] [RUNS]     (defaults bin/dynx, 3)
set -u
cd "$(dirname "$0")/.." || exit 2
DYNX=${1:-bin/dynx}
RUNS=${2:-3}
work=build/large_inputs
mkdir -p "$work/full" "$work/half"
python3 scripts/gen_large_input_decks.py "$work/full" 1.0 || exit 2
python3 scripts/gen_large_input_decks.py "$work/half" 0.5 || exit 2
# best DECK: the shortest wall time of RUNS runs of --check
best() {
    b=""
    i=0
    while [ $i -lt "$RUNS" ]; do
        t0=$(date +%s.%N)
        "$DYNX" -i "$1" --check > "$work/check.log" 2>&1 || { echo "run failed: $1" >&2; cat "$work/check.log" >&2; exit 1; }
        t1=$(date +%s.%N)
        b=$(python3 -c "import sys; t=float(sys.argv[2])-float(sys.argv[1]); b=sys.argv[3]; print('%.3f' % (t if not b else min(t, float(b))))" "$t0" "$t1" "$b")
        i=$((i + 1))
    done
    echo "$b"
}
echo "| input | size | --check wall [s], best of $RUNS |"
echo "|---|---|---|"
for k in longline history parts; do
    sz=$(wc -c < "$work/full/$k.k")
    echo "| $k.k | $sz bytes | $(best "$work/full/$k.k") |"
    if [ "$k" != longline ]; then
        sz=$(wc -c < "$work/half/$k.k")
        echo "| $k.k, half size | $sz bytes | $(best "$work/half/$k.k") |"
    fi
done
