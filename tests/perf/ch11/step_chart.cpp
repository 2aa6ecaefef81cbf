// Chapter 11's chart: how the error of a bumped normal depends on the finite-difference step.
//
// Ripples (wavelength λ = 0.1, two centres) on the unit sphere, strength 0.005 (slopes up to
// about 0.3), at 2000 points spread over the sphere. For each step ε from 1e-10 λ to 0.3 λ, the
// angle between the numerically bumped normal and the exact one (normalize(n − a ∇h) with
// RippleHeight::exactGradient, projected on the tangent plane), as RMS and maximum over the
// points; once with central differences (bump/bump.cpp's surfaceGradient) and once with
// forward differences (for comparison; one height evaluation fewer per axis). Then the time of
// one Bump::perturb for ripples and for 4-octave noise, median of 7 runs.
//
// usage: ch11_step_chart OUT_DIR   writes OUT_DIR/step.dat and OUT_DIR/finding.txt
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <memory>
#include <string>
#include <vector>

#include "bump/bump.h"
#include "bump/procedural_heights.h"
#include "core/instance.h"
#include "core/sphere.h"

using rb::Vec3;

namespace {

/// The forward-difference surface gradient (error ∝ ε), for comparison with the chapter's
/// central differences.
Vec3 forwardGradient(const rb::HeightField& f, const Vec3& x, const Vec3& n, double step) {
    Vec3 t, b;
    rb::tangentFrame(n, t, b);
    const double h0 = f.height(x);
    return (f.height(x + step * t) - h0) / step * t + (f.height(x + step * b) - h0) / step * b;
}

/// Angle between unit vectors, stable for tiny angles.
double angle(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

/// Points spread evenly over the unit sphere (a Fibonacci spiral: deterministic).
std::vector<Vec3> spherePoints(int count) {
    std::vector<Vec3> points;
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(1.0 - z * z);
        points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return points;
}

/// Median nanoseconds per Bump::perturb over the points, 7 runs.
double nanosecondsPerNormal(const rb::Bump& bump, const std::vector<Vec3>& points) {
    rb::Sphere sphere;
    rb::Instance instance;
    instance.shape = &sphere;
    instance.setTransform(rb::Mat4(1.0));
    std::vector<double> runs;
    double sink = 0.0;
    for (int run = 0; run < 7; ++run) {
        const auto start = std::chrono::steady_clock::now();
        for (int repeat = 0; repeat < 50; ++repeat)
            for (const Vec3& p : points) {
                rb::Hit hit;
                hit.p = p;
                hit.ng = hit.ns = p;
                hit.instance = &instance;
                bump.perturb(rb::Ray{2.0 * p, -p}, hit);
                sink += hit.ns.x;
            }
        const std::chrono::duration<double, std::nano> took =
            std::chrono::steady_clock::now() - start;
        runs.push_back(took.count() / (50.0 * points.size()));
    }
    std::sort(runs.begin(), runs.end());
    if (sink == 12345.678) std::puts("");  // keep the work from being optimised away
    return runs[3];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ch11_step_chart OUT_DIR\n");
        return 2;
    }
    const std::string out = argv[1];
    const double lambda = 0.1, strength = 0.005;
    const rb::RippleHeight ripples({Vec3(0.3, 0.8, 0.52), Vec3(-0.6, 0.2, 0.77)}, lambda);
    const std::vector<Vec3> points = spherePoints(2000);

    std::ofstream dat(out + "/step.dat");
    dat << "# step/lambda  central_rms  central_max  forward_rms  forward_max (radians)\n";
    double bestRms = 1e300, bestStep = 0.0, defaultRms = 0.0, bestForward = 1e300;
    for (double e = -10.0; e <= -0.5 + 1e-9; e += 0.25) {
        const double step = std::pow(10.0, e) * lambda;
        double sumC = 0, maxC = 0, sumF = 0, maxF = 0;
        for (const Vec3& n : points) {
            const Vec3 g = ripples.exactGradient(n);
            const Vec3 exact = rb::bumpedNormal(n, g - glm::dot(g, n) * n, strength);
            const double c = angle(
                rb::bumpedNormal(n, rb::surfaceGradient(ripples, n, n, step), strength), exact);
            const double f =
                angle(rb::bumpedNormal(n, forwardGradient(ripples, n, n, step), strength), exact);
            sumC += c * c;
            sumF += f * f;
            maxC = std::max(maxC, c);
            maxF = std::max(maxF, f);
        }
        const double rmsC = std::sqrt(sumC / points.size()), rmsF = std::sqrt(sumF / points.size());
        dat << std::pow(10.0, e) << ' ' << rmsC << ' ' << maxC << ' ' << rmsF << ' ' << maxF
            << '\n';
        if (rmsC < bestRms) bestRms = rmsC, bestStep = std::pow(10.0, e);
        bestForward = std::min(bestForward, rmsF);
        if (std::abs(e - std::log10(rb::kDefaultStepFraction)) < 1e-9) defaultRms = rmsC;
    }
    const rb::Bump rippleBump(std::make_shared<rb::RippleHeight>(ripples), strength);
    const rb::Bump noiseBump(std::make_shared<rb::NoiseHeight>(0.2, 4, 1), strength);
    const double nsRipple = nanosecondsPerNormal(rippleBump, points);
    const double nsNoise = nanosecondsPerNormal(noiseBump, points);

    std::ofstream finding(out + "/finding.txt");
    char text[800];
    std::snprintf(
        text, sizeof text,
        "With central differences the bumped normal's RMS error falls as the step squared "
        "to %.1e rad at a step of %.0e wavelengths and rises again below it as rounding "
        "takes over; raybook's default step (1e-3 wavelengths) gives %.1e rad, while "
        "forward differences never get below %.1e rad; a bumped normal costs %.0f ns with "
        "ripples and %.0f ns with 4-octave noise (one thread, median of 7 runs).\n",
        bestRms, bestStep, defaultRms, bestForward, nsRipple, nsNoise);
    finding << text;
    std::fputs(text, stdout);
    return 0;
}
