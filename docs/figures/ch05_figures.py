#!/usr/bin/env python3
"""Chapter 5's figures (SVG, written next to this script): Snell's law as vectors and total
internal reflection, from the equations of chapters/05-refraction.md.

    python3 docs/figures/ch05_figures.py

ch05-snell.svg   left, air into glass at 45 degrees: the unit circle around the hit point, d,
                 eta d and the normal step (eta cos theta_i - cos theta_t) n that together make
                 t, and the tangential parts sin theta_i and eta sin theta_i = sin theta_t.
                 Right, glass into air at 50 degrees, past the critical angle: eta sin theta_i
                 is longer than the circle's radius, cos^2 theta_t < 0, and only the mirror ray
                 is left; the ray at the critical angle leaves along the surface.
ch05-nested.svg  a ray through a water ball inside a glass ball, refracted at each surface with
                 the indices the medium stack gives (push on entering, pop on leaving), and the
                 table of crossings: eta_i -> eta_t and the stack after each.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, GRID, INK, ORANGE, RED, Figure, Frame2D, add, dot,
                    mul, sub)


def refract(d, n, eta):
    """The page's t = eta d + (eta cos_i - cos_t) n, or None past the critical angle."""
    cos_i = -dot(d, n)
    cos2_t = (1 - eta * eta) + eta * eta * cos_i * cos_i
    if cos2_t < 0:
        return None, cos2_t
    cos_t = math.sqrt(cos2_t)
    return add(mul(d, eta), mul(n, eta * cos_i - cos_t)), cos2_t


