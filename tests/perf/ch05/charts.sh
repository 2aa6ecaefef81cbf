#!/usr/bin/env bash
# Chapter 5's charts: run the chart programs and draw, into docs/charts/,
#   ch05-schlick-error.svg/.png   Schlick − exact Fresnel over angle, n = 1.33, 1.5, 2.4,
#                                 going in, going out (outside angle) and going out (naive)
#   ch05-fresnel-time.svg/.png    ns per evaluation of each formula (median of 21 runs)
#   ch05-finding.txt              both findings, one sentence each, with numbers; the chapter
#                                 page includes it as it is (\include{doc}): plain text
#
# usage: tests/perf/ch05/charts.sh BUILD_DIR   (run from anywhere; takes a few seconds)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch05
mkdir -p "$charts" "$data"

for program in ch05_schlick_error ch05_fresnel_bench; do
    [[ -x $build/tests/perf/ch05/$program ]] ||
        cmake --build "$build" --target "$program" >/dev/null
done
"$build/tests/perf/ch05/ch05_schlick_error" "$data"
"$build/tests/perf/ch05/ch05_fresnel_bench" "$data" >/dev/null
cat "$data/finding.txt" "$data/time-finding.txt" >"$charts/ch05-finding.txt"

# One gnuplot script per chart, drawn once as SVG and once as PNG.
draw() {
    local name=$1 size=$2
    printf '%s\n' "$3" >"$data/$name.gp"
    gnuplot -e "set terminal svg size $size font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size $size font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch05-schlick-error 1080,380 "
set multiplot layout 1,3 title 'Schlick minus exact Fresnel reflectance'
set xlabel 'angle of incidence (degrees)'
set xrange [0:90]
set xtics 15
set grid
set key top left
set ylabel 'Schlick - exact'
set yrange [-0.03:0.08]
set title 'going in (air into n)'
plot '$data/schlick-error.dat' every 10 using 1:2 with lines lw 2 title 'water 1.33', \
     '' every 10 using 1:3 with lines lw 2 title 'glass 1.5', \
     '' every 10 using 1:4 with lines lw 2 title 'diamond 2.4'
set title 'going out, at the outside angle (raybook)'
unset ylabel
plot '$data/schlick-error.dat' every 10 using 1:5 with lines lw 2 title 'water 1.33', \
     '' every 10 using 1:6 with lines lw 2 title 'glass 1.5', \
     '' every 10 using 1:7 with lines lw 2 title 'diamond 2.4'
set title 'going out, at the inside angle (naive)'
set yrange [-1:0.1]
set key bottom left
plot '$data/schlick-error.dat' every 10 using 1:8 with lines lw 2 title 'water 1.33', \
     '' every 10 using 1:9 with lines lw 2 title 'glass 1.5', \
     '' every 10 using 1:10 with lines lw 2 title 'diamond 2.4'
unset multiplot
"

draw ch05-fresnel-time 640,400 "
set title 'Time per Fresnel evaluation (n = 1.5, shuffled angles; median of 21 runs)'
set ylabel 'ns per evaluation (bar: median; whiskers: min to max)'
set style fill solid 0.6 border -1
set boxwidth 0.6
set yrange [0:*]
set grid ytics
set xtics rotate by 0
unset key
plot '$data/fresnel-time.dat' using 0:2:xtic(1) with boxes lc rgb '#4477aa' notitle, \
     '' using 0:2:3:4 with yerrorbars lc rgb 'black' pt 7 ps 0.3, \
     '' using 0:(0):(sprintf('%.1f', \$2)) with labels offset char 0,0.8
"

echo "chapter 5 charts:"
cat "$charts/ch05-finding.txt"
