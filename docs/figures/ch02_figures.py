#!/usr/bin/env python3
"""Chapter 2's figures (SVG, written next to this script): the constructions of
chapters/02-phong.md, computed with the page's own equations.

    python3 docs/figures/ch02_figures.py

ch02-phong.svg     the vectors of the Phong sum at a surface point: n, l towards the light, its
                   mirror direction r = 2(n.l)n - l, v towards the eye, the angles theta_i and
                   alpha, and the specular lobe max(0, r.v)^p around r as a polar curve.
ch02-normals.svg   a circle squashed by M = diag(2, 0.6): a tangent t goes to M t, still tangent
                   to the ellipse; the normal n taken to M n leans the wrong way, while
                   M^-T n is perpendicular to M t.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_ORANGE, GRID, INK, ORANGE, RED,
                    Figure, Frame2D, add, dot, mul, normalize, sub)


def phong_figure(name):
    n = (0.0, 1.0)
    theta_i = math.radians(38)
    l = (-math.sin(theta_i), math.cos(theta_i))  # towards the light
    r = sub(mul(n, 2 * dot(n, l)), l)  # the page's r = 2(n.l)n - l
    v = (math.sin(math.radians(58)), math.cos(math.radians(58)))  # towards the eye
    alpha = math.acos(dot(r, v))
    shininess = 20

    fig = Figure(640, 330, "the vectors of the Phong sum")
    F = Frame2D((300, 235), 190)
    o = (0.0, 0.0)
    fig.line(F((-1.45, 0)), F((1.45, 0)), DARK, 2.5)
    x = -1.45
    while x <= 1.45:
        fig.line(F((x, 0)), F((x - 0.06, -0.06)), GRID, 1)
        x += 0.09
    # The specular lobe around r: radius (r.w)^p for directions w above the surface.
    pts = []
    ang_r = math.atan2(r[1], r[0])
    for k in range(361):
        a = ang_r - math.pi / 2 + math.pi * k / 360
        w = (math.cos(a), math.sin(a))
        s = max(0.0, dot(r, w)) ** shininess
        if w[1] >= 0:
            pts.append(mul(w, 0.9 * s))
    fig.polygon([F(q) for q in pts] + [F(o)], FILL_ORANGE, ORANGE, 1.5)
    fig.arrow(F(o), F(n), DARK, 2)
    fig.text(add(F(n), (0, -8)), "*n*")
    fig.arrow(F(o), F(l), INK, 2.5)
    fig.text(add(F(mul(l, 0.55)), (-10, 0)), "*l*", "end")
    fig.dot(F(mul(l, 1.12)), "#ffd23f", 9, DARK)
    fig.text(add(F(mul(l, 1.12)), (-14, 4)), "light", "end", 12)
    fig.arrow(F(o), F(r), ORANGE, 2.5)
    fig.text(add(F(r), (10, 4)), "*r* = 2(*n*·*l*)*n* − *l*", "start", 13, ORANGE)
    fig.arrow(F(o), F(v), BLUE, 2.5)
    fig.text(add(F(v), (8, 10)), "*v* (to the eye)", "start", 14, BLUE)

    def arc(a0, a1, radius, colour, label, label_radius):
        fig.arc(F(o), radius * F.scale, a0, a1, colour, 1.5)
        mid = (a0 + a1) / 2
        fig.text(add(F((label_radius * math.cos(mid), label_radius * math.sin(mid))), (0, 5)),
                 label, fill=colour, size=13)

    a_n, a_l, a_r, a_v = (math.atan2(q[1], q[0]) for q in (n, l, r, v))
    arc(a_n, a_l, 0.32, INK, "~θ~_i", 0.42)
    arc(a_r, a_n, 0.36, ORANGE, "~θ~_i", 0.46)
    arc(a_v, a_r, 0.62, BLUE, "~α~", 0.72)
    fig.text((320, 280), f"~θ~_i = {math.degrees(theta_i):.0f}°: *n*·*l* = cos ~θ~_i = "
             f"{dot(n, l):.3f};   ~α~ = {math.degrees(alpha):.0f}°: *r*·*v* = cos ~α~ = "
             f"{dot(r, v):.3f}", size=13)
    fig.text((320, 302), f"orange: the highlight's lobe max(0, *r*·*ω*)^p around *r*, ~p~ = "
             f"{shininess}; the eye gets (*r*·*v*)^p = {dot(r, v) ** shininess:.3f}", size=12,
             fill="#555")
    return fig.write(name)


def normals_figure(name):
    M = ((2.0, 0.0), (0.0, 0.6))
    M_inv_T = ((1 / 2.0, 0.0), (0.0, 1 / 0.6))  # diagonal: the inverse transpose is 1/diag

    def apply(A, q):
        return (A[0][0] * q[0] + A[0][1] * q[1], A[1][0] * q[0] + A[1][1] * q[1])

    phi = math.radians(50)
    p = (math.cos(phi), math.sin(phi))
    n = p  # the unit circle's normal is its point
    t = (-math.sin(phi), math.cos(phi))
    fig = Figure(920, 340, "normals under non-uniform scale: the inverse transpose")
    # Left: the circle.
    F = Frame2D((140, 175), 120)
    fig.circle(F((0, 0)), F.scale, DARK, FILL_BLUE, 1.8)
    fig.dot(F(p), INK, 4)
    fig.arrow(F(p), F(add(p, mul(n, 0.6))), RED, 2.5)
    fig.text(add(F(add(p, mul(n, 0.6))), (6, -4)), "*n*", "start", fill=RED)
    fig.line(F(sub(p, mul(t, 0.5))), F(add(p, mul(t, 0.7))), BLUE, 2)
    fig.arrow(F(p), F(add(p, mul(t, 0.7))), BLUE, 2)
    fig.text(add(F(add(p, mul(t, 0.7))), (-6, -4)), "*t*", "end", fill=BLUE)
    fig.text((140, 330), "object space: *n*·*t* = 0", size=13)
    fig.arrow((280, 175), (345, 175), DARK, 2)
    fig.text((312, 200), "~M~ = diag(2, 0.6)", size=12)
    # Right: the ellipse.
    G = Frame2D((615, 185), 120)
    pts = [apply(M, (math.cos(2 * math.pi * k / 120), math.sin(2 * math.pi * k / 120)))
           for k in range(121)]
    fig.polygon([G(q) for q in pts], FILL_BLUE, DARK, 1.8)
    q = apply(M, p)
    mt = normalize(apply(M, t))
    mn = normalize(apply(M, n))
    good = normalize(apply(M_inv_T, n))
    assert abs(dot(good, mt)) < 1e-12
    fig.dot(G(q), INK, 4)
    fig.line(G(sub(q, mul(mt, 0.6))), G(add(q, mul(mt, 0.8))), BLUE, 2)
    fig.arrow(G(q), G(add(q, mul(mt, 0.8))), BLUE, 2)
    fig.text(add(G(add(q, mul(mt, 0.8))), (-6, -6)), "~M~*t*", "end", fill=BLUE)
    fig.arrow(G(q), G(add(q, mul(mn, 0.75))), GRID, 2.5, "5 3")
    fig.text(add(G(add(q, mul(mn, 0.75))), (8, 4)), "~M~*n*", "start", 13, "#667")
    fig.arrow(G(q), G(add(q, mul(good, 0.75))), RED, 2.5)
    fig.text(add(G(add(q, mul(good, 0.75))), (-4, -8)), "~M~^{−T}*n*", "end", 14, RED)
    lean = math.degrees(math.acos(dot(mn, good)))
    fig.text((615, 330), f"world space: (~M~^{{−T}}*n*)·(~M~*t*) = 0, while ~M~*n* leans "
             f"{lean:.1f}° off the normal", size=13)
    return fig.write(name)


if __name__ == "__main__":
    made = [phong_figure("ch02-phong.svg"), normals_figure("ch02-normals.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
