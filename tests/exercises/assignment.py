#!/usr/bin/env python3
"""Assignments: a chapter's exercise regions become code a student writes, checked by the
chapter's own tests and golden image.

Commands (raybook's Makefile and the exported project's Makefile call them):
    assignment.py export N DIR
        write a standalone project to DIR holding chapters 1..N, with chapter N's exercise
        regions replaced by their stubs (make assignment N).
    assignment.py check [PROJECT] [--build DIR] [--json FILE]
        in an exported project: build chapter N's tests and binary, run each exercise's tests
        and the golden image, print the table (make check). Exit 0 when everything passes.
    assignment.py grade DIR [--csv FILE]
        DIR is an exported project or a folder of them: check each, print a score table per
        student and write a CSV (make grade DIR=...).
    assignment.py solve PROJECT
        put raybook's own code back into the project's stubbed regions (the round trip's
        "restored" state; never shipped to students, it reads raybook's source).
    assignment.py roundtrip WORK [--chapters 1 2 ...]
        CI: for every chapter with regions, export, check (every exercise must fail), solve,
        check (everything must pass). Two chapters at a time (--workers), each reusing its
        export and build folder, with one compiler cache (ccache, or objcache.py without it),
        so each chapter costs only what changed. --stamps BUILD skips chapters unchanged since
        they passed.
    assignment.py list
        every chapter's exercises and the tests tagged [exN.k] for each.
    assignment.py readmes
        CI: every chapter's exported README is plain Markdown (no Doxygen or LaTeX left).
    assignment.py tags BUILD --chapter N [--apply]
        maintainer's tool: find which [chNN] tests pass once exercises 1..k are written and
        k+1.. are stubs, i.e. the [exN.k] tag each test should carry.

Which tests belong to which exercise: a chapter test tagged [exN.k] passes as soon as
exercises N.1 .. N.k are written, even while the later ones are still stubs (tags computed by
`tags`, checked by `roundtrip`). Chapters are found from CMakeLists.txt's rb_chapter(NN ...)
lines, so chapters added later need no change here.
"""

import argparse
import collections
import concurrent.futures
import csv
import json
import os
import re
import queue
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import regions as rg  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
INFO = ".assignment.json"
JOBS = str(os.cpu_count() or 2)
BUILD_TIMEOUT = int(os.environ.get("RB_BUILD_TIMEOUT", "1800"))
TEST_TIMEOUT = int(os.environ.get("RB_TEST_TIMEOUT", "120"))
# Whole-book suites that need every chapter (or the seed scenes, the showcase or the docs):
# an exported project leaves them out of its CTest list.
WHOLE_BOOK_SUITES = ["scenes_smoke", "seed_scenes_smoke", "golden-seed\\..*", "docs_warnings",
                     "batch", "bad_input.*", "scenes_portable", "dialect_examples",
                     "scene_warnings", "student_docs"]
# CTest suites that need a chapter after 1: left out of the exports of earlier chapters.
SUITES_NEEDING = {"resources": 3}  # its scenes read meshes


# ---- What belongs to which chapter ----------------------------------------------------------

def book_chapters(root: Path) -> dict[int, dict]:
    """The chapters of CMakeLists.txt's rb_chapter(NN name header function sources...) calls,
    with the module folders their sources live in (chapter 1 owns src/core, src/scene and
    src/app)."""
    text = (root / "CMakeLists.txt").read_text()
    chapters = {}
    for m in re.finditer(r"^rb_chapter\(([^)]*)\)", text, re.M):
        words = m.group(1).split()
        number = int(words[0])
        sources = words[4:]
        folders = sorted({"/".join(s.split("/")[:2]) for s in sources if s.startswith("src/")})
        chapters[number] = {"name": words[1], "header": words[2], "function": words[3],
                            "folders": folders, "span": (m.start(), m.end())}
    return chapters


def owner(path: str, chapters: dict[int, dict]) -> int | None:
    """The chapter a repository file belongs to, by the book's naming rules, or None."""
    patterns = [r"^tests/ch(\d\d)_", r"^tests/perf/ch(\d\d)/", r"^scenes/chapter(\d\d)-",
                r"^golden/chapter(\d\d)-", r"^chapters/(\d\d)-", r"^docs/figures/ch(\d\d)_",
                r"^docs/charts/ch(\d\d)-"]
    for p in patterns:
        m = re.match(p, path)
        if m:
            return int(m.group(1))
    for n, c in chapters.items():
        if n > 1 and any(path.startswith(f + "/") for f in c["folders"]):
            return n
    return None


def left_out(path: str) -> bool:
    """Files of the whole book that an assignment does not ship: the showcase and seed scenes
    and their goldens, the docs build, CI, the maintainer's ladder, the MPI tests (they render
    the showcase) and the front door (the export writes its own Makefile and README)."""
    prefixes = ("scenes/seeds/", "scenes/showcase", ".ci/", "docs/", "tests/ladder.sh",
                "tests/docs_warnings.sh", "tests/scenes/seeds.sh", "tests/perf/", "tests/fuzz/",
                "tests/exercises/README.md", "tests/exercises/student_docs.py",
                "tests/student_docs.sh", "tests/mpi/")
    # Build folders and exported projects in the working tree are nobody's source, even when
    # .gitignore does not name them (build-ex/, assignment-ch05/): an export would copy them.
    top = path.split("/", 1)[0]
    return (path.startswith(prefixes) or re.match(r"^golden/\d\d\d-", path) is not None
            or path in ("Makefile", "README.md")
            or ("/" in path and top.startswith(("build", "assignment"))))


def shared_test_fits(root: Path, path: str, chapters: dict[int, dict], last: int) -> bool:
    """Whether a test file that no single chapter owns (the stability suite, the property
    test) belongs in an export of chapters 1..last: the property test draws scenes from every
    chapter, so only the newest chapter's export has it; another shared file goes when every
    module it includes is there."""
    if not re.match(r"^tests/[^/]+\.cpp$", path) or re.match(r"^tests/ch\d\d_", path):
        return True
    if Path(path).name.startswith("property"):
        return last == max(chapters)
    modules = set(re.findall(r'^#include "(\w+)/', (root / path).read_text(), re.M))
    have = {"core"} | {f.split("/")[1] for k, c in chapters.items() if k <= last
                       for f in c["folders"]}
    return modules <= have


def tracked_files(root: Path) -> list[str]:
    """The repository's files that git tracks (as they are in the working tree): untracked
    work in progress never reaches an export."""
    import student_docs  # raybook's only: an export's copy of this script never exports
    return student_docs.git_files(root)


def page_of(root: Path, n: int) -> Path | None:
    pages = sorted((root / "chapters").glob(f"{n:02d}-*.md"))
    return pages[0] if pages else None


def scene_of(root: Path, n: int) -> Path | None:
    scenes = sorted((root / "scenes").glob(f"chapter{n:02d}-*.lua"))
    return scenes[0] if scenes else None


def sections(page: Path) -> dict[str, str]:
    """Anchor -> heading text of a chapter page."""
    found = {}
    for line in page.read_text().split("\n"):
        m = re.match(r"^#+ (.*?) \{#([\w-]+)\}\s*$", line)
        if m:
            found[m.group(2)] = m.group(1)
    return found


# ---- Exporting ------------------------------------------------------------------------------

def trim_cmake(text: str, chapters: dict[int, dict], last: int) -> str:
    """CMakeLists.txt without the rb_chapter calls of chapters after `last`."""
    for n in sorted(chapters, reverse=True):
        if n > last:
            begin, end = chapters[n]["span"]
            text = text[:begin] + text[end:].lstrip("\n")
    return text


def trim_test_helpers(text: str, chapters: dict[int, dict], last: int) -> str:
    """tests/test_helpers.h without the headers and Feature records of later chapters."""
    for n, c in chapters.items():
        if n <= last:
            continue
        for folder in c["folders"]:
            module = folder.split("/", 1)[1]
            text = re.sub(rf'^#include "{re.escape(module)}/[^"]+"\n', "", text, flags=re.M)
        text = re.sub(rf"\s*rb::{re.escape(c['function'])}\(\),?", "", text)
    # A list may now end in a comma before its brace.
    return re.sub(r",(\s*)\}", r"\1}", text)


def dropped_names(root: Path, chapters: dict[int, dict], last: int,
                  helpers: str) -> tuple[set[str], set[str]]:
    """The modules of chapters after `last`, and the names their headers declare (classes,
    structs, enums, aliases, functions) plus the test helpers that test_helpers.h defines only
    when such a module is there (inside #if __has_include("module/...") ... #endif)."""
    modules = {f.split("/")[1] for k, c in chapters.items() if k > last for f in c["folders"]}

    def declared(folders) -> set[str]:
        found: set[str] = set()
        for header in (h for f in folders for h in (root / "src" / f).glob("*.h")):
            text = header.read_text()
            # Definitions, not forward declarations (struct RenderContext;).
            found.update(re.findall(r"\b(?:class|struct|enum class|enum|using)\s+(\w+)\b(?!;)",
                                    text))
            found.update(re.findall(r"^(?:inline\s+)?[\w:<>,]+[\s*&]+(\w+)\(", text, re.M))
        return found

    kept = {f.name for f in (root / "src").iterdir() if f.is_dir()} - modules
    names = declared(modules) - declared(kept)
    for module in modules:
        for block in re.findall(rf'#if __has_include\("{module}/[^"]+"\)(.*?)#endif', helpers,
                                re.S):
            names.update(re.findall(r"^inline\s+[^(]*?(\w+)\(", block, re.M))
    names -= {"operator", "Feature"}
    return modules, names


def block_end(text: str, open_brace: int) -> int:
    """The index just after the brace that closes the one at `open_brace`, skipping strings,
    characters, raw strings and comments."""
    depth, i = 0, open_brace
    while i < len(text):
        if text.startswith("//", i):
            i = text.index("\n", i)
        elif text.startswith("/*", i):
            i = text.index("*/", i) + 2
            continue
        elif text.startswith('R"', i) and not (text[i - 1:i].isalnum() or text[i - 1:i] == "_"):
            delim = text[i + 2:text.index("(", i)]
            i = text.index(")" + delim + '"', i) + len(delim) + 2
        elif text[i] == '"' or (text[i] == "'" and not text[i - 1].isalnum()):
            q, i = text[i], i + 1
            while text[i] != q:
                i += 2 if text[i] == "\\" else 1
        elif text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return len(text)


