#!/usr/bin/env python3
"""Chapter 6's figures (SVG, written next to this script): the area light seen from a shading
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

from svgfig import (BLUE, DARK, FILL_GREY, FILL_ORANGE, GRID, INK, ORANGE, RED,
                    Figure, Frame2D, Projection, add, cross, dot, length, mul, normalize, sub)


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

    lab_s, _ = angle_arc(p, n, to_x, 0.32, INK)
    fig.text(add(P(lab_s), (0, 5)), "~θ~_s", size=13)
    lab_l, _ = angle_arc(x, n_light, to_p, 0.34, BLUE)
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


def ball_figure(name):
    """The ball light's cone, in the plane of p, n and the centre: sin theta_max = R/d."""
    fig = Figure(800, 340, "a ball light seen from p: the cone of half-angle theta_max")
    F = Frame2D((60, 290), 100)
    p = (0.0, 0.0)
    centre = (2.6, 1.5)
    R = 0.7
    d = math.hypot(*centre)
    theta_max = math.asin(R / d)
    axis = math.atan2(centre[1], centre[0])
    fig.line(F((-0.5, 0)), F((3.9, 0)), DARK, 2.5)
    x = -0.5
    while x <= 3.9:
        fig.line(F((x, 0)), F((x - 0.06, -0.06)), GRID, 1)
        x += 0.1
    # The cone: tangent lines from p, touching the ball at distance sqrt(d^2 - R^2).
    fig.polygon([F(p)] + [F((math.cos(axis + s * theta_max) * math.sqrt(d * d - R * R),
                            math.sin(axis + s * theta_max) * math.sqrt(d * d - R * R)))
                          for s in (-1, 1)], FILL_ORANGE, "none", opacity=0.7)
    for s in (-1, 1):
        a = axis + s * theta_max
        tl = math.sqrt(d * d - R * R)
        fig.line(F(p), F((math.cos(a) * tl, math.sin(a) * tl)), ORANGE, 1.5, "5 3")
        touch = (math.cos(a) * tl, math.sin(a) * tl)
        fig.line(F(touch), F(centre), GRID, 1, "2 3")
    fig.circle(F(centre), R * F.scale, DARK, "#fff6dc", 2)
    fig.dot(F(centre), INK, 3)
    fig.line(F(p), F(centre), DARK, 1.2, "2 3")
    fig.text(add(F(mul(centre, 0.55)), (4, 16)), "~d~", "start", 14)
    fig.line(F(centre), F(add(centre, (0, R))), DARK, 1.5)
    fig.text(add(F(add(centre, (0, R / 2))), (6, 4)), "~R~", "start", 14)
    # A sample direction inside the cone (the page's 1 - cos theta = u1 (1 - cos theta_max)),
    # and where it meets the sphere first: distance r_k.
    u1 = 0.55
    theta = math.acos(1 - u1 * (1 - math.cos(theta_max)))
    a = axis + theta
    w = (math.cos(a), math.sin(a))
    b = w[0] * centre[0] + w[1] * centre[1]
    r_k = b - math.sqrt(b * b - (d * d - R * R))
    x_k = mul(w, r_k)
    fig.arrow(F(p), F(x_k), RED, 2.2)
    fig.dot(F(x_k), RED, 4)
    fig.text(add(F(x_k), (-4, -10)), "*x*_k", "end", 14, RED)
    fig.text(add(F(mul(x_k, 0.5)), (-6, -8)), "~r~_k", "end", 14, RED)
    fig.arc(F(p), 1.15 * F.scale, axis, axis - theta_max, ORANGE, 1.5)
    fig.text(add(F((1.3 * math.cos(axis - theta_max / 2), 1.3 * math.sin(axis - theta_max / 2))),
                 (4, 6)), "~θ~_{max}", "start", 13, ORANGE)
    fig.arc(F(p), 0.85 * F.scale, axis, a, RED, 1.5)
    fig.text(add(F((0.75 * math.cos(axis + theta / 2), 0.75 * math.sin(axis + theta / 2))),
                 (-4, 0)), "~θ~", "end", 13, RED)
    fig.arrow(F(p), F((0, 0.9)), DARK, 2)
    fig.text(add(F((0, 0.9)), (0, -8)), "*n*")
    fig.dot(F(p), INK, 4.5)
    fig.text(add(F(p), (0, 20)), "*p*")
    lines = [
        (f"sin ~θ~_{{max}} = ~R~/~d~ = {R / d:.3f}, "
         f"~θ~_{{max}} = {math.degrees(theta_max):.1f}°", ORANGE),
        ("~p~_ω = 1 / (2π(1 − cos ~θ~_{max})) inside the cone", INK),
        (f"this sample: ~u~_1 = {u1}, ~θ~ = {math.degrees(theta):.1f}°, ~r~_k = {r_k:.3f}", RED),
        (f"~w~_k = 2(1 − cos ~θ~_{{max}}) ~r~_k² / ~R~² = "
         f"{2 * (1 - math.cos(theta_max)) * r_k ** 2 / R ** 2:.3f}", RED),
    ]
    for k, (line, colour) in enumerate(lines):
        fig.text((450, 60 + 24 * k), line, "start", 13, colour)
    return fig.write(name)


