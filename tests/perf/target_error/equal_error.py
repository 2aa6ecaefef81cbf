"""Issue 38's benchmark, the arithmetic half: rendering to a target error (--target-error)
against uniform sampling (--spp) at equal error. bench.sh renders; this reads its runs, measures
each image against its scene's reference, and writes the table and one chart per scene.

usage: python3 equal_error.py RUNS.tsv CHARTS_DIR TABLE.md COMMAND
  RUNS.tsv    one line per render, tab-separated: scene, size, kind (reference, uniform or
              adaptive), setting (spp or E), render seconds, reported error (- for uniform),
              mean and most samples per pixel (- for uniform's most), image (.hdr)
  CHARTS_DIR  gets target-error-<scene>.svg per scene
  TABLE.md    the Markdown table; COMMAND is written under it as the command that made it
Prints the same table as plain text.

Error: the RMS difference from the reference over every channel of every pixel, in linear
units (1 = white). The reference has an error of its own, independent of the render's, so the
squares add: the render's error is sqrt(measured^2 - reference^2), with the reference's error
as its --stats reported it. Uniform sampling's time at a given error comes from a least-squares
line through its points in log-log (error^2 proportional to 1/time gives slope -1/2; the fitted
slope is reported), read at the adaptive render's corrected error.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from hdr_read import read_hdr  # noqa: E402  (tests/hdr_read.py)
from svg_chart import COLOURS, Series, loglog_chart  # noqa: E402


# ---- Reading the runs ------------------------------------------------------------------------

class Run:
    """One render: what was asked, what it cost and reported, and its image."""

    def __init__(self, fields):
        self.scene, self.size, self.kind, self.setting = fields[:4]
        self.seconds = float(fields[4])
        self.reported = None if fields[5] == "-" else float(fields[5])
        self.mean_spp = float(fields[6])
        self.max_spp = fields[7]
        self.image = fields[8]
        self.measured = self.corrected = self.quantisation = None


def read_runs(path):
    """{scene: [Run, ...]} in the order the scenes first appear."""
    scenes = {}
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                run = Run(line.rstrip("\n").split("\t"))
                scenes.setdefault(run.scene, []).append(run)
    return scenes


# ---- Measuring -------------------------------------------------------------------------------

def rmse(image, reference):
    """RMS difference over every channel of every pixel."""
    if (image.width, image.height) != (reference.width, reference.height):
        raise ValueError("image and reference differ in size")
    total = sum((a - b) ** 2 for a, b in zip(image.pixels, reference.pixels))
    return math.sqrt(total / len(image.pixels))


def quantisation_rms(image, reference):
    """An estimate of the RMS of the RGBE rounding in the difference of the two images: each
    channel is stored to within a step of 2^(E - 136), a mean square error of step^2 / 12 when
    the rounding is uniform, in each image. Counted only at pixels whose stored values differ:
    where both images hold the same value, the rounding is the same and cancels."""
    total = 0.0
    for i, (a, b) in enumerate(zip(image.steps, reference.steps)):
        if image.pixels[3 * i:3 * i + 3] != reference.pixels[3 * i:3 * i + 3]:
            total += 3 * (a * a + b * b) / 12.0
    return math.sqrt(total / len(image.pixels))


def corrected_error(measured, reference_error):
    """The render's own error: the measured one less the reference's, in quadrature; None when
    the reference's reported error is larger than the measured difference."""
    d = measured ** 2 - reference_error ** 2
    return math.sqrt(d) if d > 0 else None


def measure(runs):
    """Fill in each non-reference run's measured, corrected and quantisation errors; return the
    reference run."""
    reference = next(r for r in runs if r.kind == "reference")
    ref_image = read_hdr(reference.image)
    for run in runs:
        if run is reference:
            continue
        image = read_hdr(run.image)
        run.measured = rmse(image, ref_image)
        run.corrected = corrected_error(run.measured, reference.reported)
        run.quantisation = quantisation_rms(image, ref_image)
    return reference


# ---- Equal error -----------------------------------------------------------------------------

