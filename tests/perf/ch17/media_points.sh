#!/usr/bin/env bash
# How many lamp points per pixel (chapter 17's --media-points): efficiency 1/(error^2 x time) on
# the shaft at 1 and 16 samples per pixel and on the chapter's scene at its 144, for 4 to 256
# points. The error is two seeds' renders' RMSE over sqrt 2 (8-bit, against each other: no
# reference needed); the time is one thread's user CPU seconds, the mean of the two.
#
# usage: tests/perf/ch17/media_points.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: media_points.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
rt=$build/rt_ch17
rmse=$build/tests/perf/ch08/ch08_aa_charts
tmp=$(mktemp -d /tmp/raybook-points.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

point() {  # label scene points args...: one table row's cell
  local label=$1 scene=$2 points=$3 s t=()
  shift 3
  for s in 1 2; do
    (cd "$root" && /usr/bin/time -f %U -o "$tmp/time" "$rt" --quiet --threads 1 --seed "$s" \
        --media-points="$points" --output "$tmp/$s.png" "$@" "$scene" >/dev/null 2>&1)
    t+=("$(cat "$tmp/time")")
  done
  local e
  e=$("$rmse" rmse "$tmp/1.png" "$tmp/2.png")
  awk -v l="$label" -v p="$points" -v a="${t[0]}" -v b="${t[1]}" -v e="$e" 'BEGIN {
    t = (a + b) / 2; e /= sqrt(2)
    printf "%-34s %4d points: %6.2f s, error %.5f, efficiency %.0f\n", l, p, t, e, 1 / (e * e * t) }'
}
for p in 4 16 64 256; do point "shaft, 1 sample per pixel" tests/perf/ch17/shaft.lua "$p" --media-bounces=0 --spp 1; done
for p in 4 16 64 256; do point "shaft, 16 jittered samples" tests/perf/ch17/shaft.lua "$p" --media-bounces=0 --spp 16; done
for p in 4 16 64; do point "chapter 17's scene, 144 samples" scenes/chapter17-media.lua "$p"; done