def penumbra_figure(name):
    """Side view: a light of width l at height H, an occluder's edge at height h, and the floor
    shaded by the visible share of the light (linear across the penumbra: one gradient)."""
    ell, H, h, x_e = 1.2, 3.0, 1.0, 0.0
    fig = Figure(760, 410, "where the penumbra is: similar triangles")
    F = Frame2D((300, 330), 90)
    # The floor, shaded by the share of the light segment each point sees past the edge. A
    # light point a is hidden from floor point x when the line between them passes the
    # occluder's height h left of the edge; the last visible one is a_edge(x), linear in x, so
    # the share is linear across the penumbra and one gradient draws it exactly.
    x0, x1 = -3.0, 3.6

    def share(x):
        a_edge = x + (x_e - x) * H / h
        return (ell / 2 - max(-ell / 2, min(ell / 2, a_edge))) / ell

    def grey(v):
        level = int(round(255 - 200 * (1 - v)))
        return f"#{level:02x}{level:02x}{min(255, level + 10):02x}"

    foot_dark = x_e + (x_e - ell / 2) * h / (H - h)  # sees none of the light left of here
    foot_lit = x_e + (x_e + ell / 2) * h / (H - h)  # sees all of it right of here
    assert abs(share(foot_dark)) < 1e-12 and abs(share(foot_lit) - 1.0) < 1e-12
    fill = fig.linear_gradient("penumbra", F((foot_dark, 0))[0], F((foot_lit, 0))[0],
                               [(0.0, grey(0.0)), (1.0, grey(1.0))])
    fig.rect(*F((x0, 0)), *F((x1, -0.25)), "none", fill, 0)
    fig.line(F((x0, 0)), F((x1, 0)), DARK, 2)
    # The occluder (a plate ending at its edge) and the light.
    fig.rect(*F((x0, h + 0.06)), *F((x_e, h - 0.06)), DARK, "#777", 1)
    fig.line(F((-ell / 2, H)), F((ell / 2, H)), ORANGE, 6)
    # The two boundary rays through the edge.
    feet = []
    for a in (-ell / 2, ell / 2):
        foot = x_e + (x_e - a) * h / (H - h)
        feet.append(foot)
        fig.line(F((a, H)), F((foot, 0)), GRID, 1.2, "5 3")
    fig.dot(F((x_e, h)), RED, 4)
    # Labels: the light's width, heights, and the penumbra's width on the floor.
    fig.text(add(F((0, H)), (0, -10)), "ℓ", size=15, fill=ORANGE)
    fig.line(F((2.6, 0)), F((2.6, H)), DARK, 1)
    fig.text(add(F((2.6, H / 2)), (6, 4)), "~H~", "start", 14)
    fig.line(F((-2.6, 0)), F((-2.6, h)), DARK, 1)
    fig.text(add(F((-2.6, h / 2)), (-6, 4)), "~h~", "end", 14)
    lo_f, hi_f = min(feet), max(feet)
    fig.line(F((lo_f, -0.4)), F((hi_f, -0.4)), RED, 2)
    for xf in (lo_f, hi_f):
        fig.line(F((xf, -0.32)), F((xf, -0.48)), RED, 2)
    width = ell * h / (H - h)
    assert abs((hi_f - lo_f) - width) < 1e-12
    fig.text(add(F(((lo_f + hi_f) / 2, -0.4)), (0, 18)), "~w~_{penumbra}", size=13, fill=RED)
    fig.text(add(F(((x0 + lo_f) / 2, -0.12)), (0, 4)), "umbra", size=12, fill="white")
    fig.text(add(F(((hi_f + x1) / 2, -0.12)), (0, 4)), "lit", size=12)
    fig.text((560, 40), f"~w~_{{penumbra}} = ℓ ~h~ / (~H~ − ~h~)", "start", 14, RED)
    fig.text((560, 62), f"= {ell} · {h} / ({H} − {h}) = {width:.2f}", "start", 13, RED)
    fig.text((560, 90), "floor shaded by the share", "start", 12, "#555")
    fig.text((560, 106), "of the light it sees", "start", 12, "#555")
    return fig.write(name)


if __name__ == "__main__":
    made = [solid_angle_figure("ch06-solid-angle.svg"), ball_figure("ch06-ball.svg"),
            penumbra_figure("ch06-penumbra.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
