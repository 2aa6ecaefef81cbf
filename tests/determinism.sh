#!/usr/bin/env bash
# Render a scene with 1 and with 2 threads; the PNG bytes must be identical.
# 256 × 192 pixels is 192 tiles of 16 × 16 (96 × 72 was only 30), so the second thread always
# starts long before the first could finish them all and both render part of the image. That
# both threads really took tiles, and that the image still matches bit for bit, is proved in
# tests/ch01_core.cpp ("both threads render part of the image ..."), which records the thread of
# every tile through RenderSettings::tileThreads.
set -euo pipefail
rt=$1 scene=$2 out=$3
name=$(basename "$scene" .lua)
mkdir -p "$out"
# Four rays per pixel (--spp 4): a square, so a scene's own jittered sampler (gr.antialias,
# chapter 8) takes 2 x 2 strata instead of its own count (chapter 17's 144 made this test alone
# cost 22 s, and 200 s under the sanitizers, to check the same code as 4 rays do). The adaptive
# sampler chooses its own rays per pixel and refuses --spp, so its scenes keep their settings.
spp=(--spp 4)
grep -q "^gr.antialias.*sampler *= *'adaptive'" "$scene" && spp=()
"$rt" --quiet --size 256x192 "${spp[@]}" --seed 7 --threads 1 --output "$out/$name-1.png" "$scene"
"$rt" --quiet --size 256x192 "${spp[@]}" --seed 7 --threads 2 --output "$out/$name-2.png" "$scene"
if cmp -s "$out/$name-1.png" "$out/$name-2.png"; then
  echo "$name: 1 and 2 threads give identical bytes"
else
  echo "$name: FAIL: 1 and 2 threads differ"; exit 1
fi
