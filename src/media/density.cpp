#include <algorithm>
#include <limits>
#include <stdexcept>

#include "bump/gradient_noise.h"
#include "media/medium.h"
#include "media/noise_bound.h"

namespace rb {

namespace {

/// All of space.
AABB everywhere() {
    const double inf = std::numeric_limits<double>::infinity();
    return AABB{Vec3(-inf), Vec3(inf)};
}

}  // namespace

double DensityField::depth(const Vec3&, const Vec3&, double, double, const double*, double*,
                           int) const {
    throw std::logic_error("DensityField::depth on a density that is not integrable()");
}

AABB ConstantDensity::bounds() const {
    return everywhere();
}

double NoiseDensity::at(const Vec3& p) const {
    const double n = fractalNoise(frequency_ * p, octaves_, seed_);
    return std::clamp(bias_ + gain_ * n, 0.0, 1.0);
}

double NoiseDensity::maxIn(const Vec3& lo, const Vec3& hi) const {
    // The box in noise space (a negative frequency mirrors it).
    const Vec3 a = frequency_ * lo, b = frequency_ * hi;
    const NoiseRange n = fractalNoiseRange(glm::min(a, b), glm::max(a, b), octaves_, seed_);
    // bias + gain·n is largest at n's top end when the gain is positive, at its bottom if not.
    const double top = bias_ + gain_ * (gain_ >= 0.0 ? n.hi : n.lo);
    // The bound is exact arithmetic on intervals, but noise and bound round differently: a
    // hair of slack keeps every at(p) within it.
    constexpr double kRoundingSlack = 1e-9;
    return std::clamp(top + kRoundingSlack, 0.0, 1.0);
}

AABB NoiseDensity::bounds() const {
    return everywhere();
}

}  // namespace rb
