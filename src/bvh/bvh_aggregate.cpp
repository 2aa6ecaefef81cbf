#include "bvh/bvh_aggregate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bvh/float_rounding.h"
#include "bvh/mesh.h"

namespace rb {

namespace {

/// The box around every instance of `pool` but the one at `skip`.
AABB boundsOf(const std::vector<const Instance*>& pool, size_t skip) {
    AABB box;
    for (size_t i = 0; i < pool.size(); ++i)
        if (i != skip) box.extend(pool[i]->worldBounds);
    return box;
}

}  // namespace

BVHAggregate::BVHAggregate(const std::vector<Instance>& instances, BVHLayout layout,
                           size_t binaryUpTo, size_t flatUpTo)
    : asked_(layout == BVHLayout::Wide8 && !wide8Available() ? BVHLayout::Wide4 : layout) {
    // Step 1: take the large instances out, largest first, while one's box has
    // kLargeInstanceArea times the area of the box around the rest.
    std::vector<const Instance*> rest;
    for (const Instance& i : instances) rest.push_back(&i);
    while (outside_.size() < kMaxLargeInstances && rest.size() > 1) {
        size_t largest = 0;
        for (size_t i = 1; i < rest.size(); ++i)
            if (rest[i]->worldBounds.halfArea() > rest[largest]->worldBounds.halfArea())
                largest = i;
        if (!(rest[largest]->worldBounds.halfArea() >=
              kLargeInstanceArea * boundsOf(rest, largest).halfArea()))
            break;
        outside_.push_back(rest[largest]);
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(largest));
    }
    largeCount_ = outside_.size();
    // Step 2: a few instances left join them (a tree over them would cost more than their
    // boxes); more get the tree.
    if (rest.size() <= flatUpTo) {
        outside_.insert(outside_.end(), rest.begin(), rest.end());
        return;
    }
    std::vector<AABB> boxes;
    boxes.reserve(rest.size());
    for (const Instance* i : rest) boxes.push_back(i->worldBounds);
    if (rest.size() <= binaryUpTo) layout = BVHLayout::Binary;
    bvh_.build(boxes, BVHBuildOptions{16, 2, 1.0, layout});
    for (std::uint32_t p : bvh_.primitiveOrder()) ordered_.push_back(rest[p]);
}

// [toplevel-intersect]
[[gnu::always_inline]] inline bool BVHAggregate::closestAmong(const Instance* const* instances,
                                                              std::uint32_t count, const Ray& ray,
                                                              double& tClosest, ObjectHit& best,
                                                              const Instance*& closest) const {
    bool found = false;
    for (std::uint32_t k = 0; k < count; ++k) {
        const Instance* instance = instances[k];
        // After a hit, also look at exactly its distance: two instances hit at the same t
        // (faces that touch) go to the one that comes first in the scene, as testing every
        // instance in scene order would find, whatever order they are tested in.
        const double limit = closest ? nextUp(tClosest) : tClosest;
        ObjectHit oh;
        if (!instance->intersect(ray, limit, oh)) continue;
        if (oh.t == tClosest && closest && instance > closest) continue;
        tClosest = oh.t;
        best = oh;
        closest = instance;
        found = true;
    }
    return found;
}

bool BVHAggregate::intersect(const Ray& ray, double tMax, Hit& hit) const {
    const Instance* closest = nullptr;
    ObjectHit best;
    // The instances outside the tree first, each behind its own box: their hit, if any,
    // shortens the ray through the tree.
    if (!outside_.empty()) {
        const RayInverse ri(ray);
        for (const Instance* instance : outside_) {
            double tEntry;
            if (intersectBox(instance->worldBounds, ri, tMax, tEntry))
                closestAmong(&instance, 1, ray, tMax, best, closest);
        }
    }
    bvh_.closest(
        ray, tMax,
        [&](std::uint32_t first, std::uint32_t count, double& tClosest)
            __attribute__((always_inline)) {
                return closestAmong(ordered_.data() + first, count, ray, tClosest, best, closest);
            });
    if (closest) hit = closest->toWorld(ray, best);
    return closest != nullptr;
}
// [toplevel-intersect]

bool BVHAggregate::occluded(const Ray& ray, double tMax) const {
    if (!outside_.empty()) {
        const RayInverse ri(ray);
        for (const Instance* instance : outside_) {
            double tEntry;
            if (intersectBox(instance->worldBounds, ri, tMax, tEntry) &&
                instance->occluded(ray, tMax))
                return true;
        }
    }
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
    std::vector<const Instance*> all = outside_;
    all.insert(all.end(), ordered_.begin(), ordered_.end());
    for (const Instance* i : all)
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
    if (!ordered_.empty() && bvh_.layout() != asked_)
        out += std::string(" (top level ") + bvhLayoutDescription(bvh_.layout()) + ": " +
               std::to_string(ordered_.size()) + " instances)";
    if (largeCount_ > 0)
        out += "; " + std::to_string(largeCount_) + " large instance" +
               (largeCount_ > 1 ? "s" : "") + " outside the tree";
    if (const size_t few = outside_.size() - largeCount_; few > 0)
        out += few == 1 ? "; no top-level tree: the other instance is tested behind its box"
                        : "; no top-level tree: the other " + std::to_string(few) +
                              " instances are tested behind their boxes";
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
