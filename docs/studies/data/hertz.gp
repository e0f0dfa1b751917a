set terminal pngcairo size 900,500
set output 'hertz_error.png'
set logscale x
set xlabel 'wall time [s] (2-core machine shared with other jobs)'
set ylabel 'relative error against Hertz'
set title 'Hertz contact, quarter model: error of a and p0 against run time'
set key top right
set grid
plot 'hertz.dat' u ($1==1?$4:1/0):(abs($10)) w lp pt 7 t 'a, SFS = 1', \
     'hertz.dat' u ($1==1?$4:1/0):(abs($11)) w lp pt 5 t 'p0, SFS = 1', \
     'hertz.dat' u ($1==10?$4:1/0):(abs($10)) w lp pt 6 t 'a, SFS = 10', \
     'hertz.dat' u ($1==10?$4:1/0):(abs($11)) w lp pt 4 t 'p0, SFS = 10'
