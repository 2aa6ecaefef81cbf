#!/usr/bin/env bash
# Adaptive antialiasing against POV-Ray 3.7's adaptive method 2 (+AM2), at equal error.
#
# usage: tests/perf/ch08/aa_vs_povray.sh BUILD_DIR OUT_DIR
#   AA_SIZE=WxH    image size (default 256x256)
#   AA_THREADS=N   threads for both renderers (default 1)
# Writes OUT_DIR/povray.dat (renderer, threshold, render s, RMSE) and prints a table and the
# ratio raybook/POV-Ray of render time at equal error.
#
# The scene: tests/perf/scenes/mirror_glass.lua and tests/perf/povray/mirror_glass_grey.pov (the
# peers' mirror_glass.pov with raybook's grey plane and black background, so both have the same
# edges to antialias). Each renderer's error is its RMSE against its own converged reference,
# since the two renderers' pictures differ slightly (POV-Ray's shadows through glass, its
# Fresnel): raybook's reference is jittered 16 x 16 (256 rays per pixel), POV-Ray's is +AM2 with
# threshold 0 and depth 4 (+A0.0 +R4: every pixel split into 16 x 16). POV-Ray runs without
# jitter (-J), so its samples, like raybook's adaptive ones, sit on a fixed lattice. Both write linear colour
# (POV-Ray with File_Gamma=1.0), 8 bits per channel. Times: raybook's render phase (--stats),
# POV-Ray's Trace Time; the fastest of 3 runs each, runs alternating.
# The sweep: thresholds 0.4, 0.2, 0.1, 0.05, 0.025, 0.01 at depth 3 (raybook --aa-depth 3,
# POV-Ray +R3, its default). POV-Ray's threshold compares colours its own way (the sum of the
# channel differences), so equal thresholds are not equal settings: the comparison is at equal
# error, interpolating raybook's time (log-log) at each POV-Ray point's error.
set -euo pipefail
build=$(cd "${1:?usage: aa_vs_povray.sh BUILD_DIR OUT_DIR}" && pwd)
out=${2:?usage: aa_vs_povray.sh BUILD_DIR OUT_DIR}
mkdir -p "$out"
out=$(cd "$out" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
size=${AA_SIZE:-256x256}
threads=${AA_THREADS:-1}
rt=$(ls "$build"/rt_ch[0-9]* | sort -V | tail -1)
rmse=$build/tests/perf/ch08/ch08_aa_charts
lua=$root/tests/perf/scenes/mirror_glass.lua
pov=$root/tests/perf/povray/mirror_glass_grey.pov
command -v povray >/dev/null || { echo "aa_vs_povray: povray is not installed (make bench installs it)"; exit 1; }
[ -x "$rmse" ] || { echo "aa_vs_povray: $rmse not built"; exit 1; }
tmp=$(mktemp -d /tmp/raybook-aa.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

rb() {  # output.png args... ; prints the render seconds
  local png=$1; shift
  (cd "$root" && "$rt" --quiet --stats --threads "$threads" --size "$size" --output "$png" "$@" "$lua" 2>&1) |
    awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") print $i }'
}
pv() {  # output.png args... ; prints POV-Ray's trace seconds
  local png=$1; shift
  (cd "$tmp" && povray +I"$pov" +O"$png" +W"${size%x*}" +H"${size#*x}" -D -GR +WT"$threads" \
       File_Gamma=1.0 "$@" 2>&1) |
    awk '/Trace Time:/ { t = $0; sub(/.*\(/, "", t); sub(/ seconds.*/, "", t); print t }'
}
fastest() { sort -g | head -1; }

echo "aa_vs_povray: references ($size)" >&2
rb "$tmp/rb-ref.png" --aa=jittered --spp 256 --seed 7 >/dev/null
pv "$tmp/pv-ref.png" +A0.0 +AM2 +R4 -J >/dev/null

dat=$out/povray.dat
{
  echo "# adaptive AA at $size, $threads thread(s): renderer threshold seconds rmse"
  for renderer in raybook povray; do
    echo "# $renderer"
    for t in 0.4 0.2 0.1 0.05 0.025 0.01; do
      echo "aa_vs_povray: $renderer threshold $t" >&2
      times=()
      for run in 1 2 3; do
        if [ $renderer = raybook ]; then
          times+=("$(rb "$tmp/img.png" --aa=adaptive --aa-threshold "$t" --aa-depth 3)")
          ref=$tmp/rb-ref.png
        else
          times+=("$(pv "$tmp/img.png" +A"$t" +AM2 +R3 -J)")
          ref=$tmp/pv-ref.png
        fi
      done
      echo "$renderer $t $(printf '%s\n' "${times[@]}" | fastest) $("$rmse" rmse "$tmp/img.png" "$ref")"
    done
    echo; echo
  done
  # No antialiasing at all, for scale.
  echo "# none: raybook, povray (one ray per pixel centre; -A)"
  echo "raybook none $(rb "$tmp/img.png") $("$rmse" rmse "$tmp/img.png" "$tmp/rb-ref.png")"
  echo "povray none $(pv "$tmp/img.png" -A) $("$rmse" rmse "$tmp/img.png" "$tmp/pv-ref.png")"
} >"$dat"

# The table and the ratio at equal error: for each POV-Ray point inside raybook's error range,
# raybook's time at that error by log-log interpolation between its two neighbouring points.
python3 - "$dat" "$size" "$threads" <<'PY'
import math, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
rb = [(float(r[3]), float(r[2]), r[1]) for r in rows if r[0] == "raybook" and r[1] != "none"]
pv = [(float(r[3]), float(r[2]), r[1]) for r in rows if r[0] == "povray" and r[1] != "none"]
none = {r[0]: (float(r[3]), float(r[2])) for r in rows if r[1] == "none"}
# Markdown: the chapter page includes this output (docs/charts/ch08-povray.txt), so it is two
# tables and a bullet, not aligned columns (Doxygen would run those into one paragraph).
print(f"Adaptive antialiasing, mirror_glass (grey plane) at {sys.argv[2]}, {sys.argv[3]} thread(s); "
      "each renderer's RMSE against its own converged reference; fastest of 3 runs.")
print()
print("| threshold | raybook s | raybook RMSE | POV-Ray s | POV-Ray RMSE |")
print("|---:|---:|---:|---:|---:|")
for (e1, t1, th), (e2, t2, _) in zip(rb, pv):
    print(f"| {th} | {t1:.3f} | {e1:.5f} | {t2:.3f} | {e2:.5f} |")
print(f"| none (one ray per pixel) | {none['raybook'][1]:.3f} | {none['raybook'][0]:.5f} | "
      f"{none['povray'][1]:.3f} | {none['povray'][0]:.5f} |")
print()
def time_at(points, e):
    pts = sorted(points)  # by error
    for (ea, ta, _), (eb, tb, _) in zip(pts, pts[1:]):
        if ea <= e <= eb and ea > 0 and eb > ea:
            f = (math.log(e) - math.log(ea)) / (math.log(eb) - math.log(ea))
            return math.exp(math.log(ta) + f * (math.log(tb) - math.log(ta)))
    return None
ratios = []
for e, t, th in pv:
    tr = time_at(rb, e)
    if tr is not None:
        ratios.append((th, e, tr, t, tr / t))
print("Equal error: raybook's time interpolated (log-log) at each POV-Ray point's RMSE "
      "(ratio = raybook / POV-Ray; below 1: raybook is faster).")
print()
if ratios:
    print("| POV-Ray setting | RMSE | POV-Ray s | raybook s | ratio |")
    print("|---|---:|---:|---:|---:|")
    for th, e, tr, t, r in ratios:
        print(f"| `+A{th} +AM2 +R3` | {e:.5f} | {t:.3f} | {tr:.3f} | {r:.2f} |")
    print()
    rs = sorted(r for *_, r in ratios)
    print(f"- **median ratio {rs[len(rs) // 2]:.2f}** over {len(rs)} points (below 1: raybook is faster)")
else:
    print("- the two error ranges do not overlap: no ratio at equal error")
PY
