#!/usr/bin/env python3
"""The Monte Carlo golden images' round trip (issue 21): make check and make grade compare a
chapter whose image depends on sampling choices statistically (src/app/block_stats.h), so
that any correct solution passes, however it draws its random numbers, and a biased one fails.

For each chapter below, a project is exported (chapters 1..N), solved with raybook's code, and
each planted solution put into its exercise region in turn: its rt_chN is rebuilt and the
chapter's golden image checked as make check does (run_golden.sh --statistical). A correct
solution that draws differently must pass; each biased one must fail. Builds share objects
through ccache (objcache.py without it), as the assignments' round trip does.

usage: python3 tests/exercises/mc_golden.py WORK_DIR [--chapters 13 ...]
"""
import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))
import regions as rg  # noqa: E402

# Planted solutions: (what it is, should it pass, exercise region id, its code). Each is a
# student's own way of writing the exercise, not raybook's code.
BALL_CONE = (
    "const double sin2ThetaMax = (R / d) * (R / d); "
    "const double cosThetaMax = std::sqrt(std::max(0.0, 1.0 - sin2ThetaMax)); "
    "const double oneMinusCosThetaMax = sin2ThetaMax / (1.0 + cosThetaMax); "
    "const double oneMinusCosTheta = {ONE_MINUS_COS}; "
    "const double cosTheta = 1.0 - oneMinusCosTheta; "
    "const double sin2Theta = oneMinusCosTheta * (2.0 - oneMinusCosTheta); "
    "const double cosAlpha = sin2Theta / (R / d) + cosTheta * std::sqrt(std::max(0.0, 1.0 - "
    "sin2Theta / sin2ThetaMax)); "
    "const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha)); "
    "const double phi = 2.0 * glm::pi<double>() * {PHI}; "
    "const Vec3 w = toP / d; Vec3 t, b; orthonormalBasis(w, t, b); "
    "const Vec3 x = centre + R * (sinAlpha * std::cos(phi) * t + sinAlpha * std::sin(phi) * b + "
    "cosAlpha * w); "
    "const Vec3 fromP = x - p; "
    "weight = {FACTOR} * oneMinusCosThetaMax * glm::dot(fromP, fromP) / (R * R); return x;")


def ball_cone(one_minus_cos: str, phi: str, factor: str) -> str:
    """Exercise 6.2 written out, with the cone's draw and the weight's factor as given."""
    return (BALL_CONE.replace("{ONE_MINUS_COS}", one_minus_cos).replace("{PHI}", phi)
            .replace("{FACTOR}", factor))


