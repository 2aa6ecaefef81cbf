#!/usr/bin/env bash
# Rendering on many processes gives the bytes one process gives: the showcase (every chapter,
# cheap settings, see common.sh) on ranks {1, 2, 3, 4} x threads {1, 2}, compared byte for byte
# with rt run alone; then other seeds and samplers (adaptive antialiasing, chapter 8's pixel
# sampler, and --seed) on 2 and 3 ranks, a static split, and a render to a target error, whose
# --stats line and sample-count heat map on 3 ranks are one process's too.
# Usage: bash tests/mpi/identical.sh RT_BINARY OUT_DIR
set -u
source "$(dirname "$0")/../check_helpers.sh"
source "$(dirname "$0")/common.sh"
rt_and_out_dir "$@"
cd "$OUT" && rm -f ./*.png ./*.journal

# One case: the single-process reference with OPTIONS, then each "RANKS THREADS" pair.
compare() {
    local name=$1 pairs=$2
    shift 2
    "$RT" "$@" --output "$name-ref.png" "$SHOWCASE" || { fail "$name" "rt alone failed"; return; }
    local ranks threads
    for pair in $pairs; do
        read -r ranks threads <<<"${pair/x/ }"
        local image=$name-${ranks}x$threads.png
        if ! timeout 120 "${MPIRUN[@]}" -np "$ranks" "$RT" "$@" --threads "$threads" \
            --output "$image" "$SHOWCASE"; then
            fail "$name $ranks ranks x $threads threads" "mpirun failed"
        elif ! cmp -s "$name-ref.png" "$image"; then
            fail "$name $ranks ranks x $threads threads" "$image differs from one process's"
        elif [ -e "$image.journal" ]; then
            fail "$name $ranks ranks x $threads threads" "the journal was left after the image"
        else
            ok "$name $ranks ranks x $threads threads: the same bytes as one process"
        fi
    done
}

# The sizes are halved under the sanitizers (SHRINK, common.sh), and the showcase there takes
# each rank count and each thread count once, not every pair: what they check is the code each
# case runs.
PAIRS="1x1 1x2 2x1 2x2 3x1 3x2 4x1 4x2"
[ "$SHRINK" = 2 ] && PAIRS="1x2 2x1 3x2 4x1"
compare showcase "$PAIRS" "${SHOWCASE_OPTIONS[@]}" \
    --size $((128 / SHRINK))x$((80 / SHRINK))
compare adaptive-seed7 "2x2 3x1" --quiet --size $((96 / SHRINK))x$((64 / SHRINK)) --aa=adaptive \
    --light-samples=1 --glossy-samples=1 --dof-samples=1 --photon-passes=1 --photons=20000 --seed 7
compare static "3x1" "${SHOWCASE_OPTIONS[@]}" --size $((96 / SHRINK))x$((64 / SHRINK)) \
    --mpi-lease static
# Rendering to an error: the ranks share the pilot (each takes every size-th tile), then every
# pixel's planned samples; the same bytes as one process.
TARGET=(--quiet --size 48x32 --target-error 0.05 --light-samples=1 --glossy-samples=1
        --photon-passes=1 --photons=20000)
compare target-error "1x2 3x1" "${TARGET[@]}"
# What it spent and estimated: rank 0 gathers each rank's samples, so --stats says what one
# process says and --aov sample-count draws the same heat map.
"$RT" "${TARGET[@]}" --stats --aov sample-count --output spent-ref.png "$SHOWCASE" 2>spent-ref.txt
timeout 120 "${MPIRUN[@]}" -np 3 "$RT" "${TARGET[@]}" --threads 1 --stats --aov sample-count \
    --output spent-3.png "$SHOWCASE" 2>spent-3.txt
spent=$(grep -h '^  samples ' spent-ref.txt)
if [ -z "$spent" ] || [ "$spent" != "$(grep -h '^  samples ' spent-3.txt)" ]; then
    fail "target-error --stats on 3 ranks" "one process: '$spent'; 3 ranks: '$(grep -h '^  samples ' spent-3.txt)'"
elif ! cmp -s spent-ref.samples.png spent-3.samples.png; then
    fail "target-error --aov sample-count on 3 ranks" "the heat map differs from one process's"
else
    ok "target-error on 3 ranks: --stats says what one process says ($(echo $spent)), and the heat map is the same bytes"
fi
finish
