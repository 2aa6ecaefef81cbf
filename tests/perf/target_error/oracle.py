#!/usr/bin/env python3
"""The best any per-pixel sample allocation could do on the target-error bench's scenes (issue 38).

usage: oracle.py RT RUNS_TSV [--seeds K] [--count smallest|largest] [--scenes REGEX] [--work DIR]
                 [--reuse]

For each scene of tests/perf/target_error/bench.sh (its size and arguments, read from the
script), render K seeds (16) at its smallest (or largest) uniform sample count, and estimate
each pixel's
variance of one sample, sigma_i^2 = n * (the variance between seeds), averaged over its channels.
The bench's error is the RMS over every channel of every pixel, so n_i samples in pixel i give
MSE = mean(sigma_i^2 / n_i). Then:

  oracle     the allocation that minimizes the mean n for a given MSE: n_i proportional to
             sigma_i (Lagrange), whose mean over uniform sampling's mean is
             (mean sigma)^2 / mean(sigma^2). No pilot, no floor: no design can do better.
  floor      the same with raybook's pilot: 4 planning samples a pixel set aside and at least
             10 that count (n_i = 4 + max(10, lambda sigma_i)), at the error the design reached
             at the bench's tightest target (measured against the bench's reference, as
             equal_error.py measures it, from RUNS_TSV, a bench.sh run).
  design     what the design in RUNS_TSV spent there: its mean samples a pixel over the samples
             uniform sampling needs for the same error (a log-log line through the uniform
             renders' samples and errors, as equal_error.py draws it through their times).

Both count samples, not seconds: a pixel's samples do not all cost the same. Both assume a
pixel's variance falls as 1/n; where strata make it fall faster (an edge, a lens), sigma
measured at a small count overstates the gain at a large one, hence --count largest. The spread
of a
pixel's sigma estimate between seeds makes the ratios slightly optimistic (mean(s) is corrected
by c4(K), the Gaussian bias of a standard deviation from K values).
Source: the allocation n_i ~ sigma_i is Neyman's (J. Neyman, "On the two different aspects of
the representative method", J. Royal Statistical Society 97(4), 1934), pixels as strata.
"""

import argparse
import math
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tests"))
from hdr_read import read_hdr  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import equal_error  # noqa: E402  (tests/perf/target_error/equal_error.py)

SET_ASIDE, FLOOR = 4, 10  # The landed design: a planning group of 4, then at least 8 + 2.


def bench_scenes():
    """(scene, size, uniform counts, args, uniform-only args) from bench.sh's table."""
    text = (ROOT / "tests/perf/target_error/bench.sh").read_text()
    block = text[text.index("scenes=(") : text.index("\n)\n")]
    rows = []
    for line in re.findall(r'^\s*"(.*)"\s*$', block, re.M):
        scene, size, spps, _errors, args, uargs = [f.strip() for f in line.split("|")]
        rows.append((scene, size, [int(n) for n in spps.split()], args.split(), uargs.split()))
    return rows


def tightest(runs):
    """Per scene: (error, design's samples ratio) of the render at its smallest --target-error,
    the error measured against the bench's reference."""
    out = {}
    for name, scene_runs in equal_error.read_runs(runs).items():
        equal_error.measure(scene_runs)
        adaptive = [r for r in scene_runs if r.kind == "adaptive" and r.corrected]
        uniform = [(float(r.mean_spp), r.corrected) for r in scene_runs
                   if r.kind == "uniform" and r.corrected]
        if not adaptive or len(uniform) < 2:
            continue
        run = min(adaptive, key=lambda r: float(r.setting))
        needed = equal_error.time_at_error(equal_error.loglog_fit(uniform), run.corrected)
        out[name] = (run.corrected, float(run.mean_spp) / needed)
    return out


def c4(k):
    """E[s] / sigma for k Gaussian values."""
    return math.sqrt(2.0 / (k - 1)) * math.exp(math.lgamma(k / 2) - math.lgamma((k - 1) / 2))


def pixel_sigmas(rt, scene, size, spp, args, uargs, seeds, work, reuse):
    """Each pixel's standard deviation of one sample, from `seeds` renders."""
    images = []
    for seed in range(1, seeds + 1):
        out = work / f"{Path(scene).stem}-{seed}.hdr"
        cmd = [rt, "--quiet", "--threads", "2", "--size", size, "--spp", str(spp), "--seed",
               str(seed), "--output", str(out), *args, *uargs, scene]
        if not (reuse and out.exists()):
            subprocess.run(cmd, cwd=ROOT, check=True)
        images.append(read_hdr(out).pixels)
    k = len(images)
    sigmas = []
    for p in range(0, len(images[0]), 3):
        var = 0.0
        for c in range(3):
            values = [im[p + c] for im in images]
            mean = sum(values) / k
            var += sum((v - mean) ** 2 for v in values) / (k - 1)
        sigmas.append(math.sqrt(spp * var / 3.0))
    return sigmas


def with_floor(sigmas, mse):
    """Mean samples a pixel when n_i = SET_ASIDE + max(FLOOR, lam sigma_i) reaches `mse`."""
    def error(lam):
        return sum(s * s / max(FLOOR, lam * s) for s in sigmas) / len(sigmas)
    if error(0.0) <= mse:
        return SET_ASIDE + FLOOR
    lo, hi = 0.0, 1.0
    while error(hi) > mse:
        hi *= 2.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if error(mid) > mse else (lo, mid)
    return SET_ASIDE + sum(max(FLOOR, hi * s) for s in sigmas) / len(sigmas)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rt")
    ap.add_argument("runs", help="a runs.tsv from tests/perf/target_error/bench.sh")
    ap.add_argument("--seeds", type=int, default=16)
    ap.add_argument("--count", choices=["smallest", "largest"], default="smallest")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--work", default="/tmp/raybook-oracle")
    ap.add_argument("--reuse", action="store_true", help="keep renders already in --work")
    a = ap.parse_args()
    work = Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    reached = tightest(a.runs)
    print("| scene | oracle, any E | with the pilot, at E | the design, at E | E | sigma from |")
    print("|---|---:|---:|---:|---:|---:|")
    for scene, size, counts, args, uargs in bench_scenes():
        name = Path(scene).stem
        spp = counts[0] if a.count == "smallest" else counts[-1]
        if a.scenes and not re.search(a.scenes, name):
            continue
        sigmas = pixel_sigmas(os.path.abspath(a.rt), scene, size, spp, args, uargs, a.seeds, work,
                              a.reuse)
        mean_sigma = sum(sigmas) / len(sigmas) / c4(a.seeds)
        mean_var = sum(s * s for s in sigmas) / len(sigmas)
        oracle = mean_sigma**2 / mean_var
        floor = design = error = "-"
        if name in reached:
            e, ratio = reached[name]
            floor = f"{with_floor(sigmas, e * e) / (mean_var / (e * e)):.2f}"
            design, error = f"{ratio:.2f}", f"{e:.4g}"
        print(f"| {name} | {oracle:.2f} | {floor} | {design} | {error} | {a.seeds} x {spp} |",
              flush=True)


if __name__ == "__main__":
    main()