def trim_test_file(text: str, modules: set[str], names: set[str],
                   last: int) -> tuple[str | None, list[str]]:
    """A test file without the scenarios that use a later chapter's code or are tagged
    [needs-chKK] for a later chapter K (a test of an early chapter that checks how it works
    with later ones); None when code outside the scenarios uses a later chapter (the file is
    left out). Also returns the scenarios removed."""
    uses = re.compile(r"\b(?:rb|rbtest)::(?:" + "|".join(map(re.escape, sorted(names))) + r")\b"
                      if names else r"(?!)")
    includes = re.compile(r'^#include "(?:' + "|".join(map(re.escape, sorted(modules))) +
                          r')/[^"]+"\n', re.M) if modules else re.compile(r"(?!)")
    removed, pieces, pos = [], [], 0
    for name, _span in scenarios(text):
        start = text.index("SCENARIO(", pos)
        body = text.index("{", text.index(")", _span[1]))
        end = block_end(text, body)
        pieces.append(text[pos:start])
        needs = [int(k) for k in re.findall(r"\[needs-ch(\d+)\]", text[_span[0]:_span[1]])]
        if uses.search(text[start:end]) or any(k > last for k in needs):
            removed.append(name)
            pieces.append(f"// Scenario left out of this assignment (it needs a later chapter): "
                          f"{name}\n")
        else:
            pieces.append(text[start:end])
        pos = end
    pieces.append(text[pos:])
    outside = "".join(p for p in pieces if not p.startswith("SCENARIO("))
    if uses.search(outside) or (includes.search(outside) and removed == [] and
                                 uses.search(text)):
        return None, []
    trimmed = "".join(pieces)
    if removed:
        trimmed = includes.sub("", trimmed)
    elif includes.search(trimmed):
        return None, []
    return trimmed, removed


CHECK_CMAKE = """
# make check (an assignment): chapter {n}'s tests alone, so that a check builds only them, and
# the shared test files that hold some of them{shared_note}.
file(GLOB RB_CHECK_SOURCES CONFIGURE_DEPENDS ${{CMAKE_SOURCE_DIR}}/tests/ch{nn}_*.cpp)
add_executable(raybook_check EXCLUDE_FROM_ALL source_dir.cpp ${{RB_CHECK_SOURCES}}
               {shared})
target_include_directories(raybook_check PRIVATE ${{CMAKE_SOURCE_DIR}}/src
                           ${{CMAKE_SOURCE_DIR}}/tests)
target_link_libraries(raybook_check PRIVATE rb_catch_main raybook Catch2::Catch2)
"""


def write_if_changed(path: Path, data: bytes) -> None:
    """Write a file only when its bytes change, so a build folder reused across exports
    recompiles only what changed."""
    if path.is_file() and path.read_bytes() == data:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)


def exercise_info(root: Path, n: int) -> list[dict]:
    page = page_of(root, n)
    heads = sections(page) if page else {}
    out = []
    for r in rg.find_regions(root):
        if r.chapter != n:
            continue
        out.append({"name": r.name, "id": r.id, "title": r.title, "anchor": r.anchor,
                    "section": heads.get(r.anchor, r.anchor),
                    "file": str(r.path.relative_to(root)), "tag": f"[ex{r.name}]"})
    return out


def compare_rows(root: Path, scene: Path | None) -> list[str]:
    """The README's rows that render the chapter's scene as its golden image was rendered
    (golden/NAME.txt: size, seed, args) and compare the two with ./rt --compare."""
    settings = root / "golden" / f"{scene.stem}.txt" if scene else None
    if not settings or not settings.exists():
        return []
    given = {"size": "192x144", "seed": "1", "args": ""}
    for line in settings.read_text().split("\n"):
        key, _, value = line.split("#")[0].strip().partition(" ")
        if key in given:
            given[key] = value.strip()
    render = (f"./rt --features=all --size {given['size']} --seed {given['seed']} "
              + (given["args"] + " " if given["args"] else "")
              + f"--output mine.png {scene.relative_to(root)}")
    stats = root / "golden" / f"{scene.stem}.stats"
    verdict = (f"./rt --compare golden/{scene.stem}.png mine.png --thresholds "
               f"golden/{scene.stem}.txt" + (f" --stats golden/{scene.stem}.stats"
                                             if stats.exists() else ""))
    noise = (" This chapter samples at random: a correct solution that draws other random "
             "numbers than raybook's differs from the golden by its noise here, and the next "
             "line's verdict is the one that counts." if stats.exists() else "")
    return [f"| `{render}` | renders the chapter's scene as its golden image was rendered "
            f"(`golden/{scene.stem}.txt`) |",
            f"| `./rt --compare golden/{scene.stem}.png mine.png --diff diff.png` | your render "
            f"against the golden image, in numbers: RMSE, PSNR, the largest difference and the "
            f"pixels more than one 8-bit level apart, which `diff.png` shows in magenta.{noise} |",
            f"| `{verdict}` | the verdict `make check` gives your picture, from the same code: "
            f"within the limits of `golden/{scene.stem}.txt`"
            + (", or else statistically the same estimate as raybook's renders"
               if stats.exists() else "") + " |"]


# ---- Doxygen to plain Markdown (the exported README is read on GitHub or in a terminal) ------

GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε",
         "varepsilon": "ε", "zeta": "ζ", "eta": "η", "theta": "θ", "kappa": "κ", "lambda": "λ",
         "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ",
         "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ",
         "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ",
         "Omega": "Ω"}
SYMBOLS = {"cdot": "·", "times": "×", "le": "≤", "leq": "≤", "ge": "≥", "geq": "≥", "ne": "≠",
           "neq": "≠", "approx": "≈", "infty": "∞", "to": "→", "rightarrow": "→", "pm": "±",
           "sum": "Σ", "prod": "Π", "int": "∫", "partial": "∂", "nabla": "∇", "ell": "ℓ",
           "propto": "∝", "in": "∈", "ldots": "…", "dots": "…", "cdots": "⋯", "sim": "∼",
           "lvert": "|", "rvert": "|", "lfloor": "⌊", "rfloor": "⌋", "lceil": "⌈", "rceil": "⌉",
           "quad": " ", "qquad": " ", "left": "", "right": ""}
# Names LaTeX sets upright: written as words.
FUNCTIONS = {"max", "min", "ln", "log", "exp", "cos", "sin", "tan", "arctan", "arcsin",
             "arccos", "atan2", "sqrt"}
