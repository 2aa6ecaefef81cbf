#!/usr/bin/env bash
# A journal from another render is refused: a render killed halfway leaves a journal of the
# showcase at 256x160 (128x80 under the sanitizers: SHRINK, common.sh), seed 0; --resume with
# another seed, size or scene, a journal whose rt version differs, and a file that is no journal
# each end with one clear message naming what differs, exit code 1 and no image, and leave the
# journal as it was. The right --resume then still finishes the image byte-identical to one
# process's.
# Usage: bash tests/mpi/journal_refused.sh RT_BINARY OUT_DIR
set -u
source "$(dirname "$0")/../check_helpers.sh"
source "$(dirname "$0")/common.sh"
rt_and_out_dir "$@"
cd "$OUT" && rm -f ./*.png ./*.journal ./*.txt

OPTIONS=("${SHOWCASE_OPTIONS[@]}" --light-samples=3 --threads 1)
W=$((256 / SHRINK)) H=$((160 / SHRINK))
# kill_resume.sh's reference, shared when CTest gives MPI_REFERENCES (common.sh): the same
# options, size and scene, in the same order (the thread count changes no bit).
REFERENCE=("${SHOWCASE_OPTIONS[@]}" --light-samples=3 --size ${W}x$H "$SHOWCASE")
SIZE=${W}x$H TALLER=${W}x$((H + 16))
kill_halfway 2 1 $((W * H * 12)) out.png "${OPTIONS[@]}" --size $SIZE "$SHOWCASE" \
    >/dev/null || fail "setup" "the render ended before it could be killed"
cp out.png.journal saved.journal

# refused NAME WORD ARGS...: --resume with ARGS must fail once, naming WORD, and change nothing.
refused() {
    local name=$1 word=$2
    shift 2
    timeout 60 "${MPIRUN[@]}" -np 2 "$RT" "${OPTIONS[@]}" --resume --output out.png "$@" \
        2>"$name.txt"
    local rc=$? lines
    lines=$(grep -c '^rt: error:' "$name.txt")
    if [ $rc -ne 1 ] || [ "$lines" -ne 1 ] || ! grep -q "^rt: error: .*$word" "$name.txt"; then
        fail "$name" "exit $rc, $lines error lines: $(cat "$name.txt")"
    elif [ -e out.png ] || ! cmp -s out.png.journal saved.journal; then
        fail "$name" "an image was written or the journal changed"
    else
        ok "$name refused: $(grep '^rt: error:' "$name.txt")"
    fi
}
refused "another seed" "another render: seed 0, this render has 3" --size $SIZE --seed 3 "$SHOWCASE"
refused "another size" "another render: size $SIZE, this render has $TALLER" --size $TALLER "$SHOWCASE"
other=$OUT/other-scene.lua
sed 's/0\.12/0.125/' "$SHOWCASE" >"$other"  # a wider aperture: another scene
refused "another scene" "another render: scene" --size $SIZE --assets "$ROOT/scenes" "$other"
sed -i '2s/^version=.*/version=0.0.1 (commit 0000000)/' out.png.journal
cp out.png.journal saved.journal
refused "another rt version" "another render: version 0.0.1" --size $SIZE "$SHOWCASE"
cp saved.journal old.journal
echo "not a journal" >out.png.journal && cp out.png.journal saved.journal
refused "a file that is no journal" "not a raybook tile journal" --size $SIZE "$SHOWCASE"

# The kept journal still finishes the image.
kill_halfway 2 1 $((W * H * 12)) out.png "${OPTIONS[@]}" --size $SIZE "$SHOWCASE" \
    >/dev/null || fail "setup" "the render ended before it could be killed"
reference reference.png "${REFERENCE[@]}"
if timeout 300 "${MPIRUN[@]}" -np 2 "$RT" "${OPTIONS[@]}" --resume --size $SIZE \
    --output out.png "$SHOWCASE" && cmp -s out.png reference.png; then
    ok "the right --resume finishes the image byte-identical to one process's"
else
    fail "the right --resume" "failed or gave other bytes"
fi
finish
