/// \file
/// Helpers shared by the chapter chart programs (make charts): the CPU clock, a scene file
/// built into a world as `rt` builds it, timed renders, and two renders side by side.
#pragma once

#include <time.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "core/feature.h"
#include "core/image.h"
#include "core/render.h"
#include "core/world.h"
#include "scene/lua_scene.h"

namespace rbchart {

/// The CPU time of the whole process (all threads), in seconds: a busy shared machine disturbs
/// it less than wall-clock time.
inline double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// Load the scene file `path` and build the world of its first gr.render call with
/// rb::buildWorld, as `rt` does; `featureOptions` are the chapters' --name=value options.
inline std::unique_ptr<rb::World> loadWorld(
    const std::string& path, const rb::FeatureSet& features,
    const std::map<std::string, std::string>& featureOptions = {}) {
    auto renders = rb::loadScene(path, features, rb::SceneLoadOptions{});
    return rb::buildWorld(std::move(renders.at(0)), features, featureOptions);
}

/// Render a world through its gr.render camera at width × height with the given seed and
/// samples per pixel, on all cores; `seconds` gets the CPU time the render took.
inline rb::Image renderTimed(const rb::World& w, int width, int height, std::uint64_t seed, int spp,
                             double& seconds) {
    const rb::PinholeCamera camera(w.source.job.camera, width, height);
    rb::RenderSettings settings;
    settings.seed = seed;
    settings.samplesPerPixel = spp;
    rb::RayCounters counters;
    const double t0 = cpuSeconds();
    rb::Image image = rb::render(w.scene, w.pipeline, camera, width, height, settings, counters);
    seconds = cpuSeconds() - t0;
    return image;
}

/// The pixel-by-pixel mean of two renders of one size.
inline rb::Image meanImage(const rb::Image& a, const rb::Image& b) {
    rb::Image mean(a.width(), a.height());
    for (size_t i = 0; i < a.data().size(); ++i)
        mean.data()[i] = 0.5f * (a.data()[i] + b.data()[i]);
    return mean;
}

/// Two renders of one size side by side, with a white gap of 4 pixels, written as a PNG.
inline void sideBySide(const rb::Image& left, const rb::Image& right, const std::string& path) {
    const int w = left.width(), h = left.height(), gap = 4;
    rb::Image both(2 * w + gap, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            both.set(x, y, left.get(x, y));
            both.set(w + gap + x, y, right.get(x, y));
        }
        for (int x = w; x < w + gap; ++x) both.set(x, y, rb::Colour(1.0));
    }
    rb::writePng(both, path);
}

}  // namespace rbchart
