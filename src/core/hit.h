/// \file
/// Hit: what a ray learns at the surface it meets first.
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace rb {

struct Material;
struct Instance;

/// The closest intersection of a ray with the scene, in world space.
struct Hit {
    double t = 0.0;               ///< Ray parameter of the hit.
    Vec3 p{0.0};                  ///< World-space hit point.
    Vec3 ng{0.0};                 ///< Geometric normal, unit length, as the shape defines it.
    Vec3 ns{0.0};                 ///< Shading normal (equals ng until a chapter changes it).
    /// Added to p where shadow rays start: zero, except on chapter 9's smooth meshes, where it
    /// lifts the origin off the flat facet towards the curved surface the normals describe.
    Vec3 shadowOffset{0.0};
    Vec2 uv{0.0};                 ///< Surface parameterisation, where the shape has one.
    std::uint32_t primitive = 0;  ///< Triangle index within a mesh, or 0.
    const Material* material = nullptr;  ///< Material of the instance that was hit.
    const Instance* instance = nullptr;  ///< The instance that was hit.
};

/// What a shape reports in its own object space; the scene turns it into a Hit.
struct ObjectHit {
    double t = 0.0;
    Vec3 n{0.0};  ///< Object-space geometric normal (any length).
    Vec2 uv{0.0};
    std::uint32_t primitive = 0;
    /// The material of the part that was hit, for shapes made of parts with materials of
    /// their own (chapter 14's CSG operands); null: the instance's material.
    const Material* material = nullptr;
};

}  // namespace rb
