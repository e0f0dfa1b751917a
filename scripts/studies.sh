#!/bin/sh
# make studies: error-against-run-time studies (docs/studies/).
#   1. elastic wave in a bar: mesh sweep nx = 25..400 and time-step sweep TSSFAC 0.3/0.6/0.9
#   2. Taylor bar, Simo (1992) benchmark: mesh sweep, ELFORM 1 and 2, the (8,8,64) mesh
#   3. Taylor bar, Wilkins-Guinan (1973) copper: mesh, Cowper-Symonds rate scaling
# Decks and raw output go to build/studies/, tables, plot data, PNGs and README to
# docs/studies/. Runs are sequential (one at a time) so that the wall times are clean.
# About 3-4 minutes on one core of a 2-core machine. Driver: scripts/studies.py.
set -e
cd "$(dirname "$0")/.."
[ -x bin/dynx ] || make all
command -v gnuplot > /dev/null || { echo "studies: gnuplot not found (apt-get install gnuplot-nox)"; exit 1; }
B=build/studies
D=docs/studies
mkdir -p "$B" "$D/data"
t0=$(date +%s)
for s in wave taylor wg; do
    echo "studies: $s"
    python3 scripts/studies.py $s "$B" "$D"
done
python3 scripts/studies.py readme "$B" "$D"
# render the PNGs next to the README (the .gp files read their .dat files from data/)
for g in "$D"/data/*.gp; do
    ( cd "$D/data" && gnuplot "$(basename "$g")" )
done
mv "$D"/data/*.png "$D"/
echo "studies: done in $(( $(date +%s) - t0 )) s; see $D/README.md"
