"""The two scripts' image arithmetic: an 8-bit PNG's channels in [0, 1], and the RMSE of two."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from png_read import read_png  # noqa: E402


def pixels(path):
    """Every channel of every pixel of an RGB PNG, in [0, 1]."""
    _, _, _, rows = read_png(path)
    return [v / 255.0 for row in rows for v in row]


def rmse(a, b):
    """The root-mean-square difference of two PNGs of the same size."""
    pa, pb = pixels(a), pixels(b)
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(pa, pb)) / len(pa))
