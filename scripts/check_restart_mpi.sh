#!/bin/sh
# Interrupt-and-continue of MPI runs (issue 7, last item): an MPI run stopped at a checkpoint
# and continued with `mpirun -np NP dynx -r <manifest>` must give byte-identical glstat,
# nodout, rbdout, rcforc (when the deck writes them), XDMF and d3plot.h5 (cmp, and h5diff
# with zero differences) against REFDIR, the serial run of DECK (the uninterrupted MPI run
# equals the serial run: mpi_* cases). After every stop (cycle, sigterm, mpirun, walltime)
# the combined d3plot.h5 + XDMF must hold the states the stop message names (count, last
# time; the earlier states h5diff-equal to the reference's).
#
#   sh scripts/check_restart_mpi.sh DECK REFDIR WORKDIR NP [modes...]
#
# Modes (default: cycle usr1):
#   cycle    SIGTERM raised at a random cycle on one random rank only (--raise-at-cycle
#            N:TERM@R): the other ranks learn it through the dt reduction; exit 5 expected
#   sigterm  a real SIGTERM to one rank's process (not mpirun) a random 0.05 .. 0.8 s after
#            the first status line (retried shorter if the run ended first); exit 5 expected
#   mpirun   a real SIGTERM to mpirun itself (Open MPI forwards it to every rank) a random
#            0.05 .. 0.8 s after the first status line: every rank dumps; mpirun's own exit
#            code is then 1 (Open MPI's), so the check is the message and the dump set
#   walltime --walltime 1.0 (each rank's own clock; the decision is collective), exit 5
#   usr1     SIGUSR1 at a random cycle on one random rank: every rank dumps, the run ends
#            normally with the reference files; then a continue from that dump over the
#            finished output must give the same files again
#   serial   a serial run stopped at a random cycle, continued on NP ranks from its dump
#   periodic the deck plus *DATABASE_BINARY_RUNRSF (CYCL = cycles/5 + 7, NR 1) and
#            *DATABASE_BINARY_D3DUMP (CYCL = cycles/3): the run must give the reference
#            files, runrsf.h5 must name NP parts that are on disk and the superseded
#            runrsf parts must be gone; then continued from runrsf.h5: the same files again
#   errors   (after cycle) the dump set continued with NP+1 ranks and serially (exit 2),
#            with another deck (exit 2), with one part missing and one part damaged
#            (exit 4, the message names the rank and the part file)
# Random choices come from DYNX_RESTART_SEED when set (printed either way).
# DYNX_RESTART_WINDOW="LO HI" draws the cycles of cycle, usr1 and serial from LO..HI.
# Every run that ends normally must also print the serial run's final energies, work sums
# and momentum as IEEE bits (DYNX_ENERGY_BITS=1; one extra serial run into WORKDIR/bits).
set -u
DYNX=${DYNX:-bin/dynx}
deck=$1; ref=$2; work=$3; np=$4; shift 4
deck0=$deck
modes=${*:-cycle usr1}
seed=${DYNX_RESTART_SEED:-$(od -An -N2 -tu2 /dev/urandom | tr -d ' ')}
MPIRUN=${MPIRUN:-mpirun}
mo="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && mo="$mo --allow-run-as-root"
echo "check_restart_mpi: NP $np, seed $seed"
fail=0

ncyc=$(awk '/^ *[-+.0-9]/ {c=$2} END {print c+0}' "$ref/glstat")
if [ "$ncyc" -lt 3 ]; then echo "check_restart_mpi: reference has $ncyc cycles"; exit 1; fi

