/// \file
/// Vectors, colours and matrices: the GLM types every chapter shares.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace rb {

using Vec2 = glm::dvec2;    ///< A 2D vector or texture coordinate.
using Vec3 = glm::dvec3;    ///< A point, direction or normal in 3D.
using Colour = glm::dvec3;  ///< Linear RGB radiance or reflectance.
using Mat3 = glm::dmat3;    ///< A 3x3 matrix (normal transforms).
using Mat4 = glm::dmat4;    ///< A 4x4 affine transform.

/// The largest absolute component of v.
inline double maxAbsComponent(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

/// True when every component of v is a finite number.
inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Transform a point (w = 1) by an affine matrix.
inline Vec3 transformPoint(const Mat4& m, const Vec3& p) {
    return Vec3(m * glm::dvec4(p, 1.0));
}

/// Transform a direction (w = 0) by an affine matrix.
inline Vec3 transformVector(const Mat4& m, const Vec3& v) {
    return Vec3(m * glm::dvec4(v, 0.0));
}

}  // namespace rb
