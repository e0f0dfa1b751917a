#!/bin/sh
# Regression runner: runs every tests/regression/<case>/ (sorted) and checks it.
#
#   scripts/run_regression.sh [--root DIR] [-j N] [case...]
#                                      run all cases of DIR (default tests/regression), or only
#                                      the named ones; -j N: N cases at a time (the output is
#                                      the same as with -j 1, in the same order, printed as the
#                                      cases end in that order)
#   scripts/run_regression.sh [--root DIR] --update case...   run the cases and copy their
#                                      outputs into gold/ (one at a time)
#
# A case is a directory with deck.k and optionally:
#   args        extra command-line arguments for bin/dynx (one line, split on blanks)
#   expect      expected failure: lines 'exit N' and 'stderr <substring>' (any number of
#               stderr lines; each substring must occur in stderr); '#' starts a comment
#   gold/       gold outputs (d3plot.h5, glstat, nodout, ...), each compared with the file of
#               the same name in the output directory by bin/dynx-compare
#   tolerances  tolerance file for bin/dynx-compare (format: docs/output-format.md)
#   check       an analytic check: a shell script run as 'sh check OUTDIR' from the top
#               directory after the run (after a successful run, or after an expected failure
#               when the case has an expect file); a non-zero exit fails the case (its output
#               is kept in OUTDIR/check.log and shown on failure)
# Without 'expect' the run must exit 0 and every gold file must compare equal within tolerance.
# Outputs go to build/regression/<case>/ (stdout and stderr captured there; REGRESSION_OUT
# sets another folder). A case root other than tests/regression: its cases' check scripts
# run from the top directory of dynx like the others (paths in them are theirs).
# Prints 'PASS <case>' or 'FAIL <case>: reason' per case, then 'N passed, N failed';
# exits 1 if any case failed. Environment: DYNX (default bin/dynx), DYNX_COMPARE (default
# bin/dynx-compare), REGRESSION_TIMEOUT seconds per case (default 900, when timeout(1) exists).
set -u
LC_ALL=C
export LC_ALL
start=$(pwd)
cd "$(dirname "$0")/.." || exit 2

DYNX=${DYNX:-bin/dynx}
COMPARE=${DYNX_COMPARE:-bin/dynx-compare}
ROOT=tests/regression
OUTROOT=${REGRESSION_OUT:-build/regression}
TIMEOUT=${REGRESSION_TIMEOUT:-900}

update=0
jobs=1
while [ $# -gt 0 ]; do
    case $1 in
        --update) update=1; shift ;;
        --root)
            [ $# -ge 2 ] || { echo "run_regression: --root needs a folder" >&2; exit 2; }
            ROOT=$2; shift 2 ;;
        --root=*) ROOT=${1#--root=}; shift ;;
        -j)
            [ $# -ge 2 ] || { echo "run_regression: -j needs a number" >&2; exit 2; }
            jobs=$2; shift 2 ;;
        -j*) jobs=${1#-j}; shift ;;
        --) shift; break ;;
        -*) echo "run_regression: unknown option $1 (usage: $0 [--root DIR] [-j N] [--update] [case...])" >&2
            exit 2 ;;
        *) break ;;
    esac
done
case $jobs in
    ''|*[!0-9]*|0) echo "run_regression: -j wants a whole number >= 1, got '$jobs'" >&2; exit 2 ;;
esac
case $ROOT in
    /*) ;;
    *) # relative to where it was called (kept as written when that is the top directory,
       # so the messages name tests/regression/... as the expect files do)
       [ "$start" != "$(pwd)" ] && [ -d "$start/$ROOT" ] && ROOT=$start/$ROOT ;;
esac
ROOT=${ROOT%/}
if [ ! -d "$ROOT" ]; then
    echo "run_regression: no case root $ROOT" >&2
    exit 2
fi
if [ $update -eq 1 ] && [ $# -eq 0 ]; then
    echo "usage: $0 [--root DIR] --update case..." >&2
    exit 2
fi
[ $update -eq 1 ] && jobs=1

for tool in "$DYNX" "$COMPARE"; do
    if [ ! -x "$tool" ]; then
        echo "run_regression: $tool not found; build it first (make all)" >&2
        exit 2
    fi
done

# the cases: named on the command line, else every directory under tests/regression
cases=""
if [ $# -gt 0 ]; then
    for c in "$@"; do
        c=${c%/}
        c=${c##*/}
        if [ ! -f "$ROOT/$c/deck.k" ]; then
            echo "run_regression: no case $ROOT/$c (needs deck.k)" >&2
            exit 2
        fi
        cases="$cases $c"
    done
