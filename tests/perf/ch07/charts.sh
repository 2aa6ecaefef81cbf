#!/usr/bin/env bash
# Chapter 7's charts: run ch07_glossy_charts on the chapter scene and draw, into docs/charts/,
#   ch07-equal-time.svg/.png    RMSE against CPU time, fuzz sphere and Phong lobe
#   ch07-grazing-loss.svg/.png  share of lobe samples lost below the surface near grazing
#   ch07-lobe-shapes.svg/.png   the two lobes' pdfs at matched glossiness
#   ch07-lobes.png              the converged renders side by side (fuzz | lobe)
#   ch07-finding.txt            the equal-time finding in one sentence, with numbers; the
#                               chapter page includes it as it is (\include{doc}): plain text
#
# usage: tests/perf/ch07/charts.sh BUILD_DIR   (run from anywhere; takes under a minute)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch07
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch07/ch07_glossy_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
(cd "$root" && "$program" scenes/chapter07-glossy.lua "$data")
cp "$data/lobes.png" "$charts/ch07-lobes.png"
cp "$data/finding.txt" "$charts/ch07-finding.txt"

# One gnuplot script per chart, drawn once as SVG and once as PNG.
draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch07-equal-time "
set title 'Glossy sampling at equal time (chapter scene, 128x96)'
set xlabel 'render CPU time, both threads (s)'
set ylabel 'RMSE against own 2048-direction reference'
set logscale xy
set grid
set key top right
plot '$data/equal-time.dat' index 0 using 3:4 with linespoints pt 7 title 'fuzz sphere', \
     '' index 0 using 3:4:(sprintf('%d', \$2)) with labels offset char 0,1 notitle, \
     '' index 1 using 3:4 with linespoints pt 5 title 'Phong lobe'
"

draw ch07-grazing-loss "
set title 'Energy lost below the surface near grazing'
set xlabel 'elevation of the mirror direction above the surface (degrees)'
set ylabel 'share of lobe samples rejected'
set grid
set key top right
plot '$data/grazing.dat' index 0 using 1:2 with points pt 7 lc 1 title 'fuzz, g = 0.1', \
     '' index 0 using 1:3 with points pt 5 lc 2 title 'lobe, g = 0.1', \
     '' index 0 using 1:4 with lines lc 2 title 'lobe exact, g = 0.1', \
     '' index 1 using 1:2 with points pt 6 lc 3 title 'fuzz, g = 0.3', \
     '' index 1 using 1:3 with points pt 4 lc 4 title 'lobe, g = 0.3', \
     '' index 1 using 1:4 with lines lc 4 title 'lobe exact, g = 0.3'
"

draw ch07-lobe-shapes "
set title 'The two lobes at matched glossiness (same mean cosine)'
set xlabel 'angle to the mirror direction (degrees)'
set ylabel 'p(angle) / p(0)'
set grid
set key top right
plot '$data/lobe-shapes.dat' index 0 using 1:2 with lines dt 2 lc 1 title 'fuzz, g = 0.05', \
     '' index 0 using 1:3 with lines lc 1 title 'lobe, g = 0.05', \
     '' index 1 using 1:2 with lines dt 2 lc 2 title 'fuzz, g = 0.15', \
     '' index 1 using 1:3 with lines lc 2 title 'lobe, g = 0.15', \
     '' index 2 using 1:2 with lines dt 2 lc 3 title 'fuzz, g = 0.4', \
     '' index 2 using 1:3 with lines lc 3 title 'lobe, g = 0.4'
"

echo "chapter 7 charts: $(cat "$charts/ch07-finding.txt")"
