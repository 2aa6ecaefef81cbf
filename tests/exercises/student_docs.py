#!/usr/bin/env python3
"""The student edition of the course docs: the same pages, with every exercise region's code
replaced by its stub in the listings, so that the pages a student reads hold no solution.

The chapter pages show code with Doxygen's \\snippet of source files; a snippet that spans an
exercise region shows the region's lines. The student edition feeds Doxygen, with the same
docs/Doxyfile, a copy of the files git tracks in which every exercise region is its stub
(the stub and the header comments are what regions.py and assignment.py give a student).

Commands:
    student_docs.py edition OUT [--stage DIR]
        raybook's student edition: stub every region of every chapter in a copy of the tracked
        files (DIR, by default OUT/stage) and run docs/Doxyfile on it, the pages going to
        OUT/html (make docs EDITION=student; CMake target docs-student, which also copies
        MathJax next to the pages).
    student_docs.py solution-lines ROOT CHAPTER
        print, one a line, the distinctive lines of chapter CHAPTER's regions in raybook's
        source (ROOT): lines of at least 20 characters that occur in no file of the stubbed
        tree's src/, in no test and on no chapter page. tests/student_docs.sh requires that
        none of them reach the built pages.
    student_docs.py pasted ROOT
        list the solution lines of any chapter's regions that a chapter page writes out as
        text instead of a \\snippet (CTest pasted_solutions); exit 1 when there is one.

assignment.py's export uses export_docs() to give each assignment its own docs/Doxyfile,
main page and the figures of chapters 1..N: the export's sources already hold chapter N's
stubs, so its `make docs` is a student edition of chapters 1..N.
"""

import argparse
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import regions as rg  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def git_files(root: Path) -> list[str]:
    """The files git tracks (and that exist in the working tree): never untracked work."""
    out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], stdout=subprocess.PIPE,
                         check=True).stdout.decode()
    return sorted(p for p in out.split("\0") if p and (root / p).is_file())


def stubbed(path: Path, regions: list[rg.Region]) -> str:
    """A file's text with the given regions' code replaced by their stubs (markers, header
    comments and Blank: line stay, as in an exported assignment)."""
    lines = path.read_text().split("\n")
    for r in sorted(regions, key=lambda r: -r.begin):
        header_end = r.begin + (3 if r.blank is not None else 2)
        lines = lines[:header_end] + [r.indent + r.stub()] + lines[r.end:]
    return "\n".join(lines)


def stage(root: Path, dest: Path) -> int:
    """Copy the tracked files of `root` to `dest` with every exercise region stubbed; return
    the number of regions stubbed."""
    regions = rg.find_regions(root)
    by_file: dict[Path, list[rg.Region]] = {}
    for r in regions:
        by_file.setdefault(r.path, []).append(r)
    if dest.exists():
        shutil.rmtree(dest)
    for rel in git_files(root):
        src, out = root / rel, dest / rel
        out.parent.mkdir(parents=True, exist_ok=True)
        if src in by_file:
            out.write_text(stubbed(src, by_file[src]))
        else:
            shutil.copy2(src, out)
    return len(regions)


def doxygen(tree: Path, out: Path, extra: list[str]) -> int:
    """Run the tree's docs/Doxyfile from the tree, the pages going to out/html."""
    config = (tree / "docs/Doxyfile").read_text() + "\n" + "\n".join(
        [f"OUTPUT_DIRECTORY = {out}"] + extra) + "\n"
    return subprocess.run(["doxygen", "-"], input=config.encode(), cwd=tree).returncode


def edition(args) -> int:
    out = Path(args.out).resolve()
    tree = Path(args.stage).resolve() if args.stage else out / "stage"
    count = stage(ROOT, tree)
    print(f"student_docs: {count} exercise regions stubbed in {tree}")
    shutil.rmtree(out / "html", ignore_errors=True)
    code = doxygen(tree, out, [])
    if code == 0:
        print(f"student_docs: the student edition: {out / 'html' / 'index.html'}")
    return code


def solution_lines(root: Path, chapter: int) -> list[str]:
    """Distinctive lines of a chapter's regions: long enough to be the solution's own, and in
    no file of the stubbed src/, the tests or the pages (so a line that only the solution
    has)."""
    regions = [r for r in rg.find_regions(root) if r.chapter == chapter]
    by_file: dict[Path, list[rg.Region]] = {}
    for r in regions:
        by_file.setdefault(r.path, []).append(r)
    # Every line of the stubbed src/, of the tests and of the chapter pages, whitespace runs as
    # one space: a solution line that is part of one of them (a declaration the rest of the
    # code repeats, a test's own reference code, a formula the page writes as code) is not
    # the region's listing, and its absence would prove nothing.
    elsewhere = []
    for path in sorted([*(root / "src").rglob("*"), *(root / "tests").rglob("*"),
                        *(root / "chapters").glob("*.md")]):
        if path.suffix in (".cpp", ".h", ".md") and path.is_file():
            text = stubbed(path, by_file[path]) if path in by_file else path.read_text()
            elsewhere += [" ".join(l.split()) for l in text.split("\n")]
    blob = "\n".join(elsewhere)
    lines = []
    for r in regions:
        body = r.path.read_text().split("\n")[r.begin + (3 if r.blank is not None else 2):r.end]
        mine = [" ".join(l.split()) for l in body]
        mine = [l for l in mine if len(l) >= 20 and not l.startswith("//") and l not in blob]
        if not mine:
            sys.exit(f"student_docs: exercise {r.name} ({r.id}) has no distinctive line")
        lines += [f"{r.name}\t{l}" for l in mine]
    return lines


