#!/usr/bin/env python3
"""Chapter 16's final gather against the direct read of the indirect map (issue 36, part 3).

usage: tests/perf/ch16/final_gather.py RT DATA_DIR [--size WxH] [--ref-spp N] [--rounds R]
                                       [--config NAME=ARGS ...]

RT is a binary with chapters 16 and 18 (rt_ch18). What it measures:

- The scene: chapter 16's box WITHOUT its glass and mirror balls (scenes/chapter16-photon-
  mapping.lua with the two balls cut out, as tests/perf/ch18/methods_chart.py does), because
  the reference is path traced and a path never reaches a point light through a delta surface:
  with the balls, the reference would lack the caustics the photon maps draw. Without them every
  method converges to the same picture.
- The reference: chapter 18's path tracer, --integrator=path, --ref-spp paths a pixel (default
  2048), seed 99 (a different stream from the measured renders, seed 1).
- The error: the RMSE over every channel of every pixel (8-bit PNGs, channels in [0, 1]), of
  the image as it is ("full"), and after both images are blurred by a box of half-width equal
  to the indirect map's last gather radius in pixels ("low": the low-frequency error, the
  blotches and the boundary bias a disc of that size leaves, without the grain a blur of that
  size removes). The radius in pixels is 12 footprints (the first radius, see ch16-defaults)
  times last/first radius from --stats.
- The time: the CPU seconds (user + system) of the whole run on one thread (--threads 1), the
  least of --rounds rounds: on a shared machine a process's CPU time moves far less than the
  wall clock. Also the render phase of --stats (the photon passes included) on all cores, the
  fastest of the rounds.

--pair FILE writes the chapter's own scene (with its balls) at --size, seed 1, read directly
(left) and gathered (right), side by side, as an 8-bit PNG: the page's figure
(docs/charts/ch16-gather-pair.png).

Each configuration is a name and rt's arguments; the default ones are the direct read at the
chapter's defaults (today's picture, --photon-gather 0) and the final gather at the chapter's
defaults. Prints one Markdown table row per configuration.
"""
import argparse
import os
import re
import resource
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from png_read import read_png  # noqa: E402


def channels(path):
    """The image as rows of [r, g, b] lists, in [0, 1]."""
    w, h, c, rows = read_png(path)
    return w, h, [[[row[x * c + k] / 255.0 for k in range(3)] for x in range(w)] for row in rows]


def box_blur(w, h, img, r):
    """Mean over the (2r+1)^2 box around each pixel, the box clipped to the image (a summed
    area table, so the cost does not grow with r)."""
    out = [[[0.0] * 3 for _ in range(w)] for _ in range(h)]
    for k in range(3):
        sat = [[0.0] * (w + 1) for _ in range(h + 1)]
        for y in range(h):
            run = 0.0
            for x in range(w):
                run += img[y][x][k]
                sat[y + 1][x + 1] = sat[y][x + 1] + run
        for y in range(h):
            y0, y1 = max(0, y - r), min(h, y + r + 1)
            for x in range(w):
                x0, x1 = max(0, x - r), min(w, x + r + 1)
                s = sat[y1][x1] - sat[y0][x1] - sat[y1][x0] + sat[y0][x0]
                out[y][x][k] = s / ((y1 - y0) * (x1 - x0))
    return out


def rmse(w, h, a, b):
    total = sum((a[y][x][k] - b[y][x][k]) ** 2 for y in range(h) for x in range(w)
                for k in range(3))
    return (total / (w * h * 3)) ** 0.5


def mean_difference(w, h, a, b):
    """Mean of a - b over every channel, in 8-bit levels (negative: a is darker)."""
    return 255.0 * sum(a[y][x][k] - b[y][x][k] for y in range(h) for x in range(w)
                       for k in range(3)) / (w * h * 3)


def render(rt, scene, out, size, args):
    """Render; return (render seconds, the --stats photon line)."""
    cmd = [rt, "--quiet", "--stats", "--size", size, "--output", out] + args + [scene]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"final_gather: {' '.join(cmd)} failed: {p.stderr}")
    seconds = float(re.search(r"render ([0-9.]+) s", p.stderr).group(1))
    photons = re.search(r"photons .*", p.stderr)
    return seconds, photons.group(0) if photons else ""


