#!/usr/bin/env bash
# CTest runs each Catch2 test by name (catch_discover_tests in tests/CMakeLists.txt). A name
# that CMake or Catch2 reads differently from how it was written selects no test, and a run
# of no test would pass. Two checks against that:
#
#   names RAYBOOK_TESTS              no test name holds a character that gets mangled on the
#                                    way: ';' (CMake's list separator, which cuts the name),
#                                    '\' (an escape for Catch2), a leading '#', '~' or '*' or a
#                                    trailing '*' (Catch2's test-spec syntax), or leading or
#                                    trailing blanks. Names the test and its file and line.
#   no-match RAYBOOK_TESTS ARGS...   RAYBOOK_TESTS run with a name that matches no test and
#                                    the ARGS every discovered test gets must exit non-zero.
#
# Exits 1 with a message when a check fails.
set -u
if [ $# -lt 2 ]; then
    echo "usage: $0 names|no-match RAYBOOK_TESTS [ARGS...]" >&2
    exit 2
fi
mode=$1
exe=$2
shift 2

case $mode in
names)
    # With high verbosity each name is followed by "\t@FILE:LINE".
    listing=$("$exe" --list-test-names-only --verbosity high) || true
    [ -n "$listing" ] || { echo "catch_names: $exe listed no tests" >&2; exit 1; }
    bad=0
    count=0
    while IFS= read -r line; do
        name=${line%$'\t@'*}
        where=${line##*$'\t@'}
        count=$((count + 1))
        why=""
        [[ $name == *';'* ]] && why="';' (CMake cuts the name there)"
        [[ $name == *'\'* ]] && why="'\\' (an escape for CMake and Catch2)"
        [[ $name == ['#~*']* ]] && why="'${name:0:1}' at its start (Catch2's test-spec syntax)"
        [[ $name == *'*' ]] && why="'*' at its end (a wildcard in Catch2's test spec)"
        [[ $name == [[:space:]]* || $name == *[[:space:]] ]] && why="a blank at its start or end"
        if [ -n "$why" ]; then
            echo "catch_names: the test \"$name\" ($where) has $why: CTest would run it by a" \
                 "name that selects no test; rename it" >&2
            bad=1
        fi
    done <<<"$listing"
    [ "$count" -gt 0 ] || { echo "catch_names: no test names found in the listing" >&2; exit 1; }
    [ $bad -eq 0 ] || exit 1
    echo "catch_names: $count test names, none mangled by CTest"
    ;;
no-match)
    spec="no test of raybook is named this (catch_names.sh)"
    "$exe" "$spec" "$@" >/dev/null 2>&1
    rc=$?
    if [ $rc -eq 0 ]; then
        echo "catch_names: '$exe \"$spec\" $*' matched no test and exited 0: a discovered test" \
             "whose name selects nothing would pass" >&2
        exit 1
    fi
    echo "catch_names: a run that matches no test exits $rc"
    ;;
*)
    echo "usage: $0 names|no-match RAYBOOK_TESTS [ARGS...]" >&2
    exit 2
    ;;
esac
