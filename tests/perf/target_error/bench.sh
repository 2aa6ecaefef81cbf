#!/usr/bin/env bash
# Issue 38's benchmark: rendering to a target error (--target-error E) against uniform sampling
# (--spp N) at equal error, on nine scenes; a chart per scene and one Markdown table.
#
# usage: tests/perf/target_error/bench.sh BUILD_DIR [OUT_DIR]
#   OUT_DIR              where target-error-<scene>.svg and target-error.md go
#                        (default: docs/charts; make bench passes BUILD_DIR/bench/target-error)
#   TARGET_ERROR_SCENES  an extended regular expression: only the scenes whose name matches
#                        (a partial run, for trying it out; use an OUT_DIR outside docs/)
#   TARGET_ERROR_TIGHTEN F  one more target per scene, F times its smallest (0 < F < 1), and the
#                        reference at a quarter of that: the ratio at a tighter error, for 16/F²
#                        times the tightest render's cost in the reference
# About 8 minutes on 2 idle cores. Needs BUILD_DIR/rt_ch18 and python3 (no imaging package).
#
# Per scene, all with --threads 2, at a small size, written as .hdr (linear radiance):
#   1. a reference: --target-error at a quarter of the scene's smallest E, --seed 99; its own
#      error is the estimate its --stats reports;
#   2. uniform sampling at 3-4 --spp counts and adaptive sampling at 3-4 --target-error values,
#      --seed 1; time is the "render X s" of --stats (photon passes included), one run each.
# Then equal_error.py measures each render against the reference (RMS over every channel of
# every pixel, the reference's reported error taken off in quadrature), reads uniform
# sampling's time at each adaptive render's error off a log-log fit, and writes the table and
# the charts. Raw runs go to BUILD_DIR/bench/target-error/runs.tsv, images beside it.
set -euo pipefail
build=$(cd "${1:?usage: bench.sh BUILD_DIR [OUT_DIR]}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
outdir=${2:-$root/docs/charts}
rt=$build/rt_ch18
data=$build/bench/target-error
[ -x "$rt" ] || { echo "target-error bench: $rt is not built" >&2; exit 1; }
mkdir -p "$data" "$outdir"

# ---- The scenes ----------------------------------------------------------------------------
# One line per scene, fields separated by |:
#   scene file | size | uniform --spp counts | --target-error values (largest first) |
#   arguments for every render of the scene | arguments for the uniform renders only
# Each scene's largest E was about the error of the floor alone when the whole pilot was set
# aside; the floor (4 planning samples set aside, 8 kept, 2 fresh) may reach the first one, and
# that row shows what the floor costs. The sizes keep the whole run near 8 minutes: the
# reference at
# a quarter of the smallest E costs 16 times that render. Scenes whose sampler wants n x n rays
# get square counts; the uniform counts are at least the scene's lens samples (chapter 13: 16,
# the bathhouse: 10, the garage: 9), which --spp cannot go below. The bathhouse keeps its
# full-size (320 x 240) caustic gather radius: the default is 3 pixel footprints, at 64 x 48 a
# disk 25 times the area, and 25 times the gathering. Seed 002's adaptive antialiasing ignores
# --spp, so its uniform renders use the jittered sampler.
scenes=(
  "scenes/chapter06-soft-shadows.lua   | 96x72  | 4 16 64     | 0.007 0.005 0.0035          | |"
  "scenes/chapter07-glossy.lua         | 96x72  | 4 16 64     | 0.034 0.024 0.017 0.012     | |"
  "scenes/chapter13-depth-of-field.lua | 120x80 | 16 64 256 1024 | 0.06 0.03 0.015 0.0075      | |"
  "scenes/chapter16-photon-mapping.lua | 40x40  | 4 12 36     | 0.026 0.021 0.017           | |"
  "scenes/chapter17-media.lua          | 128x96 | 4 16 64 256 | 0.04 0.025 0.015 0.01       | |"
  "scenes/chapter18-path-tracing.lua   | 80x80  | 4 16 64 256 | 0.1 0.05 0.03 0.02          | |"
  "scenes/seeds/000-bathhouse.lua      | 64x48  | 16 36 100   | 0.03 0.021 0.015 0.0105     | --photon-radius 0.0929 |"
  "scenes/seeds/001-garage.lua         | 128x96 | 9 36 144    | 0.0145 0.01 0.007 0.005     | |"
  "scenes/seeds/002-desk.lua           | 88x66  | 4 16 64     | 0.0125 0.009 0.0063 0.0045  | | --aa=jittered"
)
reference_seed=99
seed=1

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; echo "${s%"${s##*[![:space:]]}"}"; }

# Render once; print "render_seconds reported_error mean_spp max_spp" from --stats (- for the
# error and the maximum when the render had no target; its mean is then its camera rays over
# its pixels, since a scene's lens samples can raise --spp).
render() {  # scene size image [args...]
  local scene=$1 size=$2 image=$3 log
  shift 3
  if ! log=$(cd "$root" && "$rt" --quiet --stats --threads 2 --size "$size" --output "$image" "$@" "$scene" 2>&1); then
    echo "target-error bench: $rt failed on $scene $*:" >&2; echo "$log" >&2; exit 1
  fi
  awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
       $1 == "samples" && $2 == "mean" { m = $3; sub(/,/, "", m); x = $5; e = $NF }
       $1 == "rays" && $2 == "camera" { c = $3 }
       END { if (r == "") exit 1; split(size, wh, "x")
             print r, (e == "" ? "-" : e), (m == "" ? c / (wh[1] * wh[2]) : m), (x == "" ? "-" : x) }' \
         size="$size" <<<"$log" ||
    { echo "target-error bench: no render time in the output of $rt $scene" >&2; exit 1; }
}

# Render and append one line to runs.tsv: scene size kind setting seconds reported mean max
# image.
record() {  # name scene size kind setting [args...]
  local name=$1 scene=$2 size=$3 kind=$4 setting=$5 image seconds reported mean max
  shift 5
  image=$data/$name-$kind-$setting.hdr
  read -r seconds reported mean max < <(render "$scene" "$size" "$image" "$@")
  [[ $kind != uniform || $mean == "$setting" ]] ||
    echo "target-error bench: $name took $mean samples a pixel for --spp $setting" >&2
  printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$name" "$size" "$kind" "$setting" "$seconds" \
    "$reported" "$mean" "$max" "$image" >>"$runs"
  printf "target-error bench: %-24s %-9s %-7s %8s s  reported %s\n" "$name" "$kind" "$setting" \
    "$seconds" "$reported" >&2
}

# A quarter of the smallest of the values given.
quarter() { printf "%s\n" "$@" | sort -g | head -1 | awk '{ printf "%.6g", $1 / 4 }'; }

# The command as it was given, for the table (nice's niceness too, when above 0).
command_line() {
  local prefix="" rel=${1#"$root"/}
  [ "$(nice)" -gt 0 ] && prefix="nice -n $(nice) "
  echo "${prefix}bash tests/perf/target_error/bench.sh $rel${2:+ ${2#"$root"/}}"
}

runs=$data/runs.tsv
printf "# scene\tsize\tkind\tsetting\tseconds\treported\tmean_spp\tmax_spp\timage\n" >"$runs"
start=$(date +%s)
for entry in "${scenes[@]}"; do
  IFS='|' read -r scene size spps errors args uargs <<<"$entry"
  scene=$(trim "$scene"); size=$(trim "$size"); args=$(trim "$args"); uargs=$(trim "$uargs")
  name=$(basename "$scene" .lua)
  [[ -z ${TARGET_ERROR_SCENES:-} || $name =~ $TARGET_ERROR_SCENES ]] || continue
  if [[ -n ${TARGET_ERROR_TIGHTEN:-} ]]; then
    # shellcheck disable=SC2086  # the list is meant to split
    errors="$errors $(printf "%s\n" $errors | sort -g | head -1 |
      awk -v f="$TARGET_ERROR_TIGHTEN" '{ printf "%.6g", $1 * f }')"
  fi
  # shellcheck disable=SC2086  # the lists and arguments are meant to split
  {
    record "$name" "$scene" "$size" reference "$(quarter $errors)" $args \
      --target-error "$(quarter $errors)" --seed "$reference_seed"
    for n in $spps; do record "$name" "$scene" "$size" uniform "$n" $args $uargs --spp "$n" --seed "$seed"; done
    for e in $errors; do record "$name" "$scene" "$size" adaptive "$e" $args --target-error "$e" --seed "$seed"; done
  }
done
echo "target-error bench: renders took $(($(date +%s) - start)) s" >&2

python3 -B "$root/tests/perf/target_error/equal_error.py" "$runs" "$outdir" "$outdir/target-error.md" \
  "$(command_line "$1" "${2:-}")"
echo "target-error bench: charts and table in $outdir (target-error*.svg, target-error.md); $(($(date +%s) - start)) s in all" >&2
