set terminal pngcairo size 900,550 font ",11"
set output "wave_profile.png"
set xlabel "x [mm]"
set ylabel "sigma_{xx} [MPa]"
set key bottom right box
set grid
set title sprintf("Elastic wave, nx = 100, TSSFAC 0.9, t = 0.01004 ms: element stress against analytic step")
plot [0:100] "wave_analytic.dat" u 1:($2*1000) w l lw 2 lc rgb "black" t "analytic", \
     "" u 1:($2*1000) w lp pt 7 ps 0.6 lc rgb "#d62728" t "dynx nx = 100"
set output "wave_profile_zoom.png"
set title "Elastic wave near the front (t = 0.01004 ms), mesh sweep at TSSFAC 0.9"
set key top left box
plot [40.2:70.2] "wave_analytic.dat" u 1:($2*1000) w l lw 2 lc rgb "black" t "analytic", \
     "wave_profile_nx25.dat" u 1:($2*1000) w lp pt 4 ps 0.7 t "nx = 25", \
     "wave_profile_nx50.dat" u 1:($2*1000) w lp pt 6 ps 0.7 t "nx = 50", \
     "wave_profile_nx100.dat" u 1:($2*1000) w lp pt 7 ps 0.6 t "nx = 100", \
     "wave_profile_nx200.dat" u 1:($2*1000) w lp pt 5 ps 0.5 t "nx = 200", \
     "wave_profile_nx400.dat" u 1:($2*1000) w l lw 1.5 t "nx = 400", \
     "wave_profile_nx400_q2small.dat" u 1:($2*1000) w l lw 1 dt 2 lc rgb "#7f7f7f" t "nx = 400, Q2 = 1e-4"
