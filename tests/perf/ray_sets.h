/// \file
/// The ray sets the BVH benchmarks trace: coherent camera rays, incoherent rays and shadow rays,
/// all made from a mesh's bounding box with a fixed seed (tests/perf only).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "core/aabb.h"
#include "core/sampler.h"

namespace rbperf {

/// One benchmark ray: origin, direction and the far end of its interval.
struct BenchRay {
    rb::Vec3 o, d;
    double tMax;
};

/// Coherent camera rays: a pinhole 1.6 bounding radii from the box centre, looking at it,
/// 45° vertical field of view, size × size pixels.
inline std::vector<BenchRay> cameraRays(const rb::AABB& box, int size) {
    const rb::Vec3 c = box.centre();
    const double radius = 0.5 * glm::length(box.hi - box.lo);
    const rb::Vec3 eye = c + rb::Vec3(0.0, 0.0, 1.6 * radius);
    const double half = std::tan(0.5 * glm::radians(45.0));
    std::vector<BenchRay> rays;
    rays.reserve(static_cast<size_t>(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double sx = (2.0 * (x + 0.5) / size - 1.0) * half;
            const double sy = (1.0 - 2.0 * (y + 0.5) / size) * half;
            rays.push_back({eye, glm::normalize(rb::Vec3(sx, sy, -1.0)), 1e30});
        }
    return rays;
}

/// Incoherent rays: origins uniform on a sphere of 2 bounding radii around the centre, each
/// aimed at a uniform random point in the box. tMax is the distance to that point, so the set
/// serves as shadow rays (any hit before the target); unbounded() makes closest-hit rays of it.
inline std::vector<BenchRay> incoherentRays(const rb::AABB& box, int count, std::uint64_t seed) {
    const rb::Vec3 c = box.centre();
    const double radius = 0.5 * glm::length(box.hi - box.lo);
    std::vector<BenchRay> rays;
    rays.reserve(count);
    for (int i = 0; i < count; ++i) {
        rb::Sampler s(seed, static_cast<std::uint64_t>(i), 0);
        // Uniform direction on the sphere: z uniform in [-1,1], φ uniform.
        const double z = 1.0 - 2.0 * s.next1D(), phi = 2.0 * M_PI * s.next1D();
        const double rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
        const rb::Vec3 o = c + 2.0 * radius * rb::Vec3(rxy * std::cos(phi), rxy * std::sin(phi), z);
        const rb::Vec3 target = box.lo + rb::Vec3(s.next1D(), s.next1D(), s.next1D()) * (box.hi - box.lo);
        const double dist = glm::length(target - o);
        rays.push_back({o, (target - o) / dist, dist});
    }
    return rays;
}

/// The same rays with no far end (tMax = infinity): closest-hit rays that go on past their
/// target point.
inline std::vector<BenchRay> unbounded(std::vector<BenchRay> rays) {
    for (auto& r : rays) r.tMax = std::numeric_limits<double>::infinity();
    return rays;
}

}  // namespace rbperf
