#!/bin/sh
# Plane-stress lamina studies (docs/studies/lamina.md): iso-error maps of the one-step, secant and
# radial returns against the full return (data + PNG), and the ns per lamina update benchmark.
# Usage: sh scripts/studies_lamina.sh [REPS]   (needs bin/dynx-lamina: make all; gnuplot-nox)
set -eu
reps=${1:-20000}
dir=docs/studies
data=$dir/data
mkdir -p "$data"
bin/dynx-lamina maps "$data"
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot <<GP
set terminal pngcairo size 1600,820 font ",9" noenhanced
set output "$dir/lamina_maps.png"
set multiplot layout 2,4 title "log10 of |sigma - sigma_full|_vM / sigma_y, one increment from a yield state (MAT_003 E 200 GPa, nu 0.3, sigma_y 250 MPa, Et 2 GPa, BETA 1)"
set view map
set pm3d at b corners2color c1
unset surface
set contour base
set cntrparam levels discrete -14,-12,-10,-8,-6,-4,-3,-2,-1
unset clabel
set cbrange [-16:0]
set palette rgbformulae 33,13,10
set xrange [0:360]; set yrange [-6:-2]
set xtics 90; set ytics 1
set xlabel "direction theta (deg): (de1, de2) = size (cos, sin)"
set ylabel "log10 increment size"
set key off
do for [st in "uniaxial shear"] {
  do for [al in "onestep secant3 radial onestepn"] {
    set title sprintf("%s, start %s", al, st)
    splot sprintf("$data/lamina_map_%s_%s.dat", st, al) u 1:2:3 w pm3d, '' u 1:2:3 w l lc rgb "black" nosurface
  }
}
unset multiplot
GP
    echo "studies_lamina: $dir/lamina_maps.png"
fi
bin/dynx-lamina bench "$reps" | tee "$data/lamina_bench.txt"
