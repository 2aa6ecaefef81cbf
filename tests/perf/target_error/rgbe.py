"""Read a Radiance RGBE (.hdr) image with Python's standard library only, for the target-error
benchmark (equal_error.py), since this machine has no imaging package.

usage (a check by hand): python3 rgbe.py IMAGE.hdr   prints the size and the mean of each channel

The format: a text header ("#?RADIANCE" or "#?RGBE", lines of NAME=VALUE, a blank line), a
resolution line "-Y height +X width", then one scanline per row, top first. A pixel is four
bytes, a mantissa for each of red, green and blue and a shared exponent E: the channel is
(mantissa + 0.5) * 2^(E - 136), or 0 when E is 0. A scanline is stored flat (4 bytes a pixel),
or run-length encoded by component when it starts with the bytes 2, 2 and its width (8 to
32767 pixels): for each of the four components in turn, a byte above 128 is a run (that many
minus 128 copies of the next byte), any other byte a count of literal bytes that follow.
Source: G. Ward, "Real pixels", Graphics Gems II (1991), and the Radiance file format notes
(radsite.lbl.gov, "Radiance file formats", the picture file section).
"""
import sys

MIN_RLE_WIDTH, MAX_RLE_WIDTH = 8, 32767


class Image:
    """A decoded image: `pixels` holds width * height * 3 floats, row-major, top row first;
    `steps` holds each pixel's quantisation step 2^(E - 136) (0 for a black pixel)."""

    def __init__(self, width, height, pixels, steps):
        self.width, self.height, self.pixels, self.steps = width, height, pixels, steps


def _parse_header(data):
    """(width, height, offset of the first scanline) from the header and resolution line."""
    end = data.find(b"\n\n")
    if not data.startswith(b"#?") or end < 0:
        raise ValueError("not a Radiance .hdr file (no #? magic or no blank line after the header)")
    header = data[:end].decode("ascii", "replace").split("\n")
    for line in header[1:]:
        if line.startswith("FORMAT=") and line != "FORMAT=32-bit_rle_rgbe":
            raise ValueError("unsupported pixel format: " + line)
    line_end = data.find(b"\n", end + 2)
    fields = data[end + 2:line_end].decode("ascii", "replace").split()
    if len(fields) != 4 or fields[0] != "-Y" or fields[2] != "+X":
        raise ValueError("unsupported resolution line: " + " ".join(fields))
    return int(fields[3]), int(fields[1]), line_end + 1


def _read_rle_scanline(data, pos, width):
    """One run-length encoded scanline at `pos` (after its 4-byte marker): (its width * 4
    bytes as r, g, b, e per pixel, the position after it)."""
    components = []
    for _ in range(4):
        out = bytearray()
        while len(out) < width:
            count = data[pos]
            pos += 1
            if count > 128:
                out += bytes([data[pos]]) * (count - 128)
                pos += 1
            else:
                if count == 0:
                    raise ValueError("bad run-length scanline (a literal count of 0)")
                out += data[pos:pos + count]
                pos += count
        if len(out) != width:
            raise ValueError("bad run-length scanline (a run past the row's end)")
        components.append(out)
    line = bytearray(width * 4)
    for c in range(4):
        line[c::4] = components[c]
    return line, pos


def _read_scanline(data, pos, width):
    """The scanline at `pos`, flat or run-length encoded: (width * 4 bytes, next position)."""
    if pos + 4 > len(data):
        raise ValueError("pixel data cut short")
    rle = (MIN_RLE_WIDTH <= width <= MAX_RLE_WIDTH and data[pos] == 2 and data[pos + 1] == 2
           and data[pos + 2] < 128)
    if rle:
        if (data[pos + 2] << 8) | data[pos + 3] != width:
            raise ValueError("run-length scanline of the wrong width")
        return _read_rle_scanline(data, pos + 4, width)
    line = data[pos:pos + 4 * width]
    if len(line) != 4 * width:
        raise ValueError("pixel data cut short")
    if width and line[0] == 1 and line[1] == 1 and line[2] == 1:
        raise ValueError("old-style run-length encoding is not supported")
    return line, pos + 4 * width


def _decode(line, pixels, steps):
    """Append the floats and quantisation steps of one scanline's RGBE bytes."""
    for i in range(0, len(line), 4):
        e = line[i + 3]
        step = 2.0 ** (e - 136) if e else 0.0
        pixels += [(line[i + c] + 0.5) * step for c in range(3)]
        steps.append(step)


def read_hdr(path):
    """The Image in the .hdr file at `path`. Raises ValueError for anything it cannot read."""
    with open(path, "rb") as f:
        data = f.read()
    width, height, pos = _parse_header(data)
    pixels, steps = [], []
    for _ in range(height):
        try:
            line, pos = _read_scanline(data, pos, width)
        except IndexError:
            raise ValueError("pixel data cut short")
        _decode(line, pixels, steps)
    return Image(width, height, pixels, steps)


def main():
    image = read_hdr(sys.argv[1])
    n = image.width * image.height
    means = [sum(image.pixels[c::3]) / n for c in range(3)]
    print("%d x %d, channel means %.5f %.5f %.5f" % (image.width, image.height, *means))


if __name__ == "__main__":
    main()
