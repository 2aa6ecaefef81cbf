/// \file
/// Chapter 7's two ways to spread a specular direction into a lobe, each next to its pdf:
/// seed 000's fuzz sphere and the importance-sampled Phong lobe.
#pragma once

#include "core/vec.h"

namespace rb {

/// An orthonormal frame (s, t, axis) around a unit vector.
struct Frame {
    Vec3 s, t, n;  ///< Two tangents and the axis.
    /// The frame around unit vector `axis`, without branches on its direction.
    explicit Frame(const Vec3& axis);
    /// Local coordinates (x, y, z) to world: x·s + y·t + z·n.
    Vec3 toWorld(const Vec3& local) const { return local.x * s + local.y * t + local.z * n; }
};

// ---- Glossiness → the two samplers' parameters ---------------------------------------------

/// The fuzz-sphere radius of a material of glossiness g: the glossiness *is* seed 000's fuzz.
inline double fuzzFromGlossiness(double glossiness) {
    return glossiness;
}

/// The Phong exponent n whose lobe has the same mean cosine as the fuzz sphere of radius f:
/// (n+1)/(n+2) = 1 − f²/5, so n = 5/f² − 2 (exact for f ≤ 1; clamped at 0 above √2.5).
double phongExponentFromFuzz(double fuzz);

// ---- Sampler 1: the fuzz sphere (seed 000, Ray Tracing in One Weekend) ---------------------

/// A uniform point in the unit ball from three uniform numbers.
Vec3 sampleUniformBall(double u1, double u2, double u3);

/// The fuzz sphere: normalize(axis + fuzz · b) with b uniform in the unit ball.
Vec3 sampleFuzzSphere(const Vec3& axis, double fuzz, double u1, double u2, double u3);
/// Its pdf per unit solid angle at a direction whose angle α to the axis has cosine cosAlpha.
double fuzzSpherePdf(double fuzz, double cosAlpha);

// ---- Sampler 2: the Phong lobe, importance sampled ------------------------------------------

/// A direction distributed ∝ cos^n α about the axis (α: angle to the axis).
Vec3 samplePhongLobe(const Vec3& axis, double exponent, double u1, double u2);
/// Its pdf per unit solid angle: (n+1)/(2π) · cos^n α for cos α ≥ 0, else 0.
double phongLobePdf(double exponent, double cosAlpha);

}  // namespace rb
