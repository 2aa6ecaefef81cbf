"""Read an 8-bit PNG with Python's standard library only (zlib), so that the tests' shell
scripts check images without an imaging package (tests/scenes/run_all.sh, lenient.sh,
tests/interrupt.sh).

Source: the PNG specification (W3C, second edition, 2003): section 5.3 (chunks), 11.2.2
(IHDR) and 9.2 (the five row filters, Paeth's predictor in 9.4).
"""
import struct
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"
CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # colour type -> samples per pixel


def read_png(path):
    """(width, height, channels, rows) of an 8-bit, non-interlaced PNG: rows[y] is a bytearray
    of width * channels samples. Raises ValueError for anything else, a cut-short file
    included."""
    data = open(path, "rb").read()
    if data[:8] != SIGNATURE:
        raise ValueError("not a PNG file")
    pos, idat, ihdr = 8, b"", None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", data[pos + 8:pos + 21])
        elif kind == b"IDAT":
            idat += data[pos + 8:pos + 8 + length]
        pos += 12 + length
    if ihdr is None:
        raise ValueError("no IHDR chunk")
    width, height, depth, ctype, _, _, interlace = ihdr
    if depth != 8 or interlace or ctype not in CHANNELS:
        raise ValueError("unexpected PNG format (depth %d, colour type %d, interlace %d)"
                         % (depth, ctype, interlace))
    channels = CHANNELS[ctype]
    try:
        raw = zlib.decompress(idat)
    except zlib.error as e:
        raise ValueError("pixel data cut short or corrupt (%s)" % e)
    stride = width * channels
    if len(raw) != (stride + 1) * height:
        raise ValueError("wrong amount of pixel data")
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], (prev[i - channels] if i >= channels else 0)
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows
