#!/usr/bin/env python3
"""Chapter 1's figures (SVG, written next to this script): the constructions of
chapters/01-raycast.md, computed with the page's own equations.

    python3 docs/figures/ch01_figures.py

ch01-camera.svg   the camera frame (w, u, v') built from view and up by Gram-Schmidt, the image
                  plane at distance 1 with half-sizes s_x and s_y, and the ray through the
                  centre of one pixel; beside it the side view that shows fovy
ch01-sphere.svg   ray and unit sphere in the plane of the ray and the centre: f, the roots t0 and
                  t1 from the stable quadratic, and the quadratic a t^2 + 2h t + c itself drawn
                  under each ray on the same t scale, for a miss, a graze and two hits
ch01-slab.svg     the slab test in 2D: the x and y slabs of a box, the t intervals of a ray in
                  each, and their overlap (a hit) or its absence (a miss)
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, FILL_RED, GRID, INK, ORANGE,
                    RED, Figure, Frame2D, Projection, add, cross, dot, mul, normalize, sub)

# --- the camera --------------------------------------------------------------------------------


def camera_figure(name):
    # gr.render's arguments: eye, view (any length), up (not perpendicular to view), fovy.
    eye = (0.0, 0.0, 0.0)
    view = (0.0, -0.12, -2.0)
    up_hint = (0.0, 1.0, 0.5)
    fovy = 50.0
    W, H = 8, 6
    # Gram-Schmidt, as on the page: w = v/|v|, u = w x up / |.|, v' = u x w.
    w = normalize(view)
    u = normalize(cross(w, up_hint))
    vp = cross(u, w)
    s_y = math.tan(math.radians(fovy) / 2)
    s_x = s_y * W / H

    def plane(x, y):
        """The image plane's point at pixel position (x, y): w + (2x/W-1)s_x u + (1-2y/H)s_y v'."""
        return add(add(eye, w), add(mul(u, (2 * x / W - 1) * s_x), mul(vp, (1 - 2 * y / H) * s_y)))

    fig = Figure(940, 430, "the pinhole camera: frame, image plane and fovy")
    P = Projection((80, 235), 270, azimuth=60, elevation=20)

    # The frustum edges from the eye to the four corners, then the pixel grid on the plane.
    corners = [plane(0, 0), plane(W, 0), plane(W, H), plane(0, H)]
    fig.polygon([P(c) for c in corners], FILL_GREY, DARK, 1.5)
    for x in range(1, W):
        fig.line(P(plane(x, 0)), P(plane(x, H)), GRID, 0.8)
    for y in range(1, H):
        fig.line(P(plane(0, y)), P(plane(W, y)), GRID, 0.8)
    for c in corners:
        fig.line(P(eye), P(c), GRID, 1, "5 4")
    # The chosen pixel (i, j) = (5, 1) and its centre (x, y) = (i + 1/2, j + 1/2).
    i, j = 5, 1
    fig.polygon([P(plane(i, j)), P(plane(i + 1, j)), P(plane(i + 1, j + 1)), P(plane(i, j + 1))],
                FILL_RED, RED, 1.2)
    centre = plane(i + 0.5, j + 0.5)
    # Half-sizes of the plane, from its centre e + w.
    mid = add(eye, w)
    fig.line(P(mid), P(add(mid, mul(u, s_x))), BLUE, 2.5)
    fig.line(P(mid), P(add(mid, mul(vp, -s_y))), ORANGE, 2.5)
    fig.text(add(P(add(mid, mul(u, s_x * 0.55))), (-4, 18)), "~s~_x", fill=BLUE)
    fig.text(add(P(add(mid, mul(vp, -s_y * 0.5))), (-14, 4)), "~s~_y", fill=ORANGE)
    # The eye to the plane: w, distance 1.
    fig.line(P(eye), P(mid), DARK, 1, "2 3")
    fig.dot(P(mid), DARK, 3)
    # The ray through the pixel centre, drawn on to 1.45 times the plane distance.
    d = normalize(sub(centre, eye))
    far = add(eye, mul(d, 1.45 / dot(d, w)))
    fig.line(P(eye), P(centre), RED, 2)
    fig.arrow(P(centre), P(far), RED, 2)
    fig.dot(P(centre), RED, 3.5)
    fig.text(add(P(far), (8, -2)), "*d*(~x~, ~y~)", "start", fill=RED)
    label_at = add(P(corners[1]), (30, -30))
    fig.line(P(centre), add(label_at, (0, 4)), RED, 0.8)
    fig.text(add(label_at, (4, 0)), "pixel centre (~i~ + ½, ~j~ + ½)", "start", 12, RED)
    # Corner labels in pixel units.
    fig.text(add(P(corners[0]), (-4, -8)), "(0, 0)", "end", 12)
    fig.text(add(P(corners[2]), (6, 16)), "(~W~, ~H~)", "start", 12)
    # The frame at the eye.
    k = 0.38
    fig.arrow(P(eye), P(add(eye, mul(w, k))), INK, 2)
    fig.arrow(P(eye), P(add(eye, mul(u, k))), BLUE, 2)
    fig.arrow(P(eye), P(add(eye, mul(vp, k))), ORANGE, 2)
    fig.arrow(P(eye), P(add(eye, mul(normalize(up_hint), k))), GRID, 1.5, "4 3")
    fig.dot(P(eye), INK, 4.5)
    fig.text(add(P(eye), (-10, 6)), "*e*", "end")
    fig.text(add(P(add(eye, mul(w, k))), (4, -10)), "*w*", "start")
    fig.text(add(P(add(eye, mul(u, k))), (-2, 18)), "*u*", fill=BLUE)
    fig.text(add(P(add(eye, mul(vp, k))), (-12, 0)), "*v*′", "end", fill=ORANGE)
    fig.text(add(P(add(eye, mul(normalize(up_hint), k))), (6, -4)), "*u*_{up}", "start",
             fill="#667")
    fig.text((250, 420), f"3D view; the image is {W} × {H} pixels, pixel (5, 1) is red",
             size=12, fill="#555")

    # The side view: the plane of w and v', seen along u.
    F = Frame2D((600, 215), 200)
    half = math.radians(fovy) / 2
    fig.line(F((0, 0)), F((1.08, 0)), DARK, 1, "2 3")
    fig.line(F((1, -s_y)), F((1, s_y)), DARK, 2.5)
    for y in range(1, H):
        yy = (1 - 2 * y / H) * s_y
        fig.line(F((0.985, yy)), F((1.015, yy)), DARK, 1.2)
    top, bottom = (1, s_y), (1, -s_y)
    fig.line(F((0, 0)), F(top), GRID, 1, "5 4")
    fig.line(F((0, 0)), F(bottom), GRID, 1, "5 4")
    # Angles: theta_y/2 between w and the top edge, theta_y between the edges.
    fig.arc(F((0, 0)), 0.36 * F.scale, 0, half, DARK)
    fig.arc(F((0, 0)), 0.62 * F.scale, -half, half, ORANGE, 1.5)
    fig.text(add(F((0.4, 0.09)), (0, 4)), "~θ~_y / 2", "start", 13)
    fig.text(add(F((0.62 * math.cos(half), -0.62 * math.sin(half))), (2, 16)), "~θ~_y", "middle",
             13, ORANGE)
    fig.text(F((0.55, -0.04)), "1", "middle", 13)
    # s_y along the plane, bracketed on the right.
    fig.line(F((1.08, 0)), F((1.08, s_y)), ORANGE, 2.5)
    fig.text(add(F((1.08, s_y / 2)), (8, 5)), "~s~_y = tan(~θ~_y / 2)", "start", 13, ORANGE)
    fig.text(add(F(top), (0, -10)), "~y~ = 0", "middle", 12)
    fig.text(add(F(bottom), (0, 20)), "~y~ = ~H~", "middle", 12)
    # The ray through row j's centre: vertical plane coordinate (1 - 2y/H) s_y.
    yc = (1 - 2 * (j + 0.5) / H) * s_y
    fig.line(F((0, 0)), F((1, yc)), RED, 2)
    fig.arrow(F((1, yc)), F((1.3, 1.3 * yc)), RED, 2)
    fig.dot(F((1, yc)), RED, 3.5)
    fig.text(add(F((1, yc)), (-8, -8)), "~y~ = ~j~ + ½", "end", 12, RED)
    fig.arrow(F((0, 0)), F((0.25, 0)), INK, 2)
    fig.text(add(F((0.22, 0)), (0, 18)), "*w*", "middle")
    fig.dot(F((0, 0)), INK, 4.5)
    fig.text(add(F((0, 0)), (-10, 5)), "*e*", "end")
    fig.text((760, 420), "side view (along *u*): fovy", size=12, fill="#555")
    return fig.write(name)


# --- ray and sphere ----------------------------------------------------------------------------


def solve_half_b(a, h, c, o, d):
    """The page's stable quadratic: Delta = a(1 - |f|^2), q = -(h + sign(h) sqrt(Delta))."""
    f = sub(o, mul(d, h / a))
    delta = a * (1 - dot(f, f))
    if delta < 0:
        return f, delta, None
    q = -(h + math.copysign(math.sqrt(delta), h))
    t0, t1 = q / a, c / q
    return f, delta, tuple(sorted((t0, t1)))


