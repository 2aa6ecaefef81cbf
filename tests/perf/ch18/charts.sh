#!/usr/bin/env bash
# Chapter 18's charts, into docs/charts/:
#   ch18-methods.svg/.png   RMSE against render time for path tracing, photon mapping (chapter 16,
#                           caustic and indirect maps) and Whitted + A4's ambient term, on two
#                           scenes: chapter 16's box without its balls (every method can converge
#                           there but Whitted), and chapter 16's scene with its glass and mirror
#                           balls under a point light (where path tracing fails: a path can never
#                           hit a point light, so the caustics never appear)
#   ch18-methods.txt        the points as a Markdown table (\include{doc})
#   ch18-finding.txt        the finding in one sentence, with numbers (\include{doc})
#
# usage: tests/perf/ch18/charts.sh BUILD_DIR   (about 5 minutes on 2 idle cores)
#
# References: the box without balls against path tracing at 4096 paths a pixel (unbiased); the
# box with balls against photon mapping at 256 passes of 200,000 photons (what path tracing
# cannot draw is exactly what that reference has). Each is a different seed from the measured
# renders. Images are 96x96 linear PNGs (channels clamped to [0, 1]); time is the render phase
# of --stats (photon passes included), all cores, the fastest of CH18_ROUNDS rounds (default 2).
set -euo pipefail
build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch18
mkdir -p "$charts" "$data"
rt=$build/rt_ch18
[[ -x $rt ]] || { echo "charts.sh: $rt not built" >&2; exit 2; }
python3 "$root/tests/perf/ch18/methods_chart.py" "$rt" "$root" "$data" "$charts" "${CH18_ROUNDS:-2}"
for ext in svg png; do
  gnuplot -e "data='$data/methods.dat'; out='$charts/ch18-methods.$ext'" \
    "$root/tests/perf/ch18/methods.gp"
done
echo "charts: wrote $charts/ch18-methods.svg and .png"
