"""A small log-log line chart written as SVG, in the look of the gnuplot charts in docs/charts/
(640 x 420, sans 12, a boxed plot with inward ticks, dotted grey grid lines at the decades,
gnuplot's first line colours, a key at the top right, a label beside each point). The axes end
at 1, 2 or 5 times a power of ten rather than at whole decades, so close points stay apart. Used by
equal_error.py; no plotting package is needed.

usage (a demonstration): python3 svg_chart.py OUT.svg
"""
import math
import sys
from xml.sax.saxutils import escape

WIDTH, HEIGHT = 640, 420
LEFT, RIGHT, TOP, BOTTOM = 97.7, 614.8, 54.0, 362.4  # the plot box, as gnuplot places it
FONT = 'font-family="sans" font-size="12.00" fill="black" stroke="none"'
COLOURS = ["#9400d3", "#009e73", "#56b4e9", "#e69f00"]  # gnuplot's default line types 1-4


class Series:
    """One line of the chart: (x, y) points, their labels ('' for none), a colour, a marker
    ('circle', 'square' or 'open-square'), a dash pattern ('' solid) and whether each label
    goes above or below its point."""

    def __init__(self, title, points, labels, colour, marker="circle", dash="", below=False):
        self.title, self.points, self.labels = title, points, labels
        self.colour, self.marker, self.dash, self.below = colour, marker, dash, below


def nice_range(values):
    """(low, high) around `values` on a log axis: the nearest 1, 2 or 5 times a power of ten
    below the smallest and above the largest, with a little room so no point sits on the box."""
    lo, hi = min(values) / 1.15, max(values) * 1.15
    steps = [m * 10.0 ** k for k in range(-12, 13) for m in (1, 2, 5)]
    low = max(v for v in steps if v <= lo * (1 + 1e-9))
    high = min(v for v in steps if v >= hi * (1 - 1e-9))
    return low, high


def tick_label(value):
    """A tick's text: 0.001, 0.02, 1, 50."""
    return ("%.10f" % value).rstrip("0").rstrip(".")


class Axes:
    """Maps data to the plot box on log scales, each given as (low, high)."""

    def __init__(self, xrange, yrange):
        self.xr, self.yr = xrange, yrange

    def x(self, v):
        lo, hi = (math.log10(r) for r in self.xr)
        return LEFT + (math.log10(v) - lo) / (hi - lo) * (RIGHT - LEFT)

    def y(self, v):
        lo, hi = (math.log10(r) for r in self.yr)
        return BOTTOM - (math.log10(v) - lo) / (hi - lo) * (BOTTOM - TOP)


def ticks(span):
    """[(value, is_decade, labelled)] along an axis spanning (low, high): each power of ten
    and 2 to 9 times it; 2 and 5 times it are labelled too when the axis spans at most two
    decades, and the ends always."""
    low, high = span
    few = math.log10(high / low) <= 2.01
    out = []
    for k in range(math.floor(math.log10(low)) - 1, math.ceil(math.log10(high)) + 1):
        for m in range(1, 10):
            v = m * 10.0 ** k
            if low * (1 - 1e-9) <= v <= high * (1 + 1e-9):
                end = abs(v / low - 1) < 1e-6 or abs(v / high - 1) < 1e-6
                out.append((v, m == 1, m == 1 or end or (few and m in (2, 5))))
    return out


def axis_ticks(axes):
    """SVG for the grid lines, the ticks and their labels of both axes."""
    parts = []
    for value, major, labelled in ticks(axes.yr):
        y, size = axes.y(value), 9.0 if major else 4.5
        if major:
            parts.append(f'<path stroke="gray" stroke-width="0.5" stroke-dasharray="2,4" '
                         f'd="M{LEFT:.2f},{y:.2f} L{RIGHT:.2f},{y:.2f}"/>')
        parts.append(f'<path stroke="black" d="M{LEFT:.2f},{y:.2f} h{size} '
                     f'M{RIGHT:.2f},{y:.2f} h{-size}"/>')
        if labelled:
            parts.append(f'<text x="{LEFT - 8.4:.2f}" y="{y + 3.9:.2f}" {FONT} text-anchor="end">'
                         f'{tick_label(value)}</text>')
    for value, major, labelled in ticks(axes.xr):
        x, size = axes.x(value), 9.0 if major else 4.5
        if major:
            parts.append(f'<path stroke="gray" stroke-width="0.5" stroke-dasharray="2,4" '
                         f'd="M{x:.2f},{BOTTOM:.2f} L{x:.2f},{TOP:.2f}"/>')
        parts.append(f'<path stroke="black" d="M{x:.2f},{BOTTOM:.2f} v{-size} '
                     f'M{x:.2f},{TOP:.2f} v{size}"/>')
        if labelled:
            parts.append(f'<text x="{x:.2f}" y="{BOTTOM + 21.9:.2f}" {FONT} text-anchor="middle">'
                         f'{tick_label(value)}</text>')
    return parts


