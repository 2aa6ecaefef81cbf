"""Read a Radiance .hdr file (RGBE, what rt --output x.hdr writes with chapter 12) in pure
Python: read_hdr(path) returns (width, height, floats), the floats row-major RGB in linear
units. Handles flat scanlines and the run-length encoding of Greg Ward's format (each scanline
split into its four channels, each a sequence of runs and literal spans).
Source: G. Ward, "Real Pixels", Graphics Gems II (1991), and the Radiance file format notes.
"""

import math


def _header(data):
    """The image size and where the pixels begin."""
    end = data.index(b"\n\n") + 2
    if not data.startswith(b"#?"):
        raise ValueError("not a Radiance .hdr file")
    line_end = data.index(b"\n", end)
    size = data[end:line_end].split()
    if len(size) != 4 or size[0] != b"-Y" or size[2] != b"+X":
        raise ValueError(f"unsupported orientation {size!r}")
    return int(size[3]), int(size[1]), line_end + 1


def _scanline(data, at, width):
    """One scanline's RGBE bytes (4 per pixel) and where the next begins."""
    head = data[at:at + 4]
    rle = (8 <= width < 32768 and head[0] == 2 and head[1] == 2 and
           (head[2] << 8 | head[3]) == width)
    if not rle:
        return data[at:at + 4 * width], at + 4 * width
    at += 4
    channels = []
    for _ in range(4):
        out = bytearray()
        while len(out) < width:
            count = data[at]
            at += 1
            if count > 128:  # a run of one value
                out += bytes([data[at]]) * (count - 128)
                at += 1
            else:  # count literal values
                out += data[at:at + count]
                at += count
        channels.append(out)
    pixels = bytearray(4 * width)
    for c in range(4):
        pixels[c::4] = channels[c]
    return bytes(pixels), at


def read_hdr(path):
    data = open(path, "rb").read()
    width, height, at = _header(data)
    floats = []
    for _ in range(height):
        line, at = _scanline(data, at, width)
        for i in range(0, 4 * width, 4):
            r, g, b, e = line[i:i + 4]
            scale = math.ldexp(1.0, e - 136) if e else 0.0  # 2^(e − 128) / 256
            floats += (r * scale, g * scale, b * scale)
    return width, height, floats
