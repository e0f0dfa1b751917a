#!/bin/sh
# make studies (contact part): Hertz contact, quarter model (scripts/gen_contact_decks.py
# hertz): mesh sweep over the fine zone (N elements over 0.8 mm) at penalty scales SFS, with
# the error of the contact radius a and of the peak pressure p0 against Hertz (Johnson 1985,
# ch. 4; F from rcforc) and the wall time of each run. Writes docs/studies/hertz.md and
# docs/studies/hertz_error.png. Sequential runs. HERTZ_N and HERTZ_SFS override the sweep.
set -e
cd "$(dirname "$0")/.."
[ -x bin/dynx ] || make all
B=build/studies/hertz
D=docs/studies
mkdir -p "$B" "$D/data"
NS=${HERTZ_N:-"4 6 8"}
SS=${HERTZ_SFS:-"1 10"}
csv=$D/data/hertz.dat
echo "# sfs n elements wall_s F_kN a_mm a_hertz_mm p0_GPa p0_hertz_GPa err_a err_p0" > $csv
for s in $SS; do
    for n in $NS; do
        k=$B/hertz_s${s}_n$n
        python3 scripts/gen_contact_decks.py hertz --n $n --zone 0.8 --sfs $s $k.k > $k.gen
        ne=$(sed -n 's/hertz: \([0-9]*\) elements.*/\1/p' $k.gen)
        t0=$(date +%s.%N)
        bin/dynx -i $k.k -o $k --status 2 > $k.log 2>&1 || { echo "hertz s=$s n=$n failed"; tail -2 $k.log; continue; }
        t1=$(date +%s.%N)
        rm -f $k.csv
        python3 scripts/contact_post.py hertz $k --n $n --zone 0.8 --csv $k.csv > $k.post || true
        python3 - "$k.csv" "$s" "$n" "$ne" "$t0" "$t1" >> $csv <<'PY'
import sys
f = open(sys.argv[1]).read().split()
F, a, ah, p0, p0h = map(float, f[1:6])
print('%s %s %s %.2f %.5g %.5g %.5g %.5g %.5g %.4f %.4f' % (sys.argv[2], sys.argv[3], sys.argv[4],
      float(sys.argv[6]) - float(sys.argv[5]), F, a, ah, p0, p0h, a / ah - 1, p0 / p0h - 1))
PY
        tail -1 $csv
    done
done
cat > $D/data/hertz.gp <<'GP'
set terminal pngcairo size 900,500
set output 'hertz_error.png'
set logscale x
set xlabel 'wall time [s] (2-core machine shared with other jobs)'
set ylabel 'relative error against Hertz'
set title 'Hertz contact, quarter model: error of a and p0 against run time'
set key top right
set grid
plot 'hertz.dat' u ($1==1?$4:1/0):(abs($10)) w lp pt 7 t 'a, SFS = 1', \
     'hertz.dat' u ($1==1?$4:1/0):(abs($11)) w lp pt 5 t 'p0, SFS = 1', \
     'hertz.dat' u ($1==10?$4:1/0):(abs($10)) w lp pt 6 t 'a, SFS = 10', \
     'hertz.dat' u ($1==10?$4:1/0):(abs($11)) w lp pt 4 t 'p0, SFS = 10'
GP
(cd $D/data && gnuplot hertz.gp) && mv $D/data/hertz_error.png $D/
{
echo "# Hertz contact study (make studies)"
echo ""
echo "Quarter model of a steel sphere-ended punch (R = 10 mm) pressed 0.05 mm into a steel"
echo "block (E = 210 GPa, nu = 0.3, ELFORM 2) by a smooth velocity ramp and a hold (quasi-static),"
echo "\`*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\`, SFS = SFM as listed. n elements over the fine"
echo "zone of 0.8 mm. a and p0 from the block's top element layer (-sigma_zz fitted by the Hertz"
echo "ellipse), against Hertz for the measured force F: a = (3FR/4E*)^(1/3), p0 = 3F/(2 pi a^2)."
echo ""
echo "| SFS | n | elements | wall [s] | F [kN] | a [mm] | a Hertz | p0 [GPa] | p0 Hertz | error a | error p0 |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
grep -v '^#' $csv | awk '{printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %+.1f %% | %+.1f %% |\n", $1,$2,$3,$4,$5,$6,$7,$8,$9,100*$10,100*$11}'
echo ""
echo "![error against run time](hertz_error.png)"
} > $D/hertz.md
cat $D/hertz.md
