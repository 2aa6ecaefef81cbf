/// \file
/// The render loop: one or more samples per pixel, in parallel over rows with OpenMP.
#pragma once

#include <cstdint>

#include "core/camera.h"
#include "core/image.h"
#include "core/integrator.h"

namespace rb {

/// How to sample the image.
struct RenderSettings {
    int threads = 0;          ///< 0: all cores.
    std::uint64_t seed = 0;   ///< Selects the random stream (--seed).
    int samplesPerPixel = 1;  ///< 1: one ray through each pixel centre, as A4 does.
    bool progress = false;    ///< Draw a progress bar with an ETA on stderr.
};

/// Render an image of the scene through the camera. Counts rays into `counters`.
Image render(const Scene& scene, const Pipeline& pipeline, const PinholeCamera& camera, int width,
             int height, const RenderSettings& settings, RayCounters& counters);

}  // namespace rb