PLANTED = {
    6: [
        ("6.1 with the panel's strata turned a quarter (uniform, stratified)", True,
         "rectangle-sample",
         "const Vec2 q = unitSquareSample(k, n, u, sampling_); const Vec2 s(1.0 - q.y, q.x); "
         "const Vec3 x = centre + ((s.x - 0.5) * length_) * left_ + ((s.y - 0.5) * width_) * up_; "
         "const Vec3 toP = p - x; const double r = glm::length(toP); "
         "weight = r > 0.0 ? std::max(0.0, glm::dot(normal_, toP) / r) : 0.0; return x;"),
        ("6.2 drawing the cone's angle from the second number and the turn from the first",
         True, "ball-sample", ball_cone("s.y * oneMinusCosThetaMax", "s.x", "2.0")),
        ("6.1 without the panel's cos theta (every point weighs 1)", False, "rectangle-sample",
         "const Vec2 s = unitSquareSample(k, n, u, sampling_); "
         "weight = 1.0; return centre + ((s.x - 0.5) * length_) * left_ + "
         "((s.y - 0.5) * width_) * up_;"),
        ("6.2 with the cone's solid angle 2 pi (1 - cos) taken as pi (1 - cos)", False,
         "ball-sample", ball_cone("s.x * oneMinusCosThetaMax", "s.y", "1.0")),
    ],
    # Chapter 7's scene draws its lobes with the Phong sampler (7.1); the fuzz ball (7.2, seed
    # 000's "glossy") does not change its image, so only the unit tests see 7.2.
    7: [
        ("7.1 inverting the CDF with u1 in place of 1 - u1 (uniform the same)", True,
         "phong-lobe",
         "const double cosAlpha = std::pow(std::max(u1, 1e-300), 1.0 / (exponent + 1.0)); "
         "const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha)); "
         "const double phi = 2.0 * kPi * (1.0 - u2); "
         "return Frame(axis).toWorld(Vec3(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), "
         "cosAlpha));"),
        ("7.1 with cos alpha uniform (the lobe's exponent forgotten)", False, "phong-lobe",
         "const double cosAlpha = 1.0 - u1; "
         "const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha)); "
         "const double phi = 2.0 * kPi * u2; "
         "return Frame(axis).toWorld(Vec3(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), "
         "cosAlpha));"),
    ],
    13: [
        ("13.3 with another per-pixel key and a rotation for its shuffle", True,
         "stratified-lens",
         "const int rows = strataRows(slot.count), cols = slot.count / rows; "
         "const std::uint64_t key = mix64(slot.pixel * 0x9e3779b97f4a7c15ULL + slot.seed + 17); "
         "const auto cell = static_cast<std::uint32_t>((slot.index + key % slot.count) % slot.count); "
         "const Vec2 xi = sampler.next2D(); "
         "return {((cell % cols) + xi.x) / cols, ((cell / cols) + xi.y) / rows};"),
        ("13.2 as the polar map r = sqrt(u), phi = 2 pi v (uniform, other strata)", True,
         "concentric-disk",
         "const double r = std::sqrt(u.x), phi = 2.0 * glm::pi<double>() * u.y; "
         "return {r * std::cos(phi), r * std::sin(phi)};"),
        ("13.1 with the aperture's diameter used as its radius", False, "thin-lens-ray",
         "const Vec2 lens = settings_.aperture * aperturePoint(settings_.shape, u); "
         "const Vec3 offset = lens.x * camera.right() + lens.y * camera.upVector(); "
         "const Vec3 d = camera.filmDirection(film.x, film.y); "
         "return Ray{camera.eye() + offset, glm::normalize(d - offset / settings_.focusDistance)};"),
        ("13.2 without 2u - 1 (the concentric map of [0, 1]^2: a quarter of the disk)", False,
         "concentric-disk",
         "const double a = u.x, b = u.y; if (a == 0.0 && b == 0.0) return Vec2(0.0); "
         "const double q = 0.25 * glm::pi<double>(); double r, phi; "
         "if (std::abs(a) > std::abs(b)) { r = a; phi = q * (b / a); } "
         "else { r = b; phi = 2.0 * q - q * (a / b); } "
         "return {r * std::cos(phi), r * std::sin(phi)};"),
        ("13.2 as the polar map with r = u (not uniform: crowded at the centre)", False,
         "concentric-disk",
         "const double r = u.x, phi = 2.0 * glm::pi<double>() * u.y; "
         "return {r * std::cos(phi), r * std::sin(phi)};"),
        ("13.3 with every ray in the pixel's first lens stratum", False, "stratified-lens",
         "const int rows = strataRows(slot.count), cols = slot.count / rows; "
         "const Vec2 xi = sampler.next2D(); return {xi.x / cols, xi.y / rows};"),
    ],
    18: [
        ("18.1 as the balance heuristic (unbiased, a little more noise)", True,
         "power-heuristic",
         "if (std::isinf(pdfA)) return 1.0; "
         "return pdfA + pdfB > 0.0 ? pdfA / (pdfA + pdfB) : 0.0;"),
        ("18.3 choosing the lobe before drawing the direction (other numbers, same density)", True,
         "bsdf-sample",
         "const bool diffuse = sampler.next1D() < diffuseShare_; const Vec2 w = sampler.next2D(); "
         "out.wi = diffuse ? sampleCosineHemisphere(n_, w.x, w.y) "
         ": samplePhongLobe(mirrored(wo_, n_), m_.shininess, w.x, w.y); "
         "out.delta = false; out.pdf = pdf(out.wi); if (!(out.pdf > 0.0)) return false; "
         "out.weight = f(out.wi) * glm::dot(out.wi, n_) / out.pdf; return true;"),
        ("18.1 weighing every sample 1 (light reaching a lamp by both techniques counted twice)",
         False, "power-heuristic", "return 1.0;"),
        ("18.4 with the lamp's cos theta_l left out of the density per steradian", False,
         "light-sampling",
         "const double u = sampler.next1D(); const EmitterSample e = emitters_->sample(u, "
         "sampler.next2D()); const Vec3 toLight = e.p - v.p; "
         "const double distance2 = glm::dot(toLight, toLight); if (!(distance2 > 0.0)) return L; "
         "const Vec3 wi = toLight / std::sqrt(distance2); "
         "const double pdfLight = e.pdfArea * distance2; const Colour f = v.scatter(wi); "
         "if (f == Colour(0.0)) return L; const Vec3 target = offsetRayOrigin(e.p, e.n, -wi); "
         "if (integrator.occluded(Ray{v.shadowOrigin, target - v.shadowOrigin}, 1.0, counters)) "
         "return L; const double weight = settings_.strategy == PathStrategy::Mis ? "
         "powerHeuristic(pdfLight, v.pdf(wi)) : 1.0; return L + f * e.Le * (weight / pdfLight);"),
    ],
}


