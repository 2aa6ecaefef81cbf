#include "media/henyey_greenstein.h"

#include <algorithm>
#include <cmath>

namespace rb {

namespace {
constexpr double kInvFourPi = 0.25 / 3.14159265358979323846;
}

// [hg-phase]
double henyeyGreenstein(double cosTheta, double g) {
    // [exercise-hg-phase]
    // Exercise 17.1, the Henyey–Greenstein phase function: read ch17-phase.
    // Blank: return kInvFourPi;
    const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return kInvFourPi * (1.0 - g * g) / (denom * std::sqrt(denom));
    // [exercise-hg-phase]
}
// [hg-phase]

// [hg-sample]
double sampleHenyeyGreensteinCos(double g, double u) {
    // Near g = 0 the inversion divides by g: use the isotropic limit there.
    if (std::abs(g) < 1e-3) return 1.0 - 2.0 * u;
    const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    return std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
}

Vec3 sampleHenyeyGreenstein(const Vec3& forward, double g, const Vec2& u) {
    const double cosTheta = sampleHenyeyGreensteinCos(g, u.x);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * 3.14159265358979323846 * u.y;
    // An orthonormal frame around `forward`. Source: Duff et al., "Building an orthonormal
    // basis, revisited", JCGT 6(1), 2017.
    const double sign = std::copysign(1.0, forward.z);
    const double a = -1.0 / (sign + forward.z);
    const double b = forward.x * forward.y * a;
    const Vec3 t1(1.0 + sign * forward.x * forward.x * a, sign * b, -sign * forward.x);
    const Vec3 t2(b, sign + forward.y * forward.y * a, -forward.y);
    return sinTheta * std::cos(phi) * t1 + sinTheta * std::sin(phi) * t2 + cosTheta * forward;
}
// [hg-sample]

}  // namespace rb