else
    for d in "$ROOT"/*/; do
        [ -f "${d}deck.k" ] || continue
        d=${d%/}
        cases="$cases ${d##*/}"
    done
fi

npass=0
nfail=0

# run_case CASE: runs dynx for the case; sets rc
run_case() {
    c=$1
    out=$OUTROOT/$c
    rm -rf "$out"
    mkdir -p "$out"
    extra=""
    if [ -f "$ROOT/$c/args" ]; then
        extra=$(grep -v '^[[:space:]]*#' "$ROOT/$c/args" | tr '\n' ' ')
    fi
    if command -v timeout >/dev/null 2>&1; then
        # shellcheck disable=SC2086   # extra arguments are split on blanks on purpose
        timeout "$TIMEOUT" "$DYNX" -i "$ROOT/$c/deck.k" -o "$out" $extra \
            >"$out/stdout" 2>"$out/stderr"
    else
        # shellcheck disable=SC2086
        "$DYNX" -i "$ROOT/$c/deck.k" -o "$out" $extra >"$out/stdout" 2>"$out/stderr"
    fi
    rc=$?
}

# check_expect CASE: checks exit code and stderr substrings; sets reason ('' = pass)
check_expect() {
    c=$1
    reason=""
    want_exit=""
    while IFS= read -r line || [ -n "$line" ]; do
        case $line in
            ''|'#'*) continue ;;
            'exit '*)
                want_exit=${line#exit }
                want_exit=$(echo "$want_exit" | tr -d ' \t\r')
                ;;
            'stderr '*)
                sub=${line#stderr }
                if ! grep -F -q -- "$sub" "$OUTROOT/$c/stderr"; then
                    reason="${reason:+$reason; }stderr lacks '$sub'"
                fi
                ;;
            *)
                reason="${reason:+$reason; }bad line in expect: '$line'"
                ;;
        esac
    done <"$ROOT/$c/expect"
    if [ -n "$want_exit" ] && [ "$rc" != "$want_exit" ]; then
        reason="exit code $rc, expected $want_exit${reason:+; $reason}"
    fi
}

# check_gold CASE: requires exit 0 and compares every gold file; sets reason, report
check_gold() {
    c=$1
    reason=""
    report=""
    if [ "$rc" -ne 0 ]; then
        reason="exit code $rc (see $OUTROOT/$c/stderr)"
        report=$(tail -n 5 "$OUTROOT/$c/stderr")
        return
    fi
    if [ ! -d "$ROOT/$c/gold" ] && [ ! -f "$ROOT/$c/check" ]; then
        reason="no gold/, no check and no expect file"
        return
    fi
    tol=""
    [ -f "$ROOT/$c/tolerances" ] && tol="--tol $ROOT/$c/tolerances"
    ncmp=0
    for g in "$ROOT/$c"/gold/*; do
        [ -f "$g" ] || continue
        f=${g##*/}
        case $f in
            *.xdmf|*.png|README*) continue ;;   # derived or descriptive files
        esac
        ncmp=$((ncmp + 1))
        if [ ! -f "$OUTROOT/$c/$f" ]; then
            reason="${reason:+$reason; }missing output $f"
            continue
        fi
        # shellcheck disable=SC2086
        r=$("$COMPARE" $tol "$g" "$OUTROOT/$c/$f" 2>&1)
        st=$?
        if [ $st -ne 0 ]; then
            reason="${reason:+$reason; }$f differs"
            [ $st -ne 1 ] && reason="$reason (dynx-compare exit $st)"
            report="$report$r
