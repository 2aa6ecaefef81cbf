#!/usr/bin/env bash
# Stopping early is clean: Ctrl-C (SIGINT) and SIGTERM, sent while a slow scene renders or while
# an endless script runs, and --time-limit, each stop rt promptly with the exit code that says
# why (130, 143, 124), one line on stderr, and no image or temporary file left behind. With
# --partial, the only file left is NAME.partial.png: a whole PNG of the full size, holding the
# tiles finished so far.
# "Promptly" is checked loosely (the slow scene would take minutes; rt must be gone within
# 5 s of the signal), since this is a responsiveness check, not a benchmark.
#
# Usage: bash tests/interrupt.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

if [ $# -ne 2 ]; then
    echo "usage: $0 RT_BINARY OUT_DIR" >&2
    exit 2
fi
RT=$(realpath "$1")
OUT=$(mkdir -p "$2" && realpath "$2")
ROOT=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=check_helpers.sh
source "$ROOT/tests/check_helpers.sh"
SLOW="$ROOT/tests/batch/class/student07/stars.lua"
ENDLESS="$ROOT/tests/bad_input/cases/endless-loop.lua"

# expect_stop NAME EXPECTED_CODE EXPECTED_TEXT: check the run that just ended in $work.
expect_stop() {
    local name=$1 code=$2 text=$3 rc=$4 took=$5
    local problems=""
    [ "$rc" -eq "$code" ] || problems+=" exit code $rc, expected $code;"
    grep -q -- "$text" "$work/stderr" || problems+=" stderr lacks '$text': $(head -c 200 "$work/stderr");"
    [ "$took" -le 5 ] || problems+=" took ${took}s to stop;"
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
    sleep 1
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

# --partial: the tiles finished before the signal are kept, under a name that says so.
keep=out.partial.png
signal_case partial-after-sigint INT "$SLOW" 130 "tiles rendered so far to out.partial.png" --partial
keep=
# The partial image is a complete PNG of the scene's full size (the tiles not reached are black),
# and it is not all black: the tiles finished in the first second are in it.
size=$(grep -o 'gr.render([^,]*, *[^,]*, *[0-9]*, *[0-9]*' "$SLOW" | grep -o '[0-9]*, *[0-9]*$' | tr -d ' ' | tr , x)
if python3 - "$OUT/partial-after-sigint/out.partial.png" "$size" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
width, height = struct.unpack(">II", data[16:24])
assert f"{width}x{height}" == sys.argv[2], f"size {width}x{height}, expected {sys.argv[2]}"
# Concatenate the IDAT chunks and inflate them: a truncated file fails here.
pos, idat = 8, b""
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + length]
    pos += 12 + length
raw = zlib.decompress(idat)
assert len(raw) == (3 * width + 1) * height, "wrong amount of pixel data"
assert any(b for i, b in enumerate(raw) if i % (3 * width + 1) != 0), "all black"
PY
then ok "partial-image-is-a-whole-png"; else fail "partial-image-is-a-whole-png" "see above"; fi

finish
