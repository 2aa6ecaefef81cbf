#!/usr/bin/env python3
"""Chapter 10's figures (SVG, written next to this script): where texture coordinates come from.

    python3 docs/figures/ch10_figures.py

ch10-sphere.svg     the sphere's (u, v): a point p, its longitude phi about +y (from +x towards
                    -z) and its angle theta from the south pole, with the graticule drawn from
                    p(u, v) = (sin theta cos phi, -cos theta, -sin theta sin phi); next to it
                    the texture square with the same lines and the point at (phi/2pi, theta/pi)
ch10-box.svg        the unit cube unfolded: each face's u (red) and v (blue) axes, computed by
                    the face table of src/texture/uv_mapping.cpp, and the cube in 3D with the
                    same arrows, so each face shows its image upright seen from outside
ch10-bilinear.svg   bilinear filtering: four texel centres, the point (x, y) between them and
                    the four weights as the areas of the opposite rectangles

Every point is computed from the page's equations; nothing is random.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, GRID, INK, ORANGE, RED,
                    Figure, Frame2D, Projection)

PI = math.pi


def sphere_point(u, v):
    """The page's parameterisation: phi = 2 pi u about +y from +x towards -z, theta = pi v from
    the south pole."""
    phi, theta = 2 * PI * u, PI * v
    return (math.sin(theta) * math.cos(phi), -math.cos(theta), -math.sin(theta) * math.sin(phi))


def sphere_uv(p):
    """sphereUV of src/texture/uv_mapping.cpp."""
    phi = math.atan2(-p[2], p[0])
    if phi < 0:
        phi += 2 * PI
    return phi / (2 * PI), math.acos(max(-1.0, min(1.0, -p[1]))) / PI


def sphere_figure():
    fig = Figure(760, 350, "The sphere's texture coordinates: u = phi / 2 pi, v = theta / pi")
    proj = Projection((170, 190), 112, azimuth=25, elevation=20)
    toward = (math.cos(math.radians(20)) * math.sin(math.radians(25)), math.sin(math.radians(20)),
              math.cos(math.radians(20)) * math.cos(math.radians(25)))

    def visible(p):
        return sum(a * b for a, b in zip(p, toward)) >= 0

    def curve(points, stroke, width=1.2):
        # Split into front (solid) and back (dashed) runs.
        run, front = [], None
        for p in points:
            f = visible(p)
            if front is not None and f != front:
                fig.polyline([proj(q) for q in run], stroke, width, dash=None if front else "3,3")
                run = run[-1:]
            run.append(p)
            front = f
        fig.polyline([proj(q) for q in run], stroke, width, dash=None if front else "3,3")

    fig.circle(proj((0, 0, 0)), 112, DARK, "none", 1.5)
    # The graticule every 30 degrees, from p(u, v).
    for k in range(12):
        curve([sphere_point(k / 12, j / 60) for j in range(61)], GRID)
    for j in range(1, 6):
        curve([sphere_point(k / 120, j / 6) for k in range(121)], GRID)
    # The seam u = 0 (phi = 0, the +x side) in red, the equator in blue.
    curve([sphere_point(0, j / 60) for j in range(61)], RED, 2)
    # Axes.
    o = proj((0, 0, 0))
    for axis, name in (((1.45, 0, 0), "x"), ((0, 1.4, 0), "y"), ((0, 0, 1.5), "z")):
        fig.arrow(o, proj(axis), INK, 1.3)
        fig.text(proj(tuple(1.1 * c for c in axis)), f"~{name}~")
    # A point p at u = 0.12, v = 0.7, with its angles.
    u, v = 0.12, 0.7
    p = sphere_point(u, v)
    assert abs(sphere_uv(p)[0] - u) < 1e-12 and abs(sphere_uv(p)[1] - v) < 1e-12
    foot = (p[0], 0.0, p[2])
    fig.line(o, proj(p), ORANGE, 2)
    fig.line(proj(p), proj(foot), ORANGE, 1, dash="4,3")
    fig.line(o, proj(foot), ORANGE, 1, dash="4,3")
    # phi: an arc in the equator plane from +x to the foot.
    fig.polyline([proj((0.45 * math.cos(2 * PI * u * t), 0, -0.45 * math.sin(2 * PI * u * t)))
                  for t in [k / 20 for k in range(21)]], ORANGE, 1.5)
    fig.text(proj((0.62, 0, -0.25)), "φ", size=15, fill=ORANGE)
    # theta: an arc from the south pole direction to p, in p's meridian plane.
    fig.polyline([proj(tuple(0.35 * c for c in sphere_point(u, v * t)))
                  for t in [k / 20 for k in range(21)]], BLUE, 1.5)
    fig.text(proj(tuple(0.5 * c for c in sphere_point(u, 0.35))), "θ", size=15, fill=BLUE)
    fig.dot(proj(p), ORANGE, 5)
    fig.text((proj(p)[0] + 12, proj(p)[1] - 6), "*p*", anchor="start")
    fig.text(proj((0, -1.18, 0)), "south pole: θ = 0, v = 0", size=12)

    # The texture square: u across, v up, with the same lines.
    x0, y0, side = 420, 300, 250
    sq = Frame2D((x0, y0), side)
    fig.rect(x0, y0 - side / 2, x0 + side, y0, DARK, FILL_GREY, 1.5)
    for k in range(13):
        fig.line(sq((k / 12, 0)), sq((k / 12, 0.5)), RED if k in (0, 12) else GRID, 1)
    for j in range(7):
        fig.line(sq((0, j / 12)), sq((1, j / 12)), GRID, 1)
    # The image is twice as wide as tall: v spans half the square's side.
    pu, pv = sq((u, v / 2))
    fig.dot((pu, pv), ORANGE, 5)
    fig.text((pu + 10, pv - 8), f"({u}, {v})", anchor="start", size=13)
    fig.text(sq((0.5, -0.09)), "~u~ = φ / 2π", size=14)
    fig.text((x0 - 12, y0 - side / 4), "~v~", anchor="end")
    fig.text((x0 - 12, y0 - side / 4 + 18), "= θ/π", anchor="end", size=13)
    fig.text(sq((0, -0.04)), "0", size=12)
    fig.text(sq((1, -0.04)), "1", size=12)
    fig.text((x0 + side + 8, y0 - side / 2 + 5), "1", anchor="start", size=12)
    fig.text((x0 + side + 8, y0 + 0), "0", anchor="start", size=12)
    fig.text((x0 + side / 2, 140), "the image: u = 0 and u = 1 (red) are one meridian",
             size=13)
    fig.write("ch10-sphere.svg")


# The face table of src/texture/uv_mapping.cpp: (axis, positive) -> (uv(p), dp/du, dp/dv).
def box_face_uv(p, axis, positive):
    if axis == 0:
        return ((1 - p[2] if positive else p[2], p[1]), (0, 0, -1 if positive else 1), (0, 1, 0))
    if axis == 1:
        return ((p[0], 1 - p[2] if positive else p[2]), (1, 0, 0), (0, 0, -1 if positive else 1))
    return ((p[0] if positive else 1 - p[0], p[1]), (1 if positive else -1, 0, 0), (0, 1, 0))


def box_figure():
    fig = Figure(760, 380, "The box's faces: u (red) to the right and v (blue) up, seen from outside")
    # The net: a cross unfolded around the front face +z. Each square shows its face's u and v
    # axes, drawn where the face's own corners land on the net.
    s = 80
    net = {  # (axis, positive) -> page position of the square's lower-left corner
        (2, True): (150, 230), (0, True): (230, 230), (2, False): (310, 230),
        (0, False): (70, 230), (1, True): (150, 150), (1, False): (150, 310)}
    names = {(0, True): "+x", (0, False): "−x", (1, True): "+y (top)", (1, False): "−y (bottom)",
             (2, True): "+z (front)", (2, False): "−z (back)"}
    for (axis, positive), (x, y) in net.items():
        fig.rect(x, y - s, x + s, y, DARK, FILL_GREY, 1.2)
        # Unfolded, each face is seen from outside with its u to the right and v up: the arrows
        # are the uv axes themselves, which the table guarantees.
        fig.arrow((x + 10, y - 10), (x + s - 14, y - 10), RED, 2)
        fig.arrow((x + 10, y - 10), (x + 10, y - s + 14), BLUE, 2)
        fig.text((x + s / 2 + 6, y - s / 2 + 4), names[(axis, positive)], size=12)
    fig.text((150, 355), "the net (each face seen from outside)", anchor="start", size=13)

    # The cube in 3D: the three visible faces' u and v axes from the table, starting at each
    # face's (u, v) = (0.15, 0.15) point, scaled by 0.6.
    proj = Projection((590, 215), 130, azimuth=35, elevation=28)
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    edges = [(a, b) for a in corners for b in corners
             if a < b and sum(abs(i - j) for i, j in zip(a, b)) == 1]
    for a, b in edges:
        hidden = a[0] == 0 and b[0] == 0 or a[1] == 0 and b[1] == 0 or a[2] == 0 and b[2] == 0
        fig.line(proj(a), proj(b), GRID if hidden else DARK, 1.2, dash="4,3" if hidden else None)
    for axis, positive in ((0, True), (1, True), (2, True)):
        # Find the face point whose (u, v) is (0.15, 0.15) by stepping along dp/du and dp/dv
        # from the point with (u, v) = (0, 0).
        origin = [0.5, 0.5, 0.5]
        origin[axis] = 1.0
        uv, dpdu, dpdv = box_face_uv(origin, axis, positive)
        start = tuple(o - uv[0] * a - uv[1] * b + 0.15 * a + 0.15 * b
                      for o, a, b in zip(origin, dpdu, dpdv))
        assert all(abs(c - d) < 1e-12 for c, d in zip(box_face_uv(start, axis, positive)[0],
                                                      (0.15, 0.15)))
        fig.arrow(proj(start), proj(tuple(c + 0.6 * d for c, d in zip(start, dpdu))), RED, 2)
        fig.arrow(proj(start), proj(tuple(c + 0.6 * d for c, d in zip(start, dpdv))), BLUE, 2)
    fig.text(proj((1.15, 0.5, 0.5)), "+x", size=12)
    fig.text(proj((0.5, 1.22, 0.5)), "+y", size=12)
    fig.text(proj((0.5, 0.5, 1.2)), "+z", size=12)
    fig.text((590, 355), "dp/du × dp/dv points out of every face", size=13)
    fig.write("ch10-box.svg")


def bilinear_figure():
    fig = Figure(560, 330, "Bilinear filtering: the weights are the areas of the opposite rectangles")
    frame = Frame2D((110, 280), 200)
    # Texel centres (x0, y0) .. (x0 + 1, y0 + 1), the point at fractions fx, fy.
    fx, fy = 0.35, 0.6
    corners = {(0, 0): "c_{00}", (1, 0): "c_{10}", (0, 1): "c_{01}", (1, 1): "c_{11}"}
    weights = {(0, 0): (1 - fx) * (1 - fy), (1, 0): fx * (1 - fy), (0, 1): (1 - fx) * fy,
               (1, 1): fx * fy}
    fills = {(0, 0): FILL_BLUE, (1, 1): FILL_ORANGE, (1, 0): FILL_GREY, (0, 1): "#e6f2e6"}
    for (i, j), fill in fills.items():
        # The rectangle opposite corner (i, j) spans from the point to the far corner.
        a = frame((fx, fy))
        b = frame((1 - i, 1 - j))
        fig.rect(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]), GRID, fill, 1)
        mid = frame(((fx + 1 - i) / 2, (fy + 1 - j) / 2))
        fig.text((mid[0], mid[1] + 5), f"{weights[(i, j)]:.2f}", size=13)
    assert abs(sum(weights.values()) - 1) < 1e-12
    for (i, j), name in corners.items():
        c = frame((i, j))
        fig.dot(c, INK, 5)
        fig.text((c[0] + (-14 if i == 0 else 14), c[1] + (20 if j == 0 else -10)), name,
                 anchor="end" if i == 0 else "start")
    p = frame((fx, fy))
    fig.dot(p, RED, 5)
    fig.text((p[0] + 8, p[1] - 8), "(~x~, ~y~)", anchor="start", fill=RED)
    fig.line(frame((0, -0.12)), frame((fx, -0.12)), DARK, 1)
    fig.text(frame((fx / 2, -0.2)), f"~f~_x = {fx}", size=13)
    fig.line(frame((-0.12, 0)), frame((-0.12, fy)), DARK, 1)
    fig.text(frame((-0.3, fy / 2)), f"~f~_y = {fy}", size=13)
    fig.text((370, 70), "value = Σ weight · texel", anchor="start", size=14)
    fig.text((370, 96), "weight of a corner = area", anchor="start", size=13)
    fig.text((370, 116), "of the rectangle opposite it", anchor="start", size=13)
    fig.text((370, 150), "(1−~f~_x)(1−~f~_y) ~c~_{00} + ~f~_x(1−~f~_y) ~c~_{10}", anchor="start", size=12)
    fig.text((370, 170), "+ (1−~f~_x)~f~_y ~c~_{01} + ~f~_x~f~_y ~c~_{11}", anchor="start", size=12)
    fig.write("ch10-bilinear.svg")


if __name__ == "__main__":
    sphere_figure()
    box_figure()
    bilinear_figure()
