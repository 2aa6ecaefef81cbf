#!/usr/bin/env bash
# render.sh: render the three seed scenes (scenes/seeds/*.lua) at full size for the docs page
# docs/seeds.md, into docs/images/seeds/NNN-name-full.png, and print each render's time.
#
# usage: docs/images/seeds/render.sh [RT_BINARY] [SIZE] [THREADS]
#        defaults: build/rt_ch16, 640x480, 2 threads
#
# The scenes' own gr.render size is 320x240 and the golden tests render them at 192x144; the
# docs show them at twice the scenes' size. The render time is rt's own "render" phase from
# --stats (wall clock, scene loading and PNG writing excluded).
set -euo pipefail
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
rt=${1:-build/rt_ch16}
size=${2:-640x480}
threads=${3:-2}
case "$rt" in /*) ;; *) rt=$repo_root/$rt ;; esac
cd "$repo_root"
for scene in scenes/seeds/[0-9][0-9][0-9]-*.lua; do
    name=$(basename "$scene" .lua)
    out=docs/images/seeds/$name-full.png
    seconds=$("$rt" --quiet --features=all --stats --seed 1 --threads "$threads" --size "$size" \
        --output "$out" "$scene" 2>&1 | awk '$1 == "time" && $2 == "build" {print $6}')
    echo "$name: $size, $threads threads, render $seconds s -> $out"
done
# Seed 002's "global illumination next" (chapter 18): the desk path traced, 256 jittered paths a
# pixel, into docs/images/seeds/002-desk-path.png (needs rt_ch18 or later).
if "$rt" --list-features 2>/dev/null | grep -q path_tracing; then
    out=docs/images/seeds/002-desk-path.png
    seconds=$("$rt" --quiet --features=all --stats --seed 1 --threads "$threads" --size "$size" \
        --integrator=path --aa=jittered --spp 256 --output "$out" scenes/seeds/002-desk.lua 2>&1 |
        awk '$1 == "time" && $2 == "build" {print $6}')
    echo "002-desk, path traced: $size, $threads threads, render $seconds s -> $out"
fi
