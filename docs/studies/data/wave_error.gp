set terminal pngcairo size 900,600 font ",11"
set output "wave_error.png"
set logscale xy
set format y "10^{%L}"
set xlabel "dynx wall time [s] (best of 3)"
set ylabel "error"
set key outside right top box
set grid
set title "Elastic wave: error against run time (mesh sweep nx = 25..400 at TSSFAC 0.9;\ntime-step sweep TSSFAC 0.3/0.6/0.9 at nx = 100)"
plot "wave_mesh.dat" u 3:5 w lp pt 7 lc rgb "#1f77b4" t "front |error| [mm], mesh", \
     "" u 3:5:(sprintf("%d",$1)) w labels offset 0,1 notitle, \
     "" u 3:8 w lp pt 5 lc rgb "#2ca02c" t "L1 profile error [mm], mesh", \
     "" u 3:4 w lp pt 9 lc rgb "#d62728" t "plateau rel. |error|, mesh", \
     "" u 3:7 w lp pt 11 lc rgb "#9467bd" t "overshoot, mesh", \
     "wave_dt.dat" u 3:5 w lp pt 6 dt 2 lc rgb "#1f77b4" t "front |error| [mm], TSSFAC", \
     "" u 3:5:(sprintf("%.1f",$2)) w labels offset 0,-1 tc rgb "#555555" notitle, \
     "" u 3:8 w lp pt 4 dt 2 lc rgb "#2ca02c" t "L1 profile error [mm], TSSFAC", \
     "" u 3:4 w lp pt 8 dt 2 lc rgb "#d62728" t "plateau rel. |error|, TSSFAC", \
     "" u 3:7 w lp pt 10 dt 2 lc rgb "#9467bd" t "overshoot, TSSFAC"
