#!/usr/bin/env python3
"""Write tiles-height.png, chapter 11's height map: 4 x 4 square tiles (height 1) separated by
grooves (height 0) with sloped edges, 64 x 64 grey, 8 bits. Standard library only.

    python3 scenes/assets/tiles-height.py
"""
import os
import struct
import zlib

SIZE, TILES = 64, 4
PERIOD = SIZE // TILES  # 16 texels per tile
GROOVE, EDGE = 2.0, 2.0  # half-width of the groove's floor and the width of its slope, texels


def height(x, y):
    """1 on a tile, 0 in a groove, a linear slope between."""
    def across(t):
        d = abs(((t + 0.5) % PERIOD) - PERIOD / 2)  # distance from the tile's centre line
        to_groove = PERIOD / 2 - d  # distance to the groove's centre
        return min(1.0, max(0.0, (to_groove - GROOVE) / EDGE))
    return min(across(x), across(y))


def png(width, height_px, rows):
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height_px, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    rows = [[round(255 * height(x, y)) for x in range(SIZE)] for y in range(SIZE)]
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tiles-height.png")
    with open(out, "wb") as f:
        f.write(png(SIZE, SIZE, rows))
    print("wrote", out)
