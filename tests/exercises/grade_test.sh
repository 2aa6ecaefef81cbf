#!/usr/bin/env bash
# make grade over a class of four exported chapter-1 projects, each a case the grader must get
# right:
#   untouched  the export as handed out: every exercise fails, and so does the golden image;
#   solved     raybook's own code put back: every exercise and the golden image pass;
#   buggy      solved, then the last exercise replaced by its blank (compiles, wrong): only
#              that exercise fails, the ones before it pass and score, the golden image fails;
#   broken     solved, then a syntax error: reported as a build failure with score 0, never
#              a crash of the grader.
# Then the solved project's own make check (the export's copy of the scripts) must pass.
# Checks the printed table and the CSV. The builds share objects through ccache (keyed, like
# raybook's own build, on paths relative to the project: each builds in PROJECT/build, as make
# check does), so they take chapter 1's objects from make test's build and round trip; without
# ccache, through objcache.py.
#
# Usage: bash tests/exercises/grade_test.sh WORK_DIR
set -euo pipefail
[[ $# -eq 1 ]] || { echo "usage: $0 WORK_DIR" >&2; exit 2; }
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(realpath -m "$1")
CLASS=$WORK/class
SCRIPT=$ROOT/tests/exercises/assignment.py
start=$SECONDS
rm -rf "$CLASS"
mkdir -p "$CLASS"
if ! command -v ccache >/dev/null; then
    export RB_OBJCACHE=${RB_OBJCACHE:-$WORK/objcache} RB_OBJCACHE_STRIP=$CLASS
    export RB_COMPILER_LAUNCHER="python3;$ROOT/tests/exercises/objcache.py"
fi

for student in untouched solved buggy broken; do
    python3 "$SCRIPT" export 1 "$CLASS/$student" >/dev/null
done
for student in solved buggy broken; do
    python3 "$SCRIPT" solve "$CLASS/$student" >/dev/null
done
# The bug: the chapter's last region with a Blank line gets its blank code. The broken
# project gets a line that cannot compile in the same place.
read -r bug_name bug_file < <(python3 - "$ROOT" "$CLASS" <<'EOF'
import json, re, sys
from pathlib import Path
sys.path.insert(0, sys.argv[1] + "/tests/exercises")
import regions
class_dir = Path(sys.argv[2])
region = [r for r in regions.find_regions(class_dir / "buggy") if r.chapter == 1 and r.blank][-1]
for student, code in (("buggy", region.blank), ("broken", "this is not C++;")):
    r = [x for x in regions.find_regions(class_dir / student) if x.id == region.id][0]
    r.path.write_text(regions.replaced(r, code))
print(region.name, r.path.relative_to(class_dir / "broken"))
EOF
)
echo "the bug: exercise $bug_name ($bug_file) replaced by its blank"

status=0
out=$(python3 "$SCRIPT" grade "$CLASS" --csv "$WORK/grades.csv" 2>"$WORK/grade.err") || status=$?
echo "$out"
cat "$WORK/grade.err"
[[ $status -eq 0 ]] || { echo "FAIL: make grade exited with $status"; exit 1; }
# A class takes minutes: make grade says so at the start and a line as each student is graded.
for line in 'grade: 4 students' 'grade: \[1/4\] .* reuse its objects' 'grade: \[2/4\] .* min left' 'grade: \[4/4\] .* all in '; do
    grep -qE -- "$line" "$WORK/grade.err" || { echo "FAIL: make grade's progress lacks '$line'"; exit 1; }
done
echo "ok   make grade says what it is doing: a line at the start and one per student"

python3 - "$WORK/grades.csv" "$bug_name" <<'EOF'
import csv, sys
rows = {r["student"]: r for r in csv.DictReader(open(sys.argv[1]))}
bug = sys.argv[2]
failures = []
def expect(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)
expect(sorted(rows) == ["broken", "buggy", "solved", "untouched"], "one CSV row per student")
exercises = sorted({k.split()[0] for k in next(iter(rows.values())) if k.startswith("ex")})
expect(len(exercises) >= 2, f"the CSV has a column pair per exercise: {exercises}")
def passed(row, ex):
    return row[f"{ex} passed"], row[f"{ex} tests"]
u, s, b, x = rows["untouched"], rows["solved"], rows["buggy"], rows["broken"]
expect(u["build"] == s["build"] == b["build"] == "ok", "three projects build")
expect(all(int(passed(u, e)[0]) == 0 < int(passed(u, e)[1]) for e in exercises),
       "untouched: no exercise test passes")
expect(all(passed(s, e)[0] == passed(s, e)[1] for e in exercises),
       "solved: every exercise test passes")
expect(u["golden"] == "fail" and s["golden"] == "pass" and b["golden"] == "fail",
       "golden image: untouched fail, solved pass, buggy fail")
expect(s["golden rmse"] != "" and float(s["golden rmse"]) < float(b["golden rmse"] or "inf"),
       "the golden metric is reported, smaller for the solved project than the buggy one")
for e in exercises:
    p, t = passed(b, e)
    if e == "ex" + bug:
        expect(int(p) < int(t), f"buggy: {e} fails ({p}/{t})")
    elif e < "ex" + bug:
        expect(p == t, f"buggy: {e}, before the bug, passes ({p}/{t})")
def counted(row):
    return sum(int(passed(row, e)[1]) for e in exercises) + int(row["other tests"])
expect(int(u["other tests"]) > 0 and u["other passed"] == u["other tests"],
       f"untouched: the tests that need no exercise pass with every stub in place "
       f"({u['other passed']}/{u['other tests']})")
expect(s["tests passed"] == f"{counted(s)}/{counted(s)}",
       f"solved: 'tests passed' counts every exercise's tests and the other tests "
       f"({s['tests passed']})")
K = len(exercises)
expect(u["score"] == f"0/{K}" and s["score"] == f"{K}/{K}",
       f"score per exercise: untouched 0/{K}, solved {K}/{K} ({u['score']}, {s['score']})")
expect(b["score"] == f"{K - 1}/{K}",
       f"buggy: every exercise but the bugged one scores ({b['score']})")
expect(x["build"] == "failed" and x["score"] == "0", "broken: a build failure, score 0")
expect(all(r["tests changed"] == "" for r in rows.values()),
       "no project's tests, goldens or scenes differ from a fresh export")
sys.exit(1 if failures else 0)
EOF

# The export's own make check, as a student runs it: its copy of assignment.py, not raybook's
# (a module only raybook has once made every export's make check crash on import). It runs in
# a byte copy of the solved project at OWN/project, the layout of make grade's staging folders
# (CLASS/.raybook-stage-W/project): ccache keys on paths relative to the project, and objcache
# (without ccache) on the source's path below $RB_OBJCACHE_STRIP/<folder>, so the copy's compiles are the ones make grade just made (and the
# round trip, under make test), instead of chapter 1 compiled again from scratch (about 40
# files).
OWN=$WORK/own-check
rm -rf "$OWN"
mkdir -p "$OWN/project"
cp -a "$CLASS/solved/." "$OWN/project/"
rm -rf "$OWN/project/build"
if out=$(RB_OBJCACHE_STRIP=$WORK make -C "$OWN/project" --no-print-directory check 2>&1); then
    echo "ok   the solved project's own make check runs and passes"
else
    echo "$out" | tail -20
    echo "FAIL the solved project's own make check"
    exit 1
fi
echo "grade test: $((SECONDS - start)) s"
