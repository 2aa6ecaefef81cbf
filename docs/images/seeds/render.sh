#!/usr/bin/env bash
# render.sh: render the three seed scenes (scenes/seeds/*.lua) at full size for the docs page
# docs/seeds.md, into docs/images/seeds/NNN-name-full.png, and print each render's time.
#
# usage: docs/images/seeds/render.sh [RT_BINARY] [SIZE] [THREADS]
#        defaults: build/rt_ch18, 640x480, 2 threads
#
# The scenes' own gr.render size is 320x240 and the golden tests render them at 192x144; the
# docs show them at twice the scenes' size. The render time is rt's own "render" phase from
# --stats (wall clock, scene loading and PNG writing excluded).
set -euo pipefail
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
rt=${1:-build/rt_ch18}
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
# Before and after (the page's pairs). Seed 000 before its light: chapters 1-15 only, without
# the caustic map and the steam, into 000-bathhouse-before.png. Seeds 001 and 002 after:
# path traced (chapter 18), 256 jittered paths a pixel, into NNN-name-path.png (needs rt_ch18 or
# later).
seconds=$("$rt" --quiet --features=all,-photon_map,-media --stats --seed 1 --threads "$threads" \
    --size "$size" --output docs/images/seeds/000-bathhouse-before.png \
    scenes/seeds/000-bathhouse.lua 2>&1 | awk '$1 == "time" && $2 == "build" {print $6}')
echo "000-bathhouse, chapters 1-15: $size, $threads threads, render $seconds s"
if "$rt" --list-features 2>/dev/null | grep -q path_tracing; then
    for name in 001-garage 002-desk; do
        out=docs/images/seeds/$name-path.png
        seconds=$("$rt" --quiet --features=all --stats --seed 1 --threads "$threads" \
            --size "$size" --integrator=path --aa=jittered --spp 256 --output "$out" \
            scenes/seeds/$name.lua 2>&1 | awk '$1 == "time" && $2 == "build" {print $6}')
        echo "$name, path traced: $size, $threads threads, render $seconds s -> $out"
    done
fi
