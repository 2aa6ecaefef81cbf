#include "core/sphere.h"

#include <glm/gtc/constants.hpp>

namespace rb {

// [stable-quadratic]
bool solveQuadraticHalfB(double a, double h, double c, const Vec3& f, double& t0, double& t1) {
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

// [sphere-intersect]
bool Sphere::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    if (isDegenerateDirection(ray.d)) return false;
    // Compute the quadratic coefficients of |o + t·d|² = 1 (with b = 2h).
    const double a = glm::dot(ray.d, ray.d);
    const double h = glm::dot(ray.o, ray.d);
    const double c = glm::dot(ray.o, ray.o) - 1.0;
    const Vec3 f = ray.o - (h / a) * ray.d;  // centre-to-closest-point vector
    double t0, t1;
    if (!solveQuadraticHalfB(a, h, c, f, t0, t1)) return false;
    // Take the nearest root in (0, tMax): t0 from outside, t1 from inside.
    double t = t0;
    if (t <= 0.0) t = t1;
    if (t <= 0.0 || t >= tMax) return false;
    hit.t = t;
    hit.n = ray.o + t * ray.d;  // on the unit sphere the point is its own normal
    hit.uv = sphereUV(hit.n);
    hit.primitive = 0;
    return true;
}
// [sphere-intersect]

Vec2 sphereUV(const Vec3& p) {
    const double phi = std::atan2(-p.z, p.x);  // azimuth about +y, in (−π, π]
    const double theta = std::acos(std::clamp(p.y / glm::length(p), -1.0, 1.0));
    const double u = (phi < 0.0 ? phi + 2.0 * glm::pi<double>() : phi) / (2.0 * glm::pi<double>());
    return {u, theta / glm::pi<double>()};
}

}  // namespace rb
