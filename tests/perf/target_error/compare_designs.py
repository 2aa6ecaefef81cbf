"""Two or more target-error designs against each other at equal error: the runs of bench.sh,
one run per binary, compared by the time each design's adaptive renders take to reach the same
measured error. The time ratio against uniform sampling (equal_error.py) depends on the error
it is read at, and two designs given the same targets reach different errors; this compares
them at the same ones.

usage: python3 compare_designs.py [--samples] LABEL=RUNS.tsv LABEL=RUNS.tsv ...
  RUNS.tsv   bench.sh's BUILD_DIR/bench/target-error/runs.tsv (its images must still be there)
  --samples  compare mean samples per pixel (pilot included) instead of seconds: free of the
             machine's noise, blind to what a sample costs

Per scene, at three errors: the loosest and the tightest that every design's adaptive renders
reached (corrected errors, as equal_error.py measures them against each run's own reference),
and their geometric mean. Each design's time there is read off the straight line in log-log
between its two renders that bracket it. Prints a Markdown table of each design's time over
the first design's (below 1: faster than the first).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from equal_error import measure, read_runs  # noqa: E402


def adaptive_points(runs, samples):
    """(corrected error, seconds or mean samples) of the adaptive renders, in order of error."""
    measure(runs)
    return sorted((r.corrected, r.mean_spp if samples else r.seconds) for r in runs
                  if r.kind == "adaptive" and r.corrected is not None)


def time_at(points, error):
    """The time at `error`, log-log between the two points that bracket it."""
    for (e0, t0), (e1, t1) in zip(points, points[1:]):
        if e0 <= error <= e1:
            f = math.log(error / e0) / math.log(e1 / e0) if e1 != e0 else 0.0
            return math.exp(math.log(t0) + f * math.log(t1 / t0))
    raise ValueError("error outside the points")


def main():
    args = sys.argv[1:]
    samples = "--samples" in args
    designs = [arg.split("=", 1) for arg in args if arg != "--samples"]
    if len(designs) < 2 or any(len(d) != 2 for d in designs):
        sys.exit(__doc__.split("\n\n")[1])
    runs = {label: read_runs(path) for label, path in designs}
    labels = [label for label, _ in designs]
    print("| scene | error | " + " | ".join(labels) + " |")
    print("|---|---|" + "---:|" * len(labels))
    for scene in runs[labels[0]]:
        points = {label: adaptive_points(runs[label][scene], samples) for label in labels}
        loosest = min(p[-1][0] for p in points.values())
        tightest = max(p[0][0] for p in points.values())
        if tightest > loosest:
            print(f"| {scene} | no error all reached | " + " | ".join("-" for _ in labels) + " |")
            continue
        for error in (loosest, math.sqrt(loosest * tightest), tightest):
            times = [time_at(points[label], error) for label in labels]
            cells = " | ".join(f"{t / times[0]:.2f}" for t in times)
            print(f"| {scene} | {error:.4f} | {cells} |")


if __name__ == "__main__":
    main()
