#!/bin/sh
# MPI test runner: scripts/run_mpi_tests.sh [prog...]
#   (default build/debug/tests/mpi_par_test build/debug/tests/mpi_par_model_test)
# Runs each MPI test program serially (no mpirun: MPI is never initialized), then under
# `mpirun --oversubscribe -np 2, 3, 4` (plus --allow-run-as-root when run as root), then
# checks with mpi_par_test that a rank calling par_abort stops every rank with exit code 3
# and a message naming the rank. Each run has a time limit (MPI_TEST_TIMEOUT seconds, default 300), so a
# hang is a failure. Closes with 'N passed, N failed'; exits 1 if anything failed.
set -u
cd "$(dirname "$0")/.." || exit 2
if [ $# -eq 0 ]; then
    set -- build/debug/tests/mpi_par_test build/debug/tests/mpi_par_model_test
fi
TIMEOUT=${MPI_TEST_TIMEOUT:-300}
MPIRUN="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
tmp=${TMPDIR:-/tmp}/dynx_mpi.$$
trap 'rm -f "$tmp" "$tmp.err"' EXIT INT TERM
tp=0
tf=0

# run_one LABEL CMD...: runs, prints the output, adds its summary line to the totals
run_one() {
    label=$1
    shift
    echo "== $label"
    timeout "$TIMEOUT" "$@" >"$tmp" 2>"$tmp.err"
    rc=$?
    cat "$tmp"
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$tmp" | tail -n 1)
    if [ -z "$line" ]; then
        echo "FAIL $label: no summary line (exit code $rc)"
        cat "$tmp.err"
        tf=$((tf + 1))
        return
    fi
    p=${line%% passed*}
    f=${line#*passed, }
    f=${f%% failed*}
    tp=$((tp + p))
    tf=$((tf + f))
    if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $label: exit code $rc"
        cat "$tmp.err"
        tf=$((tf + 1))
    fi
}

for prog in "$@"; do
    if [ ! -x "$prog" ]; then
        echo "FAIL $prog: not found (make $prog)"
        tf=$((tf + 1))
        continue
    fi
    run_one "$prog (serial, no mpirun)" "$prog"
    for np in 2 3 4; do
        run_one "$MPIRUN -np $np $prog" $MPIRUN -np $np "$prog"
    done
done
prog=build/debug/tests/mpi_par_test

echo "== $MPIRUN -np 3 $prog abort"
timeout "$TIMEOUT" $MPIRUN -np 3 "$prog" abort >"$tmp" 2>"$tmp.err"
rc=$?
if [ $rc -eq 3 ] && grep -q 'rank 2 of 3: deliberate abort by the test' "$tmp.err"; then
    echo "  PASS par_abort on rank 2 stops all 3 ranks, exit code 3, message names the rank"
    tp=$((tp + 1))
else
    echo "  FAIL par_abort on rank 2: exit code $rc (expected 3); stderr:"
    cat "$tmp.err"
    tf=$((tf + 1))
fi
echo "$tp passed, $tf failed"
[ $tf -eq 0 ] || exit 1
exit 0
