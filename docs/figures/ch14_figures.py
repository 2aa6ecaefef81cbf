#!/usr/bin/env python3
"""Chapter 14's figures (SVG, written next to this script).

    python3 docs/figures/ch14_figures.py

ch14-intervals.svg  a ray through two overlapping discs A and B, and the intervals of A, B,
                    A u B, A n B and A - B along it, each computed by the chapter's merge
ch14-difference.svg a section of a hollow shell (disc minus a smaller disc) with a ray, its four
                    crossings and their normals: those of the subtracted disc turned round

Both figures compute everything from the page's equations: the crossings are the roots of
|o + t d - c|^2 = r^2, and the result's intervals come from the same walk as
src/csg/csg.cpp (combineCrossings), written again here in Python.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
COL_A = "#c0392b"
COL_B = "#1f4e9c"
COL_R = "#222"


def svg(width, height, body, title):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="14">\n'
            f'<title>{title}</title>\n<rect width="100%" height="100%" fill="white"/>\n'
            + "\n".join(body) + "\n</svg>\n")


def disc_crossings(o, d, c, r):
    """The roots t0 < t1 of |o + t d - c|^2 = r^2, or [] (the ray misses or touches)."""
    f = (o[0] - c[0], o[1] - c[1])
    a = d[0] ** 2 + d[1] ** 2
    h = f[0] * d[0] + f[1] * d[1]
    disc = h * h - a * (f[0] ** 2 + f[1] ** 2 - r * r)
    if disc <= 0:
        return []
    s = math.sqrt(disc)
    return [((-h - s) / a, True), ((-h + s) / a, False)]


def inside(op, a, b):
    return {"union": a or b, "intersection": a and b, "difference": a and not b}[op]


def combine(op, la, lb):
    """The chapter's merge: walk both lists from t = -inf, keep a crossing where op changes."""
    events = sorted([(t, e, "A") for t, e in la] + [(t, e, "B") for t, e in lb])
    in_a = in_b = state = False
    out = []
    for t, e, who in events:
        if who == "A":
            in_a = e
        else:
            in_b = e
        now = inside(op, in_a, in_b)
        if now != state:
            out.append((t, now, who))
            state = now
    return out


def spans(crossings):
    return [(crossings[i][0], crossings[i + 1][0]) for i in range(0, len(crossings) - 1, 2)]


def intervals_figure():
    o, d = (-3.2, 0.35), (1.0, 0.0)
    ca, ra = (-0.6, 0.0), 1.3
    cb, rb = (0.9, 0.2), 1.1
    la, lb = disc_crossings(o, d, ca, ra), disc_crossings(o, d, cb, rb)
    scale, x0, y0 = 70, 250, 120
    X = lambda x: x0 + scale * x  # noqa: E731
    Y = lambda y: y0 - scale * y  # noqa: E731
    body = [
        f'<circle cx="{X(ca[0]):.1f}" cy="{Y(ca[1]):.1f}" r="{scale * ra:.1f}" fill="{COL_A}" '
        'fill-opacity="0.15" stroke="#c0392b" stroke-width="2"/>',
        f'<circle cx="{X(cb[0]):.1f}" cy="{Y(cb[1]):.1f}" r="{scale * rb:.1f}" fill="{COL_B}" '
        'fill-opacity="0.15" stroke="#1f4e9c" stroke-width="2"/>',
        f'<text x="{X(ca[0] - 0.9):.1f}" y="{Y(ca[1] + 1.05):.1f}" fill="{COL_A}">A</text>',
        f'<text x="{X(cb[0] + 0.8):.1f}" y="{Y(cb[1] + 1.0):.1f}" fill="{COL_B}">B</text>',
        f'<line x1="{X(o[0]):.1f}" y1="{Y(o[1]):.1f}" x2="{X(2.6):.1f}" y2="{Y(o[1]):.1f}" '
        'stroke="#222" stroke-width="1.5" marker-end="url(#arrow)"/>',
        '<defs><marker id="arrow" markerWidth="10" markerHeight="8" refX="9" refY="4" '
        'orient="auto"><path d="M0,0 L10,4 L0,8 z" fill="#222"/></marker></defs>',
        f'<text x="{X(o[0]):.1f}" y="{Y(o[1]) - 8:.1f}">ray o + t d</text>',
    ]
    for t, e in la + lb:
        body.append(f'<circle cx="{X(o[0] + t):.1f}" cy="{Y(o[1]):.1f}" r="3.5" fill="#222"/>')
    rows = [("A", [(la[0][0], la[1][0])], COL_A), ("B", [(lb[0][0], lb[1][0])], COL_B)]
    for op, label in (("union", "A ∪ B"), ("intersection", "A ∩ B"), ("difference", "A − B")):
        rows.append((label, spans(combine(op, la, lb)), COL_R))
    top = 250
    for k, (label, segs, col) in enumerate(rows):
        y = top + 32 * k
        body.append(f'<text x="20" y="{y + 5}" fill="{col}">{label}</text>')
        body.append(f'<line x1="{X(o[0]):.1f}" y1="{y}" x2="{X(2.6):.1f}" y2="{y}" '
                    'stroke="#ccc" stroke-width="1"/>')
        for t0, t1 in segs:
            body.append(f'<line x1="{X(o[0] + t0):.1f}" y1="{y}" x2="{X(o[0] + t1):.1f}" '
                        f'y2="{y}" stroke="{col}" stroke-width="6"/>')
            for t in (t0, t1):
                body.append(f'<text x="{X(o[0] + t) - 12:.1f}" y="{y - 8}" font-size="11">'
                            f'{t:.2f}</text>')
    return svg(560, top + 32 * len(rows), body, "Intervals of A, B and their combinations")


