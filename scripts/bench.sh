#!/bin/sh
# make bench: ns per element-cycle and peak memory per element of the explicit hex8 kernel on
# an elastic-plastic cube of growing size (1e3 .. 1e6 elements), and the 10,368-element
# copper Taylor bar of the performance target; the 22**3 cube again with *MAT_NULL + *EOS_GRUNEISEN,
# with *MAT_STEINBERG + *EOS_GRUNEISEN, and with the brittle models *DYNX_BRITTLE_DAMAGE MODEL 1-3
# and *DYNX_BRITTLE_CRACK (fused silica of scripts/gen_brittle_deck.py; the 50 m/s impact on the
# wall puts the lateral faces in tension past the thresholds, so the damage paths run: at the
# end 93 % (MODEL 1), 6 % (2), 85 % (3) of the elements damaged) (issue 18).
# BENCH_ONLY=hirate runs only the 22**3 cube rows (piecewise-linear and issue 18's models).
# Beams (issue 17): a 20 000-element cantilever (scripts/gen_beam_deck.py bench), 1000 cycles,
# of resultant beams (ELFORM 2), of Hughes-Liu beams (ELFORM 1, 2x2 Gauss, elastic) and of
# Hughes-Liu beams of *MAT_003 yielding (the plastic cantilever's tip rotation, 4x4 Gauss);
# BENCH_ONLY=beam runs only these rows. Shells: the 80x16 cantilever plate of ELFORM 2 and 16
# (BENCH_ONLY=shell). 2D solids (issue 19): the round elastic bar of scripts/gen_quad2d_decks.py
# bar, 20 x 600 quads of ELFORM 13, 14, 15 (plane strain, area- and volume-weighted
# axisymmetric), and the 2D-vs-3D cost: the 10 x 300 ELFORM 15 bar (quad2d_bar_vw's bar at
# twice its resolution) against the same bar as a quarter of 3D hexahedra on the same r-z
# mesh (gen_quad2d_decks.py hexbar: 10 rings x 8 x 300, wedges at the axis, as quad2d_bar_hex),
# to the same end time, the ratio of their user times (BENCH_ONLY=quad).
# Appends a dated table to docs/performance.md.
set -e
cd "$(dirname "$0")/.."
B=build/bench
mkdir -p $B
host=$(uname -n); cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
{
echo ""
echo "### make bench, $(date -u +%Y-%m-%d), commit $rev, $cpu"
echo ""
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg); CPU ns: user time / (elements x cycles), the figure to compare on a loaded machine"
echo ""
echo "| case | elements | cycles | wall [s] | ns / element-cycle | CPU ns / element-cycle | peak RSS [KiB] | bytes / element |"
echo "|---|---|---|---|---|---|---|---|"
} > $B/table.md
run_case() {   # name deck elements
    /usr/bin/time -f '%U' -o $B/$1.cpu bin/dynx -i "$2" -o $B/$1 --status 2 > $B/$1.log 2>&1 || { echo "bench: $1 failed"; tail $B/$1.log; exit 1; }
    ns=$(grep 'ns per element-cycle' $B/$1.log | sed 's/.*s, \([0-9.eE+-]*\) ns per.*/\1/')
    wall=$(grep 'ns per element-cycle' $B/$1.log | sed 's/.*wall time \([0-9.eE+-]*\) s.*/\1/')
    kib=$(grep 'ns per element-cycle' $B/$1.log | sed 's/.*peak memory \([0-9]*\) KiB.*/\1/')
    cyc=$(grep 'normal termination' $B/$1.log | sed 's/.*cycle \([0-9]*\),.*/\1/')
    bpe=$(python3 -c "print(round($kib*1024/$3))")
    cns=$(python3 -c "print('%.3E' % ($(tail -1 $B/$1.cpu)*1e9/($3*$cyc)))")
    echo "| $1 | $3 | $cyc | $wall | $ns | $cns | $kib | $bpe |" >> $B/table.md
    echo "bench: $1: $ns ns/element-cycle (CPU $cns), $bpe bytes/element"
}
beam_rows() {
    for kind in bs hl hl_plastic; do
        python3 scripts/gen_beam_deck.py bench 20000 $kind $B/beam_$kind.k
        run_case beam_${kind}_20000 $B/beam_$kind.k 20000
    done
}
# Shells (issue 17): the 80x16 cantilever plate of scripts/gen_shell_deck.py (1280 shells,
# NIP 3, elastic, 1.0 ms: 9196 cycles) of Belytschko-Lin-Tsay (ELFORM 2) and fully integrated
# (ELFORM 16) shells, side by side; BENCH_ONLY=shell runs only these rows.
shell_rows() {
    for ef in 2 16; do
        SHELL_ELFORM=$ef python3 scripts/gen_shell_deck.py cantilever 80 16 $B/shell_$ef.k
        sed -i 's/^   15.0000$/    1.0000/' $B/shell_$ef.k
        run_case shell_elform${ef}_1280 $B/shell_$ef.k 1280
    done
}
# 2D solids (issue 19): ns per quad element-cycle, then the axisymmetric bar against its 3D twin
quad_rows() {
    for ef in 13 14 15; do
        mkdir -p $B/quad_$ef
        python3 scripts/gen_quad2d_decks.py bar $B/quad_$ef $ef 20 600
        run_case quad_elform${ef}_12000 $B/quad_$ef/deck.k 12000
    done
    mkdir -p $B/bar2d $B/bar3d
    python3 scripts/gen_quad2d_decks.py bar $B/bar2d 15 10 300
    run_case bar2d_elform15_3000 $B/bar2d/deck.k 3000
    python3 scripts/gen_quad2d_decks.py hexbar $B/bar3d 10 8 300
    run_case bar3d_hex_24000 $B/bar3d/deck.k 24000
    t2=$(tail -1 $B/bar2d_elform15_3000.cpu); t3=$(tail -1 $B/bar3d_hex_24000.cpu)
    r=$(python3 -c "print('%.3f' % ($t2/$t3) if $t3 > 0 else 'n/a')")
    { echo ""
      echo "2D against 3D (the same round bar, same r-z mesh, same end time): user time" \
           "bar2d_elform15_3000 $t2 s / bar3d_hex_24000 $t3 s = $r"; } >> $B/table.md
    echo "bench: 2D/3D user time $t2 / $t3 = $r"
}
if [ "${BENCH_ONLY:-}" = quad ]; then
    quad_rows
    cat $B/table.md >> docs/performance.md
    cat $B/table.md
    exit 0
