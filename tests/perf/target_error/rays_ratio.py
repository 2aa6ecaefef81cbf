#!/usr/bin/env python3
"""Rays at equal error: what a target-error render traced against uniform sampling (issue 38).

usage: rays_ratio.py RT RUNS_TSV

Times on a shared machine move with its load; the rays a render traces do not. For every render
of a target-error bench run (tests/perf/target_error/bench.sh's runs.tsv), this runs the same
render again with --stats, reads its total rays, fits a log-log line through the uniform
renders' (rays, measured error) points as equal_error.py fits times, and prints each adaptive
render's rays over uniform sampling's at its measured error. RT must be the binary the bench
ran (the errors are read from RUNS_TSV's images).
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import equal_error  # noqa: E402
import oracle  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]


def total_rays(rt, scene, size, extra):
    """The `(total N)` of --stats' rays line for one render (seed 1, 2 threads, as the bench)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = subprocess.run([rt, "--quiet", "--stats", "--threads", "2", "--size", size,
                              "--seed", "1", "--output", str(Path(tmp) / "render.hdr"), *extra,
                              scene], cwd=ROOT, capture_output=True, text=True)
    found = re.search(r"\(total (\d+)\)", out.stdout + out.stderr)
    if not found:
        sys.exit(f"rays_ratio: no ray count from {rt} {scene}:\n{out.stderr}")
    return int(found.group(1))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rt, runs = sys.argv[1], sys.argv[2]
    scenes = {Path(s).stem: (s, size, args, uargs)
              for s, size, _, args, uargs in oracle.bench_scenes()}
    print("| scene | E | measured error | rays | uniform sampling's rays at that error | ratio |")
    print("|---|---|---|---:|---:|---:|")
    for name, scene_runs in equal_error.read_runs(runs).items():
        scene, size, args, uargs = scenes[name]
        equal_error.measure(scene_runs)
        uniform = [(total_rays(rt, scene, size, ["--spp", r.setting, *args, *uargs]), r.corrected)
                   for r in scene_runs if r.kind == "uniform" and r.corrected]
        if len(uniform) < 2:
            continue
        fit = equal_error.loglog_fit(uniform)
        for r in scene_runs:
            if r.kind != "adaptive" or not r.corrected:
                continue
            rays = total_rays(rt, scene, size, ["--target-error", r.setting, *args])
            needed = equal_error.time_at_error(fit, r.corrected)
            print(f"| {name} | {r.setting} | {r.corrected:.5f} | {rays} | {needed:.0f} | "
                  f"{rays / needed:.3f} |")


if __name__ == "__main__":
    main()
