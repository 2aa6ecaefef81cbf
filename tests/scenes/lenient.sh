#!/usr/bin/env bash
# --lenient renders what it can. Each scene in tests/scenes/lenient/ calls raybook's own names
# with arguments of another course. Without --lenient it stops at its first such call (exit 1,
# with the error its header names); with --lenient it renders (exit 0, the image written, the
# stand-ins visible) and stderr ends with the list its header expects, line for line:
#   -- expect-error: TEXT            without --lenient, the error line contains TEXT
#   -- expect-lenient: TEXT          a line of the --lenient list, in order (one per line)
#   -- expect-magenta: x0 y0 x1 y1   a magenta pixel (the stand-in material) in this region,
#                                    given in fractions of the image size
#   -- expect-green: x0 y0 x1 y1     a green pixel (the scene's own material) there
#   -- expect-lit: x0 y0 x1 y1       a pixel brighter than 100 (of 255) there
# Then rt --batch over a copy of the folder: with --lenient every scene is ok, and its stdout
# line and report card give its count of stand-ins, and the report links it among those that
# needed stand-ins; without --lenient every scene is an error.
#
# Usage: bash tests/scenes/lenient.sh RT_BINARY OUT_DIR
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
set -u

HERE=$(cd "$(dirname "$0")" && pwd)

# shellcheck source=../check_helpers.sh
source "$(dirname "$0")/../check_helpers.sh"
rt_and_out_dir "$@"

# Check regions of a PNG: each argument is "KIND x0 y0 x1 y1" (KIND magenta, green or lit);
# prints one line per argument, "ok" or what the region held instead (tests/png_read.py).
pixels() {
    PYTHONPATH="$ROOT/tests" python3 - "$@" <<'PY'
import sys
from png_read import read_png
w, h, ch, lines = read_png(sys.argv[1])
rows = [[tuple(line[x * ch:x * ch + 3]) for x in range(w)] for line in lines]
tests = {'magenta': lambda r, g, b: r > 1.5 * g + 20 and b > 1.5 * g + 20,
         'green': lambda r, g, b: g > 1.5 * r + 20 and g > 1.5 * b + 20,
         'lit': lambda r, g, b: max(r, g, b) > 100}
for check in sys.argv[2:]:
    kind, *box = check.split()
    x0, y0, x1, y1 = [float(v) for v in box]
    region = [p for row in rows[int(y0 * h):int(y1 * h)] for p in row[int(x0 * w):int(x1 * w)]]
    if any(tests[kind](*p) for p in region):
        print('ok')
    else:
        print('no %s pixel in %s (brightest %s)' % (kind, ' '.join(box), max(region, key=sum)))
PY
}

