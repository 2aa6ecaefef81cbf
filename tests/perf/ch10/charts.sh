#!/usr/bin/env bash
# Chapter 10's chart: run ch10_checker_chart on tests/perf/ch10/checker_plane.lua and draw, into
# docs/charts/,
#   ch10-aliasing.svg/.png    RMSE against camera rays per pixel for chapter 8's samplers, over
#                             the whole image and over the far band next to the horizon
#   ch10-checker-1.png, ch10-checker-16.png, ch10-checker-ref.png
#                             the plane with one ray through each pixel centre, 16 jittered
#                             rays a pixel, and the reference
#   ch10-finding.txt          the finding in one sentence, with numbers (\include{doc})
#
# usage: tests/perf/ch10/charts.sh BUILD_DIR   (run from anywhere; takes about half a minute)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch10
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch10/ch10_checker_chart
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
(cd "$root" && "$program" tests/perf/ch10/checker_plane.lua "$data" "$charts")
cp "$data/finding.txt" "$charts/ch10-finding.txt"

# One gnuplot script, drawn once as SVG and once as PNG.
script="
set title 'Aliasing of a checker plane against rays (128x96)'
set xlabel 'camera rays per pixel'
set ylabel 'RMSE against jittered 32x32'
set logscale xy
set xrange [0.8:100]
set yrange [0.008:0.6]
set grid
set key outside right top vertical font ',9'
plot '$data/aliasing.dat' index 0 using 1:2 with linespoints pt 5 lc 1 title 'uniform, image', \
     '' index 0 using 1:3 with linespoints pt 4 lc 1 dt 2 title 'uniform, far band', \
     '' index 1 using 1:2 with linespoints pt 7 lc 2 title 'jittered, image', \
     '' index 1 using 1:3 with linespoints pt 6 lc 2 dt 2 title 'jittered, far band', \
     '' index 2 using 1:2 with linespoints pt 9 lc 3 title 'random, image', \
     '' index 3 using 1:2 with points pt 13 ps 1.4 lc 4 title 'adaptive, image', \
     '' index 3 using 1:3 with points pt 12 ps 1.4 lc 4 title 'adaptive, far band', \
     0.17 / sqrt(x) with lines lc rgb 'gray' dt 3 title '1/sqrt(N)', \
     0.17 / x with lines lc rgb 'black' dt 3 title '1/N'
"
printf '%s\n' "$script" >"$data/ch10-aliasing.gp"
gnuplot -e "set terminal svg size 760,420 font 'sans,12' background rgb 'white'" \
        -e "set output '$charts/ch10-aliasing.svg'" "$data/ch10-aliasing.gp"
gnuplot -e "set terminal pngcairo size 760,420 font 'sans,10'" \
        -e "set output '$charts/ch10-aliasing.png'" "$data/ch10-aliasing.gp"
echo "charts: wrote $charts/ch10-aliasing.svg and .png"
