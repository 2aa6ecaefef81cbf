/// \file
/// The unit cube from (0,0,0) to (1,1,1) (A4's gr.cube; gr.nh_box is this cube transformed).
#pragma once

#include "core/shape.h"

namespace rb {

/// The axis-aligned unit cube [0,1]³.
class Box final : public Shape {
  public:
    bool intersect(const Ray& ray, double tMax, ObjectHit& hit) const override;
    AABB bounds() const override { return AABB{Vec3(0.0), Vec3(1.0)}; }
    bool convex() const override { return true; }
};

}  // namespace rb