# ---- Each scene, without and with --lenient ----------------------------------------------------
for scene in "$HERE"/lenient/*.lua; do
    name=$(basename "$scene" .lua)
    work="$OUT/$name"
    rm -rf "$work"
    mkdir -p "$work"
    # A copy in its own folder, named as it is, so messages name it as its header does.
    cp "$scene" "$work/"
    # Without --lenient: nothing changes, the first unreadable call stops the scene.
    (cd "$work" && timeout 60 "$RT" --quiet --output out.png "$name.lua") >"$work.strict.out" 2>"$work.strict.err"
    rc=$?
    expected=$(header "$scene" expect-error)
    if [ $rc -eq 1 ] && grep -q '^rt: error: ' "$work.strict.err" &&
        grep -qF -- "$expected" "$work.strict.err" && [ ! -e "$work/out.png" ]; then
        ok "$name without --lenient: exit 1, '$expected'"
    else
        fail "$name without --lenient" "exit $rc: $(head -c 300 "$work.strict.err")"
    fi
    # With --lenient: the image, and the list at the end of stderr.
    (cd "$work" && timeout 60 "$RT" --quiet --lenient --output out.png "$name.lua") >"$work.out" 2>"$work.err"
    rc=$?
    if [ $rc -ne 0 ] || [ ! -s "$work/out.png" ]; then
        fail "$name with --lenient" "exit $rc, image $(ls "$work" | tr '\n' ' '): $(head -c 300 "$work.err")"
        continue
    fi
    ok "$name with --lenient: exit 0, out.png written"
    want=$(header "$scene" expect-lenient)
    n=$(grep -c '' <<<"$want")
    got=$(sed -n '/^rt: --lenient ignored /,$p' "$work.err")
    heading=$(head -n 1 <<<"$got")
    listed=$(tail -n +2 <<<"$got" | sed 's/^rt:   //')
    calls="$n call"
    [ "$n" -eq 1 ] || calls+=s
    if [ "$heading" = "rt: --lenient ignored unreadable arguments in $calls:" ] &&
        [ "$listed" = "$want" ] && [ "$(tail -n "$((n + 1))" "$work.err")" = "$got" ]; then
        ok "$name lists its $calls at the end of stderr"
    else
        fail "$name's list" "expected $n lines:
$want
got:
$got"
    fi
    checks=()
    for kind in magenta green lit; do
        while IFS= read -r box; do
            [ -n "$box" ] && checks+=("$kind $box")
        done < <(header "$scene" "expect-$kind")
    done
    k=0
    while IFS= read -r verdict; do
        if [ "$verdict" = ok ]; then ok "$name: ${checks[$k]}"; else fail "$name" "$verdict"; fi
        k=$((k + 1))
    done < <(pixels "$work/out.png" "${checks[@]}")
    [ "$k" -eq "${#checks[@]}" ] && [ "$k" -gt 0 ] || fail "$name" "checked $k of ${#checks[@]} regions"
done

# ---- rt --batch, with and without --lenient ----------------------------------------------------
CLASS="$OUT/class"
rm -rf "$CLASS"
cp -r "$HERE/lenient" "$CLASS"
REPORT="$CLASS/raybook-report.html"
for mode in lenient strict; do
    flag=()
    [ $mode = lenient ] && flag=(--lenient)
    timeout 300 "$RT" --batch "$CLASS" "${flag[@]}" --threads 2 --scene-time-limit 60 \
        >"$OUT/batch-$mode.out" 2>"$OUT/batch-$mode.err"
    rc=$?
    [ $rc -eq 0 ] && ok "batch ($mode): exit 0" || fail "batch ($mode)" "exit $rc: $(head -c 300 "$OUT/batch-$mode.err")"
    for scene in "$HERE"/lenient/*.lua; do
        file=$(basename "$scene")
        n=$(header "$scene" expect-lenient | grep -c '')
        if [ $mode = lenient ]; then
            noun="stand-in"
            [ "$n" -eq 1 ] || noun+=s
            line="^ok +[0-9.]+ s  $file  -- with $n $noun \(--lenient\)$"
            card="data-path=\"$file\" data-status=\"ok\" data-stand-ins=\"$n\""
        else
            line="^error +[0-9.]+ s  $file  -- "
            card="data-path=\"$file\" data-status=\"error\" data-stand-ins=\"0\""
        fi
        grep -Eq -- "$line" "$OUT/batch-$mode.out" && ok "batch ($mode): $file's line" ||
            fail "batch ($mode)" "no line /$line/ on stdout"
        grep -qF -- "$card" "$REPORT" && ok "batch ($mode): $file's card" ||
            fail "batch ($mode)" "no card with $card"
    done
    if [ $mode = lenient ]; then
        grep -q 'Needed stand-ins (--lenient):' "$REPORT" &&
            grep -qF 'material:set_bump (arguments raybook cannot read: ' "$REPORT" &&
            ok "batch (lenient): the report links the scenes with stand-ins and lists them" ||
            fail "batch (lenient)" "the report names no stand-ins"
    else
        ! grep -q 'Needed stand-ins' "$REPORT" && ok "batch (strict): no stand-ins reported" ||
            fail "batch (strict)" "the report names stand-ins"
    fi
done

finish
