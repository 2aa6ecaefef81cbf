# Chapter 18's chart: RMSE against render time, three methods, two scenes (tests/perf/ch18/charts.sh).
# usage: gnuplot -e "data='methods.dat'; out='ch18-methods.svg'" methods.gp
if (strstrt(out, ".png") > 0) { set terminal pngcairo size 960,420 font "sans,10" } else { set terminal svg size 960,420 font "sans,11" }
set output out
set multiplot layout 1,2
set logscale xy
set xlabel "render time (s)"
set ylabel "RMSE against the reference"
set grid
set key top right
set title "the box without balls (reference: path tracing, 4096 paths)"
plot data index 0 using 2:3 with linespoints lw 2 pt 7 title "path tracing", \
     data index 1 using 2:3 with linespoints lw 2 pt 5 title "photon mapping", \
     data index 2 using 2:3 with linespoints lw 2 pt 9 title "Whitted + ambient"
set title "glass and mirror balls (reference: photon mapping)"
plot data index 3 using 2:3 with linespoints lw 2 pt 7 title "path tracing", \
     data index 4 using 2:3 with linespoints lw 2 pt 5 title "photon mapping", \
     data index 5 using 2:3 with linespoints lw 2 pt 9 title "Whitted + ambient"
unset multiplot
