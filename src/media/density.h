/// \file
/// DensityField: how thick a medium is at each point of its own space (chapter 17).
#pragma once

#include <memory>
#include <string>

#include "core/aabb.h"
#include "core/vec.h"

namespace rb {

/// A medium's density: its coefficients σa and σs are scaled by density(p) at each point p
/// of the medium's own space (the space of the node it fills, or world space for fog).
/// A constant medium has density 1 everywhere; a smoke grid is zero outside its voxels.
class DensityField {
  public:
    virtual ~DensityField() = default;
    /// The density at p, ≥ 0.
    virtual double at(const Vec3& p) const = 0;
    /// An upper bound of the density over the box [lo, hi] (the majorant grid's cells).
    /// It must never be below at(p) for a p in the box; tighter bounds mean fewer null
    /// collisions.
    virtual double maxIn(const Vec3& lo, const Vec3& hi) const = 0;
    /// Where the density may be non-zero (infinite for a constant field).
    virtual AABB bounds() const = 0;
    /// True when the density is the same everywhere (closed-form transmittance applies).
    virtual bool constant() const { return false; }
    /// True when depth() integrates the density along a line exactly (a voxel grid).
    virtual bool integrable() const { return false; }
    /// The optical depth per unit density coefficient, ∫ density(o + t d) dt from t0 to t1,
    /// and the same integral from t0 up to each of the `count` sorted parameters `at` (into
    /// depthAt; those outside [t0, t1] are clamped to it). Only where integrable().
    virtual double depth(const Vec3& o, const Vec3& d, double t0, double t1, const double* at,
                         double* depthAt, int count) const;
};

}  // namespace rb
