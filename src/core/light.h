/// \file
/// The A4 point light: a position, a colour and a quadratic falloff.
#pragma once

#include <memory>

#include "core/vec.h"

namespace rb {

/// The extension point for lights with an area (chapter 6). A shaped light is sampled as
/// n × n stratified points, each shaded like a point light.
class LightShape {
  public:
    virtual ~LightShape() = default;
    /// Samples per axis the scene asked for (n × n in all).
    virtual int samplesPerAxis() const = 0;
    /// Point k of n × n on the light centred at `centre`, seen from `p`; u jitters it within
    /// its stratum. Writes the emission weight of that point towards p (1 for a uniform
    /// emitter, the cosine for a one-sided panel ...).
    virtual Vec3 samplePoint(const Vec3& centre, const Vec3& p, int k, int n, const Vec2& u,
                             double& weight) const = 0;
};

/// A point light whose intensity at distance r is colour / (c0 + c1·r + c2·r²).
struct PointLight {
    Vec3 position{0.0};
    Colour colour{1.0};
    Vec3 falloff{1.0, 0.0, 0.0};              ///< (c0, c1, c2).
    std::shared_ptr<const LightShape> shape;  ///< Null: a true point light (chapters 1–5).

    // [falloff]
    /// The light's intensity after falloff at distance r.
    Colour intensityAt(double r) const {
        const double attenuation = falloff.x + falloff.y * r + falloff.z * r * r;
        // A4's usual falloff (1, 0, 0): dividing by 1 changes nothing, so skip the divisions.
        if (attenuation == 1.0) return colour;
        return colour / attenuation;
    }
    // [falloff]
};

}  // namespace rb
