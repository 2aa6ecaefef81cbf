#!/usr/bin/env bash
# Caustics against POV-Ray 3.7's photon mapping, at equal error.
#
# usage: tests/perf/ch16/caustics_vs_povray.sh BUILD_DIR OUT_DIR
#   CAUSTICS_SIZE=WxH    image size (default 192x192, the chapter scene's)
#   CAUSTICS_THREADS=N   threads for both renderers' measured runs (default 1)
#   CAUSTICS_ROUNDS=N    timed rounds, the fastest run of each point kept (default 3)
# Writes OUT_DIR/povray.dat (renderer, quality, seconds, RMSE, photons, photon seconds) and
# prints Markdown: the two renderers' points, the ratio raybook/POV-Ray of render time at equal
# error, what differs between the two; last, a line "target caustics_povray RATIO" (the median
# ratio) for make bench's summary.
#
# The scenes: scenes/chapter16-photon-mapping.lua with gr.photons{indirect = false} (POV-Ray has
# no indirect photon map, and radiosity is left out), and tests/perf/povray/chapter16-caustics.pov
# (its comments say how the box, the balls, the camera and the materials translate). Both with
# the light made an inverse-square point light, as bright at distance 1.5 as the chapter's
# light: raybook gr.light(..., 2.25 x colour, {0, 0, 1}), POV-Ray Declare=InverseSquare=2.25.
# The chapter's light has no falloff ({1, 0, 0}), and the two renderers carry that differently
# along a photon's path: raybook applies the falloff up to the first surface the photon meets,
# so photons spread physically after a mirror or glass; POV-Ray keeps the light's "no falloff"
# along the whole path. Measured with a light 1 above a flat mirror (reflection 0.9) and 1 below
# a white ceiling: the caustic on the ceiling is 0.9 x 0.5/3² (raybook, 13.6/255 against 12.75
# predicted) against 0.9 x 0.5 (POV-Ray, 115/255 against 115), so on the chapter's light
# POV-Ray's caustics on the walls are 3 to 4 times raybook's. With 1/d² both agree (POV-Ray
# 12.8/255 on the same test) and the two converged pictures differ by RMSE 0.014.
# Quality levels: POV-Ray, photons { count N autostop 0 } with its default gather (the 20 to 100
# nearest photons, adaptive radius), N = 5,000 to 5,120,000. raybook, two series: (1) the method
# POV-Ray uses, one photon pass of N = 20,000 to 5,120,000 photons gathered by the k = 50
# nearest within the default radius (gr.photons{method = 'classic', k = 50}; 3 pixel footprints,
# 0.041); (2) the chapter's defaults, progressive (alpha 2/3, first radius 0.041), 1 to 256
# passes of 20,000 photons. The ratio at equal error is given for both; make bench's summary
# reads the first (the same method in both renderers). Each renderer's error is its RMSE against its own converged reference: raybook's
# is progressive from radius 0.01, 256 passes of 200,000 photons, seed 7; POV-Ray's count
# 20,480,000 (about 9 million photons shot). Both write linear colour (POV-Ray with
# File_Gamma=1.0), 8 bits, one ray per pixel (-A). Times: raybook's render phase (--stats;
# the photon passes included), POV-Ray's Photon Time + Trace Time.
set -euo pipefail
build=$(cd "${1:?usage: caustics_vs_povray.sh BUILD_DIR OUT_DIR}" && pwd)
out=${2:?usage: caustics_vs_povray.sh BUILD_DIR OUT_DIR}
mkdir -p "$out"
out=$(cd "$out" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
size=${CAUSTICS_SIZE:-192x192}
threads=${CAUSTICS_THREADS:-1}
rounds=${CAUSTICS_ROUNDS:-3}
rt=$build/rt_ch16
rmse=$build/tests/perf/ch08/ch08_aa_charts
pov=$root/tests/perf/povray/chapter16-caustics.pov
scene=$root/scenes/chapter16-photon-mapping.lua
command -v povray >/dev/null || { echo "caustics_vs_povray: povray is not installed (make bench installs it)"; exit 1; }
[ -x "$rt" ] || { echo "caustics_vs_povray: $rt not built"; exit 1; }
[ -x "$rmse" ] || { echo "caustics_vs_povray: $rmse not built"; exit 1; }
tmp=$(mktemp -d /tmp/raybook-caustics.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

# The raybook scene: caustics only, the inverse-square light.
light='gr.light({0, 1.8, 0.2}, {0.75, 0.75, 0.72}, {1, 0, 0})'
for text in 'gr.photons{indirect = true}' "$light"; do
  grep -qF "$text" "$scene" || { echo "caustics_vs_povray: '$text' not found in $scene"; exit 1; }
done
sed -e 's/gr.photons{indirect = true}/gr.photons{indirect = false}/' \
    -e 's/gr.light({0, 1.8, 0.2}, {0.75, 0.75, 0.72}, {1, 0, 0})/gr.light({0, 1.8, 0.2}, {1.6875, 1.6875, 1.62}, {0, 0, 1})/' \
    "$scene" >"$tmp/caustics.lua"
sed 's/gr.photons{indirect = false}/gr.photons{indirect = false, method = '"'classic'"', k = 50}/' \
    "$tmp/caustics.lua" >"$tmp/nearest.lua"

rb() {  # scene output.png threads args... ; prints "render_s photon_s emitted"
  local lua=$1 png=$2 n=$3; shift 3
  (cd "$root" && "$rt" --quiet --stats --threads "$n" --size "$size" --output "$png" "$@" "$lua" 2>&1) |
    awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
         $1 == "photons" { e = $2 * $5; p = $(NF - 1)  # "photons  P passes of N in S s; ..."
                           for (i = 2; i < NF; i++) if ($i == "in" && $(i + 2) ~ /^s/) p = $(i + 1) }
         END { if (r == "") exit 1; print r, p, e }'
}
pv() {  # count output.png threads ; prints "photon_s+trace_s photon_s shot"
  (cd "$tmp" && povray +I"$pov" +O"$2" +W"${size%x*}" +H"${size#*x}" -D -GR -A +WT"$3" \
       File_Gamma=1.0 Declare=InverseSquare=2.25 Declare=Photons="$1" 2>&1) |
    awk 'function secs(s) { sub(/.*\(/, "", s); sub(/ seconds.*/, "", s); return s + 0 }
         /Photon Time:/ { p = secs($0) } /Trace Time:/ { t = secs($0) }
         /Number of photons shot:/ { n = $NF }
         END { if (t == "") exit 1; printf "%.4f %.4f %d\n", p + t, p, n }'
}

echo "caustics_vs_povray: references ($size, $(nproc) threads)" >&2
rb "$tmp/caustics.lua" "$tmp/rb-ref.png" "$(nproc)" --seed 7 --photons 200000 --photon-passes 256 --photon-radius 0.01 >/dev/null
pv 20480000 "$tmp/pv-ref.png" "$(nproc)" >/dev/null

rbn=(1 2 4 8 16 32 64 128 256)
knn=(20000 80000 320000 1280000 5120000)
pvn=(5000 20000 80000 320000 1280000 5120000)
declare -A best rmses extra
keep() {  # key seconds photon_seconds: keep the fastest run's two times
  [ -n "$2" ] || { echo "caustics_vs_povray: no time for $1 (a render failed)" >&2; exit 1; }
  if [ -z "${best[$1]:-}" ] || awk -v a="$2" -v b="${best[$1]% *}" 'BEGIN { exit !(a < b) }'; then
    best[$1]="$2 $3"
  fi
}
# Each round runs every raybook point, then every POV-Ray point, so both renderers see the
# machine's load over the same minutes.
for round in $(seq "$rounds"); do
  echo "caustics_vs_povray: round $round of $rounds" >&2
  for n in "${knn[@]}"; do
    read -r t p e <<<"$(rb "$tmp/nearest.lua" "$tmp/img.png" "$threads" --seed 1 --photons "$n" --photon-passes 1)"
    keep "kn$n" "$t" "$p"
    if [ "$round" = 1 ]; then rmses[kn$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/rb-ref.png"); extra[kn$n]=$e; fi
  done
  for n in "${rbn[@]}"; do
    read -r t p e <<<"$(rb "$tmp/caustics.lua" "$tmp/img.png" "$threads" --seed 1 --photon-passes "$n")"
    keep "rb$n" "$t" "$p"
    if [ "$round" = 1 ]; then rmses[rb$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/rb-ref.png"); extra[rb$n]=$e; fi
  done
  for n in "${pvn[@]}"; do
    read -r t p shot <<<"$(pv "$n" "$tmp/img.png" "$threads")"
    keep "pv$n" "$t" "$p"
    if [ "$round" = 1 ]; then rmses[pv$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/pv-ref.png"); extra[pv$n]=$shot; fi
  done
done
dat=$out/povray.dat
{
  echo "# caustics at $size, $threads thread(s): renderer quality seconds rmse photons photon_seconds"
  echo "# nearest: raybook, quality = photons in one pass, k = 50 nearest (classic); photons emitted"
  for n in "${knn[@]}"; do read -r t p <<<"${best[kn$n]}"; echo "nearest $n $t ${rmses[kn$n]} ${extra[kn$n]} $p"; done
  echo; echo
  echo "# raybook: quality = passes of 20000 photons (progressive, the chapter's defaults); photons emitted"
  for n in "${rbn[@]}"; do read -r t p <<<"${best[rb$n]}"; echo "raybook $n $t ${rmses[rb$n]} ${extra[rb$n]} $p"; done
  echo; echo
  echo "# povray: quality = photons { count N }; photons shot (POV-Ray's count is approximate)"
  for n in "${pvn[@]}"; do read -r t p <<<"${best[pv$n]}"; echo "povray $n $t ${rmses[pv$n]} ${extra[pv$n]} $p"; done
} >"$dat"

python3 - "$dat" "$size" "$threads" "$rounds" <<'PY'
import math, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
def points(name):
    return [(float(r[3]), float(r[2]), int(r[1]), int(float(r[4])), float(r[5])) for r in rows if r[0] == name]
kn, rb, pv = points("nearest"), points("raybook"), points("povray")
size, threads, rounds = sys.argv[2], sys.argv[3], sys.argv[4]
print(f"Caustics of the chapter scene (gr.photons{{indirect = false}}, inverse-square light) at {size}, "
      f"{threads} thread(s), against POV-Ray 3.7's photons (tests/perf/povray/chapter16-caustics.pov); "
      f"each renderer's RMSE against its own converged reference; fastest of {rounds} rounds.")
print()
print("| POV-Ray count | photons shot | Photon Time s | Photon + Trace Time s | RMSE |")
print("|---:|---:|---:|---:|---:|")
for e, t, n, shot, ps in pv:
    print(f"| {n:,} | {shot:,} | {ps:.3f} | {t:.3f} | {e:.5f} |")
print()
print("| raybook, k = 50 nearest, 1 pass of | photon pass s | render s | RMSE |")
print("|---:|---:|---:|---:|")
for e, t, n, photons, ps in kn:
    print(f"| {photons:,} photons | {ps:.3f} | {t:.3f} | {e:.5f} |")
print()
print("| raybook defaults (progressive), passes | photons emitted | photon passes s | render s | RMSE |")
print("|---:|---:|---:|---:|---:|")
for e, t, n, photons, ps in rb:
    print(f"| {n} | {photons:,} | {ps:.3f} | {t:.3f} | {e:.5f} |")
def time_at(points, e):
    pts = sorted(points)  # by error
    for a, b in zip(pts, pts[1:]):
        if a[0] <= e <= b[0] and a[0] > 0 and b[0] > a[0]:
            f = (math.log(e) - math.log(a[0])) / (math.log(b[0]) - math.log(a[0]))
            return math.exp(math.log(a[1]) + f * (math.log(b[1]) - math.log(a[1])))
    return None
def median(v):
    v = sorted(v)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])
print()
print("Equal error: each raybook series' time interpolated (log-log) at each POV-Ray point's RMSE; "
      "ratio = raybook / POV-Ray (below 1: raybook is faster; - where the POV-Ray point's RMSE lies "
      "outside the series' range).")
print()
print("| POV-Ray count | RMSE | POV-Ray s | raybook k = 50 s | ratio | raybook defaults s | ratio |")
print("|---:|---:|---:|---:|---:|---:|---:|")
ratios = {"k": [], "p": []}
for e, t, n, _, _ in pv:
    cells = []
    for key, series in (("k", kn), ("p", rb)):
        tr = time_at(series, e)
        if tr is None:
            cells += ["-", "-"]
        else:
            ratios[key].append(tr / t)
            cells += [f"{tr:.3f}", f"**{tr / t:.2f}**"]
    print(f"| {n:,} | {e:.5f} | {t:.3f} | " + " | ".join(cells) + " |")
print()
def span(series):
    return f"{min(p[0] for p in series):.4f} to {max(p[0] for p in series):.4f}"
for key, label, series in (("k", "raybook with POV-Ray's method (k = 50 nearest, one pass)", kn),
                           ("p", "raybook's defaults (progressive)", rb)):
    if ratios[key]:
        print(f"- **{label}: median ratio {median(ratios[key]):.2f}** over {len(ratios[key])} POV-Ray "
              f"points (its RMSE spans {span(series)})")
    else:
        print(f"- {label}: no POV-Ray point within its RMSE range ({span(series)}), no ratio")
print()
print("What differs: POV-Ray splits a photon at glass into a reflected and a refracted one, each "
      "weighted by Fresnel, where raybook follows one of the two (Russian roulette); POV-Ray's "
      "gather takes the 20 to 100 nearest photons within an adaptive radius, raybook's k = 50 "
      "nearest within 3 pixel footprints, and its default, progressive method every photon within "
      "a radius that shrinks by alpha per pass, whatever the photon count, which is why its error "
      "falls slowly (see ch16-convergence); POV-Ray's count is a target (it reports the photons it "
      "shot). The chapter's light has no falloff, which POV-Ray keeps along the whole photon path "
      "and raybook only up to the first surface, so both run an inverse-square light here (see the "
      "script's comments). In the two converged pictures the caustic light on the back and side "
      "walls differs by 10 to 16% (POV-Ray's darker; measured when this script was written).")
print()
print("Each reference has an error of its own (raybook's about 0.005, as ch16-convergence estimates "
      "for the same kind of reference; POV-Ray's has 4 times the photons of its largest point), so "
      "the points below RMSE 0.01 are the least certain.")
print()
for key, name in (("k", "caustics_povray"), ("p", "caustics_povray_progressive")):
    if ratios[key]:
        print(f"target {name} {median(ratios[key]):.2f}")
PY
