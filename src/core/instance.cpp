#include "core/instance.h"

namespace rb {

// [normal-transform]
void Instance::setTransform(const Mat4& m) {
    objectToWorld = m;
    worldToObject = glm::inverse(m);
    // [exercise-normal-transform]
    // Exercise 2.2, transforming normals: read ch02-equations.
    // Blank: normalToWorld = Mat3(objectToWorld);
    // Normals transform by the inverse transpose, so they stay perpendicular to the surface
    // under non-uniform scale.
    normalToWorld = glm::transpose(Mat3(worldToObject));
    // [exercise-normal-transform]
    worldBounds = shape->bounds().transformed(m);
}
// [normal-transform]

// [instance-to-world]
Hit Instance::toWorld(const Ray& worldRay, const ObjectHit& oh) const {
    Hit hit;
    hit.t = oh.t;
    hit.p = worldRay.o + oh.t * worldRay.d;
    hit.ng = glm::normalize(normalToWorld * oh.n);
    hit.ns = hit.ng;
    hit.uv = oh.uv;
    hit.primitive = oh.primitive;
    hit.material = oh.material ? oh.material : material;
    hit.instance = this;
    return hit;
}
// [instance-to-world]

}  // namespace rb
