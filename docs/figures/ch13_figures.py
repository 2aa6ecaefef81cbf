#!/usr/bin/env python3
"""Chapter 13's figures (SVG, written next to this script): the thin lens and its samples.

    python3 docs/figures/ch13_figures.py

ch13-thin-lens.svg     a side view: the eye's lens of aperture A, the image plane at distance 1,
                       the focal plane at distance f; rays from five lens points through one image
                       position meet on the focal plane and spread at a nearer and a farther depth
                       over the blur circle A * |1 - z / f| (in the world; A * |1/f - 1/z| on the
                       image plane)
ch13-concentric.svg    the concentric map: an 8 x 8 grid of the unit square and the cells it maps
                       to on the disk (squares about the centre become rings)
ch13-strata.svg        a pixel's 16 rays: 4 x 4 jittered pixel positions (left) and the lens
                       strata they are paired with by a shuffle (right), numbered alike

The rays are computed with the page's equations (origin = eye + lens point, direction =
f * d - lens point); the concentric map is src/dof/lens_sampling.cpp's, in Python. Nothing is
random at run time: jitter and shuffle come from a fixed linear congruential sequence.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
GRID = "#9aa4b2"
RAY = "#1f4e9c"
FOCUS = "#d33"


def svg(width, height, body, title):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="14">\n'
            f'<title>{title}</title>\n<rect width="100%" height="100%" fill="white"/>\n'
            + "\n".join(body) + "\n</svg>\n")


def line(x1, y1, x2, y2, stroke="#333", width=1.5, dash=None):
    d = f' stroke-dasharray="{dash}"' if dash else ""
    return (f'<line x1="{x1:.2f}" y1="{y1:.2f}" x2="{x2:.2f}" y2="{y2:.2f}" stroke="{stroke}" '
            f'stroke-width="{width}"{d}/>')


def dot(x, y, fill="#222", r=4):
    return f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{r}" fill="{fill}"/>'


def text(x, y, s, anchor="middle", size=14, fill="#222"):
    return (f'<text x="{x:.1f}" y="{y:.1f}" text-anchor="{anchor}" font-size="{size}" '
            f'fill="{fill}">{s}</text>')


def lcg(seed):
    """A fixed stream of numbers in [0, 1) (Numerical Recipes' LCG): the same figure every run."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def concentric(u, v):
    """Shirley and Chiu's concentric map, as src/dof/lens_sampling.cpp computes it."""
    a, b = 2 * u - 1, 2 * v - 1
    if a == 0 and b == 0:
        return 0.0, 0.0
    if abs(a) > abs(b):
        r, phi = a, math.pi / 4 * (b / a)
    else:
        r, phi = b, math.pi / 2 - math.pi / 4 * (a / b)
    return r * math.cos(phi), r * math.sin(phi)


def thin_lens():
    # Side view: depth z to the right (scene units), height y up. Scale: px per unit.
    sx, sy, x0, y0 = 70.0, 70.0, 60.0, 190.0
    A, f, d = 1.6, 6.0, 0.18  # aperture, focus distance, image-plane height of the position
    near, far = 3.0, 9.0

    def P(z, y):
        return x0 + sx * z, y0 - sy * y

    body = []
    # The axis, the lens, the planes.
    body.append(line(*P(-0.3, 0), *P(9.6, 0), GRID, 1, "4 4"))
    body.append(line(*P(0, -A / 2), *P(0, A / 2), "#222", 4))
    body.append(text(*P(0, -A / 2 - 0.35), "lens, aperture A"))
    for z, label in ((1.0, "image plane (z = 1)"), (f, "focal plane (z = f)")):
        body.append(line(*P(z, -1.9), *P(z, 1.9), "#888", 1.2))
        body.append(text(*P(z, 2.05), label))
    for z, label in ((near, "z = 3"), (far, "z = 9")):
        body.append(line(*P(z, -1.3), *P(z, 1.3), GRID, 1, "3 3"))
        body.append(text(*P(z, -1.55), label, size=12))
    # Rays from five lens points through image position d: origin (0, l), direction
    # f * (1, d) - (0, l), drawn from z = 0 to z = far.
    focus = (f, f * d)
    for k in range(5):
        lens_y = A / 2 * (-1 + k / 2)
        dz, dy = f, f * d - lens_y
        t = far / dz
        body.append(line(*P(0, lens_y), *P(far, lens_y + t * dy), RAY, 1.4))
        body.append(dot(*P(0, lens_y), RAY, 3))
    body.append(dot(*P(*focus), FOCUS, 5))
    # Left of the focus, above the converging rays (right of it, the rays fan out through the text).
    body.append(text(*P(f - 0.15, f * d + 0.3), "all meet here", "end", 13, FOCUS))
    # The blur circle at the near and far depths: A * |1 - z / f| in the world.
    for z in (near, far):
        c = A * abs(1 - z / f)
        centre = z * d
        x = P(z, 0)[0] + 10
        body.append(line(x, P(z, centre - c / 2)[1], x, P(z, centre + c / 2)[1], FOCUS, 3))
        # The label goes where no ray or axis passes: just under the axis for the near bar (the
        # rays fill the space above and beside it, and its foot is just above the axis), below
        # the far bar (the rays fill the space above it).
        ly = P(z, 0)[1] + 20 if z < f else P(z, centre - c / 2)[1] + 16
        body.append(text(x + 8, ly, f"blur {c:.2f} = A|1 - z/f|", "start", 12, FOCUS)
                    .replace("<text ", '<text paint-order="stroke" stroke="white" stroke-width="4" ', 1))
    body.append(dot(*P(1.0, d), "#222", 3))
    body.append(text(*P(1.05, d + 0.25), "d", "start", 13))
    return svg(880, 360, body, "The thin lens: rays through one image position meet on the "
               "focal plane and spread elsewhere")


def concentric_figure():
    n, s, pad = 8, 240, 30
    body = []
    # The unit square and its grid, shaded by ring (max(|a|, |b|)).
    colours = ["#dbe7f6", "#b7cde9", "#93b3dc", "#6f99cf"]
    for j in range(n):
        for i in range(n):
            a, b = abs(2 * (i + 0.5) / n - 1), abs(2 * (j + 0.5) / n - 1)
            ring = min(3, int(max(a, b) * 4))
            body.append(f'<rect x="{pad + i * s / n:.1f}" y="{pad + j * s / n:.1f}" '
                        f'width="{s / n:.1f}" height="{s / n:.1f}" fill="{colours[ring]}" '
                        f'stroke="{GRID}"/>')
    body.append(text(pad + s / 2, pad + s + 22, "unit square, 8 x 8 cells"))
    # The mapped cells: each cell's boundary, sampled finely, mapped onto the disk.
    cx, cy, r = pad + s + 90 + s / 2, pad + s / 2, s / 2
    for j in range(n):
        for i in range(n):
            pts = []
            for e in range(4):
                for t in range(17):
                    q = t / 16
                    u, v = [(q, 0), (1, q), (1 - q, 1), (0, 1 - q)][e]
                    x, y = concentric((i + u) / n, (j + v) / n)
                    pts.append(f"{cx + r * x:.1f},{cy - r * y:.1f}")
            a, b = abs(2 * (i + 0.5) / n - 1), abs(2 * (j + 0.5) / n - 1)
            ring = min(3, int(max(a, b) * 4))
            body.append(f'<polygon points="{" ".join(pts)}" fill="{colours[ring]}" '
                        f'stroke="{GRID}"/>')
    body.append(text(cx, pad + s + 22, "the disk: each ring of squares is a ring"))
    body.append(text(pad + s + 45, cy + 5, "&#8594;", size=28))
    return svg(2 * s + 150, s + 60, body, "The concentric map of the square onto the disk")


def strata_figure():
    n, s, pad = 4, 200, 30
    rnd = lcg(13)
    # A shuffle of 0..15 (Fisher-Yates with the fixed stream).
    order = list(range(n * n))
    for k in range(n * n - 1, 0, -1):
        m = int(next(rnd) * (k + 1))
        order[k], order[m] = order[m], order[k]
    body = []
    for ox, title in ((pad, "pixel: jittered 4 x 4"), (pad + s + 60, "lens: 4 x 4 strata")):
        body.append(f'<rect x="{ox}" y="{pad}" width="{s}" height="{s}" fill="none" '
                    f'stroke="#333" stroke-width="2"/>')
        for k in range(1, n):
            body.append(line(ox + k * s / n, pad, ox + k * s / n, pad + s, GRID, 1))
            body.append(line(ox, pad + k * s / n, ox + s, pad + k * s / n, GRID, 1))
        body.append(text(ox + s / 2, pad + s + 22, title))
    for ray in range(n * n):
        # The pixel cell of ray k is k itself; its lens cell is the shuffle's.
        for ox, cell in ((pad, ray), (pad + s + 60, order[ray])):
            i, j = cell % n, cell // n
            # Jittered, but kept off the cell borders so that the numbers stay legible.
            x = ox + (i + 0.2 + 0.6 * next(rnd)) * s / n
            y = pad + (j + 0.2 + 0.6 * next(rnd)) * s / n
            body.append(dot(x, y, RAY, 9))
            body.append(text(x, y + 4, str(ray), size=11, fill="white"))
    return svg(2 * s + 120, s + 60, body, "A pixel's 16 rays: pixel cell k, lens cell pi(k)")


if __name__ == "__main__":
    for name, content in (("ch13-thin-lens.svg", thin_lens()),
                          ("ch13-concentric.svg", concentric_figure()),
                          ("ch13-strata.svg", strata_figure())):
        with open(os.path.join(HERE, name), "w") as out:
            out.write(content)
        print("wrote", name)
