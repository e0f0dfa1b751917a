#!/bin/sh
# make bench (issue 20): the sparse direct solver's factorization time and memory against the
# matrix size: the linear-static cantilever of scripts/gen_implicit_decks.py (10n x n x n
# B-bar hexahedra, NSOLVR 1: one assembly, one MUMPS analysis, one factorization and solve)
# for n in BENCH_IMPLICIT_N (default "2 4 8 12": 540 to 60 840 equations). The log's last
# line gives the split (MUMPS analysis, factorization + solve, assembly) and the peak
# resident memory. 1e5 equations and more (n >= 16, 139 587 equations) need several GB and
# minutes: set BENCH_IMPLICIT_N on a machine that has them. Writes build/bench/implicit.md.
# Then the largest n at NP 1 (the serial run above) against mpirun -np 2 (MUMPS factorizing
# on both ranks, distributed assembled input): the factorization's wall time, each process's
# CPU time in it and its elimination flops (MUMPS RINFO(3)): the flops give the balance
# (ideal speed-up = total / largest), the wall time the speed-up on this machine (noisy when
# shared; the CPU time of an MPI rank includes its polling while it waits).
set -e
cd "$(dirname "$0")/.."
B=build/bench
mkdir -p $B
NS=${BENCH_IMPLICIT_N:-"2 4 8 12"}
{
echo "| mesh | equations | stored entries | MUMPS analysis [s] | factorization + solve [s] | assembly [s] | peak RSS [KiB] |"
echo "|---|---|---|---|---|---|---|"
} > $B/implicit.md
for n in $NS; do
    deck=$B/implicit_cantilever_$n.k
    python3 -c "import sys; sys.path.insert(0, 'scripts'); import gen_implicit_decks as g; g.cantilever($n, '$deck')"
    log=$B/implicit_cantilever_$n.log
    bin/dynx -i $deck -o $B/implicit_cantilever_$n > $log 2>&1 || { echo "bench: cantilever n = $n failed"; tail $log; exit 1; }
    neq=$(grep 'equations, ' $log | sed 's/.*implicit: \([0-9]*\) equations.*/\1/')
    nnz=$(grep 'equations, ' $log | sed 's/.*equations, \([0-9]*\) stored.*/\1/')
    ana=$(grep 'MUMPS analysis' $log | tail -1 | sed 's/.*MUMPS analysis \([0-9.eE+-]*\) s before.*/\1/')
    fac=$(grep 'factorizations and solves' $log | sed 's/.*factorizations and solves \([0-9.eE+-]*\) s.*/\1/')
    asm=$(grep 'factorizations and solves' $log | sed 's/.*assembly \([0-9.eE+-]*\) s.*/\1/')
    kib=$(grep 'peak memory' $log | sed 's/.*peak memory \([0-9]*\) KiB.*/\1/')
    echo "| $((10*n))x${n}x${n} | $neq | $nnz | $ana | $fac | $asm | $kib |" >> $B/implicit.md
    echo "bench: implicit cantilever n = $n: $neq equations, factorization + solve $fac s, $kib KiB"
done
n=${NS##* }
deck=$B/implicit_cantilever_$n.k
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
log=$B/implicit_cantilever_${n}_np2.log
mpirun $opts -np 2 bin/dynx -i $deck -o $B/implicit_cantilever_${n}_np2 > $log 2>&1 || { echo "bench: cantilever n = $n at NP 2 failed"; tail $log; exit 1; }
{
echo
echo "Largest matrix, $((10*n))x${n}x${n}: NP 1 against NP 2 (one factorization; wall seconds; per process: CPU seconds in the factorization and elimination flops)"
echo
echo "| NP | MUMPS analysis [s] | factorization + solve [s] | per process |"
echo "|---|---|---|---|"
for f in $B/implicit_cantilever_$n.log $log; do
    np=1; [ "$f" = "$log" ] && np=2
    ana=$(grep 'MUMPS analysis' $f | tail -1 | sed 's/.*MUMPS analysis \([0-9.eE+-]*\) s before.*/\1/')
    fac=$(grep 'factorizations and solves' $f | sed 's/.*factorizations and solves \([0-9.eE+-]*\) s.*/\1/')
    per=$(grep 'elimination flops per process' $f | sed 's/.*per process: //')
    echo "| $np | $ana | $fac | $per |"
done
} >> $B/implicit.md
cat $B/implicit.md
