#!/usr/bin/env python3
"""Chapter 7's figures (SVG, written next to this script): the glossy lobes of
chapters/07-glossy.md, drawn from their densities.

    python3 docs/figures/ch07_figures.py

Glossiness g = 0.3, so fuzz radius f = 0.3 and Phong exponent n = 5/f^2 - 2.

ch07-polar-lobes.svg        both densities in the plane of incidence, as polar curves around the
                      mirror direction a, on one scale: p_Phong = (n+1)/(2 pi) cos^n alpha (peaked)
                      and p_fuzz = (r+^3 - max(0, r-)^3) / (4 pi f^3) (flat-topped, ending at
                      arcsin f).
ch07-fuzz-sphere.svg  seed 000's construction, a ball of radius f at the tip of a, a point b of
                      the unit ball, omega = (a + f b)/|a + f b|, and the chord [r-, r+] of
                      omega's line through the ball.
ch07-grazing.svg      a mirror direction 10 degrees above the surface: the lobe in the plane of
                      incidence, and 400 samples of the page's sampler seen along a, those below
                      the horizon rejected; the lost share P_lost integrated from the page's
                      formula.
"""
import math

from svgfig import (BLUE, DARK, FILL_BLUE, FILL_RED, GRID, INK, ORANGE, RED, Figure, Frame2D,
                    add, mul, rot2)

G = 0.3
F_FUZZ = G
N_PHONG = 5 / G**2 - 2


def p_phong(alpha, n=N_PHONG):
    c = math.cos(alpha)
    return (n + 1) / (2 * math.pi) * c**n if c > 0 else 0.0


def p_fuzz(alpha, f=F_FUZZ):
    s = math.sin(abs(alpha))
    if s > f or math.cos(alpha) < 0:
        return 0.0
    root = math.sqrt(f * f - s * s)
    r_plus, r_minus = math.cos(alpha) + root, math.cos(alpha) - root
    return (r_plus**3 - max(0.0, r_minus)**3) / (4 * math.pi * f**3)


def p_lost(theta, n=N_PHONG, steps=20000):
    """The page's P_lost(theta, n): the share of the Phong lobe around an axis at theta from the
    normal that points below the surface, integrated over alpha (midpoint rule)."""
    a0 = math.pi / 2 - theta  # below this, no direction of the cone can go under
    total = 0.0
    h = (math.pi / 2 - a0) / steps
    for k in range(steps):
        a = a0 + (k + 0.5) * h
        kk = math.cos(a) * math.cos(theta) / (math.sin(a) * math.sin(theta))
        lost = math.acos(kk) / math.pi if kk < 1 else 0.0
        density = (n + 1) * math.cos(a)**n * math.sin(a)  # of alpha: d(cos^(n+1)) / d alpha
        total += lost * density * h
    return total


def lcg(seed):
    """A fixed stream of numbers in [0, 1) (as in ch08_figures.py): the same figure every run."""
    state = seed
    while True:
        state = (1664525 * state + 1013904223) % 2**32
        yield state / 2**32


def surface(fig, F, x0, x1):
    fig.line(F((x0, 0)), F((x1, 0)), DARK, 2.5)
    x = x0
    while x <= x1:
        fig.line(F((x, 0)), F((x - 0.07, -0.07)), GRID, 1)
        x += 0.1


def lobe_curve(axis_angle, density, scale):
    """A polar curve: radius scale * density(alpha) at angle axis_angle + alpha."""
    pts = []
    for k in range(721):
        alpha = -math.pi / 2 + math.pi * k / 720
        r = scale * density(alpha)
        pts.append((r * math.cos(axis_angle + alpha), r * math.sin(axis_angle + alpha)))
    return pts


