/// \file
/// Axis-aligned bounding boxes and the slab test.
#pragma once

#include <limits>

#include "core/ray.h"

namespace rb {

/// An axis-aligned box [lo, hi]; empty when lo > hi.
struct AABB {
    Vec3 lo{std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity()};

    /// Grow to contain point p.
    void extend(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    /// Grow to contain box b.
    void extend(const AABB& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    /// True when no point has been added.
    bool empty() const { return lo.x > hi.x; }
    /// The box centre.
    Vec3 centre() const { return 0.5 * (lo + hi); }
    /// Half the surface area (the SAH only needs ratios).
    double halfArea() const {
        if (empty()) return 0.0;
        const Vec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
    /// The bounds of this box after an affine transform (all eight corners).
    AABB transformed(const Mat4& m) const {
        AABB out;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 c(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                         corner & 4 ? hi.z : lo.z);
            out.extend(transformPoint(m, c));
        }
        return out;
    }
};

/// A ray prepared for many box tests: the reciprocal direction (±infinity where a component
/// is ±0) and the sign of each component.
struct RayInverse {
    Vec3 o;
    Vec3 invD;
    int dirIsNeg[3];
    explicit RayInverse(const Ray& r) : o(r.o) {
        for (int i = 0; i < 3; ++i) {
            invD[i] = 1.0 / r.d[i];
            dirIsNeg[i] = std::signbit(invD[i]);
        }
    }
};

// [slab-test]
/// The slab test: does the ray enter the box for some t in (0, tMax)? Sets tEntry when it does.
[[gnu::always_inline]] inline bool intersectBox(const AABB& b, const RayInverse& ri, double tMax,
                                                double& tEntry) {
    // Intersect the three pairs of parallel planes, near plane first by the direction's sign.
    // The far distances, and tMax, are widened by a few ulps so that rounding never misses a
    // box that is hit, even exactly at tMax (a tie with the closest hit so far).
    constexpr double widen = 1.0 + 8.0 * std::numeric_limits<double>::epsilon();
    double t0 = 0.0, t1 = tMax * widen;
    for (int axis = 0; axis < 3; ++axis) {
        const double tNear = ((ri.dirIsNeg[axis] ? b.hi : b.lo)[axis] - ri.o[axis]) * ri.invD[axis];
        double tFar = ((ri.dirIsNeg[axis] ? b.lo : b.hi)[axis] - ri.o[axis]) * ri.invD[axis];
        tFar *= widen;
        // Written so a NaN leaves the interval alone: a ray parallel to a slab and starting
        // exactly on its plane gives 0·∞ = NaN, and the slab then counts as closed, the same
        // rule the Box shape uses.
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
        if (t0 > t1) return false;
    }
    tEntry = t0;
    return true;
}
// [slab-test]

}  // namespace rb
