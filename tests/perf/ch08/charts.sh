#!/usr/bin/env bash
# Chapter 8's charts: run ch08_aa_charts on the chapter scene and aa_vs_povray.sh on the
# mirror_glass scene, and draw, into docs/charts/,
#   ch08-rays.svg/.png       RMSE against camera rays per pixel: random, uniform, jittered, adaptive
#   ch08-time.svg/.png       the same against render CPU time
#   ch08-povray.svg/.png     adaptive AA against POV-Ray's +AM2: RMSE against render time
#   ch08-finding.txt         the rays finding in one sentence, with numbers (\include{doc})
#   ch08-povray.txt          the POV-Ray table and the ratio at equal error (\include{doc})
#
# usage: tests/perf/ch08/charts.sh BUILD_DIR   (run from anywhere; takes a few minutes; the
# POV-Ray chart is skipped, with a note, when povray is not installed)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch08
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch08/ch08_aa_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
(cd "$root" && "$program" rays scenes/chapter08-antialiasing.lua "$data")
cp "$data/finding.txt" "$charts/ch08-finding.txt"

# One gnuplot script per chart, drawn once as SVG and once as PNG.
draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch08-rays "
set title 'Antialiasing error against rays (chapter scene, 128x96)'
set xlabel 'camera rays per pixel'
set ylabel 'RMSE against jittered 32x32'
set logscale xy
set yrange [0.003:0.2]
set grid
set key top right
plot '$data/rays.dat' index 0 using 1:3 with linespoints pt 6 title 'random (seed 000)', \
     '' index 1 using 1:3 with linespoints pt 5 title 'uniform n x n', \
     '' index 2 using 1:3 with linespoints pt 7 title 'jittered n x n', \
     '' index 3 using 1:3 with linespoints pt 9 lw 2 title 'adaptive, depth 3 (thresholds)', \
     '' index 3 using 1:3:((\$4 == 0.4 || \$4 == 0.1 || \$4 == 0.01 || \$4 == 0) ? sprintf('%g', \$4) : '') \
        with labels offset char 0,-1 font ',9' notitle, \
     '' index 4 using 1:3 with points pt 8 ps 1.5 lw 2 title 'adaptive, depth 4, threshold 0.01'
"

draw ch08-time "
set title 'Antialiasing error against time (chapter scene, 128x96)'
set xlabel 'render CPU time, both threads (s)'
set ylabel 'RMSE against jittered 32x32'
set logscale xy
set grid
set key top right
plot '$data/rays.dat' index 0 using 2:3 with linespoints pt 6 title 'random (seed 000)', \
     '' index 1 using 2:3 with linespoints pt 5 title 'uniform n x n', \
     '' index 2 using 2:3 with linespoints pt 7 title 'jittered n x n', \
     '' index 3 using 2:3 with linespoints pt 9 lw 2 title 'adaptive, depth 3 (thresholds)', \
     '' index 4 using 2:3 with points pt 8 ps 1.5 lw 2 title 'adaptive, depth 4, threshold 0.01'
"

if command -v povray >/dev/null; then
    bash "$root/tests/perf/ch08/aa_vs_povray.sh" "$build" "$data" | tee "$data/povray.txt"
    cp "$data/povray.txt" "$charts/ch08-povray.txt"
    draw ch08-povray "
set title 'Adaptive antialiasing against POV-Ray +AM2 (mirror-glass scene, 256x256, 1 thread)'
set xlabel 'render time (s): raybook render phase, POV-Ray Trace Time'
set ylabel 'RMSE against own converged reference'
set logscale xy
set grid
set key top right
plot '$data/povray.dat' index 0 using 3:4 with linespoints pt 7 title 'raybook --aa=adaptive, depth 3', \
     '' index 0 using 3:4:2 with labels offset char 0,1 font ',9' notitle, \
     '' index 1 using 3:4 with linespoints pt 5 title 'POV-Ray +AM2 +R3', \
     '' index 1 using 3:4:2 with labels offset char 0,-1 font ',9' notitle
"
else
    echo "charts: povray is not installed; ch08-povray not redrawn (make charts installs it)"
fi

echo "chapter 8 charts: $(cat "$charts/ch08-finding.txt")"
