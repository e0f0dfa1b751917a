#!/bin/sh
# Largest-input timings of issue 15 (docs/errors.md, "Issue 15: acceptance audit"): read and
# set-up of a 2 MB line, 208 376 history nodes and 20 000 parts, each timed with
# 'DYNX -i DECK --check' (the run of least CPU time of RUNS; its wall and CPU seconds), at
# the full size and at half size for
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
# best DECK: "wall cpu" of the run with the least CPU time (user + system, from wait4) of
# RUNS runs of --check (CPU time is what the input costs; wall time on a shared machine also
# holds the waiting for a core)
best() {
    python3 - "$DYNX" "$1" "$RUNS" "$work/check.log" <<'PY'
import os, resource, subprocess, sys, time
dynx, deck, runs, log = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
best = None
for _ in range(runs):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    with open(log, 'w') as f:
        rc = subprocess.call([dynx, '-i', deck, '--check'], stdout=f, stderr=subprocess.STDOUT)
    t1 = time.time()
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if rc != 0:
        sys.stderr.write(open(log).read())
        sys.exit('run failed: %s (exit %d)' % (deck, rc))
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    if best is None or cpu < best[1]:
        best = (t1 - t0, cpu)
print('%.3f | %.3f' % best)
PY
}
echo "| input | size | --check wall [s] | --check CPU [s], least of $RUNS |"
echo "|---|---|---|---|"
for k in longline history parts; do
    sz=$(wc -c < "$work/full/$k.k")
    echo "| $k.k | $sz bytes | $(best "$work/full/$k.k") |"
    [ "$k" = longline ] && continue
    sz=$(wc -c < "$work/half/$k.k")
    echo "| $k.k, half size | $sz bytes | $(best "$work/half/$k.k") |"
done
