#!/usr/bin/env python3
"""Average PNG renders of one size, pixel by pixel, and write the mean as a PNG.

usage: average_png.py OUT.png IN.png...

tests/perf/ch17/media_vs_povray.sh uses it for raybook's pixel-centre series: N renders at one
sample per pixel (the pixel centre, as POV-Ray's -A), each with its own --seed, averaged, are N
samples of the media estimator without antialiasing. Values are 8-bit before and after; the
mean is rounded to the nearest level.
"""
import struct
import sys
import zlib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from png_read import read_png  # noqa: E402  (tests/png_read.py, the tests' one PNG reader)


def write_png(path, width, height, rows):
    """Write 8-bit RGB rows (bytes objects of 3 * width values) as a PNG."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    raw = b"".join(b"\0" + bytes(r) for r in rows)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" +
                           chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                           chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    images = [read_png(p) for p in sys.argv[2:]]
    width, height = images[0][0], images[0][1]
    if any((w, h) != (width, height) for w, h, _, _ in images):
        sys.exit("average_png: the images differ in size")
    sums = [[0] * (3 * width) for _ in range(height)]
    for w, h, channels, rows in images:
        for y in range(h):
            row, acc = rows[y], sums[y]
            for x in range(w):
                for c in range(3):
                    acc[3 * x + c] += row[channels * x + c]
    n = len(images)
    write_png(sys.argv[1], width, height,
              [[min(255, (v + n // 2) // n) for v in acc] for acc in sums])


if __name__ == "__main__":
    main()