def difference_figure():
    c, R, r = (0.0, 0.0), 1.6, 1.0
    o, d = (-3.0, 0.45), (1.0, 0.0)
    outer, inner = disc_crossings(o, d, c, R), disc_crossings(o, d, c, r)
    result = combine("difference", outer, inner)
    scale, x0, y0 = 80, 300, 170
    X = lambda x: x0 + scale * x  # noqa: E731
    Y = lambda y: y0 - scale * y  # noqa: E731
    body = [
        '<defs><marker id="arrow" markerWidth="10" markerHeight="8" refX="9" refY="4" '
        'orient="auto"><path d="M0,0 L10,4 L0,8 z" fill="context-stroke"/></marker>'
        '<marker id="arrowk" markerWidth="10" markerHeight="8" refX="9" refY="4" '
        'orient="auto"><path d="M0,0 L10,4 L0,8 z" fill="#222"/></marker></defs>',
        f'<circle cx="{X(0):.1f}" cy="{Y(0):.1f}" r="{scale * R:.1f}" fill="{COL_A}" '
        'fill-opacity="0.18" stroke="#c0392b" stroke-width="2"/>',
        f'<circle cx="{X(0):.1f}" cy="{Y(0):.1f}" r="{scale * r:.1f}" fill="white" '
        'stroke="#1f4e9c" stroke-width="2" stroke-dasharray="6 3"/>',
        f'<line x1="{X(o[0]):.1f}" y1="{Y(o[1]):.1f}" x2="{X(3.0):.1f}" y2="{Y(o[1]):.1f}" '
        'stroke="#222" stroke-width="1.5" marker-end="url(#arrowk)"/>',
        f'<text x="{X(-1.45):.1f}" y="{Y(1.5):.1f}" fill="{COL_A}">A (outer)</text>',
        f'<text x="{X(-0.45):.1f}" y="{Y(-0.3):.1f}" fill="{COL_B}">B (inner)</text>',
    ]
    for t, entering, who in result:
        p = (o[0] + t, o[1])
        centre_r = R if who == "A" else r
        n = ((p[0] - c[0]) / centre_r, (p[1] - c[1]) / centre_r)  # the operand's own normal
        colour = COL_A if who == "A" else COL_B
        if who == "B":
            # The subtracted surface: the result is entered where B is left, so turn it round.
            body.append(f'<line x1="{X(p[0]):.1f}" y1="{Y(p[1]):.1f}" '
                        f'x2="{X(p[0] + 0.55 * n[0]):.1f}" y2="{Y(p[1] + 0.55 * n[1]):.1f}" '
                        f'stroke="{colour}" stroke-width="1.5" stroke-dasharray="4 3" '
                        'marker-end="url(#arrow)"/>')
            n = (-n[0], -n[1])
        body.append(f'<line x1="{X(p[0]):.1f}" y1="{Y(p[1]):.1f}" '
                    f'x2="{X(p[0] + 0.55 * n[0]):.1f}" y2="{Y(p[1] + 0.55 * n[1]):.1f}" '
                    f'stroke="{colour}" stroke-width="2.5" marker-end="url(#arrow)"/>')
        body.append(f'<circle cx="{X(p[0]):.1f}" cy="{Y(p[1]):.1f}" r="4" fill="#222"/>')
        body.append(f'<text x="{X(p[0]) - 14:.1f}" y="{Y(p[1]) + 22:.1f}" font-size="12">'
                    f'{"in" if entering else "out"}</text>')
    body.append('<text x="20" y="330" font-size="12">solid: the operand\'s own normal; dashed: '
                'B\'s own normal before the turn</text>')
    return svg(600, 345, body, "A hollow shell A - B: crossings and normals")


def main():
    for name, text in (("ch14-intervals.svg", intervals_figure()),
                       ("ch14-difference.svg", difference_figure())):
        with open(os.path.join(HERE, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
