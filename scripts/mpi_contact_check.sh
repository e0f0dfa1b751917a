#!/bin/sh
# Contact decks in MPI runs (docs/history.md, "Parallel contact"):
#   sh scripts/mpi_contact_check.sh DECK SERIAL_OUTDIR MIN_FORCE [NP...]
# 1. the serial run's rcforc shows contact: a slave resultant |f| >= MIN_FORCE on some line
#    and some slave node in contact (so the bitwise comparison is not vacuous);
# 2. mpirun -np NP (default 1 2 3 4): glstat (with the sliding_interface column), nodout,
#    rcforc and d3plot.h5 identical to the serial run (scripts/mpi_bitwise_check.sh, zero
#    tolerance);
# 3. each run's partition report lists every local contact pair on a single rank.
set -u
deck=$1
ref=$2
fmin=$3
shift 3
nps=${*:-1 2 3 4}
python3 - "$ref/rcforc" "$fmin" <<'PY' || exit 1
import sys
fmax, nact = 0.0, 0
for line in open(sys.argv[1]):
    if line.lstrip()[:1] not in tuple('+-.0123456789'):
        continue
    w = line.split()
    fmax = max(fmax, sum(float(v)**2 for v in w[2:5])**0.5)
    nact = max(nact, int(w[8]))
ok = fmax >= float(sys.argv[2]) and nact > 0
print('serial rcforc: largest slave resultant %.6g (at least %s), most slave nodes in contact %d: %s'
      % (fmax, sys.argv[2], nact, 'ok' if ok else 'FAIL'))
sys.exit(0 if ok else 1)
PY
sh scripts/mpi_bitwise_check.sh "$deck" "$ref" $nps || exit 1
fail=0
for np in $nps; do
    rep=$ref/np$np/partition.txt
    [ -f "$rep" ] || continue
    if awk '/^contact pairs kept whole/{on=1; next} on && /split/{bad=1} END{exit bad}' "$rep"; then
        n=$(awk '/^contact pairs kept whole/{on=1; getline; next} on && NF>=4{c++} END{print c+0}' "$rep")
        bal=$(sed -n 's/^balance (max weight \/ mean weight): *\([0-9.]*\).*/\1/p' "$rep")
        echo "NP $np: $n local contact pair(s), each on one rank; balance $bal"
    else
        echo "NP $np: a contact pair was split over ranks:"; cat "$rep"; fail=1
    fi
done
exit $fail
