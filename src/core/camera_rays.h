/// \file
/// The camera-ray generator: the extension point chapter 13's thin lens plugs into.
#pragma once

#include <cstdint>

#include "core/camera.h"
#include "core/sampler.h"

namespace rb {

/// Which of a pixel's camera rays this is. A pixel sampler that places `count` rays in `count`
/// strata of the pixel numbers them 0 … count − 1, so that a generator can pair strata of its
/// own (on the lens) with the pixel's, one each, instead of multiplying the two counts.
struct RaySlot {
    std::uint64_t seed = 0;   ///< --seed.
    std::uint64_t pixel = 0;  ///< The pixel's key in rb::Sampler (y · width + x).
    int index = 0;            ///< This ray: 0 … count − 1.
    int count = 1;            ///< How many rays the pixel sampler traces for this pixel.
};

/// Turns an image position into a camera ray. Without one the core uses the pinhole camera's
/// generateRay; chapter 13 installs a thin lens.
class CameraRayGenerator {
  public:
    virtual ~CameraRayGenerator() = default;
    /// The fewest rays per pixel it needs; pixel samplers trace at least this many.
    virtual int raysPerPixel() const = 0;
    /// The camera ray through image position `film` (in pixels, as PinholeCamera::generateRay
    /// takes it), for ray `slot` of its pixel, drawing its random numbers from `sampler`.
    virtual Ray generate(const PinholeCamera& camera, const Vec2& film, const RaySlot& slot,
                         Sampler& sampler) const = 0;
};

}  // namespace rb
