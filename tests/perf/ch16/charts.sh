#!/usr/bin/env bash
# Chapter 16's charts, into docs/charts/:
#   ch16-convergence.svg/.png  RMSE of the chapter scene's caustics against render time: the
#                              classic method at four fixed radii (0.01, 0.02, 0.04, 0.08) and
#                              the progressive method (alpha = 2/3, first radius 0.04), each at
#                              1, 2, 4, ... passes of 20,000 photons
#   ch16-convergence.txt       the same points as a Markdown table (\include{doc})
#   ch16-finding.txt           the finding in one sentence, with numbers (\include{doc})
#   ch16-povray.svg/.png       raybook's caustics against POV-Ray 3.7's photons: RMSE against time
#   ch16-povray.txt            the POV-Ray tables and the ratio at equal error, Markdown (\include{doc})
#
# usage: tests/perf/ch16/charts.sh BUILD_DIR   (about 4 minutes on 2 idle cores; the POV-Ray chart
# is skipped, with a note, when povray is not installed)
#   CH16_ROUNDS=N   timed rounds per point, the fastest kept (default 3)
#
# What is measured: the caustics alone. The chapter scene runs with gr.photons{indirect =
# false} (and method = 'classic' for the classic curves), written with sed into
# BUILD_DIR/charts/ch16/; --photon-radius and --photon-passes set the rest, 20,000 photons per
# pass (the default), seed 1, 192x192, all cores. The error is the RMSE over the WHOLE image
# (8-bit PNG, channels in [0, 1]; tests/perf/ch08's rmse): every pixel the caustic maps do not
# reach is the same in every render (no randomness outside the photons at one ray per pixel),
# and the mirror ball throws a faint caustic over most of the box (over 90% of the pixels
# receive some), so no crop would hold all of it. Pixels clipped at 1 (the brightest part of the
# focus under the glass ball) hide their error in both the render and the reference.
# Time is the render phase of --stats, which includes the photon passes; the fastest of
# CH16_ROUNDS rounds (the machine is shared); the RMSE is round 1's (the image is bit-identical
# from run to run).
# The reference: progressive, first radius 0.005, 256 passes of 800,000 photons (205 million
# photons, about a minute on 2 cores), seed 99. Its own error is estimated by a second
# converged render, first radius 0.01, 256 passes of 200,000 photons, seed 98: their RMSE (about
# 0.005) is drawn as a dashed line. It overstates the reference's own error (the check has twice
# its radius, so more bias, and a quarter of its photons), but measured points near it say
# little. (A smooth caustic's bias would shrink as r²; this one's focus and the rainbow-like
# curves that light reflected inside the glass ball draws are sharp, and its bias shrinks far
# more slowly, so a converged reference needs a small radius and many photons.)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch16
mkdir -p "$charts" "$data"
rt=$build/rt_ch16
rmse=$build/tests/perf/ch08/ch08_aa_charts
[[ -x $rt && -x $rmse ]] || { echo "charts.sh: $rt or $rmse not built" >&2; exit 2; }
rounds=${CH16_ROUNDS:-3}

# The scene variants: caustics only, progressive or classic.
scene=$root/scenes/chapter16-photon-mapping.lua
photons='gr.photons{indirect = true}'
grep -qF "$photons" "$scene" || { echo "charts.sh: '$photons' not found in $scene" >&2; exit 2; }
sed "s/gr.photons{indirect = true}/gr.photons{indirect = false}/" "$scene" >"$data/progressive.lua"
sed "s/gr.photons{indirect = true}/gr.photons{indirect = false, method = 'classic'}/" "$scene" >"$data/classic.lua"

# The "photons" line of --stats, in either of its forms:
#   photons  P passes of N in S s; caustic C stored, radius A -> B; indirect D stored, radius ...
#   photons  P passes of N: C caustic, D indirect stored; radius A -> B; S s   (older builds)
run() {  # out.png scene args... ; prints "render_s photon_s caustic_stored first_radius last_radius"
    local png=$1 lua=$2; shift 2
    (cd "$root" && "$rt" --quiet --stats --output "$png" "$@" "$lua" 2>&1) |
        awk '$1 == "time" { for (i = 2; i < NF; i++) if ($(i - 1) == "render") r = $i }
             $1 == "photons" { p = $(NF - 1)
                               for (i = 2; i < NF; i++) {
                                 if ($i == "in" && $(i + 2) ~ /^s/) p = $(i + 1)
                                 if ($i == "caustic" && $(i + 1) ~ /^[0-9]+$/) n = $(i + 1)
                                 if ($(i + 1) == "caustic," && $i ~ /^[0-9]+$/) n = $i
                                 if ($i == "radius" && a == "") { a = $(i + 1); b = $(i + 3) } } }
             END { sub(/[;,]$/, "", b); if (r == "") exit 1; print r, p, n, a, b }'
}

echo "chapter 16 charts: references (about 2 minutes)" >&2
run "$data/ref.png" "$data/progressive.lua" --seed 99 --photons 800000 --photon-passes 256 \
    --photon-radius 0.005 >/dev/null
