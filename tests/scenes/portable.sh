#!/usr/bin/env bash
# Scenes travel with their folder: every sample scene (the chapter scenes and the showcase in
# scenes/, and scenes/a4/, scenes/seeds/, scenes/legacy/) renders when its folder is copied
# somewhere else together with the meshes it names (scenes/assets/ goes along as the copy's
# assets/ folder, next to the others, as it is in the repository). Each scene is run twice:
#   - from inside the copied folder:     cd copy/a4 && rt scene.lua
#   - from the folder above the copy:    cd copy && rt a4/scene.lua
# Files a scene names are looked for in the working directory, then the scene's folder, so
# both runs must find every mesh and require()d file. What is checked is that the scene loads
# and renders, so each renders as --preview (one sample of everything): the full sample counts
# made this test 36 s, and 100 s under the sanitizers, mostly in the showcase and seed 000.
#
# Usage: bash tests/scenes/portable.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

TIMEOUT=${SCENES_TIMEOUT:-60}

# shellcheck source=../check_helpers.sh
source "$(dirname "$0")/../check_helpers.sh"
rt_and_out_dir "$@"

# A copy of the scenes, far from the repository: top-level scenes in copy/, the rest in
# copy/<folder>/, meshes in copy/assets/.
COPY="$OUT/elsewhere/copy"
rm -rf "$OUT/elsewhere"
mkdir -p "$COPY"
cp "$ROOT"/scenes/*.lua "$COPY/"
for dir in a4 seeds legacy assets; do cp -r "$ROOT/scenes/$dir" "$COPY/$dir"; done

last_chapter=$("$RT" --list-features 2>/dev/null | awk '$1 ~ /^[0-9]+$/ && $1 > m {m = $1} END {print m + 0}')

# run NAME WORKDIR SCENE_ARG ARGS...: render in WORKDIR; the first image must appear there.
run() {
    local name=$1 work=$2 scene=$3
    shift 3
    local png="$work/portable-out.png"
    rm -f "$work"/portable-out*.png
    if (cd "$work" && timeout "$TIMEOUT" "$RT" --quiet --preview --size 48x36 --output portable-out.png \
        "$@" "$scene") >"$OUT/log" 2>&1 && [ -s "$png" ]; then
        ok "$name"
    else
        fail "$name" "$(head -c 400 "$OUT/log")"
    fi
    rm -f "$work"/portable-out*.png
}

for scene in "$COPY"/*.lua "$COPY"/a4/*.lua "$COPY"/seeds/*.lua "$COPY"/legacy/*.lua; do
    [ -n "$(header "$scene" rt-module)" ] && continue
    chapter=$(basename "$scene" | sed -n 's/^chapter0*\([0-9][0-9]*\)-.*/\1/p')
    [ -n "$chapter" ] && [ "$chapter" -gt "$last_chapter" ] && continue
    read -r -a args <<<"$(header "$scene" rt-args | head -n 1)"
    folder=$(dirname "$scene")
    rel=${scene#"$COPY"/}
    run "$rel from its own folder" "$folder" "$(basename "$scene")" "${args[@]}"
    if [ "$folder" != "$COPY" ]; then
        run "$rel from the folder above" "$COPY" "$rel" "${args[@]}"
    else
        run "$rel from the folder above" "$OUT/elsewhere" "copy/$rel" "${args[@]}"
    fi
done

finish
