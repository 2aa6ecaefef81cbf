#!/usr/bin/env bash
# Chapter 9's chart: run ch09_normal_charts and draw, into docs/charts/,
#   ch09-normals.svg/.png    RMS normal error on a unit icosphere against the triangle count:
#                            flat facets, interpolated exact vn, interpolated computed normals
#   ch09-finding.txt         the finding in one sentence, with numbers (\include{doc})
#
# usage: tests/perf/ch09/charts.sh BUILD_DIR   (run from anywhere; takes about a second)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch09
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch09/ch09_normal_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
"$program" "$data" >/dev/null
cp "$data/finding.txt" "$charts/ch09-finding.txt"

printf '%s\n' "
set title 'Shading-normal error on a tessellated unit sphere'
set xlabel 'triangles (icosphere, 4x per level)'
set ylabel 'RMS angle to the true normal (degrees)'
set logscale xy
set format x '%g'
set key top right
set grid
plot '$data/normals.dat' using 1:2 with linespoints lw 2 pt 7 title 'flat facets (order 1)', \
     '' using 1:4 with linespoints lw 2 pt 5 title 'interpolated, angle-weighted normals', \
     '' using 1:3 with linespoints lw 2 pt 9 title 'interpolated, exact vn (order 2)', \
     20.6*(x/20)**-0.5 with lines dt 2 lc rgb 'gray' title 'slope h^1', \
     12.9*(x/20)**-1 with lines dt 3 lc rgb 'gray' title 'slope h^2'
" >"$data/ch09-normals.gp"
gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
        -e "set output '$charts/ch09-normals.svg'" "$data/ch09-normals.gp"
gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
        -e "set output '$charts/ch09-normals.png'" "$data/ch09-normals.gp"
