#!/usr/bin/env bash
# make charts: every chapter's speed-accuracy charts into docs/charts/ (SVG and PNG, gnuplot).
#
# usage: charts.sh BUILD_DIR
# Chapter 3's BVH scaling chart is drawn here (docs/charts/ch03-bvh-scaling.gp); chapters with
# their own chart programs keep a tests/perf/chNN/charts.sh, which this script runs in order;
# then issue 38's target-error charts and table (tests/perf/target_error/bench.sh, SVG only).
set -euo pipefail
build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
charts=$root/docs/charts
mkdir -p "$charts" "$build/bench"
command -v gnuplot >/dev/null || { echo "charts: gnuplot is not installed (make charts installs it)"; exit 1; }

# Chapter 3: time per ray, build time and memory as the triangle count grows, BVH against brute
# force. The bunny (scenes/assets/bunny.obj = bunny_L0, 3,674 triangles) is Loop-subdivided into
# BUILD/bench/ (15k, 59k, 235k triangles; generated here, never committed), then each size is
# measured in its own process, so its peak memory is its own. Brute force runs on the two small
# sizes only, with fewer rays.
bench=$build/bench
perf=$build/tests/perf
l0=$root/scenes/assets/bunny.obj
"$perf/subdivide" "$l0" "$bench/bunny_L1.obj" 1
"$perf/subdivide" "$l0" "$bench/bunny_L2.obj" 2
"$perf/subdivide" "$bench/bunny_L2.obj" "$bench/bunny_L3.obj" 1
data=$bench/ch03-scaling.dat
{
  "$perf/bvh_scaling" --header --brute-rays 2048 "$l0"
  "$perf/bvh_scaling" --brute-rays 512 "$bench/bunny_L1.obj"
  "$perf/bvh_scaling" "$bench/bunny_L2.obj"
  "$perf/bvh_scaling" "$bench/bunny_L3.obj"
} >"$data"
awk 'BEGIN {
       printf "BVH scaling: the bunny and its Loop subdivisions, 2^18 incoherent rays (2048 and 512 for\n"
       printf "brute force), 1 thread, medians of 3 runs. Peak RSS is the whole process after loading the\n"
       printf "OBJ and building the mesh (getrusage), one process per size.\n\n"
       printf "%10s %9s %9s %10s %12s %10s %9s %9s %9s\n", "triangles", "mesh ms", "BVH ms",
              "BVH us/ray", "brute us/ray", "mesh B/tri", "BVH B/tri", "mesh+BVH", "peak RSS"
     }
     /^#/ { next }
     { mb = $1 * ($6 + $7) / 1048576
       printf "%10d %9.1f %9.1f %10.3f %12s %10.1f %9.1f %6.1f MiB %5.1f MiB\n", $1, $2, $3, $4,
              ($5 < 0 ? "-" : sprintf("%.1f", $5)), $6, $7, mb, $8
       n = $1; peak = $8; load = $11; mbLast = mb; if ($10 > 0) bad += $10 }
     END {
       mb = peak * 1.048576
       printf "\n%d triangles: mesh + BVH %.1f MiB; peak RSS %.1f MiB = %.1f MB (%.1f MiB after loading the\n",
              n, mbLast, peak, mb, load
       printf "OBJ, before building the mesh): %s\n",
              (mb < 80 ? "well under 100 MB" : (mb < 100 ? "under 100 MB, not by much" : "NOT under 100 MB"))
       if (bad) printf "brute force and BVH disagree on %d rays\n", bad
       else printf "brute force and BVH agree on every ray\n"
     }' "$data" | tee "$charts/ch03-scaling.txt"
for ext in svg png; do
  gnuplot -e "data='$data'; out='$charts/ch03-bvh-scaling.$ext'" "$charts/ch03-bvh-scaling.gp"
done
echo "charts: wrote $charts/ch03-bvh-scaling.svg and .png"

# The sampling lab's figures (issue 25): every sampler of the book drawn against the pdf its
# code states (./rt --warptest all), one SVG per sampler, docs/charts/chNN-lab-NAME.svg.
"$build/rt_all" --warptest all --output-dir "$charts"

# The chapters' own charts.
for script in "$root"/tests/perf/ch[0-9][0-9]/charts.sh; do
  [ -e "$script" ] || continue
  echo "charts: $script"
  bash "$script" "$build"
done

# Rendering to a target error (issue 38): RMSE against render time, uniform against adaptive,
# one chart per scene (docs/charts/target-error-<scene>.svg), and docs/charts/target-error.md.
echo "charts: tests/perf/target_error/bench.sh"
bash "$root/tests/perf/target_error/bench.sh" "$build" "$charts"
