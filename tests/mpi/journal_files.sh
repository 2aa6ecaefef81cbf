#!/usr/bin/env bash
# The journal names every file the scene reads, by content: a copy of the showcase (its
# texture poster.png, its density file plume.nvdb, its meshes) is killed halfway on 2 ranks; its
# journal lists each file; then, with the texture replaced by another image and with one byte of
# the density file's voxels changed, --resume ends with one line naming the file that changed,
# exit 1, no image and the journal as it was. With the files back as they were, --resume is
# accepted (it reuses the journal's tiles; a time limit cuts it short).
# Usage: bash tests/mpi/journal_files.sh RT_BINARY OUT_DIR
set -u
source "$(dirname "$0")/../check_helpers.sh"
source "$(dirname "$0")/common.sh"
rt_and_out_dir "$@"
cd "$OUT" && rm -rf ./*

mkdir scene && cp "$SHOWCASE" scene/ && cp -r "$ROOT/scenes/assets" scene/
SCENE=$OUT/scene/showcase.lua
OPTIONS=("${SHOWCASE_OPTIONS[@]}" --threads 1 --size 384x240 "$SCENE")
kill_halfway 2 1 $((384 * 240 * 12)) out.png "${OPTIONS[@]}" >/dev/null ||
    fail "setup" "the render ended before it could be killed"
cp out.png.journal saved.journal

files="assets/textures/wood.jpg assets/textures/poster.png assets/textures/plane.obj assets/icosa.obj assets/plume.nvdb"
missing=""
for f in $files; do
    grep -aq "^file $f=$(stat -c %s "scene/$f") bytes, hash " out.png.journal || missing="$missing $f"
done
if [ -n "$missing" ]; then fail "the journal's header" "does not name:$missing"
else ok "the journal names the scene's $(echo $files | wc -w) files by size and hash"; fi

# changed NAME FILE: --resume must fail once, naming FILE, and change nothing.
changed() {
    local name=$1 file=$2
    timeout 60 "${MPIRUN[@]}" -np 2 "$RT" "${OPTIONS[@]}" --resume --output out.png 2>"$name.txt"
    local rc=$? lines
    lines=$(grep -c '^rt: error:' "$name.txt")
    if [ $rc -ne 1 ] || [ "$lines" -ne 1 ] ||
        ! grep -q "^rt: error: --resume: $file changed since the journal .*out.png.journal was written" "$name.txt"; then
        fail "$name" "exit $rc, $lines error lines: $(cat "$name.txt")"
    elif [ -e out.png ] || ! cmp -s out.png.journal saved.journal; then
        fail "$name" "an image was written or the journal changed"
    else
        ok "$name refused: $(grep '^rt: error:' "$name.txt" | cut -c1-140)..."
    fi
}
cp scene/assets/textures/poster.png poster.saved
cp scene/assets/textures/cup.png scene/assets/textures/poster.png
changed "another texture" assets/textures/poster.png
cp poster.saved scene/assets/textures/poster.png
cp scene/assets/plume.nvdb plume.saved
# One byte of the last voxels (the grid's leaf values end the file): still a valid density.
size=$(stat -c %s plume.saved)
printf '\x3f' | dd of=scene/assets/plume.nvdb bs=1 seek=$((size - 64)) conv=notrunc status=none
changed "another density file" assets/plume.nvdb
cp plume.saved scene/assets/plume.nvdb

timeout 60 "${MPIRUN[@]}" -np 2 "$RT" "${OPTIONS[@]}" --resume --time-limit 1 --output out.png \
    2>accepted.txt
if grep -q "^rt: --resume: reused [1-9][0-9]* of 360 tiles" accepted.txt; then
    ok "the same files: --resume accepted ($(grep -o 'reused [0-9]* of 360' accepted.txt))"
else
    fail "the same files" "--resume was not accepted: $(cat accepted.txt)"
fi
finish