# DYNX_RESTART_WINDOW="LO HI": draw the stop/dump cycles of cycle, usr1 and serial from
# LO..HI (e.g. while contact is active); default 1..cycles-1
wlo=1; whi=$((ncyc - 1))
if [ -n "${DYNX_RESTART_WINDOW:-}" ]; then
    wlo=${DYNX_RESTART_WINDOW%% *}; whi=${DYNX_RESTART_WINDOW##* }
fi

rnd() {  # rnd LO HI K -> integer in [LO, HI], the K-th draw from the seed
    awk -v s="$seed" -v k="$3" -v lo="$1" -v hi="$2" \
        'BEGIN { srand(s + 7919 * k); print int(lo + rand() * (hi - lo + 1)) }'
}

same() {  # same DIR LABEL
    ok=1
    cmpd=""
    for f in glstat nodout rbdout rcforc matsum spcforc sleout elout ncforc d3plot.xdmf; do
        if [ -f "$ref/$f" ] || [ -f "$1/$f" ]; then
            if ! cmp -s "$ref/$f" "$1/$f"; then echo "  $2: $f differs"; ok=0; fi
            cmpd="$cmpd$f, "
        fi
    done
    if ! h5diff -q "$ref/d3plot.h5" "$1/d3plot.h5"; then echo "  $2: d3plot.h5 differs (h5diff)"; ok=0; fi
    if ! cmp -s "$ref/d3plot.h5" "$1/d3plot.h5"; then echo "  $2: d3plot.h5 not byte-equal (cmp)"; ok=0; fi
    if [ $ok = 1 ]; then echo "  $2: identical (${cmpd%, } byte-equal; h5diff 0 differences; d3plot.h5 byte-equal)"; else fail=1; fi
}

expect_fail() {  # expect_fail LABEL CODE SUBSTRING LOG
    if [ "$rc" -ne "$2" ]; then echo "  errors/$1: exit $rc (expected $2)"; cat "$4" | grep error | head -3; fail=1; return; fi
    if ! grep -q -- "$3" "$4"; then echo "  errors/$1: message lacks '$3'"; grep error "$4" | head -3; fail=1; return; fi
    echo "  errors/$1: exit $2, $(grep -m1 'error:' "$4" | cut -c1-150)..."
}

stopped_plot() {  # stopped_plot DIR LABEL: after a stop, the combined d3plot.h5/xdmf hold
    # the states the message names: its count, the last at the stop time, and every earlier
    # state equal to the reference's (h5diff of the state group)
    lg=$1/run1.log
    nm=$(sed -n "s/.*plot files combined into .*: \([0-9]*\) states).*/\1/p" "$lg")
    tm=$(sed -n 's/.*stopped by .* at cycle [0-9]*, time \([^;]*\);.*/\1/p' "$lg")
    if [ -z "$nm" ] || [ -z "$tm" ]; then echo "  $2: stop message lacks the combined state count or the time"; fail=1; return; fi
    nh=$(h5dump -a /nstates "$1/d3plot.h5" 2>/dev/null | sed -n 's/.*(0): *\([0-9]*\).*/\1/p')
    nx=$(grep -c '<Time ' "$1/d3plot.xdmf")
    tx=$(grep '<Time ' "$1/d3plot.xdmf" | tail -1 | sed 's/.*Value="\([^"]*\)".*/\1/')
    okt=$(awk -v a="$tm" -v b="$tx" 'BEGIN { d = a - b; if (d < 0) d = -d; s = (a < 0 ? -a : a); print (d <= 1e-5 * s + 1e-300) ? 1 : 0 }')
    if [ "$nh" != "$nm" ] || [ "$nx" != "$nm" ] || [ "$okt" != 1 ]; then
        echo "  $2: message says $nm states at time $tm; d3plot.h5 has ${nh:-none}, d3plot.xdmf $nx (last at $tx)"; fail=1; return
    fi
    q=1
    while [ $q -lt "$nm" ]; do
        gq=$(printf '/states/%06d' $q)
        if ! h5diff -q "$ref/d3plot.h5" "$1/d3plot.h5" "$gq" "$gq" >/dev/null 2>&1; then
            echo "  $2: combined state $q differs from the reference's"; fail=1; return
        fi
        q=$((q + 1))
    done
    echo "  $2: combined d3plot.h5 + xdmf after the stop: $nm states as the message says, last at t = $tm, states 1..$((nm - 1)) h5diff-equal to the reference's"
}

last_dump() { ls "$1"/d3dump*.h5 2>/dev/null | grep -v '\.rank[0-9]*\.h5$' | sort | tail -1; }

# the final energies, work sums and momentum as IEEE bits (glstat prints 11 digits): one
# serial run with DYNX_ENERGY_BITS=1; every run that ends normally must print the same bits
bits() { sed -n 's/^dynx: energy bits[^:]*: //p' "$1"; }
mkdir -p "$work/bits"
DYNX_ENERGY_BITS=1 timeout 300 "$DYNX" -i "$deck" -o "$work/bits" > "$work/bits/stdout" 2>&1
sbits=$(bits "$work/bits/stdout")
[ -n "$sbits" ] || { echo "check_restart_mpi: no energy bits from the serial run"; exit 1; }
export DYNX_ENERGY_BITS=1
mo="$mo -x DYNX_ENERGY_BITS"
samebits() {  # samebits LOG LABEL
    if [ "$(bits "$1")" != "$sbits" ]; then
        echo "  $2: energy bits differ: serial $sbits"; echo "      this run $(bits "$1")"; fail=1
    else
        echo "  $2: energy bits identical"
    fi
}

k=0
for m in $modes; do
    k=$((k + 1))
    d=$work/np$np-$m
    rm -rf "$d"; mkdir -p "$d"
    r=$(rnd 0 $((np - 1)) $((100 + k)))
    case $m in
    cycle)
        n=$(rnd $wlo $whi $k)
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" --raise-at-cycle "$n:TERM@$r" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 5 ]; then echo "  cycle: exit $rc (expected 5) with SIGTERM at cycle $n on rank $r"; fail=1; continue; fi
        grep -q "continue with: mpirun -np $np dynx" "$d/run1.log" || { echo "  cycle: no 'continue with' message"; fail=1; }
        n="$n (SIGTERM on rank $r)"
        ;;
    sigterm)
        rc=0
        for ms in $(rnd 50 800 $k) 100 20; do
            rm -rf "$d"; mkdir -p "$d"
            $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" > "$d/run1.log" 2>&1 &
            pid=$!
            # the delay counts from the first status line (mpirun's start-up varies with load)
            w=0
            while [ $w -lt 600 ] && ! grep -q '^ *0  0.0000E+00' "$d/run1.log" 2>/dev/null; do sleep 0.05; w=$((w + 1)); done
            sleep "$(echo "$ms" | awk '{printf "%.3f", $1/1000}')"
            kid=$(pgrep -P $pid | sed -n "$((r + 1))p")
            [ -n "$kid" ] && kill -TERM "$kid" 2>/dev/null
            wait $pid; rc=$?
            [ $rc -ne 0 ] && break
        done
        if [ $rc -ne 5 ]; then echo "  sigterm: exit $rc (expected 5) after ${ms} ms"; fail=1; continue; fi
        n="$(sed -n 's/.*stopped by SIGTERM at cycle \([0-9]*\).*/\1/p' "$d/run1.log") (SIGTERM to one rank's process after $ms ms)"
        ;;
    mpirun)
        rc=0
        for ms in $(rnd 50 800 $k) 100 20; do
            rm -rf "$d"; mkdir -p "$d"
            $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" > "$d/run1.log" 2>&1 &
            pid=$!
            w=0
            while [ $w -lt 600 ] && ! grep -q '^ *0  0.0000E+00' "$d/run1.log" 2>/dev/null; do sleep 0.05; w=$((w + 1)); done
            sleep "$(echo "$ms" | awk '{printf "%.3f", $1/1000}')"
            kill -TERM $pid 2>/dev/null
            wait $pid; rc=$?
            grep -q 'normal termination' "$d/run1.log" || break
        done
        if ! grep -q "stopped by SIGTERM" "$d/run1.log"; then echo "  mpirun: exit $rc, no 'stopped by SIGTERM' message"; fail=1; continue; fi
        n="$(sed -n 's/.*stopped by SIGTERM at cycle \([0-9]*\).*/\1/p' "$d/run1.log") (SIGTERM to mpirun after $ms ms, mpirun exit $rc)"
        ;;
    walltime)
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" --walltime 1.0 > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 5 ]; then echo "  walltime: exit $rc (expected 5) with --walltime 1.0"; fail=1; continue; fi
        n="$(sed -n 's/.*stopped by the wall-clock limit.* at cycle \([0-9]*\),.*/\1/p' "$d/run1.log") (--walltime 1.0)"
        ;;
    usr1)
        n=$(rnd $wlo $whi $k)
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" --raise-at-cycle "$n:USR1@$r" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 0 ]; then echo "  usr1: exit $rc (expected 0)"; fail=1; continue; fi
        grep -q 'SIGUSR1: restart dump' "$d/run1.log" || { echo "  usr1: no dump message"; fail=1; continue; }
        same "$d" "usr1 (run that dumped at cycle $n, SIGUSR1 on rank $r, and went on)"
        samebits "$d/run1.log" "usr1 (run that dumped and went on)"
        n="$n (SIGUSR1 on rank $r)"
        ;;
    serial)
        n=$(rnd $wlo $whi $k)
        "$DYNX" -i "$deck" -o "$d" --raise-at-cycle "$n:TERM" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 5 ]; then echo "  serial: exit $rc (expected 5)"; fail=1; continue; fi
        n="$n (serial run)"
        ;;
    periodic)
        c1=$((ncyc / 5 + 7)); c2=$((ncyc / 3))
        [ "$c1" -lt 1 ] && c1=1; [ "$c2" -lt 1 ] && c2=1
        awk -v c1=$c1 -v c2=$c2 '/^\*END/ { print "*DATABASE_BINARY_RUNRSF"; printf "%10d%10d\n", c1, 1; print "*DATABASE_BINARY_D3DUMP"; printf "%10d\n", c2 } { print }' "$deck" > "$d/deck.k"
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$d/deck.k" -o "$d" > "$d/run1.log" 2>&1
        rc=$?
        if [ $rc -ne 0 ]; then echo "  periodic: exit $rc"; tail -3 "$d/run1.log"; fail=1; continue; fi
        same "$d" "periodic (RUNRSF every $c1, D3DUMP every $c2 cycles; run with the dumps)"
        nr=$(ls "$d"/runrsf.cyc*.rank*.h5 2>/dev/null | wc -l)
        if [ "$nr" -ne "$np" ]; then echo "  periodic: $nr runrsf parts on disk (expected $np: superseded parts not removed?)"; fail=1; fi
        nd=$(ls "$d"/d3dump*.cyc*.rank*.h5 2>/dev/null | wc -l)
        echo "  periodic: runrsf parts on disk $nr, d3dump parts $nd ($(ls "$d"/d3dump??.h5 | wc -l) d3dump sets)"
        deck=$d/deck.k
        dump=$d/runrsf.h5
        n="$(ls "$d"/runrsf.cyc*.rank00000.h5 | sed 's/.*cyc\([0-9]*\).*/\1/') (last runrsf)"
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" -r "$dump" > "$d/run2.log" 2>&1
        rc=$?
        deck=$deck0
        if [ $rc -ne 0 ]; then echo "  periodic: continue run exit $rc"; tail -5 "$d/run2.log"; fail=1; continue; fi
        same "$d" "periodic NP $np (continued from runrsf.h5 at cycle $n)"
        samebits "$d/run2.log" "periodic NP $np (continued)"
        continue
        ;;
    errors)
        src=$work/np$np-cycle
        dump=$(last_dump "$src")
        if [ -z "$dump" ]; then echo "  errors: run mode cycle first"; fail=1; continue; fi
        cp -r "$src" "$d/set"
        dump=$d/set/$(basename "$dump")
        timeout 300 $MPIRUN $mo -np $((np + 1)) "$DYNX" -i "$deck" -o "$d/set" -r "$dump" > "$d/np.log" 2>&1
        rc=$?; expect_fail "other-NP" 2 "is a dump of a run on $np ranks; this run has $((np + 1))" "$d/np.log"
        "$DYNX" -i "$deck" -o "$d/set" -r "$dump" > "$d/serial.log" 2>&1
        rc=$?; expect_fail "serial" 2 "continue it with the same number of ranks: mpirun -np $np" "$d/serial.log"
        sed '1s/^/$ another deck\n/' "$deck" > "$d/other.k"
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$d/other.k" -o "$d/set" -r "$dump" > "$d/deck.log" 2>&1
        rc=$?; expect_fail "other-deck" 2 "is a dump of another deck" "$d/deck.log"
        part=$(ls ${dump%.h5}.cyc*.rank$(printf %05d $((np - 1))).h5)
        mv "$part" "$part.away"
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d/set" -r "$dump" > "$d/missing.log" 2>&1
        rc=$?; expect_fail "missing-part" 4 "part of rank $((np - 1)): $part is missing" "$d/missing.log"
        mv "$part.away" "$part"
        part=$(ls ${dump%.h5}.cyc*.rank00000.h5)
        printf 'XXXXXXXX' | dd of="$part" bs=1 seek=3000 conv=notrunc 2>/dev/null
        timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d/set" -r "$dump" > "$d/damaged.log" 2>&1
        rc=$?; expect_fail "damaged-part" 4 "part of rank 0: $part: its CRC-32" "$d/damaged.log"
        continue
        ;;
    esac
    dump=$(last_dump "$d")
    if [ -z "$dump" ]; then echo "  $m: no d3dump manifest in $d"; fail=1; continue; fi
    case $m in cycle|sigterm|mpirun|walltime) stopped_plot "$d" "$m NP $np" ;; esac
    if [ "$m" != serial ]; then
        for q in $(seq 0 $((np - 1))); do
            ls ${dump%.h5}.cyc*.rank$(printf %05d $q).h5 >/dev/null 2>&1 || { echo "  $m: part of rank $q missing"; fail=1; }
        done
    fi
    timeout 300 $MPIRUN $mo -np "$np" "$DYNX" -i "$deck" -o "$d" -r "$dump" > "$d/run2.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then echo "  $m: continue run exit $rc"; tail -5 "$d/run2.log"; fail=1; continue; fi
    same "$d" "$m NP $np (stopped at cycle $n of $ncyc, continued from $(basename "$dump"))"
    samebits "$d/run2.log" "$m NP $np (continued)"
done
exit $fail