def panel(fig, ox, eta_i, eta_t, theta_i_deg, title):
    F = Frame2D((ox + 215, 238), 140)
    eta = eta_i / eta_t
    theta_i = math.radians(theta_i_deg)
    n = (0.0, 1.0)
    d = (math.sin(theta_i), -math.cos(theta_i))
    t, cos2_t = refract(d, n, eta)
    r = sub(d, mul(n, 2 * dot(d, n)))
    # The media: the incident side above (index eta_i), the other below.
    dense_above = eta_i > eta_t
    y0, y1 = (0, 1.35) if dense_above else (-1.35, 0)
    fig.rect(*F((-1.5, y1)), *F((1.5, y0)), "none", FILL_BLUE, 0)
    fig.line(F((-1.5, 0)), F((1.5, 0)), DARK, 2)
    fig.text(add(F((-1.45, 1.22)), (0, 4)), f"~η~_i = {eta_i:g}", "start", 13)
    fig.text(add(F((-1.45, -1.22)), (0, 4)), f"~η~_t = {eta_t:g}", "start", 13)
    fig.circle(F((0, 0)), F.scale, GRID, "none", 1, "3 4")
    fig.line(F((0, -1.2)), F((0, 1.2)), GRID, 1, "6 4")
    fig.arrow(F((0, 0)), F((0, 0.55)), DARK, 2)
    fig.text(add(F((0, 0.55)), (8, 8)), "*n*", "start")
    o = (0.0, 0.0)
    # The incoming ray, arriving along d from the circle.
    fig.arrow(F(mul(d, -1)), F(o), INK, 2.5)
    fig.text(add(F(mul(d, -0.6)), (-12, 0)), "*d*", "end")
    theta_t = None
    if t is not None:
        theta_t = math.asin(eta * math.sin(theta_i))
        # d from the hit point (dashed), eta d, then the step along n to t.
        fig.line(F(o), F(d), GRID, 1.5, "5 4")
        fig.arrow(F(o), F(mul(d, eta)), BLUE, 2.2)
        fig.text(add(F(mul(d, eta * 0.55)), (10, -2)), "~η~*d*", "start", 13, BLUE)
        step = mul(n, eta * math.cos(theta_i) - math.sqrt(cos2_t))
        fig.arrow(F(mul(d, eta)), F(add(mul(d, eta), step)), ORANGE, 2.2)
        fig.line(F(add(mul(d, eta), mul(step, 0.5))), F((0.75, -0.35)), ORANGE, 0.8)
        fig.text(add(F((0.75, -0.35)), (4, -2)), "(~η~ cos ~θ~_i − cos ~θ~_t)*n*", "start", 12,
                 ORANGE)
        fig.arrow(F(o), F(t), RED, 3)
        fig.text(add(F(t), (10, 8)), "*t*", "start", 16, RED)
        # The tangential parts, on the tangent lines at the tips.
        # sin theta_i at the tip of -d (upper left), sin theta_t at the tip of t (lower right).
        y_d, y_t = -d[1], t[1]
        fig.line(F((0, y_d)), F((-d[0], y_d)), INK, 1.5)
        fig.text(add(F((-d[0] / 2, y_d)), (0, -6)), "sin ~θ~_i", "middle", 12)
        fig.line(F((0, y_t)), F((t[0], y_t)), RED, 1.5)
        fig.text(add(F((t[0], y_t)), (-2, 18)), "sin ~θ~_t = ~η~ sin ~θ~_i", "end", 12, RED)
        # theta_t between -n and t.
        fig.arc(F(o), 0.38 * F.scale, -math.pi / 2, math.atan2(t[1], t[0]), RED, 1.5)
        mid = (-math.pi / 2 + math.atan2(t[1], t[0])) / 2
        fig.text(add(F((0.47 * math.cos(mid), 0.47 * math.sin(mid))), (2, 6)), "~θ~_t", fill=RED)
        # The mirror ray, faint: it carries the Fresnel share.
        fig.arrow(F(o), F(mul(r, 0.8)), GRID, 1.8)
        fig.text(add(F(mul(r, 0.8)), (6, -4)), "*r*", "start", 13, "#667")
    else:
        # Past the critical angle: eta sin theta_i > 1, no point of the circle has it.
        x_tan = eta * math.sin(theta_i)
        fig.line(F((x_tan, 0.05)), F((x_tan, -1.15)), RED, 1.5, "4 3")
        fig.line(F((0, -0.55)), F((x_tan, -0.55)), RED, 1.5)
        fig.text(add(F((x_tan, -0.55)), (-4, -8)), f"~η~ sin ~θ~_i = {x_tan:.2f} > 1", "end", 12,
                 RED)
        fig.text(add(F((x_tan, -1.15)), (6, 10)), "no *t*", "start", 13, RED)
        # The ray at the critical angle leaves along the surface.
        theta_c = math.asin(eta_t / eta_i)
        dc = (math.sin(theta_c), -math.cos(theta_c))
        fig.line(F(mul(dc, -1)), F(o), ORANGE, 1.5, "6 4")
        fig.arrow(F(o), F((1.0, 0.0)), ORANGE, 1.5, "6 4")
        fig.text(add(F(mul(dc, -1)), (4, -6)), f"~θ~_c = {math.degrees(theta_c):.2f}°", "start",
                 12, ORANGE)
        fig.arrow(F(o), F(r), RED, 3)
        fig.text(add(F(r), (8, 0)), "*r*: all the light", "start", 13, RED)
        fig.text(add(F((-0.1, -0.55)), (0, 0)),
                 f"cos² ~θ~_t = {cos2_t:.2f} < 0".replace("-", "−"),
                 "end", 12, RED)
    # theta_i between -d and n.
    a_in = math.atan2(-d[1], -d[0])
    fig.arc(F(o), 0.32 * F.scale, math.pi / 2, a_in, INK, 1.5)
    mid = (math.pi / 2 + a_in) / 2
    fig.text(add(F((0.42 * math.cos(mid), 0.42 * math.sin(mid))), (0, 5)), "~θ~_i")
    fig.text((ox + 215, 24), title, weight="bold")
    if theta_t is not None:
        what = (f"~η~ = {eta_i:g}/{eta_t:g}, ~θ~_i = {theta_i_deg:g}°, "
                f"~θ~_t = {math.degrees(theta_t):.4f}°")
    else:
        what = (f"~η~ = {eta_i:g}/{eta_t:g}, ~θ~_i = {theta_i_deg:g}° > ~θ~_c: "
                "total internal reflection")
    fig.text((ox + 215, 448), what, size=13)


def snell_figure(name):
    fig = Figure(900, 460, "Snell's law as vectors, and total internal reflection")
    panel(fig, 0, 1.0, 1.5, 45, "air into glass")
    panel(fig, 450, 1.5, 1.0, 50, "glass into air, past the critical angle")
    return fig.write(name)


