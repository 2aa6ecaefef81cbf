/// \file
/// The unit sphere: centre at the origin, radius 1 (A4's gr.sphere).
#pragma once

#include "core/shape.h"

namespace rb {

/// Roots of a·t² + 2·h·t + c = 0 in increasing order; false when there are none.
/// Uses the cancellation-free form, so it stays accurate when the ray starts far away.
bool solveQuadraticHalfB(double a, double h, double c, const Vec3& f, double& t0, double& t1);

/// The unit sphere at the origin. Other spheres are this one under a transform.
class Sphere final : public Shape {
  public:
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    AABB bounds() const override { return AABB{Vec3(-1.0), Vec3(1.0)}; }
};

/// Sphere texture coordinates: u = φ/2π about +y, v = θ/π from +y (seed 000's convention).
Vec2 sphereUV(const Vec3& pObject);

}  // namespace rb
