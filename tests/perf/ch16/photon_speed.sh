#!/usr/bin/env bash
# Chapter 16's photon speed (make bench):
#   - photons traced per second, and the 2-thread speedup of the photon passes: rt_ch16 --stats
#     on the chapter scene, 1 and 2 threads;
#   - the photon grid's build time per million photons and the time of a 50-photon gather, one
#     thread: BUILD_DIR/tests/perf/ch16/ch16_photon_speed (skipped, with a note, when not built).
#
# usage: tests/perf/ch16/photon_speed.sh BUILD_DIR
#   PHOTON_RUNS=N   alternating runs per thread count (default 5)
#
# The scene: scenes/chapter16-photon-mapping.lua as it is (a caustic map and an indirect map),
# with --photons 100000 --photon-passes 8 (1.6 million photons emitted, 800,000 for each map) at
# --size 64x64 and --photon-radius 0.02, so that the render after the passes is short (the size
# and the radius change the gathers, not the tracing; the grids take the same time). Time:
# the photon passes' seconds on the "photons" line of --stats (tracing, then each pass's grid
# build, which is serial); runs alternate 1 thread, 2 threads, ...; medians, min-max beside them.
# Photons per second = photons emitted / photon-pass seconds; photon rays are the "photon" count
# of the "rays" line (one per segment a photon travels). The image is bit-identical for 1 and 2
# threads (checked here too). Prints a report and "target NAME VALUE" lines for make bench's
# summary: photon_speedup (issue 20: >= 1.9), photons_per_second (2 threads, no target), and
# ch16_photon_speed's grid_build_ms_per_million (<= 50) and gather_50_us (<= 2).
set -euo pipefail
build=$(cd "${1:?usage: photon_speed.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
runs=${PHOTON_RUNS:-5}
rt=$build/rt_ch16
speed=$build/tests/perf/ch16/ch16_photon_speed
scene=scenes/chapter16-photon-mapping.lua
count=100000
passes=8
[ -x "$rt" ] || { echo "photon_speed: $rt not built"; exit 1; }
tmp=$(mktemp -d /tmp/raybook-photons.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

one() {  # threads ; prints "photon_s photon_rays caustic_stored indirect_stored"
  (cd "$root" && "$rt" --quiet --stats --threads "$1" --size 64x64 --photons "$count" \
       --photon-passes "$passes" --photon-radius 0.02 --output "$tmp/t$1.png" "$scene" 2>&1) |
    awk '$1 == "rays" { for (i = 2; i < NF; i++) if ($i == "photon") r = $(i + 1) }
         # "photons  P passes of N in S s; caustic C stored, radius ...; indirect D stored, ..."
         # (older builds: "photons  P passes of N: C caustic, D indirect stored; ...; S s")
         $1 == "photons" { s = $(NF - 1)
                           for (i = 2; i < NF; i++) {
                             if ($i == "in" && $(i + 2) ~ /^s/) s = $(i + 1)
                             if ($i == "caustic" && $(i + 1) ~ /^[0-9]+$/) c = $(i + 1)
                             if ($(i + 1) == "caustic," && $i ~ /^[0-9]+$/) c = $i
                             if ($i == "indirect" && $(i + 1) ~ /^[0-9]+$/) d = $(i + 1)
                             if ($(i + 1) == "indirect" && $i ~ /^[0-9]+$/) d = $i } }
         END { if (s == "") exit 1; print s, r, c, d }'
}
stats() { sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
                                              printf "%.4f %.4f %.4f\n", m, v[1], v[NR] }'; }

t1=(); t2=()
for ((i = 0; i < runs; i++)); do
  read -r s rays1 c d <<<"$(one 1)"; t1+=("$s")
  read -r s _ _ _ <<<"$(one 2)"; t2+=("$s")
done
read -r m1 lo1 hi1 < <(printf "%s\n" "${t1[@]}" | stats)
read -r m2 lo2 hi2 < <(printf "%s\n" "${t2[@]}" | stats)
same=$(cmp -s "$tmp/t1.png" "$tmp/t2.png" && echo "byte-identical" || echo "DIFFERENT")
emitted=$((2 * count * passes))
awk -v m1="$m1" -v lo1="$lo1" -v hi1="$hi1" -v m2="$m2" -v lo2="$lo2" -v hi2="$hi2" -v e="$emitted" \
    -v rays="$rays1" -v c="$c" -v d="$d" -v runs="$runs" -v same="$same" -v count="$count" -v passes="$passes" 'BEGIN {
  printf "Photon passes (chapter 16): %s, caustic and indirect maps, %d passes of %d photons per map\n",
         "scenes/chapter16-photon-mapping.lua", passes, count
  printf "(%.1f million photons emitted; %d caustic and %d indirect stored; %d photon rays), %d alternating runs,\n",
         e / 1e6, c, d, rays, runs
  printf "photon-pass seconds from --stats, median (min-max); images of 1 and 2 threads %s:\n", same
  printf "  1 thread  %.3f s (%.3f-%.3f): %.2f million photons/s, %.2f million photon rays/s\n",
         m1, lo1, hi1, e / m1 / 1e6, rays / m1 / 1e6
  printf "  2 threads %.3f s (%.3f-%.3f): %.2f million photons/s, %.2f million photon rays/s\n",
         m2, lo2, hi2, e / m2 / 1e6, rays / m2 / 1e6
  s = m1 / m2
  printf "  2-thread speedup %.2fx (target >= 1.9): %s\n", s, (s >= 1.9) ? "met" : "MISSED"
  printf "target photon_speedup %.2f\n", s
  printf "target photons_per_second %.0f\n", e / m2
}'
[ "$same" = byte-identical ] || { echo "photon_speed: the 1- and 2-thread images differ" >&2; exit 1; }

if [ -x "$speed" ]; then
  "$speed"
else
  echo "(ch16_photon_speed was not built: no grid build or gather time)"
fi
