#!/usr/bin/env bash
# --lenient's stand-ins look like what the scene's author meant. Each scene in
# tests/scenes/lenient_standins/ uses calls of another course's extension of the A4 language.
# Without --lenient it stops (exit 1, the error its header names); with --lenient it renders
# (exit 0), stderr holds the warnings that name each stand-in or guess, and the picture shows
# what the stand-in must look like:
#   -- expect-error: TEXT            without --lenient, the error line contains TEXT
#   -- expect-stderr: TEXT           with --lenient, a line of stderr contains TEXT
#   -- expect-no-stderr: TEXT        with --lenient, no line of stderr contains TEXT
#   -- expect-KIND: x0 y0 x1 y1      a KIND pixel in this region (fractions of the image size):
#                                    red, green, blue or magenta (that hue, clearly), lit
#                                    (brighter than 100 of 255); black: every pixel below 20
# Then --lenient must never change a scene that renders without it: every scene under scenes/
# that renders at a small size is rendered with and without --lenient, and the PNGs must be the
# same bytes.
#
# Usage: bash tests/scenes/lenient_standins.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

HERE=$(cd "$(dirname "$0")" && pwd)

# shellcheck source=../check_helpers.sh
source "$(dirname "$0")/../check_helpers.sh"
rt_and_out_dir "$@"

# Check regions of a PNG: each argument is "KIND x0 y0 x1 y1"; prints one line per argument,
# "ok" or what the region held instead (tests/png_read.py).
pixels() {
    PYTHONPATH="$ROOT/tests" python3 - "$@" <<'PY'
import sys
from png_read import read_png
w, h, ch, lines = read_png(sys.argv[1])
rows = [[tuple(line[x * ch:x * ch + 3]) for x in range(w)] for line in lines]
def hue(a, b, c):
    return a > 1.5 * b + 20 and a > 1.5 * c + 20
tests = {'red': lambda r, g, b: hue(r, g, b),
         'green': lambda r, g, b: hue(g, r, b),
         'blue': lambda r, g, b: hue(b, r, g),
         'magenta': lambda r, g, b: r > 1.5 * g + 20 and b > 1.5 * g + 20,
         'lit': lambda r, g, b: max(r, g, b) > 100}
for check in sys.argv[2:]:
    kind, *box = check.split()
    x0, y0, x1, y1 = [float(v) for v in box]
    region = [p for row in rows[int(y0 * h):int(y1 * h)] for p in row[int(x0 * w):int(x1 * w)]]
    if kind == 'black':
        good = all(max(p) < 20 for p in region)
    else:
        good = any(tests[kind](*p) for p in region)
    print('ok' if good else 'no %s pixel in %s (brightest %s)' % (kind, ' '.join(box), max(region, key=sum)))
PY
}

# ---- Each scene, without and with --lenient ----------------------------------------------------
for scene in "$HERE"/lenient_standins/*.lua; do
    name=$(basename "$scene" .lua)
    work="$OUT/$name"
    rm -rf "$work"
    mkdir -p "$work"
    # A copy in its own folder, named as it is, so messages name it as its header does.
    cp "$scene" "$work/"
    (cd "$work" && timeout 60 "$RT" --quiet --output out.png "$name.lua") >"$work.strict.out" 2>"$work.strict.err"
    rc=$?
    expected=$(header "$scene" expect-error)
    if [ $rc -eq 1 ] && grep -q '^rt: error: ' "$work.strict.err" &&
        grep -qF -- "$expected" "$work.strict.err" && [ ! -e "$work/out.png" ]; then
        ok "$name without --lenient: exit 1, '$expected'"
    else
        fail "$name without --lenient" "exit $rc: $(head -c 300 "$work.strict.err")"
    fi
    (cd "$work" && timeout 60 "$RT" --lenient --output out.png "$name.lua") >"$work.out" 2>"$work.err"
    rc=$?
    if [ $rc -ne 0 ] || [ ! -s "$work/out.png" ]; then
        fail "$name with --lenient" "exit $rc: $(head -c 300 "$work.err")"
        continue
    fi
    ok "$name with --lenient: exit 0, out.png written"
    while IFS= read -r text; do
        [ -z "$text" ] && continue
        grep -qF -- "$text" "$work.err" && ok "$name says: $text" ||
            fail "$name" "no line of stderr contains '$text'; stderr: $(head -c 600 "$work.err")"
    done < <(header "$scene" expect-stderr)
    while IFS= read -r text; do
        [ -z "$text" ] && continue
        ! grep -qF -- "$text" "$work.err" && ok "$name does not say: $text" ||
            fail "$name" "stderr says '$text': $(grep -F -- "$text" "$work.err" | head -c 300)"
    done < <(header "$scene" expect-no-stderr)
    checks=()
    for kind in red green blue magenta lit black; do
        while IFS= read -r box; do
            [ -n "$box" ] && checks+=("$kind $box")
        done < <(header "$scene" "expect-$kind")
    done
    k=0
    while IFS= read -r verdict; do
        if [ "$verdict" = ok ]; then ok "$name: ${checks[$k]}"; else fail "$name" "${checks[$k]}: $verdict"; fi
        k=$((k + 1))
    done < <(pixels "$work/out.png" "${checks[@]}")
    [ "$k" -eq "${#checks[@]}" ] && [ "$k" -gt 0 ] || fail "$name" "checked $k of ${#checks[@]} regions"
done

# ---- --lenient never changes a scene that renders without it ------------------------------------
# The book's own scenes, the course's A4 scenes, the seeds' and the pre-2015 ones, small and
# with one sample a pixel where the scene allows it: the same bytes with and without --lenient.
# LENIENT_SAME_SKIP names scenes (FOLDER-NAME) to leave out, each said on a line of its own
# (the sanitizer tree leaves out the slowest two).
same=0
for scene in "$ROOT"/scenes/*.lua "$ROOT"/scenes/a4/*.lua "$ROOT"/scenes/seeds/*.lua "$ROOT"/scenes/legacy/*.lua; do
    [ -f "$scene" ] || continue
    grep -q 'gr.render' "$scene" || continue
    name=$(basename "$(dirname "$scene")")-$(basename "$scene" .lua)
    if [[ " ${LENIENT_SAME_SKIP:-} " == *" $name "* ]]; then
        echo "skip $name: left out of the byte-identity check (LENIENT_SAME_SKIP)"
        continue
    fi
    work="$OUT/same/$name"
    rm -rf "$work"
    mkdir -p "$work"
    args=(--quiet --threads 1 --seed 7 --size 24x18 --spp 1 --output-dir "$work")
    (cd "$(dirname "$scene")" && timeout 120 "$RT" "${args[@]}" "$scene") >/dev/null 2>"$work/strict.err" || continue
    mkdir -p "$work/lenient"
    (cd "$(dirname "$scene")" && timeout 120 "$RT" "${args[@]/$work/$work/lenient}" --lenient "$scene") >/dev/null 2>"$work/lenient.err"
    images=0 differ=""
    for png in "$work"/*.png; do
        [ -e "$png" ] || continue
        images=$((images + 1))
        cmp -s "$png" "$work/lenient/$(basename "$png")" || differ+=" $(basename "$png")"
    done
    if [ "$images" -gt 0 ] && [ -z "$differ" ]; then
        ok "$name: the same bytes with --lenient ($images image(s))"
        same=$((same + 1))
    else
        fail "$name" "with --lenient the image differs or is missing:${differ:- no image}"
    fi
done
[ "$same" -ge 10 ] && ok "$same scenes compared" || fail "byte-identical" "only $same scenes rendered"

finish
