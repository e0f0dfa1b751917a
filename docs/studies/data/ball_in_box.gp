set terminal pngcairo size 1000,520 noenhanced
set output 'ball_in_box_energy.png'
set xlabel 'time [s]'
set ylabel 'KE/KE0 - 1 (ball, out of contact)'
set title 'Rigid ball in a rigid box: kinetic energy between impacts (penalty contact, central difference)'
set key outside right
set grid
plot for [c in 's0.1_f0.9 s1_f0.9 s10_f0.9 s100_f0.9 s1_f0.6 s1_f0.3'] \
     'ball_in_box_'.c.'.dat' u 1:($3==0?$2:1/0) w l t c
