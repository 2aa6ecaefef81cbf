#!/usr/bin/env bash
# make charts: every chapter's speed-accuracy charts into docs/charts/ (SVG and PNG, gnuplot).
#
# usage: charts.sh BUILD_DIR
# Chapter 3's BVH scaling chart is drawn here; chapters with their own chart programs keep a
# tests/perf/chNN/charts.sh, which this script runs in order.
set -euo pipefail
build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
charts=$root/docs/charts
mkdir -p "$charts" "$build/bench"
command -v gnuplot >/dev/null || { echo "charts: gnuplot is not installed (make charts installs it)"; exit 1; }

# Chapter 3: time per ray and build time as the triangle count grows (bunny and its Loop
# subdivisions), BVH against brute force.
data=$build/bench/ch03-scaling.dat
"$build/tests/perf/bvh_scaling" "$root/scenes/assets/bunny.obj" "$data" | tee "$charts/ch03-scaling.txt"
for term in "svg size 760,420 font 'sans,11'" "pngcairo size 760,420 font 'sans,10'"; do
  ext=${term%% *}; ext=${ext/pngcairo/png}
  gnuplot <<GP
set terminal $term
set output "$charts/ch03-bvh-scaling.$ext"
set title "Time per ray against triangle count (bunny and its Loop subdivisions, incoherent rays)"
set logscale xy
set xlabel "triangles"
set ylabel "microseconds per ray"
set key top left
set grid
# A c·log2(n) guide through the BVH's first point.
first_n = real(system("awk 'NR==2 {print \$1}' $data"))
first_t = real(system("awk 'NR==2 {print \$3}' $data"))
guide(n) = first_t * log(n) / log(first_n)
plot "$data" using 1:3 with linespoints lw 2 pt 7 title "BVH", \
     "$data" using 1:(\$4 > 0 ? \$4 : 1/0) with linespoints lw 2 pt 5 title "brute force (every triangle)", \
     [3000:300000] guide(x) with lines dt 2 lc rgb "gray40" title "c · log n"
GP
done
echo "charts: wrote $charts/ch03-bvh-scaling.svg and .png"

# The chapters' own charts.
for script in "$root"/tests/perf/ch[0-9][0-9]/charts.sh; do
  [ -e "$script" ] || continue
  echo "charts: $script"
  bash "$script" "$build"
done
