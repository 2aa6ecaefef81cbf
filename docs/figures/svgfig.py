"""Small SVG helpers shared by the chapter figure scripts (Python 3 standard library only).

The style is chapter 8's (ch08_figures.py): white background, sans-serif 14, dark strokes,
grey guides, red for the thing the figure is about, blue for the second actor, orange for
highlights. Labels use a tiny markup so that they spell symbols the way the chapter pages do:

    *d*        bold (a vector, as \\mathbf{d} on the page)
    ~t~        italic (a scalar)
    _x _{near} subscript (one character, or a braced group)
    ^2 ^{n+1}  superscript

The 3D figures use `Projection`, a fixed orthographic view, so every point drawn is a real
point of the construction projected to the page.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

INK = "#222"
DARK = "#333"
GRID = "#9aa4b2"
RED = "#d33"
BLUE = "#1f4e9c"
ORANGE = "#e08a00"
GREEN = "#2a8a3e"
FILL_RED = "#fbe3e3"
FILL_BLUE = "#e3ebf8"
FILL_GREY = "#eef0f3"
FILL_ORANGE = "#fdf0d9"

# --- vectors (tuples) ------------------------------------------------------------------------


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(a, s):
    return tuple(x * s for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    return mul(a, 1.0 / length(a))


def rot2(v, angle):
    """Rotate a 2D vector counter-clockwise (in y-up coordinates) by angle (radians)."""
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


# --- the page -------------------------------------------------------------------------------


class Figure:
    """An SVG canvas in page units (y down), with a list of elements."""

    def __init__(self, width, height, title):
        self.width, self.height, self.title = width, height, title
        self.body = []
        self.markers = set()
        self.defs = []

    def add(self, element):
        self.body.append(element)

    def write(self, name, shift=0):
        """Write the file; shift moves everything left by that many units (one panel of a
        figure drawn in several)."""
        defs = "".join(
            f'<marker id="arrow-{c[1:]}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" '
            f'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" '
            f'fill="{c}"/></marker>' for c in sorted(self.markers)) + "".join(self.defs)
        text = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.width}" '
                f'height="{self.height}" viewBox="0 0 {self.width} {self.height}" '
                f'font-family="sans-serif" font-size="14">\n<title>{self.title}</title>\n'
                f'<defs>{defs}</defs>\n<rect width="100%" height="100%" fill="white"/>\n'
                + (f'<g transform="translate({-shift},0)">\n' if shift else "")
                + "\n".join(self.body) + ("\n</g>" if shift else "") + "\n</svg>\n")
        with open(os.path.join(HERE, name), "w") as f:
            f.write(text)
        return name

    def linear_gradient(self, ident, x0, x1, stops):
        """A horizontal gradient from page x0 to x1; stops are (offset 0..1, colour)."""
        s = "".join(f'<stop offset="{o:.4f}" stop-color="{c}"/>' for o, c in stops)
        self.defs.append(f'<linearGradient id="{ident}" gradientUnits="userSpaceOnUse" '
                         f'x1="{x0:.2f}" y1="0" x2="{x1:.2f}" y2="0">{s}</linearGradient>')
        return f"url(#{ident})"

    # Primitives, all in page units.

    def line(self, p, q, stroke=DARK, width=1.5, dash=None, arrow=False, opacity=None):
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        if arrow:
            self.markers.add(stroke)
            extra += f' marker-end="url(#arrow-{stroke[1:]})"'
        if opacity is not None:
            extra += f' stroke-opacity="{opacity}"'
        self.add(f'<line x1="{p[0]:.2f}" y1="{p[1]:.2f}" x2="{q[0]:.2f}" y2="{q[1]:.2f}" '
                 f'stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def arrow(self, p, q, stroke=DARK, width=2, dash=None):
        self.line(p, q, stroke, width, dash, arrow=True)

    def polyline(self, points, stroke=DARK, width=1.5, fill="none", dash=None, closed=False,
                 opacity=None):
        d = " ".join(f"{x:.2f},{y:.2f}" for x, y in points)
        tag = "polygon" if closed else "polyline"
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        if opacity is not None:
            extra += f' fill-opacity="{opacity}"'
        self.add(f'<{tag} points="{d}" fill="{fill}" stroke="{stroke}" '
                 f'stroke-width="{width}" stroke-linejoin="round"{extra}/>')

    def polygon(self, points, fill, stroke="none", width=1, opacity=None, dash=None):
        self.polyline(points, stroke, width, fill, dash, closed=True, opacity=opacity)

    def rect(self, x0, y0, x1, y1, stroke=DARK, fill="none", width=1.5, dash=None,
             opacity=None):
        self.polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], fill, stroke, width, opacity,
                     dash)

    def circle(self, c, r, stroke=DARK, fill="none", width=1.5, dash=None):
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        self.add(f'<circle cx="{c[0]:.2f}" cy="{c[1]:.2f}" r="{r:.2f}" fill="{fill}" '
                 f'stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def dot(self, c, fill=INK, r=4, stroke=None):
        self.circle(c, r, stroke or fill, fill, 1.2)

    def arc(self, c, r, a0, a1, stroke=DARK, width=1.2, steps=40):
        """A circular arc around page point c from angle a0 to a1 (radians, y up as in maths)."""
        pts = [(c[0] + r * math.cos(a0 + (a1 - a0) * k / steps),
                c[1] - r * math.sin(a0 + (a1 - a0) * k / steps)) for k in range(steps + 1)]
        self.polyline(pts, stroke, width)

    def text(self, p, markup, anchor="middle", size=14, fill=INK, weight=None):
        """A label at page point p (baseline), in the markup described at the top."""
        w = f' font-weight="{weight}"' if weight else ""
        self.add(f'<text x="{p[0]:.1f}" y="{p[1]:.1f}" text-anchor="{anchor}" '
                 f'font-size="{size}" fill="{fill}"{w}>{spans(markup, size)}</text>')


def spans(markup, size=14):
    """Turn the label markup into <tspan>s: bold, italic, sub- and superscripts."""
    out, bold, italic, shift = [], False, False, 0
    small = round(size * 0.72)
    i = 0

    def emit(chunk, script=0):
        nonlocal shift
        if not chunk:
            return
        attrs = []
        if bold:
            attrs.append('font-weight="bold"')
        if italic:
            attrs.append('font-style="italic"')
        target = {0: 0, -1: round(size * 0.3), 1: -round(size * 0.4)}[script]
        if target != shift:
            attrs.append(f'dy="{target - shift}"')
            shift = target
        if script:
            attrs.append(f'font-size="{small}"')
        chunk = chunk.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        out.append(f'<tspan {" ".join(attrs)}>{chunk}</tspan>' if attrs else chunk)

    buf = ""
    while i < len(markup):
        ch = markup[i]
        if ch in "*~":
            emit(buf)
            buf = ""
            if ch == "*":
                bold = not bold
            else:
                italic = not italic
            i += 1
        elif ch in "_^" and i + 1 < len(markup):
            emit(buf)
            buf = ""
            if markup[i + 1] == "{":
                j = markup.index("}", i)
                group = markup[i + 2:j]
                i = j + 1
            else:
                group = markup[i + 1]
                i += 2
            # A script is italic when it is a single letter, upright when it is a word.
            was = italic
            italic = italic or (len(group) == 1 and group.isalpha())
            emit(group, -1 if ch == "_" else 1)
            italic = was
        else:
            buf += ch
            i += 1
    emit(buf)
    if shift:
        out.append(f'<tspan dy="{-shift}"></tspan>')
    return "".join(out)


class Frame2D:
    """Maps construction coordinates (x right, y up) to page units: scale and an origin."""

    def __init__(self, origin, scale):
        self.origin, self.scale = origin, scale

    def __call__(self, p):
        return (self.origin[0] + self.scale * p[0], self.origin[1] - self.scale * p[1])


class Projection:
    """Orthographic view of 3D points: the eye looks along -(view), y of the page is the
    projection of world up. azimuth and elevation in degrees."""

    def __init__(self, origin, scale, azimuth, elevation, up=(0, 1, 0)):
        az, el = math.radians(azimuth), math.radians(elevation)
        # Direction from the scene towards the viewer.
        toward = (math.cos(el) * math.sin(az), math.sin(el), math.cos(el) * math.cos(az))
        if up != (0, 1, 0):
            raise ValueError("only y-up scenes")
        self.right = normalize(cross(up, toward))
        self.up = cross(toward, self.right)
        self.origin, self.scale = origin, scale

    def __call__(self, p):
        return (self.origin[0] + self.scale * dot(p, self.right),
                self.origin[1] - self.scale * dot(p, self.up))
