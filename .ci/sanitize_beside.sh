#!/usr/bin/env bash
# CI (.ci/run): the sanitizer tree beside make test. It builds at the idle priority (SCHED_IDLE),
# marks itself built (build-sanitize/.built), then runs its unit tests and golden images one at
# a time at nice 19 (into build-sanitize/unit.log). Exit status: the build's, else the tests'.
set -uo pipefail
cd "$(dirname "$0")/.."
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
