#include "bvh/bvh_aggregate.h"

#include <algorithm>
#include <cstdio>

#include "bvh/mesh.h"

namespace rb {

BVHAggregate::BVHAggregate(const std::vector<Instance>& instances) {
    std::vector<AABB> boxes;
    boxes.reserve(instances.size());
    for (const Instance& i : instances) boxes.push_back(i.worldBounds);
    bvh_.build(boxes, BVHBuildOptions{16, 2, 1.0});
    for (std::uint32_t p : bvh_.primitiveOrder()) ordered_.push_back(&instances[p]);
}

// [toplevel-intersect]
bool BVHAggregate::intersect(const Ray& ray, double tMax, Hit& hit) const {
    const Instance* closest = nullptr;
    ObjectHit best;
    bvh_.closest(ray, tMax, [&](std::uint32_t slot, double& tClosest) {
        ObjectHit oh;
        if (!ordered_[slot]->intersect(ray, tClosest, oh)) return false;
        tClosest = oh.t;
        best = oh;
        closest = ordered_[slot];
        return true;
    });
    if (closest) hit = closest->toWorld(ray, best);
    return closest != nullptr;
}
// [toplevel-intersect]

bool BVHAggregate::occluded(const Ray& ray, double tMax) const {
    return bvh_.any(ray, tMax,
                    [&](std::uint32_t slot, double t) { return ordered_[slot]->occluded(ray, t); });
}

std::string BVHAggregate::statistics() const {
    // Count each mesh once, however many instances share it (a smooth mesh counts the
    // faceted mesh it wraps).
    size_t nodes = bvh_.nodes().size(), bytes = bvh_.nodeBytes() + bvh_.wideNodeBytes();
    size_t triangles = 0, triangleBytes = 0, meshBvhBytes = 0;
    std::vector<const Mesh*> seen;
    for (const Instance* i : ordered_)
        if (const Mesh* mesh = i->shape->triangleMesh())
            if (std::find(seen.begin(), seen.end(), mesh) == seen.end()) {
                seen.push_back(mesh);
                nodes += mesh->bvh().nodes().size();
                meshBvhBytes += mesh->bvh().nodeBytes() + mesh->bvh().wideNodeBytes();
                triangles += mesh->triangleCount();
                triangleBytes += mesh->triangleBytes();
            }
    bytes += meshBvhBytes;
    char line[256];
    std::snprintf(line, sizeof line, "%zu nodes, %.2f MiB", nodes, bytes / 1048576.0);
    std::string out = line;
    if (triangles) {
        std::snprintf(line, sizeof line, "; %zu triangles: %.1f bytes/triangle (mesh) + %.1f (BVH)",
                      triangles, double(triangleBytes) / triangles,
                      double(meshBvhBytes) / triangles);
        out += line;
    }
    return out;
}

std::unique_ptr<Aggregate> buildBVHAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<BVHAggregate>(instances);
}

}  // namespace rb
