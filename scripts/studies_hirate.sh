#!/bin/sh
# make studies (issue 18, high-rate materials): error against run time and observed order of
#  1. the Mie-Gruneisen shock (tests/regression/mat_null_eos_gruneisen: *MAT_NULL +
#     *EOS_GRUNEISEN copper bar driven at 500 m/s, scripts/gen_wave_deck.py) at nx = 50, 100,
#     200, 400 (HIRATE_WAVE_NX): the Hugoniot point (plateau pressure against rho0 Us up) and
#     the shock front against Us t (scripts/dxpost.py wave);
#  2. the Steinberg-Guinan plate impact (tests/regression/hirate_plate_steinberg, its material
#     block on the gen_wave_deck mesh) at nx = 400, 800, 1600, 3200 (HIRATE_PLATE_NX; its check's
#     plateau windows of 16 elements need nx >= 400 over the 12 mm between the fronts): the
#     precursor front, the HEL and the shock jump of its check.py;
#  3. the Taylor tests of decks/taylor_steinberg (Steinberg-Guinan and Johnson-Cook copper)
#     on the quarter O-grid (n, n, 6n) for n = 3, 4, 6 (HIRATE_TAYLOR_N): final length and
#     footprint against the experiment, the observed order of the mesh differences and the
#     Richardson-extrapolated length;
#  4. the brittle damage models on the material-point driver paths (tests/unit/study_brittle_dt.f90):
#     D against the continuous-time equations of docs/damage.md for N = 25 .. 1600 steps.
# Writes docs/studies/hirate.md and docs/studies/data/hirate_*.dat. HIRATE_SKIP="wave plate
# taylor brittle" leaves parts out (their data files are reused when present).
set -e
cd "$(dirname "$0")/.."
[ -x bin/dynx ] || make all
B=build/studies/hirate
D=docs/studies
mkdir -p "$B" "$D/data"
skip=" ${HIRATE_SKIP:-} "
now() { date +%s.%N; }
el() { python3 -c "print('%.2f' % ($2 - $1))"; }

# ---- 1. Mie-Gruneisen shock in *MAT_NULL
if [ "${skip#* wave }" = "$skip" ]; then
    tab=$D/data/hirate_wave.dat
    echo "# nx plateau_GPa plateau_ref_GPa front_mm front_ref_mm wall_s" > $tab
    for nx in ${HIRATE_WAVE_NX:-50 100 200 400}; do
        k=$B/wave$nx
        python3 scripts/gen_wave_deck.py --nx $nx --gruneisen 3940,1.489,0,0,2.02,0.47 \
            --rho 8.93e-6 --v 500 $k.k > /dev/null
        t0=$(now); bin/dynx -i $k.k -o $k > $k.log 2>&1; t1=$(now)
        python3 scripts/dxpost.py wave $k --rho 8.93e-6 --v 500 --us-fit 3940 1.489 \
            --tol-plateau 1 --tol-front 1000 > $k.post || true
        pl=$(grep '^plateau stress' $k.post | awk '{print $4, $6}')
        fr=$(grep '^front position' $k.post | awk '{print $4, $6}')
        echo "$nx $pl $fr $(el $t0 $t1)" >> $tab
    done
fi

# ---- 2. Steinberg-Guinan plate impact: precursor, HEL, shock jump
if [ "${skip#* plate }" = "$skip" ]; then
    tab=$D/data/hirate_plate.dat
    echo "# nx precursor_mm precursor_ref_mm hel_GPa hel_ref_GPa jump_GPa jump_ref_GPa wall_s" > $tab
    for nx in ${HIRATE_PLATE_NX:-400 800 1600 3200}; do
        k=$B/plate$nx
        python3 scripts/gen_wave_deck.py --nx $nx --v 100 --tend 0.018 $k.mesh.k > /dev/null
        python3 - tests/regression/hirate_plate_steinberg/deck.k $k.mesh.k $k.k <<'PY'
import sys
ref = open(sys.argv[1]).read()
mesh = open(sys.argv[2]).read()
# the regression deck's controls and material, the mesh, loads and outputs of this nx
# (the history node is the mesh's own: its nodout is not used here)
open(sys.argv[3], 'w').write(ref[:ref.index('*NODE')] + mesh[mesh.index('*NODE'):])
PY
        t0=$(now); bin/dynx -i $k.k -o $k > $k.log 2>&1; t1=$(now)
        python3 tests/regression/hirate_plate_steinberg/check.py $k > $k.post 2>&1 || true
        pr=$(grep '^precursor front' $k.post | awk '{print $4, $6}')
        he=$(grep '^HEL sigma_xx' $k.post | awk '{print $4, $6}')
        ju=$(grep '^shock sigma_xx' $k.post | awk '{print $4, $6}')
        echo "$nx $pr $he $ju $(el $t0 $t1)" >> $tab
    done
fi

# ---- 3. Taylor tests, Steinberg-Guinan and Johnson-Cook
if [ "${skip#* taylor }" = "$skip" ]; then
    tab=$D/data/hirate_taylor.dat
    echo "# material n elements Lf_mm Rf_mm max_abs_energy_ratio_minus_1 wall_s" > $tab
    for mat in steinberg johnson_cook; do
        for n in ${HIRATE_TAYLOR_N:-3 4 6}; do
            k=$B/taylor_${mat}_$n
            python3 scripts/gen_taylor_deck.py --L 23.47 --R 3.81 --v 210 --mat wg --tend 0.1 \
                --quarter --n $n --m $n --nz $((6 * n)) $k.mesh.k > /dev/null
            python3 - decks/taylor_steinberg/deck_$mat.k $k.mesh.k $k.k <<'PY'
import sys
ref = open(sys.argv[1]).read()
mesh = open(sys.argv[2]).read()
open(sys.argv[3], 'w').write(ref[:ref.index('*NODE')] + mesh[mesh.index('*NODE'):])
PY
            t0=$(now); bin/dynx -i $k.k -o $k > $k.log 2>&1; t1=$(now)
            python3 scripts/dxpost.py taylor $k --L0 23.47 --R0 3.81 > $k.post 2>&1 || true
            lr=$(grep 'final length' $k.post | head -1 | sed 's/.*final length \([0-9.]*\) mm  footprint radius \([0-9.]*\) mm.*/\1 \2/')
            er=$(awk '!/^#/ && $10 != 0 { d = $10 - 1; if (d < 0) d = -d; if (d > m) m = d } END { printf "%.2e", m }' $k/glstat)
            echo "$mat $n $((n * n * 3 * 6 * n)) $lr $er $(el $t0 $t1)" >> $tab
        done
    done
fi

# ---- 4. brittle damage models on the material-point driver: time-step error (release build)
if [ "${skip#* brittle }" = "$skip" ]; then
    make --no-print-directory build/release/bench/study_brittle_dt > /dev/null
    build/release/bench/study_brittle_dt > $D/data/hirate_brittle_dt.md
fi

/usr/bin/python3 scripts/studies_hirate_table.py > $D/hirate.md
echo "wrote $D/hirate.md"
