#!/usr/bin/env bash
# Chapter 9's chart: run ch09_normal_charts and draw, into docs/charts/,
#   ch09-normals.svg/.png    RMS normal error on a unit icosphere against the triangle count:
#                            flat facets, interpolated exact vn, interpolated computed normals
#   ch09-image.svg/.png      RMSE of an icosphere's render against the analytic sphere's, flat
#                            (gr.mesh) and smooth (gr.smooth_mesh), against the triangle count:
#                            over the whole image, and inside the outline (shading only)
#   ch09-finding.txt         the findings in two sentences, with numbers (\include{doc})
#
# usage: tests/perf/ch09/charts.sh BUILD_DIR   (run from anywhere; takes a few seconds)
set -euo pipefail

build=$(cd "${1:?usage: charts.sh BUILD_DIR}" && pwd)
root=$(cd "$(dirname "$0")/../../.." && pwd)
charts=$root/docs/charts
data=$build/charts/ch09
mkdir -p "$charts" "$data"

program=$build/tests/perf/ch09/ch09_normal_charts
[[ -x $program ]] || { echo "charts.sh: $program not built" >&2; exit 2; }
"$program" normals "$data" >/dev/null

# The image chart: each icosphere rendered flat and smooth, and the analytic sphere, 160 x 160,
# one ray per pixel, one light from the upper left.
rt=$build/rt_ch9
[[ -x $rt ]] || { echo "charts.sh: $rt not built" >&2; exit 2; }
"$program" icospheres "$data"
scene() {  # scene NAME SHAPE-CALL
    cat >"$data/$1.lua" <<LUA
local m = gr.material({0.7, 0.5, 0.35}, {0.5, 0.5, 0.5}, 40)
local root = gr.node('root')
local s = $2
s:set_material(m)
root:add_child(s)
gr.render(root, '$1.png', 160, 160, {0, 0, 4}, {0, 0, -1}, {0, 1, 0}, 40, {0.1, 0.1, 0.1},
          {gr.light({-4, 4, 4}, {0.9, 0.9, 0.9}, {1, 0, 0})})
LUA
    (cd "$data" && "$rt" --quiet --features=all --threads 1 "$1.lua" 2>/dev/null)
}
scene sphere "gr.sphere('s')"
printf '# triangles  rmse_flat  rmse_smooth  inside_flat  inside_smooth  (against gr.sphere)\n' \
    >"$data/image.dat"
for level in 0 1 2 3 4 5; do
    scene flat_L$level "gr.mesh('s', 'icosphere_L$level.obj')"
    scene smooth_L$level "gr.smooth_mesh('s', 'icosphere_L$level.obj')"
    printf '%d %s %s %s %s\n' $((20 << (2 * level))) \
        "$("$program" rmse "$data/flat_L$level.png" "$data/sphere.png")" \
        "$("$program" rmse "$data/smooth_L$level.png" "$data/sphere.png")" \
        "$("$program" rmse-inside "$data/flat_L$level.png" "$data/sphere.png")" \
        "$("$program" rmse-inside "$data/smooth_L$level.png" "$data/sphere.png")" >>"$data/image.dat"
done
awk '!/^#/ { n++; t[n] = $1; f[n] = $2; s[n] = $3; fi[n] = $4; si[n] = $5 }
     END { printf "Rendered at 160x160 against the analytic sphere, smooth shading cuts the "
           printf "error inside the outline %.1f to %.1f times at equal triangles from %d to %d ", \
                  fi[2] / si[2], fi[5] / si[5], t[2], t[5]
           printf "(%d triangles: %.4f smooth against %.4f flat), but the whole-image RMSE only ", \
                  t[3], si[3], fi[3]
           printf "%.1f to %.1f times up to %d triangles, because the polygonal outline, which ", \
                  f[2] / s[2], f[5] / s[5], t[5]
           printf "normals cannot change, dominates it until the mesh is finer than a pixel ", \
                  t[5]
           printf "(%d triangles: %.4f against %.4f).\n", t[6], s[6], f[6] }' \
    "$data/image.dat" >"$data/image-finding.txt"
cat "$data/finding.txt" "$data/image-finding.txt" >"$charts/ch09-finding.txt"

printf '%s\n' "
set title 'Shading-normal error on a tessellated unit sphere'
set xlabel 'triangles (icosphere, 4x per level)'
set ylabel 'RMS angle to the true normal (degrees)'
set logscale xy
set format x '%g'
set key top right
set grid
plot '$data/normals.dat' using 1:2 with linespoints lw 2 pt 7 title 'flat facets (order 1)', \
     '' using 1:4 with linespoints lw 2 pt 5 title 'interpolated, angle-weighted normals', \
     '' using 1:3 with linespoints lw 2 pt 9 title 'interpolated, exact vn (order 2)', \
     20.6*(x/20)**-0.5 with lines dt 2 lc rgb 'gray' title 'slope h^1', \
     12.9*(x/20)**-1 with lines dt 3 lc rgb 'gray' title 'slope h^2'
" >"$data/ch09-normals.gp"
gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
        -e "set output '$charts/ch09-normals.svg'" "$data/ch09-normals.gp"
gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
        -e "set output '$charts/ch09-normals.png'" "$data/ch09-normals.gp"

printf '%s\n' "
set title 'Image error against the analytic sphere (160x160, one ray per pixel)'
set xlabel 'triangles (icosphere, 4x per level)'
set ylabel 'RMSE against gr.sphere'
set logscale xy
set format x '%g'
set key bottom left
set grid
plot '$data/image.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '#9400d3' title 'flat, whole image', \
     '' using 1:3 with linespoints lw 2 pt 5 lc rgb '#009e73' title 'smooth, whole image', \
     '' using 1:4 with linespoints lw 2 dt 2 pt 6 lc rgb '#9400d3' title 'flat, inside the outline', \
     '' using 1:5 with linespoints lw 2 dt 2 pt 4 lc rgb '#009e73' title 'smooth, inside the outline'
" >"$data/ch09-image.gp"
gnuplot -e "set terminal svg size 640,420 font 'sans,12' background rgb 'white'" \
        -e "set output '$charts/ch09-image.svg'" "$data/ch09-image.gp"
gnuplot -e "set terminal pngcairo size 640,420 font 'sans,10'" \
        -e "set output '$charts/ch09-image.png'" "$data/ch09-image.gp"
