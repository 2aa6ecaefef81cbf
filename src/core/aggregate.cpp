#include "core/aggregate.h"

namespace rb {

// [linear-intersect]
bool LinearAggregate::intersect(const Ray& ray, double tMax, Hit& hit) const {
    // Test every instance, shrinking tMax so that each later test only looks for closer hits.
    const Instance* closest = nullptr;
    ObjectHit best;
    for (const Instance& instance : instances_) {
        ObjectHit oh;
        if (instance.intersect(ray, tMax, oh)) {
            tMax = oh.t;
            best = oh;
            closest = &instance;
        }
    }
    if (closest) hit = closest->toWorld(ray, best);
    return closest != nullptr;
}
// [linear-intersect]

bool LinearAggregate::occluded(const Ray& ray, double tMax) const {
    for (const Instance& instance : instances_)
        if (instance.occluded(ray, tMax)) return true;
    return false;
}

std::unique_ptr<Aggregate> buildLinearAggregate(const std::vector<Instance>& instances) {
    return std::make_unique<LinearAggregate>(instances);
}

}  // namespace rb
