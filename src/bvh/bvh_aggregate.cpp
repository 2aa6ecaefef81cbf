#include "bvh/bvh_aggregate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bvh/float_rounding.h"
#include "bvh/mesh.h"

namespace rb {

BVHAggregate::BVHAggregate(const std::vector<Instance>& instances, BVHLayout layout,
                           size_t binaryUpTo)
    : asked_(layout == BVHLayout::Wide8 && !wide8Available() ? BVHLayout::Wide4 : layout) {
    std::vector<AABB> boxes;
    boxes.reserve(instances.size());
    for (const Instance& i : instances) boxes.push_back(i.worldBounds);
    if (instances.size() <= binaryUpTo) layout = BVHLayout::Binary;
    bvh_.build(boxes, BVHBuildOptions{16, 2, 1.0, layout});
    for (std::uint32_t p : bvh_.primitiveOrder()) ordered_.push_back(&instances[p]);
}

// [toplevel-intersect]
bool BVHAggregate::intersect(const Ray& ray, double tMax, Hit& hit) const {
    const Instance* closest = nullptr;
    ObjectHit best;
    bvh_.closest(
        ray, tMax,
        [&](std::uint32_t first, std::uint32_t count, double& tClosest)
            __attribute__((always_inline)) {
                bool found = false;
                for (std::uint32_t slot = first; slot < first + count; ++slot) {
                    // After a hit, also look at exactly its distance: two instances hit at the same
                    // t (faces that touch) go to the one that comes first in the scene, as testing
                    // every instance in order would find, whatever order the tree visits them in.
                    const double limit = closest ? nextUp(tClosest) : tClosest;
                    ObjectHit oh;
                    if (!ordered_[slot]->intersect(ray, limit, oh)) continue;
                    if (oh.t == tClosest && closest && ordered_[slot] > closest) continue;
                    tClosest = oh.t;
                    best = oh;
                    closest = ordered_[slot];
                    found = true;
                }
                return found;
            });
    if (closest) hit = closest->toWorld(ray, best);
    return closest != nullptr;
}
// [toplevel-intersect]

bool BVHAggregate::occluded(const Ray& ray, double tMax) const {
    return bvh_.any(
        ray, tMax,
        [&](std::uint32_t first, std::uint32_t count, double t) __attribute__((always_inline)) {
            for (std::uint32_t slot = first; slot < first + count; ++slot)
                if (ordered_[slot]->occluded(ray, t)) return true;
            return false;
        });
}

std::string BVHAggregate::statistics() const {
    // Count each mesh once, however many instances share it (a smooth mesh counts the
    // faceted mesh it wraps).
    size_t nodes = bvh_.nodeCount(), bytes = bvh_.nodeBytes();
    size_t triangles = 0, triangleBytes = 0, meshBvhBytes = 0;
    std::vector<const Mesh*> seen;
    for (const Instance* i : ordered_)
        if (const Mesh* mesh = i->shape->triangleMesh())
            if (std::find(seen.begin(), seen.end(), mesh) == seen.end()) {
                seen.push_back(mesh);
                nodes += mesh->bvh().nodeCount();
                meshBvhBytes += mesh->bvh().nodeBytes();
                triangles += mesh->triangleCount();
                triangleBytes += mesh->triangleBytes();
            }
    bytes += meshBvhBytes;
    char line[256];
    std::snprintf(line, sizeof line, "%s BVH, %zu nodes, %.2f MiB", bvhLayoutDescription(asked_),
                  nodes, bytes / 1048576.0);
    std::string out = line;
    if (bvh_.layout() != asked_)
        out += std::string(" (top level ") + bvhLayoutDescription(bvh_.layout()) + ": " +
               std::to_string(ordered_.size()) + " instances)";
    if (triangles) {
        std::snprintf(line, sizeof line, "; %zu triangles: %.1f bytes/triangle (mesh) + %.1f (BVH)",
                      triangles, double(triangleBytes) / triangles,
                      double(meshBvhBytes) / triangles);
        out += line;
    }
    return out;
}

std::unique_ptr<Aggregate> buildBVHAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<BVHAggregate>(instances, bestWideLayout());
}

std::unique_ptr<Aggregate> buildWide4BVHAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<BVHAggregate>(instances, BVHLayout::Wide4);
}

std::unique_ptr<Aggregate> buildWide8BVHAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<BVHAggregate>(instances, BVHLayout::Wide8);
}

std::unique_ptr<Aggregate> buildBinaryBVHAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<BVHAggregate>(instances, BVHLayout::Binary);
}

}  // namespace rb
