/// \file
/// The unit cube from (0,0,0) to (1,1,1) (A4's gr.cube; gr.nh_box is this cube transformed).
#pragma once

#include <algorithm>

#include "core/shape.h"

namespace rb {

/// The axis-aligned unit cube [0,1]³.
class Box final : public Shape {
  public:
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    AABB bounds() const override { return AABB{Vec3(0.0), Vec3(1.0)}; }
    bool convex() const override { return true; }
    double depthInside(const Vec3& p) const override {
        const Vec3 toFace = glm::min(p, Vec3(1.0) - p);
        return std::max(0.0, std::min({toFace.x, toFace.y, toFace.z}));
    }
};

}  // namespace rb
