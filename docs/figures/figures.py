#!/usr/bin/env python3
"""Redraw every figure of the chapter pages (the SVG files next to this script).

    python3 docs/figures/figures.py

Each chapter's figures come from its own script, chNN_figures.py, which computes every point it
draws from the chapter page's equations (Python 3 standard library only; svgfig.py holds the
shared drawing helpers). The SVG files are kept in the repository, so the docs build does not
run Python: run this after changing a script, and commit the script with its SVG files. Nothing
is random at run time, so an unchanged script writes identical files.
"""
import glob
import os
import runpy
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

if __name__ == "__main__":
    sys.path.insert(0, HERE)
    for script in sorted(glob.glob(os.path.join(HERE, "ch[0-9][0-9]_figures.py"))):
        runpy.run_path(script, run_name="__main__")
