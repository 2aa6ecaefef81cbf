#!/usr/bin/env bash
# make soak: N random legal scenes of every chapter (tests/soak/scene_gen.py), each rendered by
# the sanitizer build's rt on one thread and on two, with the scene's random --max-memory and
# --time-limit, and checked by soak_film for NaN, infinite and negative pixels.
#
#   bash tests/soak/soak.sh SANITIZE_BUILD N SEED [WORK [FIRST]]
#
# renders scenes FIRST to FIRST + N - 1 of SEED (FIRST 0 by default; scene i is the same for
# any N and FIRST, so one scene replays alone with N = 1 and FIRST = i).
#
# For each scene:
#   - soak_film renders it in-process (no limits) and finds every channel of the film finite and
#     non-negative, and after the tone map in [0, 1] (rt's writers store a NaN as 0, so the
#     files cannot show one);
#   - rt_chN --threads 1 and --threads 2 (run side by side) each end in one of three ways: the
#     image (exit 0); a refusal under a tight --max-memory (under 1 GiB: exit 1 with one
#     "rt: error:" line); stopped by --time-limit (exit 124). Anything else is a failure: another
#     exit code, a signal, a sanitizer report (exit 66, or its text on stderr), an error at an
#     ample limit (the scene is legal, so the generator or rt is wrong);
#   - when both renders finish, the two PNGs are the same bytes.
# A failure keeps the scene and both logs under WORK/failures/ and prints the command that
# replays it. The last line counts scenes, outcomes and seconds; the exit code is 1 on any
# failure.
set -uo pipefail

build=${1:?usage: soak.sh SANITIZE_BUILD N SEED [WORK [FIRST]]}
count=${2:?N}
seed=${3:?SEED}
work=${4:-$build/soak}
first_scene=${5:-0}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
rt=$(ls "$build"/rt_ch[0-9]* 2>/dev/null | sort -V | tail -n 1)
film=$build/tests/soak/soak_film
[ -x "$rt" ] && [ -x "$film" ] || {
    echo "soak: no $build/rt_chN or $film: make soak builds them" >&2
    exit 2
}
# The sanitizers' settings of make test-sanitize, unless the caller gave its own.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:exitcode=66:detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:exitcode=66:print_stacktrace=1}

rm -rf "$work"
mkdir -p "$work/scenes" "$work/out" "$work/failures"
python3 "$here/scene_gen.py" --root "$root" --out "$work/scenes" --seed "$seed" --count "$count" \
    --first "$first_scene" || exit 2
start=$SECONDS
failures=0 compared=0 refused=0 stopped=0 done_scenes=0

