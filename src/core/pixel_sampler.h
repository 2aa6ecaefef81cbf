/// \file
/// The pixel sampler: the extension point chapter 8's supersampling plugs into.
#pragma once

#include <cstdint>

#include "core/camera.h"
#include "core/image.h"
#include "core/integrator.h"
#include "core/interrupt.h"
#include "core/render.h"
#include "core/stats.h"

namespace rb {

/// Decides where the camera rays of a pixel go and how their radiance becomes the pixel's
/// colour. Without one the core traces one ray through each pixel centre (or `--spp` random
/// positions). It renders a whole tile at a time, so it may share samples between the pixels
/// of the tile; for bit-identical images on any thread count, a pixel's colour must depend only
/// on (seed, pixel position), never on which tile or thread computes it. When the pipeline has a
/// camera-ray generator (chapter 13's lens), a sampler turns each image position into a ray
/// through it, naming the ray's RaySlot, and traces at least its raysPerPixel() rays.
class PixelSampler {
  public:
    virtual ~PixelSampler() = default;
    /// Render the pixels of `tile` of a width × height image into `image`, tracing camera rays
    /// with `integrator` and counting them into `rays`. After each pixel it calls
    /// stop.afterPixel(rays.total()), which throws when the render is to stop (Ctrl-C,
    /// --time-limit).
    virtual void renderTile(const ImageTile& tile, const Integrator& integrator,
                            const PinholeCamera& camera, int width, int height, std::uint64_t seed,
                            Image& image, RayCounters& rays, PixelStop& stop) const = 0;
};

}  // namespace rb
