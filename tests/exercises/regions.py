#!/usr/bin/env python3
"""The exercise regions of the chapters, and the check that the tests notice each one.

An exercise region is the part of a chapter's code that *is* the chapter's idea: the
ray-sphere quadratic, the Phong term, Snell's law. In the source it sits between two marker
comments, which Doxygen can also use as a snippet:

    // [exercise-ray-sphere]
    // Exercise 1.1, the ray-sphere quadratic: read ch01-equations.
    // Blank: return false;
    ...the code...
    // [exercise-ray-sphere]

The second line numbers and names the exercise and names the page section that explains it.
The optional third line is the region's *blank*: the smallest code that compiles in its place
and does nothing useful (no hit, no light, no bending). Without one, the blank is the stub a
student would get, which throws.

Commands:
    regions.py list
        print every region: exercise, chapter, file and lines.
    regions.py mutate BUILD_DIR [--only ID]... [--changed]
        the tests prove they can fail: for each region, put its blank in place, rebuild the
        test program, run only that chapter's tests ([chNN]) until the first failure, and
        require one. The source is restored after each region, also on Ctrl-C. A region that
        no test notices is a defect of the tests: fix the tests, never this check. With
        --changed, a chapter whose files are unchanged since all its blanks were caught is
        skipped (content-hash stamps, stamps.py); a chapter that passes is stamped.
"""

import argparse
import os
import re
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MARKER = re.compile(r"^(?P<indent> *)// \[exercise-(?P<id>[a-z0-9-]+)\]\s*$")
HEADER = re.compile(r"^ *// Exercise (?P<chapter>\d+)\.(?P<number>\d+), (?P<title>.+): "
                    r"read (?P<anchor>[\w-]+)\.$")
BLANK = re.compile(r"^ *// Blank: (?P<code>.*)$")


@dataclass
class Region:
    """One exercise region: where it is and what replaces it."""
    id: str
    chapter: int
    number: int
    title: str
    anchor: str
    path: Path
    begin: int  # index of the opening marker line
    end: int  # index of the closing marker line
    indent: str
    blank: str | None  # code for the blank, or None: use the stub

    @property
    def name(self) -> str:
        return f"{self.chapter}.{self.number}"

    def stub(self) -> str:
        """The code a student gets: it throws, naming the exercise and where to read."""
        return (f'throw rb::ExerciseNotDone("{self.name}", "{self.title}", "{self.anchor}");')


def find_regions(root: Path = ROOT) -> list[Region]:
    """Every region under src/, in exercise order; malformed markers are errors."""
    regions = []
    for path in sorted((root / "src").rglob("*")):
        if path.suffix not in (".cpp", ".h"):
            continue
        lines = path.read_text().split("\n")
        open_at = {}
        for i, line in enumerate(lines):
            m = MARKER.match(line)
            if not m:
                continue
            rid = m.group("id")
            if rid not in open_at:
                open_at[rid] = (i, m.group("indent"))
                continue
            begin, indent = open_at.pop(rid)
            header = HEADER.match(lines[begin + 1])
            if not header:
                sys.exit(f"{path}:{begin + 2}: expected '// Exercise N.M, title: read anchor.'")
            blank = BLANK.match(lines[begin + 2])
            regions.append(Region(rid, int(header["chapter"]), int(header["number"]),
                                  header["title"], header["anchor"], path, begin, i, indent,
                                  blank["code"] if blank else None))
        for rid, (begin, _) in open_at.items():
            sys.exit(f"{path}:{begin + 1}: exercise region '{rid}' is never closed")
    regions.sort(key=lambda r: (r.chapter, r.number))
    names = [r.name for r in regions]
    duplicates = {n for n in names if names.count(n) > 1}
    if duplicates:
        sys.exit(f"exercise numbers used twice: {', '.join(sorted(duplicates))}")
    return regions


