/// \file
/// Sampling routines photon emission uses, each next to its pdf: uniform directions on the
/// sphere, cosine-weighted directions on a hemisphere, uniform directions in a cone.
#pragma once

#include <cmath>

#include "core/vec.h"

namespace rb {

/// Two unit vectors that make (s, t, n) an orthonormal basis, for unit n.
/// Source: T. Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
inline void orthonormalBasis(const Vec3& n, Vec3& s, Vec3& t) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    s = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
}

// [sample-sphere]
/// A uniform direction on the unit sphere from (u1, u2) in [0, 1)².
inline Vec3 sampleUniformSphere(double u1, double u2) {
    const double z = 1.0 - 2.0 * u1;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * M_PI * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
/// The density of sampleUniformSphere over solid angle: 1 / 4π.
inline double uniformSpherePdf() {
    return 1.0 / (4.0 * M_PI);
}
// [sample-sphere]

// [sample-cosine]
/// A direction on the hemisphere around unit n, with density cosθ / π (Malley's method: a
/// uniform point on the unit disk, lifted onto the hemisphere).
inline Vec3 sampleCosineHemisphere(const Vec3& n, double u1, double u2) {
    const double r = std::sqrt(u1), phi = 2.0 * M_PI * u2;
    Vec3 s, t;
    orthonormalBasis(n, s, t);
    return r * std::cos(phi) * s + r * std::sin(phi) * t + std::sqrt(std::max(0.0, 1.0 - u1)) * n;
}
/// The density of sampleCosineHemisphere over solid angle at cosθ = d·n.
inline double cosineHemispherePdf(double cosTheta) {
    return std::max(0.0, cosTheta) / M_PI;
}
// [sample-cosine]

// [sample-cone]
/// A uniform direction within angle θmax of the unit axis (cosThetaMax = cos θmax).
inline Vec3 sampleUniformCone(const Vec3& axis, double cosThetaMax, double u1, double u2) {
    const double cosTheta = 1.0 - u1 * (1.0 - cosThetaMax);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * M_PI * u2;
    Vec3 s, t;
    orthonormalBasis(axis, s, t);
    return sinTheta * std::cos(phi) * s + sinTheta * std::sin(phi) * t + cosTheta * axis;
}
/// The solid angle of that cone, 2π(1 − cos θmax); its density is one over this.
inline double coneSolidAngle(double cosThetaMax) {
    return 2.0 * M_PI * (1.0 - cosThetaMax);
}
// [sample-cone]

}  // namespace rb
