#!/usr/bin/env python3
"""Chapter 8's figures (SVG, written next to this script): where each pixel sampler puts its rays.

    python3 docs/figures/ch08_figures.py

ch08-uniform.svg    uniform 4 x 4: the centres of 16 sub-pixels
ch08-jittered.svg   jittered 4 x 4: one random point in each of 16 cells
ch08-adaptive.svg   adaptive, depth 3, on two neighbouring pixels crossed by an edge: the
                    squares split, the samples (corners shared between pixels and sub-squares)

The adaptive figure runs the same algorithm as src/adaptive_aa/supersampling.cpp (centre against
corners, split where they differ) on the same lattice, in Python, for a straight edge. Nothing is
random at run time: the jitter comes from a fixed linear congruential sequence, so the files only
change when this script does.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
S = 240  # pixel side in SVG units
PAD = 30
GRID = "#9aa4b2"
EDGE = "#d33"
INSIDE = "#1f4e9c"
OUTSIDE = "#ffffff"


def svg(width, height, body, title):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="14">\n'
            f'<title>{title}</title>\n<rect width="100%" height="100%" fill="white"/>\n'
            + "\n".join(body) + "\n</svg>\n")


def square(x, y, s, stroke=GRID, width=1, dash=None):
    d = f' stroke-dasharray="{dash}"' if dash else ""
    return (f'<rect x="{x:.2f}" y="{y:.2f}" width="{s:.2f}" height="{s:.2f}" fill="none" '
            f'stroke="{stroke}" stroke-width="{width}"{d}/>')


def dot(x, y, fill="#222", r=5, stroke="#222"):
    return f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{r}" fill="{fill}" stroke="{stroke}" stroke-width="1.5"/>'


def text(x, y, s, anchor="middle"):
    return f'<text x="{x:.1f}" y="{y:.1f}" text-anchor="{anchor}">{s}</text>'


def lcg(seed):
    """A fixed stream of numbers in [0, 1) (Numerical Recipes' LCG): the same figure every run."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def readable(seed, n, margin=0.18, spacing=0.5):
    """Whether the n x n jittered draw of `seed` reads as "one point per cell" in a small figure.

    Jitter puts a point anywhere in its cell, so an unlucky draw puts two points of neighbouring
    cells side by side on their common border, where they read as a clump in one cell (seed 8
    did). Choosing the seed is a drawing choice, not the sampler's: the points are still the
    stream's uniform draws. A readable draw has every point at least `margin` of a cell (a dot's
    radius and a gap) from its cell's borders and at least `spacing` of a cell from each other."""
    rnd, pts = lcg(seed), []
    for j in range(n):
        for i in range(n):
            u, v = next(rnd), next(rnd)
            pts.append((i + u, j + v, min(u, v, 1 - u, 1 - v)))
    return (all(m >= margin for *_, m in pts)
            and all((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 >= spacing ** 2
                    for k, a in enumerate(pts) for b in pts[k + 1:]))


# The first readable seed, found once by counting up from 1 (about a minute):
#     next(s for s in itertools.count(1) if readable(s, 4))
JITTER_SEED = 877937


def grid_figure(name, jitter):
    n = 4
    # Alternate cells tinted, so that each point is seen in its own cell.
    body = [f'<rect x="{PAD + i * S / n:.2f}" y="{PAD + j * S / n:.2f}" width="{S / n:.2f}" '
            f'height="{S / n:.2f}" fill="#eef1f6"/>'
            for j in range(n) for i in range(n) if (i + j) % 2]
    body.append(square(PAD, PAD, S, "#333", 2))
    for k in range(1, n):
        body.append(f'<line x1="{PAD + k * S / n}" y1="{PAD}" x2="{PAD + k * S / n}" y2="{PAD + S}" '
                    f'stroke="{GRID}" stroke-dasharray="4 3"/>')
        body.append(f'<line x1="{PAD}" y1="{PAD + k * S / n}" x2="{PAD + S}" y2="{PAD + k * S / n}" '
                    f'stroke="{GRID}" stroke-dasharray="4 3"/>')
    assert not jitter or readable(JITTER_SEED, n)
    rnd = lcg(JITTER_SEED)
    for j in range(n):
        for i in range(n):
            u, v = (next(rnd), next(rnd)) if jitter else (0.5, 0.5)
            body.append(dot(PAD + (i + u) * S / n, PAD + (j + v) * S / n))
    label = ("jittered 4 x 4: one random point per cell" if jitter
             else "uniform 4 x 4: the sub-pixel centres")
    body.append(text(PAD + S / 2, PAD + S + 24, label))
    with open(os.path.join(HERE, name), "w") as f:
        f.write(svg(S + 2 * PAD, S + 2 * PAD + 20, body, label))


def adaptive_figure(name):
    """Two pixels side by side, lattice L = 2^(D+1) points per pixel side, an edge a·x + b·y <= c."""
    depth, L = 3, 16
    a, b, c = 0.35, 1.0, 0.62  # inside (dark) below-left of the line, in pixel units
    inside = lambda i, j: a * i / L + b * j / L <= c + 0.0
    traced = {}

    def at(i, j):
        if (i, j) not in traced:
            traced[(i, j)] = inside(i, j)
        return traced[(i, j)]

    squares = []

    def split(i, j, size, d):
        h = size // 2
        corners = [at(i, j), at(i + size, j), at(i, j + size), at(i + size, j + size)]
        centre = at(i + h, j + h)
        squares.append((i, j, size))
        if d < depth and any(k != centre for k in corners):
            for (di, dj) in ((0, 0), (h, 0), (0, h), (h, h)):
                split(i + di, j + dj, h, d + 1)

    for x in range(2):
        split(x * L, 0, L, 0)
    k = S / L  # SVG units per lattice step
    W = 2 * S
    body = []
    for (i, j, size) in squares:
        edge = "#333" if size == L else GRID
        body.append(square(PAD + i * k, PAD + j * k, size * k, edge, 2 if size == L else 1))
    # The edge: a x + b y = c across both pixels (x from 0 to 2).
    x0, x1 = 0.0, 2.0
    y0, y1 = (c - a * x0) / b, (c - a * x1) / b
    body.append(f'<line x1="{PAD + x0 * S:.1f}" y1="{PAD + y0 * S:.1f}" x2="{PAD + x1 * S:.1f}" '
                f'y2="{PAD + y1 * S:.1f}" stroke="{EDGE}" stroke-width="2.5"/>')
    for (i, j), v in sorted(traced.items()):
        shared = i == L  # on the border of the two pixels: traced once, used by both
        r = 6 if (i % L == 0 and j % L == 0) else 4
        body.append(dot(PAD + i * k, PAD + j * k, INSIDE if v else OUTSIDE, r,
                        "#e08a00" if shared else "#222"))
    body.append(text(PAD + S / 2, PAD + S + 24, "pixel (0, 0)"))
    body.append(text(PAD + 1.5 * S, PAD + S + 24, "pixel (1, 0)"))
    body.append(text(PAD + S, PAD + S + 46,
                     f"depth {depth}: {len(traced)} samples for 2 pixels; "
                     f"orange rings: shared border, traced once"))
    with open(os.path.join(HERE, name), "w") as f:
        f.write(svg(W + 2 * PAD, S + 2 * PAD + 44, body, "adaptive supersampling with shared corners"))


grid_figure("ch08-uniform.svg", jitter=False)
grid_figure("ch08-jittered.svg", jitter=True)
adaptive_figure("ch08-adaptive.svg")
print("wrote", ", ".join(f"docs/figures/ch08-{n}.svg" for n in ("uniform", "jittered", "adaptive")))
