/// \file
/// The deterministic sampler: random numbers that depend only on (seed, pixel, sample, dimension).
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace rb {

/// A stateless 64-bit mixing function (SplitMix64's finaliser).
/// Source: Steele, Lea and Flood, "Fast Splittable Pseudorandom Number Generators", OOPSLA 2014.
inline std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// [sampler]
/// Uniform numbers in [0,1) for one pixel sample. Each call draws the next dimension.
/// Because a value depends only on (seed, pixel, sample, dimension) and never on the thread or
/// on what other pixels drew, an image is bit-identical for any thread count.
class Sampler {
  public:
    /// The stream for sample `sampleIndex` of pixel `pixelIndex`, under the global `seed`.
    Sampler(std::uint64_t seed, std::uint64_t pixelIndex, std::uint64_t sampleIndex)
        : key_(mix64(mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ pixelIndex) ^ sampleIndex)) {}

    /// The next dimension: a uniform double in [0, 1).
    double next1D() {
        const std::uint64_t bits = mix64(key_ + 0x9e3779b97f4a7c15ULL * ++dimension_);
        return static_cast<double>(bits >> 11) * 0x1.0p-53;  // top 53 bits → [0,1)
    }
    /// The next two dimensions.
    Vec2 next2D() {
        const double u = next1D();
        return {u, next1D()};
    }
    /// How many dimensions this stream has drawn.
    std::uint64_t dimension() const { return dimension_; }

  private:
    std::uint64_t key_;
    std::uint64_t dimension_ = 0;
};
// [sampler]

}  // namespace rb
