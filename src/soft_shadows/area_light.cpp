#include "soft_shadows/area_light.h"

#include <glm/gtc/constants.hpp>

#include "core/error.h"

namespace rb {

namespace {

/// Two unit vectors t, b that make (t, b, w) an orthonormal basis for unit w.
/// Source: Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
void orthonormalBasis(const Vec3& w, Vec3& t, Vec3& b) {
    const double sign = std::copysign(1.0, w.z);
    const double a = -1.0 / (sign + w.z);
    const double c = w.x * w.y * a;
    t = Vec3(1.0 + sign * w.x * w.x * a, sign * c, -sign * w.x);
    b = Vec3(c, sign + w.y * w.y * a, -w.y);
}

}  // namespace

// ---- Rectangle ----------------------------------------------------------------------------

RectangleLight::RectangleLight(double length, double width, const Vec3& normal, const Vec3& left,
                               int samplesPerAxis, LightSampling sampling)
    : AreaLightShape(samplesPerAxis, sampling), length_(length), width_(width) {
    if (!(length >= 0.0) || !(width >= 0.0) || !std::isfinite(length) || !std::isfinite(width))
        throw InputError("RectangleLight: length and width must be finite and >= 0");
    if (samplesPerAxis < 1) throw InputError("RectangleLight: samples per axis must be >= 1");
    const double normalLength = glm::length(normal);
    if (!(normalLength > 0.0) || !isFinite(normal))
        throw InputError("RectangleLight: the normal must be a non-zero vector");
    normal_ = normal / normalLength;
    // Gram–Schmidt: the normal wins; `left` is projected into the panel's plane.
    const Vec3 inPlane = left - glm::dot(left, normal_) * normal_;
    if (!isFinite(left) || !(glm::length(inPlane) > 1e-6 * glm::length(left)))
        throw InputError("RectangleLight: left must be non-zero and not parallel to the normal");
    left_ = glm::normalize(inPlane);
    up_ = glm::cross(normal_, left_);
}

// [rectangle-sample]
Vec3 RectangleLight::samplePoint(const Vec3& centre, const Vec3& p, int k, int n, const Vec2& u,
                                 double& weight) const {
    // [exercise-rectangle-sample]
    // Exercise 6.1, sampling a rectangular light: read ch06-equations.
    // Blank: weight = 1.0; return centre;
    // Pick the point: uniform over the panel, pdf_A = 1 / (length · width).
    const Vec2 s = unitSquareSample(k, n, u, sampling_);
    const Vec3 x = centre + ((s.x - 0.5) * length_) * left_ + ((s.y - 0.5) * width_) * up_;
    // Its emission towards p: a Lambertian panel's radiance L = I / A seen at angle θ_light
    // sends L·cosθ_light·dA; divided by the pdf that is I·cosθ_light per sample.
    const Vec3 toP = p - x;
    const double r = glm::length(toP);
    weight = r > 0.0 ? std::max(0.0, glm::dot(normal_, toP) / r) : 0.0;
    return x;
    // [exercise-rectangle-sample]
}
// [rectangle-sample]

std::shared_ptr<const AreaLightShape> RectangleLight::withSampling(LightSampling s) const {
    auto copy = std::make_shared<RectangleLight>(*this);
    copy->sampling_ = s;
    return copy;
}

// ---- Ball ---------------------------------------------------------------------------------

BallLight::BallLight(double radius, int samplesPerAxis, LightSampling sampling)
    : AreaLightShape(samplesPerAxis, sampling), radius_(radius) {
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw InputError("BallLight: the radius must be finite and >= 0");
    if (samplesPerAxis < 1) throw InputError("BallLight: samples per axis must be >= 1");
}

// [ball-sample]
Vec3 BallLight::samplePoint(const Vec3& centre, const Vec3& p, int k, int n, const Vec2& u,
                            double& weight) const {
    const double R = radius_;
    // A ball of radius 0 is exactly a point light.
    if (R == 0.0) {
        weight = 1.0;
        return centre;
    }
    const Vec2 s = unitSquareSample(k, n, u, sampling_);
    const Vec3 toP = p - centre;
    const double d = glm::length(toP);
    if (d <= R) {
        // From inside (or on) the ball the whole sphere is visible: sample its area uniformly,
        // pdf_A = 1 / (4πR²). With L = I / (πR²) each sample carries 4·I·|cosθ_light| / r².
        const double z = 1.0 - 2.0 * s.x;
        const double sinZ = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * glm::pi<double>() * s.y;
        const Vec3 normal(sinZ * std::cos(phi), sinZ * std::sin(phi), z);
        const Vec3 x = centre + R * normal;
        const double r = glm::length(p - x);
        weight = r > 0.0 ? 4.0 * std::abs(glm::dot(normal, p - x)) / r : 0.0;
        return x;
    }
    // [exercise-ball-sample]
    // Exercise 6.2, sampling the cone of a ball light: read ch06-equations.
    // Blank: weight = 1.0; return centre;
    // Compute the cone of directions from p that meet the ball: sinθ_max = R / d. The
    // form sin² / (1 + cos) keeps 1 − cosθ_max accurate for small or distant balls.
    const double sin2ThetaMax = (R / d) * (R / d);
    const double cosThetaMax = std::sqrt(std::max(0.0, 1.0 - sin2ThetaMax));
    const double oneMinusCosThetaMax = sin2ThetaMax / (1.0 + cosThetaMax);
    // Pick a direction uniformly in the cone: 1 − cosθ uniform in [0, 1 − cosθ_max],
    // pdf_ω = 1 / (2π(1 − cosθ_max)).
    const double oneMinusCosTheta = s.x * oneMinusCosThetaMax;
    const double cosTheta = 1.0 - oneMinusCosTheta;
    const double sin2Theta = oneMinusCosTheta * (2.0 - oneMinusCosTheta);
    // Find where that direction first meets the sphere, as the angle α at the centre between
    // the point and p: cosα = (d/R)·sin²θ + cosθ·√(1 − (d/R)²·sin²θ).
    // Source: pbrt-v4 (Pharr, Jakob and Humphreys), §6.2 "Spheres", sampling by solid angle.
    const double cosAlpha =
        sin2Theta / (R / d) + cosTheta * std::sqrt(std::max(0.0, 1.0 - sin2Theta / sin2ThetaMax));
    const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
    const double phi = 2.0 * glm::pi<double>() * s.y;
    const Vec3 w = toP / d;
    Vec3 t, b;
    orthonormalBasis(w, t, b);
    const Vec3 x =
        centre + R * (sinAlpha * std::cos(phi) * t + sinAlpha * std::sin(phi) * b + cosAlpha * w);
    // Its emission: radiance L = I / (πR²) over the pdf is L·2π(1 − cosθ_max) per unit
    // cosθ_receiver; the core multiplies by I / r², so the weight is 2(1 − cosθ_max)·r² / R².
    const Vec3 fromP = x - p;
    weight = 2.0 * oneMinusCosThetaMax * glm::dot(fromP, fromP) / (R * R);
    return x;
    // [exercise-ball-sample]
}

double BallLight::pdfSolidAngle(const Vec3& centre, const Vec3& p) const {
    const double d = glm::length(centre - p);
    const double sin2ThetaMax = (radius_ / d) * (radius_ / d);
    const double cosThetaMax = std::sqrt(std::max(0.0, 1.0 - sin2ThetaMax));
    return 1.0 / (2.0 * glm::pi<double>() * (sin2ThetaMax / (1.0 + cosThetaMax)));
}
// [ball-sample]

std::shared_ptr<const AreaLightShape> BallLight::withSampling(LightSampling s) const {
    auto copy = std::make_shared<BallLight>(*this);
    copy->sampling_ = s;
    return copy;
}

}  // namespace rb
