#!/bin/sh
# Conserving rigid-body solver under MPI (dx_par_emc; issue 6): a serial run of DECK in
# OUTDIR (made by the regression runner) against mpirun -np 1..4, zero tolerance
# (scripts/mpi_bitwise_check.sh: emcstat and XDMF cmp, d3plot.h5 h5diff, the final energies
# and momenta as IEEE bits), after checking that the run had contact (at least MINC emcstat
# lines with a pair), so the split pair search and the ordered gathers were exercised. With
# SPLIT=NP the slave points must be shared by at least two ranks at that NP (the partition
# is the explicit engine's: METIS on the element graph, which may keep a body whole).
#   sh scripts/mpi_emc_check.sh DECK OUTDIR MINC [NP...]
set -u
deck=$1; out=$2; minc=$3; shift 3
nps=${*:-1 2 3 4}
nc=$(awk '/^ *[-+.0-9]/ && $14 > 0 {n++} END {print n + 0}' "$out/emcstat")
if [ "$nc" -lt "$minc" ]; then echo "FAIL: $nc emcstat lines in contact (want >= $minc)"; exit 1; fi
echo "serial run: $nc emcstat lines in contact (>= $minc)"
sh scripts/mpi_bitwise_check.sh "$deck" "$out" $nps || exit 1
if [ -n "${SPLIT:-}" ]; then   # SPLIT=NP: the slave points are shared by at least 2 ranks at NP
    line=$(grep -h "conserving solver on $SPLIT ranks" "$out/np$SPLIT/stdout")
    per=$(echo "$line" | sed -n 's/.*per rank: *//p')
    nz=$(for c in $per; do [ "$c" -gt 0 ] && echo x; done | wc -l)
    if [ "$nz" -lt 2 ]; then echo "FAIL: NP $SPLIT does not split the slave points: '$line'"; exit 1; fi
    echo "NP $SPLIT: slave points searched and evaluated per rank: $per"
fi
