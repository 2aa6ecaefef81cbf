#!/usr/bin/env bash
# make bench: raybook against POV-Ray 3.7 on equivalent scenes, in one run, alternating.
#
# usage: bench.sh BUILD_DIR        (BENCH_RUNS=N sets the runs per scene and thread count, default 5)
#
# raybook's time is the "render" phase that ./rt --stats prints (after the scene is loaded and
# the BVH built); POV-Ray's is its own "Trace Time" line, because its process has a fixed idle
# floor of about 0.69 s (see ../shared/peers/README.md). Runs alternate raybook, POV-Ray,
# raybook, ... so both see the same machine load. This is a benchmark, not a test: nothing here
# gates CI. The table also goes to BUILD_DIR/bench/bench.txt.
set -euo pipefail
build=$(cd "${1:?usage: bench.sh BUILD_DIR}" && pwd)
runs=${BENCH_RUNS:-5}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
peers=$root/../shared/peers/povray
rt=$build/rt_ch7
out=$build/bench
mkdir -p "$out"
[ -d "$peers" ] || { echo "bench: $peers not found (shared/ must sit beside the repository)"; exit 1; }
command -v povray >/dev/null || { echo "bench: povray is not installed (make bench installs it)"; exit 1; }

# One line per scene: name | raybook scene | POV-Ray scene | size | target ratio (raybook/POV).
# Adding a chapter's benchmark scene is one line here.
scenes=(
  "spheres      | tests/perf/scenes/spheres.lua      | spheres.pov      | 512 | 0.5"
  "mirror_glass | tests/perf/scenes/mirror_glass.lua | mirror_glass.pov | 512 | 0.5"
  "soft         | tests/perf/scenes/soft.lua         | soft.pov         | 512 | 0.5"
  "mesh_L0      | tests/perf/scenes/mesh_L0.lua      | mesh_L0.pov      | 512 | 0.5"
  "mesh         | tests/perf/scenes/mesh.lua         | mesh.pov         | 512 | 0.2"
)

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; echo "${s%"${s##*[![:space:]]}"}"; }

# raybook's render seconds for one run.
rb_time() {  # scene threads
  (cd "$root" && "$rt" --quiet --stats --threads "$2" --output "$out/rb.png" "$1" 2>&1) |
    sed -n 's/.*render \([0-9.]*\) s.*/\1/p' | head -1
}
# POV-Ray's trace seconds for one run.
pov_time() {  # pov threads size
  (cd "$peers" && povray +I"$1" +O"$out/pov.png" +W"$3" +H"$3" -D -GR -A +WT"$2" 2>&1) |
    sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' | head -1
}
# median, min and max of the numbers on stdin.
stats() { sort -g | awk '{v[NR]=$1} END {m = NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2; printf "%.4f %.4f %.4f\n", m, v[1], v[NR]}'; }

report=$out/bench.txt
{
  echo "raybook vs POV-Ray 3.7, $runs alternating runs each, $(nproc) cores, $(date -u +%F)"
  echo "raybook: render phase of ./rt --stats; POV-Ray: its Trace Time. Ratio = median/median."
  echo
  printf "%-13s %3s  %-26s %-26s %7s %7s %s\n" scene thr "raybook s (min-max)" "POV-Ray trace s (min-max)" ratio target met
} | tee "$report"
declare -A rb_median
for threads in 1 2; do
  for line in "${scenes[@]}"; do
    IFS='|' read -r name lua pov size target <<<"$line"
    name=$(trim "$name"); lua=$(trim "$lua"); pov=$(trim "$pov"); size=$(trim "$size"); target=$(trim "$target")
    rb=(); pv=()
    for ((i = 0; i < runs; i++)); do
      rb+=("$(rb_time "$lua" "$threads")")
      pv+=("$(pov_time "$pov" "$threads" "$size")")
    done
    read -r rm rlo rhi < <(printf "%s\n" "${rb[@]}" | stats)
    read -r pm plo phi < <(printf "%s\n" "${pv[@]}" | stats)
    rb_median[$name.$threads]=$rm
    ratio=$(awk -v a="$rm" -v b="$pm" 'BEGIN {printf "%.2f", a / b}')
    met=$(awk -v r="$ratio" -v t="$target" 'BEGIN {print (r <= t) ? "met" : "MISSED"}')
    printf "%-13s %3s  %-26s %-26s %7s %7s %s\n" "$name" "$threads" \
      "$rm ($rlo-$rhi)" "$pm ($plo-$phi)" "$ratio" "<= $target" "$met" | tee -a "$report"
  done
done

{
  echo
  echo "raybook's 2-thread speedup (median 1-thread / median 2-thread render; target >= 1.9):"
  for line in "${scenes[@]}"; do
    IFS='|' read -r name _ <<<"$line"; name=$(trim "$name")
    awk -v n="$name" -v a="${rb_median[$name.1]}" -v b="${rb_median[$name.2]}" \
      'BEGIN {s = a / b; printf "  %-13s %.2fx %s\n", n, s, (s >= 1.9) ? "met" : "MISSED"}'
  done
} | tee -a "$report"

# Features a scene does not use cost nothing: the chapter-2 scene rendered by the chapter-3
# binary (the whole core, no optional chapter) and by the full binary with every feature on,
# alternating. (The chapter-2 binary itself is slower: it has no BVH yet, chapter 3 adds it.)
render_s() { (cd "$root" && "$@" --quiet --stats --threads 1 --size 1024x768 scenes/chapter02-phong.lua 2>&1) | sed -n 's/.*render \([0-9.]*\) s.*/\1/p'; }
c3=(); c7=(); c2=()
for ((i = 0; i < runs; i++)); do
  c3+=("$(render_s "$build/rt_ch3" --output "$out/c3.png")")
  c7+=("$(render_s "$rt" --features=all --output "$out/c7.png")")
  c2+=("$(render_s "$build/rt_ch2" --output "$out/c2.png")")
done
read -r m3 lo3 hi3 < <(printf "%s\n" "${c3[@]}" | stats)
read -r m7 lo7 hi7 < <(printf "%s\n" "${c7[@]}" | stats)
read -r m2 lo2 hi2 < <(printf "%s\n" "${c2[@]}" | stats)
{
  echo
  echo "Unused features cost nothing: scenes/chapter02-phong.lua at 1024x768, 1 thread (target within 2%):"
  awk -v a="$m3" -v b="$m7" -v la="$lo3" -v ha="$hi3" -v lb="$lo7" -v hb="$hi7" 'BEGIN {
    d = (b / a - 1) * 100;
    printf "  rt_ch3 %.4f s (%.4f-%.4f), rt_ch7 --features=all %.4f s (%.4f-%.4f): %+.1f%% %s\n",
           a, la, ha, b, lb, hb, d, (d <= 2 && d >= -2) ? "met" : "MISSED" }'
  echo "  rt_ch2 (no BVH yet) $m2 s ($lo2-$hi2)"
  cmp -s "$out/c3.png" "$out/c7.png" && cmp -s "$out/c2.png" "$out/c7.png" &&
    echo "  (the three images are byte-identical)"
} | tee -a "$report"

# BVH against Embree, when its benchmark program was built.
if [ -x "$build/tests/perf/bvh_vs_embree" ]; then
  echo | tee -a "$report"
  (cd "$root" && "$build/tests/perf/bvh_vs_embree" ../shared/assets/bunny_L2.obj) | tee -a "$report"
fi
echo
echo "table saved to $report"
