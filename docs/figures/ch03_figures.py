#!/usr/bin/env python3
"""Chapter 3's figures (SVG, written next to this script): the binned SAH split of
chapters/03-bvh.md, computed as src/bvh/bvh.cpp computes it, the watertight test's edge
functions, and the wide BVH of the "going further" section.

    python3 docs/figures/ch03_figures.py

ch03-watertight.svg   two triangles sharing an edge, moved into the ray's frame by the page's
               permutation and shear (the ray is the origin, seen head-on), and the three edge
               functions U, V, W as the signed areas the origin makes with each edge; left, a
               ray through one triangle, right, a ray through a point of the shared edge, where
               the neighbour's function for that edge is exactly -U.
ch03-wide.svg  twelve triangles built into a binary tree by the binned SAH (both axes, one
               triangle per leaf), then collapsed as collapseToWide() in src/bvh/bvh.cpp does:
               from the root's two children, the interior child of largest area is opened until
               there are four. Left, the four child boxes of the root's wide node and a ray, with
               each child's slab interval [t0, t1] as intersectChildren4() computes it (tMax
               infinite) and the order in which the traversal visits the children it enters;
               right, the binary tree with the binary nodes each wide node absorbs; below, the
               wide node's 128 bytes (WideNode: lo[3][4], hi[3][4], child[4], count[4]), lane c
               holding child c, so that one load fetches one plane of all four children.
ch03-sah.svg   eight triangles in a node N; their centroids (box centres) binned along x into
               B = min(16, 8) = 8 bins; every candidate plane between bins priced by
               C_split = C_trav + (A(L)|L| + A(R)|R|) / A(N), the cheapest one drawn with its
               two child boxes; beside it the cost of every candidate against C_leaf = |N|.

The figure is flat, so a box's "surface area" is its perimeter: in the plane, the chance that a
random line meeting N also meets a convex C inside it is perimeter(C) / perimeter(N) (Cauchy and
Crofton again). A is half of it, as the code's halfArea() is half the surface area. Only the x
axis is drawn; the code prices the y and z planes the same way and keeps the cheapest of all.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, FILL_RED, GREEN, GRID, INK,
                    ORANGE, RED, Figure, Frame2D, add)

TRIANGLES = [
    [(0.5, 0.8), (2.0, 1.2), (1.0, 2.6)],
    [(1.6, 3.0), (3.0, 2.4), (2.4, 4.2)],
    [(0.8, 4.0), (2.0, 4.6), (1.2, 5.4)],
    [(2.8, 0.6), (4.0, 1.4), (3.2, 2.0)],
    [(3.4, 3.4), (4.6, 3.8), (3.6, 5.0)],
    [(5.0, 0.4), (6.0, 0.7), (5.4, 1.3)],
    [(6.4, 1.0), (8.6, 1.8), (7.0, 3.4)],
    [(7.2, 3.6), (9.4, 3.0), (8.8, 5.2)],
]
C_TRAV, C_ISECT = 1.0, 1.0


def bounds(points):
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return (min(xs), min(ys)), (max(xs), max(ys))


def half_area(box):
    """Half the perimeter: the flat figure's stand-in for AABB::halfArea()."""
    (x0, y0), (x1, y1) = box
    return (x1 - x0) + (y1 - y0)


