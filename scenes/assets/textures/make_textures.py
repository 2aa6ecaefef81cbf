#!/usr/bin/env python3
"""Draw chapter 10's texture images (run once; the images are kept in the repository).

    python3 scenes/assets/textures/make_textures.py

globe.png   128 x 64, an equirectangular map (u = longitude / 360, v = latitude): sea, land
            from a sum of waves, ice caps, and a graticule every 30 degrees, so the page can
            show where u = phi / 2 pi and v = theta / pi put each line on the sphere.
crate.jpg   64 x 64, planks in a frame with an arrow pointing up (v) and a notch on the
            right (u): on every face of a box the arrow must point up and the notch right.
            Written as JPEG (netpbm's pnmtojpeg) because seed 000's gr.texture names .jpg files.
poster.png  96 x 64, a sunset: sky, sun, hills; for seed 000's plane.obj (its vt).
wood.jpg    128 x 64, horizontal planks with grain, a stand-in for seed 000's JapanWood.jpg.
cup.png     128 x 32, a paper cup's printed band (red, a white wave, brown edges), for seed
            002's cup with mapping = 'cylindrical'.
ridges.png  64 x 4, grey heights rising and falling 16 times across u (constant in v): seed
            002's ridges.png, the pressed ridges of its paper cup, for a bump map.
Pure Python (zlib) for PNG, so nothing but Debian's python3 and netpbm is needed.
"""
import math
import struct
import subprocess
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) in 0..255, row 0 at the top."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y))
                    for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data)))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def write_jpeg(path, width, height, pixel):
    ppm = (b"P6 %d %d 255\n" % (width, height) +
           bytes(c for y in range(height) for x in range(width) for c in pixel(x, y)))
    jpeg = subprocess.run(["pnmtojpeg", "--quality=92"], input=ppm, capture_output=True,
                          check=True).stdout
    Path(path).write_bytes(jpeg)


def globe(x, y, w=128, h=64):
    lon = (x + 0.5) / w * 360.0            # u = phi / 2 pi
    lat = 90.0 - (y + 0.5) / h * 180.0     # row 0 is the north pole (v = 1)
    # Graticule every 30 degrees (one texel wide).
    if abs((lon + 1.4) % 30.0) < 2.8 or abs((lat + 1.4) % 30.0) < 2.8:
        return (235, 225, 160)
    if abs(lat) > 72:
        return (240, 245, 250)
    phi, th = math.radians(lon), math.radians(lat)
    land = (math.sin(2 * phi) * math.cos(3 * th) + 0.6 * math.sin(5 * phi + 1.0) *
            math.sin(2 * th + 0.5) + 0.4 * math.cos(3 * phi - 2 * th))
    if land > 0.45:
        g = 110 + int(60 * min(1.0, land - 0.45))
        return (70, g, 50)
    return (25, 60 + int(30 * (1 + math.sin(3 * phi))), 150)


def crate(x, y, n=64):
    # The frame, then planks, then an up arrow and a notch on the right edge.
    if x < 5 or x >= n - 5 or y < 5 or y >= n - 5:
        if x >= n - 5 and 26 <= y < 38:
            return (200, 40, 30)               # the notch: +u side
        return (95, 60, 30)
    cx, cy = x - n / 2 + 0.5, y - n / 2 + 0.5
    if (abs(cx) < 4 and -4 < cy < 18) or (cy <= -4 and cy > -20 and abs(cx) < (cy + 20) * 0.9):
        return (240, 230, 200)                 # the arrow points to row 0: up, v = 1
    plank = (y // 9) % 2
    grain = int(12 * math.sin(x * 0.7 + y * 0.15))
    return (165 + grain - 25 * plank, 110 + grain - 20 * plank, 60 - 10 * plank)


def poster(x, y, w=96, h=64):
    u, v = (x + 0.5) / w, 1.0 - (y + 0.5) / h
    hill = 0.28 + 0.08 * math.sin(7 * u) + 0.05 * math.sin(17 * u + 1)
    if v < hill:
        return (40, int(90 + 60 * v), 50)
    if (u - 0.7) ** 2 + ((v - 0.45) * h / w) ** 2 < 0.012:
        return (255, 230, 120)
    return (int(250 - 120 * v), int(140 - 40 * v), int(90 + 120 * v))


def wood(x, y, w=128, h=64):
    plank = y // 16
    seam = y % 16 == 0 or (x + 37 * plank) % 96 == 0
    ring = math.sin(0.045 * (x + 23 * plank) * (1.0 + 0.15 * math.sin(0.3 * y + plank)) +
                    0.8 * math.sin(0.21 * y + 1.7 * plank))
    shade = 1.0 - 0.08 * (plank % 2)
    if seam:
        return (70, 44, 25)
    return (int((176 + 22 * ring) * shade), int((124 + 16 * ring) * shade),
            int((78 + 10 * ring) * shade))


def cup(x, y, w=128, h=32):
    t = 1.0 - (y + 0.5) / h                  # v up
    if t < 0.12 or t > 0.88:
        return (110, 60, 30)
    wave = 0.5 + 0.18 * math.sin(2 * math.pi * 3 * (x + 0.5) / w)
    if abs(t - wave) < 0.09:
        return (245, 240, 230)
    return (190, 30, 35)


def ridges(x, y, w=64, n=16):
    h = round(127.5 + 127.5 * math.cos(2 * math.pi * n * (x + 0.5) / w))
    return (h, h, h)


if __name__ == "__main__":
    write_png(HERE / "globe.png", 128, 64, globe)
    write_jpeg(HERE / "crate.jpg", 64, 64, crate)
    write_png(HERE / "poster.png", 96, 64, poster)
    write_jpeg(HERE / "wood.jpg", 128, 64, wood)
    write_png(HERE / "cup.png", 128, 32, cup)
    write_png(HERE / "ridges.png", 64, 4, ridges)
