set terminal pngcairo size 900,600 font ",11" noenhanced
set output "../scene_orders.png"
set logscale xy
set format y "%.0e"
set xlabel "dynx wall time [s]"
set ylabel "relative |error|"
set key outside right top box
set grid
set title "Scenes: error against run time (labels: observed order)"
plot "order_rod_impact.dat" u 2:(abs($3)) w lp pt 5 t "rod_impact", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_sliding_block.dat" u 2:(abs($3)) w lp pt 7 t "sliding_block", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_incline_friction.dat" u 2:(abs($3)) w lp pt 9 t "incline_friction", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_emc_bars.dat" u 2:(abs($3)) w lp pt 11 t "emc_bars", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_taylor_bar_axisym.dat" u 2:(abs($3)) w lp pt 13 t "taylor_bar_axisym", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_taylor_steinberg.dat" u 2:(abs($3)) w lp pt 15 t "taylor_steinberg", "" u 2:(abs($3)):4 w labels offset 1,1 notitle
