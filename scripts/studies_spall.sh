#!/bin/sh
# make studies (spall): the plate impact of tests/regression/spall_plate_impact
# (scripts/gen_spall_deck.py: flyer 2 mm at 200 m/s on a 4 mm target, elastic steel,
# *MAT_ADD_EROSION SIGTH 2 GPa, IMPULSE 3e-4 GPa^2 ms) at nx = 30, 60, 120, 240 (SPALL_NX):
# per mesh the errors of scripts/spall_check.py --table against the analytic times (arrival
# 2H/c, first erosion 3H/c + dt_TB, spall signal 4H/c + dt_TB), the spall-plane offset, the
# plateau error and the pull-back ratio (1/2 rho c du_fs) / sigma, the eroded elements and the
# wall time; the observed order of each error between successive meshes (log2 of the ratio).
# Writes docs/studies/spall.md and docs/studies/data/spall.dat.
set -e
cd "$(dirname "$0")/.."
[ -x bin/dynx ] || make all
B=build/studies/spall
D=docs/studies
mkdir -p "$B" "$D/data"
tab=$D/data/spall.dat
echo "# nx err_arrival_ms err_erosion_ms err_signal_ms dx_plane_mm err_plateau pullback_ratio wall_s eroded" > $tab
for nx in ${SPALL_NX:-30 60 120 240}; do
    k=$B/nx$nx
    /usr/bin/python3 scripts/gen_spall_deck.py --nx $nx --tend 0.0018 $k.k > /dev/null
    t0=$(date +%s.%N)
    bin/dynx -i $k.k -o $k --status 2 > $k.log 2>&1
    t1=$(date +%s.%N)
    row=$(/usr/bin/python3 scripts/spall_check.py $k $nx --table)
    ne=$(/usr/bin/python3 -c "
import h5py, sys
f = h5py.File('$k/d3plot.h5', 'r')
s = sorted(x for x in f['states'] if x != 'times')[-1]
print(int(f['states/' + s + '/failed'][:].sum()))")
    echo "$row $(python3 -c "print('%.2f' % ($t1 - $t0))") $ne" >> $tab
done
/usr/bin/python3 - "$tab" > $D/spall.md <<'PY'
import sys, math
rows = [l.split() for l in open(sys.argv[1]) if l.lstrip()[:1] in tuple('+-.0123456789')]
print('# Spall plate impact: errors against the mesh\n')
print('Written by `scripts/studies_spall.sh` (`make studies`). The deck of '
      '`tests/regression/spall_plate_impact` (flyer 2 mm at 200 m/s on a 4 mm target of '
      'elastic steel in uniaxial strain, Tuler-Butcher SIGTH 2 GPa, IMPULSE 3e-4 GPa^2 ms, '
      'c = 6000.98 mm/ms, sigma = 4.7108 GPa, dt_TB = 4.083e-5 ms) at nx elements over 6 mm; '
      'errors are dynx minus analytic (`scripts/spall_check.py`).\n')
print('| nx | arrival 2H/c [ns] | first erosion 3H/c+dt_TB [ns] | spall signal 4H/c+dt_TB [ns] '
      '| plane offset [mm] | plateau/2u_p - 1 | pull-back (rho c du/2)/sigma | eroded | wall [s] |')
print('|---|---|---|---|---|---|---|---|---|')
for r in rows:
    print('| %s | %+.1f | %+.1f | %+.1f | %+.4f | %+.4f | %.4f | %s | %s |' % (
        r[0], 1e6 * float(r[1]), 1e6 * float(r[2]), 1e6 * float(r[3]), float(r[4]),
        float(r[5]), float(r[6]), r[8], r[7]))
print('\nObserved order log2(|e(nx)| / |e(2 nx)|) of the spall-signal time error and of the '
      'pull-back deficit 1 - ratio:\n')
print('| nx -> 2nx | signal time | pull-back |')
print('|---|---|---|')
for a, b in zip(rows, rows[1:]):
    def order(i, f=lambda v: abs(v)):
        x, y = f(float(a[i])), f(float(b[i]))
        return '%.2f' % math.log2(x / y) if x > 0 and y > 0 else '-'
    print('| %s -> %s | %s | %s |' % (a[0], b[0], order(3), order(6, lambda v: abs(1 - v))))
print('\nReading: the first eroded element has a face at x = 2H (offset half an element: '
      'its centre). The spall-signal error falls below an element transit time and then '
      'stalls: the bulk viscosity smears the fronts over a few elements, and on the finer '
      'meshes more elements erode beside the first: with a square pulse every element of '
      'the tension zone sees the tension for the same dt_TB (it starts and ends at c on '
      'both sides of the plane), so Tuler-Butcher is marginal there and the smeared fronts '
      'tip neighbours over; a clean order needs a pulse shape without that tie. The '
      'pull-back approaches the full tension sigma as the front sharpens. The energy ratio '
      'is 1 to 11 digits on every mesh (spall_check.py).')
PY
echo "wrote $D/spall.md"
