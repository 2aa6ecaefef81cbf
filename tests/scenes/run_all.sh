#!/usr/bin/env bash
# A smoke test (CTest: scenes_smoke): every scene renders: the course-style A4 scenes
# (scenes/a4/), the legacy scenes (scenes/legacy/), the showcase and the chapter scenes, each at
# a small size, from the repository root. (Each scene names its meshes relative to its own folder; portable.sh checks
# that they also render from a copy of that folder elsewhere.)
#
# Usage: bash tests/scenes/run_all.sh RT_BINARY OUT_DIR
#
# For each scene it checks that rt exits with 0, that every image the scene asks for (one per
# gr.render call; --output names the second one X-2.png, and so on) exists, is a PNG of the
# requested size and is not entirely black. First-line comments of a scene steer it:
#   -- rt-args: ARGS          extra arguments (e.g. --legacy for a pre-2015 scene that shows no
#                             sign of its era)
#   -- rt-same-as: FILE.lua   the image must be byte-identical to that of FILE.lua, a path
#                             relative to the scene's folder (../a4/simple.lua names a scene in
#                             another folder); default for --legacy scenes: equivalent.lua
#   -- rt-era: legacy|modern  the era rt decides (the "era" line of its --stats block) must
#                             be this one: "pre-2015" for legacy, "current framework" for modern
#   -- rt-not-black: X0 Y0 X1 Y1
#                             the first image must have a non-black pixel in this region
#                             (fractions of the width and height from the top left)
#   -- rt-stats: REGEX        the --stats output must match this extended regular expression
#                             (e.g. the unique triangle count, to show a mesh named twice
#                             was loaded once, or the number of instances of a DAG)
#   -- rt-module: ...         not a scene (a helper for require); skipped
# Chapter scenes (scenes/chapterNN-*.lua) of chapters the binary does not have are skipped.
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
# It does not check what the pictures show (beyond the rt-not-black regions and the rt-same-as
# equalities): the golden tests do that for the chapter and seed scenes.
set -u

# shellcheck source=../check_helpers.sh
source "$(dirname "$0")/../check_helpers.sh"
rt_and_out_dir "$@"
cd "$ROOT" || exit 2
SIZE=${SCENES_SIZE:-160x120}
TIMEOUT=${SCENES_TIMEOUT:-60}

# Check a PNG: prints "WxH max mean" (8-bit values), then the maximum inside each region
# given as "x0 y0 x1 y1" in fractions of the image size, or an error (tests/png_read.py reads
# it with Python's standard library only).
png_info() {
    PYTHONPATH="$ROOT/tests" python3 - "$@" <<'PY'
import sys
from png_read import read_png
path = sys.argv[1]
regions = [[float(v) for v in r.split()] for r in sys.argv[2:]]
try:
    w, h, channels, rows = read_png(path)
    total, peak = 0, 0
    boxes = [(int(r[0] * w), int(r[1] * h), int(r[2] * w), int(r[3] * h)) for r in regions]
    region_peak = [0] * len(boxes)
    n = min(channels, 3)
    for y, line in enumerate(rows):
        colour = line if channels < 3 else bytes(v for i, v in enumerate(line) if i % channels < 3)
        total += sum(colour)
        peak = max(peak, max(colour))
        for k, (x0, y0, x1, y1) in enumerate(boxes):
            if y0 <= y < y1 and x1 > x0:
                region_peak[k] = max(region_peak[k], max(colour[x0 * n:x1 * n]))
    print(' '.join(['%dx%d %d %.2f' % (w, h, peak, total / (w * h * n))] +
                   [str(p) for p in region_peak]))
except Exception as e:
    print('error: %s' % e)
PY
}

# A path with its "." and ".." parts resolved, without touching the file system (so the same
# scene named two ways, scenes/a4/x.lua and scenes/legacy/../a4/x.lua, is one key).
normpath() {
    local part parts out=() IFS=/
    read -r -a parts <<<"$1"
    for part in "${parts[@]}"; do
        case "$part" in
            "" | .) ;;
            ..) if [ ${#out[@]} -gt 0 ] && [ "${out[-1]}" != .. ]; then unset 'out[-1]'; else out+=(..); fi ;;
            *) out+=("$part") ;;
        esac
    done
    local joined="${out[*]}"
    [ "${1:0:1}" = / ] && joined="/$joined"
    echo "${joined:-.}"
}

declare -A image_of  # scene path -> its first image, for the equivalence checks

