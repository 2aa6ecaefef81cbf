#!/usr/bin/env python3
"""Chapter 4's figures (SVG, written next to this script): the law of reflection of
chapters/04-reflection.md, with r computed from r = d - 2(d.n)n.

    python3 docs/figures/ch04_figures.py

ch04-reflection.svg   the incoming unit direction d at 40 degrees from the normal n, its parts
                      d_perp = (d.n)n and d_par = d - d_perp, and the mirror direction r: d
                      drawn again from the hit point (through the surface), then -2(d.n)n
                      from its tip up to the tip of r; the equal angles theta_i and theta_r.
ch04-mirrors.svg      two parallel mirrors and a camera ray reflected k = 4 times by the same
                      formula before it reaches a wall: each bounce multiplies by r.
"""
import math

from svgfig import (BLUE, DARK, GRID, INK, ORANGE, RED, Figure, Frame2D, add, dot, mul,
                    normalize, sub)

THETA_I = math.radians(40)


def hatch_surface(fig, F, x0, x1, y=0.0):
    """The mirror: a line with short hatches below it."""
    fig.line(F((x0, y)), F((x1, y)), DARK, 2.5)
    steps = int((x1 - x0) / 0.12)
    for k in range(steps + 1):
        x = x0 + k * 0.12
        fig.line(F((x, y)), F((x - 0.08, y - 0.08)), GRID, 1)


def angle_of(v):
    return math.atan2(v[1], v[0])


def reflection_figure(name):
    n = (0.0, 1.0)
    d = (math.sin(THETA_I), -math.cos(THETA_I))  # unit, arriving: d.n < 0
    d_dot_n = dot(d, n)
    d_perp = mul(n, d_dot_n)
    d_par = sub(d, d_perp)
    r = sub(d, mul(n, 2 * d_dot_n))  # the page's formula
    theta_r = math.acos(dot(r, n))
    assert abs(theta_r - THETA_I) < 1e-12 and abs(math.hypot(*r) - 1) < 1e-12

    fig = Figure(720, 430, "the law of reflection: r = d - 2(d.n)n")
    F = Frame2D((330, 215), 150)
    o = (0.0, 0.0)
    hatch_surface(fig, F, -1.9, 1.9)
    # The incoming ray arrives at the hit point along d.
    start = mul(d, -1.35)
    fig.line(F(start), F(mul(d, -0.55)), DARK, 1.5)
    fig.arrow(F(mul(d, -0.55)), F(o), INK, 2.5)
    fig.text(add(F(mul(d, -0.75)), (-12, 0)), "*d*", "end")
    # The normal.
    fig.arrow(F(o), F(n), DARK, 2)
    fig.text(add(F(n), (0, -8)), "*n*")
    # d drawn again from the hit point: it would go on through the surface.
    fig.arrow(F(o), F(d), GRID, 2, "6 4")
    fig.text(add(F(d), (12, 4)), "*d*", "start", fill="#667")
    # Its parts: d_par along the surface, d_perp = (d.n)n along the normal.
    fig.arrow(F(o), F(d_par), BLUE, 2.5)
    fig.text(add(F(d_par), (16, 20)), "*d*_∥ = *d* − (*d*·*n*)*n*", "start", 13, BLUE)
    fig.arrow(F(d_par), F(add(d_par, d_perp)), ORANGE, 2.5)
    fig.text(add(F(add(d_par, mul(d_perp, 0.5))), (16, 4)), "*d*_⊥ = (*d*·*n*)*n*", "start", 13,
             ORANGE)
    # -2(d.n)n from the tip of d to the tip of r; r from the hit point.
    fig.arrow(F(add(d, (0.06, 0))), F(add(r, (0.06, 0))), RED, 1.8, "5 3")
    fig.text(add(F((d[0] + 0.06, 0.4)), (8, 4)), "−2(*d*·*n*)*n*", "start", 13, RED)
    fig.arrow(F(o), F(r), RED, 3)
    fig.text(add(F(r), (10, 0)), "*r*", "start", 16, RED)
    fig.line(F(r), F(d_par), GRID, 1, "2 3")
    # The angles: theta_i between -d and n, theta_r between n and r.
    fig.arc(F(o), 0.42 * F.scale, math.pi / 2, angle_of(mul(d, -1)), INK, 1.5)
    fig.arc(F(o), 0.48 * F.scale, angle_of(r), math.pi / 2, RED, 1.5)
    mid_i = (math.pi / 2 + angle_of(mul(d, -1))) / 2
    mid_r = (math.pi / 2 + angle_of(r)) / 2
    fig.text(add(F((0.56 * math.cos(mid_i), 0.56 * math.sin(mid_i))), (0, 5)), "~θ~_i")
    fig.text(add(F((0.6 * math.cos(mid_r), 0.6 * math.sin(mid_r))), (0, 5)), "~θ~_r", fill=RED)
    fig.text((360, 400), f"~θ~_i = ~θ~_r = {math.degrees(THETA_I):.0f}°,  "
             f"*d*·*n* = −cos ~θ~_i = {d_dot_n:.3f}".replace("-", "−")
             + ",  |*r*| = |*d*| = 1", size=13)
    fig.text((360, 420), "*r* = *d*_∥ − *d*_⊥ = *d* − 2(*d*·*n*)*n*", size=13, fill=RED)
    return fig.write(name)


