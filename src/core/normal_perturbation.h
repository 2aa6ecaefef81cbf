/// \file
/// NormalPerturbation: the extension point that changes the shading normal at a hit (chapter
/// 11's bump maps). A material may carry one; the integrator applies it only when the chapter
/// that provides it is on.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace rb {

/// Something a material carries that tilts the shading normal of the surfaces it covers.
class NormalPerturbation {
  public:
    virtual ~NormalPerturbation() = default;
    /// Replace hit.ns by the perturbed shading normal, for a surface seen along `ray`.
    virtual void perturb(const Ray& ray, Hit& hit) const = 0;
};

}  // namespace rb
