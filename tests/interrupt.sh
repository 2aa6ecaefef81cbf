#!/usr/bin/env bash
# Stopping early is clean: Ctrl-C (SIGINT) and SIGTERM, sent while a slow scene renders or while
# an endless script runs, and --time-limit, each stop rt promptly with the exit code that says
# why (130, 143, 124), one line on stderr, and no image or temporary file left behind.
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
    leftovers=$(find "$work" -mindepth 1 ! -name stderr | tr '\n' ' ')
    [ -z "$leftovers" ] || problems+=" left behind: $leftovers;"
    if [ -n "$problems" ]; then fail "$name" "${problems%;}"; else ok "$name"; fi
}

# signal_case NAME SIGNAL SCENE CODE TEXT: start rt, wait a moment, send the signal.
signal_case() {
    local name=$1 signal=$2 scene=$3 code=$4 text=$5
    work="$OUT/$name"
    rm -rf "$work" && mkdir -p "$work"
    (cd "$work" && exec "$RT" --quiet --output out.png "$scene") 2>"$work/stderr" &
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

finish
