# Contact force history of the rod impact (decks/rod_impact): rcforc slave x force, default
# penalty (SFS = 1) and a stiff penalty (SFS = 100), against the 1D theory (rho c v A/2 over
# 2L/c from the impact at gap/v = 0.001 ms). Run from the top directory after
#   bin/dynx -i decks/rod_impact/deck.k -o build/plots/rod1
#   python3 scripts/gen_contact_decks.py rod --sfs 100 build/plots/rod_sfs100.k
#   bin/dynx -i build/plots/rod_sfs100.k -o build/plots/rod100
set terminal pngcairo size 900,500
set output 'docs/contact_force_rod.png'
set xlabel 'time [ms]'
set ylabel 'contact force on the striker [kN]'
set title 'Two equal steel rods, 10 m/s: contact force (rcforc)'
set key bottom right
t0 = 0.001; t2 = 2*100.0/sqrt(210.0/7.85e-6); f = 7.85e-6*sqrt(210.0/7.85e-6)*10*1/2
theory(t) = (t >= t0 && t <= t0 + t2) ? f : 0
set samples 2000
plot 'build/plots/rod100/rcforc' u 1:(-$3) w l lw 1 lc rgb '#d95f02' t 'SFS = 100', \
     'build/plots/rod1/rcforc' u 1:(-$3) w l lw 2 lc rgb '#1b9e77' t 'SFS = 1 (default)', \
     [0:0.062] theory(x) w l lw 1 dt 2 lc rgb 'black' t '1D theory rho c v A/2 for 2L/c'
