#!/usr/bin/env python3
"""Content-hash stamps: what lets `make test` answer a one-line change in about a minute.

A slow check that passed (a chapter's mutation check, its round trip, its ladder rung, the
whole-book CTest suites) records a stamp under BUILD/stamps/: the SHA-256 of the files it
depends on, by content, never by timestamp. The next `make test` skips the check while the
hash is the same, and says so; `make test FULL=1` and CI ignore the stamps and run everything.
A check that fails records nothing, so it runs again next time.

What a chapter's checks depend on (chapter_files):
  - the chapter's own files, by the book's naming rules (assignment.owner): its module folder
    in src/, its tests, scene, golden image and page (not its benchmarks and charts);
  - core (src/core/: chapter 1 and the interfaces every chapter builds on), the scene language
    (src/scene/) and the program (src/app/), which chapter 1's sources list holds;
  - the files no chapter owns that the checks read: the top-level and tests CMakeLists, the
    shared tests and helpers in tests/, the exercise and golden tools.
A change inside one chapter's module reruns that chapter's checks only. Later chapters link
its code too; what they see of it is covered by the unit tests and golden images, which
`make test` always runs, and by FULL=1.

The whole-book suites (scenes, determinism, bad input, MPI, batch, interrupt, docs) depend on
every tracked file outside the chapter modules' own folders (suite_files): the front end, the
scenes, the scripts. A change inside a chapter's module does not rerun them.

Commands (the Makefile calls them):
    stamps.py stale BUILD NAME KIND [N]   exit 0 if the check must run (prints why), 1 if fresh
    stamps.py record BUILD NAME KIND [N]  record the check as passed for the current files
KIND is `chapter` (with N) or `suite`.
"""

import hashlib
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import assignment as asg  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
# Files no chapter owns that every chapter's checks read.
SHARED = (r"^CMakeLists\.txt$", r"^tests/CMakeLists\.txt$", r"^tests/[^/]+\.(cpp|h|sh)$",
          r"^tests/exercises/", r"^tests/golden/", r"^src/core/", r"^src/scene/",
          r"^src/app/")
# Files no check reads: the docs build, CI and the benchmarks and charts.
NEVER_READ = (r"^docs/", r"^\.ci/", r"^tests/perf/")
# ... and, for the whole-book suites, the book's text.
IGNORED = NEVER_READ + (r"^chapters/", r"^README\.md$", r"^\.gitignore$", r"^\.clang-format$")


def chapter_files(n: int) -> list[str]:
    """The tracked files chapter n's mutation check, round trip and rung depend on."""
    chapters = asg.book_chapters(ROOT)
    files = []
    for path in asg.tracked_files(ROOT):
        if any(re.match(p, path) for p in NEVER_READ):
            continue
        mine = asg.owner(path, chapters)
        if mine == n or (mine is None and any(re.match(p, path) for p in SHARED)):
            files.append(path)
    return files


def suite_files() -> list[str]:
    """The tracked files the whole-book suites depend on: all but the chapter modules' own
    folders (2..N) and what reruns nothing."""
    chapters = asg.book_chapters(ROOT)
    modules = tuple(f + "/" for k, c in chapters.items() if k > 1 for f in c["folders"])
    return [p for p in asg.tracked_files(ROOT)
            if not p.startswith(modules) and not any(re.match(r, p) for r in IGNORED)]


def digest(files: list[str], extra: bytes = b"") -> str:
    """SHA-256 of the files' paths and contents, in order, and of `extra`."""
    h = hashlib.sha256(extra)
    for path in files:
        h.update(path.encode() + b"\0")
        h.update((ROOT / path).read_bytes())
        h.update(b"\0")
    return h.hexdigest()


def key(kind: str, n: int | None) -> str:
    return digest(chapter_files(n) if kind == "chapter" else suite_files())


def stamp_path(build: Path, name: str) -> Path:
    return build / "stamps" / name


def stale(build: Path, name: str, kind: str, n: int | None) -> bool:
    path = stamp_path(build, name)
    return not path.is_file() or path.read_text().strip() != key(kind, n)


def record(build: Path, name: str, kind: str, n: int | None) -> None:
    path = stamp_path(build, name)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(key(kind, n) + "\n")


def main() -> int:
    if len(sys.argv) < 5 or sys.argv[1] not in ("stale", "record"):
        print(__doc__, file=sys.stderr)
        return 2
    command, build, name, kind = sys.argv[1], Path(sys.argv[2]), sys.argv[3], sys.argv[4]
    n = int(sys.argv[5]) if len(sys.argv) > 5 else None
    if command == "record":
        record(build, name, kind, n)
        return 0
    return 0 if stale(build, name, kind, n) else 1


if __name__ == "__main__":
    sys.exit(main())