def loglog_fit(points):
    """Least-squares line log(error) = a + b log(time) through (time, error) points: (a, b)."""
    xs = [math.log(t) for t, _ in points]
    ys = [math.log(e) for _, e in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - b * mx, b


def time_at_error(fit, error):
    """The time the fitted line gives for `error`."""
    a, b = fit
    return math.exp((math.log(error) - a) / b)


def uniform_points(runs):
    """(time, corrected error) of the uniform renders that have a corrected error."""
    return [(r.seconds, r.corrected) for r in runs if r.kind == "uniform" and r.corrected]


class Row:
    """One adaptive render against uniform sampling at its error."""

    def __init__(self, run, fit, errors):
        self.run = run
        c = run.corrected
        self.ratio = run.reported / c if c else None
        self.uniform_seconds = time_at_error(fit, c) if c and fit else None
        self.time_ratio = run.seconds / self.uniform_seconds if self.uniform_seconds else None
        self.extrapolated = bool(c and errors and not min(errors) <= c <= max(errors))


def scene_rows(runs):
    """(fit or None, [Row]) for one scene's adaptive renders."""
    points = uniform_points(runs)
    fit = loglog_fit(points) if len(points) >= 2 else None
    if fit and fit[1] >= 0:  # error not falling with time: no line to read times off
        fit = None
    errors = [e for _, e in points]
    return fit, [Row(r, fit, errors) for r in runs if r.kind == "adaptive"]


# ---- Writing ---------------------------------------------------------------------------------

def fmt(value, pattern):
    """`value` in `pattern`, or n/a for None."""
    return "n/a" if value is None else pattern % value


MAIN_HEADER = ["scene", "E", "reported", "measured", "ratio", "mean spp adaptive",
               "time adaptive (s)", "uniform time at equal error (s)", "time ratio"]


def main_cells(scene, row):
    """The main table's cells for one adaptive render."""
    r = row.run
    uniform = fmt(row.uniform_seconds, "%.3f") + (" (extrapolated)" if row.extrapolated else "")
    return [scene, r.setting, "%.5f" % r.reported, fmt(r.corrected, "%.5f"),
            fmt(row.ratio, "%.2f"), "%.1f" % r.mean_spp, "%.3f" % r.seconds, uniform,
            fmt(row.time_ratio, "%.2f")]


UNIFORM_HEADER = ["scene", "spp", "time (s)", "measured, raw", "measured, corrected",
                  "RGBE rounding (estimate)"]


def uniform_cells(scene, run):
    """The uniform table's cells for one uniform render (spp: the samples it took)."""
    return [scene, "%g" % run.mean_spp, "%.3f" % run.seconds, "%.5f" % run.measured,
            fmt(run.corrected, "%.5f"), "%.5f" % run.quantisation]


ROUNDING_HEADER = ["scene", "E", "reported", "measured, raw", "measured, corrected",
                   "RGBE rounding (estimate)", "measured, less rounding", "ratio"]


def rounding_cells(scene, run):
    """The rounding table's cells for one adaptive render: its corrected error with the .hdr
    rounding also taken off in quadrature, and the reported error against that."""
    less = corrected_error(run.corrected, run.quantisation) if run.corrected else None
    return [scene, run.setting, "%.5f" % run.reported, "%.5f" % run.measured,
            fmt(run.corrected, "%.5f"), "%.5f" % run.quantisation, fmt(less, "%.5f"),
            fmt(less and run.reported / less, "%.2f")]


SCENE_HEADER = ["scene", "size", "reference E", "reported", "mean spp", "max spp", "time (s)",
                "uniform fit slope"]


def scene_cells(scene, reference, fit):
    """The per-scene table's cells: the reference and the uniform fit."""
    return [scene, reference.size, reference.setting, "%.5f" % reference.reported,
            "%.0f" % reference.mean_spp, reference.max_spp, "%.1f" % reference.seconds,
            fmt(fit and fit[1], "%.2f")]


def markdown(header, rows):
    """A Markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in rows]
    return "\n".join(lines) + "\n"


def plain(header, rows):
    """The same table as aligned plain text."""
    widths = [max(len(c) for c in col) for col in zip(header, *rows)]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(cells, widths))
                     for cells in [header] + rows) + "\n"


NOTES = """Rendering to a target error (`--target-error E`, default `--min-spp 8`) against uniform
sampling (`--spp N`, the scene's own pixel sampler), seed 1, 2 threads, `.hdr` output (linear
radiance). Each scene's reference is an adaptive render at a quarter of the smallest E, seed 99.

- **measured**: the RMS difference from the reference over every channel of every pixel (linear,
  1 = white), *corrected for the reference's own error* by subtracting in quadrature:
  sqrt(measured^2 - reference_reported^2). The raw figures are in the last two tables.
- **reported**: the error `--stats` estimated (`estimated RMS error`); **ratio** = reported /
  measured (1: the estimate is honest; below 1: it is optimistic).
- **uniform time at equal error**: from a least-squares line through the uniform renders'
  (time, corrected error) points in log-log (slope -0.5 when error^2 is proportional to
  1/time), read at the adaptive render's corrected error; "extrapolated" when that error lies
  outside the uniform points'. **time ratio** = adaptive / uniform: below 1, adaptive is faster.
- Times are the `render X s` of `--stats`, one run each, on a shared 2-core machine: a few
  percent of noise, more when the machine is busy.
- RGBE rounding: `.hdr` keeps 8 bits of mantissa per pixel, so both images carry a rounding
  error that adds, in quadrature, to the measured difference (step^2 / 12 per channel, counted
  where the two images differ). Near an error of 0.003 it is no longer small; the second table
  takes it off too.
- A reference whose reported error is above its E had pixels held at `--max-spp` (4096).
"""


def write_table(path, scenes, results, command):
    """The Markdown file: notes, the main table, the uniform points, the per-scene facts."""
    main, rounding, uniform, facts = [], [], [], []
    for scene, runs in scenes.items():
        reference, fit, rows = results[scene]
        main += [main_cells(scene, row) for row in rows]
        rounding += [rounding_cells(scene, row.run) for row in rows]
        uniform += [uniform_cells(scene, r) for r in runs if r.kind == "uniform"]
        facts.append(scene_cells(scene, reference, fit))
    tables = [(MAIN_HEADER, main), (ROUNDING_HEADER, rounding), (UNIFORM_HEADER, uniform),
              (SCENE_HEADER, facts)]
    titles = ["", "Reported against measured with the `.hdr` rounding also taken off:\n\n",
              "Uniform sampling's points:\n\n", "Each scene's reference and uniform fit:\n\n"]
    with open(path, "w") as f:
        f.write("# Rendering to a target error against uniform sampling (issue 38)\n\n")
        f.write(NOTES + "\n")
        for title, (header, rows) in zip(titles, tables):
            f.write(title + markdown(header, rows) + "\n")
        f.write("Made by (from the repository root, after building `build/rt_ch18`):\n\n")
        f.write("    " + command + "\n")
    return tables


def fit_line(fit, runs):
    """The uniform fit drawn across every render's time span, as (time, error) points."""
    times = [r.seconds for r in runs if r.kind != "reference"]
    lo, hi = min(times), max(times)
    return [(t, math.exp(fit[0] + fit[1] * math.log(t))) for t in (lo, hi)]


def write_chart(path, scene, runs, fit):
    """One scene's chart: corrected RMSE against render time, uniform against adaptive."""
    uni = [r for r in runs if r.kind == "uniform" and r.corrected]
    ada = [r for r in runs if r.kind == "adaptive" and r.corrected]
    series = [Series("uniform (--spp), measured", [(r.seconds, r.corrected) for r in uni],
                     ["%g spp" % r.mean_spp for r in uni], COLOURS[0])]
    if fit:
        series.append(Series("uniform, log-log fit", fit_line(fit, runs), ["", ""], COLOURS[0],
                             marker="", dash="4,4"))
    series.append(Series("adaptive (--target-error), measured",
                         [(r.seconds, r.corrected) for r in ada],
                         ["E %s" % r.setting for r in ada], COLOURS[1], "square", below=True))
    series.append(Series("adaptive, its reported error", [(r.seconds, r.reported) for r in ada],
                         ["" for r in ada], COLOURS[1], "open-square", dash="2,3"))
    size = runs[0].size.replace("x", " x ")
    svg = loglog_chart("%s: error against render time (%s, 2 threads)" % (scene, size),
                       "render time (s)",
                       "RMSE against the reference (linear, corrected)", series)
    with open(path, "w") as f:
        f.write(svg)


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: equal_error.py RUNS.tsv CHARTS_DIR TABLE.md COMMAND")
    runs_path, charts, table, command = sys.argv[1:]
    scenes = read_runs(runs_path)
    results = {}
    for scene, runs in scenes.items():
        reference = measure(runs)
        fit, rows = scene_rows(runs)
        results[scene] = (reference, fit, rows)
        write_chart(os.path.join(charts, "target-error-%s.svg" % scene), scene, runs, fit)
    for header, rows in write_table(table, scenes, results, command):
        print(plain(header, rows))


if __name__ == "__main__":
    main()