render_scene() {
    local scene=$1
    local name=${scene%.lua}
    local rel=${name#scenes/}
    local png="$OUT/$rel.png"
    mkdir -p "$(dirname "$png")"
    rm -f "$OUT/$rel".png "$OUT/$rel"-[0-9]*.png
    local args
    read -r -a args <<<"$(header "$scene" rt-args | head -n 1)"
    local start=$SECONDS
    timeout "$TIMEOUT" "$RT" --quiet --stats "${args[@]}" --size "$SIZE" --output "$png" "$scene" \
        >"$OUT/$rel.log" 2>&1
    local rc=$?
    local took=$((SECONDS - start))
    if [ $rc -ne 0 ]; then
        local why="exit code $rc"
        [ $rc -eq 124 ] && why="timed out after ${TIMEOUT}s"
        fail "$name" "$why: $(head -c 400 "$OUT/$rel.log")"
        return
    fi
    # One image per gr.render call written in the scene (calls in comments do not count).
    local renders
    renders=$(sed 's/--.*//' "$scene" | grep -c 'gr\.render *(')
    [ "$renders" -lt 1 ] && renders=1
    local k image info problems="" regions=()
    mapfile -t regions < <(header "$scene" rt-not-black)
    for k in $(seq 1 "$renders"); do
        image=$png
        [ "$k" -gt 1 ] && image="$OUT/$rel-$k.png"
        if [ ! -s "$image" ]; then
            problems+=" $(basename "$image") is missing or empty;"
            continue
        fi
        if [ "$k" -eq 1 ]; then
            info=$(png_info "$image" "${regions[@]}")
            local r field=4
            for r in "${regions[@]}"; do
                if [[ "$info" != error* ]] && [ "$(echo "$info" | cut -d' ' -f$field)" -eq 0 ]; then
                    problems+=" $(basename "$image") is black in the region $r (rt-not-black);"
                fi
                field=$((field + 1))
            done
        else
            info=$(png_info "$image")
        fi
        case "$info" in
            error*) problems+=" $(basename "$image"): $info;" ;;
            "$SIZE "*)
                if [ "$(echo "$info" | cut -d' ' -f2)" -eq 0 ]; then
                    problems+=" $(basename "$image") is entirely black;"
                fi ;;
            *) problems+=" $(basename "$image") is ${info%% *}, expected $SIZE;" ;;
        esac
    done
    local pattern
    while IFS= read -r pattern; do
        [ -z "$pattern" ] && continue
        grep -Eq -- "$pattern" "$OUT/$rel.log" || problems+=" --stats shows no match for '$pattern' (rt-stats);"
    done < <(header "$scene" rt-stats)
    # The era rt decided, from the era line of its --stats block.
    local era want
    era=$(grep -m 1 '^  era ' "$OUT/$rel.log")
    while IFS= read -r want; do
        [ -z "$want" ] && continue
        case "$want" in
            legacy) [[ "$era" == *pre-2015* ]] ||
                problems+=" rt-era: legacy, but rt says '${era:-no era line}';" ;;
            modern) [[ "$era" == *"current framework"* ]] ||
                problems+=" rt-era: modern, but rt says '${era:-no era line}';" ;;
            *) problems+=" rt-era: '$want' is neither legacy nor modern;" ;;
        esac
    done < <(header "$scene" rt-era)
    if [ -n "$problems" ]; then
        fail "$name" "${problems%;}"
        return
    fi
    image_of[$(normpath "$scene")]=$png
    ok "$name ($renders image$([ "$renders" -gt 1 ] && echo s), ${took}s)"
}

# The last chapter in this binary: later chapters' scenes cannot render with it.
last_chapter=$("$RT" --list-features 2>/dev/null | awk '$1 ~ /^[0-9]+$/ && $1 > m {m = $1} END {print m + 0}')

scenes=()
for f in scenes/chapter*.lua scenes/showcase.lua scenes/a4/*.lua scenes/legacy/*.lua; do
    [ -f "$f" ] || continue
    [ -n "$(header "$f" rt-module)" ] && continue
    chapter=$(basename "$f" | sed -n 's/^chapter0*\([0-9][0-9]*\)-.*/\1/p')
    if [ -n "$chapter" ] && [ "$chapter" -gt "$last_chapter" ]; then
        echo "skip ${f%.lua} (chapter $chapter; this binary has chapters 1-$last_chapter)"
        continue
    fi
    scenes+=("$f")
done

for scene in "${scenes[@]}"; do
    render_scene "$scene"
done

# Legacy scenes must give the same picture as their modern equivalent (rt-same-as), byte for byte.
for scene in "${scenes[@]}"; do
    same=$(header "$scene" rt-same-as | head -n 1)
    if [ -z "$same" ] && header "$scene" rt-args | grep -q -- '--legacy'; then
        same=equivalent.lua
    fi
    [ -z "$same" ] && continue
    # Both paths resolved, as where the images were recorded: ../a4/x.lua names scenes/a4/x.lua.
    this=$(normpath "$scene")
    other=$(normpath "$(dirname "$scene")/$same")
    name="${this%.lua} = ${other%.lua}"
    if [ ! -f "$other" ]; then
        fail "$name" "rt-same-as names $same, which is not a file ($other)"
    elif [ -z "${image_of[$this]:-}" ] || [ -z "${image_of[$other]:-}" ]; then
        fail "$name" "one of the two did not render or failed its checks (or is not among the scenes run)"
    elif cmp -s "${image_of[$this]}" "${image_of[$other]}"; then
        ok "$name (byte-identical)"
    else
        fail "$name" "the images differ: ${image_of[$this]} and ${image_of[$other]}"
    fi
done

finish
