#!/bin/sh
# Serial and MPI runs agree bit for bit (docs/history.md, "ParaDyn step 5").
#   sh scripts/mpi_bitwise_check.sh DECK SERIAL_OUTDIR [NP...]      (default NP: 1 2 3 4)
# SERIAL_OUTDIR holds a serial run of DECK (bin/dynx -i DECK -o SERIAL_OUTDIR). For each NP,
# runs `mpirun -np NP bin/dynx -i DECK -o SERIAL_OUTDIR/npNP` (--oversubscribe; as root also
# --allow-run-as-root; rank 0 partitions the deck itself) and compares glstat and nodout
# (and rbdout / rcforc / emcstat / matsum / spcforc / sleout / elout / ncforc when the serial run wrote one) with cmp and d3plot.h5 with h5diff: zero
# tolerance. glstat prints 11 digits, so the final energies, work sums and momentum are also
# compared as IEEE bit patterns (DYNX_ENERGY_BITS=1: one more serial run into
# SERIAL_OUTDIR/bits). Exit 1 on any difference.
# DYNX_MPI_ARGS: more dynx options for the MPI runs (e.g. --contact-split strips); their
# output then goes to SERIAL_OUTDIR/npNP_TAG with TAG = DYNX_MPI_TAG (default: args).
set -u
deck=$1
ref=$2
shift 2
nps=${*:-1 2 3 4}
MPIRUN=${MPIRUN:-mpirun}
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
fail=0
bits() { sed -n 's/^dynx: energy bits[^:]*: //p' "$1"; }
rm -rf "$ref/bits"
mkdir -p "$ref/bits"
DYNX_ENERGY_BITS=1 timeout 300 bin/dynx -i "$deck" -o "$ref/bits" >"$ref/bits/stdout" 2>&1
sbits=$(bits "$ref/bits/stdout")
[ -n "$sbits" ] || { echo "serial run for the energy bits failed:"; tail -n 5 "$ref/bits/stdout"; }
xargs_=${DYNX_MPI_ARGS:-}
tag=""
[ -n "$xargs_" ] && tag=_${DYNX_MPI_TAG:-args}
for np in $nps; do
    out=$ref/np$np$tag
    rm -rf "$out"
    mkdir -p "$out"
    t0=$(date +%s)
    DYNX_ENERGY_BITS=1 timeout 300 $MPIRUN $opts -x DYNX_ENERGY_BITS -np "$np" bin/dynx -i "$deck" -o "$out" $xargs_ >"$out/stdout" 2>"$out/stderr"
    rc=$?
    t1=$(date +%s)
    if [ $rc -ne 0 ]; then
        echo "NP $np: exit $rc"; cat "$out/stderr"; fail=1; continue
    fi
    res=""
    for f in glstat nodout rbdout rcforc emcstat matsum spcforc sleout elout ncforc d3plot.xdmf; do
        [ -f "$ref/$f" ] || continue
        if cmp -s "$ref/$f" "$out/$f"; then res="$res $f=identical"; else res="$res $f=DIFFERS"; fail=1; fi
    done
    if [ -n "$sbits" ] && [ "$sbits" = "$(bits "$out/stdout")" ]; then
        res="$res energy-bits=identical"
    else
        res="$res energy-bits=DIFFERS"; fail=1
        echo "serial: $sbits"; echo "NP $np:  $(bits "$out/stdout")"
    fi
    if h5diff -q "$ref/d3plot.h5" "$out/d3plot.h5" >/dev/null 2>&1; then
        res="$res d3plot.h5=identical"
    else
        res="$res d3plot.h5=DIFFERS"; fail=1
        h5diff "$ref/d3plot.h5" "$out/d3plot.h5" | head -5
    fi
    echo "NP $np${xargs_:+ $xargs_} ($((t1 - t0)) s):$res"
done
exit $fail
