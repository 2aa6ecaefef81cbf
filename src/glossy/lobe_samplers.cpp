#include "glossy/lobe_samplers.h"

#include <glm/gtc/constants.hpp>

namespace rb {

namespace {
constexpr double kPi = glm::pi<double>();
}  // namespace

// [frame]
Frame::Frame(const Vec3& axis) : n(axis) {
    // Source: Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1.0 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    s = Vec3(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
    t = Vec3(b, sign + axis.y * axis.y * a, -axis.y);
}
// [frame]

// [glossiness-mapping]
double phongExponentFromFuzz(double fuzz) {
    // Match the mean cosine to the axis. The fuzz sphere's is 1 − f²/5 (for f ≤ 1), the
    // Phong lobe's is (n+1)/(n+2), so 1/(n+2) = f²/5.
    if (!(fuzz > 0.0)) return 0.0;
    return std::max(0.0, 5.0 / (fuzz * fuzz) - 2.0);
}
// [glossiness-mapping]

// [fuzz-sphere]
Vec3 sampleUniformBall(double u1, double u2, double u3) {
    // [exercise-fuzz-ball]
    // Exercise 7.2, a uniform point in the fuzz ball: read ch07-equations.
    // Blank: return Vec3(0.0);
    // A uniform direction (Archimedes: z uniform in [-1, 1]) at radius ∛u3, because the
    // volume inside radius r grows as r³.
    const double z = 1.0 - 2.0 * u1;
    const double phi = 2.0 * kPi * u2;
    const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
    return std::cbrt(u3) * Vec3(ring * std::cos(phi), ring * std::sin(phi), z);
    // [exercise-fuzz-ball]
}

Vec3 sampleFuzzSphere(const Vec3& axis, double fuzz, double u1, double u2, double u3) {
    const Vec3 d = axis + fuzz * sampleUniformBall(u1, u2, u3);
    const double length = glm::length(d);
    // Catch the degenerate direction: a fuzz sphere of radius ≥ 1 contains the origin.
    if (!(length > 1e-12)) return axis;
    return d / length;
}

double fuzzSpherePdf(double fuzz, double cosAlpha) {
    // A direction ω meets the ball (centre at distance 1 along the axis, radius f) on the
    // chord r ∈ [r−, r+], r± = cos α ± √(f² − sin²α). The point is uniform in the ball, so
    // p(ω) = ∫ r² dr / V = (r+³ − max(0, r−)³) / (4π f³).
    const double sin2Alpha = std::max(0.0, 1.0 - cosAlpha * cosAlpha);
    const double fuzz2 = fuzz * fuzz;
    if (!(fuzz > 0.0) || sin2Alpha > fuzz2) return 0.0;  // the ray misses the ball
    const double halfChord = std::sqrt(fuzz2 - sin2Alpha);
    const double rPlus = cosAlpha + halfChord, rMinus = cosAlpha - halfChord;
    if (rPlus <= 0.0) return 0.0;  // the ball lies behind the origin
    // Factor r+³ − r−³ = (r+ − r−)(r+² + r+r− + r−²) to avoid cancellation when f is small.
    const double cubes = rMinus > 0.0
                             ? 2.0 * halfChord * (rPlus * rPlus + rPlus * rMinus + rMinus * rMinus)
                             : rPlus * rPlus * rPlus;
    return cubes / (4.0 * kPi * fuzz2 * fuzz);
}
// [fuzz-sphere]

// [phong-lobe]
Vec3 samplePhongLobe(const Vec3& axis, double exponent, double u1, double u2) {
    // [exercise-phong-lobe]
    // Exercise 7.1, sampling the Phong lobe: read ch07-equations.
    // Blank: return axis;
    // Invert the CDF of cos α, P(cos α ≤ μ) = μ^(n+1): cos α = ξ^(1/(n+1)) with ξ = 1 − u1
    // in (0, 1]. Compute 1 − cos α with expm1 so that sin α keeps its precision when n is
    // huge and cos α rounds to 1.
    const double oneMinusCos = -std::expm1(std::log1p(-u1) / (exponent + 1.0));
    const double cosAlpha = 1.0 - oneMinusCos;
    const double sinAlpha = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    const double phi = 2.0 * kPi * u2;
    return Frame(axis).toWorld(Vec3(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha));
    // [exercise-phong-lobe]
}

double phongLobePdf(double exponent, double cosAlpha) {
    if (cosAlpha < 0.0) return 0.0;  // the lobe covers the hemisphere about the axis only
    return (exponent + 1.0) / (2.0 * kPi) * std::pow(cosAlpha, exponent);
}
// [phong-lobe]

}  // namespace rb
