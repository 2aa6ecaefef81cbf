#!/usr/bin/env bash
# The figures of the page "Rendering to an error" (docs/target-error.md): chapter 7's scene
# rendered to an RMS error of 0.01 with its heat map of samples per pixel, and uniform sampling
# given about the same time. Run from the repository root after make chapter18:
#   bash docs/images/target-error/render.sh [RT]
# It prints each render's --stats lines; the page quotes them.
set -eu
RT=${1:-build/rt_ch18}
OUT=docs/images/target-error
SCENE=scenes/chapter07-glossy.lua
"$RT" --quiet --stats --threads 2 --target-error 0.01 --aov sample-count \
    --output "$OUT/glossy-target-0.01.png" "$SCENE" 2>&1 | grep -E "samples|render "
"$RT" --quiet --stats --threads 2 --spp 23 --output "$OUT/glossy-uniform-23.png" "$SCENE" 2>&1 |
    grep -E "render "