ACCENTS = {"bar": "\u0304", "hat": "\u0302", "tilde": "\u0303", "vec": "\u20d7"}
SUPERSCRIPT = dict(zip("0123456789+-=()nikTp′", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱᵏᵀᵖ′"))
SUBSCRIPT = dict(zip("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ"))


def plain_math(tex: str) -> str:
    """A Doxygen formula (LaTeX) as plain text with Unicode: \\sigma_s(s)\\,T(a, s) becomes
    σₛ(s) T(a, s), P^{-1/3} becomes P^(−1/3), \\frac{a}{b} (a)/(b), \\mathbf{n} **n**."""
    group = r"\{((?:[^{}]|\{[^{}]*\})*)\}"

    def wrapped(body: str) -> str:  # a fraction's part: in parentheses unless one word
        return body if re.fullmatch(r"\\?\w+", body.strip()) else "(" + body + ")"
    text = tex.replace("\\{", "\x00").replace("\\}", "\x01")
    # Fractions, roots, fonts and accents, innermost first.
    for _ in range(4):
        text = re.sub(r"\\frac" + group + group,
                      lambda m: wrapped(m.group(1)) + "/" + wrapped(m.group(2)), text)
        text = re.sub(r"\\sqrt" + group, r"√(\1)", text)
        text = re.sub(r"\\(?:text|mathrm|operatorname|mathit)" + group, r"\1", text)
        text = re.sub(r"\\mathbf" + group, r"**\1**", text)
        text = re.sub(r"\\(bar|hat|tilde|vec)\s*(?:" + group + r"|(\\[a-zA-Z]+|\w))",
                      lambda m: (m.group(2) or m.group(3)) + "\x02" + m.group(1), text)
    text = re.sub(r"\\sqrt\s*", "√", text)
    text = re.sub(r"\\([,;:! ])", lambda m: "" if m.group(1) == "!" else " ", text)

    def command(m: re.Match) -> str:
        name = m.group(1)
        if name in GREEK:
            return GREEK[name]
        if name in SYMBOLS:
            return SYMBOLS[name]
        return name if name in FUNCTIONS else m.group(0)
    text = re.sub(r"\\([a-zA-Z]+)", command, text)
    text = re.sub(r"(.)\x02(bar|hat|tilde|vec)", lambda m: m.group(1) + ACCENTS[m.group(2)],
                  text)
    text = text.replace("'", "′").replace("-", "−")

    def script(m: re.Match) -> str:
        mark, body = m.group(1), m.group(2) if m.group(2) is not None else m.group(3)
        table = SUPERSCRIPT if mark == "^" else SUBSCRIPT
        plain = body.replace("−", "-")
        if all(c in table for c in plain):
            return "".join(table[c] for c in plain)
        return mark + (body if re.fullmatch(r"\w+", body) else "(" + body + ")")
    text = re.sub(r"([\^_])(?:" + group + r"|([^\s{\\]))", script, text)
    text = text.replace("{", "").replace("}", "").replace("\x00", "{").replace("\x01", "}")
    return re.sub(r"  +", " ", text).strip()


def plain_markdown(text: str, headings: dict[str, str]) -> str:
    """Chapter-page Markdown without Doxygen's own markup: formulas (\\f$...\\f$, \\f[...\\f])
    as Unicode text, \\ref as the text or heading it names with its anchor."""
    text = re.sub(r"\\f\[(.*?)\\f\]", lambda m: "\n\n    " + plain_math(m.group(1)) + "\n\n",
                  text, flags=re.S)
    text = re.sub(r"\\f\$(.*?)\\f\$", lambda m: plain_math(m.group(1)), text, flags=re.S)

    def ref(m: re.Match) -> str:
        anchor, label = m.group(1), m.group(2)
        return f"*{label or headings.get(anchor, anchor)}* (`#{anchor}`)"
    return re.sub(r'\\ref ([\w-]+)(?: "([^"]*)")?', ref, text)


def page_headings(root: Path) -> dict[str, str]:
    """Anchor -> heading text over every chapter page."""
    found: dict[str, str] = {}
    for page in sorted((root / "chapters").glob("*.md")):
        found.update(sections(page))
    return found


def readme(root: Path, n: int, exercises: list[dict], left: list[str]) -> str:
    """The exported project's README, built from the chapter page."""
    page = page_of(root, n)
    text = page.read_text() if page else ""
    lines = text.split("\n")
    title = re.sub(r"\s*\{#[\w-]+\}", "", lines[0].lstrip("# ")) if lines else f"Chapter {n}"
    intro = []
    for line in lines[1:]:
        if line.startswith("#") or line.strip() == "[TOC]":
            break
        intro.append(line)
    scene = scene_of(root, n)
    page_rel = page.relative_to(root) if page else "chapters/"
    out = [f"# Assignment: {title}", "",
           f"This project holds chapters 1 to {n} of raybook. Chapters 1 to {n - 1} are "
           f"complete; in chapter {n} the code that *is* the chapter's idea has been taken out "
           f"and replaced by stubs. Each stub throws `rb::ExerciseNotDone`, which names the "
           f"exercise and the section of `{page_rel}` that explains it.", ""]
    headings = page_headings(root)
    out += plain_markdown("\n".join(intro).strip(), headings).split("\n")
    out += ["", "## What to implement, in this order", "",
            f"Read `{page_rel}` first. Then write each exercise between its two "
            "`// [exercise-…]` marker comments (keep the markers):", ""]
    for e in exercises:
        out.append(f"{e['name'].split('.')[1]}. **Exercise {e['name']}, {e['title']}**, in "
                   f"`{e['file']}`. Read the section *{e['section']}* (`#{e['anchor']}`). "
                   f"Its tests carry the tag `{e['tag']}`.")
    out += ["", "Write them in this order: each exercise's row in `make check` holds the tests "
            "that need it and none of the later exercises, so it turns green as soon as it and "
            "the exercises before it are written, while the later ones are still stubs. A test "
            "that needs several exercises carries the tag of each (run "
            f"`build/tests/raybook_check \"{exercises[0]['tag'] if exercises else '[exN.1]'}\"` "
            "for every test that needs that exercise) and counts in the row of the last of "
            "them."]
    # The sampling lab's commands the chapter's Exercises section names (./rt --warptest NAME).
    exercises_text = re.search(r"\n## Exercises \{#[\w-]+\}\n(.*?)(\n## |\Z)", text, re.S)
    lab = list(dict.fromkeys(re.findall(r"`\./rt --warptest ([\w-]+)`",
                                        exercises_text.group(1) if exercises_text else "")))
    lab_rows = [f"| `./rt --warptest {name}` | after `make chapter{n}`: draws your sampler's "
                f"points against the pdf your code states, prints the chi-square statistic, "
                f"degrees of freedom, p-value and PASS or FAIL, and writes "
                f"`warptest-{name}.svg` (observed, expected, their difference) |" for name in lab]
    out += ["",
            "## How to check your work", "",
            "| command | what it does |", "|---|---|",
            f"| `make check` | builds chapter {n}'s tests, runs each exercise's tests and the "
            f"golden image, and prints a table: exercise, tests passed, pass/fail, what to read. "
            f"When the picture is wrong it names the HTML report that shows the expected and "
            f"your image and their difference |",
            f"| `make chapter{n}` | builds `./rt` from chapters 1 to {n} |",
            f"| `./rt --features=all {scene.relative_to(root) if scene else 'scenes/'}` | "
            f"renders the chapter's scene |",
            *lab_rows,
            *compare_rows(root, scene),
            f"| `build/tests/raybook_check \"[ex{n}.1]\"` | after `make check`, runs the "
            f"tests that need exercise {n}.1 with Catch2's full messages "
            f"(`check` names the spec of a failing row) |",
            f"| `make test` | every test of chapters 1 to {n} and their golden images |",
            f"| `make docs` | the chapter pages 1 to {n} with their formulas and code, into "
            f"`docs/html/index.html` (chapter {n}'s exercises show their stubs) |", "",
            "A stub that is still in place makes its tests fail with a message such as "
            f"`exercise {exercises[0]['name'] if exercises else n} (...) is not written yet: "
            "read the section ... of the chapter page`.", ""]
    if left:
        out += ["Tests of chapters 1 to {} that use code of a later chapter are left out of this "
                "project:".format(n), ""] + [f"- {l}" for l in left] + [""]
    more = re.search(r"\n## Exercises \{#[\w-]+\}\n(.*?)(\n## |\Z)", text, re.S)
    if more:
        challenges = re.split(r"\n\n(?=1\. )", more.group(1), maxsplit=1)
        if len(challenges) == 2:
            out += ["## Going further", "", plain_markdown(challenges[1].strip(), headings), ""]
    return "\n".join(out)


def export(args) -> int:
    root = ROOT
    n = args.chapter
    chapters = book_chapters(root)
    if n not in chapters:
        sys.exit(f"assignment: chapter {n} is not written; the written chapters are "
                 f"{' '.join(str(c) for c in sorted(chapters))}")
    dest = Path(args.dir).resolve()
    # Inside the repository only under a folder of its own: assignment-chNN/ or the build
    # folder (make test's grade test exports into build/grade-test/class/NAME).
    if dest == root or root in dest.parents and not dest.relative_to(root).parts[0].startswith(
            ("assignment", "build")):
        sys.exit(f"assignment: refusing to write into {dest}: an export inside raybook "
                 f"would mix with raybook's own files; use a folder whose name starts with "
                 f"'assignment' or 'build' (such as {root / f'assignment-ch{n:02d}'}), or a "
                 f"folder outside {root}")
    files = [p for p in tracked_files(root) if not left_out(p)
             and (owner(p, chapters) or 0) <= n and shared_test_fits(root, p, chapters, n)]
    exercises = exercise_info(root, n)
    if not exercises:
        sys.exit(f"assignment: chapter {n} has no exercise regions")
    contents: dict[str, bytes] = {p: (root / p).read_bytes() for p in files}
    # Chapter N's regions become stubs.
    for rel, text in stub_files([r for r in rg.find_regions(root) if r.chapter == n],
                                root).items():
        contents[rel] = text.encode()
    contents["CMakeLists.txt"] = trim_cmake(contents["CMakeLists.txt"].decode(), chapters,
                                            n).encode()
    contents["tests/test_helpers.h"] = trim_test_helpers(
        contents["tests/test_helpers.h"].decode(), chapters, n).encode()
    # Test files and scenarios that use a later chapter's code are left out.
    modules, names = dropped_names(root, chapters, n, contents["tests/test_helpers.h"].decode())
    left = []
    for rel in [r for r in contents if re.match(r"^tests/[^/]+\.cpp$", r)]:
        trimmed, removed = trim_test_file(contents[rel].decode(), modules, names, n)
        if trimmed is None:
            del contents[rel]
            left.append(f"{rel} (the whole file)")
        else:
            contents[rel] = trimmed.encode()
            left += [f"{rel}: {s}" for s in removed]
    # Benchmarks and fuzz targets are not part of an assignment.
    for folder in ("tests/perf", "tests/fuzz"):
        contents[f"{folder}/CMakeLists.txt"] = b"# Not part of an assignment (see raybook).\n"
    # make check runs chapter N's tests only (its rows' [exN.k] and the other [chNN] ones):
    # a shared test file (tests/stability.cpp) goes into raybook_check only when it holds one,
    # since compiling it costs a first check, and every step of the round trip, as much as a
    # chapter's own test file. Its tests of other chapters run in make test.
    mine = re.compile(rf"\[(?:ch{n:02d}|ex{n}\.\d+)\]")
    shared = sorted(rel for rel in contents if re.match(r"^tests/stability[^/]*\.cpp$", rel)
                    and mine.search(contents[rel].decode()))
    contents["tests/CMakeLists.txt"] += CHECK_CMAKE.format(
        n=n, nn=f"{n:02d}", shared_note=f" ({', '.join(shared)})" if shared else " (none here)",
        shared=" ".join("${CMAKE_SOURCE_DIR}/" + rel for rel in shared)).encode()
    template = (root / "tests/exercises/assignment.mk").read_text()
    contents["Makefile"] = template.replace("@CHAPTER@", str(n)).replace(
        "@WHOLE_BOOK@", "|".join(WHOLE_BOOK_SUITES + [s for s, k in SUITES_NEEDING.items()
                                                     if k > n])).encode()
    contents["README.md"] = readme(root, n, exercises, left).encode()
    # The golden report's advice: raybook's maintainers re-render a golden image on purpose
    # (make golden-update); an assignment has no such target, its golden images are fixed.
    for rel in ("src/app/compare.cpp", "tests/golden/run_golden.sh"):
        if rel in contents:
            text = re.sub(r'If (?:the|a) change is intended, run <code>make(?:\s|"\s*")*'
                          r'golden-update</code> and say(?:[^."]|"\s*")*\.',
                          "The golden images are raybook's: change your code in src/, never "
                          "them.", contents[rel].decode())
            text = text.replace("; run make golden-update",
                                "; export the assignment again (raybook's make assignment N)")
            contents[rel] = text.encode()
    for rel, data in contents.items():
        if rel.startswith("tests/golden/") and b"golden-update" in data:
            sys.exit(f"assignment: {rel} would tell a student to run make golden-update, which "
                     f"an assignment lacks: teach export() to reword it")
    # The docs of chapters 1..N (make docs): chapter N's listings show the stubs, since the
    # sources do.
    import student_docs  # raybook's only (see tracked_files)
    contents.update(student_docs.export_docs(root, n, {
        p: contents[p].decode() for p in contents if re.match(r"^chapters/\d\d-.*\.md$", p)}))
    contents[".gitignore"] = b"/build/\n/rt\n/rt.tmp*\n/*.png\n/docs/html/\n"
    scene = scene_of(root, n)
    info = {"chapter": n, "page": str(page_of(root, n).relative_to(root)),
            "scene": str(scene.relative_to(root)) if scene else None,
            "exercises": exercises, "left_out": left}
    contents[INFO] = (json.dumps(info, indent=2) + "\n").encode()
    # Sync: write what changed, remove what the export no longer has.
    dest.mkdir(parents=True, exist_ok=True)
    for rel, data in contents.items():
        write_if_changed(dest / rel, data)
        if (root / rel).is_file() and os.access(root / rel, os.X_OK):
            (dest / rel).chmod(0o755)
    for path in sorted(dest.rglob("*"), reverse=True):
        rel = str(path.relative_to(dest))
        if rel.startswith("build") or rel in ("rt",):
            continue
        if path.is_file() and rel not in contents:
            path.unlink()
        elif path.is_dir() and not any(path.iterdir()):
            path.rmdir()
    print(f"assignment: chapter {n} written to {dest} "
          f"({len(exercises)} exercises: {', '.join(e['name'] for e in exercises)})")
    print(f"  cd {dest} && make check")
    return 0


def stub_text(text: str, regions: list[rg.Region]) -> str:
    """A file's text with some of its regions' code replaced by their stubs (markers and
    header comments stay), and the stub's header included."""
    lines = text.split("\n")
    # From the bottom up, so that the line numbers of the regions above stay right.
    for region in sorted(regions, key=lambda r: -r.begin):
        header_end = region.begin + (3 if region.blank is not None else 2)
        lines = lines[:header_end] + [region.indent + region.stub()] + lines[region.end:]
    if '#include "core/error.h"' not in lines:
        first = next((i for i, l in enumerate(lines) if l.startswith("#include")), 0)
        lines.insert(first + 1, '#include "core/error.h"')
    return "\n".join(lines)


def stub_files(regions: list[rg.Region], root: Path) -> dict[str, str]:
    """Path (relative to root) -> text with the given regions stubbed."""
    by_file: dict[Path, list[rg.Region]] = {}
    for r in regions:
        by_file.setdefault(r.path, []).append(r)
    return {str(path.relative_to(root)): stub_text(path.read_text(), rs)
            for path, rs in by_file.items()}


def solve_regions(project: Path, ids: set[str] | None = None) -> None:
    """Put raybook's code back into the project's regions of its chapter (all, or those whose
    id is in `ids`)."""
    n = json.loads((project / INFO).read_text())["chapter"]
    for r in rg.find_regions(ROOT):
        if r.chapter != n or (ids is not None and r.id not in ids):
            continue
        original = r.path.read_text().split("\n")
        target = project / r.path.relative_to(ROOT)
        lines = target.read_text().split("\n")
        begin = next(i for i, l in enumerate(lines) if l.strip() == f"// [exercise-{r.id}]")
        end = next(i for i in range(begin + 1, len(lines))
                   if lines[i].strip() == f"// [exercise-{r.id}]")
        lines[begin:end + 1] = original[r.begin:r.end + 1]
        write_if_changed(target, "\n".join(lines).encode())


def solve(args) -> int:
    """Put raybook's region code back into a project's stubs."""
    project = Path(args.project).resolve()
    solve_regions(project)
    n = json.loads((project / INFO).read_text())["chapter"]
    print(f"assignment: chapter {n}'s regions restored in {project}")
    return 0


# ---- Checking -------------------------------------------------------------------------------

def run(command, timeout, cwd=None, env=None, on_line=None) -> tuple[int, str]:
    """Run a command; return its exit code (124 on timeout, -1 when it cannot start) and its
    output. With `on_line`, each line of output is handed to it as it comes."""
    # A make started from inside another make must not inherit its job server.
    env = {k: v for k, v in (env or os.environ).items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    if on_line is not None:
        return run_line_by_line(command, timeout, cwd, env, on_line)
    try:
        p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, errors="replace", timeout=timeout, cwd=cwd, env=env)
        return p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        return 124, out + f"\n(timed out after {timeout} s)"
    except OSError as e:  # the program is missing: its build failed, which is reported there
        return -1, f"cannot run {command[0]}: {e.strerror}"


def run_line_by_line(command, timeout, cwd, env, on_line) -> tuple[int, str]:
    """run() for a command whose output is shown while it runs."""
    try:
        p = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True, errors="replace", cwd=cwd, env=env)
    except OSError as e:
        return -1, f"cannot run {command[0]}: {e.strerror}"
    timed_out = threading.Event()
    timer = threading.Timer(timeout, lambda: (timed_out.set(), p.kill()))
    timer.start()
    lines = []
    try:
        for line in p.stdout:
            lines.append(line)
            on_line(line.rstrip("\n"))
        code = p.wait()
    finally:
        timer.cancel()
    out = "".join(lines)
    return (124, out + f"\n(timed out after {timeout} s)") if timed_out.is_set() else (code, out)


# A first make check compiles every chapter up to the assignment's and its tests: chapter 17's
# export, 119 files, compiled in 3.7 minutes on a quiet 2-core machine with an empty ccache
# (2026-11-30; the whole make check took 3 min 53 s), and took 11 to 28 minutes on a busy one
# (issue 39; 16 minutes under a load near 10): about 4 to 30 seconds of one core per file.
CORE_SECONDS_PER_FILE = (4, 30)


def build_targets(build: Path, targets: list[str], say=None) -> tuple[int, str]:
    """`cmake --build` of `targets`. With `say`, tell a student what is built, step by step:
    "[12/57] building chapter 9: src/smooth_mesh/vertex_normals.cpp"; a first build says
    once how long it will take."""
    command = ["cmake", "--build", str(build), "-j", JOBS, "--target", *targets]
    if say is None:
        return run(command, BUILD_TIMEOUT)
    first = not (build / "tests" / "raybook_check").exists()
    total = len(planned_compiles(build, targets, first))
    if first and total:
        cores = int(JOBS)
        low, high = (max(1, round(total * s / cores / 60)) for s in CORE_SECONDS_PER_FILE)
        say(f"make check: the first build compiles {total} files (every chapter up to this "
            f"one, and the tests) on {cores} core{'s' * (cores > 1)}: about "
            f"{low} minutes, up to {high} on a busy machine. Later checks compile only what "
            f"changed.")
    done = 0

    def tell(line: str) -> None:
        nonlocal done, total
        # Under a make whose output is a terminal (make check), CMake colours its lines.
        line = re.sub(r"\x1b\[[0-9;]*m", "", line)
        compiled = re.search(r"Building CXX object (\S+?)\.o$", line)
        linked = re.search(r"Linking CXX (?:executable|static library) (\S+)$", line)
        if compiled:
            done += 1
            total = max(total, done)
            say(f"[{done}/{total}] building {compiled_what(compiled.group(1))}")
        elif linked:
            say(f"        linking {Path(linked.group(1)).name}")
        elif re.search(r"error|Error \d", line):
            say(line)

    return run(command, BUILD_TIMEOUT, on_line=tell)


def planned_compiles(build: Path, targets: list[str], first: bool) -> set[str]:
    """The objects `cmake --build` of `targets` will compile. A first build compiles every
    object of the targets and of all they depend on (CMake's Makefile2 lists each target's
    dependencies as "A.dir/all: B.dir/all", each target's build.make its objects); a later
    one what make's dry run lists (it names an object once per target that needs it)."""
    found = r"Building CXX object (\S+?)\.o\b"
    if not first:
        _, planned = run(["cmake", "--build", str(build), "--target", *targets, "--", "-n"], 120)
        return set(re.findall(found, planned))
    graph = (build / "CMakeFiles" / "Makefile2").read_text(errors="replace")
    needs = {}
    for target, needed in re.findall(r"^(\S+\.dir)/all: (\S+\.dir)/all$", graph, re.M):
        needs.setdefault(target, set()).add(needed)
    folders = {f"{'tests/' * (t == 'raybook_check')}CMakeFiles/{t}.dir" for t in targets}
    todo = list(folders)
    while todo:
        for needed in needs.get(todo.pop(), ()):
            if needed not in folders:
                folders.add(needed)
                todo.append(needed)
    compiles = set()
    for folder in folders:
        rules = build / folder / "build.make"
        if rules.is_file():
            compiles |= set(re.findall(found, rules.read_text(errors="replace")))
    return compiles


def compiled_what(object_path: str) -> str:
    """An object file named as a student reads it: "chapter 9: src/smooth_mesh/normals.cpp",
    "the tests: tests/ch17_media.cpp"."""
    target, _, source = object_path.partition(".dir/")
    chapter = re.search(r"rb_ch(\d+)$", target)
    if chapter:
        return f"chapter {int(chapter.group(1))}: {source}"
    if target.endswith("raybook_check"):
        return f"the tests: tests/{source}"
    return source


def catch_escape(name: str) -> str:
    """A test name as a Catch2 test spec that matches only it."""
    return re.sub(r"([\\\[\],*~\"])", r"\\\1", name)


def list_tests(program: Path, spec: str) -> list[str]:
    code, out = run([str(program), spec, "--list-test-names-only"], 60)
    return [l for l in out.split("\n") if l.strip()] if code >= 0 else []


def run_tests(program: Path, names: list[str], cwd: Path, fail_fast: bool = False) -> list[dict]:
    """Run each test in its own process (a crash or hang fails that test alone); with
    `fail_fast`, stop at the first failure."""
    results = []
    for name in names:
        if fail_fast and results and not results[-1]["passed"]:
            break
        code, out = run([str(program), catch_escape(name)], TEST_TIMEOUT, cwd=cwd)
        why = ""
        if code != 0:
            # Catch2 wraps long messages after a hyphen ("ch10-" / "mesh"): rejoin those words.
            flat = " ".join(re.sub(r"(?<=\w)-\n\s*(?=\w)", "-", out).split())
            stub = re.search(r"exercise \S+ \(.*?\) is not written yet: .*?replace this stub", flat)
            failed = re.search(r"(\S+:\d+: FAILED:.*?)(?: -{20}| ={20}|$)", flat)
            why = (stub.group(0) if stub else f"timed out after {TEST_TIMEOUT} s" if code == 124
                   else failed.group(1)[:400] if failed and code > 0
                   else f"failed (exit {code})" if code > 0 else f"crashed (signal {-code})")
        results.append({"name": name, "passed": code == 0, "why": why, "output": out[-3000:]})
    return results


def row_spec(exercises: list[dict], k: int) -> str:
    """The Catch2 test spec of exercise k's row (k counts from 0): the tests tagged with it and
    with none of the chapter's later exercises. A test carries the tag of every exercise it
    needs, so it sits in the row of the last of them and passes once exercises 1..k are
    written, while the later ones are still stubs."""
    return exercises[k]["tag"] + "".join("~" + e["tag"] for e in exercises[k + 1:])


def use_compiler_cache(cache: Path, strip: Path) -> None:
    """The compiler cache of the round trip, make grade and mc_golden.py, which build exports
    in PROJECT/build, the folder make check uses. With ccache installed (make deps installs
    it) no launcher is given: the export's CMakeLists.txt puts ccache in front of the compiler
    with the project as its base folder, so its keys name the sources relative to the build
    folder (../src/core/sphere.cpp), as raybook's own build in the clone's build/ does. A file
    the export did not change is then the object raybook's build compiled (chapter 1's core,
    the earlier chapters), and a project's copy in another folder (the other slot, a grading
    stage) takes it too. Without ccache, objcache.py (keyed on the preprocessed source, with
    STRIP/<project> taken out) shares objects between projects side by side in `strip`. A
    launcher already in $RB_COMPILER_LAUNCHER wins."""
    if "RB_COMPILER_LAUNCHER" in os.environ or shutil.which("ccache"):
        return
    here = Path(__file__).resolve().parent
    os.environ["RB_COMPILER_LAUNCHER"] = f"{sys.executable};{here / 'objcache.py'}"
    os.environ.setdefault("RB_OBJCACHE", str(cache))
    os.environ.setdefault("RB_OBJCACHE_STRIP", str(strip))


def use_ninja() -> None:
    """Build the round trip's and mc_golden.py's exports with Ninja when it is installed (make
    deps installs it; $RB_CMAKE_GENERATOR, when set, wins). A round-trip step builds one or
    two changed files, and a chapter's round trip builds 2K + 1 times for K exercises: with
    CMake's Makefiles each build spends about 3 s of CPU checking that nothing else changed
    (make's recursion over every chapter's library and their dependency scans), with Ninja
    0.2 s. make check and make grade keep CMake's default generator."""
    if "RB_CMAKE_GENERATOR" not in os.environ and shutil.which("ninja"):
        os.environ["RB_CMAKE_GENERATOR"] = "Ninja"


def cache_generator(build: Path) -> str | None:
    """The CMake generator a configured build folder uses, or None."""
    cache = build / "CMakeCache.txt"
    if not cache.is_file():
        return None
    m = re.search(r"^CMAKE_GENERATOR:INTERNAL=(.*)$", cache.read_text(errors="replace"), re.M)
    return m.group(1) if m else None


def configured(build: Path, project: Path, launcher: str | None,
               generator: str | None = None) -> bool:
    """Whether `build` is a configured build folder of `project`, with `launcher` (and with
    `generator`, when given)."""
    cache = build / "CMakeCache.txt"
    rules = "build.ninja" if (generator or cache_generator(build)) == "Ninja" else "Makefile"
    if not cache.is_file() or not (build / rules).is_file():
        return False
    text = cache.read_text(errors="replace")
    home = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$", text, re.M)
    given = re.search(r"^CMAKE_CXX_COMPILER_LAUNCHER:[A-Z]+=(.*)$", text, re.M)
    return (home is not None and Path(home.group(1)).resolve() == project.resolve()
            and (given.group(1) if given else None) == launcher
            and generator in (None, cache_generator(build)))


def check_project(project: Path, build: Path, golden: bool = True,
                  others: bool | set[str] = True, rows: set[int] | None = None,
                  fail_fast: bool = False, skip: set[str] = frozenset(), say=None) -> dict:
    """Build and check one exported project; return its results (never raises on a student's
    failure: a build failure is a result). With `say`, each step is told as it starts (make
    check: a student must see it work). Without `golden` the chapter's binary is neither
    built nor rendered, without `others` the untagged tests are not run (given a set of test
    names, only those of them); only the exercise rows in `rows` (indices from 0) are run when
    it is given, the others are "not run"; with `fail_fast` a row stops at its first failing
    test (its verdict is the same); the tests named in `skip` are not run, and a row left with
    none is "not run". The round trip's steps between the stubbed and the solved project, and
    its planted bugs, use these."""
    info = json.loads((project / INFO).read_text())
    n = info["chapter"]
    result = {"project": str(project), "chapter": n, "build": "ok", "build_log": "",
              "exercises": [], "golden": {"status": "not run", "metric": "", "report": ""}}
    build.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    configure = ["cmake", "-S", str(project), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"]
    launcher = os.environ.get("RB_COMPILER_LAUNCHER")
    if launcher:
        configure.append(f"-DCMAKE_CXX_COMPILER_LAUNCHER={launcher}")
    generator = os.environ.get("RB_CMAKE_GENERATOR") or None  # use_ninja()
    if generator:
        configure += ["-G", generator]
        if cache_generator(build) not in (None, generator):  # CMake refuses to switch
            (build / "CMakeCache.txt").unlink()
            shutil.rmtree(build / "CMakeFiles", ignore_errors=True)
    # A build folder already configured for this project needs no second configure (2 s each
    # time): `cmake --build` configures again by itself when a CMakeLists.txt or a globbed
    # folder changed.
    tell = say or (lambda _: None)
    if configured(build, project, launcher, generator):
        code, out = 0, ""
    else:
        tell(f"make check: configuring the build in {build}")
        code, out = run(configure, 300)
    if code == 0:
        # Chapter N's tests and, for the golden image, its rt: nothing else of the project.
        targets = ["raybook_check"] + ([f"rt_ch{n}"] if golden else [])
        code, out = build_targets(build, targets, say)
    if code != 0:
        result["build"] = "timed out" if code == 124 else "failed"
        errors = [l for l in out.split("\n") if "error" in l.lower()]
        result["build_log"] = "\n".join(errors[:15]) or out[-2000:]
        for e in info["exercises"]:
            result["exercises"].append({**e, "tests": 0, "passed": 0, "status": "no build",
                                        "failures": []})
        return result
    result["seconds"] = {"build": time.monotonic() - started}
    started = time.monotonic()
    program = build / "tests" / "raybook_check"
    tagged = set()
    # How many of the chapter's exercises each test needs (one tag each).
    needs = collections.Counter(t for e in info["exercises"]
                                for t in list_tests(program, e["tag"]))
    for k, e in enumerate(info["exercises"]):
        spec = row_spec(info["exercises"], k)
        names = list_tests(program, spec)
        tagged.update(names)
        # A row runs its narrowest tests first: a test that needs only this exercise tests it
        # most directly, and is the cheapest (chapter 17's widest, the slab's closed form, takes
        # 19 s), so with `fail_fast` a stub's row stops at once.
        run_names = sorted((t for t in names if t not in skip), key=lambda t: needs[t])
        if (rows is not None and k not in rows) or (names and not run_names):
            result["exercises"].append({**e, "spec": spec, "tests": len(names), "passed": 0,
                                        "status": "not run", "failures": []})
            continue
        tell(f"make check: exercise {e['name']}: running its {len(run_names)} "
             f"test{'s' * (len(run_names) != 1)}")
        tests = run_tests(program, run_names, project, fail_fast)
        passed = sum(t["passed"] for t in tests)
        status = "pass" if run_names and passed == len(run_names) else "fail"
        result["exercises"].append({**e, "spec": spec, "tests": len(names), "passed": passed,
                                    "status": status,
                                    "failures": [t for t in tests if not t["passed"]]})
    # The chapter's other tests (those that need no exercise of the chapter).
    if others:
        rest = [t for t in list_tests(program, f"[ch{n:02d}]") if t not in tagged
                and (others is True or t in others)]
        tell(f"make check: chapter {n}'s other tests ({len(rest)})")
        tests = run_tests(program, rest, project)
        result["others"] = {"tests": len(rest), "passed": sum(t["passed"] for t in tests),
                            "failures": [t for t in tests if not t["passed"]]}
    result["seconds"]["tests"] = time.monotonic() - started
    started = time.monotonic()
    # The golden image.
    if golden and info.get("scene"):
        tell(f"make check: rendering {Path(info['scene']).name} for the golden image")
        report = build / "golden-report"
        code, out = run(["bash", str(project / "tests/golden/run_golden.sh"),
                         str(build / f"rt_ch{n}"), info["scene"], str(project / "golden"),
                         str(report),
                         "--report-name=check", "--statistical"], 600, cwd=project)
        name = Path(info["scene"]).stem
        m = re.search(r"RMSE ([0-9.eE+-]+)", out)
        html = report / "check.html"
        stats = project / "golden" / f"{name}.stats"
        renders = (re.search(r"^renders (\d+)$", stats.read_text(errors="replace"), re.M)
                   if stats.is_file() else None)
        result["golden"] = {"status": "pass" if code == 0 else "fail", "scene": name,
                            "metric": m.group(1) if m else "", "output": out.strip()[-1500:],
                            "report": str(html) if code != 0 and html.exists() else "",
                            "stats_renders": renders.group(1) if renders else ""}
    result["seconds"]["golden"] = time.monotonic() - started
    return result


def table(result: dict) -> str:
    n = result["chapter"]
    rows = ["| exercise | tests | pass/fail | what to read |", "|---|---|---|---|"]
    for e in result["exercises"]:
        tests = f"{e['passed']}/{e['tests']} `{e['tag']}`" if result["build"] == "ok" else "-"
        rows.append(f"| {e['name']} {e['title']} | {tests} | {e['status']} | "
                    f"{e['section']} (`#{e['anchor']}`), `{e['file']}` |")
    if result["build"] != "ok":
        return "\n".join(rows) + f"\n\nbuild {result['build']}:\n{result['build_log']}"
    o = result.get("others", {"tests": 0})
    if o["tests"]:
        rows.append(f"| chapter {n}, other tests | {o['passed']}/{o['tests']} `[ch{n:02d}]` | "
                    f"{'pass' if o['passed'] == o['tests'] else 'fail'} | the whole page |")
    g = result["golden"]
    if g["status"] != "not run":
        if g["report"]:
            what = "diff: " + g["report"]
        elif g["status"] == "fail":
            what = (g.get("output", "").split("\n")[0].split(": ", 1)[-1] or "the render failed")
        elif "the same estimate" in g.get("output", ""):
            what = statistical_verdict(g)
        else:
            what = f"golden/{g.get('scene', '')}.png"
        rows.append(f"| golden image {g.get('scene', '')} | rmse {g['metric'] or '-'} | "
                    f"{g['status']} | {what} |")
    return "\n".join(rows)


def statistical_verdict(g: dict) -> str:
    """The golden row's words for a render that is not the golden's pixels but passed the
    statistical check (src/app/block_stats.h): what was compared, and what it shows and does
    not. It says nothing of random numbers: a chapter whose exercises draw none (chapter 16's
    radius and density) passes this way too, with a difference smaller than the noise."""
    out = g.get("output", "")
    rmse = re.search(r"RMSE ([0-9.eE+-]+) > ([0-9.eE+-]+)", out)
    blocks = re.search(r"\((\d+) of (\d+) (blocks|groups of [^)]*?blocks) off", out)
    renders = g.get("stats_renders", "")
    return (f"golden/{g.get('scene', '')}.png: not its pixels"
            + (f" (RMSE {rmse.group(1)} > {rmse.group(2)})" if rmse else "")
            + f"; compared block by block with raybook's own {renders + ' ' * bool(renders)}"
            f"renders (golden/{g.get('scene', '')}.stats)"
            + (f", {blocks.group(1)} of {blocks.group(2)} {blocks.group(3)} off" if blocks
               else "")
            + ": the same picture up to their noise, but a difference smaller than that noise "
            "is not seen")


def passed_all(result: dict) -> bool:
    return (result["build"] == "ok" and all(e["status"] == "pass" for e in result["exercises"])
            and result.get("others", {}).get("passed", 0) == result.get("others", {}).get(
                "tests", 0) and result["golden"]["status"] in ("pass", "not run"))


def check(args) -> int:
    project = Path(args.project).resolve()
    if not (project / INFO).is_file():
        sys.exit(f"check: {project} is not an exported assignment (no {INFO}); "
                 "make one with make assignment N")
    build = Path(args.build).resolve() if args.build else project / "build"
    result = check_project(project, build, say=lambda line: print(line, flush=True))
    print()
    print(table(result))
    for e in result["exercises"]:
        for t in e.get("failures", [])[:1]:
            print(f"\n{e['name']}: {t['name']}\n  {t['why']}")
            if len(e["failures"]) > 1:
                print(f"  (and {len(e['failures']) - 1} more; run build/tests/raybook_check "
                      f"\"{e.get('spec', e['tag'])}\" for every message)")
    if result["golden"]["status"] == "fail":
        print("\ngolden image: " + "\n  ".join(result["golden"]["output"].splitlines()[:3]))
        if result["golden"]["report"]:
            print(f"  open {result['golden']['report']} (expected, yours, and the difference)")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=2))
    ok = passed_all(result)
    print("\nall exercises pass" if ok else "\nnot done yet")
    return 0 if ok else 1


