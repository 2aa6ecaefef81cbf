#!/usr/bin/env bash
# Chapter 15's chart: run ch15_quadric_costs and draw, into docs/charts/,
#   ch15-costs.svg/.png     ns per ray of the sphere and the quadrics, and of a cylinder
#                           tessellated with n segments against its silhouette error
#   ch15-finding.txt        the finding in one sentence, with numbers (\include{doc})
#   ch15-leaks.txt          rim rays missed by the slab clip and by seed 001's separate tests
#
# usage: tests/perf/ch15/charts.sh BUILD_DIR   (run from anywhere; takes about ten seconds)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch15
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch15/ch15_quadric_costs
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
"$program" "$data"
cp "$data/finding.txt" "$charts/ch15-finding.txt"
cp "$data/leaks.txt" "$charts/ch15-leaks.txt"

draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

# The quadrics' costs as horizontal lines over the tessellated cylinder's curve.
sphere=$(awk '$1 == "sphere" {print $2}' "$data/shapes.dat")
cylinder=$(awk '$1 == "cylinder" {print $2}' "$data/shapes.dat")
cone=$(awk '$1 == "cone" {print $2}' "$data/shapes.dat")
draw ch15-costs "
set title 'Cost per ray: quadrics against a tessellated cylinder (1 thread)'
set xlabel 'segments n of the tessellated cylinder (4n triangles)'
set ylabel 'ns per closest-hit ray'
set y2label 'silhouette error at 512 px wide (px)'
set logscale xy
set logscale y2
set format y2 '%g'
set ytics nomirror
set y2tics
set yrange [5:20000]
set grid
set key top left Left reverse samplen 2 font ',9'
set arrow from 51, graph 0 to 51, graph 1 nohead dt 3 lc rgb '#888888'
set label 'half a pixel: n = 51' at 56, graph 0.05 font ',9'
plot '$data/mesh.dat' using 1:3 with linespoints pt 7 lw 2 title 'tessellated cylinder (BVH)', \
     '' using 1:4 axes x1y2 with linespoints pt 6 dt 2 title 'its silhouette error (right)', \
     $cylinder with lines lw 2 title 'capped cylinder (quadric)', \
     $cone with lines lw 2 title 'capped cone (quadric)', \
     $sphere with lines lw 2 title 'sphere'
"
cat "$charts/ch15-finding.txt"