def run(command, cwd=None, env=None, timeout=1800):
    p = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=timeout)
    return p.returncode, p.stdout


def plant(project: Path, region_id: str, code: str | None) -> None:
    """Put `code` into the project's region (None: raybook's own code back)."""
    sys.path.insert(0, str(HERE))
    import assignment  # noqa: E402
    assignment.solve_regions(project, {region_id})
    if code is not None:
        region = next(r for r in rg.find_regions(project) if r.id == region_id)
        region.path.write_text(rg.replaced(region, code))


def check_chapter(n: int, work: Path) -> list[str]:
    # The layout of make check, the round trip's slots and make grade's staging folders
    # (PROJECT/build): ccache (or, without it, objcache.py with one $RB_OBJCACHE) gives each the
    # others' objects, and raybook's own build's. The export rewrites every file it holds and
    # removes the others (the build folder stays).
    project = work / f"ch{n:02d}" / "project"
    build = project / "build"
    env = dict(os.environ)
    script = str(HERE / "assignment.py")
    code, out = run([sys.executable, script, "export", str(n), str(project)], env=env)
    if code != 0:
        return [f"chapter {n}: export failed:\n{out[-1500:]}"]
    run([sys.executable, script, "solve", str(project)], env=env)
    configure = ["cmake", "-S", str(project), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"]
    if env.get("RB_COMPILER_LAUNCHER"):
        configure.append(f"-DCMAKE_CXX_COMPILER_LAUNCHER={env['RB_COMPILER_LAUNCHER']}")
    if env.get("RB_CMAKE_GENERATOR"):  # assignment.use_ninja()
        configure += ["-G", env["RB_CMAKE_GENERATOR"]]
        import assignment  # noqa: E402
        if assignment.cache_generator(build) not in (None, env["RB_CMAKE_GENERATOR"]):
            (build / "CMakeCache.txt").unlink()
    code, out = run(configure, env=env)
    if code != 0:
        return [f"chapter {n}: configure failed:\n{out[-1500:]}"]
    scene = json.loads((project / ".assignment.json").read_text())["scene"]
    problems = []
    cases = [("raybook's own solution", True, None, None)] + PLANTED[n]
    for what, should_pass, region_id, code_text in cases:
        if region_id:
            plant(project, region_id, code_text)
        code, out = run(["cmake", "--build", str(build), "-j", str(os.cpu_count() or 2),
                         "--target", f"rt_ch{n}"], env=env)
        if code != 0:
            problems.append(f"{what}: does not build:\n{out[-1500:]}")
        else:
            code, out = run(["bash", str(project / "tests/golden/run_golden.sh"),
                             str(build / f"rt_ch{n}"), scene, str(project / "golden"),
                             str(build / "golden-report"),
                             "--report-name=planted", "--statistical"], cwd=project, env=env)
            passed = code == 0
            verdict = out.strip().splitlines()[0] if out.strip() else "(no output)"
            ok = passed == should_pass
            print(f"  {'ok  ' if ok else 'FAIL'} {what}: {'passes' if passed else 'fails'}"
                  f" (should {'pass' if should_pass else 'fail'}): {verdict}", flush=True)
            if not ok:
                problems.append(f"{what}: {'passed' if passed else 'failed'}, should not")
        if region_id:
            plant(project, region_id, None)
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("work")
    parser.add_argument("--chapters", type=int, nargs="*", default=sorted(PLANTED))
    args = parser.parse_args()
    work = Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    import assignment  # noqa: E402
    assignment.use_compiler_cache(work / "objcache", work)  # the chapters' projects share objects
    assignment.use_ninja()
    failures = 0
    for n in args.chapters:
        start = time.monotonic()
        print(f"chapter {n}: Monte Carlo golden, planted solutions", flush=True)
        problems = check_chapter(n, work)
        for p in problems:
            print("  " + p.replace("\n", "\n  "))
        print(f"chapter {n}: {'ok' if not problems else 'FAIL'} "
              f"({time.monotonic() - start:.0f} s)", flush=True)
        failures += bool(problems)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
