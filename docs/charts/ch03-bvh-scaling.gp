# ch03-bvh-scaling.gp: chapter 3's chart of time per ray against triangle count, the BVH against
# brute force, for the bunny and its Loop subdivisions. tests/perf/charts.sh runs it twice:
#   gnuplot -e "data='BUILD/bench/ch03-scaling.dat'; out='docs/charts/ch03-bvh-scaling.svg'" ch03-bvh-scaling.gp
# (out ending in .png draws a PNG). The data file is what tests/perf/bvh_scaling prints:
# 1 triangles, 2 mesh build ms, 3 BVH build ms, 4 BVH µs/ray, 5 brute-force µs/ray (-1: not run).
if (!exists("data")) data = "build/bench/ch03-scaling.dat"
if (!exists("out")) out = "docs/charts/ch03-bvh-scaling.svg"
set encoding utf8
if (out[strlen(out)-3:] eq ".png") {
  set terminal pngcairo size 800,460 font "sans,10"
} else {
  set terminal svg size 800,460 font "sans,11" background "white"
}
set output out

# The first mesh anchors both guides: c·log n through its BVH time, c·n through its brute force.
stats data using 1 every ::0::0 nooutput
n0 = STATS_min
stats data using 4 every ::0::0 nooutput
t0 = STATS_min
stats data using 5 every ::0::0 nooutput
b0 = STATS_min
stats data using 1 nooutput
nMax = STATS_max

set title "Time per ray against triangle count: the bunny and its Loop subdivisions, 262,144 incoherent rays, 1 thread"
set logscale xy
set xrange [n0 / 1.6 : nMax * 1.6]
set yrange [0.1 : 5000]
set format x "%.0s%c"
set format y "%g"
set xlabel "triangles (log scale)"
set ylabel "microseconds per ray (log scale)"
set grid xtics ytics mytics lc rgb "#dddddd"
set key top left box opaque

logGuide(n) = t0 * log(n) / log(n0)
linearGuide(n) = b0 * n / n0
plot data using 1:($5 > 0 ? $5 : 1/0) with linespoints lw 2 pt 5 ps 1.2 lc rgb "#d95f02" \
         title "brute force: every triangle (measured)", \
     [n0:nMax] linearGuide(x) with lines dt 3 lw 2 lc rgb "#d95f02" \
         title "brute force extrapolated (c·n)", \
     data using 1:4 with linespoints lw 2 pt 7 ps 1.2 lc rgb "#1b9e77" title "BVH (measured)", \
     [n0:nMax] logGuide(x) with lines dt 2 lw 1.5 lc rgb "gray40" \
         title "c·log n through the first BVH point", \
     data using 1:4:(sprintf("%.2f µs", $4)) with labels offset 0,1.2 font ",9" notitle, \
     data using 1:($5 > 0 ? $5 : 1/0):(sprintf("%.0f µs", $5)) with labels offset 0,1.2 font ",9" notitle