def changed_tests(project: Path) -> list[str]:
    """The files a grade relies on (tests, golden images, scenes, the exercise list) that
    differ from a fresh export of the same chapter by this raybook: a student is to change
    src/ only."""
    n = json.loads((project / INFO).read_text())["chapter"]
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / "assignment"
        code, out = run([sys.executable, __file__, "export", str(n), str(fresh)], 300)
        if code != 0:
            return [f"(cannot export chapter {n} to compare: {out.strip()[-200:]})"]
        changed = []
        for path in sorted(fresh.rglob("*")):
            rel = path.relative_to(fresh)
            if path.is_file() and (rel.parts[0] in ("tests", "golden", "scenes")
                                   or str(rel) == INFO) and "exercises" not in rel.parts:
                theirs = project / rel
                if not theirs.is_file() or theirs.read_bytes() != path.read_bytes():
                    changed.append(str(rel))
        return changed


def sync_tree(source: Path, dest: Path, skip: set[str]) -> None:
    """Make dest hold source's files (top-level names in `skip` left out), writing only the
    files whose bytes differ, so their modification times tell make what changed."""
    dest.mkdir(parents=True, exist_ok=True)
    wanted = set()
    for path in source.rglob("*"):
        rel = path.relative_to(source)
        if rel.parts[0] in skip or not path.is_file() or path.is_symlink():
            continue
        wanted.add(rel)
        target = dest / rel
        data = path.read_bytes()
        if not target.is_file() or target.read_bytes() != data:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
    for path in sorted(dest.rglob("*"), reverse=True):
        rel = path.relative_to(dest)
        if path.is_file() and rel not in wanted and rel.parts[0] not in skip:
            path.unlink()


