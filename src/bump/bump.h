/// \file
/// Chapter 11, bump mapping: a height field over a surface tilts its shading normal, so a
/// smooth surface shades as if it were rippled, rough or embossed (Blinn 1978). The gradient
/// of the height is taken numerically, so any height field works: procedural ripples and noise,
/// or an image.
#pragma once

#include <memory>

#include "bump/height_field.h"
#include "core/feature.h"
#include "core/integrator.h"
#include "core/normal_perturbation.h"

namespace rb {

struct RenderContext;

/// The default finite-difference step, as a fraction of the height field's feature size (the
/// chapter's chart shows why: the error is smallest around 1e-4 to 1e-2 of it).
inline constexpr double kDefaultStepFraction = 1e-3;

/// The least cosine between a bumped normal and the direction to the viewer: a bump that would
/// tip the normal further is held at this angle (just under 90°), on the viewer's side.
inline constexpr double kMinCosView = 0.01;

/// An orthonormal tangent frame (t, b) with t × b = n around the unit normal n, continuous
/// except where n.z changes sign. Source: Duff et al., "Building an orthonormal basis,
/// revisited", JCGT 6(1), 2017.
void tangentFrame(const Vec3& n, Vec3& t, Vec3& b);

/// The surface gradient of `field` at object-space point x on a surface with unit normal n:
/// the height's rate of change along each of two tangent directions, by central differences
/// with the given step, as a tangent vector.
Vec3 surfaceGradient(const HeightField& field, const Vec3& x, const Vec3& n, double step);

/// The normal of the surface displaced by strength · h along the unit normal n, given the
/// surface gradient g of h: normalize(n − strength · g) (Blinn's approximation, which drops the
/// terms in h · dn, small for bumps low against the surface's curvature). Returns n when g is
/// not finite.
Vec3 bumpedNormal(const Vec3& n, const Vec3& g, double strength);

/// The bumped unit normal `bumped`, kept on the same side of the viewer as the unbumped
/// `original`: if it tips over (or to within kMinCosView of the tangent plane), it is turned
/// towards the viewer direction v (unit, pointing at the viewer), in the plane of the two,
/// until its cosine with v is kMinCosView.
Vec3 keepViewerSide(const Vec3& bumped, const Vec3& original, const Vec3& v);

/// A bump: a height field, a strength (object units of displacement per unit of height) and
/// a finite-difference step. The chapter's NormalPerturbation.
class Bump final : public NormalPerturbation {
  public:
    /// A bump of `field` scaled by strength (finite); step > 0 in object units, or 0 for
    /// kDefaultStepFraction of the field's feature size.
    Bump(std::shared_ptr<const HeightField> field, double strength, double step = 0.0);
    /// Tilt hit.ns by the height field's gradient at the hit, in the instance's object space.
    /// A zero strength leaves hit.ns as it is, bit for bit.
    void perturb(const Ray& ray, Hit& hit) const override;
    /// The height field.
    const HeightField& field() const { return *field_; }
    /// The strength.
    double strength() const { return strength_; }
    /// The finite-difference step in object units.
    double step() const { return step_; }

  private:
    std::shared_ptr<const HeightField> field_;
    double strength_;
    double step_;
};

/// Chapter 11's shading-normal stage: a hit whose material carries a bump has its shading
/// normal tilted by it. Installed after chapter 9's smooth normals, so the bump tilts the
/// interpolated normal of a smooth mesh.
class BumpNormals final : public ShadingNormal {
  public:
    /// Apply the bump of hit.material, if it has one.
    void apply(const Ray& ray, Hit& hit) const override;
};

/// Plug chapter 11 into one render: a BumpNormals stage when some material of the scene has
/// a bump; a scene without bumps keeps the core's path untouched.
void installBump(Pipeline& pipeline, Scene& scene, const RenderContext& context);

/// Chapter 11's Lua calls: material:set_bump{...} and seed 002's material:set_bump_map(file).
void bindBump(LuaBindings& lua);

/// Chapter 11's feature record.
Feature bumpFeature();

}  // namespace rb