def pasted_solutions(root: Path) -> list[str]:
    """Lines of an exercise region's solution (15 characters or more, not a comment) that a
    chapter page writes out as text, not through a \\snippet: the student edition stubs
    snippets, but text on a page reaches every student as it is."""
    pages = {p: {" ".join(l.split()) for l in p.read_text().split("\n")}
             for p in sorted((root / "chapters").glob("*.md"))}
    found = []
    for r in rg.find_regions(root):
        body = r.path.read_text().split("\n")[r.begin + (3 if r.blank is not None else 2):r.end]
        for line in (" ".join(l.split()) for l in body):
            if len(line) < 15 or line.startswith("//"):
                continue
            found += [f"{page.relative_to(root)}: exercise {r.name}'s solution line: {line}"
                      for page, lines in pages.items() if line in lines]
    return found


def pasted(args) -> int:
    found = pasted_solutions(Path(args.root).resolve())
    for f in found:
        print(f"student_docs: {f} (show it with \\snippet FILE {{region}} instead)")
    print(f"student_docs: {len(found)} solution lines pasted into chapter pages")
    return 1 if found else 0


def export_docs(root: Path, n: int, pages: dict[str, str]) -> dict[str, bytes]:
    """The docs of an assignment of chapters 1..n: its Doxyfile (raybook's, with the inputs an
    export has), a main page listing chapters 1..n, the stylesheet and the chapters' figures
    and charts. `pages` maps the exported chapter pages to their text; a \\ref to a page the
    export lacks (a later chapter, the reference, the seed pages) becomes its text."""
    out: dict[str, bytes] = {}
    doxyfile = (root / "docs/Doxyfile").read_text()
    # The chapters' figures and charts (the images and the findings the pages include; not
    # the scripts that draw them).
    for f in git_files(root):
        m = re.match(r"^docs/(?:figures|charts)/ch(\d\d)-[^/]*\.(?:svg|png|txt)$", f)
        if m and int(m.group(1)) <= n:
            out[f] = (root / f).read_bytes()
    image_dirs = ["golden"] + sorted({str(Path(f).parent) for f in out})

    def setting(text: str, key: str, value: str) -> str:
        pattern = re.compile(rf"^{key}\s*=.*?(?<!\\)\n", re.M | re.S)
        assert pattern.search(text), key
        return pattern.sub(lambda _: f"{key} = {value}\n", text, count=1)

    doxyfile = setting(doxyfile, "INPUT", "docs/mainpage.md chapters src tests")
    doxyfile = setting(doxyfile, "IMAGE_PATH", " ".join(image_dirs))
    doxyfile = setting(doxyfile, "PROJECT_NAME", f"\"raybook, chapters 1 to {n}\"")
    # Doxygen matches EXCLUDE_PATTERNS against absolute paths: raybook's */build/* would leave
    # out every file of an export that sits in a folder called build (as make test's does), and
    # the export's inputs hold no build folder.
    doxyfile = setting(doxyfile, "EXCLUDE_PATTERNS", "")
    out["docs/Doxyfile"] = ("# The docs of this assignment (written by raybook's make "
                            "assignment N): make docs\n" + doxyfile).encode()
    out["docs/raybook.css"] = (root / "docs/raybook.css").read_bytes()
    # Anchors the export's pages define; a \ref to any other becomes plain text.
    anchors: set[str] = set()
    for text in pages.values():
        anchors.update(re.findall(r"\{#([\w-]+)\}", text))
        anchors.update(re.findall(r"\\anchor ([\w-]+)", text))

    def unref(m: re.Match) -> str:
        if m.group(1) in anchors:
            return m.group(0)
        return m.group(2) if m.group(2) is not None else f"`{m.group(1)}`"

    for rel, text in pages.items():
        new = re.sub(r'\\ref ([\w-]+)(?: "([^"]*)")?', unref, text)
        if new != text:
            out[rel] = new.encode()
    titles = []
    for rel in sorted(pages):
        first = pages[rel].split("\n", 1)[0]
        m = re.match(r"^# (.*?) \{#([\w-]+)\}", first)
        if m:
            titles.append(f"{len(titles) + 1}. \\subpage {m.group(2)}")
    out["docs/mainpage.md"] = "\n".join([
        f"\\mainpage raybook, chapters 1 to {n}", "",
        f"The chapter pages of this assignment. Chapter {n}'s exercise regions show their "
        "stubs: the code is yours to write (see `README.md`). `make docs` builds these pages "
        "into `docs/html/index.html`.", "",
        "## The chapters", ""] + titles + [""]).encode()
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    e = sub.add_parser("edition")
    e.add_argument("out")
    e.add_argument("--stage")
    e.set_defaults(func=edition)
    s = sub.add_parser("solution-lines")
    s.add_argument("root")
    s.add_argument("chapter", type=int)
    s.set_defaults(func=lambda a: print("\n".join(solution_lines(Path(a.root).resolve(),
                                                                  a.chapter))) or 0)
    p = sub.add_parser("pasted")
    p.add_argument("root")
    p.set_defaults(func=pasted)
    args = parser.parse_args()
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
