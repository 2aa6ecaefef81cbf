#!/usr/bin/env bash
# Chapter 6's charts: run ch06_soft_shadow_charts on the chapter scene and draw, into docs/charts/,
#   ch06-error-vs-samples.svg/.png  RMSE against samples per light, independent and stratified
#   ch06-error-vs-time.svg/.png     RMSE against render CPU time, independent and stratified
#   ch06-hard-vs-soft.png           the chapter scene, point lights | area lights
#   ch06-highlight.png              a shiny sphere's highlights, point lights | area lights
#   ch06-finding.txt                the finding in one sentence, with numbers; the chapter page
#                                   includes it as it is (\include{doc}), so keep it plain text
#
# usage: tests/perf/ch06/charts.sh BUILD_DIR   (run from anywhere; takes under a minute)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch06
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch06/ch06_soft_shadow_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
(cd "$root" && "$program" scenes/chapter06-soft-shadows.lua tests/perf/ch06/highlight.lua "$data")
cp "$data/hard-vs-soft.png" "$charts/ch06-hard-vs-soft.png"
cp "$data/highlight.png" "$charts/ch06-highlight.png"
cp "$data/finding.txt" "$charts/ch06-finding.txt"

# One gnuplot script per chart, drawn once as SVG and once as PNG.
draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch06-error-vs-samples "
set title 'Soft-shadow error against samples per light (chapter scene, 128x96)'
set xlabel 'samples per light N = n x n'
set ylabel 'RMSE against a 2 x 64x64-sample reference'
set logscale xy
set grid
set key bottom left
plot '$data/convergence.dat' index 0 using 3:5 with linespoints pt 7 lc 1 title 'independent', \
     '' index 1 using 3:5 with linespoints pt 5 lc 2 title 'stratified (jittered)', \
     0.103/sqrt(x) with lines dt 2 lc rgb 'gray40' title 'slope -1/2', \
     0.103/x**0.75 with lines dt 3 lc rgb 'gray40' title 'slope -3/4', \
     0.103/x with lines dt 4 lc rgb 'gray40' title 'slope -1'
"

draw ch06-error-vs-time "
set title 'Soft-shadow error against render time (chapter scene, 128x96)'
set xlabel 'render CPU time, all threads (s)'
set ylabel 'RMSE against a 2 x 64x64-sample reference'
set logscale xy
set grid
set key top right
plot '$data/convergence.dat' index 0 using 4:5 with linespoints pt 7 lc 1 title 'independent', \
     '' index 0 using 4:5:(sprintf('%d', \$3)) with labels offset char 0,1 notitle, \
     '' index 1 using 4:5 with linespoints pt 5 lc 2 title 'stratified (jittered)', \
     '' index 1 using 4:5:(sprintf('%d', \$3)) with labels offset char 0,-1 notitle
"

echo "chapter 6 charts: $(cat "$charts/ch06-finding.txt")"