def sphere_figure(name):
    cases = [("miss", 1.3), ("graze", 1.0), ("two hits", 0.6)]
    fig = Figure(900, 440, "ray and unit sphere: miss, graze, two hits")
    d = (1.25, 0.0)  # not normalised: a = |d|^2 = 1.5625
    for k, (label, b) in enumerate(cases):
        ox = 300 * k
        F = Frame2D((ox + 150, 140), 62)
        o = (-2.2, b)
        a, h, c = dot(d, d), dot(o, d), dot(o, o) - 1
        f, delta, roots = solve_half_b(a, h, c, o, d)
        if label == "graze":
            delta, roots = 0.0, (-h / a, -h / a)  # exactly tangent: one double root
        # The unit sphere (a circle in this plane) and its centre.
        fig.circle(F((0, 0)), F.scale, DARK, FILL_GREY, 1.5)
        fig.dot(F((0, 0)), INK, 3)
        fig.text(add(F((0, 0)), (-6, 16)), "0", "end", 12)
        # The ray o + t d for t in [0, 3.6].
        tmax = 3.55
        end = add(o, mul(d, tmax))
        fig.line(F(o), F(end), DARK, 1.2)
        fig.arrow(F(o), F(add(o, d)), INK, 2)
        fig.dot(F(o), INK, 4)
        fig.text(add(F(o), (0, -10)), "*o*", "middle")
        fig.text(add(F(add(o, mul(d, 0.5))), (0, -8)), "*d*", "middle")
        # f: from the centre to the closest point of the line, at t = -h/a.
        fig.arrow(F((0, 0)), F(f), BLUE, 2)
        fig.text(add(F(mul(f, 0.5)), (8, 4)), "*f*", "start", fill=BLUE)
        for t in roots or ():
            fig.dot(F(add(o, mul(d, t))), RED, 5)
        if roots and label == "two hits":
            fig.text(add(F(add(o, mul(d, roots[0]))), (-6, -8)), "~t~_0", "end", fill=RED)
            fig.text(add(F(add(o, mul(d, roots[1]))), (6, -8)), "~t~_1", "start", fill=RED)
        if label == "graze":
            fig.text(add(F(add(o, mul(d, roots[0]))), (0, -10)), "~t~_0 = ~t~_1", fill=RED)
        fig.text((ox + 150, 26), f"{label}: |*f*| {'>' if b > 1 else '=' if b == 1 else '<'} 1",
                 weight="bold")

        # The quadratic a t^2 + 2h t + c, on the same t scale as the ray above.
        G = Frame2D((0, 330), 1)
        qscale = 13.0  # page units per unit of q

        def plot(t, q):
            return (F(add(o, mul(d, t)))[0], G.origin[1] - qscale * q)

        fig.line(plot(0, 0), plot(tmax, 0), DARK, 1)
        fig.text(add(plot(tmax, 0), (4, 4)), "~t~", "start", 13)
        fig.line(plot(0, -3.2), plot(0, 7.2), DARK, 1)
        pts = []
        n = 120
        for s in range(n + 1):
            t = tmax * s / n
            q = a * t * t + 2 * h * t + c
            if -3.2 <= q <= 7.2:
                pts.append(plot(t, q))
        fig.polyline(pts, BLUE, 2)
        tv = -h / a
        qmin = -delta / a  # the minimum of the parabola: |f|^2 - 1
        fig.line(plot(tv, 0), plot(tv, qmin), GRID, 1, "3 3")
        fig.dot(plot(tv, qmin), BLUE, 3)
        fig.text(add(plot(tv, qmin), (8, 14 if qmin < 0 else -6)),
                 f"−Δ/~a~ = |*f*|² − 1 = {0.0 if abs(qmin) < 5e-3 else qmin:.2f}"
                 .replace("-", "−"),
                 "start", 12, BLUE)
        for t in roots or ():
            fig.dot(plot(t, 0), RED, 4.5)
            fig.line(plot(t, 0), F(add(o, mul(d, t))), RED, 0.8, "2 3")
        fig.text(add(plot(0, 7.2), (6, 10)), "~a~~t~² + 2~h~~t~ + ~c~", "start", 12, BLUE)
        what = ("Δ < 0: no real root" if delta < 0 else
                "Δ = 0: one double root" if delta == 0 else
                f"Δ > 0: ~t~_0 = {roots[0]:.2f}, ~t~_1 = {roots[1]:.2f}")
        fig.text((ox + 150, 400), what, size=13)
        fig.text(add(plot(tv, 0), (0, -8 if qmin < 0 else 16)), "−~h~/~a~", size=11, fill="#555")
    fig.text((450, 430), f"the same *d* in all three: ~a~ = |*d*|² = {dot(d, d):.4g}; "
             "*f* = *o* − (~h~/~a~) *d*", size=12, fill="#555")
    return fig.write(name)