def marker(kind, x, y, colour):
    """SVG for one point marker."""
    if kind == "circle":
        return f'<circle cx="{x:.2f}" cy="{y:.2f}" r="4" fill="{colour}" stroke="{colour}"/>'
    fill = "none" if kind == "open-square" else colour
    return (f'<rect x="{x - 4:.2f}" y="{y - 4:.2f}" width="8" height="8" fill="{fill}" '
            f'stroke="{colour}" stroke-width="1.2"/>')


def series_svg(axes, s):
    """SVG for a series: its line, markers and point labels."""
    pts = [(axes.x(px), axes.y(py)) for px, py in s.points]
    dash = f' stroke-dasharray="{s.dash}"' if s.dash else ""
    parts = []
    if len(pts) > 1:
        path = " L".join(f"{x:.2f},{y:.2f}" for x, y in pts)
        parts.append(f'<path fill="none" stroke="{s.colour}" stroke-width="1.5"{dash} '
                     f'd="M{path}"/>')
    for (x, y), label in zip(pts, s.labels):
        if s.marker:
            parts.append(marker(s.marker, x, y, s.colour))
        if label:  # above and to the left, or below and to the right
            dx, dy, anchor = (7, 17, "start") if s.below else (-7, -8, "end")
            parts.append(f'<text x="{x + dx:.2f}" y="{y + dy:.2f}" {FONT} text-anchor="{anchor}">'
                         f'{escape(label)}</text>')
    return parts


def key_svg(series):
    """SVG for the key at the top right: each title, right-aligned, beside a sample line."""
    parts = []
    for i, s in enumerate(series):
        y = TOP + 16 + 17 * i
        dash = f' stroke-dasharray="{s.dash}"' if s.dash else ""
        parts.append(f'<text x="{RIGHT - 60:.2f}" y="{y + 4:.2f}" {FONT} text-anchor="end">'
                     f'{escape(s.title)}</text>')
        parts.append(f'<path stroke="{s.colour}" stroke-width="1.5"{dash} '
                     f'd="M{RIGHT - 52:.2f},{y:.2f} h40"/>')
        if s.marker:
            parts.append(marker(s.marker, RIGHT - 32, y, s.colour))
    return parts


def loglog_chart(title, xlabel, ylabel, series):
    """The whole SVG document: a log-log chart of `series` (a list of Series)."""
    xs = [p[0] for s in series for p in s.points]
    ys = [p[1] for s in series for p in s.points]
    axes = Axes(nice_range(xs), nice_range(ys))
    mid_x, mid_y = (LEFT + RIGHT) / 2, (TOP + BOTTOM) / 2
    parts = [f'<?xml version="1.0" encoding="utf-8" standalone="no"?>',
             f'<svg width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" '
             f'xmlns="http://www.w3.org/2000/svg">',
             f'<title>{escape(title)}</title>',
             f'<rect x="0" y="0" width="{WIDTH}" height="{HEIGHT}" fill="#ffffff"/>',
             '<g fill="none" stroke-width="1">']
    parts += axis_ticks(axes)
    parts.append(f'<path stroke="black" d="M{LEFT:.2f},{TOP:.2f} L{LEFT:.2f},{BOTTOM:.2f} '
                 f'L{RIGHT:.2f},{BOTTOM:.2f} L{RIGHT:.2f},{TOP:.2f} Z"/>')
    for s in series:
        parts += series_svg(axes, s)
    parts += key_svg(series)
    parts.append(f'<text x="{mid_x:.2f}" y="{TOP - 24:.2f}" {FONT} text-anchor="middle">'
                 f'{escape(title)}</text>')
    parts.append(f'<text x="{mid_x:.2f}" y="{HEIGHT - 6:.2f}" {FONT} text-anchor="middle">'
                 f'{escape(xlabel)}</text>')
    parts.append(f'<text transform="translate(18,{mid_y:.2f}) rotate(-90)" {FONT} '
                 f'text-anchor="middle">{escape(ylabel)}</text>')
    parts += ["</g>", "</svg>", ""]
    return "\n".join(parts)


def main():
    demo = [Series("uniform", [(0.1, 0.05), (0.4, 0.025), (1.6, 0.0125)], ["4", "16", "64"],
                   COLOURS[0]),
            Series("adaptive", [(0.08, 0.04), (0.3, 0.02)], ["0.04", "0.02"], COLOURS[1],
                   "square", below=True)]
    with open(sys.argv[1], "w") as f:
        f.write(loglog_chart("a demonstration", "render time (s)", "RMSE", demo))


if __name__ == "__main__":
    main()
