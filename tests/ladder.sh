#!/usr/bin/env bash
# The chapter ladder, climbed the way a student climbs it: for each written chapter N, run
# `make chapterN` in the repository root and check the ./rt it leaves:
#   - it is the chapter-N binary of the build (byte for byte), the one the golden tests use;
#   - `./rt --version` prints a version, a commit and "chapters 1-N" ("chapter 1" for N = 1;
#     "chapters 1-8, 10" when chapter 9 is not written yet);
#   - `./rt --list-features` lists exactly the written chapters 1..N;
#   - it holds no code of a later chapter (no later chapter's --list-features title is in it);
#   - it renders chapter N's scene (small, from the repository root and from a copy of the
#     scene in another folder) to a PNG of the asked size.
# `make chapterK` for the first chapter K that is not written must fail, saying the chapter is
# planned. At the end, ./rt is the newest chapter again.
#
# Usage: bash tests/ladder.sh MAKE_COMMAND BUILD_DIR "1 2 3 ..."
# Prints one line per check and a final "N passed, M failed"; exits 1 on any failure.
# With LADDER_STAMPS=1 (make test without FULL=1), a rung whose chapter files are unchanged since
# it passed is skipped, and a rung that passes is stamped (tests/exercises/stamps.py).
set -u

if [ $# -ne 3 ]; then
    echo "usage: $0 MAKE_COMMAND BUILD_DIR CHAPTERS" >&2
    exit 2
fi
MAKE_CMD=$1
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT" || exit 2
BUILD=$(realpath "$2")
read -r -a CHAPTERS <<<"$3"
OUT="$BUILD/ladder"
rm -rf "$OUT"
mkdir -p "$OUT"
# A make started from inside another make (or from CTest) must not inherit its job server.
unset MAKEFLAGS MFLAGS MAKELEVEL

# shellcheck source=check_helpers.sh
source "$ROOT/tests/check_helpers.sh"

last=${CHAPTERS[-1]}
# Each chapter's --list-features title, from the newest binary: a string that only that
# chapter's code holds.
declare -A title
while read -r n name state rest; do
    [[ $n =~ ^[0-9]+$ ]] || continue
    title[$n]=${rest% (core)}
done < <("$BUILD/rt_ch$last" --list-features)

# The written chapters up to n, as --version prints them: runs of consecutive numbers, "1-8, 10".
chapter_runs() {
    local n=$1 runs="" first="" prev=""
    for m in "${CHAPTERS[@]}" ""; do
        if [ -n "$m" ] && [ "$m" -gt "$n" ]; then m=""; fi
        if [ -n "$prev" ] && { [ -z "$m" ] || [ "$m" -ne $((prev + 1)) ]; }; then
            runs+="${runs:+, }$first$([ "$prev" -gt "$first" ] && echo "-$prev")"
            first=""
        fi
        [ -z "$m" ] && break
        [ -z "$first" ] && first=$m
        prev=$m
    done
    echo "$runs"
}

# The size of a PNG, "WxH", from its header.
png_size() { python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]) if d[:8]==b"\x89PNG\r\n\x1a\n" else "not a PNG")' "$1"; }

STAMPS="python3 $ROOT/tests/exercises/stamps.py"
skipped=""
for n in "${CHAPTERS[@]}"; do
    rung="chapter$n"
    if [ "${LADDER_STAMPS:-}" = 1 ] && ! $STAMPS stale "$BUILD" "rung-ch$n" chapter "$n"; then
        skipped+=" $n"
        continue
    fi
    failed_before=$failed
    if ! $MAKE_CMD chapter"$n" >"$OUT/make-$n.log" 2>&1; then
        fail "$rung" "make chapter$n failed: $(tail -n 5 "$OUT/make-$n.log")"
        continue
    fi
    cmp -s ./rt "$BUILD/rt_ch$n" && ok "$rung: ./rt is $BUILD/rt_ch$n" ||
        fail "$rung" "./rt differs from $BUILD/rt_ch$n"

    version=$(./rt --version)
    runs=$(chapter_runs "$n")
    if grep -Eq "^raybook [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{7,}(-dirty)?|unknown)\)" <<<"$version" &&
        grep -qF "$( [ "$n" -eq 1 ] && echo "chapter 1" || echo "chapters $runs"):" <<<"$version"; then
        ok "$rung: --version names the version, the commit and chapters $runs"
    else
        fail "$rung" "--version printed: $version"
    fi

    listed=$(./rt --list-features | awk '$1 ~ /^[0-9]+$/ {printf "%s ", $1}')
    expected=$(for m in "${CHAPTERS[@]}"; do [ "$m" -le "$n" ] && printf '%s ' "$m"; done)
    expected=${expected% }
    [ "$listed" = "$expected " ] && ok "$rung: --list-features shows chapters $expected" ||
        fail "$rung" "--list-features shows chapters '$listed', expected '$expected'"

    later=""
    for m in "${!title[@]}"; do
        [ "$m" -gt "$n" ] && grep -aqF -- "${title[$m]}" ./rt && later+=" $m"
    done
    [ -z "$later" ] && ok "$rung: holds no code of a later chapter" ||
        fail "$rung" "the binary holds code of chapter(s)$later"

    scene=$(ls scenes/chapter"$(printf %02d "$n")"-*.lua)
    png="$OUT/chapter$n.png"
    if ./rt --quiet --size 64x48 --output "$png" "$scene" >"$OUT/render-$n.log" 2>&1 &&
        [ "$(png_size "$png")" = 64x48 ]; then
        ok "$rung: renders $scene"
    else
        fail "$rung" "rendering $scene: $(head -c 300 "$OUT/render-$n.log")"
    fi
    # The same scene from a copy of its folder elsewhere, run inside that folder.
    copy="$OUT/copy-$n"
    mkdir -p "$copy" && cp -r scenes/. "$copy/"
    if (cd "$copy" && "$ROOT/rt" --quiet --size 64x48 --output out.png "$(basename "$scene")") \
        >"$OUT/copy-$n.log" 2>&1 && [ "$(png_size "$copy/out.png")" = 64x48 ]; then
        ok "$rung: renders a copy of $scene from its own folder"
    else
        fail "$rung" "rendering a copy of $scene in $copy: $(head -c 300 "$OUT/copy-$n.log")"
    fi
    rm -rf "$copy"
    if [ "${LADDER_STAMPS:-}" = 1 ] && [ "$failed" -eq "$failed_before" ]; then
        $STAMPS record "$BUILD" "rung-ch$n" chapter "$n"
    fi
done
[ -n "$skipped" ] && echo "skip rungs$skipped: unchanged since they passed (make test FULL=1 climbs them)"

# The first rung not written is planned, and make says so instead of building something else.
next=1
while [[ " ${CHAPTERS[*]} " == *" $next "* ]]; do next=$((next + 1)); done
if $MAKE_CMD chapter"$next" >"$OUT/make-$next.log" 2>&1; then
    fail "chapter$next" "make chapter$next succeeded, but chapter $next is not written"
elif grep -q "planned" "$OUT/make-$next.log"; then
    ok "chapter$next: make says it is planned"
else
    fail "chapter$next" "make chapter$next failed without saying it is planned: $(cat "$OUT/make-$next.log")"
fi

# Leave the newest chapter in ./rt, as make rt would.
$MAKE_CMD chapter"$last" >/dev/null 2>&1 || fail "restore" "make chapter$last failed"

finish
