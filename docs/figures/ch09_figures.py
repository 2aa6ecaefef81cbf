#!/usr/bin/env python3
"""Chapter 9's figures (SVG, written next to this script): smooth normals on flat triangles.

    python3 docs/figures/ch09_figures.py

ch09-interpolation.svg  a cross-section of a low-poly sphere: the corner normals and the normals
                        interpolated across one facet, against the flat facet's own normal
ch09-cube-corner.svg    the cube corner (1,0,0) split unevenly into triangles: the angles each
                        face contributes (90° per face however it is split) and the
                        angle-weighted normal
ch09-mirror.svg         a shading normal whose mirror ray dives under the surface, and the
                        adapted normal (the half vector of the view and the lifted mirror ray)
ch09-terminator.svg     the shadow terminator in cross-section: a lit point's shadow ray from
                        the flat facet runs through the inside; from the Phong-tessellated
                        point above it, it passes over the facet's edge

Every point is computed from the page's equations (the cross-sections are the 2D case: a
"triangle" is a segment, its barycentrics (1 - t, t)).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svgfig import (BLUE, DARK, FILL_GREY, GREEN, GRID, ORANGE, RED, Figure, Frame2D,  # noqa: E402
                    Projection, add, dot, mul, normalize, sub)
from svgfig import cross as cross_product  # noqa: E402


def unit(angle):
    return (math.cos(angle), math.sin(angle))


def lerp_normal(n0, n1, t):
    """The page's n_s = ((1 - t) n0 + t n1) / |...| (barycentrics (1 - t, t))."""
    return normalize(add(mul(n0, 1 - t), mul(n1, t)))


def polygon_arc(sides, a0, a1):
    """Vertices of a regular polygon inscribed in the unit circle, between angles a0 and a1."""
    step = 2 * math.pi / sides
    k0, k1 = math.ceil(a0 / step - 1e-9), math.floor(a1 / step + 1e-9)
    return [unit(k * step) for k in range(k0, k1 + 1)]


def interpolation():
    f = Figure(560, 380, "Corner normals interpolated across a facet")
    fr = Frame2D((280, 365), 210)
    # The true circle (dashed) and the 8-sided polygon over the upper half.
    f.polyline([fr(unit(math.pi * k / 90)) for k in range(0, 91)], GRID, 1.2, dash="5,4")
    verts = polygon_arc(8, 0, math.pi)
    f.polyline([fr(v) for v in verts], DARK, 2)
    for v in verts:
        f.dot(fr(v), DARK, 3.5)
    # One facet: between the vertices at 45° and 90°.
    p0, p1 = unit(math.pi / 4), unit(math.pi / 2)
    n0, n1 = p0, p1  # exact corner normals of the unit circle
    ng = normalize(add(p0, p1))
    L = 0.32
    f.arrow(fr(p0), fr(add(p0, mul(n0, L))), BLUE, 2.2)
    f.arrow(fr(p1), fr(add(p1, mul(n1, L))), BLUE, 2.2)
    f.text(add(fr(add(p0, mul(n0, L))), (14, 4)), "*n*_0", "start", fill=BLUE)
    f.text(add(fr(add(p1, mul(n1, L))), (-10, 10)), "*n*_1", "end", fill=BLUE)
    for t in (0.25, 0.5, 0.75):
        p = add(mul(p0, 1 - t), mul(p1, t))
        ns = lerp_normal(n0, n1, t)
        f.arrow(fr(p), fr(add(p, mul(ns, L))), RED, 1.8)
        f.dot(fr(p), RED, 3)
    pm = add(mul(p0, 0.5), mul(p1, 0.5))
    f.arrow(fr(pm), fr(add(pm, mul(ng, 0.5 * L))), GRID, 1.6, dash="4,3")
    f.text(add(fr(add(pm, mul(lerp_normal(n0, n1, 0.5), L))), (4, -8)), "*n*_s", "start",
           fill=RED)
    f.text(add(fr(add(pm, mul(ng, 0.5 * L))), (24, 14)), "*n*_g", "start", fill=GRID)
    f.text((40, 30), "corner normals (blue), interpolated normals (red),", "start", 13)
    f.text((40, 48), "the facet's own normal (grey): the dashed circle is the surface", "start", 13)
    return f.write("ch09-interpolation.svg")