def replaced(region: Region, code: str) -> str:
    """The text of the region's file with the region's code replaced by `code` (one line; the
    markers and the header comments stay)."""
    lines = region.path.read_text().split("\n")
    header_end = region.begin + (3 if region.blank is not None else 2)
    body = [region.indent + code] if code else []
    return "\n".join(lines[:header_end] + body + lines[region.end:])


def list_regions(_args) -> int:
    for r in find_regions():
        where = f"{r.path.relative_to(ROOT)}:{r.begin + 1}-{r.end + 1}"
        print(f"{r.name:5} {r.id:20} chapter {r.chapter:2}  {where:40} {r.title}")
    return 0


def run(command: list[str], timeout: int) -> tuple[int, str]:
    """Run a command; return its exit code (124 on timeout) and its output."""
    try:
        p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, timeout=timeout)
        return p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        return 124, out


def mutate(args) -> int:
    build = Path(args.build).resolve()
    tests = build / "tests" / "raybook_tests"
    regions = [r for r in find_regions() if not args.only or r.id in args.only]
    if args.changed:
        import stamps  # noqa: E402 (it imports assignment.py, which imports this file)
        fresh = sorted({r.chapter for r in regions
                        if not stamps.stale(build, f"mutate-ch{r.chapter:02d}", "chapter",
                                            r.chapter)})
        if fresh:
            print(f"mutation check: chapters {' '.join(map(str, fresh))} unchanged since all "
                  f"their blanks were caught (make test FULL=1 reruns them)")
        regions = [r for r in regions if r.chapter not in fresh]
    jobs = str(os.cpu_count() or 2)
    failures = []
    original = {}

    def restore(*_):
        for path, text in original.items():
            path.write_text(text)
        original.clear()

    signal.signal(signal.SIGINT, lambda *a: (restore(), sys.exit(130)))
    signal.signal(signal.SIGTERM, lambda *a: (restore(), sys.exit(143)))
    print(f"{'exercise':9} {'region':20} {'result':8} {'seconds':>7}  what failed")
    try:
        for r in regions:
            start = time.monotonic()
            original[r.path] = r.path.read_text()
            r.path.write_text(replaced(r, r.blank if r.blank is not None else r.stub()))
            code, out = run(["cmake", "--build", str(build), "-j", jobs, "--target",
                             "raybook_tests"], 900)
            if code != 0:
                restore()
                failures.append(r)
                print(f"{r.name:9} {r.id:20} {'NO BUILD':8} {time.monotonic() - start:7.0f}  "
                      f"the blank does not compile:\n{out[-2000:]}")
                continue
            # The first failing test is enough (--abort): a blank can make a slow test slower.
            code, out = run([str(tests), "--abort", f"[ch{r.chapter:02d}]"], 600)
            restore()
            seconds = time.monotonic() - start
            # Catch2 prints "FAILED:" per failed assertion, with the scenario above it.
            caught = [line.strip() for line in out.split("\n") if line.startswith("Scenario:")]
            if code == 0:
                failures.append(r)
                print(f"{r.name:9} {r.id:20} {'MISSED':8} {seconds:7.0f}  "
                      f"no [ch{r.chapter:02d}] test noticed the blank")
            else:
                what = caught[0] if caught else f"exit code {code}"
                print(f"{r.name:9} {r.id:20} {'caught':8} {seconds:7.0f}  {what[:70]}")
    finally:
        restore()
    # Leave the build as the source is.
    run(["cmake", "--build", str(build), "-j", jobs, "--target", "raybook_tests"], 900)
    print(f"{len(regions) - len(failures)} of {len(regions)} blanks caught")
    if args.changed:
        for n in sorted({r.chapter for r in regions} - {r.chapter for r in failures}):
            stamps.record(build, f"mutate-ch{n:02d}", "chapter", n)
    return 1 if failures else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("list").set_defaults(func=list_regions)
    m = sub.add_parser("mutate")
    m.add_argument("build")
    m.add_argument("--only", action="append", default=[])
    m.add_argument("--changed", action="store_true",
                   help="skip chapters unchanged since they passed; stamp those that pass")
    m.set_defaults(func=mutate)
    args = parser.parse_args()
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
