/// \file
/// Procedural height fields, defined in object space: a planar ramp (the tests' and the page's
/// reference), circular ripples (water), and fractal gradient noise (rough surfaces).
#pragma once

#include <cstdint>
#include <vector>

#include "bump/height_field.h"

namespace rb {

/// h(x) = slope · x: a plane tilted so that the height rises by |slope| per unit along slope.
/// Its surface gradient is the part of `slope` in the tangent plane, known exactly.
class RampHeight final : public HeightField {
  public:
    explicit RampHeight(const Vec3& slope) : slope_(slope) {}
    /// slope · x.
    double height(const Vec3& x) const override;
    /// 1 object unit (a ramp has no scale of its own).
    double featureSize() const override { return 1.0; }
    /// The ramp's gradient.
    const Vec3& slope() const { return slope_; }

  private:
    Vec3 slope_;
};

/// Ripples spreading from one or more centres: h(x) = Σ_c sin(2π |x − c| / λ) / √(1 + |x − c|/λ),
/// crests one wavelength λ apart whose height falls off with distance (as a ring wave's does,
/// by the square root, spreading its energy over a growing circle).
class RippleHeight final : public HeightField {
  public:
    /// Ripples of wavelength lambda (> 0) around each centre (at least one).
    RippleHeight(std::vector<Vec3> centres, double lambda)
        : centres_(std::move(centres)), lambda_(lambda) {}
    /// The sum of the centres' ring waves at x.
    double height(const Vec3& x) const override;
    /// The wavelength.
    double featureSize() const override { return lambda_; }
    /// The exact gradient of height() (for the tests and the chart, not for rendering).
    Vec3 exactGradient(const Vec3& x) const;

  private:
    std::vector<Vec3> centres_;
    double lambda_;
};

/// Fractal gradient noise with cells of `scale` object units: h(x) = fBm(x / scale).
class NoiseHeight final : public HeightField {
  public:
    /// Noise with cell size scale (> 0), `octaves` layers (1 to 8), and a seed.
    NoiseHeight(double scale, int octaves, std::uint32_t seed)
        : scale_(scale), octaves_(octaves), seed_(seed) {}
    /// fBm at x / scale.
    double height(const Vec3& x) const override;
    /// The cell size of the finest octave.
    double featureSize() const override;

  private:
    double scale_;
    int octaves_;
    std::uint32_t seed_;
};

}  // namespace rb
