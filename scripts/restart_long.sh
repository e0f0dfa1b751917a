#!/bin/sh
# Long restart checks (make restart-long): every scene deck in decks/ run to the end, then
# stopped by SIGTERM (self-raised at a random cycle and a real one after a random delay), by
# the wall-clock limit and by SIGUSR1, and continued (scripts/check_restart.sh); then 20
# kill -9 runs on the whole Simo Taylor impact (scripts/kill9_check.py --endtim 0.08).
set -u
cd "$(dirname "$0")/.." || exit 2
fail=0
for deck in decks/*/*.k; do
    scene=$(basename "$(dirname "$deck")")_$(basename "$deck" .k)
    out=build/restart_long/$scene
    rm -rf "$out"; mkdir -p "$out"
    echo "== $scene"
    t0=$(date +%s%N)
    if ! bin/dynx -i "$deck" -o "$out/ref" > "$out/ref.log" 2>&1; then
        echo "   reference run failed"; fail=1; continue
    fi
    ms=$(( ($(date +%s%N) - t0) / 1000000 ))
    # a real SIGTERM after a random delay and the wall-clock limit need a run of some seconds
    modes="cycle usr1"
    [ $ms -gt 2500 ] && modes="cycle sigterm walltime usr1"
    echo "   reference run ${ms} ms: modes $modes"
    sh scripts/check_restart.sh "$deck" "$out/ref" "$out" $modes || fail=1
done
python3 scripts/kill9_check.py --runs 20 --endtim 0.08 --workdir build/restart_long/kill9 || fail=1
exit $fail
