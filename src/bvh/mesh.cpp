#include "bvh/mesh.h"

#include "core/error.h"
#include "bvh/triangle.h"

namespace rb {

Mesh::Mesh(const ObjData& data, const std::string& name) {
    // Keep the triangles with non-zero area; a degenerate one can never be hit and has no
    // normal.
    std::vector<std::array<Vec3, 3>> kept;
    std::vector<std::uint32_t> keptSource;
    std::vector<AABB> boxes;
    for (size_t i = 0; i < data.triangles.size(); ++i) {
        const auto& c = data.triangles[i];
        const std::array<Vec3, 3> v{data.positions[c[0].v], data.positions[c[1].v],
                                    data.positions[c[2].v]};
        if (!(glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) > 0.0)) {
            ++dropped_;
            continue;
        }
        AABB box;
        for (const Vec3& p : v) box.extend(p);
        boxes.push_back(box);
        kept.push_back(v);
        keptSource.push_back(static_cast<std::uint32_t>(i));
    }
    if (kept.empty()) throw InputError(name + ": the mesh has no triangle with non-zero area");
    // Build the BVH (the boxes are freed inside), then store triangles in the order its leaves
    // visit them.
    bvh_.build(std::move(boxes));
    bounds_ = bvh_.nodes().front().bounds;
    const auto& order = bvh_.primitiveOrder();
    triangles_.reserve(order.size());
    source_.reserve(order.size());
    for (std::uint32_t p : order) {
        triangles_.push_back(kept[p]);
        source_.push_back(keptSource[p]);
    }
}

size_t Mesh::triangleBytes() const {
    return triangles_.size() * (sizeof(triangles_[0]) + sizeof(source_[0]));
}

// [mesh-intersect]
bool Mesh::intersect(const Ray& ray, double tMax, ObjectHit& hit) const {
    if (isDegenerateDirection(ray.d)) return false;
    const WatertightRay wray(ray);
    std::uint32_t hitSlot = 0;
    TriangleHit best{};
    const bool found = bvh_.closest(ray, tMax, [&](std::uint32_t slot, double& tClosest) {
        const auto& v = triangles_[slot];
        TriangleHit th;
        if (!intersectTriangle(wray, v[0], v[1], v[2], tClosest, th)) return false;
        tClosest = th.t;
        best = th;
        hitSlot = slot;
        return true;
    });
    if (!found) return false;
    const auto& v = triangles_[hitSlot];
    hit.t = best.t;
    hit.n = glm::cross(v[1] - v[0], v[2] - v[0]);  // geometric normal, by the winding
    hit.uv = Vec2(best.b1, best.b2);               // barycentrics until chapter 10
    hit.primitive = source_[hitSlot];
    return true;
}
// [mesh-intersect]

bool Mesh::occluded(const Ray& ray, double tMax) const {
    if (isDegenerateDirection(ray.d)) return false;
    const WatertightRay wray(ray);
    return bvh_.any(ray, tMax, [&](std::uint32_t slot, double t) {
        const auto& v = triangles_[slot];
        TriangleHit th;
        return intersectTriangle(wray, v[0], v[1], v[2], t, th);
    });
}

}  // namespace rb
