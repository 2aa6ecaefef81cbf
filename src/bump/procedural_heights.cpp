#include "bump/procedural_heights.h"

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "bump/gradient_noise.h"

namespace rb {

double RampHeight::height(const Vec3& x) const {
    return glm::dot(slope_, x);
}

// [ripples]
double RippleHeight::height(const Vec3& x) const {
    // [exercise-ripples]
    // Exercise 11.4, ripples on water: read ch11-procedural.
    // Blank: return 0.0;
    const double k = 2.0 * glm::pi<double>() / lambda_;  // wave number
    double h = 0.0;
    for (const Vec3& c : centres_) {
        const double r = glm::length(x - c);
        // A ring wave: one crest per wavelength, its height falling as 1/√(distance).
        h += std::sin(k * r) / std::sqrt(1.0 + r / lambda_);
    }
    return h;
    // [exercise-ripples]
}
// [ripples]

Vec3 RippleHeight::exactGradient(const Vec3& x) const {
    // d/dr [sin(kr) (1 + r/λ)^(-1/2)] = k cos(kr) s − sin(kr) s³ / (2λ), s = (1 + r/λ)^(-1/2),
    // along the unit vector (x − c)/r.
    const double k = 2.0 * glm::pi<double>() / lambda_;
    Vec3 g(0.0);
    for (const Vec3& c : centres_) {
        const double r = glm::length(x - c);
        if (r == 0.0) continue;  // the centre: the gradient is not defined; take 0
        const double s = 1.0 / std::sqrt(1.0 + r / lambda_);
        const double dhdr = k * std::cos(k * r) * s - std::sin(k * r) * s * s * s / (2.0 * lambda_);
        g += dhdr * (x - c) / r;
    }
    return g;
}

double NoiseHeight::height(const Vec3& x) const {
    return fractalNoise(x / scale_, octaves_, seed_);
}

double NoiseHeight::featureSize() const {
    return scale_ / std::pow(2.0, octaves_ - 1);
}

}  // namespace rb
