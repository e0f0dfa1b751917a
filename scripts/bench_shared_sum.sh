#!/bin/sh
# make bench (part 2): the fixed-order shared-node sum (dx_par par_shared_sum) against the
# plain sum of per-rank partials (par_shared_sum_plain) on a METIS partition of the
# 100 000-element box, NP = 2 and 4 (oversubscribed on a 2-core machine: reported as such).
# The two variants alternate inside one run (10 rounds); the slowest rank's time per step
# is reported. Appends a dated table to docs/performance.md.
set -e
cd "$(dirname "$0")/.."
prog=build/release/bench/mpi_shared_bench
MPIRUN="mpirun --oversubscribe"
[ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
B=build/bench
mkdir -p $B
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
ncpu=$(nproc)
{
echo ""
echo "### make bench: fixed-order vs plain shared-node sum, $(date -u +%Y-%m-%d), commit $rev, $ncpu cores"
echo ""
echo "| NP | elements | shared-node entries | scatter+exchange fixed [ms] | plain [ms] | ratio | exchange fixed [ms] | plain [ms] | ratio |"
echo "|---|---|---|---|---|---|---|---|---|"
} > $B/shared_sum.md
for np in 2 4; do
    timeout 900 $MPIRUN -np $np $prog 50 50 40 200 > $B/shared_sum_$np.log 2>&1 || {
        echo "bench_shared_sum: NP=$np failed"; cat $B/shared_sum_$np.log; exit 1; }
    awk -v np=$np -v ncpu=$ncpu '
        /^np / { ne = $4; nsh = $10 }
        /^scatter/ { sf = $4 * 1000; sp = $6 * 1000; sr = $8 }
        /^exchange/ { xf = $5 * 1000; xp = $7 * 1000; xr = $9 }
        END { note = (np > ncpu) ? " (oversubscribed)" : "";
              printf "| %d%s | %d | %d | %.2f | %.2f | %.3f | %.2f | %.2f | %.3f |\n",
                     np, note, ne, nsh, sf, sp, sr, xf, xp, xr }' $B/shared_sum_$np.log >> $B/shared_sum.md
done
{
echo ""
echo "scatter+exchange: one step = scatter the 8 corner forces of every element (shared corners"
echo "into contribution slots for the fixed-order sum), a barrier, and the exchange. 'exchange'"
echo "times the exchange call alone, after the barrier (so without waiting for slower ranks)."
echo "Ratio = fixed/plain. The machine is shared with other jobs: compare ratios, not times."
} >> $B/shared_sum.md
cat $B/shared_sum.md >> docs/performance.md
cat $B/shared_sum.md
