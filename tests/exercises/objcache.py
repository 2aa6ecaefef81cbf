#!/usr/bin/env python3
"""A small compiler cache for the assignment round trip (assignment.py roundtrip), make grade
and mc_golden.py on a machine without ccache (with ccache they use it: use_compiler_cache in
assignment.py), used as CMAKE_CXX_COMPILER_LAUNCHER: `objcache.py c++ ARGS... -o OBJ -c SOURCE`.

The round trip exports chapter after chapter into the same folders and builds them there. Most
translation units do not change from one chapter to the next, but an export rewrites some files
with the same text, and some flags change from one project to the next.
This launcher keys each object on the compiler, the flags that are not -D definitions (their
effect is in the preprocessed text) and the preprocessed source, and copies a cached object
(with its dependency file) instead of compiling when the key is known. The cache folder is
$RB_OBJCACHE.
Anything it does not understand is compiled as it is, without the cache.

With $RB_OBJCACHE_STRIP=FOLDER, projects side by side in FOLDER (grade_test.sh's class, the
round trip's slots) share objects too: FOLDER/<project> is replaced by a placeholder in the key
and in the dependency file. Such an object keeps the first project's paths in its __FILE__
strings, which only assertion messages show. An object compiled with a -D definition that names
the project's folder is never shared: the path is in its code. Only tests/source_dir.cpp has
one (RB_SOURCE_DIR, the folder the tests read scenes from), so the test files are shared too.
"""

import hashlib
import re
import os
import shutil
import subprocess
import sys
from pathlib import Path


def main() -> int:
    command = sys.argv[1:]
    cache = os.environ.get("RB_OBJCACHE")
    args = command[1:]
    if not cache or "-c" not in args or "-o" not in args:
        return subprocess.call(command)
    out = args[args.index("-o") + 1]
    depfile = args[args.index("-MF") + 1] if "-MF" in args else None
    dep_target = args[args.index("-MT") + 1] if "-MT" in args else out
    # The preprocessor run: the same command without its outputs, printing to stdout.
    pre, skip = [command[0]], False
    for a in args:
        if skip:
            skip = False
            continue
        if a in ("-o", "-MF", "-MT"):
            skip = True
            continue
        if a == "-MD":
            continue
        pre.append(a)
    pre.append("-E")
    p = subprocess.run(pre, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    if p.returncode != 0:
        return subprocess.call(command)
    key_flags = [a for a in pre if not a.startswith("-D")]
    text = "\0".join(key_flags).encode() + b"\0" + p.stdout
    strip = os.environ.get("RB_OBJCACHE_STRIP")
    root = None
    if strip:
        pattern = re.escape(os.path.abspath(strip)) + r"/[^/\s]+"
        m = re.search(pattern, os.path.abspath(args[args.index("-c") + 1]))
        root = m.group(0) if m else None
        # A definition that names the project's folder (the tests' RB_SOURCE_DIR, where they
        # read scenes and meshes) is compiled into the object: such an object is the project's
        # own, and its key keeps the folder.
        if root and any(a.startswith("-D") and root in a for a in args):
            root = None
        if root:
            text = text.replace(root.encode(), b"@ROOT@")
    h = hashlib.sha256()
    h.update(text)
    key = h.hexdigest()
    folder = Path(cache)
    cached_obj, cached_dep = folder / f"{key}.o", folder / f"{key}.d"
    if cached_obj.is_file() and (depfile is None or cached_dep.is_file()):
        shutil.copyfile(cached_obj, out)
        if depfile:
            dep = cached_dep.read_text().replace("@TARGET@", dep_target, 1)
            Path(depfile).write_text(dep.replace("@ROOT@", root) if root else dep)
        return 0
    code = subprocess.call(command)
    if code == 0:
        folder.mkdir(parents=True, exist_ok=True)
        tmp = folder / f"{key}.{os.getpid()}"
        shutil.copyfile(out, tmp)
        if depfile and Path(depfile).is_file():
            dep = Path(depfile).read_text().replace(dep_target, "@TARGET@", 1)
            (folder / f"{key}.d").write_text(dep.replace(root, "@ROOT@") if root else dep)
        os.replace(tmp, cached_obj)
    return code


if __name__ == "__main__":
    sys.exit(main())
