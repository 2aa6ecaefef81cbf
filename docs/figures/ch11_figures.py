#!/usr/bin/env python3
"""Chapter 11's figures (SVG, written next to this script): the constructions of
chapters/11-bump.md, computed from the page's equations.

    python3 docs/figures/ch11_figures.py

ch11-bump.svg     a cross-section of a flat surface bumped by ripples h(x) = sin(kx) at strength
                  a: the displaced profile the bump pretends is there (dashed), the two heights
                  the central difference reads at x - eps and x + eps, the surface gradient
                  a dh/dx t, and the bumped normal n' = normalize(n - a dh/dx t), which is
                  perpendicular to the displaced profile.
ch11-facing.svg   a bump steep enough to tip the normal over: the raw n' faces away from the
                  viewer (n'.v < 0), and the rule of keepViewerSide turns it towards v, in the
                  plane of n' and v, until n'.v = kMinCosView = 0.01.
"""
import math

from svgfig import BLUE, DARK, GRID, ORANGE, RED, Figure, Frame2D, add, mul, normalize, sub

K = 2 * math.pi / 2.0  # wave number: wavelength 2 units
A = 0.2  # strength
X0 = 0.85  # the point the figure is about
EPS = 0.2  # a large step, so the two samples show
MIN_COS_VIEW = 0.01  # bump.h's kMinCosView


def height(x):
    return math.sin(K * x)


def bump_figure(name):
    fig = Figure(620, 330, "Bump mapping: the bumped normal of a rippled flat surface")
    F = Frame2D((60, 250), 120)
    # The real, flat surface, and the profile the bump pretends (displaced by a h).
    fig.line(F((-0.3, 0)), F((4.0, 0)), DARK, 2.5)
    xs = [-0.3 + k * 0.02 for k in range(216)]
    fig.polyline([F((x, A * height(x))) for x in xs], BLUE, 1.6, dash="6 4")
    fig.text(F((2.5, -0.42)), "displaced: ~y~ = ~a h~(~x~), ~h~ = sin ~kx~", "middle", 13, BLUE)
    fig.text(F((4.0, 0.08)), "real surface", "end", 13, DARK)
    # The central difference: heights at x - eps and x + eps.
    for s in (-1, 1):
        x = X0 + s * EPS
        fig.line(F((x, 0)), F((x, A * height(x))), GRID, 1.2, dash="3 3")
        fig.dot(F((x, A * height(x))), ORANGE, 4)
    fig.text(F((X0 - EPS - 0.05, -0.2)), "~x~ − ε", "end", 13)
    fig.text(F((X0 + EPS + 0.05, -0.2)), "~x~ + ε", "start", 13)
    slope = (height(X0 + EPS) - height(X0 - EPS)) / (2 * EPS)
    # n, the gradient term and n' = n - a grad h (drawn at one scale L, then normalised).
    L = 1.3
    p = F((X0, 0))
    g = A * slope  # a dh/dx along the tangent t = (1, 0)
    n_bumped = normalize((-g, 1.0))
    fig.arrow(p, F((X0, L)), DARK, 2)
    fig.text(F((X0 - 0.06, L + 0.02)), "*n*", "end")
    fig.arrow(F((X0, L)), F((X0 - L * g, L)), ORANGE, 2)
    fig.text(F((X0 - 0.5 * L * g, L + 0.1)), "−~a~ ∇~h~", "middle", 13, ORANGE)
    fig.arrow(p, F(add((X0, 0.0), mul(n_bumped, L))), RED, 2.5)
    fig.text(F(add((X0, 0.0), add(mul(n_bumped, L), (0.08, -0.1)))), "*n*′", "start", 14, RED)
    # The displaced profile's tangent at x: n' is perpendicular to it.
    t = normalize((1.0, A * K * math.cos(K * X0)))
    fig.line(F(sub((X0, 0), mul(t, 0.5))), F(add((X0, 0), mul(t, 0.5))), BLUE, 1.2)
    fig.text(F((X0 + 1.1, 1.3)),
             "~slope~ = (~h~(~x~+ε) − ~h~(~x~−ε)) / 2ε = %.3f" % slope, "start", 13)
    fig.text(F((X0 + 1.1, 1.1)), "exact ~h~′(~x~) = ~k~ cos ~kx~ = %.3f" % (K * math.cos(K * X0)),
             "start", 13)
    fig.text(F((X0 + 1.1, 0.9)),
             "*n*′ = normalize(*n* − ~a~ ∇~h~): %.1f° from *n*" % abs(math.degrees(
                 math.atan2(-n_bumped[0], n_bumped[1]))), "start", 13, RED)
    return fig.write(name)


def facing_figure(name):
    fig = Figure(520, 300, "A bump that would tip the normal away from the viewer")
    F = Frame2D((260, 230), 150)
    fig.line(F((-1.5, 0)), F((1.5, 0)), DARK, 2.5)
    fig.text(F((1.45, -0.15)), "surface", "end", 13)
    v = normalize((math.cos(math.radians(35)), math.sin(math.radians(35))))
    n = (0.0, 1.0)
    g = (1.6, 0.0)  # a steep gradient along +x (towards the viewer's side)
    raw = normalize(sub(n, g))  # leans to -x, away from the viewer
    cos_view = raw[0] * v[0] + raw[1] * v[1]
    across = normalize(sub(raw, mul(v, cos_view)))
    kept = add(mul(v, MIN_COS_VIEW), mul(across, math.sqrt(1 - MIN_COS_VIEW ** 2)))
    o = (0.0, 0.0)
    fig.arrow(F(o), F(mul(v, 1.2)), BLUE, 2)
    fig.text(F(add(mul(v, 1.25), (0.02, 0.0))), "*v* (to the viewer)", "start", 13, BLUE)
    fig.arrow(F(o), F(n), DARK, 1.5, dash="5 4")
    fig.text(F((0.05, 1.02)), "*n*", "start")
    fig.arrow(F(o), F(raw), GRID, 2, dash="5 4")
    fig.text(F(add(raw, (-0.05, 0.05))), "raw *n*′: *n*′·*v* = %.2f" % cos_view, "end", 13)
    fig.arrow(F(o), F(kept), RED, 2.5)
    fig.text(F(add(kept, (-0.05, -0.12))), "kept: *n*′·*v* = %.2f" % MIN_COS_VIEW, "end", 13, RED)
    # The plane perpendicular to v, where cos = 0.
    perp = (-v[1], v[0])
    fig.line(F(mul(perp, -1.3)), F(mul(perp, 1.3)), GRID, 1, dash="2 4")
    fig.text(F(mul(perp, 1.32)), "*n*′·*v* = 0", "middle", 12, GRID)
    return fig.write(name)


if __name__ == "__main__":
    for written in (bump_figure("ch11-bump.svg"), facing_figure("ch11-facing.svg")):
        print("wrote", written)