# --- the slab test -----------------------------------------------------------------------------


def slab_intervals(o, d, lo, hi):
    """t_near and t_far on each axis (swapped when d_i < 0), then enter/exit with t in (0, inf)."""
    near, far = [], []
    for i in range(2):
        t_lo, t_hi = (lo[i] - o[i]) / d[i], (hi[i] - o[i]) / d[i]
        near.append(min(t_lo, t_hi))
        far.append(max(t_lo, t_hi))
    return near, far, max(0.0, *near), min(far)


def slab_figure(name):
    lo, hi = (1.6, 1.0), (3.6, 2.4)
    rays = [("hit", (-0.2, 3.3), (1.0, -0.62)),
            ("miss", (-0.35, 0.75), (1.0, 1.0))]
    fig = Figure(900, 535, "the slab test: a ray's t intervals in the x and y slabs")
    for k, (label, o, d) in enumerate(rays):
        ox = 450 * k
        F = Frame2D((ox + 60, 342), 85)
        xmin, xmax, ymin, ymax = -0.45, 4.3, -0.15, 3.55
        # The slabs: x between the planes x = lo_x and x = hi_x, y likewise; the box is both.
        fig.rect(*F((lo[0], ymax)), *F((hi[0], ymin)), "none", FILL_BLUE, 0)
        fig.rect(*F((xmin, hi[1])), *F((xmax, lo[1])), "none", FILL_ORANGE, 0, opacity=0.8)
        for x in (lo[0], hi[0]):
            fig.line(F((x, ymin)), F((x, ymax)), BLUE, 1.2, "5 3")
        for y in (lo[1], hi[1]):
            fig.line(F((xmin, y)), F((xmax, y)), ORANGE, 1.2, "5 3")
        fig.rect(*F(lo), *F(hi), DARK, "none", 2.5)
        fig.text(add(F((lo[0], ymin)), (0, 16)), "~x~ = lo_x", size=12, fill=BLUE)
        fig.text(add(F((hi[0], ymin)), (0, 16)), "~x~ = hi_x", size=12, fill=BLUE)
        fig.text(add(F((xmax, hi[1])), (0, -5)), "~y~ = hi_y", "end", 12, ORANGE)
        fig.text(add(F((xmax, lo[1])), (0, 15)), "~y~ = lo_y", "end", 12, ORANGE)
        near, far, t_enter, t_exit = slab_intervals(o, d, lo, hi)
        # The ray, drawn for t in [0, t_end].
        t_end = min((xmax - 0.1 - o[0]) / d[0],
                    ((ymax if d[1] > 0 else ymin) - o[1]) / d[1])
        fig.line(F(o), F(add(o, mul(d, t_end))), DARK, 1.5)
        fig.arrow(F(o), F(add(o, mul(d, 0.55))), INK, 2.2)
        fig.dot(F(o), INK, 4)
        fig.text(add(F(o), (-4, -9)), "*o*", "middle")
        side = normalize((-d[1], d[0]))  # the label sits on the left of the ray, off the arrow
        fig.text(add(F(add(add(o, mul(d, 0.3)), mul(side, 0.22))), (0, 5)), "*d*")
        hit = t_enter <= t_exit
        if hit:
            fig.line(F(add(o, mul(d, t_enter))), F(add(o, mul(d, t_exit))), RED, 4)
        for t, colour in ((near[0], BLUE), (far[0], BLUE), (near[1], ORANGE), (far[1], ORANGE)):
            fig.dot(F(add(o, mul(d, t))), colour, 4.5)

        # The t axis: t maps to the x of the ray point, so every mark sits under its crossing.
        def T(t, row):
            return (F(add(o, mul(d, t)))[0], 385 + 24 * row)

        base = 3
        t_axis = max(t_end, *far) + 0.25
        fig.line(T(0, base), T(t_axis, base), DARK, 1)
        fig.text(add(T(t_axis, base), (4, 4)), "~t~", "start", 13)
        fig.line(T(0, base - 0.2), T(0, base + 0.2), DARK, 1)
        fig.text(add(T(0, base), (0, 17)), "0", size=12)
        rows = [(0, near[0], far[0], BLUE, "~x~ slab"), (1, near[1], far[1], ORANGE, "~y~ slab")]
        for row, t0, t1, colour, name_ in rows:
            fig.line(T(t0, row), T(t1, row), colour, 5)
            fig.text(add(T(t1, row), (8, 5)), name_, "start", 12, colour)
        for t in near + far:
            fig.line(F(add(o, mul(d, t))), T(t, base), GRID, 0.8, "2 3")
        if hit:
            fig.line(T(t_enter, 2), T(t_exit, 2), RED, 5)
            fig.text(add(T(t_exit, 2), (8, 5)), "both: inside the box", "start", 12, RED)
        else:
            fig.text(add(T(min(far), 2), (0, 5)), "no overlap", "start", 12, RED)
        # Tick labels on the t axis, one line under the other where they are close.
        lab = [(near[0], "~t~_{near,x}", BLUE), (far[0], "~t~_{far,x}", BLUE),
               (near[1], "~t~_{near,y}", ORANGE), (far[1], "~t~_{far,y}", ORANGE)]
        lab.sort()
        for idx, (t, s, colour) in enumerate(lab):
            fig.text(add(T(t, base), (0, 18 + 14 * (idx % 2))), s, size=11, fill=colour)
        verdict = (f"hit: ~t~_{{enter}} = max(0, {max(near):.2f}) ≤ ~t~_{{exit}} = {min(far):.2f}"
                   if hit else
                   f"miss: ~t~_{{enter}} = {max(near):.2f} > ~t~_{{exit}} = {min(far):.2f}")
        fig.text((ox + 225, 522), verdict, size=13, fill=RED)
        fig.text((ox + 225, 22), label, weight="bold")
    return fig.write(name)


if __name__ == "__main__":
    made = [camera_figure("ch01-camera.svg"), sphere_figure("ch01-sphere.svg"),
            slab_figure("ch01-slab.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