fi
if [ "${BENCH_ONLY:-}" = shell ]; then
    shell_rows
    cat $B/table.md >> docs/performance.md
    cat $B/table.md
    exit 0
fi
if [ "${BENCH_ONLY:-}" = beam ]; then
    beam_rows
    cat $B/table.md >> docs/performance.md
    cat $B/table.md
    exit 0
fi
sizes="10 22 46 100"; [ "${BENCH_ONLY:-}" = hirate ] && sizes=22
for n in $sizes; do
    ne=$((n*n*n))
    cyc=$((20000000 / ne)); [ $cyc -lt 50 ] && cyc=50; [ $cyc -gt 2000 ] && cyc=2000
    python3 scripts/gen_cube_deck.py $n $cyc $B/cube_$n.k
    run_case cube_$ne $B/cube_$n.k $ne
done
# the high-rate materials beside the piecewise-linear figure of the same 22**3 cube (issue 18):
# *MAT_NULL + *EOS_GRUNEISEN and *MAT_STEINBERG + *EOS_GRUNEISEN (copper constants)
hydro_deck() {   # in out kind
    python3 - "$1" "$2" "$3" <<'PYEOF'
import argparse, sys
sys.path.insert(0, 'scripts')
src, out, kind = sys.argv[1:]
s = open(src).read()
i, j = s.index('*PART'), s.index('*NODE')
if kind in ('tb', 'jh2', 'growth', 'crack'):
    from gen_brittle_deck import block_material
    # FT 0.1 GPa for the crack model (0.5 is never reached here: the wall only compresses,
    # the lateral tension stays near 0.16 GPa), so its crack paths run as the scalar models' do
    mat = block_material(argparse.Namespace(model=kind, erod=0, fluid=False,
                                            ft=0.1 if kind == 'crack' else 0.5, sigy=6.0))
    open(out, 'w').write(s[:i] + '*PART\ncube\n         1         1         1\n'
                         '*SECTION_SOLID\n         1         1\n' + mat + s[j:])
    sys.exit(0)
eos = ('*EOS_GRUNEISEN\n         1    3940.0     1.489       0.0       0.0      2.02      0.47'
       '       0.0\n       1.0                   0\n')
mat = {'null': '*MAT_NULL\n         1    7.8E-6    -1.0E3       0.0\n',
       'steinberg': '*MAT_STEINBERG\n         1    7.8E-6      47.7      0.12      36.0      0.45'
       '       0.0      0.64\n    0.0283    0.0283   3.77e-4     0.001       0.0    1790.0      2.02'
       '       1.5\n     -1.e3       1.0   1.14e-3\n\n'}[kind]
open(out, 'w').write(s[:i] + '*PART\ncube\n         1         1         1         1\n'
                     '*SECTION_SOLID\n         1         1\n' + mat + eos + s[j:])
PYEOF
}
ne=10648
hydro_deck $B/cube_22.k $B/null_gruneisen_22.k null
run_case null_gruneisen_$ne $B/null_gruneisen_22.k $ne
hydro_deck $B/cube_22.k $B/steinberg_22.k steinberg
run_case steinberg_$ne $B/steinberg_22.k $ne
for kind in tb jh2 growth crack; do
    hydro_deck $B/cube_22.k $B/brittle_${kind}_22.k $kind
    run_case brittle_${kind}_$ne $B/brittle_${kind}_22.k $ne
done
if [ -f ../shared/bench/gen_taylor.py ] && [ "${BENCH_ONLY:-}" != hirate ]; then
    python3 ../shared/bench/gen_taylor.py 8 4 54 0.080 $B/taylor_10k.k > /dev/null
    run_case taylor_10k $B/taylor_10k.k 10368
fi
[ "${BENCH_ONLY:-}" != hirate ] && beam_rows
[ "${BENCH_ONLY:-}" != hirate ] && shell_rows
[ "${BENCH_ONLY:-}" != hirate ] && quad_rows
cat $B/table.md >> docs/performance.md
cat $B/table.md
