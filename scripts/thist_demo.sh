#!/bin/sh
# The time-history toolbox on a scene: a filtered and an unfiltered contact force side by
# side, and their spectra (docs/toolbox.md, "Example"; issue 21's closing note).
#   sh scripts/thist_demo.sh [outdir]     (default build/thist_demo; PNGs to docs/img/)
# Runs decks/ball_in_box (rigid ball in a rigid box, SI units) for 0.4 s with the contact
# force (rcforc) written every 0.1 ms instead of 1 ms (a copy of the deck, two cards
# changed), then
#   dynx-thist rcforc --col slave_x --cfc 60         resampled to the mean step, SAE J211 CFC 60
#   dynx-thist rcforc --col slave_x --psd --nseg 4   Welch PSD (Hann), raw and CFC 60
# and draws docs/img/thist_contact_force.png (raw | CFC 60, two panels, same scales) and
# docs/img/thist_contact_spectrum.png (both PSDs, log scale, CFC 60's -3 dB at 100 Hz).
# About 15 s on one core. Needs bin/dynx, bin/dynx-thist (make all) and gnuplot.
set -eu
cd "$(dirname "$0")/.."
out=${1:-build/thist_demo}
img=docs/img
mkdir -p "$out" "$img"
for b in bin/dynx bin/dynx-thist; do
    [ -x "$b" ] || { echo "thist_demo: $b missing: run make all" >&2; exit 2; }
done
command -v gnuplot > /dev/null 2>&1 || { echo "thist_demo: gnuplot missing (apt-get install gnuplot-nox)" >&2; exit 2; }
# the deck: end time 0.4 s (card after *CONTROL_TERMINATION), rcforc every 1e-4 s
awk '
    /^\*/ { card = $0; print; next }
    card == "*CONTROL_TERMINATION" && !/^\$/ { print "       0.4"; card = ""; next }
    card == "*DATABASE_RCFORC" && !/^\$/ { print "    0.0001"; card = ""; next }
    { print }' decks/ball_in_box/deck.k > "$out/deck.k"
bin/dynx -i "$out/deck.k" -o "$out/run" > "$out/run.log" 2>&1
f=$out/run/rcforc
bin/dynx-thist "$f" --col slave_x --cfc 60 -o "$out/force.csv"
bin/dynx-thist "$f" --col slave_x --psd --nseg 4 -o "$out/psd_raw.csv"
bin/dynx-thist "$f" --col slave_x --cfc 60 --psd --nseg 4 -o "$out/psd_cfc60.csv"
gnuplot <<GP
set terminal pngcairo size 1200,500 noenhanced
set output "$img/thist_contact_force.png"
set datafile separator ","
set multiplot layout 1,2 title "ball in box (decks/ball_in_box, 0.4 s): contact force on the ball, x component (rcforc slave_x)"
set xlabel "time (s)"
set ylabel "force (N)"
set grid
set yrange [*:*]
stats "$out/force.csv" using 2 nooutput
set yrange [STATS_min*1.1:STATS_max*1.1]
set title "unfiltered (resampled to 0.1 ms)"
plot "$out/force.csv" using 1:2 with lines lw 1.5 lc rgb "#9400d3" notitle
set title "SAE J211 CFC 60 (dynx-thist --cfc 60)"
plot "$out/force.csv" using 1:3 with lines lw 1.5 lc rgb "#009e73" notitle
unset multiplot
set output "$img/thist_contact_spectrum.png"
set terminal pngcairo size 1000,600 noenhanced
set title "power spectral density of the contact force (Welch, Hann, 4 segments)"
set xlabel "frequency (Hz)"
set ylabel "PSD (N^2/Hz)"
set logscale xy
set xrange [2.5:5000]
set yrange [*:*]
set arrow from 100, graph 0 to 100, graph 1 nohead dt 2
set label "CFC 60: -3 dB at 100 Hz" at 110, graph 0.08
plot "$out/psd_raw.csv" using 1:2 with lines lw 1.5 title "unfiltered", \
     "$out/psd_cfc60.csv" using 1:2 with lines lw 1.5 title "CFC 60"
GP
echo "thist_demo: wrote $img/thist_contact_force.png and $img/thist_contact_spectrum.png (data in $out/)"
