#!/usr/bin/env bash
# student_docs: an assignment's docs are a student edition. Exports chapter CHAPTER (5 by
# default: three exercise regions and many formulas) into OUT_DIR, runs the export's own
# `make docs` (configure, Doxygen with the export's docs/Doxyfile, WARN_AS_ERROR, MathJax
# copied next to the pages) and checks that
#   - Doxygen wrote no warning (the export's make docs fails on one; its output is searched too);
#   - the chapter page shows each exercise's stub (rb::ExerciseNotDone("N.k", ...));
#   - no built page holds a solution line of the chapter's regions (the distinctive lines of
#     student_docs.py solution-lines: in raybook's regions and nowhere in the stubbed src/);
#   - the pages load MathJax from mathjax/MathJax.js, and that file is there (offline formulas);
#   - the export's golden report and Makefile never name make golden-update;
#   - an untracked file in raybook's working tree does not reach the export.
#
# usage: student_docs.sh OUT_DIR [CHAPTER]   (run from the repository root)
set -euo pipefail
out=${1:?usage: student_docs.sh OUT_DIR [CHAPTER]}
chapter=${2:-5}
[ -f docs/Doxyfile ] || { echo "student_docs: run from the repository root"; exit 2; }
root=$(pwd)
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
export_dir=$out/export
failures=0
fail() { echo "student_docs: FAIL: $*"; failures=$((failures + 1)); }

# An untracked, not ignored file where an export would copy it if it took untracked work.
probe=tests/student_docs_probe.$$.txt
trap 'rm -f "$root/$probe"' EXIT
echo "untracked work in progress" >"$probe"
if [ "$(git status --porcelain -- "$probe")" != "?? $probe" ]; then
    fail "$probe is not an untracked, unignored file; the untracked-file check cannot run"
fi

echo "student_docs: exporting chapter $chapter"
python3 tests/exercises/assignment.py export "$chapter" "$export_dir" >"$out/export.log"
rm -f "$probe"
if [ -e "$export_dir/$probe" ]; then
    fail "the untracked file $probe reached the export"
else
    echo "student_docs: ok: the untracked file $probe stayed out of the export"
fi

echo "student_docs: the export's make docs"
start=$(date +%s)
if ! make -C "$export_dir" docs BUILD="$out/build" >"$out/make-docs.log" 2>&1; then
    fail "the export's make docs failed:"
    tail -40 "$out/make-docs.log"
    exit 1
fi
echo "student_docs: ok: make docs built the pages in $(( $(date +%s) - start )) s"
if grep -E "warning:|error:" "$out/make-docs.log"; then
    fail "Doxygen warned (above)"
else
    echo "student_docs: ok: no Doxygen warning"
fi

html=$export_dir/docs/html
page=$html/ch$(printf %02d "$chapter").html
[ -f "$page" ] || { fail "no chapter page $page"; exit 1; }

# The text of the pages, tags removed and entities decoded, one file a line group.
python3 - "$html" "$page" >"$out/text.txt" <<'EOF'
import html, re, sys
from pathlib import Path
for path in sorted(Path(sys.argv[1]).glob("*.html")):
    text = html.unescape(re.sub(r"<[^>]+>", "", path.read_text(errors="replace")))
    for line in text.split("\n"):
        print(f"{path.name}\t{' '.join(line.split())}")
EOF
chapter_page=$(basename "$page")

python3 tests/exercises/student_docs.py solution-lines . "$chapter" >"$out/solution-lines.txt"
count=$(grep -c . "$out/solution-lines.txt")
[ "$count" -gt 0 ] || fail "no solution line to look for"
leaked=0
while IFS=$'\t' read -r exercise line; do
    needle=$(echo "$line" | tr -s ' \t' ' ')
    if grep -qF -- "$needle" "$out/text.txt"; then
        fail "exercise $exercise's solution line '$line' is in $(grep -F -- "$needle" \
            "$out/text.txt" | cut -f1 | sort -u | tr '\n' ' ')"
        leaked=$((leaked + 1))
    fi
done <"$out/solution-lines.txt"
[ "$leaked" -eq 0 ] && echo "student_docs: ok: none of the $count solution lines of chapter $chapter's regions is in any page"

for exercise in $(cut -f1 "$out/solution-lines.txt" | sort -u); do
    stub="throw rb::ExerciseNotDone(\"$exercise\","
    if awk -F'\t' -v page="$chapter_page" -v stub="$stub" \
        '$1 == page && index($2, stub) { found = 1 } END { exit !found }' "$out/text.txt"; then
        echo "student_docs: ok: $chapter_page shows exercise $exercise's stub"
    else
        fail "$chapter_page does not show exercise $exercise's stub ($stub)"
    fi
done

if grep -q 'src="mathjax/MathJax.js' "$page" && [ -s "$html/mathjax/MathJax.js" ] \
    && grep -q '\\(' "$page"; then
    echo "student_docs: ok: $chapter_page has formulas and loads MathJax from mathjax/MathJax.js, which is there"
else
    fail "$chapter_page has no formulas, or does not load mathjax/MathJax.js, or the file is missing"
fi

if grep -rl "golden-update" "$export_dir/tests/golden" "$export_dir/Makefile"; then
    fail "the export's golden report or Makefile names make golden-update (files above)"
else
    echo "student_docs: ok: the export's golden report and Makefile never name make golden-update"
fi

if [ "$failures" -gt 0 ]; then
    echo "student_docs: $failures check(s) failed"
    exit 1
fi
echo "student_docs: the export's docs are a student edition"
