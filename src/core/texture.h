/// \file
/// Texture: a colour that varies over a surface, bound to a material by a named slot.
#pragma once

#include "core/hit.h"

namespace rb {

/// A colour that varies over a surface: the extension point "a texture lookup for material
/// colours". Chapter 10 derives image and checker textures; chapter 11 reads height maps
/// through the same slots. The core only stores textures in Material::textures.
class Texture {
  public:
    virtual ~Texture() = default;
    /// The linear RGB colour at a surface point. `hit` is as the intersection left it (hit.uv
    /// holds what the shape stored); the texture maps it to its own (u, v) itself.
    virtual Colour evaluate(const Hit& hit) const = 0;
};

}  // namespace rb
