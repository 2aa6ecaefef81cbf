#!/usr/bin/env bash
# Chapter 13's charts, into docs/charts/:
#   ch13-samples.svg/.png   RMSE of the chapter scene against rays per pixel, for lens samples
#                           paired with jittered pixel positions, with random pixel positions,
#                           and with every ray through the pixel centre
#   ch13-povray.svg/.png    raybook's lens against POV-Ray's focal blur: RMSE against time
#   ch13-finding.txt        the samples finding in one sentence, with numbers (\include{doc})
#   ch13-povray.txt         the POV-Ray table and the ratio at equal error (\include{doc})
#
# usage: tests/perf/ch13/charts.sh BUILD_DIR   (takes a few minutes; the POV-Ray chart is
# skipped, with a note, when povray is not installed)
# The reference is the scene at 4096 rays per pixel (jittered, paired lens), seed 99, apart
# from the measured runs' seed 1; its own RMSE is about 1/64 of a 1-ray render's.
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch13
mkdir -p "$charts" "$data"
rt=$build/rt_ch13
rmse=$build/tests/perf/ch08/ch08_aa_charts
[[ -x $rt && -x $rmse ]] || { echo "charts.sh: $rt or $rmse not built" >&2; exit 2; }
scene=scenes/chapter13-depth-of-field.lua

run() {  # out.png args... ; prints the render seconds
    local png=$1; shift
    (cd "$root" && "$rt" --quiet --stats --features=all --output "$png" "$@" "$scene" 2>&1) |
        awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") print $i }'
}
run "$data/ref.png" --aa=jittered --spp 4096 --dof-samples 4096 --seed 99 >/dev/null
{
    echo "# chapter 13 scene: rays per pixel, render s, RMSE against the 4096-ray reference"
    for series in paired random centre; do
        echo "# $series"
        for n in 1 4 16 64 256; do
            case $series in
                paired) args=(--aa=jittered --spp "$n" --dof-samples "$n") ;;
                random) args=(--aa=random --spp "$n" --dof-samples "$n") ;;
                centre) args=(--aa=none --dof-samples "$n") ;;
            esac
            t=$(run "$data/img.png" --seed 1 "${args[@]}")
            echo "$n $t $("$rmse" rmse "$data/img.png" "$data/ref.png")"
        done
        echo; echo
    done
} >"$data/samples.dat"

# The finding: the paired series' slope (log RMSE against log rays, 16 to 256) and the errors
# at 16 rays.
python3 - "$data/samples.dat" >"$charts/ch13-finding.txt" <<'PY'
import math, sys
blocks = open(sys.argv[1]).read().split("\n\n\n")
series = {}
for b in blocks:
    lines = [l for l in b.strip().split("\n") if l]
    if not lines:
        continue
    name = lines[1][2:] if lines[0].startswith("# chapter") else lines[0][2:]
    series[name] = {int(l.split()[0]): float(l.split()[2]) for l in lines if not l.startswith("#")}
p, r, c = series["paired"], series["random"], series["centre"]
slope = math.log(p[256] / p[16]) / math.log(256 / 16)
print(f"With lens samples paired one-to-one with jittered pixel positions, the chapter scene's "
      f"RMSE falls from {p[1]:.4f} at 1 ray per pixel to {p[16]:.4f} at 16 and {p[256]:.4f} at 256 "
      f"(slope {slope:.2f} from 16 to 256; 1/sqrt(N) is -0.5); random pixel positions with the "
      f"same lens strata give {r[16]:.4f} at 16 rays, and every ray through the pixel centre "
      f"stalls at {c[256]:.4f} (its aliasing never averages away).")
PY

draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

# The 1-ray error of the paired series, for a 1/sqrt(N) guide line.
e1=$(awk '!/^#/ && NF { print $3; exit }' "$data/samples.dat")
draw ch13-samples "
set title 'Depth-of-field error against rays (chapter scene, 192x128)'
set xlabel 'camera rays per pixel (= lens samples)'
set ylabel 'RMSE against 4096 rays per pixel'
set logscale xy
set grid
set key bottom left
plot '$data/samples.dat' index 0 using 1:3 with linespoints pt 7 lw 2 title 'lens strata paired with jittered pixel positions', \
     '' index 1 using 1:3 with linespoints pt 5 title 'lens strata with random pixel positions', \
     '' index 2 using 1:3 with linespoints pt 6 title 'lens strata, every ray through the pixel centre', \
     [1:256] $e1 / sqrt(x) with lines dt 2 lc rgb 'gray' title '1/sqrt(N) from 1 ray'
"

if command -v povray >/dev/null; then
    bash "$root/tests/perf/ch13/dof_vs_povray.sh" "$build" "$data" | tee "$data/povray.txt"
    cp "$data/povray.txt" "$charts/ch13-povray.txt"
    draw ch13-povray "
set title 'Depth of field against POV-Ray focal blur (dof scene, 128x128, 1 thread)'
set xlabel 'render time (s): raybook render phase, POV-Ray Trace Time'
set ylabel 'RMSE against own converged reference'
set logscale xy
set grid
set key top right
plot '$data/povray.dat' index 0 using 3:4 with linespoints pt 7 title 'raybook, N lens samples paired with N jittered pixel positions', \
     '' index 0 using 3:4:2 with labels offset char 0,1 font ',9' notitle, \
     '' index 1 every ::0::5 using 3:4 with linespoints pt 5 title 'POV-Ray blur_samples N, N (dof64.pov: N = 64)' noenhanced, \
     '' index 1 every ::0::5 using 3:4:2 with labels offset char 0,-1 font ',9' notitle, \
     '' index 1 every ::6::6 using 3:4 with points pt 13 ps 1.8 lc rgb '#d33' title 'POV-Ray dof.pov (adaptive stop, up to 64)'
"
else
    echo "charts: povray is not installed; ch13-povray not redrawn (make charts installs it)"
fi

echo "chapter 13 charts: $(cat "$charts/ch13-finding.txt")"
