set terminal pngcairo size 900,600 font ",11"
set output "taylor_error.png"
set logscale xy
set xlabel "dynx wall time [s]"
set ylabel "|error| against converged reference [mm]"
set key outside right top box
set grid
set title "Taylor bar (Simo 1992), quarter model: error against run time\n(reference Lf = 21.45 mm, Rf = 7.225 mm; labels (n,m,nz); Rf crosses the reference)"
plot "taylor_e1.dat" u 1:(abs($5)) w lp pt 7 lc rgb "#d62728" t "|Rf - 7.225|, ELFORM 1 IHQ 1", \
     "" u 1:(abs($5)):6 w labels offset 0,1 tc rgb "#d62728" notitle, \
     "" u 1:(abs($3)) w lp pt 5 lc rgb "#1f77b4" t "|Lf - 21.45|, ELFORM 1 IHQ 1", \
     "taylor_e2.dat" u 1:(abs($5)) w lp pt 6 dt 2 lc rgb "#d62728" t "|Rf - 7.225|, ELFORM 2", \
     "" u 1:(abs($5)):6 w labels offset 0,-1 tc rgb "#555555" notitle, \
     "" u 1:(abs($3)) w lp pt 4 dt 2 lc rgb "#1f77b4" t "|Lf - 21.45|, ELFORM 2"
