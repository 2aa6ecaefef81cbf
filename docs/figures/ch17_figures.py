#!/usr/bin/env python3
"""Chapter 17's figures (SVG, written next to this script): the constructions of
chapters/17-media.md, computed with the page's equations.

    python3 docs/figures/ch17_figures.py

ch17-events.svg       what a medium does to the light along a ray: light from the background
                      crosses a slab of medium towards the eye; at one particle it is absorbed
                      (sigma_a), at another scattered out of the ray (sigma_s), and at a third
                      the light of a lamp is scattered into it (sigma_s times the phase
                      function). Below, the transmittance T = e^(-sigma_t d) across the slab,
                      from Beer-Lambert, for sigma_t = 1.2 per unit.
ch17-delta-tracking.svg
                      free-flight sampling in a medium whose extinction sigma_t(t) varies along
                      the ray, under a constant majorant mu. Top: delta tracking's tentative
                      collisions, exponential steps of rate mu; at each one a uniform height
                      u mu decides real (below sigma_t(t): the flight ends there) or null (above:
                      go on). Bottom: ratio tracking along the same ray, the estimate multiplied
                      by 1 - sigma_t/mu at every tentative collision, against the exact
                      transmittance exp(-integral of sigma_t), dashed.
ch17-hg-lobes.svg     the Henyey-Greenstein phase function for g = -0.5, 0, 0.5 and 0.9 as polar
                      curves r = p(cos theta) around the scattering point, light arriving from the
                      left; each panel has its own scale (the isotropic 1/(4 pi), dashed, at that
                      scale) and lists p forward and backward.
ch17-majorant-dda.svg a density field (two Gaussian puffs) over a 10 x 6 majorant grid, each
                      cell shaded by its bound (the largest density on a 9 x 9 lattice in the
                      cell, plus the field's maximum slope times the lattice's half-diagonal, so
                      the bound holds between lattice points); a ray and the cells the 3D DDA (here
                      in 2D) visits, in order; below, the density along the ray, the per-cell
                      majorant as a step function and the one global bound, dashed.

The random numbers of ch17-delta-tracking.svg come from a fixed linear congruential sequence
(as in ch08_figures.py), so the files only change when this script does. Run as a script, it
prints the numbers the figures show: the tentative collisions, the ratio-tracking estimate
against the exact transmittance, the phase function's peaks and the cells the DDA visits.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, FILL_RED, GREEN, GRID, INK,
                    ORANGE, RED, Figure, Frame2D, add, mul)


def lcg(seed):
    """A fixed stream of numbers in [0, 1) (Numerical Recipes' LCG): the same figure every run."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def henyey_greenstein(cos_theta, g):
    """p(cos theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2))."""
    denom = 1 + g * g - 2 * g * cos_theta
    return (1 - g * g) / (4 * math.pi * denom * math.sqrt(denom))


# --- ch17-events.svg -------------------------------------------------------------------------

SIGMA_T_EVENTS = 0.5


def events_figure(name):
    fig = Figure(800, 470, "absorption, out-scattering and in-scattering along a ray")
    F = Frame2D((60, 210), 110)  # x in [0, 6], the ray at y = 0
    x0, x1 = 0.9, 5.1  # the slab
    # The slab and its particles (fixed positions from the LCG).
    fig.rect(*F((x0, 1.2)), *F((x1, -1.2)), GRID, FILL_GREY, 1.2)
    rng = lcg(17)
    for _ in range(46):
        p = (x0 + 0.1 + (x1 - x0 - 0.2) * next(rng), -1.1 + 2.2 * next(rng))
        if abs(p[1]) > 0.18:
            fig.dot(F(p), GRID, 2.2)
    fig.text(add(F((x0, 1.2)), (6, 18)), "a medium absorbs (~σ~_a) and scatters (~σ~_s)", "start",
             13, DARK)
    # The ray: light from the background on the left travels right, to the eye.
    fig.arrow(F((-0.2, 0)), F((6.05, 0)), BLUE, 2.5)
    fig.text(add(F((-0.2, 0)), (0, -12)), "from the background", "start", 13, BLUE)
    eye = F((6.25, 0))
    fig.polyline([add(eye, (10, -12)), eye, add(eye, (10, 12))], INK, 2)
    fig.text(add(eye, (2, 30)), "eye", "middle", 13)
    # Absorption: a particle on the ray takes light out of it for good.
    pa = (1.9, 0)
    fig.dot(F(pa), INK, 6)
    fig.text(add(F(pa), (0, -44)), "absorption", "middle", 14, RED, "bold")
    fig.text(add(F(pa), (0, -26)), "light becomes heat: ~σ~_a", "middle", 13, RED)
    for k in range(5):  # little heat ripples
        a = math.pi / 2 + (k - 2) * 0.45
        fig.arc(F(pa), 13 + 3 * (k % 2), a - 0.12, a + 0.12, RED, 1.2, 6)
    # Out-scattering: a particle turns some of the ray's light away from it.
    po = (3.0, 0)
    fig.dot(F(po), INK, 6)
    for ang in (-62, -25, 38):
        d = (math.cos(math.radians(ang)), math.sin(math.radians(ang)))
        fig.arrow(F(add(po, mul(d, 0.1))), F(add(po, mul(d, 0.8))), ORANGE, 2)
    fig.text(add(F(po), (0, 92)), "out-scattering", "middle", 14, ORANGE, "bold")
    fig.text(add(F(po), (0, 110)), "light leaves the ray: ~σ~_s", "middle", 13, ORANGE)
    # In-scattering: the lamp's light scattered into the ray, towards the eye.
    pi_ = (4.2, 0)
    lamp = (3.5, 1.75)
    fig.dot(F(lamp), ORANGE, 7)
    for k in range(8):
        a = 2 * math.pi * k / 8
        u = (math.cos(a), math.sin(a))
        fig.line(F(add(lamp, mul(u, 0.11))), F(add(lamp, mul(u, 0.19))), ORANGE, 1.5)
    fig.text(add(F(lamp), (-18, 5)), "lamp", "end", 13, DARK)
    fig.arrow(F(lamp), F(add(pi_, mul((lamp[0] - pi_[0], lamp[1] - pi_[1]), 0.08))), GREEN, 2)
    fig.dot(F(pi_), INK, 6)
    fig.arrow(F(add(pi_, (0.08, 0.04))), F(add(pi_, (0.75, 0.04))), GREEN, 2.5)
    fig.text(add(F(pi_), (46, -64)), "in-scattering", "middle", 14, GREEN, "bold")
    fig.text(add(F(pi_), (46, -46)), "light joins the ray: ~σ~_s·~p~(~ω~′, ~ω~)", "middle", 13,
             GREEN)
    # Below: Beer-Lambert across the slab.
    G = Frame2D((60, 455), 110)  # T in [0, 1] drawn 0.8 units high
    h = 0.8
    fig.line(G((x0 - 0.3, 0)), G((x1 + 0.3, 0)), GRID, 1)
    fig.line(G((x0 - 0.3, 0)), G((x0 - 0.3, h)), GRID, 1)
    fig.text(add(G((x0 - 0.3, h)), (-6, 5)), "1", "end", 12, DARK)
    fig.text(add(G((x0 - 0.3, 0)), (-6, 5)), "0", "end", 12, DARK)
    pts = [G((x0 - 0.3, h)), G((x0, h))]
    for k in range(101):
        x = x0 + (x1 - x0) * k / 100
        pts.append(G((x, h * math.exp(-SIGMA_T_EVENTS * (x - x0)))))
    t_end = math.exp(-SIGMA_T_EVENTS * (x1 - x0))
    pts.append(G((x1 + 0.3, h * t_end)))
    fig.polyline(pts, BLUE, 2.2)
    fig.text(add(G((x0 + 1.3, h * math.exp(-SIGMA_T_EVENTS * 1.3))), (10, -6)),
             "~T~(~d~) = exp(−~d~·~σ~_t)", "start", 14, BLUE)
    fig.text(add(G((x1 + 0.3, h * t_end)), (8, 4)), f"{t_end:.4f}", "start", 12, DARK)
    fig.text(add(G((x0 - 0.3, h)), (-22, -8)), "~T~", "end", 14)
    fig.line(G((x0, 0)), G((x0, h)), GRID, 1, "3,3")
    fig.line(G((x1, 0)), G((x1, h)), GRID, 1, "3,3")
    return fig.write(name), t_end


# --- ch17-delta-tracking.svg -----------------------------------------------------------------

T_END = 10.0
MU = 1.0  # the majorant


def sigma_t_track(t):
    """The extinction along the ray: a thin haze with a thicker puff, always below MU."""
    return 0.08 + 0.72 * math.exp(-((t - 6.0) / 1.3) ** 2)


def optical_depth(t, steps=4000):
    """The integral of sigma_t from 0 to t (Simpson's rule)."""
    if t <= 0:
        return 0.0
    h = t / steps
    s = sigma_t_track(0) + sigma_t_track(t)
    for k in range(1, steps):
        s += (4 if k % 2 else 2) * sigma_t_track(k * h)
    return s * h / 3


def tentative_collisions(seed):
    """Every tentative collision in [0, T_END] at rate MU, each with its uniform height."""
    rng = lcg(seed)
    t, out = 0.0, []
    while True:
        t -= math.log(1 - next(rng)) / MU
        if t >= T_END:
            return out
        out.append((t, next(rng)))


def delta_tracking_figure(name, seed=40):
    collisions = tentative_collisions(seed)
    fig = Figure(820, 520, "delta tracking and ratio tracking under a majorant")
    sx = 62.0
    top = Frame2D((70, 215), sx)  # y: sigma in [0, 1.2] scaled by 150
    yscale = 150.0 / sx

    def P(t, y):
        return top((t, y * yscale))

    # Axes, majorant, sigma_t.
    fig.line(P(0, 0), P(T_END + 0.3, 0), DARK, 1.2, arrow=True)
    fig.line(P(0, 0), P(0, 1.15), DARK, 1.2, arrow=True)
    fig.text(add(P(T_END + 0.3, 0), (0, 18)), "~t~", "end", 14)
    fig.rect(*P(0, MU), *P(T_END, 0), "none", FILL_BLUE, 0, opacity=0.45)
    fig.line(P(0, MU), P(T_END, MU), BLUE, 2)
    fig.text(add(P(T_END, MU), (6, 5)), "majorant ~μ~", "start", 13, BLUE)
    curve = [P(T_END * k / 400, sigma_t_track(T_END * k / 400)) for k in range(401)]
    fig.polygon(curve + [P(T_END, 0), P(0, 0)], FILL_ORANGE)
    fig.polyline(curve, ORANGE, 2.2)
    fig.text(add(P(6.0, sigma_t_track(6.0)), (0, -8)), "~σ~_t(~t~)", "middle", 14, ORANGE)
    fig.text(add(P(0, 0), (-8, 5)), "0", "end", 12, DARK)
    fig.text(add(P(0, MU), (-8, 5)), "~μ~", "end", 13, BLUE)
    fig.text(add(P(0, 1.15), (8, 0)), "delta tracking: the flight ends at the first real "
             "collision", "start", 13, DARK)
    # The tentative collisions until the first real one, then the rest faintly.
    first_real = None
    log = []
    for i, (t, u) in enumerate(collisions):
        real = u * MU < sigma_t_track(t)
        if first_real is None:
            log.append((t, u * MU, "real" if real else "null"))
        faint = first_real is not None
        fig.line(P(t, 0), P(t, u * MU), GRID, 1, "2,3")
        if real and first_real is None:
            first_real = i
            fig.dot(P(t, u * MU), RED, 6)
            fig.text(add(P(t, u * MU), (0, -14)), "real: scatter or absorb", "middle", 13, RED,
                     "bold")
        elif faint:
            fig.circle(P(t, u * MU), 3.5, GRID, "white", 1.2)
        else:
            fig.circle(P(t, u * MU), 5, DARK, "white", 1.6)
        fig.line(add(P(t, 0), (0, -4)), add(P(t, 0), (0, 4)), DARK if not faint else GRID, 1.5)
    # Label the null collisions and the exponential steps.
    t_null, u_null = collisions[1]
    fig.text(add(P(t_null, u_null * MU), (10, 4)), "null: go on", "start", 13, DARK)
    t_a = 0.0
    for t, _ in collisions[:first_real + 1]:
        fig.line(add(P(t_a, 0), (2, 20)), add(P(t, 0), (-2, 20)), DARK, 1.2, arrow=True)
        t_a = t
    fig.text(add(P(0, 0), (0, 40)), "steps of −ln(1 − ~ξ~) / ~μ~: exponential, rate ~μ~", "start", 13, DARK)

    # Bottom: ratio tracking along the same ray, every tentative collision.
    bottom = Frame2D((70, 480), sx)
    yb = 150.0 / sx

    def Q(t, y):
        return bottom((t, y * yb))

    fig.line(Q(0, 0), Q(T_END + 0.3, 0), DARK, 1.2, arrow=True)
    fig.line(Q(0, 0), Q(0, 1.15), DARK, 1.2, arrow=True)
    fig.text(add(Q(T_END + 0.3, 0), (0, 18)), "~t~", "end", 14)
    fig.text(add(Q(0, 0), (-8, 5)), "0", "end", 12, DARK)
    fig.text(add(Q(0, 1), (-8, 5)), "1", "end", 12, DARK)
    exact = [Q(T_END * k / 200, math.exp(-optical_depth(T_END * k / 200))) for k in range(201)]
    fig.polyline(exact, BLUE, 2, dash="6,4")
    steps = [Q(0, 1.0)]
    estimate = 1.0
    for t, _ in collisions:
        steps.append(Q(t, estimate))
        estimate *= 1 - sigma_t_track(t) / MU
        steps.append(Q(t, estimate))
        fig.line(add(Q(t, 0), (0, -4)), add(Q(t, 0), (0, 4)), DARK, 1.5)
    steps.append(Q(T_END, estimate))
    fig.polyline(steps, RED, 2.2)
    exact_end = math.exp(-optical_depth(T_END))
    low = min(estimate, exact_end)
    fig.text(add(Q(T_END, low), (8, -22)), f"exact {exact_end:.3f}", "start", 12, BLUE)
    fig.text(add(Q(T_END, low), (8, -6)), f"estimate {estimate:.3f}", "start", 12, RED)
    fig.text(add(Q(0, 1.15), (8, 0)), "ratio tracking: multiply by 1 − ~σ~_t(~t~)/~μ~ at each "
             "tentative collision", "start", 13, DARK)
    fig.text(add(Q(1.0, 0.55), (0, 0)), "estimate", "start", 13, RED)
    fig.text(add(Q(1.0, 0.42), (0, 0)), "exact exp(−∫~σ~_t·d~t~)", "start", 13, BLUE)
    return fig.write(name), log, estimate, exact_end, len(collisions)


# --- ch17-hg-lobes.svg -----------------------------------------------------------------------

G_VALUES = (-0.5, 0.0, 0.5, 0.9)


def hg_figure(name):
    fig = Figure(760, 270, "the Henyey-Greenstein phase function for four values of g")
    peaks = []
    for i, g in enumerate(G_VALUES):
        cx = 95 + 190 * i
        c = (cx, 130)
        peak = max(henyeyGreenstein_both(g))
        scale = 70.0 / peak  # the largest lobe radius, in page units
        F = Frame2D(c, scale)
        # Light arrives from the left.
        fig.arrow(add(c, (-88, 0)), add(c, (-10, 0)), GRID, 1.5)
        # The isotropic reference at the same scale.
        fig.circle(c, scale / (4 * math.pi), GRID, "none", 1.2, "4,3")
        pts = []
        for k in range(721):
            theta = 2 * math.pi * k / 720
            r = henyey_greenstein(math.cos(theta), g)
            pts.append(F((r * math.cos(theta), r * math.sin(theta))))
        fig.polygon(pts, FILL_RED, RED, 2)
        fig.dot(c, INK, 3)
        forward, backward = henyey_greenstein(1, g), henyey_greenstein(-1, g)
        peaks.append((g, forward, backward))
        fig.text((cx, 232), f"~g~ = {g:g}", "middle", 15, INK, "bold")
        fig.text((cx, 252), f"forward {forward:.3g}, back {backward:.3g}", "middle", 12, DARK)
    fig.text((12, 22), "light arrives from the left; each lobe on its own scale; dashed: "
             "isotropic 1/(4~π~) at that scale", "start", 12, DARK)
    return fig.write(name), peaks


def henyeyGreenstein_both(g):
    """p forward and backward: the lobe's largest radius is one of them."""
    return henyey_greenstein(1, g), henyey_greenstein(-1, g)


# --- ch17-majorant-dda.svg -------------------------------------------------------------------

NX, NY = 10, 6
W, H = 10.0, 6.0
PUFFS = ((3.2, 3.4, 1.1, 1.0), (6.8, 2.4, 0.8, 0.7))  # (x, y, radius, height)
RAY_O, RAY_D = (0.0, 0.6), (1.0, 0.52)


def density(x, y):
    return sum(h * math.exp(-((x - px) ** 2 + (y - py) ** 2) / r**2) for px, py, r, h in PUFFS)


def slope_bound():
    """An upper bound of |grad density|: each Gaussian's gradient is at most h sqrt(2/e) / r."""
    return sum(h * math.sqrt(2 / math.e) / r for _, _, r, h in PUFFS)


def cell_bound(i, j, n=9):
    """The largest density on an n x n lattice over the cell, plus the slope bound times the
    half-diagonal of a lattice step: no point of the cell can be denser."""
    dx, dy = W / NX, H / NY
    best = 0.0
    for a in range(n):
        for b in range(n):
            best = max(best, density(i * dx + dx * a / (n - 1), j * dy + dy * b / (n - 1)))
    return best + slope_bound() * 0.5 * math.hypot(dx / (n - 1), dy / (n - 1))


def dda(o, d):
    """The cells a ray visits in order (Amanatides and Woo), with the t where it enters each
    and leaves it; the ray starts inside the grid."""
    dx, dy = W / NX, H / NY
    cell = [int(o[0] / dx), int(o[1] / dy)]
    size = (dx, dy)
    n = (NX, NY)
    step, next_t, delta = [0, 0], [0.0, 0.0], [0.0, 0.0]
    for a in range(2):
        if d[a] > 0:
            step[a] = 1
            next_t[a] = ((cell[a] + 1) * size[a] - o[a]) / d[a]
            delta[a] = size[a] / d[a]
        else:
            step[a] = -1
            next_t[a] = (cell[a] * size[a] - o[a]) / d[a]
            delta[a] = -size[a] / d[a]
    t, out = 0.0, []
    while 0 <= cell[0] < n[0] and 0 <= cell[1] < n[1]:
        a = 0 if next_t[0] < next_t[1] else 1
        out.append((tuple(cell), t, next_t[a]))
        t = next_t[a]
        cell[a] += step[a]
        next_t[a] += delta[a]
    return out


def majorant_figure(name):
    fig = Figure(760, 720, "a majorant grid and the cells a ray visits")
    F = Frame2D((60, 450), 62)
    bounds = {(i, j): cell_bound(i, j) for i in range(NX) for j in range(NY)}
    top = max(bounds.values())
    dx, dy = W / NX, H / NY
    for (i, j), b in bounds.items():
        shade = int(255 - 150 * b / top)
        fig.rect(*F((i * dx, (j + 1) * dy)), *F(((i + 1) * dx, j * dy)), GRID,
                 f"rgb({shade},{shade},{min(255, shade + 25)})", 0.8)
    # The field's contours over the cells.
    for level in (0.2, 0.4, 0.6, 0.8):
        for px, py, r, h in PUFFS:
            if h > level:
                rr = r * math.sqrt(math.log(h / level))
                fig.circle(F((px, py)), rr * F.scale, ORANGE, "none", 1.1, "3,3")
    visited = dda(RAY_O, RAY_D)
    for (i, j), _, _ in visited:
        fig.rect(*F((i * dx, (j + 1) * dy)), *F(((i + 1) * dx, j * dy)), BLUE, "none", 2.2)
    t_exit = visited[-1][2]
    fig.arrow(F(RAY_O), F(add(RAY_O, mul(RAY_D, t_exit + 0.6))), RED, 2.5)
    for _, t0, _ in visited[1:]:
        fig.dot(F(add(RAY_O, mul(RAY_D, t0))), RED, 3.5)
    fig.text(add(F(RAY_O), (-6, 4)), "*o*", "end", 15, RED)
    fig.text((60, 22), "cells shaded by their bound; blue: the cells the DDA visits, in order; "
             "red dots: where the ray crosses a wall", "start", 12, DARK)
    fig.text((60, 38), "dashed orange: contours 0.2, 0.4, 0.6, 0.8 of the density", "start", 12,
             DARK)
    # Below: the density along the ray and its majorants.
    G = Frame2D((60, 700), 1.0)
    tmax = t_exit
    sx = 620 / tmax
    sy = 140 / top

    def P(t, y):
        return G((t * sx, y * sy))

    fig.line(P(0, 0), P(tmax, 0), DARK, 1.2, arrow=True)
    fig.line(P(0, 0), P(0, top * 1.1), DARK, 1.2, arrow=True)
    fig.text(add(P(tmax, 0), (0, -6)), "~t~", "end", 14)
    glob = max(bounds[c] for c, _, _ in visited)
    fig.line(P(0, glob), P(tmax, glob), GRID, 1.5, "6,4")
    fig.text(add(P(tmax, glob), (-4, -6)), "one bound for the whole ray", "end", 12, DARK)
    stair = []
    for c, t0, t1 in visited:
        stair += [P(t0, bounds[c]), P(t1, bounds[c])]
        fig.line(P(t0, 0), P(t0, bounds[c]), GRID, 0.8, "2,3")
    fig.polyline(stair, BLUE, 2.2)
    curve = [P(tmax * k / 400, density(*add(RAY_O, mul(RAY_D, tmax * k / 400))))
             for k in range(401)]
    fig.polyline(curve, ORANGE, 2.2)
    fig.text(add(P(0, top * 1.1), (8, 4)), "density along the ray (orange) and each cell's "
             "majorant (blue)", "start", 12, DARK)
    return fig.write(name), visited, bounds


if __name__ == "__main__":
    made = []
    name, t_end = events_figure("ch17-events.svg")
    made.append(name)
    name, log, estimate, exact_end, count = delta_tracking_figure("ch17-delta-tracking.svg")
    made.append(name)
    name, peaks = hg_figure("ch17-hg-lobes.svg")
    made.append(name)
    name, visited, bounds = majorant_figure("ch17-majorant-dda.svg")
    made.append(name)
    print("wrote", ", ".join("docs/figures/" + m for m in made))
    print(f"events: T across the slab (sigma_t = {SIGMA_T_EVENTS}, d = 4.2) = {t_end:.4f}")
    print("delta tracking: " + ", ".join(f"t = {t:.3f} ({kind}, height {y:.3f} against sigma_t "
                                          f"{sigma_t_track(t):.3f})" for t, y, kind in log))
    print(f"ratio tracking: {count} tentative collisions, estimate {estimate:.4f}, exact "
          f"{exact_end:.4f}")
    for g, fwd, back in peaks:
        print(f"HG g = {g:g}: p(forward) = {fwd:.4f}, p(back) = {back:.4f}")
    print("DDA: " + " ".join(f"{c}" for c, _, _ in visited))
    on_ray = max(density(*add(RAY_O, mul(RAY_D, tt / 1000 * visited[-1][2])))
                 for tt in range(1001))
    print(f"majorant: largest bound {max(bounds.values()):.3f}, densest point on the ray "
          f"{on_ray:.3f}")
