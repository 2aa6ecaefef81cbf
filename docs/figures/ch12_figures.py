#!/usr/bin/env python3
"""Chapter 12's figures (SVG, written next to this script), in the notation of
chapters/12-tone-mapping.md.

    python3 docs/figures/ch12_figures.py

ch12-curves.svg   display luminance L_d against scaled luminance L (log axis): clipping
                  (min(L, 1)), Reinhard's L / (1 + L), and L (1 + L / L_white^2) / (1 + L) for
                  L_white = 2 and 10, each reaching 1 exactly at its L_white; each drawn as the
                  display shows it, clamped to 1 (the shaded band above 1), with the L_white
                  formulas' unclamped continuation dashed.
ch12-scales.svg   the local operator's scale selection on one row of an image with an edge:
                  scaled luminance 0.05 left of the edge and 20 right of it, a pixel 6 pixels left
                  of the edge, and for each scale s_i = 1.6^i the centre blur V1 and surround V2
                  (the reach of their Gaussians, 2 sigma), the normalised difference
                  V = (V1 - V2) / (2^phi a / s^2 + V1) and whether |V| < epsilon; the search stops
                  at the first scale whose surround reaches across the edge.

The blurs are computed as src/tone_map/reinhard.cpp computes them (the same weights, cut at 3
sigma and renormalised at the border), on a row of 80 pixels; a row of a 2D image that is
constant along y blurs the same way. Nothing is random, so the files only change when this
script does.
"""
import math

from svgfig import BLUE, DARK, GREEN, GRID, INK, ORANGE, RED, Figure


def reinhard(L, white):
    """The page's global operator; white = None is L / (1 + L)."""
    burn = 1.0 if white is None else 1.0 + L / (white * white)
    return L * burn / (1.0 + L)


def curves_figure(name):
    f = Figure(560, 360, "Tone curves: clipping, L/(1+L) and L_white")
    x0, x1, y0, y1 = 70, 530, 300, 40  # plot box in page units
    lo, hi, top = -2.0, 2.0, 1.2  # log10 L from 0.01 to 100; L_d up to 1.2

    def page(L, Ld):
        return (x0 + (math.log10(L) - lo) / (hi - lo) * (x1 - x0), y0 - Ld / top * (y0 - y1))

    # Axes, grid and ticks.
    f.rect(x0, y1, x1, y0, GRID, width=1)
    for e in range(-2, 3):
        p = page(10.0**e, 0)
        f.line((p[0], y0), (p[0], y1), GRID, 0.8, dash="3 3")
        f.text((p[0], y0 + 18), f"10^{{{e}}}" if e not in (0, 1) else ("1" if e == 0 else "10"),
               size=12)
    for v in (0.0, 0.5, 1.0):
        y = page(1.0, v)[1]
        f.line((x0, y), (x1, y), GRID, 0.8 if v != 1.0 else 1.2, dash=None if v == 1.0 else "3 3")
        f.text((x0 - 8, y + 4), f"{v:g}", anchor="end", size=12)
    f.text(((x0 + x1) / 2, y0 + 40), "scaled luminance ~L~ = ~a~ L_w / L̄_w (log scale)")
    f.text((22, (y0 + y1) / 2 - 40), "~L_d~", anchor="middle")
    # What the display cannot show: above 1 every channel is clamped to 1 (the page's
    # "the channels are clamped to [0, 1]"), so the band above the line L_d = 1 is shaded.
    band_top, one = page(1.0, top)[1], page(1.0, 1.0)[1]
    f.rect(x0, band_top, x1, one, "none", "#eceff3", 0)
    f.text((x0 + 8, band_top + 15), "above 1: clamped to 1", anchor="start", size=12, fill=DARK)
    # The curves, sampled densely in log L, as the display shows them: each one clamped to 1.
    # The L_white curves are also drawn dashed where the formula alone rises above 1.
    samples = [10.0 ** (lo + (hi - lo) * k / 400) for k in range(401)]
    for white, colour in ((2.0, GREEN), (10.0, ORANGE)):
        pts = [page(L, reinhard(L, white)) for L in samples
               if L >= white and reinhard(L, white) <= top]
        f.polyline(pts, colour, 1.4, dash="5 4")
    # The clamped parts at L_d = 1 lie on one line: clip's (red, from L = 1) is drawn widest,
    # then L_white = 2's (green, from 2) and L_white = 10's (orange, from 10) narrower on top of
    # it, so each stays visible from where it joins; the curves themselves are all 2.2 wide.
    for white, colour, width in ((0.0, RED, 7.0), (2.0, GREEN, 4.4), (10.0, ORANGE, 2.2)):
        f.line(page(max(white, 1.0), 1.0), page(10.0**hi, 1.0), colour, width)
    f.polyline([page(L, min(L, 1.0)) for L in samples], RED, 2.2)
    f.polyline([page(L, reinhard(L, None)) for L in samples], BLUE, 2.2)
    for white, colour in ((2.0, GREEN), (10.0, ORANGE)):
        f.polyline([page(L, reinhard(L, white)) for L in samples if L <= white], colour, 2.2)
        f.dot(page(white, 1.0), colour, 4.5)
    # Legend, bottom right, where no curve passes (every curve is above 0.5 for L > 1).
    entries = [(RED, 2.2, None, "clip: min(~L~, 1)"), (BLUE, 2.2, None, "~L~ / (1 + ~L~)"),
               (GREEN, 2.2, None, "~L~_{white} = 2 (dot: reaches 1)"),
               (ORANGE, 2.2, None, "~L~_{white} = 10 (dot: reaches 1)"),
               (DARK, 1.4, "5 4", "before the clamp")]
    lx, ly = page(1.5, 0)[0], y0 - 14 - 19 * (len(entries) - 1)
    f.rect(lx - 8, ly - 17, x1 - 6, y0 - 5, GRID, "white", 0.8)
    for k, (colour, width, dash, label) in enumerate(entries):
        y = ly + 19 * k
        f.line((lx, y - 4), (lx + 28, y - 4), colour, width, dash=dash)
        f.text((lx + 36, y), label, anchor="start", size=13)
    return f.write(name)


