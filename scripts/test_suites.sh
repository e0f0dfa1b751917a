#!/bin/sh
# make test after the build: runs every suite in turn (a failing suite does not stop the
# others), shows each suite's output, and ends with one line 'N passed, N failed' summed
# over the suites: a suite that prints 'N passed, M failed' counts those; a suite that does
# not (fuzz, disk full, kill -9 checks) counts as 1 passed or 1 failed by its exit code.
# Exits 1 if anything failed. Arguments: the unit-test programs, then '--', then the MPI
# test programs.
set -u
cd "$(dirname "$0")/.." || exit 2
unit=""; mpi=""; seen=0
for a in "$@"; do
    if [ "$a" = "--" ]; then seen=1; continue; fi
    if [ $seen -eq 0 ]; then unit="$unit $a"; else mpi="$mpi $a"; fi
done
tp=0; tf=0; bad=""
log=${TMPDIR:-/tmp}/dynx_suite.$$
trap 'rm -f "$log" "$log.rc"' EXIT INT TERM
suite() {   # name, command...
    name=$1; shift
    echo "== $name"
    { "$@"; echo $? > "$log.rc"; } 2>&1 | tee "$log"     # shown as it runs
    rc=$(cat "$log.rc")
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -1)
    if [ -n "$line" ]; then
        p=${line%% passed*}; f=${line#*passed, }; f=${f%% failed*}
    elif [ $rc -eq 0 ]; then
        p=1; f=0
    else
        p=0; f=1
    fi
    [ $rc -ne 0 ] && [ "$f" -eq 0 ] && f=1     # a crash with no failure counted
    tp=$((tp + p)); tf=$((tf + f))
    [ "$f" -gt 0 ] && bad="$bad $name"
}
suite layers python3 scripts/check_layers.py
suite keywords-doc python3 scripts/check_keywords_doc.py
# documented study numbers against reruns of the cheap rows and generated blocks (issue 23)
suite study-docs /usr/bin/python3 scripts/doc_numbers.py --check
# shellcheck disable=SC2086
suite unit sh scripts/run_unit_tests.sh $unit
# shellcheck disable=SC2086
suite mpi sh scripts/run_mpi_tests.sh $mpi
suite partition sh scripts/run_partition_tests.sh
suite regression sh scripts/run_regression.sh
suite regression-runner sh scripts/test_run_regression.sh
suite diskfull sh scripts/diskfull_check.sh
suite fuzz python3 scripts/fuzz_decks.py --count 2000 --seed 7 --jobs 2 --harness bin/dynx-fuzz-debug --dynx bin/dynx-debug
suite fuzz-proc python3 scripts/fuzz_decks.py --count 200 --seed 7 --jobs 2 --restart-share 0.5 --workdir build/fuzz-proc
suite kill9 python3 scripts/kill9_check.py --runs 20 --seed 7
suite kill9-sweep-dump python3 scripts/kill9_sweep.py --endtim 0.009 --target d3dump02 --stride 7
suite kill9-sweep python3 scripts/kill9_sweep.py --workdir build/kill9_sweep_sample --stride 23
[ -n "$bad" ] && echo "failed suites:$bad"
echo "$tp passed, $tf failed"
[ "$tf" -eq 0 ]
