#!/usr/bin/env bash
# Chapter 12's charts: run ch12_tone_charts on the chapter scene and draw, into docs/charts/,
#   ch12-side-by-side.png   the film clipped, through the global and through the local operator
#   ch12-measures.svg/.png  what each keeps: pixels burnt to white, visible edges kept (all,
#                           bright, shade)
#   ch12-finding.txt        the finding in one sentence, with numbers (\include{doc})
#
# usage: tests/perf/ch12/charts.sh BUILD_DIR   (run from anywhere; takes a second)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch12
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch12/ch12_tone_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
(cd "$root" && "$program" scenes/chapter12-tone-mapping.lua "$data")
cp "$data/finding.txt" "$charts/ch12-finding.txt"
cp "$data/side-by-side.png" "$charts/ch12-side-by-side.png"

# One gnuplot script, drawn once as SVG and once as PNG.
draw() {
    local name=$1
    printf '%s\n' "$2" >"$data/$name.gp"
    gnuplot -e "set terminal svg size 820,400 font 'sans,12' background rgb 'white'" \
            -e "set output '$charts/$name.svg'" "$data/$name.gp"
    gnuplot -e "set terminal pngcairo size 820,400 font 'sans,10'" \
            -e "set output '$charts/$name.png'" "$data/$name.gp"
}

draw ch12-measures "
set title 'What each tone map keeps of the chapter scene (192x144, film 22850:1)'
set ylabel 'percent of the pixels, or of the visible edges in the film'
set yrange [0:105]
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set key top left
set grid ytics
set xtics font ',10'
plot '$data/bars.dat' using 2:xtic(1) title 'clipped (none)' lc rgb '#999999', \
     '' using 3 title 'Reinhard global' lc rgb '#3b6fb6', \
     '' using 4 title 'Reinhard local' lc rgb '#d9822b'
"

echo "chapter 12 charts: $(cat "$charts/ch12-finding.txt")"
