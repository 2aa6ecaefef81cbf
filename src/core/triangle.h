/// \file
/// Watertight ray–triangle intersection (Woop, Benthin and Wald 2013).
#pragma once

#include "core/ray.h"

namespace rb {

/// A ray prepared for the watertight test: a permutation that makes z the dominant axis of
/// the direction, and a shear that turns the direction into +z.
struct WatertightRay {
    Vec3 o;
    int kx, ky, kz;
    double Sx, Sy, Sz;
    /// Prepare ray r.
    explicit WatertightRay(const Ray& r);
};

/// The result of a triangle test: distance and barycentrics (b0 for p0, b1 for p1, b2 for p2).
struct TriangleHit {
    double t;
    double b0, b1, b2;
};

/// Does the ray hit triangle (p0, p1, p2) at some t in (0, tMax)? Either side counts (no
/// back-face culling). Watertight: a ray through a shared edge hits at least one of the two
/// triangles, and a degenerate triangle is never hit.
bool intersectTriangle(const WatertightRay& ray, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                       double tMax, TriangleHit& hit);

}  // namespace rb
