/// \file
/// Medium: what fills fog, a box of smoke or a glass of milk (chapter 17).
#pragma once

#include <algorithm>
#include <memory>
#include <string>

#include "core/vec.h"
#include "media/density.h"

namespace rb {

/// A participating medium: at a point p of its own space it absorbs σa·density(p) and scatters
/// σs·density(p) of the light per unit of world length, with a Henyey–Greenstein phase
/// function of asymmetry g. Coefficients are RGB, so a medium may tint what it lets through.
struct Medium {
    Colour sigmaA{0.0};  ///< Absorption coefficient at density 1, per unit length.
    Colour sigmaS{0.0};  ///< Scattering coefficient at density 1, per unit length.
    double g = 0.0;      ///< Phase asymmetry in (−1, 1): 0 isotropic, > 0 forward.
    std::shared_ptr<const DensityField> density;  ///< The medium's density field.
    std::string where;                            ///< The gr.medium call, for messages.

    /// Extinction at density 1: σt = σa + σs.
    Colour sigmaT() const { return sigmaA + sigmaS; }
    /// The largest channel of σt: with a density bound, a majorant for every channel.
    double sigmaTMax() const {
        const Colour t = sigmaT();
        return std::max({t.r, t.g, t.b});
    }
    /// True when the density is the same everywhere, so transmittance has a closed form.
    bool homogeneous() const { return density->constant(); }
};

/// Density 1 everywhere: a homogeneous medium.
class ConstantDensity final : public DensityField {
  public:
    double at(const Vec3&) const override { return 1.0; }
    double maxIn(const Vec3&, const Vec3&) const override { return 1.0; }
    AABB bounds() const override;
    bool constant() const override { return true; }
};

/// Procedural smoke from chapter 11's gradient noise:
/// density(p) = clamp(bias + gain·fBm(frequency·p), 0, 1).
class NoiseDensity final : public DensityField {
  public:
    NoiseDensity(double frequency, int octaves, double bias, double gain, std::uint32_t seed)
        : frequency_(frequency), octaves_(octaves), bias_(bias), gain_(gain), seed_(seed) {}
    double at(const Vec3& p) const override;
    /// The density's bound from the noise's interval over the box (media/noise_bound.h).
    double maxIn(const Vec3& lo, const Vec3& hi) const override;
    AABB bounds() const override;

  private:
    double frequency_;
    int octaves_;
    double bias_, gain_;
    std::uint32_t seed_;
};

}  // namespace rb
