#!/usr/bin/env bash
# Fog and a light shaft, and the chapter's smoke plume, against POV-Ray 3.7's media, at equal
# error.
#
# usage: tests/perf/ch17/media_vs_povray.sh BUILD_DIR OUT_DIR
#   MEDIA_SIZE=WxH    image size (default 160x120)
#   MEDIA_THREADS=N   threads for both renderers' measured runs (default 1)
#   MEDIA_ROUNDS=N    timed rounds, the fastest run of each point kept (default 3)
#   PLUME_SIZE=WxH    the plume's image size (default 96x96, as tests/perf/ch17/charts.sh)
#   PLUME_REFERENCE=N renders averaged for raybook's plume reference (default 2048)
#   MEDIA_PLUME=no    leave the plume out (the shaft alone)
#   MEDIA_RB_ARGS=... options for raybook's measured runs, not its references (to compare
#                     settings, e.g. --media-points=4)
# Writes OUT_DIR/povray.dat and OUT_DIR/plume.dat (renderer, quality, seconds, RMSE) and prints
# Markdown: the renderers' points, the ratio raybook/POV-Ray of render time at equal error;
# last, the "target NAME RATIO" lines for make bench.
#
# The scenes: tests/perf/ch17/shaft.lua (--media-bounces=0: single scattering) and
# tests/perf/povray/chapter17-media.pov (its comments say how the geometry, the light, the
# finish and the fog translate, and how the two phase functions were matched: converged, the
# two pictures' means agree within 3%). Homogeneous fog, because POV-Ray reads no VDB file.
# Both render without antialiasing (POV-Ray -A; raybook --aa=none); both write linear colour
# (POV-Ray with File_Gamma=1.0), 8 bits. raybook's N samples per pixel spread over the pixel (a
# 1-sample and a 1024-sample render differ at the edges), so series (2) below pays pixel noise
# that POV-Ray's one ray per pixel centre does not; series (1) does not.
# Quality levels: POV-Ray, media method 3 (its default: one interval, adaptive, jitter 0.5)
# with samples N = 2 to 100. raybook, three series: (1) its default estimator at the pixel
# centres, as POV-Ray's -A: N = 1 to 64 renders of one sample each (seeds 1..N), averaged
# (tests/perf/ch17/average_png.py), the time their sum; (2) the same default with N = 1 to 256
# samples per pixel, jittered over the pixel (an antialiased picture: it also pays the noise of
# the shaft's and the floor's edges); (3) ray marching (--media=march), POV-Ray's kind of
# method: a step S from a jittered start, a shadow ray at every step, one sample per pixel,
# S = 0.4 down to 0.0125. Each renderer's error is its RMSE against its own converged
# reference: (1) against 256 one-sample renders with 64 lamp points per ray, (2) against 4096
# samples per pixel (seed 7), (3) marched at step 0.003 (1 sample per pixel); POV-Ray's at
# samples 2000. Times: raybook's render phase (--stats), POV-Ray's Trace Time. The targets
# printed last: media_povray (series 1, like for like), media_povray_aa (series 2),
# media_povray_march (series 3) and media_povray_plume (below).
#
# The plume: tests/perf/ch17/plume.lua (a heterogeneous NanoVDB density) against
# tests/perf/povray/chapter17-plume.pov, whose comments say how it translates and how the two
# converged pictures agree (means within 0.5%). POV-Ray reads no VDB file, so ch17_vdb_df3
# (tests/perf/ch17/vdb_df3.cpp; built when NanoVDB is found) first writes the density as raybook
# reads it into a df3 file, on the same trilinear samples. Only series (1), like for like: N = 1
# to 256 renders of one sample at the pixel centres, averaged, against PLUME_REFERENCE (default
# 2048) such renders at 64 lamp points (on the plume 64 points hardly lower a render's noise,
# which is the camera rays' delta tracking: 256 renders left the reference an own error of
# 0.0057, half the 64-render point's RMSE; 2048 take about 3 minutes, most of it starting
# processes); POV-Ray with samples N = 2 to 100 against samples 500 (on the plume POV-Ray's
# shadow rays sample the media too, so its time grows about as N^1.8: samples 500 took 86 s on
# 2 threads, 2000 would take about 17 minutes). Printed as "target media_povray_plume RATIO".
# Since the grid's transmittance is integrated exactly (--media-shadows=exact), one render's
# error is below POV-Ray's at 100 samples, so a second series, N = 1 to 64 lamp points in one
# render at the pixel centres (as on the shaft), meets POV-Ray's errors: "target
# media_povray_plume_points RATIO".
# Without NanoVDB (no ch17_vdb_df3) the plume is left out, with a note.
set -euo pipefail
build=$(cd "${1:?usage: media_vs_povray.sh BUILD_DIR OUT_DIR}" && pwd)
out=${2:?usage: media_vs_povray.sh BUILD_DIR OUT_DIR}
mkdir -p "$out"
out=$(cd "$out" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
size=${MEDIA_SIZE:-160x120}
threads=${MEDIA_THREADS:-1}
rounds=${MEDIA_ROUNDS:-3}
rt=$build/rt_ch17
rmse=$build/tests/perf/ch08/ch08_aa_charts
df3=$build/tests/perf/ch17/ch17_vdb_df3
shaft=(tests/perf/ch17/shaft.lua "$root/tests/perf/povray/chapter17-media.pov" "$size")
plume=(tests/perf/ch17/plume.lua "$root/tests/perf/povray/chapter17-plume.pov" "${PLUME_SIZE:-96x96}")
use() {  # scene .pov size: what rb and pv render
  scene=$1 pov=$2 size=$3
}
use "${shaft[@]}"
command -v povray >/dev/null || { echo "media_vs_povray: povray is not installed (make bench installs it)"; exit 1; }
[ -x "$rt" ] || { echo "media_vs_povray: $rt not built"; exit 1; }
[ -x "$rmse" ] || { echo "media_vs_povray: $rmse not built"; exit 1; }
plume_on=yes
[ -x "$df3" ] || { plume_on=; echo "media_vs_povray: $df3 not built (no NanoVDB: make deps); no plume" >&2; }
[ "${MEDIA_PLUME:-yes}" != no ] || plume_on=
read -r -a rb_args <<<"${MEDIA_RB_ARGS:-}"
measured() {  # rb's arguments with MEDIA_RB_ARGS before the run's own
  local png=$1 n=$2; shift 2
  rb "$png" "$n" ${rb_args[@]+"${rb_args[@]}"} "$@"
}
tmp=$(mktemp -d /tmp/raybook-media.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

rb() {  # output.png threads args... ; prints the render seconds
  local png=$1 n=$2; shift 2
  (cd "$root" && "$rt" --quiet --stats --threads "$n" --size "$size" --aa=none --media-bounces=0 \
       --output "$png" "$@" "$scene" 2>&1) |
    awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
         END { if (r == "") exit 1; print r }'
}
pv() {  # samples output.png threads ; prints the Trace Time
  (cd "$tmp" && povray +I"$pov" +O"$2" +W"${size%x*}" +H"${size#*x}" -D -GR -A +WT"$3" \
       File_Gamma=1.0 Declare=Samples="$1" 2>&1) |
    awk '/Trace Time:/ { t = $0; sub(/.*\(/, "", t); sub(/ seconds.*/, "", t) }
         END { if (t == "") exit 1; print t }'
}

average=$root/tests/perf/ch17/average_png.py
centre_reference() {  # out.png count: count renders of one sample each, 64 lamp points per ray,
  # averaged. Prints the average's own error: its two halves' averages differ by twice that.
  local i half=$(($2 / 2))
  for i in $(seq "$2"); do
    rb "$tmp/ref-$i.png" "$(nproc)" --seed $((1000 + i)) --spp 1 --media-points=64 >/dev/null
  done
  python3 "$average" "$1" $(seq -f "$tmp/ref-%g.png" "$2")
  python3 "$average" "$tmp/half-1.png" $(seq -f "$tmp/ref-%g.png" "$half")
  python3 "$average" "$tmp/half-2.png" $(seq -f "$tmp/ref-%g.png" $((half + 1)) "$2")
  "$rmse" rmse "$tmp/half-1.png" "$tmp/half-2.png" | awk '{ printf "%.5f\n", $1 / 2 }'
  rm -f "$tmp"/ref-*.png "$tmp"/half-*.png
}
echo "media_vs_povray: references ($size, $(nproc) threads)" >&2
rb "$tmp/rb-ref.png" "$(nproc)" --seed 7 --spp 4096 >/dev/null
rb "$tmp/mr-ref.png" "$(nproc)" --seed 7 --spp 1 --media=march --media-step=0.003 >/dev/null
pv 2000 "$tmp/pv-ref.png" "$(nproc)" >/dev/null
rc_error=$(centre_reference "$tmp/rc-ref.png" 256)
# The plume's: its density for POV-Ray (plume.df3, placed by plume.inc, read by pv in $tmp).
if [ -n "$plume_on" ]; then
  use "${plume[@]}"
  echo "media_vs_povray: the plume's references ($size, $(nproc) threads)" >&2
  (cd "$root" && "$df3" scenes/assets/plume.nvdb density "$tmp/plume.df3" "$tmp/plume.inc") >&2
  pv 500 "$tmp/pl-pv-ref.png" "$(nproc)" >/dev/null
  pl_renders=${PLUME_REFERENCE:-2048}
  pl_error=$(centre_reference "$tmp/pl-rc-ref.png" "$pl_renders")
  use "${shaft[@]}"
fi

rbn=(1 4 16 64 256)
rcn=(1 4 16 64)
rpn=(4 16 64 256 1024)
plume_rcn=(1 4 16 64 256)
plume_rpn=(1 2 4 16 64)
steps=(0.4 0.2 0.1 0.05 0.025 0.0125)
pvn=(2 5 10 20 50 100)
declare -A best rmses
keep() {  # key seconds: keep the fastest run
  [ -n "$2" ] || { echo "media_vs_povray: no time for $1 (a render failed)" >&2; exit 1; }
  if [ -z "${best[$1]:-}" ] || awk -v a="$2" -v b="${best[$1]}" 'BEGIN { exit !(a < b) }'; then best[$1]=$2; fi
}
centre_series() {  # key-prefix reference.png round counts...
  local key=$1 ref=$2 round=$3 n i t total
  shift 3
  for n in "$@"; do
    # N renders of one sample at the pixel centre (as POV-Ray's -A), seeds 1..N, averaged.
    total=0
    for i in $(seq "$n"); do
      t=$(measured "$tmp/rc-$i.png" "$threads" --seed "$i" --spp 1)
      total=$(awk -v a="$total" -v b="$t" 'BEGIN { print a + b }')
    done
    keep "$key$n" "$total"
    if [ "$round" = 1 ]; then
      python3 "$average" "$tmp/img.png" $(seq -f "$tmp/rc-%g.png" "$n")
      rmses[$key$n]=$("$rmse" rmse "$tmp/img.png" "$ref")
    fi
  done
}
povray_series() {  # key-prefix reference.png round
  for n in "${pvn[@]}"; do
    keep "$1$n" "$(pv "$n" "$tmp/img.png" "$threads")"
    if [ "$3" = 1 ]; then rmses[$1$n]=$("$rmse" rmse "$tmp/img.png" "$2"); fi
  done
}
# Each round runs every raybook point, then every POV-Ray point, so both renderers see the
# machine's load over the same minutes.
for round in $(seq "$rounds"); do
  echo "media_vs_povray: round $round of $rounds" >&2
  for n in "${rbn[@]}"; do
    keep "rb$n" "$(measured "$tmp/img.png" "$threads" --seed 1 --spp "$n")"
    [ "$round" = 1 ] && rmses[rb$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/rb-ref.png")
  done
  centre_series rc "$tmp/rc-ref.png" "$round" "${rcn[@]}"
  for n in "${rpn[@]}"; do
    # One render at the pixel centres with N lamp points per ray: POV-Ray's samples per ray.
    keep "rp$n" "$(measured "$tmp/img.png" "$threads" --seed 1 --spp 1 --media-points="$n")"
    [ "$round" = 1 ] && rmses[rp$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/rc-ref.png")
  done
  for s in "${steps[@]}"; do
    keep "mr$s" "$(rb "$tmp/img.png" "$threads" --seed 1 --spp 1 --media=march --media-step="$s")"
    [ "$round" = 1 ] && rmses[mr$s]=$("$rmse" rmse "$tmp/img.png" "$tmp/mr-ref.png")
  done
  povray_series pv "$tmp/pv-ref.png" "$round"
  [ -n "$plume_on" ] || continue
  use "${plume[@]}"
  centre_series pl-rc "$tmp/pl-rc-ref.png" "$round" "${plume_rcn[@]}"
  for n in "${plume_rpn[@]}"; do
    # One render at the pixel centres with N lamp points per ray, as on the shaft.
    keep "pl-rp$n" "$(measured "$tmp/img.png" "$threads" --seed 1 --spp 1 --media-points="$n")"
    [ "$round" = 1 ] && rmses[pl-rp$n]=$("$rmse" rmse "$tmp/img.png" "$tmp/pl-rc-ref.png")
  done
  povray_series pl-pv "$tmp/pl-pv-ref.png" "$round"
  use "${shaft[@]}"
done
series() {  # renderer key-prefix qualities...: a "renderer quality seconds rmse" line each
  local name=$1 key=$2 q; shift 2
  for q in "$@"; do echo "$name $q ${best[$key$q]} ${rmses[$key$q]}"; done
  echo; echo
}
dat=$out/povray.dat
centre="# centre: quality = renders of 1 sample at the pixel centre, averaged (the default estimator)"
{
  echo "# fog and a light shaft at $size, $threads thread(s): renderer quality seconds rmse"
  echo "# raybook: quality = samples per pixel (delta tracking, the default)"
  series raybook rb "${rbn[@]}"
  echo "# povray: quality = media samples (method 3)"
  series povray pv "${pvn[@]}"
  echo "# march: quality = step (raybook --media=march, 1 sample per pixel)"
  series march mr "${steps[@]}"
  echo "$centre"
  series centre rc "${rcn[@]}"
  echo "# points: quality = lamp points per ray, one render at the pixel centres"
  series points rp "${rpn[@]}"
} >"$dat"
rm -f "$out/plume.dat"
[ -z "$plume_on" ] || {
  echo "# the plume at ${plume[2]}, $threads thread(s): renderer quality seconds rmse"
  echo "# povray: quality = media samples (method 3)"
  series povray pl-pv "${pvn[@]}"
  echo "$centre"
  series centre pl-rc "${plume_rcn[@]}"
  echo "# points: quality = lamp points per ray, one render at the pixel centres"
  series points pl-rp "${plume_rpn[@]}"
} >"$out/plume.dat"

python3 - "$dat" "$out/plume.dat" "$size" "${plume[2]}" "$threads" "$rounds" "$rc_error" \
        "${pl_renders:-0}" "${pl_error:-0}" <<'PY'
import math, os, sys
def load(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    return lambda name: [(float(r[3]), float(r[2]), r[1]) for r in rows if r[0] == name]
points = load(sys.argv[1])
plume = load(sys.argv[2]) if os.path.exists(sys.argv[2]) else None
rb, pv, mr, rc = points("raybook"), points("povray"), points("march"), points("centre")
rp = points("points")
size, plume_size, threads, rounds, rc_error, pl_renders, pl_error = sys.argv[3:10]
def table(head, time, series):
    print()
    print(f"| {head} | {time} s | RMSE |")
    print("|---:|---:|---:|")
    for e, t, n in series:
        print(f"| {n} | {t:.3f} | {e:.5f} |")
def tables(pv, rc):
    """POV-Ray's points, then raybook's default at the pixel centres."""
    table("POV-Ray media samples", "Trace Time", pv)
    table("raybook's default, renders of 1 sample at the pixel centre, averaged", "render", rc)
print(f"Fog and a light shaft (tests/perf/ch17/shaft.lua, single scattering) at {size}, {threads} "
      f"thread(s), against POV-Ray 3.7's media (tests/perf/povray/chapter17-media.pov); each "
      f"renderer's RMSE against its own converged reference; fastest of {rounds} rounds. raybook's "
      f"pixel-centre reference (256 one-sample renders at 64 lamp points) has an error of its own "
      f"of about {rc_error} (its two halves' averages differ by twice that).")
tables(pv, rc)
table("raybook's default, one render at the pixel centres, lamp points per ray", "render", rp)
table("raybook's default, samples per pixel (jittered over the pixel)", "render", rb)
table("raybook, ray marching, step (1 sample per pixel)", "render", mr)
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
def span(series):
    return f"{min(p[0] for p in series):.4f} to {max(p[0] for p in series):.4f}"
def equal_error(pv, columns):
    """The equal-error table of POV-Ray's points against each (key, heading, label, series);
    prints it and each series' median ratio, and returns the ratios by key."""
    print()
    print("Equal error: each raybook series' time interpolated (log-log) at each POV-Ray point's "
          "RMSE; ratio = raybook / POV-Ray (below 1: raybook is faster; - where the POV-Ray "
          "point's RMSE lies outside the series' range).")
    print()
    print("| POV-Ray samples | RMSE | POV-Ray s | " +
          " | ".join(f"{heading} s | ratio" for _, heading, _, _ in columns) + " |")
    print("|---:|---:|---:|" + "---:|---:|" * len(columns))
    ratios = {key: [] for key, _, _, _ in columns}
    for e, t, n in pv:
        cells = []
        for key, _, _, series in columns:
            tr = time_at(series, e)
            if tr is None:
                cells += ["-", "-"]
            else:
                ratios[key].append(tr / t)
                cells += [f"{tr:.3f}", f"**{tr / t:.2f}**"]
        print(f"| {n} | {e:.5f} | {t:.3f} | " + " | ".join(cells) + " |")
    print()
    for key, _, label, series in columns:
        if ratios[key]:
            print(f"- **{label}: median ratio {median(ratios[key]):.2f}** over {len(ratios[key])} "
                  f"POV-Ray points (its RMSE spans {span(series)})")
        else:
            print(f"- {label}: no POV-Ray point within its RMSE range ({span(series)}), no ratio")
    return ratios
ratios = equal_error(pv, [
    ("c", "raybook pixel centres", "raybook's default at the pixel centres (as POV-Ray's -A)", rc),
    ("n", "raybook points", "raybook's default at the pixel centres, N lamp points per ray (as POV-Ray's N samples)", rp),
    ("d", "raybook jittered", "raybook's default, N samples jittered over the pixel (antialiased)", rb),
    ("m", "raybook marching", "raybook's ray marching (POV-Ray's kind of method)", mr)])
print()
print("What differs: POV-Ray's method 3 places its samples along each camera ray's stretch of fog "
      "(jittered, adaptively refined where neighbouring samples differ) and lights every one, as "
      "raybook's ray marching does at a fixed step. raybook's default draws, per pixel, "
      "--media-points (64) stratified lamp points along its rays and one forced free flight, weighted by MIS; the "
      "floor behind the fog is seen through the closed-form transmittance. POV-Ray's -A traces one "
      "ray through each pixel centre: the pixel-centre series does the same (N one-sample renders "
      "with their own seeds, averaged, against 256 such renders at 64 lamp points), while the "
      "jittered series spreads its samples over the pixel and so also pays the noise of the "
      "antialiased edges. raybook's marching series is measured against its own reference "
      "marched at step 0.003. Each reference has an error of its own, so points near the smallest "
      "errors are the least certain.")
if plume:
    prc, ppv, prp = plume("centre"), plume("povray"), plume("points")
    print()
    print()
    print(f"The chapter's smoke plume (tests/perf/ch17/plume.lua: a NanoVDB density, sigma_s 30, "
          f"sigma_a 3, g 0.2; single scattering) at {plume_size}, {threads} thread(s), against "
          f"tests/perf/povray/chapter17-plume.pov, the same density written for POV-Ray as a df3 "
          f"file (ch17_vdb_df3); each renderer's RMSE against its own converged reference "
          f"(raybook: {pl_renders} one-sample renders at 64 lamp points, whose own error is about "
          f"{pl_error}, from its two halves; POV-Ray: samples 500); fastest of {rounds} rounds.")
    tables(ppv, prc)
    table("raybook's default, one render at the pixel centres, lamp points per ray", "render",
          prp)
    ratios.update(equal_error(ppv, [
        ("p", "raybook pixel centres", "the plume, raybook's default at the pixel centres", prc),
        ("q", "raybook points", "the plume, N lamp points in one render at the pixel centres",
         prp)]))
print()
for key, name in (("c", "media_povray"), ("n", "media_povray_points"), ("d", "media_povray_aa"),
                  ("m", "media_povray_march"), ("p", "media_povray_plume"),
                  ("q", "media_povray_plume_points")):
    if ratios.get(key):
        print(f"target {name} {median(ratios[key]):.2f}")
PY
