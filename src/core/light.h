/// \file
/// The A4 point light: a position, a colour and a quadratic falloff.
#pragma once

#include "core/vec.h"

namespace rb {

/// A point light whose intensity at distance r is colour / (c0 + c1·r + c2·r²).
struct PointLight {
    Vec3 position{0.0};
    Colour colour{1.0};
    Vec3 falloff{1.0, 0.0, 0.0};  ///< (c0, c1, c2).

    /// The light's intensity after falloff at distance r.
    Colour intensityAt(double r) const {
        return colour / (falloff.x + falloff.y * r + falloff.z * r * r);
    }
};

}  // namespace rb
