#include "quadrics/cylinder.h"

#include <limits>

#include "core/sphere.h"

namespace rb {

// [cylinder-side]
SideSpans cylinderSideSpans(const Ray& ray) {
    SideSpans spans;
    // [exercise-cylinder-side]
    // Exercise 15.1, the cylinder side quadratic: read ch15-cylinder.
    // Blank: return spans;
    // Compute the quadratic coefficients of (o_x + t·d_x)² + (o_z + t·d_z)² = 1 (with b = 2h):
    // chapter 1's unit sphere with y dropped, a unit circle in the xz plane.
    const Vec3 o(ray.o.x, 0.0, ray.o.z), d(ray.d.x, 0.0, ray.d.z);
    const double a = glm::dot(d, d);
    const double c = glm::dot(o, o) - 1.0;
    if (a == 0.0) {
        // Parallel to the axis: inside everywhere or nowhere.
        if (c <= 0.0)
            spans.add(-std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity());
        return spans;
    }
    const double h = glm::dot(o, d);
    const Vec3 f = o - (h / a) * d;  // axis-to-closest-point vector, in the xz plane
    // Chapter 1's cancellation-free solver: the same roots, accurate when the ray starts far.
    double t0, t1;
    if (solveQuadraticHalfB(a, h, c, f, t0, t1)) spans.add(t0, t1);
    return spans;
    // [exercise-cylinder-side]
}
// [cylinder-side]

int Cylinder::crossings(const Ray& ray, std::array<QuadricCrossing, 2>& out) const {
    if (isDegenerateDirection(ray.d)) return 0;
    const SideSpans side = cylinderSideSpans(ray);
    return capped() ? solidCrossings(ray, side, out) : openCrossings(ray, side, out);
}

// [cylinder-normal]
Vec3 Cylinder::normal(const Vec3& p, QuadricPart part) const {
    if (part == QuadricPart::Bottom) return Vec3(0.0, -1.0, 0.0);
    if (part == QuadricPart::Top) return Vec3(0.0, 1.0, 0.0);
    // ∇(x² + z² − 1)/2: straight out from the axis.
    return Vec3(p.x, 0.0, p.z);
}
// [cylinder-normal]

}  // namespace rb
