/// \file
/// Chapter 4, reflection: mirror reflection traced recursively up to a depth limit.
#pragma once

#include "core/feature.h"
#include "core/integrator.h"

namespace rb {

/// The mirror direction of d about the unit normal n: d − 2(d·n)n (d need not be unit length).
Vec3 reflect(const Vec3& d, const Vec3& n);

/// Radiance arriving at hit from the specular direction `axis` (unit), leaving on the side of
/// the unit normal `side`. With a glossy lobe installed (chapter 7) and a glossy material, the
/// average over the lobe's samples; otherwise one sharp ray. Counts rays as `kind`, or as
/// glossy when the lobe spreads them. Only at depth 0 does a glossy surface average many
/// lobe samples; deeper, it takes one, so the ray count does not grow like N^depth.
/// Shared by reflection and refraction.
/// `weight` is what the caller will multiply the result by; a ray whose weight in the pixel
/// (ctx.weight · weight) falls below the scene's minWeight is not traced and returns black.
Colour traceSpecular(const ShadeContext& ctx, const Hit& hit, const Vec3& axis, const Vec3& side,
                     RayKind kind, const MediumStack& media, double weight);

/// Mirror reflection: colour + reflect · L(mirror direction), where `reflect` is the
/// material's reflectivity. Beyond the scene's maximum depth it adds nothing.
class ReflectionTerm final : public ShadingTerm {
public:
    Colour apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                 const Colour& colour) const override;
};

/// Chapter 4's feature record.
Feature reflectionFeature();

}  // namespace rb
