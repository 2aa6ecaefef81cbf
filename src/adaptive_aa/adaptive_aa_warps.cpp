/// \file
/// Chapter 8's samplers in the sampling lab: where jitteredPixel (exercise 8.1) and
/// randomPixel place a pixel's rays. Both must spread them uniformly over the pixel (density 1
/// on the unit square); the lab records the positions they hand to the radiance function.
#include "adaptive_aa/supersampling.h"
#include "lab/warp.h"

namespace rb {

namespace {

/// The domain of positions within a pixel.
WarpDomain pixelDomain() {
    return {0.0, 1.0, 0.0, 1.0, "x within the pixel", "y within the pixel"};
}

/// A pixel estimator's sample positions, relative to its pixel, over as many pixels as it
/// takes to reach `count`.
template <typename Estimator>
void drawPixelPositions(std::uint64_t count, std::uint64_t seed, int perPixel,
                        std::vector<Vec2>& points, Estimator estimator) {
    for (std::uint64_t index = 0; index * perPixel < count; ++index) {
        // Pixels along a row of a wide image, so every pixel has its own key.
        const PixelRef pixel{static_cast<int>(index % 4096), static_cast<int>(index / 4096), seed,
                             index};
        estimator(pixel, [&](const Vec2& p, const RaySlot&, Sampler&) {
            points.push_back({p.x - pixel.x, p.y - pixel.y});
            return Colour(0.0);
        });
    }
}

Warp jitteredWarp() {
    Warp w;
    w.name = "jittered";
    w.chapter = 8;
    w.title = "jittered supersampling: one uniform position in each of n × n cells of the pixel";
    w.exercise = "8.1";
    w.parameters = {{"n", 4, 1, 64, "cells per side (n × n rays per pixel)"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const int n = static_cast<int>(v.at("n"));
        WarpSetup s;
        s.domain = pixelDomain();
        s.caption = std::to_string(n) + " × " + std::to_string(n) + " rays per pixel";
        s.draw = [n](std::uint64_t count, std::uint64_t seed, std::vector<Vec2>& points) {
            drawPixelPositions(count, seed, n * n, points,
                               [n](const PixelRef& pixel, const RadianceAt& radiance) {
                                   jitteredPixel(pixel, n, radiance);
                               });
        };
        s.pdf = [](const Vec2&) { return 1.0; };
        return s;
    };
    return w;
}

Warp randomWarp() {
    Warp w;
    w.name = "random";
    w.chapter = 8;
    w.title = "random supersampling (seed 000's, --spp N): N independent uniform positions";
    w.exercise = "";
    w.parameters = {{"count", 16, 1, 4096, "rays per pixel"}};
    w.setup = [](const std::map<std::string, double>& v) {
        const int count = static_cast<int>(v.at("count"));
        WarpSetup s;
        s.domain = pixelDomain();
        s.caption = std::to_string(count) + " rays per pixel";
        s.draw = [count](std::uint64_t total, std::uint64_t seed, std::vector<Vec2>& points) {
            drawPixelPositions(total, seed, count, points,
                               [count](const PixelRef& pixel, const RadianceAt& radiance) {
                                   randomPixel(pixel, count, radiance);
                               });
        };
        s.pdf = [](const Vec2&) { return 1.0; };
        return s;
    };
    return w;
}

}  // namespace

/// Chapter 8's samplers for ./rt --warptest.
std::vector<Warp> adaptiveAaWarps() {
    return {jitteredWarp(), randomWarp()};
}

}  // namespace rb
