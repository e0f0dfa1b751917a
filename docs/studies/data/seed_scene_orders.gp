set terminal pngcairo size 900,600 font ",11" noenhanced
set output "../seed_scene_orders.png"
set logscale xy
set format y "%.0e"
set xlabel "dynx CPU time [s]"
set ylabel "relative |error|"
set key outside right top box
set grid
set title "Scenes: error against run time (labels: observed order)"
plot "order_brittle_impact.dat" u 2:(abs($3)) w lp pt 5 t "brittle_impact", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_pressure_table.dat" u 2:(abs($3)) w lp pt 7 t "pressure_table", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_shell_projectile_plate.dat" u 2:(abs($3)) w lp pt 9 t "shell_projectile_plate", "" u 2:(abs($3)):4 w labels offset 1,1 notitle, \
     "order_shell_box_post.dat" u 2:(abs($3)) w lp pt 11 t "shell_box_post", "" u 2:(abs($3)):4 w labels offset 1,1 notitle