def cube_triangles():
    """The triangles of scenes/assets/cube.obj (the file the chapter's test reads)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "assets",
                        "cube.obj")
    vs, tris = [], []
    with open(path) as obj:
        for line in obj:
            w = line.split()
            if w and w[0] == "v":
                vs.append(tuple(float(x) for x in w[1:4]))
            elif w and w[0] == "f":
                tris.append([vs[int(x) - 1] for x in w[1:4]])
    return tris


def cube_corner():
    f = Figure(520, 310, "Angle-weighted normal at a cube corner")
    corner = (1.0, 0.0, 0.0)
    view = Projection((260, 160), 160, azimuth=160, elevation=-30)

    def pr(p):
        return view(sub(p, corner))  # the corner at the page point (260, 160)

    fills = {(0, 0, -1): "#eef0f3", (1, 0, 0): "#fdf0d9", (0, -1, 0): "#e3ebf8"}
    total = (0.0, 0.0, 0.0)
    for tri in cube_triangles():
        if corner not in tri:
            continue
        # Put the corner first, keeping the winding.
        k = tri.index(corner)
        tri = tri[k:] + tri[:k]
        n = normalize(cross_product(sub(tri[1], tri[0]), sub(tri[2], tri[0])))
        f.polygon([pr(p) for p in tri], fills[tuple(round(c) for c in n)], DARK, 1.2)
        a, b = normalize(sub(tri[1], tri[0])), normalize(sub(tri[2], tri[0]))
        alpha = math.acos(max(-1.0, min(1.0, dot(a, b))))
        total = add(total, mul(n, alpha))
        mid = normalize(add(a, b))
        f.text(add(pr(add(corner, mul(mid, 0.3))), (0, 5)), f"{round(math.degrees(alpha))}°",
               size=12)
    n_v = normalize(total)
    f.arrow(pr(corner), pr(add(corner, mul(n_v, 1.0))), RED, 2.4)
    f.text(add(pr(add(corner, mul(n_v, 1.0))), (-6, 34)), "*n*_v = (1, −1, −1)/√3", "middle",
           fill=RED)
    f.dot(pr(corner), DARK, 4)
    f.text((20, 282), "each face meets the corner (1, 0, 0) at 90° in all, whether one or two",
           "start", 13)
    f.text((20, 300), "of its triangles touch it: the angle weights are equal, the normal "
           "symmetric", "start", 13)
    return f.write("ch09-cube-corner.svg")


def mirror():
    f = Figure(600, 320, "Adapting the shading normal so the mirror ray stays above the surface")
    fr = Frame2D((300, 190), 150)
    eps = math.radians(6)  # drawn exaggerated; the code uses 1e-3 rad
    f.line(fr((-1.7, 0)), fr((1.7, 0)), DARK, 2.5)
    f.polygon([fr((-1.7, 0)), fr((1.7, 0)), fr((1.7, -0.6)), fr((-1.7, -0.6))], FILL_GREY)
    ng = (0.0, 1.0)
    wo = normalize((-0.9, 0.42))  # towards the viewer, grazing from the left
    ns = normalize((0.45, 1.0))   # leans away from the viewer
    r = sub(mul(ns, 2 * dot(wo, ns)), wo)
    along = normalize(sub(r, mul(ng, dot(r, ng))))
    lifted = add(mul(along, math.cos(eps)), mul(ng, math.sin(eps)))
    ns2 = normalize(add(wo, lifted))
    o = fr((0, 0))
    f.arrow(o, fr(mul(ng, 0.9)), GRID, 2, dash="4,3")
    f.text(add(fr(mul(ng, 0.9)), (-10, 0)), "*n*_g", "end", fill=GRID)
    f.arrow(o, fr(mul(wo, 1.2)), DARK, 2)
    f.text(add(fr(mul(wo, 1.2)), (-6, -6)), "ω_o", "end")
    f.arrow(o, fr(mul(ns, 0.9)), BLUE, 2)
    f.text(add(fr(mul(ns, 0.9)), (6, -4)), "*n*_s", "start", fill=BLUE)
    f.arrow(o, fr(mul(r, 1.2)), RED, 2, dash="6,4")
    f.text(add(fr(mul(r, 1.2)), (-14, 6)), "*r*: under the surface", "end", fill=RED)
    f.arrow(o, fr(mul(lifted, 1.5)), GREEN, 2.2)
    f.text(add(fr(mul(lifted, 1.5)), (0, -8)), "*r*′ at elevation ε", "end", fill=GREEN)
    f.arrow(o, fr(mul(ns2, 0.9)), GREEN, 2.2)
    f.text(add(fr(mul(ns2, 0.9)), (-6, -6)), "*n*_s′", "end", fill=GREEN)
    f.text((20, 308), "*n*_s′ = (ω_o + *r*′)/|ω_o + *r*′| mirrors ω_o into *r*′ (ε drawn at 6°; the code "
           "uses 0.06°)", "start", 13)
    return f.write("ch09-mirror.svg")


def terminator():
    f = Figure(720, 360, "The shadow terminator in cross-section")
    fr = Frame2D((140, 330), 300)
    sides = 10
    step = 2 * math.pi / sides
    # The true circle and the polygon, around the facet between 36° and 72°.
    f.polyline([fr(unit(math.radians(a))) for a in range(0, 121)], GRID, 1.2, dash="5,4")
    verts = [unit(k * step) for k in range(0, 4)]
    f.polygon([fr((0, 0))] + [fr(v) for v in verts], FILL_GREY, DARK, 2)
    p0, p1 = verts[1], verts[2]
    n0, n1 = p0, p1
    ng = normalize(add(p0, p1))
    t = 0.3
    p = add(mul(p0, 1 - t), mul(p1, t))
    ns = lerp_normal(n0, n1, t)
    # The light: slightly above the shading normal's horizon, below the facet's plane.
    tangent = (-ns[1], ns[0])
    l = normalize(add(mul(tangent, -1.0), mul(ns, 0.12)))
    assert dot(l, ns) > 0 and dot(l, ng) < 0
    # The page's p' = sum b_k q_k, q_k = p projected up onto corner k's tangent line.
    q = []
    for v, n in ((p0, n0), (p1, n1)):
        h = dot(sub(p, v), n)
        q.append(sub(p, mul(n, h)) if h < 0 else p)
    p_lift = add(mul(q[0], 1 - t), mul(q[1], t))
    # The flat shadow ray dips under the facet's plane, so it runs inside the polygon and
    # meets the next facet (from verts[0] to verts[1]) from within: blocked.
    a, b = verts[0], verts[1]
    e = sub(b, a)
    det = -l[0] * e[1] + l[1] * e[0]
    s_hit = (-(a[0] - p[0]) * e[1] + (a[1] - p[1]) * e[0]) / det
    exit_point = add(p, mul(l, s_hit))
    f.line(fr(p), fr(exit_point), RED, 2, dash="6,4")
    x = fr(exit_point)
    f.line((x[0] - 6, x[1] - 6), (x[0] + 6, x[1] + 6), RED, 2.5)
    f.line((x[0] - 6, x[1] + 6), (x[0] + 6, x[1] - 6), RED, 2.5)
    f.text(add(x, (12, 5)), "from *p*: blocked by the next facet, from inside", "start", 13,
           fill=RED)
    end2 = add(p_lift, mul(l, 0.75))
    f.arrow(fr(p_lift), fr(end2), GREEN, 2.2)
    f.text(add(fr(end2), (6, -8)), "from *p*′: on to the light", "start", 13, fill=GREEN)
    f.arrow(fr(p), fr(add(p, mul(ns, 0.25))), BLUE, 2)
    f.text(add(fr(add(p, mul(ns, 0.25))), (6, -4)), "*n*_s", "start", fill=BLUE)
    for (v, n), qk in zip(((p0, n0), (p1, n1)), q):
        d = (-n[1], n[0])
        f.line(fr(add(v, mul(d, -0.28))), fr(add(v, mul(d, 0.28))), ORANGE, 1.2, dash="3,3")
        f.line(fr(p), fr(qk), ORANGE, 1.2)
        f.dot(fr(qk), ORANGE, 3)
    f.dot(fr(p), RED, 4)
    f.text(add(fr(p), (-10, 6)), "*p*", "end", fill=RED)
    f.dot(fr(p_lift), GREEN, 4)
    f.text(add(fr(p_lift), (-10, -8)), "*p*′", "end", fill=GREEN)
    f.text((330, 326), "orange: the corners' tangent lines, and *p* projected", "start", 13)
    f.text((330, 344), "onto them; *p*′ blends the projections by *p*'s barycentrics", "start",
           13)
    return f.write("ch09-terminator.svg")


if __name__ == "__main__":
    for draw in (interpolation, cube_corner, mirror, terminator):
        print(draw())