def blur(row, alpha_s):
    """The 1D blur of src/tone_map/reinhard.cpp: exp(-k^2/(alpha s)^2), 3 sigma, renormalised."""
    radius = max(1, math.ceil(3.0 * alpha_s / math.sqrt(2.0)))
    out = []
    for i in range(len(row)):
        total = weight = 0.0
        for k in range(max(-radius, -i), min(radius, len(row) - 1 - i) + 1):
            w = math.exp(-(k * k) / (alpha_s * alpha_s))
            total += w * row[i + k]
            weight += w
        out.append(total / weight)
    return out, radius


def scales_figure(name):
    n, edge, pixel = 80, 40, 34  # the edge lies between pixels 39 and 40
    row = [0.05 if i < edge else 20.0 for i in range(n)]
    key, phi, eps = 0.18, 8.0, 0.05
    alpha1 = 1.0 / (2.0 * math.sqrt(2.0))
    f = Figure(640, 460, "Local operator: growing the neighbourhood until it meets an edge")
    px0, px1 = 60, 600
    unit = (px1 - px0) / n

    def x_of(i):
        return px0 + (i + 0.5) * unit

    # The row of pixels: dark left, bright right, the pixel marked.
    top = 50
    for i in range(n):
        fill = "#2b2b2b" if row[i] < 1 else "#f4f1e6"
        f.rect(px0 + i * unit, top, px0 + (i + 1) * unit, top + 22, GRID, fill, 0.5)
    f.rect(px0 + pixel * unit, top - 3, px0 + (pixel + 1) * unit, top + 25, RED, "none", 2)
    f.text((x_of(pixel), top - 10), "pixel", size=12, fill=RED)
    f.text((px0 + edge * unit, top + 40), "edge", size=12)
    f.line((px0 + edge * unit, top + 26), (px0 + edge * unit, 420), DARK, 1, dash="4 3")
    f.text((px0 + 10 * unit, top + 40), "~L~ = 0.05", size=12)
    f.text((px0 + 65 * unit, top + 40), "~L~ = 20", size=12)
    chosen = None
    y = top + 70
    for i in range(8):
        s = 1.6**i
        centre, r1 = blur(row, alpha1 * s)
        surround, r2 = blur(row, alpha1 * 1.6 * s)
        v1, v2 = centre[pixel], surround[pixel]
        V = (v1 - v2) / (2.0**phi * key / (s * s) + v1)
        ok = abs(V) < eps and chosen is None
        stop = abs(V) >= eps and chosen is None
        colour = GREEN if ok else (RED if stop else GRID)
        # The reach of each Gaussian: 2 sigma = 2 alpha s / sqrt(2), in pixels.
        reach1 = 2.0 * alpha1 * s / math.sqrt(2.0)
        reach2 = 2.0 * alpha1 * 1.6 * s / math.sqrt(2.0)
        f.line((x_of(pixel) - reach2 * unit, y), (x_of(pixel) + reach2 * unit, y), colour, 7,
               opacity=0.35)
        f.line((x_of(pixel) - reach1 * unit, y), (x_of(pixel) + reach1 * unit, y), colour, 7)
        mark = "< ε: grow" if ok else ("≥ ε: stop, keep the scale before" if stop else "not tried")
        f.text((px0 - 8, y + 5), f"s_{i}", anchor="end", size=13)
        f.text((px1 + 0, y - 8), f"|V| = {abs(V):.3f} {mark}", anchor="end", size=12,
               fill=colour if colour != GRID else INK)
        if stop:
            chosen = i - 1 if i > 0 else 0
        y += 40
    f.text((330, 448), f"chosen: s_{chosen} = {1.6**chosen:.2f} pixels (dark bar: centre V1, "
           "light: surround V2, each 2σ wide)", size=12)
    return f.write(name)


if __name__ == "__main__":
    for written in (curves_figure("ch12-curves.svg"), scales_figure("ch12-scales.svg")):
        print("wrote", written)
