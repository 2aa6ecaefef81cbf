#!/usr/bin/env bash
# Chapter 14's charts: run ch14_csg_charts and csg_vs_povray.sh, and draw, into docs/charts/,
#   ch14-cost.svg/.png     nanoseconds per ray against the number of CSG operands
#   ch14-finding.txt       the finding in one sentence, with numbers (\include{doc})
#   ch14-povray.txt        the CSG scene against POV-Ray (\include{doc})
#
# usage: tests/perf/ch14/charts.sh BUILD_DIR   (run from anywhere; takes about a minute)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch14
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch14/ch14_csg_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
"$program" "$data"
cp "$data/finding.txt" "$charts/ch14-finding.txt"

cat >"$data/cost.gp" <<GP
set title 'Cost of one ray against a CSG solid of N spheres (1 thread)'
set xlabel 'operands N'
set ylabel 'nanoseconds per ray (closest hit)'
set logscale xy 2
set format y '%g'
set grid
set key top left
plot '$data/cost.dat' using 1:3 with linespoints pt 5 title 'chain of nested unions', \\
     '' using 1:2 with linespoints pt 7 lw 2 title 'balanced union (two groups)', \\
     '' using 1:4 with linespoints pt 9 title 'big ball minus a group of N balls', \\
     '' using 1:5 with linespoints pt 6 dt 2 title 'no CSG: the N spheres in the BVH'
GP
gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
        -e "set output '$charts/ch14-cost.svg'" "$data/cost.gp"
gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
        -e "set output '$charts/ch14-cost.png'" "$data/cost.gp"

if command -v povray >/dev/null; then
  bash "$root/tests/perf/ch14/csg_vs_povray.sh" "$build" | tee "$data/povray.txt"
  cp "$data/povray.txt" "$charts/ch14-povray.txt"
else
  echo "charts: povray is not installed; ch14-povray.txt not redrawn"
fi
echo "chapter 14 charts: $(cat "$charts/ch14-finding.txt")"
