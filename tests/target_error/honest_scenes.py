"""The error rt --target-error reports is the error its picture has, on every Monte Carlo
chapter's scene (CTest: target_error_scenes).

For each chapter scene that draws random numbers (6, 7, 13, 16, 17, 18) at a small size:
a reference in which every pixel takes the same R fresh samples (--min-spp R --max-spp R, so
that no sample count depends on the samples), with its own reported error; then the scene
rendered to two targets with four seeds each. The measured squared error of each render is its
mean squared difference from the reference (linear radiance from .hdr files, every channel of
every pixel) less the reference's own reported squared error; over a scene's four renders, the
root of the summed measured over the summed reported must lie within ±25%.

Usage: python3 tests/target_error/honest_scenes.py RT_BINARY OUT_DIR
Prints one line per scene and target, then "N passed, M failed"; exits 1 on any failure.
"""

import math
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from hdr_read import read_hdr  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
# Scene: (size, reference samples per pixel, the two targets, more options). The targets are
# each scene's own scale of noise, a tenth to a twentieth of its brightest colours; the
# reference's own error is at most about half the smaller target. Photon mapping's final
# gather of 32 rays makes its samples the dearest (0.4 ms each): here it gathers 4.
SCENES = {
    "chapter06-soft-shadows": ("32x24", 256, (0.02, 0.01), []),
    "chapter07-glossy": ("32x24", 256, (0.04, 0.02), []),
    "chapter13-depth-of-field": ("40x30", 512, (0.05, 0.025), []),
    "chapter16-photon-mapping": ("32x24", 128, (0.04, 0.02), ["--photon-gather=4"]),
    "chapter17-media": ("40x30", 256, (0.02, 0.012), []),
    "chapter18-path-tracing": ("40x30", 1024, (0.1, 0.05), []),
}


def render(rt, scene, size, out, *args):
    """Render `scene` at `size` to `out` (.hdr) with `args`; return the error --stats reports."""
    result = subprocess.run([rt, "--quiet", "--stats", "--size", size, "--output", str(out),
                             *args, str(scene)], capture_output=True, text=True, cwd=ROOT)
    if result.returncode != 0:
        raise RuntimeError(f"rt failed on {scene}: {result.stderr.strip()[-500:]}")
    found = re.search(r"estimated RMS error ([0-9.eE+-]+)", result.stderr)
    if not found:
        raise RuntimeError(f"no estimated error in --stats for {scene}")
    return float(found.group(1))


def mean_squared_difference(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)


def main():
    rt, out = sys.argv[1], Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    passed = failed = 0
    for name, (size, samples, targets, options) in SCENES.items():
        scene = ROOT / "scenes" / f"{name}.lua"
        ref_path = out / f"{name}-reference.hdr"
        ref_error = render(rt, scene, size, ref_path, *options, "--target-error", "1",
                           "--min-spp", str(samples), "--max-spp", str(samples), "--seed", "1000")
        ref = read_hdr(ref_path).pixels
        for target in targets:
            measured = reported = 0.0
            for seed in (1, 2, 3, 4):
                path = out / f"{name}-{target}-{seed}.hdr"
                error = render(rt, scene, size, path, *options, "--target-error", str(target),
                               "--seed", str(seed))
                measured += mean_squared_difference(read_hdr(path).pixels, ref) - ref_error ** 2
                reported += error ** 2
            ratio = math.sqrt(max(measured, 0.0) / reported)
            ok = 0.75 <= ratio <= 1.25
            passed, failed = passed + ok, failed + (not ok)
            print(f"{'ok  ' if ok else 'FAIL'} {name} E = {target}: measured "
                  f"{math.sqrt(max(measured, 0) / 4):.4g}, reported {math.sqrt(reported / 4):.4g}"
                  f" (ratio {ratio:.2f}, allowed 0.75 to 1.25; reference's own error "
                  f"{ref_error:.3g})", flush=True)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
