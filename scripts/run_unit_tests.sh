#!/bin/sh
# Unit-test runner: scripts/run_unit_tests.sh prog...
# Runs each unit-test program, prints its output, and closes with the total
# 'N passed, N failed' summed from the programs' own last summary lines. A program that
# exits non-zero without failing checks (a crash, an error stop) counts as one failure.
# Exits 1 if anything failed.
set -u
tp=0
tf=0
tmp=${TMPDIR:-/tmp}/dynx_unit.$$
trap 'rm -f "$tmp"' EXIT INT TERM
for prog in "$@"; do
    echo "== $prog"
    if [ ! -x "$prog" ]; then
        echo "FAIL $prog: not found or not executable"
        tf=$((tf + 1))
        continue
    fi
    "$prog" >"$tmp" 2>&1
    rc=$?
    cat "$tmp"
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$tmp" | tail -n 1)
    if [ -z "$line" ]; then
        echo "FAIL $prog: no summary line (exit code $rc)"
        tf=$((tf + 1))
        continue
    fi
    p=${line%% passed*}
    f=${line#*passed, }
    f=${f%% failed*}
    tp=$((tp + p))
    tf=$((tf + f))
    if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $prog: exit code $rc"
        tf=$((tf + 1))
    fi
done
echo "$tp passed, $tf failed"
[ $tf -eq 0 ] || exit 1
exit 0
