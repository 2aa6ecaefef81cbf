#!/usr/bin/env python3
"""Chapter 6's figure (SVG, written next to this script): the area light seen from a shading
point, in the notation of chapters/06-soft-shadows.md.

    python3 docs/figures/ch06_figures.py

ch06-solid-angle.svg   a shading point p on a floor with normal n, a one-sided rectangular light
                       of size l x w, its 3 x 3 stratified samples (one jittered point per cell,
                       the page's s_k), one sample x_k with the distance r_k and the angles
                       theta_l (at the light) and theta_s (at the surface), a patch dA at x_k, and
                       the light and the patch projected onto the unit hemisphere around p: the
                       solid angle Omega_A and d omega = cos theta_l dA / r^2.

Everything is computed in 3D and drawn with a fixed orthographic projection. The jitter comes
from a fixed linear congruential sequence (as in ch08_figures.py), so the file only changes when
this script does.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, GRID, INK, ORANGE, RED,
                    Figure, Projection, add, cross, dot, length, mul, normalize, sub)


def lcg(seed):
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def solid_angle_figure(name):
    p = (0.0, 0.0, 0.0)
    n = (0.0, 1.0, 0.0)
    centre = (1.25, 1.45, -0.4)
    n_light = normalize((-0.2, -1.0, 0.1))  # the side the panel emits to
    e1 = normalize(cross(n_light, (0.0, 0.0, 1.0)))
    e2 = cross(e1, n_light)
    ell, w = 1.5, 1.0

    def on_light(s, t):
        """The panel point of unit-square coordinates (s, t)."""
        return add(centre, add(mul(e1, (s - 0.5) * ell), mul(e2, (t - 0.5) * w)))

    fig = Figure(900, 470, "an area light seen from a shading point: solid angle and weights")
    P = Projection((215, 330), 150, azimuth=20, elevation=34)
    # The floor around p.
    floor = [(-1.0, 0, 0.9), (1.9, 0, 0.9), (1.9, 0, -1.3), (-1.0, 0, -1.3)]
    fig.polygon([P(q) for q in floor], FILL_GREY, GRID, 1)
    # The unit hemisphere around p: its rim on the floor, and a meridian for shape.
    rho = 0.8
    rim = [add(p, (rho * math.cos(a), 0, rho * math.sin(a)))
           for a in (2 * math.pi * k / 96 for k in range(97))]
    fig.polyline([P(q) for q in rim], GRID, 1.2, dash="4 3")
    for phi in (0.0, math.pi / 2):
        arc = [add(p, (rho * math.cos(b) * math.cos(phi), rho * math.sin(b),
                       rho * math.cos(b) * math.sin(phi))) for b in
               (math.pi * k / 48 for k in range(49))]
        fig.polyline([P(q) for q in arc], GRID, 1, dash="2 4")

    def on_sphere(q):
        return add(p, mul(normalize(sub(q, p)), rho))

    # The panel's outline projected onto the hemisphere: the solid angle Omega_A.
    outline = []
    for (s0, t0), (s1, t1) in (((0, 0), (1, 0)), ((1, 0), (1, 1)), ((1, 1), (0, 1)),
                               ((0, 1), (0, 0))):
        for k in range(24):
            a = k / 24
            outline.append(on_light(s0 + (s1 - s0) * a, t0 + (t1 - t0) * a))
    fig.polygon([P(on_sphere(q)) for q in outline], FILL_ORANGE, ORANGE, 1.5)
    # Rays from p to the panel's corners (thin), the panel itself, and its 3 x 3 strata.
    corners = [on_light(0, 0), on_light(1, 0), on_light(1, 1), on_light(0, 1)]
    for c in corners:
        fig.line(P(p), P(c), ORANGE, 0.8, "3 4")
    fig.polygon([P(c) for c in corners], "#fff6dc", DARK, 2)
    m = 3
    for k in range(1, m):
        fig.line(P(on_light(k / m, 0)), P(on_light(k / m, 1)), GRID, 1)
        fig.line(P(on_light(0, k / m)), P(on_light(1, k / m)), GRID, 1)
    rnd = lcg(6)
    samples = []
    for k in range(m * m):
        u1, u2 = next(rnd), next(rnd)
        samples.append((((k % m) + u1) / m, ((k // m) + u2) / m))
    chosen = 4
    for k, (s, t) in enumerate(samples):
        if k != chosen:
            fig.dot(P(on_light(s, t)), DARK, 2.5)
    # The chosen sample x_k, a small patch dA around it and that patch on the hemisphere.
    s, t = samples[chosen]
    x = on_light(s, t)
    h = 0.07
    patch = [on_light(s - h, t - h), on_light(s + h, t - h), on_light(s + h, t + h),
             on_light(s - h, t + h)]
    fig.polygon([P(q) for q in patch], RED, RED, 1, opacity=0.5)
    fig.polygon([P(on_sphere(q)) for q in patch], RED, RED, 1)
    fig.line(P(p), P(x), RED, 2)
    fig.dot(P(x), RED, 4)
    fig.text(add(P(x), (8, -8)), "*x*_k", "start", 14, RED)
    fig.text(add(P(on_sphere(x)), (10, 12)), "d~ω~", "start", 13, RED)
    fig.line(P(on_light(s + h, t - h)), P(on_light(s + 0.2, t - 0.32)), RED, 0.8)
    fig.text(add(P(on_light(s + 0.2, t - 0.32)), (2, -3)), "d~A~", "start", 13, RED)
    fig.text(add(P(mul(x, 0.62)), (-10, 0)), "~r~_k", "end", 14, RED)
    # Normals and angles: theta_s at p between n and x - p; theta_l at x between the light's
    # normal and p - x.
    to_x = normalize(sub(x, p))
    to_p = mul(to_x, -1)
    fig.arrow(P(p), P(mul(n, 0.95)), INK, 2)
    fig.text(add(P(mul(n, 0.95)), (-8, 0)), "*n*", "end")
    fig.arrow(P(x), P(add(x, mul(n_light, 0.6))), BLUE, 2)

    def angle_arc(at, a, b, radius, colour):
        """An arc at 3D point `at` from unit vector a towards unit vector b, in their plane."""
        ang = math.acos(max(-1.0, min(1.0, dot(a, b))))
        perp = normalize(sub(b, mul(a, dot(a, b))))
        pts = [add(at, mul(add(mul(a, math.cos(ang * k / 24)), mul(perp, math.sin(ang * k / 24))),
                           radius)) for k in range(25)]
        fig.polyline([P(q) for q in pts], colour, 1.5)
        mid = add(mul(a, math.cos(ang / 2)), mul(perp, math.sin(ang / 2)))
        return add(at, mul(mid, radius * 1.45)), math.degrees(ang)

    lab_s, theta_s = angle_arc(p, n, to_x, 0.32, INK)
    fig.text(add(P(lab_s), (0, 5)), "~θ~_s", size=13)
    lab_l, theta_l = angle_arc(x, n_light, to_p, 0.34, BLUE)
    fig.text(add(P(lab_l), (-6, 5)), "~θ~_l", "end", 13, BLUE)
    fig.dot(P(p), INK, 4.5)
    fig.text(add(P(p), (-8, 16)), "*p*", "end")
    # Side lengths of the panel.
    fig.text(add(P(on_light(0.5, -0.12)), (0, 5)), "ℓ", size=15)
    fig.text(add(P(on_light(1.06, 0.5)), (0, 5)), "~w~", "middle", 15)
    leftmost = min((P(on_sphere(q)) for q in outline), key=lambda q: q[0])
    fig.text(add(leftmost, (-6, 4)), "~Ω~_A", "end", 14, ORANGE)

    # The conversion, with the numbers of this sample.
    r = length(sub(x, p))
    cos_l, cos_s = dot(n_light, to_p), dot(n, to_x)
    tx, ty = 590, 60
    lines = [
        ("a patch d~A~ at *x*_k covers, seen from *p*,", INK),
        ("d~ω~ = cos ~θ~_l d~A~ / ~r~²", RED),
        ("so", INK),
        ("~E~ = ∫_A ~L~ cos ~θ~_l cos ~θ~_s / ~r~² ~V~ d~A~", INK),
        ("   = ∫ ~L~ cos ~θ~_s ~V~ d~ω~  over ~Ω~_A", INK),
        ("sampled uniformly on the panel (~p~ = 1/~A~,", INK),
        ("~L~ = ~I~/~A~), each sample weighs", INK),
        ("~w~_k = max(0, cos ~θ~_{l,k})", BLUE),
        ("", INK),
        (f"this sample: ~r~_k = {r:.2f}, ~θ~_l = {math.degrees(math.acos(cos_l)):.1f}°, "
         f"~θ~_s = {math.degrees(math.acos(cos_s)):.1f}°", "#555"),
        (f"~w~_k = {cos_l:.3f};  3 × 3 strata, one jittered point each", "#555"),
    ]
    for k, (line, colour) in enumerate(lines):
        fig.text((tx, ty + 24 * k), line, "start", 14 if k < 9 else 12, colour)
    return fig.write(name)


if __name__ == "__main__":
    print("wrote docs/figures/" + solid_angle_figure("ch06-solid-angle.svg"))
