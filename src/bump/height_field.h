/// \file
/// HeightField: a scalar height over an object's surface, the input of a bump. Chapter 11
/// turns its surface gradient into a tilted shading normal.
#pragma once

#include "core/vec.h"

namespace rb {

/// A height h(x) at object-space points x near a surface. A bump displaces the surface by
/// strength · h along its normal, but only in the shading normal: the geometry stays put.
class HeightField {
  public:
    virtual ~HeightField() = default;
    /// The height at object-space point x (any finite number; the bump's strength scales it).
    virtual double height(const Vec3& x) const = 0;
    /// The length over which the height changes noticeably (a wavelength, a noise cell, a
    /// texel), in object units: the default finite-difference step is a fraction of it.
    virtual double featureSize() const = 0;
};

}  // namespace rb
