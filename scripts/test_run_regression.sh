#!/bin/sh
# The regression runner on another case root, one case at a time and in parallel
# (scripts/run_regression.sh --root DIR -j N): a root of three quick cases built here from
# tests/regression/bad_missing_card (exit 2 expected), one of them made to fail (its expect
# asks for exit 3). Checks: -j 1 and -j 3 print the same lines in the same order (the
# cases' order), the last line is '2 passed, 1 failed' and the exit status 1; a root given
# relative to the calling folder is found; an unknown option and -j 0 are refused (exit 2).
# Prints 'N passed, M failed'.
set -u
cd "$(dirname "$0")/.." || exit 2
top=$(pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dynx_runner.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
pass=0; fail=0
ok() { echo "  PASS $*"; pass=$((pass + 1)); }
bad() { echo "  FAIL $*"; fail=$((fail + 1)); }
mkdir -p "$tmp/root"
for c in a_pass b_fail c_pass; do
    cp -r tests/regression/bad_missing_card "$tmp/root/$c"
done
sed -i 's/^exit 2$/exit 3/' "$tmp/root/b_fail/expect"
REGRESSION_OUT=$tmp/out1 sh scripts/run_regression.sh --root "$tmp/root" > "$tmp/serial.txt" 2>&1
rc1=$?
REGRESSION_OUT=$tmp/out3 sh scripts/run_regression.sh --root "$tmp/root" -j 3 > "$tmp/par.txt" 2>&1
rc3=$?
if cmp -s "$tmp/serial.txt" "$tmp/par.txt"; then
    ok "-j 1 and -j 3 print the same lines"
else
    bad "-j 1 and -j 3 differ"; diff "$tmp/serial.txt" "$tmp/par.txt"
fi
order=$(grep -oE '^(PASS|FAIL) [a-z_]+' "$tmp/par.txt" | tr '\n' ' ')
if [ "$order" = "PASS a_pass FAIL b_fail PASS c_pass " ] && \
   [ "$(tail -n 1 "$tmp/par.txt")" = "2 passed, 1 failed" ] && [ $rc1 -eq 1 ] && [ $rc3 -eq 1 ]; then
    ok "order a, b, c; last line '2 passed, 1 failed'; exit 1 both ways"
else
    bad "order '$order', last line '$(tail -n 1 "$tmp/par.txt")', exit $rc1 / $rc3"
fi
(cd "$tmp" && REGRESSION_OUT=$tmp/out4 sh "$top/scripts/run_regression.sh" --root root -j 2 a_pass > "$tmp/rel.txt" 2>&1)
if [ "$(cat "$tmp/rel.txt")" = "PASS a_pass
1 passed, 0 failed" ]; then
    ok "a root relative to the calling folder, a named case"
else
    bad "relative root"; cat "$tmp/rel.txt"
fi
sh scripts/run_regression.sh --bogus > /dev/null 2>&1; r1=$?
sh scripts/run_regression.sh -j 0 > /dev/null 2>&1; r2=$?
if [ $r1 -eq 2 ] && [ $r2 -eq 2 ]; then ok "unknown option, -j 0: exit 2"; else bad "exit $r1, $r2 (want 2, 2)"; fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