"
        fi
    done
    [ $ncmp -eq 0 ] && [ ! -f "$ROOT/$c/check" ] && reason="gold/ holds no files to compare"
    if [ -f "$ROOT/$c/check" ]; then
        if ! sh "$ROOT/$c/check" "$OUTROOT/$c" >"$OUTROOT/$c/check.log" 2>&1; then
            reason="${reason:+$reason; }analytic check failed"
            report="$report$(cat "$OUTROOT/$c/check.log")
"
        fi
    fi
}

# one_case CASE: runs and checks it, prints 'PASS CASE' or 'FAIL CASE: reason' (and the
# report) or the UPDATE lines
one_case() {
    c=$1
    run_case "$c"
    if [ $update -eq 1 ]; then
        if [ -f "$ROOT/$c/expect" ]; then
            echo "UPDATE $c: has an expect file (no gold outputs); nothing copied"
            return
        fi
        if [ "$rc" -ne 0 ]; then
            echo "UPDATE $c: run failed with exit code $rc; gold left unchanged" >&2
            echo "FAIL $c: run failed"
            return
        fi
        mkdir -p "$ROOT/$c/gold"
        files=$(ls "$ROOT/$c/gold")
        [ -n "$files" ] || files="d3plot.h5 glstat nodout"
        for f in $files; do
            if [ -f "$OUTROOT/$c/$f" ]; then
                cp "$OUTROOT/$c/$f" "$ROOT/$c/gold/$f"
                echo "UPDATE $c: gold/$f"
            fi
        done
        return
    fi
    if [ -f "$ROOT/$c/expect" ]; then
        report=""
        check_expect "$c"
        [ -n "$reason" ] && report=$(tail -n 5 "$OUTROOT/$c/stderr")
        # a failing run may also have a check (e.g. its last state must stay readable)
        if [ -f "$ROOT/$c/check" ] && \
           ! sh "$ROOT/$c/check" "$OUTROOT/$c" >"$OUTROOT/$c/check.log" 2>&1; then
            reason="${reason:+$reason; }check failed"
            report="$report$(cat "$OUTROOT/$c/check.log")"
        fi
    else
        check_gold "$c"
    fi
    if [ -z "$reason" ]; then
        echo "PASS $c"
    else
        echo "FAIL $c: $reason"
        [ -n "$report" ] && printf '%s\n' "$report" | sed '/^$/d; s/^/    /'
    fi
}

# the results, one file per case, printed in the cases' order and counted
resdir=$OUTROOT/.results.$$
rm -rf "$resdir"
mkdir -p "$resdir"
trap 'rm -rf "$resdir"' EXIT
tally() {   # tally CASE: print its result, count it
    cat "$resdir/$1"
    if grep -q "^FAIL $1:" "$resdir/$1"; then
        nfail=$((nfail + 1))
    else
        npass=$((npass + 1))
    fi
}
if [ "$jobs" -le 1 ]; then
    for c in $cases; do
        one_case "$c" >"$resdir/$c"
        tally "$c"
    done
else
    # N lanes, case k in lane k mod N, each lane one case after the other in the background;
    # a case's result is printed once it and every case before it have ended
    lane=0
    while [ $lane -lt "$jobs" ]; do
        (
            k=0
            for c in $cases; do
                if [ $((k % jobs)) -eq $lane ]; then
                    one_case "$c" >"$resdir/$c.part"
                    mv "$resdir/$c.part" "$resdir/$c"
                fi
                k=$((k + 1))
            done
        ) &
        lane=$((lane + 1))
    done
    for c in $cases; do
        while [ ! -f "$resdir/$c" ]; do sleep 0.2; done
        tally "$c"
    done
    wait
fi

if [ $update -eq 1 ]; then
    echo "Reminder: gold files change only with a reason in the commit message."
    [ $nfail -eq 0 ] || exit 1
    exit 0
fi
[ -n "$cases" ] || echo "run_regression: no cases under $ROOT"
echo "$npass passed, $nfail failed"
[ $nfail -eq 0 ] || exit 1
exit 0
