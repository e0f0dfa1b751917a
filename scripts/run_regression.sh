#!/bin/sh
# Regression runner: runs every tests/regression/<case>/ (sorted) and checks it.
#
#   scripts/run_regression.sh [case...]          run all cases (or only the named ones)
#   scripts/run_regression.sh --update case...   run the cases and copy their outputs into gold/
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
# Outputs go to build/regression/<case>/ (stdout and stderr captured there).
# Prints 'PASS <case>' or 'FAIL <case>: reason' per case, then 'N passed, N failed';
# exits 1 if any case failed. Environment: DYNX (default bin/dynx), DYNX_COMPARE (default
# bin/dynx-compare), REGRESSION_TIMEOUT seconds per case (default 900, when timeout(1) exists).
set -u
LC_ALL=C
export LC_ALL
cd "$(dirname "$0")/.." || exit 2

DYNX=${DYNX:-bin/dynx}
COMPARE=${DYNX_COMPARE:-bin/dynx-compare}
ROOT=tests/regression
OUTROOT=build/regression
TIMEOUT=${REGRESSION_TIMEOUT:-900}

update=0
if [ "${1:-}" = "--update" ]; then
    update=1
    shift
    if [ $# -eq 0 ]; then
        echo "usage: $0 --update case..." >&2
        exit 2
    fi
fi

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

for c in $cases; do
    run_case "$c"
    if [ $update -eq 1 ]; then
        if [ -f "$ROOT/$c/expect" ]; then
            echo "UPDATE $c: has an expect file (no gold outputs); nothing copied"
            continue
        fi
        if [ "$rc" -ne 0 ]; then
            echo "UPDATE $c: run failed with exit code $rc; gold left unchanged" >&2
            nfail=$((nfail + 1))
            continue
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
        npass=$((npass + 1))
        continue
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
        npass=$((npass + 1))
    else
        echo "FAIL $c: $reason"
        [ -n "$report" ] && printf '%s\n' "$report" | sed '/^$/d; s/^/    /'
        nfail=$((nfail + 1))
    fi
done

if [ $update -eq 1 ]; then
    echo "Reminder: gold files change only with a reason in the commit message."
    [ $nfail -eq 0 ] || exit 1
    exit 0
fi
[ -n "$cases" ] || echo "run_regression: no cases under $ROOT"
echo "$npass passed, $nfail failed"
[ $nfail -eq 0 ] || exit 1
exit 0
