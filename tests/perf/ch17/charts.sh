#!/usr/bin/env bash
# Chapter 17's charts, into docs/charts/:
#   ch17-convergence.svg/.png  RMSE of a single-scattering plume against render time: the
#                              default (transmittance integrated exactly through the voxels),
#                              ratio and delta tracking, and ray marching at four step sizes,
#                              each at 1, 4, 9, 16, ... samples per pixel (squares: the jittered sampler)
#   ch17-convergence.txt       the same points as a Markdown table (\include{doc})
#   ch17-finding.txt           the finding in one sentence, with numbers (\include{doc})
#   ch17-majorant.svg/.png     null collisions per real collision, and time per free flight,
#                              against the majorant grid's resolution (ch17_majorant)
#   ch17-majorant.txt          ch17_majorant's table
#   ch17-povray.svg/.png       raybook's media against POV-Ray 3.7's: RMSE against time
#   ch17-povray.txt            the POV-Ray tables and the ratio at equal error, Markdown
#
# usage: tests/perf/ch17/charts.sh BUILD_DIR   (about 6 minutes on 2 idle cores; the POV-Ray chart
# is skipped, with a note, when povray is not installed)
#   CH17_ROUNDS=N   timed rounds per point, the fastest kept (default 3)
#   CH17_CHARTS="convergence majorant povray"   the charts to draw (default: all three)
#
# The scene: tests/perf/ch17/plume.lua, the chapter's VDB plume (scenes/assets/plume.nvdb,
# sigma_s 30, sigma_a 3, g 0.2, scaled 1.1) in a group node over a grey floor, one point light
# without falloff, 96x96, a jittered sampler, --media-bounces=0 (single scattering), so all the
# methods estimate the same image: the light scattered once in the smoke towards the camera, and
# the smoke's shadow on the floor. In the first three series a camera ray takes its single
# scattering at lamp points read off one pass through the smoke (chapter 17, "Where to look for
# single scattering", change 4); what they change is how a transmittance is estimated:
#   default  --media-shadows=exact (the default): integrated exactly through the voxel grid;
#   ratio  --media-shadows=ratio: by ratio tracking;
#   delta  --media-shadows=delta: by delta tracking (0 or 1);
#   march  --media=march --media-step=S: a fixed step S from a jittered start along camera rays,
#          a shadow ray (marched with the same step) at every step. Biased: its error flattens
#          at a floor set by S.
# The error is the RMSE over the whole image (8-bit PNG, channels in [0, 1]; tests/perf/ch08's
# rmse) against a reference rendered by default at 8100 samples per pixel (seed 99). A pixel's
# lamp points are shared by its samples (--media-points, 64 by default), at least one a ray: the
# reference's rays take one each, 8100 a pixel. Its own error is estimated from a second render
# with the same settings (seed 98): their RMSE divided by sqrt(2); drawn dashed. The series
# points-1024 is the default with 1024 points per pixel (the same as the default from 1024
# samples on).
# Time is the render phase of --stats on all cores; the fastest of CH17_ROUNDS rounds (the
# machine is shared); the RMSE is round 1's (a render is bit-identical from run to run).
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch17
mkdir -p "$charts" "$data"
rt=$build/rt_ch17
rmse=$build/tests/perf/ch08/ch08_aa_charts
majorant=$build/tests/perf/ch17/ch17_majorant
[[ -x $rt && -x $rmse ]] || { echo "charts.sh: $rt or $rmse not built" >&2; exit 2; }
rounds=${CH17_ROUNDS:-3}
charts_wanted=${CH17_CHARTS:-convergence majorant povray}
wants() { [[ " $charts_wanted " == *" $1 "* ]]; }
scene=tests/perf/ch17/plume.lua

run() {  # out.png args... ; prints the render seconds
    local png=$1; shift
    (cd "$root" && "$rt" --quiet --stats --media-bounces=0 --output "$png" "$@" "$scene" 2>&1) |
        awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
             END { if (r == "") exit 1; print r }'
}

