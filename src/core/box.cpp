#include "core/box.h"

namespace rb {

// [box-intersect]
bool Box::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    // [exercise-box-slabs]
    // Exercise 1.3, the ray–box slab test: read ch01-equations.
    // Blank: return false;
    if (isDegenerateDirection(ray.d)) return false;
    // Clip the ray against each slab 0 ≤ x_axis ≤ 1, remembering which face bounds the interval.
    double tEnter = -std::numeric_limits<double>::infinity();
    double tExit = std::numeric_limits<double>::infinity();
    int enterAxis = -1, exitAxis = -1;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.o[axis], d = ray.d[axis];
        if (d == 0.0) {
            // Parallel to this slab: inside it everywhere or nowhere.
            if (o < 0.0 || o > 1.0) return false;
            continue;
        }
        double tNear = (0.0 - o) / d, tFar = (1.0 - o) / d;
        if (tNear > tFar) std::swap(tNear, tFar);
        if (tNear > tEnter) {
            tEnter = tNear;
            enterAxis = axis;
        }
        if (tFar < tExit) {
            tExit = tFar;
            exitAxis = axis;
        }
        if (tEnter > tExit) return false;
    }
    // Take the entry face when it is ahead of the origin, else the exit face (ray starts inside).
    double t;
    int axis;
    if (tEnter > 0.0) {
        t = tEnter;
        axis = enterAxis;
    } else {
        t = tExit;
        axis = exitAxis;
    }
    if (t <= 0.0 || t >= tMax || axis < 0) return false;
    // The outward normal of the face: −axis on the 0 face, +axis on the 1 face.
    const Vec3 p = ray.o + t * ray.d;
    hit.t = t;
    hit.n = Vec3(0.0);
    hit.n[axis] = p[axis] > 0.5 ? 1.0 : -1.0;
    // Face coordinates: the two other axes, in [0,1].
    hit.uv = Vec2(p[(axis + 1) % 3], p[(axis + 2) % 3]);
    hit.primitive = static_cast<std::uint32_t>(axis);
    return true;
    // [exercise-box-slabs]
}
// [box-intersect]

}  // namespace rb
