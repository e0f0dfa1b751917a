#!/bin/sh
# Serial and MPI agree bit for bit on every regression deck (issue 6 acceptance), beyond the
# mpi_* cases that make test runs: for each tests/regression/<case>/deck.k that runs to a
# normal end serially (no `expect` file, not the mpi_* cases themselves; the conserving
# solver's emc_* decks included: dx_par_emc), run it serially, then under mpirun at each NP,
# and compare with scripts/mpi_bitwise_check.sh (glstat, nodout, rbdout, rcforc, emcstat, XDMF
# cmp; d3plot.h5 h5diff; final energies as IEEE bits; zero tolerance). Decks whose serial run
# takes longer than MAXSEC seconds are listed as skipped (time), not passed.
#   sh scripts/mpi_all_decks.sh [NP...]        (default NP: 2 3 4; MAXSEC default 60)
#   MATCH='emc_*' sh scripts/mpi_all_decks.sh  only the cases whose name matches (shell glob)
# Output: one line per deck (PASS / FAIL / SKIP), then the counts; exit 1 if any deck failed.
set -u
cd "$(dirname "$0")/.." || exit 2
MAXSEC=${MAXSEC:-60}
MATCH=${MATCH:-*}
nps=${*:-2 3 4}
work=build/mpi_all_decks
rm -rf "$work"; mkdir -p "$work"
np_=0; nf=0; ns=0
for dir in tests/regression/*/; do
    c=$(basename "$dir")
    [ -f "$dir/deck.k" ] || continue
    [ -f "$dir/expect" ] && continue
    case $c in mpi_*|bad_*) continue ;; esac
    case $c in $MATCH) ;; *) continue ;; esac
    case $c in implicit_*|eigen_*) echo "SKIP $c (the implicit Newton solver and the eigenvalue run are serial only)"; ns=$((ns + 1)); continue ;; esac
    grep -qi '^\*CASE' "$dir/deck.k" && { echo "SKIP $c (a *CASE deck: one serial process per case; under MPI each case is started with --case)"; ns=$((ns + 1)); continue; }
    [ -f "$dir/args" ] && { echo "SKIP $c (extra arguments: $(cat "$dir/args"))"; ns=$((ns + 1)); continue; }
    ref=$work/$c
    mkdir -p "$ref"
    t0=$(date +%s)
    timeout "$MAXSEC" bin/dynx -i "$dir/deck.k" -o "$ref" >"$ref.log" 2>&1
    rc=$?
    t1=$(date +%s)
    if [ $rc -eq 124 ]; then echo "SKIP $c (serial run over ${MAXSEC} s)"; ns=$((ns + 1)); continue; fi
    if [ $rc -ne 0 ]; then echo "SKIP $c (serial exit $rc)"; ns=$((ns + 1)); continue; fi
    use=" $nps"     # every NP, also above the element count (empty ranks: mpi_empty_ranks)
    if sh scripts/mpi_bitwise_check.sh "$dir/deck.k" "$ref" $use >"$ref.cmp" 2>&1; then
        echo "PASS $c (serial $((t1 - t0)) s; NP$use identical)"
        np_=$((np_ + 1))
    else
        echo "FAIL $c: $(grep -m1 'DIFFERS\|exit' "$ref.cmp")"
        nf=$((nf + 1))
    fi
done
echo "$np_ decks identical at NP $nps, $nf differ, $ns skipped"
[ $nf -eq 0 ]