run "$data/ref-check.png" "$data/progressive.lua" --seed 98 --photons 200000 --photon-passes 256 \
    --photon-radius 0.01 >/dev/null
refError=$("$rmse" rmse "$data/ref-check.png" "$data/ref.png")

# The series: name, scene, radius, pass counts.
series=("classic 0.01 classic 1 2 4 8 16 32 64"
        "classic 0.02 classic 1 2 4 8 16 32 64"
        "classic 0.04 classic 1 2 4 8 16 32 64"
        "classic 0.08 classic 1 2 4 8 16 32 64"
        "progressive 0.04 progressive 1 2 4 8 16 32 64 128 256")
declare -A best line
for round in $(seq "$rounds"); do
    echo "chapter 16 charts: round $round of $rounds" >&2
    for s in "${series[@]}"; do
        read -r method radius lua passes <<<"$s"
        for n in $passes; do
            key="$method $radius $n"
            out=$(run "$data/img.png" "$data/$lua.lua" --seed 1 --photon-radius "$radius" \
                      --photon-passes "$n") || { echo "charts.sh: $rt failed ($key passes)" >&2; exit 1; }
            read -r t p stored r0 r1 <<<"$out"
            if [ "$round" = 1 ]; then
                line[$key]="$stored $r0 $r1 $("$rmse" rmse "$data/img.png" "$data/ref.png")"
            fi
            # The fastest run's render time, and its photon passes' time.
            if [ -z "${best[$key]:-}" ] || awk -v a="$t" -v b="${best[$key]% *}" 'BEGIN { exit !(a < b) }'; then
                best[$key]="$t $p"
            fi
        done
    done
done
{
    echo "# chapter 16 scene, caustics only, 192x192, 20000 photons per pass, seed 1"
    echo "# reference: progressive, r0 0.005, 256 x 800000 photons, seed 99; its own error (estimated) $refError"
    echo "# passes render_s photon_s stored first_radius last_radius rmse (the times of the fastest run)"
    for s in "${series[@]}"; do
        read -r method radius _ passes <<<"$s"
        echo "# $method $radius"
        for n in $passes; do echo "$n ${best[$method $radius $n]} ${line[$method $radius $n]}"; done
        echo; echo
    done
} >"$data/convergence.dat"

# The finding and the table.
python3 - "$data/convergence.dat" "$refError" "$charts/ch16-finding.txt" "$charts/ch16-convergence.txt" \
    "$(nproc)" <<'PY'
import math, sys
dat, ref_error, finding, table = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
threads = sys.argv[5]
series, name = {}, None
for l in open(dat):
    l = l.strip()
    if l.startswith("# classic") or l.startswith("# progressive"):
        name = l[2:]
        series[name] = {}
    elif l and not l.startswith("#"):
        f = l.split()
        series[name][int(f[0])] = {"s": float(f[1]), "photon_s": float(f[2]), "stored": int(f[3]),
                                   "r0": float(f[4]), "r1": float(f[5]), "rmse": float(f[6])}
classic = [k for k in series if k.startswith("classic")]
prog = series["progressive 0.04"]
last = max(prog)
def floor(k):
    return series[k][64]["rmse"]
def beats(k):  # the first pass count at which the progressive method is below the classic floor
    for n in sorted(prog):
        if prog[n]["rmse"] < floor(k):
            return n
    return None
slope = math.log(prog[last]["rmse"] / prog[64]["rmse"]) / math.log(last / 64)
flat = [k for k in classic if 1 - series[k][64]["rmse"] / series[k][16]["rmse"] < 0.05]
still = [k for k in classic if k not in flat]
def radius(k):
    return k.split()[1]
floors = ", ".join(f"{floor(k):.4f} at radius {radius(k)}" for k in reversed(flat))
crossing = []
for k in reversed(classic):
    n = beats(k)
    if n and float(radius(k)) <= 0.04:  # the progressive method starts at 0.04
        crossing.append(f"the radius-{radius(k)} floor after {n} passes ({prog[n]['s']:.2f} s)")
sentence = (
    f"With 20,000 photons per pass the classic method's caustic error flattens at a floor set by "
    f"its radius ({floors} after 64 passes, each within 5% of its 16-pass value")
for k in still:
    sentence += (f"; radius {radius(k)}, still noise-bound, falls from "
                 f"{series[k][16]['rmse']:.4f} to {series[k][64]['rmse']:.4f}")
sentence += (
    f"), while the progressive method (alpha 2/3, first radius 0.04) keeps falling, from "
    f"{prog[1]['rmse']:.4f} at 1 pass to {prog[64]['rmse']:.4f} at 64 and "
    f"{prog[last]['rmse']:.4f} at {last} passes ({prog[last]['s']:.1f} s), but slowly (slope "
    f"{slope:.2f} in log RMSE over log passes from 64 passes on), crossing "
    + (" and ".join(crossing) if crossing else "none of the classic floors") +
    f" (whole-image RMSE at 192x192 against a 205-million-photon reference whose own error is "
    f"about {ref_error:.4f}).")