def lobes_figure(names):
    """Three panels, each written to its own file (the page shows each at its own section)."""
    peak = p_phong(0.0)
    fig = Figure(330, 400, "the Phong lobe and the fuzz lobe on one scale")

    # Left: the two densities around the mirror direction.
    F = Frame2D((150, 300), 200)
    theta = math.radians(45)  # the mirror direction's angle from the normal
    axis = math.pi / 2 - theta
    surface(fig, F, -0.65, 0.65)
    d_in = (math.cos(axis), -math.sin(axis))  # arriving: a is its mirror image
    a = (math.cos(axis), math.sin(axis))
    fig.arrow(F(mul(d_in, -0.6)), F((0, 0)), INK, 2)
    fig.text(add(F(mul(d_in, -0.45)), (-8, -4)), "*d*", "end")
    fig.arrow(F((0, 0)), F((0, 0.55)), DARK, 1.8)
    fig.text(add(F((0, 0.55)), (0, -6)), "*n*")
    scale = 1.0 / peak
    phong = lobe_curve(axis, p_phong, scale)
    fuzz = lobe_curve(axis, p_fuzz, scale)
    fig.polygon([F(q) for q in phong], FILL_RED, RED, 2)
    fig.polyline([F(q) for q in fuzz], BLUE, 2, dash="6 3")
    fig.line(F((0, 0)), F(mul(a, 1.12)), GRID, 1, "3 3")
    fig.text(add(F(mul(a, 1.12)), (4, -4)), "*a*", "start")
    fig.text(add(F(mul(a, 0.55)), (12, 18)), "~p~_{Phong}", "start", 13, RED)
    fig.text(add(F(rot2(mul(a, 0.72), 0.2)), (-6, -4)), "~p~_{fuzz}", "end", 13, BLUE)
    fig.text((150, 24), "the two lobes, one scale", weight="bold")
    fig.text((150, 345), f"~g~ = {G}: ~f~ = {F_FUZZ}, ~n~ = 5/~f~² − 2 = {N_PHONG:.1f}",
             size=12)
    fig.text((150, 363), f"peaks (~n~+1)/2π = {p_phong(0):.2f}, (3 + ~f~²)/(2π~f~²) = "
             f"{p_fuzz(0):.2f}", size=12)
    fig.text((150, 381), f"fuzz lobe ends at arcsin ~f~ = {math.degrees(math.asin(F_FUZZ)):.1f}°",
             size=12)

    made = [fig.write(names[0])]

    # Middle: the fuzz sphere.
    fig = Figure(310, 400, "the fuzz sphere: omega = (a + f b) / |a + f b|")
    H = Frame2D((345, 300), 215)
    axis2 = math.radians(62)
    a2 = (math.cos(axis2), math.sin(axis2))
    f = F_FUZZ
    fig.line(H((-0.1, 0)), H((1.15, 0)), DARK, 2.5)
    fig.arrow(H((0, 0)), H(a2), INK, 2.2)
    fig.text(add(H(mul(a2, 0.5)), (-10, 0)), "*a*", "end")
    fig.circle(H(a2), f * H.scale, BLUE, FILL_BLUE, 1.8)
    # The cone of half-angle arcsin f, tangent to the ball.
    half = math.asin(f)
    tangent_len = math.sqrt(1 - f * f)
    for sgn in (-1, 1):
        t = rot2(a2, sgn * half)
        fig.line(H((0, 0)), H(mul(t, tangent_len)), GRID, 1.2, "5 3")
    fig.arc(H((0, 0)), 0.32 * H.scale, axis2, axis2 - half, DARK, 1.2)
    fig.text(add(H(rot2(mul(a2, 0.4), -half / 2)), (4, 6)), "arcsin ~f~", "start", 11)
    # A point b of the unit ball (fixed), the aimed point a + f b, omega and its chord.
    b = (0.62, -0.35)
    aim = add(a2, mul(b, f))
    omega_len = math.hypot(*aim)
    omega = mul(aim, 1 / omega_len)
    fig.line(H(a2), H(aim), BLUE, 1.8)
    fig.text(add(H(add(a2, mul(b, f * 0.5))), (-2, -8)), "~f~*b*", "middle", 12, BLUE)
    fig.dot(H(a2), INK, 3)
    fig.dot(H(aim), BLUE, 4)
    # Chord of omega's line through the ball: r = cos(alpha) -+ sqrt(f^2 - sin^2 alpha).
    cos_al = omega[0] * a2[0] + omega[1] * a2[1]
    sin_al = math.sqrt(max(0.0, 1 - cos_al * cos_al))
    root = math.sqrt(f * f - sin_al * sin_al)
    r_minus, r_plus = cos_al - root, cos_al + root
    fig.line(H(mul(omega, r_minus)), H(mul(omega, r_plus)), ORANGE, 4)
    fig.arrow(H((0, 0)), H(mul(omega, r_plus + 0.12)), RED, 2.2)
    fig.text(add(H(mul(omega, r_plus + 0.12)), (6, 4)), "~ω~", "start", 15, RED)
    fig.dot(H(mul(omega, r_minus)), ORANGE, 3.5)
    fig.dot(H(mul(omega, r_plus)), ORANGE, 3.5)
    fig.text(add(H(mul(omega, r_minus)), (-10, 12)), "~r~_−", "end", 12, ORANGE)
    fig.text(add(H(mul(omega, r_plus)), (8, 10)), "~r~_+", "start", 12, ORANGE)
    fig.text((460, 24), "the fuzz sphere", weight="bold")
    fig.text((460, 345), "~ω~ = (*a* + ~f~*b*) / |*a* + ~f~*b*|,  *b* uniform in the unit ball",
             size=12)
    fig.text((460, 363), "~p~_{fuzz} ∝ the chord's volume ∫ ~r~² d~r~ from ~r~_− to ~r~_+",
             size=12)

    made.append(fig.write(names[1], shift=305))

    # Right: near grazing the lobe pokes under the surface. Above, the plane of incidence.
    fig = Figure(320, 400, "near grazing, part of the lobe is below the surface")
    K = Frame2D((625, 128), 135)
    theta3 = math.radians(80)
    axis3 = math.pi / 2 - theta3
    a3 = (math.cos(axis3), math.sin(axis3))
    lobe3 = lobe_curve(axis3, p_phong, 1.2 / peak)  # drawn 1.2 times larger
    fig.polygon([K(q) for q in lobe3], FILL_RED, RED, 2)
    surface(fig, K, -0.1, 1.35)
    fig.arrow(K((0, 0)), K((0, 0.45)), DARK, 1.8)
    fig.text(add(K((0, 0.45)), (0, -6)), "*n*")
    fig.line(K((0, 0)), K(mul(a3, 1.3)), GRID, 1, "3 3")
    fig.text(add(K(mul(a3, 1.3)), (4, -2)), "*a*", "start")
    fig.text(add(K((0.45, 0.0)), (0, 16)), "10°", "middle", 11)
    # Below, the lobe seen along a (angle alpha from a drawn as distance, azimuth phi as angle):
    # samples drawn as the page's sampler draws them, the horizon omega.n = 0 as a curve.
    centre = (770, 250)
    px_per_rad = 44 / math.radians(10)

    def along(alpha, phi):
        """phi measured from the plane of a and n, towards n drawn upwards."""
        return (centre[0] + px_per_rad * alpha * math.sin(phi),
                centre[1] - px_per_rad * alpha * math.cos(phi))

    for deg in (5, 10, 15):
        fig.circle(centre, px_per_rad * math.radians(deg), GRID, "none", 0.8, "2 3")
    horizon = []
    for k in range(1, 240):
        phi = math.pi / 2 + math.pi * k / 240  # only cos(phi) < 0 reaches below
        alpha = math.atan(-math.cos(theta3) / (math.sin(theta3) * math.cos(phi)))
        if alpha < math.radians(17):
            horizon.append(along(alpha, phi))
    rnd = lcg(7)
    below_count, total = 0, 400
    for _ in range(total):
        xi1, xi2 = next(rnd), next(rnd)
        cos_a = xi1 ** (1 / (N_PHONG + 1))
        alpha, phi = math.acos(cos_a), 2 * math.pi * xi2
        under = (math.cos(alpha) * math.cos(theta3)
                 + math.sin(alpha) * math.sin(theta3) * math.cos(phi)) <= 0
        below_count += under
        if alpha < math.radians(17):
            fig.dot(along(alpha, phi), "#777" if under else RED, 1.8)
    fig.polyline(horizon, DARK, 2)
    fig.text(add(max(horizon), (6, 4)), "*ω*·*n* = 0", "start", 11)
    fig.line(add(centre, (-6, 0)), add(centre, (6, 0)), INK, 2)
    fig.line(add(centre, (0, -6)), add(centre, (0, 6)), INK, 2)
    lost = p_lost(theta3)
    fig.text((770, 24), "near grazing", weight="bold")
    fig.text((770, 345), f"{total} samples seen along *a* (+), rings 5°, 10°, 15°;",
             size=12)
    fig.text((770, 363), f"grey: below the surface, rejected ({below_count})", size=12)
    fig.text((770, 381), f"~P~_{{lost}}(80°, ~n~ = {N_PHONG:.1f}) = {100 * lost:.1f}%", size=12,
             fill=RED)
    made.append(fig.write(names[2], shift=610))
    return made


if __name__ == "__main__":
    made = lobes_figure(["ch07-polar-lobes.svg", "ch07-fuzz-sphere.svg", "ch07-grazing.svg"])
    print("wrote", ", ".join("docs/figures/" + m for m in made))