def keep_report(result: dict, stage: Path, project: Path, build: Path) -> None:
    """Copy a graded stage's golden report to the student's build folder, and name the
    student's paths in the result instead of the stage's."""
    result["project"] = str(project)
    report = result["golden"].get("report", "")
    if report:
        shutil.rmtree(build / "golden-report", ignore_errors=True)
        shutil.copytree(stage / "project" / "build" / "golden-report", build / "golden-report")
        result["golden"]["report"] = str(build / "golden-report" / Path(report).name)


# ---- Grading --------------------------------------------------------------------------------

def grade(args) -> int:
    target = Path(args.dir).resolve()
    projects = ([target] if (target / INFO).is_file() else
                sorted(p for p in target.iterdir() if (p / INFO).is_file()))
    if not projects:
        sys.exit(f"grade: no exported assignment in {target} (looked for {INFO})")
    out = Path(args.csv) if args.csv else (target if target.is_dir() and len(projects) > 1
                                          else target.parent) / "grades.csv"
    # Compile what is the same once: ccache, keyed on paths relative to the project (or,
    # without ccache, objcache.py, keyed on the preprocessed source with each project's folder
    # taken out, kept beside the builds for the next run), so the second student's build
    # compiles only the files that student changed (use_compiler_cache).
    cache_root = Path(args.build_root).resolve() if args.build_root else target
    use_compiler_cache(cache_root / ".raybook-objcache", projects[0].parent)
    # The first student is graded alone, its build on every core: it compiles every chapter,
    # and the others take those objects from the cache. Then the rest go side by side, one a
    # core by default: after the first build a student's time is mostly tests, one process at
    # a time. (Half the cores, the default until 2026-11, graded a class of 30 of chapter 17
    # in about 19 minutes on 2 cores, most of it one test process beside an idle core.) Each
    # test keeps its own time limit. The results print in the students' order.
    global JOBS
    cores = os.cpu_count() or 2
    parallel = max(1, min(args.parallel or cores, len(projects)))

    # Each worker grades in a staging copy of its own (build root/.stage-W): the next student's
    # files are copied over it where their bytes differ, so make rebuilds only what that
    # student changed (normally the exercise files) and relinks. Reports are copied back to
    # the student's own build folder. The stage builds in its copy's build/ (stage/project/
    # build), the folder make check uses, so that ccache's keys match raybook's own build.
    root = Path(args.build_root).resolve() if args.build_root else target
    workers = queue.Queue()
    for w in range(parallel):
        workers.put(root / f".raybook-stage-{w}")

    # A class takes minutes: say so at the start, and a line as each student is graded, with
    # how many are left and a guess at the time (the first build compiles every chapter).
    print(f"grade: {len(projects)} student{'s' * (len(projects) != 1)}: {projects[0].name} "
          f"alone first (its build compiles every chapter), then {parallel} at a time (each "
          f"compiles only what the student changed)", file=sys.stderr, flush=True)
    began = time.monotonic()
    graded = []
    lock = threading.Lock()

    def one(project: Path) -> tuple[dict, list[str], float]:
        # The student's code runs only in its own build and tests; a separate build folder
        # keeps the student's folder as it was handed in.
        build = root / project.name if args.build_root else project / "build"
        start = time.monotonic()
        changed = changed_tests(project)
        stage = workers.get()
        try:
            sync_tree(project, stage / "project", skip={"build"})
            result = check_project(stage / "project", stage / "project" / "build")
            keep_report(result, stage, project, build)
        finally:
            workers.put(stage)
        seconds = time.monotonic() - start
        with lock:
            graded.append(seconds)
            left = len(projects) - len(graded)
            # The time left, from the median of the students graded after the first (its
            # build is the long one, so it says nothing of the others').
            later = sorted(graded[1:])
            print(f"grade: [{len(graded)}/{len(projects)}] {project.name} in {seconds:.0f} s"
                  + (f"; all in {time.monotonic() - began:.0f} s" if not left else
                     "; the others reuse its objects" if not later else
                     f"; about {max(1, round(left * later[len(later) // 2] / parallel / 60))} "
                     f"min left"),
                  file=sys.stderr, flush=True)
        return result, changed, seconds

    with concurrent.futures.ThreadPoolExecutor(parallel) as pool:
        JOBS = str(cores)
        results = [one(projects[0])]
        JOBS = str(max(1, cores // parallel))
        results += list(pool.map(one, projects[1:]))
    rows = []
    exercise_names: list[str] = []
    for project, (result, changed, seconds) in zip(projects, results):
        print(f"## {project.name} (chapter {result['chapter']}, {seconds:.0f} s)")
        print(table(result))
        print()
        if changed:
            print(f"note: files that grading relies on differ from a fresh export: "
                  f"{', '.join(changed[:10])}")
        row = {"student": project.name, "chapter": result["chapter"], "build": result["build"],
               "tests changed": " ".join(changed)}
        for e in result["exercises"]:
            key = f"ex{e['name']}"
            if key not in exercise_names:
                exercise_names.append(key)
            row[f"{key} passed"] = e["passed"] if result["build"] == "ok" else ""
            row[f"{key} tests"] = e["tests"] if result["build"] == "ok" else ""
        ok = result["build"] == "ok"
        # The chapter's tests that need none of its exercises ("other tests" in make check).
        others = result.get("others", {"tests": 0, "passed": 0})
        row["other passed"] = others["passed"] if ok else ""
        row["other tests"] = others["tests"] if ok else ""
        row["golden"] = result["golden"]["status"]
        row["golden rmse"] = result["golden"]["metric"]
        total = sum(e["tests"] for e in result["exercises"]) + others["tests"]
        passed = sum(e["passed"] for e in result["exercises"]) + others["passed"]
        # Credit per exercise: an exercise counts when every test of its row passes; each
        # row holds the tests that need it and no later exercise, so a solved exercise
        # counts while the later ones are still stubs.
        solved = sum(e["status"] == "pass" for e in result["exercises"])
        row["tests passed"] = f"{passed}/{total}" if ok else "0"
        row["score"] = f"{solved}/{len(result['exercises'])}" if ok else "0"
        rows.append(row)
    fields = ["student", "chapter", "build", "tests changed"]
    for key in exercise_names:
        fields += [f"{key} passed", f"{key} tests"]
    fields += ["other passed", "other tests", "golden", "golden rmse", "tests passed", "score"]
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for row in rows:
            w.writerow(row)
    print("| student | build | " + " | ".join(exercise_names) +
          " | other tests | golden | tests passed | score (exercises solved) |")
    print("|---|---|" + "---|" * len(exercise_names) + "---|---|---|---|")
    for row in rows:
        cells = [f"{row.get(k + ' passed', '')}/{row.get(k + ' tests', '')}"
                 if row["build"] == "ok" and f"{k} passed" in row else "-"
                 for k in exercise_names + ["other"]]
        golden = f"{row['golden']} {row['golden rmse']}".strip()
        print(f"| {row['student']} | {row['build']} | " + " | ".join(cells) +
              f" | {golden} | {row['tests passed']} | {row['score']} |")
    print(f"\ngrades written to {out}")
    return 0


# ---- Maintainer's tools ---------------------------------------------------------------------

def tags(args) -> int:
    """Which [exN.k] tags the chapter's tests should carry: the exercises each test needs.
    Two experiments, each a rebuild of the test program per step:
      single       each region alone stubbed: the tests that then fail need it;
      progressive  for k = 0..K-1, exercises 1..k written and the rest stubs: the tests that
                   pass.
    A test is tagged with every exercise it needs, and so counts in the row of the last of
    them (check's row_spec). A test that needs exercises 1..k only and still fails with 1..k
    written is reported: it needs something the single stubs do not show. With --apply the
    tags are written into the SCENARIO lines of tests/chNN_*.cpp."""
    build = Path(args.build).resolve()
    program = build / "tests" / "raybook_tests"
    regions = [r for r in rg.find_regions() if r.chapter == args.chapter]
    names = list_tests(program, f"[ch{args.chapter:02d}]")
    originals = {r.path: r.path.read_text() for r in regions}

    def passing(stubbed: list[rg.Region]) -> set[str]:
        for path, text in originals.items():
            path.write_text(text)
        for rel, text in stub_files(stubbed, ROOT).items():
            (ROOT / rel).write_text(text)
        code, out = run(["cmake", "--build", str(build), "-j", JOBS, "--target",
                         "raybook_tests"], BUILD_TIMEOUT)
        if code != 0:
            sys.exit(out[-3000:])
        return {t for t, res in zip(names, run_tests(program, names, ROOT)) if res["passed"]}

    try:
        single = [set(names) - passing([r]) for r in regions]
        progressive = [passing(regions[k:]) for k in range(len(regions))]
    finally:
        for path, text in originals.items():
            path.write_text(text)
        run(["cmake", "--build", str(build), "-j", JOBS, "--target", "raybook_tests"],
            BUILD_TIMEOUT)
    owned: dict[str, list[str]] = {t: [r.name for k, r in enumerate(regions) if t in single[k]]
                                   for t in names}
    for t in names:
        last = max((k for k, r in enumerate(regions) if t in single[k]), default=-1)
        late = last + 1 < len(regions) and t not in progressive[last + 1]
        print(("".join(f"[ex{e}]" for e in owned[t]) or "(none)") + "\t" + t +
              ("\t(FAILS with the exercises it needs written: split it or fix the order)"
               if late else ""))
    if args.apply:
        apply_tags(args.chapter, owned)
    return 0


STRING = re.compile(r'\s*"((?:[^"\\]|\\.)*)"')


def scenarios(text: str):
    """Each SCENARIO of a test file: (its name, the span of its tag string's contents)."""
    for m in re.finditer(r"\bSCENARIO\(", text):
        pos, parts = m.end(), []
        while (s := STRING.match(text, pos)):
            parts.append(s.group(1))
            pos = s.end()
        comma = re.compile(r"\s*,").match(text, pos)
        tag = STRING.match(text, comma.end()) if comma else None
        if parts and tag:
            name = re.sub(r"\\(.)", r"\1", "".join(parts))
            yield name, tag.span(1)


def apply_tags(chapter: int, owned: dict[str, list[str]]) -> None:
    """Add [exN.k] to the tag string of each SCENARIO (only tags change)."""
    found = set()
    for path in sorted((ROOT / "tests").glob("*.cpp")):
        text = path.read_text()
        edits = []
        for name, (begin, end) in scenarios(text):
            key = "Scenario: " + name
            if key not in owned:
                continue
            found.add(key)
            tags_now = re.sub(r"\[ex\d+\.\d+\]", "", text[begin:end])
            edits.append((begin, end, tags_now + "".join(f"[ex{e}]" for e in sorted(owned[key]))))
        changed = text
        for begin, end, tags_new in sorted(edits, reverse=True):
            changed = changed[:begin] + tags_new + changed[end:]
        if changed != text:
            path.write_text(changed)
            print(f"tagged {path.relative_to(ROOT)}")
    for key in owned:
        if owned[key] and key not in found:
            print(f"not found in the test files (tag it by hand): {key}")


# Formulas of the chapter pages and what the README must show for them (plain_math).
PLAIN_MATH_CASES = [
    (r"\sigma_s(s)\,T(a, s)", "σₛ(s) T(a, s)"),
    (r"P^{-1/3}", "P^(−1/3)"),
    (r"\max(0, \mathbf{n}\cdot\mathbf{h})^{p'}", "max(0, **n**·**h**)ᵖ′"),
    (r"(1 - r)\,L_{\text{Phong}}", "(1 − r) L_Phong"),
    (r"\frac{1}{2} \le \sqrt{x}", "1/2 ≤ √(x)"),
    (r"e^{-\sigma_c d}\,\prod_i (1 - \sigma_t(t_i)/\bar\mu_r)",
     "e^(−σ_c d) Πᵢ (1 − σₜ(tᵢ)/μ̄ᵣ)"),
]


def check_readmes(_args) -> int:
    """Every chapter's exported README (built as `export` builds it, nothing written) is plain
    Markdown: no Doxygen command (\f$, \ref, \snippet, ...) and no LaTeX left; and
    plain_math turns the sample formulas into the expected text."""
    problems = [f"plain_math({tex!r}) = {plain_math(tex)!r}, expected {want!r}"
                for tex, want in PLAIN_MATH_CASES if plain_math(tex) != want]
    chapters = sorted({r.chapter for r in rg.find_regions(ROOT)})
    for n in chapters:
        text = readme(ROOT, n, exercise_info(ROOT, n), [])
        for number, line in enumerate(text.split("\n"), start=1):
            left = re.findall(r"\\(?:f[$\[\]{}]|[a-zA-Z]+)", line)
            if left:
                problems.append(f"chapter {n}'s README, line {number}: {' '.join(left)} in: "
                                f"{line.strip()[:120]}")
    for p in problems:
        print(f"readmes: {p}")
    print(f"readmes: {len(chapters)} chapters' READMEs, {len(PLAIN_MATH_CASES)} formulas, "
          f"{len(problems)} problems")
    return 1 if problems else 0


def list_exercises(_args) -> int:
    """Every chapter's exercises and the tests tagged for each (read from the test files)."""
    tagged: dict[str, list[str]] = {}
    for path in sorted((ROOT / "tests").glob("*.cpp")):
        text = path.read_text()
        for name, (begin, end) in scenarios(text):
            for ex in re.findall(r"\[ex(\d+\.\d+)\]", text[begin:end]):
                tagged.setdefault(ex, []).append(f"{path.name}: {name}")
    for r in rg.find_regions():
        tests = tagged.get(r.name, [])
        print(f"{r.name} {r.title} ({r.path.relative_to(ROOT)}), {len(tests)} tests:")
        for t in tests:
            print(f"    {t}")
    return 0


def rows_line(result: dict) -> str:
    """One project state's rows, compactly: 13.1 5/5, 13.2 red, 13.3 - (tests passed of the
    row's tests; red: stopped at its first failing test; -: not run)."""
    if result["build"] != "ok":
        return f"build {result['build']}"
    def cell(e: dict) -> str:
        if e["status"] == "not run":
            return "-"
        if e["passed"] + len(e["failures"]) < e["tests"]:
            return "red"  # stopped at its first failing test
        return f"{e['passed']}/{e['tests']}"
    return ", ".join(f"{e['name']} {cell(e)}" for e in result["exercises"])


def step_problems(result: dict, written: int, what: str) -> list[str]:
    """The round trip's rule for a project with exercises 1..written written and the rest
    stubs: each exercise's row has tests; the rows of the written exercises pass, each row
    of a stubbed one fails."""
    if result["build"] != "ok":
        return [f"{what}: does not build:\n{result['build_log']}"]
    problems = []
    for k, e in enumerate(result["exercises"]):
        if e["status"] == "not run":
            continue
        if e["tests"] == 0:
            problems.append(f"{what}: exercise {e['name']}'s row has no test ({e['spec']}: "
                            f"tagged {e['tag']} and no later exercise)")
        elif k < written and e["status"] != "pass":
            t = e["failures"][0]
            problems.append(f"{what}: exercise {e['name']}'s row fails, though it and the "
                            f"exercises before it are written: {t['name']}: {t['why'][:300]}")
        elif k >= written and e["status"] == "pass":
            problems.append(f"{what}: exercise {e['name']}'s row passes with its stub")
    return problems


def untagged_problem(test: str, exercise: str, n: int) -> str:
    """The round trip's rule for an untagged test (in "other tests") that failed while
    exercise `exercise` and the later ones were stubs, and passes once it is written."""
    return (f"other test fails while exercise {exercise} is a stub: {test}: it needs "
            f"{exercise} but carries no exercise's tag; tag it [ex{exercise}] (and the tag of "
            f"each earlier exercise of chapter {n} it needs) in its SCENARIO line")


def bug_problems(result: dict, region: rg.Region, needing: set[str]) -> list[str]:
    """The round trip's rule for a solved project with one region replaced by its blank (a
    planted bug): that exercise's row fails; a test of another row fails only if it is tagged
    with the bugged exercise (it needs it)."""
    what = f"a bug in {region.name} (its blank)"
    if result["build"] != "ok":
        return [f"{what}: does not build:\n{result['build_log']}"]
    problems = []
    for e in result["exercises"]:
        if e["name"] == region.name:
            if e["status"] == "pass":
                problems.append(f"{what}: its own row passes")
            continue
        for t in e["failures"]:
            if t["name"] not in needing:
                problems.append(f"{what}: reddens {e['name']}'s row, whose test does not "
                                f"carry [ex{region.name}]: {t['name']}")
    return problems


def roundtrip_chapter(n: int, project: Path, build: Path, bugs: bool) -> tuple[list[str], str]:
    """The round trip of one chapter: export (every exercise stubbed), then write exercises
    1, 2, ... K one at a time, checking after each that the written exercises' rows pass and
    the stubbed ones' fail; solved, the untagged tests and the golden image pass too. With
    `bugs`, each exercise in turn is replaced by its blank in the solved project: only the
    rows that need it may fail."""
    subprocess.run([sys.executable, __file__, "export", str(n), str(project)], check=True,
                   stdout=subprocess.DEVNULL)
    regions = [r for r in rg.find_regions(ROOT) if r.chapter == n]
    problems, log = [], []
    spent = {"build": 0.0, "tests": 0.0, "golden": 0.0}

    def check_project(*args, **kwargs) -> dict:  # the module's, adding up where time goes
        result = globals()["check_project"](*args, **kwargs)
        for what, seconds in result.get("seconds", {}).items():
            spent[what] += seconds
        return result

    def spent_line() -> str:
        return "time: " + ", ".join(f"{what} {s:.0f} s" for what, s in spent.items())

    # With every exercise stubbed, the chapter's untagged tests ("other tests") must pass: a
    # test that needs an exercise carries its tag. Those that fail are run again after each
    # exercise is written; the one after which a test passes is the exercise it needs. The
    # others that pass here are not run again once solved: they pass without the chapter's
    # exercises, and make test's unit tests run them on raybook's own (solved) code.
    result = check_project(project, build, golden=False, fail_fast=True)
    problems += step_problems(result, 0, "stubbed")
    others = result.get("others", {"tests": 0, "passed": 0, "failures": []})
    untagged = {t["name"] for t in others["failures"]}
    log.append(f"stubbed {rows_line(result)}, other tests {others['passed']}/{others['tests']}")
    for k, r in enumerate(regions, start=1):
        solve_regions(project, {r.id})
        last = k == len(regions)
        # Exercise k's row must pass and the later ones fail (each stops at its first failing
        # test); the earlier rows passed at their own step, and are run again once solved.
        result = (check_project(project, build, others=untagged) if last else
                  check_project(project, build, golden=False, others=untagged,
                                rows=set(range(k - 1, len(regions))), fail_fast=True))
        problems += step_problems(result, k, f"{n}.1-{r.name} written")
        if result["build"] == "ok":  # a build failure is reported by step_problems
            still = {t["name"] for t in result.get("others", {}).get("failures", [])}
            problems += [untagged_problem(t, r.name, n) for t in sorted(untagged - still)]
            untagged = still
        if last and not passed_all(result):
            failed = result.get("others", {}).get("failures", [])
            problems.append("the solved export does not pass:\n" + table(result) + "".join(
                f"\nother test failed: {t['name']}: {t['why'][:300]}" for t in failed))
        log.append(f"1..{r.name} {rows_line(result)}" +
                   (f", golden {result['golden']['status']}" if last else ""))
    if not bugs:
        return problems, "; ".join(log + [spent_line()])
    program = build / "tests" / "raybook_check"
    exercises = exercise_info(project, n)
    for r in regions:
        if r.blank is None:
            log.append(f"bug {r.name}: no blank, not planted")
            continue
        mine = next(x for x in rg.find_regions(project) if x.id == r.id)
        write_if_changed(mine.path, rg.replaced(mine, r.blank).encode())
        # The rule (bug_problems) asks two things: the bugged exercise's row fails, so it
        # stops at its first failing test; and every other row's tests that do not carry the
        # exercise's tag pass. Those that carry it may pass or fail, so they are not run (in
        # chapter 17 they are most of the chapter's test time).
        needing = set(list_tests(program, f"[ex{r.name}]"))
        own = set(list_tests(program, row_spec(exercises, regions.index(r))))
        result = check_project(project, build, golden=False, others=False, fail_fast=True,
                               skip=needing - own)
        problems += bug_problems(result, r, needing)
        red = [e["name"] for e in result["exercises"] if e["status"] == "fail"]
        log.append(f"bug {r.name}: red {' '.join(red) or 'none'}")
        solve_regions(project, {r.id})
    return problems, "; ".join(log + [spent_line()])


SLOW_FIRST = (17, 1, 2, 18, 3, 16)  # roundtrip(): the chapters whose round trip is longest


def roundtrip(args) -> int:
    """Every chapter's round trip, `--workers` chapters at a time (default 2), each in a
    project folder of its own that builds in its build/ (WORK/slotK/project/build, as make
    check does), all sharing one compiler cache (use_compiler_cache): ccache, which also holds
    raybook's own build, so a file an export did not change is not compiled again; without
    ccache, objcache.py, and then chapter 1 runs alone first to fill it with the core every
    later chapter compiles. make grade's staging folders and mc_golden.py's chapters have the
    same layout, so they take each other's objects too. With `--stamps BUILD`, a chapter
    unchanged since its round trip passed (stamps.py) is skipped, and one that passes is
    stamped."""
    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    use_compiler_cache(work / "objcache", work)  # the slots share objects
    use_ninja()
    chapters = args.chapters or sorted({r.chapter for r in rg.find_regions()})
    if args.stamps:
        import stamps
        fresh = [n for n in chapters
                 if not stamps.stale(Path(args.stamps), f"roundtrip-ch{n:02d}", "chapter", n)]
        if fresh:
            print(f"round trip: chapters {' '.join(map(str, fresh))} unchanged since they "
                  f"passed (make test FULL=1 reruns them)", flush=True)
        chapters = [n for n in chapters if n not in fresh]
    slots = queue.Queue()
    for k in range(max(1, args.workers)):
        slots.put(work / f"slot{k}")

    def one(n: int) -> tuple[int, list[str]]:
        slot = slots.get()
        try:
            start = time.monotonic()
            problems, log = roundtrip_chapter(n, slot / "project", slot / "project" / "build",
                                              not args.no_bugs)
        finally:
            slots.put(slot)
        verdict = "ok" if not problems else "FAIL"
        print(f"chapter {n}: {verdict} ({time.monotonic() - start:.0f} s): {log}" +
              "".join("\n  " + p.replace("\n", "\n  ") for p in problems), flush=True)
        if not problems and args.stamps:
            stamps.record(Path(args.stamps), f"roundtrip-ch{n:02d}", "chapter", n)
        return n, problems

    failures = []
    total = time.monotonic()
    # objcache.py starts empty: chapter 1 runs alone first and fills it with the core every
    # later chapter compiles. ccache already holds the core, from raybook's own build.
    objcache = "objcache.py" in os.environ.get("RB_COMPILER_LAUNCHER", "")
    first, rest = (chapters[:1], chapters[1:]) if objcache else ([], chapters)
    # The longest round trips start first, so that no worker is left with one at the end while
    # the other idles: in CI's log of 2026-11-30, chapter 17 took 398 s (its statistical
    # tests), 1 and 2 over 100 s (the first builds), 18, 3 and 16 70-92 s, the others 20-30 s.
    rest.sort(key=lambda n: SLOW_FIRST.index(n) if n in SLOW_FIRST else len(SLOW_FIRST))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.workers)) as pool:
        results = [one(n) for n in first] + list(pool.map(one, rest))
    failures = [n for n, problems in results if problems]
    print(f"round trip: {len(chapters) - len(failures)} of {len(chapters)} chapters ok "
          f"in {time.monotonic() - total:.0f} s"
          + (f"; failed: {' '.join(map(str, failures))}" if failures else ""))
    return 1 if failures else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("export")
    p.add_argument("chapter", type=int)
    p.add_argument("dir")
    p.set_defaults(func=export)
    p = sub.add_parser("check")
    p.add_argument("project", nargs="?", default=".")
    p.add_argument("--build")
    p.add_argument("--json")
    p.set_defaults(func=check)
    p = sub.add_parser("grade")
    p.add_argument("dir")
    p.add_argument("--csv")
    p.add_argument("--build-root")
    p.add_argument("--parallel", type=int, default=0,
                   help="students graded side by side after the first, which is graded alone "
                        "(default: one a core)")
    p.set_defaults(func=grade)
    p = sub.add_parser("solve")
    p.add_argument("project")
    p.set_defaults(func=solve)
    sub.add_parser("list").set_defaults(func=list_exercises)
    sub.add_parser("readmes").set_defaults(func=check_readmes)
    p = sub.add_parser("roundtrip")
    p.add_argument("work")
    p.add_argument("--chapters", type=int, nargs="*")
    p.add_argument("--no-bugs", action="store_true",
                   help="skip the planted bugs (each exercise replaced by its blank)")
    p.add_argument("--workers", type=int, default=2,
                   help="chapters checked side by side (default 2)")
    p.add_argument("--stamps", metavar="BUILD",
                   help="skip chapters unchanged since they passed; stamp those that pass")
    p.set_defaults(func=roundtrip)
    p = sub.add_parser("tags")
    p.add_argument("build")
    p.add_argument("--chapter", type=int, required=True)
    p.add_argument("--apply", action="store_true")
    p.set_defaults(func=tags)
    args = parser.parse_args()
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