# fail SCENE WHY [LOG...]: keep the scene and the logs, and say how to replay it.
fail() {
    local scene=$1 why=$2
    shift 2
    failures=$((failures + 1))
    local kept="$work/failures/$(basename "$scene")"
    cp "$scene" "$kept"
    local index=$(basename "$scene" .lua)
    # Each log under the scene's name (soak_film's is shared by the scenes of its batch).
    for log in "$@"; do
        local copy=$(basename "$log")
        [[ $copy == "$index"* ]] || copy="$index-$copy"
        cp "$log" "$work/failures/$copy"
    done
    index=$((10#${index#scene-}))
    echo "FAIL $(basename "$scene"): $why"
    echo "  scene kept: $kept (logs beside it)"
    echo "  replay:     bash tests/soak/soak.sh $build 1 $seed $work-replay $index"
    echo "  or rt:      $(sed -n '1s/^-- soak scene [0-9]* of seed [0-9]*: chapter [0-9]*, //p' "$scene" |
                          sed "s|^|$rt --threads 1 |") --output /tmp/soak.png $kept"
}

# The pixel check, for a list of scenes (path and feature list, two words each). A crash or a
# sanitizer report names the scene it was checking; the scenes after it are checked again.
check_films() {
    local -a pairs=("$@")
    while [ ${#pairs[@]} -gt 0 ]; do
        local log="$work/out/film.log"
        # A scene still rendering after 600 s (the slowest of the first 2,000 took about a
        # minute) is a hang or a pathological slowdown: it fails, the rest are checked again.
        timeout -s KILL 600 "$film" "${pairs[@]}" >"$log" 2>&1
        local rc=$?
        while read -r verdict scene why; do
            [ "$verdict" = BAD ] && fail "${scene%:}" "soak_film: $why" "$log"
        done < <(grep -E '^(BAD) ' "$log")
        local checked
        checked=$(grep -c '^checking ' "$log")
        if [ $rc -eq 0 ] || [ $rc -eq 1 ] || [ $rc -eq 3 ]; then
            return
        fi
        # Crashed in the last scene it named: that one fails, the rest are checked again.
        local last
        last=$(grep '^checking ' "$log" | tail -n 1 | cut -d' ' -f2)
        if [ $rc = 137 ]; then
            fail "${last:-${pairs[0]}}" "soak_film was still rendering after 600 s (killed)" "$log"
        else
            fail "${last:-${pairs[0]}}" "soak_film ended with exit code $rc (a crash or a sanitizer report)" "$log"
        fi
        pairs=("${pairs[@]:$((2 * (checked > 0 ? checked : 1)))}")
    done
}

# judge SCENE THREADS RC LOG MEMORY: is this ending of rt one a legal scene may have?
judge() {
    local scene=$1 threads=$2 rc=$3 log=$4 memory=$5
    if grep -qE 'Sanitizer|runtime error:' "$log"; then
        fail "$scene" "--threads $threads: a sanitizer report (exit $rc)" "$log"
        return 1
    fi
    case $rc in
        0) return 0 ;;
        124) grep -q -- '--time-limit' "$log" && return 0 ;;
        1) if [[ $memory == *M ]] && [ "$(grep -c '^rt: error:' "$log")" = 1 ]; then return 0; fi ;;
    esac
    fail "$scene" "--threads $threads: exit code $rc ($(grep -m1 '^rt: error:' "$log" || echo 'no message'))" "$log"
    return 1
}

chunk=25
mapfile -t lines <"$work/scenes/index.txt"
for ((first = 0; first < ${#lines[@]}; first += chunk)); do
    pairs=()
    for line in "${lines[@]:first:chunk}"; do
        read -r scene chapter features memory seconds <<<"$line"
        pairs+=("$scene" "$features")
    done
    check_films "${pairs[@]}"
    for line in "${lines[@]:first:chunk}"; do
        read -r scene chapter features memory seconds <<<"$line"
        name=$(basename "$scene" .lua)
        pids=()
        for t in 1 2; do
            # A render past its --time-limit by far (or a hang) is killed, and fails.
            timeout -s KILL $((seconds + 120)) "$rt" --quiet --threads $t --features="$features" \
                --max-memory "$memory" --time-limit "$seconds" \
                --output "$work/out/$name-t$t.png" "$scene" >"$work/out/$name-t$t.log" 2>&1 &
            pids+=($!)
        done
        wait "${pids[0]}"; rc1=$?
        wait "${pids[1]}"; rc2=$?
        ok=1
        judge "$scene" 1 $rc1 "$work/out/$name-t1.log" "$memory" || ok=0
        judge "$scene" 2 $rc2 "$work/out/$name-t2.log" "$memory" || ok=0
        [ $rc1 = 1 ] || [ $rc2 = 1 ] && refused=$((refused + 1))
        [ $rc1 = 124 ] || [ $rc2 = 124 ] && stopped=$((stopped + 1))
        if [ $ok = 1 ] && [ $rc1 = 0 ] && [ $rc2 = 0 ]; then
            if cmp -s "$work/out/$name-t1.png" "$work/out/$name-t2.png"; then
                compared=$((compared + 1))
            else
                fail "$scene" "the images of --threads 1 and --threads 2 differ" \
                    "$work/out/$name-t1.png" "$work/out/$name-t2.png"
            fi
        fi
        [ $ok = 1 ] && rm -f "$work/out/$name"-t[12].*
        done_scenes=$((done_scenes + 1))
    done
    echo "soak: $done_scenes of $count scenes, $failures failures, $((SECONDS - start)) s"
done
echo "soak: $done_scenes scenes of seed $seed in $((SECONDS - start)) s: $compared rendered on" \
     "1 and 2 threads to the same bytes, $refused refused by --max-memory, $stopped stopped" \
     "by --time-limit (on either thread count), $failures failures"
[ $failures = 0 ]
