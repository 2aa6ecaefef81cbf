#include <algorithm>
#include <limits>

#include "bump/gradient_noise.h"
#include "media/medium.h"

namespace rb {

namespace {

/// All of space.
AABB everywhere() {
    const double inf = std::numeric_limits<double>::infinity();
    return AABB{Vec3(-inf), Vec3(inf)};
}

}  // namespace

AABB ConstantDensity::bounds() const {
    return everywhere();
}

double NoiseDensity::at(const Vec3& p) const {
    const double n = fractalNoise(frequency_ * p, octaves_, seed_);
    return std::clamp(bias_ + gain_ * n, 0.0, 1.0);
}

AABB NoiseDensity::bounds() const {
    return everywhere();
}

}  // namespace rb
