#!/usr/bin/env python3
"""Chapter 15's figures (SVG, written next to this script): the constructions of
chapters/15-quadrics.md, computed with the page's own equations.

    python3 docs/figures/ch15_figures.py

ch15-caps.svg   two rays in the plane of the axis. Left, the capped cylinder: the side's span
                (the roots of the side quadratic), the slab between the caps, and their
                overlap, which enters through the cap. Right, the cone: a ray steeper than the
                side is inside the double cone on two rays of t, one of them in the upper
                nappe, which the slab cuts away; what is left enters through the side.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_ORANGE, GRID, INK, ORANGE, RED, Figure,
                    Frame2D, add, mul, normalize)

INF = float("inf")


def side_spans(o, d, a0, b):
    """Where the line o + t d (in the plane z = 0) has x^2 <= (a0 + b y)^2: the page's
    quadratic A t^2 + 2H t + C with w = a0 + b o_y and w_d = b d_y, read by the sign of A."""
    w, wd = a0 + b * o[1], b * d[1]
    A = d[0] * d[0] - wd * wd
    H = o[0] * d[0] - w * wd
    C = o[0] * o[0] - w * w
    disc = H * H - A * C
    if disc < 0:
        return [(-INF, INF)] if A < 0 else []
    q = -(H + math.copysign(math.sqrt(disc), H))
    t0, t1 = sorted((q / A, C / q))
    return [(t0, t1)] if A > 0 else [(-INF, t0), (t1, INF)]


def slab(o, d):
    s0, s1 = (-1 - o[1]) / d[1], (1 - o[1]) / d[1]
    return min(s0, s1), max(s0, s1)


def panel(fig, ox, title, o, d, a0, b, upper):
    F = Frame2D((ox + 215, 215), 78)
    xmin, xmax, ymin, ymax = -2.5, 2.5, -1.6, 2.2 if upper else 1.6
    # The slab between the caps, and the solid's outline in the plane of the axis.
    fig.rect(*F((xmin, 1)), *F((xmax, -1)), "none", FILL_ORANGE, 0, opacity=0.8)
    for y in (-1, 1):
        fig.line(F((xmin, y)), F((xmax, y)), ORANGE, 1.2, "5 3")
    fig.text(add(F((xmax, 1)), (0, -5)), "~y~ = 1", "end", 12, ORANGE)
    fig.text(add(F((xmax, -1)), (0, 15)), "~y~ = −1", "end", 12, ORANGE)
    ys = [ymin + (ymax - ymin) * k / 60 for k in range(61)]
    for sgn in (-1, 1):
        fig.polyline([F((sgn * abs(a0 + b * y), y)) for y in ys], BLUE, 1.2, dash="4 3")
    solid = [F((abs(a0 + b * y), y)) for y in (-1, 1)] + [F((-abs(a0 + b * y), y))
                                                         for y in (1, -1)]
    fig.polygon(solid, FILL_BLUE, DARK, 2.5)
    spans = side_spans(o, d, a0, b)
    s0, s1 = slab(o, d)
    # The ray, from t = 0 until it leaves the drawing.
    t_end = min(((ymin if d[1] < 0 else ymax) - o[1]) / d[1], 3.2)
    fig.line(F(o), F(add(o, mul(d, t_end))), DARK, 1.5)
    fig.arrow(F(o), F(add(o, mul(d, 0.35))), INK, 2.2)
    fig.dot(F(o), INK, 4)
    fig.text(add(F(o), (12, -4)), "*o*", "start")
    pieces = [(max(lo, s0), min(hi, s1)) for lo, hi in spans]
    pieces = [(a, c) for a, c in pieces if a <= c]
    for a, c in pieces:
        fig.line(F(add(o, mul(d, a))), F(add(o, mul(d, c))), RED, 4)
    ends = [t for lo, hi in spans for t in (lo, hi) if math.isfinite(t)]
    for t in ends:
        if t <= t_end:
            fig.dot(F(add(o, mul(d, t))), BLUE, 4.5)
    for t in (s0, s1):
        fig.dot(F(add(o, mul(d, t))), ORANGE, 4.5)

    # The t axis under the drawing: row 0 the side, row 1 the slab, row 2 both.
    x0, x1 = ox + 40, ox + 400
    tmin, tmax = 0.0, t_end

    def T(t, row):
        t = min(max(t, tmin), tmax)
        return (x0 + (x1 - x0) * (t - tmin) / (tmax - tmin), 400 + 24 * row)

    fig.line(T(tmin, 3), T(tmax, 3), DARK, 1)
    fig.text(add(T(tmax, 3), (4, 4)), "~t~", "start", 13)
    for lo, hi in spans:
        fig.line(T(lo, 0), T(hi, 0), BLUE, 5)
    fig.text(add(T(tmax, 0), (8, 5)), "side", "start", 12, BLUE)
    fig.line(T(s0, 1), T(s1, 1), ORANGE, 5)
    fig.text(add(T(tmax, 1), (8, 5)), "slab", "start", 12, ORANGE)
    for a, c in pieces:
        fig.line(T(a, 2), T(c, 2), RED, 5)
    fig.text(add(T(tmax, 2), (8, 5)), "solid", "start", 12, RED)
    for t in ends + [s0, s1]:
        if tmin <= t <= tmax:
            fig.line(T(t, 0), T(t, 3), GRID, 0.8, "2 3")
    fig.text((ox + 215, 24), title, weight="bold")
    (a, c), = pieces
    part = "the cap" if a == s0 else "the side"
    fig.text((ox + 215, 505), f"enters through {part} at ~t~ = {a:.2f}, leaves at {c:.2f}",
             size=13, fill=RED)


def caps_figure(name):
    fig = Figure(900, 520, "caps as a slab: the side's span and the slab's, and their overlap")
    d = normalize((0.55, -1.0))
    panel(fig, 0, "capped cylinder", (-1.3, 2.0), d, 1.0, 0.0, False)
    d = normalize((0.2, -1.0))
    panel(fig, 450, "cone: two nappes, the slab keeps one", (-0.3, 2.1), d, 0.5, -0.5, True)
    return fig.write(name)


if __name__ == "__main__":
    made = [caps_figure("ch15-caps.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
