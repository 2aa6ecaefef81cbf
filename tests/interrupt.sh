#!/usr/bin/env bash
# Stopping early is clean: Ctrl-C (SIGINT) and SIGTERM, sent while a slow scene renders or while
# an endless script runs, and --time-limit, each stop rt promptly with the exit code that says
# why (130, 143, 124), one line on stderr, and no image or temporary file left behind. With
# --partial, the only file left is NAME.partial.png: a whole PNG of the full size, holding the
# tiles finished so far.
# "Promptly" is checked loosely (the slow scene would take minutes; rt must be gone within
# 5 s of the signal, 20 s under the sanitizers, RB_SANITIZE=1, where the one-slow-tile scene's
# pixel alone takes seconds: it took 8 s once beside other work), since this is a
# responsiveness check, not a benchmark.
#
# Usage: bash tests/interrupt.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

# shellcheck source=check_helpers.sh
source "$(dirname "$0")/check_helpers.sh"
rt_and_out_dir "$@"
SLOW="$ROOT/tests/batch/class/student07/stars.lua"
PROMPT=5
[ "${RB_SANITIZE:-0}" = 1 ] && PROMPT=20
ENDLESS="$ROOT/tests/bad_input/cases/endless-loop.lua"

# expect_stop NAME EXPECTED_CODE EXPECTED_TEXT: check the run that just ended in $work.
expect_stop() {
    local name=$1 code=$2 text=$3 rc=$4 took=$5
    local problems=""
    [ "$rc" -eq "$code" ] || problems+=" exit code $rc, expected $code;"
    grep -q -- "$text" "$work/stderr" || problems+=" stderr lacks '$text': $(head -c 200 "$work/stderr");"
    [ "$took" -le "$PROMPT" ] || problems+=" took ${took}s to stop (allowed ${PROMPT}s);"
    leftovers=$(find "$work" -mindepth 1 ! -name stderr ! -name "${keep:-stderr}" | tr '\n' ' ')
    [ -z "$leftovers" ] || problems+=" left behind: $leftovers;"
    if [ -n "$problems" ]; then fail "$name" "${problems%;}"; else ok "$name"; fi
}

# signal_case NAME SIGNAL SCENE CODE TEXT [RT OPTIONS...]: start rt, wait a moment, send the
# signal.
signal_case() {
    local name=$1 signal=$2 scene=$3 code=$4 text=$5
    shift 5
    work="$OUT/$name"
    rm -rf "$work" && mkdir -p "$work"
    (cd "$work" && exec "$RT" --quiet --output out.png "$@" "$scene") 2>"$work/stderr" &
    local pid=$!
    sleep "${SIGNAL_DELAY:-1}"
    local start=$SECONDS
    kill "-$signal" "$pid"
    wait "$pid"
    local rc=$?
    expect_stop "$name" "$code" "$text" "$rc" $((SECONDS - start))
}

signal_case sigint-while-rendering INT "$SLOW" 130 "interrupted (Ctrl-C)"
signal_case sigterm-while-rendering TERM "$SLOW" 143 "terminated (SIGTERM)"
signal_case sigint-while-scripting INT "$ENDLESS" 130 "interrupted (Ctrl-C)"

work="$OUT/time-limit"
rm -rf "$work" && mkdir -p "$work"
start=$SECONDS
(cd "$work" && exec "$RT" --quiet --time-limit 1 --output out.png "$SLOW") 2>"$work/stderr"
rc=$?
expect_stop time-limit 124 "time limit of 1 s" "$rc" $((SECONDS - start - 1))

# --partial: the tiles finished before the signal are kept, under a name that says so. The scene
# puts the camera inside a large sphere lit by ambient light, so every pixel of a finished tile
# is non-black, and takes 64 samples a pixel, so that it is far from done after 2 seconds.
PARTIAL_SCENE="$OUT/inside-sphere.lua"
cat >"$PARTIAL_SCENE" <<'EOF'
local root = gr.node('root')
local s = gr.sphere('s')
s:scale(100, 100, 100)
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 10))
root:add_child(s)
gr.render(root, 'inside.png', 2000, 2000, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60,
          {0.5, 0.5, 0.5}, {gr.light({0, 0, 0}, {0.2, 0.2, 0.2}, {1, 0, 0})})
