/// \file
/// Chapter 7, glossy: reflection and refraction spread into a lobe of directions (blurry
/// mirrors, frosted glass), by seed 000's fuzz sphere or by importance-sampling a Phong lobe.
#pragma once

#include "core/feature.h"
#include "core/integrator.h"

namespace rb {

struct RenderContext;

/// Which distribution spreads the specular direction.
enum class LobeKind {
    Fuzz,  ///< Seed 000's fuzz sphere: normalize(axis + fuzz · uniform point in the ball).
    Phong  ///< The normalised Phong lobe ∝ cos^n α, importance sampled.
};

/// The samples per glossy surface when nothing asks for a number.
inline constexpr int kDefaultGlossySamples = 16;

/// The glossy lobe sampler that chapter 7 installs as Pipeline::lobe. A material is glossy
/// when its `glossiness` is positive; its glossiness is the fuzz radius, and the Phong
/// exponent is chosen to match it (see phongExponentFromFuzz).
class GlossyLobe final : public LobeSampler {
  public:
    /// A sampler of the given kind that averages `samples` directions per glossy surface.
    GlossyLobe(LobeKind kind, int samples) : kind_(kind), samples_(samples) {}
    /// `samples` for a material with glossiness > 0, else 0 (a sharp mirror). traceSpecular
    /// uses the count where the camera sees the surface and one sample at deeper bounces.
    int sampleCount(const Material& m) const override;
    /// One direction of the material's lobe about `axis`; false (no light) when it falls on
    /// the far side of the surface, that is when direction · n ≤ 0.
    bool sample(const Material& m, const Vec3& axis, const Vec3& n, Sampler& sampler,
                Vec3& direction) const override;
    /// The distribution in use.
    LobeKind kind() const { return kind_; }

  private:
    LobeKind kind_;
    int samples_;
};

/// The samples per glossy surface for one render. Precedence, first that is present:
/// --glossy-samples=N, gr.option('glossy_samples', N), seed 001's gr.render `dist` (dist²
/// rays), kDefaultGlossySamples. Throws InputError for a value that is not a whole number
/// from 0 to 65536.
int glossySampleCount(const RenderContext& context);

/// The lobe for one render: --glossy-sampler=fuzz|lobe, else gr.option('glossy_sampler', 0|1)
/// (0 fuzz, 1 lobe), else the Phong lobe. Throws InputError for anything else.
LobeKind glossyLobeKind(const RenderContext& context);

/// Chapter 7's feature record.
Feature glossyFeature();

}  // namespace rb
