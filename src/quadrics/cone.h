/// \file
/// The unit cone of chapter 15: a base of radius 1 at y = −1 narrowing to the apex at y = +1
/// (height 2, like the cylinder), or a frustum cut off at y = +1 with a top radius r₁ < 1;
/// capped by its disks or open.
#pragma once

#include "quadrics/quadric.h"

namespace rb {

/// Roots of A·t² + 2·H·t + C = 0, given disc = H² − A·C computed without cancellation, in
/// increasing order; returns how many (0, 1 when A = 0, or 2). A may be negative or zero.
int quadraticRoots(double A, double H, double C, double disc, std::array<double, 2>& roots);

/// The radius r(y) = a + b·y of a cone with radius 1 at y = −1 and topRadius at y = +1.
struct ConeProfile {
    double a, b;
    /// The profile through radius 1 at the bottom and topRadius at the top.
    explicit ConeProfile(double topRadius)
        : a(0.5 * (1.0 + topRadius)), b(0.5 * (topRadius - 1.0)) {}
};

/// Where the line o + t·d is inside the double cone x² + z² ≤ (a + b·y)²: one interval, two
/// rays (a line steeper than the cone runs through both nappes) or nothing.
SideSpans coneSideSpans(const Ray& ray, const ConeProfile& profile);

/// The cone x² + z² = (a + b·y)², −1 ≤ y ≤ 1; other cones are this one under a transform.
class Cone final : public Quadric {
  public:
    /// A cone with radius 1 at y = −1 and `topRadius` (0 for a pointed cone, up to 1) at
    /// y = +1; capped (solid) or open.
    explicit Cone(double topRadius = 0.0, bool capped = true)
        : Quadric(capped), topRadius_(topRadius), profile_(topRadius) {}
    int crossings(const Ray& ray, std::array<QuadricCrossing, 2>& out) const override;
    Vec3 normal(const Vec3& p, QuadricPart part) const override;
    double radiusSlope() const override { return profile_.b; }
    /// The radius at y = +1 (0: a pointed cone).
    double topRadius() const { return topRadius_; }

  private:
    double topRadius_;
    ConeProfile profile_;
};

}  // namespace rb
