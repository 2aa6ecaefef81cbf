/// \file
/// MajorantGrid: coarse bounds of a density field, so tracking takes long steps where the
/// medium is thin and short ones only where it is thick (chapter 17).
#pragma once

#include <vector>

#include "core/aabb.h"
#include "core/ray.h"
#include "media/density.h"

namespace rb {

/// A res × res × res grid over a box of the medium's space; each cell holds an upper bound of
/// the density in it. A constant field gets one unbounded cell.
class MajorantGrid {
  public:
    /// Bound `field` over `box` (the field's bounds within the medium's shape) in res³ cells.
    MajorantGrid(const DensityField& field, const AABB& box, int res);
    /// Calls visit(t0, t1, bound) for each cell the ray crosses within [tMin, tMax], in the
    /// order the ray meets them, with the density bound of that cell; stops early when visit
    /// returns false. Outside the box the density is 0 and nothing is visited.
    template <class Visit>
    void traverse(const Ray& ray, double tMin, double tMax, Visit&& visit) const;
    int resolution() const { return res_; }  ///< Cells per axis.

  private:
    /// The bound of cell (x, y, z).
    double cell(int x, int y, int z) const { return bounds_[(z * res_ + y) * res_ + x]; }
    AABB box_;
    int res_ = 1;
    bool unbounded_ = false;  ///< One cell covering all space (a constant field).
    std::vector<double> bounds_;
};

/// The parameter interval where a ray is inside a box, clipped to [tMin, tMax]; false if empty.
bool clipToBox(const Ray& ray, const AABB& box, double& tMin, double& tMax);

// [majorant-traverse]
template <class Visit>
void MajorantGrid::traverse(const Ray& ray, double tMin, double tMax, Visit&& visit) const {
    if (unbounded_) {
        visit(tMin, tMax, bounds_[0]);
        return;
    }
    if (!clipToBox(ray, box_, tMin, tMax)) return;
    // A 3D DDA (Amanatides and Woo): step from cell to cell along the ray, each time across
    // the nearest of the three next cell walls.
    const Vec3 extent = box_.hi - box_.lo;
    const Vec3 p = ray.o + tMin * ray.d;
    int cellIndex[3], step[3], stop[3];
    double nextT[3], deltaT[3];
    for (int a = 0; a < 3; ++a) {
        const double cellSize = extent[a] / res_;
        const double local = (p[a] - box_.lo[a]) / cellSize;
        cellIndex[a] = std::clamp(static_cast<int>(local), 0, res_ - 1);
        if (ray.d[a] > 0.0) {
            step[a] = 1;
            stop[a] = res_;
            nextT[a] = tMin + (box_.lo[a] + (cellIndex[a] + 1) * cellSize - p[a]) / ray.d[a];
            deltaT[a] = cellSize / ray.d[a];
        } else if (ray.d[a] < 0.0) {
            step[a] = -1;
            stop[a] = -1;
            nextT[a] = tMin + (box_.lo[a] + cellIndex[a] * cellSize - p[a]) / ray.d[a];
            deltaT[a] = -cellSize / ray.d[a];
        } else {
            step[a] = 0;
            stop[a] = -2;
            nextT[a] = std::numeric_limits<double>::infinity();
            deltaT[a] = 0.0;
        }
    }
    double t = tMin;
    while (t < tMax) {
        // The wall crossed first ends this cell.
        const int a =
            nextT[0] < nextT[1] ? (nextT[0] < nextT[2] ? 0 : 2) : (nextT[1] < nextT[2] ? 1 : 2);
        const double tEnd = std::min(nextT[a], tMax);
        if (tEnd > t && !visit(t, tEnd, cell(cellIndex[0], cellIndex[1], cellIndex[2]))) return;
        t = tEnd;
        cellIndex[a] += step[a];
        if (cellIndex[a] == stop[a]) return;
        nextT[a] += deltaT[a];
    }
}
// [majorant-traverse]

}  // namespace rb
