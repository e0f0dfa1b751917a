#!/bin/sh
# Partitioner tests (bin/dynx-part), run by `make test`:
#  - every regression deck that reads (not bad_*) and a generated 100 000-element box
#    (scripts/gen_box_deck.py) at NP = 2, 3, 4: the rank files pass `dynx-part --verify`
#    (checksums, deck hash, NP, every element on exactly one rank, symmetric shared-node
#    lists), and the balance statistic (max weight / mean weight) is <= 1.1, or <= the best
#    the element granularity allows where that is worse (8 unit elements on 3 ranks: 3/2.67),
#    or than the heaviest local contact pair allows (kept whole on one rank: its weight over
#    the mean weight; the report lists the pairs and their ranks).
#    The patch and single-element decks are only verified.
#  - the partition is reproducible (same report and checksums from a second run)
#  - errors: files for another NP or another deck (exit 2, file named), a corrupt file
#    (exit 4, checksum), a missing file (exit 4), bad -n, a bad deck (exit 2). Shell and
#    beam decks are partitioned and verified like the patch decks (issue 17: shells and
#    beams under MPI).
# Closes with 'N passed, N failed'; exits 1 if anything failed.
set -u
LC_ALL=C
export LC_ALL
cd "$(dirname "$0")/.." || exit 2
PART=${DYNX_PART:-bin/dynx-part}
OUT=build/partition_tests
MAXBAL=1.1
np_=0
nf_=0
pass() { echo "  PASS $1"; np_=$((np_ + 1)); }
fail() { echo "  FAIL $1"; nf_=$((nf_ + 1)); }
rm -rf "$OUT"
mkdir -p "$OUT"
popt=""

# partition DECK NP DIR CHECKBAL
partition() {
    deck=$1; n=$2; dir=$3; chk=$4
    # shellcheck disable=SC2086
    if ! "$PART" "$deck" -n "$n" -o "$dir" $popt >"$dir.log" 2>&1; then
        fail "$deck -n $n: dynx-part failed: $(tail -n 1 "$dir.log")"
        return
    fi
    bal=$(sed -n 's/^balance (max weight \/ mean weight): *\([0-9.]*\).*/\1/p' "$dir/partition.txt")
    # shellcheck disable=SC2086
    if "$PART" "$deck" -n "$n" -o "$dir" --verify $popt >"$dir.verify" 2>&1; then
        pass "$deck -n $n: rank files verified, balance $bal"
    else
        fail "$deck -n $n: --verify: $(tail -n 1 "$dir.verify")"
    fi
    if [ "$chk" = 1 ]; then
        # the bound: MAXBAL, or the best a split of W unit-cost elements allows when that is
        # worse (8 elements on 3 ranks: ceil(8/3)/(8/3) = 1.125); with elements of unequal
        # weight (decks with rigid parts: 4 and 1), the list-scheduling bound
        # (W/n + wmax (1 - 1/n))/(W/n) with wmax the heaviest element; or, with contact
        # pairs kept whole, the heaviest pair over the mean (a pair that is the whole model
        # puts everything on one rank); with fewer vertices than ranks (elements and merged
        # contact groups: overlapping pairs merge, e.g. three rods in a row with two contacts
        # are one group) dynx-part puts one vertex per rank without METIS, and the heaviest
        # vertex, possibly the whole model, sets the balance: any value up to n is allowed
        lim=$(awk -v m="$MAXBAL" -v n="$n" '/^ *[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ *$/ { w += $3 }
              /fewer elements or contact groups than ranks/ { few = 1 }
              /^heaviest element weight:/ { x = $4 }
              /^contact pairs kept whole/ { cp = 1; next }
              cp && /^ *[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+/ { if ($3 > gw) gw = $3 }
              END { q = w / n; c = int(q); if (c < q) c++; g = c / q
                    if (x > 1) { h = (q + x * (1 - 1 / n)) / q; if (h > g) g = h }
                    if (gw / q > g) g = gw / q
                    if (few) g = n
                    print (g > m ? g : m) }' \
              "$dir/partition.txt")
        if awk -v b="$bal" -v m="$lim" 'BEGIN { exit !(b != "" && b + 0 <= m + 1e-4) }'; then
            pass "$deck -n $n: balance $bal <= $lim"
        else
            fail "$deck -n $n: balance '$bal' > $lim"
        fi
    fi
}

echo "== regression decks"
for d in tests/regression/*/; do
    c=${d%/}; c=${c##*/}
    case $c in
        bad_*) continue ;;   # decks with input errors
        shell_*|beam_*|mpi_beam_*) nps="2 3 4"; chk=0 ;;   # verified (small meshes)
        extreme_crushed_element|extreme_distorted_element) nps="2"; chk=0 ;;
        patch_*|mpi_patch_*) nps="2 3 4"; chk=0 ;;
        *) nps="2 3 4"; chk=1 ;;
    esac
    # decks that stop on an input error by design (--check listings: their expect says exit 2)
    [ -f "${d}expect" ] && grep -q '^exit 2' "${d}expect" && continue
    # *CASE decks: read one case at a time (dynx --case ID; dynx-part refuses the whole deck
    # naming the subcase, as mpirun does without --case)
    grep -qi '^\*CASE' "${d}deck.k" && continue
    # decks run with --ignore-unknown are partitioned with it
    popt=""
    [ -f "${d}args" ] && grep -q -e '--ignore-unknown' "${d}args" && popt=--ignore-unknown
    # a deck of ne elements is split into at most ne ranks (dynx-part refuses more, tested below)
    # shellcheck disable=SC2086
    ne=$("$PART" "${d}deck.k" -n 1 -o "$OUT/${c}_1" $popt 2>/dev/null | sed -n 's/^ranks 1, elements \([0-9]*\),.*/\1/p')
    for n in $nps; do
        [ -n "$ne" ] && [ "$n" -gt "$ne" ] && continue
        partition "${d}deck.k" "$n" "$OUT/${c}_$n" "$chk"
    done