def nested_figure(name):
    """A ray through a water ball inside a glass ball (2D), refracted at every surface with the
    indices the medium stack gives: push on entering, pop on leaving."""
    objects = {"glass": ((0.0, 0.0), 1.0, 1.5), "water": ((0.12, -0.08), 0.55, 1.33)}
    o, d = (-1.9, 0.6), (1.0, 0.0)
    stack = []  # names, innermost last

    def current():
        return objects[stack[-1]][2] if stack else 1.0

    path, crossings = [o], []
    for _ in range(8):
        # The nearest surface ahead.
        best = None
        for name_, (c, radius, _eta) in objects.items():
            oc = sub(o, c)
            b = dot(oc, d)
            disc = b * b - (dot(oc, oc) - radius * radius)
            if disc < 0:
                continue
            for t in (-b - math.sqrt(disc), -b + math.sqrt(disc)):
                if t > 1e-9 and (best is None or t < best[0]):
                    best = (t, name_)
        if best is None:
            break
        t, name_ = best
        c, radius, eta_obj = objects[name_]
        p = add(o, mul(d, t))
        n_out = mul(sub(p, c), 1 / radius)
        entering = dot(d, n_out) < 0
        eta_i = current()
        if entering:
            eta_t, after = eta_obj, stack + [name_]
        else:
            after = [s_ for s_ in stack if s_ != name_]
            eta_t = objects[after[-1]][2] if after else 1.0
        n = n_out if entering else mul(n_out, -1)  # towards the side the ray comes from
        refracted, _cos2 = refract(d, n, eta_i / eta_t)
        assert refracted is not None  # no total internal reflection on this path
        crossings.append((p, eta_i, eta_t, list(after), n))
        stack = after
        path.append(p)
        o, d = p, refracted
    path.append(add(o, mul(d, 0.7)))

    fig = Figure(900, 340, "a ray through a water ball inside a glass ball")
    F = Frame2D((300, 170), 140)
    for name_, (c, radius, _eta) in objects.items():
        fill = "#e3ebf8" if name_ == "glass" else "#c9daf2"
        fig.circle(F(c), radius * F.scale, DARK, fill, 1.8)
    fig.text(add(F((0, 0.78)), (0, 0)), "glass, ~η~ = 1.5", size=12)
    fig.text(add(F(objects["water"][0]), (0, 34)), "water, ~η~ = 1.33", size=12)
    fig.text(add(F((-1.75, -1.0)), (0, 0)), "air, ~η~ = 1", size=12)
    # The straight line the ray would follow without refraction, then the refracted path.
    fig.line(F(path[0]), F(add(path[0], (3.4, 0))), GRID, 1, "4 4")
    for k in range(len(path) - 1):
        if k == len(path) - 2:
            fig.arrow(F(path[k]), F(path[k + 1]), RED, 2.2)
        else:
            fig.line(F(path[k]), F(path[k + 1]), RED, 2.2)
    for k, (p, eta_i, eta_t, after, n) in enumerate(crossings, 1):
        fig.line(F(add(p, mul(n, 0.22))), F(add(p, mul(n, -0.22))), GRID, 1)
        fig.dot(F(p), INK, 3.5)
        fig.text(add(F(p), (0, -9 if k % 2 else 18)), str(k), size=12, weight="bold")
    fig.text(add(F(path[0]), (0, -8)), "*o*")
    # The table of crossings.
    tx, ty = 560, 70
    fig.text((tx, ty - 28), "crossing", "start", 13)
    fig.text((tx + 74, ty - 28), "~η~_i → ~η~_t", "start", 13)
    fig.text((tx + 174, ty - 28), "stack after", "start", 13)
    for k, (p, eta_i, eta_t, after, n) in enumerate(crossings, 1):
        names = ", ".join(after) if after else "(air)"
        fig.text((tx, ty + 24 * (k - 1)), f"{k}", "start", 13, weight="bold")
        fig.text((tx + 74, ty + 24 * (k - 1)), f"{eta_i:g} → {eta_t:g}", "start", 13, RED)
        fig.text((tx + 174, ty + 24 * (k - 1)), names, "start", 13)
    fig.text((tx, ty + 24 * len(crossings) + 14),
             "the water's surface bends by 1.5/1.33, not 1/1.33", "start", 12, "#555")
    return fig.write(name)


if __name__ == "__main__":
    made = [snell_figure("ch05-snell.svg"), nested_figure("ch05-nested.svg")]
    print("wrote", ", ".join("docs/figures/" + m for m in made))
