#!/usr/bin/env python3
"""The milk ball's error against render time (issue 36): tests/perf/ch17/milk.lua rendered at a
ladder of samples per pixel, each render's RMSE against a converged reference, and the time at
which the error reaches a target (0.01), interpolated on log-log axes.

usage: milk_convergence.py --rt BUILD/rt_ch18 --out DIR [options] [-- extra rt options]

  --scene FILE      another scene instead of the milk ball (chapter 17's own scene, to
                    compare two binaries at equal time: render the reference with the newer
                    one, then run the older one with the same DIR, which reuses it)
  --ref-seeds N     renders averaged into the reference (default 32), each --ref-spp samples
  --ref-spp N       samples per pixel of each reference render (default 256)
  --ref-args "..."  rt options for the reference only (default: --media-bounces 1000000,
                    so no path is cut short: the reference is the unbiased answer)
  --spp LIST        samples per pixel of the series (default 16,36,64,144,256: the jittered sampler takes square numbers)
  --seeds N         renders (seeds 1000...) per point; their MSEs and times are averaged
  --target E        the RMSE whose time is reported (default 0.01)
  --label NAME      the series' name in the table
  --fresh           render the reference again even when DIR holds one

The reference is kept in DIR/<scene>-reference.txt (one linear value per line, the mean of the
renders) and reused. Times are CPU seconds (user + system) of rt with --threads 1: on a shared
machine the wall time of a render swings with the load, its CPU time much less. Each point
also gives the render phase's wall seconds from --stats, for reference. Prints a table and a
line "target milk_time_to_E SECONDS" for make bench.
Source of the interpolation: between the two points that bracket the target, log RMSE is taken
as linear in log time (RMSE ~ t^-1/2 for an unbiased estimator); beyond the last point, the
last two points' slope (with one point, the slope -1/2).
"""
import argparse
import math
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from hdr_read import read_hdr  # noqa: E402  (tests/hdr_read.py)

ROOT = Path(__file__).resolve().parents[3]
SCENE = ROOT / "tests" / "perf" / "ch17" / "milk.lua"


def render(rt, scene, spp, seed, out, extra, threads=1):
    """Render `scene`; returns (linear pixels, CPU seconds, render wall seconds)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    cmd = [rt, "--quiet", "--stats", "--threads", str(threads), "--spp", str(spp), "--seed",
           str(seed), "--output", str(out)] + extra + [str(scene)]
    run = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if run.returncode != 0:
        sys.exit(f"milk_convergence: {' '.join(cmd)} failed:\n{run.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    wall = float("nan")
    for line in (run.stdout + run.stderr).splitlines():
        words = line.split()
        if words[:1] == ["time"] and "render" in words:
            wall = float(words[words.index("render") + 1])
    return read_hdr(str(out)).pixels, cpu, wall


def reference(args, tmp):
    """The mean of --ref-seeds renders, each --ref-spp samples a pixel (cached in DIR)."""
    path = Path(args.out) / f"{Path(args.scene).stem}-reference.txt"
    if path.exists() and not args.fresh:
        return [float(v) for v in path.read_text().split()]
    total = None
    for k in range(args.ref_seeds):
        pixels, cpu, _ = render(args.rt, args.scene, args.ref_spp, k + 1, tmp / "ref.hdr",
                                args.ref_args.split(), threads=args.ref_threads)
        total = pixels if total is None else [a + b for a, b in zip(total, pixels)]
        print(f"  reference render {k + 1}/{args.ref_seeds}: {cpu:.1f} CPU s", file=sys.stderr)
    mean = [v / args.ref_seeds for v in total]
    path.write_text("\n".join(f"{v:.9g}" for v in mean) + "\n")
    return mean


def time_to(points, target):
    """The time at which the RMSE reaches `target`, on log-log axes through `points`
    ((time, rmse) in order of time)."""
    logs = [(math.log(t), math.log(e)) for t, e in points]
    if len(logs) == 1:  # one point: RMSE ~ t^-1/2
        return math.exp(logs[0][0] + 2.0 * (logs[0][1] - math.log(target)))
    for (t0, e0), (t1, e1) in zip(logs, logs[1:]):
        if e0 >= math.log(target) >= e1 and e0 != e1:
            return math.exp(t0 + (math.log(target) - e0) * (t1 - t0) / (e1 - e0))
    (t0, e0), (t1, e1) = logs[-2], logs[-1]
    if e1 >= e0:
        return float("inf")
    return math.exp(t1 + (math.log(target) - e1) * (t1 - t0) / (e1 - e0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rt", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--scene", default=str(SCENE))
    parser.add_argument("--ref-seeds", type=int, default=32)
    parser.add_argument("--ref-spp", type=int, default=256)
    parser.add_argument("--ref-threads", type=int, default=2)
    parser.add_argument("--ref-args", default="--media-bounces 1000000")
    parser.add_argument("--spp", default="16,36,64,144,256")
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--target", type=float, default=0.01)
    parser.add_argument("--label", default="milk")
    parser.add_argument("--fresh", action="store_true")
    parser.add_argument("extra", nargs="*", help="rt options for the series")
    args = parser.parse_args()
    Path(args.out).mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="raybook-milk.") as tmpdir:
        tmp = Path(tmpdir)
        ref = reference(args, tmp)
        n = len(ref)
        print(f"{args.label}: RMSE against the reference ({args.ref_seeds} x {args.ref_spp} spp, "
              f"{args.ref_args}), {args.seeds} seeds a point, 1 thread; rt options: "
              f"{' '.join(args.extra) or '(none)'}")
        print(f"  {'spp':>5} {'CPU s':>8} {'render s':>9} {'RMSE':>8}")
        points = []
        for spp in [int(s) for s in args.spp.split(",")]:
            mse = cpu = wall = 0.0
            for seed in range(1000, 1000 + args.seeds):
                pixels, c, w = render(args.rt, args.scene, spp, seed, tmp / "x.hdr", args.extra)
                mse += sum((a - b) ** 2 for a, b in zip(pixels, ref)) / n
                cpu += c
                wall += w
            rmse = math.sqrt(mse / args.seeds)
            points.append((cpu / args.seeds, rmse))
            print(f"  {spp:>5} {cpu / args.seeds:>8.3f} {wall / args.seeds:>9.3f} {rmse:>8.5f}")
        t = time_to(points, args.target)
        print(f"  time to RMSE {args.target}: {t:.3f} CPU s")
        print(f"target milk_time_to_{args.target} {t:.4f}")


if __name__ == "__main__":
    main()
