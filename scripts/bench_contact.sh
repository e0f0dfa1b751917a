#!/bin/sh
# make bench (contact part): N elastic cubes (3^3 hexes each) with random velocities in a box
# of stonewalls, *CONTACT_AUTOMATIC_SINGLE_SURFACE, 200 cycles, N = 1 .. 1000. Reports the
# wall time per cycle of the bucket sorts and of the local search + penalty forces (printed
# by dynx at the end of the run), per cycle and per slave node. Then the cost of contact for
# a deck without *CONTACT: the same 1000-cube deck without the keyword, run alternately with
# bin/dynx and with a binary built from the commit before contact (CONTACT_BASE, default
# 1d8c3f3) when git can provide it. Appends a dated table to docs/performance.md.
set -e
cd "$(dirname "$0")/.."
B=build/bench_contact
mkdir -p $B
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
NCYC=${NCYC:-200}
{
echo ""
echo "### make bench (contact), $(date -u +%Y-%m-%d), commit $rev, $cpu, load $(cut -d' ' -f1 /proc/loadavg)"
echo ""
echo "| cubes | elements | contact nodes | cycles | bucket sorts | candidates / node | search [us/cycle] | forces [us/cycle] | search+forces [ns / node-cycle] | total [us/cycle] |"
echo "|---|---|---|---|---|---|---|---|---|---|"
} > $B/table.md
for n in 1 8 27 64 125 216 343 512 729 1000; do
    python3 scripts/gen_contact_decks.py cubes --ncube $n --ncyc $NCYC $B/cubes_$n.k
    bin/dynx -i $B/cubes_$n.k -o $B/cubes_$n --status 1 > $B/cubes_$n.log 2>&1 || { tail $B/cubes_$n.log; exit 1; }
    python3 - "$B/cubes_$n.log" "$n" >> $B/table.md <<'PY'
import re, sys
log = open(sys.argv[1]).read()
m = re.search(r'contact: \d+ interface\(s\), (\d+) contact nodes, (\d+) bucket sorts, wall time '
              r'search ([0-9.E+-]+) s, local search \+ forces ([0-9.E+-]+) s, candidates per '
              r'slave node ([0-9.E+-]+)', log)
cyc = int(re.search(r'normal termination at cycle (\d+)', log).group(1))
wall = float(re.search(r'wall time ([0-9.E+-]+) s,', log).group(1))
ne = int(re.search(r'(\d+) elements', log).group(1))
nodes, sorts, ts, tf, cand = int(m.group(1)), int(m.group(2)), float(m.group(3)), float(m.group(4)), float(m.group(5))
print('| %s | %d | %d | %d | %d | %.2f | %.1f | %.1f | %.0f | %.1f |' % (
    sys.argv[2], ne, nodes, cyc, sorts, cand, 1e6 * ts / cyc, 1e6 * tf / cyc,
    1e9 * (ts + tf) / cyc / nodes, 1e6 * wall / cyc))
PY
    tail -1 $B/table.md
done
# ---- a deck without *CONTACT pays nothing: new binary against the pre-contact binary
python3 scripts/gen_contact_decks.py cubes --ncube 1000 --ncyc $NCYC --nocontact $B/nocontact.k
base=${CONTACT_BASE:-1d8c3f3}
old=$B/old/bin/dynx
if [ ! -x $old ] && git cat-file -e "$base^{commit}" 2>/dev/null; then
    rm -rf $B/old && mkdir -p $B/old
    git archive "$base" | tar -x -C $B/old
    (cd $B/old && make -j2 bin/dynx > build.log 2>&1) || echo "bench: could not build $base"
fi
if [ -x $old ]; then
    echo "" >> $B/table.md
    echo "Deck without *CONTACT (1000 cubes, 27,000 hexes, stonewalls, $NCYC cycles), ns per element-cycle, runs alternating:" >> $B/table.md
    echo "" >> $B/table.md
    echo "| run | pre-contact $base | this commit | ratio new/old |" >> $B/table.md
    echo "|---|---|---|---|" >> $B/table.md
    for k in 1 2 3; do
        $old -i $B/nocontact.k -o $B/nc_old --status 1 > $B/nc_old.log 2>&1
        bin/dynx -i $B/nocontact.k -o $B/nc_new --status 1 > $B/nc_new.log 2>&1
        o=$(sed -n 's/.*s, \([0-9.eE+-]*\) ns per element-cycle.*/\1/p' $B/nc_old.log)
        w=$(sed -n 's/.*s, \([0-9.eE+-]*\) ns per element-cycle.*/\1/p' $B/nc_new.log)
        echo "| $k | $o | $w | $(python3 -c "print('%.3f' % ($w/$o))") |" >> $B/table.md
    done
fi
cat $B/table.md >> docs/performance.md
cat $B/table.md