done

popt=""
echo "== 100 000-element box (scripts/gen_box_deck.py)"
python3 scripts/gen_box_deck.py "$OUT/box.k" 50 50 40
for n in 2 3 4; do
    partition "$OUT/box.k" "$n" "$OUT/box_$n" 1
done

echo "== reproducibility and errors"
deck=tests/regression/taylor_simo/deck.k
other=tests/regression/taylor_wilkins_guinan/deck.k
"$PART" "$deck" -n 3 -o "$OUT/rep" >/dev/null 2>&1
if cmp -s "$OUT/rep/partition.txt" "$OUT/taylor_simo_3/partition.txt" && \
   [ "$(h5dump -a /checksum "$OUT/rep/rank_00001.h5" | grep '(0)')" = \
     "$(h5dump -a /checksum "$OUT/taylor_simo_3/rank_00001.h5" | grep '(0)')" ]; then
    pass "a second run gives the same partition report and rank-file checksums"
else
    fail "a second run gives a different partition"
fi
# expect_err LABEL CODE TEXT CMD...
expect_err() {
    label=$1; code=$2; text=$3; shift 3
    "$@" >"$OUT/err.out" 2>"$OUT/err.txt"
    rc=$?
    if [ $rc -eq "$code" ] && grep -qF -- "$text" "$OUT/err.txt"; then
        pass "$label: exit $code, '$text'"
    else
        fail "$label: exit $rc (expected $code), stderr: $(cat "$OUT/err.txt")"
    fi
}
expect_err "files for NP = 3 read with -n 2" 2 "rank_00000.h5: rank file was written for NP = 3" \
    "$PART" "$deck" -n 2 -o "$OUT/rep" --verify
expect_err "files read for another deck" 2 "rank_00000.h5: rank file was written for another deck" \
    "$PART" "$other" -n 3 -o "$OUT/rep" --verify
cp -r "$OUT/rep" "$OUT/corrupt"
off=$(h5dump -p -d /elements "$OUT/corrupt/rank_00001.h5" | sed -n 's/.*OFFSET \([0-9]*\).*/\1/p')
if [ -n "$off" ]; then
    python3 -c "
import sys
p, o = sys.argv[1], int(sys.argv[2]) + 5
b = bytearray(open(p, 'rb').read()); b[o] ^= 1; open(p, 'wb').write(bytes(b))" \
        "$OUT/corrupt/rank_00001.h5" "$off"
    expect_err "one flipped bit in /elements" 4 "rank_00001.h5: rank file is corrupt (checksum mismatch)" \
        "$PART" "$deck" -n 3 -o "$OUT/corrupt" --verify
else
    fail "could not find the /elements data offset with h5dump -p"
fi
cp -r "$OUT/rep" "$OUT/missing"
rm -f "$OUT/missing/rank_00002.h5"
expect_err "a missing rank file" 4 "rank_00002.h5: no such file" \
    "$PART" "$deck" -n 3 -o "$OUT/missing" --verify
expect_err "a deck with an input error" 2 "deck.k:14:11: *MAT_ELASTIC: field RO:" \
    "$PART" tests/regression/bad_negative_density/deck.k -n 2 -o "$OUT/x"
expect_err "-n 0" 2 "-n needs a positive integer" "$PART" "$deck" -n 0
# more ranks than elements: one element per rank, the last rank empty, files readable
rm -rf "$OUT/empty"
if "$PART" tests/regression/patch_constant_strain/deck.k -n 8 -o "$OUT/empty" \
        >"$OUT/err.out" 2>"$OUT/err.txt" \
   && "$PART" tests/regression/patch_constant_strain/deck.k -n 8 -o "$OUT/empty" --verify \
        >>"$OUT/err.out" 2>>"$OUT/err.txt" \
   && grep -q '^empty ranks (no elements): 1' "$OUT/empty/partition.txt" \
   && [ -f "$OUT/empty/rank_00007.h5" ]; then
    pass "7 elements on 8 ranks: exit 0, files verified, report lists 1 empty rank"
else
    fail "7 elements on 8 ranks: $(cat "$OUT/err.txt"; grep empty "$OUT/empty/partition.txt" 2>/dev/null)"
fi
echo "$np_ passed, $nf_ failed"
[ $nf_ -eq 0 ] || exit 1
exit 0
