#!/usr/bin/env python3
"""Chapter 18's Cornell box, raybook against Cycles at equal error (cycles_bench.sh says how).
usage: cycles_bench.py RT ROOT OUT_DIR ROUNDS"""
import math
import os
import re
import subprocess
import sys

rt, root, out, rounds = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from images import pixels, rmse  # noqa: E402

scene = os.path.join(root, "scenes", "chapter18-path-tracing.lua")
script = os.path.join(root, "tests", "perf", "ch18", "cornell_cycles.py")
SPP = [16, 64, 256]
REF = 4096


def raybook(png, spp, seed):
    p = subprocess.run([rt, "--quiet", "--stats", "--threads", "2", "--spp", str(spp), "--seed",
                        str(seed), "--output", png, scene], capture_output=True, text=True)
    if p.returncode:
        sys.exit(p.stderr)
    return float(re.search(r"render ([0-9.]+) s", p.stderr).group(1))


def cycles(png, spp, seed):
    p = subprocess.run(["blender", "-b", "--factory-startup", "--python", script, "--", png,
                        str(spp), str(seed)], capture_output=True, text=True)
    m = re.search(r"render_seconds ([0-9.]+)", p.stdout)
    if p.returncode or not m:
        sys.exit(p.stdout[-2000:] + p.stderr[-2000:])
    return float(m.group(1))



def time_at(curve, error):
    """The time at which a curve of (time, rmse) points reaches `error` (log-log interpolation,
    extrapolated from the nearest segment)."""
    pts = sorted(curve, key=lambda p: -p[1])
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e1 <= error or (t1, e1) == pts[-1]:
            s = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))
    return float("nan")


renderers = {"raybook": raybook, "cycles": cycles}
for name, render in renderers.items():
    render(f"{out}/{name}-ref.png", REF, 99)
curves = {}
for name, render in renderers.items():
    points = []
    for spp in SPP:
        png = f"{out}/{name}-{spp}.png"
        t = min(render(png, spp, 1) for _ in range(rounds))
        points.append((t, rmse(png, f"{out}/{name}-ref.png")))
    curves[name] = points
ra, cy = pixels(f"{out}/raybook-ref.png"), pixels(f"{out}/cycles-ref.png")
mean_r = [sum(ra[c::3]) / (len(ra) / 3) for c in range(3)]
mean_c = [sum(cy[c::3]) / (len(cy) / 3) for c in range(3)]
print("chapter 18's Cornell box, 160x160, 2 threads; each against its own 4096-sample render")
print("| samples | raybook s | raybook RMSE | Cycles s | Cycles RMSE |")
print("|---:|---:|---:|---:|---:|")
for i, spp in enumerate(SPP):
    (tr, er), (tc, ec) = curves["raybook"][i], curves["cycles"][i]
    print(f"| {spp} | {tr:.3f} | {er:.4f} | {tc:.3f} | {ec:.4f} |")
ratios = [t / time_at(curves["cycles"], e) for t, e in curves["raybook"]]
print("raybook / Cycles time at equal error: " + ", ".join(f"{r:.2f}" for r in ratios) +
      f" (median {sorted(ratios)[len(ratios) // 2]:.2f})")
print("converged means (sRGB, per channel) raybook " + " ".join(f"{m:.4f}" for m in mean_r) +
      ", Cycles " + " ".join(f"{m:.4f}" for m in mean_c) + "; relative difference " +
      " ".join(f"{(c - r) / r:+.1%}" for r, c in zip(mean_r, mean_c)))
