/// \file
/// The image post-process: the extension point chapter 12's tone mapping plugs into.
#pragma once

#include <cstdint>

#include "core/image.h"

namespace rb {

/// Turns the finished film (linear radiance, any value ≥ 0) into the image that is written.
/// It runs once, after the render and before the 8-bit output is encoded; without one the
/// core writes the film as the CS488 framework does (each channel clamped to [0, 1]).
class PostProcess {
  public:
    virtual ~PostProcess() = default;
    /// Replace the film's pixels by their display values in [0, 1].
    virtual void apply(Image& film) const = 0;
    /// The working memory apply() allocates per pixel, beyond the film itself: the core checks
    /// it against the memory budget (--max-memory) before the render starts.
    virtual std::uint64_t bytesPerPixel() const = 0;
};

}  // namespace rb