def binned_sah_x(triangles):
    """findSplit on the x axis: bins by centroid, sweeps, the cost of every plane."""
    boxes = [bounds(t) for t in triangles]
    centroids = [((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2) for lo, hi in boxes]
    n = len(triangles)
    n_bins = max(2, min(16, n))
    c_lo, c_hi = min(c[0] for c in centroids), max(c[0] for c in centroids)
    scale = n_bins / (c_hi - c_lo)
    bins = [min(n_bins - 1, int((c[0] - c_lo) * scale)) for c in centroids]
    node = bounds([p for t in triangles for p in t])
    costs = []
    for b in range(1, n_bins):
        left = [i for i in range(n) if bins[i] < b]
        right = [i for i in range(n) if bins[i] >= b]
        if not left or not right:
            costs.append(None)
            continue
        box_l = bounds([p for i in left for p in triangles[i]])
        box_r = bounds([p for i in right for p in triangles[i]])
        cost = C_TRAV + (half_area(box_l) * len(left) * C_ISECT
                         + half_area(box_r) * len(right) * C_ISECT) / half_area(node)
        costs.append((cost, b, left, right, box_l, box_r))
    return node, centroids, (c_lo, c_hi), n_bins, costs


def sah_figure(name):
    node, centroids, (c_lo, c_hi), n_bins, costs = binned_sah_x(TRIANGLES)
    best = min((c for c in costs if c), key=lambda c: c[0])
    cost, b_best, left, right, box_l, box_r = best
    fig = Figure(900, 430, "the binned SAH: one split candidate and its cost")
    F = Frame2D((40, 330), 52)
    pad = 0.12
    # Child boxes first (filled), then the node, then the triangles on top.
    fig.rect(*F((box_l[0][0] - pad / 2, box_l[1][1] + pad / 2)),
             *F((box_l[1][0] + pad / 2, box_l[0][1] - pad / 2)), BLUE, FILL_BLUE, 2)
    fig.rect(*F((box_r[0][0] - pad / 2, box_r[1][1] + pad / 2)),
             *F((box_r[1][0] + pad / 2, box_r[0][1] - pad / 2)), ORANGE, FILL_ORANGE, 2,
             opacity=0.85)
    fig.rect(*F((node[0][0] - pad, node[1][1] + pad)), *F((node[1][0] + pad, node[0][1] - pad)),
             DARK, "none", 2.5)
    for i, tri in enumerate(TRIANGLES):
        colour = BLUE if i in left else ORANGE
        fig.polygon([F(p) for p in tri], "white", colour, 1.8)
        fig.polygon([F(p) for p in tri], colour, "none", opacity=0.25)
        cx, cy = F(centroids[i])
        fig.line((cx - 4, cy - 4), (cx + 4, cy + 4), INK, 1.5)
        fig.line((cx - 4, cy + 4), (cx + 4, cy - 4), INK, 1.5)
    # The bins along x over the centroid extent, under the node.
    y_bins = node[0][1] - 0.55
    width = (c_hi - c_lo) / n_bins
    for k in range(n_bins + 1):
        x = c_lo + k * width
        fig.line(F((x, y_bins - 0.12)), F((x, y_bins + 0.12)), DARK, 1.2)
        if 0 < k < n_bins:
            plane_colour, plane_width = (RED, 2.5) if k == b_best else (GRID, 1)
            fig.line(F((x, y_bins + 0.12)), F((x, node[1][1] + pad + 0.25)), plane_colour,
                     plane_width, "6 4")
    fig.line(F((c_lo, y_bins)), F((c_hi, y_bins)), DARK, 1.2)
    for i, c in enumerate(centroids):
        fig.dot(F((c[0], y_bins)), BLUE if i in left else ORANGE, 3.5)
    fig.text(add(F((c_lo, y_bins)), (0, 22)), "~c~_{lo}", size=12)
    fig.text(add(F((c_hi, y_bins)), (0, 22)), "~c~_{hi}", size=12)
    fig.text(add(F(((c_lo + c_hi) / 2, y_bins)), (0, 22)),
             f"~B~ = {n_bins} bins of the centroids' ~x~", size=12)
    x_best = c_lo + b_best * width
    fig.text(add(F((x_best, node[1][1] + pad + 0.25)), (0, -6)), "split", size=12, fill=RED)
    fig.text(add(F((node[0][0] - pad, node[1][1] + pad)), (0, -8)), "~N~", "start", weight="bold")
    fig.text(add(F((box_l[0][0], box_l[1][1] + pad / 2)), (18, 14)), "~L~", "start",
             fill=BLUE, weight="bold")
    fig.text(add(F((box_r[1][0], box_r[1][1] + pad / 2)), (-8, 16)), "~R~", "end",
             fill=ORANGE, weight="bold")

    # The sums, with the numbers of this node.
    a_n, a_l, a_r = half_area(node), half_area(box_l), half_area(box_r)
    tx, ty = 575, 40
    lines = [
        (f"~A~(~N~) = {a_n:.2f},  |~N~| = {len(TRIANGLES)}", INK),
        (f"~A~(~L~) = {a_l:.2f},  |~L~| = {len(left)}", BLUE),
        (f"~A~(~R~) = {a_r:.2f},  |~R~| = {len(right)}", ORANGE),
        ("~C~_{split} = ~C~_{trav} + (~A~(~L~)|~L~| + ~A~(~R~)|~R~|) / ~A~(~N~)", INK),
        (f"= 1 + ({a_l:.2f}·{len(left)} + {a_r:.2f}·{len(right)}) / {a_n:.2f} = {cost:.2f}", RED),
        (f"~C~_{{leaf}} = |~N~| = {len(TRIANGLES)}: split", INK),
    ]
    for k, (s, colour) in enumerate(lines):
        fig.text((tx, ty + 21 * k), s, "start", 13, colour)

    # Every candidate's cost, the leaf cost as a line.
    G = Frame2D((610, 390), 1)
    bar_w, y_unit = 34, 20.0
    y_top = 9
    fig.line(G((-8, 0)), G((bar_w * (n_bins - 1) + 8, 0)), DARK, 1)
    fig.line(G((-8, 0)), G((-8, y_unit * y_top)), DARK, 1)
    for v in range(0, y_top + 1, 2):
        fig.line(G((-12, y_unit * v)), G((-8, y_unit * v)), DARK, 1)
        fig.text(add(G((-14, y_unit * v)), (0, 4)), str(v), "end", 11)
    for k, c in enumerate(costs):
        x = bar_w * k
        if c:
            fill = RED if c[1] == b_best else FILL_GREY
            fig.rect(*G((x + 4, y_unit * c[0])), *G((x + bar_w - 4, 0)), DARK, fill, 1)
            fig.text(add(G((x + bar_w / 2, y_unit * c[0])), (0, -4)), f"{c[0]:.1f}", size=10)
        fig.text(add(G((x + bar_w / 2, 0)), (0, 14)), str(k + 1), size=11)
    leaf = len(TRIANGLES) * C_ISECT
    fig.line(G((-8, y_unit * leaf)), G((bar_w * (n_bins - 1) + 8, y_unit * leaf)), BLUE, 1.5,
             "5 3")
    fig.text(add(G((bar_w * (n_bins - 1) + 8, y_unit * leaf)), (-2, -5)), "~C~_{leaf}", "end",
             12, BLUE)
    fig.text((G((bar_w * (n_bins - 1) / 2, 0))[0], 422), "~C~_{split} of the plane before bin ~b~",
             size=12)
    return fig.write(name)


def to_ray_space(o, d, points):
    """The page's steps 1 and 2: choose the axes, then translate by o and shear every vertex so
    that the ray becomes the +z axis. Returns the (x, y) of each vertex in that frame."""
    kz = max(range(3), key=lambda i: abs(d[i]))
    kx, ky = (kz + 1) % 3, (kz + 2) % 3
    if d[kz] < 0:
        kx, ky = ky, kx
    sx, sy = d[kx] / d[kz], d[ky] / d[kz]
    out = []
    for p in points:
        a = [p[i] - o[i] for i in range(3)]
        out.append((a[kx] - sx * a[kz], a[ky] - sy * a[kz]))
    return out


def edge_functions(A, B, C):
    """Step 3: U for edge (p1, p2), V for (p2, p0), W for (p0, p1)."""
    U = C[0] * B[1] - C[1] * B[0]
    V = A[0] * C[1] - A[1] * C[0]
    W = B[0] * A[1] - B[1] * A[0]
    return U, V, W


def watertight_figure(name):
    # Two triangles sharing the edge (p1, p2), and two rays: one through the first triangle,
    # one exactly through a point of the shared edge.
    p0, p1, p2, p3 = (0.0, 0.0, 0.0), (2.0, 0.4, 0.3), (0.5, 1.8, -0.2), (2.4, 2.2, 0.1)
    d = (0.1, 0.05, -1.0)
    on_edge = tuple(0.45 * a + 0.55 * b for a, b in zip(p1, p2))
    rays = [("a ray through triangle 0", (0.9, 0.75, 3.0)),
            ("a ray through a point of the shared edge",
             tuple(on_edge[i] - 3.0 * d[i] for i in range(3)))]
    fig = Figure(900, 395, "the watertight test in ray space: edge functions U, V, W")
    for k, (title, o) in enumerate(rays):
        A, B, C, D = to_ray_space(o, d, [p0, p1, p2, p3])
        U, V, W = edge_functions(A, B, C)
        # The neighbour (p1, p3, p2): its V is the shared edge's function, from the same
        # products in the other order.
        U_n, V_n, W_n = edge_functions(B, D, C)
        assert V_n == -U
        F = Frame2D((450 * k + 190, 200), 105)
        origin = (0.0, 0.0)
        fig.polygon([F(A), F(B), F(C)], "#f4f6f9", DARK, 2)
        fig.polygon([F(B), F(D), F(C)], "#f4f6f9", DARK, 2)
        # The three signed areas with the ray: shaded when positive (blue) or negative (red).
        for (P, Q), value, label in (((B, C), U, "~U~"), ((C, A), V, "~V~"),
                                      ((A, B), W, "~W~")):
            colour = BLUE if value > 0 else RED if value < 0 else DARK
            fig.polygon([F(origin), F(P), F(Q)], colour, colour, 1, opacity=0.18)
            if label == "~U~":  # a thin sliver: label it beside the shared edge, outside
                mid = ((P[0] + Q[0]) / 2 + 0.28, (P[1] + Q[1]) / 2 + 0.22)
            else:
                mid = ((P[0] + Q[0] + origin[0]) / 3, (P[1] + Q[1] + origin[1]) / 3)
            fig.text(add(F(mid), (0, 5)), f"{label} = {value:.3f}".replace("-", "−"), size=12,
                     fill=colour)
        for P, s in ((A, "*p*_0"), (B, "*p*_1"), (C, "*p*_2"), (D, "*p*_3")):
            fig.dot(F(P), INK, 3.5)
            off = (-8, 4) if P[0] < 0.3 else (8, 4)
            fig.text(add(F(P), off), s, "end" if P[0] < 0.3 else "start", 13)
        cx, cy = F(origin)
        fig.circle((cx, cy), 6, RED, "white", 2)
        fig.dot((cx, cy), RED, 2)
        fig.text((cx + 10, cy + 18), "ray", "start", 12, RED)
        fig.text((450 * k + 225, 24), title, weight="bold")
        hits = [all(x >= 0 for x in e) or all(x <= 0 for x in e)
                for e in ((U, V, W), (U_n, V_n, W_n))]
        claim = {(True, True): "both claim it", (True, False): "triangle 0 claims it",
                 (False, True): "the neighbour claims it", (False, False): "neither (a crack)"}
        fig.text((450 * k + 225, 358),
                 f"the neighbour's ~V~ for the same edge is −~U~ = {V_n:.3g}".replace("-", "−"),
                 size=12, fill="#555")
        fig.text((450 * k + 225, 380), f"{claim[tuple(hits)]}", size=13, weight="bold")
    return fig.write(name)


# The wide BVH figure: a small binary SAH tree, collapsed into four-wide nodes.

WIDE_TRIANGLES = [
    [(0.3, 0.4), (1.5, 0.6), (0.7, 1.6)],
    [(1.2, 1.5), (2.4, 1.2), (1.9, 2.5)],
    [(0.4, 2.6), (1.4, 2.9), (0.6, 3.8)],
    [(1.6, 3.4), (2.7, 3.1), (2.2, 4.3)],
    [(3.4, 0.3), (4.6, 0.7), (3.9, 1.5)],
    [(4.2, 1.6), (5.3, 1.3), (5.0, 2.4)],
    [(5.8, 0.4), (7.0, 0.9), (6.2, 1.7)],
    [(6.6, 1.8), (7.9, 1.5), (7.4, 2.8)],
    [(4.0, 3.6), (5.1, 3.3), (4.6, 4.5)],
    [(8.2, 0.5), (9.5, 0.8), (8.8, 1.9)],
    [(8.6, 2.6), (9.7, 2.3), (9.3, 3.6)],
    [(7.0, 3.7), (8.3, 3.5), (7.6, 4.6)],
]
CHILD_COLOURS = [BLUE, ORANGE, GREEN, RED]
BAND = "#e6e9ee"  # the grey band around the binary nodes one wide node absorbs


def build_binary(prims, nodes):
    """The binned SAH build of src/bvh/bvh.cpp in the plane, one triangle per leaf: append
    the subtree over prims to nodes (first child right after its parent) and return its index."""
    index = len(nodes)
    box = bounds([p for i in prims for p in WIDE_TRIANGLES[i]])
    nodes.append({"box": box, "prims": prims, "kids": None})
    if len(prims) == 1:
        return index
    cents = {i: tuple((a + b) / 2 for a, b in zip(*bounds(WIDE_TRIANGLES[i]))) for i in prims}
    n_bins = max(2, min(16, len(prims)))
    best = None
    for axis in range(2):
        lo, hi = min(c[axis] for c in cents.values()), max(c[axis] for c in cents.values())
        if hi == lo:
            continue
        bin_of = {i: min(n_bins - 1, int((cents[i][axis] - lo) * n_bins / (hi - lo)))
                  for i in prims}
        for b in range(1, n_bins):
            left = [i for i in prims if bin_of[i] < b]
            right = [i for i in prims if bin_of[i] >= b]
            if not left or not right:
                continue
            cost = C_TRAV + sum(
                half_area(bounds([p for i in side for p in WIDE_TRIANGLES[i]])) * len(side)
                for side in (left, right)) / half_area(box)
            if best is None or cost < best[0]:
                best = (cost, left, right)
    _, left, right = best
    build_binary(left, nodes)
    second = build_binary(right, nodes)
    nodes[index]["kids"] = (index + 1, second)
    return index


def collapse(nodes, i, wide):
    """collapseNode: the binary nodes wide node len(wide) absorbs, and its (up to) four
    children, opening the interior child of largest area until there are four."""
    kids = list(nodes[i]["kids"])
    absorbed = [i]
    while len(kids) < 4:
        interior = [k for k in range(len(kids)) if nodes[kids[k]]["kids"]]
        if not interior:
            break
        open_ = max(interior, key=lambda k: half_area(nodes[kids[k]]["box"]))
        opened = kids[open_]
        absorbed.append(opened)
        kids[open_:open_ + 1] = list(nodes[opened]["kids"])
    me = {"binary": i, "absorbed": absorbed, "kids": kids}
    wide.append(me)
    for k in kids:
        if nodes[k]["kids"]:
            collapse(nodes, k, wide)
    return me


def slab_2d(o, d, box):
    """intersectChildren4 for one lane, in the plane, tMax infinite: [t0, t1], a hit when
    t0 <= t1."""
    t0, t1 = 0.0, math.inf
    for axis in range(2):
        near, far = (box[0][axis], box[1][axis]) if d[axis] >= 0 else (box[1][axis],
                                                                        box[0][axis])
        t0 = max(t0, (near - o[axis]) / d[axis])
        t1 = min(t1, (far - o[axis]) / d[axis])
    return t0, t1


def rounded_group(fig, points, edges, radius):
    """A light band around a group of tree nodes: thick round-capped strokes along its edges."""
    for p, q in edges:
        fig.add(f'<line x1="{p[0]:.2f}" y1="{p[1]:.2f}" x2="{q[0]:.2f}" y2="{q[1]:.2f}" '
                f'stroke="{BAND}" stroke-width="{2 * radius}" stroke-linecap="round"/>')
    for p in points:
        fig.circle(p, radius, BAND, BAND, 0)


def wide_figure(name):
    nodes = []
    build_binary(list(range(len(WIDE_TRIANGLES))), nodes)
    wide = []
    collapse(nodes, 0, wide)
    root = wide[0]
    # Which root child each binary node lies under (for the colours).
    colour_of = {}

    def paint(k, colour):
        colour_of[k] = colour
        if nodes[k]["kids"]:
            for kid in nodes[k]["kids"]:
                paint(kid, colour)

    for c, k in enumerate(root["kids"]):
        paint(k, CHILD_COLOURS[c])

    fig = Figure(900, 690, "a binary BVH collapsed into a four-wide node, and its memory layout")

    # Left: the triangles, the root's four child boxes, and a ray.
    F = Frame2D((30, 330), 44)
    o, target = (-0.3, 4.7), (9.9, 0.9)
    d = (target[0] - o[0], target[1] - o[1])
    intervals = [slab_2d(o, d, nodes[k]["box"]) for k in root["kids"]]
    pad = 0.08
    for c, k in enumerate(root["kids"]):
        (x0, y0), (x1, y1) = nodes[k]["box"]
        fig.rect(*F((x0 - pad, y1 + pad)), *F((x1 + pad, y0 - pad)), CHILD_COLOURS[c], "none", 2)
        fig.text(add(F((x0 - pad, y1 + pad)), (4, -5)), f"child {c}", "start", 12,
                 CHILD_COLOURS[c], "bold")
    for i, tri in enumerate(WIDE_TRIANGLES):
        leaf = next(k for k in range(len(nodes)) if nodes[k]["prims"] == [i])
        colour = colour_of[leaf]
        fig.polygon([F(p) for p in tri], colour, colour, 1.2, opacity=0.22)
        cx = sum(p[0] for p in tri) / 3
        cy = sum(p[1] for p in tri) / 3
        fig.text(add(F((cx, cy)), (0, 4)), str(i), size=10, fill=DARK)
    t_end = 1.05
    fig.arrow(F(o), F((o[0] + t_end * d[0], o[1] + t_end * d[1])), INK, 1.6)
    fig.dot(F(o), INK, 3.5)
    fig.text(add(F(o), (-4, -8)), "ray", "start", 12)
    for c, (t0, t1) in enumerate(intervals):
        if t0 <= t1:
            for t in (t0, t1):
                fig.dot(F((o[0] + t * d[0], o[1] + t * d[1])), CHILD_COLOURS[c], 3.5)

    # Right: the binary tree; each wide node is a grey band around the binary nodes it absorbs.
    leaves = [k for k in range(len(nodes)) if not nodes[k]["kids"]]
    pos = {}

    def place(k, depth):
        if not nodes[k]["kids"]:
            pos[k] = (490 + 33 * leaves.index(k), 60 + 52 * depth)
        else:
            a, b = nodes[k]["kids"]
            place(a, depth + 1)
            place(b, depth + 1)
            pos[k] = ((pos[a][0] + pos[b][0]) / 2, 60 + 52 * depth)

    place(0, 0)
    for w, group in enumerate(wide):
        inside = set(group["absorbed"])
        edges = [(pos[k], pos[kid]) for k in inside for kid in nodes[k]["kids"] if kid in inside]
        rounded_group(fig, [pos[k] for k in inside], edges, 14)
        top = pos[group["binary"]]
        fig.text(add(top, (-18, -2)), f"W{w}", "end", 12, DARK, "bold")
    for k, node in enumerate(nodes):
        if node["kids"]:
            for kid in node["kids"]:
                colour = DARK if k in root["absorbed"] else colour_of[kid]
                fig.line(pos[k], pos[kid], colour, 1.4)
    for k, node in enumerate(nodes):
        if node["kids"]:
            colour = DARK if k in root["absorbed"] else colour_of[k]
            fig.circle(pos[k], 6, colour, "white" if k in root["absorbed"] else colour, 2)
        else:
            fig.rect(pos[k][0] - 9, pos[k][1] - 9, pos[k][0] + 9, pos[k][1] + 9,
                     colour_of[k], "white", 1.8)
            fig.text(add(pos[k], (0, 4)), str(node["prims"][0]), size=10)
    for c, k in enumerate(root["kids"]):
        fig.text(add(pos[k], (0, -12 if nodes[k]["kids"] else -14)), f"{c}", "end" if c < 2
                 else "start", 11, CHILD_COLOURS[c], "bold")
    fig.text((685, 24), f"the binary tree: W0 absorbs {len(root['absorbed'])} binary nodes "
             f"(white), {len(wide)} wide nodes in all", size=12)

    # Below: the 128 bytes of W0, one row of four lanes per 16-byte load.
    rows = [("lo[0]", "lo.x", lambda k: nodes[k]["box"][0][0]),
            ("lo[1]", "lo.y", lambda k: nodes[k]["box"][0][1]),
            ("lo[2]", "lo.z", lambda k: 0.0),
            ("hi[0]", "hi.x", lambda k: nodes[k]["box"][1][0]),
            ("hi[1]", "hi.y", lambda k: nodes[k]["box"][1][1]),
            ("hi[2]", "hi.z", lambda k: 0.0),
            ("child", "node or first pack", None),
            ("count", "0 or triangles", None)]
    x0, y0, cell_w, cell_h = 130, 392, 62, 30
    fig.text((x0 - 100, y0 - 34), "W0 in memory (WideNode, 128 bytes)", "start", 13,
             weight="bold")
    for c in range(4):
        fig.text((x0 + cell_w * c + cell_w / 2, y0 - 14), f"lane {c}", size=11,
                 fill=CHILD_COLOURS[c])
    wide_index = {group["binary"]: w for w, group in enumerate(wide)}
    for r, (field, meaning, value) in enumerate(rows):
        y = y0 + cell_h * r
        fig.text((x0 - 100, y + 20), f"{16 * r:3d}", "start", 11, GRID)
        fig.text((x0 - 8, y + 20), field, "end", 12)
        for c, k in enumerate(root["kids"]):
            fill = {BLUE: FILL_BLUE, ORANGE: FILL_ORANGE, GREEN: "#e2f2e5",
                    RED: FILL_RED}[CHILD_COLOURS[c]]
            fig.rect(x0 + cell_w * c, y, x0 + cell_w * (c + 1), y + cell_h, DARK, fill, 1)
            if value:
                text = f"{value(k):.1f}"
            elif field == "child":
                text = f"W{wide_index[k]}" if nodes[k]["kids"] else "pack"
            else:
                text = "0" if nodes[k]["kids"] else str(len(nodes[k]["prims"]))
            fig.text((x0 + cell_w * c + cell_w / 2, y + 20), text, size=12)
        fig.text((x0 + 4 * cell_w + 8, y + 20), meaning, "start", 11, "#555")
    fig.text((x0 - 100, y0 + cell_h * 8 + 18),
             "count is 4 × 16 bits: 8 bytes, then 8 of padding (alignas 64)", "start", 11, "#555")

    # Below right: the four lanes of the slab test for this ray, and the visiting order.
    t_max = max(t1 for t0, t1 in intervals if t0 <= t1) * 1.08
    scale = 300 / t_max
    fig.text((545, y0 - 34), "one slab test, four lanes: [~t~_0, ~t~_1] of each child", "start",
             13, weight="bold")
    order = sorted((t0, c) for c, (t0, t1) in enumerate(intervals) if t0 <= t1)
    for c, (t0, t1) in enumerate(intervals):
        y = y0 + 22 + 44 * c
        fig.text((555, y + 4), f"lane {c}", "end", 11, CHILD_COLOURS[c])
        fig.line((565, y), (565 + 300, y), GRID, 1)
        if t0 <= t1:
            fig.line((565 + scale * t0, y), (565 + scale * t1, y), CHILD_COLOURS[c], 5)
            rank = [cc for _, cc in order].index(c)
            fig.text((565 + scale * t0, y - 9), f"~t~_0 = {t0:.2f}", "start", 11,
                     CHILD_COLOURS[c])
            fig.text((565 + scale * t1 + 6, y + 4), f"visit {rank + 1}", "start", 11, INK, "bold")
        else:
            fig.text((565 + 150, y - 6), f"miss: ~t~_0 = {t0:.2f} > ~t~_1 = {t1:.2f}", size=11,
                     fill="#555")
    y_axis = y0 + 22 + 44 * 4 - 10
    fig.line((565, y_axis), (865, y_axis), DARK, 1)
    for t in range(0, int(t_max * 10) + 1, 2):
        fig.line((565 + scale * t / 10, y_axis), (565 + scale * t / 10, y_axis + 4), DARK, 1)
        fig.text((565 + scale * t / 10, y_axis + 16), f"{t / 10:.1f}", size=10)
    fig.text((715, y_axis + 32), "~t~ along the ray (|~d~| scaled so the arrow ends at 1.05)",
             size=11, fill="#555")
    return fig.write(name)


if __name__ == "__main__":
    made = [sah_figure("ch03-sah.svg"), watertight_figure("ch03-watertight.svg"),
            wide_figure("ch03-wide.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