EOF
keep=out.partial.png
SIGNAL_DELAY=2 signal_case partial-after-sigint INT "$PARTIAL_SCENE" 130 \
    "tiles rendered so far to out.partial.png" --partial --spp 64
keep=
# The partial image is a whole PNG of the scene's full size, and it holds exactly the tiles that
# stderr says were finished: that many 16 x 16 tiles have colour, the rest are black.
tiles=$(grep -o 'wrote the [0-9]* of' "$OUT/partial-after-sigint/stderr" | grep -o '[0-9]*')
if PYTHONPATH="$ROOT/tests" python3 - "$OUT/partial-after-sigint/out.partial.png" 2000x2000 "${tiles:-missing}" <<'PY'
import sys
from png_read import read_png
# A truncated file fails here (tests/png_read.py inflates every IDAT chunk).
width, height, channels, rows = read_png(sys.argv[1])
assert f"{width}x{height}" == sys.argv[2], f"size {width}x{height}, expected {sys.argv[2]}"
assert channels == 3, f"{channels} channels, expected RGB"
lit = sum(1 for ty in range(0, height, 16) for tx in range(0, width, 16)
          if any(rows[y][3 * tx:3 * min(tx + 16, width)].strip(b"\0")
                 for y in range(ty, min(ty + 16, height))))
assert sys.argv[3].isdigit(), "stderr does not say how many tiles were written"
assert int(sys.argv[3]) > 0, "no tile was finished before the signal"
assert lit == int(sys.argv[3]), f"{lit} tiles have colour, stderr says {sys.argv[3]}"
PY
then ok "partial-image-holds-the-finished-tiles"; else
    fail "partial-image-holds-the-finished-tiles" "see above"; fi

# A stop inside a tile: one 16 x 16 tile of 65,536 samples a pixel under 64 lights takes minutes
# (275 s on one thread here). Ctrl-C and --time-limit stop it within a pixel's time, not the
# tile's (each tile asks after every pixel: PixelStop in src/core/interrupt.h), and the half-done
# tile is dropped: --partial writes 0 of 1 tiles, every pixel black. Before the pixels asked, a
# slow scene of the soak (tests/soak/README.md, scene 941) took 230 s to stop at --time-limit 1.
ONE_TILE_SCENE="$OUT/one-slow-tile.lua"
cat >"$ONE_TILE_SCENE" <<'EOF'
local root = gr.node('root')
local s = gr.sphere('s')
s:scale(100, 100, 100)
s:set_material(gr.material({0.5, 0.5, 0.5}, {0, 0, 0}, 10))
root:add_child(s)
local lights = {}
for i = 1, 64 do lights[i] = gr.light({0, 0, i}, {0.01, 0.01, 0.01}, {1, 0, 0}) end
gr.render(root, 'slow.png', 16, 16, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, {0.5, 0.5, 0.5}, lights)
EOF
signal_case sigint-inside-a-tile INT "$ONE_TILE_SCENE" 130 "interrupted (Ctrl-C)" --spp 65536
work="$OUT/time-limit-inside-a-tile"
rm -rf "$work" && mkdir -p "$work"
start=$SECONDS
(cd "$work" && exec "$RT" --quiet --time-limit 1 --partial --spp 65536 --output out.png \
    "$ONE_TILE_SCENE") 2>"$work/stderr"
rc=$?
keep=out.partial.png
expect_stop time-limit-inside-a-tile 124 "wrote the 0 of 1 tiles" "$rc" $((SECONDS - start - 1))
keep=
if PYTHONPATH="$ROOT/tests" python3 - "$work/out.partial.png" <<'PY'
import sys
from png_read import read_png
width, height, channels, rows = read_png(sys.argv[1])
assert (width, height) == (16, 16), f"size {width}x{height}, expected 16x16"
assert not any(row.strip(b"\0") for row in rows), "the half-done tile was kept"
PY
then ok "a-half-done-tile-is-dropped"; else fail "a-half-done-tile-is-dropped" "see above"; fi

finish