with open(finding, "w") as out:
    out.write(sentence + "\n")
with open(table, "w") as out:
    out.write("Caustic error of the chapter scene (gr.photons{indirect = false}, 192x192, 20,000 "
              "photons per pass, seed 1): RMSE over the whole image against the converged "
              f"reference (own error about {ref_error:.4f}), and the render time in seconds "
              f"(photon passes included, {threads} threads, fastest of the rounds).\n\n")
    names = list(reversed(classic)) + ["progressive 0.04"]
    heads = [f"classic, r = {k.split()[1]}" for k in reversed(classic)] + ["progressive, r0 = 0.04"]
    out.write("| passes | " + " | ".join(heads) + " |\n")
    out.write("|---:|" + "---:|" * len(heads) + "\n")
    for n in sorted(prog):
        cells = []
        for k in names:
            p = series[k].get(n)
            cells.append(f"{p['rmse']:.4f} ({p['s']:.3g} s)" if p else "")
        out.write(f"| {n} | " + " | ".join(cells) + " |\n")
    stored = prog[last]["stored"]
    out.write(f"\nThe progressive radius shrinks from {prog[last]['r0']:g} to {prog[last]['r1']:g} "
              f"over {last} passes ({stored:,} caustic photons stored); the classic method keeps "
              "its radius.\n")
PY

draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 720,480 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 720,480 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch16-convergence "
set title 'Caustic error against time: fixed radius against shrinking radius (chapter scene, 192x192)'
set xlabel 'render time (s), photon passes included; points at 1, 2, 4, ... passes of 20,000 photons'
set ylabel 'RMSE against the converged reference'
set logscale xy
set xrange [0.01:10]
set yrange [0.004:0.045]
set ytics (0.004, 0.005, 0.006, 0.008, 0.01, 0.015, 0.02, 0.03, 0.04)
set format x '%g'
set grid
set key at graph 0.02, graph 0.2 left bottom reverse Left box opaque font ',9'
set label sprintf('own error of the reference (estimated): %.4f', $refError) at graph 0.5, first $refError offset 0,0.7 font ',9' tc rgb 'gray40'
plot '$data/convergence.dat' index 0 using 2:7 with linespoints pt 6 lc rgb '#8fb3d9' title 'classic, radius 0.01', \\
     '' index 1 using 2:7 with linespoints pt 4 lc rgb '#4a7fbf' title 'classic, radius 0.02', \\
     '' index 2 using 2:7 with linespoints pt 8 lc rgb '#1f4e8c' title 'classic, radius 0.04', \\
     '' index 3 using 2:7 with linespoints pt 10 lc rgb '#0b2447' title 'classic, radius 0.08', \\
     '' index 4 using 2:7 with linespoints pt 7 lw 2.5 lc rgb '#dd3333' title 'progressive, alpha 2/3, first radius 0.04 (labels: passes)', \\
     '' index 4 using 2:7:1 with labels offset char 0,-1 font ',8' tc rgb '#dd3333' notitle, \\
     $refError with lines dt 2 lc rgb 'gray50' notitle
"

if command -v povray >/dev/null; then
    bash "$root/tests/perf/ch16/caustics_vs_povray.sh" "$build" "$data/povray" | tee "$data/povray.txt"
    grep -v '^target ' "$data/povray.txt" >"$charts/ch16-povray.txt"
    draw ch16-povray "
set title 'Caustics against POV-Ray 3.7 photons (chapter scene, inverse-square light, 192x192, 1 thread)'
set xlabel 'render time (s): raybook render phase (photon passes included); POV-Ray Photon + Trace Time'
set ylabel 'RMSE against own converged reference'
set logscale xy
set format x '%g'
set yrange [0.003:0.12]
set ytics (0.003, 0.005, 0.007, 0.01, 0.015, 0.02, 0.03, 0.05, 0.07, 0.1)
set grid
set key top right reverse Left box opaque font ',9'
plot '$data/povray/povray.dat' index 2 using 3:4 with linespoints pt 5 lc rgb '#1f4e8c' title 'POV-Ray, photons { count N }' noenhanced, \\
     '' index 2 using 3:4:(sprintf('%gk', \$2 / 1000)) with labels offset char 0,1 font ',8' tc rgb '#1f4e8c' notitle, \\
     '' index 0 using 3:4 with linespoints pt 7 lw 2 lc rgb '#dd3333' title 'raybook, 1 pass of N photons, k = 50 nearest', \\
     '' index 0 using 3:4:(sprintf('%gk', \$2 / 1000)) with labels offset char 0,-1 font ',8' tc rgb '#dd3333' notitle, \\
     '' index 1 using 3:4 with linespoints pt 6 lc rgb '#e8a33d' title 'raybook defaults: N passes of 20k (progressive)', \\
     '' index 1 every 2::2 using 3:4:2 with labels offset char 0,-1 font ',8' tc rgb '#e8a33d' notitle
"
else
    echo "charts: povray is not installed; ch16-povray not redrawn (make charts installs it)"
fi

echo "chapter 16 charts: $(cat "$charts/ch16-finding.txt")"
