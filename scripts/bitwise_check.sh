#!/bin/sh
# Byte-for-byte check of a refactor: compares every output file of the regression runs in
# build/regression/ against a baseline copy made before the change (the same tree from the
# old commit):
#   cp -a build/regression /tmp/base     # on the old commit, after scripts/run_regression.sh
#   scripts/bitwise_check.sh /tmp/base   # on the new commit, after scripts/run_regression.sh
# stdout, stderr, *.stdout, check.log, strace logs, mpirun's *.out/*.err and the output-folder
# lock .dynx.lock (pid, host) are skipped (wall times,
# paths, pids), and so are the interrupted runs under restart*/ (the cycle a signal or a
# wall-clock limit hits depends on timing; their check scripts compare them bitwise with the
# uninterrupted run), and the kill -9 runs under kill9/ and killed/ (killed at the N-th system
# call or after a wall time; mpi_plot_combine's serial reference ends where that kill fell;
# faults_busy_output_folder/busy/ is the run a second dynx finds busy: it stops when killed);
# every other file (glstat, nodout, rbdout, d3plot.h5,
# d3plot.xdmf, rank parts, dumps) must be identical, HDF5 files up to the run stamp attribute.
# Prints one line per differing or missing file and 'N identical, N differ'; exits 1 on any
# difference.
set -u
cd "$(dirname "$0")/.." || exit 2
base=${1:?usage: scripts/bitwise_check.sh BASEDIR}
new=${2:-build/regression}
same=0
diff=0
tmp=${TMPDIR:-/tmp}/dynx_bitwise.$$
trap 'rm -f "$tmp"' EXIT INT TERM
(cd "$base" && find . -type f ! -name stdout ! -name stderr ! -name check.log ! -name '*.log' ! -name '*.err' ! -name '*.out' ! -name strace.txt ! -name '*.stdout' ! -name .dynx.lock ! -path '*/faults_busy_output_folder/busy/*' ! -path '*/restart*/*' ! -path '*/kill9/*' ! -path '*/killed/*' ! -path '*/mpi_plot_combine/serial/*' ! -name box_serial.k | sort) > "$tmp"
# HDF5 files whose only difference is the run stamp attribute (rank files, dumps)
only_stamp_differs() {
    case "$1" in *.h5) ;; *) return 1 ;; esac
    ! h5diff "$1" "$2" 2>&1 | grep -v -e '^attribute: <stamp of' -e '^1 differences found$' \
        -e '^-*$' -e '^Some objects are not comparable' -e '^Use -c for a list' | grep -q .
}
while IFS= read -r f; do
    if [ ! -f "$new/$f" ]; then
        echo "MISSING $new/$f"
        diff=$((diff + 1))
    elif cmp -s "$base/$f" "$new/$f"; then
        same=$((same + 1))
    elif only_stamp_differs "$base/$f" "$new/$f"; then
        same=$((same + 1))      # differs only in the run stamp of rank files and dumps
    else
        echo "DIFFER $new/$f"
        diff=$((diff + 1))
    fi
done < "$tmp"
echo "$same identical, $diff differ"
[ "$diff" -eq 0 ]
