/// \file
/// The unit cylinder of chapter 15: radius 1 about the y axis, from y = −1 to y = +1 (height 2,
/// seed 001's default), capped by two disks or open at both ends.
#pragma once

#include "quadrics/quadric.h"

namespace rb {

/// Where the line o + t·d is inside the infinite cylinder x² + z² ≤ 1: one interval, the
/// whole line (parallel to the axis, inside it) or nothing.
SideSpans cylinderSideSpans(const Ray& ray);

/// The cylinder x² + z² = 1, −1 ≤ y ≤ 1; other cylinders are this one under a transform.
class Cylinder final : public Quadric {
  public:
    /// A capped (solid) cylinder, or an open tube when `capped` is false.
    explicit Cylinder(bool capped = true) : Quadric(capped) {}
    int crossings(const Ray& ray, std::array<QuadricCrossing, 2>& out) const override;
    Vec3 normal(const Vec3& p, QuadricPart part) const override;
};

}  // namespace rb
