#!/usr/bin/env bash
# --preview (CTest: preview): rt renders a scene at a quarter of each side of the size it asks
# for, says so in one line on stderr (none with --quiet), and gives the same bytes every run and
# for any thread count. The scene is written here (two spheres, 256 x 192), so the test runs in
# every chapter's build and every exported assignment; see below for chapter 6's.
#
# Usage: bash tests/preview.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

# shellcheck source=check_helpers.sh
source "$(dirname "$0")/check_helpers.sh"
rt_and_out_dir "$@"

scene="$OUT/scene.lua"
cat >"$scene" <<'EOF'
root = gr.node('root')
local red = gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 25)
local ball = gr.sphere('ball')
ball:set_material(red)
ball:scale(1.5, 1, 1)
ball:translate(-1, 0, -4)
root:add_child(ball)
local other = gr.sphere('other')
other:set_material(red)
other:translate(2, 0.5, -6)
root:add_child(other)
gr.render(root, 'scene.png', 256, 192, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2},
          {gr.light({5, 5, 5}, {1, 1, 1}, {1, 0, 0})})
EOF

# With chapter 6, its scene instead (also 256 x 192): its area lights' shadow rays are random
# samples, which the preview cuts to one each, so the same bytes twice mean something there.
ch6="$ROOT/scenes/chapter06-soft-shadows.lua"
if "$RT" --list-features | grep -q soft_shadows && [ -f "$ch6" ] && grep -q "256, 192" "$ch6"; then
    scene=$ch6
fi

# The width and height in a PNG's header (bytes 16 to 23, big-endian).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8 }'; }

"$RT" --preview --threads 1 --output "$OUT/one.png" "$scene" 2>"$OUT/one.stderr"
rc=$?
"$RT" --preview --threads 2 --quiet --output "$OUT/two.png" "$scene" 2>"$OUT/two.stderr"
rc2=$?
if [ $rc -ne 0 ] || [ $rc2 -ne 0 ]; then
    fail run "exit codes $rc and $rc2: $(head -c 300 "$OUT/one.stderr" "$OUT/two.stderr")"
    finish
    exit
fi
size=$(png_size "$OUT/one.png")
# Source: a quarter of 256 x 192.
[ "$size" = 64x48 ] && ok "a quarter of each side: $size" || fail size "$size, expected 64x48"
cmp -s "$OUT/one.png" "$OUT/two.png" && ok "the same bytes with 1 and 2 threads" ||
    fail determinism "one.png and two.png differ"
"$RT" --preview --threads 1 --quiet --output "$OUT/again.png" "$scene" 2>/dev/null
cmp -s "$OUT/one.png" "$OUT/again.png" && ok "the same bytes run after run" ||
    fail repeat "one.png and again.png differ"
grep -q '^rt: preview: 64x48 (a quarter of 256x192), --spp 1' "$OUT/one.stderr" &&
    ok "one line says it is a preview" ||
    fail line "no 'rt: preview: 64x48 (a quarter of 256x192), --spp 1' line: $(head -c 300 "$OUT/one.stderr")"
[ "$(grep -c '^rt: preview:' "$OUT/one.stderr")" -eq 1 ] || fail line-count "more than one preview line"
grep -q 'preview' "$OUT/two.stderr" && fail quiet "--quiet still prints: $(cat "$OUT/two.stderr")" ||
    ok "--quiet keeps it off stderr"
# --size wins over the preview's quarter.
"$RT" --preview --size 20x10 --quiet --output "$OUT/sized.png" "$scene" 2>/dev/null
size=$(png_size "$OUT/sized.png")
[ "$size" = 20x10 ] && ok "--size wins: $size" || fail sized "$size, expected 20x10"
finish
