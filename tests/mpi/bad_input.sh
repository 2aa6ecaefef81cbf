#!/usr/bin/env bash
# Bad input on any rank ends the whole job with one clear message and exit code 1, and no rank
# hangs (each run has a time limit) or leaves an image or a journal: a broken scene on every
# rank, on rank 1 only and on rank 0 only (mpirun's MPMD form gives ranks different command
# lines), a photon pass over the memory limit on rank 1 only, ranks given different seeds, an output folder that does not exist, and bad options.
# Usage: bash tests/mpi/bad_input.sh RT_BINARY OUT_DIR
set -u
source "$(dirname "$0")/../check_helpers.sh"
source "$(dirname "$0")/common.sh"
rt_and_out_dir "$@"
cd "$OUT" && rm -rf ./*.png ./*.journal ./*.txt
cat >broken.lua <<'LUA'
root = gr.node('root')
gr.render(root, 'broken.png', 32, 32, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},
          {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
error('the student forgot an end')
LUA
GOOD=("${SHOWCASE_OPTIONS[@]}" --size 64x40 --output good.png "$SHOWCASE")

# expect NAME PATTERN MPIRUN-ARGS...: exit code 1 within the time limit, exactly one "rt:" line
# on stderr, matching PATTERN, and no image or journal left.
expect() {
    local name=$1 pattern=$2
    shift 2
    timeout 60 "${MPIRUN[@]}" "$@" 2>"$OUT/$name.txt" >/dev/null
    local rc=$? lines
    lines=$(grep -c '^rt:' "$OUT/$name.txt")
    if [ $rc -eq 124 ]; then
        fail "$name" "still running after 60 s"
    elif [ $rc -ne 1 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$pattern" "$OUT/$name.txt"; then
        fail "$name" "exit code $rc, $lines rt lines: $(head -c 600 "$OUT/$name.txt")"
    elif ls ./*.png ./*.journal >/dev/null 2>&1; then
        fail "$name" "left $(ls ./*.png ./*.journal 2>/dev/null | tr '\n' ' ')"
    else
        ok "$name: exit 1 in ${SECONDS}s, one line: $(grep '^rt:' "$OUT/$name.txt")"
    fi
    SECONDS=0
}
SECONDS=0
expect "broken scene on 3 ranks" "the student forgot an end" -np 3 "$RT" --quiet broken.lua
expect "broken scene on rank 1 only" "the student forgot an end" \
    -np 1 "$RT" "${GOOD[@]}" : -np 2 "$RT" --quiet broken.lua
expect "broken scene on rank 0 only" "the student forgot an end" \
    -np 1 "$RT" --quiet broken.lua : -np 2 "$RT" "${GOOD[@]}"
expect "a photon pass over --max-memory on rank 1 only, while rank 0 traces its share" \
    "photon pass 1 (200000 photons) needs about" \
    -np 1 "$RT" "${GOOD[@]}" --photons=200000 : -np 1 "$RT" "${GOOD[@]}" --photons=200000 --max-memory 128M
expect "ranks given different seeds" "the ranks were given different renders" \
    -np 1 "$RT" "${GOOD[@]}" --seed 1 : -np 1 "$RT" "${GOOD[@]}" --seed 2
expect "an output folder that does not exist" "does not exist" \
    -np 2 "$RT" "${SHOWCASE_OPTIONS[@]}" --output no/such/folder.png "$SHOWCASE"
expect "a bad option" "--mpi-lease: expected dynamic or static" \
    -np 2 "$RT" --mpi-lease sometimes "$SHOWCASE"
expect "a --tile-timeout that is no time" "--tile-timeout: expected seconds above 0 and at most 86400" \
    -np 2 "$RT" --tile-timeout=inf "$SHOWCASE"
finish
