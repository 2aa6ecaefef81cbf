/// \file
/// Material: the A4 Phong parameters plus named extra parameters that chapter modules read.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "core/normal_perturbation.h"
#include "core/vec.h"

namespace rb {

/// A surface material. The core reads kd, ks and shininess (A4's gr.material); later chapters
/// read their own named parameters ("reflect", "ior", ...) from `params`.
struct Material {
    Colour kd{0.0};                        ///< Diffuse reflectance.
    Colour ks{0.0};                        ///< Specular reflectance.
    double shininess = 1.0;                ///< Phong exponent.
    /// Chapter parameters by name, e.g. "reflect". std::less<> lets a lookup compare a string
    /// literal directly, without building a std::string on every hit.
    std::map<std::string, double, std::less<>> params;
    /// Tilts the shading normal where this material is hit (chapter 11's bump), or null.
    std::shared_ptr<const NormalPerturbation> bump;

    /// A chapter parameter, or fallback when the scene did not set it.
    double param(std::string_view name, double fallback = 0.0) const {
        auto it = params.find(name);
        return it == params.end() ? fallback : it->second;
    }
};

}  // namespace rb
