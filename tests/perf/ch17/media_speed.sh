#!/usr/bin/env bash
# Chapter 17's speed (make bench):
#   - the 2-thread speedup of the chapter scene: rt_ch17 --stats on scenes/chapter17-media.lua
#     as it is (its size, its 144 jittered samples per pixel, fog, the VDB plume, multiple
#     scattering), 1 and 2 threads;
#   - null collisions per real collision and time per free flight against the majorant grid's
#     resolution: BUILD_DIR/tests/perf/ch17/ch17_majorant (skipped, with a note, when not built).
#
# usage: tests/perf/ch17/media_speed.sh BUILD_DIR
#   MEDIA_RUNS=N   alternating runs per thread count (default 5)
#
# Time: the render phase of --stats; runs alternate 1 thread, 2 threads, ...; medians, min-max
# beside them. The image must be bit-identical for 1 and 2 threads (checked). Prints a report
# and "target NAME VALUE" lines for make bench's summary: media_speedup (issue 22: >= 1.9), and
# ch17_majorant's null_per_real_global, null_per_real_16 and flight_speedup_16 (no targets).
set -euo pipefail
build=$(cd "${1:?usage: media_speed.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
runs=${MEDIA_RUNS:-5}
rt=$build/rt_ch17
majorant=$build/tests/perf/ch17/ch17_majorant
scene=scenes/chapter17-media.lua
[ -x "$rt" ] || { echo "media_speed: $rt not built"; exit 1; }
tmp=$(mktemp -d /tmp/raybook-media-speed.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

one() {  # threads ; prints "render_s total_rays"
  (cd "$root" && "$rt" --quiet --stats --threads "$1" --output "$tmp/t$1.png" "$scene" 2>&1) |
    awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
         $1 == "rays" { t = $NF; sub(/\)/, "", t) }
         END { if (r == "") exit 1; print r, t }'
}
stats() { sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
                                              printf "%.4f %.4f %.4f\n", m, v[1], v[NR] }'; }

t1=(); t2=()
for ((i = 0; i < runs; i++)); do
  read -r s rays <<<"$(one 1)"; t1+=("$s")
  read -r s _ <<<"$(one 2)"; t2+=("$s")
done
read -r m1 lo1 hi1 < <(printf "%s\n" "${t1[@]}" | stats)
read -r m2 lo2 hi2 < <(printf "%s\n" "${t2[@]}" | stats)
same=$(cmp -s "$tmp/t1.png" "$tmp/t2.png" && echo "byte-identical" || echo "DIFFERENT")
awk -v m1="$m1" -v lo1="$lo1" -v hi1="$hi1" -v m2="$m2" -v lo2="$lo2" -v hi2="$hi2" -v rays="$rays" \
    -v runs="$runs" -v same="$same" -v scene="$scene" 'BEGIN {
  printf "Chapter 17 scene (%s as it is, %d rays), %d alternating runs, render seconds\n", scene, rays, runs
  printf "from --stats, median (min-max); images of 1 and 2 threads %s:\n", same
  printf "  1 thread  %.3f s (%.3f-%.3f)\n", m1, lo1, hi1
  printf "  2 threads %.3f s (%.3f-%.3f)\n", m2, lo2, hi2
  s = m1 / m2
  printf "  2-thread speedup %.2fx (target >= 1.9): %s\n", s, (s >= 1.9) ? "met" : "MISSED"
  printf "target media_speedup %.2f\n", s
}'
[ "$same" = byte-identical ] || { echo "media_speed: the 1- and 2-thread images differ" >&2; exit 1; }

if [ -x "$majorant" ]; then
  (cd "$root" && "$majorant" scenes/assets/plume.nvdb 100000)
else
  echo "(ch17_majorant was not built: no majorant measure)"
fi
