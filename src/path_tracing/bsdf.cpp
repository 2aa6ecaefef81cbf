#include "path_tracing/bsdf.h"

#include <algorithm>
#include <cmath>

#include "glossy/lobe_samplers.h"
#include "phong/phong.h"
#include "photon_map/emission.h"
#include "reflection/reflection.h"
#include "refraction/refraction.h"

namespace rb {

namespace {

constexpr double kInvPi = 1.0 / 3.14159265358979323846;

/// The mean of a colour's channels.
double mean(const Colour& c) {
    return (c.r + c.g + c.b) / 3.0;
}

/// wo mirrored about unit n: the axis of the Phong lobe.
Vec3 mirrored(const Vec3& wo, const Vec3& n) {
    return 2.0 * glm::dot(n, wo) * n - wo;
}

}  // namespace

// [normalized-phong]
double normalizedPhong(double shininess, const Vec3& n, const Vec3& wo, const Vec3& wi) {
    // [exercise-normalized-phong]
    // Exercise 18.2, the normalized Phong lobe: read ch18-phong.
    // Blank: return 0.0;
    const double cosAlpha = glm::dot(mirrored(wo, n), wi);
    if (cosAlpha <= 0.0) return 0.0;
    // (n + 2)/(2π) makes the lobe times cos θi integrate to at most 1 over the hemisphere.
    return (shininess + 2.0) * 0.5 * kInvPi * std::pow(cosAlpha, shininess);
    // [exercise-normalized-phong]
}
// [normalized-phong]

Shares materialShares(const Material& m, bool mirrors, bool glass) {
    Shares s;
    s.kd = glm::max(m.kd, Colour(0.0));
    s.ks = glm::max(m.ks, Colour(0.0));
    s.mirror = mirrors ? std::max(0.0, m.param("reflect")) : 0.0;
    s.transparency = glass ? std::clamp(m.param("transparency"), 0.0, 1.0) : 0.0;
    // A material that would reflect more than it receives is scaled down as a whole.
    const Colour total = s.kd + s.ks + Colour(s.mirror);
    s.scale = std::max({1.0, total.r, total.g, total.b});
    if (s.scale > 1.0) {
        s.kd /= s.scale;
        s.ks /= s.scale;
        s.mirror /= s.scale;
    }
    return s;
}

Bsdf::Bsdf(const Hit& hit, const Material& m, const Vec3& wo, bool mirrors,
           const RefractionTerm* refraction, const LobeSampler* lobe)
    : hit_(hit),
      m_(m),
      wo_(wo),
      n_(faceForward(hit.ns, wo)),
      ng_(faceForward(hit.ng, wo)),
      shares_(materialShares(m, mirrors, refraction != nullptr)),
      refraction_(refraction),
      lobe_(lobe && lobe->sampleCount(m) > 0 ? lobe : nullptr) {
    const double diffuse = mean(shares_.kd), specular = mean(shares_.ks);
    const double opaque = shares_.mirror + diffuse + specular;
    mirrorProbability_ = opaque > 0.0 ? shares_.mirror / opaque : 0.0;
    smoothProbability_ =
        opaque > 0.0 ? (1.0 - shares_.transparency) * (1.0 - mirrorProbability_) : 0.0;
    diffuseShare_ = diffuse + specular > 0.0 ? diffuse / (diffuse + specular) : 0.0;
}

// [bsdf-f]
Colour Bsdf::f(const Vec3& wi) const {
    // Light from below the surface (either normal) is not reflected.
    if (glm::dot(wi, n_) <= 0.0 || glm::dot(wi, ng_) <= 0.0) return Colour(0.0);
    Colour value = shares_.kd * kInvPi;
    if (shares_.ks != Colour(0.0)) value += shares_.ks * normalizedPhong(m_.shininess, n_, wo_, wi);
    return (1.0 - shares_.transparency) * value;
}
// [bsdf-f]

// [bsdf-pdf]
double Bsdf::pdf(const Vec3& wi) const {
    if (smoothProbability_ <= 0.0) return 0.0;
    const double cosTheta = glm::dot(wi, n_);
    if (cosTheta <= 0.0 || glm::dot(wi, ng_) <= 0.0) return 0.0;
    double density = diffuseShare_ * cosineHemispherePdf(cosTheta);
    if (diffuseShare_ < 1.0)
        density +=
            (1.0 - diffuseShare_) * phongLobePdf(m_.shininess, glm::dot(mirrored(wo_, n_), wi));
    return smoothProbability_ * density;
}
// [bsdf-pdf]

// [bsdf-sample]
bool Bsdf::sample(Sampler& sampler, const MediumStack& media, BsdfSample& out) const {
    const double u = sampler.next1D();
    const Vec3 d = -wo_;
    if (u < shares_.transparency) {
        // Glass (chapter 5): the mirror ray with probability F, else the refracted one; the
        // choice's probability cancels the Fresnel weight.
        const DielectricSplit split =
            splitAtDielectric(d, hit_, m_.param("ior", 1.0), media, refraction_->formulaFor(m_));
        out.delta = true;
        out.pdf = 0.0;
        out.weight = Colour(1.0);
        out.transmitted = !(split.F >= 1.0 || sampler.next1D() < split.F);
        out.wi = out.transmitted ? split.transmitted : split.reflected;
        if (out.transmitted) out.media = split.media.beyond;
        const Vec3 side = out.transmitted ? -ng_ : ng_;
        return !lobe_ || lobe_->sample(m_, out.wi, side, sampler, out.wi);
    }
    // The opaque part: u, rescaled to [0, 1), picks the mirror or the smooth lobes.
    const double v = (u - shares_.transparency) / (1.0 - shares_.transparency);
    if (v < mirrorProbability_) {
        out.delta = true;
        out.pdf = 0.0;
        out.weight = Colour(shares_.mirror / mirrorProbability_);
        out.wi = glm::normalize(reflect(d, n_));
        return !lobe_ || lobe_->sample(m_, out.wi, ng_, sampler, out.wi);
    }
    if (smoothProbability_ <= 0.0) return false;  // a black material absorbs
    // [exercise-bsdf-sample]
    // Exercise 18.3, the BSDF sampler and its pdf: read ch18-bsdf.
    // Blank: return false;
    const Vec2 w = sampler.next2D();
    out.wi = sampler.next1D() < diffuseShare_
                 ? sampleCosineHemisphere(n_, w.x, w.y)
                 : samplePhongLobe(mirrored(wo_, n_), m_.shininess, w.x, w.y);
    out.delta = false;
    out.pdf = pdf(out.wi);
    if (!(out.pdf > 0.0)) return false;  // below the surface: no light comes this way
    out.weight = f(out.wi) * glm::dot(out.wi, n_) / out.pdf;
    return true;
    // [exercise-bsdf-sample]
}
// [bsdf-sample]

}  // namespace rb
