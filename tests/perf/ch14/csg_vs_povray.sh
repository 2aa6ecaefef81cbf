#!/usr/bin/env bash
# The CSG scene against POV-Ray 3.7: render time of the same picture, as a ratio.
#
# usage: tests/perf/ch14/csg_vs_povray.sh BUILD_DIR
#   CSG_SIZE=WxH    image size (default 1024x1024)
#   CSG_THREADS=N   threads for both renderers (default 1)
#   CSG_RUNS=N      runs of each, alternating (default 7)
#
# The scene: tests/perf/scenes/csg.lua and tests/perf/povray/csg_spheres_boxes.pov (the peers'
# csg.pov without the cylinders and cones of chapter 15: a box minus a sphere and a lens made of
# two spheres, on a plane, two point lights, one ray per pixel, no AA). Times: raybook's render
# phase (--stats), POV-Ray's own Trace Time (its process has an idle wall-time floor of about
# 0.7 s; see $RB_SHARED/peers/README.md). Prints the times and two ratios raybook / POV-Ray:
# the median of the ratios of each pair of back-to-back runs (robust to the load drifting),
# and fastest against fastest.
set -euo pipefail
build=$(cd "${1:?usage: csg_vs_povray.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
size=${CSG_SIZE:-1024x1024}
threads=${CSG_THREADS:-1}
runs=${CSG_RUNS:-7}
rt=$(ls "$build"/rt_ch[0-9]* | sort -V | tail -1)
lua=$root/tests/perf/scenes/csg.lua
pov=$root/tests/perf/povray/csg_spheres_boxes.pov
command -v povray >/dev/null || { echo "csg_vs_povray: povray is not installed"; exit 1; }
tmp=$(mktemp -d /tmp/raybook-csg.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

rb() {  # prints the render seconds and the rays: "seconds camera shadow"
  (cd "$root" && "$rt" --quiet --stats --threads "$threads" --size "$size" --output "$tmp/rb.png" "$lua" 2>&1) |
    awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
         $1 == "rays" { for (i = 2; i < NF; i++) { if ($i == "camera") c = $(i + 1); if ($i == "shadow") s = $(i + 1) } }
         END { print r, c, s }'
}
pv() {  # prints POV-Ray's trace seconds and its shadow ray tests
  (cd "$tmp" && povray +I"$pov" +O"$tmp/pov.png" +W"${size%x*}" +H"${size#*x}" -D -GR -A +WT"$threads" 2>&1) |
    awk '/Trace Time:/ { t = $0; sub(/.*\(/, "", t); sub(/ seconds.*/, "", t) }
         /Shadow Ray Tests:/ { s = $4 }
         END { print t, s }'
}

rbTimes=(); pvTimes=()
for run in $(seq "$runs"); do
  read -r t camera shadow <<<"$(rb)"; rbTimes+=("$t")
  read -r tp shadowPov <<<"$(pv)"; pvTimes+=("$tp")
done
rbBest=$(printf '%s\n' "${rbTimes[@]}" | sort -g | head -1)
pvBest=$(printf '%s\n' "${pvTimes[@]}" | sort -g | head -1)
# Markdown: the chapter page includes this output (docs/charts/ch14-povray.txt).
echo "CSG scene (box minus sphere, lens of two spheres; the peers' csg.pov without chapter 15's"
echo "quadrics) at $size, $threads thread(s), $runs alternating runs:"
echo ""
echo "- raybook $(basename "$rt") render phase, fastest ${rbBest} s ($camera camera rays, $shadow shadow rays); runs: ${rbTimes[*]}"
echo "- POV-Ray 3.7 Trace Time, fastest ${pvBest} s ($shadowPov shadow ray tests); runs: ${pvTimes[*]}"
paired=$(for i in "${!rbTimes[@]}"; do awk -v a="${rbTimes[$i]}" -v b="${pvTimes[$i]}" 'BEGIN { print a / b }'; done |
  sort -g | awk '{ r[NR] = $1 } END { print r[int((NR + 1) / 2)] }')
awk -v p="$paired" -v a="$rbBest" -v b="$pvBest" 'BEGIN {
  printf "- **ratio raybook / POV-Ray: median of back-to-back pairs %.2f**, fastest against fastest %.2f (below 1: raybook is faster)\n", p, a / b }'
