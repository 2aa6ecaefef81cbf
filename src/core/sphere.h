/// \file
/// The unit sphere: centre at the origin, radius 1 (A4's gr.sphere).
#pragma once

#include <algorithm>

#include "core/shape.h"

namespace rb {

/// Roots of a·t² + 2·h·t + c = 0 in increasing order; false when there are none.
/// Uses the cancellation-free form, so it stays accurate when the ray starts far away.
// [stable-quadratic]
inline bool solveQuadraticHalfB(double a, double h, double c, const Vec3& f, double& t0,
                                double& t1) {
    // The discriminant h² − a·c loses all its digits when the ray starts far away, because
    // both terms grow like |o|². The equal quantity a·(1 − |f|²), with f the vector from the
    // centre to the ray's closest point, does not. Source: Haines et al., "Precision
    // Improvements for Ray/Sphere Intersection", Ray Tracing Gems (2019), ch. 7.
    const double disc = a * (1.0 - glm::dot(f, f));
    if (disc < 0.0) return false;
    const double rootDisc = std::sqrt(disc);
    // Compute the root away from cancellation first, then the other from the product c/a.
    const double q = -(h + std::copysign(rootDisc, h));
    if (q == 0.0) {
        t0 = t1 = 0.0;  // ray starts at the centre with zero direction: a degenerate ray
        return false;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}
// [stable-quadratic]

/// The unit sphere at the origin. Other spheres are this one under a transform.
class Sphere final : public Shape {
  public:
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    AABB bounds() const override { return AABB{Vec3(-1.0), Vec3(1.0)}; }
    bool convex() const override { return true; }
    double depthInside(const Vec3& p) const override { return std::max(0.0, 1.0 - glm::length(p)); }
};

}  // namespace rb
