#include "media/majorant_grid.h"

#include <algorithm>
#include <cmath>

namespace rb {

bool clipToBox(const Ray& ray, const AABB& box, double& tMin, double& tMax) {
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / ray.d[a];
        double t0 = (box.lo[a] - ray.o[a]) * inv;
        double t1 = (box.hi[a] - ray.o[a]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        // A ray parallel to a slab it lies outside gives NaN or an empty interval.
        if (std::isnan(t0) || std::isnan(t1)) {
            if (ray.o[a] < box.lo[a] || ray.o[a] > box.hi[a]) return false;
            continue;
        }
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
    }
    return tMin < tMax;
}

// [majorant-build]
MajorantGrid::MajorantGrid(const DensityField& field, const AABB& box, int res) {
    const bool finite = isFinite(box.lo) && isFinite(box.hi) && !box.empty();
    if (field.constant() || !finite) {
        // One cell for all space: the field's own bound.
        unbounded_ = true;
        bounds_.assign(1, field.maxIn(box.lo, box.hi));
        return;
    }
    box_ = box;
    res_ = std::max(1, res);
    bounds_.resize(static_cast<size_t>(res_) * res_ * res_);
    const Vec3 cellSize = (box.hi - box.lo) / static_cast<double>(res_);
    for (int z = 0; z < res_; ++z)
        for (int y = 0; y < res_; ++y)
            for (int x = 0; x < res_; ++x) {
                const Vec3 lo = box.lo + Vec3(x, y, z) * cellSize;
                bounds_[(z * res_ + y) * res_ + x] = field.maxIn(lo, lo + cellSize);
            }
}
// [majorant-build]

}  // namespace rb
