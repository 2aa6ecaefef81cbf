#!/usr/bin/env bash
# Bad input: every case must end with exit code 1, exactly one line on stderr that starts with
# "rt: error:", names the scene file (and the line, where one applies) and says what was wrong,
# and must leave no image and no temporary file behind. It must also end in time: a hang is a
# failure.
#
# Usage: bash tests/bad_input/run.sh RT_BINARY OUT_DIR [--every-case]
# Environment: BAD_INPUT_TIMEOUT (hang limit, CPU s), BAD_INPUT_MEMORY_KB (memory cap),
# BAD_INPUT_SKIP (a pattern of scene cases to leave out), RB_SANITIZE=1 (a sanitizer build).
#
# With --every-case a case that this binary would skip is a failure instead: CTest runs the
# suite once with the newest chapter's binary (which skips the later-chapter-* cases whose
# chapter it has) and once with the chapter-3 binary and --every-case (which has none of
# those chapters), so every case is run by at least one test, and a case that no binary runs
# cannot hide among the skips.
#
# The table of cases:
#   cases/*.lua   one broken scene each. Header comments say what to expect:
#                   -- expect: TEXT           the message must contain TEXT (may repeat)
#                   -- reject: TEXT           the message must not contain TEXT (may repeat)
#                   -- rt-args: ARGS          extra command-line arguments (e.g. --legacy)
#                   -- skip-if-feature: NAME  skip when the binary has chapter module NAME
#                                             (the case tests a call of a later chapter)
#                   -- needs-feature: NAME    skip when the binary lacks chapter module NAME
#                                             (the case tests that chapter's own checks; the
#                                             newest chapter's binary always runs it)
#                 The line that must be named in the message ends with the marker "--!".
#   cases/objs/   broken OBJ files, named by the cases that load them (resolved against the
#                 scene's folder, since each case runs in an empty working directory).
#   cases/cli.txt command-line cases: name | expected text | arguments. A name written
#                 "NAME [FEATURE]" is skipped by a binary without chapter module FEATURE.
#
# Each case runs in its own empty folder under OUT_DIR/work/, with the scene given by its
# absolute path; afterwards that folder must still be empty (no PNG, no *.tmp* file).
set -u

