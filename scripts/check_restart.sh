#!/bin/sh
# Interrupt-and-continue check (issue 7): a run stopped at a checkpoint and continued with
# -r must give byte-identical time histories (glstat, nodout), an identical XDMF file and
# plot states equal to the uninterrupted run with zero tolerance (h5diff exit 0).
#
#   sh scripts/check_restart.sh DECK REFDIR WORKDIR [modes...]
#
# REFDIR holds the uninterrupted run of DECK. Modes (default: cycle usr1):
#   cycle    SIGTERM raised by dynx itself at a random cycle (--raise-at-cycle N:TERM: the
#            real handler path, without timing luck)
#   sigterm  a real SIGTERM after a random delay (0.2 .. 1.2 s; retried shorter if the run
#            ended first), exit code 5 expected, then continue from the dump
#   walltime --walltime 0.8: a dump and exit 5 before 0.8 s of wall time, then continue
#   usr1     SIGUSR1 at a random cycle (--raise-at-cycle N:USR1: dump and go on); the run
#            must end normally with
#            the reference files, then a continue from that dump over the finished output
#            (the states and lines written after the dump are dropped and rewritten) must
#            give the same files again
# Random choices come from DYNX_RESTART_SEED when set (printed either way).
# DYNX_RESTART_WINDOW="LO HI" draws the stop/dump cycles from LO..HI only (e.g. the cycles in
# which a contact is closed or a rigid body is driven), clamped to 1..(cycles - 1).
set -u
DYNX=${DYNX:-bin/dynx}
deck=$1; ref=$2; work=$3; shift 3
modes=${*:-cycle usr1}
seed=${DYNX_RESTART_SEED:-$(od -An -N2 -tu2 /dev/urandom | tr -d ' ')}
echo "check_restart: seed $seed"
fail=0

if [ -f "$ref/glstat" ]; then
    ncyc=$(awk '/^ *[-+.0-9]/ {c=$2} END {print c+0}' "$ref/glstat")
else   # conserving rigid-body solver: emcstat, cycle in column 1
    ncyc=$(awk '/^ *[-+.0-9]/ {c=$1} END {print c+0}' "$ref/emcstat")
fi
if [ "$ncyc" -lt 3 ]; then echo "check_restart: reference has $ncyc cycles"; exit 1; fi

lo=1; hi=$((ncyc - 1))
if [ -n "${DYNX_RESTART_WINDOW:-}" ]; then
    set -- $DYNX_RESTART_WINDOW
    [ "$1" -gt "$lo" ] && lo=$1
    [ "$2" -lt "$hi" ] && hi=$2
    if [ "$lo" -gt "$hi" ]; then echo "check_restart: window $DYNX_RESTART_WINDOW outside 1..$((ncyc - 1))"; exit 1; fi
    echo "check_restart: cycles drawn from $lo..$hi"
fi

rnd() {  # rnd LO HI K -> integer in [LO, HI], the K-th draw from the seed
    awk -v s="$seed" -v k="$3" -v lo="$1" -v hi="$2" \
        'BEGIN { srand(s + 7919 * k); print int(lo + rand() * (hi - lo + 1)) }'
}

same() {  # same DIR LABEL
    ok=1
    for f in glstat nodout rbdout rcforc emcstat matsum spcforc sleout elout ncforc d3plot.xdmf; do
        if [ -f "$ref/$f" ] || [ -f "$1/$f" ]; then
            if ! cmp -s "$ref/$f" "$1/$f"; then echo "  $2: $f differs"; ok=0; fi
        fi
    done
    if ! h5diff -q "$ref/d3plot.h5" "$1/d3plot.h5"; then echo "  $2: d3plot.h5 differs (h5diff)"; ok=0; fi
    if ! cmp -s "$ref/d3plot.h5" "$1/d3plot.h5"; then echo "  $2: d3plot.h5 not byte-equal (cmp)"; ok=0; fi
    if [ $ok = 1 ]; then echo "  $2: identical (glstat, nodout, rbdout, rcforc, emcstat, matsum, spcforc, sleout, elout, ncforc, xdmf byte-equal (those written); h5diff 0 differences; d3plot.h5 byte-equal)"; else fail=1; fi
}

last_dump() { ls "$1"/d3dump*.h5 2>/dev/null | sort | tail -1; }

for m in $modes; do
    d=$work/$m
    rm -rf "$d"; mkdir -p "$d"
    case $m in
    cycle)
        n=$(rnd $lo $hi 1)
        "$DYNX" -i "$deck" -o "$d" --raise-at-cycle "$n:TERM" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 5 ]; then echo "  cycle: exit $rc (expected 5) at --stop-at-cycle $n"; fail=1; continue; fi
        grep -q 'continue with: dynx' "$d/run1.log" || { echo "  cycle: no 'continue with' message"; fail=1; }
        ;;
    sigterm)
        rc=0
        for ms in $(rnd 200 1200 2) 100 30; do
            rm -rf "$d"; mkdir -p "$d"
            "$DYNX" -i "$deck" -o "$d" > "$d/run1.log" 2>&1 &
            pid=$!
            sleep "$(echo "$ms" | awk '{printf "%.3f", $1/1000}')"
            kill -TERM $pid 2>/dev/null
            wait $pid; rc=$?
            [ $rc -ne 0 ] && break
        done
        if [ $rc -ne 5 ]; then echo "  sigterm: exit $rc (expected 5) after ${ms} ms"; fail=1; continue; fi
        n=$(sed -n 's/.*stopped by SIGTERM at cycle \([0-9]*\).*/\1/p' "$d/run1.log")
        echo "  sigterm: stopped at cycle $n after ${ms} ms"
        ;;
    walltime)
        "$DYNX" -i "$deck" -o "$d" --walltime 0.8 > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 5 ]; then echo "  walltime: exit $rc (expected 5) with --walltime 0.8"; fail=1; continue; fi
        grep -q 'stopped by the wall-clock limit' "$d/run1.log" || { echo "  walltime: no limit message"; fail=1; }
        n=$(sed -n 's/.*stopped by the wall-clock limit.* at cycle \([0-9]*\),.*/\1/p' "$d/run1.log")
        ;;
    usr1)
        n=$(rnd $lo $hi 3)
        "$DYNX" -i "$deck" -o "$d" --raise-at-cycle "$n:USR1" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 0 ]; then echo "  usr1: exit $rc (expected 0)"; fail=1; continue; fi
        grep -q 'SIGUSR1: restart dump' "$d/run1.log" || { echo "  usr1: no dump message"; fail=1; continue; }
        same "$d" "usr1 (run that dumped and went on)"
        ;;
    esac
    dump=$(last_dump "$d")
    if [ -z "$dump" ]; then echo "  $m: no d3dump file in $d"; fail=1; continue; fi
    "$DYNX" -i "$deck" -o "$d" -r "$dump" > "$d/run2.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then echo "  $m: continue run exit $rc"; cat "$d/run2.log"; fail=1; continue; fi
    same "$d" "$m (stopped at cycle $n of $ncyc, continued from $(basename "$dump"))"
done
exit $fail
