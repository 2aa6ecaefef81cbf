/// \file
/// Chapter 5, refraction: Snell's law, the Fresnel split between a mirror ray and a refracted
/// ray, total internal reflection, and an index-of-refraction stack for nested media.
#pragma once

#include "core/feature.h"
#include "core/integrator.h"
#include "refraction/fresnel.h"

namespace rb {

/// Snell's law in vector form: the unit refracted direction of the unit direction d at a
/// surface with unit normal n on the incident side (d·n ≤ 0), going from index eta_i into
/// eta_t. Returns false (and leaves t alone) under total internal reflection.
bool refractDirection(const Vec3& d, const Vec3& n, double eta_i, double eta_t, Vec3& t);

/// The media on both sides of a surface a ray is about to cross, and the media it travels
/// through once it has crossed.
struct MediaCrossing {
    double eta_i = 1.0;    ///< Index of refraction on the ray's side.
    double eta_t = 1.0;    ///< Index of refraction on the far side.
    bool entering = true;  ///< The ray goes into the object.
    MediumStack beyond;    ///< The stack a transmitted ray carries.
};

/// Which media meet where a ray travelling through `media` crosses the surface of `instance`,
/// an object of index `ior`. `entering` says which way the ray crosses (for closed shapes: it
/// arrives against the outward geometric normal). Entering pushes the object onto the stack;
/// leaving pops it, and the stack tells what lies beyond (MediumStack::iorBeyond).
MediaCrossing crossSurface(const MediumStack& media, const Instance* instance, double ior,
                           bool entering);

/// What a smooth dielectric surface does to one ray: it splits it into a mirror ray that
/// carries the share F and a refracted ray that carries 1 − F.
struct DielectricSplit {
    Vec3 reflected{0.0};      ///< Unit mirror direction.
    Vec3 transmitted{0.0};    ///< Unit refracted direction (zero under total internal reflection).
    double F = 1.0;           ///< Fresnel reflectance: the reflected share (1 under TIR).
    double cosTheta_i = 0.0;  ///< Cosine of the angle of incidence.
    bool totalInternalReflection = false;  ///< No refracted ray exists.
    MediaCrossing media;                   ///< The indices on both sides, and the stack beyond.
};

/// Split a ray with unit direction d at `hit` on an object of index `ior`, travelling through
/// `media`, using `formula` for the reflectance.
DielectricSplit splitAtDielectric(const Vec3& d, const Hit& hit, double ior,
                                  const MediumStack& media, FresnelFormula formula);

/// Which Fresnel formula a render uses: each material's own choice (its `schlick` field), or
/// one for all (--fresnel=exact|schlick).
enum class FresnelChoice { PerMaterial, Exact, Schlick };

/// Transmission through transparent materials (seed 001's semantics): with transparency τ,
/// colour_out = (1 − τ)·colour + τ·(F·L_reflected + (1 − F)·L_transmitted), where colour is
/// everything earlier terms computed (Phong, and chapter 4's mirror term). Beyond the scene's
/// maximum depth it returns the colour unchanged. Shadow rays stay opaque: a glass object
/// casts a full, hard shadow (no caustics).
class RefractionTerm final : public ShadingTerm {
  public:
    /// Both rays are traced at depths below this; deeper, one of them is picked with
    /// probability F and 1 − F, so nested glass cannot grow a tree of 2^depth rays.
    static constexpr int kFullSplitDepth = 8;

    /// A term that picks the Fresnel formula by `choice`.
    explicit RefractionTerm(FresnelChoice choice = FresnelChoice::PerMaterial) : choice_(choice) {}
    /// The colour at hit after transmission, given the colour so far.
    Colour apply(const ShadeContext& ctx, const Ray& ray, const Hit& hit,
                 const Colour& colour) const override;
    /// The formula this term uses for material m.
    FresnelFormula formulaFor(const Material& m) const;

  private:
    FresnelChoice choice_;
};

/// Chapter 5's feature record.
Feature refractionFeature();

}  // namespace rb
