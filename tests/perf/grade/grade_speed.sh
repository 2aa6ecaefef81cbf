#!/usr/bin/env bash
# make grade at class scale (issue 21: 100 students of one chapter in at most 30 minutes on 2
# cores). Builds a class of STUDENTS exported chapter-N projects, each one a little different,
# as real hand-ins are, and times `assignment.py grade` over it from a cold start (no build
# folder, no compiler cache).
#
# usage: tests/perf/grade/grade_speed.sh WORK_DIR [CHAPTER] [STUDENTS]
#        defaults: chapter 13, 100 students
#
# The class: a quarter untouched, a quarter with only the first exercise written, half with
# every exercise written; each student's exercise files carry a comment of their own, so every
# student's exercise files compile anew (identical files would be cache hits and flatter the
# time). Prints the total, the first student's (cold) time, the median of the others, and
# "target grade_minutes_per_100 M" (measured with 100 students or more; from fewer, the first
# student's time plus 99 at the others' mean pace).
set -euo pipefail
work=$(realpath -m "${1:?usage: grade_speed.sh WORK_DIR [CHAPTER] [STUDENTS]}")
chapter=${2:-13}
students=${3:-100}
root=$(cd "$(dirname "$0")/../../.." && pwd)
script=$root/tests/exercises/assignment.py
rm -rf "$work"
mkdir -p "$work/class"
python3 "$script" export "$chapter" "$work/template" >/dev/null
python3 - "$root" "$work" "$chapter" "$students" <<'PY'
import shutil, sys
from pathlib import Path
sys.path.insert(0, sys.argv[1] + "/tests/exercises")
import assignment, regions
work, chapter, students = Path(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
for i in range(students):
    project = work / "class" / f"student{i + 1:03d}"
    shutil.copytree(work / "template", project)
    kind = i % 4
    if kind >= 2:
        assignment.solve_regions(project)
    elif kind == 1:
        first = min((r for r in regions.find_regions(project) if r.chapter == chapter),
                    key=lambda r: r.number)
        assignment.solve_regions(project, {first.id})
    for path in sorted({r.path for r in regions.find_regions(project) if r.chapter == chapter}):
        path.write_text(path.read_text() + f"// handed in by student {i + 1}\n")
PY
start=$(date +%s.%N)
python3 "$script" grade "$work/class" --build-root "$work/builds" --csv "$work/grades.csv" \
    >"$work/grade.log" 2>&1
end=$(date +%s.%N)
python3 - "$work" "$start" "$end" "$students" "$chapter" <<'PY'
import csv, re, sys
from pathlib import Path
work, start, end, n, chapter = Path(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
times = [float(t) for t in re.findall(r"^## \S+ \(chapter \d+, (\d+) s\)", (work / "grade.log").read_text(), re.M)]
rows = list(csv.DictReader(open(work / "grades.csv")))
scores = sorted({r["score"] for r in rows})
rest = sorted(times[1:])
median = rest[len(rest) // 2] if rest else 0.0
total = end - start
print(f"make grade, chapter {chapter}, {n} students from a cold start: {total:.0f} s in all "
      f"({total / 60:.1f} min); first student {times[0]:.0f} s (cold build), the others "
      f"median {median:.0f} s; scores seen: {', '.join(scores)}")
# 100 students: the first (cold) student, then the others at this run's mean pace.
per_100 = times[0] + (total - times[0]) / max(1, n - 1) * 99 if n < 100 else total * 100 / n
print(f"target grade_minutes_per_100 {per_100 / 60:.1f}"
      + ("" if n >= 100 else f" (from {n}: the first student, then 99 at the others' mean)"))
PY
