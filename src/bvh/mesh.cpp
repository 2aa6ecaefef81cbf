#include "bvh/mesh.h"

#include <cmath>
#include <limits>

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
    // Keep the texture coordinates of every triangle, by OBJ index, when the file has any.
    if (!data.texcoords.empty()) {
        texcoords_.reserve(data.triangles.size());
        for (const auto& c : data.triangles) {
            TriangleTexcoords t;
            if (c[0].vt < 0 || c[1].vt < 0 || c[2].vt < 0) {
                t.uv.fill(Vec2(std::numeric_limits<double>::quiet_NaN()));
            } else {
                for (int k = 0; k < 3; ++k) t.uv[k] = data.texcoords[c[k].vt];
                // Solve p1 − p0 = Δu1·dp/du + Δv1·dp/dv and p2 − p0 likewise (Cramer's rule).
                const Vec3 dp1 = data.positions[c[1].v] - data.positions[c[0].v];
                const Vec3 dp2 = data.positions[c[2].v] - data.positions[c[0].v];
                const Vec2 duv1 = t.uv[1] - t.uv[0], duv2 = t.uv[2] - t.uv[0];
                const double det = duv1.x * duv2.y - duv1.y * duv2.x;
                if (det != 0.0 && std::isfinite(1.0 / det)) {
                    t.dpdu = (duv2.y * dp1 - duv1.y * dp2) / det;
                    t.dpdv = (duv1.x * dp2 - duv2.x * dp1) / det;
                }
            }
            texcoords_.push_back(t);
        }
    }
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

const TriangleTexcoords* Mesh::texcoords(std::uint32_t triangle) const {
    if (triangle >= texcoords_.size() || std::isnan(texcoords_[triangle].uv[0].x)) return nullptr;
    return &texcoords_[triangle];
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
    hit.uv = Vec2(best.b1, best.b2);  // barycentrics; chapter 10 turns them into `vt` (u, v)
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
