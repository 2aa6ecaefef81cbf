"""Read a Radiance .hdr file (RGBE, what rt --output x.hdr writes with chapter 12) in pure
Python: read_hdr(path) returns an HdrImage, its `pixels` row-major RGB floats in linear units.
A pixel is a mantissa byte per channel and a shared exponent E: the channel is
(mantissa + 0.5)·2^(E − 136), the middle of the bin a writer that truncates leaves it in, or 0
when E is 0; `steps` holds each pixel's bin width 2^(E − 136), its quantisation step. Handles
flat scanlines and the run-length encoding (a scanline split into its four components, each a
sequence of runs and literal spans). Used by the target_error_scenes test and the target-error
benchmark (tests/perf/target_error/).
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


class HdrImage:
    """A decoded image: width × height pixels, `pixels` 3 floats each, `steps` one each."""

    def __init__(self, width, height, pixels, steps):
        self.width, self.height, self.pixels, self.steps = width, height, pixels, steps


def read_hdr(path):
    """The HdrImage in the .hdr file at `path`. Raises ValueError for what it cannot read."""
    data = open(path, "rb").read()
    width, height, at = _header(data)
    pixels, steps = [], []
    for _ in range(height):
        try:
            line, at = _scanline(data, at, width)
        except IndexError:
            raise ValueError("pixel data cut short")
        for i in range(0, 4 * width, 4):
            r, g, b, e = line[i:i + 4]
            step = math.ldexp(1.0, e - 136) if e else 0.0
            pixels += ((r + 0.5) * step, (g + 0.5) * step, (b + 0.5) * step)
            steps.append(step)
    return HdrImage(width, height, pixels, steps)
