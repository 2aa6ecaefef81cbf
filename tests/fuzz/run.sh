#!/usr/bin/env bash
# Run each fuzz target for a while, one after the other (make fuzz). Not a test: make test only
# replays the corpus (CTest fuzz_replay.*).
#
# Usage: bash tests/fuzz/run.sh FUZZ_BUILD_DIR SECONDS TARGET...
#
# Each target starts from its seed corpus, tests/fuzz/corpus/TARGET (read only), and keeps what
# it finds in FUZZ_BUILD_DIR/corpus/TARGET, so the committed corpus stays small; a crash, hang,
# leak or sanitizer report is written to FUZZ_BUILD_DIR/artifacts/TARGET-*. The log of each run is
# FUZZ_BUILD_DIR/logs/TARGET.log; the last lines printed are one summary line per target.
set -u
if [ $# -lt 3 ]; then
    echo "usage: $0 FUZZ_BUILD_DIR SECONDS TARGET..." >&2
    exit 2
fi
BUILD=$(realpath "$1")
SECONDS_EACH=$2
shift 2
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$BUILD/logs" "$BUILD/artifacts"

summaries=()
failed=0
for target in "$@"; do
    exe="$BUILD/tests/fuzz/fuzz_$target"
    work="$BUILD/corpus/$target"
    log="$BUILD/logs/$target.log"
    mkdir -p "$work"
    echo "fuzz: $target for ${SECONDS_EACH}s (log: $log)"
    # One process (the machine's cores are shared); a 10 s input is a hang; the scene loader's
    # own limits (tests/fuzz/fuzz_lua_scene.cpp) keep each input far below 2 GiB.
    "$exe" "$work" "$HERE/corpus/$target" \
        -dict="$HERE/$target.dict" \
        -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$BUILD/artifacts/$target-" -print_final_stats=1 >"$log" 2>&1
    rc=$?
    # The last status line holds the coverage (cov: edges, ft: features) and the corpus.
    status=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
    stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -n 1; }
    line="$target: $(stat number_of_executed_units) runs, $(stat average_exec_per_sec) exec/s,"
    line+=" cov $(grep -oE 'cov: [0-9]+' <<<"$status" | cut -d' ' -f2),"
    line+=" ft $(grep -oE 'ft: [0-9]+' <<<"$status" | cut -d' ' -f2),"
    line+=" corpus $(grep -oE 'corp: [0-9]+/[0-9A-Za-z]+' <<<"$status" | cut -d' ' -f2),"
    line+=" peak rss $(stat peak_rss_mb) MB"
    if [ $rc -ne 0 ]; then
        failed=1
        line+=" -- FOUND A PROBLEM (exit $rc): $(grep -m1 -E 'ERROR|runtime error|Timeout|out-of-memory' "$log")"
    fi
    summaries+=("$line")
done
echo
printf 'fuzz: %s\n' "${summaries[@]}"
if [ $failed -ne 0 ]; then
    echo "fuzz: inputs that failed are in $BUILD/artifacts/; replay one with" \
         "$BUILD/tests/fuzz/fuzz_TARGET FILE, then add it to tests/fuzz/regressions/TARGET/" \
         "with the fix (see tests/fuzz/README.md)" >&2
fi
exit $failed