every_case=0
if [ $# -eq 3 ] && [ "$3" = "--every-case" ]; then
    every_case=1
elif [ $# -ne 2 ]; then
    echo "usage: $0 RT_BINARY OUT_DIR [--every-case]" >&2
    exit 2
fi
RT=$(realpath "$1")
OUT=$(mkdir -p "$2" && realpath "$2")
HERE=$(cd "$(dirname "$0")" && pwd)
CASES="$HERE/cases"
# A hang is a case that runs past TIMEOUT seconds of CPU (ulimit -t: a loop that never ends),
# or past 6 x TIMEOUT seconds on the clock (a case that waits forever). CPU time, not the clock,
# so that a case slowed by a busy machine is not taken for a hang: endless-loop's billion Lua
# instructions take 8 s of CPU, and took more than 20 s on the clock beside CI's other tests.
TIMEOUT=${BAD_INPUT_TIMEOUT:-20}
# Keep a runaway case from taking the machine down with it (virtual memory, in KiB).
MEMORY_CAP_KB=${BAD_INPUT_MEMORY_KB:-6291456}
# Scene cases to leave out, a shell pattern on the case name (e.g. BAD_INPUT_SKIP='memory-*').
SKIP_PATTERN=${BAD_INPUT_SKIP:-}
# Under the sanitizers (make test-sanitize; CTest sets RB_SANITIZE=1 in that build only):
#  - the hang limit is SANITIZER_SLOWDOWN times longer. AddressSanitizer makes every malloc and
#    free several times slower, and the memory-* cases make tens of millions of them on their way
#    to Lua's 2 GiB limit; LeakSanitizer then walks all those chunks at exit. memory-table takes
#    about 35 s of CPU under the sanitizers, and passed 120 s on a busy machine. A hang still
#    fails, only later. The normal build's limit is unchanged.
#  - the memory cap is ASan's own (hard_rss_limit_mb, on resident memory), not ulimit -v: ASan
#    reserves terabytes of address space for its shadow memory, so a virtual-memory cap would
#    stop every case before it starts.
SANITIZER_SLOWDOWN=10
if [ "${RB_SANITIZE:-0}" = 1 ]; then
    TIMEOUT=$((TIMEOUT * SANITIZER_SLOWDOWN))
    export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=$((MEMORY_CAP_KB / 1024))"
    MEMORY_CAP_KB=unlimited
fi

passed=0
failed=0
skipped=0
features=$("$RT" --list-features 2>/dev/null | awk '{print $2}')

ok() { echo "ok   $1"; passed=$((passed + 1)); }
fail() { echo "FAIL $1: $2"; failed=$((failed + 1)); }

# run_case NAME SCENE_BASENAME MARKER_LINE EXPECTED... [-! REJECTED...] -- ARGS...
# Runs RT with ARGS in an empty folder and checks the result.
run_case() {
    local name=$1 scene=$2 line=$3
    shift 3
    local expected=() rejected=()
    while [ $# -gt 0 ] && [ "$1" != "--" ] && [ "$1" != "-!" ]; do
        expected+=("$1")
        shift
    done
    if [ "${1:-}" = "-!" ]; then
        shift
        while [ $# -gt 0 ] && [ "$1" != "--" ]; do
            rejected+=("$1")
            shift
        done
    fi
    shift  # the "--"
    local work="$OUT/work/$name"
    rm -rf "$work"
    mkdir -p "$work"
    (cd "$work" && ulimit -v "$MEMORY_CAP_KB" && ulimit -t "$TIMEOUT" &&
        exec timeout -k 5 $((6 * TIMEOUT)) "$RT" "$@") >"$OUT/$name.stdout" 2>"$OUT/$name.stderr"
    local rc=$?
    local err
    err=$(cat "$OUT/$name.stderr")
    local lines
    lines=$(wc -l <"$OUT/$name.stderr")
    local leftovers
    leftovers=$(cd "$work" && find . -mindepth 1 | sed 's|^\./||' | tr '\n' ' ')
    local tmps
    tmps=$(find "$CASES" "$HERE/fixtures" -name '*.tmp*' | tr '\n' ' ')

    # 124: the clock's limit (timeout); 152 (SIGXCPU) and 137 (SIGKILL): the CPU limit.
    if [ $rc -eq 124 ] || [ $rc -eq 137 ] || [ $rc -eq 152 ]; then
        fail "$name" "ran past ${TIMEOUT} s of CPU or $((6 * TIMEOUT)) s on the clock (a hang); stderr: ${err:0:200}"
        return
    fi
    if [ $rc -ne 1 ]; then
        fail "$name" "exit code $rc, expected 1; stderr: ${err:0:300}"
        return
    fi
    if [ "$lines" -ne 1 ] || [ "$(wc -c <"$OUT/$name.stderr")" -eq 0 ]; then
        fail "$name" "expected exactly one line on stderr, got $lines: ${err:0:300}"
        return
    fi
    if [[ "$err" != "rt: error: "* ]]; then
        fail "$name" "stderr does not start with 'rt: error: ': $err"
        return
    fi
    if [ -n "$scene" ] && [[ "$err" != *"$scene"* ]]; then
        fail "$name" "the message does not name the scene file $scene: $err"
        return
    fi
    if [ -n "$line" ] && [[ "$err" != *"$scene:$line:"* ]]; then
        fail "$name" "the message does not name the line ($scene:$line:): $err"
        return
    fi
    local e
    for e in "${expected[@]}"; do
        if [[ "$err" != *"$e"* ]]; then
            fail "$name" "the message lacks \"$e\": $err"
            return
        fi
    done
    for e in "${rejected[@]}"; do
        if [[ "$err" == *"$e"* ]]; then
            fail "$name" "the message should not say \"$e\": $err"
            return
        fi
    done
    if [ -n "$leftovers" ]; then
        fail "$name" "files were written: $leftovers"
        return
    fi
    if [ -n "$tmps" ]; then
        fail "$name" "temporary files were left: $tmps"
        return
    fi
    ok "$name"
}

# ---- Broken scenes ------------------------------------------------------------------------
for scene in "$CASES"/*.lua; do
    name=$(basename "$scene" .lua)
    base=$(basename "$scene")
    # shellcheck disable=SC2053  # the pattern is a glob on purpose
    if [ -n "$SKIP_PATTERN" ] && [[ $name == $SKIP_PATTERN ]]; then
        echo "skip $name (BAD_INPUT_SKIP=$SKIP_PATTERN)"
        skipped=$((skipped + 1))
        continue
    fi
    skip_feature=$(sed -n 's/^-- skip-if-feature: *//p' "$scene" | head -n 1)
    if [ -n "$skip_feature" ] && grep -qx "$skip_feature" <<<"$features"; then
        if [ "$every_case" -eq 1 ]; then
            fail "$name" "--every-case, but this binary has $skip_feature, so the case would be skipped; run it with a chapter binary that lacks $skip_feature"
            continue
        fi
        echo "skip $name (this binary has $skip_feature, so the call is valid)"
        skipped=$((skipped + 1))
        continue
    fi
    need_feature=$(sed -n 's/^-- needs-feature: *//p' "$scene" | head -n 1)
    if [ -n "$need_feature" ] && ! grep -qx "$need_feature" <<<"$features"; then
        echo "skip $name (this binary lacks $need_feature, whose checks the case tests)"
        skipped=$((skipped + 1))
        continue
    fi
    # The expected line: the one that ends with the marker "--!".
    line=$(grep -n -- '--!$' "$scene" | head -n 1 | cut -d: -f1)
    mapfile -t expected < <(sed -n 's/^-- expect: *//p' "$scene")
    mapfile -t rejected < <(sed -n 's/^-- reject: *//p' "$scene")
    read -r -a rt_args <<<"$(sed -n 's/^-- rt-args: *//p' "$scene" | head -n 1)"
    if [ ${#expected[@]} -eq 0 ]; then
        fail "$name" "the case has no '-- expect:' line"
        continue
    fi
    run_case "$name" "$base" "$line" "${expected[@]}" -! "${rejected[@]}" -- "${rt_args[@]}" "$scene"
done

# ---- Command-line errors ------------------------------------------------------------------
while IFS='|' read -r name expected args; do
    name=$(echo "$name" | xargs)
    [ -z "$name" ] && continue
    [[ "$name" == \#* ]] && continue
    # "NAME [FEATURE]": the case tests that chapter module's own option; skipped by a binary
    # without it (where the option is unknown), as a scene's needs-feature.
    if [[ "$name" =~ ^([^ ]+)\ \[([a-z_]+)\]$ ]]; then
        name=${BASH_REMATCH[1]}
        if ! grep -qx "${BASH_REMATCH[2]}" <<<"$features"; then
            echo "skip $name (this binary lacks ${BASH_REMATCH[2]}, whose option the case tests)"
            skipped=$((skipped + 1))
            continue
        fi
    fi
    expected=$(echo "$expected" | sed 's/^ *//; s/ *$//')
    args=${args//\{ok\}/$HERE/fixtures/ok.lua}
    args=${args//\{missing\}/$OUT/no-such-scene.lua}
    args=${args//\{fixtures\}/$HERE/fixtures}
    expected=${expected//\{missing\}/$OUT/no-such-scene.lua}
    read -r -a argv <<<"$args"
    run_case "$name" "" "" "$expected" -- "${argv[@]}"
done <"$CASES/cli.txt"

[ "$skipped" -gt 0 ] && echo "($skipped skipped)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