def mirrors_figure(name):
    """Two parallel mirrors (y = 0 and y = 1), a camera ray that zig-zags k = 4 times between
    them by r = d - 2(d.n)n, then reaches a wall: the radiance it carries back is r^k L_w."""
    r_mirror, k_bounces = 0.8, 4
    fig = Figure(850, 300, "two parallel mirrors: r^k after k bounces")
    F = Frame2D((60, 230), 170)
    x_wall = 4.1
    for y in (0.0, 1.0):
        fig.line(F((0, y)), F((x_wall, y)), DARK, 2.5)
        x = 0.0
        while x <= x_wall:
            dy = -0.05 if y == 0 else 0.05
            fig.line(F((x, y)), F((x - 0.05, y + dy)), GRID, 1)
            x += 0.08
    fig.rect(*F((x_wall, 1.0)), *F((x_wall + 0.12, 0.0)), DARK, "#f3c4c4", 1.5)
    fig.text(add(F((x_wall + 0.06, 0.5)), (12, 4)), "wall ~L~_w", "start", 13)
    # The path: from the eye, the direction chosen so that the ray meets the wall after k
    # bounces; each bounce uses the page's reflection formula.
    o = (0.0, 0.5)
    slope = k_bounces / x_wall  # k mirror gaps in all: the wall is met half-way up
    d = normalize((1.0, slope))
    path = [o]
    p = o
    bounces = 0
    while True:
        t_wall = (x_wall - p[0]) / d[0]
        t_hit = ((1.0 if d[1] > 0 else 0.0) - p[1]) / d[1]
        if t_wall <= t_hit:
            path.append(add(p, mul(d, t_wall)))
            break
        p = add(p, mul(d, t_hit))
        n = (0.0, -1.0) if d[1] > 0 else (0.0, 1.0)  # facing the ray
        d = sub(d, mul(n, 2 * dot(d, n)))
        path.append(p)
        bounces += 1
    assert bounces == k_bounces
    for j in range(len(path) - 1):
        # Segment j carries L_j, what is seen after j reflections: L_j = r L_(j+1).
        fig.line(F(path[j]), F(path[j + 1]), RED, 2.5)
        mid = mul(add(path[j], path[j + 1]), 0.5)
        label = f"~L~_{j}" + (" = ~L~_w" if j == len(path) - 2 else "")
        fig.text(add(F(mid), (10, 4)), label, "start", 12, RED)
    for j, p in enumerate(path[1:-1], 1):
        fig.dot(F(p), INK, 3.5)
        fig.text(add(F(p), (0, 18 if p[1] == 0 else -8)), "×~r~", size=12)
    fig.dot(F(o), INK, 5)
    fig.text(add(F(o), (-8, 4)), "eye", "end", 12)
    fig.text((410, 270), f"~L~_0 = ~r~ ~L~_1 = … = ~r~^k ~L~_w:  ~r~ = {r_mirror}, "
             f"~k~ = {k_bounces}, ~L~_0 = {r_mirror ** k_bounces:.4f} ~L~_w", size=13)
    return fig.write(name)


if __name__ == "__main__":
    made = [reflection_figure("ch04-reflection.svg"), mirrors_figure("ch04-mirrors.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
