#!/usr/bin/env bash
# Chapter 11's chart: run ch11_step_chart and draw, into docs/charts/,
#   ch11-step.svg/.png     the bumped normal's error against the finite-difference step,
#                          central and forward differences
#   ch11-finding.txt       the finding in one sentence, with numbers (\include{doc})
#
# usage: tests/perf/ch11/charts.sh BUILD_DIR   (run from anywhere; takes a few seconds)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch11
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch11/ch11_step_chart
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
"$program" "$data" >/dev/null
cp "$data/finding.txt" "$charts/ch11-finding.txt"

plot="
set title 'Bumped-normal error against the finite-difference step (ripples on a sphere)'
set xlabel 'step / wavelength'
set ylabel 'angle to the exact bumped normal (rad)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set key top left
set arrow from 1e-3, graph 0 to 1e-3, graph 1 nohead dashtype 2 lc rgb 'gray40'
set label 'default' at 1.3e-3, graph 0.95 font ',9' tc rgb 'gray40'
plot '$data/step.dat' using 1:2 with linespoints pt 7 lw 2 title 'central differences, RMS', \
     '' using 1:3 with lines dashtype 2 lc 1 title 'central, max', \
     '' using 1:4 with linespoints pt 5 lw 2 title 'forward differences, RMS', \
     '' using 1:5 with lines dashtype 2 lc 2 title 'forward, max'
"
printf '%s\n' "$plot" >"$data/ch11-step.gp"
gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white' enhanced" \
        -e "set output '$charts/ch11-step.svg'" "$data/ch11-step.gp"
gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10' enhanced" \
        -e "set output '$charts/ch11-step.png'" "$data/ch11-step.gp"

echo "chapter 11 charts: $(cat "$charts/ch11-finding.txt")"
