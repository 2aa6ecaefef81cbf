/// \file
/// The surface scattering model of chapter 18's path tracer: every raybook material as one
/// BSDF. A4's kd is a Lambertian lobe, ks and shininess a normalized Phong lobe, chapter 4's
/// `reflect` a mirror and chapter 5's `transparency` glass with Fresnel; chapter 7's glossiness
/// spreads the mirror and the glass into lobes.
#pragma once

#include "core/hit.h"
#include "core/integrator.h"
#include "core/material.h"
#include "core/medium_stack.h"

namespace rb {

class RefractionTerm;

/// The normalized Phong lobe's value (per steradian): ks (n+2)/(2π) cos^n α, α the angle
/// between wi and wo mirrored about n. Its albedo is at most ks for every n.
/// Source: E. Lafortune and Y. Willems, "Using the modified Phong reflectance model for
/// physically based rendering", KU Leuven CW 197, 1994.
double normalizedPhong(double shininess, const Vec3& n, const Vec3& wo, const Vec3& wi);

/// A material's shares, scaled so that it reflects at most what it receives: kd + ks +
/// reflect ≤ 1 in every channel of the opaque part.
struct Shares {
    Colour kd{0.0}, ks{0.0};
    double mirror = 0.0;        ///< Chapter 4's reflect.
    double transparency = 0.0;  ///< Chapter 5's τ: the glass part.
    double scale = 1.0;         ///< What kd, ks and reflect were divided by (1: nothing).
};
/// The shares of material m; `mirrors` and `glass` say whether chapters 4 and 5 are on.
Shares materialShares(const Material& m, bool mirrors, bool glass);

/// One sampled direction of a BSDF.
struct BsdfSample {
    Vec3 wi{0.0};        ///< The new direction (unit), away from the surface.
    Colour weight{0.0};  ///< f · |cos θi| / pdf: what the path's throughput is multiplied by.
    double pdf = 0.0;    ///< Its density per steradian, 0 for a mirror or glass (a delta).
    bool delta = false;  ///< A mirror or glass direction: light sampling cannot find it.
    bool transmitted = false;  ///< Through glass: the path crosses to the far side.
    MediumStack media{};       ///< The media beyond, when transmitted.
};

/// The BSDF at one hit, facing the ray that found it.
class Bsdf {
  public:
    /// `wo` is the unit direction back along the ray; `media` the ray's media (for glass).
    /// `refraction` is chapter 5's term (its Fresnel formula), null when glass is off;
    /// `lobe` chapter 7's glossy spread, or null.
    Bsdf(const Hit& hit, const Material& m, const Vec3& wo, bool mirrors,
         const RefractionTerm* refraction, const LobeSampler* lobe);
    /// The smooth part's value f(wo, wi) (Lambert and Phong; mirror and glass are deltas).
    Colour f(const Vec3& wi) const;
    /// The density with which sample() draws wi by the smooth part (for MIS).
    double pdf(const Vec3& wi) const;
    /// Draw a direction: glass, mirror or the smooth lobes, in proportion to their shares.
    /// False when the path ends (absorbed, or a lobe below the surface).
    bool sample(Sampler& sampler, const MediumStack& media, BsdfSample& out) const;
    /// True when the smooth part can reflect light (light sampling is worth its shadow ray).
    bool hasSmoothPart() const { return smoothProbability_ > 0.0; }
    /// The shading normal, on the side of wo.
    const Vec3& n() const { return n_; }
    /// The geometric normal, on the side of wo.
    const Vec3& ng() const { return ng_; }

  private:
    const Hit& hit_;
    const Material& m_;
    Vec3 wo_, n_, ng_;
    Shares shares_;
    const RefractionTerm* refraction_;
    const LobeSampler* lobe_;
    double mirrorProbability_ = 0.0;  ///< Of the opaque part.
    double smoothProbability_ = 0.0;  ///< Of the whole: (1 − τ)(1 − mirror's).
    double diffuseShare_ = 0.0;       ///< Of the smooth part's samples: Lambert's.
};

}  // namespace rb
