#!/usr/bin/env bash
# CI (.ci/run): the WebAssembly tree and the sanitizer tree beside make test. First make web:
# emscripten and Chromium installed (at the normal priority: apt mostly waits on the network and
# the disk), then rt_web built at the idle priority (SCHED_IDLE). make test's own make web, at
# the start of its whole-book stage, waits for this one (build-web/.lock) and finds the tree
# built; should this one fail, make test's says why. Then the sanitizer tree builds at the idle
# priority, marks itself built (build-sanitize/.built), and runs its unit tests and golden
# images one at a time at nice 19 (into build-sanitize/unit.log). Exit status: the sanitizer
# build's, else its tests'.
set -uo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
{ make --no-print-directory web-deps && chrt --idle 0 make --no-print-directory web; } \
    >build-sanitize/web.log 2>&1 || echo "make web failed beside make test (build-sanitize/web.log)"
echo "make web took $((SECONDS - start)) s beside make test"
start=$SECONDS
chrt --idle 0 make sanitize-build >build-sanitize/build.log 2>&1 || exit 1
touch build-sanitize/.built
echo "make sanitize-build took $((SECONDS - start)) s beside make test"
start=$SECONDS
nice -n 19 make --no-print-directory sanitize-ctest SANITIZE_CTEST="-j 1 -L 'unit|golden'" \
    >build-sanitize/unit.log 2>&1
status=$?
echo "its unit tests and golden images took $((SECONDS - start)) s (exit $status)" >>build-sanitize/unit.log
exit $status
