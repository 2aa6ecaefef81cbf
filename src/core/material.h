/// \file
/// Material: the A4 Phong parameters plus named extra parameters and textures that chapter
/// modules read.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "core/normal_perturbation.h"
#include "core/vec.h"

namespace rb {

class Texture;

/// Orders parameter names by length, then alphabetically. Transparent, like std::less<>: a
/// lookup by string literal builds no std::string; and since the names a chapter looks up on
/// every hit ("reflect", "transparency", "ior") differ in length, a lookup mostly settles on
/// the lengths alone, without comparing characters.
struct ShortlexLess {
    using is_transparent = void;
    /// True when a comes before b.
    bool operator()(std::string_view a, std::string_view b) const {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
    }
};

/// A surface material. The core reads kd, ks and shininess (A4's gr.material); later chapters
/// read their own named parameters ("reflect", "ior", ...) from `params`.
struct Material {
    Colour kd{0.0};          ///< Diffuse reflectance.
    Colour ks{0.0};          ///< Specular reflectance.
    double shininess = 1.0;  ///< Phong exponent.
    /// Chapter parameters by name, e.g. "reflect", looked up on every hit (see ShortlexLess).
    std::map<std::string, double, ShortlexLess> params;
    /// Tilts the shading normal where this material is hit (chapter 11's bump), or null.
    std::shared_ptr<const NormalPerturbation> bump;

    /// Textures by slot: "kd" and "ks" replace those colours (chapter 10), "bump" is chapter
    /// 11's height map. Empty for an untextured material, which then costs nothing to shade.
    std::map<std::string, std::shared_ptr<const Texture>, std::less<>> textures = {};
    /// Radiance the surface emits on both sides: chapter 18's emitting surfaces (zero for
    /// A4's materials, which only reflect).
    Colour emission{0.0};

    /// A chapter parameter, or fallback when the scene did not set it.
    double param(std::string_view name, double fallback = 0.0) const {
        auto it = params.find(name);
        return it == params.end() ? fallback : it->second;
    }
    /// The texture in `slot`, or null when the material has none there.
    const Texture* texture(std::string_view slot) const {
        if (textures.empty()) return nullptr;
        auto it = textures.find(slot);
        return it == textures.end() ? nullptr : it->second.get();
    }
};

}  // namespace rb
