set terminal pngcairo size 900,600 font ",11" noenhanced
set output "../more_scene_orders.png"
set logscale xy
set format y "%.0e"
set xlabel "dynx CPU time [s]"
set ylabel "relative |error|"
set key outside right top box
set grid
set title "Scenes: error against run time (labels: observed order)"
plot "order_brittle_impact_2d.dat" u 2:(abs($3)) w lp pt 5 t "brittle_impact_2d", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_cmc_implant.dat" u 2:(abs($3)) w lp pt 7 t "cmc_implant", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_ssnv104.dat" u 2:(abs($3)) w lp pt 9 t "ssnv104", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_knee_insert.dat" u 2:(abs($3)) w lp pt 11 t "knee_insert", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_laser_backside.dat" u 2:(abs($3)) w lp pt 13 t "laser_backside", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_laser_subsurface.dat" u 2:(abs($3)) w lp pt 15 t "laser_subsurface", "" u 2:(abs($3)):4 w labels offset 1,1 notitle