def cpu_seconds(rt, scene, size, args):
    """The CPU seconds of one render on one thread (its image is the same bits)."""
    cmd = [rt, "--quiet", "--threads", "1", "--size", size, "--output",
           os.path.join(os.path.dirname(scene), "cpu.png")] + args + [scene]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.exit(f"final_gather: {' '.join(cmd)} failed: {p.stderr}")
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def write_pair(left, right, out):
    """Two PNGs of one size side by side, 4 white pixels apart."""
    a, b = read_png(left), read_png(right)
    w, h = a[0], a[1]
    rows = [bytes(a[3][y][:w * 3]) + b"\xff" * 12 + bytes(b[3][y][:w * 3]) for y in range(h)]
    raw = b"".join(b"\x00" + r for r in rows)

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" +
                chunk(b"IHDR", struct.pack(">IIBBBBB", 2 * w + 4, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rt")
    ap.add_argument("data")
    ap.add_argument("--size", default="192x192")
    ap.add_argument("--ref-spp", type=int, default=2048)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--config", action="append", default=[],
                    help="NAME=ARGS: a configuration of rt arguments (split on spaces)")
    ap.add_argument("--scene", choices=["box", "balls"], default="box",
                    help="box: without the balls, against the path-traced reference; balls: "
                         "the chapter's own scene, timed only")
    ap.add_argument("--pair", help="write the direct read and the gather side by side here")
    o = ap.parse_args()
    os.makedirs(o.data, exist_ok=True)
    # Step 1: the scenes, photons switched on by the scene as the chapter's does.
    source = open(os.path.join(ROOT, "scenes", "chapter16-photon-mapping.lua")).read()
    assert "gr.photons{indirect = true}" in source
    no_balls = re.sub(r"\nlocal ball = .*?root:add_child\(mirror\)\n", "\n", source, flags=re.S)
    assert no_balls != source
    scene = os.path.join(o.data, o.scene + ".lua")
    with open(scene, "w") as f:
        f.write(no_balls if o.scene == "box" else source)
    if o.pair:
        chapter = os.path.join(ROOT, "scenes", "chapter16-photon-mapping.lua")
        sides = [os.path.join(o.data, "pair-direct.png"), os.path.join(o.data, "pair-gather.png")]
        for side, args in zip(sides, [["--photon-gather", "0"], []]):
            render(o.rt, chapter, side, o.size, args + ["--seed", "1"])
        write_pair(sides[0], sides[1], o.pair)
        return
    # Step 2: the reference, path traced (no photons: the scene's gr.photons is ignored by the
    # path tracer, which draws every path itself).
    ref = os.path.join(o.data, f"ref-{o.scene}-{o.size}-{o.ref_spp}.png")
    if o.scene == "box" and not os.path.exists(ref):
        print(f"final_gather: reference, {o.ref_spp} paths a pixel", file=sys.stderr)
        t, _ = render(o.rt, scene, ref, o.size,
                      ["--integrator=path", "--spp", str(o.ref_spp), "--seed", "99"])
        print(f"final_gather: reference took {t:.1f} s", file=sys.stderr)
    configs = [c.split("=", 1) for c in o.config] or [
        ["direct read (before)", "--photon-gather 0"], ["final gather (default)", ""]]
    print("| configuration | CPU s, 1 thread | render s, all cores | RMSE full | RMSE low | "
          "mean diff (levels) | photons |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for name, args in configs:
        out = os.path.join(o.data, re.sub(r"[^A-Za-z0-9]+", "_", name) + ".png")
        best, cpu, line = None, None, ""
        for _ in range(o.rounds):
            t, line = render(o.rt, scene, out, o.size, args.split() + ["--seed", "1"])
            c = cpu_seconds(o.rt, scene, o.size, args.split() + ["--seed", "1"])
            best = t if best is None else min(best, t)
            cpu = c if cpu is None else min(cpu, c)
        if o.scene != "box":
            print(f"| {name} | {cpu:.2f} | {best:.3f} | | | | {line} |", flush=True)
            continue
        # Step 3: the blur radius: the indirect map's last radius in pixels.
        m = re.search(r"indirect \d+ stored, radius ([0-9.e+-]+) -> ([0-9.e+-]+)", line)
        r_px = max(1, round(12.0 * float(m.group(2)) / float(m.group(1))))
        w, h, a = channels(out)
        _, _, b = channels(ref)
        full = rmse(w, h, a, b)
        low = rmse(w, h, box_blur(w, h, a, r_px), box_blur(w, h, b, r_px))
        print(f"| {name} | {cpu:.2f} | {best:.3f} | {full:.4f} | {low:.4f} (blur {r_px} px) | "
              f"{mean_difference(w, h, a, b):+.2f} | {line} |", flush=True)


if __name__ == "__main__":
    main()
