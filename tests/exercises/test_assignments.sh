#!/usr/bin/env bash
# make test-assignments: the assignments' round trip (assignment.py roundtrip), and beside it
# make grade's tests (grade_test.sh) and the Monte Carlo goldens (mc_golden.py).
#
# The three are independent (each exports into a folder of its own under BUILD; they share only
# the compiler cache), and none keeps the 2-core machine busy alone: a round-trip step compiles
# one or two files, links and runs its tests one process at a time; the grade test grades one
# student at a time; the Monte Carlo goldens build one binary and render. Run one after the
# other they left a core idle for much of the stage. So the grade test and the Monte Carlo
# goldens run side by side with the round trip, each into its own log (BUILD/grade-test.log,
# BUILD/mc-golden.log), printed when it ends; the stage fails when any of the three fails.
#
# Usage: bash tests/exercises/test_assignments.sh BUILD [--stamps]
#   --stamps   (make test without FULL=1) skip round-trip chapters, and the grade test and the
#              Monte Carlo goldens, unchanged since they passed (tests/exercises/stamps.py);
#              record those that pass.
set -u
[[ $# -ge 1 && $# -le 2 ]] || { echo "usage: $0 BUILD [--stamps]" >&2; exit 2; }
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=$(realpath -m "$1")
STAMPS=${2:-}
STAMPS_PY=(python3 "$HERE/stamps.py")

grading=1
if [[ -n $STAMPS ]] && ! "${STAMPS_PY[@]}" stale "$BUILD" grading suite; then
    grading=""
    echo "skip make grade's tests: nothing outside the chapter modules changed since they" \
         "passed (make test FULL=1 runs them)"
fi

pids=()
# An interrupted or failing make test takes the side jobs with it.
trap 'for p in "${pids[@]}"; do kill -- "-$p" 2>/dev/null || kill "$p" 2>/dev/null; done' EXIT
if [[ -n $grading ]]; then
    mkdir -p "$BUILD"
    setsid bash "$HERE/grade_test.sh" "$BUILD/grade-test" >"$BUILD/grade-test.log" 2>&1 &
    grade_pid=$!
    setsid python3 "$HERE/mc_golden.py" "$BUILD/mc-golden" >"$BUILD/mc-golden.log" 2>&1 &
    mc_pid=$!
    pids=("$grade_pid" "$mc_pid")
    echo "make grade's tests and the Monte Carlo goldens run beside the round trip" \
         "(logs: $BUILD/grade-test.log, $BUILD/mc-golden.log)"
fi

status=0
python3 "$HERE/assignment.py" roundtrip "$BUILD/assignments" ${STAMPS:+--stamps "$BUILD"} ||
    status=1

if [[ -n $grading ]]; then
    grading_ok=1
    for job in "grade-test $grade_pid make grade's tests" "mc-golden $mc_pid the Monte Carlo goldens"; do
        read -r log pid what <<<"$job"
        if wait "$pid"; then
            echo "--- $what: ok ($BUILD/$log.log)"
            cat "$BUILD/$log.log"
        else
            echo "--- $what: FAILED ($BUILD/$log.log)"
            cat "$BUILD/$log.log"
            grading_ok=""
            status=1
        fi
    done
    if [[ -n $grading_ok && -n $STAMPS ]]; then
        "${STAMPS_PY[@]}" record "$BUILD" grading suite
    fi
fi
pids=()
trap - EXIT
exit "$status"
