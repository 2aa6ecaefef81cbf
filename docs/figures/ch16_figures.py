#!/usr/bin/env python3
"""Chapter 16's figures (SVG, written next to this script): the constructions of
chapters/16-photon-mapping.md, computed with the page's equations.

    python3 docs/figures/ch16_figures.py

ch16-two-passes.svg   Jensen's two passes. Left, pass 1: photons from a point light above a
                      glass ball (n = 1.5) over a diffuse floor; those through the ball are
                      refracted at both surfaces and land close together on the floor (the
                      caustic map, orange); others land on the floor directly and bounce to the
                      red wall and back (the global map, blue; red once the wall has coloured
                      them). Right, pass 2: a camera ray meets the floor at x, and the disk of
                      radius r around x gathers the photons inside: L = sum f Phi_p / (pi r^2);
                      under it, the floor around x seen from above, magnified, with 160 caustic
                      photons aimed at the ball from every azimuth (the light is on the ball's
                      axis, so each one travels in a plane through the axis and the 2D trace
                      gives its landing point) and those inside the disk ringed.
ch16-ball-focus.svg   nine parallel rays at heights -0.9R .. 0.9R through a glass ball of index
                      1.5, refracted at both surfaces: the paraxial rays cross the axis at
                      nR/(2(n - 1)) = 1.5R from the centre, the marginal ones nearer (spherical
                      aberration); the crossings of each height are listed.
ch16-nephroid.svg     40 parallel rays reflected once inside a circular mirror of radius R: the
                      reflected chords envelope a nephroid, whose analytic curve
                      x = (R/4)(3 cos t - cos 3t), y = (R/4)(3 sin t - sin 3t), |t| <= pi/2, is
                      drawn dashed; its cusp lies at R/2 from the centre.
ch16-hash-grid.svg    the hashed uniform grid of the gather: photons on a plane, cells of side 2r,
                      a gather point x and its disk of radius r, the 2 x 2 block of cells the disk
                      can touch (chosen by the quadrant of its cell that x lies in) and the
                      photons of that block inside the disk; a table of cell (i, j) -> hash ->
                      bucket for the block, with Teschner et al.'s hash and 64 buckets. Only the
                      hash's low 6 bits count, and two cells outside the block land in its
                      buckets: their photons are in the buckets too, and the distance test
                      rejects them.
ch16-sppm-radius.svg  stochastic progressive photon mapping: r_i / r_0 against the pass i (log
                      axis) for alpha = 0.5, 2/3 and 0.9 under r_{i+1}^2 = r_i^2 (N_i + alpha M_i)
                      / (N_i + M_i), N_{i+1} = N_i + alpha M_i, N_0 = 0, and the asymptote
                      r_i^2 / r_0^2 = i^(alpha - 1) / Gamma(alpha) for alpha = 2/3, dashed. Every
                      pass emits the same number of photons, so the count expected in the disk
                      shrinks with its area, M_i = M_0 r_i^2 / r_0^2; then N_i = i M_i and the
                      update is r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) whatever M_0 is. (A
                      count M_i fixed at 1 would give r_i^2 ~ i^(1 - 1/alpha) instead.)

Every ray is traced: Snell's law in the vector form of chapter 5 (ch05_figures.py's refract),
the mirror direction d - 2 (d.n) n of chapter 4, and the roots of |o + t d - c|^2 = R^2. The
photons of ch16-hash-grid.svg and the directions of the caustic photons seen from above in
ch16-two-passes.svg come from a fixed linear congruential sequence (as in ch08_figures.py), so
the files only change when this script does. Run as a script, it prints
the numbers the figures check: the ball's paraxial focus and the ring's cusp found by tracing,
against their closed forms.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, FILL_RED, GREEN, GRID, INK,
                    ORANGE, RED, Figure, Frame2D, add, dot, length, mul, normalize, sub)

N_GLASS = 1.5


def lcg(seed):
    """A fixed stream of numbers in [0, 1) (Numerical Recipes' LCG): the same figure every run."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def refract(d, n, eta):
    """Chapter 5's t = eta d + (eta cos_i - cos_t) n (n faces the incoming ray), or None past
    the critical angle."""
    cos_i = -dot(d, n)
    cos2_t = 1 - eta * eta * (1 - cos_i * cos_i)
    if cos2_t < 0:
        return None
    return add(mul(d, eta), mul(n, eta * cos_i - math.sqrt(cos2_t)))


def reflect(d, n):
    return sub(d, mul(n, 2 * dot(d, n)))


def hit_circle(o, d, c, radius):
    """The smallest t > 0 with |o + t d - c| = radius (d a unit vector), or None."""
    oc = sub(o, c)
    b = dot(oc, d)
    disc = b * b - (dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    s = math.sqrt(disc)
    for t in (-b - s, -b + s):
        if t > 1e-9:
            return t
    return None


def through_ball(o, d, c, radius, n=N_GLASS):
    """A ray through a glass ball: the entry point, the exit point and the direction out."""
    p1 = add(o, mul(d, hit_circle(o, d, c, radius)))
    d1 = refract(d, normalize(sub(p1, c)), 1 / n)
    p2 = add(p1, mul(d1, hit_circle(p1, d1, c, radius)))
    d2 = refract(d1, normalize(sub(c, p2)), n)
    return p1, p2, d2


# --- ch16-two-passes.svg ---------------------------------------------------------------------

LIGHT = (0.0, 3.2)
BALL, BALL_R = (0.0, 1.2), 0.5  # the light at 4R above the centre images 2.4R below it
WALL_X, FLOOR_X0, TOP = 2.0, -2.1, 3.45


def scene(fig, F, faint):
    """The floor, the red wall, the glass ball and the light."""
    fig.rect(*F((FLOOR_X0, 0)), *F((WALL_X, -0.12)), "none", FILL_GREY, 0)
    fig.line(F((FLOOR_X0, 0)), F((WALL_X, 0)), DARK, 2)
    fig.rect(*F((WALL_X, TOP)), *F((WALL_X + 0.12, -0.12)), "none", FILL_RED, 0)
    fig.line(F((WALL_X, 0)), F((WALL_X, TOP)), RED, 2.5)
    fig.circle(F(BALL), BALL_R * F.scale, DARK, FILL_BLUE, 1.8)
    fig.dot(F(LIGHT), ORANGE if not faint else GRID, 6)
    for k in range(8):
        a = 2 * math.pi * k / 8
        u = (math.cos(a), math.sin(a))
        fig.line(F(add(LIGHT, mul(u, 0.1))), F(add(LIGHT, mul(u, 0.17))),
                 ORANGE if not faint else GRID, 1.5)


def to_floor_or_wall(o, d):
    """Where a ray from o along d meets the floor (y = 0) or the wall (x = WALL_X)."""
    hits = []
    if d[1] < 0:
        hits.append((-o[1] / d[1], "floor"))
    if d[0] > 0:
        hits.append(((WALL_X - o[0]) / d[0], "wall"))
    t, what = min(hits)
    p = add(o, mul(d, t))
    if what == "floor" and p[0] < FLOOR_X0:
        return None, "out"
    return p, what


def photon_paths():
    """Pass 1: (polyline, stored photons as (point, colour)) for each photon traced."""
    paths = []
    # Through the ball: impact parameters -0.8R .. 0.8R, refracted at both surfaces.
    for k in range(9):
        b = BALL_R * (-0.8 + 0.2 * k)
        dist = length(sub(BALL, LIGHT))
        a = math.asin(b / dist)
        d = (math.sin(a), -math.cos(a))
        p1, p2, d2 = through_ball(LIGHT, d, BALL, BALL_R)
        p3, what = to_floor_or_wall(p2, d2)
        assert what == "floor"
        paths.append(([LIGHT, p1, p2, p3], [(p3, ORANGE)]))
    # Straight to the floor, then diffuse bounces in fixed directions (degrees above the
    # floor, towards +x), stored at every diffuse hit; a photon that has met the red wall is
    # red.
    for angle, bounces in ((-22.0, (120.0,)), (-29.0, ()), (19.0, (38.0, 225.0)),
                           (25.0, (62.0,)), (30.0, ())):
        a = math.radians(angle)
        o, d = LIGHT, (math.sin(a), -math.cos(a))
        pts, stored, colour = [LIGHT], [], BLUE
        for bounce in (None,) + bounces:
            if bounce is not None:
                d = (math.cos(math.radians(bounce)), math.sin(math.radians(bounce)))
            p, what = to_floor_or_wall(o, d) if d[1] < 0 or d[0] > 0 else (None, "out")
            if p is None:
                # Leaves the scene: drawn to the panel's edge.
                t = min(t for t in ((TOP - o[1]) / d[1] if d[1] > 0 else math.inf,
                                    (FLOOR_X0 - o[0]) / d[0] if d[0] < 0 else math.inf))
                pts.append(add(o, mul(d, t)))
                break
            pts.append(p)
            if what == "wall":
                colour = RED
            stored.append((p, colour))
            o = p
        paths.append((pts, stored))
    return paths


def caustic_landing(theta):
    """Where a photon leaving the light at angle theta from the downward axis lands on the
    floor, through the ball. The light is on the ball's axis, so every photon travels in a
    plane through the axis: this 2D trace gives the landing of a 3D photon at any azimuth."""
    d = (math.sin(theta), -math.cos(theta))
    _p1, p2, d2 = through_ball(LIGHT, d, BALL, BALL_R)
    p3, what = to_floor_or_wall(p2, d2)
    return p3[0] if what == "floor" else None


def two_passes_figure(name):
    fig = Figure(900, 580, "Jensen's two passes: photons stored, then gathered around x")
    paths = photon_paths()
    stored = [s for _pts, st in paths for s in st]
    # Pass 1.
    F = Frame2D((232, 336), 84)
    scene(fig, F, False)
    for pts, st in paths:
        colour = ORANGE if any(c == ORANGE for _p, c in st) else BLUE
        for k in range(len(pts) - 1):
            fig.line(F(pts[k]), F(pts[k + 1]), colour, 1.2, opacity=0.8)
    for p, colour in stored:
        fig.dot(F(p), colour, 3.5, "white")
    fig.text((225, 24), "pass 1: photons from the light", weight="bold")
    fig.text(add(F(BALL), (0, 5)), "glass", size=12)
    fig.text(add(F((-1.25, 0)), (0, 22)), "diffuse floor", size=12)
    fig.text(add(F((WALL_X, 2.6)), (-8, 0)), "red wall", "end", 12, RED)
    fig.text(add(F((0.0, 0.0)), (0, 22)), "caustic", size=12, fill=ORANGE)
    y = 410
    for k, (colour, label) in enumerate(((ORANGE, "caustic map: light → glass → floor"),
                                         (BLUE, "global map: every diffuse hit"),
                                         (RED, "global map, after the red wall"))):
        fig.dot((70, y + 26 * k - 4), colour, 4, "white")
        fig.text((82, y + 26 * k), label, "start", 13)
    fig.text((70, y + 26 * 3 + 6), "photons are stored where they meet a diffuse surface",
             "start", 12, "#555")
    # Pass 2: the same photons, a camera ray to x and the gather disk.
    G = Frame2D((682, 336), 84)
    scene(fig, G, True)
    x, r = (0.14, 0.0), 0.16
    eye = (-1.85, 2.2)
    ray = normalize(sub(x, eye))
    assert hit_circle(eye, ray, BALL, BALL_R) is None  # the camera sees the floor, not glass
    fig.circle(G(x), r * G.scale, RED, FILL_RED, 1.2)
    for p, colour in stored:
        fig.dot(G(p), colour, 3.5, "white")
    side = (-ray[1], ray[0])
    body = [add(eye, add(mul(ray, a), mul(side, b)))
            for a, b in ((-0.2, 0.11), (0.04, 0.0), (-0.2, -0.11))]
    fig.polygon([G(q) for q in body], INK)
    fig.text(add(G(eye), (-6, -14)), "camera", "middle", 12)
    fig.arrow(G(add(eye, mul(ray, 0.06))), G(add(x, mul(ray, -r - 0.03))), INK, 1.8)
    fig.dot(G(x), INK, 3)
    fig.text(add(G(x), (12, -14)), "*x*", "start")
    fig.text((675, 24), "pass 2: gather around *x*", weight="bold")
    # The floor around x seen from above, magnified: the caustic photons, aimed at the ball
    # at every azimuth (the nine of pass 1 among them), and the disk of radius r.
    half_w, half_h = 0.62, 0.21
    box = (470, 392, 880, 392 + 410 * half_h / half_w)
    mag = (box[2] - box[0]) / (2 * half_w)

    def T(q):
        """Floor coordinates (x, z) to the inset."""
        return ((box[0] + box[2]) / 2 + mag * (q[0] - x[0]), (box[1] + box[3]) / 2 - mag * q[1])

    for sx in (-1, 1):
        fig.line(G((x[0] + sx * half_w, -0.02)), ((box[0], box[2])[sx > 0], box[1]), GRID, 1,
                 "3 3")
    fig.rect(*G((x[0] - half_w, 0.07)), *G((x[0] + half_w, -0.09)), GRID, "none", 1)
    fig.rect(*box, DARK, FILL_GREY, 1)
    fig.circle(T(x), r * mag, RED, FILL_RED, 1.5)
    photons = [(p[0], 0.0) for p, c in stored if c == ORANGE]
    rnd = lcg(16)
    theta_max = math.asin(BALL_R / length(sub(BALL, LIGHT)))
    while len(photons) < 160:
        # Uniform over the cone of directions that meets the ball, uniform in azimuth.
        cos_t = 1 - next(rnd) * (1 - math.cos(theta_max))
        phi = 2 * math.pi * next(rnd)
        rho = caustic_landing(math.acos(cos_t))
        if rho is not None:
            photons.append((abs(rho) * math.cos(phi), abs(rho) * math.sin(phi)))
    margin = 3 / mag  # keep the dots inside the frame
    shown = [q for q in photons
             if abs(q[0] - x[0]) < half_w - margin and abs(q[1]) < half_h - margin]
    inside = [q for q in shown if length(sub(q, x)) < r]
    for q in shown:
        if q in inside:
            fig.circle(T(q), 2.6, INK, ORANGE, 1.1)
        else:
            fig.dot(T(q), ORANGE, 2.2)
    rim = add(x, (r * math.cos(math.radians(-30)), r * math.sin(math.radians(-30))))
    fig.line(T(x), T(rim), INK, 1.5)
    fig.dot(T(x), INK, 3.5)
    for at, label in ((add(T(x), (-1, -13)), "*x*"),
                      (add(T(add(x, mul(sub(rim, x), 0.55))), (4, 15)), "~r~")):
        fig.rect(at[0] - 7, at[1] - 13, at[0] + 7, at[1] + 4, "none", "white", 0, opacity=0.85)
        fig.text(at, label, "middle", 14)
    fig.text((box[2] - 70, box[1] - 6), "the floor around *x*, from above", "end", 12, "#555")
    fig.text(((box[0] + box[2]) / 2, box[3] + 24), "~L~ ≈ Σ ~f~·Φ_p / (π ~r~^2)", size=15,
             fill=RED)
    fig.text(((box[0] + box[2]) / 2, box[3] + 44),
             f"over the {len(inside)} caustic photons inside the disk", size=12, fill=RED)
    return fig.write(name), len(stored), len(photons), len(inside)


# --- ch16-ball-focus.svg ---------------------------------------------------------------------


def axis_crossing(p, d):
    """Where the line p + t d meets y = 0."""
    return p[0] - p[1] * d[0] / d[1]


def ball_focus_figure(name):
    fig = Figure(760, 345, "parallel rays through a glass ball: the paraxial focus and "
                 "spherical aberration")
    F = Frame2D((250, 170), 105)
    R, n = 1.0, N_GLASS
    x_left, x_right, y_lim = -2.2, 2.45, 1.45
    f_closed = n * R / (2 * (n - 1))
    fig.line(F((x_left, 0)), F((x_right, 0)), GRID, 1, "6 4")
    fig.circle(F((0, 0)), R * F.scale, DARK, FILL_BLUE, 1.8)
    fig.text(add(F((-0.75, R)), (0, 0)), f"glass, ~n~ = {n:g}", "end", 12)
    crossings = {}
    for k in range(9):
        h = R * (-0.9 + 0.225 * k)
        o = (x_left, h)
        p1, p2, d2 = through_ball(o, (1.0, 0.0), (0, 0), R)
        # Out of the ball until the ray leaves the drawing.
        t_end = min((x_right - p2[0]) / d2[0],
                    (y_lim * (1 if d2[1] > 0 else -1) - p2[1]) / d2[1] if d2[1] else math.inf)
        fig.polyline([F(o), F(p1), F(p2), F(add(p2, mul(d2, t_end)))], RED, 1.4)
        if abs(h) > 1e-9:
            crossings[round(abs(h), 3)] = axis_crossing(p2, d2)
    # The paraxial limit, traced: a ray at height 1e-4 R.
    p1, p2, d2 = through_ball((x_left, 1e-4 * R), (1.0, 0.0), (0, 0), R)
    f_traced = axis_crossing(p2, d2)
    fig.dot(F((0, 0)), INK, 3.5)
    fig.text(add(F((0, 0)), (0, 18)), "centre", size=12)
    for h, x in crossings.items():
        fig.dot(F((x, 0)), BLUE if h < 0.8 else ORANGE, 3.5)
    fig.dot(F((f_closed, 0)), INK, 4.5)
    # The distance centre to focus, under the ball.
    y_dim = -1.22
    for x in (0.0, f_closed):
        fig.line(F((x, -0.05)), F((x, y_dim - 0.06)), GRID, 1, "3 3")
    fig.arrow(F((f_closed / 2, y_dim)), F((0, y_dim)), INK, 1.2)
    fig.arrow(F((f_closed / 2, y_dim)), F((f_closed, y_dim)), INK, 1.2)
    fig.text(add(F((f_closed / 2, y_dim)), (0, 20)),
             f"paraxial focus: ~nR~ / (2(~n~ − 1)) = {f_closed:g}~R~", size=13)
    # The marginal rays' crossing, labelled above the drawing.
    marginal = crossings[0.9]
    fig.line(F((marginal, 0.08)), F((marginal, 1.12)), ORANGE, 1, "3 3")
    fig.text(add(F((marginal, 1.12)), (6, -4)), f"rays at ±0.9~R~ cross at {marginal:.3f}~R~",
             "end", 12, ORANGE)
    # The crossings, as a table.
    tx, ty = 575, 150
    fig.text((tx, ty), "height ~h~", "start", 12)
    fig.text((tx + 110, ty), "crosses at", "start", 12)
    for k, (h, x) in enumerate(sorted(crossings.items())):
        colour = BLUE if h < 0.8 else ORANGE
        fig.text((tx, ty + 18 * (k + 1)), f"±{h:g}~R~", "start", 12, colour)
        fig.text((tx + 110, ty + 18 * (k + 1)), f"{x:.3f}~R~", "start", 12, colour)
    fig.text((tx, ty + 18 * 5 + 4), "~h~ → 0", "start", 12)
    fig.text((tx + 110, ty + 18 * 5 + 4), f"{f_traced:.4f}~R~", "start", 12)
    fig.text((tx, ty - 26), "axis crossings", "start", 13, weight="bold")
    return fig.write(name), f_traced, f_closed, crossings


# --- ch16-nephroid.svg -----------------------------------------------------------------------


def nephroid(t, R):
    return (R / 4 * (3 * math.cos(t) - math.cos(3 * t)),
            R / 4 * (3 * math.sin(t) - math.sin(3 * t)))


def reflected_ray(h, R):
    """A ray along +x at height h, reflected inside the ring: the hit point and the mirror
    direction."""
    o, d = (-2 * R, h), (1.0, 0.0)
    # The far side of the ring: the second root of |o + t d|^2 = R^2.
    b = dot(o, d)
    t = -b + math.sqrt(b * b - (dot(o, o) - R * R))
    p = add(o, mul(d, t))
    return p, reflect(d, mul(p, -1 / R))  # the normal facing the ray points to the centre


def line_intersection(p, d, q, e):
    """The point where p + s d meets q + u e."""
    den = d[0] * e[1] - d[1] * e[0]
    s = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
    return add(p, mul(d, s))


def nephroid_figure(name):
    fig = Figure(620, 460, "parallel rays reflected in a circular mirror: the nephroid caustic")
    R = 1.0
    F = Frame2D((330, 205), 165)
    x_left = -1.75
    fig.circle(F((0, 0)), R * F.scale, DARK, "none", 2.5)
    fig.line(F((x_left, 0)), F((1.2, 0)), GRID, 1, "6 4")
    rays = 40
    for k in range(rays):
        h = R * (-1 + (2 * k + 1) / rays)
        p, r = reflected_ray(h, R)
        # The incoming ray: outside the ring, then faint inside it (it enters over the rim).
        x_in = -math.sqrt(R * R - h * h)
        fig.line(F((x_left, h)), F((x_in, h)), GRID, 0.8)
        fig.line(F((x_in, h)), F(p), GRID, 0.6, opacity=0.45)
        # The reflected chord, to where it meets the ring again.
        q = add(p, mul(r, hit_circle(p, r, (0, 0), R)))
        fig.line(F(p), F(q), BLUE, 0.9, opacity=0.75)
    curve = [nephroid(-math.pi / 2 + math.pi * k / 200, R) for k in range(201)]
    fig.polyline([F(c) for c in curve], RED, 1.8, dash="6 4")
    cusp = nephroid(0.0, R)
    fig.dot(F((0, 0)), INK, 3.5)
    fig.text(add(F((0, 0)), (-6, 18)), "centre", "end", 12)
    fig.dot(F(cusp), RED, 4.5)
    # R/2, under the ring: from the centre to the cusp.
    y_dim = -1.13
    for x in (0.0, cusp[0]):
        fig.line(F((x, -0.04)), F((x, y_dim - 0.05)), DARK, 0.8, "3 3")
    fig.arrow(F((cusp[0] / 2, y_dim)), F((0, y_dim)), INK, 1.2)
    fig.arrow(F((cusp[0] / 2, y_dim)), F((cusp[0], y_dim)), INK, 1.2)
    fig.text(add(F((cusp[0] / 2, y_dim)), (0, 20)), "~R~/2", size=14)
    fig.text(add(F((cusp[0], y_dim)), (6, 20)), "cusp", "start", 12, RED)
    fig.text(add(F((x_left, 1.08)), (0, 0)), "parallel rays", "start", 12)
    fig.text(add(F((0.74, 0.86)), (10, -4)), "mirror, radius ~R~", "start", 12)
    # Legend.
    fig.line((30, 440), (58, 440), BLUE, 1.5)
    fig.text((64, 444), "reflected once (traced)", "start", 12)
    fig.line((250, 440), (278, 440), RED, 1.8, "6 4")
    fig.text((284, 444), "nephroid (~R~/4)(3 cos ~t~ − cos 3~t~, 3 sin ~t~ − sin 3~t~)",
             "start", 12)
    return fig.write(name)


def nephroid_check(R=1.0, rays=40):
    """The envelope found by tracing: neighbouring reflected rays intersected. Returns the
    cusp (rays at +-1e-4 R), where the figure's two rays nearest the axis cross, and the
    largest distance of traced envelope points from the analytic curve at the same t."""
    p, r = reflected_ray(1e-4 * R, R)
    q, e = reflected_ray(-1e-4 * R, R)
    cusp = line_intersection(p, r, q, e)
    p, r = reflected_ray(R / rays, R)
    q, e = reflected_ray(-R / rays, R)
    nearest = line_intersection(p, r, q, e)
    worst = 0.0
    for k in range(1, 200):
        h = R * (-1 + 2 * k / 200)
        p, r = reflected_ray(h, R)
        q, e = reflected_ray(h + 1e-6, R)
        env = line_intersection(p, r, q, e)
        # The analytic point of the same parameter: t is the angle of the hit point.
        t = math.asin(h / R)
        worst = max(worst, length(sub(env, nephroid(t, R))))
    return cusp, nearest, worst


# --- ch16-hash-grid.svg ----------------------------------------------------------------------

TABLE_SIZE = 64


def cell_hash(i, j):
    """Teschner et al.'s spatial hash in two dimensions, as an unsigned 32-bit number."""
    return ((i * 73856093) ^ (j * 19349663)) % 2**32


def hash_grid_figure(name):
    cols, rows, s = 7, 4, 76.0  # cells; the side in page units is 2r
    x0, y0 = 44.0, 52.0

    def P(p):
        """Grid coordinates (in cells, y up) to the page."""
        return (x0 + s * p[0], y0 + s * (rows - p[1]))

    fig = Figure(900, 420, "a hashed grid of cells of side 2r: a gather touches a 2 x 2 block")
    rnd = lcg(16)
    photons = [(cols * next(rnd), rows * next(rnd)) for _ in range(240)]
    x = (3.7, 1.72)  # the gather point, in cells
    r = 0.5  # the radius in cells (the side is 2r)
    # The block: the cells nearest x's quadrant of its cell.
    i0, j0 = math.floor(x[0] - 0.5), math.floor(x[1] - 0.5)
    block = [(i, j) for j in (j0 + 1, j0) for i in (i0, i0 + 1)]
    buckets = {cell_hash(i, j) % TABLE_SIZE: (i, j) for i, j in block}
    # Other cells whose hash falls in one of the block's buckets: their photons are in the
    # buckets too, and the distance test rejects them.
    sharing = {(i, j): buckets[cell_hash(i, j) % TABLE_SIZE] for i in range(cols)
               for j in range(rows)
               if (i, j) not in block and cell_hash(i, j) % TABLE_SIZE in buckets}
    for i, j in block:
        fig.rect(*P((i, j + 1)), *P((i + 1, j)), "none", FILL_ORANGE, 0)
    for k in range(cols + 1):
        fig.line(P((k, 0)), P((k, rows)), GRID, 1)
    for k in range(rows + 1):
        fig.line(P((0, k)), P((cols, k)), GRID, 1)
    fig.rect(*P((i0, j0 + 2)), *P((i0 + 2, j0)), ORANGE, "none", 2)
    for i, j in sharing:
        fig.rect(*add(P((i, j + 1)), (3, 3)), *add(P((i + 1, j)), (-3, -3)), ORANGE, "none", 1.2,
                 "4 3")
    fig.circle(P(x), r * s, RED, FILL_RED, 1.5)
    # x's cell, split into quarters (dashed).
    ci, cj = math.floor(x[0]), math.floor(x[1])
    fig.line(P((ci + 0.5, cj)), P((ci + 0.5, cj + 1)), ORANGE, 1.4, "4 3")
    fig.line(P((ci, cj + 0.5)), P((ci + 1, cj + 0.5)), ORANGE, 1.4, "4 3")
    in_buckets = inside = 0
    for p in photons:
        c = (math.floor(p[0]), math.floor(p[1]))
        if c in block:
            in_buckets += 1
            if length(sub(p, x)) < r:
                inside += 1
                fig.dot(P(p), RED, 4)
            else:
                fig.dot(P(p), BLUE, 3)
        elif c in sharing:
            in_buckets += 1
            fig.circle(P(p), 3, BLUE, "white", 1.3)
        else:
            fig.dot(P(p), GRID, 2.5)
    rim = add(x, mul((math.cos(math.radians(-35)), math.sin(math.radians(-35))), r))
    fig.line(P(x), P(rim), INK, 1.5)
    fig.dot(P(x), INK, 3.5)
    for at, label in ((add(P(x), (-12, -5)), "*x*"),
                      (add(P(add(x, mul(sub(rim, x), 0.5))), (-2, 17)), "~r~")):
        fig.rect(at[0] - 7, at[1] - 13, at[0] + 7, at[1] + 4, "none", "white", 0, opacity=0.85)
        fig.text(at, label, "middle", 14)
    # The side 2r, over the top row.
    fig.arrow(P((0.5, rows + 0.12)), P((0, rows + 0.12)), INK, 1.2)
    fig.arrow(P((0.5, rows + 0.12)), P((1, rows + 0.12)), INK, 1.2)
    fig.text(add(P((0.5, rows + 0.12)), (0, -6)), "2~r~", size=13)
    # Cell indices.
    for i in range(cols):
        fig.text(add(P((i + 0.5, 0)), (0, 18)), f"{i}", size=12, fill="#555")
    for j in range(rows):
        fig.text(add(P((0, j + 0.5)), (-10, 4)), f"{j}", "end", size=12, fill="#555")
    fig.text(add(P((cols / 2, 0)), (0, 40)),
             "a point ~p~ is in cell (~i~, ~j~) = (⌊~p~_x / 2~r~⌋, ⌊~p~_y / 2~r~⌋)", size=12,
             fill="#555")
    # The table.
    tx, ty = 596, 82
    for dx, head in ((0, "cell (~i~, ~j~)"), (80, "hash ~h~"), (170, "bucket"),
                     (222, "shared with")):
        fig.text((tx + dx, ty - 28), head, "start", 13)
    for k, (i, j) in enumerate(block):
        h = cell_hash(i, j)
        y = ty + 24 * k
        fig.text((tx, y), f"({i}, {j})", "start", 13, weight="bold")
        fig.text((tx + 80, y), f"{h}", "start", 13)
        fig.text((tx + 170, y), f"{h % TABLE_SIZE}", "start", 13, ORANGE)
        also = [c for c, owner in sharing.items() if owner == (i, j)]
        fig.text((tx + 222, y), ", ".join(f"({a}, {b})" for a, b in also) or "–", "start", 13,
                 BLUE if also else "#555")
    ty += 24 * len(block) + 4
    fig.text((tx, ty), "~h~ = (73856093 ~i~ xor 19349663 ~j~) mod 2^{32}", "start", 12,
             "#555")
    fig.text((tx, ty + 18), f"bucket = ~h~ mod {TABLE_SIZE}", "start", 12, "#555")
    shared = ", ".join(f"({a}, {b})" for a, b in sorted(sharing))
    fig.text((tx, ty + 46), f"the four buckets hold {in_buckets} photons:", "start", 13)
    fig.dot((tx + 6, ty + 64), BLUE, 3)
    fig.text((tx + 18, ty + 68), "in the block, outside the disk", "start", 13)
    fig.circle((tx + 6, ty + 82), 3, BLUE, "white", 1.3)
    fig.text((tx + 18, ty + 86), f"in {shared}, same buckets", "start", 13)
    fig.text((tx + 18, ty + 104), "(both fail the distance test)", "start", 12, "#555")
    fig.dot((tx + 6, ty + 118), RED, 4)
    fig.text((tx + 18, ty + 122), f"{inside} inside the disk: gathered", "start", 13, RED)
    fig.text((tx, ty + 152), "*x* lies in the upper right quarter of", "start", 12, "#555")
    fig.text((tx, ty + 170), "its cell, so the disk can only reach", "start", 12, "#555")
    fig.text((tx, ty + 188), "the cells right of it and above it", "start", 12, "#555")
    return fig.write(name), block, sharing, in_buckets, inside


# --- ch16-sppm-radius.svg --------------------------------------------------------------------


def sppm_radii(alpha, passes, M0=1.0):
    """r_i / r_0 for i = 0 .. passes. Each pass emits as many photons as the last, so the count
    expected in the disk falls with its area: M_i = M0 (r_i / r_0)^2; N_0 = 0."""
    r2, N, out = 1.0, 0.0, [1.0]
    for _ in range(passes):
        M = M0 * r2
        r2 *= (N + alpha * M) / (N + M)
        N += alpha * M
        out.append(math.sqrt(r2))
    return out


def sppm_figure(name):
    f = Figure(600, 380, "SPPM: the gather radius over the passes")
    x0, x1, y0, y1 = 84, 574, 320, 30
    passes = 64

    def page(i, v):
        return (x0 + math.log2(i) / math.log2(passes) * (x1 - x0), y0 - v * (y0 - y1))

    f.rect(x0, y1, x1, y0, GRID, width=1)
    for e in range(7):
        p = page(2**e, 0)
        f.line((p[0], y0), (p[0], y1), GRID, 0.8, dash="3 3")
        f.text((p[0], y0 + 18), f"{2**e}", size=12)
    for v in (0.0, 0.25, 0.5, 0.75, 1.0):
        y = page(1, v)[1]
        f.line((x0, y), (x1, y), GRID, 0.8, dash="3 3")
        f.text((x0 - 8, y + 4), f"{v:g}", anchor="end", size=12)
    f.text(((x0 + x1) / 2, y0 + 42), "pass ~i~ (log scale)")
    f.text((30, (y0 + y1) / 2 + 5), "~r~_i / ~r~_0", anchor="middle")
    curves = {}
    for alpha, label, colour in ((0.5, "0.5", BLUE), (2 / 3, "2/3", RED), (0.9, "0.9", GREEN)):
        radii = sppm_radii(alpha, passes)
        curves[label] = radii
        f.polyline([page(i, radii[i]) for i in range(1, passes + 1)], colour, 2.2)
        f.text(add(page(passes, radii[passes]), (-4, -9)), f"~α~ = {label}", "end", 13, colour)
    # The asymptote for alpha = 2/3: r_i^2 / r_0^2 -> i^(alpha - 1) / Gamma(alpha).
    alpha = 2 / 3
    asym = [(i, math.sqrt(i ** (alpha - 1) / math.gamma(alpha)))
            for i in (2 ** (6 * k / 120) for k in range(121))]
    f.polyline([page(i, v) for i, v in asym if v <= 1.0], RED, 1.5, dash="6 4")
    # Legend.
    lx, ly = x0 + 14, y0 - 66
    f.rect(lx - 8, ly - 18, lx + 320, ly + 52, GRID, "white", 0.8)
    f.line((lx, ly - 4), (lx + 28, ly - 4), DARK, 2.2)
    f.text((lx + 36, ly), "~r~_{i+1}^2 = ~r~_i^2 (~N~_i + ~α~ ~M~_i) / (~N~_i + ~M~_i)", "start",
           13)
    f.text((lx + 36, ly + 20), "~N~_{i+1} = ~N~_i + ~α~ ~M~_i,  ~M~_i ∝ ~r~_i^2", "start", 13)
    f.line((lx, ly + 40), (lx + 28, ly + 40), RED, 1.5, "6 4")
    f.text((lx + 36, ly + 44), "~r~_i^2 / ~r~_0^2 → ~i~^{α−1} / Γ(~α~),  ~α~ = 2/3", "start", 13)
    return f.write(name), curves


if __name__ == "__main__":
    made = []
    name, stored, aimed, inside = two_passes_figure("ch16-two-passes.svg")
    made.append(name)
    name, f_traced, f_closed, crossings = ball_focus_figure("ch16-ball-focus.svg")
    made.append(name)
    made.append(nephroid_figure("ch16-nephroid.svg"))
    name, block, sharing, in_block, gathered = hash_grid_figure("ch16-hash-grid.svg")
    made.append(name)
    name, curves = sppm_figure("ch16-sppm-radius.svg")
    made.append(name)
    print("wrote", ", ".join("docs/figures/" + m for m in made))
    print(f"two passes: {stored} photons stored in pass 1, {aimed} caustic photons from above, "
          f"{inside} inside the gather disk")
    print(f"ball focus: traced (h = 1e-4 R) {f_traced:.6f} R, nR/(2(n-1)) = {f_closed:.6f} R; "
          + ", ".join(f"h = {h:g}R: {x:.4f}R" for h, x in sorted(crossings.items())))
    cusp, nearest, worst = nephroid_check()
    print(f"nephroid: traced cusp ({cusp[0]:.6f}, {cusp[1]:.1e}) R, closed form (0.5, 0) R; "
          f"the drawn rays at +-R/40 cross at {nearest[0]:.6f} R; traced envelope within "
          f"{worst:.1e} R of the analytic curve")
    print(f"hash grid: block {block}, cells sharing its buckets {sharing}, {in_block} photons "
          f"in its buckets, {gathered} inside the disk")
    for label, radii in curves.items():
        alpha = {"0.5": 0.5, "2/3": 2 / 3, "0.9": 0.9}[label]
        asym = math.sqrt(64 ** (alpha - 1) / math.gamma(alpha))
        print(f"sppm alpha = {label}: r_64/r_0 = {radii[64]:.4f}, asymptote {asym:.4f}")
