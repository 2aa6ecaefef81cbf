/// \file
/// Rays, and how a ray leaving a surface is moved off it so it cannot hit that surface again.
#pragma once

#include "core/vec.h"

namespace rb {

/// A ray o + t·d for t in (0, tMax). The direction need not be unit length, so the same t
/// is valid after an affine transform into an object's space.
struct Ray {
    Vec3 o;  ///< Origin.
    Vec3 d;  ///< Direction (not necessarily normalised).
};

/// The relative size of the offset that lifts a spawned ray off a surface.
/// Rounding error in a hit point computed in double precision is a few ulps of the largest
/// coordinate involved (about 1e-16 relative); 1e-9 leaves a margin of ten million.
inline constexpr double kOffsetScale = 1e-9;

/// True when a direction cannot define a ray: zero, or with a NaN component.
inline bool isDegenerateDirection(const Vec3& d) {
    return !(glm::dot(d, d) > 0.0) || std::isnan(d.x) || std::isnan(d.y) || std::isnan(d.z);
}

// [offset-origin]
/// Move a new ray's origin p off the surface with geometric normal ng, to the side that the
/// direction dir leaves towards, so that the ray cannot re-hit the surface it starts on.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& ng, const Vec3& dir) {
    // The error of p scales with the magnitude of its coordinates, so the offset does too:
    // that keeps the test valid at every scene scale.
    const double offset = kOffsetScale * std::max(maxAbsComponent(p), 1e-300);
    const Vec3 push = ng * offset;
    return glm::dot(dir, ng) > 0.0 ? p + push : p - push;
}
// [offset-origin]

}  // namespace rb
