/// \file
/// Chapter 2's local shading: A4 Phong with ambient light, point lights with falloff and hard
/// shadows.
#pragma once

#include "core/integrator.h"
#include "core/feature.h"

namespace rb {

/// Chapter 2: Phong shading with point lights and hard shadows.
Feature phongFeature();

/// Phong's diffuse plus specular reflection of one light arriving from unit direction l, seen
/// from unit direction v, at a surface with unit normal n (already facing v):
/// kd·max(0, n·l) + ks·max(0, r·v)^shininess, where r is l mirrored about n.
Colour phongBrdfTerm(const Material& m, const Vec3& n, const Vec3& l, const Vec3& v);

/// The normal turned to face the viewer: raybook never culls back faces, so a surface seen
/// from behind is shaded as its front.
inline Vec3 faceForward(const Vec3& n, const Vec3& v) {
    return glm::dot(n, v) < 0.0 ? -n : n;
}

/// A4 shading: kd·ambient + Σ visible · I(r) · phongBrdfTerm. A SurfaceShader.
Colour shadePhong(const ShadeContext& ctx, const Ray& ray, const Hit& hit);

}  // namespace rb