# Point labels are plotted after every line and point, in an opaque box (set style textbox), so
# no later series draws its dots over them.
draw() {
    local name=$1
    printf '%s\n%s\n' "set style textbox opaque noborder margins 0.5,0.5" "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 720,480 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 720,480 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

if wants convergence; then
echo "chapter 17 charts: references (about a minute)" >&2
run "$data/ref.png" --seed 99 --spp 8100 >/dev/null
run "$data/ref-check.png" --seed 98 --spp 8100 >/dev/null
refError=$(awk -v e="$("$rmse" rmse "$data/ref-check.png" "$data/ref.png")" 'BEGIN { printf "%.5f", e / sqrt(2) }')

# The series: name, ./rt arguments (no spaces inside one), samples per pixel.
# The jittered sampler takes square sample counts: roughly doubling, 1 to 576 (24 x 24).
series=("default --media-shadows=exact 1 4 9 16 36 64 144 256 576"
        "points-1024 --media-points=1024 1 4 9 16 36 64 144 256 576"
        "ratio --media-shadows=ratio 1 4 9 16 36 64 144 256 576"
        "delta --media-shadows=delta 1 4 9 16 36 64 144 256 576"
        "march-0.1 --media=march,--media-step=0.1 1 4 9 16 36 64 144"
        "march-0.05 --media=march,--media-step=0.05 1 4 9 16 36 64"
        "march-0.02 --media=march,--media-step=0.02 1 4 9 16 36"
        "march-0.01 --media=march,--media-step=0.01 1 4 9 16")
declare -A best err
for round in $(seq "$rounds"); do
    echo "chapter 17 charts: round $round of $rounds" >&2
    for s in "${series[@]}"; do
        read -r name args spps <<<"$s"
        IFS=, read -r -a extra <<<"$args"
        for n in $spps; do
            key="$name $n"
            t=$(run "$data/img.png" --seed 1 --spp "$n" "${extra[@]}") ||
                { echo "charts.sh: $rt failed ($key spp)" >&2; exit 1; }
            [ "$round" = 1 ] && err[$key]=$("$rmse" rmse "$data/img.png" "$data/ref.png")
            if [ -z "${best[$key]:-}" ] || awk -v a="$t" -v b="${best[$key]}" 'BEGIN { exit !(a < b) }'; then
                best[$key]=$t
            fi
        done
    done
done
{
    echo "# tests/perf/ch17/plume.lua, 96x96, --media-bounces=0, seed 1, $(nproc) threads"
    echo "# reference: the default at 8100 spp (a lamp point a ray), seed 99; its own error (estimated) $refError"
    echo "# spp render_s rmse (the time of the fastest run)"
    for s in "${series[@]}"; do
        read -r name _ spps <<<"$s"
        echo "# $name"
        for n in $spps; do echo "$n ${best[$name $n]} ${err[$name $n]}"; done
        echo; echo
    done
} >"$data/convergence.dat"

python3 - "$data/convergence.dat" "$refError" "$charts/ch17-finding.txt" "$charts/ch17-convergence.txt" \
    "$(nproc)" <<'PY'
import math, sys
dat, ref_error, finding, table, threads = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
series, name = {}, None
for l in open(dat):
    l = l.strip()
    if l.startswith(("# default", "# points", "# ratio", "# delta", "# march")):
        name = l[2:]
        series[name] = {}
    elif l and not l.startswith("#"):
        f = l.split()
        series[name][int(f[0])] = (float(f[1]), float(f[2]))  # seconds, rmse
def time_at(points, e):  # log-log interpolation of the time at which a series reaches RMSE e
    pts = sorted(points.values(), key=lambda p: p[1])
    for a, b in zip(pts, pts[1:]):
        if a[1] <= e <= b[1] and a[1] > 0 and b[1] > a[1]:
            f = (math.log(e) - math.log(a[1])) / (math.log(b[1]) - math.log(a[1]))
            return math.exp(math.log(a[0]) + f * (math.log(b[0]) - math.log(a[0])))
    return None
default, many, ratio, delta = (series["default"], series["points-1024"], series["ratio"],
                               series["delta"])
last = max(ratio)
marches = [k for k in series if k.startswith("march")]
def step(k):
    return k.split("-", 1)[1]
def flat(k):  # the error changed by under 5% over the last two sample counts: bias-bound
    n = sorted(series[k])
    return 1 - series[k][n[-1]][1] / series[k][n[-2]][1] < 0.05
floors = ", ".join(f"{series[k][max(series[k])][1]:.4f} at step {step(k)}" for k in marches if flat(k))
falling = [k for k in marches if not flat(k)]
def median_ratio(slow, fast):  # slow's time over fast's at fast's errors, from 9 samples on
    r = sorted(time_at(slow, fast[n][1]) / fast[n][0] for n in sorted(fast)
               if n >= 9 and time_at(slow, fast[n][1]))
    return (r[len(r) // 2], len(r)) if r else (None, 0)
best = min(default, key=lambda n: default[n][1])  # the default's least error
sentence = (
    f"On the plume in single scattering (96x96, {threads} threads), the default (transmittance "
    f"integrated exactly through the voxels) goes from {default[1][1]:.4f} at 1 sample per pixel "
    f"({default[1][0]:.3f} s) to {default[best][1]:.4f} at {best} ({default[best][0]:.2f} s)"
    + (f" and ends at {default[last][1]:.4f} at {last} ({default[last][0]:.2f} s)"
       if best != last else "") +
    f": a pixel's 64 lamp "
    f"points are shared by its samples, at least one a ray, so from 64 samples on each ray takes "
    f"one and the error goes on falling (with 1024 points per pixel: {many[1][1]:.4f} at 1 "
    f"sample, {many[last][1]:.4f} at {last}, {many[last][0]:.2f} s); ratio tracking reaches {ratio[last][1]:.4f} in {ratio[last][0]:.2f} s "
    f"and delta tracking {delta[last][1]:.4f} in {delta[last][0]:.2f} s")
for slow, label in ((ratio, "ratio"), (delta, "delta")):
    med, count = median_ratio(slow, default)
    if med and count >= 3:  # fewer: the two series hardly share an error level
        sentence += (f"; at equal error {label} tracking takes {med:.2f}x the default's time "
                     f"(median over {count} points)")
sentence += (
    f"; ray marching costs far more per sample (a marched shadow ray at every step) and its error "
    f"stops at a floor set by its step ({floors}, each within 5% of the previous sample count's)")
if falling:
    sentence += ", while " + " and ".join(
        f"step {step(k)} still falls, to {series[k][max(series[k])][1]:.4f} at {max(series[k])} "
        f"samples ({series[k][max(series[k])][0]:.2f} s)" for k in falling)
sentence += (
    f" (whole-image RMSE against an 8100-sample reference, a lamp point a ray, whose own error is about "
    f"{ref_error:.4f}).")
with open(finding, "w") as out:
    out.write(sentence + "\n")
with open(table, "w") as out:
    out.write("Error of the plume in single scattering (tests/perf/ch17/plume.lua, 96x96, "
              "--media-bounces=0, seed 1): RMSE over the whole image against the converged "
              f"reference (own error about {ref_error:.4f}), and the render time in seconds "
              f"({threads} threads, fastest of the rounds).\n\n")
    names = ["default", "points-1024", "ratio", "delta"] + marches
    heads = ["default (exact)", "1024 points", "ratio tracking", "delta tracking"] + [f"march, step {step(k)}" for k in marches]
    out.write("| spp | " + " | ".join(heads) + " |\n")
    out.write("|---:|" + "---:|" * len(heads) + "\n")
    for n in sorted(ratio):
        cells = []
        for k in names:
            p = series[k].get(n)
            cells.append(f"{p[1]:.4f} ({p[0]:.3g} s)" if p else "")
        out.write(f"| {n} | " + " | ".join(cells) + " |\n")
PY

draw ch17-convergence "
set title 'Single-scattering plume: error against time (96x96, points at 1, 4, 9, 16, 36, ... spp)'
set xlabel 'render time (s)'
set ylabel 'RMSE against the converged reference'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set yrange [0.0008:0.5]
set key top right reverse Left box opaque font ',8'
set label sprintf('own error of the reference (estimated): %.4f', $refError) at graph 0.42, first $refError offset 0,0.7 font ',9' tc rgb 'gray40'
plot '$data/convergence.dat' index 0 using 2:3 with linespoints pt 7 lw 2.5 lc rgb '#2a9d4a' title 'default: transmittance integrated exactly through the voxels', \\
     '' index 1 using 2:3 with linespoints pt 9 lw 2 dt 2 lc rgb '#2a9d4a' title 'default, 1024 lamp points per pixel (--media-points)', \\
     '' index 2 using 2:3 with linespoints pt 7 lw 2 lc rgb '#dd3333' title 'ratio tracking of the transmittance', \\
     '' index 3 using 2:3 with linespoints pt 5 lw 2 lc rgb '#e8a33d' title 'delta tracking of the transmittance', \\
     '' index 4 using 2:3 with linespoints pt 6 lc rgb '#8fb3d9' title 'ray marching, step 0.1', \\
     '' index 5 using 2:3 with linespoints pt 4 lc rgb '#4a7fbf' title 'ray marching, step 0.05', \\
     '' index 6 using 2:3 with linespoints pt 8 lc rgb '#1f4e8c' title 'ray marching, step 0.02', \\
     '' index 7 using 2:3 with linespoints pt 10 lc rgb '#0b2447' title 'ray marching, step 0.01', \\
     $refError with lines dt 2 lc rgb 'gray50' notitle, \\
     '' index 0 using 2:3:1 with labels boxed offset char -0.8,-1 font ',8' tc rgb '#2a9d4a' notitle, \\
     '' index 7 using 2:3:1 with labels boxed offset char 0.8,1 font ',8' tc rgb '#0b2447' notitle
"
else
    echo "charts: ch17-convergence not asked for (CH17_CHARTS)"
fi

# The majorant grid.
if ! wants majorant; then
    echo "charts: ch17-majorant not asked for (CH17_CHARTS)"
elif [ -x "$majorant" ]; then
    (cd "$root" && "$majorant" scenes/assets/plume.nvdb 100000) | tee "$data/majorant.out"
    grep -v '^target ' "$data/majorant.out" >"$charts/ch17-majorant.txt"
    awk '$1 ~ /^[0-9]+$/ && NF == 8' "$data/majorant.out" >"$data/majorant.dat"
    draw ch17-majorant "
set title 'Majorant grid: null collisions and time per free flight (plume, 1 thread)'
set xlabel 'majorant grid cells per axis (--media-majorant; 1 = one global majorant)'
set ylabel 'null collisions per real collision'
set y2label 'time per free flight (ns)'
set logscale x 2
set logscale y
set xrange [0.8:80]
set yrange [0.5:100]
set y2range [0:*]
set ytics nomirror
set y2tics
set format y '%g'
set grid
set key top right box opaque font ',9'
plot '$data/majorant.dat' using 1:5 with linespoints pt 7 lw 2.5 lc rgb '#dd3333' title 'null per real collision (delta tracking)', \\
     '' using 1:6 axes x1y2 with linespoints pt 5 lc rgb '#1f4e8c' title 'ns per free flight (right axis)', \\
     '' using 1:8 axes x1y2 with linespoints pt 4 dt 2 lc rgb '#4a7fbf' title 'ns per ratio-tracking estimate (right axis)', \\
     '' using 1:5:(sprintf('%.2f', \$5)) with labels boxed offset char 0,1.1 font ',8' tc rgb '#dd3333' notitle
"
else
    echo "charts: $majorant not built; ch17-majorant not redrawn"
fi

if ! wants povray; then
    echo "charts: ch17-povray not asked for (CH17_CHARTS)"
elif command -v povray >/dev/null; then
    bash "$root/tests/perf/ch17/media_vs_povray.sh" "$build" "$data/povray" | tee "$data/povray.txt"
    grep -v '^target ' "$data/povray.txt" >"$charts/ch17-povray.txt"
    draw ch17-povray "
set title 'Fog and a light shaft against POV-Ray 3.7 media (1 thread)'
set xlabel 'render time (s): raybook render phase; POV-Ray Trace Time'
set ylabel 'RMSE against own converged reference'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right reverse Left box opaque font ',9'
plot '$data/povray/povray.dat' index 1 using 3:4 with linespoints pt 5 lc rgb '#1f4e8c' title 'POV-Ray, media { intervals 1 samples N }' noenhanced, \\
     '' index 3 using 3:4 with linespoints pt 7 lw 2 lc rgb '#dd3333' title 'raybook default, N renders at the pixel centres', \\
     '' index 4 using 3:4 with linespoints pt 9 lw 2 lc rgb '#2a9d4a' title 'raybook default, one render, N lamp points per ray', \\
     '' index 0 using 3:4 with linespoints pt 4 lw 1 dt 2 lc rgb '#aa5555' title 'raybook default, N spp jittered (antialiased)', \\
     '' index 2 using 3:4 with linespoints pt 6 lw 2 lc rgb '#e8a33d' title 'raybook ray marching, step S, 1 spp', \\
     '' index 1 using 3:4:2 with labels boxed offset char 0,1 font ',8' tc rgb '#1f4e8c' notitle, \\
     '' index 3 using 3:4:2 with labels boxed offset char 1.2,0.9 font ',8' tc rgb '#dd3333' notitle, \\
     '' index 4 using 3:4:2 with labels boxed offset char -1.2,-0.9 font ',8' tc rgb '#2a9d4a' notitle, \\
     '' index 2 using 3:4:2 with labels boxed offset char -1.4,-0.8 font ',8' tc rgb '#e8a33d' notitle
"
else
    echo "charts: povray is not installed; ch17-povray not redrawn (make charts installs it)"
fi

echo "chapter 17 charts: $(cat "$charts/ch17-finding.txt")"
