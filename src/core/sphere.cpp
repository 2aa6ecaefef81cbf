#include "core/sphere.h"


namespace rb {


// [sphere-intersect]
bool Sphere::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    // [exercise-ray-sphere]
    // Exercise 1.1, the ray–sphere quadratic: read ch01-equations.
    // Blank: return false;
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
    hit.primitive = 0;
    return true;
    // [exercise-ray-sphere]
}
// [sphere-intersect]


}  // namespace rb
